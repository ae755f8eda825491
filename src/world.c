/* Worlds: creation, settings, the step, and handle resolution. */
#include "world.h"

#include <stdlib.h>
#include <string.h>

#include "chain.h"
#include "math_internal.h"
#include "memory.h"
#include "timer.h"
#include "units.h"

/* Worlds live in a fixed table so that a world handle can be checked without
 * touching freed memory. A slot's generation counts the worlds it held; one
 * whose generation would wrap is retired, so an old world handle never matches
 * a new world. Object handles carry the world slot but not its generation: the
 * pools of a slot's next world start where the last one's left off. */
static tb_world* worlds[TB_MAX_WORLDS];
static uint16_t world_generations[TB_MAX_WORLDS];
static bool world_retired[TB_MAX_WORLDS];
enum { HISTORY_BODIES, HISTORY_SHAPES, HISTORY_CHAINS, HISTORY_JOINTS, HISTORY_POOLS };
static tb_pool_history handle_history[TB_MAX_WORLDS][HISTORY_POOLS];

static tb_pool* handle_pool(tb_world* w, int which) {
  return which == HISTORY_BODIES   ? &w->bodies
         : which == HISTORY_SHAPES ? &w->shapes
         : which == HISTORY_CHAINS ? &w->chains
                                   : &w->joints;
}

tb_world_def tb_default_world_def(void) {
  /* lengths and speeds in the length units (tb_set_length_units_per_meter) */
  return (tb_world_def){.gravity = {0.0f, tb_meters(-10.0f)},
                        .integrator = TB_INTEGRATOR_MIDPOINT,
                        .hit_event_threshold = tb_meters(1.0f),
                        .contact_hertz = 120.0f,
                        .contact_damping_ratio = 10.0f,
                        .contact_push_max_velocity = tb_meters(3.0f),
                        .relax_iterations = 8,
                        .joint_hertz = 60.0f,
                        .joint_damping_ratio = 2.0f,
                        .restitution_threshold = tb_meters(1.0f),
                        .maximum_linear_speed = tb_meters(1000.0f),
                        .enable_sleep = true,
                        .enable_continuous = true,
                        .enable_warm_starting = true};
}

/* names[] are the arguments as the caller spells them (a def field or a
 * setter parameter), so the message names what to fix. */
static tb_result check_contact_tuning(tb_world* w, const char* fn, const char* const names[3], float hertz, float zeta,
                                      float push) {
  tb_result r = tb_check_positive(w, fn, names[0], hertz);
  if (r == TB_OK) r = tb_check_non_negative(w, fn, names[1], zeta);
  if (r == TB_OK) r = tb_check_non_negative(w, fn, names[2], push);
  return r;
}
static tb_result check_joint_tuning(tb_world* w, const char* fn, const char* const names[2], float hertz, float zeta) {
  tb_result r = tb_check_positive(w, fn, names[0], hertz);
  if (r == TB_OK) r = tb_check_non_negative(w, fn, names[1], zeta);
  return r;
}
static const char* const def_contact_names[3] = {"def->contact_hertz", "def->contact_damping_ratio",
                                                 "def->contact_push_max_velocity"};
static const char* const def_joint_names[2] = {"def->joint_hertz", "def->joint_damping_ratio"};
static const char* const setter_contact_names[3] = {"hertz", "damping_ratio", "push_max_velocity"};
static const char* const setter_joint_names[2] = {"hertz", "damping_ratio"};

static tb_result check_relax_iterations(tb_world* w, const char* fn, const char* name, int n) {
  if (n < 1 || n > TB_MAX_RELAX_ITERATIONS)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %d must be in 1..%d", fn, name, n, TB_MAX_RELAX_ITERATIONS);
  return TB_OK;
}

static tb_result check_maximum_linear_speed(tb_world* w, const char* fn, const char* name, float speed) {
  if (!(speed > 0.0f && speed <= tb_units.max_speed)) /* NaN fails too */
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be > 0 and at most TB_MAX_SPEED (%g units/s)", fn,
                   name, (double)speed, (double)tb_units.max_speed);
  return TB_OK;
}

static tb_result check_integrator(tb_world* w, const char* fn, tb_integrator in) {
  if ((int)in < (int)TB_INTEGRATOR_SEMI_IMPLICIT_EULER || (int)in > (int)TB_INTEGRATOR_RK4)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: integrator %d is not a tb_integrator", fn, (int)in);
  return TB_OK;
}

tb_world_id tb_create_world(const tb_world_def* def) {
  const tb_world_id null_id = {0, 0};
  if (def == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_create_world: def is NULL");
    return null_id;
  }
  if (tb_check_gravity(NULL, "tb_create_world", "def->gravity", def->gravity) != TB_OK) return null_id;
  if (check_integrator(NULL, "tb_create_world", def->integrator) != TB_OK) return null_id;
  if (check_contact_tuning(NULL, "tb_create_world", def_contact_names, def->contact_hertz, def->contact_damping_ratio,
                           def->contact_push_max_velocity) != TB_OK ||
      check_joint_tuning(NULL, "tb_create_world", def_joint_names, def->joint_hertz, def->joint_damping_ratio) !=
          TB_OK ||
      tb_check_non_negative(NULL, "tb_create_world", "def->restitution_threshold", def->restitution_threshold) !=
          TB_OK ||
      check_relax_iterations(NULL, "tb_create_world", "def->relax_iterations", def->relax_iterations) != TB_OK ||
      check_maximum_linear_speed(NULL, "tb_create_world", "def->maximum_linear_speed", def->maximum_linear_speed) !=
          TB_OK)
    return null_id;
  if (!tb_value_ok(def->hit_event_threshold) || def->hit_event_threshold < 0.0f) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_create_world: def->hit_event_threshold = %g must be >= 0 and finite",
            (double)def->hit_event_threshold);
    return null_id;
  }
  int slot = -1, retired = 0;
  for (int i = 0; i < TB_MAX_WORLDS && slot < 0; ++i) {
    retired += world_retired[i];
    if (worlds[i] == NULL && !world_retired[i]) slot = i;
  }
  if (slot < 0) {
    tb_fail(NULL, TB_ERR_CAPACITY,
            "tb_create_world: all %d world slots are in use or retired (%d retired: each holds 65,535 worlds in turn)",
            TB_MAX_WORLDS, retired);
    return null_id;
  }
  tb_world* w = tb_mem_alloc(sizeof *w);
  if (w == NULL) {
    tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "tb_create_world: no memory");
    return null_id;
  }
  memset(w, 0, sizeof *w);
  w->index = (uint16_t)slot;
  w->generation = world_generations[slot];
  w->gravity = def->gravity;
  w->integrator = def->integrator;
  w->force_field = def->force_field;
  w->force_field_context = def->force_field_context;
  w->user_data = def->user_data;
  w->hit_event_threshold = def->hit_event_threshold;
  w->custom_filter = def->custom_filter;
  w->custom_filter_context = def->custom_filter_context;
  w->pre_solve = def->pre_solve;
  w->pre_solve_context = def->pre_solve_context;
  w->friction_mix = def->friction_mix;
  w->restitution_mix = def->restitution_mix;
  w->mix_context = def->mix_context;
  tb_pool_init(&w->bodies, sizeof(tb_body));
  tb_pool_init(&w->shapes, sizeof(tb_shape));
  tb_pool_init(&w->contacts, sizeof(tb_contact));
  tb_pool_init(&w->chains, sizeof(tb_chain));
  tb_pool_init(&w->joints, sizeof(tb_joint));
  tb_pool_init(&w->islands, tb_island_size());
  w->contact_hertz = def->contact_hertz;
  w->contact_damping_ratio = def->contact_damping_ratio;
  w->contact_push_max_velocity = def->contact_push_max_velocity;
  w->relax_iterations = def->relax_iterations;
  w->joint_hertz = def->joint_hertz;
  w->joint_damping_ratio = def->joint_damping_ratio;
  w->restitution_threshold = def->restitution_threshold;
  w->maximum_linear_speed = def->maximum_linear_speed;
  w->enable_sleep = def->enable_sleep;
  w->enable_continuous = def->enable_continuous;
  w->enable_warm_starting = def->enable_warm_starting;
  w->enable_profile = def->enable_profile;
  if (tb_broad_phase_init(&w->broad_phase) != TB_OK) {
    tb_broad_phase_free(&w->broad_phase);
    tb_mem_free(w, sizeof *w);
    tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "tb_create_world: no memory");
    return null_id;
  }
  /* last: nothing can fail after the history moved in */
  for (int k = 0; k < HISTORY_POOLS; ++k) tb_pool_inherit(handle_pool(w, k), &handle_history[slot][k]);
  worlds[slot] = w;
  return (tb_world_id){(uint16_t)(slot + 1), w->generation};
}

tb_world* tb_world_get(tb_world_id id, const char* fn) {
  int slot = (int)id.index1 - 1;
  if (slot < 0 || slot >= TB_MAX_WORLDS) {
    tb_fail(NULL, TB_ERR_STALE_HANDLE, "%s: the world handle is null or invalid", fn);
    return NULL;
  }
  tb_world* w = worlds[slot];
  if (w == NULL || w->generation != id.generation) {
    tb_fail(NULL, TB_ERR_STALE_HANDLE, "%s: the world was destroyed", fn);
    return NULL;
  }
  return w;
}

tb_world* tb_world_get_unlocked(tb_world_id id, const char* fn) {
  tb_world* w = tb_world_get(id, fn);
  if (w != NULL && w->locked) {
    tb_fail(w, TB_ERR_LOCKED, "%s: the world is locked (inside tb_world_step, or a query or draw callback)", fn);
    return NULL;
  }
  return w;
}

/* Shared checks of body and shape handles: the world, then slot and generation.
 * fn == NULL resolves quietly (for the *_is_valid queries). */
typedef enum handle_kind { BODY, SHAPE, CHAIN, JOINT } handle_kind;

static inline void* resolve(int32_t index1, uint16_t world0, uint16_t gen, handle_kind kind, tb_world** out,
                            const char* fn, bool unlocked) {
  const char* what = kind == SHAPE ? "shape" : kind == CHAIN ? "chain" : kind == JOINT ? "joint" : "body";
  if (index1 <= 0 || world0 >= TB_MAX_WORLDS || worlds[world0] == NULL) {
    if (fn != NULL)
      tb_fail(NULL, TB_ERR_STALE_HANDLE, "%s: the %s handle is null, or its world was destroyed", fn, what);
    return NULL;
  }
  tb_world* w = worlds[world0];
  tb_pool* pool = kind == SHAPE ? &w->shapes : kind == CHAIN ? &w->chains : kind == JOINT ? &w->joints : &w->bodies;
  int index = index1 - 1;
  if (!tb_pool_alive(pool, index) || pool->generations[index] != gen) {
    if (fn != NULL) tb_fail(w, TB_ERR_STALE_HANDLE, "%s: the %s was destroyed (stale handle)", fn, what);
    return NULL;
  }
  if (unlocked && w->locked) {
    tb_fail(w, TB_ERR_LOCKED, "%s: the world is locked (inside tb_world_step, or a query or draw callback)", fn);
    return NULL;
  }
  if (out != NULL) *out = w;
  return tb_pool_at(pool, index);
}

tb_body* tb_body_get(tb_body_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, BODY, w, fn, false);
}
tb_shape* tb_shape_get(tb_shape_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, SHAPE, w, fn, false);
}
struct tb_chain* tb_chain_get(tb_chain_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, CHAIN, w, fn, false);
}
tb_joint* tb_joint_get(tb_joint_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, JOINT, w, fn, false);
}
tb_joint* tb_joint_get_unlocked(tb_joint_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, JOINT, w, fn, true);
}
tb_body* tb_body_get_unlocked(tb_body_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, BODY, w, fn, true);
}
tb_shape* tb_shape_get_unlocked(tb_shape_id id, tb_world** w, const char* fn) {
  return resolve(id.index1, id.world0, id.generation, SHAPE, w, fn, true);
}

tb_body_id tb_make_body_id(const tb_world* w, int index) {
  return (tb_body_id){index + 1, w->index, w->bodies.generations[index]};
}
tb_shape_id tb_make_shape_id(const tb_world* w, int index) {
  return (tb_shape_id){index + 1, w->index, w->shapes.generations[index]};
}
tb_joint_id tb_make_joint_id(const tb_world* w, int index) {
  return (tb_joint_id){index + 1, w->index, w->joints.generations[index]};
}

tb_result tb_destroy_world(tb_world_id id) {
  tb_world* w = tb_world_get_unlocked(id, "tb_destroy_world");
  if (w == NULL) return tb_last_result();
  int slot = w->index;
  worlds[slot] = NULL;
  tb_chains_free(w);
  bool histories_kept = true;
  for (int k = 0; k < HISTORY_POOLS; ++k)
    histories_kept &= tb_pool_end_life(handle_pool(w, k), &handle_history[slot][k]);
  if (world_generations[slot] == UINT16_MAX || !histories_kept) {
    world_retired[slot] = true;
    for (int k = 0; k < HISTORY_POOLS; ++k) tb_pool_history_free(&handle_history[slot][k]);
  } else {
    world_generations[slot] += 1;
  }
  tb_pool_free(&w->contacts);
  tb_islands_free(w);
  tb_mem_free(w->awake, (size_t)w->awake_capacity * sizeof *w->awake);
  tb_solver_free(w);
  tb_contact_solver_free(w);
  tb_mem_free(w->new_contact_bodies, (size_t)w->new_contact_capacity * sizeof *w->new_contact_bodies);
  tb_mem_free(w->step_contacts, (size_t)w->step_contact_capacity * sizeof *w->step_contacts);
  tb_mem_free(w->step_joints, (size_t)w->step_joint_capacity * sizeof *w->step_joints);
  tb_mem_free(w->walked_joints, (size_t)w->walked_joint_capacity * sizeof *w->walked_joints);
  tb_mem_free(w->step_joint_info, (size_t)w->step_joint_info_capacity * sizeof *w->step_joint_info);
  tb_joint_tree_free(&w->joint_tree);
  tb_wide_joints_free(&w->wide_joints);
  tb_mem_free(w->scratch, (size_t)w->scratch_capacity * sizeof *w->scratch);
  tb_broad_phase_free(&w->broad_phase);
  tb_mem_free(w->begin_events, (size_t)w->begin_capacity * sizeof *w->begin_events);
  tb_mem_free(w->end_events, (size_t)w->end_capacity * sizeof *w->end_events);
  tb_mem_free(w->hit_events, (size_t)w->hit_capacity * sizeof *w->hit_events);
  tb_mem_free(w->sensor_begin_events, (size_t)w->sensor_begin_capacity * sizeof *w->sensor_begin_events);
  tb_mem_free(w->sensor_end_events, (size_t)w->sensor_end_capacity * sizeof *w->sensor_end_events);
  tb_mem_free(w, sizeof *w);
  return TB_OK;
}

bool tb_world_is_valid(tb_world_id id) {
  int slot = (int)id.index1 - 1;
  return slot >= 0 && slot < TB_MAX_WORLDS && worlds[slot] != NULL && worlds[slot]->generation == id.generation;
}

/* A stage boundary of the profile: the clock while the profile is on, 0 when
 * it is off (a read costs 25 ns, and a step reads it seven times). */
static double stage_clock(const tb_world* w) { return w->enable_profile ? tb_clock_ms() : 0.0; }

tb_result tb_world_step(tb_world_id id, float time_step, int substeps) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_step");
  if (w == NULL) return tb_last_result();
  if (!isfinite(time_step) || time_step <= 0.0f || time_step > TB_MAX_TIME_STEP)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT,
                   "tb_world_step: time_step = %g must be in (0, TB_MAX_TIME_STEP = %g] seconds (longer steps are "
                   "not stable: take several per frame)",
                   (double)time_step, (double)TB_MAX_TIME_STEP);
  if (substeps < 1 || substeps > 64)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "tb_world_step: substeps = %d must be in 1..64", substeps);
  if (!(time_step / (float)substeps >= TB_MIN_SUBSTEP))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT,
                   "tb_world_step: time_step = %g s in %d substeps is too short: a substep below TB_MIN_SUBSTEP "
                   "(%g s) has a reciprocal the solver cannot use (it overflows, or turns distances into speeds "
                   "beyond TB_MAX_VALUE)",
                   (double)time_step, substeps, (double)TB_MIN_SUBSTEP);
  w->locked = true;
  w->begin_count = w->end_count = w->hit_count = 0;
  w->sensor_begin_count = w->sensor_end_count = 0;
  w->bad_mix_count = 0;
  unsigned failures_before = tb_mem_failure_count();
  tb_profile* p = &w->profile;
  double t0 = stage_clock(w);
  int pairs_before = w->contacts.count;
  tb_broad_phase_update_pairs(w); /* pairs of the proxies that moved last step */
  p->new_pair_count = w->contacts.count - pairs_before;
  double t1 = stage_clock(w);
  tb_contacts_update(w); /* manifolds at the start of the step; events; wake-ups */
  double t2 = stage_clock(w);
  p->relax_pass_count = 0; /* (tb_solve counts them) */
  int bad = tb_solve(w, time_step, substeps);
  p->awake_body_count = w->awake_count; /* before sleep removes any */
  p->awake_contact_count = w->step_contact_count;
  p->awake_joint_count = w->step_joint_count;
  double t3 = stage_clock(w);
  p->continuous_count = w->enable_continuous ? tb_solve_continuous(w) : 0;
  double t4 = stage_clock(w);
  /* Shapes follow the bodies that moved. Their fat boxes stretch a quarter of
   * the way along the motion predicted for the next step (v dt / 4). The whole
   * way, as before, more than doubled the pairs of a churning pile (spinner:
   * 44,600 against 25,000 at a quarter, Box2D v3 23,000); no stretch at all
   * (20,000) left pileup_1000's bodies deeper than their contact forces
   * explain (6.4 mm, against 3.7 at a quarter and a 5 mm bound), in every
   * margin tried (broad_phase.c: shape_margin). A body that touched nothing
   * this step (no contact in the solver: in flight) moves as predicted, and
   * its boxes stretch the whole way: at a quarter, balls in flight at 3 m/s
   * left their boxes every step and were re-inserted and paired again
   * (elastic_balls: 8.7% of its instructions). The stretch is capped at the
   * shape's margin (tb_broad_phase_move_proxy). */
  for (int i = 0; i < w->awake_count; ++i) {
    int index = w->awake[i];
    tb_body_keep_in_world(tb_body_at(w, index));
    /* (the solver's contact count, in awake order; a step the solver skipped
     * for want of memory leaves the last one's) */
    bool in_flight = i < w->degree_capacity && w->contact_degree[i] == 0;
    float ahead = in_flight ? 1.0f : 0.25f;
    tb_body_update_proxies(w, index, tb_scale(ahead * time_step, tb_body_at(w, index)->linear_velocity), true);
  }
  tb_broad_phase_rebuild(w);
  double t5 = stage_clock(w);
  tb_update_sleep(w);
  double t6 = stage_clock(w);
  p->broad_phase = (float)((t1 - t0) + (t5 - t4));
  p->narrow_phase = (float)(t2 - t1);
  p->solver = (float)(t3 - t2);
  p->continuous = (float)(t4 - t3);
  p->islands = (float)(t6 - t5);
  p->step = (float)(t6 - t0);
  p->pair_count = w->contacts.count;
  w->locked = false;
  w->time += time_step;
  w->step_count += 1;
  unsigned failures = tb_mem_failure_count() - failures_before;
  if (failures > 0)
    return tb_fail(w, TB_ERR_OUT_OF_MEMORY,
                   "tb_world_step: %u allocations failed in the step; the world is consistent, what they were for was "
                   "skipped (new contacts are found again later, events dropped, or the solve waits for the next step)",
                   failures);
  if (bad > 0)
    return tb_fail(w, TB_ERR_NUMERIC,
                   "tb_world_step: %d bodies got a non-finite state (from a force or the force field) and were "
                   "left as they were before the step",
                   bad);
  if (w->bad_mix_count > 0)
    return tb_fail(w, TB_ERR_NUMERIC,
                   "tb_world_step: the world's %s returned %g, outside its range, for %d new contacts; they use the "
                   "default rule instead",
                   w->bad_mix_name, (double)w->bad_mix_value, w->bad_mix_count);
  return TB_OK;
}

tb_result tb_world_set_gravity(tb_world_id id, tb_vec2 gravity) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_set_gravity");
  if (w == NULL) return tb_last_result();
  if (tb_check_gravity(w, "tb_world_set_gravity", "gravity", gravity) != TB_OK) return tb_last_result();
  w->gravity = gravity;
  return TB_OK;
}

tb_vec2 tb_world_get_gravity(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_gravity");
  return w != NULL ? w->gravity : (tb_vec2){0.0f, 0.0f};
}

tb_result tb_world_set_integrator(tb_world_id id, tb_integrator integrator) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_set_integrator");
  if (w == NULL) return tb_last_result();
  tb_result r = check_integrator(w, "tb_world_set_integrator", integrator);
  if (r == TB_OK) w->integrator = integrator;
  return r;
}

tb_integrator tb_world_get_integrator(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_integrator");
  return w != NULL ? w->integrator : TB_INTEGRATOR_SEMI_IMPLICIT_EULER;
}

tb_result tb_world_set_force_field(tb_world_id id, tb_force_field_fn* fn, void* context) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_set_force_field");
  if (w == NULL) return tb_last_result();
  w->force_field = fn;
  w->force_field_context = context;
  return TB_OK;
}

tb_result tb_world_set_pre_solve(tb_world_id id, tb_pre_solve_fn* fn, void* context) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_set_pre_solve");
  if (w == NULL) return tb_last_result();
  w->pre_solve = fn;
  w->pre_solve_context = context;
  return TB_OK;
}

tb_result tb_world_enable_sleeping(tb_world_id id, bool enable) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_enable_sleeping");
  if (w == NULL) return tb_last_result();
  w->enable_sleep = enable;
  if (!enable) tb_wake_all(w);
  return TB_OK;
}

bool tb_world_is_sleeping_enabled(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_is_sleeping_enabled");
  return w != NULL && w->enable_sleep;
}

tb_result tb_world_enable_profile(tb_world_id id, bool enable) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_enable_profile");
  if (w == NULL) return tb_last_result();
  w->enable_profile = enable;
  return TB_OK;
}

bool tb_world_is_profile_enabled(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_is_profile_enabled");
  return w != NULL && w->enable_profile;
}

tb_result tb_world_enable_continuous(tb_world_id id, bool enable) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_enable_continuous");
  if (w == NULL) return tb_last_result();
  w->enable_continuous = enable;
  return TB_OK;
}

bool tb_world_is_continuous_enabled(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_is_continuous_enabled");
  return w != NULL && w->enable_continuous;
}

tb_result tb_world_enable_warm_starting(tb_world_id id, bool enable) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_enable_warm_starting");
  if (w == NULL) return tb_last_result();
  w->enable_warm_starting = enable;
  return TB_OK;
}

tb_result tb_world_set_contact_tuning(tb_world_id id, float hertz, float damping_ratio, float push_max_velocity) {
  const char* fn = "tb_world_set_contact_tuning";
  tb_world* w = tb_world_get_unlocked(id, fn);
  if (w == NULL) return tb_last_result();
  tb_result r = check_contact_tuning(w, fn, setter_contact_names, hertz, damping_ratio, push_max_velocity);
  if (r != TB_OK) return r;
  w->contact_hertz = hertz;
  w->contact_damping_ratio = damping_ratio;
  w->contact_push_max_velocity = push_max_velocity;
  return TB_OK;
}

tb_result tb_world_set_relax_iterations(tb_world_id id, int iterations) {
  const char* fn = "tb_world_set_relax_iterations";
  tb_world* w = tb_world_get_unlocked(id, fn);
  if (w == NULL) return tb_last_result();
  tb_result r = check_relax_iterations(w, fn, "iterations", iterations);
  if (r == TB_OK) w->relax_iterations = iterations;
  return r;
}

int tb_world_get_relax_iterations(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_relax_iterations");
  return w != NULL ? w->relax_iterations : 0;
}

tb_result tb_world_set_joint_tuning(tb_world_id id, float hertz, float damping_ratio) {
  const char* fn = "tb_world_set_joint_tuning";
  tb_world* w = tb_world_get_unlocked(id, fn);
  if (w == NULL) return tb_last_result();
  tb_result r = check_joint_tuning(w, fn, setter_joint_names, hertz, damping_ratio);
  if (r != TB_OK) return r;
  w->joint_hertz = hertz;
  w->joint_damping_ratio = damping_ratio;
  return TB_OK;
}

tb_result tb_world_set_restitution_threshold(tb_world_id id, float speed) {
  const char* fn = "tb_world_set_restitution_threshold";
  tb_world* w = tb_world_get_unlocked(id, fn);
  if (w == NULL) return tb_last_result();
  tb_result r = tb_check_non_negative(w, fn, "speed", speed);
  if (r == TB_OK) w->restitution_threshold = speed;
  return r;
}

tb_result tb_world_set_maximum_linear_speed(tb_world_id id, float speed) {
  const char* fn = "tb_world_set_maximum_linear_speed";
  tb_world* w = tb_world_get_unlocked(id, fn);
  if (w == NULL) return tb_last_result();
  tb_result r = check_maximum_linear_speed(w, fn, "speed", speed);
  if (r == TB_OK) w->maximum_linear_speed = speed;
  return r;
}

double tb_world_get_time(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_time");
  return w != NULL ? w->time : 0.0;
}

void* tb_world_get_user_data(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_user_data");
  return w != NULL ? w->user_data : NULL;
}

tb_result tb_world_set_user_data(tb_world_id id, void* user_data) {
  tb_world* w = tb_world_get_unlocked(id, "tb_world_set_user_data");
  if (w == NULL) return tb_last_result();
  w->user_data = user_data;
  return TB_OK;
}

tb_counts tb_world_get_counts(tb_world_id id) {
  tb_counts c = {0};
  tb_world* w = tb_world_get(id, "tb_world_get_counts");
  if (w == NULL) return c;
  c.body_count = w->bodies.count;
  c.shape_count = w->shapes.count;
  c.step_count = w->step_count;
  c.awake_body_count = w->awake_count;
  c.joint_count = w->joints.count;
  c.awake_contact_count = w->step_contact_count;
  c.sleeping_island_count = w->islands.count;
  c.contact_count = w->contacts.count;
  for (int i = 0; i < w->contacts.high; ++i)
    if (tb_pool_alive(&w->contacts, i) && (((tb_contact*)tb_pool_at(&w->contacts, i))->flags & TB_CONTACT_TOUCHING))
      c.touching_count += 1;
  for (int t = 0; t < 3; ++t) {
    int h = tb_tree_get_height(&w->broad_phase.trees[t]);
    if (h > c.tree_height) c.tree_height = h;
  }
  return c;
}

tb_profile tb_world_get_profile(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_profile");
  return w != NULL ? w->profile : (tb_profile){0};
}

tb_contact_events tb_world_get_contact_events(tb_world_id id) {
  tb_contact_events e = {0};
  tb_world* w = tb_world_get(id, "tb_world_get_contact_events");
  if (w == NULL) return e;
  e.begin_events = w->begin_events;
  e.end_events = w->end_events;
  e.hit_events = w->hit_events;
  e.begin_count = w->begin_count;
  e.end_count = w->end_count;
  e.hit_count = w->hit_count;
  return e;
}

tb_sensor_events tb_world_get_sensor_events(tb_world_id id) {
  tb_sensor_events e = {0};
  tb_world* w = tb_world_get(id, "tb_world_get_sensor_events");
  if (w == NULL) return e;
  e.begin_events = w->sensor_begin_events;
  e.end_events = w->sensor_end_events;
  e.begin_count = w->sensor_begin_count;
  e.end_count = w->sensor_end_count;
  return e;
}

/* The hash takes explicitly listed fields (struct padding is never hashed),
 * a 32-bit word at a time: xor, multiply by an odd constant, fold the high
 * half down. Each of these is a bijection of the state, so two worlds that
 * differ in one field always hash apart. Pointers the user handed in (user
 * data, callbacks, contexts) count only as set or not: their values change
 * from run to run. */
typedef struct hasher {
  uint64_t h;
} hasher;

static void hash_word(hasher* s, uint32_t x) {
  uint64_t h = (s->h ^ x) * 0x9e3779b97f4a7c15ull;
  s->h = h ^ (h >> 32);
}
static void hash_float(hasher* s, float x) {
  uint32_t bits;
  memcpy(&bits, &x, sizeof bits);
  hash_word(s, bits);
}
static void hash_int(hasher* s, int x) { hash_word(s, (uint32_t)x); }
static void hash_u64(hasher* s, uint64_t x) {
  hash_word(s, (uint32_t)x);
  hash_word(s, (uint32_t)(x >> 32));
}
static void hash_double(hasher* s, double x) {
  uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  hash_u64(s, bits);
}
static void hash_set(hasher* s, const void* p) { hash_int(s, p != NULL); }
static void hash_vec(hasher* s, tb_vec2 v) {
  hash_float(s, v.x);
  hash_float(s, v.y);
}
static void hash_aabb(hasher* s, tb_aabb a) {
  hash_vec(s, a.lower);
  hash_vec(s, a.upper);
}
static void hash_floats(hasher* s, const float* f, size_t n) {
  for (size_t k = 0; k < n; ++k) hash_float(s, f[k]);
}

static void hash_settings(hasher* s, const tb_world* w) {
  hash_vec(s, w->gravity);
  hash_int(s, (int)w->integrator);
  hash_double(s, w->time);
  hash_int(s, w->step_count);
  const float f[] = {w->hit_event_threshold,       w->contact_hertz,       w->contact_damping_ratio,
                     w->contact_push_max_velocity, w->joint_hertz,         w->joint_damping_ratio,
                     w->restitution_threshold,     w->maximum_linear_speed};
  hash_floats(s, f, sizeof f / sizeof f[0]);
  hash_int(s, w->relax_iterations);
  hash_int(s, w->enable_sleep + 2 * w->enable_continuous + 4 * w->enable_warm_starting);
  hash_int(s, w->force_field != NULL);
  hash_set(s, w->force_field_context);
  hash_int(s, w->custom_filter != NULL);
  hash_set(s, w->custom_filter_context);
  hash_int(s, w->pre_solve != NULL);
  hash_set(s, w->pre_solve_context);
  hash_int(s, w->friction_mix != NULL);
  hash_int(s, w->restitution_mix != NULL);
  hash_set(s, w->mix_context);
  hash_set(s, w->user_data);
}

static void hash_shape(hasher* s, const tb_shape* sh) {
  hash_int(s, (int)sh->type);
  hash_int(s, sh->body);
  const float f[] = {sh->density, sh->friction, sh->restitution, sh->rolling_resistance, sh->tangent_speed};
  hash_floats(s, f, sizeof f / sizeof f[0]);
  hash_u64(s, sh->filter.category_bits);
  hash_u64(s, sh->filter.mask_bits);
  hash_int(s, sh->filter.group_index);
  hash_int(s, sh->sensor + 2 * sh->enable_sensor_events + 4 * sh->enable_contact_events + 8 * sh->enable_hit_events +
                  16 * sh->enable_pre_solve_events + 32 * sh->in_move_buffer + 64 * (sh->proxy >= 0));
  hash_int(s, sh->tree);
  hash_int(s, sh->chain);
  hash_set(s, sh->user_data);
  hash_aabb(s, sh->aabb);
  switch (sh->type) {
    case TB_SHAPE_CIRCLE:
      hash_vec(s, sh->geom.circle.center);
      hash_float(s, sh->geom.circle.radius);
      break;
    case TB_SHAPE_CAPSULE:
      hash_vec(s, sh->geom.capsule.center1);
      hash_vec(s, sh->geom.capsule.center2);
      hash_float(s, sh->geom.capsule.radius);
      break;
    case TB_SHAPE_SEGMENT:
      hash_vec(s, sh->geom.segment.point1);
      hash_vec(s, sh->geom.segment.point2);
      break;
    case TB_SHAPE_CHAIN_SEGMENT:
      hash_vec(s, sh->geom.chain_segment.ghost1);
      hash_vec(s, sh->geom.chain_segment.segment.point1);
      hash_vec(s, sh->geom.chain_segment.segment.point2);
      hash_vec(s, sh->geom.chain_segment.ghost2);
      break;
    case TB_SHAPE_POLYGON: {
      const tb_polygon* p = &sh->geom.polygon;
      hash_int(s, p->count);
      for (int i = 0; i < p->count && i < TB_MAX_POLYGON_VERTICES; ++i) {
        hash_vec(s, p->vertices[i]);
        hash_vec(s, p->normals[i]);
      }
      hash_vec(s, p->centroid);
      hash_float(s, p->radius);
      break;
    }
  }
}

/* A body with its shapes, its place in the awake set or a sleeping island,
 * and the order of its contact and joint lists (the solver's order). */
static void hash_body(hasher* s, const tb_world* w, int i) {
  const tb_body* b = tb_body_at(w, i);
  hash_int(s, i);
  hash_int(s, (int)b->type);
  hash_vec(s, b->center);
  hash_vec(s, b->center_residual);
  hash_vec(s, b->transform.p);
  hash_vec(s, (tb_vec2){b->transform.q.c, b->transform.q.s});
  hash_vec(s, b->local_center);
  hash_vec(s, b->linear_velocity);
  hash_vec(s, b->force);
  hash_float(s, b->angle_residual);
  const float f[] = {b->angle,           b->angular_velocity, b->torque,      b->mass,
                     b->inv_mass,        b->inertia,          b->inv_inertia, b->linear_damping,
                     b->angular_damping, b->gravity_scale,    b->sleep_time,  b->sleep_threshold,
                     b->max_extent,      b->min_extent};
  hash_floats(s, f, sizeof f / sizeof f[0]);
  hash_int(s, b->fixed_rotation + 2 * b->enabled + 4 * b->mass_overridden + 8 * b->is_bullet + 16 * b->enable_sleep);
  hash_int(s, b->awake_index);
  hash_int(s, b->sleep_island);
  hash_int(s, b->island_next);
  hash_set(s, b->user_data);
  hash_int(s, b->shape_count);
  for (int k = b->shape_list; k >= 0; k = tb_shape_at(w, k)->next) {
    hash_int(s, k);
    hash_shape(s, tb_shape_at(w, k));
  }
  hash_int(s, b->contact_count);
  for (int key = b->contact_list; key >= 0;) {
    hash_int(s, key);
    key = ((const tb_contact*)tb_pool_at(&w->contacts, key >> 1))->edges[key & 1].next;
  }
  hash_int(s, b->joint_count);
  for (int key = b->joint_list; key >= 0; key = tb_joint_at(w, key >> 1)->edges[key & 1].next) hash_int(s, key);
}

/* A contact: its shapes, mixed material, flags and the manifold with the
 * impulses kept for warm starting. */
static void hash_contact(hasher* s, int i, const tb_contact* c) {
  hash_int(s, i);
  hash_int(s, c->shape_a);
  hash_int(s, c->shape_b);
  hash_int(s, (int)c->flags);
  const float f[] = {c->friction,      c->restitution,     c->rolling_resistance,
                     c->tangent_speed, c->rolling_impulse, c->impact_depth};
  hash_floats(s, f, sizeof f / sizeof f[0]);
  const tb_manifold* m = &c->manifold;
  hash_vec(s, m->normal);
  hash_int(s, m->point_count);
  for (int k = 0; k < m->point_count && k < 2; ++k) {
    const tb_manifold_point* p = &m->points[k];
    hash_vec(s, p->point);
    hash_word(s, p->id);
    hash_floats(s, (const float[]){p->separation, p->normal_impulse, p->tangent_impulse}, 3);
  }
  /* the manifold kept for reuse: the next step's manifold depends on it */
  const tb_manifold_cache* k = &c->cache;
  hash_int(s, k->point_count);
  if (k->point_count > 0) {
    hash_vec(s, k->normal);
    hash_vec(s, k->relative_center);
    hash_floats(s, (const float[]){k->relative_rot.c, k->relative_rot.s}, 2);
    for (int i = 0; i < k->point_count && i < 2; ++i) {
      hash_vec(s, k->points[i]);
      hash_floats(s, &k->separation[i], 1);
    }
  }
}

static void hash_joint(hasher* s, int i, const tb_joint* j) {
  hash_int(s, i);
  hash_int(
      s, (int)j->type + 8 * j->collide_connected + 16 * j->enable_spring + 32 * j->enable_limit + 64 * j->enable_motor);
  hash_int(s, j->edges[0].body);
  hash_int(s, j->edges[1].body);
  hash_set(s, j->user_data);
  hash_vec(s, j->local_anchor_a);
  hash_vec(s, j->local_anchor_b);
  hash_vec(s, j->local_axis_a);
  hash_vec(s, j->target);
  hash_vec(s, j->linear_impulse);
  hash_vec(s, j->force);
  const float f[] = {j->reference_angle,
                     j->length,
                     j->lower,
                     j->upper,
                     j->hertz,
                     j->damping_ratio,
                     j->angular_hertz,
                     j->angular_damping_ratio,
                     j->motor_speed,
                     j->max_motor,
                     j->max_force,
                     j->max_torque,
                     j->correction_factor,
                     j->angular_impulse,
                     j->axial_impulse,
                     j->spring_impulse,
                     j->motor_impulse,
                     j->lower_impulse,
                     j->upper_impulse,
                     j->last_h,
                     j->torque,
                     j->motor_output};
  hash_floats(s, f, sizeof f / sizeof f[0]);
}

/* A broad-phase tree by its shape, not its node numbers: the leaves (shape,
 * fat box, category bits) in depth-first order, each node marked leaf or
 * internal, which fixes the shape of a tree whose internal nodes all have two
 * children. Walked through the parent links: no stack, no allocation. */
static void hash_tree(hasher* s, const tb_tree* t) {
  hash_int(s, t->proxy_count);
  int prev = TB_TREE_NULL;
  for (int n = t->root; n != TB_TREE_NULL;) {
    const tb_tree_node* node = &t->nodes[n];
    int next;
    if (prev == node->parent) { /* arrived from above: visit */
      bool leaf = node->child1 == TB_TREE_NULL;
      hash_int(s, leaf);
      if (leaf) {
        hash_int(s, node->user_id);
        hash_aabb(s, node->aabb);
        hash_u64(s, node->category_bits);
      }
      next = leaf ? node->parent : node->child1;
    } else {
      next = prev == node->child1 ? node->child2 : node->parent;
    }
    prev = n;
    n = next;
  }
}

/* The slot only: a generation depends on what earlier worlds in the same world
 * slot did, and a world's hash must not. */
static void hash_shape_id(hasher* s, tb_shape_id id) { hash_int(s, id.index1); }

/* Events of the last step (and the end events of shapes destroyed since). */
static void hash_events(hasher* s, const tb_world* w) {
  hash_int(s, w->begin_count);
  for (int i = 0; i < w->begin_count; ++i) {
    hash_shape_id(s, w->begin_events[i].shape_a);
    hash_shape_id(s, w->begin_events[i].shape_b);
  }
  hash_int(s, w->end_count);
  for (int i = 0; i < w->end_count; ++i) {
    hash_shape_id(s, w->end_events[i].shape_a);
    hash_shape_id(s, w->end_events[i].shape_b);
  }
  hash_int(s, w->hit_count);
  for (int i = 0; i < w->hit_count; ++i) {
    hash_shape_id(s, w->hit_events[i].shape_a);
    hash_shape_id(s, w->hit_events[i].shape_b);
    hash_float(s, w->hit_events[i].approach_speed);
  }
  hash_int(s, w->sensor_begin_count);
  for (int i = 0; i < w->sensor_begin_count; ++i) {
    hash_shape_id(s, w->sensor_begin_events[i].sensor);
    hash_shape_id(s, w->sensor_begin_events[i].visitor);
  }
  hash_int(s, w->sensor_end_count);
  for (int i = 0; i < w->sensor_end_count; ++i) {
    hash_shape_id(s, w->sensor_end_events[i].sensor);
    hash_shape_id(s, w->sensor_end_events[i].visitor);
  }
}

uint64_t tb_world_hash(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_hash");
  if (w == NULL) return 0;
  hasher s = {0xcbf29ce484222325ull};
  hash_settings(&s, w);
  hash_int(&s, w->bodies.count);
  hash_int(&s, w->shapes.count);
  for (int i = 0; i < w->bodies.high; ++i)
    if (tb_pool_alive(&w->bodies, i)) hash_body(&s, w, i);
  /* the awake set in its order: the order of the solver bodies */
  hash_int(&s, w->awake_count);
  for (int i = 0; i < w->awake_count; ++i) hash_int(&s, w->awake[i]);
  hash_int(&s, w->islands.count);
  hash_int(&s, w->contacts.count);
  for (int i = 0; i < w->contacts.high; ++i)
    if (tb_pool_alive(&w->contacts, i)) hash_contact(&s, i, (const tb_contact*)tb_pool_at(&w->contacts, i));
  hash_int(&s, w->joints.count);
  for (int i = 0; i < w->joints.high; ++i)
    if (tb_pool_alive(&w->joints, i)) hash_joint(&s, i, tb_joint_at(w, i));
  hash_int(&s, w->chains.count);
  for (int i = 0; i < w->chains.high; ++i) {
    if (!tb_pool_alive(&w->chains, i)) continue;
    const tb_chain* c = (const tb_chain*)tb_pool_at(&w->chains, i);
    hash_int(&s, i);
    hash_int(&s, c->body);
    hash_int(&s, c->loop);
    hash_int(&s, c->count);
    for (int k = 0; k < c->count; ++k) hash_int(&s, c->shapes[k]);
  }
  /* the broad phase: the trees and the proxies queued for pair finding (the
   * pair set mirrors the contacts) */
  for (int t = 0; t < 3; ++t) hash_tree(&s, &w->broad_phase.trees[t]);
  for (int i = 0; i < w->broad_phase.move_count; ++i)
    if (w->broad_phase.move_buffer[i] >= 0) hash_int(&s, w->broad_phase.move_buffer[i]);
  hash_events(&s, w);
  return s.h;
}

const char* tb_world_last_error(tb_world_id id) {
  int slot = (int)id.index1 - 1;
  if (!tb_world_is_valid(id)) return "the world handle is null or the world was destroyed";
  return worlds[slot]->last_error;
}

/* ---- memory ---------------------------------------------------------------- */

int tb_world_count(void) {
  int n = 0;
  for (int i = 0; i < TB_MAX_WORLDS; ++i) n += worlds[i] != NULL;
  return n;
}

size_t tb_get_retained_byte_count(void) {
  size_t bytes = 0;
  for (int slot = 0; slot < TB_MAX_WORLDS; ++slot)
    for (int k = 0; k < HISTORY_POOLS; ++k) bytes += tb_pool_history_bytes(&handle_history[slot][k]);
  return bytes;
}

/* Copies every slot's handle history into blocks of the new allocator, then
 * frees the old blocks with the current one; false (nothing changed) when the
 * new allocator has no memory. Called only while no world exists. */
bool tb_world_histories_move(tb_alloc_fn* alloc, tb_free_fn* free_fn, void* context) {
  uint16_t* copies[TB_MAX_WORLDS][HISTORY_POOLS];
  bool ok = true;
  for (int slot = 0; slot < TB_MAX_WORLDS; ++slot)
    for (int k = 0; k < HISTORY_POOLS; ++k) {
      size_t bytes = tb_pool_history_bytes(&handle_history[slot][k]);
      copies[slot][k] = ok && bytes > 0 ? alloc(bytes, TB_ALLOCATION_ALIGNMENT, context) : NULL;
      if (bytes > 0 && copies[slot][k] == NULL) ok = false;
    }
  for (int slot = 0; slot < TB_MAX_WORLDS; ++slot)
    for (int k = 0; k < HISTORY_POOLS; ++k) {
      tb_pool_history* h = &handle_history[slot][k];
      uint16_t* copy = copies[slot][k];
      if (copy == NULL) continue;
      if (ok) {
        memcpy(copy, h->generations, tb_pool_history_bytes(h));
        tb_mem_free(h->generations, tb_pool_history_bytes(h));
        h->generations = copy;
      } else {
        free_fn(copy, tb_pool_history_bytes(h), context);
      }
    }
  return ok;
}

static void memory_stats(const tb_world* w, tb_memory_stats* m) {
  *m = (tb_memory_stats){0};
  m->world = sizeof *w;
  m->bodies = tb_pool_bytes(&w->bodies) + (size_t)w->awake_capacity * sizeof *w->awake;
  m->shapes = tb_pool_bytes(&w->shapes) + tb_pool_bytes(&w->chains) + tb_chains_bytes(w);
  m->contacts = tb_pool_bytes(&w->contacts) + tb_broad_phase_pair_bytes(&w->broad_phase);
  m->joints = tb_pool_bytes(&w->joints);
  m->broad_phase = tb_broad_phase_tree_bytes(&w->broad_phase);
  m->islands = tb_pool_bytes(&w->islands);
  m->solver = tb_solver_bytes(w) + tb_contact_solver_bytes(w) + tb_joint_tree_bytes(&w->joint_tree) +
              tb_wide_joints_bytes(&w->wide_joints) + (size_t)w->new_contact_capacity * sizeof *w->new_contact_bodies +
              (size_t)w->step_contact_capacity * sizeof *w->step_contacts +
              (size_t)w->step_joint_capacity * sizeof *w->step_joints +
              (size_t)w->walked_joint_capacity * sizeof *w->walked_joints +
              (size_t)w->step_joint_info_capacity * sizeof *w->step_joint_info +
              (size_t)w->scratch_capacity * sizeof *w->scratch;
  m->events = (size_t)w->begin_capacity * sizeof *w->begin_events + (size_t)w->end_capacity * sizeof *w->end_events +
              (size_t)w->hit_capacity * sizeof *w->hit_events +
              (size_t)w->sensor_begin_capacity * sizeof *w->sensor_begin_events +
              (size_t)w->sensor_end_capacity * sizeof *w->sensor_end_events;
  for (int k = 0; k < HISTORY_POOLS; ++k)
    m->handle_history += tb_pool_history_bytes(&handle_pool((tb_world*)w, k)->inherited);
  m->total = m->world + m->bodies + m->shapes + m->contacts + m->joints + m->broad_phase + m->islands + m->solver +
             m->events + m->handle_history;
}

size_t tb_world_get_byte_count(tb_world_id id) {
  tb_world* w = tb_world_get(id, "tb_world_get_byte_count");
  if (w == NULL) return 0;
  tb_memory_stats m;
  memory_stats(w, &m);
  return m.total;
}

tb_result tb_world_get_memory_stats(tb_world_id id, tb_memory_stats* stats) {
  tb_world* w = tb_world_get(id, "tb_world_get_memory_stats");
  if (w == NULL) {
    if (stats != NULL) *stats = (tb_memory_stats){0};
    return tb_last_result();
  }
  if (stats == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "tb_world_get_memory_stats: stats is NULL");
  memory_stats(w, stats);
  return TB_OK;
}
