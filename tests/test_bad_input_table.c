/* Bad input, table-driven (issue 7): the calls tests/test_bad_input.c does not
 * cover (joints, chains, queries, world settings, polygons, collision, geometry
 * and distance queries, sleep and contact getters), each with every bad value
 * of its tables. Each rejected call
 * returns its documented error, names the argument in tb_last_error(), and
 * leaves tb_world_hash and the counts as they were. Also: stale and foreign
 * handles, calls into the world from inside callbacks, and a NaN from the
 * force field that must stay in its body. */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

static tb_world_id W, OTHER;
/* W's twin: built by the same calls. A test that only makes refused calls on W
 * leaves TWIN_CHECK set, and teardown then holds W to its twin, also after
 * 600 more steps, so a refusal that changed anything the hash does not see
 * shows up too. */
static tb_world_id TWIN;
static bool TWIN_CHECK;
static tb_body_id GROUND, A, B, C, FOREIGN_BODY, DEAD_BODY;
static tb_shape_id BOX, CHAIN_SEG;
static tb_chain_id CHAIN, DEAD_CHAIN;
static tb_joint_id JD, JR, JP, JW, JH, JM, JO, DEAD_JOINT; /* distance, revolute, ..., wHeel, Mouse, mOtor */
static uint64_t HASH;
static tb_counts COUNTS;

static void snapshot(void) {
  HASH = tb_world_hash(W);
  COUNTS = tb_world_get_counts(W);
}

/* The scene, in world w (bodies of another world go to OTHER); the handles
 * kept are those of the last call. */
static void build(tb_world_id w) {
  tb_body_def bd = tb_default_body_def();
  GROUND = tb_create_body(w, &bd);
  const tb_vec2 ground_points[4] = {{-20, 0}, {-5, 0}, {5, 0}, {20, 0}};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = ground_points;
  cd.count = 4;
  CHAIN = tb_create_chain(GROUND, &cd);
  ck_assert(!tb_chain_id_is_null(CHAIN));
  ck_assert_int_eq(tb_chain_get_segments(CHAIN, &CHAIN_SEG, 1), 1);
  DEAD_CHAIN = tb_create_chain(GROUND, &cd);
  ck_assert_int_eq(tb_destroy_chain(DEAD_CHAIN), TB_OK);
  A = tbt_box_body(w, 0.0f, 2.0f, 0.5f, 0.5f);
  B = tbt_box_body(w, 2.0f, 2.0f, 0.5f, 0.5f);
  C = tbt_box_body(w, 4.0f, 0.45f, 0.5f, 0.5f); /* resting on the chain: a contact */
  ck_assert_int_eq(tb_body_get_shapes(A, &BOX, 1), 1);
  DEAD_BODY = tbt_box_body(w, 9.0f, 2.0f, 0.5f, 0.5f);
  FOREIGN_BODY = tbt_box_body(OTHER, 0.0f, 2.0f, 0.5f, 0.5f);

  tb_distance_joint_def dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = B;
  dd.length = 2.0f;
  JD = tb_create_distance_joint(w, &dd);
  tb_revolute_joint_def rd = tb_default_revolute_joint_def();
  rd.body_a = A;
  rd.body_b = B;
  JR = tb_create_revolute_joint(w, &rd);
  tb_prismatic_joint_def pd = tb_default_prismatic_joint_def();
  pd.body_a = A;
  pd.body_b = B;
  JP = tb_create_prismatic_joint(w, &pd);
  tb_weld_joint_def wd = tb_default_weld_joint_def();
  wd.body_a = B;
  wd.body_b = C;
  JW = tb_create_weld_joint(w, &wd);
  tb_wheel_joint_def hd = tb_default_wheel_joint_def();
  hd.body_a = GROUND;
  hd.body_b = C;
  JH = tb_create_wheel_joint(w, &hd);
  tb_mouse_joint_def md = tb_default_mouse_joint_def();
  md.body_a = GROUND;
  md.body_b = A;
  md.target = (tb_vec2){0.0f, 2.0f};
  JM = tb_create_mouse_joint(w, &md);
  tb_motor_joint_def od = tb_default_motor_joint_def();
  od.body_a = GROUND;
  od.body_b = B;
  JO = tb_create_motor_joint(w, &od);
  DEAD_JOINT = tb_create_revolute_joint(w, &rd);
  const tb_joint_id all[] = {JD, JR, JP, JW, JH, JM, JO, DEAD_JOINT};
  for (int i = 0; i < 8; ++i) ck_assert(tb_joint_is_valid(all[i]));
  ck_assert_int_eq(tb_destroy_joint(DEAD_JOINT), TB_OK);
  ck_assert_int_eq(tb_destroy_body(DEAD_BODY), TB_OK);
  tb_body_apply_force_to_center(A, (tb_vec2){1.0f, 2.0f});
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
}

static void setup(void) {
  W = tbt_world(0.0f, -10.0f);
  OTHER = tbt_world(0.0f, -10.0f);
  TWIN = tbt_world(0.0f, -10.0f);
  build(TWIN);
  build(W);
  snapshot();
  TWIN_CHECK = true;
}

/* W still equals its twin, and does after 600 steps of both (a test that
 * goes on to change W on purpose calls this first). */
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
  if (TWIN_CHECK) check_twin();
  tb_destroy_world(TWIN);
  tb_destroy_world(W);
  if (tb_world_is_valid(OTHER)) tb_destroy_world(OTHER);
}

static void assert_unchanged(const char* what) {
  ck_assert_msg(tb_world_hash(W) == HASH, "%s changed the world (hash)", what);
  tb_counts c = tb_world_get_counts(W);
  ck_assert_msg(c.body_count == COUNTS.body_count && c.shape_count == COUNTS.shape_count &&
                    c.joint_count == COUNTS.joint_count && c.step_count == COUNTS.step_count,
                "%s changed the counts", what);
}

/* What a call returned when it returns a tb_result, else `code`: _Generic
 * evaluates only the branch it picks, so the call runs once either way. */
#define RETURNED(call, code) _Generic((call), tb_result : (call), default : ((void)(call), (code)))
_Static_assert(_Generic(tb_destroy_world((tb_world_id){0, 0}), tb_result : 1, default : 0) &&
                   !_Generic(tb_world_get_counts((tb_world_id){0, 0}), tb_result : 1, default : 0),
               "RETURNED tells tb_result calls from the others");

/* A call that must be rejected with `code` (recorded, and returned when the
 * call returns a tb_result), name `word` in its message and leave the world
 * as it was. */
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
    assert_unchanged(#call);                                                                                       \
  } while (0)

/* The same for the world's tuning calls (their checks are shared by the
 * world definition and the setters, which name the argument each way). */
#define REJECT_WORLD_NAME(call, code, fn, word)                                                                   \
  do {                                                                                                            \
    REJECT(call, code, fn);                                                                                       \
    ck_assert_msg(strstr(tb_last_error(), (word)) != NULL, "%s: message '%s' lacks '%s'", #call, tb_last_error(), \
                  (word));                                                                                        \
  } while (0)

/* The values no real parameter accepts, and the lengths no length accepts. */
static const float bad_reals[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f};
#define N_BAD (int)(sizeof bad_reals / sizeof bad_reals[0])
static const float bad_sizes[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, 0.0f, -1.0f};
#define N_BAD_SIZES (int)(sizeof bad_sizes / sizeof bad_sizes[0])
static const float bad_non_negatives[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, -1.0f, -1e-30f};
#define N_BAD_NN (int)(sizeof bad_non_negatives / sizeof bad_non_negatives[0])

/* ---- world -------------------------------------------------------------- */

START_TEST(world_settings) {
  const char* ct = "tb_world_set_contact_tuning";
  const char* jt = "tb_world_set_joint_tuning";
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    float x = bad_sizes[i];
    REJECT_WORLD_NAME(tb_world_set_contact_tuning(W, x, 10.0f, 3.0f), TB_ERR_INVALID_ARGUMENT, ct, "hertz");
    REJECT_WORLD_NAME(tb_world_set_joint_tuning(W, x, 2.0f), TB_ERR_INVALID_ARGUMENT, jt, "hertz");
    REJECT(tb_world_set_maximum_linear_speed(W, x), TB_ERR_INVALID_ARGUMENT, "speed");
  }
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    REJECT_WORLD_NAME(tb_world_set_contact_tuning(W, 30.0f, x, 3.0f), TB_ERR_INVALID_ARGUMENT, ct, "damping_ratio");
    REJECT_WORLD_NAME(tb_world_set_contact_tuning(W, 30.0f, 10.0f, x), TB_ERR_INVALID_ARGUMENT, ct,
                      "push_max_velocity");
    REJECT_WORLD_NAME(tb_world_set_joint_tuning(W, 60.0f, x), TB_ERR_INVALID_ARGUMENT, jt, "damping_ratio");
    REJECT(tb_world_set_restitution_threshold(W, x), TB_ERR_INVALID_ARGUMENT, "speed");
  }
  /* the same fields through the definition */
  for (int i = 0; i < N_BAD_NN; ++i) {
    tb_world_def wd = tb_default_world_def();
    wd.contact_hertz = bad_non_negatives[i];
    REJECT_WORLD_NAME(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "tb_create_world", "contact_hertz");
    wd = tb_default_world_def();
    wd.contact_push_max_velocity = bad_non_negatives[i];
    REJECT_WORLD_NAME(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "tb_create_world", "contact_push_max_velocity");
    wd = tb_default_world_def();
    wd.joint_damping_ratio = bad_non_negatives[i];
    REJECT_WORLD_NAME(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "tb_create_world", "joint_damping_ratio");
    wd = tb_default_world_def();
    wd.hit_event_threshold = bad_non_negatives[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "hit_event_threshold");
    wd = tb_default_world_def();
    wd.maximum_linear_speed = bad_non_negatives[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "maximum_linear_speed");
    wd = tb_default_world_def();
    wd.restitution_threshold = bad_non_negatives[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "restitution_threshold");
  }
  /* gravity: finite and no longer than TB_MAX_GRAVITY (7072 on both axes is 10001 m/s^2 long) */
  const tb_vec2 bad_gravity[] = {{0, -1e6f},    {7072.0f, -7072.0f}, {NAN, 0},
                                 {0, INFINITY}, {1e30f, 0},          {-1e30f, -1e30f}};
  for (int i = 0; i < 6; ++i) {
    REJECT(tb_world_set_gravity(W, bad_gravity[i]), TB_ERR_INVALID_ARGUMENT, "gravity");
    tb_world_def wd = tb_default_world_def();
    wd.gravity = bad_gravity[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "def->gravity");
  }
  /* the time step and the substeps at and around their limits */
  const float bad_steps[] = {0.0f, -0.0f, -1e-30f, 1.0000001f, NAN, -NAN};
  for (int i = 0; i < 6; ++i) REJECT(tb_world_step(W, bad_steps[i], 4), TB_ERR_INVALID_ARGUMENT, "time_step");
  /* steps longer than the solver keeps stable (issue 23: up to 1 s was
   * taken, and a car reached 1.6e13 m/s) */
  const float long_steps[] = {nextafterf(TB_MAX_TIME_STEP, INFINITY), 0.1f, 0.5f, 1.0f};
  for (int i = 0; i < 4; ++i)
    for (int sub = 1; sub <= 64; sub *= 4)
      REJECT(tb_world_step(W, long_steps[i], sub), TB_ERR_INVALID_ARGUMENT, "TB_MAX_TIME_STEP");
  const int bad_substeps[] = {0, -1, 65, 2147483647, -2147483647 - 1};
  for (int i = 0; i < 5; ++i)
    REJECT(tb_world_step(W, 1.0f / 60.0f, bad_substeps[i]), TB_ERR_INVALID_ARGUMENT, "substeps");
  /* steps too short for the solver (issue 23): 1e-45 (whose reciprocal is
   * infinite) and FLT_MIN were taken, and every step then failed with
   * TB_ERR_NUMERIC; a substep below TB_MIN_SUBSTEP is refused, and the
   * message says why. TB_MIN_SUBSTEP itself is accepted. */
  const float short_steps[] = {1e-45f, FLT_MIN, 1e-20f, 0.5f * TB_MIN_SUBSTEP};
  for (int i = 0; i < 4; ++i)
    REJECT(tb_world_step(W, short_steps[i], 1), TB_ERR_INVALID_ARGUMENT, "below TB_MIN_SUBSTEP");
  REJECT(tb_world_step(W, 2.0f * TB_MIN_SUBSTEP, 4), TB_ERR_INVALID_ARGUMENT, "4 substeps");
  /* the speed cap beyond TB_MAX_SPEED, where a step can carry a body out of
   * the world (it took up to TB_MAX_VALUE) */
  const float fast[] = {nextafterf(TB_MAX_SPEED, INFINITY), 1e9f, TB_MAX_VALUE};
  for (int i = 0; i < 3; ++i) {
    REJECT(tb_world_set_maximum_linear_speed(W, fast[i]), TB_ERR_INVALID_ARGUMENT, "TB_MAX_SPEED");
    tb_world_def wd = tb_default_world_def();
    wd.maximum_linear_speed = fast[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "TB_MAX_SPEED");
  }
  /* the relax passes: the same integer range checks, as setter and as field */
  const int bad_relax[] = {0, -1, TB_MAX_RELAX_ITERATIONS + 1, 2147483647, -2147483647 - 1};
  for (int i = 0; i < 5; ++i) {
    REJECT(tb_world_set_relax_iterations(W, bad_relax[i]), TB_ERR_INVALID_ARGUMENT, "iterations");
    tb_world_def wd = tb_default_world_def();
    wd.relax_iterations = bad_relax[i];
    REJECT(tb_create_world(&wd), TB_ERR_INVALID_ARGUMENT, "relax_iterations");
  }
}
END_TEST

/* Every world function on a destroyed world, a null handle and garbage. */
START_TEST(stale_worlds) {
  tb_world_id dead = tbt_world(0.0f, 0.0f);
  ck_assert_int_eq(tb_destroy_world(dead), TB_OK);
  const tb_world_id handles[] = {dead, {0, 0}, {60000, 1}, {1, 65535}};
  for (int i = 0; i < 4; ++i) {
    tb_world_id w = handles[i];
    ck_assert(!tb_world_is_valid(w));
    REJECT(tb_destroy_world(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_gravity(w, (tb_vec2){0, 0}), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_gravity(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_integrator(w, TB_INTEGRATOR_RK4), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_integrator(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_force_field(w, NULL, NULL), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_pre_solve(w, NULL, NULL), TB_ERR_STALE_HANDLE, "world");
    tb_debug_draw dd0 = tb_default_debug_draw();
    REJECT(tb_world_draw(w, &dd0), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_time(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_enable_sleeping(w, false), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_is_sleeping_enabled(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_enable_continuous(w, false), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_is_continuous_enabled(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_enable_warm_starting(w, false), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_enable_profile(w, true), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_is_profile_enabled(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_contact_tuning(w, 30, 10, 3), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_joint_tuning(w, 60, 2), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_relax_iterations(w, 4), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_relax_iterations(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_restitution_threshold(w, 1), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_maximum_linear_speed(w, 1), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_user_data(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_set_user_data(w, NULL), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_counts(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_profile(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_hash(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_contact_events(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_sensor_events(w), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_get_byte_count(w), TB_ERR_STALE_HANDLE, "world");
    tb_memory_stats stats = {.total = 1};
    REJECT(tb_world_get_memory_stats(w, &stats), TB_ERR_STALE_HANDLE, "world");
    ck_assert_uint_eq(stats.total, 0);
    tb_body_def bd = tb_default_body_def();
    REJECT(tb_create_body(w, &bd), TB_ERR_STALE_HANDLE, "world");
    tb_distance_joint_def dd = tb_default_distance_joint_def();
    dd.body_a = A;
    dd.body_b = B;
    REJECT(tb_create_distance_joint(w, &dd), TB_ERR_STALE_HANDLE, "world");
    tb_query_filter f = tb_default_query_filter();
    REJECT(tb_world_cast_ray_closest(w, (tb_vec2){0, 0}, (tb_vec2){1, 0}, f), TB_ERR_STALE_HANDLE, "world");
    REJECT(tb_world_overlap_aabb(w, ((tb_aabb){{0, 0}, {1, 1}}), f, NULL, NULL), TB_ERR_STALE_HANDLE, "world");
    ck_assert_uint_eq(tb_world_hash(w), 0);
  }
}
END_TEST

/* The global settings (allocator, log, assert, length units): NULL hooks
 * and bad units are refused first, then any change while a world exists
 * (here W, its twin and OTHER); the settings stay as they were. */
START_TEST(global_settings) {
  REJECT(tb_set_allocator(NULL, tb_default_free, NULL), TB_ERR_NULL_ARGUMENT, "alloc is NULL");
  REJECT(tb_set_allocator(tb_default_alloc, NULL, NULL), TB_ERR_NULL_ARGUMENT, "free is NULL");
  REJECT(tb_set_allocator(NULL, NULL, NULL), TB_ERR_NULL_ARGUMENT, "tb_set_allocator");
  REJECT(tb_set_allocator(tb_default_alloc, tb_default_free, NULL), TB_ERR_LOCKED, "no world exists");
  REJECT(tb_set_log_function(NULL, NULL), TB_ERR_LOCKED, "tb_set_log_function");
  REJECT(tb_set_assert_function(NULL, NULL), TB_ERR_LOCKED, "tb_set_assert_function");
  const float bad_units[] = {NAN, INFINITY, -INFINITY, 0.0f, -1.0f, -100.0f, 1e-4f, 1e4f, 1e30f};
  for (int i = 0; i < (int)(sizeof bad_units / sizeof bad_units[0]); ++i)
    REJECT(tb_set_length_units_per_meter(bad_units[i]), TB_ERR_INVALID_ARGUMENT, "units_per_meter");
  REJECT(tb_set_length_units_per_meter(100.0f), TB_ERR_LOCKED, "tb_set_length_units_per_meter");
  REJECT(tb_set_length_units_per_meter(1.0f), TB_ERR_LOCKED, "no world exists");
  ck_assert_float_eq(tb_get_length_units_per_meter(), 1.0f);
  REJECT(tb_world_get_memory_stats(W, NULL), TB_ERR_NULL_ARGUMENT, "stats");
  ck_assert_uint_gt(tb_world_get_byte_count(W), 0);
}
END_TEST

static void never_drawn_polygon(tb_transform xf, const tb_vec2* v, int n, float r, tb_color c, void* context) {
  (void)xf, (void)v, (void)n, (void)r, (void)c, (void)context;
  ck_abort_msg("a refused draw called the game");
}

static void never_drawn_segment(tb_vec2 p1, tb_vec2 p2, tb_color c, void* context) {
  (void)p1, (void)p2, (void)c, (void)context;
  ck_abort_msg("a refused draw called the game");
}

/* The debug-draw settings: every bad number of each field, and NULL. */
START_TEST(draw_settings) {
  REJECT(tb_world_draw(W, NULL), TB_ERR_NULL_ARGUMENT, "draw");
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    tb_debug_draw d = tb_default_debug_draw();
    d.normal_length = bad_sizes[i];
    REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, "normal_length");
    d = tb_default_debug_draw();
    d.point_size = bad_sizes[i];
    REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, "point_size");
  }
  for (int i = 0; i < N_BAD; ++i) { /* 1e30 too: the world ends at TB_MAX_LENGTH */
    tb_debug_draw d = tb_default_debug_draw();
    d.use_drawing_bounds = true;
    d.drawing_bounds = (tb_aabb){{bad_reals[i], 0.0f}, {1.0f, 1.0f}};
    REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, "drawing_bounds");
    d.drawing_bounds = (tb_aabb){{0.0f, 0.0f}, {1.0f, bad_reals[i]}};
    REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, "drawing_bounds");
  }
  tb_debug_draw d = tb_default_debug_draw();
  d.use_drawing_bounds = true;
  d.drawing_bounds = (tb_aabb){{0.0f, 1.0f}, {1.0f, 0.0f}}; /* lower.y > upper.y */
  REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, "drawing_bounds");
  /* every component of every colour in [0, 1]: NaN, infinite or out-of-range
   * colours never reach the game's callbacks */
  const char* const color_names[] = {
      "static_body",   "kinematic_body", "awake_body", "asleep_body",   "bullet_body",       "disabled_body",  "sensor",
      "sensor_active", "joint",          "aabb",       "contact_point", "speculative_point", "contact_normal", "text"};
  _Static_assert(sizeof(tb_debug_colors) == 14 * sizeof(tb_color), "14 colours");
  const float bad_components[] = {NAN, INFINITY, -INFINITY, -0.01f, 1.01f};
  for (int c = 0; c < 14; ++c) {
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < 5; ++i) {
        d = tb_default_debug_draw();
        d.draw_solid_polygon = never_drawn_polygon;
        d.draw_segment = never_drawn_segment;
        tb_color* colors = &d.colors.static_body;
        float* part = &colors[c].r + k;
        *part = bad_components[i];
        char word[64];
        snprintf(word, sizeof word, "colors.%s.%c", color_names[c], "rgba"[k]);
        REJECT(tb_world_draw(W, &d), TB_ERR_INVALID_ARGUMENT, word);
      }
    }
  }
}
END_TEST

/* ---- polygons and boxes ---------------------------------------------------- */

typedef struct polygon_case {
  const char* what;
  tb_vec2 points[12];
  int count;
  float radius;
  tb_result code;
  const char* word;
} polygon_case;

static const polygon_case polygon_cases[] = {
    {"two points", {{0, 0}, {1, 0}}, 2, 0.0f, TB_ERR_DEGENERATE_POLYGON, "count"},
    {"negative count", {{0, 0}, {1, 0}, {0, 1}}, -3, 0.0f, TB_ERR_DEGENERATE_POLYGON, "count"},
    {"duplicates", {{1, 1}, {1, 1}, {1, 1}, {1, 1}}, 4, 0.0f, TB_ERR_DEGENERATE_POLYGON, "distinct"},
    {"near duplicates",
     {{0, 0}, {0.001f, 0}, {0, 0.001f}, {0.001f, 0.001f}},
     4,
     0.0f,
     TB_ERR_DEGENERATE_POLYGON,
     "distinct"},
    {"collinear", {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {-4, -4}}, 5, 0.0f, TB_ERR_DEGENERATE_POLYGON, "collinear"},
    {"nearly collinear", {{0, 0}, {10, 0}, {5, 0.001f}}, 3, 0.0f, TB_ERR_DEGENERATE_POLYGON, "collinear"},
    {"zero area sliver", {{0, 0}, {0.012f, 0}, {0.006f, 0.003f}}, 3, 0.0f, TB_ERR_DEGENERATE_POLYGON, "area"},
    {"nine-gon",
     {{1, 0},
      {0.766f, 0.643f},
      {0.174f, 0.985f},
      {-0.5f, 0.866f},
      {-0.940f, 0.342f},
      {-0.940f, -0.342f},
      {-0.5f, -0.866f},
      {0.174f, -0.985f},
      {0.766f, -0.643f}},
     9,
     0.0f,
     TB_ERR_TOO_MANY_VERTICES,
     "vertices"},
    {"NaN point", {{0, 0}, {1, 0}, {NAN, 1}}, 3, 0.0f, TB_ERR_INVALID_ARGUMENT, "points[2]"},
    {"infinite point", {{0, 0}, {INFINITY, 0}, {0, 1}}, 3, 0.0f, TB_ERR_INVALID_ARGUMENT, "points[1]"},
    {"huge point", {{0, 0}, {1, 0}, {0, 1e30f}}, 3, 0.0f, TB_ERR_INVALID_ARGUMENT, "points[2]"},
    {"negative radius", {{0, 0}, {1, 0}, {0, 1}}, 3, -0.1f, TB_ERR_INVALID_ARGUMENT, "radius"},
    {"NaN radius", {{0, 0}, {1, 0}, {0, 1}}, 3, NAN, TB_ERR_INVALID_ARGUMENT, "radius"},
    {"huge radius", {{0, 0}, {1, 0}, {0, 1}}, 3, 1e30f, TB_ERR_INVALID_ARGUMENT, "radius"},
};

START_TEST(make_polygon_table) {
  for (size_t i = 0; i < sizeof polygon_cases / sizeof polygon_cases[0]; ++i) {
    const polygon_case* c = &polygon_cases[i];
    tb_polygon out;
    memset(&out, 0x5a, sizeof out);
    tb_polygon before = out;
    tb_clear_error();
    ck_assert_msg(tb_make_polygon(c->points, c->count, c->radius, &out) == c->code, "%s: got %s (%s)", c->what,
                  tb_result_name(tb_last_result()), tb_last_error());
    ck_assert_msg(tb_last_result() == c->code, "%s", c->what);
    ck_assert_msg(strstr(tb_last_error(), c->word) != NULL, "%s: '%s' lacks '%s'", c->what, tb_last_error(), c->word);
    ck_assert_msg(memcmp(&out, &before, sizeof out) == 0, "%s: out was written", c->what);
  }
  tb_polygon out;
  REJECT(tb_make_polygon(NULL, 3, 0.0f, &out), TB_ERR_NULL_ARGUMENT, "points");
  REJECT(tb_make_polygon(polygon_cases[0].points, 3, 0.0f, NULL), TB_ERR_NULL_ARGUMENT, "out");
  /* boxes: every size, centre and angle argument */
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    float x = bad_sizes[i];
    /* each box maker names itself (offset and rounded boxes said "tb_make_box") */
    REJECT(tb_make_box(x, 1.0f, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_box: hx");
    REJECT(tb_make_box(1.0f, x, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_box: hy");
    REJECT(tb_make_offset_box(x, 1.0f, (tb_vec2){0, 0}, 0.0f, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_offset_box: hx");
    REJECT(tb_make_offset_box(1.0f, x, (tb_vec2){0, 0}, 0.0f, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_offset_box: hy");
    REJECT(tb_make_rounded_box(x, 1.0f, 0.1f, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_rounded_box: hx");
    REJECT(tb_make_rounded_box(1.0f, x, 0.1f, &out), TB_ERR_INVALID_ARGUMENT, "tb_make_rounded_box: hy");
  }
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    REJECT(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){x, 0}, 0.0f, &out), TB_ERR_INVALID_ARGUMENT,
           "tb_make_offset_box: center");
    REJECT(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){0, x}, 0.0f, &out), TB_ERR_INVALID_ARGUMENT,
           "tb_make_offset_box: center");
    if (isfinite(x)) continue; /* any finite angle is an angle */
    REJECT(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){0, 0}, x, &out), TB_ERR_INVALID_ARGUMENT,
           "tb_make_offset_box: angle");
  }
  for (int i = 0; i < N_BAD_NN; ++i)
    REJECT(tb_make_rounded_box(1.0f, 1.0f, bad_non_negatives[i], &out), TB_ERR_INVALID_ARGUMENT,
           "tb_make_rounded_box: radius");
  REJECT(tb_make_box(1.0f, 1.0f, NULL), TB_ERR_NULL_ARGUMENT, "tb_make_box: out");
  REJECT(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){0, 0}, 0.0f, NULL), TB_ERR_NULL_ARGUMENT, "tb_make_offset_box: out");
  REJECT(tb_make_rounded_box(1.0f, 1.0f, 0.1f, NULL), TB_ERR_NULL_ARGUMENT, "tb_make_rounded_box: out");
  /* a box too thin for a float at its centre collapses: it must be refused, not
   * handed out as a polygon that no shape accepts */
  REJECT(tb_make_offset_box(0.001f, 0.001f, (tb_vec2){9e6f, 9e6f}, 0.3f, &out), TB_ERR_DEGENERATE_POLYGON,
         "tb_make_offset_box: a box");
  ck_assert_int_eq(tb_make_offset_box(0.5f, 0.001f, (tb_vec2){1, 2}, 0.3f, &out), TB_OK); /* a 2 mm card is fine */
}
END_TEST

/* Hand-made polygons that no hull could be: tb_create_polygon_shape must refuse them. */
START_TEST(hand_made_polygon_table) {
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, &box), TB_OK);
  tb_polygon pentagon;
  const tb_vec2 ring[5] = {{1, 0}, {0.309f, 0.951f}, {-0.809f, 0.588f}, {-0.809f, -0.588f}, {0.309f, -0.951f}};
  ck_assert_int_eq(tb_make_polygon(ring, 5, 0.0f, &pentagon), TB_OK);
  tb_shape_def sd = tb_default_shape_def();

  /* a pentagram: the pentagon's vertices in star order turn left at every
   * corner but wind twice around the centre */
  tb_polygon star = pentagon;
  for (int i = 0; i < 5; ++i) {
    tb_vec2 a = pentagon.vertices[(2 * i) % 5], b = pentagon.vertices[(2 * i + 2) % 5];
    tb_vec2 e = {b.x - a.x, b.y - a.y};
    float len = sqrtf(e.x * e.x + e.y * e.y);
    star.vertices[i] = a;
    star.normals[i] = (tb_vec2){e.y / len, -e.x / len};
  }
  REJECT(tb_create_polygon_shape(A, &sd, &star), TB_ERR_DEGENERATE_POLYGON, "convex");
  /* unit normals that do not belong to their edges */
  tb_polygon turned = box;
  for (int i = 0; i < 4; ++i) turned.normals[i] = box.normals[(i + 1) % 4];
  REJECT(tb_create_polygon_shape(A, &sd, &turned), TB_ERR_DEGENERATE_POLYGON, "normals");
  tb_polygon inward = box;
  for (int i = 0; i < 4; ++i) inward.normals[i] = (tb_vec2){-box.normals[i].x, -box.normals[i].y};
  REJECT(tb_create_polygon_shape(A, &sd, &inward), TB_ERR_DEGENERATE_POLYGON, "normals");
  /* a centroid that is not the polygon's */
  tb_polygon off = box;
  off.centroid = (tb_vec2){5.0f, 0.0f};
  REJECT(tb_create_polygon_shape(A, &sd, &off), TB_ERR_DEGENERATE_POLYGON, "centroid");
  off.centroid = (tb_vec2){NAN, 0.0f};
  REJECT(tb_create_polygon_shape(A, &sd, &off), TB_ERR_DEGENERATE_POLYGON, "centroid");
  /* collinear and zero-area hand-made polygons */
  tb_polygon flat = box;
  flat.vertices[1] =
      (tb_vec2){(box.vertices[0].x + box.vertices[2].x) * 0.5f, (box.vertices[0].y + box.vertices[2].y) * 0.5f};
  REJECT(tb_create_polygon_shape(A, &sd, &flat), TB_ERR_DEGENERATE_POLYGON, "convex");
  tb_polygon dot = box;
  for (int i = 0; i < 4; ++i) dot.vertices[i] = (tb_vec2){3.0f, 3.0f};
  REJECT(tb_create_polygon_shape(A, &sd, &dot), TB_ERR_DEGENERATE_POLYGON, "convex");
  tb_polygon big = box;
  big.count = -1;
  REJECT(tb_create_polygon_shape(A, &sd, &big), TB_ERR_DEGENERATE_POLYGON, "count");
  check_twin();
  /* the real ones are accepted (and tb_make_polygon's output is never refused) */
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(A, &sd, &pentagon)));
}
END_TEST

START_TEST(mass_and_collide_functions) {
  tb_circle circle = {{0, 0}, 1.0f};
  tb_capsule capsule = {{0, 0}, {1, 0}, 0.5f};
  tb_polygon box;
  tb_make_box(1, 1, &box);
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    REJECT(tb_compute_circle_mass(&circle, x), TB_ERR_INVALID_ARGUMENT, "density");
    REJECT(tb_compute_capsule_mass(&capsule, x), TB_ERR_INVALID_ARGUMENT, "density");
    REJECT(tb_compute_polygon_mass(&box, x), TB_ERR_INVALID_ARGUMENT, "density");
  }
  REJECT(tb_compute_circle_mass(NULL, 1.0f), TB_ERR_NULL_ARGUMENT, "circle");
  REJECT(tb_compute_capsule_mass(NULL, 1.0f), TB_ERR_NULL_ARGUMENT, "capsule");
  REJECT(tb_compute_polygon_mass(NULL, 1.0f), TB_ERR_NULL_ARGUMENT, "polygon");
  tb_circle bad_circle = {{0, 0}, -1.0f};
  REJECT(tb_compute_circle_mass(&bad_circle, 1.0f), TB_ERR_INVALID_ARGUMENT, "radius");

  /* manifolds: NULL shapes and non-finite transforms give an empty manifold */
  tb_transform id = {{0, 0}, {1, 0}};
  tb_segment segment = {{-1, 0}, {1, 0}};
  tb_chain_segment chain = {{-2, 0}, {{-1, 0}, {1, 0}}, {2, 0}};
  for (int i = 0; i < N_BAD; ++i) {
    tb_transform bad = {{bad_reals[i], 0}, {1, 0}};
    tb_transform bad_rot = {{0, 0}, {bad_reals[i], 0}};
    tb_manifold m;
#define EMPTY(call)                                                           \
  do {                                                                        \
    tb_clear_error();                                                         \
    m = (call);                                                               \
    ck_assert_msg(m.point_count == 0, "%s: %d points", #call, m.point_count); \
    ck_assert_msg(tb_last_result() != TB_OK, "%s: no error recorded", #call); \
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "transform"));              \
  } while (0)
    EMPTY(tb_collide_circles(&circle, bad, &circle, id));
    EMPTY(tb_collide_circles(&circle, id, &circle, bad_rot));
    EMPTY(tb_collide_capsule_and_circle(&capsule, bad, &circle, id));
    EMPTY(tb_collide_capsules(&capsule, id, &capsule, bad));
    EMPTY(tb_collide_segment_and_circle(&segment, bad_rot, &circle, id));
    EMPTY(tb_collide_segment_and_capsule(&segment, id, &capsule, bad));
    EMPTY(tb_collide_segment_and_polygon(&segment, bad, &box, id));
    EMPTY(tb_collide_polygon_and_circle(&box, id, &circle, bad));
    EMPTY(tb_collide_polygon_and_capsule(&box, bad, &capsule, id));
    EMPTY(tb_collide_polygons(&box, id, &box, bad_rot));
    EMPTY(tb_collide_chain_segment_and_circle(&chain, bad, &circle, id));
    EMPTY(tb_collide_chain_segment_and_capsule(&chain, id, &capsule, bad));
    EMPTY(tb_collide_chain_segment_and_polygon(&chain, bad_rot, &box, id));
#undef EMPTY
  }
  tb_clear_error();
  ck_assert_int_eq(tb_collide_polygons(NULL, id, &box, id).point_count, 0);
  ck_assert_int_eq(tb_last_result(), TB_ERR_NULL_ARGUMENT);
  tb_clear_error();
  ck_assert_int_eq(tb_collide_chain_segment_and_circle(&chain, id, NULL, id).point_count, 0);
  ck_assert_int_eq(tb_last_result(), TB_ERR_NULL_ARGUMENT);

  /* bad shapes: every collide function checks its shapes as the mass and
   * shape functions do (a polygon of count 100 overflowed the stack, 9 read
   * past the vertices, NaN circles gave TB_OK) and gives an empty manifold */
#define REJECT_COLLIDE(call, code, arg, word)                                                                      \
  do {                                                                                                             \
    tb_clear_error();                                                                                              \
    tb_manifold m_ = (call);                                                                                       \
    ck_assert_msg(m_.point_count == 0, "%s: %d points", #call, m_.point_count);                                    \
    ck_assert_msg(tb_last_result() == (code), "%s: got %s, want %s (%s)", #call, tb_result_name(tb_last_result()), \
                  tb_result_name(code), tb_last_error());                                                          \
    ck_assert_msg(strstr(tb_last_error(), (arg)) != NULL && strstr(tb_last_error(), (word)) != NULL,               \
                  "%s: message '%s' lacks '%s' or '%s'", #call, tb_last_error(), (arg), (word));                   \
    assert_unchanged(#call);                                                                                       \
  } while (0)
  const tb_result bad = TB_ERR_INVALID_ARGUMENT;
  /* NULL shapes, each argument of each function */
  const tb_result null = TB_ERR_NULL_ARGUMENT;
  REJECT_COLLIDE(tb_collide_circles(NULL, id, &circle, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_circles(&circle, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_capsule_and_circle(NULL, id, &circle, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_capsule_and_circle(&capsule, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_capsules(NULL, id, &capsule, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_capsules(&capsule, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_circle(NULL, id, &circle, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_circle(&segment, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_capsule(NULL, id, &capsule, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_capsule(&segment, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_polygon(NULL, id, &box, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_segment_and_polygon(&segment, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_polygon_and_circle(NULL, id, &circle, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_polygon_and_circle(&box, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_polygon_and_capsule(NULL, id, &capsule, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_polygon_and_capsule(&box, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_polygons(NULL, id, &box, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_polygons(&box, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_circle(NULL, id, &circle, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_circle(&chain, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_capsule(NULL, id, &capsule, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_capsule(&chain, id, NULL, id), null, "shape b", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_polygon(NULL, id, &box, id), null, "shape a", "NULL");
  REJECT_COLLIDE(tb_collide_chain_segment_and_polygon(&chain, id, NULL, id), null, "shape b", "NULL");

  /* circles: NaN, infinite or huge centres; NaN, infinite, huge, zero or negative radii */
  tb_circle bad_circles[N_BAD + N_BAD_SIZES];
  const char* circle_words[N_BAD + N_BAD_SIZES];
  for (int i = 0; i < N_BAD; ++i) {
    bad_circles[i] = (tb_circle){{bad_reals[i], 0}, 1.0f};
    circle_words[i] = "circle center";
  }
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    bad_circles[N_BAD + i] = (tb_circle){{0, 0}, bad_sizes[i]};
    circle_words[N_BAD + i] = "circle radius";
  }
  for (int i = 0; i < N_BAD + N_BAD_SIZES; ++i) {
    const tb_circle* c = &bad_circles[i];
    const char* w = circle_words[i];
    REJECT_COLLIDE(tb_collide_circles(c, id, &circle, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_circles(&circle, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_capsule_and_circle(&capsule, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_segment_and_circle(&segment, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_polygon_and_circle(&box, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_chain_segment_and_circle(&chain, id, c, id), bad, "shape b", w);
  }

  /* capsules: a NaN, infinite or huge end; NaN, infinite, huge, zero or negative radii; one point */
  tb_capsule bad_capsules[N_BAD + N_BAD_SIZES + 1];
  const char* capsule_words[N_BAD + N_BAD_SIZES + 1];
  for (int i = 0; i < N_BAD; ++i) {
    bad_capsules[i] = (tb_capsule){{0, 0}, {1, bad_reals[i]}, 0.5f};
    capsule_words[i] = "capsule centers";
  }
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    bad_capsules[N_BAD + i] = (tb_capsule){{0, 0}, {1, 0}, bad_sizes[i]};
    capsule_words[N_BAD + i] = "capsule radius";
  }
  bad_capsules[N_BAD + N_BAD_SIZES] = (tb_capsule){{1, 1}, {1, 1}, 0.5f};
  capsule_words[N_BAD + N_BAD_SIZES] = "coincide";
  for (int i = 0; i < N_BAD + N_BAD_SIZES + 1; ++i) {
    const tb_capsule* c = &bad_capsules[i];
    const char* w = capsule_words[i];
    REJECT_COLLIDE(tb_collide_capsule_and_circle(c, id, &circle, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_capsules(c, id, &capsule, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_capsules(&capsule, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_segment_and_capsule(&segment, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_polygon_and_capsule(&box, id, c, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_chain_segment_and_capsule(&chain, id, c, id), bad, "shape b", w);
  }

  /* segments and chain segments: a NaN, infinite or huge end; one point; bad ghost vertices */
  for (int i = 0; i <= N_BAD; ++i) {
    tb_segment s = {{i < N_BAD ? bad_reals[i] : 1.0f, 0}, {1, 0}};
    const char* w = i < N_BAD ? "segment points" : "coincide";
    REJECT_COLLIDE(tb_collide_segment_and_circle(&s, id, &circle, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_segment_and_capsule(&s, id, &capsule, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_segment_and_polygon(&s, id, &box, id), bad, "shape a", w);
    tb_chain_segment cs = chain;
    cs.segment = s;
    REJECT_COLLIDE(tb_collide_chain_segment_and_circle(&cs, id, &circle, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_chain_segment_and_capsule(&cs, id, &capsule, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_chain_segment_and_polygon(&cs, id, &box, id), bad, "shape a", w);
    if (i == N_BAD) continue;
    cs = chain;
    (i % 2 ? &cs.ghost1 : &cs.ghost2)->y = bad_reals[i];
    REJECT_COLLIDE(tb_collide_chain_segment_and_circle(&cs, id, &circle, id), bad, "shape a", "ghost");
    REJECT_COLLIDE(tb_collide_chain_segment_and_capsule(&cs, id, &capsule, id), bad, "shape a", "ghost");
    REJECT_COLLIDE(tb_collide_chain_segment_and_polygon(&cs, id, &box, id), bad, "shape a", "ghost");
  }

  /* polygons: counts outside 3..TB_MAX_POLYGON_VERTICES (9 read past the
   * arrays, 100 overflowed the stack), NaN, infinite or huge vertices, bad
   * radii, and a clockwise (hand-made) one */
  const int bad_counts[] = {0, 2, TB_MAX_POLYGON_VERTICES + 1, 100, -1};
  enum { N_COUNTS = sizeof bad_counts / sizeof bad_counts[0] };
  tb_polygon bad_polygons[N_COUNTS + N_BAD + N_BAD_NN + 1];
  const char* polygon_words[N_COUNTS + N_BAD + N_BAD_NN + 1];
  int n_polygons = 0;
  for (int i = 0; i < N_COUNTS; ++i) {
    bad_polygons[n_polygons] = box;
    bad_polygons[n_polygons].count = bad_counts[i];
    polygon_words[n_polygons++] = "polygon count";
  }
  for (int i = 0; i < N_BAD; ++i) {
    bad_polygons[n_polygons] = box;
    bad_polygons[n_polygons].vertices[1].x = bad_reals[i];
    polygon_words[n_polygons++] = "polygon vertex";
  }
  for (int i = 0; i < N_BAD_NN; ++i) {
    bad_polygons[n_polygons] = box;
    bad_polygons[n_polygons].radius = bad_non_negatives[i];
    polygon_words[n_polygons++] = "polygon radius";
  }
  bad_polygons[n_polygons] = box;
  for (int i = 0; i < 4; ++i) bad_polygons[n_polygons].vertices[i] = box.vertices[3 - i];
  polygon_words[n_polygons++] = "convex";
  for (int i = 0; i < n_polygons; ++i) {
    const tb_polygon* p = &bad_polygons[i];
    const char* w = polygon_words[i];
    REJECT_COLLIDE(tb_collide_segment_and_polygon(&segment, id, p, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_polygon_and_circle(p, id, &circle, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_polygon_and_capsule(p, id, &capsule, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_polygons(p, id, &box, id), bad, "shape a", w);
    REJECT_COLLIDE(tb_collide_polygons(&box, id, p, id), bad, "shape b", w);
    REJECT_COLLIDE(tb_collide_chain_segment_and_polygon(&chain, id, p, id), bad, "shape b", w);
  }
#undef REJECT_COLLIDE

  /* the good shapes of these rows do touch: the rows above are empty because
   * they were refused, not because nothing was there */
  tb_clear_error();
  ck_assert_int_eq(tb_collide_circles(&circle, id, &circle, id).point_count, 1);
  ck_assert_int_eq(tb_collide_capsules(&capsule, id, &capsule, id).point_count, 2);
  ck_assert_int_gt(tb_collide_segment_and_polygon(&segment, id, &box, id).point_count, 0);
  ck_assert_int_gt(tb_collide_polygons(&box, id, &box, id).point_count, 0);
  ck_assert_int_gt(
      tb_collide_chain_segment_and_polygon(&chain, id, &box, (tb_transform){{0, 0.9f}, {1, 0}}).point_count, 0);
  ck_assert_int_eq(tb_last_result(), TB_OK);
}
END_TEST

/* ---- geometry queries, proxies, distance, casts, TOI, hulls (issue 24) ------ */

/* A refused call of the geometry and distance API: `code` recorded, `word` in
 * the message, the documented harmless result (`ok`, about what `stmt`
 * declared) and the world untouched. */
#define REFUSED(stmt, code, word, ok)                                                                              \
  do {                                                                                                             \
    tb_clear_error();                                                                                              \
    stmt;                                                                                                          \
    ck_assert_msg(tb_last_result() == (code), "%s: got %s, want %s (%s)", #stmt, tb_result_name(tb_last_result()), \
                  tb_result_name(code), tb_last_error());                                                          \
    ck_assert_msg(strstr(tb_last_error(), (word)) != NULL, "%s: message '%s' lacks '%s'", #stmt, tb_last_error(),  \
                  (word));                                                                                         \
    ck_assert_msg((ok), "%s: not the documented result on error", #stmt);                                          \
    assert_unchanged(#stmt);                                                                                       \
  } while (0)

static bool zero_box(tb_aabb b) { return b.lower.x == 0 && b.lower.y == 0 && b.upper.x == 0 && b.upper.y == 0; }
static bool zero_vec(tb_vec2 v) { return v.x == 0 && v.y == 0; }
static bool missed(tb_result r, tb_result code, const tb_cast_output* o) {
  return r == code && !o->hit && o->fraction == 0 && zero_vec(o->point) && zero_vec(o->normal);
}

/* Every query on one placed geometry (aabb, point test, closest point, ray)
 * refused with code and word. */
#define REFUSED_QUERIES(kind, g, xf, pt, code, word)                                                      \
  do {                                                                                                    \
    REFUSED(tb_aabb b_ = tb_compute_##kind##_aabb((g), (xf)), code, word, zero_box(b_));                  \
    REFUSED(bool in_ = tb_point_in_##kind((g), (xf), (pt)), code, word, !in_);                            \
    REFUSED(tb_vec2 c_ = tb_closest_point_on_##kind((g), (xf), (pt)), code, word, zero_vec(c_));          \
    tb_ray_input ray_ = {(pt), {1.0f, 0.0f}, 1.0f};                                                       \
    tb_cast_output o_;                                                                                    \
    REFUSED(tb_result r_ = tb_ray_cast_##kind(&ray_, (g), (xf), &o_), code, word, missed(r_, code, &o_)); \
  } while (0)

START_TEST(geometry_and_distance_calls) {
  const tb_transform id = {{0, 0}, {1, 0}};
  const tb_vec2 origin = {0, 0};
  tb_circle circle = {{0, 0}, 1.0f};
  tb_capsule capsule = {{0, 0}, {1, 0}, 0.5f};
  tb_segment segment = {{-1, 0}, {1, 0}};
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(1, 1, &box), TB_OK);
  const tb_result bad = TB_ERR_INVALID_ARGUMENT, null = TB_ERR_NULL_ARGUMENT;

  /* transforms and points: not finite, beyond TB_MAX_LENGTH, not a rotation */
  for (int i = 0; i < N_BAD + 2; ++i) {
    float x = i < N_BAD ? bad_reals[i] : (i == N_BAD ? 0.5f : 2.0f); /* 0.5, 2: not a unit rotation */
    tb_transform bad_p = {{x, 0}, {1, 0}}, bad_q = {{0, 0}, {x, 0}};
    tb_transform t = i < N_BAD ? bad_p : bad_q;
    REFUSED_QUERIES(circle, &circle, t, origin, bad, "transform");
    REFUSED_QUERIES(capsule, &capsule, bad_q, origin, bad, "transform");
    REFUSED_QUERIES(segment, &segment, t, origin, bad, "transform");
    REFUSED_QUERIES(polygon, &box, bad_q, origin, bad, "transform");
    tb_polygon out = box;
    REFUSED(tb_result r = tb_transform_polygon(&box, t, &out), bad, "transform",
            r == bad && memcmp(&out, &box, sizeof out) == 0);
    tb_distance_input din = {tb_make_circle_proxy(&circle), tb_make_circle_proxy(&circle), id, t};
    tb_distance_output dout;
    REFUSED(tb_result r = tb_shape_distance(&din, NULL, &dout), bad, "transform", r == bad && dout.distance == FLT_MAX);
    tb_shape_cast_input cin = {din.proxy_a, din.proxy_b, t, id, {1, 0}};
    tb_cast_output cout;
    REFUSED(tb_result r = tb_shape_cast(&cin, &cout), bad, "transform", missed(r, bad, &cout));
    if (i >= N_BAD) continue;
    /* the rest take the bad number itself */
    tb_vec2 p = {0, x};
    REFUSED(bool in = tb_point_in_circle(&circle, id, p), bad, "point", !in);
    REFUSED(bool in = tb_point_in_polygon(&box, id, p), bad, "point", !in);
    REFUSED(tb_vec2 c = tb_closest_point_on_capsule(&capsule, id, p), bad, "point", zero_vec(c));
    REFUSED(tb_vec2 c = tb_closest_point_on_segment(&segment, id, p), bad, "point", zero_vec(c));
    tb_ray_input rays[3] = {{p, {1, 0}, 1.0f}, {origin, p, 1.0f}, {origin, {1, 0}, x}};
    for (int k = 0; k < 3; ++k) {
      REFUSED(tb_result r = tb_ray_cast_polygon(&rays[k], &box, id, &cout), bad, k < 2 ? "ray" : "max_fraction",
              missed(r, bad, &cout));
    }
    REFUSED(tb_segment_distance_output s = tb_segment_distance(origin, p, origin, origin), bad, "point",
            s.distance_sq == FLT_MAX && zero_vec(s.closest1));
    REFUSED(tb_shape_proxy pr = tb_make_proxy(&p, 1, 0.0f), bad, "point 0", pr.count == 0);
    REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(&origin, 1, 0.0f, p, 0.0f), bad, "position", pr.count == 0);
    REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(&origin, 1, 0.0f, origin, x), bad, "angle", pr.count == 0);
    cin.xf_a = id;
    cin.translation_b = p;
    REFUSED(tb_result r = tb_shape_cast(&cin, &cout), bad, "translation", missed(r, bad, &cout));
    /* time of impact: sweeps, max_fraction, target, tolerance */
    tb_sweep still = {{0, 0}, {0, 0}, {0, 0}, 0, 0};
    tb_toi_input tin = {din.proxy_a, din.proxy_b, still, still, 1.0f, TB_LINEAR_SLOP, 0.001f};
    tb_toi_output tout;
    tin.sweep_b.c2 = p;
    REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "sweep",
            r == bad && tout.state == TB_TOI_FAILED && tout.fraction == 0);
    tin.sweep_b = still;
    tin.sweep_a.a1 = x;
    if (!isfinite(x)) /* angles up to TB_MAX_VALUE are accepted (body angles may wind) */
      REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "sweep", r == bad && tout.state == TB_TOI_FAILED);
    tin.sweep_a = still;
    tin.max_fraction = x;
    REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "max_fraction", r == bad);
    tin.max_fraction = 1.0f;
    tin.target = x;
    REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "target", r == bad);
    tin.target = TB_LINEAR_SLOP;
    /* placed polygons and boxes */
    tb_hull hull;
    ck_assert_int_eq(tb_compute_hull(box.vertices, 4, &hull), TB_OK);
    REFUSED(tb_result r = tb_make_offset_polygon(&hull, p, 0.0f, &out), bad, "tb_make_offset_polygon: position",
            r == bad && memcmp(&out, &box, sizeof out) == 0);
    REFUSED(tb_result r = tb_make_offset_rounded_polygon(&hull, origin, x, 0.1f, &out), bad,
            "tb_make_offset_rounded_polygon: angle", r == bad);
    REFUSED(tb_result r = tb_make_offset_rounded_box(1, 1, p, 0.0f, 0.1f, &out), bad,
            "tb_make_offset_rounded_box: center", r == bad);
    REFUSED(tb_result r = tb_make_offset_rounded_box(1, 1, origin, x, 0.1f, &out), bad,
            "tb_make_offset_rounded_box: angle", r == bad);
    const tb_vec2 tri[3] = {{0, 0}, {1, 0}, p};
    REFUSED(tb_result r = tb_compute_hull(tri, 3, &hull), bad, "tb_compute_hull: points[2]",
            r == bad && hull.count == 0);
  }
  /* sizes: radii, tolerances, half extents */
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    tb_polygon out = box;
    tb_hull hull;
    ck_assert_int_eq(tb_compute_hull(box.vertices, 4, &hull), TB_OK);
    REFUSED(tb_shape_proxy pr = tb_make_proxy(&origin, 1, x), bad, "radius", pr.count == 0);
    REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(&origin, 1, x, origin, 0.0f), bad, "radius", pr.count == 0);
    REFUSED(tb_result r = tb_make_polygon_from_hull(&hull, x, &out), bad, "tb_make_polygon_from_hull: radius",
            r == bad && memcmp(&out, &box, sizeof out) == 0);
    REFUSED(tb_result r = tb_make_offset_rounded_polygon(&hull, origin, 0.0f, x, &out), bad, "radius", r == bad);
    REFUSED(tb_result r = tb_make_offset_rounded_box(1, 1, origin, 0.0f, x, &out), bad,
            "tb_make_offset_rounded_box: radius", r == bad);
  }
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    float x = bad_sizes[i];
    tb_polygon out;
    REFUSED(tb_result r = tb_make_offset_rounded_box(x, 1, origin, 0.0f, 0.1f, &out), bad,
            "tb_make_offset_rounded_box: hx", r == bad);
    REFUSED(tb_result r = tb_make_offset_rounded_box(1, x, origin, 0.0f, 0.1f, &out), bad,
            "tb_make_offset_rounded_box: hy", r == bad);
    tb_toi_input tin = {.proxy_a = tb_make_circle_proxy(&circle), .proxy_b = tb_make_circle_proxy(&circle)};
    tin.sweep_b.c1 = tin.sweep_b.c2 = (tb_vec2){5, 0};
    tin.max_fraction = 1.0f;
    tin.tolerance = x;
    tb_toi_output tout;
    REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "tolerance", r == bad);
  }

  /* bad geometry, refused by every query as by the shape functions */
  tb_circle bad_circle = {{0, 0}, -1.0f};
  tb_capsule bad_capsule = {{1, 1}, {1, 1}, 0.5f};
  tb_segment bad_segment = {{NAN, 0}, {1, 0}};
  tb_polygon bad_count = box, clockwise = box;
  bad_count.count = TB_MAX_POLYGON_VERTICES + 1;
  for (int i = 0; i < 4; ++i) clockwise.vertices[i] = box.vertices[3 - i];
  REFUSED_QUERIES(circle, &bad_circle, id, origin, bad, "radius");
  REFUSED_QUERIES(capsule, &bad_capsule, id, origin, bad, "coincide");
  REFUSED_QUERIES(segment, &bad_segment, id, origin, bad, "finite");
  REFUSED_QUERIES(polygon, &bad_count, id, origin, bad, "count");
  REFUSED_QUERIES(polygon, &clockwise, id, origin, bad, "convex");
  REFUSED(tb_shape_proxy pr = tb_make_circle_proxy(&bad_circle), bad, "radius", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_capsule_proxy(&bad_capsule), bad, "coincide", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_segment_proxy(&bad_segment), bad, "finite", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_polygon_proxy(&clockwise), bad, "convex", pr.count == 0);
  tb_polygon out = box;
  REFUSED(tb_result r = tb_transform_polygon(&bad_count, id, &out), bad, "count", r == bad);

  /* NULL: each pointer of each function */
  REFUSED_QUERIES(circle, (const tb_circle*)NULL, id, origin, null, "circle");
  REFUSED_QUERIES(capsule, (const tb_capsule*)NULL, id, origin, null, "NULL");
  REFUSED_QUERIES(segment, (const tb_segment*)NULL, id, origin, null, "NULL");
  REFUSED_QUERIES(polygon, (const tb_polygon*)NULL, id, origin, null, "NULL");
  tb_cast_output cout;
  tb_ray_input ray = {{-5, 0}, {10, 0}, 1.0f};
  REFUSED(tb_result r = tb_ray_cast_circle(NULL, &circle, id, &cout), null, "ray", missed(r, null, &cout));
  REFUSED(tb_result r = tb_ray_cast_capsule(&ray, &capsule, id, NULL), null, "output", r == null);
  REFUSED(tb_shape_proxy pr = tb_make_proxy(NULL, 1, 0.0f), null, "points", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(NULL, 1, 0.0f, origin, 0.0f), null, "points", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_circle_proxy(NULL), null, "NULL", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_capsule_proxy(NULL), null, "NULL", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_segment_proxy(NULL), null, "NULL", pr.count == 0);
  REFUSED(tb_shape_proxy pr = tb_make_polygon_proxy(NULL), null, "NULL", pr.count == 0);
  tb_distance_input din = {tb_make_circle_proxy(&circle), tb_make_circle_proxy(&circle), id, id};
  tb_distance_output dout;
  REFUSED(tb_result r = tb_shape_distance(NULL, NULL, &dout), null, "input", r == null && dout.distance == FLT_MAX);
  REFUSED(tb_result r = tb_shape_distance(&din, NULL, NULL), null, "output", r == null);
  REFUSED(tb_result r = tb_shape_cast(NULL, &cout), null, "input", missed(r, null, &cout));
  REFUSED(tb_result r = tb_shape_cast(NULL, NULL), null, "output", r == null);
  tb_toi_output tout;
  REFUSED(tb_result r = tb_time_of_impact(NULL, &tout), null, "input", r == null && tout.state == TB_TOI_FAILED);
  REFUSED(tb_result r = tb_time_of_impact(NULL, NULL), null, "output", r == null);
  tb_hull hull;
  REFUSED(tb_result r = tb_compute_hull(NULL, 3, &hull), null, "tb_compute_hull: points", r == null && hull.count == 0);
  REFUSED(tb_result r = tb_compute_hull(box.vertices, 4, NULL), null, "out", r == null);
  ck_assert_int_eq(tb_compute_hull(box.vertices, 4, &hull), TB_OK);
  REFUSED(tb_result r = tb_make_polygon_from_hull(NULL, 0.0f, &out), null, "hull", r == null);
  REFUSED(tb_result r = tb_make_polygon_from_hull(&hull, 0.0f, NULL), null, "out", r == null);
  REFUSED(tb_result r = tb_make_offset_polygon(NULL, origin, 0.0f, &out), null, "hull", r == null);
  REFUSED(tb_result r = tb_make_offset_rounded_polygon(&hull, origin, 0.0f, 0.1f, NULL), null, "out", r == null);
  REFUSED(tb_result r = tb_make_offset_rounded_box(1, 1, origin, 0.0f, 0.1f, NULL), null, "out", r == null);
  REFUSED(tb_result r = tb_transform_polygon(NULL, id, &out), null, "polygon", r == null);
  REFUSED(tb_result r = tb_transform_polygon(&box, id, NULL), null, "out", r == null);

  /* counts out of range: proxies, hulls, a proxy handed in by hand */
  const int bad_counts[] = {0, -1, TB_MAX_POLYGON_VERTICES + 1, 100};
  tb_vec2 many[100] = {{0, 0}};
  for (int i = 0; i < 4; ++i) {
    int n = bad_counts[i];
    REFUSED(tb_shape_proxy pr = tb_make_proxy(many, n, 0.0f), bad, "count", pr.count == 0);
    REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(many, n, 0.0f, origin, 1.0f), bad, "count", pr.count == 0);
    tb_hull h = hull;
    h.count = n;
    REFUSED(tb_result r = tb_make_polygon_from_hull(&h, 0.0f, &out), bad, "count", r == bad);
    REFUSED(tb_result r = tb_make_offset_polygon(&h, origin, 0.0f, &out), bad, "count", r == bad);
    tb_distance_input d = din;
    d.proxy_b.count = n;
    REFUSED(tb_result r = tb_shape_distance(&d, NULL, &dout), bad, "proxy", r == bad && dout.distance == FLT_MAX);
    tb_toi_input tin = {.proxy_a = din.proxy_a, .proxy_b = d.proxy_b};
    tin.max_fraction = 1.0f;
    tin.tolerance = 0.001f;
    REFUSED(tb_result r = tb_time_of_impact(&tin, &tout), bad, "proxy", r == bad);
  }

  /* degenerate: a hull that is not one; polygons that collapse in float far out */
  tb_hull fake = {{{-1, -1}, {1, -1}, {0, 0}, {1, 1}, {-1, 1}}, 5};
  REFUSED(tb_result r = tb_make_polygon_from_hull(&fake, 0.0f, &out), TB_ERR_DEGENERATE_POLYGON, "not a hull",
          r == TB_ERR_DEGENERATE_POLYGON);
  const tb_vec2 dots[3] = {{0, 0}, {0.001f, 0}, {0, 0.001f}};
  REFUSED(tb_result r = tb_compute_hull(dots, 3, &hull), TB_ERR_DEGENERATE_POLYGON, "tb_compute_hull: only",
          r == TB_ERR_DEGENERATE_POLYGON && hull.count == 0);
  tb_polygon tiny;
  ck_assert_int_eq(tb_make_box(0.001f, 0.001f, &tiny), TB_OK);
  tb_transform far = {{9e6f, 9e6f}, {cosf(0.3f), sinf(0.3f)}};
  REFUSED(tb_result r = tb_transform_polygon(&tiny, far, &out), TB_ERR_DEGENERATE_POLYGON, "placed",
          r == TB_ERR_DEGENERATE_POLYGON);
  tb_polygon small; /* 2 cm: a hull (the corners are more than TB_LINEAR_SLOP apart) */
  ck_assert_int_eq(tb_make_box(0.01f, 0.01f, &small), TB_OK);
  tb_hull tiny_hull;
  ck_assert_int_eq(tb_compute_hull(small.vertices, 4, &tiny_hull), TB_OK);
  REFUSED(tb_result r = tb_make_offset_polygon(&tiny_hull, far.p, 0.3f, &out), TB_ERR_DEGENERATE_POLYGON, "placed",
          r == TB_ERR_DEGENERATE_POLYGON);
  REFUSED(tb_result r = tb_make_offset_rounded_box(0.001f, 0.001f, far.p, 0.3f, 0.1f, &out), TB_ERR_DEGENERATE_POLYGON,
          "tb_make_offset_rounded_box", r == TB_ERR_DEGENERATE_POLYGON);
  /* placed proxy points beyond TB_MAX_LENGTH */
  tb_vec2 edge = {0.9f * TB_MAX_LENGTH, 0};
  REFUSED(tb_shape_proxy pr = tb_make_offset_proxy(&edge, 1, 0.0f, edge, 0.0f), bad, "placed", pr.count == 0);

  /* the good calls of these rows succeed: the refusals above were the input's */
  tb_clear_error();
  ck_assert(tb_point_in_circle(&circle, id, origin));
  ck_assert_int_eq(tb_compute_hull(box.vertices, 4, &hull), TB_OK);
  ck_assert_int_eq(tb_make_offset_polygon(&hull, origin, 0.5f, &out), TB_OK);
  ck_assert_int_eq(tb_shape_distance(&din, NULL, &dout), TB_OK);
  ck_assert_int_eq(tb_last_result(), TB_OK);
}
END_TEST
#undef REFUSED_QUERIES
#undef REFUSED

/* ---- bodies and shapes: the calls test_bad_input.c leaves out ---------------- */

START_TEST(body_and_shape_extras) {
  for (int i = 0; i < N_BAD_NN; ++i) {
    REJECT(tb_body_set_sleep_threshold(A, bad_non_negatives[i]), TB_ERR_INVALID_ARGUMENT, "speed");
    REJECT(tb_shape_set_rolling_resistance(BOX, bad_non_negatives[i]), TB_ERR_INVALID_ARGUMENT, "rolling_resistance");
    tb_body_def bd = tb_default_body_def();
    bd.sleep_threshold = bad_non_negatives[i];
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "sleep_threshold");
    tb_shape_def sd = tb_default_shape_def();
    sd.rolling_resistance = bad_non_negatives[i];
    tb_circle c = {{0, 0}, 0.5f};
    REJECT(tb_create_circle_shape(A, &sd, &c), TB_ERR_INVALID_ARGUMENT, "rolling_resistance");
  }
  for (int i = 0; i < N_BAD; ++i) {
    REJECT(tb_shape_set_tangent_speed(BOX, bad_reals[i]), TB_ERR_INVALID_ARGUMENT, "speed");
    tb_shape_def sd = tb_default_shape_def();
    sd.tangent_speed = bad_reals[i];
    tb_circle c = {{0, 0}, 0.5f};
    REJECT(tb_create_circle_shape(A, &sd, &c), TB_ERR_INVALID_ARGUMENT, "tangent_speed");
  }
  /* restitution in [0, 1] (issue 23 item 7: 1e18 threw a box at 6e18 m/s) */
  const float bad_restitution[] = {1.0001f, 2.0f, 1e18f};
  for (int i = 0; i < 3; ++i) {
    REJECT(tb_shape_set_restitution(BOX, bad_restitution[i]), TB_ERR_INVALID_ARGUMENT, "restitution");
    tb_shape_def sd = tb_default_shape_def();
    sd.restitution = bad_restitution[i];
    tb_circle c = {{0, 0}, 0.5f};
    REJECT(tb_create_circle_shape(A, &sd, &c), TB_ERR_INVALID_ARGUMENT, "def->restitution");
    tb_vec2 pts[2] = {{0, 5}, {1, 5}};
    tb_chain_def cd = tb_default_chain_def();
    cd.points = pts;
    cd.count = 2;
    cd.restitution = bad_restitution[i];
    REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "def->restitution");
  }
  /* angles within TB_MAX_ANGLE everywhere: a box's too (1e30 used to be taken) */
  const float bad_angles[] = {1.1e6f, -1.0e7f, 1e30f, NAN, INFINITY};
  for (int i = 0; i < 5; ++i) {
    float x = bad_angles[i];
    tb_polygon box;
    REJECT(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){0, 0}, x, &box), TB_ERR_INVALID_ARGUMENT, "angle");
    tb_body_def bd = tb_default_body_def();
    bd.angle = x;
    REJECT(tb_create_body(W, &bd), TB_ERR_INVALID_ARGUMENT, "def->angle");
    REJECT(tb_body_set_transform(A, (tb_vec2){0, 2}, x), TB_ERR_INVALID_ARGUMENT, "angle");
    tb_revolute_joint_def rd = tb_default_revolute_joint_def();
    rd.body_a = A;
    rd.body_b = B;
    rd.reference_angle = x;
    REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "reference_angle");
    rd.reference_angle = 0.0f;
    rd.lower_angle = -fabsf(x);
    REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "lower_angle");
    REJECT(tb_revolute_joint_set_limits(JR, true, -1.0f, fabsf(x)), TB_ERR_INVALID_ARGUMENT, "upper");
    tb_prismatic_joint_def pd = tb_default_prismatic_joint_def();
    pd.body_a = A;
    pd.body_b = B;
    pd.reference_angle = x;
    REJECT(tb_create_prismatic_joint(W, &pd), TB_ERR_INVALID_ARGUMENT, "reference_angle");
    tb_weld_joint_def wd = tb_default_weld_joint_def();
    wd.body_a = A;
    wd.body_b = B;
    wd.reference_angle = x;
    REJECT(tb_create_weld_joint(W, &wd), TB_ERR_INVALID_ARGUMENT, "reference_angle");
    tb_motor_joint_def od = tb_default_motor_joint_def();
    od.body_a = GROUND;
    od.body_b = A;
    od.angular_offset = x;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "angular_offset");
    REJECT(tb_motor_joint_set_offsets(JO, (tb_vec2){0, 0}, x), TB_ERR_INVALID_ARGUMENT, "angular_offset");
  }
  /* negative and zero sizes of every shape type */
  tb_shape_def sd = tb_default_shape_def();
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    float x = bad_sizes[i];
    tb_capsule cap = {{0, 0}, {1, 0}, x};
    REJECT(tb_create_capsule_shape(A, &sd, &cap), TB_ERR_INVALID_ARGUMENT, "radius");
    tb_circle circle = {{0, 0}, x};
    REJECT(tb_create_circle_shape(A, &sd, &circle), TB_ERR_INVALID_ARGUMENT, "radius");
  }
  tb_joint_id joints[2];
  REJECT(tb_body_get_joints(A, NULL, 2), TB_ERR_NULL_ARGUMENT, "out");
  REJECT(tb_body_get_joints(A, joints, -1), TB_ERR_INVALID_ARGUMENT, "capacity");
  REJECT(tb_body_get_contact_data(C, NULL, 2), TB_ERR_NULL_ARGUMENT, "out");
  tb_contact_data data[2];
  REJECT(tb_body_get_contact_data(C, data, -1), TB_ERR_INVALID_ARGUMENT, "capacity");
  REJECT(tb_body_get_shapes(A, (tb_shape_id[1]){{0, 0, 0}}, -5), TB_ERR_INVALID_ARGUMENT, "capacity");
  REJECT(tb_shape_get_chain_segment(BOX, &(tb_chain_segment){0}), TB_ERR_INVALID_ARGUMENT, "type");
  REJECT(tb_shape_get_chain_segment(CHAIN_SEG, NULL), TB_ERR_NULL_ARGUMENT, "out");
  REJECT(tb_destroy_shape(CHAIN_SEG), TB_ERR_INVALID_ARGUMENT, "chain");
  /* a dead body's sleep, joint and contact calls */
  tb_body_id b = DEAD_BODY;
  REJECT(tb_body_is_awake(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_set_awake(b, true), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_is_sleep_enabled(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_enable_sleep(b, false), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_get_sleep_threshold(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_set_sleep_threshold(b, 1), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_is_bullet(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_set_bullet(b, true), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_get_joint_count(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_get_joints(b, joints, 2), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_get_contact_capacity(b), TB_ERR_STALE_HANDLE, "body");
  REJECT(tb_body_get_contact_data(b, data, 2), TB_ERR_STALE_HANDLE, "body");
  tb_chain_def cd = tb_default_chain_def();
  REJECT(tb_create_chain(b, &cd), TB_ERR_STALE_HANDLE, "body");
  /* a dead shape's newer calls */
  tb_shape_id dead_shape = CHAIN_SEG;
  dead_shape.generation ^= 0x5a5a;
  REJECT(tb_shape_get_rolling_resistance(dead_shape), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_set_rolling_resistance(dead_shape, 0), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_get_tangent_speed(dead_shape), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_set_tangent_speed(dead_shape, 0), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_get_filter(dead_shape), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_set_filter(dead_shape, tb_default_filter()), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_is_sensor(dead_shape), TB_ERR_STALE_HANDLE, "shape");
  REJECT(tb_shape_get_chain_segment(dead_shape, &(tb_chain_segment){0}), TB_ERR_STALE_HANDLE, "shape");
}
END_TEST

/* ---- one shape's geometry, and the dynamic tree (issue 24) ------------------- */

static tb_result set_circle_in_callback;
static bool test_point_in_callback;

static bool set_geometry_reenter(tb_shape_id shape, void* context) {
  (void)context;
  tb_circle c = {{0, 0}, 2.0f};
  set_circle_in_callback = tb_shape_set_circle(shape, &c);
  test_point_in_callback = tb_shape_test_point(shape, tb_body_get_position(tb_shape_get_body(shape)));
  return true;
}

START_TEST(shape_geometry_calls) {
  tb_shape_def sd = tb_default_shape_def();
  /* bad geometry of every type, NULL geometry, a chain segment */
  for (int i = 0; i < N_BAD_SIZES; ++i) {
    tb_circle circle = {{0, 0}, bad_sizes[i]};
    REJECT(tb_shape_set_circle(BOX, &circle), TB_ERR_INVALID_ARGUMENT, "radius");
    tb_capsule capsule = {{0, 0}, {1, 0}, bad_sizes[i]};
    REJECT(tb_shape_set_capsule(BOX, &capsule), TB_ERR_INVALID_ARGUMENT, "radius");
  }
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    tb_circle circle = {{x, 0}, 0.5f};
    REJECT(tb_shape_set_circle(BOX, &circle), TB_ERR_INVALID_ARGUMENT, "center");
    tb_segment segment = {{0, 0}, {0, x}};
    REJECT(tb_shape_set_segment(BOX, &segment), TB_ERR_INVALID_ARGUMENT, "segment");
    tb_vec2 p = {x, 1.0f};
    REJECT(tb_shape_test_point(BOX, p), TB_ERR_INVALID_ARGUMENT, "point");
    REJECT(tb_shape_get_closest_point(BOX, p), TB_ERR_INVALID_ARGUMENT, "target");
    REJECT(tb_shape_ray_cast(BOX, p, (tb_vec2){1, 0}), TB_ERR_INVALID_ARGUMENT, "origin");
    REJECT(tb_shape_ray_cast(BOX, (tb_vec2){0, 0}, p), TB_ERR_INVALID_ARGUMENT, "translation");
  }
  REJECT(tb_shape_ray_cast(BOX, (tb_vec2){0, 0}, (tb_vec2){0, 0}), TB_ERR_INVALID_ARGUMENT, "zero");
  tb_segment dot = {{1, 1}, {1, 1}};
  REJECT(tb_shape_set_segment(BOX, &dot), TB_ERR_INVALID_ARGUMENT, "coincide");
  tb_capsule ball = {{1, 1}, {1, 1}, 0.5f};
  REJECT(tb_shape_set_capsule(BOX, &ball), TB_ERR_INVALID_ARGUMENT, "coincide");
  tb_polygon box, flat;
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, &box), TB_OK);
  flat = box;
  for (int i = 0; i < 4; ++i) flat.vertices[i] = (tb_vec2){3.0f, 3.0f};
  REJECT(tb_shape_set_polygon(BOX, &flat), TB_ERR_DEGENERATE_POLYGON, "convex");
  flat = box;
  flat.count = TB_MAX_POLYGON_VERTICES + 1;
  REJECT(tb_shape_set_polygon(BOX, &flat), TB_ERR_DEGENERATE_POLYGON, "count");
  REJECT(tb_shape_set_circle(BOX, NULL), TB_ERR_NULL_ARGUMENT, "circle");
  REJECT(tb_shape_set_capsule(BOX, NULL), TB_ERR_NULL_ARGUMENT, "capsule");
  REJECT(tb_shape_set_segment(BOX, NULL), TB_ERR_NULL_ARGUMENT, "segment");
  REJECT(tb_shape_set_polygon(BOX, NULL), TB_ERR_NULL_ARGUMENT, "polygon");
  tb_circle fine = {{0, 0}, 0.5f};
  REJECT(tb_shape_set_circle(CHAIN_SEG, &fine), TB_ERR_INVALID_ARGUMENT, "chain");
  REJECT(tb_shape_set_polygon(CHAIN_SEG, &box), TB_ERR_INVALID_ARGUMENT, "chain");
  /* a shape whose box would reach beyond the edge of the world at its body
   * (placed in A's frame: A has moved and turned in the first step, its
   * joints pulling against each other) */
  tb_capsule edge = {tb_body_get_local_point(A, (tb_vec2){9.95e6f, 2.0f}),
                     tb_body_get_local_point(A, (tb_vec2){9.999e6f, 2.0f}), 2000.0f}; /* reaches 1e7 + 1 km */
  REJECT(tb_shape_set_capsule(BOX, &edge), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  /* dead, foreign-world and garbage shape handles, and a shape of a dead world */
  tb_world_id gone = tbt_world(0, 0);
  tb_body_id gone_body = tbt_box_body(gone, 0, 0, 0.5f, 0.5f);
  tb_shape_id gone_shape;
  tb_body_get_shapes(gone_body, &gone_shape, 1);
  tb_destroy_world(gone);
  tb_shape_id dead_shape = BOX;
  dead_shape.generation ^= 0x5a5a;
  const tb_shape_id stale[] = {dead_shape, gone_shape, {0, 0, 0}, {1 << 30, 0, 0}};
  for (int i = 0; i < 4; ++i) {
    tb_shape_id s = stale[i];
    REJECT(tb_shape_set_circle(s, &fine), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_polygon(s, &box), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_capsule(s, &ball), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_set_segment(s, &dot), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_test_point(s, (tb_vec2){0, 0}), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_get_closest_point(s, (tb_vec2){0, 0}), TB_ERR_STALE_HANDLE, "shape");
    REJECT(tb_shape_ray_cast(s, (tb_vec2){0, 0}, (tb_vec2){1, 0}), TB_ERR_STALE_HANDLE, "shape");
  }
  /* refused getters give the documented values */
  tb_ray_result r;
  REJECT(r = tb_shape_ray_cast(dead_shape, (tb_vec2){0, 0}, (tb_vec2){1, 0}), TB_ERR_STALE_HANDLE, "shape");
  ck_assert(!r.hit && r.fraction == 1.0f && tb_shape_id_is_null(r.shape) && r.point.x == 0.0f);
  tb_vec2 q;
  REJECT(q = tb_shape_get_closest_point(dead_shape, (tb_vec2){5, 5}), TB_ERR_STALE_HANDLE, "shape");
  ck_assert(q.x == 0.0f && q.y == 0.0f);
  /* from inside a query callback: changes refused, reads allowed */
  set_circle_in_callback = TB_OK;
  test_point_in_callback = false;
  tb_vec2 at = tb_body_get_position(A);
  ck_assert_int_eq(tb_world_overlap_point(W, at, tb_default_query_filter(), set_geometry_reenter, NULL), TB_OK);
  ck_assert_int_eq(set_circle_in_callback, TB_ERR_LOCKED);
  ck_assert(test_point_in_callback);
  assert_unchanged("tb_shape_set_circle from a callback");
  /* the dynamic tree's refusals leave the world alone too */
  REJECT(tb_dynamic_tree_create(-1.0f), TB_ERR_INVALID_ARGUMENT, "margin");
  REJECT(tb_dynamic_tree_create_proxy(NULL, (tb_aabb){{0, 0}, {1, 1}}, 1, NULL), TB_ERR_NULL_ARGUMENT, "tree");
  tb_dynamic_tree* tree = tb_dynamic_tree_create(0.1f);
  REJECT(tb_dynamic_tree_create_proxy(tree, (tb_aabb){{0, 0}, {NAN, 1}}, 1, NULL), TB_ERR_INVALID_ARGUMENT, "aabb");
  REJECT(tb_dynamic_tree_destroy_proxy(tree, 0), TB_ERR_INVALID_ARGUMENT, "proxy");
  REJECT(tb_dynamic_tree_get_user_data(tree, 3), TB_ERR_INVALID_ARGUMENT, "proxy");
  ck_assert_int_eq(tb_dynamic_tree_destroy(tree), TB_OK);
  check_twin();
  /* a density at TB_MAX_VALUE: a large circle's mass overflows and is refused */
  ck_assert_int_eq(tb_shape_set_density(BOX, TB_MAX_VALUE), TB_OK);
  snapshot();
  tb_circle huge = {{0, 0}, 1e3f};
  REJECT(tb_shape_set_circle(BOX, &huge), TB_ERR_INVALID_ARGUMENT, "overflows");
  (void)sd;
}
END_TEST

/* ---- chains ---------------------------------------------------------------- */

START_TEST(chain_calls) {
  tb_chain_def cd = tb_default_chain_def();
  REJECT(tb_create_chain(GROUND, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_chain(GROUND, &cd), TB_ERR_NULL_ARGUMENT, "points");
  tb_vec2 pts[4] = {{0, 0}, {1, 0}, {2, 0.5f}, {3, 0}};
  cd.points = pts;
  cd.count = 1;
  REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "count");
  cd.count = -7;
  REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "count");
  cd.count = 2;
  cd.is_loop = true;
  REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "count");
  cd.is_loop = false;
  cd.count = 4;
  for (int i = 0; i < N_BAD; ++i) {
    tb_vec2 keep = pts[2];
    pts[2].y = bad_reals[i];
    REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "points[2]");
    pts[2] = keep;
  }
  for (int i = 0; i < N_BAD_NN; ++i) {
    cd.friction = bad_non_negatives[i];
    REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "friction");
    cd.friction = 0.6f;
    cd.restitution = bad_non_negatives[i];
    REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "restitution");
    cd.restitution = 0.0f;
  }
  tb_vec2 twice[3] = {{0, 0}, {0.001f, 0}, {2, 0}};
  cd.points = twice;
  cd.count = 3;
  REJECT(tb_create_chain(GROUND, &cd), TB_ERR_INVALID_ARGUMENT, "closer");
  tb_shape_id out[2];
  REJECT(tb_chain_get_segments(CHAIN, NULL, 2), TB_ERR_NULL_ARGUMENT, "out");
  REJECT(tb_chain_get_segments(CHAIN, out, -1), TB_ERR_INVALID_ARGUMENT, "capacity");
  const tb_chain_id stale[] = {DEAD_CHAIN, {0, 0, 0}, {CHAIN.index1, CHAIN.world0, (uint16_t)(CHAIN.generation + 1)}};
  for (int i = 0; i < 3; ++i) {
    ck_assert(!tb_chain_is_valid(stale[i]));
    REJECT(tb_destroy_chain(stale[i]), TB_ERR_STALE_HANDLE, "chain");
    REJECT(tb_chain_get_segment_count(stale[i]), TB_ERR_STALE_HANDLE, "chain");
    REJECT(tb_chain_get_segments(stale[i], out, 2), TB_ERR_STALE_HANDLE, "chain");
  }
}
END_TEST

/* A static body near the edge of the world with a chain and boxes resting on
 * it, stepped for half a second: the world of issue 23, item 4. */
static tb_body_id edge_world(tb_world_id w) {
  tb_body_def bd = tb_default_body_def();
  bd.position = (tb_vec2){TB_MAX_LENGTH - 100.0f, 0.0f};
  tb_body_id ground = tb_create_body(w, &bd);
  tb_vec2 points[12];
  for (int i = 0; i < 12; ++i) points[i] = (tb_vec2){5.0f * (float)i, 0.5f * (float)(i % 3)};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = points;
  cd.count = 12;
  ck_assert(tb_chain_is_valid(tb_create_chain(ground, &cd)));
  for (int i = 0; i < 5; ++i) tbt_box_body(w, TB_MAX_LENGTH - 90.0f + 6.0f * (float)i, 3.0f, 0.5f, 0.5f);
  for (int i = 0; i < 30; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  return ground;
}

/* Every creator that could put something beyond TB_MAX_LENGTH on a body at
 * the edge is refused before it changes anything: a chain whose last segment
 * reaches beyond (its first seven fit), a shape of each type, a type change
 * and re-enabling. The world keeps its hash, and its twin that never got
 * these calls still equals it 600 steps later. */
START_TEST(refusals_at_the_edge_of_the_world) {
  tb_world_id twin = tbt_world(0.0f, -10.0f);
  edge_world(twin);
  tb_world_id keep = W;
  W = tbt_world(0.0f, -10.0f);
  tb_body_id ground = edge_world(W);
  snapshot();
  tb_vec2 points[8];
  for (int i = 0; i < 8; ++i) points[i] = (tb_vec2){7.0f * (float)i, 1.0f + (float)i};
  points[7].x = 300.0f; /* 200 m beyond the edge */
  tb_chain_def cd = tb_default_chain_def();
  cd.points = points;
  cd.count = 8;
  REJECT(tb_create_chain(ground, &cd), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  cd.is_loop = true;
  REJECT(tb_create_chain(ground, &cd), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  tb_shape_def sd = tb_default_shape_def();
  tb_circle circle = {{300.0f, 0.0f}, 1.0f};
  REJECT(tb_create_circle_shape(ground, &sd, &circle), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  tb_capsule capsule = {{0.0f, 0.0f}, {300.0f, 0.0f}, 1.0f};
  REJECT(tb_create_capsule_shape(ground, &sd, &capsule), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  tb_segment segment = {{0.0f, 0.0f}, {300.0f, 0.0f}};
  REJECT(tb_create_segment_shape(ground, &sd, &segment), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  tb_polygon box;
  ck_assert_int_eq(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){300.0f, 0.0f}, 0.0f, &box), TB_OK);
  REJECT(tb_create_polygon_shape(ground, &sd, &box), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  /* bodies placed with their boxes across the edge cannot enter a tree anew */
  tb_body_id across[2], disabled[2];
  const tb_world_id worlds[2] = {twin, W};
  for (int k = 0; k < 2; ++k) {
    across[k] = tbt_box_body(worlds[k], 0.0f, 0.0f, 2.0f, 2.0f); /* floats are 1 m apart there: reach 2 m beyond */
    ck_assert_int_eq(tb_body_set_transform(across[k], (tb_vec2){TB_MAX_LENGTH, 50.0f}, 0.0f), TB_OK);
    disabled[k] = tbt_box_body(worlds[k], 0.0f, 0.0f, 2.0f, 2.0f);
    ck_assert_int_eq(tb_body_set_transform(disabled[k], (tb_vec2){TB_MAX_LENGTH, -50.0f}, 0.0f), TB_OK);
    ck_assert_int_eq(tb_body_set_enabled(disabled[k], false), TB_OK);
  }
  snapshot();
  REJECT(tb_body_set_enabled(disabled[1], true), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  REJECT(tb_body_set_type(across[1], TB_KINEMATIC_BODY), TB_ERR_INVALID_ARGUMENT, "beyond TB_MAX_LENGTH");
  ck_assert_uint_eq(tb_world_hash(W), tb_world_hash(twin));
  for (int i = 0; i < 600; ++i) {
    tb_world_step(W, 1.0f / 60.0f, 4);
    tb_world_step(twin, 1.0f / 60.0f, 4);
  }
  ck_assert_uint_eq(tb_world_hash(W), tb_world_hash(twin));
  tb_destroy_world(twin);
  tb_destroy_world(W);
  W = keep;
  snapshot();
}
END_TEST

/* ---- joints ---------------------------------------------------------------- */

START_TEST(joint_creation) {
  tb_distance_joint_def dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = B;
  REJECT(tb_create_distance_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_revolute_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_prismatic_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_weld_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_wheel_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_mouse_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  REJECT(tb_create_motor_joint(W, NULL), TB_ERR_NULL_ARGUMENT, "def");
  /* the same body twice, a dead body, a body of another world */
  dd.body_b = A;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "same body");
  dd.body_b = DEAD_BODY;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_STALE_HANDLE, "body_b");
  dd.body_b = FOREIGN_BODY;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_FOREIGN_HANDLE, "body_b");
  dd.body_a = FOREIGN_BODY;
  dd.body_b = A;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_FOREIGN_HANDLE, "body_a");
  tb_revolute_joint_def rd = tb_default_revolute_joint_def();
  rd.body_a = A;
  rd.body_b = FOREIGN_BODY;
  REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_FOREIGN_HANDLE, "body_b");
  tb_mouse_joint_def md = tb_default_mouse_joint_def();
  md.body_a = FOREIGN_BODY;
  md.body_b = A;
  REJECT(tb_create_mouse_joint(W, &md), TB_ERR_FOREIGN_HANDLE, "body_a");
  /* and every other joint type, each side */
  for (int side = 0; side < 2; ++side) {
    tb_body_id ba = side == 0 ? A : FOREIGN_BODY, bb = side == 0 ? FOREIGN_BODY : A;
    const char* which = side == 0 ? "body_b" : "body_a";
    tb_prismatic_joint_def pd = tb_default_prismatic_joint_def();
    pd.body_a = ba;
    pd.body_b = bb;
    REJECT(tb_create_prismatic_joint(W, &pd), TB_ERR_FOREIGN_HANDLE, which);
    tb_weld_joint_def wd = tb_default_weld_joint_def();
    wd.body_a = ba;
    wd.body_b = bb;
    REJECT(tb_create_weld_joint(W, &wd), TB_ERR_FOREIGN_HANDLE, which);
    tb_wheel_joint_def hd = tb_default_wheel_joint_def();
    hd.body_a = ba;
    hd.body_b = bb;
    REJECT(tb_create_wheel_joint(W, &hd), TB_ERR_FOREIGN_HANDLE, which);
    tb_motor_joint_def od = tb_default_motor_joint_def();
    od.body_a = ba;
    od.body_b = bb;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_FOREIGN_HANDLE, which);
  }
  /* the foreign world is untouched too */
  uint64_t other = tb_world_hash(OTHER);
  REJECT(tb_create_distance_joint(OTHER, &dd), TB_ERR_FOREIGN_HANDLE, "body_b");
  ck_assert_uint_eq(tb_world_hash(OTHER), other);

  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    dd = tb_default_distance_joint_def();
    dd.body_a = A;
    dd.body_b = B;
    dd.local_anchor_a.x = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "local_anchor_a");
    dd.local_anchor_a.x = 0.0f;
    dd.length = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "length");
    dd.length = 1.0f;
    dd.motor_speed = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "motor_speed");

    rd = tb_default_revolute_joint_def();
    rd.body_a = A;
    rd.body_b = B;
    rd.reference_angle = x;
    REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "reference_angle");
    rd.reference_angle = 0.0f;
    rd.local_anchor_b.y = x;
    REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "local_anchor_b");

    tb_prismatic_joint_def pd = tb_default_prismatic_joint_def();
    pd.body_a = A;
    pd.body_b = B;
    pd.local_axis_a.y = x;
    REJECT(tb_create_prismatic_joint(W, &pd), TB_ERR_INVALID_ARGUMENT, "local_axis_a");
    pd.local_axis_a = (tb_vec2){1, 0};
    pd.lower_translation = x;
    REJECT(tb_create_prismatic_joint(W, &pd), TB_ERR_INVALID_ARGUMENT, "lower_translation");

    tb_weld_joint_def wd = tb_default_weld_joint_def();
    wd.body_a = A;
    wd.body_b = B;
    wd.reference_angle = x;
    REJECT(tb_create_weld_joint(W, &wd), TB_ERR_INVALID_ARGUMENT, "reference_angle");

    tb_wheel_joint_def hd = tb_default_wheel_joint_def();
    hd.body_a = A;
    hd.body_b = B;
    hd.motor_speed = x;
    REJECT(tb_create_wheel_joint(W, &hd), TB_ERR_INVALID_ARGUMENT, "motor_speed");

    md = tb_default_mouse_joint_def();
    md.body_a = GROUND;
    md.body_b = A;
    md.target.x = x;
    REJECT(tb_create_mouse_joint(W, &md), TB_ERR_INVALID_ARGUMENT, "target");

    tb_motor_joint_def od = tb_default_motor_joint_def();
    od.body_a = GROUND;
    od.body_b = A;
    od.linear_offset.y = x;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "linear_offset");
    od.linear_offset.y = 0.0f;
    od.angular_offset = x;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "angular_offset");
  }
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    dd = tb_default_distance_joint_def();
    dd.body_a = A;
    dd.body_b = B;
    dd.max_motor_force = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "max_motor_force");
    dd.max_motor_force = 0.0f;
    dd.hertz = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "hertz");
    dd.hertz = 0.0f;
    dd.damping_ratio = x;
    REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "damping_ratio");
    rd = tb_default_revolute_joint_def();
    rd.body_a = A;
    rd.body_b = B;
    rd.max_motor_torque = x;
    REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "max_motor_torque");
    tb_weld_joint_def wd = tb_default_weld_joint_def();
    wd.body_a = A;
    wd.body_b = B;
    wd.angular_hertz = x;
    REJECT(tb_create_weld_joint(W, &wd), TB_ERR_INVALID_ARGUMENT, "angular_hertz");
    md = tb_default_mouse_joint_def();
    md.body_a = GROUND;
    md.body_b = A;
    md.max_force = x;
    REJECT(tb_create_mouse_joint(W, &md), TB_ERR_INVALID_ARGUMENT, "max_force");
    tb_motor_joint_def od = tb_default_motor_joint_def();
    od.body_a = GROUND;
    od.body_b = A;
    od.max_torque = x;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "max_torque");
    od.max_torque = 1.0f;
    od.correction_factor = x;
    REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "correction_factor");
  }
  /* limits in the wrong order, lengths too short, a zero axis */
  dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = B;
  dd.min_length = 2.0f;
  dd.max_length = 1.0f;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "min_length");
  dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = B;
  dd.length = 0.0f;
  REJECT(tb_create_distance_joint(W, &dd), TB_ERR_INVALID_ARGUMENT, "length");
  rd = tb_default_revolute_joint_def();
  rd.body_a = A;
  rd.body_b = B;
  rd.lower_angle = 1.0f;
  rd.upper_angle = -1.0f;
  REJECT(tb_create_revolute_joint(W, &rd), TB_ERR_INVALID_ARGUMENT, "lower_angle");
  tb_wheel_joint_def hd = tb_default_wheel_joint_def();
  hd.body_a = A;
  hd.body_b = B;
  hd.local_axis_a = (tb_vec2){0, 0};
  REJECT(tb_create_wheel_joint(W, &hd), TB_ERR_INVALID_ARGUMENT, "local_axis_a");
  tb_motor_joint_def od = tb_default_motor_joint_def();
  od.body_a = GROUND;
  od.body_b = A;
  od.correction_factor = 1.5f;
  REJECT(tb_create_motor_joint(W, &od), TB_ERR_INVALID_ARGUMENT, "correction_factor");
}
END_TEST

START_TEST(joint_calls) {
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    REJECT(tb_distance_joint_set_length(JD, x), TB_ERR_INVALID_ARGUMENT, "length");
    REJECT(tb_distance_joint_set_limits(JD, true, x, 3.0f), TB_ERR_INVALID_ARGUMENT, "min_length");
    REJECT(tb_revolute_joint_set_limits(JR, true, -1.0f, x), TB_ERR_INVALID_ARGUMENT, "upper");
    REJECT(tb_revolute_joint_set_motor(JR, true, x, 1.0f), TB_ERR_INVALID_ARGUMENT, "speed");
    REJECT(tb_prismatic_joint_set_limits(JP, true, x, 1.0f), TB_ERR_INVALID_ARGUMENT, "lower");
    REJECT(tb_prismatic_joint_set_motor(JP, true, x, 1.0f), TB_ERR_INVALID_ARGUMENT, "speed");
    REJECT(tb_wheel_joint_set_motor(JH, true, x, 1.0f), TB_ERR_INVALID_ARGUMENT, "speed");
    REJECT(tb_mouse_joint_set_target(JM, ((tb_vec2){x, 0})), TB_ERR_INVALID_ARGUMENT, "target");
    REJECT(tb_motor_joint_set_offsets(JO, ((tb_vec2){0, x}), 0.0f), TB_ERR_INVALID_ARGUMENT, "linear_offset");
    REJECT(tb_motor_joint_set_offsets(JO, ((tb_vec2){0, 0}), x), TB_ERR_INVALID_ARGUMENT, "angular_offset");
  }
  for (int i = 0; i < N_BAD_NN; ++i) {
    float x = bad_non_negatives[i];
    REJECT(tb_distance_joint_set_spring(JD, true, x, 0.5f), TB_ERR_INVALID_ARGUMENT, "hertz");
    REJECT(tb_distance_joint_set_spring(JD, true, 1.0f, x), TB_ERR_INVALID_ARGUMENT, "damping_ratio");
    REJECT(tb_revolute_joint_set_motor(JR, true, 1.0f, x), TB_ERR_INVALID_ARGUMENT, "max_torque");
    REJECT(tb_revolute_joint_set_spring(JR, true, x, 0.5f), TB_ERR_INVALID_ARGUMENT, "hertz");
    REJECT(tb_prismatic_joint_set_motor(JP, true, 1.0f, x), TB_ERR_INVALID_ARGUMENT, "max_force");
    REJECT(tb_prismatic_joint_set_spring(JP, true, 1.0f, x), TB_ERR_INVALID_ARGUMENT, "damping_ratio");
    REJECT(tb_weld_joint_set_stiffness(JW, x, 0, 0, 0), TB_ERR_INVALID_ARGUMENT, "linear_hertz");
    REJECT(tb_weld_joint_set_stiffness(JW, 0, 0, 0, x), TB_ERR_INVALID_ARGUMENT, "angular_damping_ratio");
    REJECT(tb_wheel_joint_set_motor(JH, true, 1.0f, x), TB_ERR_INVALID_ARGUMENT, "max_torque");
    REJECT(tb_wheel_joint_set_spring(JH, true, x, 0.7f), TB_ERR_INVALID_ARGUMENT, "hertz");
  }
  REJECT(tb_distance_joint_set_limits(JD, true, 3.0f, 1.0f), TB_ERR_INVALID_ARGUMENT, "min_length");
  REJECT(tb_revolute_joint_set_limits(JR, true, 1.0f, -1.0f), TB_ERR_INVALID_ARGUMENT, "lower");
  REJECT(tb_prismatic_joint_set_limits(JP, true, 1.0f, -1.0f), TB_ERR_INVALID_ARGUMENT, "lower");
  REJECT(tb_distance_joint_set_length(JD, 0.0f), TB_ERR_INVALID_ARGUMENT, "length");
  /* a setter of one joint type on a joint of another */
  REJECT(tb_distance_joint_set_length(JR, 1.0f), TB_ERR_INVALID_ARGUMENT, "revolute");
  REJECT(tb_revolute_joint_set_motor(JP, true, 1.0f, 1.0f), TB_ERR_INVALID_ARGUMENT, "prismatic");
  REJECT(tb_prismatic_joint_get_translation(JR), TB_ERR_INVALID_ARGUMENT, "revolute");
  REJECT(tb_weld_joint_set_stiffness(JD, 1, 1, 1, 1), TB_ERR_INVALID_ARGUMENT, "distance");
  REJECT(tb_wheel_joint_set_spring(JM, true, 1, 1), TB_ERR_INVALID_ARGUMENT, "mouse");
  REJECT(tb_mouse_joint_set_target(JO, ((tb_vec2){0, 0})), TB_ERR_INVALID_ARGUMENT, "motor");
  REJECT(tb_motor_joint_set_offsets(JW, ((tb_vec2){0, 0}), 0), TB_ERR_INVALID_ARGUMENT, "weld");
  REJECT(tb_revolute_joint_get_angle(JH), TB_ERR_INVALID_ARGUMENT, "wheel");
  tb_joint_id out[2];
  REJECT(tb_body_get_joints(A, out, -3), TB_ERR_INVALID_ARGUMENT, "capacity");
}
END_TEST

/* Every joint function on a destroyed joint, a null one and a garbage one. */
START_TEST(stale_joints) {
  tb_joint_id garbage = JR;
  garbage.generation = (uint16_t)(garbage.generation + 77);
  tb_joint_id far = {1000000, JR.world0, 1};
  const tb_joint_id handles[] = {DEAD_JOINT, {0, 0, 0}, garbage, far};
  for (int i = 0; i < 4; ++i) {
    tb_joint_id j = handles[i];
    tb_vec2 o = {0, 0};
    ck_assert(!tb_joint_is_valid(j));
    REJECT(tb_destroy_joint(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_type(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_body_a(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_body_b(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_local_anchor_a(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_local_anchor_b(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_collide_connected(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_set_collide_connected(j, true), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_user_data(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_set_user_data(j, NULL), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_constraint_force(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_joint_get_constraint_torque(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_distance_joint_set_length(j, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_distance_joint_get_length(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_distance_joint_get_current_length(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_distance_joint_set_spring(j, true, 1, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_distance_joint_set_limits(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_revolute_joint_get_angle(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_revolute_joint_set_limits(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_revolute_joint_set_motor(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_revolute_joint_set_spring(j, true, 1, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_revolute_joint_get_motor_torque(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_get_translation(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_get_speed(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_set_limits(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_set_motor(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_set_spring(j, true, 1, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_prismatic_joint_get_motor_force(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_weld_joint_set_stiffness(j, 1, 1, 1, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_wheel_joint_set_motor(j, true, 0, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_wheel_joint_set_spring(j, true, 1, 1), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_wheel_joint_get_motor_torque(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_mouse_joint_set_target(j, o), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_mouse_joint_get_target(j), TB_ERR_STALE_HANDLE, "joint");
    REJECT(tb_motor_joint_set_offsets(j, o, 0), TB_ERR_STALE_HANDLE, "joint");
  }
}
END_TEST

/* ---- queries --------------------------------------------------------------- */

static bool count_overlap(tb_shape_id shape, void* context) {
  (void)shape;
  *(int*)context += 1;
  return true;
}

static float count_cast(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  (void)shape, (void)point, (void)normal;
  *(int*)context += 1;
  return fraction;
}

START_TEST(query_calls) {
  tb_query_filter f = tb_default_query_filter();
  int hits = 0;
  tb_vec2 o = {0, 5}, t = {0, -10};
  tb_shape_proxy proxy = {{{0, 0}}, 1, 0.5f};
  tb_transform id = {{0, 2}, {1, 0}};
  for (int i = 0; i < N_BAD; ++i) {
    float x = bad_reals[i];
    tb_vec2 v = {x, 0};
    REJECT(tb_world_cast_ray(W, v, t, f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "origin");
    REJECT(tb_world_cast_ray(W, o, v, f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "translation");
    REJECT(tb_world_cast_ray_closest(W, v, t, f), TB_ERR_INVALID_ARGUMENT, "origin");
    tb_ray_result res[4];
    int n = 0;
    REJECT(tb_world_cast_ray_all(W, o, v, f, res, 4, &n), TB_ERR_INVALID_ARGUMENT, "translation");
    REJECT(tb_world_overlap_point(W, v, f, count_overlap, &hits), TB_ERR_INVALID_ARGUMENT, "point");
    REJECT(tb_world_overlap_aabb(W, ((tb_aabb){{x, 0}, {1, 1}}), f, count_overlap, &hits), TB_ERR_INVALID_ARGUMENT,
           "aabb");
    REJECT(tb_world_overlap_shape(W, &proxy, ((tb_transform){v, {1, 0}}), f, count_overlap, &hits),
           TB_ERR_INVALID_ARGUMENT, "transform");
    REJECT(tb_world_overlap_shape(W, &proxy, ((tb_transform){o, {x, 0}}), f, count_overlap, &hits),
           TB_ERR_INVALID_ARGUMENT, "transform");
    REJECT(tb_world_cast_shape(W, &proxy, id, v, f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "translation");
    tb_shape_proxy bad = proxy;
    bad.points[0].y = x;
    REJECT(tb_world_overlap_shape(W, &bad, id, f, count_overlap, &hits), TB_ERR_INVALID_ARGUMENT, "proxy");
    bad = proxy;
    bad.radius = x;
    REJECT(tb_world_cast_shape(W, &bad, id, t, f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "proxy");
  }
  REJECT(tb_world_cast_ray(W, o, ((tb_vec2){0, 0}), f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "translation");
  REJECT(tb_world_cast_ray(W, o, t, f, NULL, NULL), TB_ERR_NULL_ARGUMENT, "fn");
  REJECT(tb_world_overlap_aabb(W, ((tb_aabb){{0, 0}, {1, 1}}), f, NULL, NULL), TB_ERR_NULL_ARGUMENT, "fn");
  REJECT(tb_world_overlap_aabb(W, ((tb_aabb){{1, 1}, {0, 0}}), f, count_overlap, &hits), TB_ERR_INVALID_ARGUMENT,
         "aabb");
  REJECT(tb_world_overlap_point(W, o, f, NULL, NULL), TB_ERR_NULL_ARGUMENT, "fn");
  REJECT(tb_world_overlap_shape(W, NULL, id, f, count_overlap, &hits), TB_ERR_NULL_ARGUMENT, "proxy");
  REJECT(tb_world_cast_shape(W, &proxy, id, t, f, NULL, NULL), TB_ERR_NULL_ARGUMENT, "fn");
  tb_shape_proxy many = proxy;
  many.count = TB_MAX_POLYGON_VERTICES + 1;
  REJECT(tb_world_overlap_shape(W, &many, id, f, count_overlap, &hits), TB_ERR_INVALID_ARGUMENT, "count");
  many.count = 0;
  REJECT(tb_world_cast_shape(W, &many, id, t, f, count_cast, &hits), TB_ERR_INVALID_ARGUMENT, "count");
  tb_ray_result res[2];
  int n = 0;
  REJECT(tb_world_cast_ray_all(W, o, t, f, res, 2, NULL), TB_ERR_NULL_ARGUMENT, "count");
  REJECT(tb_world_cast_ray_all(W, o, t, f, NULL, 2, &n), TB_ERR_INVALID_ARGUMENT, "out");
  REJECT(tb_world_cast_ray_all(W, o, t, f, res, -1, &n), TB_ERR_INVALID_ARGUMENT, "capacity");
  ck_assert_int_eq(hits, 0);
}
END_TEST

/* What refused getters return, as the header says: zero, and the identity
 * for a rotation or transform; a refused closest-ray cast looks like a ray
 * that hit nothing. */
START_TEST(refused_getters_return_the_documented_values) {
  tb_rot q = {0.5f, 0.5f};
  REJECT(q = tb_body_get_rotation(DEAD_BODY), TB_ERR_STALE_HANDLE, "body");
  ck_assert(q.c == 1.0f && q.s == 0.0f);
  tb_transform xf = {{1, 1}, {0, 1}};
  REJECT(xf = tb_body_get_transform(DEAD_BODY), TB_ERR_STALE_HANDLE, "body");
  ck_assert(xf.p.x == 0.0f && xf.p.y == 0.0f && xf.q.c == 1.0f && xf.q.s == 0.0f);
  tb_ray_result r = {{1, 1, 1}, {1, 1}, {1, 1}, 0.5f, true};
  REJECT(r = tb_world_cast_ray_closest(W, (tb_vec2){NAN, 0}, (tb_vec2){1, 0}, tb_default_query_filter()),
         TB_ERR_INVALID_ARGUMENT, "origin");
  ck_assert(!r.hit && r.fraction == 1.0f && tb_shape_id_is_null(r.shape));
  ck_assert(r.point.x == 0.0f && r.point.y == 0.0f && r.normal.x == 0.0f && r.normal.y == 0.0f);
  tb_ray_result miss = tb_world_cast_ray_closest(W, (tb_vec2){0, 50}, (tb_vec2){1, 0}, tb_default_query_filter());
  ck_assert(!miss.hit && miss.fraction == r.fraction);
}
END_TEST

/* ---- calls into the world from inside callbacks ---------------------------- */

typedef struct reentry {
  int calls;
  tb_result destroy_body, destroy_shape, create_body, destroy_joint, step, set_velocity, destroy_world;
  tb_result create_shape, destroy_chain, create_joint;
  tb_result user_data[4]; /* world, body, shape, joint: a change like any other */
} reentry;

static void try_everything(reentry* r) {
  r->calls += 1;
  r->destroy_body = tb_destroy_body(B);
  r->destroy_shape = tb_destroy_shape(BOX);
  tb_body_def bd = tb_default_body_def();
  r->create_body = tb_body_id_is_null(tb_create_body(W, &bd)) ? tb_last_result() : TB_OK;
  tb_circle c = {{0, 0}, 0.25f};
  tb_shape_def sd = tb_default_shape_def();
  r->create_shape = tb_shape_id_is_null(tb_create_circle_shape(C, &sd, &c)) ? tb_last_result() : TB_OK;
  r->destroy_joint = tb_destroy_joint(JD);
  r->destroy_chain = tb_destroy_chain(CHAIN);
  tb_distance_joint_def dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = C;
  r->create_joint = tb_joint_id_is_null(tb_create_distance_joint(W, &dd)) ? tb_last_result() : TB_OK;
  r->step = tb_world_step(W, 1.0f / 60.0f, 1);
  r->set_velocity = tb_body_set_linear_velocity(A, (tb_vec2){1, 1});
  r->destroy_world = tb_destroy_world(W);
  static int marker;
  r->user_data[0] = tb_world_set_user_data(W, &marker);
  r->user_data[1] = tb_body_set_user_data(A, &marker);
  r->user_data[2] = tb_shape_set_user_data(BOX, &marker);
  r->user_data[3] = tb_joint_set_user_data(JD, &marker);
}

#define assert_all_locked(r) assert_all_locked_at((r), __LINE__)
static void assert_all_locked_at(const reentry* r, int line) {
  ck_assert_msg(r->calls > 0, "line %d: the callback was never called", line);
  ck_assert_int_eq(r->destroy_body, TB_ERR_LOCKED);
  ck_assert_int_eq(r->destroy_shape, TB_ERR_LOCKED);
  ck_assert_int_eq(r->create_body, TB_ERR_LOCKED);
  ck_assert_int_eq(r->create_shape, TB_ERR_LOCKED);
  ck_assert_int_eq(r->destroy_joint, TB_ERR_LOCKED);
  ck_assert_int_eq(r->destroy_chain, TB_ERR_LOCKED);
  ck_assert_int_eq(r->create_joint, TB_ERR_LOCKED);
  ck_assert_int_eq(r->step, TB_ERR_LOCKED);
  ck_assert_int_eq(r->set_velocity, TB_ERR_LOCKED);
  ck_assert_int_eq(r->destroy_world, TB_ERR_LOCKED);
  for (int k = 0; k < 4; ++k) ck_assert_msg(r->user_data[k] == TB_ERR_LOCKED, "line %d: user data setter %d", line, k);
  ck_assert(tb_world_is_valid(W) && tb_body_is_valid(B) && tb_shape_is_valid(BOX) && tb_joint_is_valid(JD) &&
            tb_chain_is_valid(CHAIN));
}

static bool overlap_reenter(tb_shape_id shape, void* context) {
  (void)shape;
  try_everything(context);
  return true;
}

static float cast_reenter(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  (void)shape, (void)point, (void)normal;
  try_everything(context);
  return fraction;
}

/* A query callback may read the world, but every change is refused (bodies,
 * shapes, chains, joints, stepping, the world itself): the trees are being
 * walked. The query still reports the same shapes. */
START_TEST(changes_inside_query_callbacks) {
  tb_query_filter f = tb_default_query_filter();
  reentry r = {0};
  ck_assert_int_eq(tb_world_overlap_aabb(W, ((tb_aabb){{-10, -1}, {10, 5}}), f, overlap_reenter, &r), TB_OK);
  assert_all_locked(&r);
  assert_unchanged("overlap_aabb callback");
  r = (reentry){0};
  tb_vec2 at = tb_body_get_position(A); /* the joints have pulled A a little */
  ck_assert_int_eq(tb_world_overlap_point(W, at, f, overlap_reenter, &r), TB_OK);
  assert_all_locked(&r);
  r = (reentry){0};
  tb_shape_proxy proxy = {{{0, 0}}, 1, 0.5f};
  ck_assert_int_eq(tb_world_overlap_shape(W, &proxy, (tb_transform){at, {1, 0}}, f, overlap_reenter, &r), TB_OK);
  assert_all_locked(&r);
  r = (reentry){0};
  ck_assert_int_eq(tb_world_cast_ray(W, (tb_vec2){-10, at.y}, (tb_vec2){20, 0}, f, cast_reenter, &r), TB_OK);
  assert_all_locked(&r);
  r = (reentry){0};
  ck_assert_int_eq(
      tb_world_cast_shape(W, &proxy, (tb_transform){{-10, at.y}, {1, 0}}, (tb_vec2){20, 0}, f, cast_reenter, &r),
      TB_OK);
  assert_all_locked(&r);
  assert_unchanged("query callbacks");
  check_twin();
  /* and the world is usable again afterwards */
  ck_assert_int_eq(tb_body_set_linear_velocity(A, (tb_vec2){0.5f, 0}), TB_OK);
  ck_assert_int_eq(tb_world_step(W, 1.0f / 60.0f, 4), TB_OK);
}
END_TEST

static reentry step_reentry;

static bool pre_solve_reenter(tb_shape_id a, tb_shape_id b, const tb_manifold* m, void* context) {
  (void)a, (void)b, (void)m, (void)context;
  try_everything(&step_reentry);
  return true;
}

static bool filter_reenter(tb_shape_id a, tb_shape_id b, void* context) {
  (void)a, (void)b, (void)context;
  try_everything(&step_reentry);
  return true;
}

static void field_reenter(double t, const tb_body_state* s, void* context, tb_vec2* force, float* torque) {
  (void)t, (void)s, (void)context, (void)force, (void)torque;
  if (step_reentry.calls == 0) try_everything(&step_reentry);
}

START_TEST(changes_inside_step_callbacks) {
  /* pre-solve: on a shape that asks for it */
  tb_world_def wd = tb_default_world_def();
  wd.pre_solve = pre_solve_reenter;
  wd.custom_filter = filter_reenter;
  wd.force_field = field_reenter;
  tb_world_id keep = W;
  tb_chain_id keep_chain = CHAIN;
  W = tb_create_world(&wd);
  tb_body_def bd = tb_default_body_def();
  tb_body_id ground = tb_create_body(W, &bd);
  /* a chain of this world, far below the boxes, for the callbacks to try to destroy */
  const tb_vec2 deep[2] = {{-5, -20}, {5, -20}};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = deep;
  cd.count = 2;
  CHAIN = tb_create_chain(ground, &cd);
  ck_assert(tb_chain_is_valid(CHAIN));
  tb_polygon floor;
  tb_make_box(10, 0.5f, &floor);
  tb_shape_def sd = tb_default_shape_def();
  sd.enable_pre_solve_events = true;
  tb_create_polygon_shape(ground, &sd, &floor);
  A = tbt_box_body(W, 0, 0.95f, 0.5f, 0.5f);
  B = tbt_box_body(W, 3, 0.95f, 0.5f, 0.5f);
  C = tbt_box_body(W, 6, 0.95f, 0.5f, 0.5f);
  tb_body_get_shapes(A, &BOX, 1);
  tb_distance_joint_def dd = tb_default_distance_joint_def();
  dd.body_a = A;
  dd.body_b = C;
  dd.length = 6.0f;
  JD = tb_create_distance_joint(W, &dd);
  step_reentry = (reentry){0};
  ck_assert_int_eq(tb_world_step(W, 1.0f / 60.0f, 4), TB_OK);
  assert_all_locked(&step_reentry);
  tb_counts counts = tb_world_get_counts(W);
  ck_assert_int_eq(counts.body_count, 4);
  ck_assert_int_eq(counts.joint_count, 1);
  ck_assert_int_eq(counts.shape_count, 5); /* the floor, three boxes, one chain segment */
  ck_assert_int_eq(tb_chain_get_segment_count(CHAIN), 1);
  tb_destroy_world(W);
  W = keep;
  CHAIN = keep_chain;
}
END_TEST

static reentry draw_reentry;

static void polygon_reenter(tb_transform xf, const tb_vec2* v, int n, float r, tb_color c, void* context) {
  (void)xf, (void)v, (void)n, (void)r, (void)c, (void)context;
  try_everything(&draw_reentry);
}

static void segment_reenter(tb_vec2 p1, tb_vec2 p2, tb_color c, void* context) {
  (void)p1, (void)p2, (void)c, (void)context;
  try_everything(&draw_reentry);
}

/* A draw callback walks the same pools a destroy frees: every change from
 * inside one is refused, the drawing goes on, and nothing changed. */
START_TEST(changes_inside_draw_callbacks) {
  tb_debug_draw d = tb_default_debug_draw();
  d.draw_solid_polygon = polygon_reenter;
  d.draw_segment = segment_reenter;
  d.draw_aabbs = true;
  draw_reentry = (reentry){0};
  ck_assert_int_eq(tb_world_draw(W, &d), TB_OK);
  assert_all_locked(&draw_reentry);
  assert_unchanged("draw callbacks");
  check_twin();
  /* and the world is unlocked again afterwards */
  ck_assert_int_eq(tb_body_set_linear_velocity(A, (tb_vec2){0.5f, 0}), TB_OK);
  ck_assert_int_eq(tb_world_step(W, 1.0f / 60.0f, 4), TB_OK);
}
END_TEST

/* ---- NaN through the force field ------------------------------------------- */

static tb_body_id poisoned;

static void nan_field(double t, const tb_body_state* s, void* context, tb_vec2* force, float* torque) {
  (void)t, (void)context;
  if (s->body.index1 == poisoned.index1) {
    *force = (tb_vec2){NAN, 0.0f};
    *torque = INFINITY;
  } else {
    *force = (tb_vec2){0.0f, 1.0f};
  }
}

/* A NaN from the user's field is caught at the end of the step and reported;
 * the body keeps its state from before the step, and its neighbours (touching
 * it, jointed to it) are simulated as usual with finite states. */
START_TEST(nan_from_the_force_field_is_contained) {
  for (int integrator = 0; integrator < 3; ++integrator) {
    tb_world_id w = tbt_world(0.0f, -10.0f);
    tb_world_set_integrator(w, (tb_integrator)integrator);
    tb_body_def bd = tb_default_body_def();
    tb_body_id ground = tb_create_body(w, &bd);
    tb_polygon floor;
    tb_make_box(20, 0.5f, &floor);
    tb_shape_def sd = tb_default_shape_def();
    tb_create_polygon_shape(ground, &sd, &floor);
    tb_body_id left = tbt_box_body(w, -1.0f, 0.99f, 0.5f, 0.5f);
    poisoned = tbt_box_body(w, 0.0f, 0.99f, 0.5f, 0.5f); /* touches left and right */
    tb_body_id right = tbt_box_body(w, 1.0f, 0.99f, 0.5f, 0.5f);
    tb_body_id hanger = tbt_box_body(w, 0.0f, 3.0f, 0.2f, 0.2f);
    tb_body_id free_body = tbt_box_body(w, 10.0f, 5.0f, 0.2f, 0.2f);
    tb_revolute_joint_def rd = tb_default_revolute_joint_def();
    rd.body_a = poisoned;
    rd.body_b = hanger;
    rd.local_anchor_a = (tb_vec2){0.0f, 2.0f};
    tb_create_revolute_joint(w, &rd);
    tb_body_set_linear_velocity(poisoned, (tb_vec2){0.25f, 0.5f});
    for (int i = 0; i < 10; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    tb_transform before = tb_body_get_transform(poisoned);
    tb_vec2 v_before = tb_body_get_linear_velocity(poisoned);
    float w_before = tb_body_get_angular_velocity(poisoned);
    tb_vec2 free_before = tb_body_get_linear_velocity(free_body);

    ck_assert_int_eq(tb_world_set_force_field(w, nan_field, NULL), TB_OK);
    tb_clear_error();
    ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_NUMERIC);
    ck_assert_int_eq(tb_last_result(), TB_ERR_NUMERIC);
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "1 bodies"));
    ck_assert_ptr_nonnull(strstr(tb_world_last_error(w), "force field"));
    tb_transform after = tb_body_get_transform(poisoned);
    ck_assert(memcmp(&before, &after, sizeof before) == 0);
    tb_vec2 v_after = tb_body_get_linear_velocity(poisoned);
    ck_assert(memcmp(&v_before, &v_after, sizeof v_after) == 0);
    ck_assert(tb_body_get_angular_velocity(poisoned) == w_before);
    const tb_body_id others[] = {left, right, hanger, free_body};
    for (int k = 0; k < 4; ++k) {
      tb_vec2 p = tb_body_get_position(others[k]), v = tb_body_get_linear_velocity(others[k]);
      ck_assert_msg(isfinite(p.x) && isfinite(p.y) && isfinite(v.x) && isfinite(v.y) &&
                        isfinite(tb_body_get_angle(others[k])) && isfinite(tb_body_get_angular_velocity(others[k])),
                    "integrator %d: neighbour %d poisoned", integrator, k);
    }
    /* the untouched body got the field's force: (0, 1) N on top of gravity */
    tb_vec2 free_after = tb_body_get_linear_velocity(free_body);
    float m = tb_body_get_mass(free_body);
    ck_assert_near(free_after.y - free_before.y, (-10.0f + 1.0f / m) / 60.0f, 1e-4);
    /* the world goes on once the field behaves */
    ck_assert_int_eq(tb_world_set_force_field(w, NULL, NULL), TB_OK);
    for (int i = 0; i < 30; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    ck_assert(isfinite(tb_body_get_position(poisoned).y));
    tb_destroy_world(w);
  }
}
END_TEST

/* ---- found by fuzz/fuzz_manifold.c ------------------------------------------- */

/* An incident edge that meets the reference face's slab in one point (its end
 * exactly on the side plane) was clipped to that point twice: a 2-point
 * manifold of coincident points, while the swapped order gave 1 point. */
START_TEST(clip_to_a_single_point_gives_one_point) {
  tb_capsule a = {{-0.40911f, -0.882567f}, {0.0117648f, -0.246052f}, 0.510823f};
  tb_capsule b = {{0.0117648f, 0.0117648f}, {0.511765f, 0.0117648f}, 0.510823f};
  tb_transform xf = {{0.0470591f, 0.0470591f}, {0.999291f, 0.0376381f}};
  tb_manifold ab = tb_collide_capsules(&a, xf, &b, xf), ba = tb_collide_capsules(&b, xf, &a, xf);
  ck_assert_int_eq(ab.point_count, ba.point_count);
  ck_assert_int_eq(ab.point_count, 1);
  ck_assert_near(ab.normal.x, -ba.normal.x, 1e-6);
  ck_assert_near(ab.normal.y, -ba.normal.y, 1e-6);
  ck_assert_near(ab.points[0].point.x, ba.points[0].point.x, 1e-5);
  ck_assert_near(ab.points[0].point.y, ba.points[0].point.y, 1e-5);
}
END_TEST

static Suite* bad_input_table_suite(void) {
  Suite* s = suite_create("bad_input_table");
  TCase* tc = tcase_create("bad_input_table");
  tcase_add_checked_fixture(tc, setup, teardown);
  tcase_add_test(tc, world_settings);
  tcase_add_test(tc, stale_worlds);
  tcase_add_test(tc, global_settings);
  tcase_add_test(tc, draw_settings);
  tcase_add_test(tc, make_polygon_table);
  tcase_add_test(tc, hand_made_polygon_table);
  tcase_add_test(tc, mass_and_collide_functions);
  tcase_add_test(tc, geometry_and_distance_calls);
  tcase_add_test(tc, body_and_shape_extras);
  tcase_add_test(tc, shape_geometry_calls);
  tcase_add_test(tc, chain_calls);
  tcase_add_test(tc, refusals_at_the_edge_of_the_world);
  tcase_add_test(tc, joint_creation);
  tcase_add_test(tc, joint_calls);
  tcase_add_test(tc, stale_joints);
  tcase_add_test(tc, query_calls);
  tcase_add_test(tc, refused_getters_return_the_documented_values);
  tcase_add_test(tc, changes_inside_query_callbacks);
  tcase_add_test(tc, changes_inside_step_callbacks);
  tcase_add_test(tc, changes_inside_draw_callbacks);
  tcase_add_test(tc, nan_from_the_force_field_is_contained);
  tcase_add_test(tc, clip_to_a_single_point_gives_one_point);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(bad_input_table_suite)
