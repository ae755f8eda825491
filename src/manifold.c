/* Contact manifolds of convex shape pairs (the narrow phase).
 *
 * Every shape is a core (a point, a segment or a convex polygon) inflated by a
 * radius: a circle is a point, a capsule a segment, a polygon may be rounded and
 * a segment has radius 0. Contacts are found between the cores and the radii are
 * taken off the separations, so a rounded shape costs no more than a sharp one.
 *
 * Precision: each pair is computed in the frame of shape A. B is placed by the
 * relative transform inv(xfA) xfB, whose translation is a difference of nearby
 * positions (exact for floats within a factor 2 of each other), so the geometry
 * works with coordinates of the size of the shapes however far from the origin
 * they are; only the final world points pick up the rounding of the world
 * position. Separations and normals keep the precision of the local frame.
 *
 * Points: each lies midway between the two surfaces, separation is the signed
 * gap along the normal (A to B), and a point is kept while its separation is
 * below TB_SPECULATIVE_DISTANCE. Feature ids: see manifold.h. */
#include "manifold.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#include "error.h"
#include "math_internal.h"

/* Below this core gap (m) a direction between two closest points is noise; the
 * face normal of the separating-axis test is used instead. */
#define TB_CORE_GAP_TOLERANCE (0.1f * TB_LINEAR_SLOP)

/* ------------------------------------------------------------- helpers -- */

/* inv(a) * b: the placement of B seen from A's frame. */
static inline tb_transform relative_transform(tb_transform a, tb_transform b) {
  tb_rot q = {a.q.c * b.q.c + a.q.s * b.q.s, a.q.c * b.q.s - a.q.s * b.q.c};
  return (tb_transform){tb_inv_rotate(a.q, tb_sub(b.p, a.p)), q};
}

/* Placed within TB_MAX_LENGTH and turned by a unit rotation (as the queries ask). */
static bool transform_ok(tb_transform xf) {
  return tb_point_ok(xf.p) && isfinite(xf.q.c) && isfinite(xf.q.s) &&
         fabsf(xf.q.c * xf.q.c + xf.q.s * xf.q.s - 1.0f) <= 1e-3f;
}

/* Public entry points reject NULL shapes and non-finite transforms with an empty
 * manifold (the shapes themselves are trusted: tb_check_* vetted them). */
static inline bool args_ok(const void* a, tb_transform xfa, const void* b, tb_transform xfb, const char* fn) {
  if (a == NULL || b == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: shape %s is NULL", fn, a == NULL ? "a" : "b");
    return false;
  }
  if (!transform_ok(xfa) || !transform_ok(xfb)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
            "%s: transform %s is not finite, beyond TB_MAX_LENGTH or not a unit rotation", fn,
            transform_ok(xfa) ? "xfb" : "xfa");
    return false;
  }
  return true;
}

static float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

/* A manifold in A's frame, as the helpers build it; to_world moves it to world
 * once. to_world returns one compound literal built from scalars, which the
 * compiler writes straight into the caller's return slot. (GCC 12 does not
 * elide the copy of a local tb_manifold that is returned, and that copy reads
 * back 16 bytes at a time what was just stored 4 at a time, which defeats
 * store forwarding: it cost as much as a circle-circle collision.) */
typedef struct local_manifold {
  tb_vec2 normal; /* A to B */
  tb_vec2 point[2];
  float sep[2];
  uint32_t id[2];
  int count;
} local_manifold;

static inline void add_point(local_manifold* m, tb_vec2 p, float sep, uint32_t id) {
  m->point[m->count] = p;
  m->sep[m->count] = sep;
  m->id[m->count] = id;
  m->count += 1;
}

static inline tb_manifold to_world(const local_manifold* l, tb_transform xfa) {
  tb_manifold_point p0 = {{0.0f, 0.0f}, 0.0f, 0u, 0.0f, 0.0f}, p1 = p0;
  tb_vec2 n = {0.0f, 0.0f};
  if (l->count > 0) {
    n = tb_rotate(xfa.q, l->normal);
    p0 = (tb_manifold_point){tb_transform_point(xfa, l->point[0]), l->sep[0], l->id[0], 0.0f, 0.0f};
  }
  if (l->count > 1) p1 = (tb_manifold_point){tb_transform_point(xfa, l->point[1]), l->sep[1], l->id[1], 0.0f, 0.0f};
  return (tb_manifold){n, {p0, p1}, l->count};
}

/* One contact between core points pa (on A) and pb (on B), A's frame, radii ra
 * and rb. The normal is unit(pb - pa), or unit(fallback) when the cores
 * (nearly) coincide and no direction is meaningful. */
static inline void point_contact(local_manifold* m, tb_vec2 pa, tb_vec2 pb, float ra, float rb, tb_vec2 fallback) {
  tb_vec2 d = tb_sub(pb, pa);
  float dist = tb_length(d);
  float sep = dist - ra - rb;
  if (!(sep < TB_SPECULATIVE_DISTANCE)) return; /* also rejects NaN */
  tb_vec2 n = dist > FLT_EPSILON ? tb_scale(1.0f / dist, d) : tb_normalize(fallback);
  m->normal = n;
  /* A's surface is pa + ra n, B's is pa + (dist - rb) n: midway is ra + sep / 2 */
  add_point(m, tb_mul_add(pa, ra + 0.5f * sep, n), sep, 0u);
}

/* ------------------------------------------------------ circle contacts -- */

tb_manifold tb_collide_circles(const tb_circle* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_circles")) {
    tb_vec2 cb = tb_transform_point(relative_transform(xfa, xfb), b->center);
    point_contact(&m, a->center, cb, a->radius, b->radius, tb_v2(1.0f, 0.0f));
  }
  return to_world(&m, xfa);
}

/* Circle b against segment p1-p2 (A's frame) inflated by ra. */
static inline void segment_circle(local_manifold* m, tb_vec2 p1, tb_vec2 p2, float ra, const tb_circle* b,
                                  tb_transform xfa, tb_transform xfb) {
  tb_vec2 c = tb_transform_point(relative_transform(xfa, xfb), b->center);
  tb_vec2 e = tb_sub(p2, p1);
  float u = tb_dot(tb_sub(c, p1), e);
  /* beyond an end: radial from the end centre */
  if (u <= 0.0f || u >= tb_dot(e, e)) {
    point_contact(m, u <= 0.0f ? p1 : p2, c, ra, b->radius, tb_right_perp(e));
    return;
  }
  /* beside the segment: along its normal, taken directly rather than from c
   * minus the closest point, which would cancel digits; a centre right on the
   * core is pushed to the right side */
  tb_vec2 n = tb_normalize(tb_right_perp(e));
  float s = tb_dot(n, tb_sub(c, p1));
  if (s < 0.0f) {
    n = tb_neg(n);
    s = -s;
  }
  float sep = s - ra - b->radius;
  if (!(sep < TB_SPECULATIVE_DISTANCE)) return;
  m->normal = n;
  add_point(m, tb_mul_add(c, ra - s + 0.5f * sep, n), sep, 0u);
}

tb_manifold tb_collide_capsule_and_circle(const tb_capsule* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_capsule_and_circle"))
    segment_circle(&m, a->center1, a->center2, a->radius, b, xfa, xfb);
  return to_world(&m, xfa);
}

tb_manifold tb_collide_segment_and_circle(const tb_segment* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_segment_and_circle"))
    segment_circle(&m, a->point1, a->point2, 0.0f, b, xfa, xfb);
  return to_world(&m, xfa);
}

/* The circle's centre c is closest to a face or to a vertex of the core polygon.
 * The face of greatest separation s_i = n_i . (c - v_i) is the closest face when
 * c lies in that face's slab; otherwise c is in the region of one of the face's
 * two vertices (the separation function of convex sets is unimodal around the
 * closest direction, so the best face is adjacent to the closest vertex). Inside
 * the core (s <= 0) the best face is the way out. */
static inline void polygon_circle(local_manifold* m, const tb_polygon* a, tb_vec2 c, float rb) {
  float r = a->radius + rb;
  int face = 0;
  float s = -FLT_MAX;
  for (int i = 0; i < a->count; ++i) {
    float si = tb_dot(a->normals[i], tb_sub(c, a->vertices[i]));
    if (si > s) {
      s = si;
      face = i;
    }
  }
  if (!(s - r < TB_SPECULATIVE_DISTANCE)) return;
  tb_vec2 v1 = a->vertices[face], v2 = a->vertices[face + 1 < a->count ? face + 1 : 0];
  if (s > 0.0f) {
    tb_vec2 e = tb_sub(v2, v1);
    bool before = tb_dot(tb_sub(c, v1), e) < 0.0f;
    bool after = tb_dot(tb_sub(c, v2), e) > 0.0f;
    if (before || after) {
      point_contact(m, before ? v1 : v2, c, a->radius, rb, a->normals[face]);
      return;
    }
  }
  tb_vec2 n = a->normals[face];
  float sep = s - r;
  m->normal = n;
  /* core point c - s n; A's surface a->radius further along n */
  add_point(m, tb_mul_add(c, a->radius - s + 0.5f * sep, n), sep, 0u);
}

tb_manifold tb_collide_polygon_and_circle(const tb_polygon* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_polygon_and_circle"))
    polygon_circle(&m, a, tb_transform_point(relative_transform(xfa, xfb), b->center), b->radius);
  return to_world(&m, xfa);
}

/* ------------------------------------------- polygon-like contacts (SAT) -- */

/* A convex core: count vertices counter-clockwise, edge i from v[i] to
 * v[i + 1] with outward unit normal n[i], plus a radius. A segment is the
 * two-vertex polygon p1 -> p2 -> p1 whose two edges face opposite ways. */
typedef struct core {
  const tb_vec2* v;
  const tb_vec2* n;
  int count;
  float radius;
} core;

static int next_index(int i, int count) { return i + 1 < count ? i + 1 : 0; }

/* Segment p1-p2 as a two-vertex core; v and n (2 entries each) hold its data. */
static core segment_core(tb_vec2 p1, tb_vec2 p2, float radius, tb_vec2* v, tb_vec2* n) {
  v[0] = p1;
  v[1] = p2;
  n[0] = tb_normalize(tb_right_perp(tb_sub(p2, p1)));
  n[1] = tb_neg(n[0]);
  return (core){v, n, 2, radius};
}

/* Polygon b moved by xf into v and n. */
static core moved_polygon(const tb_polygon* b, tb_transform xf, tb_vec2* v, tb_vec2* n) {
  for (int i = 0; i < b->count; ++i) {
    v[i] = tb_transform_point(xf, b->vertices[i]);
    n[i] = tb_rotate(xf.q, b->normals[i]);
  }
  return (core){v, n, b->count, b->radius};
}

static core polygon_core(const tb_polygon* a) { return (core){a->vertices, a->normals, a->count, a->radius}; }

/* The edge of p along whose normal q lies farthest out: the greatest, over p's
 * edges, of the least signed distance of q's vertices to the edge's line. For
 * polygons with area that is minus the penetration depth when they overlap and
 * a lower bound of the core gap when they do not. Stops at the first edge above
 * limit: it separates the cores by more than any contact needs. */
static float max_separation(const core* p, const core* q, float limit, int* edge) {
  float best = -FLT_MAX;
  int best_i = 0;
  for (int i = 0; i < p->count; ++i) {
    tb_vec2 n = p->n[i], v = p->v[i];
    float s = FLT_MAX;
    for (int j = 0; j < q->count; ++j) { /* difference first: exact for nearby points */
      float d = tb_dot(n, tb_sub(q->v[j], v));
      s = d < s ? d : s;
    }
    if (s > best) {
      best = s;
      best_i = i;
      if (s > limit) break;
    }
  }
  *edge = best_i;
  return best;
}

/* Fractions s, t of the closest points p1 + s (q1 - p1) and p2 + t (q2 - p2)
 * of two segments of nonzero length. Minimising the squared distance gives the
 * 2x2 normal equations a s - b t = -c, b s - e t = -f; solve for s, clamp, take
 * the best t for it, and if t had to be clamped the best s for that t. Clamped
 * values are exactly 0 or 1, which is how callers recognise vertices. Nearly
 * parallel segments (sin^2 of the angle below 1e-6) start from s = 0: any pair
 * of the overlap is closest to within length * 1e-3. */
static void closest_fractions(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2, float* s_out, float* t_out) {
  tb_vec2 d1 = tb_sub(q1, p1), d2 = tb_sub(q2, p2), r = tb_sub(p1, p2);
  float a = tb_dot(d1, d1), e = tb_dot(d2, d2), b = tb_dot(d1, d2);
  float c = tb_dot(d1, r), f = tb_dot(d2, r);
  float den = a * e - b * b; /* a e sin^2(angle) >= 0 */
  float s = den > 1e-6f * a * e ? clamp01((b * f - c * e) / den) : 0.0f;
  float t = (b * s + f) / e;
  if (t < 0.0f) {
    t = 0.0f;
    s = clamp01(-c / a);
  } else if (t > 1.0f) {
    t = 1.0f;
    s = clamp01((b - c) / a);
  }
  *s_out = s;
  *t_out = t;
}

/* The chosen reference edge (i1 -> i2 of ref, normal n) and incident edge
 * (j1 -> j2 of inc); flip when the reference belongs to B. */
typedef struct face_pair {
  const core* ref;
  const core* inc;
  int i1, i2, j1, j2;
  bool flip;
  tb_vec2 n;
  float s; /* separation along n (separating-axis test) */
} face_pair;

/* Feature id of a reference-side and an incident-side feature, as (A, B). */
static inline uint32_t pair_id(const face_pair* fp, int ref_index, uint32_t ref_type, int inc_index,
                               uint32_t inc_type) {
  return fp->flip ? tb_make_feature_id((uint32_t)inc_index, inc_type, (uint32_t)ref_index, ref_type)
                  : tb_make_feature_id((uint32_t)ref_index, ref_type, (uint32_t)inc_index, inc_type);
}

/* Feature at fraction f of edge k1 -> k2: a vertex at the ends, else the edge. */
static inline void feature_at(float f, int k1, int k2, int* index, uint32_t* type) {
  *index = f == 0.0f ? k1 : (f == 1.0f ? k2 : k1);
  *type = (f == 0.0f || f == 1.0f) ? TB_FEATURE_VERTEX : TB_FEATURE_EDGE;
}

/* One point between the closest points of the two edges (fractions fr, fi).
 * The normal joins them: this is the rounded-corner case (vertex against
 * vertex, gap beyond the tolerance), where no face normal is right. When they
 * (nearly) touch the separating axis is kept, with its depth. */
static void closest_contact(local_manifold* m, const face_pair* fp, float fr, float fi) {
  tb_vec2 cr = tb_lerp(fp->ref->v[fp->i1], fp->ref->v[fp->i2], fr);
  tb_vec2 ci = tb_lerp(fp->inc->v[fp->j1], fp->inc->v[fp->j2], fi);
  tb_vec2 d = tb_sub(ci, cr);
  float dist = tb_length(d);
  float r = fp->ref->radius + fp->inc->radius;
  tb_vec2 n = fp->n;
  float sep = fp->s - r;
  if (dist > TB_CORE_GAP_TOLERANCE) {
    n = tb_scale(1.0f / dist, d);
    sep = dist - r;
  }
  if (!(sep < TB_SPECULATIVE_DISTANCE)) return;
  int ri, ii;
  uint32_t rt, it;
  feature_at(fr, fp->i1, fp->i2, &ri, &rt);
  feature_at(fi, fp->j1, fp->j2, &ii, &it);
  m->normal = fp->flip ? tb_neg(n) : n;
  add_point(m, tb_mul_add(cr, fp->ref->radius + 0.5f * sep, n), sep, pair_id(fp, ri, rt, ii, it));
}

/* Contact of two cores, both in A's frame (a's own frame).
 *
 * 1. Separating axes: the edge of A and the edge of B of greatest separation;
 *    nothing when either exceeds the radii plus the speculative distance. The
 *    larger one gives the reference face (ties go to A). The choice does not
 *    depend on the argument order, so swapping the shapes mirrors the manifold.
 * 2. Incident edge: the edge of the other core whose normal is most opposed.
 * 3. Cores apart (s beyond the tolerance) and the closest points of the two
 *    edges both at vertices: rounded corners meet, one point along the line
 *    between the vertices (a face normal misstates the gap of rounded corners;
 *    for sharp ones it is the true gap, useful to speculative contacts).
 * 4. Otherwise clip the incident edge to the reference face's slab (the core
 *    face, not widened by the radii: beyond it the rounded surface curves away)
 *    and keep the clipped points whose separation is below the speculative
 *    distance. An incident edge wholly outside the slab (a degenerate case, e.g.
 *    two collinear segments end to end, where the segments' face normals are not
 *    enough axes) falls back to step 3's closest points. */
#define TB_SLAB_TOLERANCE 1e-5f /* m: far above float rounding at game sizes, far below a slop */
static void collide_cores(local_manifold* m, const core* a, const core* b) {
  float limit = a->radius + b->radius + TB_SPECULATIVE_DISTANCE;
  int ea, eb;
  float sa = max_separation(a, b, limit, &ea);
  if (!(sa < limit)) return;
  float sb = max_separation(b, a, limit, &eb);
  if (!(sb < limit)) return;

  face_pair fp;
  fp.flip = sb > sa;
  fp.ref = fp.flip ? b : a;
  fp.inc = fp.flip ? a : b;
  fp.i1 = fp.flip ? eb : ea;
  fp.i2 = next_index(fp.i1, fp.ref->count);
  fp.s = fp.flip ? sb : sa;
  fp.n = fp.ref->n[fp.i1];
  fp.j1 = 0;
  float most = FLT_MAX;
  for (int j = 0; j < fp.inc->count; ++j) {
    float d = tb_dot(fp.n, fp.inc->n[j]);
    if (d < most) {
      most = d;
      fp.j1 = j;
    }
  }
  fp.j2 = next_index(fp.j1, fp.inc->count);

  /* slab of the reference face: u in [0, len] along its tangent */
  tb_vec2 r1 = fp.ref->v[fp.i1], r2 = fp.ref->v[fp.i2];
  tb_vec2 p[2] = {fp.inc->v[fp.j1], fp.inc->v[fp.j2]};
  tb_vec2 t = tb_left_perp(fp.n);
  float len = tb_dot(tb_sub(r2, r1), t);
  float u[2] = {tb_dot(tb_sub(p[0], r1), t), tb_dot(tb_sub(p[1], r1), t)};
  /* A vertex within TB_SLAB_TOLERANCE of a side plane counts as inside: the
   * choice below between one closest point and clipping must not hang on the
   * rounding of u, which differs when the shapes are swapped. */
  const float e = TB_SLAB_TOLERANCE;
  bool outside = (u[0] < -e && u[1] < -e) || (u[0] > len + e && u[1] > len + e);
  bool leaves = u[0] < -e || u[0] > len + e || u[1] < -e || u[1] > len + e;
  /* with both incident vertices in the slab the nearer one faces the reference
   * edge: only an incident edge that leaves the slab can meet it at a vertex */
  if (outside || (leaves && fp.s > TB_CORE_GAP_TOLERANCE)) {
    float fr, fi;
    closest_fractions(r1, r2, p[0], p[1], &fr, &fi);
    if (outside || ((fr == 0.0f || fr == 1.0f) && (fi == 0.0f || fi == 1.0f))) {
      closest_contact(m, &fp, fr, fi);
      return;
    }
  }
  float rr = fp.ref->radius, ri = fp.inc->radius;
  tb_vec2 first = {0.0f, 0.0f};
  for (int k = 0; k < 2; ++k) {
    tb_vec2 q = p[k];
    uint32_t id;
    if (u[k] < 0.0f) { /* cut at the side plane through r1 (the other end is inside) */
      q = tb_lerp(p[k], p[1 - k], -u[k] / (u[1 - k] - u[k]));
      id = pair_id(&fp, fp.i1, TB_FEATURE_VERTEX, fp.j1, TB_FEATURE_EDGE);
    } else if (u[k] > len) {
      q = tb_lerp(p[k], p[1 - k], (len - u[k]) / (u[1 - k] - u[k]));
      id = pair_id(&fp, fp.i2, TB_FEATURE_VERTEX, fp.j1, TB_FEATURE_EDGE);
    } else {
      id = pair_id(&fp, fp.i1, TB_FEATURE_EDGE, k == 0 ? fp.j1 : fp.j2, TB_FEATURE_VERTEX);
    }
    float sq = tb_dot(fp.n, tb_sub(q, r1)); /* core separation of this point */
    float sep = sq - rr - ri;
    if (!(sep < TB_SPECULATIVE_DISTANCE)) continue;
    /* an incident edge that meets the slab in a single point (one vertex on a
     * side plane, the other outside) clips to that vertex twice: keep one, as
     * the swapped order does (two coincident points make the solver's 2x2
     * block singular) */
    if (m->count == 1 && tb_distance_sq(q, first) <= 1e-12f * (1.0f + tb_length_sq(q))) continue;
    first = q;
    /* reference surface at q - sq n + rr n, incident surface at q - ri n */
    add_point(m, tb_mul_add(q, 0.5f * (rr - sq - ri), fp.n), sep, id);
  }
  m->normal = fp.flip ? tb_neg(fp.n) : fp.n;
}

/* ------------------------------------------------------- public wrappers -- */

tb_manifold tb_collide_capsules(const tb_capsule* a, tb_transform xfa, const tb_capsule* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_capsules")) {
    tb_transform rel = relative_transform(xfa, xfb);
    tb_vec2 va[2], na[2], vb[2], nb[2];
    core ca = segment_core(a->center1, a->center2, a->radius, va, na);
    core cb = segment_core(tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius, vb, nb);
    collide_cores(&m, &ca, &cb);
  }
  return to_world(&m, xfa);
}

tb_manifold tb_collide_segment_and_capsule(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_segment_and_capsule")) {
    tb_transform rel = relative_transform(xfa, xfb);
    tb_vec2 va[2], na[2], vb[2], nb[2];
    core ca = segment_core(a->point1, a->point2, 0.0f, va, na);
    core cb = segment_core(tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius, vb, nb);
    collide_cores(&m, &ca, &cb);
  }
  return to_world(&m, xfa);
}

tb_manifold tb_collide_segment_and_polygon(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                           tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_segment_and_polygon")) {
    tb_vec2 va[2], na[2], vb[TB_MAX_POLYGON_VERTICES], nb[TB_MAX_POLYGON_VERTICES];
    core ca = segment_core(a->point1, a->point2, 0.0f, va, na);
    core cb = moved_polygon(b, relative_transform(xfa, xfb), vb, nb);
    collide_cores(&m, &ca, &cb);
  }
  return to_world(&m, xfa);
}

tb_manifold tb_collide_polygon_and_capsule(const tb_polygon* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_polygon_and_capsule")) {
    tb_transform rel = relative_transform(xfa, xfb);
    tb_vec2 vb[2], nb[2];
    core ca = polygon_core(a);
    core cb = segment_core(tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius, vb, nb);
    collide_cores(&m, &ca, &cb);
  }
  return to_world(&m, xfa);
}

tb_manifold tb_collide_polygons(const tb_polygon* a, tb_transform xfa, const tb_polygon* b, tb_transform xfb) {
  local_manifold m = {0};
  if (args_ok(a, xfa, b, xfb, "tb_collide_polygons")) {
    tb_vec2 vb[TB_MAX_POLYGON_VERTICES], nb[TB_MAX_POLYGON_VERTICES];
    core ca = polygon_core(a);
    core cb = moved_polygon(b, relative_transform(xfa, xfb), vb, nb);
    collide_cores(&m, &ca, &cb);
  }
  return to_world(&m, xfa);
}
