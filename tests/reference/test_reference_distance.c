/* Reference suite of the distance module: tumble against Box2D 2.4.1.
 *
 * - GJK distance against b2Distance on 10,000 random pairs of circles and
 *   polygons (3..8 vertices). Box2D gets every polygon with radius 0 through
 *   b2DistanceProxy::Set(vertices, count, radius) (b2DistanceProxy::Set(shape)
 *   would add b2_polygonRadius = 0.01 m), circles with their radius. Distances
 *   must agree to 1e-4 m; the closest points to 1e-3 m where they are unique
 *   (separated shapes, and not two parallel edges facing each other).
 * - Ray casts against b2CircleShape, b2PolygonShape and two-sided b2EdgeShape
 *   ::RayCast on 10,000 random rays each: hit or miss must agree, fractions to
 *   1e-5 (relative, absolute below 1), normals to 1e-4.
 * - Time of impact against b2TimeOfImpact on random sweeps with rotation, with
 *   Box2D's own target and tolerance. The ground truth is a brute-force sweep of
 *   1e4 samples: tumble must never be later than the first sample closer than
 *   the target; Box2D's result is counted, not asserted (see below).
 * - Shape cast against b2ShapeCast: Box2D stops at a gap of about b2_linearSlop
 *   (its target is max(slop, ra + rb - slop) on the cores, tolerance slop / 2),
 *   tumble at a gap in [0, TB_CAST_TOLERANCE]; so the check is that at Box2D's
 *   fraction tumble's gap lies in [0, 1.5 slop] and that hits agree.
 *
 * The measured numbers are printed on stderr. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../src/distance.h"
#include "../../src/math_internal.h"
#include "../test_util.h"
#include "b2_distance_shim.h"

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- helpers -- */

static tb_transform xf_make(float x, float y, float angle) {
  return (tb_transform){{x, y}, {cosf(angle), sinf(angle)}};
}

static b2d_transform to_b2d_xf(tb_transform xf) { return (b2d_transform){xf.p.x, xf.p.y, xf.q.c, xf.q.s}; }

static b2d_proxy to_b2d_proxy(const tb_shape_proxy* p) {
  b2d_proxy out;
  memset(&out, 0, sizeof out);
  for (int i = 0; i < p->count; ++i) {
    out.x[i] = p->points[i].x;
    out.y[i] = p->points[i].y;
  }
  out.count = p->count;
  out.radius = p->radius;
  return out;
}

static b2d_sweep to_b2d_sweep(const tb_sweep* s) {
  return (b2d_sweep){s->local_center.x, s->local_center.y, s->c1.x, s->c1.y, s->c2.x, s->c2.y, s->a1, s->a2};
}

static tb_polygon random_polygon(unsigned* rng, int n) {
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
    if (tb_make_polygon(pts, n, 0.0f, &p) == TB_OK && p.count == n) return p;
  }
}

/* A circle (a quarter of the time) or a polygon of 3..8 vertices, radius 0. */
static tb_shape_proxy random_proxy(unsigned* rng) {
  if (tbt_rand(rng, 0.0f, 1.0f) < 0.25f) {
    tb_circle c = {{tbt_rand(rng, -0.3f, 0.3f), tbt_rand(rng, -0.3f, 0.3f)}, tbt_rand(rng, 0.1f, 1.0f)};
    return tb_make_circle_proxy(&c);
  }
  tb_polygon p = random_polygon(rng, 3 + (int)tbt_rand(rng, 0.0f, 6.0f));
  return tb_make_polygon_proxy(&p);
}

static double dmax(double a, double b) { return a > b ? a : b; }

/* Closest points are unique unless two parallel edges face each other: then at
 * least two core points of each shape are (nearly) extreme along the normal. */
static bool closest_points_unique(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb,
                                  tb_vec2 n) {
  if (a->count < 2 || b->count < 2) return true;
  float da[TB_MAX_POLYGON_VERTICES], db[TB_MAX_POLYGON_VERTICES], max_a = -FLT_MAX, min_b = FLT_MAX;
  for (int i = 0; i < a->count; ++i) {
    da[i] = tb_dot(tb_transform_point(xa, a->points[i]), n);
    max_a = fmaxf(max_a, da[i]);
  }
  for (int i = 0; i < b->count; ++i) {
    db[i] = tb_dot(tb_transform_point(xb, b->points[i]), n);
    min_b = fminf(min_b, db[i]);
  }
  int ea = 0, eb = 0;
  for (int i = 0; i < a->count; ++i) ea += da[i] >= max_a - 1e-3f;
  for (int i = 0; i < b->count; ++i) eb += db[i] <= min_b + 1e-3f;
  return ea < 2 || eb < 2;
}

static float gap_of(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb) {
  tb_distance_input in = {*a, *b, xa, xb};
  tb_distance_output out;
  ck_assert_int_eq(tb_shape_distance(&in, NULL, &out), TB_OK);
  return out.distance;
}

/* Gap of the cores minus the radii (negative when the rounded shapes overlap). */
static float signed_gap(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb) {
  tb_shape_proxy ca = *a, cb = *b;
  ca.radius = 0.0f;
  cb.radius = 0.0f;
  return gap_of(&ca, xa, &cb, xb) - a->radius - b->radius;
}

/* Separation of the rounded shapes along the unit axis n (A to B): the least
 * extent of B along n minus the greatest of A, minus the radii. */
static double separation_along(const tb_shape_proxy* a, tb_transform xa, const tb_shape_proxy* b, tb_transform xb,
                               tb_vec2 n) {
  double max_a = -DBL_MAX, min_b = DBL_MAX;
  for (int i = 0; i < a->count; ++i) {
    tb_vec2 p = tb_transform_point(xa, a->points[i]);
    max_a = dmax(max_a, (double)p.x * n.x + (double)p.y * n.y);
  }
  for (int i = 0; i < b->count; ++i) {
    tb_vec2 p = tb_transform_point(xb, b->points[i]);
    double d = (double)p.x * n.x + (double)p.y * n.y;
    min_b = d < min_b ? d : min_b;
  }
  return min_b - max_a - a->radius - b->radius;
}

/* ------------------------------------------------------------- distance -- */

START_TEST(distance_matches_b2distance) {
  unsigned rng = 2024;
  const int n = 10000;
  int separated = 0, unique = 0, bad_distance = 0, bad_points = 0;
  double max_dd = 0.0, max_dp = 0.0;
  long iters_tb = 0, iters_b2 = 0;
  for (int i = 0; i < n; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_transform xa = xf_make(tbt_rand(&rng, -4, 4), tbt_rand(&rng, -4, 4), tbt_rand(&rng, -4, 4));
    tb_transform xb = xf_make(tbt_rand(&rng, -4, 4), tbt_rand(&rng, -4, 4), tbt_rand(&rng, -4, 4));
    tb_distance_input in = {a, b, xa, xb};
    tb_distance_output d;
    ck_assert_int_eq(tb_shape_distance(&in, NULL, &d), TB_OK);
    b2d_proxy pa = to_b2d_proxy(&a), pb = to_b2d_proxy(&b);
    b2d_distance_output r;
    ck_assert(b2d_distance(&pa, to_b2d_xf(xa), &pb, to_b2d_xf(xb), 1, &r));
    iters_tb += d.iterations;
    iters_b2 += r.iterations;
    double dd = fabs((double)d.distance - (double)r.distance);
    max_dd = dmax(max_dd, dd);
    bad_distance += dd > 1e-4;
    if (d.distance > 0.0f && r.distance > 0.0f) {
      ++separated;
      if (closest_points_unique(&a, xa, &b, xb, d.normal)) {
        ++unique;
        double dp = dmax(hypot(d.point_a.x - r.ax, d.point_a.y - r.ay), hypot(d.point_b.x - r.bx, d.point_b.y - r.by));
        max_dp = dmax(max_dp, dp);
        bad_points += dp > 1e-3;
      }
    }
  }
  fprintf(stderr,
          "reference_distance: b2Distance, %d pairs (%d separated, %d with unique closest points): max |dd| %.3g m, "
          "max |dp| %.3g m; mean iterations tumble %.2f, Box2D %.2f\n",
          n, separated, unique, max_dd, max_dp, (double)iters_tb / n, (double)iters_b2 / n);
  ck_assert_msg(bad_distance == 0, "%d distances differ by more than 1e-4 (max %g)", bad_distance, max_dd);
  ck_assert_msg(bad_points == 0, "%d closest points differ by more than 1e-3 (max %g)", bad_points, max_dp);
  ck_assert_int_gt(separated, n / 2);
  ck_assert_int_gt(unique, n / 3);
}
END_TEST

/* -------------------------------------------------------------- ray casts -- */

typedef struct ray_stats {
  int rays, hits, disagree, bad_fraction, bad_normal, box2d_worse;
  double max_df, max_dn;
} ray_stats;

/* A hit worked out in double, when the caller can: the ground truth for the
 * cases where the two engines differ by more than the tolerance. */
typedef struct ray_truth {
  bool known, hit;
  double fraction, nx, ny;
} ray_truth;

static void compare_ray(ray_stats* st, const tb_cast_output* t, int b2_hit, const b2d_ray_output* b,
                        const ray_truth* truth) {
  ++st->rays;
  if (t->hit != (b2_hit != 0)) {
    ++st->disagree;
    return;
  }
  if (!t->hit) return;
  ++st->hits;
  double df = fabs((double)t->fraction - (double)b->fraction) / dmax(1.0, fabs(b->fraction));
  double dn = hypot(t->normal.x - b->nx, t->normal.y - b->ny);
  if ((df > 1e-5 || dn > 1e-4) && truth->known && truth->hit) {
    /* Off Box2D by more than the tolerance: fine if Box2D is the one that is
     * off, and tumble is within the tolerance of the truth. */
    double tf = fabs(t->fraction - truth->fraction), bf = fabs(b->fraction - truth->fraction);
    double tn = hypot(t->normal.x - truth->nx, t->normal.y - truth->ny);
    double bn = hypot(b->nx - truth->nx, b->ny - truth->ny);
    if (tf <= 1e-5 && tn <= 1e-4 && tf <= bf && tn <= dmax(bn, 1e-6)) {
      ++st->box2d_worse;
      return;
    }
  }
  st->max_df = dmax(st->max_df, df);
  st->max_dn = dmax(st->max_dn, dn);
  st->bad_fraction += df > 1e-5;
  st->bad_normal += dn > 1e-4;
}

static bool report_rays(const char* shape, const ray_stats* st) {
  fprintf(stderr,
          "reference_distance: %s ray casts, %d rays, %d hits: %d hit/miss disagreements, max |dfraction| %.3g, "
          "max |dnormal| %.3g (leaving out %d grazing rays where Box2D is off the double-precision answer by more "
          "than 1e-5 and tumble is not)\n",
          shape, st->rays, st->hits, st->disagree, st->max_df, st->max_dn, st->box2d_worse);
  return st->disagree == 0 && st->bad_fraction == 0 && st->bad_normal == 0 && st->hits > st->rays / 10;
}

/* The circle's entry in double: |o + f d - c| = r, smaller root, origin outside. */
static ray_truth circle_truth(const tb_ray_input* ray, const tb_circle* c, tb_transform xf) {
  ray_truth t = {true, false, 0.0, 0.0, 0.0};
  double cx = xf.p.x + (double)xf.q.c * c->center.x - (double)xf.q.s * c->center.y;
  double cy = xf.p.y + (double)xf.q.s * c->center.x + (double)xf.q.c * c->center.y;
  double dx = ray->translation.x, dy = ray->translation.y, sx = ray->origin.x - cx, sy = ray->origin.y - cy;
  double a = dx * dx + dy * dy, b = sx * dx + sy * dy, k = sx * sx + sy * sy - (double)c->radius * c->radius;
  double disc = b * b - a * k;
  if (a == 0.0 || disc < 0.0 || k < 0.0) return t;
  double f = (-b - sqrt(disc)) / a;
  if (f < 0.0 || f > ray->max_fraction) return t;
  t.hit = true;
  t.fraction = f;
  t.nx = (sx + f * dx) / c->radius;
  t.ny = (sy + f * dy) / c->radius;
  return t;
}

/* A random ray aimed near the origin (where the shapes are), sometimes too short,
 * sometimes starting inside, and clipped by a random max fraction. */
static tb_ray_input random_ray(unsigned* rng) {
  tb_vec2 from = {tbt_rand(rng, -5, 5), tbt_rand(rng, -5, 5)};
  tb_vec2 aim = {tbt_rand(rng, -2, 2), tbt_rand(rng, -2, 2)};
  tb_ray_input ray = {from, tb_scale(tbt_rand(rng, 0.3f, 2.0f), tb_sub(aim, from)), 1.0f};
  if (tbt_rand(rng, 0, 1) < 0.2f) ray.max_fraction = tbt_rand(rng, 0.2f, 1.0f);
  return ray;
}

static b2d_ray to_b2d_ray(const tb_ray_input* r) {
  return (b2d_ray){r->origin.x, r->origin.y, r->origin.x + r->translation.x, r->origin.y + r->translation.y,
                   r->max_fraction};
}

START_TEST(ray_casts_match_box2d) {
  unsigned rng = 4242;
  const int n = 10000;
  ray_stats circle = {0}, polygon = {0}, edge = {0};
  for (int i = 0; i < n; ++i) {
    tb_transform xf = xf_make(tbt_rand(&rng, -1, 1), tbt_rand(&rng, -1, 1), tbt_rand(&rng, -4, 4));
    b2d_transform bxf = to_b2d_xf(xf);
    tb_cast_output t;
    b2d_ray_output b;

    tb_ray_input ray = random_ray(&rng);
    b2d_ray bray = to_b2d_ray(&ray);
    tb_circle c = {{tbt_rand(&rng, -0.5f, 0.5f), tbt_rand(&rng, -0.5f, 0.5f)}, tbt_rand(&rng, 0.1f, 1.5f)};
    ck_assert_int_eq(tb_ray_cast_circle(&ray, &c, xf, &t), TB_OK);
    ray_truth truth = circle_truth(&ray, &c, xf);
    compare_ray(&circle, &t, b2d_ray_cast_circle(c.center.x, c.center.y, c.radius, bxf, &bray, &b), &b, &truth);

    ray = random_ray(&rng);
    bray = to_b2d_ray(&ray);
    tb_polygon p = random_polygon(&rng, 3 + i % 6);
    float xy[2 * TB_MAX_POLYGON_VERTICES];
    for (int k = 0; k < p.count; ++k) {
      xy[2 * k] = p.vertices[k].x;
      xy[2 * k + 1] = p.vertices[k].y;
    }
    ck_assert_int_eq(tb_ray_cast_polygon(&ray, &p, xf, &t), TB_OK);
    const ray_truth unknown = {false, false, 0.0, 0.0, 0.0};
    compare_ray(&polygon, &t, b2d_ray_cast_polygon(xy, p.count, bxf, &bray, &b), &b, &unknown);

    ray = random_ray(&rng);
    bray = to_b2d_ray(&ray);
    tb_segment s = {{tbt_rand(&rng, -1.5f, 1.5f), tbt_rand(&rng, -1.5f, 1.5f)},
                    {tbt_rand(&rng, -1.5f, 1.5f), tbt_rand(&rng, -1.5f, 1.5f)}};
    if (tb_distance_sq(s.point1, s.point2) < 0.01f) s.point2.x += 1.0f;
    ck_assert_int_eq(tb_ray_cast_segment(&ray, &s, xf, &t), TB_OK);
    compare_ray(&edge, &t, b2d_ray_cast_edge(s.point1.x, s.point1.y, s.point2.x, s.point2.y, bxf, &bray, &b), &b,
                &unknown);
  }
  bool ok_circle = report_rays("circle", &circle), ok_polygon = report_rays("polygon", &polygon);
  bool ok_edge = report_rays("edge", &edge);
  ck_assert_msg(ok_circle, "circle rays disagree with Box2D (%d hit/miss, %d fractions, %d normals)", circle.disagree,
                circle.bad_fraction, circle.bad_normal);
  ck_assert_msg(ok_polygon, "polygon rays disagree with Box2D (%d hit/miss, %d fractions, %d normals)",
                polygon.disagree, polygon.bad_fraction, polygon.bad_normal);
  ck_assert_msg(ok_edge, "edge rays disagree with Box2D (%d hit/miss, %d fractions, %d normals)", edge.disagree,
                edge.bad_fraction, edge.bad_normal);
}
END_TEST

/* --------------------------------------------------------- time of impact -- */

START_TEST(toi_matches_box2d_and_brute_force) {
  unsigned rng = 777;
  const int n = 400;
  const float slop = b2d_linear_slop();
  ck_assert_float_eq(slop, TB_LINEAR_SLOP);
  int cases = 0, tb_hits = 0, b2_hits = 0, both_hits = 0, state_disagree = 0, tb_late = 0, b2_late = 0, b2_missed = 0;
  int b2_tunnelled = 0, b2_in_band = 0;
  int tb_bad_gap = 0, tb_failed = 0, b2_failed = 0, tb_max_iter = 0;
  double max_dt = 0.0, max_b2_late = 0.0, sum_dt = 0.0;
  for (int i = 0; i < n; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    float ang = tbt_rand(&rng, 0, (float)(2 * PI));
    tb_vec2 c1b = {3.5f * cosf(ang), 3.5f * sinf(ang)};
    tb_vec2 c2b = {c1b.x - 7.0f * cosf(ang) + tbt_rand(&rng, -2.5f, 2.5f),
                   c1b.y - 7.0f * sinf(ang) + tbt_rand(&rng, -2.5f, 2.5f)};
    float spin = i % 4 == 0 ? 0.0f : tbt_rand(&rng, -3.0f, 3.0f);
    float a1a = tbt_rand(&rng, -3, 3), a1b = tbt_rand(&rng, -3, 3);
    tb_sweep sa = {{tbt_rand(&rng, -0.3f, 0.3f), tbt_rand(&rng, -0.3f, 0.3f)},
                   {0, 0},
                   {tbt_rand(&rng, -1, 1), tbt_rand(&rng, -1, 1)},
                   a1a,
                   a1a + 0.5f * spin};
    tb_sweep sb = {{tbt_rand(&rng, -0.3f, 0.3f), tbt_rand(&rng, -0.3f, 0.3f)}, c1b, c2b, a1b, a1b - spin};

    /* Box2D's target and tolerance, restated as tumble's gap between the
     * rounded surfaces (negative for rounded pairs: Box2D lets them sink). */
    const float radius = a.radius + b.radius;
    const float core_target = fmaxf(slop, radius - 3.0f * slop);
    const float target = core_target - radius, tol = 0.25f * slop;
    if (signed_gap(&a, tb_sweep_transform(&sa, 0), &b, tb_sweep_transform(&sb, 0)) < target + tol) continue;
    ++cases;

    tb_toi_input in = {a, b, sa, sb, 1.0f, target, tol};
    tb_toi_output t;
    ck_assert_int_eq(tb_time_of_impact(&in, &t), TB_OK);
    b2d_proxy pa = to_b2d_proxy(&a), pb = to_b2d_proxy(&b);
    b2d_sweep bsa = to_b2d_sweep(&sa), bsb = to_b2d_sweep(&sb);
    b2d_toi_output r;
    ck_assert(b2d_time_of_impact(&pa, &bsa, &pb, &bsb, 1.0f, &r));

    double first = -1.0;
    for (int k = 0; k <= 10000 && first < 0.0; ++k) {
      float s = (float)k / 10000.0f;
      if (signed_gap(&a, tb_sweep_transform(&sa, s), &b, tb_sweep_transform(&sb, s)) < target) first = s;
    }

    tb_max_iter = t.iterations > tb_max_iter ? t.iterations : tb_max_iter;
    bool tb_hit = t.state == TB_TOI_HIT, b2_hit = r.state == B2D_TOI_TOUCHING;
    tb_hits += tb_hit;
    b2_hits += b2_hit;
    tb_failed += t.state == TB_TOI_FAILED;
    b2_failed += r.state == B2D_TOI_FAILED;
    state_disagree += tb_hit != b2_hit;
    if (tb_hit) {
      float g = signed_gap(&a, tb_sweep_transform(&sa, t.fraction), &b, tb_sweep_transform(&sb, t.fraction));
      tb_bad_gap += g < target - tol - 1e-5f || g > target + tol + 1e-5f;
    }
    if (first >= 0.0) {
      tb_late +=
          !(t.state == TB_TOI_HIT && t.fraction <= first + 1e-6) && !(t.state == TB_TOI_FAILED && t.fraction <= first);
      if (!b2_hit) {
        /* Box2D missed it: a contact that ends again before t = 1 (the known
         * limit of its root finder), or did the shapes end up closer than the
         * target (tunnelling)? */
        float end = signed_gap(&a, tb_sweep_transform(&sa, 1.0f), &b, tb_sweep_transform(&sb, 1.0f));
        if (end < target - tol)
          ++b2_tunnelled;
        else
          ++b2_missed;
      } else if (r.t > first + 1e-6) {
        /* Later than the first sample below the target: within its tolerance
         * band, or past it? */
        float g = signed_gap(&a, tb_sweep_transform(&sa, r.t), &b, tb_sweep_transform(&sb, r.t));
        if (g < target - tol - 1e-5f) {
          ++b2_late;
          max_b2_late = dmax(max_b2_late, r.t - first);
        } else {
          ++b2_in_band;
        }
      }
    }
    if (tb_hit && b2_hit) {
      ++both_hits;
      double dt = fabs((double)t.fraction - (double)r.t);
      max_dt = dmax(max_dt, dt);
      sum_dt += dt;
    }
  }
  fprintf(stderr,
          "reference_distance: TOI, %d sweeps: hits tumble %d, Box2D %d, both %d (max |dt| %.3g, mean %.3g); state "
          "disagreements %d; against the brute-force first contact: tumble late %d; Box2D missed %d contacts that end "
          "before t = 1, tunnelled %d, hit later but within its tolerance band %d, hit past the band %d (by up to "
          "%.3g); failed: tumble %d, Box2D %d; tumble max iterations %d\n",
          cases, tb_hits, b2_hits, both_hits, max_dt, both_hits ? sum_dt / both_hits : 0.0, state_disagree, tb_late,
          b2_missed, b2_tunnelled, b2_in_band, b2_late, max_b2_late, tb_failed, b2_failed, tb_max_iter);
  ck_assert_int_eq(tb_late, 0);
  ck_assert_int_eq(tb_bad_gap, 0);
  ck_assert_int_gt(both_hits, cases / 4);
}
END_TEST

/* ------------------------------------------------------------ shape cast -- */

/* Measured behaviour of b2ShapeCast in 2.4.1: it treats every radius below
 * b2_polygonRadius as b2_polygonRadius and stops when the cores are within that
 * total radius minus 2 b2_linearSlop, plus up to half a slop. For bare polygons
 * that is a gap of 1 cm, for two circles an overlap of 1 cm. tumble stops at a
 * gap in [0, TB_CAST_TOLERANCE]. So hit/miss may differ only for casts whose
 * closest approach lies between the two stopping gaps. */
START_TEST(shape_cast_matches_box2d) {
  unsigned rng = 99;
  const int n = 2000;
  const float slop = b2d_linear_slop(), b2_polygon_radius = 2.0f * slop;
  int cases = 0, hits = 0, explained = 0, unexplained = 0, bad_b2_gap = 0, circle_hits = 0;
  double min_gap = DBL_MAX, max_gap = -DBL_MAX, max_dn_tb = 0.0, max_dn_b2 = 0.0;
  double max_deficit_tb = 0.0, max_deficit_b2 = 0.0;
  for (int i = 0; i < n; ++i) {
    tb_shape_proxy a = random_proxy(&rng), b = random_proxy(&rng);
    tb_transform xa = xf_make(0, 0, tbt_rand(&rng, -3, 3));
    float ang = tbt_rand(&rng, 0, (float)(2 * PI));
    tb_transform xb = xf_make(4.0f * cosf(ang), 4.0f * sinf(ang), tbt_rand(&rng, -3, 3));
    tb_vec2 tr = {-8.0f * cosf(ang) + tbt_rand(&rng, -3, 3), -8.0f * sinf(ang) + tbt_rand(&rng, -3, 3)};
    if (signed_gap(&a, xa, &b, xb) < 4.0f * slop) continue;
    ++cases;
    /* Box2D's stopping gap between the rounded surfaces, as measured. */
    const float b2_stop =
        fmaxf(a.radius, b2_polygon_radius) + fmaxf(b.radius, b2_polygon_radius) - 2.0f * slop - a.radius - b.radius;
    tb_shape_cast_input in = {a, b, xa, xb, tr};
    tb_cast_output t;
    ck_assert_int_eq(tb_shape_cast(&in, &t), TB_OK);
    b2d_proxy pa = to_b2d_proxy(&a), pb = to_b2d_proxy(&b);
    b2d_cast_output r;
    ck_assert(b2d_shape_cast(&pa, to_b2d_xf(xa), &pb, to_b2d_xf(xb), tr.x, tr.y, &r));
    if (t.hit != (r.hit != 0)) {
      float closest = FLT_MAX;
      for (int k = 0; k <= 2000; ++k) {
        tb_transform xk = {tb_mul_add(xb.p, (float)k / 2000.0f, tr), xb.q};
        closest = fminf(closest, signed_gap(&a, xa, &b, xk));
      }
      float lo = fminf(0.0f, b2_stop) - 1e-3f, hi = fmaxf(TB_CAST_TOLERANCE, b2_stop + 0.5f * slop) + 1e-3f;
      if (closest >= lo && closest <= hi)
        ++explained;
      else
        ++unexplained;
      continue;
    }
    if (!t.hit) continue;
    ++hits;
    tb_transform xr = {tb_mul_add(xb.p, r.fraction, tr), xb.q};
    double g = signed_gap(&a, xa, &b, xr) - b2_stop;
    min_gap = g < min_gap ? g : min_gap;
    max_gap = dmax(max_gap, g);
    bad_b2_gap += g < -1e-4 || g > 0.5 * slop + 1e-4;
    /* Normals. Any contact normal must be a separating axis: the separation
     * along it equals the gap, so the deficit gap - separation(n) is 0 for an
     * exact normal (and grows with its error). Where two vertices meet the
     * normal is a cone, hence this rather than a comparison of directions;
     * with a circle the normal is unique and the directions are compared too. */
    tb_transform xt = {tb_mul_add(xb.p, t.fraction, tr), xb.q};
    max_deficit_tb = dmax(max_deficit_tb, signed_gap(&a, xa, &b, xt) - separation_along(&a, xa, &b, xt, t.normal));
    tb_vec2 rn = {r.nx, r.ny};
    max_deficit_b2 = dmax(max_deficit_b2, signed_gap(&a, xa, &b, xr) - separation_along(&a, xa, &b, xr, rn));
    if (a.count == 1 || b.count == 1) {
      tb_distance_input at = {a, b, xa, xt};
      tb_shape_proxy ca = a, cb = b;
      ca.radius = cb.radius = 0.0f;
      at.proxy_a = ca;
      at.proxy_b = cb;
      tb_distance_output d;
      ck_assert_int_eq(tb_shape_distance(&at, NULL, &d), TB_OK);
      max_dn_tb = dmax(max_dn_tb, hypot(t.normal.x - d.normal.x, t.normal.y - d.normal.y));
      max_dn_b2 = dmax(max_dn_b2, hypot(r.nx - d.normal.x, r.ny - d.normal.y));
      ++circle_hits;
    }
  }
  fprintf(stderr,
          "reference_distance: shape cast, %d casts, %d hits: %d hit/miss disagreements, all %d where the closest "
          "approach lies between the two engines' stopping gaps (%d otherwise); Box2D's gap at its fraction minus "
          "its stopping gap in [%.3g, %.3g] m; normal as a separating axis: max deficit %.3g m (tumble), %.3g m "
          "(Box2D); with a circle (%d hits), normal off the GJK normal by up to %.3g (tumble), %.3g (Box2D)\n",
          cases, hits, explained + unexplained, explained, unexplained, min_gap, max_gap, max_deficit_tb,
          max_deficit_b2, circle_hits, max_dn_tb, max_dn_b2);
  ck_assert_int_eq(unexplained, 0);
  ck_assert_msg(bad_b2_gap == 0, "%d casts: Box2D did not stop where it was measured to", bad_b2_gap);
  ck_assert_msg(max_deficit_tb <= TB_CAST_TOLERANCE, "tumble's cast normal is not a separating axis (deficit %g)",
                max_deficit_tb);
  ck_assert_msg(max_dn_tb <= 1e-3, "tumble's cast normal is off the GJK normal by %g", max_dn_tb);
  ck_assert_int_gt(hits, cases / 4);
}
END_TEST

static Suite* reference_distance_suite(void) {
  Suite* s = suite_create("reference_distance");
  TCase* tc = tcase_create("box2d");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, distance_matches_b2distance);
  tcase_add_test(tc, ray_casts_match_box2d);
  tcase_add_test(tc, toi_matches_box2d_and_brute_force);
  tcase_add_test(tc, shape_cast_matches_box2d);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(reference_distance_suite)
