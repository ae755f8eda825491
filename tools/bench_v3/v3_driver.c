/* One run of one of Box2D v3's benchmark scenes, timed as v3's own
 * benchmark/main.c times it: the scene is built by v3's shared/benchmarks.c
 * (compiled from the v3 tree given to make bench-v3, never from this
 * repository), step 0 (with the scene's step function, if any) is not timed,
 * steps 1..N-1 are, single-threaded, 60 Hz, 4 substeps. The time is the
 * process's CPU time (CLOCK_PROCESS_CPUTIME_ID), so that another process on a
 * shared machine does not count.
 *
 *   bench_v3_box2d SCENE [STEPS]
 * prints: box2d_v3 SCENE STEPS MS_PER_STEP bodies B shapes S joints J pairs P
 * coloured K awake A, where P counts v3's contacts (shape pairs whose fat
 * boxes overlap) and K the constraints in its graph colours (awake touching
 * contacts and joints). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "benchmarks.h"
#include "box2d/box2d.h"

typedef struct scene {
  const char* name;
  void (*create)(b2WorldId world);
  float (*step)(b2WorldId world, int step);
  int steps;
} scene;

/* v3's list, names and step counts as in its benchmark/main.c */
static const scene k_scenes[] = {
    {"compounds", CreateCompounds, NULL, 500},
    {"joint_grid", CreateJointGrid, NULL, 500},
    {"junkyard", CreateJunkyard, StepJunkyard, 800},
    {"large_pyramid", CreateLargePyramid, NULL, 500},
    {"many_pyramids", CreateManyPyramids, NULL, 200},
    {"rain", CreateRain, StepRain, 1000},
    {"smash", CreateSmash, NULL, 300},
    {"spinner", CreateSpinner, StepSpinner, 500},
    {"tumbler", CreateTumbler, NULL, 750},
    {"washer", CreateWasher, NULL, 500},
};

static double cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENE [STEPS]\n", argv[0]);
    return 2;
  }
  const scene* sc = NULL;
  for (size_t i = 0; i < sizeof k_scenes / sizeof k_scenes[0]; ++i)
    if (strcmp(k_scenes[i].name, argv[1]) == 0) sc = &k_scenes[i];
  if (sc == NULL) {
    fprintf(stderr, "%s: no v3 scene named %s\n", argv[0], argv[1]);
    return 2;
  }
  int steps = argc > 2 ? atoi(argv[2]) : sc->steps;
  if (steps < 2) steps = 2;
  b2WorldDef def = b2DefaultWorldDef();
  def.workerCount = 1;
  b2WorldId world = b2CreateWorld(&def);
  sc->create(world);
  if (sc->step != NULL) sc->step(world, 0);
  b2World_Step(world, 1.0f / 60.0f, 4);
  double t0 = cpu_seconds();
  for (int i = 1; i < steps; ++i) {
    if (sc->step != NULL) sc->step(world, i);
    b2World_Step(world, 1.0f / 60.0f, 4);
  }
  double ms = 1e3 * (cpu_seconds() - t0) / (double)(steps - 1);
  b2Counters c = b2World_GetCounters(world);
  int coloured = 0;
  for (size_t k = 0; k < sizeof c.colorCounts / sizeof c.colorCounts[0]; ++k) coloured += c.colorCounts[k];
  printf("box2d_v3 %s %d %.4f bodies %d shapes %d joints %d pairs %d coloured %d awake %d\n", sc->name, steps, ms,
         c.bodyCount, c.shapeCount, c.jointCount, c.contactCount, coloured, b2World_GetAwakeBodyCount(world));
  b2DestroyWorld(world);
  return 0;
}
