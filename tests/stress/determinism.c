/* Determinism of the stress scenes: each is built by the function its test
 * uses (so with the test's settings, sleep included), stepped for a fixed
 * number of steps and its world hash printed. The same program run twice
 * in-process must print the same lines, and `make stress` compares the -O0
 * build's lines with the -O2 build's. */
#include <stdio.h>
#include <string.h>

#include "stress.h"

typedef struct hashed_scene {
  const char* name;
  int steps;
  tb_world_id (*make)(void); /* the test's world, built as the test builds it */
} hashed_scene;

static tb_world_id stack_15(void) { return stress_new_stack(15); }
static tb_world_id stack_30(void) { return stress_new_stack(30); }
static tb_world_id pyramid_20(void) { return stress_new_pyramid(0.0f, 0.0f, 20, 0.5f); }
static tb_world_id pyramid_100(void) { return stress_new_pyramid(0.0f, 0.0f, 100, 0.5f); }
static tb_world_id pyramid_65km(void) { return stress_new_pyramid(65000.0f, 65000.0f, 20, 0.5f); }
static tb_world_id tiny_pyramid(void) { return stress_new_pyramid(0.0f, 0.0f, 10, 0.0125f); }
static tb_world_id large_pyramid(void) { return stress_new_pyramid(0.0f, 0.0f, 10, 25.0f); }
static tb_world_id mass_ratio_100(void) { return stress_new_mass_ratio(100.0f); }
static tb_world_id mass_ratio_400(void) { return stress_new_mass_ratio(400.0f); }
static tb_world_id mass_ratio_1000(void) { return stress_new_mass_ratio(1000.0f); }

/* Steps: 10 s for most, enough to settle, collapse or recover; the bullets'
 * 2 s; the base-100 pyramid 2 s to keep the -O0 build's run short. The
 * long-run scenes are checked by their own tests, not hashed here. */
static const hashed_scene k_scenes[] = {
    {"stack_15", 600, stack_15},
    {"stack_30", 600, stack_30},
    {"pyramid_20", 600, pyramid_20},
    {"pyramid_100", 120, pyramid_100},
    {"card_house", 600, stress_new_card_house},
    {"arch", 600, stress_new_arch},
    {"mass_ratio_100", 600, mass_ratio_100},
    {"mass_ratio_400", 600, mass_ratio_400},
    {"mass_ratio_1000", 600, mass_ratio_1000},
    {"ball_and_chain", 600, stress_new_ball_and_chain},
    {"overlap_boxes", 600, stress_new_overlap_boxes},
    {"overlap_circles", 600, stress_new_overlap_circles},
    {"bullets", 120, stress_new_bullets},
    {"pyramid_65km", 600, pyramid_65km},
    {"tiny_boxes", 600, tiny_pyramid},
    {"large_boxes", 600, large_pyramid},
};

#define SCENE_COUNT ((int)(sizeof k_scenes / sizeof k_scenes[0]))

static uint64_t run(const hashed_scene* s) {
  tb_world_id w = s->make();
  for (int i = 0; i < s->steps; ++i)
    if (!stress_step(w)) break;
  uint64_t h = tb_world_hash(w);
  tb_destroy_world(w);
  return h;
}

bool stress_print_hashes(FILE* out) {
  bool same = true;
  for (int i = 0; i < SCENE_COUNT; ++i) {
    uint64_t a = run(&k_scenes[i]), b = run(&k_scenes[i]);
    if (a != b) {
      fprintf(stderr, "%s: two runs differ: %016llx, %016llx\n", k_scenes[i].name, (unsigned long long)a,
              (unsigned long long)b);
      same = false;
    }
    fprintf(out, "%s %016llx\n", k_scenes[i].name, (unsigned long long)a);
  }
  return same;
}
