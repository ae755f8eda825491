/* The world: pools of bodies and shapes, settings, and the handle checks every
 * entry point goes through. */
#ifndef TB_WORLD_H
#define TB_WORLD_H

#include "body.h"
#include "broad_phase.h"
#include "contact.h"
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
  tb_pool bodies;   /* of tb_body */
  tb_pool shapes;   /* of tb_shape */
  tb_pool contacts; /* of tb_contact */
  tb_pool chains;   /* of tb_chain */
  tb_broad_phase broad_phase;
  float hit_event_threshold;
  tb_custom_filter_fn* custom_filter;
  void* custom_filter_context;
  tb_pre_solve_fn* pre_solve;
  void* pre_solve_context;
  tb_mix_fn* friction_mix;
  tb_mix_fn* restitution_mix;
  void* mix_context;
  /* events of the last step (cleared when the next one starts) */
  tb_contact_begin_event* begin_events;
  tb_contact_end_event* end_events;
  tb_contact_hit_event* hit_events;
  tb_sensor_event* sensor_begin_events;
  tb_sensor_event* sensor_end_events;
  int begin_count, begin_capacity, end_count, end_capacity, hit_count, hit_capacity;
  int sensor_begin_count, sensor_begin_capacity, sensor_end_count, sensor_end_capacity;
  char last_error[TB_ERROR_MESSAGE_CAPACITY];
} tb_world;

/* Resolve handles, recording an error that names fn when they are bad. */
tb_world* tb_world_get(tb_world_id id, const char* fn);
tb_body* tb_body_get(tb_body_id id, tb_world** world, const char* fn);
tb_shape* tb_shape_get(tb_shape_id id, tb_world** world, const char* fn);
struct tb_chain* tb_chain_get(tb_chain_id id, tb_world** world, const char* fn);
/* The same, also refusing a world that is inside its step. */
tb_world* tb_world_get_unlocked(tb_world_id id, const char* fn);
tb_body* tb_body_get_unlocked(tb_body_id id, tb_world** world, const char* fn);
tb_shape* tb_shape_get_unlocked(tb_shape_id id, tb_world** world, const char* fn);

static inline tb_body* tb_body_at(const tb_world* w, int i) { return (tb_body*)tb_pool_at(&w->bodies, i); }
static inline tb_shape* tb_shape_at(const tb_world* w, int i) { return (tb_shape*)tb_pool_at(&w->shapes, i); }

tb_body_id tb_make_body_id(const tb_world* w, int index);
tb_shape_id tb_make_shape_id(const tb_world* w, int index);

/* Chains of a body go with it (chain.c). */
void tb_chains_destroy_of_body(tb_world* w, int body);
void tb_chains_free(tb_world* w);

/* Shape AABBs and broad-phase proxies follow a body that moved. */
void tb_body_update_proxies(tb_world* world, int body, tb_vec2 displacement);

/* Free motion of every simulated body over one step (motion.c). Bodies whose new
 * state is not finite keep their old state; returns how many did. */
int tb_integrate_bodies(tb_world* world, float time_step, int substeps);

#endif
