/* The world: pools of bodies and shapes, settings, and the handle checks every
 * entry point goes through. */
#ifndef TB_WORLD_H
#define TB_WORLD_H

#include "body.h"
#include "broad_phase.h"
#include "contact.h"
#include "error.h"
#include "joint.h"
#include "joint_tree.h"
#include "joint_wide.h"
#include "solver.h"
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
  uint32_t walk_stamp; /* tb_contacts_update's calls, 0 skipped on wrapping (tb_contact.walk_stamp) */
  tb_profile profile;  /* of the last step */
  tb_pool bodies;      /* of tb_body */
  tb_pool shapes;      /* of tb_shape */
  tb_pool contacts;    /* of tb_contact */
  tb_pool chains;      /* of tb_chain */
  tb_pool joints;      /* of tb_joint */
  tb_pool islands;     /* of tb_island: sleeping islands */
  tb_broad_phase broad_phase;
  float hit_event_threshold;
  tb_custom_filter_fn* custom_filter;
  void* custom_filter_context;
  tb_pre_solve_fn* pre_solve;
  void* pre_solve_context;
  tb_mix_fn* friction_mix;
  tb_mix_fn* restitution_mix;
  void* mix_context;
  /* mix results out of range in this step (the first one kept for the message) */
  int bad_mix_count;
  float bad_mix_value;
  const char* bad_mix_name;
  /* solver settings (tb_world_def) */
  float contact_hertz, contact_damping_ratio, contact_push_max_velocity;
  int relax_iterations;
  float joint_hertz, joint_damping_ratio;
  float restitution_threshold, maximum_linear_speed;
  bool enable_sleep, enable_continuous, enable_warm_starting;
  bool enable_profile; /* the profile's stage times are measured (tb_world_step) */
  /* the awake set: body indices; body->awake_index is the position here */
  int* awake;
  int awake_count, awake_capacity;
  /* per-step scratch, grown as needed and kept (no allocation in a steady step) */
  struct tb_solver_body* states;
  int state_capacity;
  void* motions; /* per awake body: gravity, force and damping terms of the step (solver.c) */
  int motion_capacity;
  int32_t* changed_in; /* per solver body: the relax pass that last moved it (relax_activity.h) */
  int changed_in_capacity;
  float* reach; /* per solver body: its max_extent */
  int reach_capacity;
  int* new_contact_bodies; /* moving bodies with new contacts to sort into their lists (contact.c) */
  int new_contact_body_count, new_contact_capacity;
  int* step_contacts; /* touching contacts the solver handles this step */
  int step_contact_count, step_contact_capacity;
  void* constraints; /* tb_contact_constraint (contact_solver.c) */
  int constraint_capacity;
  int* color_lanes; /* per colour: contacts, then the next lane (contact_solver.c) */
  int color_capacity;
  /* the blocks' layout (contact_solver.c: lay_out_blocks), kept while the step contacts are those it
   * was laid out for and no contact, awake body or joint link came or went (contact.c, island.c,
   * joint.c) */
  int32_t* lane_contacts; /* per lane of the blocks: its step contact, -1 for an unused lane */
  int lane_contact_capacity;
  int32_t* laid_out_contacts; /* the step contacts the layout is for */
  int laid_out_count, laid_out_capacity, laid_out_colors;
  bool layout_valid;
  uint8_t* contact_degree; /* per solver body: 0, 1 or 2 for more contacts or a joint (contact_solver.c) */
  int degree_capacity;
  void* wide; /* coloured blocks of four contacts */
  int wide_capacity, wide_count;
  int wide_fixed_from; /* the first block of contacts with a body that does not move (contact_solver.c) */
  void* deep_contacts; /* contacts with a point overlapping deeply this step (contact_solver.c) */
  int deep_capacity, deep_count;
  void* bounces; /* the points that bounce this step, for the restitution passes (contact_solver.c) */
  int bounce_capacity;
  float* push_velocities; /* per solver body: the push-out's (v.x, v.y, w, unused), momentum-free */
  int push_capacity;
  int* step_joints;
  int step_joint_count, step_joint_capacity;
  /* the step joints as collect_joints (solver.c) walked them, kept while the walk would find the
   * same: no body joined or left the awake set, no joint was linked or unlinked */
  int* walked_joints;
  int walked_joint_count, walked_joint_capacity;
  bool walked_joints_valid;
  struct tb_step_joint* step_joint_info; /* per step joint, in step order (joint.h) */
  int step_joint_info_capacity;
  int scalar_joint_count; /* the first ones of step_joints, solved one at a time; the rest in wide_joints */
  /* the last ones of step_joints: joints a joint tree solves whole (tb_joint_point_only), which
   * the passes leave alone (solver.c: set_apart_tree_joints) */
  int tree_joint_count;
  bool joints_one_at_a_time; /* tests' reference: joint_wide.c takes no joint (not in the public API) */
  bool contacts_four_lanes;  /* tests' reference: no eight-lane contact passes (contact_solver.c) */
  tb_joint_tree joint_tree;
  tb_wide_joints wide_joints;
  int* scratch; /* island search stack and marks */
  int scratch_capacity;
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
tb_joint* tb_joint_get(tb_joint_id id, tb_world** world, const char* fn);
tb_joint* tb_joint_get_unlocked(tb_joint_id id, tb_world** world, const char* fn);
struct tb_chain* tb_chain_get(tb_chain_id id, tb_world** world, const char* fn);
/* The same, also refusing a world that is inside its step. */
tb_world* tb_world_get_unlocked(tb_world_id id, const char* fn);
tb_body* tb_body_get_unlocked(tb_body_id id, tb_world** world, const char* fn);
tb_shape* tb_shape_get_unlocked(tb_shape_id id, tb_world** world, const char* fn);

static inline tb_body* tb_body_at(const tb_world* w, int i) { return (tb_body*)tb_pool_at(&w->bodies, i); }
static inline tb_shape* tb_shape_at(const tb_world* w, int i) { return (tb_shape*)tb_pool_at(&w->shapes, i); }
static inline tb_joint* tb_joint_at(const tb_world* w, int i) { return (tb_joint*)tb_pool_at(&w->joints, i); }

tb_body_id tb_make_body_id(const tb_world* w, int index);
tb_shape_id tb_make_shape_id(const tb_world* w, int index);
tb_joint_id tb_make_joint_id(const tb_world* w, int index);

/* Sleep and the awake set (island.c). Waking a body wakes its sleeping island;
 * a dynamic or kinematic body joins the awake set, a static one does nothing. */
void tb_wake_body(tb_world* w, int body);
/* Takes a body out of the awake set or its sleeping island (before it is
 * destroyed, disabled or made static). */
void tb_remove_body_from_sets(tb_world* w, int body);
/* Adds a newly created or enabled non-static body to the awake set (awake) or
 * to a fresh sleeping island of its own (asleep). false when out of memory. */
bool tb_add_body_to_sets(tb_world* w, int body, bool awake);
void tb_wake_all(tb_world* w);
/* After the solver: islands that rested for TB_TIME_TO_SLEEP fall asleep. */
void tb_update_sleep(tb_world* w);
/* Puts the island of an awake body to sleep now (tb_body_set_awake(false)). */
void tb_sleep_island_of(tb_world* w, int body);
void tb_islands_free(tb_world* w);
size_t tb_island_size(void);

/* Chains of a body go with it (chain.c). */
void tb_chains_destroy_of_body(tb_world* w, int body);
/* Frees what each live chain owns; the chain pool itself goes with the world. */
void tb_chains_free(tb_world* w);

/* Shape AABBs and broad-phase proxies follow a body that moved. enlarge: the
 * proxies keep their place in the tree and tb_broad_phase_rebuild joins them
 * later (the step moves many at once); else each is re-inserted. */
void tb_body_update_proxies(tb_world* world, int body, tb_vec2 displacement, bool enlarge);

/* Free motion of one dynamic body over a step with the world's integrator,
 * within the step's speed caps (motion.c). false when a state is not finite
 * (the body keeps its old one). */
bool tb_integrate_free_body(tb_world* world, int body, const struct tb_step_context* ctx);
/* The soft-step solver (solver.c): moves the awake bodies over one step;
 * returns how many got a non-finite state and were left as they were. */
int tb_solve(tb_world* world, float time_step, int substeps);
/* The contact constraints of a step (contact_solver.c): prepare (false when
 * out of memory), then per substep warm start and solve, then finish
 * (restitution, impulses kept for the next step). */
bool tb_contact_solver_prepare(tb_world* w, struct tb_step_context* ctx);
void tb_contact_solver_warm_start(tb_world* w, struct tb_step_context* ctx);
/* Whether the contact passes run eight lanes at a time on this processor (AVX2). */
bool tb_contact_solver_eight_lanes(void);
void tb_contact_solver_reset(tb_world* w);
/* One pass over the contacts, in their colour order or (backward) the
 * reverse; returns the largest normal speed change a point got in a relax
 * pass (m/s; 0 for a biased pass). */
float tb_contact_solver_solve(tb_world* w, struct tb_step_context* ctx, bool use_bias, bool backward);
/* Pushes deeply overlapping points apart through momentum-free push
 * velocities (ctx->push_velocities, NULL when no point is deep) that move the
 * bodies in the next position update and are then dropped. */
void tb_contact_solver_push_out(tb_world* w, struct tb_step_context* ctx);
void tb_contact_solver_finish(tb_world* w, struct tb_step_context* ctx);
/* Continuous collision (continuous.c): fast bodies and bullets stop at their
 * first time of impact. Returns the number of bodies swept. */
int tb_solve_continuous(tb_world* world);

/* Memory (world.c, and each part's own file for its private types). */
int tb_world_count(void);
bool tb_world_histories_move(tb_alloc_fn* alloc, tb_free_fn* free_fn, void* context);
size_t tb_chains_bytes(const tb_world* w);
size_t tb_solver_bytes(const tb_world* w);
size_t tb_contact_solver_bytes(const tb_world* w);
/* Free the step scratch of solver.c and contact_solver.c. */
void tb_solver_free(tb_world* w);
void tb_contact_solver_free(tb_world* w);

#endif
