/* Convex polygons from arbitrary points, and boxes. */
#include <string.h>

#include "test_util.h"

static bool is_ccw_convex(const tb_polygon* p) {
  for (int i = 0; i < p->count; ++i) {
    tb_vec2 a = p->vertices[i], b = p->vertices[(i + 1) % p->count], c = p->vertices[(i + 2) % p->count];
    float cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    if (cross <= 0.0f) return false;
  }
  return true;
}

START_TEST(square_from_shuffled_points_with_interior) {
  tb_vec2 pts[] = {{1, 1}, {0, 0.5f}, {-1, -1}, {0.2f, 0.1f}, {1, -1}, {-1, 1}, {0, 0}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 7, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4); /* the interior points are dropped */
  ck_assert(is_ccw_convex(&p));
  for (int i = 0; i < p.count; ++i) {
    tb_vec2 e = {p.vertices[(i + 1) % 4].x - p.vertices[i].x, p.vertices[(i + 1) % 4].y - p.vertices[i].y};
    ck_assert_near(p.normals[i].x * e.x + p.normals[i].y * e.y, 0.0, 1e-6); /* normal is perpendicular */
    ck_assert_near(p.normals[i].x * p.normals[i].x + p.normals[i].y * p.normals[i].y, 1.0, 1e-6);
    /* and points outward: away from the centroid */
    tb_vec2 d = {p.vertices[i].x - p.centroid.x, p.vertices[i].y - p.centroid.y};
    ck_assert(p.normals[i].x * d.x + p.normals[i].y * d.y > 0.0f);
  }
  ck_assert_near(p.centroid.x, 0.0, 1e-6);
  ck_assert_near(p.centroid.y, 0.0, 1e-6);
}
END_TEST

START_TEST(collinear_points_on_edges_are_dropped) {
  tb_vec2 pts[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 8, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  /* nearly collinear (within half a slop of the line): dropped as well */
  tb_vec2 near[] = {{0, 0}, {1, 0.001f}, {2, 0}, {1, 1}};
  ck_assert_int_eq(tb_make_polygon(near, 4, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 3);
}
END_TEST

START_TEST(near_duplicates_are_welded) {
  tb_vec2 pts[] = {{0, 0}, {0.001f, 0.001f}, {1, 0}, {1.002f, 0}, {0, 1}, {0, 1.0001f}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 6, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 3);
  ck_assert(is_ccw_convex(&p));
}
END_TEST

START_TEST(degenerate_inputs_are_errors) {
  tb_polygon p, before;
  memset(&p, 0x5a, sizeof p);
  before = p;
  tb_vec2 two[] = {{0, 0}, {1, 0}};
  ck_assert_int_eq(tb_make_polygon(two, 2, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  tb_vec2 dup[] = {{0, 0}, {0, 0}, {1, 1}, {0.001f, 0}};
  ck_assert_int_eq(tb_make_polygon(dup, 4, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "distinct"));
  tb_vec2 line[] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  ck_assert_int_eq(tb_make_polygon(line, 4, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "collinear"));
  /* a sliver: three distinct, not collinear within the slop, but ~zero area */
  tb_vec2 sliver[] = {{0, 0}, {0.008f, 0}, {0.004f, 0.0035f}};
  ck_assert_int_eq(tb_make_polygon(sliver, 3, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  tb_vec2 nan_pt[] = {{0, 0}, {1, 0}, {NAN, 1}};
  ck_assert_int_eq(tb_make_polygon(nan_pt, 3, 0.0f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "points[2]"));
  tb_vec2 inf_pt[] = {{0, 0}, {INFINITY, 0}, {0, 1}};
  ck_assert_int_eq(tb_make_polygon(inf_pt, 3, 0.0f, &p), TB_ERR_INVALID_ARGUMENT);
  tb_vec2 huge[] = {{0, 0}, {1e30f, 0}, {0, 1}};
  ck_assert_int_eq(tb_make_polygon(huge, 3, 0.0f, &p), TB_ERR_INVALID_ARGUMENT);
  tb_vec2 ok[] = {{0, 0}, {1, 0}, {0, 1}};
  ck_assert_int_eq(tb_make_polygon(ok, 3, -0.1f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_polygon(ok, 3, NAN, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_polygon(NULL, 3, 0.0f, &p), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_make_polygon(ok, -1, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  ck_assert_int_eq(memcmp(&p, &before, sizeof p), 0); /* output untouched on error */
  ck_assert_int_eq(tb_make_polygon(ok, 3, 0.0f, NULL), TB_ERR_NULL_ARGUMENT);
}
END_TEST

/* The corner tests in double (fuzz_hull found it): on the left edge of a
 * 0.19 m square, x = -1e-45 (a subnormal) at the top, 0 at the bottom and at
 * (0, 0.125). In float the turn at the bottom corner, 1e-45 x 0.125,
 * underflowed to 0, read as collinear, and the hull dropped the corner
 * (0, 0), leaving it 0.10 m outside. */
START_TEST(subnormal_offsets_keep_a_corner) {
  const float tiny = -1.40129846e-45f;
  tb_vec2 pts[] = {{tiny, 0.185787186f}, {0.18578431f, 0.0f}, {0.0f, 0.0f}, {0.18578431f, 0.18578431f}, {0.0f, 0.125f}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 5, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < p.count; ++i) {
      double d = (double)p.normals[i].x * ((double)pts[k].x - p.vertices[i].x) +
                 (double)p.normals[i].y * ((double)pts[k].y - p.vertices[i].y);
      ck_assert_double_le(d, 1e-6);
    }
}
END_TEST

START_TEST(vertex_limit_is_an_error_not_a_cut) {
  tb_vec2 pts[TB_MAX_POLYGON_VERTICES + 1];
  for (int i = 0; i <= TB_MAX_POLYGON_VERTICES; ++i) {
    double a = 2.0 * 3.14159265358979 * i / (TB_MAX_POLYGON_VERTICES + 1);
    pts[i] = (tb_vec2){(float)cos(a), (float)sin(a)};
  }
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, TB_MAX_POLYGON_VERTICES, 0.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, TB_MAX_POLYGON_VERTICES);
  ck_assert_int_eq(tb_make_polygon(pts, TB_MAX_POLYGON_VERTICES + 1, 0.0f, &p), TB_ERR_TOO_MANY_VERTICES);
}
END_TEST

/* Random point clouds: the hull contains every input point (within the weld
 * tolerance) and is convex, counter-clockwise. */
START_TEST(random_hulls_contain_their_points) {
  unsigned seed = 12345u;
  int made = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    int n = 3 + trial % 20;
    tb_vec2 pts[32];
    float scale = tbt_rand(&seed, 0.05f, 50.0f);
    for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){scale * tbt_rand(&seed, -1, 1), scale * tbt_rand(&seed, -1, 1)};
    tb_polygon p;
    tb_result r = tb_make_polygon(pts, n, 0.0f, &p);
    if (r == TB_ERR_TOO_MANY_VERTICES) continue;
    ck_assert_int_eq(r, TB_OK);
    ++made;
    ck_assert(is_ccw_convex(&p));
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < p.count; ++k) {
        float d = p.normals[k].x * (pts[i].x - p.vertices[k].x) + p.normals[k].y * (pts[i].y - p.vertices[k].y);
        ck_assert_msg(d <= TB_LINEAR_SLOP, "point %d lies %g outside edge %d", i, (double)d, k);
      }
  }
  ck_assert_int_gt(made, 1000);
}
END_TEST

START_TEST(boxes) {
  tb_polygon p;
  ck_assert_int_eq(tb_make_box(1.0f, 2.0f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  ck_assert(is_ccw_convex(&p));
  ck_assert_int_eq(tb_make_box(0.0f, 1.0f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "hx"));
  ck_assert_int_eq(tb_make_box(1.0f, -1.0f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "hy"));
  ck_assert_int_eq(tb_make_box(NAN, 1.0f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){0, 0}, INFINITY, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_offset_box(1.0f, 1.0f, (tb_vec2){NAN, 0}, 0.0f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 1.0f, -0.5f, &p), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_make_offset_box(0.5f, 0.25f, (tb_vec2){3, 4}, 1.0f, &p), TB_OK);
  ck_assert(is_ccw_convex(&p));
  ck_assert_near(p.centroid.x, 3.0, 1e-6);
  ck_assert_near(p.centroid.y, 4.0, 1e-6);
}
END_TEST

/* Slivers 7e6 m long and 0.39 m wide (found by the hull fuzzer). Its float
 * centroid lies inside in exact arithmetic, but a float difference of
 * coordinates near 4e6 m rounds by 0.25 m: the validation that the mass and
 * shape functions run refused the polygon tb_make_polygon had made. */
START_TEST(far_sliver_is_accepted_everywhere) {
  const tb_vec2 points[3] = {
      {-0x1.95944ep+22f, -0x1.959594p+21f}, {0x1.19594p-130f, 0.0f}, {0x1.94p-2f, 0x1.fd9594p-124f}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(points, 3, 0.0f, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
  ck_assert_msg(md.mass > 0.0f, "%s", tb_last_error());
  /* with the far point lower (y -6153573 instead of -3322546.5) the float centroid lies
   * 0.2 m outside in exact arithmetic too: refused, not handed out */
  const tb_vec2 thinner[3] = {{points[0].x, -0x1.779594p+22f}, points[1], points[2]};
  ck_assert_int_eq(tb_make_polygon(thinner, 3, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
}
END_TEST

Suite* hull_suite(void) {
  Suite* s = suite_create("hull");
  TCase* tc = tcase_create("hull");
  tcase_add_test(tc, square_from_shuffled_points_with_interior);
  tcase_add_test(tc, collinear_points_on_edges_are_dropped);
  tcase_add_test(tc, near_duplicates_are_welded);
  tcase_add_test(tc, degenerate_inputs_are_errors);
  tcase_add_test(tc, vertex_limit_is_an_error_not_a_cut);
  tcase_add_test(tc, subnormal_offsets_keep_a_corner);
  tcase_add_test(tc, random_hulls_contain_their_points);
  tcase_add_test(tc, boxes);
  tcase_add_test(tc, far_sliver_is_accepted_everywhere);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(hull_suite)
