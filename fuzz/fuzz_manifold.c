/* libFuzzer harness: every tb_collide_* function on random shapes and
 * transforms.
 *
 * Invariants: at most 2 points; a manifold with points has a finite unit normal
 * and finite points and separations, each separation below the speculative
 * distance. Swapping two shapes of the same type (circles, capsules, polygons)
 * gives the same number of points (one against two only where a move of A by
 * a few rounding units gives that count too: the orders then straddle one of
 * the engine's thresholds; a speculative point against none is not compared,
 * see the check) and the opposite normal, and the same points (as a
 * set; two points closer than the tolerance count as one). Tolerances:
 * shapes are placed within 4 m of the origin with sizes up to 2 m, so
 * coordinates stay below ~10 m where a float step is ~1e-6 m; a manifold takes
 * a few dozen operations, so 1e-4 m for points and 1e-3 for the normal's
 * components leave a wide margin over rounding while still catching a wrong
 * feature (those differ by centimetres or by a whole face direction). The
 * orders are only compared when the answer is well defined: for circles and
 * capsules when their cores (centre points, centre segments) are more than
 * 1e-3 m apart (coincident centres have no preferred direction), and for
 * polygons and capsules when no two faces tie within 1e-3 m in the
 * separating-axis test (ties go to A by design, so each order then picks its
 * own first shape's face: both answers are right). Points are compared within
 * 1e-4 m plus twice how far they move when A turns or shifts by a few rounding
 * units (rounding_spread: ill-conditioned clips, threshold straddles), the
 * normals within 1e-3 plus twice how far the normal moves. */
#include "fuzz_common.h"

typedef struct shape {
  int type; /* 0 circle, 1 capsule, 2 segment, 3 polygon, 4 chain segment */
  tb_circle circle;
  tb_capsule capsule;
  tb_segment segment;
  tb_polygon polygon;
  tb_chain_segment chain;
} shape;

static void make_shape(fuzz_input* in, int type, shape* s) {
  s->type = type;
  switch (type) {
    case 0:
      s->circle = (tb_circle){{fuzz_range(in, -1, 1), fuzz_range(in, -1, 1)}, fuzz_range(in, 0.01f, 2.0f)};
      return;
    case 1:
      s->capsule = (tb_capsule){{fuzz_range(in, -1, 1), fuzz_range(in, -1, 1)},
                                {fuzz_range(in, -1, 1), fuzz_range(in, -1, 1)},
                                fuzz_range(in, 0.01f, 1.0f)};
      if (fabsf(s->capsule.center1.x - s->capsule.center2.x) + fabsf(s->capsule.center1.y - s->capsule.center2.y) <
          0.02f)
        s->capsule.center2.x += 0.5f;
      return;
    case 2:
    case 4: {
      tb_vec2 p1 = {fuzz_range(in, -2, 2), fuzz_range(in, -2, 2)}, p2 = {fuzz_range(in, -2, 2), fuzz_range(in, -2, 2)};
      if (fabsf(p1.x - p2.x) + fabsf(p1.y - p2.y) < 0.02f) p2.x += 1.0f;
      s->segment = (tb_segment){p1, p2};
      uint8_t ends = fuzz_u8(in);
      tb_vec2 g1 = {fuzz_range(in, -3, 3), fuzz_range(in, -3, 3)}, g2 = {fuzz_range(in, -3, 3), fuzz_range(in, -3, 3)};
      s->chain = (tb_chain_segment){(ends & 1) ? p1 : g1, s->segment, (ends & 2) ? p2 : g2};
      return;
    }
    default: {
      uint8_t k = fuzz_u8(in);
      int n = 3 + k % 8;
      tb_vec2 pts[10];
      for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){fuzz_range(in, -1.5f, 1.5f), fuzz_range(in, -1.5f, 1.5f)};
      float radius = (k & 0x80) ? fuzz_range(in, 0.0f, 0.5f) : 0.0f;
      if (tb_make_polygon(pts, n, radius, &s->polygon) != TB_OK)
        tb_make_offset_box(0.5f, 0.25f, pts[0], pts[1].x, &s->polygon);
      s->polygon.radius = radius;
      return;
    }
  }
}

static tb_transform make_transform(fuzz_input* in) {
  float a = fuzz_range(in, -3.2f, 3.2f);
  return (tb_transform){{fuzz_range(in, -4, 4), fuzz_range(in, -4, 4)}, {cosf(a), sinf(a)}};
}

static tb_manifold collide(const shape* a, tb_transform xa, const shape* b, tb_transform xb) {
  switch (a->type * 5 + b->type) {
    case 0 * 5 + 0: return tb_collide_circles(&a->circle, xa, &b->circle, xb);
    case 1 * 5 + 0: return tb_collide_capsule_and_circle(&a->capsule, xa, &b->circle, xb);
    case 1 * 5 + 1: return tb_collide_capsules(&a->capsule, xa, &b->capsule, xb);
    case 2 * 5 + 0: return tb_collide_segment_and_circle(&a->segment, xa, &b->circle, xb);
    case 2 * 5 + 1: return tb_collide_segment_and_capsule(&a->segment, xa, &b->capsule, xb);
    case 2 * 5 + 3: return tb_collide_segment_and_polygon(&a->segment, xa, &b->polygon, xb);
    case 3 * 5 + 0: return tb_collide_polygon_and_circle(&a->polygon, xa, &b->circle, xb);
    case 3 * 5 + 1: return tb_collide_polygon_and_capsule(&a->polygon, xa, &b->capsule, xb);
    case 3 * 5 + 3: return tb_collide_polygons(&a->polygon, xa, &b->polygon, xb);
    case 4 * 5 + 0: return tb_collide_chain_segment_and_circle(&a->chain, xa, &b->circle, xb);
    case 4 * 5 + 1: return tb_collide_chain_segment_and_capsule(&a->chain, xa, &b->capsule, xb);
    case 4 * 5 + 3: return tb_collide_chain_segment_and_polygon(&a->chain, xa, &b->polygon, xb);
  }
  abort();
}

/* The 12 pairs with a function, A's type first. */
static const int pairs[12][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 3},
                                 {3, 0}, {3, 1}, {3, 3}, {4, 0}, {4, 1}, {4, 3}};

static void check_manifold(const tb_manifold* m, const char* what) {
  FUZZ_CHECK(m->point_count >= 0 && m->point_count <= 2, "%s: %d points", what, m->point_count);
  if (m->point_count == 0) return;
  FUZZ_CHECK(fuzz_vec_finite(m->normal), "%s: normal not finite", what);
  float len = sqrtf(m->normal.x * m->normal.x + m->normal.y * m->normal.y);
  FUZZ_CHECK(fabsf(len - 1.0f) < 1e-4f, "%s: |normal| = %.9g", what, (double)len);
  for (int i = 0; i < m->point_count; ++i) {
    const tb_manifold_point* p = &m->points[i];
    FUZZ_CHECK(fuzz_vec_finite(p->point) && isfinite(p->separation), "%s: point %d not finite", what, i);
    FUZZ_CHECK(p->separation < TB_SPECULATIVE_DISTANCE + 1e-4f, "%s: separation %g beyond speculative", what,
               (double)p->separation);
    FUZZ_CHECK(p->normal_impulse == 0.0f && p->tangent_impulse == 0.0f, "%s: impulses", what);
  }
}

/* For two polygons: the gap between the best and the second best face of
 * either core in the separating-axis test. When two faces tie (within a
 * millimetre, e.g. identical boxes on top of each other) either is a right
 * answer, and the two orders may pick different ones. */
static float face_margin(const tb_polygon* a, tb_transform xa, const tb_polygon* b, tb_transform xb) {
  float best = -INFINITY, second = -INFINITY;
  for (int k = 0; k < 2; ++k) {
    const tb_polygon* p = k ? b : a;
    const tb_polygon* q = k ? a : b;
    tb_transform xp = k ? xb : xa, xq = k ? xa : xb;
    for (int i = 0; i < p->count; ++i) {
      tb_vec2 n = {xp.q.c * p->normals[i].x - xp.q.s * p->normals[i].y,
                   xp.q.s * p->normals[i].x + xp.q.c * p->normals[i].y};
      tb_vec2 v = {xp.p.x + xp.q.c * p->vertices[i].x - xp.q.s * p->vertices[i].y,
                   xp.p.y + xp.q.s * p->vertices[i].x + xp.q.c * p->vertices[i].y};
      float sep = INFINITY;
      for (int j = 0; j < q->count; ++j) {
        tb_vec2 w = {xq.p.x + xq.q.c * q->vertices[j].x - xq.q.s * q->vertices[j].y,
                     xq.p.y + xq.q.s * q->vertices[j].x + xq.q.c * q->vertices[j].y};
        sep = fminf(sep, n.x * (w.x - v.x) + n.y * (w.y - v.y));
      }
      if (sep > best) {
        second = best;
        best = sep;
      } else if (sep > second) {
        second = sep;
      }
    }
  }
  return best - second;
}

static tb_polygon capsule_core(const tb_capsule* c) {
  tb_polygon p;
  memset(&p, 0, sizeof p);
  tb_vec2 e = {c->center2.x - c->center1.x, c->center2.y - c->center1.y};
  float len = sqrtf(e.x * e.x + e.y * e.y);
  p.count = 2;
  p.vertices[0] = c->center1;
  p.vertices[1] = c->center2;
  p.normals[0] = (tb_vec2){e.y / len, -e.x / len};
  p.normals[1] = (tb_vec2){-e.y / len, e.x / len};
  return p;
}

/* Is any point within tol of the speculative limit? Then a tiny rounding
 * difference may legitimately keep it in one order and drop it in the other. */
static bool near_limit(const tb_manifold* m, float tol) {
  for (int i = 0; i < m->point_count; ++i)
    if (fabsf(m->points[i].separation - TB_SPECULATIVE_DISTANCE) < tol) return true;
  return false;
}

static bool has_point(const tb_manifold* m, tb_vec2 p, float tol) {
  for (int i = 0; i < m->point_count; ++i)
    if (fabsf(m->points[i].point.x - p.x) <= tol && fabsf(m->points[i].point.y - p.y) <= tol) return true;
  return false;
}

/* How far apart the two orders' points may be (file comment). */
#define SWAP_POINT_TOL 1e-4f

/* Points closer than tol are one contact: a clip at the edge of a tolerance
 * band may add a second point on top of the first in one order only (the
 * solver takes such a pair one point after the other). */
static int distinct_points(const tb_manifold* m, float tol) {
  if (m->point_count == 2 && fabsf(m->points[0].point.x - m->points[1].point.x) <= tol &&
      fabsf(m->points[0].point.y - m->points[1].point.y) <= tol)
    return 1;
  return m->point_count;
}

/* How far the manifold's points (and, in normal_spread, its normal's
 * components) move when A turns or shifts by a few rounding units. The two
 * orders compute in different frames, so their inputs differ by about that
 * much; where the answer is ill-conditioned it moves further (a clip point on
 * an incident edge that crosses a side plane at a grazing angle amplifies a
 * rounding of 1e-6 m a few hundred times), and the swapped order's points are
 * allowed twice that far off (the moves probe six directions, the other
 * order's rounding may lie between them); where a move changes the point count
 * the configuration sits on a discontinuity and the points are not compared. */
static const float rounding_moves[6][3] = {/* turn (rad), shift x, shift y (m) */
                                           {4e-6f, 0.0f, 0.0f},  {-4e-6f, 0.0f, 0.0f}, {0.0f, 4e-6f, 0.0f},
                                           {0.0f, -4e-6f, 0.0f}, {0.0f, 0.0f, 4e-6f},  {0.0f, 0.0f, -4e-6f}};

static tb_manifold moved_collide(const shape* a, tb_transform xa, const shape* b, tb_transform xb, int k) {
  float d = rounding_moves[k][0];
  tb_transform x = {{xa.p.x + rounding_moves[k][1], xa.p.y + rounding_moves[k][2]},
                    {xa.q.c - d * xa.q.s, xa.q.s + d * xa.q.c}};
  return collide(a, x, b, xb);
}

static float rounding_spread(const shape* a, tb_transform xa, const shape* b, tb_transform xb, const tb_manifold* m,
                             float* normal_spread) {
  float spread = 0.0f;
  *normal_spread = 0.0f;
  for (int k = 0; k < 6; ++k) {
    tb_manifold p = moved_collide(a, xa, b, xb, k);
    /* every move probes the normal, also after one that changed the count */
    if (m->point_count > 0 && p.point_count > 0)
      *normal_spread = fmaxf(*normal_spread, fmaxf(fabsf(p.normal.x - m->normal.x), fabsf(p.normal.y - m->normal.y)));
    if (distinct_points(&p, SWAP_POINT_TOL) != distinct_points(m, SWAP_POINT_TOL))
      spread = INFINITY; /* at a discontinuity */
    for (int i = 0; i < m->point_count; ++i) {
      float nearest = INFINITY;
      for (int j = 0; j < p.point_count; ++j)
        nearest = fminf(nearest,
                        hypotf(p.points[j].point.x - m->points[i].point.x, p.points[j].point.y - m->points[i].point.y));
      spread = fmaxf(spread, nearest);
    }
  }
  return spread;
}

/* Does a move of A by a few rounding units give this order the swapped
 * order's point count? Then the two orders straddle one of the engine's
 * thresholds (a slab tolerance, the rounded-corner test) by a rounding
 * difference, and either count is right. */
static bool count_within_rounding(const shape* a, tb_transform xa, const shape* b, tb_transform xb, int count) {
  for (int k = 0; k < 6; ++k) {
    tb_manifold p = moved_collide(a, xa, b, xb, k);
    if (distinct_points(&p, SWAP_POINT_TOL) == count) return true;
  }
  return false;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz_input in = {data, size, 0};
  const int* pair = pairs[fuzz_u8(&in) % 12];
  shape a, b;
  make_shape(&in, pair[0], &a);
  make_shape(&in, pair[1], &b);
  tb_transform xa = make_transform(&in), xb = make_transform(&in);
  tb_clear_error();
  tb_manifold m = collide(&a, xa, &b, xb);
  FUZZ_CHECK(tb_last_result() == TB_OK, "valid input refused: %s", tb_last_error());
  check_manifold(&m, "a-b");
  /* the same relative placement, both moved by one rigid motion: same answer
   * moved (checked for the count only where no point sits at the limit) */
  if (pair[0] == pair[1]) {
    tb_manifold r = collide(&b, xb, &a, xa);
    check_manifold(&r, "b-a");
    const float tol = SWAP_POINT_TOL;
    /* the deepest point of either order gives the core distance */
    float deepest = INFINITY;
    for (int i = 0; i < m.point_count; ++i) deepest = fminf(deepest, m.points[i].separation);
    for (int i = 0; i < r.point_count; ++i) deepest = fminf(deepest, r.points[i].separation);
    float ra = a.type == 0 ? a.circle.radius : a.type == 1 ? a.capsule.radius : a.polygon.radius;
    float rb = b.type == 0 ? b.circle.radius : b.type == 1 ? b.capsule.radius : b.polygon.radius;
    /* round cores (points, segments) that touch or cross have no normal of
     * their own; polygon cores always have a face, unless two faces tie */
    bool defined = m.point_count + r.point_count == 0 || deepest + ra + rb > 1e-3f;
    if (a.type == 3) defined = face_margin(&a.polygon, xa, &b.polygon, xb) > 1e-3f;
    if (a.type == 1) { /* a capsule core is a two-sided edge: a 2-vertex polygon */
      tb_polygon ca = capsule_core(&a.capsule), cb = capsule_core(&b.capsule);
      defined = defined && face_margin(&ca, xa, &cb, xb) > 1e-3f;
    }
    if (!defined) return 0;
    int count = distinct_points(&m, tol), swapped = distinct_points(&r, tol);
    if (count != swapped) {
      /* One point or two may hang on a rounding difference. So may a
       * speculative point (shapes apart): where a grazing incident edge
       * crosses the slab tolerance, the clip cuts at the side plane while the
       * rounded-corner test switched at the tolerance, and the separation
       * jumps by tolerance / slope (centimetres), across the speculative
       * limit. A touching contact against none is never excused. */
      bool straddle = deepest > 0.0f || (count > 0 && swapped > 0 && count_within_rounding(&a, xa, &b, xb, swapped));
      FUZZ_CHECK(near_limit(&m, 1e-3f) || near_limit(&r, 1e-3f) || straddle, "swap: %d points, swapped %d", count,
                 swapped);
      return 0;
    }
    if (count == 0) return 0;
    float normal_spread;
    float point_tol = tol + 2.0f * rounding_spread(&a, xa, &b, xb, &m, &normal_spread);
    float normal_tol = 1e-3f + 2.0f * normal_spread;
    FUZZ_CHECK(fabsf(m.normal.x + r.normal.x) < normal_tol && fabsf(m.normal.y + r.normal.y) < normal_tol,
               "swap: normal (%.7g, %.7g), swapped (%.7g, %.7g)", (double)m.normal.x, (double)m.normal.y,
               (double)r.normal.x, (double)r.normal.y);
    for (int i = 0; i < m.point_count; ++i) {
      FUZZ_CHECK(has_point(&r, m.points[i].point, point_tol), "swap: point (%.7g, %.7g) missing",
                 (double)m.points[i].point.x, (double)m.points[i].point.y);
    }
    for (int i = 0; i < r.point_count; ++i) {
      FUZZ_CHECK(has_point(&m, r.points[i].point, point_tol), "swap: point (%.7g, %.7g) added",
                 (double)r.points[i].point.x, (double)r.points[i].point.y);
    }
  }
  /* bad transforms: an empty manifold and an error, never a crash */
  if (in.at < in.size && (fuzz_u8(&in) & 7) == 0) {
    tb_transform bad = xa;
    bad.p.x = NAN;
    tb_clear_error();
    tb_manifold e = collide(&a, bad, &b, xb);
    FUZZ_CHECK(e.point_count == 0 && tb_last_result() == TB_ERR_INVALID_ARGUMENT, "NaN transform accepted");
  }
  return 0;
}
