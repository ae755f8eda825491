/* One run of one of Box2D v3's benchmark scenes, timed as v3's own
 * benchmark/main.c times it: the scene is built by v3's shared/benchmarks.c
 * (compiled from the v3 tree given to make bench-v3, never from this
 * repository), step 0 (with the scene's step function, if any) is not timed,
 * steps 1..N-1 are, single-threaded, 60 Hz, 4 substeps. The time is the
 * process's CPU time (CLOCK_PROCESS_CPUTIME_ID), so that another process on a
 * shared machine does not count.
 *
 *   bench_v3_box2d SCENE [STEPS]
 * SCENE pyramid_base_N (N in 1..100) is v3's large pyramid with a base of N
 * boxes, built here through v3's API the way v3's builder lays it out (the
 * small-pyramid scaling rows; sleeping off, 500 steps by default).
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

/* A pyramid of `base` boxes of half-size 0.5 (density 1) on a static ground
 * box of half-extents 100 x 1 whose top is y = 0; row i (from 0 at the
 * bottom) holds base - i boxes centred on x = 0, 1 m apart. */
static int g_base;
static void create_pyramid(b2WorldId world) {
  b2World_EnableSleeping(world, false);
  b2BodyDef ground_def = b2DefaultBodyDef();
  ground_def.position = (b2Pos){0.0f, -1.0f};
  b2BodyId ground = b2CreateBody(world, &ground_def);
  b2ShapeDef ground_shape = b2DefaultShapeDef();
  b2Polygon ground_box = b2MakeBox(100.0f, 1.0f);
  b2CreatePolygonShape(ground, &ground_shape, &ground_box);
  b2BodyDef def = b2DefaultBodyDef();
  def.type = b2_dynamicBody;
  b2ShapeDef shape = b2DefaultShapeDef();
  shape.density = 1.0f;
  b2Polygon box = b2MakeSquare(0.5f);
  for (int row = 0; row < g_base; ++row)
    for (int k = 0; k < g_base - row; ++k) {
      def.position = (b2Pos){0.5f * (float)(row + 1) + (float)k - 0.5f * (float)g_base, (float)row + 0.5f};
      b2BodyId body = b2CreateBody(world, &def);
      b2CreatePolygonShape(body, &shape, &box);
    }
}

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
  scene pyramid = {argv[1], create_pyramid, NULL, 500};
  if (sscanf(argv[1], "pyramid_base_%d", &g_base) == 1) {
    if (g_base < 1 || g_base > 100) {
      fprintf(stderr, "%s: %s: the base is 1 to 100\n", argv[0], argv[1]);
      return 2;
    }
    sc = &pyramid;
  }
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
