/* The world: pools of bodies and shapes, settings, and the handle checks every
 * entry point goes through. */
#ifndef TB_WORLD_H
#define TB_WORLD_H

#include "body.h"
#include "error.h"
#include "pool.h"
#include "shape.h"

#define TB_MAX_WORLDS 128

typedef struct tb_world {
  uint16_t index;
  uint16_t generation;
  bool locked; /* inside tb_world_step: mutations are refused */
  tb_vec2 gravity;
  tb_integrator integrator;
  tb_force_field_fn* force_field;
  void* force_field_context;
  void* user_data;
  double time;
  int step_count;
  tb_pool bodies; /* of tb_body */
  tb_pool shapes; /* of tb_shape */
  char last_error[TB_ERROR_MESSAGE_CAPACITY];
} tb_world;

/* Resolve handles, recording an error that names fn when they are bad. */
tb_world* tb_world_get(tb_world_id id, const char* fn);
tb_body* tb_body_get(tb_body_id id, tb_world** world, const char* fn);
tb_shape* tb_shape_get(tb_shape_id id, tb_world** world, const char* fn);
/* The same, also refusing a world that is inside its step. */
tb_world* tb_world_get_unlocked(tb_world_id id, const char* fn);
tb_body* tb_body_get_unlocked(tb_body_id id, tb_world** world, const char* fn);
tb_shape* tb_shape_get_unlocked(tb_shape_id id, tb_world** world, const char* fn);

static inline tb_body* tb_body_at(const tb_world* w, int i) { return (tb_body*)tb_pool_at(&w->bodies, i); }
static inline tb_shape* tb_shape_at(const tb_world* w, int i) { return (tb_shape*)tb_pool_at(&w->shapes, i); }

tb_body_id tb_make_body_id(const tb_world* w, int index);
tb_shape_id tb_make_shape_id(const tb_world* w, int index);

/* Free motion of every simulated body over one step (motion.c). Bodies whose new
 * state is not finite keep their old state; returns how many did. */
int tb_integrate_bodies(tb_world* world, float time_step, int substeps);

#endif
