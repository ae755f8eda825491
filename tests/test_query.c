/* World queries against brute force and closed forms. */
#include <string.h>

#include "test_util.h"

static tb_shape_id static_circle(tb_world_id w, float x, float y, float r) {
  tb_body_def bd = tb_default_body_def();
  bd.position = (tb_vec2){x, y};
  tb_circle c = {{0, 0}, r};
  tb_shape_def sd = tb_default_shape_def();
  return tb_create_circle_shape(tb_create_body(w, &bd), &sd, &c);
}

static tb_shape_id dynamic_box(tb_world_id w, float x, float y, float h) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){x, y};
  tb_polygon p;
  tb_make_box(h, h, &p);
  tb_shape_def sd = tb_default_shape_def();
  return tb_create_polygon_shape(tb_create_body(w, &bd), &sd, &p);
}

static bool same(tb_shape_id a, tb_shape_id b) { return a.index1 == b.index1 && a.generation == b.generation; }

START_TEST(ray_closest_and_all) {
  tb_world_id w = tbt_world(0, 0);
  tb_shape_id c1 = static_circle(w, 5.0f, 0.0f, 1.0f);
  tb_shape_id c2 = static_circle(w, 10.0f, 0.0f, 1.0f);
  tb_shape_id b1 = dynamic_box(w, 15.0f, 0.0f, 0.5f);
  static_circle(w, 5.0f, 5.0f, 1.0f); /* off the ray */
  tb_query_filter f = tb_default_query_filter();
  tb_ray_result r = tb_world_cast_ray_closest(w, (tb_vec2){0, 0}, (tb_vec2){20, 0}, f);
  ck_assert(r.hit && same(r.shape, c1));
  ck_assert_near(r.point.x, 4.0, 1e-5);
  ck_assert_near(r.normal.x, -1.0, 1e-5);
  ck_assert_near(r.fraction, 0.2, 1e-6);
  tb_ray_result all[4];
  int n = 0;
  ck_assert_int_eq(tb_world_cast_ray_all(w, (tb_vec2){0, 0}, (tb_vec2){20, 0}, f, all, 4, &n), TB_OK);
  ck_assert_int_eq(n, 3);
  ck_assert(same(all[0].shape, c1) && same(all[1].shape, c2) && same(all[2].shape, b1));
  ck_assert_near(all[2].point.x, 14.5, 1e-5);
  /* capacity smaller than the hits: the nearest ones, and the full count */
  ck_assert_int_eq(tb_world_cast_ray_all(w, (tb_vec2){0, 0}, (tb_vec2){20, 0}, f, all, 1, &n), TB_OK);
  ck_assert_int_eq(n, 3);
  ck_assert(same(all[0].shape, c1));
  /* a short ray misses */
  r = tb_world_cast_ray_closest(w, (tb_vec2){0, 0}, (tb_vec2){3, 0}, f);
  ck_assert(!r.hit);
  /* destroyed shapes are never seen */
  tb_destroy_shape(c1);
  r = tb_world_cast_ray_closest(w, (tb_vec2){0, 0}, (tb_vec2){20, 0}, f);
  ck_assert(r.hit && same(r.shape, c2));
  tb_destroy_world(w);
}
END_TEST

/* A callback that clips the ray to each hit ends with the closest one, whatever
 * the visiting order; one that returns 0 stops at the first. */
static float clip(tb_shape_id s, tb_vec2 p, tb_vec2 n, float fraction, void* ctx) {
  (void)p;
  (void)n;
  tb_ray_result* best = ctx;
  if (fraction < best->fraction) *best = (tb_ray_result){s, p, n, fraction, true};
  return fraction;
}
static float stop(tb_shape_id s, tb_vec2 p, tb_vec2 n, float fraction, void* ctx) {
  (void)s;
  (void)p;
  (void)n;
  (void)fraction;
  *(int*)ctx += 1;
  return 0.0f;
}

START_TEST(ray_callback_clipping) {
  tb_world_id w = tbt_world(0, 0);
  unsigned seed = 3;
  for (int i = 0; i < 200; ++i) static_circle(w, tbt_rand(&seed, -50, 50), tbt_rand(&seed, -50, 50), 0.5f);
  tb_query_filter f = tb_default_query_filter();
  for (int k = 0; k < 100; ++k) {
    tb_vec2 o = {tbt_rand(&seed, -60, 60), tbt_rand(&seed, -60, 60)};
    tb_vec2 d = {tbt_rand(&seed, -100, 100), tbt_rand(&seed, -100, 100)};
    tb_ray_result best = {{0, 0, 0}, {0, 0}, {0, 0}, 2.0f, false};
    ck_assert_int_eq(tb_world_cast_ray(w, o, d, f, clip, &best), TB_OK);
    tb_ray_result closest = tb_world_cast_ray_closest(w, o, d, f);
    ck_assert_int_eq(best.hit, closest.hit);
    if (closest.hit) ck_assert_float_eq(best.fraction, closest.fraction);
    tb_ray_result all[256];
    int n = 0;
    tb_world_cast_ray_all(w, o, d, f, all, 256, &n);
    if (n > 0) ck_assert_float_eq(all[0].fraction, closest.fraction);
    for (int i = 1; i < n; ++i) ck_assert(all[i - 1].fraction <= all[i].fraction);
    int calls = 0;
    tb_world_cast_ray(w, o, d, f, stop, &calls);
    ck_assert_int_le(calls, 1);
    ck_assert_int_eq(calls, n > 0 ? 1 : 0);
  }
  tb_destroy_world(w);
}
END_TEST

static bool collect(tb_shape_id s, void* ctx) {
  int* count = ctx;
  (void)s;
  *count += 1;
  return true;
}

/* AABB overlap and point tests against brute force over 1,000 circles. */
START_TEST(overlaps_match_brute_force) {
  tb_world_id w = tbt_world(0, 0);
  unsigned seed = 11;
  enum { N = 1000 };
  tb_vec2 centers[N];
  float radii[N];
  for (int i = 0; i < N; ++i) {
    centers[i] = (tb_vec2){tbt_rand(&seed, -100, 100), tbt_rand(&seed, -100, 100)};
    radii[i] = tbt_rand(&seed, 0.1f, 3.0f);
    static_circle(w, centers[i].x, centers[i].y, radii[i]);
  }
  tb_query_filter f = tb_default_query_filter();
  for (int k = 0; k < 100; ++k) {
    tb_vec2 lo = {tbt_rand(&seed, -110, 100), tbt_rand(&seed, -110, 100)};
    tb_aabb box = {lo, {lo.x + tbt_rand(&seed, 0, 20), lo.y + tbt_rand(&seed, 0, 20)}};
    int got = 0, want = 0;
    tb_world_overlap_aabb(w, box, f, collect, &got);
    for (int i = 0; i < N; ++i)
      want += centers[i].x - radii[i] <= box.upper.x && centers[i].x + radii[i] >= box.lower.x &&
              centers[i].y - radii[i] <= box.upper.y && centers[i].y + radii[i] >= box.lower.y;
    ck_assert_int_eq(got, want);
    tb_vec2 p = {tbt_rand(&seed, -100, 100), tbt_rand(&seed, -100, 100)};
    got = want = 0;
    tb_world_overlap_point(w, p, f, collect, &got);
    for (int i = 0; i < N; ++i) {
      float dx = p.x - centers[i].x, dy = p.y - centers[i].y;
      want += dx * dx + dy * dy <= radii[i] * radii[i];
    }
    ck_assert_int_eq(got, want);
  }
  tb_destroy_world(w);
}
END_TEST

START_TEST(point_in_rounded_polygon_and_capsule) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_def bd = tb_default_body_def();
  tb_body_id b = tb_create_body(w, &bd);
  tb_polygon p;
  tb_make_rounded_box(1.0f, 1.0f, 0.5f, &p);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(b, &sd, &p);
  tb_query_filter f = tb_default_query_filter();
  int n = 0;
  tb_world_overlap_point(w, (tb_vec2){1.4f, 0.0f}, f, collect, &n); /* in the side rounding */
  ck_assert_int_eq(n, 1);
  n = 0;
  tb_world_overlap_point(w, (tb_vec2){1.4f, 1.4f}, f, collect, &n); /* corner: 0.566 from (1, 1) > 0.5 */
  ck_assert_int_eq(n, 0);
  n = 0;
  tb_world_overlap_point(w, (tb_vec2){1.3f, 1.3f}, f, collect, &n); /* corner: 0.424 < 0.5 */
  ck_assert_int_eq(n, 1);
  tb_capsule cap = {{5, 0}, {7, 0}, 0.5f};
  tb_create_capsule_shape(b, &sd, &cap);
  n = 0;
  tb_world_overlap_point(w, (tb_vec2){6.0f, 0.45f}, f, collect, &n);
  ck_assert_int_eq(n, 1);
  n = 0;
  tb_world_overlap_point(w, (tb_vec2){7.4f, 0.4f}, f, collect, &n); /* 0.566 from the end centre */
  ck_assert_int_eq(n, 0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(query_filters_and_sensors) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_def bd = tb_default_body_def();
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  sd.filter.category_bits = 2;
  tb_circle c = {{0, 0}, 1};
  tb_create_circle_shape(b, &sd, &c);
  sd = tb_default_shape_def();
  sd.is_sensor = true;
  tb_circle c2 = {{0.5f, 0}, 1};
  tb_create_circle_shape(b, &sd, &c2);
  tb_query_filter f = tb_default_query_filter();
  int n = 0;
  tb_world_overlap_point(w, (tb_vec2){0.2f, 0}, f, collect, &n);
  ck_assert_int_eq(n, 2); /* the default query sees both: its mask has every category */
  n = 0;
  f.mask_bits = 2;
  tb_world_overlap_point(w, (tb_vec2){0.2f, 0}, f, collect, &n);
  ck_assert_int_eq(n, 1); /* only the category-2 circle */
  n = 0;
  f = tb_default_query_filter();
  f.skip_sensors = true;
  tb_world_overlap_point(w, (tb_vec2){0.2f, 0}, f, collect, &n);
  ck_assert_int_eq(n, 1);
  /* a disabled body's shapes are not seen */
  tb_body_set_enabled(b, false);
  n = 0;
  f = tb_default_query_filter();
  f.mask_bits = UINT64_MAX;
  tb_world_overlap_point(w, (tb_vec2){0.2f, 0}, f, collect, &n);
  ck_assert_int_eq(n, 0);
  tb_destroy_world(w);
}
END_TEST

static float first_hit(tb_shape_id s, tb_vec2 p, tb_vec2 n, float fraction, void* ctx) {
  tb_ray_result* r = ctx;
  if (fraction < r->fraction) *r = (tb_ray_result){s, p, n, fraction, true};
  return fraction;
}

START_TEST(shape_overlap_and_cast) {
  tb_world_id w = tbt_world(0, 0);
  tb_shape_id wall = dynamic_box(w, 10.0f, 0.0f, 1.0f);
  tb_shape_proxy probe = {{{0.0f, 0.0f}}, 1, 0.5f}; /* a disc of radius 0.5 */
  tb_query_filter f = tb_default_query_filter();
  tb_transform at = {{8.6f, 0.0f}, {1.0f, 0.0f}}; /* reaches x = 9.1, past the face at 9 */
  int n = 0;
  ck_assert_int_eq(tb_world_overlap_shape(w, &probe, at, f, collect, &n), TB_OK);
  ck_assert_int_eq(n, 1);
  at.p.x = 8.0f; /* 0.5 m from the wall's face */
  n = 0;
  tb_world_overlap_shape(w, &probe, at, f, collect, &n);
  ck_assert_int_eq(n, 0);
  /* cast the disc 10 m to the right: it touches the face at x = 9 - 0.5 */
  tb_ray_result hit = {{0, 0, 0}, {0, 0}, {0, 0}, 2.0f, false};
  tb_transform start = {{0.0f, 0.0f}, {1.0f, 0.0f}};
  ck_assert_int_eq(tb_world_cast_shape(w, &probe, start, (tb_vec2){10.0f, 0.0f}, f, first_hit, &hit), TB_OK);
  ck_assert(hit.hit && same(hit.shape, wall));
  ck_assert_near(hit.fraction, 0.85, 2e-5); /* within the cast tolerance of 1e-4 m over 10 m */
  ck_assert_near(hit.point.x, 9.0, 2e-4);
  ck_assert_near(hit.normal.x, -1.0, 1e-4);
  tb_destroy_world(w);
}
END_TEST

START_TEST(bad_queries) {
  tb_world_id w = tbt_world(0, 0);
  static_circle(w, 0, 0, 1);
  uint64_t h = tb_world_hash(w);
  tb_query_filter f = tb_default_query_filter();
  int n = 0;
  ck_assert_int_eq(tb_world_cast_ray(w, (tb_vec2){NAN, 0}, (tb_vec2){1, 0}, f, clip, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "origin"));
  ck_assert_int_eq(tb_world_cast_ray(w, (tb_vec2){0, 0}, (tb_vec2){0, 0}, f, clip, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "zero"));
  ck_assert_int_eq(tb_world_cast_ray(w, (tb_vec2){0, 0}, (tb_vec2){INFINITY, 0}, f, clip, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_cast_ray(w, (tb_vec2){0, 0}, (tb_vec2){1, 0}, f, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert(!tb_world_cast_ray_closest(w, (tb_vec2){0, NAN}, (tb_vec2){1, 0}, f).hit);
  ck_assert_int_eq(tb_world_cast_ray_all(w, (tb_vec2){0, 0}, (tb_vec2){1, 0}, f, NULL, 4, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_cast_ray_all(w, (tb_vec2){0, 0}, (tb_vec2){1, 0}, f, NULL, 0, NULL), TB_ERR_NULL_ARGUMENT);
  tb_aabb bad = {{1, 1}, {0, 0}};
  ck_assert_int_eq(tb_world_overlap_aabb(w, bad, f, collect, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_overlap_point(w, (tb_vec2){NAN, 0}, f, collect, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_overlap_point(w, (tb_vec2){0, 0}, f, NULL, &n), TB_ERR_NULL_ARGUMENT);
  tb_shape_proxy empty = {{{0, 0}}, 0, 0.0f};
  tb_transform id = {{0, 0}, {1, 0}};
  ck_assert_int_eq(tb_world_overlap_shape(w, &empty, id, f, collect, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_overlap_shape(w, NULL, id, f, collect, &n), TB_ERR_NULL_ARGUMENT);
  tb_shape_proxy disc = {{{0, 0}}, 1, 0.5f};
  tb_transform skew = {{0, 0}, {2, 0}};
  ck_assert_int_eq(tb_world_cast_shape(w, &disc, skew, (tb_vec2){1, 0}, f, clip, &n), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_world_cast_shape(w, &disc, id, (tb_vec2){NAN, 0}, f, clip, &n), TB_ERR_INVALID_ARGUMENT);
  tb_world_id stale = w;
  ck_assert_uint_eq(tb_world_hash(w), h);
  tb_destroy_world(w);
  ck_assert_int_eq(tb_world_overlap_point(stale, (tb_vec2){0, 0}, f, collect, &n), TB_ERR_STALE_HANDLE);
}
END_TEST

static Suite* query_suite(void) {
  Suite* s = suite_create("query");
  TCase* tc = tcase_create("query");
  tcase_add_test(tc, ray_closest_and_all);
  tcase_add_test(tc, ray_callback_clipping);
  tcase_add_test(tc, overlaps_match_brute_force);
  tcase_add_test(tc, point_in_rounded_polygon_and_capsule);
  tcase_add_test(tc, query_filters_and_sensors);
  tcase_add_test(tc, shape_overlap_and_cast);
  tcase_add_test(tc, bad_queries);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(query_suite)
