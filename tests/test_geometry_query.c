/* The public geometry and distance API (tumble.h sections "geometry" and
 * "distance", issue 24) against closed forms: bounding boxes, point tests,
 * closest points and ray casts of each geometry at a transform; proxies, GJK
 * distance, segment distance, shape cast and time of impact; hulls and placed
 * polygons. (tests/test_distance.c holds the randomised and brute-force checks
 * of the algorithms underneath; this suite checks the public entry points on
 * cases solved by hand.)
 *
 * Tolerances: the inputs are floats of size 1..10 m, so one operation rounds by
 * ~6e-8 relative, ~1e-6 m at 10 m; the computations here chain a handful, so
 * TOL = 1e-5 m keeps a margin of 10 while a wrong formula (an error of a
 * radius, a sign, a missed rotation: 0.1 m and more) fails by orders of
 * magnitude. Casts and TOI converge to their own documented tolerance, which
 * the checks use. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "test_util.h"

#define PI 3.14159265358979323846
#define TOL 1e-5

static tb_transform xf_make(float x, float y, float angle) {
  return (tb_transform){{x, y}, {cosf(angle), sinf(angle)}};
}

static const tb_transform identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};

/* local -> world by xf, in double (the expected values) */
static tb_vec2 place(tb_transform xf, double x, double y) {
  return (tb_vec2){(float)(xf.p.x + (double)xf.q.c * x - (double)xf.q.s * y),
                   (float)(xf.p.y + (double)xf.q.s * x + (double)xf.q.c * y)};
}

#define ck_assert_vec_near(v, ex, ey, tol) \
  do {                                     \
    tb_vec2 v_ = (v);                      \
    ck_assert_near(v_.x, (ex), (tol));     \
    ck_assert_near(v_.y, (ey), (tol));     \
  } while (0)

#define ck_assert_box_near(b, lx, ly, ux, uy, tol) \
  do {                                             \
    tb_aabb b_ = (b);                              \
    ck_assert_near(b_.lower.x, (lx), (tol));       \
    ck_assert_near(b_.lower.y, (ly), (tol));       \
    ck_assert_near(b_.upper.x, (ux), (tol));       \
    ck_assert_near(b_.upper.y, (uy), (tol));       \
  } while (0)

/* ------------------------------------------------------------ bounding boxes -- */

START_TEST(aabbs_of_placed_geometry) {
  /* circle centre (1, 0) turned a quarter turn about the body origin at (2, 3):
   * its centre goes to (2, 4), the box is that +- r */
  tb_circle circle = {{1.0f, 0.0f}, 0.5f};
  ck_assert_box_near(tb_compute_circle_aabb(&circle, xf_make(2, 3, (float)(PI / 2))), 1.5, 3.5, 2.5, 4.5, TOL);

  /* capsule (-1,0)-(1,0), r 0.25, at 45 degrees: the centres go to
   * +-(sqrt(2)/2, sqrt(2)/2), the box is that +- r */
  tb_capsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
  double h = sqrt(0.5) + 0.25;
  ck_assert_box_near(tb_compute_capsule_aabb(&capsule, xf_make(0, 0, (float)(PI / 4))), -h, -h, h, h, TOL);

  /* segment (0,0)-(3,4) moved by (1,1): no radius */
  tb_segment segment = {{0.0f, 0.0f}, {3.0f, 4.0f}};
  ck_assert_box_near(tb_compute_segment_aabb(&segment, xf_make(1, 1, 0)), 1, 1, 4, 5, TOL);

  /* a 2 x 1 box turned by 30 degrees reaches hx|cos| + hy|sin| in x and
   * hx|sin| + hy|cos| in y; rounding adds its radius on every side */
  tb_polygon box;
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 0.5f, 0.1f, &box), TB_OK);
  double c = cos(PI / 6), s = sin(PI / 6);
  double ex = 1.0 * c + 0.5 * s + 0.1, ey = 1.0 * s + 0.5 * c + 0.1;
  ck_assert_box_near(tb_compute_polygon_aabb(&box, xf_make(-4, 7, (float)(PI / 6))), -4 - ex, 7 - ey, -4 + ex, 7 + ey,
                     TOL);
  ck_assert_int_eq(tb_last_result(), TB_OK);
}
END_TEST

/* ---------------------------------------------------------------- point tests -- */

START_TEST(point_tests_follow_the_rounded_surface) {
  tb_transform xf = xf_make(3, -2, 0.7f);
  tb_clear_error();
  /* circle r 1 about local (0.5, 0): 1e-3 inside and outside along a diagonal */
  tb_circle circle = {{0.5f, 0.0f}, 1.0f};
  double u = sqrt(0.5);
  ck_assert(tb_point_in_circle(&circle, xf, place(xf, 0.5 + 0.999 * u, 0.999 * u)));
  ck_assert(!tb_point_in_circle(&circle, xf, place(xf, 0.5 + 1.001 * u, 1.001 * u)));

  /* capsule (-1,0)-(1,0), r 0.5: near the cap's diagonal the rounding decides;
   * both points lie inside the capsule's bounding rectangle [-1.5, 1.5] x
   * [-0.5, 0.5], so a box test would take both */
  tb_capsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
  ck_assert(tb_point_in_capsule(&capsule, xf, place(xf, 1.0 + 0.49 * u, 0.49 * u)));
  ck_assert(!tb_point_in_capsule(&capsule, xf, place(xf, 1.0 + 0.51 * u, 0.51 * u)));
  ck_assert(tb_point_in_capsule(&capsule, xf, place(xf, -0.3, 0.499)));
  ck_assert(!tb_point_in_capsule(&capsule, xf, place(xf, -0.3, 0.501)));

  /* a rounded box (core 1 x 1, r 0.2): the corner is round */
  tb_polygon box;
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 1.0f, 0.2f, &box), TB_OK);
  ck_assert(tb_point_in_polygon(&box, xf, place(xf, 1.0 + 0.199 * u, 1.0 + 0.199 * u)));
  ck_assert(!tb_point_in_polygon(&box, xf, place(xf, 1.0 + 0.201 * u, 1.0 + 0.201 * u)));
  ck_assert(tb_point_in_polygon(&box, xf, place(xf, 1.199, 0.3)));
  ck_assert(!tb_point_in_polygon(&box, xf, place(xf, 1.201, 0.3)));
  ck_assert(tb_point_in_polygon(&box, xf, place(xf, 0, 0)));
  /* sharp: the same corner point is outside */
  tb_polygon sharp;
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, &sharp), TB_OK);
  ck_assert(!tb_point_in_polygon(&sharp, xf, place(xf, 1.0 + 0.1 * u, 1.0 + 0.1 * u)));
  ck_assert(tb_point_in_polygon(&sharp, xf, place(xf, 0.999, -0.999)));

  /* a segment contains nothing, not even its own midpoint */
  tb_segment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  ck_assert(!tb_point_in_segment(&segment, identity, (tb_vec2){0.0f, 0.0f}));
  ck_assert_int_eq(tb_last_result(), TB_OK); /* false because empty, not refused */
}
END_TEST

/* ------------------------------------------------------------- closest points -- */

START_TEST(closest_points_by_hand) {
  tb_transform xf = xf_make(5, 5, 0.3f);
  tb_clear_error();
  /* circle r 1 at the body origin: a point 5 m off along (3, 4)/5 comes back
   * at 1 m along the same direction (the rotation does not matter for a
   * circle about the origin) */
  tb_circle circle = {{0.0f, 0.0f}, 1.0f};
  ck_assert_vec_near(tb_closest_point_on_circle(&circle, xf, (tb_vec2){8.0f, 9.0f}), 5.6, 5.8, TOL);
  /* inside: the point itself, unchanged to the bit */
  tb_vec2 in = {5.3f, 4.6f};
  tb_vec2 got = tb_closest_point_on_circle(&circle, xf, in);
  ck_assert(got.x == in.x && got.y == in.y);

  /* capsule (-1,0)-(1,0), r 0.5: above the middle -> the flat side; beyond an
   * end -> the cap, along the diagonal from its centre */
  tb_capsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
  tb_vec2 e;
  e = place(xf, 0.25, 0.5);
  ck_assert_vec_near(tb_closest_point_on_capsule(&capsule, xf, place(xf, 0.25, 2.0)), e.x, e.y, TOL);
  e = place(xf, 1.0 + 0.5 * sqrt(0.5), 0.5 * sqrt(0.5));
  ck_assert_vec_near(tb_closest_point_on_capsule(&capsule, xf, place(xf, 2.0, 1.0)), e.x, e.y, TOL);
  got = tb_closest_point_on_capsule(&capsule, xf, place(xf, -1.2, 0.1));
  e = place(xf, -1.2, 0.1);
  ck_assert(got.x == e.x && got.y == e.y);

  /* segment (0,0)-(2,0): the foot of the perpendicular, or the nearer end */
  tb_segment segment = {{0.0f, 0.0f}, {2.0f, 0.0f}};
  e = place(xf, 1.0, 0.0);
  ck_assert_vec_near(tb_closest_point_on_segment(&segment, xf, place(xf, 1.0, 1.0)), e.x, e.y, TOL);
  e = place(xf, 0.0, 0.0);
  ck_assert_vec_near(tb_closest_point_on_segment(&segment, xf, place(xf, -1.0, -1.0)), e.x, e.y, TOL);
  e = place(xf, 2.0, 0.0);
  ck_assert_vec_near(tb_closest_point_on_segment(&segment, xf, place(xf, 3.0, 0.5)), e.x, e.y, TOL);

  /* a 2 x 2 box: face, corner, inside; rounded by 0.25: pushed out by r */
  tb_polygon box, rounded;
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, &box), TB_OK);
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 1.0f, 0.25f, &rounded), TB_OK);
  e = place(xf, 1.0, 0.5);
  ck_assert_vec_near(tb_closest_point_on_polygon(&box, xf, place(xf, 3.0, 0.5)), e.x, e.y, TOL);
  e = place(xf, 1.0, 1.0);
  ck_assert_vec_near(tb_closest_point_on_polygon(&box, xf, place(xf, 2.0, 2.0)), e.x, e.y, TOL);
  e = place(xf, 1.25, 0.5);
  ck_assert_vec_near(tb_closest_point_on_polygon(&rounded, xf, place(xf, 3.0, 0.5)), e.x, e.y, TOL);
  e = place(xf, 1.0 + 0.25 * sqrt(0.5), 1.0 + 0.25 * sqrt(0.5));
  ck_assert_vec_near(tb_closest_point_on_polygon(&rounded, xf, place(xf, 2.0, 2.0)), e.x, e.y, TOL);
  e = place(xf, 0.2, -0.7);
  got = tb_closest_point_on_polygon(&box, xf, e);
  ck_assert(got.x == e.x && got.y == e.y);
  /* within the rounding but outside the core: inside the shape */
  e = place(xf, 1.1, 0.0);
  got = tb_closest_point_on_polygon(&rounded, xf, e);
  ck_assert(got.x == e.x && got.y == e.y);
  ck_assert_int_eq(tb_last_result(), TB_OK);
}
END_TEST

/* ---------------------------------------------------------------- ray casts -- */

static tb_cast_output ray_hit(tb_result r, tb_cast_output out) {
  ck_assert_int_eq(r, TB_OK);
  return out;
}

START_TEST(ray_casts_by_hand) {
  tb_cast_output out;
  /* circle r 1 at (10, 0); ray from (0, 0.6) along (20, 0): enters where
   * (x - 10)^2 + 0.36 = 1, x = 9.2: fraction 0.46, normal (-0.8, 0.6) */
  tb_circle circle = {{0.0f, 0.0f}, 1.0f};
  tb_ray_input ray = {{0.0f, 0.6f}, {20.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_circle(&ray, &circle, xf_make(10, 0, 0.4f), &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.46, 1e-6); /* 1e-5 m over 20 m */
  ck_assert_vec_near(out.point, 9.2, 0.6, TOL);
  ck_assert_vec_near(out.normal, -0.8, 0.6, TOL);
  ck_assert_int_eq(out.iterations, 0);
  /* max_fraction short of the entry: a miss, all zero */
  ray.max_fraction = 0.45f;
  out = ray_hit(tb_ray_cast_circle(&ray, &circle, xf_make(10, 0, 0), &out), out);
  ck_assert(!out.hit && out.fraction == 0.0f);
  /* from inside: no hit; from the surface inwards: a hit at 0 */
  tb_ray_input inside = {{10.2f, 0.0f}, {5.0f, 0.0f}, 1.0f};
  ck_assert(!ray_hit(tb_ray_cast_circle(&inside, &circle, xf_make(10, 0, 0), &out), out).hit);
  tb_ray_input surface = {{9.0f, 0.0f}, {5.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_circle(&surface, &circle, xf_make(10, 0, 0), &out), out);
  ck_assert(out.hit && out.fraction == 0.0f);

  /* capsule (-1,0)-(1,0), r 0.5, turned a quarter turn at (0, 0): the flat
   * side faces -x at x = -0.5; a ray from (-5, 0.3) along (10, 0) meets it
   * at fraction 0.45 with normal (-1, 0) */
  tb_capsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
  tb_transform quarter = xf_make(0, 0, (float)(PI / 2));
  tb_ray_input side = {{-5.0f, 0.3f}, {10.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_capsule(&side, &capsule, quarter, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.45, 1e-6);
  ck_assert_vec_near(out.normal, -1.0, 0.0, TOL);
  /* unturned, the cap about (1, 0): a ray from (5, 0.3) along (-10, 0) enters
   * where (x - 1)^2 + 0.09 = 0.25, x = 1.4: fraction 0.36, normal (0.8, 0.6) */
  tb_ray_input cap = {{5.0f, 0.3f}, {-10.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_capsule(&cap, &capsule, identity, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.36, 1e-6);
  ck_assert_vec_near(out.point, 1.4, 0.3, TOL);
  ck_assert_vec_near(out.normal, 0.8, 0.6, TOL);

  /* segment (-1,0)-(1,0) turned upright: hit from either side at x = 0, the
   * normal facing the ray's origin; a ray along its line misses */
  tb_segment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  tb_ray_input from_left = {{-2.0f, 0.5f}, {4.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_segment(&from_left, &segment, quarter, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.5, 1e-6);
  ck_assert_vec_near(out.normal, -1.0, 0.0, TOL);
  tb_ray_input from_right = {{2.0f, 0.5f}, {-4.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_segment(&from_right, &segment, quarter, &out), out);
  ck_assert(out.hit);
  ck_assert_vec_near(out.normal, 1.0, 0.0, TOL);
  /* (unturned: a float quarter turn leaves cos = -4e-8, so "along" would cross) */
  tb_ray_input along = {{-3.0f, 0.0f}, {6.0f, 0.0f}, 1.0f};
  ck_assert(!ray_hit(tb_ray_cast_segment(&along, &segment, identity, &out), out).hit);

  /* 2 x 2 box at the origin: a ray from (-3, 0.5) along (4, 0) enters x = -1
   * at 0.5; rounded by 0.5 it enters x = -1.5 at 0.375; at height 1.3 it
   * meets the corner disc about (-1, 1), x = -1 - 0.4: fraction 0.4, normal
   * (-0.8, 0.6) */
  tb_polygon box, rounded;
  ck_assert_int_eq(tb_make_box(1.0f, 1.0f, &box), TB_OK);
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 1.0f, 0.5f, &rounded), TB_OK);
  tb_ray_input face = {{-3.0f, 0.5f}, {4.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_polygon(&face, &box, identity, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.5, 1e-6);
  ck_assert_vec_near(out.normal, -1.0, 0.0, TOL);
  out = ray_hit(tb_ray_cast_polygon(&face, &rounded, identity, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.375, 1e-6);
  tb_ray_input corner = {{-3.0f, 1.3f}, {4.0f, 0.0f}, 1.0f};
  out = ray_hit(tb_ray_cast_polygon(&corner, &rounded, identity, &out), out);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.4, 1e-6);
  ck_assert_vec_near(out.normal, -0.8, 0.6, TOL);
  /* the sharp box is missed at that height (1.3 > 1) */
  ck_assert(!ray_hit(tb_ray_cast_polygon(&corner, &box, identity, &out), out).hit);
  /* from inside: no hit */
  tb_ray_input in_box = {{0.0f, 0.0f}, {4.0f, 0.0f}, 1.0f};
  ck_assert(!ray_hit(tb_ray_cast_polygon(&in_box, &box, identity, &out), out).hit);
}
END_TEST

/* ------------------------------------------------------------------ proxies -- */

START_TEST(proxies_and_offset_proxies) {
  const tb_vec2 pts[3] = {{1.0f, 0.0f}, {0.0f, 2.0f}, {-1.0f, -1.0f}};
  tb_shape_proxy p = tb_make_proxy(pts, 3, 0.25f);
  ck_assert_int_eq(p.count, 3);
  ck_assert(p.radius == 0.25f && p.points[1].x == 0.0f && p.points[1].y == 2.0f);
  /* a quarter turn then a move by (10, 20): (x, y) -> (10 - y, 20 + x) */
  tb_shape_proxy o = tb_make_offset_proxy(pts, 3, 0.25f, (tb_vec2){10.0f, 20.0f}, (float)(PI / 2));
  ck_assert_int_eq(o.count, 3);
  ck_assert(o.radius == 0.25f);
  ck_assert_vec_near(o.points[0], 10.0, 21.0, TOL);
  ck_assert_vec_near(o.points[1], 8.0, 20.0, TOL);
  ck_assert_vec_near(o.points[2], 11.0, 19.0, TOL);
  /* angle 0 is exact: only the move */
  o = tb_make_offset_proxy(pts, 3, 0.0f, (tb_vec2){0.5f, 0.0f}, 0.0f);
  ck_assert(o.points[2].x == -0.5f && o.points[2].y == -1.0f);

  tb_circle circle = {{1.0f, 2.0f}, 0.5f};
  tb_capsule capsule = {{0.0f, 0.0f}, {1.0f, 0.0f}, 0.1f};
  tb_segment segment = {{0.0f, 0.0f}, {0.0f, 1.0f}};
  tb_polygon box;
  ck_assert_int_eq(tb_make_rounded_box(0.5f, 0.5f, 0.05f, &box), TB_OK);
  p = tb_make_circle_proxy(&circle);
  ck_assert(p.count == 1 && p.radius == 0.5f && p.points[0].x == 1.0f && p.points[0].y == 2.0f);
  p = tb_make_capsule_proxy(&capsule);
  ck_assert(p.count == 2 && p.radius == 0.1f && p.points[1].x == 1.0f);
  p = tb_make_segment_proxy(&segment);
  ck_assert(p.count == 2 && p.radius == 0.0f && p.points[1].y == 1.0f);
  p = tb_make_polygon_proxy(&box);
  ck_assert(p.count == 4 && p.radius == 0.05f);
}
END_TEST

/* ----------------------------------------------------------------- distance -- */

static tb_shape_proxy box_proxy(float hx, float hy, float radius) {
  tb_polygon box;
  ck_assert_int_eq(tb_make_rounded_box(hx, hy, radius, &box), TB_OK);
  return tb_make_polygon_proxy(&box);
}

START_TEST(distance_between_boxes_and_circles) {
  tb_shape_proxy a = box_proxy(0.5f, 0.5f, 0.0f), b = box_proxy(0.5f, 0.5f, 0.0f);
  tb_distance_output out;
  tb_simplex_cache cache = {0};

  /* unit boxes 3 m apart, axis aligned: face to face, distance 2, the points
   * on x = 0.5 and x = 2.5 at one height within both faces */
  tb_distance_input in = {a, b, identity, xf_make(3, 0, 0)};
  ck_assert_int_eq(tb_shape_distance(&in, &cache, &out), TB_OK);
  ck_assert_near(out.distance, 2.0, TOL);
  ck_assert_near(out.point_a.x, 0.5, TOL);
  ck_assert_near(out.point_b.x, 2.5, TOL);
  ck_assert_near(out.point_a.y, out.point_b.y, TOL);
  ck_assert(fabsf(out.point_a.y) <= 0.5f + TOL);
  ck_assert_vec_near(out.normal, 1.0, 0.0, TOL);
  ck_assert_int_gt(cache.count, 0);

  /* B turned by 45 degrees: its corner points at A, 3 - sqrt(2)/2 from A's
   * centre, so the distance is 2.5 - sqrt(2)/2, from (0.5, 0) to that corner */
  in.xf_b = xf_make(3, 0, (float)(PI / 4));
  tb_simplex_cache cold = {0};
  ck_assert_int_eq(tb_shape_distance(&in, &cold, &out), TB_OK);
  double d = 2.5 - sqrt(0.5);
  ck_assert_near(out.distance, d, TOL);
  ck_assert_vec_near(out.point_a, 0.5, 0.0, TOL);
  ck_assert_vec_near(out.point_b, 3.0 - sqrt(0.5), 0.0, TOL);
  int cold_iterations = out.iterations;
  /* warm: the cache already holds the answer's simplex, so the same result
   * takes no more support evaluations than the cold start */
  tb_distance_output warm;
  ck_assert_int_eq(tb_shape_distance(&in, &cold, &warm), TB_OK);
  ck_assert_near(warm.distance, d, TOL);
  ck_assert_int_le(warm.iterations, cold_iterations);

  /* circles r 0.5 and 0.25, centres 3 m apart along (3, 4)/5: 2.25, points
   * on the two circles along the line of centres */
  tb_circle ca = {{0.0f, 0.0f}, 0.5f}, cb = {{0.0f, 0.0f}, 0.25f};
  tb_distance_input cin = {tb_make_circle_proxy(&ca), tb_make_circle_proxy(&cb), xf_make(1, 1, 0.3f),
                           xf_make(1.0f + 1.8f, 1.0f + 2.4f, -1.0f)};
  ck_assert_int_eq(tb_shape_distance(&cin, NULL, &out), TB_OK);
  ck_assert_near(out.distance, 2.25, TOL);
  ck_assert_vec_near(out.point_a, 1.0 + 0.3, 1.0 + 0.4, TOL);
  ck_assert_vec_near(out.point_b, 2.8 - 0.15, 3.4 - 0.2, TOL);
  ck_assert_vec_near(out.normal, 0.6, 0.8, TOL);

  /* rounded boxes (r 0.1 each): the core distance less both radii */
  tb_distance_input rin = {box_proxy(0.5f, 0.5f, 0.1f), box_proxy(0.5f, 0.5f, 0.1f), identity, xf_make(3, 0, 0)};
  ck_assert_int_eq(tb_shape_distance(&rin, NULL, &out), TB_OK);
  ck_assert_near(out.distance, 1.8, TOL);

  /* overlapping cores: 0, zero normal, simplex of 3 */
  in.xf_b = xf_make(0.5f, 0.2f, 0.3f);
  ck_assert_int_eq(tb_shape_distance(&in, NULL, &out), TB_OK);
  ck_assert(out.distance == 0.0f && out.normal.x == 0.0f && out.normal.y == 0.0f);
  ck_assert_int_eq(out.simplex_count, 3);

  /* a million metres out (1e6 and 1e6 + 3 are floats): only the relative
   * placement counts, still exactly 2 */
  tb_distance_input far = {a, b, xf_make(1.0e6f, -1.0e6f, 0), xf_make(1.0e6f + 3.0f, -1.0e6f, 0)};
  ck_assert_int_eq(tb_shape_distance(&far, NULL, &out), TB_OK);
  ck_assert_near(out.distance, 2.0, TOL);
}
END_TEST

START_TEST(segment_distance_by_hand) {
  /* crossing at (1, 0): distance 0, the crossing point on both */
  tb_segment_distance_output s =
      tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){2, 0}, (tb_vec2){1, -1}, (tb_vec2){1, 1});
  ck_assert_near(s.distance_sq, 0.0, 1e-12);
  ck_assert_vec_near(s.closest1, 1.0, 0.0, TOL);
  ck_assert_near(s.fraction1, 0.5, TOL);
  ck_assert_near(s.fraction2, 0.5, TOL);
  /* parallel, overlapping over x in [1, 2] one metre apart: the middle of
   * the overlap, x = 1.5 */
  s = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){2, 0}, (tb_vec2){1, 1}, (tb_vec2){3, 1});
  ck_assert_near(s.distance_sq, 1.0, TOL);
  ck_assert_vec_near(s.closest1, 1.5, 0.0, TOL);
  ck_assert_vec_near(s.closest2, 1.5, 1.0, TOL);
  ck_assert_near(s.fraction1, 0.75, TOL);
  ck_assert_near(s.fraction2, 0.25, TOL);
  /* end to end: (1, 0) and (2, 1), squared distance 2 */
  s = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){1, 0}, (tb_vec2){2, 1}, (tb_vec2){2, 3});
  ck_assert_near(s.distance_sq, 2.0, TOL);
  ck_assert(s.fraction1 == 1.0f && s.fraction2 == 0.0f);
  /* a zero-length segment is a point: its distance to the other segment */
  s = tb_segment_distance((tb_vec2){0.5f, 2}, (tb_vec2){0.5f, 2}, (tb_vec2){0, 0}, (tb_vec2){1, 0});
  ck_assert_near(s.distance_sq, 4.0, TOL);
  ck_assert_near(s.fraction2, 0.5, TOL);
}
END_TEST

/* ------------------------------------------------------------ casts and TOI -- */

START_TEST(shape_cast_by_hand) {
  /* a circle r 0.25 from (5, 0) along (-10, 0) at a fixed unit box: contact
   * when its centre reaches x = 0.75, fraction 0.425, at A's point (0.5, 0)
   * with normal (1, 0). The cast stops within TB_CAST_TOLERANCE of contact,
   * never past it: fraction in [0.425 - tol / 10, 0.425] (+ rounding) */
  tb_circle c = {{0.0f, 0.0f}, 0.25f};
  tb_shape_cast_input in = {
      box_proxy(0.5f, 0.5f, 0.0f), tb_make_circle_proxy(&c), identity, xf_make(5, 0, 0), {-10.0f, 0.0f}};
  tb_cast_output out;
  ck_assert_int_eq(tb_shape_cast(&in, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert(out.fraction <= 0.425f + 1e-6f && out.fraction >= 0.425f - TB_CAST_TOLERANCE / 10.0f - 1e-6f);
  ck_assert_vec_near(out.point, 0.5, 0.0, 1e-4);
  ck_assert_vec_near(out.normal, 1.0, 0.0, TOL);
  ck_assert_int_gt(out.iterations, 0);
  /* moving away or past: no hit */
  in.translation_b = (tb_vec2){0.0f, 10.0f};
  ck_assert_int_eq(tb_shape_cast(&in, &out), TB_OK);
  ck_assert(!out.hit);
  in.translation_b = (tb_vec2){-4.0f, 0.0f}; /* stops at x = 1, 0.25 short */
  ck_assert_int_eq(tb_shape_cast(&in, &out), TB_OK);
  ck_assert(!out.hit);
  /* already overlapping: a hit at 0 */
  in.xf_b = xf_make(0.6f, 0, 0);
  in.translation_b = (tb_vec2){1.0f, 0.0f};
  ck_assert_int_eq(tb_shape_cast(&in, &out), TB_OK);
  ck_assert(out.hit && out.fraction == 0.0f);
}
END_TEST

START_TEST(time_of_impact_by_hand) {
  /* a circle r 0.25 crossing a fixed unit box at constant speed, centre from
   * (5, 0) to (-5, 0): the gap is 4.25 - 10 t, so it reaches the target
   * (TB_LINEAR_SLOP) at t = (4.25 - slop) / 10; a hit has the gap within
   * the tolerance, i.e. t within tolerance / 10 */
  tb_circle c = {{0.0f, 0.0f}, 0.25f};
  const float target = TB_LINEAR_SLOP, tol = 0.25f * TB_LINEAR_SLOP;
  tb_sweep fixed = {{0, 0}, {0, 0}, {0, 0}, 0.0f, 0.0f};
  tb_sweep moving = {{0, 0}, {5, 0}, {-5, 0}, 0.0f, 0.0f};
  tb_toi_input in = {box_proxy(0.5f, 0.5f, 0.0f), tb_make_circle_proxy(&c), fixed, moving, 1.0f, target, tol};
  tb_toi_output out;
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_HIT);
  ck_assert_near(out.fraction, (4.25 - TB_LINEAR_SLOP) / 10.0, tol / 10.0 + 1e-6);
  ck_assert_int_gt(out.iterations, 0);

  /* searched only up to 0.3: separated, fraction = max_fraction */
  in.max_fraction = 0.3f;
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_SEPARATED);
  ck_assert(out.fraction == 0.3f);
  /* moving away: separated over the whole interval */
  in.max_fraction = 1.0f;
  in.sweep_b = (tb_sweep){{0, 0}, {5, 0}, {15, 0}, 0.0f, 0.0f};
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_SEPARATED);
  ck_assert(out.fraction == 1.0f);
  /* overlapping at the start */
  in.sweep_b = (tb_sweep){{0, 0}, {0.6f, 0}, {5, 0}, 0.0f, 0.0f};
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_OVERLAPPED);
  ck_assert(out.fraction == 0.0f);

  /* rotation: a 2 m rod (segment) turning a quarter turn about its centre at
   * the origin sweeps over a circle r 0.1 at (0.5, 0.5), which is rho =
   * sqrt(0.5) from the pivot at 45 degrees. At angle th the gap is
   * rho sin(pi/4 - th) - 0.1; it reaches the target at
   * th = pi/4 - asin((0.1 + slop) / rho), i.e. t = th / (pi/2). A gap error of
   * tol moves th by tol / (rho cos(pi/4 - th)) */
  tb_segment rod = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  tb_circle dot = {{0.0f, 0.0f}, 0.1f};
  tb_sweep turn = {{0, 0}, {0, 0}, {0, 0}, 0.0f, (float)(PI / 2)};
  tb_sweep still = {{0, 0}, {0.5f, 0.5f}, {0.5f, 0.5f}, 0.0f, 0.0f};
  tb_toi_input rin = {tb_make_segment_proxy(&rod), tb_make_circle_proxy(&dot), turn, still, 1.0f, target, tol};
  ck_assert_int_eq(tb_time_of_impact(&rin, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_HIT);
  double rho = sqrt(0.5);
  double phi = asin((0.1 + TB_LINEAR_SLOP) / rho); /* pi/4 - th */
  double th = PI / 4 - phi;
  double dt = tol / (rho * cos(phi)) / (PI / 2);
  ck_assert_near(out.fraction, th / (PI / 2), dt + 1e-6);
  /* the sweep's transform there: the rod's angle is th */
  tb_transform x = tb_sweep_transform(&turn, out.fraction);
  ck_assert_near(atan2(x.q.s, x.q.c), th, dt * (PI / 2) + 1e-5);
  /* tb_sweep_transform places the body origin: centre c at local centre l
   * means origin = c - R l */
  tb_sweep off = {{1.0f, 0.0f}, {0, 0}, {0, 2}, 0.0f, (float)PI};
  x = tb_sweep_transform(&off, 0.5f);
  ck_assert_vec_near(x.p, 0.0, 0.0, TOL); /* c (0, 1) minus (0, 1): a quarter turn of (1, 0) */
}
END_TEST

/* ------------------------------------------------------------------ polygons -- */

static double polygon_area(const tb_polygon* p) {
  tb_mass_data md = tb_compute_polygon_mass(p, 1.0f);
  return md.mass;
}

START_TEST(hulls_and_placed_polygons) {
  /* a 4 x 2 rectangle listed with an interior point, a duplicate and a point
   * on an edge: the hull is the four corners, counter-clockwise */
  const tb_vec2 pts[7] = {{2, 1}, {0, 0}, {-2, 1}, {-2, -1}, {2, -1}, {2, 1}, {0, -1}};
  tb_hull hull;
  ck_assert_int_eq(tb_compute_hull(pts, 7, &hull), TB_OK);
  ck_assert_int_eq(hull.count, 4);
  double twice_area = 0.0;
  for (int i = 0; i < 4; ++i) {
    tb_vec2 a = hull.points[i], b = hull.points[(i + 1) % 4];
    ck_assert(fabsf(a.x) == 2.0f && fabsf(a.y) == 1.0f);
    twice_area += (double)a.x * b.y - (double)a.y * b.x;
  }
  ck_assert_near(twice_area, 16.0, 1e-9); /* positive: counter-clockwise */

  /* the polygon of the hull, rounded: area 8 + perimeter 12 r + pi r^2 */
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon_from_hull(&hull, 0.1f, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  ck_assert(p.radius == 0.1f);
  ck_assert_rel(polygon_area(&p), 8.0 + 12.0 * 0.1 + PI * 0.01, 1e-5);

  /* offset: turned a quarter turn and moved to (2, 3), the 4 x 2 rectangle
   * becomes 2 x 4 about (2, 3); area and radius kept, normals unit */
  ck_assert_int_eq(tb_make_offset_polygon(&hull, (tb_vec2){2, 3}, (float)(PI / 2), &p), TB_OK);
  ck_assert_box_near(tb_compute_polygon_aabb(&p, identity), 1, 1, 3, 5, TOL);
  ck_assert_vec_near(p.centroid, 2, 3, TOL);
  ck_assert_rel(polygon_area(&p), 8.0, 1e-5);
  for (int i = 0; i < p.count; ++i) ck_assert_near(hypot(p.normals[i].x, p.normals[i].y), 1.0, 1e-6);
  ck_assert(p.radius == 0.0f);
  ck_assert_int_eq(tb_make_offset_rounded_polygon(&hull, (tb_vec2){2, 3}, (float)(PI / 2), 0.5f, &p), TB_OK);
  ck_assert(p.radius == 0.5f);
  ck_assert_box_near(tb_compute_polygon_aabb(&p, identity), 0.5, 0.5, 3.5, 5.5, TOL);

  /* offset rounded box: core 2 x 1 about (1, 2), radius 0.1: area
   * 2 + perimeter 6 r + pi r^2, box grown by r */
  ck_assert_int_eq(tb_make_offset_rounded_box(1.0f, 0.5f, (tb_vec2){1, 2}, 0.0f, 0.1f, &p), TB_OK);
  ck_assert(p.radius == 0.1f);
  ck_assert_box_near(tb_compute_polygon_aabb(&p, identity), -0.1, 1.4, 2.1, 2.6, TOL);
  ck_assert_rel(polygon_area(&p), 2.0 + 0.6 + PI * 0.01, 1e-5);
  ck_assert_vec_near(tb_compute_polygon_mass(&p, 1.0f).center, 1, 2, TOL);

  /* transform: a box placed by xf is the offset box at xf (same corners);
   * in place too */
  tb_polygon box, offset;
  ck_assert_int_eq(tb_make_box(1.0f, 0.5f, &box), TB_OK);
  tb_transform xf = xf_make(1, -1, 0.75f);
  ck_assert_int_eq(tb_make_offset_box(1.0f, 0.5f, xf.p, 0.75f, &offset), TB_OK);
  ck_assert_int_eq(tb_transform_polygon(&box, xf, &p), TB_OK);
  ck_assert_int_eq(p.count, 4);
  for (int i = 0; i < 4; ++i) {
    ck_assert_vec_near(p.vertices[i], offset.vertices[i].x, offset.vertices[i].y, 1e-6);
    ck_assert_vec_near(p.normals[i], offset.normals[i].x, offset.normals[i].y, 1e-6);
  }
  ck_assert_vec_near(p.centroid, 1, -1, 1e-6);
  ck_assert_int_eq(tb_transform_polygon(&box, xf, &box), TB_OK);
  ck_assert(memcmp(&box, &p, sizeof box) == 0);

  /* a hull that is not one (an interior point) is refused, out untouched */
  tb_hull fake = {{{-1, -1}, {1, -1}, {0, 0}, {1, 1}, {-1, 1}}, 5};
  tb_polygon before = p;
  ck_assert_int_eq(tb_make_polygon_from_hull(&fake, 0.0f, &p), TB_ERR_DEGENERATE_POLYGON);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "tb_make_polygon_from_hull"));
  ck_assert(memcmp(&before, &p, sizeof p) == 0);
  /* a refused hull computation leaves an empty hull, refused in turn */
  ck_assert_int_eq(tb_compute_hull(pts, 2, &hull), TB_ERR_DEGENERATE_POLYGON);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "tb_compute_hull: "));
  ck_assert_int_eq(hull.count, 0);
  ck_assert_int_eq(tb_make_offset_polygon(&hull, (tb_vec2){0, 0}, 0.0f, &p), TB_ERR_INVALID_ARGUMENT);
}
END_TEST

static Suite* geometry_query_suite(void) {
  Suite* s = suite_create("geometry_query");
  TCase* tc = tcase_create("geometry_query");
  tcase_add_test(tc, aabbs_of_placed_geometry);
  tcase_add_test(tc, point_tests_follow_the_rounded_surface);
  tcase_add_test(tc, closest_points_by_hand);
  tcase_add_test(tc, ray_casts_by_hand);
  tcase_add_test(tc, proxies_and_offset_proxies);
  tcase_add_test(tc, distance_between_boxes_and_circles);
  tcase_add_test(tc, segment_distance_by_hand);
  tcase_add_test(tc, shape_cast_by_hand);
  tcase_add_test(tc, time_of_impact_by_hand);
  tcase_add_test(tc, hulls_and_placed_polygons);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(geometry_query_suite)
