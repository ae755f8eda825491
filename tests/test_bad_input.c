/* Bad input everywhere: each rejected call returns its documented error, the
 * message names the argument, and the world's hash is the same afterwards. */
#include <string.h>

#include "test_util.h"

static tb_world_id W;
static tb_body_id DYN, STAT, DEAD_BODY;
static tb_shape_id BOX, DEAD_SHAPE;
static uint64_t HASH;
/* W's twin, built by the same calls: a test that only makes refused calls on
 * W leaves TWIN_CHECK set, and W must then still equal its twin, also 600
 * steps later (state the hash does not see would show there). */
static tb_world_id TWIN;
static bool TWIN_CHECK;

/* The scene in world w; the handles kept are those of the last call. */
static void build(tb_world_id w) {
  DYN = tbt_box_body(w, 0.0f, 5.0f, 0.5f, 0.5f);
  tb_body_def bd = tb_default_body_def();
  STAT = tb_create_body(w, &bd);
  ck_assert_int_eq(tb_body_get_shapes(DYN, &BOX, 1), 1);
  tb_body_id doomed = tbt_box_body(w, 3.0f, 5.0f, 0.5f, 0.5f);
  tb_shape_id doomed_shape;
  tb_body_get_shapes(doomed, &doomed_shape, 1);
  DEAD_SHAPE = doomed_shape;
  tb_destroy_shape(doomed_shape);
  DEAD_BODY = doomed;
  tb_destroy_body(doomed);
  tb_body_apply_force_to_center(DYN, (tb_vec2){1.0f, 2.0f}); /* pending force is state too */
  tb_world_step(w, 1.0f / 60.0f, 4);
}

static void setup(void) {
  W = tbt_world(0.0f, -10.0f);
  TWIN = tbt_world(0.0f, -10.0f);
  build(TWIN);
  build(W);
  HASH = tb_world_hash(W);
  TWIN_CHECK = true;
}

/* W equals its twin now and 600 steps later (a test that goes on to change
 * W on purpose calls this first). */
static void check_twin(void) {
  TWIN_CHECK = false;
  ck_assert_msg(tb_world_hash(W) == tb_world_hash(TWIN), "the refused calls changed the world");
  for (int i = 0; i < 600; ++i) {
    tb_world_step(W, 1.0f / 60.0f, 4);
    tb_world_step(TWIN, 1.0f / 60.0f, 4);
  }
  ck_assert_msg(tb_world_hash(W) == tb_world_hash(TWIN), "the refused calls changed the world's later steps");
}

static void teardown(void) {
  if (TWIN_CHECK && tb_world_is_valid(W)) check_twin();
  tb_destroy_world(TWIN);
  tb_destroy_world(W);
}

/* What a call returned when it returns a tb_result, else `code`: _Generic
 * evaluates only the branch it picks, so the call runs once either way. */
#define RETURNED(call, code) _Generic((call), tb_result : (call), default : ((void)(call), (code)))
_Static_assert(_Generic(tb_destroy_world((tb_world_id){0, 0}), tb_result : 1, default : 0) &&
                   !_Generic(tb_world_get_counts((tb_world_id){0, 0}), tb_result : 1, default : 0),
               "RETURNED tells tb_result calls from the others");

/* Evaluate a call that must be rejected with `code` (recorded, and returned
 * when the call returns a tb_result), name `word` in its message, and leave
 * the world as it was. */
#define REJECT(call, code, word)                                                                                   \
  do {                                                                                                             \
    tb_clear_error();                                                                                              \
    tb_result returned_ = RETURNED(call, code);                                                                    \
    ck_assert_msg(returned_ == (code), "%s: returned %s, want %s (%s)", #call, tb_result_name(returned_),          \
                  tb_result_name(code), tb_last_error());                                                          \
    ck_assert_msg(tb_last_result() == (code), "%s: got %s, want %s (%s)", #call, tb_result_name(tb_last_result()), \
                  tb_result_name(code), tb_last_error());                                                          \
    ck_assert_msg(strstr(tb_last_error(), (word)) != NULL, "%s: message '%s' lacks '%s'", #call, tb_last_error(),  \
                  (word));                                                                                         \
    ck_assert_msg(tb_world_hash(W) == HASH, "%s changed the world", #call);                                        \
  } while (0)

static const float bad_reals[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f};
#define N_BAD (int)(sizeof bad_reals / sizeof bad_reals[0])
/* ... and what no quantity that must be >= 0 accepts */
static const float bad_non_negatives[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, -1.0f, -1e-30f};
#define N_BAD_NN (int)(sizeof bad_non_negatives / sizeof bad_non_negatives[0])

START_TEST(world_calls) {
  REJECT(tb_create_world(NULL), TB_ERR_NULL_ARGUMENT, "def");
  tb_world_def wd = tb_default_world_def();
  for (int i = 0; i < N_BAD; ++i) {
    wd.gravity = (tb_vec2){0.0f, bad_reals[i]};
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "gravity");
    REJECT(tb_world_set_gravity(W, wd.gravity), TB_ERR_INVALID_ARGUMENT, "gravity");
  }
  wd = tb_default_world_def();
  wd.integrator = (tb_integrator)7;
  REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "integrator");
  REJECT(tb_world_set_integrator(W, (tb_integrator)-1), TB_ERR_INVALID_ARGUMENT, "integrator");
  const float bad_steps[] = {0.0f, -1.0f / 60.0f, NAN, INFINITY, -INFINITY, 2.0f, 1e30f};
  for (int i = 0; i < 7; ++i) REJECT(tb_world_step(W, bad_steps[i], 4), TB_ERR_INVALID_ARGUMENT, "time_step");
  const int bad_substeps[] = {0, -1, 65, 1000000};
  for (int i = 0; i < 4; ++i)
    REJECT(tb_world_step(W, 1.0f / 60.0f, bad_substeps[i]), TB_ERR_INVALID_ARGUMENT, "substeps");
  const tb_world_id null_world = {0, 0}, garbage = {999, 3};
  REJECT(tb_world_step(null_world, 1.0f / 60.0f, 4), TB_ERR_STALE_HANDLE, "world");
  REJECT(tb_world_step(garbage, 1.0f / 60.0f, 4), TB_ERR_STALE_HANDLE, "world");
  REJECT(tb_world_get_gravity(garbage), TB_ERR_STALE_HANDLE, "world");
  REJECT(tb_world_get_counts(null_world), TB_ERR_STALE_HANDLE, "world");
  REJECT(tb_create_body(garbage, NULL), TB_ERR_STALE_HANDLE, "world");
}
END_TEST

START_TEST(destroyed_world) {
  tb_world_id other = tbt_world(0.0f, 0.0f);
  tb_body_id ob = tbt_box_body(other, 0, 0, 1, 1);
  tb_shape_id os;
  tb_body_get_shapes(ob, &os, 1);
  ck_assert_int_eq(tb_destroy_world(other), TB_OK);
  REJECT(tb_destroy_world(other), TB_ERR_STALE_HANDLE, "world");
  REJECT(tb_world_step(other, 1.0f / 60.0f, 1), TB_ERR_STALE_HANDLE, "destroyed");
  REJECT(tb_body_get_position(ob), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_shape_get_density(os), TB_ERR_STALE_HANDLE, "shape");
  /* a new world in the same slot does not revive the old handles */
  tb_world_id again = tbt_world(0.0f, 0.0f);
  ck_assert(!tb_world_is_valid(other));
  REJECT(tb_world_step(other, 1.0f / 60.0f, 1), TB_ERR_STALE_HANDLE, "destroyed");
  ck_assert(!tb_body_is_valid(ob));
  tb_destroy_world(again);
}
END_TEST

START_TEST(body_creation) {
  REJECT(tb_create_body(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  tb_body_def bd = tb_default_body_def();
  bd.type = (tb_body_type)5;
  REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "type");
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    bd = tb_default_body_def();
    bd.position.x = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "position");
    bd = tb_default_body_def();
    bd.angle = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "angle");
    bd = tb_default_body_def();
    bd.linear_velocity.y = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "linear_velocity");
    bd = tb_default_body_def();
    bd.angular_velocity = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "angular_velocity");
    bd = tb_default_body_def();
    bd.gravity_scale = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "gravity_scale");
    bd = tb_default_body_def();
    bd.linear_damping = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "linear_damping");
  }
  bd = tb_default_body_def();
  bd.angular_damping = -1.0f;
  REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "angular_damping");
  ck_assert(tb_body_id_is_null(tb_create_body(W, &bd)));
}
END_TEST

START_TEST(body_calls) {
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    tb_vec2 v = {x, 0.0f};
    REJECT(tb_body_set_transform(DYN, v, 0.0f), TB_ERR_INVALID_ARGUMENT, "position");
    REJECT(tb_body_set_transform(DYN, (tb_vec2){0, 0}, x), TB_ERR_INVALID_ARGUMENT, "angle");
    REJECT(tb_body_set_linear_velocity(DYN, v), TB_ERR_INVALID_ARGUMENT, "v =");
    REJECT(tb_body_set_angular_velocity(DYN, x), TB_ERR_INVALID_ARGUMENT, "w =");
    REJECT(tb_body_set_linear_damping(DYN, x), TB_ERR_INVALID_ARGUMENT, "damping");
    REJECT(tb_body_set_angular_damping(DYN, x), TB_ERR_INVALID_ARGUMENT, "damping");
    REJECT(tb_body_set_gravity_scale(DYN, x), TB_ERR_INVALID_ARGUMENT, "scale");
    REJECT(tb_body_apply_force(DYN, v, (tb_vec2){0, 0}), TB_ERR_INVALID_ARGUMENT, "force");
    REJECT(tb_body_apply_force(DYN, (tb_vec2){1, 0}, v), TB_ERR_INVALID_ARGUMENT, "world_point");
    REJECT(tb_body_apply_force_to_center(DYN, v), TB_ERR_INVALID_ARGUMENT, "force");
    REJECT(tb_body_apply_torque(DYN, x), TB_ERR_INVALID_ARGUMENT, "torque");
    REJECT(tb_body_apply_linear_impulse(DYN, v, (tb_vec2){0, 0}), TB_ERR_INVALID_ARGUMENT, "impulse");
    REJECT(tb_body_apply_linear_impulse(DYN, (tb_vec2){1, 0}, v), TB_ERR_INVALID_ARGUMENT, "world_point");
    REJECT(tb_body_apply_linear_impulse_to_center(DYN, v), TB_ERR_INVALID_ARGUMENT, "impulse");
    REJECT(tb_body_apply_angular_impulse(DYN, x), TB_ERR_INVALID_ARGUMENT, "impulse");
    REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){x, {0, 0}, 1.0f})), TB_ERR_INVALID_ARGUMENT, "mass");
    REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){1.0f, {0, 0}, x})), TB_ERR_INVALID_ARGUMENT, "inertia");
    REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){1.0f, v, 1.0f})), TB_ERR_INVALID_ARGUMENT, "center");
    REJECT(tb_body_get_world_point(DYN, v), TB_ERR_INVALID_ARGUMENT, "local_point");
    REJECT(tb_body_get_local_point(DYN, v), TB_ERR_INVALID_ARGUMENT, "world_point");
    REJECT(tb_body_get_world_vector(DYN, v), TB_ERR_INVALID_ARGUMENT, "local_vector");
    REJECT(tb_body_get_local_vector(DYN, v), TB_ERR_INVALID_ARGUMENT, "world_vector");
    REJECT(tb_body_get_angular_momentum(DYN, v), TB_ERR_INVALID_ARGUMENT, "world_point");
    REJECT(tb_body_get_point_velocity(DYN, v), TB_ERR_INVALID_ARGUMENT, "world_point");
  }
  REJECT(tb_body_set_linear_damping(DYN, -0.5f), TB_ERR_INVALID_ARGUMENT, "damping");
  REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){0.0f, {0, 0}, 1.0f})), TB_ERR_INVALID_ARGUMENT, "mass");
  REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){-1.0f, {0, 0}, 1.0f})), TB_ERR_INVALID_ARGUMENT, "mass");
  REJECT(tb_body_set_mass_data(DYN, ((tb_mass_data){1.0f, {0, 0}, -1.0f})), TB_ERR_INVALID_ARGUMENT, "inertia");
  REJECT(tb_body_set_mass_data(STAT, ((tb_mass_data){1.0f, {0, 0}, 1.0f})), TB_ERR_WRONG_BODY_TYPE, "dynamic");
  REJECT(tb_body_set_type(DYN, (tb_body_type)3), TB_ERR_INVALID_ARGUMENT, "type");
  /* an impulse whose result overflows TB_MAX_VALUE is refused whole */
  check_twin();
  tb_body_id light = tbt_box_body(W, 7.0f, 0.0f, 0.01f, 0.01f); /* 4e-4 kg */
  HASH = tb_world_hash(W);
  REJECT(tb_body_apply_linear_impulse_to_center(light, ((tb_vec2){1e18f, 0.0f})), TB_ERR_INVALID_ARGUMENT, "overflow");
  tb_shape_id out;
  REJECT(tb_body_get_shapes(DYN, NULL, 4), TB_ERR_NULL_ARGUMENT, "out");
  (void)out;
}
END_TEST

/* Every body function on a destroyed body, and on a null handle. */
START_TEST(stale_bodies) {
  const tb_body_id handles[2] = {DEAD_BODY, {0, 0, 0}};
  for (int i = 0; i < 2; ++i) {
    tb_body_id b = handles[i];
    tb_vec2 o = {0, 0};
    ck_assert(!tb_body_is_valid(b));
    REJECT(tb_destroy_body(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_world(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_type(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_type(b, TB_DYNAMIC_BODY), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_position(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_angle(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_rotation(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_transform(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_transform(b, o, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_local_center(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_world_center(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_linear_velocity(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_linear_velocity(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_angular_velocity(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_angular_velocity(b, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_point_velocity(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_linear_damping(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_linear_damping(b, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_angular_damping(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_angular_damping(b, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_gravity_scale(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_gravity_scale(b, 1.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_is_fixed_rotation(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_fixed_rotation(b, true), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_is_enabled(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_enabled(b, false), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_user_data(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_user_data(b, NULL), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_force(b, o, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_force_to_center(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_torque(b, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_linear_impulse(b, o, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_linear_impulse_to_center(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_apply_angular_impulse(b, 0.0f), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_force(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_torque(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_mass(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_rotational_inertia(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_mass_data(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_set_mass_data(b, ((tb_mass_data){1, {0, 0}, 1})), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_reset_mass_data(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_world_point(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_local_point(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_world_vector(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_local_vector(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_kinetic_energy(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_linear_momentum(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_angular_momentum(b, o), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_shape_count(b), TB_ERR_STALE_HANDLE, "body");
    REJECT(tb_body_get_shapes(b, NULL, 0), TB_ERR_STALE_HANDLE, "body");
    tb_shape_def sd = tb_default_shape_def();
    tb_circle c = {{0, 0}, 1};
    REJECT(tb_create_circle_shape(b, &sd, &c), TB_ERR_STALE_HANDLE, "body");
  }
}
END_TEST

START_TEST(shape_creation) {
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0, 0}, 0.5f};
  REJECT(tb_create_circle_shape(DYN, NULL, &c), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_circle_shape(DYN, &sd, NULL), TB_ERR_NULL_ARGUMENT, "geometry");
  /* the other shape types, NULL def and NULL geometry */
  tb_capsule cap0 = {{0, 0}, {1, 0}, 0.2f};
  tb_segment seg0 = {{0, 0}, {1, 0}};
  tb_polygon box0;
  ck_assert_int_eq(tb_make_box(0.5f, 0.5f, &box0), TB_OK);
  REJECT(tb_create_capsule_shape(DYN, NULL, &cap0), TB_ERR_NULL_ARGUMENT, "tb_create_capsule_shape: def");
  REJECT(tb_create_capsule_shape(DYN, &sd, NULL), TB_ERR_NULL_ARGUMENT, "tb_create_capsule_shape: the geometry");
  REJECT(tb_create_segment_shape(DYN, NULL, &seg0), TB_ERR_NULL_ARGUMENT, "tb_create_segment_shape: def");
  REJECT(tb_create_segment_shape(DYN, &sd, NULL), TB_ERR_NULL_ARGUMENT, "tb_create_segment_shape: the geometry");
  REJECT(tb_create_polygon_shape(DYN, NULL, &box0), TB_ERR_NULL_ARGUMENT, "tb_create_polygon_shape: def");
  REJECT(tb_create_polygon_shape(DYN, &sd, NULL), TB_ERR_NULL_ARGUMENT, "tb_create_polygon_shape: the geometry");
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    sd = tb_default_shape_def();
    sd.density = x;
    REJECT(tb_create_circle_shape(DYN, &sd, &c), TB_ERR_INVALID_ARGUMENT, "density");
    sd = tb_default_shape_def();
    sd.friction = x;
    REJECT(tb_create_circle_shape(DYN, &sd, &c), TB_ERR_INVALID_ARGUMENT, "friction");
    sd = tb_default_shape_def();
    sd.restitution = x;
    REJECT(tb_create_circle_shape(DYN, &sd, &c), TB_ERR_INVALID_ARGUMENT, "restitution");
    sd = tb_default_shape_def();
    tb_circle bc = {{x, 0}, 0.5f};
    REJECT(tb_create_circle_shape(DYN, &sd, &bc), TB_ERR_INVALID_ARGUMENT, "center");
    bc = (tb_circle){{0, 0}, x};
    REJECT(tb_create_circle_shape(DYN, &sd, &bc), TB_ERR_INVALID_ARGUMENT, "radius");
    tb_capsule cap = {{0, 0}, {1, x}, 0.2f};
    REJECT(tb_create_capsule_shape(DYN, &sd, &cap), TB_ERR_INVALID_ARGUMENT, "capsule");
    tb_segment seg = {{x, 0}, {1, 0}};
    REJECT(tb_create_segment_shape(DYN, &sd, &seg), TB_ERR_INVALID_ARGUMENT, "segment");
  }
  sd = tb_default_shape_def();
  sd.density = -1.0f;
  REJECT(tb_create_circle_shape(DYN, &sd, &c), TB_ERR_INVALID_ARGUMENT, "density");
  sd = tb_default_shape_def();
  tb_circle zero = {{0, 0}, 0.0f}, neg = {{0, 0}, -1.0f};
  REJECT(tb_create_circle_shape(DYN, &sd, &zero), TB_ERR_INVALID_ARGUMENT, "radius");
  REJECT(tb_create_circle_shape(DYN, &sd, &neg), TB_ERR_INVALID_ARGUMENT, "radius");
  tb_capsule same = {{1, 1}, {1, 1}, 0.2f};
  REJECT(tb_create_capsule_shape(DYN, &sd, &same), TB_ERR_INVALID_ARGUMENT, "coincide");
  tb_capsule thin = {{0, 0}, {1, 0}, 0.0f};
  REJECT(tb_create_capsule_shape(DYN, &sd, &thin), TB_ERR_INVALID_ARGUMENT, "radius");
  tb_segment dot = {{2, 2}, {2, 2}};
  REJECT(tb_create_segment_shape(DYN, &sd, &dot), TB_ERR_INVALID_ARGUMENT, "coincide");
  /* a huge density makes the mass overflow */
  sd.density = 1e18f;
  tb_circle big = {{0, 0}, 1e6f};
  REJECT(tb_create_circle_shape(DYN, &sd, &big), TB_ERR_INVALID_ARGUMENT, "overflow");
}
END_TEST

/* Polygons filled by hand must still be what tb_make_polygon makes. */
START_TEST(hand_made_polygons) {
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon p;
  tb_make_box(1.0f, 1.0f, &p);
  tb_polygon bad = p;
  bad.count = 2;
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "count");
  bad.count = TB_MAX_POLYGON_VERTICES + 1;
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "count");
  bad = p; /* clockwise order */
  for (int i = 0; i < 4; ++i) bad.vertices[i] = p.vertices[3 - i];
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "convex");
  bad = p; /* not convex: a vertex pulled inside */
  bad.vertices[2] = (tb_vec2){0.0f, 0.0f};
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "convex");
  bad = p; /* duplicate vertices */
  bad.vertices[1] = bad.vertices[0];
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "convex");
  bad = p;
  bad.vertices[1].x = NAN;
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "vertex");
  bad = p;
  bad.normals[0] = (tb_vec2){0.0f, -2.0f};
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "normals");
  bad = p;
  bad.radius = -1.0f;
  REJECT(tb_create_polygon_shape(DYN, &sd, &bad), TB_ERR_DEGENERATE_POLYGON, "radius");
}
END_TEST

START_TEST(shape_calls) {
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    REJECT(tb_shape_set_density(BOX, x), TB_ERR_INVALID_ARGUMENT, "tb_shape_set_density: density");
    REJECT(tb_shape_set_friction(BOX, x), TB_ERR_INVALID_ARGUMENT, "tb_shape_set_friction: friction");
    REJECT(tb_shape_set_restitution(BOX, x), TB_ERR_INVALID_ARGUMENT, "tb_shape_set_restitution: restitution");
    REJECT(tb_shape_set_rolling_resistance(BOX, x), TB_ERR_INVALID_ARGUMENT,
           "tb_shape_set_rolling_resistance: rolling_resistance");
  }
  for (int i = 0; i < N_BAD; ++i)
    REJECT(tb_shape_set_tangent_speed(BOX, bad_reals[i]), TB_ERR_INVALID_ARGUMENT, "tb_shape_set_tangent_speed: speed");
  tb_circle c;
  REJECT(tb_shape_get_circle(BOX, &c), TB_ERR_INVALID_ARGUMENT, "type");
  tb_polygon p;
  /* every geometry getter with a NULL out, on a shape of its own type */
  tb_shape_def sd = tb_default_shape_def();
  check_twin();
  tb_shape_id circle = tb_create_circle_shape(DYN, &sd, &(tb_circle){{0, 0}, 0.25f});
  tb_shape_id capsule = tb_create_capsule_shape(DYN, &sd, &(tb_capsule){{0, 0}, {0.5f, 0}, 0.25f});
  tb_shape_id segment = tb_create_segment_shape(DYN, &sd, &(tb_segment){{0, 0}, {0.5f, 0}});
  ck_assert(tb_shape_is_valid(circle) && tb_shape_is_valid(capsule) && tb_shape_is_valid(segment));
  HASH = tb_world_hash(W);
  REJECT(tb_shape_get_circle(circle, NULL), TB_ERR_NULL_ARGUMENT, "tb_shape_get_circle: out");
  REJECT(tb_shape_get_capsule(capsule, NULL), TB_ERR_NULL_ARGUMENT, "tb_shape_get_capsule: out");
  REJECT(tb_shape_get_segment(segment, NULL), TB_ERR_NULL_ARGUMENT, "tb_shape_get_segment: out");
  REJECT(tb_shape_get_polygon(BOX, NULL), TB_ERR_NULL_ARGUMENT, "tb_shape_get_polygon: out");
  const tb_shape_id handles[2] = {DEAD_SHAPE, {0, 0, 0}};
  for (int i = 0; i < 2; ++i) {
    tb_shape_id s = handles[i];
    ck_assert(!tb_shape_is_valid(s));
    REJECT(tb_destroy_shape(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_type(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_body(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_density(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_density(s, 1.0f), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_friction(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_friction(s, 1.0f), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_restitution(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_restitution(s, 1.0f), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_user_data(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_user_data(s, NULL), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_mass_data(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_aabb(s), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_polygon(s, &p), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_capsule(s, NULL), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_segment(s, NULL), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_circle(s, &c), TB_ERR_STALE_HANDLE, "shape");
  }
}
END_TEST

/* A stale handle whose slot was reused by a new object stays stale. */
START_TEST(reused_slots) {
  tb_body_id fresh = tbt_box_body(W, 9.0f, 9.0f, 0.5f, 0.5f);
  tbt_box_body(TWIN, 9.0f, 9.0f, 0.5f, 0.5f);       /* the twin too: it stays W's twin */
  ck_assert_int_eq(fresh.index1, DEAD_BODY.index1); /* the freed slot came back */
  ck_assert(!tb_body_is_valid(DEAD_BODY));
  uint64_t h = tb_world_hash(W);
  tb_clear_error();
  ck_assert_int_eq(tb_body_set_linear_velocity(DEAD_BODY, (tb_vec2){1, 1}), TB_ERR_STALE_HANDLE);
  ck_assert_uint_eq(tb_world_hash(W), h);
  ck_assert_float_eq(tb_body_get_linear_velocity(fresh).x, 0.0f);
}
END_TEST

START_TEST(errors_are_recorded_on_the_world) {
  tb_body_set_linear_damping(DYN, -1.0f);
  ck_assert_ptr_nonnull(strstr(tb_world_last_error(W), "tb_body_set_linear_damping"));
  ck_assert_ptr_nonnull(strstr(tb_world_last_error(W), "damping = -1"));
  ck_assert_str_eq(tb_result_name(TB_ERR_STALE_HANDLE), "TB_ERR_STALE_HANDLE");
  tb_clear_error();
  ck_assert_str_eq(tb_last_error(), "");
  ck_assert_int_eq(tb_last_result(), TB_OK);
}
END_TEST

static Suite* bad_input_suite(void) {
  Suite* s = suite_create("bad_input");
  TCase* tc = tcase_create("bad_input");
  tcase_add_checked_fixture(tc, setup, teardown);
  tcase_add_test(tc, world_calls);
  tcase_add_test(tc, destroyed_world);
  tcase_add_test(tc, body_creation);
  tcase_add_test(tc, body_calls);
  tcase_add_test(tc, stale_bodies);
  tcase_add_test(tc, shape_creation);
  tcase_add_test(tc, hand_made_polygons);
  tcase_add_test(tc, shape_calls);
  tcase_add_test(tc, reused_slots);
  tcase_add_test(tc, errors_are_recorded_on_the_world);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(bad_input_suite)
