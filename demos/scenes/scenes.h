/* The scene catalogue: one set of scenes shared by the demos, the dynamics
 * benchmark (tools/bench_dynamics.c) and the tests. Public tumble API only.
 *
 * Use: create the world with tb_scene_create_world(scene), which is
 * tb_default_world_def() changed by the scene's configure hook (only
 * one_way_platform has one: its pre-solve callback), then call
 * scene->build(world, scale). Each build sets the world's gravity itself
 * ((0, -10) everywhere but smash, which has none) and creates its bodies;
 * nothing else about the world is changed. Step at 60 Hz with 4 substeps for
 * scene->default_steps steps, calling scene->update (when not NULL) before
 * each step: some scenes spawn bodies or lodge bullets there.
 *
 * scale in (0, 1] shrinks the twelve performance scenes for quick runs: every
 * count along a side (pyramid base, pyramids per row and column, grid sides,
 * tumbler grid, rain's rows and columns) is multiplied by scale, so the body
 * count goes as scale^2 (rain_2000 spawns 2,000 scale^2 bodies, spinner 6,076
 * scale^2). The structure scenes (vertical_stack ... chain_100)
 * and the gallery scenes are small and ignore scale. A scale outside (0, 1] is
 * taken as 1.
 *
 * Named bodies: a few bodies carry a tag, a static string, as user data (the
 * top box of a pyramid, the bullets, the heavy box ...; see scenes.c and
 * gallery.c; shapes of a few static parts carry one too: "platform",
 * "sensor", "belt_upper", "belt_lower"). Every other body a scene creates has
 * NULL user data. Find bodies with tb_scene_find_body.
 *
 * The performance scenes are Box2D v3's ten benchmark scenes under v3's names,
 * built as v3 builds them (make bench-v3 times them beside v3), then
 * rain_2000 and tumbler_kinematic, the earlier forms of rain and tumbler.
 * tools/bench_dynamics_b2.cpp rebuilds six of them with Box2D 2.4.1
 * (large_pyramid, many_pyramids, joint_grid, rain_2000, smash,
 * tumbler_kinematic) from the same parameters: change both together. */
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
  /* NULL, or changes the world definition before the world is created, for
   * what only a definition can set (the one-way platform's pre-solve
   * callback). tb_scene_create_world applies it. */
  void (*configure)(tb_world_def* def);
} tb_scene;

/* All scenes: the twelve performance scenes first (v3's ten: compounds,
 * joint_grid, junkyard, large_pyramid, many_pyramids, rain, smash, spinner,
 * tumbler, washer; then rain_2000, tumbler_kinematic), then the gallery: the
 * structure scenes and the demo scenes of gallery.c (every scene that is not
 * a performance scene). */
const tb_scene* tb_scenes(int* count);
/* NULL when there is no scene of that name. */
const tb_scene* tb_scene_find(const char* name);
/* Whether the scene is one of the twelve performance scenes. */
int tb_scene_is_performance(const tb_scene* scene);

/* A world for the scene: tb_default_world_def() changed by scene->configure
 * (when not NULL). Build the scene in it next. The null handle on error. */
tb_world_id tb_scene_create_world(const tb_scene* scene);

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
