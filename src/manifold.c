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
#include <string.h>

#include "error.h"
#include "geometry.h"
#include "math_internal.h"
#include "units.h"

#if !defined(__GNUC__)
#error "tumble's manifolds need GCC-style vector extensions (GCC or Clang)"
#endif

/* Below this core gap (m) a direction between two closest points is noise; the
 * face normal of the separating-axis test is used instead. */
#define TB_CORE_GAP_TOLERANCE (0.1f * tb_units.linear_slop)

/* ------------------------------------------------------------- helpers -- */

/* inv(a) * b: the placement of B seen from A's frame. */
static inline tb_transform relative_transform(tb_transform a, tb_transform b) {
  tb_rot q = {a.q.c * b.q.c + a.q.s * b.q.s, a.q.c * b.q.s - a.q.s * b.q.c};
  return (tb_transform){tb_inv_rotate(a.q, tb_sub(b.p, a.p)), q};
}

/* Placed within TB_MAX_LENGTH and turned by a unit rotation (as the queries
 * ask). NaN and infinities fail the comparisons, so they need no test of
 * their own (a non-finite c or s makes c^2 + s^2 - 1 infinite or NaN). */
static bool transform_ok(tb_transform xf) {
  return (fabsf(xf.p.x) <= TB_MAX_LENGTH) & (fabsf(xf.p.y) <= TB_MAX_LENGTH) &
         (fabsf(xf.q.c * xf.q.c + xf.q.s * xf.q.s - 1.0f) <= 1e-3f);
}

/* The public entry points' checks (the narrow phase calls the _unchecked
 * forms: its shapes were vetted when they were made, its transforms come from
 * the solver). NULL shapes, then the shapes as the mass and shape functions
 * check them (why_a, why_b: tb_check_*'s answer, NULL when fine), then the
 * transforms. A polygon's count must be checked before anything reads it:
 * the cores below hold TB_MAX_POLYGON_VERTICES points. */
bool tb_collide_args_ok(const char* fn, const void* a, const char* why_a, tb_transform xfa, const void* b,
                        const char* why_b, tb_transform xfb) {
  if (a == NULL || b == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: shape %s is NULL", fn, a == NULL ? "a" : "b");
    return false;
  }
  if (why_a != NULL || why_b != NULL) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: shape %s: %s", fn, why_a != NULL ? "a" : "b",
            why_a != NULL ? why_a : why_b);
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
 * store forwarding: it cost as much as a circle-circle collision.) The caller
 * that keeps the manifold somewhere copies it out of that slot the same way,
 * so the narrow phase has store_world write it in place instead. */
typedef struct local_manifold {
  tb_vec2 normal; /* A to B */
  tb_vec2 point[2];
  float sep[2];
  uint32_t id[2];
  int count;
  bool bounded;   /* the touching features end: patch is set (else unbounded) */
  tb_patch patch; /* see manifold.h */
} local_manifold;

static inline void add_point(local_manifold* m, tb_vec2 p, float sep, uint32_t id) {
  m->point[m->count] = p;
  m->sep[m->count] = sep;
  m->id[m->count] = id;
  m->count += 1;
}

/* The normal and points of l in world (zero past its count). */
static inline void world_parts(const local_manifold* l, tb_transform xfa, tb_vec2* n, tb_manifold_point* p0,
                               tb_manifold_point* p1) {
  *n = (tb_vec2){0.0f, 0.0f};
  *p0 = *p1 = (tb_manifold_point){{0.0f, 0.0f}, 0.0f, 0u, 0.0f, 0.0f};
  if (l->count > 0) {
    *n = tb_rotate(xfa.q, l->normal);
    *p0 = (tb_manifold_point){tb_transform_point(xfa, l->point[0]), l->sep[0], l->id[0], 0.0f, 0.0f};
  }
  if (l->count > 1) *p1 = (tb_manifold_point){tb_transform_point(xfa, l->point[1]), l->sep[1], l->id[1], 0.0f, 0.0f};
}

/* The patch of l (unbounded unless a face contact set it); the slide range
 * is a distance along the tangent, the same in A's frame and in world (the
 * ends stay in A's frame: they are rarely needed). */
static inline void store_patch(const local_manifold* l, tb_patch* patch) {
  if (patch == NULL) return;
  if (l->bounded && l->count > 0)
    *patch = l->patch;
  else
    *patch = (tb_patch){.slide_min = -FLT_MAX, .slide_max = FLT_MAX};
}

static inline tb_manifold to_world(const local_manifold* l, tb_transform xfa, tb_patch* patch) {
  tb_vec2 n;
  tb_manifold_point p0, p1;
  world_parts(l, xfa, &n, &p0, &p1);
  store_patch(l, patch);
  return (tb_manifold){n, {p0, p1}, l->count};
}

static inline void store_world(const local_manifold* l, tb_transform xfa, tb_manifold* out, tb_patch* patch) {
  tb_vec2 n;
  tb_manifold_point p0, p1;
  world_parts(l, xfa, &n, &p0, &p1);
  out->normal = n;
  out->points[0] = p0;
  out->points[1] = p1;
  out->point_count = l->count;
  store_patch(l, patch);
}

/* The patch of a face contact (normal n, A to B, A's frame): A's feature
 * spans a1-a2 and B's b1-b2 (b1 = b2 for a point), offset and radius as in
 * tb_patch. B keeps touching while its feature, moved by d along
 * t = right_perp(n), overlaps A's: a_min <= b_max + d and b_min + d <= a_max. */
static inline void set_patch(local_manifold* m, tb_vec2 n, tb_vec2 a1, tb_vec2 a2, tb_vec2 b1, tb_vec2 b2, float offset,
                             float radius) {
  tb_vec2 t = tb_right_perp(n);
  float ua1 = tb_dot(t, a1), ua2 = tb_dot(t, a2), ub1 = tb_dot(t, b1), ub2 = tb_dot(t, b2);
  float a_min = ua1 < ua2 ? ua1 : ua2, a_max = ua1 < ua2 ? ua2 : ua1;
  float b_min = ub1 < ub2 ? ub1 : ub2, b_max = ub1 < ub2 ? ub2 : ub1;
  m->bounded = true;
  m->patch = (tb_patch){a_min - b_max,       a_max - b_min,       offset, offset, radius, true,
                        ua1 < ua2 ? a1 : a2, ua1 < ua2 ? a2 : a1, n};
}

/* The patch of a contact between two core points, A's offset_a and B's
 * offset_b along the normal from the manifold point. */
static inline void set_point_patch(local_manifold* m, float offset_a, float offset_b, float radius) {
  m->bounded = true;
  m->patch = (tb_patch){.offset_a = offset_a, .offset_b = offset_b, .radius = radius};
}

/* One contact between core points pa (on A) and pb (on B), A's frame, radii ra
 * and rb. The normal is unit(pb - pa), or unit(fallback) when the cores
 * (nearly) coincide and no direction is meaningful. */
static inline void point_contact(local_manifold* m, tb_vec2 pa, tb_vec2 pb, float ra, float rb, tb_vec2 fallback) {
  tb_vec2 d = tb_sub(pb, pa);
  float dist = tb_length(d);
  float sep = dist - ra - rb;
  if (!(sep < tb_units.speculative_distance)) return; /* also rejects NaN */
  tb_vec2 n = dist > FLT_EPSILON ? tb_scale(1.0f / dist, d) : tb_normalize(fallback);
  m->normal = n;
  /* A's surface is pa + ra n, B's is pa + (dist - rb) n: midway is ra + sep / 2 */
  add_point(m, tb_mul_add(pa, ra + 0.5f * sep, n), sep, 0u);
  if (dist > FLT_EPSILON && ra + rb > 0.0f) set_point_patch(m, -(ra + 0.5f * sep), rb + 0.5f * sep, ra + rb);
}

/* ------------------------------------------------------ circle contacts -- */

tb_manifold tb_collide_circles_unchecked(const tb_circle* a, tb_transform xfa, const tb_circle* b, tb_transform xfb,
                                         tb_patch* patch) {
  local_manifold m = {0};
  tb_vec2 cb = tb_transform_point(relative_transform(xfa, xfb), b->center);
  point_contact(&m, a->center, cb, a->radius, b->radius, tb_v2(1.0f, 0.0f));
  return to_world(&m, xfa, patch);
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
  if (!(sep < tb_units.speculative_distance)) return;
  m->normal = n;
  add_point(m, tb_mul_add(c, ra - s + 0.5f * sep, n), sep, 0u);
  set_patch(m, n, p1, p2, c, c, b->radius + 0.5f * sep, ra + b->radius); /* the point is c - (rb + sep / 2) n */
}

tb_manifold tb_collide_capsule_and_circle_unchecked(const tb_capsule* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  segment_circle(&m, a->center1, a->center2, a->radius, b, xfa, xfb);
  return to_world(&m, xfa, patch);
}

tb_manifold tb_collide_segment_and_circle_unchecked(const tb_segment* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  segment_circle(&m, a->point1, a->point2, 0.0f, b, xfa, xfb);
  return to_world(&m, xfa, patch);
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
  if (!(s - r < tb_units.speculative_distance)) return;
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
  set_patch(m, n, v1, v2, c, c, rb + 0.5f * sep, r);
}

tb_manifold tb_collide_polygon_and_circle_unchecked(const tb_polygon* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  polygon_circle(&m, a, tb_transform_point(relative_transform(xfa, xfb), b->center), b->radius);
  return to_world(&m, xfa, patch);
}

/* ------------------------------------------- polygon-like contacts (SAT) -- */

/* A convex core: count vertices counter-clockwise, edge i from vertex i to
 * vertex i + 1 with outward unit normal i, plus a radius. A segment is the
 * two-vertex polygon p1 -> p2 -> p1 whose two edges face opposite ways.
 *
 * The vertices and normals are kept component by component, in groups of
 * four lanes (past count: finite filler, never an edge), so that the
 * separating-axis search below runs over four edges at once: a plain loop the
 * compiler turns into vector code. The groups are built in vector registers
 * and stored whole: stored lane by lane and then loaded whole, they would
 * stall the loads until every separate store had landed (no store
 * forwarding), which cost more than the search. */
#define CORE_CAPACITY ((TB_MAX_POLYGON_VERTICES + 3) / 4 * 4)
typedef struct core {
  _Alignas(16) float vx[CORE_CAPACITY];
  _Alignas(16) float vy[CORE_CAPACITY];
  _Alignas(16) float nx[CORE_CAPACITY];
  _Alignas(16) float ny[CORE_CAPACITY];
  int count;
  float radius;
} core;

static inline tb_vec2 core_vertex(const core* c, int i) { return (tb_vec2){c->vx[i], c->vy[i]}; }
static inline tb_vec2 core_normal(const core* c, int i) { return (tb_vec2){c->nx[i], c->ny[i]}; }

/* Four float lanes (GCC and Clang vector extensions, as in contact_solver.c).
 * SHUFFLE: lane k of the result is lane i_k of a (0-3) or of b (4-7). */
typedef float lane4 __attribute__((vector_size(16)));
typedef int32_t mask4 __attribute__((vector_size(16)));

#if defined(__clang__) || __GNUC__ >= 12
#define SHUFFLE(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
#define SHUFFLE(a, b, i0, i1, i2, i3) __builtin_shuffle(a, b, (mask4){i0, i1, i2, i3})
#endif

static inline lane4 splat4(float x) { return (lane4){x, x, x, x}; }

/* Group g of a core's four columns. */
typedef struct core_group {
  lane4 vx, vy, nx, ny;
} core_group;

static inline void store_group(core* c, int g, const core_group* q) {
  memcpy(&c->vx[4 * g], &q->vx, sizeof q->vx);
  memcpy(&c->vy[4 * g], &q->vy, sizeof q->vy);
  memcpy(&c->nx[4 * g], &q->nx, sizeof q->nx);
  memcpy(&c->ny[4 * g], &q->ny, sizeof q->ny);
}

/* x and y of points p[4 g .. 4 g + 3] of an array of `size`, zero from lane
 * `count` on: two 16-byte loads split by two shuffles (lanes past size are
 * built one by one). */
static inline void columns(const tb_vec2* p, int size, int count, int g, lane4* x, lane4* y) {
  int i0 = 4 * g;
  lane4 lo, hi;
  if (i0 + 4 <= size) {
    memcpy(&lo, &p[i0], sizeof lo);
    memcpy(&hi, &p[i0 + 2], sizeof hi);
  } else {
    tb_vec2 q[4] = {{0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}};
    for (int l = 0; i0 + l < count; ++l) q[l] = p[i0 + l];
    lo = (lane4){q[0].x, q[0].y, q[1].x, q[1].y};
    hi = (lane4){q[2].x, q[2].y, q[3].x, q[3].y};
  }
  mask4 used = (mask4){0, 1, 2, 3} < (mask4){count - i0, count - i0, count - i0, count - i0};
  *x = (lane4)((mask4)SHUFFLE(lo, hi, 0, 2, 4, 6) & used);
  *y = (lane4)((mask4)SHUFFLE(lo, hi, 1, 3, 5, 7) & used);
}

static int next_index(int i, int count) { return i + 1 < count ? i + 1 : 0; }

/* Segment p1-p2 as a two-vertex core. */
static void segment_core(core* c, tb_vec2 p1, tb_vec2 p2, float radius) {
  tb_vec2 n = tb_normalize(tb_right_perp(tb_sub(p2, p1)));
  core_group q = {{p1.x, p2.x, 0.0f, 0.0f}, {p1.y, p2.y, 0.0f, 0.0f}, {n.x, -n.x, 0.0f, 0.0f}, {n.y, -n.y, 0.0f, 0.0f}};
  store_group(c, 0, &q);
  c->count = 2;
  c->radius = radius;
}

/* Polygon b moved by xf, group by group with the operations of
 * tb_transform_point and tb_rotate. */
static void polygon_core(core* c, const tb_polygon* b, tb_transform xf) {
  lane4 px = splat4(xf.p.x), py = splat4(xf.p.y), qc = splat4(xf.q.c), qs = splat4(xf.q.s);
  for (int g = 0; 4 * g < b->count; ++g) {
    lane4 vx, vy, nx, ny;
    columns(b->vertices, TB_MAX_POLYGON_VERTICES, b->count, g, &vx, &vy);
    columns(b->normals, TB_MAX_POLYGON_VERTICES, b->count, g, &nx, &ny);
    core_group q = {px + (qc * vx - qs * vy), py + (qs * vx + qc * vy), qc * nx - qs * ny, qs * nx + qc * ny};
    store_group(c, g, &q);
  }
  c->count = b->count;
  c->radius = b->radius;
}

/* Polygon a where it is (A's own frame). */
static void local_polygon_core(core* c, const tb_polygon* a) {
  for (int g = 0; 4 * g < a->count; ++g) {
    core_group q;
    columns(a->vertices, TB_MAX_POLYGON_VERTICES, a->count, g, &q.vx, &q.vy);
    columns(a->normals, TB_MAX_POLYGON_VERTICES, a->count, g, &q.nx, &q.ny);
    store_group(c, g, &q);
  }
  c->count = a->count;
  c->radius = a->radius;
}

/* The edge of p along whose normal q lies farthest out: the greatest, over p's
 * edges, of the least signed distance of q's vertices to the edge's line (the
 * lowest index among equals). For polygons with area that is minus the
 * penetration depth when they overlap and a lower bound of the core gap when
 * they do not. */
static float max_separation(const core* p, const core* q, int* edge) {
  float best = -FLT_MAX;
  int best_i = 0;
  for (int i0 = 0; i0 < p->count; i0 += 4) {
    float s[4] = {FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX};
    for (int j = 0; j < q->count; ++j) {
      float qx = q->vx[j], qy = q->vy[j];
      for (int l = 0; l < 4; ++l) { /* n . (q_j - v): difference first, exact for nearby points */
        float d = p->nx[i0 + l] * (qx - p->vx[i0 + l]) + p->ny[i0 + l] * (qy - p->vy[i0 + l]);
        s[l] = d < s[l] ? d : s[l];
      }
    }
    for (int l = 0; l < 4 && i0 + l < p->count; ++l) {
      if (s[l] > best) {
        best = s[l];
        best_i = i0 + l;
      }
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
  /* an edge whose squared length underflows (a core 1e-30 thick) is a point:
   * its fraction is 0, not 0 / 0 */
  float s = den > 1e-6f * a * e ? clamp01((b * f - c * e) / den) : 0.0f;
  float t = e > 0.0f ? (b * s + f) / e : 0.0f;
  if (t < 0.0f) {
    t = 0.0f;
    s = a > 0.0f ? clamp01(-c / a) : 0.0f;
  } else if (t > 1.0f) {
    t = 1.0f;
    s = a > 0.0f ? clamp01((b - c) / a) : 0.0f;
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
  tb_vec2 cr = tb_lerp(core_vertex(fp->ref, fp->i1), core_vertex(fp->ref, fp->i2), fr);
  tb_vec2 ci = tb_lerp(core_vertex(fp->inc, fp->j1), core_vertex(fp->inc, fp->j2), fi);
  tb_vec2 d = tb_sub(ci, cr);
  float dist = tb_length(d);
  float r = fp->ref->radius + fp->inc->radius;
  tb_vec2 n = fp->n;
  float sep = fp->s - r;
  bool apart = dist > TB_CORE_GAP_TOLERANCE;
  if (apart) {
    n = tb_scale(1.0f / dist, d);
    sep = dist - r;
  }
  if (!(sep < tb_units.speculative_distance)) return;
  int ri, ii;
  uint32_t rt, it;
  feature_at(fr, fp->i1, fp->i2, &ri, &rt);
  feature_at(fi, fp->j1, fp->j2, &ii, &it);
  m->normal = fp->flip ? tb_neg(n) : n;
  add_point(m, tb_mul_add(cr, fp->ref->radius + 0.5f * sep, n), sep, pair_id(fp, ri, rt, ii, it));
  /* two vertices apart: the gap follows their roundings (a vertex against an
   * edge's interior, in the degenerate cases, keeps its gap, and so do
   * vertices that touch, whose normal is the face's: no patch) */
  if (apart && r > 0.0f && rt == TB_FEATURE_VERTEX && it == TB_FEATURE_VERTEX) {
    float to_ref = fp->ref->radius + 0.5f * sep, to_inc = fp->inc->radius + 0.5f * sep;
    if (fp->flip)
      set_point_patch(m, -to_inc, to_ref, r);
    else
      set_point_patch(m, -to_ref, to_inc, r);
  }
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
#define TB_SLAB_TOLERANCE tb_meters(1e-5f) /* m: far above float rounding at game sizes, far below a slop */
static void clip_to_face(local_manifold* m, face_pair fp);

static void collide_cores(local_manifold* m, const core* a, const core* b) {
  float limit = a->radius + b->radius + tb_units.speculative_distance;
  int ea, eb;
  float sa = max_separation(a, b, &ea);
  if (!(sa < limit)) return;
  float sb = max_separation(b, a, &eb);
  if (!(sb < limit)) return;

  face_pair fp;
  fp.flip = sb > sa;
  fp.ref = fp.flip ? b : a;
  fp.inc = fp.flip ? a : b;
  fp.i1 = fp.flip ? eb : ea;
  fp.i2 = next_index(fp.i1, fp.ref->count);
  fp.s = fp.flip ? sb : sa;
  fp.n = core_normal(fp.ref, fp.i1);
  clip_to_face(m, fp);
}

/* B's contact on face `edge` of A, that face the reference whichever face of
 * B separates more: a one-sided chain face whose neighbours do not take B's
 * tilted face (see chain.c) still holds B up. Steps 2 to 4 above. */
static void collide_on_face(local_manifold* m, const core* a, int edge, const core* b) {
  face_pair fp;
  fp.flip = false;
  fp.ref = a;
  fp.inc = b;
  fp.i1 = edge;
  fp.i2 = next_index(edge, a->count);
  fp.n = core_normal(a, edge);
  tb_vec2 r1 = core_vertex(a, edge);
  fp.s = FLT_MAX;
  for (int j = 0; j < b->count; ++j) fp.s = tb_minf(fp.s, tb_dot(fp.n, tb_sub(core_vertex(b, j), r1)));
  if (!(fp.s < a->radius + b->radius + tb_units.speculative_distance)) return;
  clip_to_face(m, fp);
}

/* Steps 2 to 4 of collide_cores for the reference face fp names. */
static void clip_to_face(local_manifold* m, face_pair fp) {
  fp.j1 = 0;
  float most = FLT_MAX;
  for (int j = 0; j < fp.inc->count; ++j) {
    float d = tb_dot(fp.n, core_normal(fp.inc, j));
    if (d < most) {
      most = d;
      fp.j1 = j;
    }
  }
  fp.j2 = next_index(fp.j1, fp.inc->count);

  /* slab of the reference face: u in [0, len] along its tangent */
  tb_vec2 r1 = core_vertex(fp.ref, fp.i1), r2 = core_vertex(fp.ref, fp.i2);
  tb_vec2 p[2] = {core_vertex(fp.inc, fp.j1), core_vertex(fp.inc, fp.j2)};
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
    /* rounded corners meet only where the incident vertex lies outside the
     * slab; one within the tolerance of a side plane is clipped, whichever
     * side of the plane its rounding put the reference's closest point. (The
     * clip below still cuts at the plane itself, so where a grazing incident
     * edge crosses the tolerance the separation jumps by tolerance / slope;
     * cutting at the widened plane instead removed the jump but changed how
     * flush boxes far from the origin track the same boxes at it.) */
    float ui = u[0] + fi * (u[1] - u[0]);
    bool corner = (fr == 0.0f || fr == 1.0f) && (fi == 0.0f || fi == 1.0f) && (ui < -e || ui > len + e);
    if (outside || corner) {
      closest_contact(m, &fp, fr, fi);
      return;
    }
  }
  float rr = fp.ref->radius, ri = fp.inc->radius;
  /* an incident edge that crosses the face by under half its length runs
   * steeply along the side planes: cutting it at a plane it is within the
   * tolerance of would move the point far along it and drop a deep end-to-end
   * contact in one argument order */
  bool steep = fabsf(u[1] - u[0]) < 0.5f * tb_length(tb_sub(p[1], p[0]));
  /* the incident feature that touches spans the kept points' vertices (a
   * cut point's vertex lies beyond the slab, where its edge runs on): u_lo
   * to u_hi along t, against the reference face's 0 to len */
  float u_lo = FLT_MAX, u_hi = -FLT_MAX;
  for (int k = 0; k < 2; ++k) {
    tb_vec2 q = p[k];
    uint32_t id;
    /* A vertex beyond a side plane is cut back to it when the other end is
     * inside the slab; where the incident edge runs steeply along the plane,
     * one within the tolerance stays (see steep). When the other end lies on
     * that plane too (within the tolerance), the edge meets the slab in that
     * end alone, whichever side of the plane rounding put either: a vertex
     * within the tolerance stays as it is, one beyond it is dropped (a cut
     * there would divide by a rounding difference, or add a point on top of
     * the other end, which makes the solver's 2x2 block singular). */
    bool cut_low = u[k] < (steep ? -e : 0.0f) && u[1 - k] > e;
    bool cut_high = u[k] > len + (steep ? e : 0.0f) && u[1 - k] < len - e;
    if (cut_low) { /* cut at the side plane through r1 */
      q = tb_lerp(p[k], p[1 - k], -u[k] / (u[1 - k] - u[k]));
      id = pair_id(&fp, fp.i1, TB_FEATURE_VERTEX, fp.j1, TB_FEATURE_EDGE);
    } else if (cut_high) {
      q = tb_lerp(p[k], p[1 - k], (len - u[k]) / (u[1 - k] - u[k]));
      id = pair_id(&fp, fp.i2, TB_FEATURE_VERTEX, fp.j1, TB_FEATURE_EDGE);
    } else {
      if (u[k] < -e || u[k] > len + e) continue;
      id = pair_id(&fp, fp.i1, TB_FEATURE_EDGE, k == 0 ? fp.j1 : fp.j2, TB_FEATURE_VERTEX);
    }
    float sq = tb_dot(fp.n, tb_sub(q, r1)); /* core separation of this point */
    float sep = sq - rr - ri;
    if (!(sep < tb_units.speculative_distance)) continue;
    /* reference surface at q - sq n + rr n, incident surface at q - ri n */
    add_point(m, tb_mul_add(q, 0.5f * (rr - sq - ri), fp.n), sep, id);
    u_lo = u[k] < u_lo ? u[k] : u_lo;
    u_hi = u[k] > u_hi ? u[k] : u_hi;
  }
  m->normal = fp.flip ? tb_neg(fp.n) : fp.n;
  if (m->count == 0) return;
  /* The incident feature keeps touching while, moved by d along t, it
   * overlaps [0, len]: -u_hi <= d <= len - u_lo. The manifold's tangent
   * right_perp(normal) is -t (normal fp.n: A is the reference, and d is B's
   * slide) or t (normal -fp.n: B is the reference, and B's slide relative to
   * A is -d): the same range either way, and r1 (u = 0) is where it ends
   * for d > 0. The incident core lies ri + sep / 2 beyond the points along
   * fp.n. */
  float offset = ri + 0.5f * m->sep[0];
  if (fp.flip) offset = -offset;
  m->bounded = true;
  m->patch = (tb_patch){u_lo - len, u_hi, offset, offset, rr + ri, true, r2, r1, fp.n};
}

/* ------------------------------------------- unchecked pairs of cores -- */

tb_manifold tb_collide_capsules_unchecked(const tb_capsule* a, tb_transform xfa, const tb_capsule* b, tb_transform xfb,
                                          tb_patch* patch) {
  local_manifold m = {0};
  tb_transform rel = relative_transform(xfa, xfb);
  core ca, cb;
  segment_core(&ca, a->center1, a->center2, a->radius);
  segment_core(&cb, tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius);
  collide_cores(&m, &ca, &cb);
  return to_world(&m, xfa, patch);
}

tb_manifold tb_collide_segment_and_capsule_unchecked(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                                     tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  tb_transform rel = relative_transform(xfa, xfb);
  core ca, cb;
  segment_core(&ca, a->point1, a->point2, 0.0f);
  segment_core(&cb, tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius);
  collide_cores(&m, &ca, &cb);
  return to_world(&m, xfa, patch);
}

tb_manifold tb_collide_segment_and_polygon_unchecked(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                                     tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  core ca, cb;
  segment_core(&ca, a->point1, a->point2, 0.0f);
  polygon_core(&cb, b, relative_transform(xfa, xfb));
  collide_cores(&m, &ca, &cb);
  return to_world(&m, xfa, patch);
}

/* The left face of a segment (normal left_perp(point2 - point1)) is edge 1 of
 * its core, which runs point2 -> point1. */
enum { SEGMENT_LEFT_FACE = 1 };

tb_manifold tb_collide_segment_face_and_capsule_unchecked(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                                          tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  tb_transform rel = relative_transform(xfa, xfb);
  core ca, cb;
  segment_core(&ca, a->point1, a->point2, 0.0f);
  segment_core(&cb, tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius);
  collide_on_face(&m, &ca, SEGMENT_LEFT_FACE, &cb);
  return to_world(&m, xfa, patch);
}

tb_manifold tb_collide_segment_face_and_polygon_unchecked(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                                          tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  core ca, cb;
  segment_core(&ca, a->point1, a->point2, 0.0f);
  polygon_core(&cb, b, relative_transform(xfa, xfb));
  collide_on_face(&m, &ca, SEGMENT_LEFT_FACE, &cb);
  return to_world(&m, xfa, patch);
}

tb_manifold tb_collide_polygon_and_capsule_unchecked(const tb_polygon* a, tb_transform xfa, const tb_capsule* b,
                                                     tb_transform xfb, tb_patch* patch) {
  local_manifold m = {0};
  tb_transform rel = relative_transform(xfa, xfb);
  core ca, cb;
  local_polygon_core(&ca, a);
  segment_core(&cb, tb_transform_point(rel, b->center1), tb_transform_point(rel, b->center2), b->radius);
  collide_cores(&m, &ca, &cb);
  return to_world(&m, xfa, patch);
}

/* two polygons in A's frame */
static void polygons_local(local_manifold* m, const tb_polygon* a, tb_transform xfa, const tb_polygon* b,
                           tb_transform xfb) {
  core ca, cb;
  local_polygon_core(&ca, a);
  polygon_core(&cb, b, relative_transform(xfa, xfb));
  collide_cores(m, &ca, &cb);
}

void tb_collide_polygons_into(const tb_polygon* a, tb_transform xfa, const tb_polygon* b, tb_transform xfb,
                              tb_manifold* out, tb_patch* patch) {
  local_manifold m = {0};
  polygons_local(&m, a, xfa, b, xfb);
  store_world(&m, xfa, out, patch);
}

/* ------------------------------------------------- checked public entries -- */

static const tb_manifold no_contact = {.point_count = 0};

/* tb_check_*'s verdict on a shape that may be NULL (NULL is reported first) */

tb_manifold tb_collide_circles(const tb_circle* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_circle, a), xfa, b, TB_COLLIDE_WHY(tb_check_circle, b),
                          xfb))
    return no_contact;
  return tb_collide_circles_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_capsule_and_circle(const tb_capsule* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_capsule, a), xfa, b, TB_COLLIDE_WHY(tb_check_circle, b),
                          xfb))
    return no_contact;
  return tb_collide_capsule_and_circle_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_capsules(const tb_capsule* a, tb_transform xfa, const tb_capsule* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_capsule, a), xfa, b, TB_COLLIDE_WHY(tb_check_capsule, b),
                          xfb))
    return no_contact;
  return tb_collide_capsules_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_segment_and_circle(const tb_segment* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_segment, a), xfa, b, TB_COLLIDE_WHY(tb_check_circle, b),
                          xfb))
    return no_contact;
  return tb_collide_segment_and_circle_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_segment_and_capsule(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_segment, a), xfa, b, TB_COLLIDE_WHY(tb_check_capsule, b),
                          xfb))
    return no_contact;
  return tb_collide_segment_and_capsule_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_segment_and_polygon(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                           tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_segment, a), xfa, b, TB_COLLIDE_WHY(tb_check_polygon, b),
                          xfb))
    return no_contact;
  return tb_collide_segment_and_polygon_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_polygon_and_circle(const tb_polygon* a, tb_transform xfa, const tb_circle* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_polygon, a), xfa, b, TB_COLLIDE_WHY(tb_check_circle, b),
                          xfb))
    return no_contact;
  return tb_collide_polygon_and_circle_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_polygon_and_capsule(const tb_polygon* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_polygon, a), xfa, b, TB_COLLIDE_WHY(tb_check_capsule, b),
                          xfb))
    return no_contact;
  return tb_collide_polygon_and_capsule_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_polygons(const tb_polygon* a, tb_transform xfa, const tb_polygon* b, tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(tb_check_polygon, a), xfa, b, TB_COLLIDE_WHY(tb_check_polygon, b),
                          xfb))
    return no_contact;
  local_manifold m = {0};
  polygons_local(&m, a, xfa, b, xfb);
  return to_world(&m, xfa, NULL);
}
