/* tb_world_hash covers the whole world: every public call that changes the
 * world moves the hash, and (where the call can be undone exactly) setting
 * the old value back restores it. The bad-input tests and the API fuzzer rely
 * on this: "a rejected call leaves the hash unchanged" proves nothing about a
 * setting the hash does not see. Also: identical worlds hash alike, whatever
 * their world slot; a step moves the hash; the state a step carries over
 * (warm-start impulses, rest timers, fat boxes) is hashed, checked from
 * inside; user pointers count only as set or not (their values differ from
 * run to run). */
#include <string.h>

#include "../src/world.h"
#include "test_util.h"

#define DT (1.0f / 60.0f)
#define SUBSTEPS 4
#define JOINT_TYPES 7

/* One world with something of everything: a static ground (a box and a
 * chain), a box resting on the ground and a ball on the chain (contacts with
 * warm-start impulses), a body created asleep, a body with a mass override,
 * and one joint of each type, each holding its own body to the ground. */
typedef struct scene {
  tb_world_id w;
  tb_body_id ground, box, ball, sleeper, heavy;
  tb_shape_id ground_shape, box_shape, ball_shape, chain_segment;
  tb_chain_id chain;
  tb_body_id jointed[JOINT_TYPES];
  tb_joint_id distance, revolute, prismatic, weld, wheel, mouse, motor;
  /* state read after the warm-up steps, for the undo calls */
  tb_vec2 box_v;
  float box_w;
} scene;

static tb_body_id body_at(tb_world_id w, tb_body_type type, tb_vec2 p, bool awake) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = p;
  bd.is_awake = awake;
  tb_body_id b = tb_create_body(w, &bd);
  ck_assert(!tb_body_id_is_null(b));
  return b;
}

static tb_shape_id add_box(tb_body_id b, float hx, float hy) {
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(hx, hy, &box), TB_OK);
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id s = tb_create_polygon_shape(b, &sd, &box);
  ck_assert(!tb_shape_id_is_null(s));
  return s;
}

static tb_body_id jointed_body(scene* s, int k) {
  tb_body_id b = body_at(s->w, TB_DYNAMIC_BODY, (tb_vec2){-20.0f - 3.0f * (float)k, 5.0f}, true);
  add_box(b, 0.2f, 0.2f);
  s->jointed[k] = b;
  return b;
}

static void make_joints(scene* s) {
  tb_distance_joint_def dd = tb_default_distance_joint_def();
  dd.body_a = s->ground;
  dd.body_b = jointed_body(s, 0);
  dd.local_anchor_a = (tb_vec2){-20.0f, 8.0f};
  dd.length = 3.0f;
  dd.min_length = 0.5f;
  dd.max_length = 5.0f;
  s->distance = tb_create_distance_joint(s->w, &dd);

  tb_revolute_joint_def rd = tb_default_revolute_joint_def();
  rd.body_a = s->ground;
  rd.body_b = jointed_body(s, 1);
  rd.local_anchor_a = (tb_vec2){-22.0f, 5.0f}; /* a pendulum of 1 m */
  rd.local_anchor_b = (tb_vec2){1.0f, 0.0f};
  rd.lower_angle = -1.0f;
  rd.upper_angle = 1.0f;
  rd.hertz = 1.0f;
  rd.damping_ratio = 0.5f;
  s->revolute = tb_create_revolute_joint(s->w, &rd);

  tb_prismatic_joint_def pd = tb_default_prismatic_joint_def();
  pd.body_a = s->ground;
  pd.body_b = jointed_body(s, 2);
  pd.local_anchor_a = (tb_vec2){-26.0f, 5.0f};
  pd.local_axis_a = (tb_vec2){0.0f, 1.0f};
  pd.lower_translation = -1.0f;
  pd.upper_translation = 1.0f;
  pd.hertz = 1.0f;
  pd.damping_ratio = 0.5f;
  s->prismatic = tb_create_prismatic_joint(s->w, &pd);

  tb_weld_joint_def wd = tb_default_weld_joint_def();
  wd.body_a = s->ground;
  wd.body_b = jointed_body(s, 3);
  wd.local_anchor_a = (tb_vec2){-29.0f, 5.0f};
  s->weld = tb_create_weld_joint(s->w, &wd);

  tb_wheel_joint_def hd = tb_default_wheel_joint_def();
  hd.body_a = s->ground;
  hd.body_b = jointed_body(s, 4);
  hd.local_anchor_a = (tb_vec2){-32.0f, 5.0f};
  s->wheel = tb_create_wheel_joint(s->w, &hd);

  tb_mouse_joint_def md = tb_default_mouse_joint_def();
  md.body_a = s->ground;
  md.body_b = jointed_body(s, 5);
  md.target = (tb_vec2){-35.0f, 5.0f};
  s->mouse = tb_create_mouse_joint(s->w, &md);

  tb_motor_joint_def od = tb_default_motor_joint_def();
  od.body_a = s->ground;
  od.body_b = jointed_body(s, 6);
  od.linear_offset = (tb_vec2){-38.0f, 5.0f};
  s->motor = tb_create_motor_joint(s->w, &od);

  const tb_joint_id all[JOINT_TYPES] = {s->distance, s->revolute, s->prismatic, s->weld, s->wheel, s->mouse, s->motor};
  for (int k = 0; k < JOINT_TYPES; ++k) ck_assert(!tb_joint_id_is_null(all[k]));
}

/* Built, stepped a little (contacts and joints get impulses), then every
 * awake body set awake once more: its rest timer is zero, so that a call that
 * wakes a body changes nothing beyond what it sets. */
static scene make_scene(void) {
  scene s;
  memset(&s, 0, sizeof s);
  s.w = tbt_world(0.0f, -10.0f);
  s.ground = body_at(s.w, TB_STATIC_BODY, (tb_vec2){0.0f, 0.0f}, true);
  s.ground_shape = add_box(s.ground, 5.0f, 0.5f);
  tb_chain_def cd = tb_default_chain_def();
  const tb_vec2 points[3] = {{6.0f, 0.0f}, {8.0f, 0.0f}, {10.0f, 0.0f}};
  cd.points = points;
  cd.count = 3;
  s.chain = tb_create_chain(s.ground, &cd);
  ck_assert(!tb_chain_id_is_null(s.chain));
  ck_assert_int_eq(tb_chain_get_segments(s.chain, &s.chain_segment, 1), 1);

  s.box = body_at(s.w, TB_DYNAMIC_BODY, (tb_vec2){0.0f, 0.75f}, true);
  s.box_shape = add_box(s.box, 0.25f, 0.25f);
  s.ball = body_at(s.w, TB_DYNAMIC_BODY, (tb_vec2){7.0f, 0.3f}, true);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, 0.3f};
  s.ball_shape = tb_create_circle_shape(s.ball, &sd, &c);
  ck_assert(!tb_shape_id_is_null(s.ball_shape));
  s.sleeper = body_at(s.w, TB_DYNAMIC_BODY, (tb_vec2){50.0f, 50.0f}, false);
  add_box(s.sleeper, 0.5f, 0.5f);
  s.heavy = body_at(s.w, TB_DYNAMIC_BODY, (tb_vec2){3.0f, 0.75f}, true);
  add_box(s.heavy, 0.25f, 0.25f);
  ck_assert_int_eq(tb_body_set_mass_data(s.heavy, (tb_mass_data){5.0f, {0.0f, 0.0f}, 1.0f}), TB_OK);
  make_joints(&s);

  for (int i = 0; i < 10; ++i) ck_assert_int_eq(tb_world_step(s.w, DT, SUBSTEPS), TB_OK);
  ck_assert(tb_body_get_contact_capacity(s.box) == 1 && tb_body_get_contact_capacity(s.ball) == 1);
  ck_assert(!tb_body_is_awake(s.sleeper));
  tb_body_id awake[] = {s.box, s.ball, s.heavy};
  for (size_t k = 0; k < sizeof awake / sizeof awake[0]; ++k)
    ck_assert_int_eq(tb_body_set_awake(awake[k], true), TB_OK);
  for (int k = 0; k < JOINT_TYPES; ++k) ck_assert_int_eq(tb_body_set_awake(s.jointed[k], true), TB_OK);
  s.box_v = tb_body_get_linear_velocity(s.box);
  s.box_w = tb_body_get_angular_velocity(s.box);
  return s;
}

static void force_field(double time, const tb_body_state* state, void* context, tb_vec2* force, float* torque) {
  (void)time, (void)state, (void)context;
  *force = (tb_vec2){0.0f, 0.0f};
  *torque = 0.0f;
}

static bool pre_solve(tb_shape_id a, tb_shape_id b, const tb_manifold* m, void* context) {
  (void)a, (void)b, (void)m, (void)context;
  return true;
}

static int token; /* something for user data and contexts to point at */

/* ---- the table ---------------------------------------------------------------
 * Each case changes the scene through one public call (do_) and, where the
 * call can be undone exactly, sets the old value back (undo_). */

typedef struct hash_case {
  const char* name;
  void (*change)(scene*);
  void (*undo)(scene*); /* NULL: no exact undo (contacts end, a body moves, ...) */
} hash_case;

#define OK(call) ck_assert_msg((call) == TB_OK, "%s: %s", #call, tb_last_error())
#define MADE(id, null_check) ck_assert_msg(!null_check(id), "%s: %s", #id, tb_last_error())
#define SETTER(name, change_call, undo_call)           \
  static void do_##name(scene* s) { OK(change_call); } \
  static void undo_##name(scene* s) { OK(undo_call); }
#define ONE_WAY(name, change_call) \
  static void do_##name(scene* s) { OK(change_call); }
#define TWO_WAY_CASE(name) \
  { #name, do_##name, undo_##name }
#define ONE_WAY_CASE(name) \
  { #name, do_##name, NULL }

/* world */
SETTER(world_set_gravity, tb_world_set_gravity(s->w, (tb_vec2){1.0f, -9.0f}),
       tb_world_set_gravity(s->w, (tb_vec2){0.0f, -10.0f}))
SETTER(world_set_integrator, tb_world_set_integrator(s->w, TB_INTEGRATOR_RK4),
       tb_world_set_integrator(s->w, TB_INTEGRATOR_MIDPOINT))
SETTER(world_set_force_field, tb_world_set_force_field(s->w, force_field, NULL),
       tb_world_set_force_field(s->w, NULL, NULL))
SETTER(world_set_force_field_context, tb_world_set_force_field(s->w, NULL, &token),
       tb_world_set_force_field(s->w, NULL, NULL))
SETTER(world_set_pre_solve, tb_world_set_pre_solve(s->w, pre_solve, NULL), tb_world_set_pre_solve(s->w, NULL, NULL))
SETTER(world_set_pre_solve_context, tb_world_set_pre_solve(s->w, NULL, &token),
       tb_world_set_pre_solve(s->w, NULL, NULL))
SETTER(world_enable_continuous, tb_world_enable_continuous(s->w, false), tb_world_enable_continuous(s->w, true))
SETTER(world_enable_warm_starting, tb_world_enable_warm_starting(s->w, false),
       tb_world_enable_warm_starting(s->w, true))
SETTER(world_set_contact_tuning, tb_world_set_contact_tuning(s->w, 60.0f, 10.0f, 3.0f),
       tb_world_set_contact_tuning(s->w, 120.0f, 10.0f, 3.0f))
SETTER(world_set_contact_damping, tb_world_set_contact_tuning(s->w, 120.0f, 5.0f, 3.0f),
       tb_world_set_contact_tuning(s->w, 120.0f, 10.0f, 3.0f))
SETTER(world_set_contact_push, tb_world_set_contact_tuning(s->w, 120.0f, 10.0f, 1.0f),
       tb_world_set_contact_tuning(s->w, 120.0f, 10.0f, 3.0f))
SETTER(world_set_relax_iterations, tb_world_set_relax_iterations(s->w, 3), tb_world_set_relax_iterations(s->w, 8))
SETTER(world_set_joint_tuning, tb_world_set_joint_tuning(s->w, 30.0f, 2.0f),
       tb_world_set_joint_tuning(s->w, 60.0f, 2.0f))
SETTER(world_set_joint_damping, tb_world_set_joint_tuning(s->w, 60.0f, 1.0f),
       tb_world_set_joint_tuning(s->w, 60.0f, 2.0f))
SETTER(world_set_restitution_threshold, tb_world_set_restitution_threshold(s->w, 2.0f),
       tb_world_set_restitution_threshold(s->w, 1.0f))
SETTER(world_set_maximum_linear_speed, tb_world_set_maximum_linear_speed(s->w, 100.0f),
       tb_world_set_maximum_linear_speed(s->w, 1000.0f))
SETTER(world_set_user_data, tb_world_set_user_data(s->w, &token), tb_world_set_user_data(s->w, NULL))
/* turning sleep off wakes the sleeper: the undo puts it back to sleep */
static void do_world_enable_sleeping(scene* s) { OK(tb_world_enable_sleeping(s->w, false)); }
static void undo_world_enable_sleeping(scene* s) {
  OK(tb_world_enable_sleeping(s->w, true));
  OK(tb_body_set_awake(s->sleeper, false));
}

/* bodies */
ONE_WAY(body_set_type, tb_body_set_type(s->box, TB_KINEMATIC_BODY))
ONE_WAY(body_set_type_static, tb_body_set_type(s->box, TB_STATIC_BODY))
ONE_WAY(body_set_transform, tb_body_set_transform(s->box, (tb_vec2){0.0f, 2.0f}, 0.5f))
SETTER(body_set_linear_velocity, tb_body_set_linear_velocity(s->box, (tb_vec2){1.0f, 0.0f}),
       tb_body_set_linear_velocity(s->box, s->box_v))
SETTER(body_set_angular_velocity, tb_body_set_angular_velocity(s->box, 1.0f),
       tb_body_set_angular_velocity(s->box, s->box_w))
SETTER(body_set_linear_damping, tb_body_set_linear_damping(s->box, 0.5f), tb_body_set_linear_damping(s->box, 0.0f))
SETTER(body_set_angular_damping, tb_body_set_angular_damping(s->box, 0.5f), tb_body_set_angular_damping(s->box, 0.0f))
SETTER(body_set_gravity_scale, tb_body_set_gravity_scale(s->box, 0.5f), tb_body_set_gravity_scale(s->box, 1.0f))
static void do_body_set_fixed_rotation(scene* s) { OK(tb_body_set_fixed_rotation(s->box, true)); }
static void undo_body_set_fixed_rotation(scene* s) {
  OK(tb_body_set_fixed_rotation(s->box, false));
  OK(tb_body_set_angular_velocity(s->box, s->box_w));
}
ONE_WAY(body_set_enabled, tb_body_set_enabled(s->box, false))
SETTER(body_set_user_data, tb_body_set_user_data(s->box, &token), tb_body_set_user_data(s->box, NULL))
ONE_WAY(body_set_asleep, tb_body_set_awake(s->box, false))
SETTER(body_set_awake, tb_body_set_awake(s->sleeper, true), tb_body_set_awake(s->sleeper, false))
SETTER(body_enable_sleep, tb_body_enable_sleep(s->box, false), tb_body_enable_sleep(s->box, true))
SETTER(body_set_sleep_threshold, tb_body_set_sleep_threshold(s->box, 0.5f), tb_body_set_sleep_threshold(s->box, 0.05f))
SETTER(body_set_bullet, tb_body_set_bullet(s->box, true), tb_body_set_bullet(s->box, false))
/* forces add up from zero; the opposite force takes them back to zero exactly */
SETTER(body_apply_force, tb_body_apply_force(s->box, (tb_vec2){3.0f, 1.0f}, (tb_vec2){0.25f, 1.0f}),
       tb_body_apply_force(s->box, (tb_vec2){-3.0f, -1.0f}, (tb_vec2){0.25f, 1.0f}))
SETTER(body_apply_force_to_center, tb_body_apply_force_to_center(s->box, (tb_vec2){3.0f, 1.0f}),
       tb_body_apply_force_to_center(s->box, (tb_vec2){-3.0f, -1.0f}))
SETTER(body_apply_torque, tb_body_apply_torque(s->box, 2.0f), tb_body_apply_torque(s->box, -2.0f))
static void undo_velocities(scene* s) {
  OK(tb_body_set_linear_velocity(s->box, s->box_v));
  OK(tb_body_set_angular_velocity(s->box, s->box_w));
}
ONE_WAY(body_apply_linear_impulse, tb_body_apply_linear_impulse(s->box, (tb_vec2){0.5f, 0.0f}, (tb_vec2){0.0f, 1.0f}))
ONE_WAY(body_apply_linear_impulse_to_center, tb_body_apply_linear_impulse_to_center(s->box, (tb_vec2){0.5f, 0.0f}))
ONE_WAY(body_apply_angular_impulse, tb_body_apply_angular_impulse(s->box, 0.5f))
ONE_WAY(body_set_mass_data, tb_body_set_mass_data(s->box, (tb_mass_data){2.0f, {0.0f, 0.0f}, 0.5f}))
ONE_WAY(body_reset_mass_data, tb_body_reset_mass_data(s->heavy))
static void do_create_body(scene* s) {
  MADE(body_at(s->w, TB_DYNAMIC_BODY, (tb_vec2){-5.0f, 20.0f}, true), tb_body_id_is_null);
}
ONE_WAY(destroy_body, tb_destroy_body(s->box))

/* shapes (the density of the ground's box: a static body's mass data stays
 * zero, so the old density restores it exactly) */
SETTER(shape_set_density, tb_shape_set_density(s->ground_shape, 2.0f), tb_shape_set_density(s->ground_shape, 1.0f))
ONE_WAY(shape_set_density_dynamic, tb_shape_set_density(s->box_shape, 2.0f))
SETTER(shape_set_friction, tb_shape_set_friction(s->box_shape, 0.1f), tb_shape_set_friction(s->box_shape, 0.6f))
SETTER(shape_set_restitution, tb_shape_set_restitution(s->box_shape, 0.5f),
       tb_shape_set_restitution(s->box_shape, 0.0f))
SETTER(shape_set_rolling_resistance, tb_shape_set_rolling_resistance(s->ball_shape, 0.2f),
       tb_shape_set_rolling_resistance(s->ball_shape, 0.0f))
SETTER(shape_set_tangent_speed, tb_shape_set_tangent_speed(s->ground_shape, 2.0f),
       tb_shape_set_tangent_speed(s->ground_shape, 0.0f))
ONE_WAY(shape_set_filter, tb_shape_set_filter(s->box_shape, (tb_filter){2u, UINT64_MAX, 0}))
ONE_WAY(shape_set_filter_group, tb_shape_set_filter(s->box_shape, (tb_filter){1u, UINT64_MAX, -1}))
SETTER(shape_set_user_data, tb_shape_set_user_data(s->box_shape, &token), tb_shape_set_user_data(s->box_shape, NULL))
static void do_create_circle_shape(scene* s) {
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.1f, 0.0f}, 0.1f};
  MADE(tb_create_circle_shape(s->box, &sd, &c), tb_shape_id_is_null);
}
static void do_create_capsule_shape(scene* s) {
  tb_shape_def sd = tb_default_shape_def();
  tb_capsule c = {{-0.1f, 0.0f}, {0.1f, 0.0f}, 0.1f};
  MADE(tb_create_capsule_shape(s->box, &sd, &c), tb_shape_id_is_null);
}
static void do_create_segment_shape(scene* s) {
  tb_shape_def sd = tb_default_shape_def();
  tb_segment g = {{-1.0f, 2.0f}, {1.0f, 2.0f}};
  MADE(tb_create_segment_shape(s->ground, &sd, &g), tb_shape_id_is_null);
}
static void do_create_polygon_shape(scene* s) {
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon p;
  OK(tb_make_offset_box(0.1f, 0.1f, (tb_vec2){0.1f, 0.1f}, 0.3f, &p));
  MADE(tb_create_polygon_shape(s->box, &sd, &p), tb_shape_id_is_null);
}
/* a sensor is a shape flag without a setter: a sensor shape must hash unlike
 * the same shape that pushes */
static void do_create_sensor_shape(scene* s) {
  tb_shape_def sd = tb_default_shape_def();
  sd.is_sensor = true;
  tb_circle c = {{0.1f, 0.0f}, 0.1f};
  MADE(tb_create_circle_shape(s->box, &sd, &c), tb_shape_id_is_null);
}
ONE_WAY(destroy_shape, tb_destroy_shape(s->box_shape))

/* chains: no setters of their own; their segments are shapes */
SETTER(chain_segment_set_friction, tb_shape_set_friction(s->chain_segment, 0.1f),
       tb_shape_set_friction(s->chain_segment, 0.6f))
SETTER(chain_segment_set_restitution, tb_shape_set_restitution(s->chain_segment, 0.5f),
       tb_shape_set_restitution(s->chain_segment, 0.0f))
SETTER(chain_segment_set_tangent_speed, tb_shape_set_tangent_speed(s->chain_segment, 1.0f),
       tb_shape_set_tangent_speed(s->chain_segment, 0.0f))
static void do_create_chain(scene* s) {
  tb_chain_def cd = tb_default_chain_def();
  const tb_vec2 points[2] = {{-4.0f, 3.0f}, {4.0f, 3.0f}};
  cd.points = points;
  cd.count = 2;
  MADE(tb_create_chain(s->ground, &cd), tb_chain_id_is_null);
}
ONE_WAY(destroy_chain, tb_destroy_chain(s->chain))

/* joints */
ONE_WAY(joint_set_collide_connected, tb_joint_set_collide_connected(s->revolute, true))
SETTER(joint_set_user_data, tb_joint_set_user_data(s->revolute, &token), tb_joint_set_user_data(s->revolute, NULL))
SETTER(distance_joint_set_length, tb_distance_joint_set_length(s->distance, 2.0f),
       tb_distance_joint_set_length(s->distance, 3.0f))
SETTER(distance_joint_set_spring, tb_distance_joint_set_spring(s->distance, true, 2.0f, 0.5f),
       tb_distance_joint_set_spring(s->distance, false, 0.0f, 0.0f))
SETTER(distance_joint_set_limits, tb_distance_joint_set_limits(s->distance, true, 1.0f, 4.0f),
       tb_distance_joint_set_limits(s->distance, false, 0.5f, 5.0f))
SETTER(revolute_joint_set_limits, tb_revolute_joint_set_limits(s->revolute, true, -0.5f, 0.5f),
       tb_revolute_joint_set_limits(s->revolute, false, -1.0f, 1.0f))
SETTER(revolute_joint_set_motor, tb_revolute_joint_set_motor(s->revolute, true, 1.0f, 10.0f),
       tb_revolute_joint_set_motor(s->revolute, false, 0.0f, 0.0f))
SETTER(revolute_joint_set_spring, tb_revolute_joint_set_spring(s->revolute, true, 2.0f, 0.1f),
       tb_revolute_joint_set_spring(s->revolute, false, 1.0f, 0.5f))
SETTER(prismatic_joint_set_limits, tb_prismatic_joint_set_limits(s->prismatic, true, -0.5f, 0.5f),
       tb_prismatic_joint_set_limits(s->prismatic, false, -1.0f, 1.0f))
SETTER(prismatic_joint_set_motor, tb_prismatic_joint_set_motor(s->prismatic, true, 1.0f, 10.0f),
       tb_prismatic_joint_set_motor(s->prismatic, false, 0.0f, 0.0f))
SETTER(prismatic_joint_set_spring, tb_prismatic_joint_set_spring(s->prismatic, true, 2.0f, 0.1f),
       tb_prismatic_joint_set_spring(s->prismatic, false, 1.0f, 0.5f))
SETTER(weld_joint_set_stiffness, tb_weld_joint_set_stiffness(s->weld, 5.0f, 0.5f, 0.0f, 0.0f),
       tb_weld_joint_set_stiffness(s->weld, 0.0f, 0.0f, 0.0f, 0.0f))
SETTER(weld_joint_set_angular_stiffness, tb_weld_joint_set_stiffness(s->weld, 0.0f, 0.0f, 5.0f, 0.5f),
       tb_weld_joint_set_stiffness(s->weld, 0.0f, 0.0f, 0.0f, 0.0f))
SETTER(wheel_joint_set_motor, tb_wheel_joint_set_motor(s->wheel, true, 1.0f, 10.0f),
       tb_wheel_joint_set_motor(s->wheel, false, 0.0f, 0.0f))
SETTER(wheel_joint_set_spring, tb_wheel_joint_set_spring(s->wheel, true, 2.0f, 0.5f),
       tb_wheel_joint_set_spring(s->wheel, true, 1.0f, 0.7f))
SETTER(mouse_joint_set_target, tb_mouse_joint_set_target(s->mouse, (tb_vec2){-34.0f, 6.0f}),
       tb_mouse_joint_set_target(s->mouse, (tb_vec2){-35.0f, 5.0f}))
SETTER(motor_joint_set_offsets, tb_motor_joint_set_offsets(s->motor, (tb_vec2){-38.0f, 6.0f}, 0.5f),
       tb_motor_joint_set_offsets(s->motor, (tb_vec2){-38.0f, 5.0f}, 0.0f))
static void do_create_joints(scene* s) {
  tb_body_id b = body_at(s->w, TB_DYNAMIC_BODY, (tb_vec2){-5.0f, 20.0f}, true);
  tb_revolute_joint_def rd = tb_default_revolute_joint_def();
  rd.body_a = s->ground;
  rd.body_b = b;
  rd.local_anchor_a = (tb_vec2){-5.0f, 20.0f};
  MADE(tb_create_revolute_joint(s->w, &rd), tb_joint_id_is_null);
}
static void do_create_joint_between_bodies(scene* s) {
  tb_weld_joint_def wd = tb_default_weld_joint_def();
  wd.body_a = s->box;
  wd.body_b = s->heavy;
  MADE(tb_create_weld_joint(s->w, &wd), tb_joint_id_is_null);
}
ONE_WAY(destroy_joint, tb_destroy_joint(s->revolute))

static const hash_case k_cases[] = {
    TWO_WAY_CASE(world_set_gravity),
    TWO_WAY_CASE(world_set_integrator),
    TWO_WAY_CASE(world_set_force_field),
    TWO_WAY_CASE(world_set_force_field_context),
    TWO_WAY_CASE(world_set_pre_solve),
    TWO_WAY_CASE(world_set_pre_solve_context),
    TWO_WAY_CASE(world_enable_sleeping),
    TWO_WAY_CASE(world_enable_continuous),
    TWO_WAY_CASE(world_enable_warm_starting),
    TWO_WAY_CASE(world_set_contact_tuning),
    TWO_WAY_CASE(world_set_contact_damping),
    TWO_WAY_CASE(world_set_contact_push),
    TWO_WAY_CASE(world_set_relax_iterations),
    TWO_WAY_CASE(world_set_joint_tuning),
    TWO_WAY_CASE(world_set_joint_damping),
    TWO_WAY_CASE(world_set_restitution_threshold),
    TWO_WAY_CASE(world_set_maximum_linear_speed),
    TWO_WAY_CASE(world_set_user_data),

    ONE_WAY_CASE(body_set_type),
    ONE_WAY_CASE(body_set_type_static),
    ONE_WAY_CASE(body_set_transform),
    TWO_WAY_CASE(body_set_linear_velocity),
    TWO_WAY_CASE(body_set_angular_velocity),
    TWO_WAY_CASE(body_set_linear_damping),
    TWO_WAY_CASE(body_set_angular_damping),
    TWO_WAY_CASE(body_set_gravity_scale),
    TWO_WAY_CASE(body_set_fixed_rotation),
    ONE_WAY_CASE(body_set_enabled),
    TWO_WAY_CASE(body_set_user_data),
    ONE_WAY_CASE(body_set_asleep),
    TWO_WAY_CASE(body_set_awake),
    TWO_WAY_CASE(body_enable_sleep),
    TWO_WAY_CASE(body_set_sleep_threshold),
    TWO_WAY_CASE(body_set_bullet),
    TWO_WAY_CASE(body_apply_force),
    TWO_WAY_CASE(body_apply_force_to_center),
    TWO_WAY_CASE(body_apply_torque),
    {"body_apply_linear_impulse", do_body_apply_linear_impulse, undo_velocities},
    {"body_apply_linear_impulse_to_center", do_body_apply_linear_impulse_to_center, undo_velocities},
    {"body_apply_angular_impulse", do_body_apply_angular_impulse, undo_velocities},
    ONE_WAY_CASE(body_set_mass_data),
    ONE_WAY_CASE(body_reset_mass_data),
    ONE_WAY_CASE(create_body),
    ONE_WAY_CASE(destroy_body),

    TWO_WAY_CASE(shape_set_density),
    ONE_WAY_CASE(shape_set_density_dynamic),
    TWO_WAY_CASE(shape_set_friction),
    TWO_WAY_CASE(shape_set_restitution),
    TWO_WAY_CASE(shape_set_rolling_resistance),
    TWO_WAY_CASE(shape_set_tangent_speed),
    ONE_WAY_CASE(shape_set_filter),
    ONE_WAY_CASE(shape_set_filter_group),
    TWO_WAY_CASE(shape_set_user_data),
    ONE_WAY_CASE(create_circle_shape),
    ONE_WAY_CASE(create_capsule_shape),
    ONE_WAY_CASE(create_segment_shape),
    ONE_WAY_CASE(create_polygon_shape),
    ONE_WAY_CASE(create_sensor_shape),
    ONE_WAY_CASE(destroy_shape),

    TWO_WAY_CASE(chain_segment_set_friction),
    TWO_WAY_CASE(chain_segment_set_restitution),
    TWO_WAY_CASE(chain_segment_set_tangent_speed),
    ONE_WAY_CASE(create_chain),
    ONE_WAY_CASE(destroy_chain),

    ONE_WAY_CASE(joint_set_collide_connected),
    TWO_WAY_CASE(joint_set_user_data),
    TWO_WAY_CASE(distance_joint_set_length),
    TWO_WAY_CASE(distance_joint_set_spring),
    TWO_WAY_CASE(distance_joint_set_limits),
    TWO_WAY_CASE(revolute_joint_set_limits),
    TWO_WAY_CASE(revolute_joint_set_motor),
    TWO_WAY_CASE(revolute_joint_set_spring),
    TWO_WAY_CASE(prismatic_joint_set_limits),
    TWO_WAY_CASE(prismatic_joint_set_motor),
    TWO_WAY_CASE(prismatic_joint_set_spring),
    TWO_WAY_CASE(weld_joint_set_stiffness),
    TWO_WAY_CASE(weld_joint_set_angular_stiffness),
    TWO_WAY_CASE(wheel_joint_set_motor),
    TWO_WAY_CASE(wheel_joint_set_spring),
    TWO_WAY_CASE(mouse_joint_set_target),
    TWO_WAY_CASE(motor_joint_set_offsets),
    ONE_WAY_CASE(create_joints),
    ONE_WAY_CASE(create_joint_between_bodies),
    ONE_WAY_CASE(destroy_joint),
};

#define CASE_COUNT ((int)(sizeof k_cases / sizeof k_cases[0]))

/* One case on a fresh scene: the call moves the hash; the undo restores it. */
START_TEST(every_change_moves_the_hash) {
  const hash_case* c = &k_cases[_i];
  scene s = make_scene();
  uint64_t before = tb_world_hash(s.w);
  ck_assert_uint_eq(tb_world_hash(s.w), before); /* reading it changes nothing */
  c->change(&s);
  uint64_t after = tb_world_hash(s.w);
  ck_assert_msg(after != before, "%s did not move the world hash (%016llx)", c->name, (unsigned long long)before);
  if (c->undo != NULL) {
    c->undo(&s);
    uint64_t back = tb_world_hash(s.w);
    ck_assert_msg(back == before, "%s and its undo: hash %016llx, not the original %016llx", c->name,
                  (unsigned long long)back, (unsigned long long)before);
  }
  tb_destroy_world(s.w);
}
END_TEST

/* Two worlds built alike hash alike, also in different world slots and after
 * stepping side by side; a step moves the hash. */
START_TEST(identical_worlds_hash_alike) {
  scene a = make_scene(), b = make_scene();
  ck_assert_uint_eq(tb_world_hash(a.w), tb_world_hash(b.w));
  uint64_t before = tb_world_hash(a.w);
  for (int i = 0; i < 30; ++i) {
    ck_assert_int_eq(tb_world_step(a.w, DT, SUBSTEPS), TB_OK);
    ck_assert_int_eq(tb_world_step(b.w, DT, SUBSTEPS), TB_OK);
    ck_assert_uint_eq(tb_world_hash(a.w), tb_world_hash(b.w));
  }
  ck_assert_uint_ne(tb_world_hash(a.w), before);
  tb_destroy_world(a.w);
  /* built again in the freed slot: the same bits as the world that stayed */
  scene c = make_scene();
  for (int i = 0; i < 30; ++i) ck_assert_int_eq(tb_world_step(c.w, DT, SUBSTEPS), TB_OK);
  ck_assert_uint_eq(tb_world_hash(c.w), tb_world_hash(b.w));
  tb_destroy_world(b.w);
  tb_destroy_world(c.w);
}
END_TEST

/* Every step moves the hash: over 2 s of the scene, while its bodies come to
 * rest and fall asleep, and in an empty world, where only the time advances. */
START_TEST(a_step_moves_the_hash) {
  scene s = make_scene();
  for (int i = 0; i < 120; ++i) {
    uint64_t before = tb_world_hash(s.w);
    ck_assert_int_eq(tb_world_step(s.w, DT, SUBSTEPS), TB_OK);
    ck_assert_uint_ne(tb_world_hash(s.w), before);
  }
  tb_destroy_world(s.w);
  tb_world_id empty = tbt_world(0.0f, -10.0f);
  uint64_t before = tb_world_hash(empty);
  ck_assert_int_eq(tb_world_step(empty, DT, SUBSTEPS), TB_OK);
  ck_assert_uint_ne(tb_world_hash(empty), before);
  tb_destroy_world(empty);
}
END_TEST

/* What carries over from one step to the next without a setter of its own:
 * the impulses contacts and joints keep for warm starting, the rest timers,
 * the broad phase's fat boxes. Poked from inside (white box): each change
 * moves the hash, and the old value restores it. */
#define POKE(type, field, value)                                                                 \
  do {                                                                                           \
    type old_ = (field);                                                                         \
    (field) = (value);                                                                           \
    ck_assert_msg(tb_world_hash(s.w) != before, "%s is not in the hash", #field);                \
    (field) = old_;                                                                              \
    ck_assert_msg(tb_world_hash(s.w) == before, "%s: the old value gives another hash", #field); \
  } while (0)

START_TEST(carried_state_is_hashed) {
  scene s = make_scene();
  tb_world* w = tb_world_get(s.w, "test");
  uint64_t before = tb_world_hash(s.w);
  /* the box's contact with the ground */
  int key = tb_body_at(w, s.box.index1 - 1)->contact_list;
  ck_assert_int_ge(key, 0);
  tb_contact* c = (tb_contact*)tb_pool_at(&w->contacts, key >> 1);
  ck_assert_int_gt(c->manifold.point_count, 0);
  POKE(float, c->manifold.points[0].normal_impulse, c->manifold.points[0].normal_impulse + 1.0f);
  POKE(float, c->manifold.points[0].tangent_impulse, c->manifold.points[0].tangent_impulse + 1.0f);
  POKE(uint32_t, c->manifold.points[0].id, c->manifold.points[0].id + 1u);
  POKE(float, c->rolling_impulse, c->rolling_impulse + 1.0f);
  POKE(float, c->impact_depth, c->impact_depth + 1.0e-3f);
  POKE(float, c->friction, c->friction + 1.0f);
  POKE(uint32_t, c->flags, c->flags ^ (uint32_t)TB_CONTACT_ENABLED);
  /* a joint's accumulated impulses and the substep they belong to */
  tb_joint* j = tb_joint_at(w, s.revolute.index1 - 1);
  POKE(float, j->linear_impulse.x, j->linear_impulse.x + 1.0f);
  POKE(float, j->spring_impulse, j->spring_impulse + 1.0f);
  POKE(float, j->lower_impulse, j->lower_impulse + 1.0f);
  POKE(float, j->last_h, j->last_h * 2.0f);
  /* a body's rest timer, the rounding its centre carries, its awake slot */
  tb_body* b = tb_body_at(w, s.box.index1 - 1);
  POKE(float, b->sleep_time, b->sleep_time + 0.25f);
  POKE(float, b->center_residual.x, b->center_residual.x + 1.0e-9f);
  POKE(float, b->angle_residual, b->angle_residual + 1.0e-9f);
  POKE(int, w->awake[0], w->awake[1]);
  /* the fat box of the box's proxy */
  const tb_shape* sh = tb_shape_at(w, s.box_shape.index1 - 1);
  tb_tree_node* leaf = &w->broad_phase.trees[sh->tree].nodes[sh->proxy];
  POKE(float, leaf->aabb.upper.x, leaf->aabb.upper.x + 1.0f);
  tb_destroy_world(s.w);
}
END_TEST

/* User data and callback contexts are the caller's pointers, different on
 * every run (ASLR): the hash sees only whether one is set, so two runs of the
 * same program agree. */
START_TEST(user_pointers_count_as_set_or_not) {
  static int other;
  scene s = make_scene();
  uint64_t none = tb_world_hash(s.w);
  ck_assert_int_eq(tb_body_set_user_data(s.box, &token), TB_OK);
  uint64_t one = tb_world_hash(s.w);
  ck_assert_uint_ne(one, none);
  ck_assert_int_eq(tb_body_set_user_data(s.box, &other), TB_OK);
  ck_assert_uint_eq(tb_world_hash(s.w), one);
  tb_destroy_world(s.w);
}
END_TEST

static Suite* world_hash_suite(void) {
  Suite* s = suite_create("world_hash");
  TCase* tc = tcase_create("world_hash");
  tcase_add_loop_test(tc, every_change_moves_the_hash, 0, CASE_COUNT);
  tcase_add_test(tc, identical_worlds_hash_alike);
  tcase_add_test(tc, a_step_moves_the_hash);
  tcase_add_test(tc, carried_state_is_hashed);
  tcase_add_test(tc, user_pointers_count_as_set_or_not);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(world_hash_suite)
