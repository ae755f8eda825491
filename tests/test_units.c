/* Length units (tb_set_length_units_per_meter): a scene built in pixels moves
 * as the same scene in metres, scaled. At a power of two every float of the
 * scene scales exactly, so any length tolerance left in metres shows up as a
 * difference in the bits; at 100 px/m rounding differs and the motion agrees
 * within a tolerance derived below.
 *
 * Every test leaves the default of 1 behind (the suites also run in one
 * process under make sanitize). */
#include <stdio.h>
#include <string.h>

#include "test_util.h"

#define BOXES 4
#define STEPS 300

typedef struct scene {
  tb_world_id world;
  tb_body_id boxes[BOXES];
  tb_body_id ball, pendulum;
} scene;

typedef struct run {
  tb_vec2 box_position[BOXES], ball_position, pendulum_position;
  float box_angle[BOXES], ball_angle, pendulum_angle;
  int sleep_step; /* the first step after which the stack sleeps; -1 never */
  tb_vec2 ball_velocity;
} run;

/* A ground with a 20-degree slope, a stack of boxes, a ball rolling down the
 * slope and a box pendulum on a revolute joint, all lengths times k (metres
 * to units), densities over k^2 (the same masses), gravity times k. */
static scene build(float k) {
  tb_world_def wd = tb_default_world_def();
  ck_assert_float_eq(wd.gravity.y, -10.0f * k);
  scene sc;
  sc.world = tb_create_world(&wd);
  ck_assert(!tb_world_id_is_null(sc.world));
  tb_body_def gd = tb_default_body_def();
  tb_body_id ground = tb_create_body(sc.world, &gd);
  tb_shape_def sd = tb_default_shape_def();
  sd.density = 1.0f / (k * k);
  tb_polygon floor;
  ck_assert_int_eq(tb_make_offset_box(60.0f * k, 0.5f * k, (tb_vec2){0.0f, -0.5f * k}, 0.0f, &floor), TB_OK);
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(ground, &sd, &floor)));
  const tb_vec2 slope[3] = {{6.0f * k, 0.0f}, {16.0f * k, 0.0f}, {6.0f * k, 3.64f * k}};
  tb_polygon ramp;
  ck_assert_int_eq(tb_make_polygon(slope, 3, 0.0f, &ramp), TB_OK);
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(ground, &sd, &ramp)));
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(0.5f * k, 0.5f * k, &box), TB_OK);
  for (int i = 0; i < BOXES; ++i) {
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = (tb_vec2){-4.0f * k, (0.6f + 1.1f * (float)i) * k}; /* dropped 0.1 m */
    sc.boxes[i] = tb_create_body(sc.world, &bd);
    ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(sc.boxes[i], &sd, &box)));
  }
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){6.5f * k, 3.8f * k};
  sc.ball = tb_create_body(sc.world, &bd);
  tb_circle ball = {{0.0f, 0.0f}, 0.25f * k};
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(sc.ball, &sd, &ball)));
  bd.position = (tb_vec2){-10.0f * k, 4.0f * k};
  sc.pendulum = tb_create_body(sc.world, &bd);
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(sc.pendulum, &sd, &box)));
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = ground;
  jd.body_b = sc.pendulum;
  jd.local_anchor_a = (tb_vec2){-8.0f * k, 4.0f * k};
  jd.local_anchor_b = (tb_vec2){2.0f * k, 0.0f};
  ck_assert(!tb_joint_id_is_null(tb_create_revolute_joint(sc.world, &jd)));
  return sc;
}

static tb_vec2 scaled(float s, tb_vec2 v) { return (tb_vec2){s * v.x, s * v.y}; }

/* Runs the scene at units_per_meter k, positions read back in metres. */
static run simulate(float k) {
  ck_assert_int_eq(tb_set_length_units_per_meter(k), TB_OK);
  scene sc = build(k);
  run r = {.sleep_step = -1};
  for (int step = 0; step < STEPS; ++step) {
    ck_assert_int_eq(tb_world_step(sc.world, 1.0f / 60.0f, 4), TB_OK);
    if (r.sleep_step < 0 && !tb_body_is_awake(sc.boxes[BOXES - 1])) r.sleep_step = step;
  }
  for (int i = 0; i < BOXES; ++i) {
    r.box_position[i] = tb_body_get_position(sc.boxes[i]);
    r.box_angle[i] = tb_body_get_angle(sc.boxes[i]);
  }
  r.ball_position = tb_body_get_position(sc.ball);
  r.ball_angle = tb_body_get_angle(sc.ball);
  r.ball_velocity = tb_body_get_linear_velocity(sc.ball);
  r.pendulum_position = tb_body_get_position(sc.pendulum);
  r.pendulum_angle = tb_body_get_angle(sc.pendulum);
  ck_assert_int_eq(tb_destroy_world(sc.world), TB_OK);
  ck_assert_int_eq(tb_set_length_units_per_meter(1.0f), TB_OK);
  for (int i = 0; i < BOXES; ++i) r.box_position[i] = scaled(1.0f / k, r.box_position[i]);
  r.ball_position = scaled(1.0f / k, r.ball_position);
  r.ball_velocity = scaled(1.0f / k, r.ball_velocity);
  r.pendulum_position = scaled(1.0f / k, r.pendulum_position);
  return r;
}

/* 128 px/m: a power of two, so every product and quotient of the scene is
 * the metre one times a power of two, exactly (no overflow or underflow at
 * these sizes). The bits must agree: a tolerance left in metres would make
 * some comparison go the other way. */
START_TEST(power_of_two_units_move_bit_for_bit_as_metres) {
  run m = simulate(1.0f), px = simulate(128.0f);
  ck_assert_int_ge(m.sleep_step, 0);
  ck_assert_int_eq(px.sleep_step, m.sleep_step);
  ck_assert_mem_eq(&px.box_position, &m.box_position, sizeof m.box_position);
  ck_assert_mem_eq(&px.box_angle, &m.box_angle, sizeof m.box_angle);
  ck_assert_mem_eq(&px.ball_position, &m.ball_position, sizeof m.ball_position);
  ck_assert_mem_eq(&px.ball_velocity, &m.ball_velocity, sizeof m.ball_velocity);
  ck_assert_float_eq(px.ball_angle, m.ball_angle);
  ck_assert_mem_eq(&px.pendulum_position, &m.pendulum_position, sizeof m.pendulum_position);
  ck_assert_float_eq(px.pendulum_angle, m.pendulum_angle);
  ck_assert_float_gt(m.ball_position.x, 10.0f); /* it rolled down, past the ramp's foot */
}
END_TEST

/* 100 px/m: every operation rounds differently (relative 6e-8 each), and
 * the steps compound it. The motion here is smooth (a stack that settles, a
 * ball rolling 29 m, an undamped pendulum), so the differences stay a small
 * multiple of float rounding of the lengths: relative 1e-5 of the scene's
 * 30 m extent, 3e-4 m, is the bound (measured: boxes 3e-8 m, ball 4.2e-5 m
 * after 29 m, pendulum 8e-6 m). It is still 16 times below the slop
 * (5e-3 m), where a tolerance left in metres would show (a contact found or
 * lost, a point welded), and sleep, decided on speeds against a threshold,
 * comes on the same step. */
START_TEST(pixel_units_agree_with_metres) {
  run m = simulate(1.0f), px = simulate(100.0f);
  float worst = 0.0f;
  for (int i = 0; i < BOXES; ++i)
    worst = fmaxf(worst, fmaxf(fabsf(px.box_position[i].x - m.box_position[i].x),
                               fabsf(px.box_position[i].y - m.box_position[i].y)));
  printf("units 100: sleep %d/%d, boxes %g, ball %g %g (at %g %g), pendulum %g %g\n", px.sleep_step, m.sleep_step,
         (double)worst, (double)(px.ball_position.x - m.ball_position.x),
         (double)(px.ball_position.y - m.ball_position.y), (double)m.ball_position.x, (double)m.ball_position.y,
         (double)(px.pendulum_position.x - m.pendulum_position.x),
         (double)(px.pendulum_position.y - m.pendulum_position.y));
  const float tol = 1e-5f * 30.0f; /* m, see above */
  for (int i = 0; i < BOXES; ++i) {
    ck_assert_near(px.box_position[i].x, m.box_position[i].x, tol);
    ck_assert_near(px.box_position[i].y, m.box_position[i].y, tol);
    ck_assert_near(px.box_angle[i], m.box_angle[i], tol);
  }
  ck_assert_near(px.ball_position.x, m.ball_position.x, tol);
  ck_assert_near(px.ball_position.y, m.ball_position.y, tol);
  ck_assert_near(px.pendulum_position.x, m.pendulum_position.x, tol);
  ck_assert_near(px.pendulum_position.y, m.pendulum_position.y, tol);
  /* sleep is decided on speeds against a threshold: the same step */
  ck_assert_int_ge(m.sleep_step, 0);
  ck_assert_int_eq(px.sleep_step, m.sleep_step);
}
END_TEST

/* The defaults that are lengths, speeds or forces scale; the rest do not. */
START_TEST(defaults_scale_with_the_units) {
  ck_assert_int_eq(tb_set_length_units_per_meter(100.0f), TB_OK);
  ck_assert_float_eq(tb_get_length_units_per_meter(), 100.0f);
  tb_world_def wd = tb_default_world_def();
  ck_assert_float_eq(wd.gravity.y, -1000.0f);
  ck_assert_float_eq(wd.maximum_linear_speed, 1.0e5f);
  ck_assert_float_eq(wd.restitution_threshold, 100.0f);
  ck_assert_float_eq(wd.hit_event_threshold, 100.0f);
  ck_assert_float_eq(wd.contact_push_max_velocity, 300.0f);
  ck_assert_float_eq(wd.contact_hertz, 120.0f);
  ck_assert_float_eq(tb_default_body_def().sleep_threshold, 5.0f);
  ck_assert_float_eq(tb_default_distance_joint_def().length, 100.0f);
  ck_assert_float_eq(tb_default_debug_draw().normal_length, 0.3f * 100.0f);
  /* limits: a pixel world takes 100 times the metre speed cap and gravity */
  wd.maximum_linear_speed = 50.0f * TB_MAX_SPEED;
  wd.gravity = (tb_vec2){0.0f, -50.0f * TB_MAX_GRAVITY};
  tb_world_id w = tb_create_world(&wd);
  ck_assert(!tb_world_id_is_null(w));
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  /* the weld distance: two corners 0.42 apart are one point at 100 px/m
   * (slop 0.5 px), two at 1 unit/m (slop 0.005 m) */
  const tb_vec2 close[5] = {{0.0f, 0.0f}, {10.0f, 0.0f}, {10.0f, 10.0f}, {0.0f, 10.0f}, {0.3f, -0.3f}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(close, 5, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  ck_assert_int_eq(tb_set_length_units_per_meter(1.0f), TB_OK);
  ck_assert_int_eq(tb_make_polygon(close, 5, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 5);
  ck_assert_float_eq(tb_default_world_def().gravity.y, -10.0f);
}
END_TEST

Suite* units_suite(void) {
  Suite* s = suite_create("units");
  TCase* tc = tcase_create("core");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, power_of_two_units_move_bit_for_bit_as_metres);
  tcase_add_test(tc, pixel_units_agree_with_metres);
  tcase_add_test(tc, defaults_scale_with_the_units);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(units_suite)
