/* Determinism of the stress scenes: every stress test's scene is built by
 * the same function its test uses (so with the test's settings, sleep
 * included), stepped for a fixed number of steps and its world hash printed.
 * The -O3 build runs each scene twice in-process and the two hashes must be
 * equal; `make stress` runs the -O0 build once (`--hashes-once`, as -O0 is
 * about 5 times slower) and compares its lines with the -O3 build's. */
#include <stdio.h>

#include "stress.h"

typedef struct hashed_scene {
  const char* name;
  int steps;
  tb_world_id (*make)(void);  /* the test's world, stepped `steps` times */
  uint64_t (*run)(int steps); /* instead of make: a test that changes its world as it steps */
} hashed_scene;

static tb_world_id stack_15(void) { return stress_new_stack(15); }
static tb_world_id stack_30(void) { return stress_new_stack(30); }
static tb_world_id pyramid_20(void) { return stress_new_pyramid(0.0f, 0.0f, 20, 0.5f); }
static tb_world_id pyramid_100(void) { return stress_new_pyramid(0.0f, 0.0f, 100, 0.5f); }
static tb_world_id mass_ratio_100(void) { return stress_new_mass_ratio(100.0f); }
static tb_world_id mass_ratio_400(void) { return stress_new_mass_ratio(400.0f); }
static tb_world_id mass_ratio_1000(void) { return stress_new_mass_ratio(1000.0f); }
/* mass_ratio_edge's scenes at its largest ratio, where they fail */
static tb_world_id heavy_on_light(void) { return stress_new_heavy_on_light(1e6f); }
static tb_world_id heavy_pendulum(void) { return stress_new_heavy_pendulum(1e6f); }
static tb_world_id spinner(void) { return stress_new_spinner(NULL, NULL); }
static tb_world_id pyramid_8km(void) { return stress_new_pyramid(8000.0f, 8000.0f, 20, 0.5f); }
static tb_world_id pyramid_65km(void) { return stress_new_pyramid(65000.0f, 65000.0f, 20, 0.5f); }
static tb_world_id tiny_boxes(void) { return stress_new_pyramid(0.0f, 0.0f, 10, 0.0125f); }
static tb_world_id large_boxes(void) { return stress_new_pyramid(0.0f, 0.0f, 10, 25.0f); }
static tb_world_id pileup_300(void) { return stress_new_pileup(300); }
static tb_world_id pileup_1000(void) { return stress_new_pileup(1000); }

/* Steps: each test's own run (30 s for the structures and mass ratios, 3 s
 * for the overlaps, 2 s for the bullets, 10 s for the spinner and the scale
 * pyramids), except where that would make the -O0 run too slow:
 * - pyramid_100 (about 70 ms a step at -O0): its first 5 s, by when its top
 *   has sunk to within 1 % of where it stays (at 2 s it was still bouncing);
 * - one_hour: its first minute, four turns of the drum with its load tumbling;
 * - pileup_1000: its first 10 steps, the 499,500 pairs and the start of the
 *   spreading, where its cost is (about 1 s a step at -O0);
 * - churn: its first 5,000 steps, 250 lifetimes of each of the 20 live bodies
 *   (every create and destroy path but the retiring of a slot, which takes
 *   65,535 reuses).
 * The scale test's origin run is pyramid_20's scene. */
static const hashed_scene k_scenes[] = {
    {"stack_15", 1800, stack_15, NULL},
    {"stack_30", 1800, stack_30, NULL},
    {"pyramid_20", 1800, pyramid_20, NULL},
    {"pyramid_100", 300, pyramid_100, NULL},
    {"card_house", 1800, stress_new_card_house, NULL},
    {"arch", 1800, stress_new_arch, NULL},
    {"mass_ratio_100", 1800, mass_ratio_100, NULL},
    {"mass_ratio_400", 1800, mass_ratio_400, NULL},
    {"mass_ratio_1000", 1800, mass_ratio_1000, NULL},
    {"ball_and_chain", 1800, stress_new_ball_and_chain, NULL},
    {"mass_ratio_edge_stack", 180, heavy_on_light, NULL},
    {"mass_ratio_edge_pendulum", 180, heavy_pendulum, NULL},
    {"overlap_boxes", 180, stress_new_overlap_boxes, NULL},
    {"overlap_circles", 180, stress_new_overlap_circles, NULL},
    {"pileup_300", 600, pileup_300, NULL},
    {"pileup_1000", 10, pileup_1000, NULL},
    {"bullets", 120, stress_new_bullets, NULL},
    {"spinner", 600, spinner, NULL},
    {"scale_offset_8km", 600, pyramid_8km, NULL},
    {"scale_offset_65km", 600, pyramid_65km, NULL},
    {"tiny_boxes", 600, tiny_boxes, NULL},
    {"large_boxes", 600, large_boxes, NULL},
    {"one_hour", 3600, stress_new_drum, NULL},
    {"churn", 5000, NULL, stress_churn_hash},
};

#define SCENE_COUNT ((int)(sizeof k_scenes / sizeof k_scenes[0]))

static uint64_t run(const hashed_scene* s) {
  if (s->run != NULL) return s->run(s->steps);
  tb_world_id w = s->make();
  for (int i = 0; i < s->steps; ++i)
    if (!stress_step(w)) break;
  uint64_t h = tb_world_hash(w);
  tb_destroy_world(w);
  return h;
}

bool stress_print_hashes(FILE* out, int runs) {
  bool same = true;
  for (int i = 0; i < SCENE_COUNT; ++i) {
    uint64_t a = run(&k_scenes[i]);
    uint64_t b = runs > 1 ? run(&k_scenes[i]) : a;
    if (a != b) {
      fprintf(stderr, "%s: two runs differ: %016llx, %016llx\n", k_scenes[i].name, (unsigned long long)a,
              (unsigned long long)b);
      same = false;
    }
    fprintf(out, "%s %016llx\n", k_scenes[i].name, (unsigned long long)a);
  }
  return same;
}
