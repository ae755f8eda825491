/* The scene catalogue: one set of scenes shared by the demos, the dynamics
 * benchmark (tools/bench_dynamics.c) and the tests. Public tumble API only.
 *
 * Use: create a world from tb_default_world_def(), then call scene->build(world,
 * scale). Each build sets the world's gravity itself ((0, -10) everywhere but
 * smash, which has none) and creates every body; nothing else about the world is
 * changed. Step at 60 Hz with 4 substeps for scene->default_steps steps,
 * calling scene->update (when not NULL) before each step.
 *
 * scale in (0, 1] shrinks the six performance scenes for quick runs: every count
 * along a side (pyramid base, pyramids per row and column, grid sides, tumbler
 * grid) is multiplied by scale, so the body count goes as scale^2 (rain spawns
 * 2,000 scale^2 bodies). The structure scenes (vertical_stack ... bullet_block)
 * are small and ignore scale. A scale outside (0, 1] is taken as 1.
 *
 * Named bodies: a few bodies carry a tag, a static string, as user data (the
 * top box of a pyramid, the bullets, the heavy box ...; see scenes.c). Every
 * other body a scene creates has NULL user data. Find them with
 * tb_scene_find_body.
 *
 * tools/bench_dynamics_b2.cpp rebuilds the six performance scenes with Box2D
 * 2.4.1 from the same parameters: change both together. */
#ifndef TUMBLE_SCENES_H
#define TUMBLE_SCENES_H

#include <stdint.h>

#include "tumble.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tb_scene {
  const char* name;
  const char* description; /* one line */
  void (*build)(tb_world_id world, float scale);
  int default_steps; /* at 60 Hz */
  tb_aabb bounds;    /* where every body's origin should stay (full scale) */
  /* NULL, or called before each step with the index of the step about to be
   * taken (0, 1, ...): scenes that spawn bodies over time or drive motors. */
  void (*update)(tb_world_id world, int step);
  /* NULL (the camera fits bounds), or the tag of a body the camera follows. */
  const char* follow_tag;
} tb_scene;

/* All scenes: the six performance scenes first (large_pyramid, many_pyramids,
 * joint_grid, rain, smash, tumbler), then the structure scenes. */
const tb_scene* tb_scenes(int* count);
/* NULL when there is no scene of that name. */
const tb_scene* tb_scene_find(const char* name);
/* Whether the scene is one of the six the benchmark times. */
int tb_scene_is_performance(const tb_scene* scene);

/* The body whose user data is the tag (compared as a string), or the null
 * handle. Looks through every shape of the world: for setup and checks, not per
 * step. */
tb_body_id tb_scene_find_body(tb_world_id world, const char* tag);

/* Up to capacity of the world's bodies that have shapes, in creation order
 * (ascending handle index); returns how many there are (may exceed capacity). */
int tb_scene_collect_bodies(tb_world_id world, tb_body_id* out, int capacity);

/* Number of non-static bodies whose origin is outside the bounds. */
int tb_scene_count_outside(tb_world_id world, tb_aabb bounds);

/* FNV-1a (64 bit) over the bit patterns of every body's position (x, y),
 * angle, linear velocity (x, y) and angular velocity, in creation order; the
 * Box2D bench hashes the same six floats per body in creation order. */
uint64_t tb_scene_state_hash(tb_world_id world);

#ifdef __cplusplus
}
#endif

#endif /* TUMBLE_SCENES_H */
