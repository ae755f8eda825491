/* Distance, shape cast, time of impact and ray casts of convex shapes.
 *
 * Sources (ideas, not code): Gilbert, Johnson and Keerthi (1988) for the distance
 * algorithm; van den Bergen, "Ray Casting against General Convex Objects with
 * Application to Continuous Collision Detection" (2004) for the GJK ray cast;
 * Catto, "Computing Distance" (GDC 2010) for the barycentric simplex solver, and
 * "Continuous Collision" (GDC 2013) for conservative advancement and its bound;
 * Ericson, "Real-Time Collision Detection" (2005) for Voronoi-region tests. */
#include "distance.h"

#include <float.h>
#include <string.h>

#include "error.h"
#include "geometry.h"
#include "math_internal.h"
#include "units.h"

#define GJK_MAX_ITERATIONS 32
#define CAST_MAX_ITERATIONS 50
#define TOI_MAX_ITERATIONS 100

/* ------------------------------------------------------------ validation -- */

static bool proxy_ok(const tb_shape_proxy* p) {
  if (p->count < 1 || p->count > TB_MAX_POLYGON_VERTICES) return false;
  if (!(p->radius >= 0.0f) || !tb_length_ok(p->radius)) return false;
  for (int i = 0; i < p->count; ++i)
    if (!tb_point_ok(p->points[i])) return false;
  return true;
}

/* A transform must place things within the world limits and rotate without
 * scaling (a non-unit rotation would silently scale every shape). */
bool tb_transform_ok(tb_transform xf) {
  if (!tb_point_ok(xf.p) || !tb_finite(xf.q.c) || !tb_finite(xf.q.s)) return false;
  return fabsf(xf.q.c * xf.q.c + xf.q.s * xf.q.s - 1.0f) <= 1e-3f;
}

static bool sweep_ok(const tb_sweep* s) {
  return tb_point_ok(s->local_center) && tb_point_ok(s->c1) && tb_point_ok(s->c2) && tb_value_ok(s->a1) &&
         tb_value_ok(s->a2);
}

/* ---------------------------------------------------------------- proxies -- */

/* Checks and copies the points; fn names the public function called. */
static tb_shape_proxy make_proxy(const char* fn, const tb_vec2* points, int count, float radius) {
  tb_shape_proxy proxy;
  memset(&proxy, 0, sizeof proxy);
  if (points == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: points is NULL", fn);
    return proxy;
  }
  if (count < 1 || count > TB_MAX_POLYGON_VERTICES) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: count %d is not in 1..TB_MAX_POLYGON_VERTICES", fn, count);
    return proxy;
  }
  if (!(radius >= 0.0f) || !tb_length_ok(radius)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: radius must be >= 0, finite and <= TB_MAX_LENGTH", fn);
    return proxy;
  }
  for (int i = 0; i < count; ++i) {
    if (!tb_point_ok(points[i])) {
      tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: point %d is not finite or beyond TB_MAX_LENGTH", fn, i);
      return proxy;
    }
    proxy.points[i] = points[i];
  }
  proxy.count = count;
  proxy.radius = radius;
  return proxy;
}

tb_shape_proxy tb_make_proxy(const tb_vec2* points, int count, float radius) {
  return make_proxy(__func__, points, count, radius);
}

/* The placed points must stay within TB_MAX_LENGTH like any proxy point. */
tb_shape_proxy tb_make_offset_proxy(const tb_vec2* points, int count, float radius, tb_vec2 position, float angle) {
  const char* fn = __func__;
  tb_shape_proxy proxy;
  memset(&proxy, 0, sizeof proxy);
  if (!tb_point_ok(position)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: position is not finite or beyond TB_MAX_LENGTH", fn);
    return proxy;
  }
  if (tb_check_angle(NULL, fn, "angle", angle) != TB_OK) return proxy;
  tb_shape_proxy local = make_proxy(fn, points, count, radius);
  if (local.count == 0) return proxy;
  tb_transform xf = {position, angle == 0.0f ? (tb_rot){1.0f, 0.0f} : tb_make_rot(angle)};
  for (int i = 0; i < local.count; ++i) {
    local.points[i] = tb_transform_point(xf, local.points[i]);
    if (!tb_point_ok(local.points[i])) {
      tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: placed point %d lies beyond TB_MAX_LENGTH", fn, i);
      return proxy;
    }
  }
  return local;
}

static tb_shape_proxy bad_proxy(const char* fn, const char* why) {
  tb_shape_proxy proxy;
  memset(&proxy, 0, sizeof proxy);
  if (why == NULL)
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: shape is NULL", fn);
  else
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: %s", fn, why);
  return proxy;
}

tb_shape_proxy tb_make_circle_proxy(const tb_circle* circle) {
  const char* why = circle != NULL ? tb_check_circle(circle) : NULL;
  if (circle == NULL || why != NULL) return bad_proxy("tb_make_circle_proxy", why);
  return tb_make_proxy(&circle->center, 1, circle->radius);
}

tb_shape_proxy tb_make_capsule_proxy(const tb_capsule* capsule) {
  const char* why = capsule != NULL ? tb_check_capsule(capsule) : NULL;
  if (capsule == NULL || why != NULL) return bad_proxy("tb_make_capsule_proxy", why);
  tb_vec2 pts[2] = {capsule->center1, capsule->center2};
  return tb_make_proxy(pts, 2, capsule->radius);
}

tb_shape_proxy tb_make_segment_proxy(const tb_segment* segment) {
  const char* why = segment != NULL ? tb_check_segment(segment) : NULL;
  if (segment == NULL || why != NULL) return bad_proxy("tb_make_segment_proxy", why);
  tb_vec2 pts[2] = {segment->point1, segment->point2};
  return tb_make_proxy(pts, 2, 0.0f);
}

tb_shape_proxy tb_make_polygon_proxy(const tb_polygon* polygon) {
  const char* why = polygon != NULL ? tb_check_polygon(polygon) : NULL;
  if (polygon == NULL || why != NULL) return bad_proxy("tb_make_polygon_proxy", why);
  return tb_make_proxy(polygon->vertices, polygon->count, polygon->radius);
}

/* ------------------------------------------------------ segment distance -- */

static float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

/* Fraction along a-b of the point closest to p (0 for a zero-length segment). */
static float point_segment_fraction(tb_vec2 p, tb_vec2 a, tb_vec2 b) {
  tb_vec2 e = tb_sub(b, a);
  float ee = tb_dot(e, e);
  if (!(ee > 0.0f)) return 0.0f;
  return clamp01(tb_dot(tb_sub(p, a), e) / ee);
}

/* In 2D two segments either cross (distance 0) or are closest at an endpoint of
 * one of them, so four point-segment distances settle every other case. This
 * avoids the ill-conditioned 2x2 solve of the classic method for near-parallel
 * segments, whose error grows like length * angle / epsilon. */
tb_segment_distance_output tb_segment_distance_unchecked(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2) {
  tb_segment_distance_output out;
  tb_vec2 d1 = tb_sub(q1, p1), d2 = tb_sub(q2, p2);

  /* Proper crossing: the endpoints of each segment lie strictly on both sides of
   * the other's line. s = o1 / (o1 - o2) is where the signed area against line 2
   * vanishes; o1 and o2 have opposite signs, so the division is well conditioned. */
  float o1 = tb_cross(d2, tb_sub(p1, p2)), o2 = tb_cross(d2, tb_sub(q1, p2));
  float o3 = tb_cross(d1, tb_sub(p2, p1)), o4 = tb_cross(d1, tb_sub(q2, p1));
  if (((o1 < 0.0f && o2 > 0.0f) || (o1 > 0.0f && o2 < 0.0f)) &&
      ((o3 < 0.0f && o4 > 0.0f) || (o3 > 0.0f && o4 < 0.0f))) {
    out.fraction1 = clamp01(o1 / (o1 - o2));
    out.fraction2 = clamp01(o3 / (o3 - o4));
    out.closest1 = tb_mul_add(p1, out.fraction1, d1);
    out.closest2 = tb_mul_add(p2, out.fraction2, d2);
    out.distance_sq = 0.0f;
    return out;
  }

  /* Endpoint candidates: p1, q1 against segment 2; p2, q2 against segment 1. */
  float best = FLT_MAX;
  float fr[4][2] = {{0.0f, point_segment_fraction(p1, p2, q2)},
                    {1.0f, point_segment_fraction(q1, p2, q2)},
                    {point_segment_fraction(p2, p1, q1), 0.0f},
                    {point_segment_fraction(q2, p1, q1), 1.0f}};
  out.fraction1 = 0.0f;
  out.fraction2 = 0.0f;
  for (int i = 0; i < 4; ++i) {
    tb_vec2 c1 = tb_mul_add(p1, fr[i][0], d1), c2 = tb_mul_add(p2, fr[i][1], d2);
    float dsq = tb_distance_sq(c1, c2);
    if (dsq < best) {
      best = dsq;
      out.fraction1 = fr[i][0];
      out.fraction2 = fr[i][1];
    }
  }

  /* Parallel segments whose projections overlap: every point of the overlap is
   * as close, so take its middle (stable under small motions, unlike an end). */
  float l1 = tb_dot(d1, d1), l2 = tb_dot(d2, d2);
  float cr = tb_cross(d1, d2);
  if (l1 > 0.0f && l2 > 0.0f && cr * cr <= 1e-14f * l1 * l2) { /* angle below ~1e-7 rad */
    float s0 = tb_dot(tb_sub(p2, p1), d1) / l1, s1 = tb_dot(tb_sub(q2, p1), d1) / l1;
    float lo = tb_maxf(0.0f, tb_minf(s0, s1)), hi = tb_minf(1.0f, tb_maxf(s0, s1));
    if (lo <= hi) {
      out.fraction1 = 0.5f * (lo + hi);
      out.fraction2 = point_segment_fraction(tb_mul_add(p1, out.fraction1, d1), p2, q2);
    }
  }
  out.closest1 = tb_mul_add(p1, out.fraction1, d1);
  out.closest2 = tb_mul_add(p2, out.fraction2, d2);
  out.distance_sq = tb_distance_sq(out.closest1, out.closest2);
  return out;
}

tb_segment_distance_output tb_segment_distance(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2) {
  if (!tb_point_ok(p1) || !tb_point_ok(q1) || !tb_point_ok(p2) || !tb_point_ok(q2)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_segment_distance: a point is not finite or beyond TB_MAX_LENGTH");
    tb_segment_distance_output out;
    memset(&out, 0, sizeof out);
    out.distance_sq = FLT_MAX;
    return out;
  }
  return tb_segment_distance_unchecked(p1, q1, p2, q2);
}

/* ----------------------------------------------------------------- simplex -- */

/* A vertex of the Minkowski difference B - A: w = wb - wa, with the indices of
 * the support points and its barycentric weight in the closest point. */
typedef struct simplex_vertex {
  tb_vec2 wa, wb, w;
  float a;
  int ia, ib;
} simplex_vertex;

typedef struct simplex {
  simplex_vertex v[3];
  int count;
} simplex;

static int support(const tb_vec2* pts, int count, tb_vec2 d) {
  int best = 0;
  float best_value = tb_dot(pts[0], d);
  for (int i = 1; i < count; ++i) {
    float value = tb_dot(pts[i], d);
    if (value > best_value) {
      best = i;
      best_value = value;
    }
  }
  return best;
}

static void simplex_add(simplex* s, const tb_vec2* pa, const tb_vec2* pb, int ia, int ib) {
  simplex_vertex* v = &s->v[s->count++];
  v->ia = ia;
  v->ib = ib;
  v->wa = pa[ia];
  v->wb = pb[ib];
  v->w = tb_sub(v->wb, v->wa);
  v->a = 1.0f;
}

static bool simplex_has(const simplex* s, int ia, int ib) {
  for (int i = 0; i < s->count; ++i)
    if (s->v[i].ia == ia && s->v[i].ib == ib) return true;
  return false;
}

static tb_vec2 simplex_point(const simplex* s) {
  tb_vec2 p = {0.0f, 0.0f};
  for (int i = 0; i < s->count; ++i) p = tb_mul_add(p, s->v[i].a, s->v[i].w);
  return p;
}

/* Closest point to x of segment v[i]-v[j]; the simplex becomes that support set.
 * With y = w - x and e = y_j - y_i, the closest point is y_i + u e with
 * u = -y_i.e / e.e, so the unnormalised weights are (y_j.e, -y_i.e): a weight
 * <= 0 means x lies beyond the other end (its Voronoi region). */
static void solve_edge(simplex* s, int i, int j, tb_vec2 x) {
  simplex_vertex vi = s->v[i], vj = s->v[j];
  tb_vec2 yi = tb_sub(vi.w, x), yj = tb_sub(vj.w, x);
  tb_vec2 e = tb_sub(yj, yi);
  float ui = tb_dot(yj, e), uj = -tb_dot(yi, e);
  if (uj <= 0.0f) {
    s->v[0] = vi;
    s->v[0].a = 1.0f;
    s->count = 1;
  } else if (ui <= 0.0f) {
    s->v[0] = vj;
    s->v[0].a = 1.0f;
    s->count = 1;
  } else {
    float inv = 1.0f / (ui + uj);
    s->v[0] = vi;
    s->v[1] = vj;
    s->v[0].a = ui * inv;
    s->v[1].a = uj * inv;
    s->count = 2;
  }
}

static void keep_vertex(simplex* s, int i) {
  s->v[0] = s->v[i];
  s->v[0].a = 1.0f;
  s->count = 1;
}

/* Closest point to x of the triangle, by its Voronoi regions: vertices, then
 * edges (outside the edge: the signed area of x with the edge has the opposite
 * sign of the triangle's), else the interior, weighted by the sub-areas. */
static void solve_triangle(simplex* s, tb_vec2 x) {
  tb_vec2 y1 = tb_sub(s->v[0].w, x), y2 = tb_sub(s->v[1].w, x), y3 = tb_sub(s->v[2].w, x);
  tb_vec2 e12 = tb_sub(y2, y1), e13 = tb_sub(y3, y1), e23 = tb_sub(y3, y2);
  float u12 = tb_dot(y2, e12), v12 = -tb_dot(y1, e12);
  float u13 = tb_dot(y3, e13), v13 = -tb_dot(y1, e13);
  float u23 = tb_dot(y3, e23), v23 = -tb_dot(y2, e23);
  float area = tb_cross(e12, e13);
  float t1 = area * tb_cross(y2, y3), t2 = area * tb_cross(y3, y1), t3 = area * tb_cross(y1, y2);

  if (v12 <= 0.0f && v13 <= 0.0f) {
    keep_vertex(s, 0);
  } else if (u12 > 0.0f && v12 > 0.0f && t3 <= 0.0f) {
    solve_edge(s, 0, 1, x);
  } else if (u13 > 0.0f && v13 > 0.0f && t2 <= 0.0f) {
    solve_edge(s, 0, 2, x);
  } else if (u12 <= 0.0f && v23 <= 0.0f) {
    keep_vertex(s, 1);
  } else if (u13 <= 0.0f && u23 <= 0.0f) {
    keep_vertex(s, 2);
  } else if (u23 > 0.0f && v23 > 0.0f && t1 <= 0.0f) {
    solve_edge(s, 1, 2, x);
  } else {
    float sum = t1 + t2 + t3;
    if (sum > 0.0f) {
      float inv = 1.0f / sum;
      s->v[0].a = t1 * inv;
      s->v[1].a = t2 * inv;
      s->v[2].a = t3 * inv;
      return;
    }
    /* Rounding left no region (a sliver triangle): keep the best edge. */
    simplex best = *s;
    float best_dsq = FLT_MAX;
    static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k) {
      simplex trial = *s;
      solve_edge(&trial, pairs[k][0], pairs[k][1], x);
      float dsq = tb_distance_sq(simplex_point(&trial), x);
      if (dsq < best_dsq) {
        best_dsq = dsq;
        best = trial;
      }
    }
    *s = best;
  }
}

/* Reduce the simplex to the support set of its closest point to x and return
 * that point (in Minkowski space). */
static tb_vec2 simplex_solve(simplex* s, tb_vec2 x) {
  if (s->count == 2)
    solve_edge(s, 0, 1, x);
  else if (s->count == 3)
    solve_triangle(s, x);
  else
    s->v[0].a = 1.0f;
  return simplex_point(s);
}

/* The direction from the simplex towards x. For an edge it is the edge's normal
 * rather than x - closest, which loses its direction as the distance shrinks.
 * Zero when x lies on the simplex. */
static tb_vec2 search_direction(const simplex* s, tb_vec2 x) {
  if (s->count == 1) return tb_sub(x, s->v[0].w);
  tb_vec2 e = tb_sub(s->v[1].w, s->v[0].w);
  float side = tb_cross(e, tb_sub(x, s->v[0].w));
  if (side > 0.0f) return tb_left_perp(e);
  if (side < 0.0f) return tb_right_perp(e);
  return (tb_vec2){0.0f, 0.0f};
}

/* Distance from x to the solved simplex, and the unit direction from the simplex
 * towards x. For an edge both come from the edge's normal: x - closest has an
 * absolute error of ~eps |x|, so near the edge its direction is poor, and a tilt
 * of the support plane by an angle moves the edge's far end by length * angle. */
static float simplex_separation(const simplex* s, tb_vec2 x, tb_vec2* dir) {
  *dir = (tb_vec2){0.0f, 0.0f};
  if (s->count == 3) return 0.0f;
  *dir = tb_normalize(search_direction(s, x));
  if (s->count == 1) return tb_length(tb_sub(x, s->v[0].w));
  return tb_dot(tb_sub(x, s->v[0].w), *dir);
}

static void witness_points(const simplex* s, tb_vec2* pa, tb_vec2* pb) {
  tb_vec2 a = {0.0f, 0.0f}, b = {0.0f, 0.0f};
  for (int i = 0; i < s->count; ++i) {
    a = tb_mul_add(a, s->v[i].a, s->v[i].wa);
    b = tb_mul_add(b, s->v[i].a, s->v[i].wb);
  }
  *pa = a;
  *pb = b;
}

/* -------------------------------------------------------------------- GJK -- */

typedef struct core_distance {
  tb_vec2 pa, pb; /* closest points of the cores */
  tb_vec2 normal; /* unit, A to B; zero when the cores touch or overlap */
  float distance; /* of the cores */
  int iterations;
  int count;
} core_distance;

/* GJK between point sets pa (count na) and pb (count nb), both in one frame. */
static core_distance gjk(const tb_vec2* pa, int na, const tb_vec2* pb, int nb, tb_simplex_cache* cache) {
  simplex s;
  s.count = 0;
  if (cache != NULL && cache->count >= 1 && cache->count <= 3) {
    for (int i = 0; i < cache->count; ++i) {
      int ia = cache->index_a[i], ib = cache->index_b[i];
      if (ia >= na || ib >= nb) {
        s.count = 0; /* stale cache (the proxies changed): cold start */
        break;
      }
      simplex_add(&s, pa, pb, ia, ib);
    }
  }
  if (s.count == 0) simplex_add(&s, pa, pb, 0, 0);

  const tb_vec2 origin = {0.0f, 0.0f};
  tb_vec2 closest = simplex_solve(&s, origin);
  float dist_sq = tb_length_sq(closest);
  int iterations = 0;
  while (iterations < GJK_MAX_ITERATIONS && s.count < 3) {
    tb_vec2 d = search_direction(&s, origin);
    if (d.x == 0.0f && d.y == 0.0f) break; /* the origin is on the simplex: cores touch */
    int ia = support(pa, na, tb_neg(d)), ib = support(pb, nb, d);
    ++iterations;
    if (simplex_has(&s, ia, ib)) break; /* nothing further in direction d: converged */
    simplex saved = s;
    simplex_add(&s, pa, pb, ia, ib);
    tb_vec2 c = simplex_solve(&s, origin);
    float csq = tb_length_sq(c);
    /* The distance must fall at every step; if rounding stalls it, the previous
     * simplex is as good an answer and stopping here rules out cycling. */
    if (!(csq < dist_sq)) {
      s = saved;
      break;
    }
    closest = c;
    dist_sq = csq;
  }

  core_distance out;
  witness_points(&s, &out.pa, &out.pb);
  out.iterations = iterations;
  out.count = s.count;
  out.distance = tb_length(tb_sub(out.pb, out.pa));
  out.normal = (tb_vec2){0.0f, 0.0f};
  if (s.count < 3 && out.distance > 0.0f) {
    /* Normal from A to B: the direction of the closest point of B - A. */
    out.normal = tb_normalize(tb_neg(search_direction(&s, origin)));
  } else {
    out.distance = 0.0f;
  }
  if (cache != NULL) {
    cache->count = (uint8_t)s.count;
    for (int i = 0; i < s.count; ++i) {
      cache->index_a[i] = (uint8_t)s.v[i].ia;
      cache->index_b[i] = (uint8_t)s.v[i].ib;
    }
  }
  return out;
}

/* B's points in A's frame: rotation qA^T qB, translation qA^T (pB - pA). The
 * difference pB - pA is taken first so that large world coordinates cancel. */
static void points_in_frame_of(tb_transform xfa, tb_transform xfb, const tb_shape_proxy* b, tb_vec2* out) {
  tb_rot q = {xfa.q.c * xfb.q.c + xfa.q.s * xfb.q.s, xfa.q.c * xfb.q.s - xfa.q.s * xfb.q.c};
  tb_vec2 p = tb_inv_rotate(xfa.q, tb_sub(xfb.p, xfa.p));
  for (int i = 0; i < b->count; ++i) out[i] = tb_add(p, tb_rotate(q, b->points[i]));
}

static void distance_miss(tb_distance_output* out) {
  memset(out, 0, sizeof *out);
  out->distance = FLT_MAX;
}

tb_result tb_shape_distance(const tb_distance_input* input, tb_simplex_cache* cache, tb_distance_output* output) {
  if (output == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_shape_distance: output is NULL");
  distance_miss(output);
  if (input == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_shape_distance: input is NULL");
  if (!proxy_ok(&input->proxy_a) || !proxy_ok(&input->proxy_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_shape_distance: bad proxy (count, radius or points)");
  if (!tb_transform_ok(input->xf_a) || !tb_transform_ok(input->xf_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_shape_distance: transform is not finite or not a rotation");

  const tb_shape_proxy* a = &input->proxy_a;
  const tb_shape_proxy* b = &input->proxy_b;
  tb_vec2 pb[TB_MAX_POLYGON_VERTICES];
  points_in_frame_of(input->xf_a, input->xf_b, b, pb);
  core_distance c = gjk(a->points, a->count, pb, b->count, cache);

  float ra = a->radius, rb = b->radius;
  tb_vec2 pa_local = c.pa, pb_local = c.pb;
  float distance = 0.0f;
  if (c.count < 3 && c.distance > 0.0f) {
    /* Move the core points out to the rounded surfaces along the normal. */
    pa_local = tb_mul_add(c.pa, ra, c.normal);
    pb_local = tb_mul_add(c.pb, -rb, c.normal);
    if (c.distance > ra + rb) {
      distance = c.distance - ra - rb;
    } else {
      pa_local = tb_lerp(pa_local, pb_local, 0.5f);
      pb_local = pa_local;
    }
  } else {
    pb_local = pa_local; /* the cores share this point (up to rounding) */
  }
  output->point_a = tb_transform_point(input->xf_a, pa_local);
  output->point_b = tb_transform_point(input->xf_a, pb_local);
  output->normal = tb_rotate(input->xf_a.q, c.normal);
  output->distance = distance;
  output->iterations = c.iterations;
  output->simplex_count = c.count;
  return TB_OK;
}

/* ------------------------------------------------------------ shape cast -- */

static void cast_miss(tb_cast_output* out) { memset(out, 0, sizeof *out); }

/* GJK ray cast in Minkowski space. B at fraction l is B + l r, so the shapes
 * touch when the point x = -l r comes within R = ra + rb of the core set
 * M = B - A. Each step takes the support point w of M towards x; if x is more
 * than R above the plane through w (normal v, from M towards x), x moves along
 * -r onto that plane lifted by R, which is safe: nothing of M lies above it.
 * For a rounded shape this is Newton's method on the distance along the ray. */
tb_result tb_shape_cast(const tb_shape_cast_input* input, tb_cast_output* output) {
  if (output == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_shape_cast: output is NULL");
  cast_miss(output);
  if (input == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_shape_cast: input is NULL");
  if (!proxy_ok(&input->proxy_a) || !proxy_ok(&input->proxy_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_shape_cast: bad proxy (count, radius or points)");
  if (!tb_transform_ok(input->xf_a) || !tb_transform_ok(input->xf_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_shape_cast: transform is not finite or not a rotation");
  if (!tb_point_ok(input->translation_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_shape_cast: translation is not finite or too long");

  const tb_shape_proxy* a = &input->proxy_a;
  const tb_shape_proxy* b = &input->proxy_b;
  const tb_vec2* pa = a->points;
  tb_vec2 pb[TB_MAX_POLYGON_VERTICES];
  points_in_frame_of(input->xf_a, input->xf_b, b, pb);
  tb_vec2 r = tb_inv_rotate(input->xf_a.q, input->translation_b);
  const float radius = a->radius + b->radius;
  const float tol = tb_meters(TB_CAST_TOLERANCE);

  simplex s;
  s.count = 0;
  simplex_add(&s, pa, pb, 0, 0);
  float lambda = 0.0f;
  tb_vec2 x = {0.0f, 0.0f};
  tb_vec2 dir;
  float dist = simplex_separation(&s, x, &dir);
  tb_vec2 plane_normal = {0.0f, 0.0f}; /* dir at the last advance */
  int iterations = 0;
  for (;;) {
    if (s.count == 3 || (dir.x == 0.0f && dir.y == 0.0f)) break; /* x on the core set */
    if (iterations == CAST_MAX_ITERATIONS) break;                /* lambda is still a safe lower bound */
    ++iterations;
    int ia = support(pa, a->count, tb_neg(dir)), ib = support(pb, b->count, dir);
    tb_vec2 w = tb_sub(pb[ib], pa[ia]);
    float h = tb_dot(tb_sub(x, w), dir); /* height of x above the support plane */
    /* Done when within tolerance of contact and the simplex is the feature of
     * M nearest x: then its plane is the support plane (h = dist). Stopping on
     * the distance alone can leave a chord of M whose normal is meaningless. */
    if (dist <= radius + tol && dist - h <= 0.1f * tol) break;
    bool advanced = false;
    if (h > radius) {
      float speed = tb_dot(r, dir);      /* approach to the plane per unit fraction */
      if (!(speed > 0.0f)) return TB_OK; /* moving away or parallel: never touches */
      lambda += (h - radius) / speed;
      if (!(lambda <= 1.0f)) return TB_OK; /* touches beyond the end of the cast */
      x = tb_scale(-lambda, r);
      plane_normal = dir;
      advanced = true;
    }
    if (!simplex_has(&s, ia, ib)) {
      simplex_add(&s, pa, pb, ia, ib);
    } else if (!advanced) {
      break; /* no new support point and x did not move: converged (dist ~ R) */
    }
    simplex_solve(&s, x);
    dist = simplex_separation(&s, x, &dir);
  }

  tb_vec2 core_a, core_b, n;
  if (lambda == 0.0f) {
    /* In contact from the start: the loop stopped as soon as the shapes were
     * within reach, so ask GJK whether the cores themselves overlap. */
    core_distance c = gjk(pa, a->count, pb, b->count, NULL);
    core_a = c.pa;
    n = c.normal;
  } else {
    witness_points(&s, &core_a, &core_b);
    /* Normal A to B is -dir. Near contact of bare cores x sits on the core
     * set up to rounding: an edge's normal is still exact but its side is not,
     * and between two vertices dir is noise, so the last plane decides. */
    if (s.count == 2 && (dir.x != 0.0f || dir.y != 0.0f))
      n = tb_dot(dir, plane_normal) >= 0.0f ? tb_neg(dir) : dir;
    else
      n = tb_neg(dist > tol ? dir : plane_normal);
  }
  output->point = tb_transform_point(input->xf_a, tb_mul_add(core_a, a->radius, n));
  output->normal = tb_rotate(input->xf_a.q, n);
  output->fraction = lambda;
  output->iterations = iterations;
  output->hit = true;
  return TB_OK;
}

/* --------------------------------------------------------- time of impact -- */

tb_transform tb_sweep_transform(const tb_sweep* sweep, float t) {
  tb_transform xf;
  tb_vec2 c = tb_lerp(sweep->c1, sweep->c2, t);
  xf.q = tb_make_rot(sweep->a1 + t * (sweep->a2 - sweep->a1));
  xf.p = tb_sub(c, tb_rotate(xf.q, sweep->local_center));
  return xf;
}

/* Largest distance of a proxy point from the centre of mass: the radius of the
 * circle any core point moves on when the body turns. */
static float sweep_reach(const tb_shape_proxy* p, tb_vec2 local_center) {
  float r2 = 0.0f;
  for (int i = 0; i < p->count; ++i) r2 = tb_maxf(r2, tb_distance_sq(p->points[i], local_center));
  return sqrtf(r2);
}

/* Conservative advancement. At time t let n be the unit normal between the cores
 * (A to B) and g the gap. Along the fixed axis n the gap can close no faster than
 *   mu = (vA - vB).n + |wA| reachA + |wB| reachB
 * (a point at distance rho from its centre of mass moves at most |w| rho by
 * rotation), and the separation along any fixed axis is a lower bound of the
 * distance. So the gap stays >= target until t + (g - target) / mu, which is the
 * next t; mu <= 0 means the shapes cannot close in at all. */
tb_result tb_time_of_impact(const tb_toi_input* input, tb_toi_output* output) {
  if (output == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_time_of_impact: output is NULL");
  output->state = TB_TOI_FAILED;
  output->fraction = 0.0f;
  output->iterations = 0;
  if (input == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_time_of_impact: input is NULL");
  const tb_shape_proxy* a = &input->proxy_a;
  const tb_shape_proxy* b = &input->proxy_b;
  if (!proxy_ok(a) || !proxy_ok(b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_time_of_impact: bad proxy (count, radius or points)");
  if (!sweep_ok(&input->sweep_a) || !sweep_ok(&input->sweep_b))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_time_of_impact: sweep is not finite or out of range");
  const float radius = a->radius + b->radius;
  const float target = input->target, tol = input->tolerance;
  if (!(input->max_fraction >= 0.0f && input->max_fraction <= 1.0f))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_time_of_impact: max_fraction must be in [0, 1]");
  if (!tb_length_ok(target) || !(target + radius >= 0.0f))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                   "tb_time_of_impact: target must be finite and >= -(radius_a + radius_b)");
  if (!(tol > 0.0f) || !tb_length_ok(tol))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_time_of_impact: tolerance must be > 0 and finite");

  float start_distance;
  tb_time_of_impact_unchecked(input, output, &start_distance);
  return TB_OK;
}

void tb_time_of_impact_unchecked(const tb_toi_input* input, tb_toi_output* output, float* start_distance) {
  const tb_shape_proxy* a = &input->proxy_a;
  const tb_shape_proxy* b = &input->proxy_b;
  const float radius = a->radius + b->radius;
  const float target = input->target, tol = input->tolerance;
  output->state = TB_TOI_FAILED;
  output->fraction = 0.0f;
  output->iterations = 0;
  const tb_sweep* sa = &input->sweep_a;
  const tb_sweep* sb = &input->sweep_b;
  const tb_vec2 dv = tb_sub(tb_sub(sa->c2, sa->c1), tb_sub(sb->c2, sb->c1));
  const float spin = fabsf(sa->a2 - sa->a1) * sweep_reach(a, sa->local_center) +
                     fabsf(sb->a2 - sb->a1) * sweep_reach(b, sb->local_center);
  const float t_max = input->max_fraction;

  tb_simplex_cache cache = {0};
  tb_vec2 pb[TB_MAX_POLYGON_VERTICES];
  float t = 0.0f, t_safe = 0.0f;
  for (int iter = 1; iter <= TOI_MAX_ITERATIONS; ++iter) {
    output->iterations = iter;
    tb_transform xfa = tb_sweep_transform(sa, t), xfb = tb_sweep_transform(sb, t);
    points_in_frame_of(xfa, xfb, b, pb);
    core_distance c = gjk(a->points, a->count, pb, b->count, &cache);
    if (iter == 1) *start_distance = c.distance;
    float gap = c.distance - radius;
    if (gap < target + tol) {
      if (gap >= target - tol) {
        output->state = TB_TOI_HIT;
        output->fraction = t;
      } else if (t == 0.0f) {
        output->state = TB_TOI_OVERLAPPED;
        output->fraction = 0.0f;
      } else {
        /* Stepped past the target: only rounding can do this. */
        output->state = TB_TOI_FAILED;
        output->fraction = t_safe;
      }
      return;
    }
    tb_vec2 n = tb_rotate(xfa.q, c.normal);
    float mu = tb_dot(dv, n) + spin;
    if (!(mu > 0.0f)) break;
    t_safe = t;
    t += (gap - target) / mu;
    if (!(t < t_max)) break; /* gap >= target all the way to t_max */
    if (iter == TOI_MAX_ITERATIONS) {
      output->state = TB_TOI_FAILED;
      output->fraction = t;
      return;
    }
  }
  output->state = TB_TOI_SEPARATED;
  output->fraction = t_max;
}

/* ------------------------------------------------------------- ray casts -- */

/* A ray in a shape's frame: origin o, translation d, hit fraction and normal. */
/* The ray in a shape's frame. ray_begin fills it on every path that reads it;
 * its callers still zero it first, since -O3 cannot see that. */
typedef struct local_ray {
  tb_vec2 o, d;
  float max_fraction;
} local_ray;

typedef struct local_hit {
  float fraction;
  tb_vec2 normal;
} local_hit;

/* Entry of the ray into the disc (c, r); the origin must not be inside. Uses the
 * closest approach of the line to the centre rather than the textbook quadratic,
 * whose constant term |o - c|^2 - r^2 cancels badly for distant origins. */
static bool ray_disc(const local_ray* ray, tb_vec2 c, float r, float max_fraction, local_hit* hit) {
  float len = tb_length(ray->d);
  if (!(len > 0.0f) || !(r > 0.0f)) return false;
  tb_vec2 u = tb_scale(1.0f / len, ray->d);
  tb_vec2 s = tb_sub(c, ray->o);
  float tc = tb_dot(s, u);              /* along the ray to the closest approach */
  tb_vec2 perp = tb_mul_add(s, -tc, u); /* centre off the line */
  float h2 = r * r - tb_length_sq(perp);
  if (h2 < 0.0f) return false;
  float entry = tc - sqrtf(h2);
  if (entry < 0.0f) return false; /* behind the origin, or the origin is inside */
  float fraction = entry / len;
  if (fraction > max_fraction) return false;
  hit->fraction = fraction;
  hit->normal = tb_normalize(tb_mul_add(tb_neg(s), entry, u));
  return true;
}

/* Squared distance from p to the convex core (1 point, 2 points, or a CCW
 * polygon with its outward normals); 0 inside. */
static float core_distance_sq(const tb_vec2* v, const tb_vec2* normals, int n, tb_vec2 p) {
  if (n == 1) return tb_distance_sq(p, v[0]);
  if (n >= 3) {
    bool inside = true;
    for (int i = 0; i < n && inside; ++i) inside = tb_dot(normals[i], tb_sub(p, v[i])) <= 0.0f;
    if (inside) return 0.0f;
  }
  float best = FLT_MAX;
  int edges = n == 2 ? 1 : n;
  for (int i = 0; i < edges; ++i) {
    tb_vec2 a = v[i], b = v[(i + 1) % n];
    tb_vec2 q = tb_lerp(a, b, point_segment_fraction(p, a, b));
    best = tb_minf(best, tb_distance_sq(p, q));
  }
  return best;
}

/* A rounded core (n points, outward edge normals, radius r > 0). Its boundary is
 * made of the edges pushed out by r and arcs of the vertex discs, and every disc
 * lies inside the shape, so from an outside origin the first of the disc entries
 * and crossings of the pushed-out edges is where the ray enters. A capsule is the
 * two-point case, with edges 0-1 and 1-0. */
static bool ray_rounded(const local_ray* ray, const tb_vec2* v, const tb_vec2* normals, int n, float r,
                        local_hit* hit) {
  if (core_distance_sq(v, normals, n, ray->o) < r * r) return false; /* starts inside */
  bool found = false;
  float best = ray->max_fraction;
  for (int i = 0; i < n; ++i) {
    local_hit h;
    if (ray_disc(ray, v[i], r, best, &h)) {
      *hit = h;
      best = h.fraction;
      found = true;
    }
  }
  for (int i = 0; i < n; ++i) {
    tb_vec2 nrm = normals[i];
    float denom = tb_dot(nrm, ray->d);
    if (!(denom < 0.0f)) continue; /* only entering through the outer side */
    tb_vec2 a = tb_mul_add(v[i], r, nrm), b = tb_mul_add(v[(i + 1) % n], r, nrm);
    float t = tb_dot(nrm, tb_sub(a, ray->o)) / denom;
    if (t < 0.0f || t > best) continue;
    tb_vec2 e = tb_sub(b, a);
    float s = tb_dot(tb_sub(tb_mul_add(ray->o, t, ray->d), a), e);
    if (s < 0.0f || s > tb_dot(e, e)) continue;
    hit->fraction = t;
    hit->normal = nrm;
    best = t;
    found = true;
  }
  return found;
}

/* A sharp convex polygon: clip the ray's interval [0, max] by each edge's half
 * plane (Cyrus-Beck). The entry is the last entering plane; an origin inside
 * every plane has no entering plane and reports no hit. */
static bool ray_polygon(const local_ray* ray, const tb_vec2* v, const tb_vec2* normals, int n, local_hit* hit) {
  float lower = 0.0f, upper = ray->max_fraction;
  int entry = -1;
  for (int i = 0; i < n; ++i) {
    /* Inside edge i where dot(n, o + t d - v) <= 0, i.e. t * denom <= num. */
    float num = tb_dot(normals[i], tb_sub(v[i], ray->o));
    float denom = tb_dot(normals[i], ray->d);
    if (denom == 0.0f) {
      if (num < 0.0f) return false; /* parallel and outside */
    } else if (denom < 0.0f) {
      if (num < lower * denom) { /* t > num/denom: the interval starts later */
        lower = num / denom;
        entry = i;
      }
    } else if (num < upper * denom) {
      upper = num / denom;
    }
    if (upper < lower) return false;
  }
  if (entry < 0) return false;
  hit->fraction = lower;
  hit->normal = normals[entry];
  return true;
}

/* Two-sided segment: intersection with the line, normal facing the origin. */
static bool ray_segment(const local_ray* ray, tb_vec2 p1, tb_vec2 p2, local_hit* hit) {
  tb_vec2 e = tb_sub(p2, p1);
  tb_vec2 nrm = tb_normalize(tb_right_perp(e));
  float denom = tb_dot(nrm, ray->d);
  if (denom == 0.0f) return false;
  float num = tb_dot(nrm, tb_sub(p1, ray->o));
  float t = num / denom;
  if (t < 0.0f || t > ray->max_fraction) return false;
  float s = tb_dot(tb_sub(tb_mul_add(ray->o, t, ray->d), p1), e);
  if (s < 0.0f || s > tb_dot(e, e)) return false;
  hit->fraction = t;
  hit->normal = num > 0.0f ? tb_neg(nrm) : nrm;
  return true;
}

/* Validates the ray and moves it into the shape's frame. */
static tb_result ray_begin(const char* fn, const tb_ray_input* ray, const void* shape, tb_transform xf,
                           tb_cast_output* out, local_ray* local) {
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: output is NULL", fn);
  cast_miss(out);
  if (ray == NULL || shape == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: ray or shape is NULL", fn);
  if (!tb_point_ok(ray->origin) || !tb_point_ok(ray->translation))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: ray is not finite or beyond TB_MAX_LENGTH", fn);
  if (!(ray->max_fraction >= 0.0f) || !tb_value_ok(ray->max_fraction))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: max_fraction must be >= 0 and finite", fn);
  if (!tb_transform_ok(xf))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: transform is not finite or not a rotation", fn);
  local->o = tb_inv_transform_point(xf, ray->origin);
  local->d = tb_inv_rotate(xf.q, ray->translation);
  local->max_fraction = ray->max_fraction;
  return TB_OK;
}

/* The world point comes from the world ray, so it does not pick up the rounding
 * of the round trip through the shape's frame. */
static void ray_finish(const tb_ray_input* ray, tb_transform xf, const local_hit* h, tb_cast_output* out) {
  out->hit = true;
  out->fraction = h->fraction;
  out->point = tb_mul_add(ray->origin, h->fraction, ray->translation);
  out->normal = tb_rotate(xf.q, h->normal);
}

tb_result tb_ray_cast_circle(const tb_ray_input* ray, const tb_circle* circle, tb_transform xf, tb_cast_output* out) {
  local_ray r = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f};
  tb_result res = ray_begin("tb_ray_cast_circle", ray, circle, xf, out, &r);
  if (res != TB_OK) return res;
  const char* why = tb_check_circle(circle);
  if (why != NULL) return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_ray_cast_circle: %s", why);
  local_hit h;
  if (ray_disc(&r, circle->center, circle->radius, r.max_fraction, &h)) ray_finish(ray, xf, &h, out);
  return TB_OK;
}

tb_result tb_ray_cast_capsule(const tb_ray_input* ray, const tb_capsule* capsule, tb_transform xf,
                              tb_cast_output* out) {
  local_ray r = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f};
  tb_result res = ray_begin("tb_ray_cast_capsule", ray, capsule, xf, out, &r);
  if (res != TB_OK) return res;
  const char* why = tb_check_capsule(capsule);
  if (why != NULL) return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_ray_cast_capsule: %s", why);
  tb_vec2 v[2] = {capsule->center1, capsule->center2};
  tb_vec2 nrm = tb_normalize(tb_right_perp(tb_sub(v[1], v[0])));
  tb_vec2 normals[2] = {nrm, tb_neg(nrm)};
  local_hit h;
  if (ray_rounded(&r, v, normals, 2, capsule->radius, &h)) ray_finish(ray, xf, &h, out);
  return TB_OK;
}

tb_result tb_ray_cast_segment(const tb_ray_input* ray, const tb_segment* segment, tb_transform xf,
                              tb_cast_output* out) {
  local_ray r = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f};
  tb_result res = ray_begin("tb_ray_cast_segment", ray, segment, xf, out, &r);
  if (res != TB_OK) return res;
  const char* why = tb_check_segment(segment);
  if (why != NULL) return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_ray_cast_segment: %s", why);
  local_hit h;
  if (ray_segment(&r, segment->point1, segment->point2, &h)) ray_finish(ray, xf, &h, out);
  return TB_OK;
}

tb_result tb_ray_cast_polygon(const tb_ray_input* ray, const tb_polygon* polygon, tb_transform xf,
                              tb_cast_output* out) {
  local_ray r = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f};
  tb_result res = ray_begin("tb_ray_cast_polygon", ray, polygon, xf, out, &r);
  if (res != TB_OK) return res;
  const char* why = tb_check_polygon(polygon);
  if (why != NULL) return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_ray_cast_polygon: %s", why);
  local_hit h;
  bool hit = polygon->radius > 0.0f
                 ? ray_rounded(&r, polygon->vertices, polygon->normals, polygon->count, polygon->radius, &h)
                 : ray_polygon(&r, polygon->vertices, polygon->normals, polygon->count, &h);
  if (hit) ray_finish(ray, xf, &h, out);
  return TB_OK;
}
