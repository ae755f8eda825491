/* Continuous collision (see continuous.h for the contract).
 *
 * Each shape of a fast body is swept along the body's motion over the step:
 * its centre of mass moves linearly from center0 to center and its angle from
 * angle0 to angle (tb_sweep). Candidates come from the broad-phase trees,
 * queried with a box that holds the whole swept shape; each is tested with the
 * conservative-advancement time of impact, which never steps past the first
 * time the gap between the surfaces falls to the target. The body then goes
 * back to the earliest such time.
 *
 * Why the query box holds the swept shape. A core point at r from the centre
 * of mass is at c(t) + R(a(t)) r. The centre term is linear in t, so the
 * point's distance from the straight line between its two end positions (which
 * the union of the start and end boxes holds) is that of the rotation term
 * alone: |R(a(t)) r - lerp(R(a1) r, R(a2) r, t)|. With turn d = |a2 - a1| this
 * is at most |r| d / 2 (each end is at most an arc away: (1 - t) d t + t d
 * (1 - t) <= d / 2), at most |r| d^2 / 8 per axis (a function that vanishes at
 * both ends, of second derivative at most |r| d^2) and at most 2 |r|. The box
 * is grown by |r|max times the least of the three. */
#include "continuous.h"

#include <float.h>

#include "broad_phase.h"
#include "contact.h"
#include "distance.h"
#include "geometry.h"
#include "joint.h"
#include "math_internal.h"
#include "world.h"

/* A shape closing in on a chain segment by less than this fraction of its
 * thinnest half-width cannot cross it within the step: the segment's contact
 * handles it. This keeps a body sliding fast along a chain from stopping at
 * every joint between segments. */
#define CHAIN_APPROACH_FRACTION 0.25f
/* Radius of the core disc swept for a pair that already touches at t = 0, as a
 * fraction of the shape's thinnest half-width. */
#define CORE_FRACTION 0.25f

/* Centroid in body coordinates. */
static tb_vec2 shape_centroid(const tb_shape* s) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return s->geom.circle.center;
    case TB_SHAPE_CAPSULE: return tb_lerp(s->geom.capsule.center1, s->geom.capsule.center2, 0.5f);
    case TB_SHAPE_SEGMENT: return tb_lerp(s->geom.segment.point1, s->geom.segment.point2, 0.5f);
    case TB_SHAPE_CHAIN_SEGMENT:
      return tb_lerp(s->geom.chain_segment.segment.point1, s->geom.chain_segment.segment.point2, 0.5f);
    case TB_SHAPE_POLYGON: break;
  }
  return s->geom.polygon.centroid;
}

/* Thinnest half-width: the least distance from the centroid to the surface
 * (0 for segments, which have no inside). */
static float shape_min_extent(const tb_shape* s) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return s->geom.circle.radius;
    case TB_SHAPE_CAPSULE: return s->geom.capsule.radius;
    case TB_SHAPE_SEGMENT:
    case TB_SHAPE_CHAIN_SEGMENT: return 0.0f;
    case TB_SHAPE_POLYGON: break;
  }
  const tb_polygon* p = &s->geom.polygon;
  float least = FLT_MAX;
  for (int i = 0; i < p->count; ++i) least = tb_minf(least, tb_dot(p->normals[i], tb_sub(p->vertices[i], p->centroid)));
  return tb_maxf(least, 0.0f) + p->radius;
}

static bool boxes_overlap(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

/* One shape of the fast body being swept. */
typedef struct sweep_context {
  tb_world* w;
  int body;  /* the fast body's slot */
  int shape; /* the swept shape's slot */
  const tb_shape* s;
  tb_shape_proxy proxy;
  tb_sweep sweep;
  tb_aabb box;        /* holds the shape over the whole sweep */
  tb_transform start; /* the body's pose at t = 0 */
  tb_vec2 centroid_local;
  tb_vec2 centroid1, centroid2; /* world, at t = 0 and t = 1 */
  float extent;                 /* the shape's thinnest half-width */
  bool bullet;                  /* candidates may be kinematic or dynamic */
  float t;                      /* earliest impact so far; 1 = none */
} sweep_context;

typedef enum toi_kind {
  TOI_NONE,      /* no impact before t_max */
  TOI_IMPACT,    /* the gap reaches the target at t > 0 */
  TOI_AT_START,  /* the gap is at the target already at t = 0 */
  TOI_OVERLAPPED /* closer than the target at t = 0 */
} toi_kind;

/* Time of impact of the swept proxy against a fixed one, searched in [0, t_max);
 * *start_distance: their cores' distance at t = 0 (0 where they overlap). */
static toi_kind impact(const tb_shape_proxy* fixed, const tb_sweep* fixed_sweep, const tb_shape_proxy* moving,
                       const tb_sweep* moving_sweep, float t_max, float* t, float* start_distance) {
  tb_toi_input in = {*fixed, *moving, *fixed_sweep, *moving_sweep, t_max, TB_TOI_TARGET, TB_TOI_TOLERANCE};
  tb_toi_output out;
  tb_time_of_impact_unchecked(&in, &out, start_distance);
  switch (out.state) {
    case TB_TOI_SEPARATED: return TOI_NONE;
    case TB_TOI_OVERLAPPED: return TOI_OVERLAPPED;
    case TB_TOI_HIT:
    case TB_TOI_FAILED: /* t is still a safe time: the gap stays above target up to it */
      if (out.fraction > 0.0f) {
        *t = out.fraction;
        return TOI_IMPACT;
      }
      return TOI_AT_START;
  }
  return TOI_NONE;
}

/* A chain segment is one-sided: the shape must start on its front (left) side
 * and close in on it far enough to be able to cross it. */
static bool chain_faces(const sweep_context* sc, const tb_shape* chain, tb_transform xf) {
  const tb_segment* g = &chain->geom.chain_segment.segment;
  tb_vec2 p1 = tb_transform_point(xf, g->point1);
  tb_vec2 n = tb_normalize(tb_left_perp(tb_rotate(xf.q, tb_sub(g->point2, g->point1))));
  float offset1 = tb_dot(tb_sub(sc->centroid1, p1), n), offset2 = tb_dot(tb_sub(sc->centroid2, p1), n);
  if (offset1 < 0.0f) return false;
  return offset1 - offset2 >= CHAIN_APPROACH_FRACTION * sc->extent && offset1 > offset2;
}

/* Whether the step drives a core that starts at the target gap (or closer)
 * into the obstacle: its centre moves towards the obstacle by more than its
 * radius (never when the centre starts inside: then there is no normal).
 * Left alone, such a core went through: a small box knocked into a wall's
 * corner by a faster box was stopped with its core at the target gap, and
 * the next knock carried it into the wall (issue 23). A body sliding along
 * the surface moves its core along it, not into it, and is still left alone. */
static bool core_driven_in(const sweep_context* sc, const tb_shape_proxy* other, tb_transform other_xf,
                           const tb_shape_proxy* core) {
  tb_distance_input in = {*other, *core, other_xf, tb_sweep_transform(&sc->sweep, 0.0f)};
  tb_simplex_cache cache = {0};
  tb_distance_output out;
  if (tb_shape_distance(&in, &cache, &out) != TB_OK) return false;
  tb_vec2 moved = tb_sub(sc->centroid2, sc->centroid1);
  return tb_dot(moved, out.normal) < -core->radius; /* normal: from the obstacle to the core */
}

/* How far two convex polygon cores overlap: the length of the least
 * translation that parts them, 0 when apart. In the plane that translation is
 * along a face normal of one of them (separating axis theorem): along face i
 * of P (normal n, vertex v) the other reaches min_w n . (w - v) beyond it,
 * and the overlap is minus the largest of those over both polygons' faces. */
static float polygon_overlap(const tb_polygon* a, tb_transform xa, const tb_polygon* b, tb_transform xb) {
  tb_vec2 wa[TB_MAX_POLYGON_VERTICES], wb[TB_MAX_POLYGON_VERTICES];
  for (int i = 0; i < a->count; ++i) wa[i] = tb_transform_point(xa, a->vertices[i]);
  for (int i = 0; i < b->count; ++i) wb[i] = tb_transform_point(xb, b->vertices[i]);
  float most = -FLT_MAX;
  for (int side = 0; side < 2; ++side) {
    const tb_polygon* p = side == 0 ? a : b;
    tb_rot q = side == 0 ? xa.q : xb.q;
    const tb_vec2* pv = side == 0 ? wa : wb;
    const tb_vec2* ov = side == 0 ? wb : wa;
    int other_count = side == 0 ? b->count : a->count;
    for (int i = 0; i < p->count; ++i) {
      tb_vec2 n = tb_rotate(q, p->normals[i]);
      float reach = FLT_MAX;
      for (int j = 0; j < other_count; ++j) reach = tb_minf(reach, tb_dot(n, tb_sub(ov[j], pv[i])));
      most = tb_maxf(most, reach);
    }
  }
  return tb_maxf(-most, 0.0f);
}

/* Whether a touching shape's core cannot come within the target gap of the
 * obstacle during the sweep, so that sweeping it would find nothing. The
 * shape holds the disc of radius extent about its centroid (extent is its
 * thinnest half-width); if it overlaps the obstacle (convex) by depth p, the
 * least move that parts them leaves that disc outside, so the centroid is at
 * least extent - p from the obstacle now, and the core's surface extent - p
 * - CORE_FRACTION extent. With the cores apart, p is the radii less their
 * distance (0 if positive); with the cores overlapping it is their overlap
 * plus the radii, which polygon_overlap finds for two polygons (a box
 * sliding on a box; for other shapes no answer). Over the sweep the core moves no further than its centroid. One
 * tolerance more than the search's is kept, against rounding. */
static bool core_out_of_reach(const sweep_context* sc, const tb_shape* other, tb_transform other_xf, float radii,
                              float core_distance) {
  float depth;
  if (core_distance > 0.0f)
    depth = tb_maxf(radii - core_distance, 0.0f);
  else if (sc->s->type == TB_SHAPE_POLYGON && other->type == TB_SHAPE_POLYGON)
    depth = polygon_overlap(&sc->s->geom.polygon, sc->start, &other->geom.polygon, other_xf) + radii;
  else
    return false;
  float core_gap = (1.0f - CORE_FRACTION) * sc->extent - depth;
  /* how far the centroid can move: |dc| + |r| |da|, r its arm from the centre of mass */
  const tb_sweep* sw = &sc->sweep;
  float travel = tb_length(tb_sub(sw->c2, sw->c1)) +
                 tb_length(tb_sub(sc->centroid_local, sw->local_center)) * fabsf(sw->a2 - sw->a1);
  return core_gap - travel > TB_TOI_TARGET + 2.0f * TB_TOI_TOLERANCE;
}

static bool candidate(int32_t proxy, int32_t other_index, void* context) {
  (void)proxy;
  sweep_context* sc = context;
  tb_world* w = sc->w;
  const tb_shape* o = tb_shape_at(w, other_index);
  if (o->body == sc->body || o->sensor) return true;
  const tb_body* ob = tb_body_at(w, o->body);
  if (ob->type != TB_STATIC_BODY && !sc->bullet) return true;
  if (ob->type == TB_DYNAMIC_BODY && ob->is_bullet) return true; /* bullet against bullet: the contact's */
  if (!tb_filters_collide(sc->s->filter, o->filter) || !tb_shape_types_collide(sc->s->type, o->type)) return true;
  tb_sweep fixed = {ob->local_center, ob->center, ob->center, ob->angle, ob->angle};
  tb_transform xf = tb_sweep_transform(&fixed, 0.0f);
  tb_aabb tight = ob->type == TB_STATIC_BODY ? o->aabb : tb_shape_geom_aabb(o, xf);
  if (!boxes_overlap(tight, sc->box)) return true;
  if (o->type == TB_SHAPE_CHAIN_SEGMENT && !chain_faces(sc, o, xf)) return true;
  if (w->pre_solve != NULL && (sc->s->enable_pre_solve_events || o->enable_pre_solve_events)) return true;
  if (ob->joint_count > 0 && tb_body_at(w, sc->body)->joint_count > 0 &&
      !tb_joints_allow_collision(w, sc->body, o->body))
    return true;
  if (w->custom_filter != NULL &&
      !w->custom_filter(tb_make_shape_id(w, sc->shape), tb_make_shape_id(w, other_index), w->custom_filter_context))
    return true;

  tb_shape_proxy other = tb_shape_geom_proxy(o);
  float t = sc->t, start_distance;
  toi_kind k = impact(&other, &fixed, &sc->proxy, &sc->sweep, sc->t, &t, &start_distance);
  if ((k == TOI_AT_START || k == TOI_OVERLAPPED) && sc->extent > 0.0f) {
    /* Already touching: the contact owns the pair and the body is not held
     * back (holding it would stop it sliding along the surface). Only its
     * core, a disc of a quarter of the shape's thinnest half-width about its
     * centroid, is still swept: if the contact loses the body, the core stops
     * at the target gap instead of passing through. A core already at the
     * target gap at t = 0 is left alone too: holding it there can keep the
     * body, and the velocity the solver gave it, in place for good. */
    if (core_out_of_reach(sc, o, xf, sc->proxy.radius + other.radius, start_distance))
      return true; /* (a ball rolling on the ground: its core stays far above it) */
    tb_shape_proxy core = tb_make_proxy(&sc->centroid_local, 1, CORE_FRACTION * sc->extent);
    k = impact(&other, &fixed, &core, &sc->sweep, sc->t, &t, &start_distance);
    /* not a jointed body: held at its start while its partners moved on, it
     * opened its joints by the whole step and their correction threw it (a
     * ragdoll at 1/30 s with one substep reached 580 m/s) */
    if ((k == TOI_AT_START || k == TOI_OVERLAPPED) && tb_body_at(sc->w, sc->body)->joint_count == 0 &&
        core_driven_in(sc, &other, xf, &core)) {
      t = 0.0f; /* the body stays where it started; the contact pushes it out */
      k = TOI_IMPACT;
    }
  }
  if (k == TOI_IMPACT && t < sc->t) sc->t = t;
  return true;
}

/* Sweeps every non-sensor shape of a fast body; moves it back to the earliest
 * impact. */
static void sweep_body(tb_world* w, int body_index, bool bullet) {
  tb_body* b = tb_body_at(w, body_index);
  sweep_context sc = {.w = w, .body = body_index, .bullet = bullet, .t = 1.0f};
  sc.sweep = (tb_sweep){b->local_center, b->center0, b->center, b->angle0, b->angle};
  tb_transform xf1 = tb_sweep_transform(&sc.sweep, 0.0f), xf2 = tb_sweep_transform(&sc.sweep, 1.0f);
  sc.start = xf1;
  float turn = fabsf(b->angle - b->angle0);
  float growth = tb_minf(tb_minf(0.5f * turn, 0.125f * turn * turn), 2.0f);
  for (int i = b->shape_list; i >= 0; i = tb_shape_at(w, i)->next) {
    const tb_shape* s = tb_shape_at(w, i);
    if (s->sensor) continue;
    sc.shape = i;
    sc.s = s;
    sc.proxy = tb_shape_geom_proxy(s);
    sc.centroid_local = shape_centroid(s);
    sc.centroid1 = tb_transform_point(xf1, sc.centroid_local);
    sc.centroid2 = tb_transform_point(xf2, sc.centroid_local);
    sc.extent = shape_min_extent(s);
    float reach2 = 0.0f;
    for (int k = 0; k < sc.proxy.count; ++k)
      reach2 = tb_maxf(reach2, tb_distance_sq(sc.proxy.points[k], b->local_center));
    float grow = growth * sqrtf(reach2);
    tb_aabb a1 = tb_shape_geom_aabb(s, xf1), a2 = tb_shape_geom_aabb(s, xf2);
    sc.box = (tb_aabb){{tb_minf(a1.lower.x, a2.lower.x) - grow, tb_minf(a1.lower.y, a2.lower.y) - grow},
                       {tb_maxf(a1.upper.x, a2.upper.x) + grow, tb_maxf(a1.upper.y, a2.upper.y) + grow}};
    /* The tree holds each proxy's category bits: the mask prunes, unless a
     * group (which overrides the bits) may be shared. */
    uint64_t mask = s->filter.group_index == 0 ? s->filter.mask_bits : UINT64_MAX;
    tb_tree_query(&w->broad_phase.trees[TB_STATIC_BODY], sc.box, mask, candidate, &sc);
    if (bullet) {
      tb_tree_query(&w->broad_phase.trees[TB_KINEMATIC_BODY], sc.box, mask, candidate, &sc);
      tb_tree_query(&w->broad_phase.trees[TB_DYNAMIC_BODY], sc.box, mask, candidate, &sc);
    }
  }
  if (sc.t < 1.0f) {
    float t = sc.t;
    b->center = tb_lerp(b->center0, b->center, t);
    b->center_residual = (tb_vec2){0.0f, 0.0f};
    b->angle = b->angle0 + t * (b->angle - b->angle0);
    b->angle_residual = 0.0f;
    tb_body_sync_transform(b);
  }
}

static bool found_one(int32_t proxy, int32_t user_id, void* context) {
  (void)proxy;
  (void)user_id;
  *(bool*)context = true;
  return false; /* one is enough */
}

/* Whether a fast body's sweep can meet anything of the static tree: whether
 * its swept box (both ends, grown by its extent and by the turn's bulge,
 * which covers each shape's box in sweep_body) overlaps a static proxy's.
 * Most fast bodies are away from the static world (a swinging grid, debris in
 * the air, the middle of a pile in a bin): they skip the transforms, the
 * shapes' boxes and their queries, which would find nothing. */
static bool may_reach_static(const tb_world* w, const tb_body* b) {
  const tb_tree* tree = &w->broad_phase.trees[TB_STATIC_BODY];
  if (tree->root == TB_TREE_NULL) return false;
  float turn = fabsf(b->angle - b->angle0);
  float r = b->max_extent * (1.0f + tb_minf(tb_minf(0.5f * turn, 0.125f * turn * turn), 2.0f));
  tb_aabb box = {{tb_minf(b->center0.x, b->center.x) - r, tb_minf(b->center0.y, b->center.y) - r},
                 {tb_maxf(b->center0.x, b->center.x) + r, tb_maxf(b->center0.y, b->center.y) + r}};
  bool found = false;
  (void)tb_tree_query(tree, box, UINT64_MAX, found_one, &found);
  return found;
}

int tb_solve_continuous(tb_world* w) {
  if (!w->enable_continuous) return 0;
  /* Fast bodies against the static world first, then bullets, which also see
   * where the other moving bodies ended. */
  int bullets = 0, swept = 0;
  for (int i = 0; i < w->awake_count; ++i) {
    int index = w->awake[i];
    const tb_body* b = tb_body_at(w, index);
    if (b->type != TB_DYNAMIC_BODY || !(b->is_fast || b->is_bullet)) continue;
    swept += 1;
    if (b->is_bullet) {
      bullets += 1;
      continue;
    }
    if (may_reach_static(w, b)) sweep_body(w, index, false);
  }
  for (int i = 0; i < w->awake_count && bullets > 0; ++i) {
    int index = w->awake[i];
    const tb_body* b = tb_body_at(w, index);
    if (b->type != TB_DYNAMIC_BODY || !b->is_bullet) continue;
    bullets -= 1;
    sweep_body(w, index, true);
  }
  return swept;
}
