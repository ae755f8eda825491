/* Reference suite of the narrow phase: tumble's contact manifolds against Box2D
 * 2.4.1 on random configurations of every pair Box2D has (circle-circle,
 * polygon-circle, polygon-polygon, edge-circle, edge-polygon).
 *
 * Same geometry in both engines. Box2D's polygons and edges carry a skin of
 * b2_polygonRadius = 0.01 m around their core, so the tumble side is built with
 * the same surfaces: polygons of radius 0.01, and for an edge (tumble's segment
 * has no radius) either a capsule of radius 0.01, or the bare segment with the
 * skin moved onto the other shape (circle radius + 0.01, polygon radius 0.02).
 * Moving the skin keeps normals and separations but moves the surfaces: Box2D's
 * point (midway) then lies 0.01 m further along the normal than tumble's.
 *
 * Every configuration is put in exactly one class, decided from the geometry in
 * double before the results are looked at (except where noted). Deliberate
 * differences, each its own class and counted:
 * - SPECULATIVE: the skinned shapes do not touch by Box2D's own test (its
 *   separating-axis or distance test exceeds the radii). Box2D reports nothing;
 *   tumble may report speculative points, whose separations must then be >= 0
 *   (within 1e-5) and below TB_SPECULATIVE_DISTANCE. Checked.
 * - NEAR: within 1e-5 m of a decision threshold of either engine (touching, the
 *   0.1 * linear slop corner tolerance); float rounding may go either way.
 * - TIE (polygons): the reference face. Box2D keeps A's face unless B's is
 *   better by 0.1 * b2_linearSlop; tumble takes the strictly better one, so that
 *   swapping the shapes mirrors the manifold. Between the two rules the faces
 *   differ, and so may normals and points.
 * - HYSTERESIS (edge-polygon): Box2D keeps the edge's normal unless the polygon's
 *   face is better by its relative (0.98) and absolute (0.001 m) tolerances;
 *   tumble again takes the better one.
 * - CORNER: the cores are apart (by more than tumble's 0.0005 m tolerance) and
 *   their closest features are two vertices, so the skinned corners are rounded.
 *   Box2D 2.4.1 uses a face normal there, whose separation is not the distance
 *   of the rounded shapes (more overlap when the deepest vertex is kept, less
 *   when its clipping cuts it off); tumble joins the two vertices. Checked:
 *   tumble's smallest separation is the exact one (core distance - radii, in
 *   double, within 1e-4), or tumble reports nothing when that is beyond the
 *   speculative distance.
 * - SIDE (polygons): Box2D clips the incident edge against its reference face's
 *   side planes pushed out by the radii (0.02 m); tumble clips at the core face,
 *   since past it the rounded surface curves away. An incident vertex in that
 *   0.02 m band is kept whole by Box2D and cut by tumble, which moves the point
 *   and its separation. Classified from Box2D's reported reference face.
 *   Checked: the normals agree.
 * - CLIPFAIL: Box2D's separating-axis test accepts but its clipping leaves fewer
 *   than two points, and Box2D reports nothing; tumble falls back to the edges'
 *   closest points (one point). Classified after the fact (Box2D has 0 points).
 * Everything else is COMPARED: same point count, normals within 1e-4, each of
 * Box2D's points matched by a tumble point within 1e-3 m with its separation
 * within 1e-4 m. One difference is allowed there and counted (EXTRA): tumble
 * keeps a second point with separation in [0, TB_SPECULATIVE_DISTANCE) that
 * Box2D drops because it is not touching. Any other disagreement is a MISMATCH
 * and fails the suite. The counts and largest errors are printed on stderr. */
#include <float.h>
#include <stdio.h>
#include <string.h>

#include "../test_util.h"
#include "b2_collide_shim.h"

/* configurations per pair: enough for 10,000 compared with Box2D */
#define CONFIGS 12000
#define POLYGON_CONFIGS 30000
#define EDGE_POLYGON_CONFIGS 17000
#define SKIN 0.01f /* b2_polygonRadius, checked against Box2D in skin_matches_box2d */
#define FUZZ 1e-5  /* m: around a decision threshold, float rounding decides */
#define SLOP 0.005 /* b2_linearSlop and TB_LINEAR_SLOP */

/* ------------------------------------------------------------------ stats -- */

enum {
  EMPTY,
  COMPARED,
  EXTRA,
  SPECULATIVE,
  NEAR,
  CLOSE,
  TIE,
  HYSTERESIS,
  CORNER,
  SIDE,
  CLIPFAIL,
  MISMATCH,
  CLASS_COUNT
};
static const char* const class_names[CLASS_COUNT] = {"empty",  "compared", "extra",    "speculative",
                                                     "near",   "close",    "tie",      "hysteresis",
                                                     "corner", "side",     "clipfail", "MISMATCH"};

typedef struct stats {
  const char* name;
  int configs;
  int count[CLASS_COUNT];
  double max_normal, max_sep, max_point;
} stats;

static void print_stats(const stats* s) {
  fprintf(stderr, "%-44s %5d configs: compared %5d (max err: normal %.2e, separation %.2e m, point %.2e m)\n", s->name,
          s->configs, s->count[COMPARED] + s->count[EXTRA], s->max_normal, s->max_sep, s->max_point);
  fprintf(stderr, "%44s", "");
  for (int c = 0; c < CLASS_COUNT; ++c)
    if (s->count[c] > 0 && c != COMPARED) fprintf(stderr, " %s %d", class_names[c], s->count[c]);
  fprintf(stderr, "\n");
}

static void finish(const stats* s) {
  print_stats(s);
  ck_assert_msg(s->count[MISMATCH] == 0, "%s: %d mismatches", s->name, s->count[MISMATCH]);
  ck_assert_int_ge(s->count[COMPARED] + s->count[EXTRA], 10000);
}

static void mismatch(stats* s, int k, const char* why) {
  if (s->count[MISMATCH]++ < 10) fprintf(stderr, "%s #%d: %s\n", s->name, k, why);
}

static double dmax(double a, double b) { return a > b ? a : b; }

/* ------------------------------------------------------------- geometry -- */

static tb_transform xf_make(float x, float y, float angle) {
  return (tb_transform){{x, y}, {cosf(angle), sinf(angle)}};
}

static b2c_transform to_b2c(tb_transform xf) { return (b2c_transform){xf.p.x, xf.p.y, xf.q.c, xf.q.s}; }

static b2c_polygon to_b2c_polygon(const tb_polygon* p) {
  b2c_polygon b;
  memset(&b, 0, sizeof b);
  b.count = p->count;
  for (int i = 0; i < p->count; ++i) {
    b.vertices[i][0] = p->vertices[i].x, b.vertices[i][1] = p->vertices[i].y;
    b.normals[i][0] = p->normals[i].x, b.normals[i][1] = p->normals[i].y;
  }
  b.centroid[0] = p->centroid.x, b.centroid[1] = p->centroid.y;
  return b;
}

/* A core in world coordinates, double: 1 point (circle), 2 (edge: edge 0 runs
 * v0 -> v1 with the right-hand normal, edge 1 back) or a counter-clockwise
 * polygon, with unit edge normals. */
typedef struct dcore {
  double x[8], y[8], nx[8], ny[8];
  int count;
} dcore;

static dcore make_core(const tb_vec2* v, int count, tb_transform xf) {
  dcore c;
  memset(&c, 0, sizeof c);
  c.count = count;
  for (int i = 0; i < count; ++i) {
    c.x[i] = xf.p.x + (double)xf.q.c * v[i].x - (double)xf.q.s * v[i].y;
    c.y[i] = xf.p.y + (double)xf.q.s * v[i].x + (double)xf.q.c * v[i].y;
  }
  for (int i = 0; i < count && count >= 2; ++i) {
    int j = (i + 1) % count;
    double ex = c.x[j] - c.x[i], ey = c.y[j] - c.y[i], l = hypot(ex, ey);
    c.nx[i] = ey / l, c.ny[i] = -ex / l;
  }
  return c;
}

static int edge_count(const dcore* c) { return c->count == 1 ? 0 : c->count; }

static double point_segment_distance(double px, double py, double ax, double ay, double bx, double by, int* vertex) {
  double ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
  double t = ((px - ax) * ex + (py - ay) * ey) / l2;
  *vertex = t <= 0.0 || t >= 1.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return hypot(px - ax - t * ex, py - ay - t * ey);
}

static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int inside(const dcore* p, int i, const dcore* q) {
  if (q->count < 3) return 0;
  for (int k = 0; k < q->count; ++k) {
    int l = (k + 1) % q->count;
    if (orient(q->x[k], q->y[k], q->x[l], q->y[l], p->x[i], p->y[i]) < 0.0) return 0;
  }
  return 1;
}

/* Exact distance between two cores (0 when they intersect); *vertex_pair tells
 * whether the closest features are two vertices. */
static double core_distance(const dcore* a, const dcore* b, int* vertex_pair) {
  *vertex_pair = 0;
  for (int i = 0; i < edge_count(a); ++i)
    for (int j = 0; j < edge_count(b); ++j) {
      int i2 = (i + 1) % a->count, j2 = (j + 1) % b->count;
      double o1 = orient(a->x[i], a->y[i], a->x[i2], a->y[i2], b->x[j], b->y[j]);
      double o2 = orient(a->x[i], a->y[i], a->x[i2], a->y[i2], b->x[j2], b->y[j2]);
      double o3 = orient(b->x[j], b->y[j], b->x[j2], b->y[j2], a->x[i], a->y[i]);
      double o4 = orient(b->x[j], b->y[j], b->x[j2], b->y[j2], a->x[i2], a->y[i2]);
      if (o1 * o2 < 0.0 && o3 * o4 < 0.0) return 0.0;
    }
  if (inside(a, 0, b) || inside(b, 0, a)) return 0.0;
  double d = DBL_MAX;
  for (int pass = 0; pass < 2; ++pass) {
    const dcore* p = pass ? b : a;
    const dcore* q = pass ? a : b;
    for (int i = 0; i < p->count; ++i) {
      if (q->count == 1) {
        double dj = hypot(p->x[i] - q->x[0], p->y[i] - q->y[0]);
        if (dj < d) d = dj, *vertex_pair = 1;
      }
      for (int j = 0; j < edge_count(q); ++j) {
        int j2 = (j + 1) % q->count, v;
        double dj = point_segment_distance(p->x[i], p->y[i], q->x[j], q->y[j], q->x[j2], q->y[j2], &v);
        if (dj < d) d = dj, *vertex_pair = v;
      }
    }
  }
  return d;
}

/* Greatest, over p's edges, of the least separation of q's vertices. */
static double sat(const dcore* p, const dcore* q, int* face) {
  double best = -DBL_MAX;
  for (int i = 0; i < edge_count(p); ++i) {
    double s = DBL_MAX;
    for (int j = 0; j < q->count; ++j) {
      double d = p->nx[i] * (q->x[j] - p->x[i]) + p->ny[i] * (q->y[j] - p->y[i]);
      s = d < s ? d : s;
    }
    if (s > best) best = s, *face = i;
  }
  return best;
}

/* ------------------------------------------------------ configurations -- */

static tb_polygon random_polygon(unsigned* seed) {
  float scale = tbt_rand(seed, 0.1f, 2.0f);
  tb_polygon p;
  for (;;) {
    tb_vec2 pts[8];
    int n = 3 + (int)tbt_rand(seed, 0.0f, 5.99f); /* 3..8: tbt_rand may round up to hi */
    for (int i = 0; i < n; ++i) {
      float a = tbt_rand(seed, 0.0f, 6.2831853f), r = scale * tbt_rand(seed, 0.3f, 1.0f);
      pts[i] = (tb_vec2){0.3f * scale + r * cosf(a), -0.2f * scale + r * sinf(a)};
    }
    if (tb_make_polygon(pts, n, 0.0f, &p) == TB_OK) return p;
  }
}

/* A random placement of core b (given by count body-frame points) against core
 * a (already placed): b's core centre on a's, then moved along a random
 * direction u. The core distance is 0 up to an exit point and increasing after
 * it, so bisection reaches any wanted distance. 45% of the configurations have
 * overlapping cores (anywhere between centred and the exit point; when neither
 * core has area, a core distance within the radii instead), the rest a core
 * distance from 0 to the radii + 0.04 m. */
static tb_transform random_placement(unsigned* seed, const dcore* a, const tb_vec2* b, int count, double radii) {
  float angle = tbt_rand(seed, -3.2f, 3.2f), dir = tbt_rand(seed, -3.2f, 3.2f);
  dcore b0 = make_core(b, count, xf_make(0.0f, 0.0f, angle));
  double ax = 0, ay = 0, bx = 0, by = 0;
  for (int i = 0; i < a->count; ++i) ax += a->x[i] / a->count, ay += a->y[i] / a->count;
  for (int i = 0; i < b0.count; ++i) bx += b0.x[i] / b0.count, by += b0.y[i] / b0.count;
  double ux = cos(dir), uy = sin(dir), u = tbt_rand(seed, 0.0f, 1.0f);
  /* cores without area only overlap where they touch: there overlap the radii */
  int flat = a->count < 3 && count < 3, vv;
  double want = u < 0.45 ? (flat ? u / 0.45 * radii : 0.0) : (u - 0.45) / 0.55 * (radii + 0.04);
  double lo = 0.0, hi = 1.0;
  for (;;) {
    dcore c = make_core(b, count, xf_make((float)(ax - bx + hi * ux), (float)(ay - by + hi * uy), angle));
    if (core_distance(a, &c, &vv) > want) break;
    lo = hi;
    hi *= 2.0;
  }
  for (int k = 0; k < 40; ++k) {
    double mid = 0.5 * (lo + hi);
    dcore c = make_core(b, count, xf_make((float)(ax - bx + mid * ux), (float)(ay - by + mid * uy), angle));
    if (core_distance(a, &c, &vv) > want)
      hi = mid;
    else
      lo = mid;
  }
  double t = u < 0.45 && !flat ? tbt_rand(seed, 0.0f, 1.0f) * lo : lo;
  return xf_make((float)(ax - bx + t * ux), (float)(ay - by + t * uy), angle);
}

static tb_segment random_segment(unsigned* seed) {
  for (;;) {
    tb_segment e = {{tbt_rand(seed, -1.5f, 1.5f), tbt_rand(seed, -1.5f, 1.5f)},
                    {tbt_rand(seed, -1.5f, 1.5f), tbt_rand(seed, -1.5f, 1.5f)}};
    if (hypot(e.point2.x - e.point1.x, e.point2.y - e.point1.y) >= 0.1) return e;
  }
}

static tb_transform random_xf(unsigned* seed) {
  return xf_make(tbt_rand(seed, -5.0f, 5.0f), tbt_rand(seed, -5.0f, 5.0f), tbt_rand(seed, -3.2f, 3.2f));
}

/* ----------------------------------------------------------- comparison -- */

/* tumble's manifold in Box2D's conventions: the normal flipped when the shapes
 * were passed the other way round, the points moved along the normal by shift
 * (where the skin was moved from one shape to the other). */
static tb_manifold as_box2d(tb_manifold m, bool swapped, float shift) {
  if (swapped) m.normal = (tb_vec2){-m.normal.x, -m.normal.y};
  for (int i = 0; i < m.point_count; ++i) {
    m.points[i].point.x += shift * m.normal.x;
    m.points[i].point.y += shift * m.normal.y;
  }
  return m;
}

static bool speculative_only(const tb_manifold* t) {
  for (int i = 0; i < t->point_count; ++i)
    if (!(t->points[i].separation >= -FUZZ && t->points[i].separation < TB_SPECULATIVE_DISTANCE)) return false;
  return true;
}

/* COMPARED (or EXTRA) when the manifolds agree, else MISMATCH. */
static void compare(stats* s, int k, const b2c_manifold* b, const tb_manifold* t) {
  char why[200];
  int extra = t->point_count - b->point_count;
  if (b->point_count == 0 && t->point_count == 0) {
    s->count[EMPTY]++;
    return;
  }
  if (b->point_count == 0 || extra < 0 || extra > 1) {
    snprintf(why, sizeof why, "point count %d, Box2D %d", t->point_count, b->point_count);
    mismatch(s, k, why);
    return;
  }
  double en = hypot(t->normal.x - b->normal[0], t->normal.y - b->normal[1]);
  double ep = 0.0, es = 0.0;
  bool used[2] = {false, false};
  for (int i = 0; i < b->point_count; ++i) {
    int best = -1;
    double bd = DBL_MAX;
    for (int j = 0; j < t->point_count; ++j) {
      double d = hypot(t->points[j].point.x - b->points[i][0], t->points[j].point.y - b->points[i][1]);
      if (!used[j] && d < bd) bd = d, best = j;
    }
    used[best] = true;
    ep = dmax(ep, bd);
    es = dmax(es, fabs(t->points[best].separation - b->separations[i]));
  }
  bool extra_ok = true;
  for (int j = 0; j < t->point_count; ++j)
    if (!used[j]) extra_ok = t->points[j].separation >= -FUZZ;
  if (en > 1e-4 || ep > 1e-3 || es > 1e-4 || !extra_ok) {
    snprintf(
        why, sizeof why,
        "normal (%.6f, %.6f) vs (%.6f, %.6f); point err %.2e, separation err %.2e; counts %d/%d; seps %.5f vs %.5f",
        t->normal.x, t->normal.y, b->normal[0], b->normal[1], ep, es, t->point_count, b->point_count,
        t->points[0].separation, b->separations[0]);
    mismatch(s, k, why);
    return;
  }
  s->count[extra ? EXTRA : COMPARED]++;
  s->max_normal = dmax(s->max_normal, en);
  s->max_point = dmax(s->max_point, ep);
  s->max_sep = dmax(s->max_sep, es);
}

/* Pairs with a circle: one point, decided by the exact gap between the skinned
 * shapes (core distance - radii). When the circle's centre is within 1 cm of a
 * vertex of the other core (or of the other centre), the normal is the
 * direction between two close points, only as good as the rounding of their
 * coordinates over their distance: Box2D subtracts world positions of up to
 * 5 m (rounding ~5e-7 m each, so its normal is off by up to ~1e-6 m / distance,
 * 1e-4 at 1 cm; measured 4e-4 at 1 mm). That is CLOSE, where tumble's normal is
 * checked against the exact (double) one within 5e-7 m / distance instead of
 * against Box2D's, and its separation against the exact one. */
static void classify_round(stats* s, int k, const dcore* a, const dcore* b, double radii, const b2c_manifold* bm,
                           const tb_manifold* t) {
  int vertex_pair;
  double dist = core_distance(a, b, &vertex_pair), gap = dist - radii;
  s->configs++;
  if (vertex_pair && dist < 1e-2 && fabs(gap) > FUZZ) {
    /* the vertex of a closest to b's centre */
    int v = 0;
    for (int i = 1; i < a->count; ++i)
      if (hypot(a->x[i] - b->x[0], a->y[i] - b->y[0]) < hypot(a->x[v] - b->x[0], a->y[v] - b->y[0])) v = i;
    double nx = (b->x[0] - a->x[v]) / dist, ny = (b->y[0] - a->y[v]) / dist;
    if (t->point_count == 1 && hypot(t->normal.x - nx, t->normal.y - ny) * dist < 5e-7 &&
        fabs(t->points[0].separation - gap) < 1e-4)
      s->count[CLOSE]++;
    else
      mismatch(s, k, "close: tumble's normal must be the exact direction up to rounding");
    return;
  }
  if (fabs(gap) <= FUZZ) {
    s->count[NEAR]++;
  } else if (gap > 0.0) {
    if (bm->point_count != 0 || !speculative_only(t))
      mismatch(s, k, "separated: Box2D must report nothing and tumble only speculative points");
    else
      s->count[t->point_count ? SPECULATIVE : EMPTY]++;
  } else {
    compare(s, k, bm, t);
  }
}

START_TEST(skin_matches_box2d) { ck_assert_float_eq(b2c_polygon_radius(), SKIN); }
END_TEST

START_TEST(circles) {
  stats s = {"circle-circle", 0, {0}, 0, 0, 0};
  unsigned seed = 11u;
  for (int k = 0; k < CONFIGS; ++k) {
    tb_circle a = {{tbt_rand(&seed, -0.5f, 0.5f), tbt_rand(&seed, -0.5f, 0.5f)}, tbt_rand(&seed, 0.05f, 1.0f)};
    tb_circle b = {{tbt_rand(&seed, -0.5f, 0.5f), tbt_rand(&seed, -0.5f, 0.5f)}, tbt_rand(&seed, 0.05f, 1.0f)};
    tb_transform xa = random_xf(&seed);
    dcore ca = make_core(&a.center, 1, xa);
    tb_transform xb = random_placement(&seed, &ca, &b.center, 1, a.radius + b.radius);
    dcore cb = make_core(&b.center, 1, xb);
    b2c_manifold bm;
    b2c_collide_circles(a.center.x, a.center.y, a.radius, to_b2c(xa), b.center.x, b.center.y, b.radius, to_b2c(xb),
                        &bm);
    tb_manifold tm = tb_collide_circles(&a, xa, &b, xb);
    classify_round(&s, k, &ca, &cb, a.radius + b.radius, &bm, &tm);
  }
  finish(&s);
}
END_TEST

START_TEST(polygon_and_circle) {
  stats s = {"polygon-circle", 0, {0}, 0, 0, 0};
  unsigned seed = 22u;
  for (int k = 0; k < CONFIGS; ++k) {
    tb_polygon a = random_polygon(&seed);
    a.radius = SKIN;
    tb_circle b = {{tbt_rand(&seed, -0.5f, 0.5f), tbt_rand(&seed, -0.5f, 0.5f)}, tbt_rand(&seed, 0.05f, 1.0f)};
    tb_transform xa = random_xf(&seed);
    dcore ca = make_core(a.vertices, a.count, xa);
    tb_transform xb = random_placement(&seed, &ca, &b.center, 1, SKIN + b.radius);
    dcore cb = make_core(&b.center, 1, xb);
    b2c_polygon pa = to_b2c_polygon(&a);
    b2c_manifold bm;
    b2c_collide_polygon_and_circle(&pa, to_b2c(xa), b.center.x, b.center.y, b.radius, to_b2c(xb), &bm);
    tb_manifold tm = tb_collide_polygon_and_circle(&a, xa, &b, xb);
    classify_round(&s, k, &ca, &cb, SKIN + b.radius, &bm, &tm);
  }
  finish(&s);
}
END_TEST

/* Edge-circle twice: against tumble's segment with the skin moved onto the
 * circle, and against a capsule of radius SKIN (the same surface as Box2D's). */
START_TEST(edge_and_circle) {
  stats s1 = {"edge-circle (segment, circle + skin)", 0, {0}, 0, 0, 0};
  stats s2 = {"edge-circle (capsule of radius skin)", 0, {0}, 0, 0, 0};
  unsigned seed = 33u;
  for (int k = 0; k < CONFIGS; ++k) {
    tb_segment e = random_segment(&seed);
    tb_vec2 ev[2] = {e.point1, e.point2};
    tb_circle b = {{tbt_rand(&seed, -0.5f, 0.5f), tbt_rand(&seed, -0.5f, 0.5f)}, tbt_rand(&seed, 0.05f, 1.0f)};
    tb_transform xa = random_xf(&seed);
    dcore ca = make_core(ev, 2, xa);
    tb_transform xb = random_placement(&seed, &ca, &b.center, 1, SKIN + b.radius);
    dcore cb = make_core(&b.center, 1, xb);
    b2c_manifold bm;
    b2c_collide_edge_and_circle(e.point1.x, e.point1.y, e.point2.x, e.point2.y, to_b2c(xa), b.center.x, b.center.y,
                                b.radius, to_b2c(xb), &bm);
    tb_circle grown = {b.center, b.radius + SKIN};
    tb_manifold t1 = as_box2d(tb_collide_segment_and_circle(&e, xa, &grown, xb), false, SKIN);
    classify_round(&s1, k, &ca, &cb, SKIN + b.radius, &bm, &t1);
    tb_capsule cap = {e.point1, e.point2, SKIN};
    tb_manifold t2 = tb_collide_capsule_and_circle(&cap, xa, &b, xb);
    classify_round(&s2, k, &ca, &cb, SKIN + b.radius, &bm, &t2);
  }
  finish(&s1);
  finish(&s2);
}
END_TEST

/* The clipping of an incident edge against a reference face, in double: the
 * face's tangent coordinate u (0 at its first vertex, len at its second) and
 * the core separation s of the incident edge's two vertices. */
typedef struct clip_frame {
  double ox, oy, nx, ny, len;
  double u[2], s[2];
} clip_frame;

static clip_frame make_clip_frame(const dcore* ref, int f, const dcore* inc, int g) {
  clip_frame c;
  int f2 = (f + 1) % ref->count;
  c.ox = ref->x[f], c.oy = ref->y[f], c.nx = ref->nx[f], c.ny = ref->ny[f];
  c.len = -c.ny * (ref->x[f2] - c.ox) + c.nx * (ref->y[f2] - c.oy);
  for (int e = 0; e < 2; ++e) {
    int j = (g + e) % inc->count;
    c.u[e] = -c.ny * (inc->x[j] - c.ox) + c.nx * (inc->y[j] - c.oy);
    c.s[e] = c.nx * (inc->x[j] - c.ox) + c.ny * (inc->y[j] - c.oy);
  }
  return c;
}

/* Clips the incident edge to u in [lo, hi]: writes up to 2 (u, s) points. */
static int clip_to(const clip_frame* c, double lo, double hi, double u[2], double s[2]) {
  if ((c->u[0] < lo && c->u[1] < lo) || (c->u[0] > hi && c->u[1] > hi)) return 0;
  for (int e = 0; e < 2; ++e) {
    double bound = c->u[e] < lo ? lo : (c->u[e] > hi ? hi : c->u[e]);
    double f = bound == c->u[e] ? 0.0 : (bound - c->u[e]) / (c->u[1 - e] - c->u[e]);
    u[e] = bound;
    s[e] = c->s[e] + f * (c->s[1 - e] - c->s[e]);
  }
  return 2;
}

/* Do the points of m sit at the predicted (u, separation) pairs, in any order? */
static bool points_match(const clip_frame* c, const double* u, const double* sep, int n, const float (*pts)[2],
                         const float* seps, int count) {
  if (n != count) return false;
  for (int i = 0; i < n; ++i) {
    bool found = false;
    for (int j = 0; j < count && !found; ++j) {
      double uj = -c->ny * (pts[j][0] - c->ox) + c->nx * (pts[j][1] - c->oy);
      found = fabs(uj - u[i]) < 1e-3 && fabs(seps[j] - sep[i]) < 1e-4;
    }
    if (!found) return false;
  }
  return true;
}

/* Box2D 2.4.1: side planes pushed out by the radii; points kept while the
 * skins touch (core separation <= radii). */
static bool box2d_clip_matches(const clip_frame* c, double r, const b2c_manifold* m) {
  double u[2], s[2], ku[2], ks[2];
  int n = clip_to(c, -r, c->len + r, u, s), kept = 0;
  for (int i = 0; i < n; ++i)
    if (s[i] <= r) ku[kept] = u[i], ks[kept++] = s[i] - r;
  return points_match(c, ku, ks, kept, m->points, m->separations, m->point_count);
}

/* tumble: side planes at the core face; points kept below the speculative distance. */
static bool tumble_clip_matches(const clip_frame* c, double r, const tb_manifold* m) {
  double u[2], s[2], ku[2], ks[2];
  int n = clip_to(c, 0.0, c->len, u, s), kept = 0;
  for (int i = 0; i < n; ++i)
    if (s[i] - r < TB_SPECULATIVE_DISTANCE) ku[kept] = u[i], ks[kept++] = s[i] - r;
  float pts[2][2] = {{0}}, seps[2] = {0};
  for (int i = 0; i < m->point_count; ++i)
    pts[i][0] = m->points[i].point.x, pts[i][1] = m->points[i].point.y, seps[i] = m->points[i].separation;
  return points_match(c, ku, ks, kept, (const float(*)[2])pts, seps, m->point_count);
}

/* Polygon-like pairs: core a (a polygon, or an edge as a two-vertex core) and
 * polygon core b, total radius 0.02 in both engines. edge_rule selects Box2D's
 * edge-polygon axis rule (hysteresis, no side band) over its polygon-polygon one
 * (A favoured by 0.1 slop, side planes widened by the radii). */
static void classify_polygons(stats* s, int k, const dcore* a, const dcore* b, bool edge_rule, const b2c_manifold* bm,
                              const tb_manifold* tm) {
  const double r = 2.0 * SKIN;
  s->configs++;
  int fa = 0, fb = 0; /* (sat sets them) */
  double sa = sat(a, b, &fa), sb = sat(b, a, &fb), smax = dmax(sa, sb);
  int vertex_pair;
  double dist = core_distance(a, b, &vertex_pair);
  if (fabs(smax - r) <= FUZZ || fabs(smax - 0.1 * SLOP) <= FUZZ || (vertex_pair && fabs(dist - r) <= FUZZ)) {
    s->count[NEAR]++;
    return;
  }
  if (smax > r) { /* Box2D's separating-axis test rejects */
    if (bm->point_count != 0 || !speculative_only(tm))
      mismatch(s, k, "separated: Box2D must report nothing and tumble only speculative points");
    else
      s->count[tm->point_count ? SPECULATIVE : EMPTY]++;
    return;
  }
  /* which shape holds the reference face: tumble takes the better, Box2D biases */
  bool tumble_b = sb > sa;
  bool box2d_b = edge_rule ? sb - r > 0.98 * (sa - r) + 0.001 : sb > sa + 0.1 * SLOP;
  bool box2d_b_lo = edge_rule ? sb - r > 0.98 * (sa - r) + 0.001 - FUZZ : sb > sa + 0.1 * SLOP - FUZZ;
  bool box2d_b_hi = edge_rule ? sb - r > 0.98 * (sa - r) + 0.001 + FUZZ : sb > sa + 0.1 * SLOP + FUZZ;
  if (fabs(sb - sa) <= FUZZ || box2d_b_lo != box2d_b_hi) {
    s->count[NEAR]++;
    return;
  }
  if (tumble_b != box2d_b) {
    /* each engine took the face its own rule picks: Box2D's manifold names the
     * shape, and tumble's normal is that face's (unless rounded corners meet) */
    bool ok = bm->point_count == 0 || (bm->type == B2C_FACE_B) == box2d_b;
    if (tm->point_count > 0 && !(smax > 0.1 * SLOP && vertex_pair)) {
      double nx = tumble_b ? -b->nx[fb] : a->nx[fa], ny = tumble_b ? -b->ny[fb] : a->ny[fa];
      ok = ok && hypot(tm->normal.x - nx, tm->normal.y - ny) < 1e-4;
    }
    if (ok)
      s->count[edge_rule ? HYSTERESIS : TIE]++;
    else
      mismatch(s, k, "reference face: each engine must take the face its rule picks");
    return;
  }
  if (smax > 0.1 * SLOP && vertex_pair) {
    /* rounded corners: tumble's separation is exact. (Near the edge of a face's
     * slab the vertex-vertex normal turns into the face normal; the separation
     * is continuous there but the normal turns fast: a 1e-5 m difference in
     * separation is already 0.03 rad at 2 cm. So no threshold on the gain.) */
    double smin = tm->point_count ? tm->points[0].separation : DBL_MAX, exact = dist - r;
    if (tm->point_count == 2 && tm->points[1].separation < smin) smin = tm->points[1].separation;
    if (fabs(exact - TB_SPECULATIVE_DISTANCE) <= FUZZ)
      s->count[NEAR]++;
    else if (exact > TB_SPECULATIVE_DISTANCE ? tm->point_count == 0 : fabs(smin - exact) < 1e-4)
      s->count[CORNER]++;
    else
      mismatch(s, k, "rounded corner: tumble must give the exact rounded separation");
    return;
  }
  if (bm->point_count == 0) { /* accepted by the axis test, emptied by Box2D's clipping */
    if (tm->point_count == 1)
      s->count[CLIPFAIL]++;
    else
      mismatch(s, k, "Box2D's clipping failed; tumble should fall back to one point");
    return;
  }
  if (!edge_rule) {
    /* Box2D's reference face, read from its manifold, and the incident edge of
     * the other polygon (the most opposed normal) */
    const dcore* ref = bm->type == B2C_FACE_B ? b : a;
    const dcore* inc = bm->type == B2C_FACE_B ? a : b;
    double nx = bm->type == B2C_FACE_B ? -bm->normal[0] : bm->normal[0];
    double ny = bm->type == B2C_FACE_B ? -bm->normal[1] : bm->normal[1];
    int f = 0, g = 0;
    for (int i = 1; i < ref->count; ++i)
      if (ref->nx[i] * nx + ref->ny[i] * ny > ref->nx[f] * nx + ref->ny[f] * ny) f = i;
    for (int j = 1; j < inc->count; ++j)
      if (inc->nx[j] * nx + inc->ny[j] * ny < inc->nx[g] * nx + inc->ny[g] * ny) g = j;
    clip_frame cf = make_clip_frame(ref, f, inc, g);
    if (cf.u[0] < -FUZZ || cf.u[0] > cf.len + FUZZ || cf.u[1] < -FUZZ || cf.u[1] > cf.len + FUZZ) {
      /* the incident edge crosses a side plane: each engine must match its own
       * clipping, Box2D's widened by the radii and keeping points that touch,
       * tumble's at the core face and keeping speculative points */
      bool normals = tm->point_count > 0 && hypot(tm->normal.x - bm->normal[0], tm->normal.y - bm->normal[1]) < 1e-4;
      if (normals && box2d_clip_matches(&cf, r, bm) && tumble_clip_matches(&cf, r, tm))
        s->count[SIDE]++;
      else
        mismatch(s, k, "side planes: each engine must match its own clipping");
      return;
    }
  }
  compare(s, k, bm, tm);
}

START_TEST(polygons) {
  stats s = {"polygon-polygon", 0, {0}, 0, 0, 0};
  unsigned seed = 44u;
  for (int k = 0; k < POLYGON_CONFIGS; ++k) {
    tb_polygon a = random_polygon(&seed), b = random_polygon(&seed);
    a.radius = b.radius = SKIN;
    tb_transform xa = random_xf(&seed);
    dcore ca = make_core(a.vertices, a.count, xa);
    tb_transform xb = random_placement(&seed, &ca, b.vertices, b.count, 2.0 * SKIN);
    dcore cb = make_core(b.vertices, b.count, xb);
    b2c_polygon pa = to_b2c_polygon(&a), pb = to_b2c_polygon(&b);
    b2c_manifold bm;
    b2c_collide_polygons(&pa, to_b2c(xa), &pb, to_b2c(xb), &bm);
    tb_manifold tm = tb_collide_polygons(&a, xa, &b, xb);
    classify_polygons(&s, k, &ca, &cb, false, &bm, &tm);
  }
  finish(&s);
}
END_TEST

/* Edge-polygon twice: tumble's segment against the polygon with both skins
 * (radius 0.02), and tumble's polygon (0.01) against a capsule (0.01) with the
 * shapes passed the other way round. */
START_TEST(edge_and_polygon) {
  stats s1 = {"edge-polygon (segment, polygon + 2 skins)", 0, {0}, 0, 0, 0};
  stats s2 = {"edge-polygon (polygon-capsule, swapped)", 0, {0}, 0, 0, 0};
  unsigned seed = 55u;
  for (int k = 0; k < EDGE_POLYGON_CONFIGS; ++k) {
    tb_segment e = random_segment(&seed);
    tb_vec2 ev[2] = {e.point1, e.point2};
    tb_polygon b = random_polygon(&seed);
    tb_transform xa = random_xf(&seed);
    dcore ca = make_core(ev, 2, xa);
    tb_transform xb = random_placement(&seed, &ca, b.vertices, b.count, 2.0 * SKIN);
    dcore cb = make_core(b.vertices, b.count, xb);
    b2c_polygon pb = to_b2c_polygon(&b);
    b2c_manifold bm;
    b2c_collide_edge_and_polygon(e.point1.x, e.point1.y, e.point2.x, e.point2.y, to_b2c(xa), &pb, to_b2c(xb), &bm);
    tb_polygon b2 = b;
    b2.radius = 2.0f * SKIN;
    tb_manifold t1 = as_box2d(tb_collide_segment_and_polygon(&e, xa, &b2, xb), false, SKIN);
    classify_polygons(&s1, k, &ca, &cb, true, &bm, &t1);
    tb_polygon b1 = b;
    b1.radius = SKIN;
    tb_capsule cap = {e.point1, e.point2, SKIN};
    tb_manifold t2 = as_box2d(tb_collide_polygon_and_capsule(&b1, xb, &cap, xa), true, 0.0f);
    classify_polygons(&s2, k, &ca, &cb, true, &bm, &t2);
  }
  finish(&s1);
  finish(&s2);
}
END_TEST

static Suite* reference_manifold_suite(void) {
  Suite* s = suite_create("reference manifold");
  TCase* tc = tcase_create("box2d");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, skin_matches_box2d);
  tcase_add_test(tc, circles);
  tcase_add_test(tc, polygon_and_circle);
  tcase_add_test(tc, edge_and_circle);
  tcase_add_test(tc, polygons);
  tcase_add_test(tc, edge_and_polygon);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(reference_manifold_suite)
