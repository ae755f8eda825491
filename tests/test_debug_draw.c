/* tb_world_draw: which callbacks it calls for each shape type, joint and
 * contact, the switches, the state colours, and bad input. */
#include <stdio.h>
#include <string.h>

#include "test_util.h"

typedef struct recorder {
  int polygons, circles, capsules, segments, points, transforms, strings;
  tb_color last_polygon_color, last_circle_color;
  int last_polygon_count;
  float last_polygon_radius;
  tb_transform last_circle_transform;
  float last_circle_radius;
  char last_string[64];
} recorder;

static void rec_polygon(tb_transform xf, const tb_vec2* v, int count, float radius, tb_color color, void* ctx) {
  (void)xf;
  (void)v;
  recorder* r = ctx;
  r->polygons += 1;
  r->last_polygon_count = count;
  r->last_polygon_radius = radius;
  r->last_polygon_color = color;
}
static void rec_circle(tb_transform xf, float radius, tb_color color, void* ctx) {
  recorder* r = ctx;
  r->circles += 1;
  r->last_circle_transform = xf;
  r->last_circle_radius = radius;
  r->last_circle_color = color;
}
static void rec_capsule(tb_vec2 a, tb_vec2 b, float radius, tb_color color, void* ctx) {
  (void)a, (void)b, (void)radius, (void)color;
  ((recorder*)ctx)->capsules += 1;
}
static void rec_segment(tb_vec2 a, tb_vec2 b, tb_color color, void* ctx) {
  (void)a, (void)b, (void)color;
  ((recorder*)ctx)->segments += 1;
}
static void rec_point(tb_vec2 p, float size, tb_color color, void* ctx) {
  (void)p, (void)size, (void)color;
  ((recorder*)ctx)->points += 1;
}
static void rec_transform(tb_transform xf, void* ctx) {
  (void)xf;
  ((recorder*)ctx)->transforms += 1;
}
static void rec_string(tb_vec2 p, const char* text, tb_color color, void* ctx) {
  (void)p, (void)color;
  recorder* r = ctx;
  r->strings += 1;
  snprintf(r->last_string, sizeof r->last_string, "%s", text);
}

static tb_debug_draw recording_draw(recorder* r) {
  memset(r, 0, sizeof *r);
  tb_debug_draw d = tb_default_debug_draw();
  d.draw_solid_polygon = rec_polygon;
  d.draw_solid_circle = rec_circle;
  d.draw_solid_capsule = rec_capsule;
  d.draw_segment = rec_segment;
  d.draw_point = rec_point;
  d.draw_transform = rec_transform;
  d.draw_string = rec_string;
  d.context = r;
  return d;
}

static bool same_color(tb_color a, tb_color b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

static tb_body_id body(tb_world_id w, tb_body_type type, float x, float y) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = (tb_vec2){x, y};
  return tb_create_body(w, &bd);
}

START_TEST(each_shape_type_has_its_callback) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_body_id b = body(w, TB_DYNAMIC_BODY, 0.0f, 0.0f);
  tb_polygon box;
  ck_assert_int_eq(tb_make_rounded_box(0.5f, 0.25f, 0.1f, &box), TB_OK);
  tb_create_polygon_shape(b, &sd, &box);
  tb_circle c = {{1.0f, 2.0f}, 0.3f};
  tb_create_circle_shape(b, &sd, &c);
  tb_capsule cap = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.2f};
  tb_create_capsule_shape(b, &sd, &cap);
  tb_body_id g = body(w, TB_STATIC_BODY, 0.0f, -5.0f);
  tb_segment seg = {{-5.0f, 0.0f}, {5.0f, 0.0f}};
  tb_create_segment_shape(g, &sd, &seg);
  tb_vec2 pts[4] = {{-3.0f, 1.0f}, {-1.0f, 0.0f}, {1.0f, 0.0f}, {3.0f, 1.0f}};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = pts;
  cd.count = 4;
  ck_assert(!tb_chain_id_is_null(tb_create_chain(g, &cd)));

  recorder r;
  tb_debug_draw d = recording_draw(&r);
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.polygons, 1);
  ck_assert_int_eq(r.last_polygon_count, 4);
  ck_assert_float_eq(r.last_polygon_radius, 0.1f);
  ck_assert_int_eq(r.circles, 1);
  /* the circle's centre is placed by the body: body at the origin, angle 0 */
  ck_assert_float_eq(r.last_circle_transform.p.x, 1.0f);
  ck_assert_float_eq(r.last_circle_transform.p.y, 2.0f);
  ck_assert_float_eq(r.last_circle_radius, 0.3f);
  ck_assert_int_eq(r.capsules, 1);
  ck_assert_int_eq(r.segments, 1 + 3); /* the segment shape and the chain's 3 segments */
  ck_assert_int_eq(r.points + r.transforms + r.strings, 0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(switches_pick_what_is_drawn) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_id g = body(w, TB_STATIC_BODY, 0.0f, 0.0f);
  tb_polygon ground;
  tb_make_offset_box(10.0f, 0.5f, (tb_vec2){0.0f, -0.5f}, 0.0f, &ground);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(g, &sd, &ground);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.5f, 0.5f, 0.5f); /* resting on the ground: 2 contact points */
  /* the pin's own static body: a joint stops its two bodies colliding */
  tb_body_id pin = body(w, TB_STATIC_BODY, 0.0f, 0.0f);
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = pin;
  jd.body_b = b;
  jd.local_anchor_a = (tb_vec2){0.0f, 2.0f};
  jd.local_anchor_b = (tb_vec2){0.0f, 1.5f};
  ck_assert(!tb_joint_id_is_null(tb_create_revolute_joint(w, &jd)));
  for (int i = 0; i < 10; ++i) tb_world_step(w, 1.0f / 60.0f, 4);

  recorder r;
  tb_debug_draw d = recording_draw(&r);
  d.draw_shapes = false;
  d.draw_joints = false;
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.polygons + r.segments + r.points + r.transforms + r.strings, 0);

  d = recording_draw(&r);
  d.draw_shapes = false;
  d.draw_joints = true; /* revolute: 3 segments (origin-anchor-anchor-origin) and the pin */
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.segments, 3);
  ck_assert_int_eq(r.points, 1);

  d = recording_draw(&r);
  d.draw_shapes = d.draw_joints = false;
  d.draw_aabbs = true; /* 2 shapes, 4 sides each */
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.segments, 8);

  d = recording_draw(&r);
  d.draw_shapes = d.draw_joints = false;
  d.draw_contact_points = d.draw_contact_normals = true; /* box on ground: 2 points, 2 normals */
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.points, 2);
  ck_assert_int_eq(r.segments, 2);

  d = recording_draw(&r);
  d.draw_shapes = d.draw_joints = false;
  d.draw_centers_of_mass = d.draw_masses = true; /* the one dynamic body; static bodies have none */
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.transforms, 1);
  ck_assert_int_eq(r.strings, 1);
  ck_assert_str_eq(r.last_string, "1 kg"); /* a 1 m box of density 1 */

  /* drawing bounds away from everything: nothing is drawn */
  d = recording_draw(&r);
  d.draw_aabbs = d.draw_contact_points = d.draw_centers_of_mass = true;
  d.use_drawing_bounds = true;
  d.drawing_bounds = (tb_aabb){{100.0f, 100.0f}, {110.0f, 110.0f}};
  ck_assert_int_eq(tb_world_draw(w, &d), TB_OK);
  ck_assert_int_eq(r.polygons + r.segments + r.points + r.transforms, 0);

  /* NULL callbacks are skipped */
  tb_debug_draw none = tb_default_debug_draw();
  none.draw_aabbs = none.draw_contact_points = none.draw_centers_of_mass = none.draw_masses = true;
  ck_assert_int_eq(tb_world_draw(w, &none), TB_OK);
  tb_destroy_world(w);
}
END_TEST

START_TEST(colours_follow_body_state) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_debug_colors colors = tb_default_debug_draw().colors;
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, 0.5f};
  recorder r;
  tb_debug_draw d = recording_draw(&r);

  tb_body_id b = body(w, TB_STATIC_BODY, 0.0f, 0.0f);
  tb_create_circle_shape(b, &sd, &c);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.static_body));

  tb_body_set_type(b, TB_KINEMATIC_BODY);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.kinematic_body));

  tb_body_set_type(b, TB_DYNAMIC_BODY);
  tb_body_set_awake(b, true);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.awake_body));

  tb_body_set_bullet(b, true);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.bullet_body));

  tb_body_set_awake(b, false);
  ck_assert(!tb_body_is_awake(b));
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.asleep_body));

  tb_body_set_enabled(b, false);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_circle_color, colors.disabled_body));
  tb_destroy_world(w);
}
END_TEST

START_TEST(sensors_light_up_while_overlapped) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_debug_colors colors = tb_default_debug_draw().colors;
  tb_body_id s = body(w, TB_STATIC_BODY, 0.0f, 0.0f);
  tb_shape_def sensor = tb_default_shape_def();
  sensor.is_sensor = true;
  tb_polygon box;
  tb_make_box(1.0f, 1.0f, &box);
  tb_create_polygon_shape(s, &sensor, &box);
  /* a ball 5 m away, moving through the sensor at 30 m/s */
  tb_body_id ball = body(w, TB_DYNAMIC_BODY, -5.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, 0.25f};
  tb_create_circle_shape(ball, &sd, &c);
  tb_body_set_linear_velocity(ball, (tb_vec2){30.0f, 0.0f});

  recorder r;
  tb_debug_draw d = recording_draw(&r);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_polygon_color, colors.sensor));
  /* 5 m at 30 m/s: inside after 10 steps (x = 0) */
  for (int i = 0; i < 9; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_float_lt(fabsf(tb_body_get_position(ball).x), 0.5f);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_polygon_color, colors.sensor_active));
  for (int i = 0; i < 20; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_draw(w, &d);
  ck_assert(same_color(r.last_polygon_color, colors.sensor));
  tb_destroy_world(w);
}
END_TEST

static tb_world_id locked_world;
static tb_result locked_result;
static void draw_inside_step(double t, const tb_body_state* s, void* ctx, tb_vec2* f, float* torque) {
  (void)t, (void)s, (void)ctx;
  *f = (tb_vec2){0.0f, 0.0f};
  *torque = 0.0f;
  tb_debug_draw d = tb_default_debug_draw();
  locked_result = tb_world_draw(locked_world, &d);
}

START_TEST(bad_input_is_rejected) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tbt_box_body(w, 0.0f, 0.0f, 0.5f, 0.5f);
  tb_debug_draw d = tb_default_debug_draw();
  uint64_t before = tb_world_hash(w);

  ck_assert_int_eq(tb_world_draw(w, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "tb_world_draw"));
  ck_assert_int_eq(tb_world_draw((tb_world_id){0, 0}, &d), TB_ERR_STALE_HANDLE);

  d.normal_length = NAN;
  ck_assert_int_eq(tb_world_draw(w, &d), TB_ERR_INVALID_ARGUMENT);
  d = tb_default_debug_draw();
  d.point_size = 0.0f;
  ck_assert_int_eq(tb_world_draw(w, &d), TB_ERR_INVALID_ARGUMENT);
  d = tb_default_debug_draw();
  d.use_drawing_bounds = true;
  d.drawing_bounds = (tb_aabb){{1.0f, 0.0f}, {0.0f, 1.0f}}; /* lower.x > upper.x */
  ck_assert_int_eq(tb_world_draw(w, &d), TB_ERR_INVALID_ARGUMENT);
  d.drawing_bounds = (tb_aabb){{0.0f, 0.0f}, {INFINITY, 1.0f}};
  ck_assert_int_eq(tb_world_draw(w, &d), TB_ERR_INVALID_ARGUMENT);
  ck_assert_uint_eq(tb_world_hash(w), before);

  /* from inside the step (a force field runs there) */
  locked_world = w;
  locked_result = TB_OK;
  tb_world_set_force_field(w, draw_inside_step, NULL);
  tb_world_step(w, 1.0f / 60.0f, 1);
  ck_assert_int_eq(locked_result, TB_ERR_LOCKED);
  tb_world_set_force_field(w, NULL, NULL);

  tb_destroy_world(w);
  d = tb_default_debug_draw();
  ck_assert_int_eq(tb_world_draw(w, &d), TB_ERR_STALE_HANDLE);
}
END_TEST

static Suite* debug_draw_suite(void) {
  Suite* s = suite_create("debug_draw");
  TCase* tc = tcase_create("core");
  tcase_add_test(tc, each_shape_type_has_its_callback);
  tcase_add_test(tc, switches_pick_what_is_drawn);
  tcase_add_test(tc, colours_follow_body_state);
  tcase_add_test(tc, sensors_light_up_while_overlapped);
  tcase_add_test(tc, bad_input_is_rejected);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(debug_draw_suite)
