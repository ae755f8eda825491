/* Distance queries (src/distance.c): segment closest points, GJK distance, shape
 * cast, time of impact and ray casts, against closed forms and against an
 * independent brute force written here in double (vertex-edge distances and an
 * edge-crossing / containment overlap test), plus warm starting, precision far
 * from the origin and bad input.
 *
 * Tolerances: inputs are floats of size ~1..10 m, so a float computation carries
 * ~1e-6 m of rounding; 1e-5 m leaves a margin of 10. Casts and TOI converge to
 * TB_CAST_TOLERANCE and the TOI's own tolerance, which the checks use. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/distance.h"
#include "../src/math_internal.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define TOL 1e-5

/* ------------------------------------------------------------- helpers -- */

static tb_transform xf_make(float x, float y, float angle) {
  return (tb_transform){{x, y}, {cosf(angle), sinf(angle)}};
}

static const tb_transform identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};

static tb_shape_proxy box_proxy(float hx, float hy, float radius) {
  tb_vec2 pts[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  return tb_make_proxy(pts, 4, radius);
}

static tb_distance_output distance_of(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b,
                                      tb_transform xb, tb_simplex_cache* cache) {
  tb_distance_input in = {*a, *b, xa, xb};
  tb_distance_output out;
  ck_assert_int_eq(tb_shape_distance(&in, cache, &out), TB_OK);
  return out;
}

/* A random convex polygon of n vertices (sorted angles on a jittered circle),
 * built by tb_make_polygon so it is CCW. */
static tb_polygon random_polygon(unsigned* rng, int n, float radius) {
  for (;;) {
    tb_vec2 pts[TB_MAX_POLYGON_VERTICES];
    float size = tbt_rand(rng, 0.2f, 1.5f);
    float a0 = tbt_rand(rng, 0.0f, (float)(2.0 * PI));
    for (int i = 0; i < n; ++i) {
      float a = a0 + (float)(2.0 * PI) * ((float)i + tbt_rand(rng, -0.3f, 0.3f)) / (float)n;
      float r = size * tbt_rand(rng, 0.6f, 1.0f);
      pts[i] = (tb_vec2){r * cosf(a), r * sinf(a)};
    }
    tb_polygon p;
    if (tb_make_polygon(pts, n, radius, &p) == TB_OK) return p;
  }
}

/* A random proxy: circle, capsule, segment, sharp or rounded polygon. */
static tb_shape_proxy random_proxy(unsigned* rng) {
  int kind = (int)tbt_rand(rng, 0.0f, 5.0f);
  if (kind == 0) {
    tb_vec2 c = {tbt_rand(rng, -0.3f, 0.3f), tbt_rand(rng, -0.3f, 0.3f)};
    return tb_make_proxy(&c, 1, tbt_rand(rng, 0.1f, 1.0f));
  }
  if (kind == 1 || kind == 2) {
    float h = tbt_rand(rng, 0.2f, 1.5f), a = tbt_rand(rng, 0.0f, 3.0f);
    tb_vec2 pts[2] = {{-h * cosf(a), -h * sinf(a)}, {h * cosf(a), h * sinf(a)}};
    return tb_make_proxy(pts, 2, kind == 1 ? tbt_rand(rng, 0.05f, 0.5f) : 0.0f);
  }
  int n = 3 + (int)tbt_rand(rng, 0.0f, 6.0f);
  tb_polygon p = random_polygon(rng, n, kind == 4 ? tbt_rand(rng, 0.02f, 0.3f) : 0.0f);
  return tb_make_polygon_proxy(&p);
}

/* ---- independent brute force, in double ---- */

typedef struct dvec {
  double x, y;
} dvec;

static dvec dsub(dvec a, dvec b) { return (dvec){a.x - b.x, a.y - b.y}; }
static double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y; }
static double dcross(dvec a, dvec b) { return a.x * b.y - a.y * b.x; }

static double point_segment(dvec p, dvec a, dvec b) {
  dvec e = dsub(b, a), ap = dsub(p, a);
  double ee = ddot(e, e), s = ee > 0.0 ? ddot(ap, e) / ee : 0.0;
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  dvec d = {ap.x - s * e.x, ap.y - s * e.y};
  return sqrt(ddot(d, d));
}

static bool segments_cross(dvec a, dvec b, dvec c, dvec d) {
  double o1 = dcross(dsub(b, a), dsub(c, a)), o2 = dcross(dsub(b, a), dsub(d, a));
  double o3 = dcross(dsub(d, c), dsub(a, c)), o4 = dcross(dsub(d, c), dsub(b, c));
  return o1 * o2 <= 0.0 && o3 * o4 <= 0.0 && !(o1 == 0.0 && o2 == 0.0);
}

/* p inside the convex polygon v (either orientation). */
static bool inside_convex(dvec p, const dvec* v, int n) {
  int pos = 0, neg = 0;
  for (int i = 0; i < n; ++i) {
    double c = dcross(dsub(v[(i + 1) % n], v[i]), dsub(p, v[i]));
    pos += c > 0.0;
    neg += c < 0.0;
  }
  return pos == 0 || neg == 0;
}

static int world_points(const tb_shape_proxy* p, tb_transform xf, dvec* out) {
  for (int i = 0; i < p->count; ++i) {
    double x = p->points[i].x, y = p->points[i].y;
    out[i] = (dvec){xf.p.x + (double)xf.q.c * x - (double)xf.q.s * y, xf.p.y + (double)xf.q.s * x + (double)xf.q.c * y};
  }
  return p->count;
}

/* Gap between the rounded shapes (negative when the rounded shapes overlap,
 * -(ra + rb) when the cores overlap). */
static double brute_gap(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb) {
  dvec va[TB_MAX_POLYGON_VERTICES], vb[TB_MAX_POLYGON_VERTICES];
  int na = world_points(a, xa, va), nb = world_points(b, xb, vb);
  int ea = na == 1 ? 0 : (na == 2 ? 1 : na), eb = nb == 1 ? 0 : (nb == 2 ? 1 : nb);
  double radius = (double)a->radius + (double)b->radius;
  for (int i = 0; i < ea; ++i)
    for (int j = 0; j < eb; ++j)
      if (segments_cross(va[i], va[(i + 1) % na], vb[j], vb[(j + 1) % nb])) return -radius;
  if (na >= 3 && inside_convex(vb[0], va, na)) return -radius;
  if (nb >= 3 && inside_convex(va[0], vb, nb)) return -radius;
  double best = DBL_MAX;
  for (int i = 0; i < na; ++i) {
    if (nb == 1) best = fmin(best, sqrt(ddot(dsub(va[i], vb[0]), dsub(va[i], vb[0]))));
    for (int j = 0; j < eb; ++j) best = fmin(best, point_segment(va[i], vb[j], vb[(j + 1) % nb]));
  }
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < ea; ++i) best = fmin(best, point_segment(vb[j], va[i], va[(i + 1) % na]));
  return best - radius;
}

/* Separation of the rounded shapes along the unit axis n (A to B): the least
 * extent of B along n minus the greatest of A, minus the radii. It is at most
 * the gap, with equality exactly for a contact normal. */
static double separation_along(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb,
                               tb_vec2 n) {
  dvec va[TB_MAX_POLYGON_VERTICES], vb[TB_MAX_POLYGON_VERTICES];
  int na = world_points(a, xa, va), nb = world_points(b, xb, vb);
  double max_a = -DBL_MAX, min_b = DBL_MAX;
  for (int i = 0; i < na; ++i) max_a = fmax(max_a, va[i].x * n.x + va[i].y * n.y);
  for (int i = 0; i < nb; ++i) min_b = fmin(min_b, vb[i].x * n.x + vb[i].y * n.y);
  return min_b - max_a - a->radius - b->radius;
}

/* ------------------------------------------------------ segment distance -- */

START_TEST(segment_closest_points) {
  /* Skew, closest at an endpoint of one and the interior of the other. */
  tb_segment_distance_output o =
      tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){4, 0}, (tb_vec2){1, 1}, (tb_vec2){3, 5});
  ck_assert_near(o.distance_sq, 1.0, TOL);
  ck_assert_near(o.fraction1, 0.25, TOL);
  ck_assert_near(o.fraction2, 0.0, TOL);
  ck_assert_near(o.closest1.x, 1.0, TOL);
  ck_assert_near(o.closest2.y, 1.0, TOL);

  /* Crossing: distance 0 at the intersection (1, 1). */
  o = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){2, 2}, (tb_vec2){0, 2}, (tb_vec2){2, 0});
  ck_assert_float_eq(o.distance_sq, 0.0f);
  ck_assert_near(o.closest1.x, 1.0, TOL);
  ck_assert_near(o.closest1.y, 1.0, TOL);
  ck_assert_near(o.fraction2, 0.5, TOL);

  /* Point against segment (first segment degenerate). */
  o = tb_segment_distance((tb_vec2){1, 3}, (tb_vec2){1, 3}, (tb_vec2){-2, 1}, (tb_vec2){4, 1});
  ck_assert_near(o.distance_sq, 4.0, TOL);
  ck_assert_near(o.closest2.x, 1.0, TOL);
  ck_assert_near(o.fraction2, 0.5, TOL);
  /* Beyond an end, second segment degenerate. */
  o = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){1, 0}, (tb_vec2){4, 4}, (tb_vec2){4, 4});
  ck_assert_near(o.distance_sq, 25.0, TOL);
  ck_assert_near(o.fraction1, 1.0, TOL);
  /* Both degenerate. */
  o = tb_segment_distance((tb_vec2){1, 1}, (tb_vec2){1, 1}, (tb_vec2){4, 5}, (tb_vec2){4, 5});
  ck_assert_near(o.distance_sq, 25.0, TOL);

  /* Parallel, overlapping over x in [1, 3]: the middle of the overlap. */
  o = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){3, 0}, (tb_vec2){5, 0.5f}, (tb_vec2){1, 0.5f});
  ck_assert_near(o.distance_sq, 0.25, TOL);
  ck_assert_near(o.closest1.x, 2.0, TOL);
  ck_assert_near(o.closest2.x, 2.0, TOL);
  ck_assert_near(o.closest2.y, 0.5, TOL);
  /* Parallel without overlap: end to end. */
  o = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){1, 0}, (tb_vec2){4, 4}, (tb_vec2){6, 4});
  ck_assert_near(o.distance_sq, 25.0, TOL);
  /* Collinear, overlapping: distance 0. */
  o = tb_segment_distance((tb_vec2){0, 0}, (tb_vec2){2, 0}, (tb_vec2){1, 0}, (tb_vec2){5, 0});
  ck_assert_float_eq(o.distance_sq, 0.0f);
  ck_assert_near(o.closest1.x, 1.5, TOL);
  /* Nearly parallel and long: the classic 2x2 solve loses ~length * eps / angle. */
  o = tb_segment_distance((tb_vec2){-10, 0}, (tb_vec2){10, 0}, (tb_vec2){-10, 1}, (tb_vec2){10, 1.00001f});
  ck_assert_near(o.distance_sq, 1.0, 1e-5);
  ck_assert_near(o.closest1.x, -10.0, TOL);

  /* Against the brute force on random segments. */
  unsigned rng = 7;
  int bad = 0;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    tb_vec2 p[4];
    for (int k = 0; k < 4; ++k) p[k] = (tb_vec2){tbt_rand(&rng, -3, 3), tbt_rand(&rng, -3, 3)};
    if (i % 10 == 0) p[3] = tb_add(p[2], tb_sub(p[1], p[0])); /* parallel */
    o = tb_segment_distance(p[0], p[1], p[2], p[3]);
    dvec d[4];
    for (int k = 0; k < 4; ++k) d[k] = (dvec){p[k].x, p[k].y};
    double want = segments_cross(d[0], d[1], d[2], d[3])
                      ? 0.0
                      : fmin(fmin(point_segment(d[0], d[2], d[3]), point_segment(d[1], d[2], d[3])),
                             fmin(point_segment(d[2], d[0], d[1]), point_segment(d[3], d[0], d[1])));
    double err = fabs(sqrt(o.distance_sq) - want);
    worst = fmax(worst, err);
    bad += err > TOL;
  }
  ck_assert_msg(bad == 0, "%d random segment pairs off by more than %g (worst %g)", bad, TOL, worst);
}
END_TEST

/* --------------------------------------------------------------- proxies -- */

START_TEST(proxies_of_shapes) {
  tb_circle c = {{1, 2}, 0.5f};
  tb_shape_proxy p = tb_make_circle_proxy(&c);
  ck_assert_int_eq(p.count, 1);
  ck_assert_float_eq(p.radius, 0.5f);
  ck_assert_float_eq(p.points[0].x, 1.0f);
  tb_capsule cap = {{-1, 0}, {1, 0}, 0.25f};
  p = tb_make_capsule_proxy(&cap);
  ck_assert_int_eq(p.count, 2);
  ck_assert_float_eq(p.radius, 0.25f);
  tb_segment seg = {{0, 0}, {0, 3}};
  p = tb_make_segment_proxy(&seg);
  ck_assert_int_eq(p.count, 2);
  ck_assert_float_eq(p.radius, 0.0f);
  tb_polygon poly;
  ck_assert_int_eq(tb_make_rounded_box(1, 0.5f, 0.1f, &poly), TB_OK);
  p = tb_make_polygon_proxy(&poly);
  ck_assert_int_eq(p.count, 4);
  ck_assert_float_eq(p.radius, 0.1f);
}
END_TEST

/* ------------------------------------------------------------ closed forms -- */

START_TEST(circle_circle) {
  tb_vec2 o = {0, 0};
  tb_shape_proxy a = tb_make_proxy(&o, 1, 0.5f), b = tb_make_proxy(&o, 1, 0.75f);
  tb_distance_output d = distance_of(&a, xf_make(1, 1, 0.3f), &b, xf_make(4, 5, -1.0f), NULL);
  ck_assert_near(d.distance, 5.0 - 1.25, TOL);
  ck_assert_near(d.normal.x, 0.6, TOL);
  ck_assert_near(d.normal.y, 0.8, TOL);
  ck_assert_near(d.point_a.x, 1.0 + 0.6 * 0.5, TOL);
  ck_assert_near(d.point_a.y, 1.0 + 0.8 * 0.5, TOL);
  ck_assert_near(d.point_b.x, 4.0 - 0.6 * 0.75, TOL);
  ck_assert_near(d.point_b.y, 5.0 - 0.8 * 0.75, TOL);
  ck_assert_int_eq(d.simplex_count, 1);
}
END_TEST

START_TEST(box_box_gap) {
  tb_shape_proxy a = box_proxy(1.0f, 0.5f, 0.0f), b = box_proxy(0.5f, 0.5f, 0.0f);
  /* Side by side with a gap of 0.25, B shifted up so the faces overlap in y. */
  tb_distance_output d = distance_of(&a, identity, &b, xf_make(1.75f, 0.3f, 0.0f), NULL);
  ck_assert_near(d.distance, 0.25, TOL);
  ck_assert_near(d.normal.x, 1.0, TOL);
  ck_assert_near(d.normal.y, 0.0, TOL);
  ck_assert_near(d.point_a.x, 1.0, TOL);
  ck_assert_near(d.point_b.x, 1.25, TOL);
  ck_assert_near(d.point_a.y, d.point_b.y, TOL);

  /* B turned 45 degrees, a corner towards A's top face: gap = y - 0.5 - h sqrt 2. */
  d = distance_of(&a, identity, &b, xf_make(0.2f, 2.0f, (float)(PI / 4)), NULL);
  ck_assert_near(d.distance, 2.0 - 0.5 - 0.5 * sqrt(2.0), TOL);
  ck_assert_near(d.normal.y, 1.0, TOL);
  ck_assert_near(d.point_b.x, 0.2, TOL);

  /* The whole configuration turned and moved: same distance. */
  tb_transform xa = xf_make(-3.0f, 7.0f, 1.1f);
  tb_vec2 pb = tb_add(xa.p, (tb_vec2){xa.q.c * 1.75f - xa.q.s * 0.3f, xa.q.s * 1.75f + xa.q.c * 0.3f});
  d = distance_of(&a, xa, &b, (tb_transform){pb, xa.q}, NULL);
  ck_assert_near(d.distance, 0.25, TOL);
  ck_assert_near(d.normal.x, xa.q.c, TOL);
  ck_assert_near(d.normal.y, xa.q.s, TOL);
}
END_TEST

START_TEST(point_segment_and_parallel_segments) {
  tb_vec2 seg[2] = {{-2, 0}, {2, 0}};
  tb_vec2 o = {0, 0};
  tb_shape_proxy s = tb_make_proxy(seg, 2, 0.0f), p = tb_make_proxy(&o, 1, 0.0f);
  tb_distance_output d = distance_of(&s, identity, &p, xf_make(1.0f, -1.5f, 0.0f), NULL);
  ck_assert_near(d.distance, 1.5, TOL);
  ck_assert_near(d.point_a.x, 1.0, TOL);
  ck_assert_near(d.normal.y, -1.0, TOL);
  ck_assert_int_eq(d.simplex_count, 2);
  /* Beyond the end: distance to the end point. */
  d = distance_of(&s, identity, &p, xf_make(5.0f, 4.0f, 0.0f), NULL);
  ck_assert_near(d.distance, 5.0, TOL);

  /* Parallel segments 0.75 apart, also rotated as a pair; any closest pair. */
  tb_shape_proxy s2 = tb_make_proxy(seg, 2, 0.0f);
  d = distance_of(&s, xf_make(0, 0, 0.4f), &s2,
                  xf_make(1.0f * -sinf(0.4f) * 0.75f + cosf(0.4f), 0.75f * cosf(0.4f) + sinf(0.4f), 0.4f), NULL);
  ck_assert_near(d.distance, 0.75, TOL);
  ck_assert_near(d.normal.x, -sinf(0.4f), TOL);
  ck_assert_near(d.normal.y, cosf(0.4f), TOL);
}
END_TEST

START_TEST(rounded_shapes) {
  /* Capsule (core -1..1 on x, radius 0.2) above a rounded box (core 1 x 0.5,
   * radius 0.1): gap = 1.0 - 0.5 - 0.2 - 0.1. */
  tb_capsule cap = {{-1, 0}, {1, 0}, 0.2f};
  tb_polygon rb;
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 0.5f, 0.1f, &rb), TB_OK);
  tb_shape_proxy a = tb_make_polygon_proxy(&rb), b = tb_make_capsule_proxy(&cap);
  tb_distance_output d = distance_of(&a, identity, &b, xf_make(0.5f, 1.0f, 0.0f), NULL);
  ck_assert_near(d.distance, 0.2, TOL);
  ck_assert_near(d.normal.y, 1.0, TOL);
  ck_assert_near(d.point_a.y, 0.6, TOL);
  ck_assert_near(d.point_b.y, 0.8, TOL);
  /* Corner to corner along the diagonal: the rounded corners are arcs. */
  d = distance_of(&a, identity, &b, xf_make(1.0f + 1.0f + 3.0f, 0.5f + 4.0f, 0.0f), NULL);
  ck_assert_near(d.distance, 5.0 - 0.3, TOL);
  ck_assert_near(d.point_a.x, 1.0 + 0.1 * 0.6, TOL);
  ck_assert_near(d.point_a.y, 0.5 + 0.1 * 0.8, TOL);
}
END_TEST

START_TEST(overlap_gives_zero) {
  tb_shape_proxy a = box_proxy(1.0f, 1.0f, 0.0f), b = box_proxy(0.5f, 0.5f, 0.0f);
  tb_distance_output d = distance_of(&a, identity, &b, xf_make(0.8f, 0.3f, 0.5f), NULL);
  ck_assert_float_eq(d.distance, 0.0f);
  ck_assert_int_eq(d.simplex_count, 3);
  ck_assert_float_eq(d.normal.x, 0.0f);
  ck_assert_float_eq(d.normal.y, 0.0f);
  ck_assert_float_eq(d.point_a.x, d.point_b.x);
  /* B inside A entirely. */
  d = distance_of(&a, identity, &b, xf_make(0.1f, -0.1f, 0.2f), NULL);
  ck_assert_float_eq(d.distance, 0.0f);
  /* Rounded overlap with separated cores: 0, points at the middle, normal kept. */
  tb_vec2 o = {0, 0};
  tb_shape_proxy c1 = tb_make_proxy(&o, 1, 1.0f), c2 = tb_make_proxy(&o, 1, 0.5f);
  d = distance_of(&c1, identity, &c2, xf_make(1.3f, 0.0f, 0.0f), NULL);
  ck_assert_float_eq(d.distance, 0.0f);
  ck_assert_near(d.normal.x, 1.0, TOL);
  ck_assert_near(d.point_a.x, 0.5 * (1.0 + 0.8), TOL);
  ck_assert_float_eq(d.point_a.x, d.point_b.x);
  /* Identical shapes at one place; duplicate points in a proxy. */
  tb_vec2 dup[5] = {{0, 0}, {1, 0}, {1, 0}, {0, 1}, {0, 0}};
  tb_shape_proxy t = tb_make_proxy(dup, 5, 0.0f);
  d = distance_of(&t, identity, &t, identity, NULL);
  ck_assert_float_eq(d.distance, 0.0f);
  d = distance_of(&t, identity, &t, xf_make(3.0f, 0.0f, 0.0f), NULL);
  ck_assert_near(d.distance, 2.0, TOL);
}
END_TEST

/* GJK against the brute force on random pairs of every kind. */
START_TEST(random_pairs_vs_brute_force) {
  unsigned rng = 99;
  int bad = 0, overlaps = 0;
  double worst = 0.0;
  for (int i = 0; i < 5000; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_transform xa = xf_make(tbt_rand(&rng, -2, 2), tbt_rand(&rng, -2, 2), tbt_rand(&rng, -4, 4));
    tb_transform xb = xf_make(tbt_rand(&rng, -2, 2), tbt_rand(&rng, -2, 2), tbt_rand(&rng, -4, 4));
    tb_distance_output d = distance_of(&a, xa, &b, xb, NULL);
    double want = fmax(0.0, brute_gap(&a, xa, &b, xb));
    overlaps += want == 0.0;
    double err = fabs(d.distance - want);
    /* The reported points must be that far apart too (when separated). */
    if (want > 0.0) err = fmax(err, fabs(tb_length(tb_sub(d.point_b, d.point_a)) - want));
    worst = fmax(worst, err);
    bad += err > TOL;
  }
  ck_assert_msg(bad == 0, "%d of 5000 pairs off by more than %g (worst %g)", bad, TOL, worst);
  ck_assert_int_gt(overlaps, 100);
}
END_TEST

/* Warm start: the cached simplex of the same (or a slightly moved) pair gives
 * the same answer in fewer support evaluations. */
START_TEST(warm_start) {
  unsigned rng = 5;
  long cold_total = 0, warm_total = 0, moved_cold = 0, moved_warm = 0;
  int worse = 0, differ = 0;
  for (int i = 0; i < 2000; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_transform xa = xf_make(tbt_rand(&rng, -3, 3), tbt_rand(&rng, -3, 3), tbt_rand(&rng, -4, 4));
    tb_transform xb = xf_make(tbt_rand(&rng, -3, 3), tbt_rand(&rng, -3, 3), tbt_rand(&rng, -4, 4));
    tb_simplex_cache cache = {0};
    tb_distance_output cold = distance_of(&a, xa, &b, xb, &cache);
    tb_distance_output warm = distance_of(&a, xa, &b, xb, &cache);
    cold_total += cold.iterations;
    warm_total += warm.iterations;
    worse += warm.iterations > cold.iterations;
    differ += fabsf(warm.distance - cold.distance) > 1e-6f;
    /* Next "step": B moved a little. */
    tb_transform xb2 = xf_make(xb.p.x + 0.01f, xb.p.y - 0.02f, atan2f(xb.q.s, xb.q.c) + 0.02f);
    tb_distance_output m_warm = distance_of(&a, xa, &b, xb2, &cache);
    tb_distance_output m_cold = distance_of(&a, xa, &b, xb2, NULL);
    moved_warm += m_warm.iterations;
    moved_cold += m_cold.iterations;
    differ += fabsf(m_warm.distance - m_cold.distance) > 1e-5f;
  }
  ck_assert_int_eq(differ, 0);
  ck_assert_int_eq(worse, 0);
  ck_assert_msg(2 * warm_total < cold_total, "warm %ld vs cold %ld iterations", warm_total, cold_total);
  ck_assert_msg(moved_warm < moved_cold, "moved: warm %ld vs cold %ld iterations", moved_warm, moved_cold);
  /* A stale cache (indices beyond the proxies) is ignored, not trusted. */
  tb_simplex_cache stale = {3, {7, 7, 7}, {7, 7, 7}};
  tb_shape_proxy box = box_proxy(0.5f, 0.5f, 0.0f);
  tb_distance_output d = distance_of(&box, identity, &box, xf_make(2.0f, 0.0f, 0.0f), &stale);
  ck_assert_near(d.distance, 1.0, TOL);
}
END_TEST

/* 1e4 m from the origin the world coordinates carry ~1e-3 m of rounding, but the
 * distance is computed from pB - pA, so it keeps the precision of a pair placed
 * at the origin. The relative placements are exact in float at both places. */
START_TEST(far_from_origin) {
  unsigned rng = 11;
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    float ang_a = tbt_rand(&rng, -3, 3), ang_b = tbt_rand(&rng, -3, 3);
    /* offsets on a 1/256 grid are exact both near 0 and near 1e4 */
    float dx = floorf(tbt_rand(&rng, -3, 3) * 256.0f) / 256.0f, dy = floorf(tbt_rand(&rng, -3, 3) * 256.0f) / 256.0f;
    const float far = 10000.0f;
    tb_distance_output near_d = distance_of(&a, xf_make(0, 0, ang_a), &b, xf_make(dx, dy, ang_b), NULL);
    tb_distance_output far_d =
        distance_of(&a, xf_make(far, -far, ang_a), &b, xf_make(far + dx, -far + dy, ang_b), NULL);
    worst = fmax(worst, fabs(near_d.distance - far_d.distance));
    double want = fmax(0.0, brute_gap(&a, xf_make(0, 0, ang_a), &b, xf_make(dx, dy, ang_b)));
    worst = fmax(worst, fabs(far_d.distance - want));
  }
  ck_assert_msg(worst <= TOL, "far from the origin the distance is off by %g", worst);
}
END_TEST

/* ------------------------------------------------------------- ray casts -- */

static tb_cast_output ray_circle(tb_vec2 o, tb_vec2 d, const tb_circle* c, tb_transform xf) {
  tb_ray_input ray = {o, d, 1.0f};
  tb_cast_output out;
  ck_assert_int_eq(tb_ray_cast_circle(&ray, c, xf, &out), TB_OK);
  return out;
}

START_TEST(ray_closed_forms) {
  /* Circle at (3, 1) radius 1 in the world (local centre offset by the body). */
  tb_circle c = {{1, 0}, 1.0f};
  tb_transform xf = xf_make(2.0f, 1.0f, 0.0f);
  tb_cast_output h = ray_circle((tb_vec2){0, 1}, (tb_vec2){10, 0}, &c, xf);
  ck_assert(h.hit);
  ck_assert_near(h.fraction, 0.2, TOL);
  ck_assert_near(h.point.x, 2.0, TOL);
  ck_assert_near(h.normal.x, -1.0, TOL);
  /* Off-centre by 0.6: enters at x = 3 - sqrt(1 - 0.36) = 2.2. */
  h = ray_circle((tb_vec2){0, 1.6f}, (tb_vec2){10, 0}, &c, xf);
  ck_assert(h.hit);
  ck_assert_near(h.fraction, 0.22, TOL);
  ck_assert_near(h.normal.x, -0.8, TOL);
  ck_assert_near(h.normal.y, 0.6, TOL);
  /* Misses: passes above, too short, pointing away, starting inside. */
  ck_assert(!ray_circle((tb_vec2){0, 2.1f}, (tb_vec2){10, 0}, &c, xf).hit);
  ck_assert(!ray_circle((tb_vec2){0, 1}, (tb_vec2){1.9f, 0}, &c, xf).hit);
  ck_assert(!ray_circle((tb_vec2){0, 1}, (tb_vec2){-10, 0}, &c, xf).hit);
  ck_assert(!ray_circle((tb_vec2){3, 1}, (tb_vec2){10, 0}, &c, xf).hit);
  /* On the surface going in: fraction 0. */
  h = ray_circle((tb_vec2){2, 1}, (tb_vec2){1, 0}, &c, xf);
  ck_assert(h.hit);
  ck_assert_float_eq(h.fraction, 0.0f);

  /* Axis-aligned rays against a box 2 x 1 centred at (5, 0), turned 90 degrees
   * (so 1 wide in x, 2 tall in y in the world). */
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(1.0f, 0.5f, &box), TB_OK);
  tb_transform bx = xf_make(5.0f, 0.0f, (float)(PI / 2));
  tb_ray_input ray = {{0, 0.7f}, {10, 0}, 1.0f};
  tb_cast_output out;
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, bx, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.45, TOL);
  ck_assert_near(out.normal.x, -1.0, TOL);
  ck_assert_near(out.point.y, 0.7, TOL);
  ray = (tb_ray_input){{5.2f, -4}, {0, 8}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, bx, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 3.0 / 8.0, TOL);
  ck_assert_near(out.normal.y, -1.0, TOL);
  ray.max_fraction = 0.3f; /* stops short */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, bx, &out), TB_OK);
  ck_assert(!out.hit);
  ray = (tb_ray_input){{5.0f, 0.0f}, {3, 0}, 1.0f}; /* from inside */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, bx, &out), TB_OK);
  ck_assert(!out.hit);
  ray = (tb_ray_input){{0, 1.2f}, {10, 0}, 1.0f}; /* passes above */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, bx, &out), TB_OK);
  ck_assert(!out.hit);

  /* Rounded box (core 1 x 0.5, radius 0.25): face, then the corner arc. */
  tb_polygon rb;
  ck_assert_int_eq(tb_make_rounded_box(1.0f, 0.5f, 0.25f, &rb), TB_OK);
  ray = (tb_ray_input){{-5, 0.2f}, {10, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &rb, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.point.x, -1.25, TOL);
  ck_assert_near(out.normal.x, -1.0, TOL);
  ray = (tb_ray_input){{-5, 0.65f}, {10, 0}, 1.0f}; /* 0.15 above the core corner */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &rb, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.point.x, -1.0 - 0.2, TOL);
  ck_assert_near(out.normal.x, -0.8, TOL);
  ck_assert_near(out.normal.y, 0.6, TOL);
  ray = (tb_ray_input){{-5, 0.76f}, {10, 0}, 1.0f}; /* misses the arc */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &rb, identity, &out), TB_OK);
  ck_assert(!out.hit);

  /* Capsule from (0,0) to (2,0), radius 0.5: side, end cap, from inside. */
  tb_capsule cap = {{0, 0}, {2, 0}, 0.5f};
  ray = (tb_ray_input){{1, 3}, {0, -4}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_capsule(&ray, &cap, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 2.5 / 4.0, TOL);
  ck_assert_near(out.normal.y, 1.0, TOL);
  ray = (tb_ray_input){{6, 0.3f}, {-6, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_capsule(&ray, &cap, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.point.x, 2.4, TOL);
  ck_assert_near(out.normal.x, 0.8, TOL);
  ray = (tb_ray_input){{1, 0.2f}, {0, 4}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_capsule(&ray, &cap, identity, &out), TB_OK);
  ck_assert(!out.hit);

  /* Segment: from either side, normal towards the origin; along its line: no hit. */
  tb_segment seg = {{0, -1}, {0, 1}};
  ray = (tb_ray_input){{-2, 0.5f}, {4, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_segment(&ray, &seg, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.fraction, 0.5, TOL);
  ck_assert_near(out.normal.x, -1.0, TOL);
  ray = (tb_ray_input){{2, 0.5f}, {-4, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_segment(&ray, &seg, identity, &out), TB_OK);
  ck_assert(out.hit);
  ck_assert_near(out.normal.x, 1.0, TOL);
  ray = (tb_ray_input){{0, -3}, {0, 6}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_segment(&ray, &seg, identity, &out), TB_OK);
  ck_assert(!out.hit);
}
END_TEST

/* Rays against rounded polygons agree with a cast of a point (the same ray as a
 * shape cast), to the cast's tolerance over the ray's length. */
START_TEST(ray_vs_point_cast) {
  unsigned rng = 21;
  int disagree = 0, hits = 0;
  double worst = 0.0;
  tb_vec2 o = {0, 0};
  tb_shape_proxy point = tb_make_proxy(&o, 1, 0.0f);
  for (int i = 0; i < 3000; ++i) {
    tb_polygon p = random_polygon(&rng, 3 + i % 6, i % 2 ? tbt_rand(&rng, 0.05f, 0.4f) : 0.0f);
    tb_transform xf = xf_make(tbt_rand(&rng, -1, 1), tbt_rand(&rng, -1, 1), tbt_rand(&rng, -3, 3));
    /* aimed at a point near the shape, so that about half of them hit */
    tb_vec2 from = {tbt_rand(&rng, -4, 4), tbt_rand(&rng, -4, 4)};
    tb_vec2 aim = {tbt_rand(&rng, -1.5f, 1.5f), tbt_rand(&rng, -1.5f, 1.5f)};
    tb_ray_input ray = {from, tb_scale(tbt_rand(&rng, 0.5f, 2.0f), tb_sub(aim, from)), 1.0f};
    tb_cast_output r;
    ck_assert_int_eq(tb_ray_cast_polygon(&ray, &p, xf, &r), TB_OK);
    tb_shape_cast_input in = {tb_make_polygon_proxy(&p), point, xf, {ray.origin, {1, 0}}, ray.translation};
    tb_cast_output c;
    ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
    /* From inside the ray reports no hit, the cast a hit at 0: compare outside starts only. */
    bool inside = c.hit && c.fraction == 0.0f;
    if (inside) continue;
    double len = tb_length(ray.translation);
    if (r.hit != c.hit) {
      /* Only a grazing ray may fall either way: one that never gets deeper
       * than the cast tolerance below the surface, nor further above it. */
      double deepest = DBL_MAX;
      for (int k = 0; k <= 2000; ++k) {
        tb_vec2 q = tb_mul_add(ray.origin, (float)k / 2000.0f, ray.translation);
        deepest = fmin(deepest, brute_gap(&in.proxy_a, xf, &point, (tb_transform){q, {1, 0}}));
      }
      if (fabs(deepest) > 2.0 * TB_CAST_TOLERANCE) ++disagree;
      continue;
    }
    if (!r.hit) continue;
    ++hits;
    /* The cast stops early by at most its tolerance in gap (more along an
     * oblique ray); the ray is exact. */
    double gap =
        brute_gap(&in.proxy_a, xf, &point, (tb_transform){tb_mul_add(ray.origin, c.fraction, ray.translation), {1, 0}});
    double err = (r.fraction - c.fraction) * len;
    worst = fmax(worst, gap);
    if (err < -1e-5 || gap < -1e-5 || gap > TB_CAST_TOLERANCE + 1e-5) ++disagree;
    if (tb_dot(r.normal, c.normal) < 0.999f) ++disagree;
  }
  ck_assert_msg(disagree == 0, "%d rays disagree with the point cast (worst %g m)", disagree, worst);
  ck_assert_int_gt(hits, 1000);
}
END_TEST

/* ------------------------------------------------------------ shape cast -- */

START_TEST(shape_cast_closed_forms) {
  /* Circle r 0.5 moving right by 10 towards a box (face at x = 4): touches at 3.5. */
  tb_vec2 o = {0, 0};
  tb_shape_proxy box = box_proxy(1.0f, 1.0f, 0.0f), ball = tb_make_proxy(&o, 1, 0.5f);
  tb_shape_cast_input in = {box, ball, xf_make(5, 0, 0), xf_make(0, 0.3f, 0), {10, 0}};
  tb_cast_output c;
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(c.hit);
  ck_assert_near(c.fraction * 10.0, 3.5, TB_CAST_TOLERANCE);
  ck_assert(c.fraction * 10.0 <= 3.5 + 1e-5);
  ck_assert_near(c.normal.x, -1.0, 1e-4); /* from A (the box) to B, which comes from the left */
  ck_assert_near(c.point.x, 4.0, 1e-4);
  ck_assert_near(c.point.y, 0.3, 1e-4);

  /* Box against box, B turned 45 degrees falling onto A's top face. */
  tb_shape_proxy small = box_proxy(0.5f, 0.5f, 0.0f);
  in = (tb_shape_cast_input){box, small, identity, xf_make(0.2f, 5.0f, (float)(PI / 4)), {0, -10}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(c.hit);
  ck_assert_near(c.fraction * 10.0, 4.0 - 0.5 * sqrt(2.0), 1e-4);
  ck_assert_near(c.normal.y, 1.0, 1e-4);
  ck_assert_near(c.point.x, 0.2, 1e-4);
  ck_assert_near(c.point.y, 1.0, 1e-4);

  /* Missing: passes beside; moving away; too short. */
  in = (tb_shape_cast_input){box, ball, xf_make(5, 0, 0), xf_make(0, 1.6f, 0), {10, 0}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(!c.hit);
  in = (tb_shape_cast_input){box, ball, xf_make(5, 0, 0), xf_make(0, 0, 0), {-10, 0}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(!c.hit);
  in = (tb_shape_cast_input){box, ball, xf_make(5, 0, 0), xf_make(0, 0, 0), {3, 0}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(!c.hit);

  /* Starting in contact: hit at 0; with overlapping cores the normal is zero. */
  in = (tb_shape_cast_input){box, ball, identity, xf_make(0.5f, 0.2f, 0), {3, 0}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(c.hit);
  ck_assert_float_eq(c.fraction, 0.0f);
  ck_assert_float_eq(c.normal.x, 0.0f);
  in = (tb_shape_cast_input){box, ball, identity, xf_make(1.3f, 0.0f, 0), {3, 0}};
  ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
  ck_assert(c.hit);
  ck_assert_float_eq(c.fraction, 0.0f);
  ck_assert_near(c.normal.x, 1.0, 1e-4);
}
END_TEST

/* Shape cast against a brute-force sweep: the first sample (of 1e4) where the
 * rounded shapes touch. The cast may stop up to TB_CAST_TOLERANCE early, never
 * late, and at its fraction the gap is in [0, tolerance]. */
START_TEST(shape_cast_vs_brute_force) {
  unsigned rng = 31;
  int bad = 0, hits = 0;
  char what[160] = "";
  for (int i = 0; i < 150; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_transform xa = xf_make(0, 0, tbt_rand(&rng, -3, 3));
    float ang = tbt_rand(&rng, 0, (float)(2 * PI));
    tb_transform xb = xf_make(4.0f * cosf(ang), 4.0f * sinf(ang), tbt_rand(&rng, -3, 3));
    tb_vec2 tr = {-8.0f * cosf(ang) + tbt_rand(&rng, -2, 2), -8.0f * sinf(ang) + tbt_rand(&rng, -2, 2)};
    if (brute_gap(&a, xa, &b, xb) <= 0.0) continue;
    tb_shape_cast_input in = {a, b, xa, xb, tr};
    tb_cast_output c;
    ck_assert_int_eq(tb_shape_cast(&in, &c), TB_OK);
    double first = -1.0;
    for (int k = 0; k <= 10000 && first < 0.0; ++k) {
      float f = (float)k / 10000.0f;
      if (brute_gap(&a, xa, &b, (tb_transform){tb_mul_add(xb.p, f, tr), xb.q}) < 0.0) first = f;
    }
    tb_transform xt = {tb_mul_add(xb.p, c.fraction, tr), xb.q};
    double at = c.hit ? brute_gap(&a, xa, &b, xt) : 0.0;
    bool ok = c.hit ? (at >= -1e-5 && at <= TB_CAST_TOLERANCE + 1e-5 && (first < 0.0 || c.fraction <= first + 1e-6))
                    : first < 0.0;
    /* The normal must be a separating axis at the contact: the separation of
     * the shapes along it equals the gap (up to the tolerance). */
    if (c.hit && ok) ok = at - separation_along(&a, xa, &b, xt, c.normal) <= TB_CAST_TOLERANCE + 1e-5;
    if (!ok) {
      ++bad;
      snprintf(what, sizeof what, "pair %d: hit %d at %.7f (gap %.3g), brute first %.5f", i, c.hit, c.fraction, at,
               first);
    }
    hits += c.hit;
  }
  ck_assert_msg(bad == 0, "%d casts wrong, e.g. %s", bad, what);
  ck_assert_int_gt(hits, 50);
}
END_TEST

/* --------------------------------------------------------- time of impact -- */

static tb_sweep sweep_make(tb_vec2 lc, tb_vec2 c1, tb_vec2 c2, float a1, float a2) {
  return (tb_sweep){lc, c1, c2, a1, a2};
}

static double gap_at(const tb_toi_input* in, float t) {
  return brute_gap(&in->proxy_a, tb_sweep_transform(&in->sweep_a, t), &in->proxy_b,
                   tb_sweep_transform(&in->sweep_b, t));
}

START_TEST(toi_closed_forms) {
  /* A box falling 10 m onto a ground box: faces 4 m apart, target slop. */
  tb_shape_proxy ground = box_proxy(5.0f, 0.5f, 0.0f), box = box_proxy(0.5f, 0.5f, 0.0f);
  tb_toi_input in = {ground,
                     box,
                     sweep_make((tb_vec2){0, 0}, (tb_vec2){0, 0}, (tb_vec2){0, 0}, 0, 0),
                     sweep_make((tb_vec2){0, 0}, (tb_vec2){0, 5}, (tb_vec2){0, -5}, 0, 0),
                     1.0f,
                     TB_LINEAR_SLOP,
                     0.25f * TB_LINEAR_SLOP};
  tb_toi_output out;
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_HIT);
  ck_assert_near(out.fraction, (4.0 - TB_LINEAR_SLOP) / 10.0, 0.25 * TB_LINEAR_SLOP / 10.0);
  ck_assert_int_le(out.iterations, 3);

  /* max_fraction short of the contact: separated at max_fraction. */
  in.max_fraction = 0.3f;
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_SEPARATED);
  ck_assert_float_eq(out.fraction, 0.3f);
  in.max_fraction = 1.0f;

  /* Moving apart: separated. */
  in.sweep_b = sweep_make((tb_vec2){0, 0}, (tb_vec2){0, 5}, (tb_vec2){0, 9}, 0, 0);
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_SEPARATED);
  ck_assert_float_eq(out.fraction, 1.0f);

  /* Starting inside: overlapped at 0. */
  in.sweep_b = sweep_make((tb_vec2){0, 0}, (tb_vec2){0, 0.5f}, (tb_vec2){0, 9}, 0, 0);
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_OVERLAPPED);
  ck_assert_float_eq(out.fraction, 0.0f);

  /* A spinning bar (half length 2, centre of mass offset in the body) with no
   * translation, 1.5 m above the ground's top: its tip reaches down at a turn of
   * asin(1.5 / 2) from the horizontal. */
  tb_vec2 bar_pts[2] = {{-1.0f, 0.0f}, {3.0f, 0.0f}};
  tb_shape_proxy bar = tb_make_proxy(bar_pts, 2, 0.0f);
  in = (tb_toi_input){ground,
                      bar,
                      sweep_make((tb_vec2){0, 0}, (tb_vec2){0, 0}, (tb_vec2){0, 0}, 0, 0),
                      sweep_make((tb_vec2){1, 0}, (tb_vec2){0, 2}, (tb_vec2){0, 2}, 0, (float)(-PI)),
                      1.0f,
                      TB_LINEAR_SLOP,
                      0.25f * TB_LINEAR_SLOP};
  ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
  ck_assert_int_eq(out.state, TB_TOI_HIT);
  double t_touch = asin((1.5 - TB_LINEAR_SLOP) / 2.0) / PI;
  ck_assert(out.fraction <= t_touch + 1e-6);
  ck_assert_near(gap_at(&in, out.fraction), TB_LINEAR_SLOP, 0.25 * TB_LINEAR_SLOP);
}
END_TEST

/* TOI against a brute-force sweep of 1e4 samples: the first sample with a gap
 * below target. The TOI must not be later, and at its t the gap must be within
 * target +- tolerance. A separated result must have no sample below target. */
START_TEST(toi_vs_brute_force) {
  unsigned rng = 77;
  const float target = TB_LINEAR_SLOP, tol = 0.25f * TB_LINEAR_SLOP;
  int bad = 0, hits = 0, separated = 0, failed = 0, rotating = 0, max_iter = 0;
  long sum_iter = 0;
  char what[200] = "";
  for (int i = 0; i < 200; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_vec2 lca = {tbt_rand(&rng, -0.3f, 0.3f), tbt_rand(&rng, -0.3f, 0.3f)};
    tb_vec2 lcb = {tbt_rand(&rng, -0.3f, 0.3f), tbt_rand(&rng, -0.3f, 0.3f)};
    float ang = tbt_rand(&rng, 0, (float)(2 * PI));
    tb_vec2 c1b = {3.5f * cosf(ang), 3.5f * sinf(ang)};
    tb_vec2 c2b = {c1b.x - 7.0f * cosf(ang) + tbt_rand(&rng, -2.5f, 2.5f),
                   c1b.y - 7.0f * sinf(ang) + tbt_rand(&rng, -2.5f, 2.5f)};
    float spin = i % 3 == 0 ? 0.0f : tbt_rand(&rng, -3.0f, 3.0f); /* two thirds rotate, up to ~half a turn */
    float a1a = tbt_rand(&rng, -3, 3), a1b = tbt_rand(&rng, -3, 3);
    tb_toi_input in = {a,
                       b,
                       sweep_make(lca, (tb_vec2){0, 0}, (tb_vec2){tbt_rand(&rng, -1, 1), tbt_rand(&rng, -1, 1)}, a1a,
                                  a1a + 0.5f * spin),
                       sweep_make(lcb, c1b, c2b, a1b, a1b - spin),
                       1.0f,
                       target,
                       tol};
    if (gap_at(&in, 0.0f) < target + tol) continue;
    rotating += spin != 0.0f;
    tb_toi_output out;
    ck_assert_int_eq(tb_time_of_impact(&in, &out), TB_OK);
    max_iter = out.iterations > max_iter ? out.iterations : max_iter;
    sum_iter += out.iterations;
    double first = -1.0;
    for (int k = 0; k <= 10000 && first < 0.0; ++k)
      if (gap_at(&in, (float)k / 10000.0f) < target) first = k / 10000.0;
    bool ok;
    double g = gap_at(&in, out.fraction);
    if (out.state == TB_TOI_HIT) {
      ++hits;
      ok = g >= target - tol - 1e-5 && g <= target + tol + 1e-5 && (first < 0.0 || out.fraction <= first + 1e-6);
    } else if (out.state == TB_TOI_SEPARATED) {
      ++separated;
      ok = first < 0.0 && out.fraction == 1.0f;
    } else {
      ++failed;
      ok = out.state == TB_TOI_FAILED && (first < 0.0 || out.fraction <= first) && g >= target - 1e-5;
    }
    if (!ok) {
      ++bad;
      snprintf(what, sizeof what, "sweep %d: state %d t %.6f gap %.6f, brute first %.5f", i, (int)out.state,
               out.fraction, g, first);
    }
  }
  fprintf(stderr,
          "distance: TOI vs brute force, %d sweeps (%d rotating): %d hits, %d separated, %d failed; "
          "iterations mean %.1f, max %d\n",
          hits + separated + failed, rotating, hits, separated, failed, (double)sum_iter / (hits + separated + failed),
          max_iter);
  ck_assert_msg(bad == 0, "%d TOIs wrong, e.g. %s", bad, what);
  ck_assert_msg(failed <= 2, "%d TOIs did not converge", failed);
  ck_assert_int_gt(hits, 40);
  ck_assert_int_gt(separated, 10);
  ck_assert_int_gt(rotating, 50);
  ck_assert_int_le(max_iter, 100);
}
END_TEST

/* -------------------------------------------------------------- bad input -- */

START_TEST(bad_input) {
  tb_vec2 pts[2] = {{0, 0}, {1, 0}};
  tb_vec2 nan_pt = {NAN, 0};
  /* Proxies. */
  ck_assert_int_eq(tb_make_proxy(pts, 0, 0.0f).count, 0);
  ck_assert_int_eq(tb_last_result(), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_make_proxy(pts, TB_MAX_POLYGON_VERTICES + 1, 0.0f).count, 0);
  ck_assert_int_eq(tb_make_proxy(NULL, 1, 0.0f).count, 0);
  ck_assert_int_eq(tb_last_result(), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_make_proxy(&nan_pt, 1, 0.0f).count, 0);
  ck_assert_int_eq(tb_make_proxy(pts, 2, -1.0f).count, 0);
  ck_assert_int_eq(tb_make_proxy(pts, 2, NAN).count, 0);
  tb_circle bad_circle = {{0, 0}, -1.0f};
  ck_assert_int_eq(tb_make_circle_proxy(&bad_circle).count, 0);
  ck_assert_int_eq(tb_make_circle_proxy(NULL).count, 0);
  tb_segment bad_seg = {{1, 1}, {1, 1}};
  ck_assert_int_eq(tb_make_segment_proxy(&bad_seg).count, 0);
  ck_assert(strlen(tb_last_error()) > 0);

  /* Distance with an empty proxy, NaN transform, non-unit rotation, NULLs. */
  tb_shape_proxy good = tb_make_proxy(pts, 2, 0.0f), empty;
  memset(&empty, 0, sizeof empty);
  tb_distance_input din = {good, empty, identity, identity};
  tb_distance_output dout;
  ck_assert_int_eq(tb_shape_distance(&din, NULL, &dout), TB_ERR_INVALID_ARGUMENT);
  ck_assert_float_eq(dout.distance, FLT_MAX);
  din.proxy_b = good;
  din.xf_b.p.x = NAN;
  ck_assert_int_eq(tb_shape_distance(&din, NULL, &dout), TB_ERR_INVALID_ARGUMENT);
  din.xf_b = (tb_transform){{0, 0}, {2.0f, 0.0f}};
  ck_assert_int_eq(tb_shape_distance(&din, NULL, &dout), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_shape_distance(NULL, NULL, &dout), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_shape_distance(&din, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  good.count = 99; /* a corrupted proxy */
  din = (tb_distance_input){good, good, identity, identity};
  ck_assert_int_eq(tb_shape_distance(&din, NULL, &dout), TB_ERR_INVALID_ARGUMENT);
  good.count = 2;

  /* Rays: NaN is an error; zero length and negative max are handled. */
  tb_circle c = {{0, 0}, 1.0f};
  tb_cast_output out;
  tb_ray_input ray = {{NAN, 0}, {1, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, &out), TB_ERR_INVALID_ARGUMENT);
  ck_assert(!out.hit);
  ray = (tb_ray_input){{-3, 0}, {NAN, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, &out), TB_ERR_INVALID_ARGUMENT);
  ray = (tb_ray_input){{-3, 0}, {INFINITY, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, &out), TB_ERR_INVALID_ARGUMENT);
  ray = (tb_ray_input){{-3, 0}, {6, 0}, -1.0f};
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, &out), TB_ERR_INVALID_ARGUMENT);
  ray = (tb_ray_input){{-3, 0}, {0, 0}, 1.0f};
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(1, 1, &box), TB_OK);
  tb_capsule cap = {{0, 0}, {1, 0}, 0.5f};
  tb_segment seg = {{0, -1}, {0, 1}};
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, &out), TB_OK);
  ck_assert(!out.hit);
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, identity, &out), TB_OK);
  ck_assert(!out.hit);
  ck_assert_int_eq(tb_ray_cast_capsule(&ray, &cap, identity, &out), TB_OK);
  ck_assert(!out.hit);
  ck_assert_int_eq(tb_ray_cast_segment(&ray, &seg, identity, &out), TB_OK);
  ck_assert(!out.hit);
  ray = (tb_ray_input){{0, 0}, {0, 0}, 1.0f}; /* zero length, inside */
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &box, identity, &out), TB_OK);
  ck_assert(!out.hit);
  ray = (tb_ray_input){{-3, 0}, {6, 0}, 1.0f};
  ck_assert_int_eq(tb_ray_cast_circle(NULL, &c, identity, &out), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_ray_cast_circle(&ray, NULL, identity, &out), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, identity, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_ray_cast_circle(&ray, &bad_circle, identity, &out), TB_ERR_INVALID_ARGUMENT);
  tb_polygon broken = box;
  broken.count = 0;
  ck_assert_int_eq(tb_ray_cast_polygon(&ray, &broken, identity, &out), TB_ERR_INVALID_ARGUMENT);
  ck_assert(!out.hit);

  /* Shape cast. */
  tb_shape_cast_input sin_ = {good, empty, identity, identity, {1, 0}};
  ck_assert_int_eq(tb_shape_cast(&sin_, &out), TB_ERR_INVALID_ARGUMENT);
  ck_assert(!out.hit);
  sin_.proxy_b = good;
  sin_.translation_b.y = NAN;
  ck_assert_int_eq(tb_shape_cast(&sin_, &out), TB_ERR_INVALID_ARGUMENT);
  sin_.translation_b = (tb_vec2){0, 0}; /* zero translation, apart: no hit */
  sin_.xf_b = xf_make(0, 3, 0);
  ck_assert_int_eq(tb_shape_cast(&sin_, &out), TB_OK);
  ck_assert(!out.hit);

  /* TOI. */
  tb_sweep still = {{0, 0}, {0, 0}, {0, 0}, 0, 0};
  tb_toi_input tin = {good, empty, still, still, 1.0f, TB_LINEAR_SLOP, 0.001f};
  tb_toi_output tout;
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tout.state, TB_TOI_FAILED);
  tin.proxy_b = good;
  tin.sweep_b.c2.x = NAN;
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  tin.sweep_b = still;
  tin.sweep_b.a2 = INFINITY;
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  tin.sweep_b = still;
  tin.tolerance = 0.0f;
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  tin.tolerance = 0.001f;
  tin.max_fraction = 1.5f;
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  tin.max_fraction = 1.0f;
  tin.target = -1.0f; /* below -(ra + rb) = 0 */
  ck_assert_int_eq(tb_time_of_impact(&tin, &tout), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_time_of_impact(NULL, &tout), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_time_of_impact(&tin, NULL), TB_ERR_NULL_ARGUMENT);
}
END_TEST

static Suite* distance_suite(void) {
  Suite* s = suite_create("distance");
  TCase* tc = tcase_create("core");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, segment_closest_points);
  tcase_add_test(tc, proxies_of_shapes);
  tcase_add_test(tc, circle_circle);
  tcase_add_test(tc, box_box_gap);
  tcase_add_test(tc, point_segment_and_parallel_segments);
  tcase_add_test(tc, rounded_shapes);
  tcase_add_test(tc, overlap_gives_zero);
  tcase_add_test(tc, random_pairs_vs_brute_force);
  tcase_add_test(tc, warm_start);
  tcase_add_test(tc, far_from_origin);
  tcase_add_test(tc, ray_closed_forms);
  tcase_add_test(tc, ray_vs_point_cast);
  tcase_add_test(tc, shape_cast_closed_forms);
  tcase_add_test(tc, shape_cast_vs_brute_force);
  tcase_add_test(tc, toi_closed_forms);
  tcase_add_test(tc, toi_vs_brute_force);
  tcase_add_test(tc, bad_input);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(distance_suite)
