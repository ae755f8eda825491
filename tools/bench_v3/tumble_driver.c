/* One run of one scene of the catalogue (demos/scenes), timed with the
 * protocol of Box2D v3's benchmark/main.c so that tools/bench_v3.sh can put
 * the two side by side: build, step 0 not timed, steps 1..N-1 timed in process
 * CPU time, 60 Hz, 4 substeps. v3's sleep settings are the scenes' own
 * (sleeping off in large_pyramid, many_pyramids and joint_grid, as v3's
 * builders turn it off there).
 *
 *   bench_v3_tumble SCENE [STEPS] [--relax-iterations N] [--contact-hertz F]
 * SCENE pyramid_base_N (N in 1..100) is large_pyramid with a base of N boxes
 * (the small-pyramid scaling rows; sleeping off, 500 steps by default). The
 * options run the scene at another solver setting than tumble's default (8
 * relax passes, 120 Hz contacts), to put tumble at v3's own policy (one relax
 * pass a substep, 30 Hz contacts) beside v3 (docs/bench/V3.md).
 * prints: tumble SCENE STEPS MS_PER_STEP bodies B shapes S joints J pairs P
 * touching T awake A bytes N body_bytes BB contact_bytes CB relax R hash H (the
 * world's bytes, its body and contact parts per body and per contact, the
 * relax passes per substep over the timed steps (tb_profile.relax_pass_count;
 * v3 runs one), and the world hash after the last step: equal hashes, equal
 * results) */
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../../demos/scenes/scenes.h"

/* The scenes v3 builds with sleeping off. */
static int v3_sleeps(const char* name) {
  return strcmp(name, "large_pyramid") != 0 && strcmp(name, "many_pyramids") != 0 && strcmp(name, "joint_grid") != 0;
}

static double cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int usage(const char* program) {
  fprintf(stderr, "usage: %s SCENE [STEPS] [--relax-iterations N] [--contact-hertz F]\n", program);
  return 2;
}

int main(int argc, char** argv) {
  if (argc < 2) return usage(argv[0]);
  int steps_arg = 0, relax_iterations = 0;
  float contact_hertz = 0.0f;
  bool set_relax = false, set_hertz = false; /* else the defaults */
  for (int i = 2; i < argc; ++i) {
    if (strcmp(argv[i], "--relax-iterations") == 0 && i + 1 < argc)
      relax_iterations = atoi(argv[++i]), set_relax = true;
    else if (strcmp(argv[i], "--contact-hertz") == 0 && i + 1 < argc)
      contact_hertz = (float)atof(argv[++i]), set_hertz = true;
    else if (argv[i][0] != '-' && steps_arg == 0)
      steps_arg = atoi(argv[i]);
    else
      return usage(argv[0]);
  }
  /* pyramid_base_N: the catalogue builds large_pyramid at a scale, base 100 x scale */
  int base = 0;
  const char* name = argv[1];
  if (sscanf(argv[1], "pyramid_base_%d", &base) == 1) {
    if (base < 1 || base > 100) {
      fprintf(stderr, "%s: %s: the base is 1 to 100\n", argv[0], argv[1]);
      return 2;
    }
    name = "large_pyramid";
  }
  const tb_scene* sc = tb_scene_find(name);
  if (sc == NULL) {
    fprintf(stderr, "%s: no scene named %s\n", argv[0], argv[1]);
    return 2;
  }
  int steps = steps_arg > 0 ? steps_arg : sc->default_steps;
  if (steps < 2) steps = 2;
  tb_world_id world = tb_scene_create_world(sc);
  tb_world_def def = tb_default_world_def();
  if ((set_relax && tb_world_set_relax_iterations(world, relax_iterations) != TB_OK) ||
      (set_hertz && tb_world_set_contact_tuning(world, contact_hertz, def.contact_damping_ratio,
                                                def.contact_push_max_velocity) != TB_OK)) {
    fprintf(stderr, "%s: %s\n", argv[0], tb_last_error());
    return 2;
  }
  sc->build(world, base > 0 ? (float)base / 100.0f : 1.0f);
  if (!v3_sleeps(sc->name)) tb_world_enable_sleeping(world, false);
  if (sc->update != NULL) sc->update(world, 0);
  if (tb_world_step(world, 1.0f / 60.0f, 4) != TB_OK) {
    fprintf(stderr, "%s: step failed: %s\n", argv[0], tb_last_error());
    return 1;
  }
  long relax_passes = 0; /* the profile's counts are kept with its clock off */
  double t0 = cpu_seconds();
  for (int i = 1; i < steps; ++i) {
    if (sc->update != NULL) sc->update(world, i);
    if (tb_world_step(world, 1.0f / 60.0f, 4) != TB_OK) {
      fprintf(stderr, "%s: step %d failed: %s\n", argv[0], i, tb_last_error());
      return 1;
    }
    relax_passes += tb_world_get_profile(world).relax_pass_count;
  }
  double ms = 1e3 * (cpu_seconds() - t0) / (double)(steps - 1);
  tb_counts c = tb_world_get_counts(world);
  /* memory (issue 21): the world's bytes, and the bodies' and contacts'
   * parts per body and per contact (pairs: every contact, touching or not) */
  tb_memory_stats mem;
  if (tb_world_get_memory_stats(world, &mem) != TB_OK) {
    fprintf(stderr, "%s: memory stats: %s\n", argv[0], tb_last_error());
    return 1;
  }
  printf(
      "tumble %s %d %.4f bodies %d shapes %d joints %d pairs %d touching %d awake %d bytes %zu"
      " body_bytes %.0f contact_bytes %.0f relax %.2f hash %016" PRIx64 "\n",
      argv[1], steps, ms, c.body_count, c.shape_count, c.joint_count, c.contact_count, c.touching_count,
      c.awake_body_count, mem.total, c.body_count > 0 ? (double)mem.bodies / c.body_count : 0.0,
      c.contact_count > 0 ? (double)mem.contacts / c.contact_count : 0.0, (double)relax_passes / (4.0 * (steps - 1)),
      tb_world_hash(world));
  tb_destroy_world(world);
  return 0;
}
