/* Chains: creation as one-sided segment shapes with ghost vertices, and the
 * manifolds of a chain segment.
 *
 * A chain segment collides like a plain segment, then the result is filtered:
 * - one-sided: nothing whose centre lies behind the segment (its right side),
 *   and no normal pointing behind it;
 * - ghost vertices: a contact whose normal is not the segment's face normal
 *   comes from a segment end (a vertex region). At a flat or concave joint
 *   that region belongs to the neighbour's face, so the contact is dropped (a
 *   box sliding over the joint never meets a tilted normal and does not catch);
 *   at a convex joint the region is shared, and the segment whose face normal
 *   is closer to the contact normal keeps it, so exactly one reports it. */
#include "memory.h"
#include "chain.h"

#include <float.h>
#include <stdlib.h>

#include "geometry.h"
#include "manifold.h"
#include "math_internal.h"
#include "world.h"
#include "units.h"

tb_chain_def tb_default_chain_def(void) {
  return (tb_chain_def){.friction = 0.6f, .filter = tb_default_filter(), .enable_sensor_events = true};
}

static tb_chain* chain_at(const tb_world* w, int i) { return (tb_chain*)tb_pool_at(&w->chains, i); }

static tb_chain_id make_chain_id(const tb_world* w, int index) {
  return (tb_chain_id){index + 1, w->index, w->chains.generations[index]};
}

static void free_chain(tb_world* w, int index) {
  tb_chain* c = chain_at(w, index);
  tb_mem_free(c->shapes, (size_t)c->count * sizeof *c->shapes);
  tb_pool_release(&w->chains, index);
}

/* Segment i of the chain as a shape, its ghost vertices from its neighbours. */
static tb_shape segment_proto(const tb_chain_def* def, int chain, int i) {
  int n = def->count, i0 = i - 1, i2 = i + 1, i3 = i + 2;
  if (def->is_loop) {
    i0 = (i0 + n) % n;
    i2 %= n;
    i3 %= n;
  }
  const tb_vec2* p = def->points;
  tb_shape proto = {.type = TB_SHAPE_CHAIN_SEGMENT,
                    .friction = def->friction,
                    .restitution = def->restitution,
                    .filter = def->filter,
                    .enable_sensor_events = def->enable_sensor_events,
                    .enable_contact_events = true,
                    .chain = chain,
                    .user_data = def->user_data};
  proto.geom.chain_segment = (tb_chain_segment){i0 >= 0 ? p[i0] : p[i], {p[i], p[i2]}, i3 < n ? p[i3] : p[i2]};
  return proto;
}

/* Every check and every allocation comes before the first segment is linked,
 * so a refused chain leaves the world exactly as it was (its trees too). */
tb_chain_id tb_create_chain(tb_body_id body_id, const tb_chain_def* def) {
  const tb_chain_id null_id = {0, 0, 0};
  const char* fn = "tb_create_chain";
  tb_world* w = NULL;
  tb_body* b = tb_body_get_unlocked(body_id, &w, fn);
  if (b == NULL) return null_id;
  if (def == NULL || def->points == NULL) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, def == NULL ? "def" : "def->points");
    return null_id;
  }
  int n = def->count;
  if (n < (def->is_loop ? 3 : 2)) {
    tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->count = %d, need at least %d points", fn, n, def->is_loop ? 3 : 2);
    return null_id;
  }
  if (tb_check_non_negative(w, fn, "def->friction", def->friction) ||
      tb_check_restitution(w, fn, "def->restitution", def->restitution))
    return null_id;
  for (int i = 0; i < n; ++i) {
    if (!tb_point_ok(def->points[i])) {
      tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->points[%d] is not finite or beyond TB_MAX_LENGTH", fn, i);
      return null_id;
    }
    int j = i + 1 < n ? i + 1 : 0;
    if ((j > 0 || def->is_loop) &&
        tb_distance_sq(def->points[i], def->points[j]) < tb_units.linear_slop * tb_units.linear_slop) {
      tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->points[%d] and [%d] are closer than TB_LINEAR_SLOP", fn, i, j);
      return null_id;
    }
  }
  int body = body_id.index1 - 1;
  int segments = def->is_loop ? n : n - 1;
  for (int i = 0; i < segments; ++i) {
    tb_shape proto = segment_proto(def, -1, i);
    if (tb_shape_prepare(w, body, &proto, segments, fn) != TB_OK) return null_id;
  }
  int index = tb_pool_alloc(&w->chains);
  int* shapes = index >= 0 ? tb_mem_alloc((size_t)segments * sizeof *shapes) : NULL;
  int allocated = 0;
  while (shapes != NULL && allocated < segments && (shapes[allocated] = tb_pool_alloc(&w->shapes)) >= 0) allocated += 1;
  if (allocated < segments) {
    while (allocated > 0) tb_pool_release(&w->shapes, shapes[--allocated]);
    tb_mem_free(shapes, (size_t)segments * sizeof *shapes);
    if (index >= 0) tb_pool_release(&w->chains, index);
    tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for %d segments", fn, segments);
    return null_id;
  }
  tb_chain* c = chain_at(w, index);
  *c = (tb_chain){body, shapes, segments, def->is_loop};
  for (int i = 0; i < segments; ++i) {
    tb_shape proto = segment_proto(def, index, i);
    tb_shape_link(w, body, shapes[i], &proto);
  }
  tb_body_update_mass(w, tb_body_at(w, body)); /* no mass, but the centre may move */
  return make_chain_id(w, index);
}

tb_result tb_destroy_chain(tb_chain_id id) {
  tb_world* w = NULL;
  tb_chain* c = tb_chain_get(id, &w, "tb_destroy_chain");
  if (c == NULL) return tb_last_result();
  if (w->locked)
    return tb_fail(w, TB_ERR_LOCKED,
                   "tb_destroy_chain: the world is locked (inside tb_world_step, or a query or draw callback)");
  int body = c->body;
  for (int k = 0; k < c->count; ++k) tb_shape_detach(w, c->shapes[k]);
  free_chain(w, id.index1 - 1);
  tb_body_update_mass(w, tb_body_at(w, body));
  tb_wake_body(w, body);
  return TB_OK;
}

bool tb_chain_is_valid(tb_chain_id id) { return tb_chain_get(id, NULL, NULL) != NULL; }

int tb_chain_get_segment_count(tb_chain_id id) {
  tb_chain* c = tb_chain_get(id, NULL, "tb_chain_get_segment_count");
  return c != NULL ? c->count : 0;
}

int tb_chain_get_segments(tb_chain_id id, tb_shape_id* out, int capacity) {
  tb_world* w = NULL;
  tb_chain* c = tb_chain_get(id, &w, "tb_chain_get_segments");
  if (c == NULL) return 0;
  if (out == NULL && capacity > 0) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "tb_chain_get_segments: out is NULL");
    return 0;
  }
  if (capacity < 0) {
    tb_fail(w, TB_ERR_INVALID_ARGUMENT, "tb_chain_get_segments: capacity = %d is negative", capacity);
    return 0;
  }
  int n = 0;
  for (; n < c->count && n < capacity; ++n) out[n] = tb_make_shape_id(w, c->shapes[n]);
  return n;
}

void tb_chains_destroy_of_body(tb_world* w, int body) {
  for (int i = 0; i < w->chains.high; ++i)
    if (tb_pool_alive(&w->chains, i) && chain_at(w, i)->body == body) free_chain(w, i);
}

void tb_chains_free(tb_world* w) {
  for (int i = 0; i < w->chains.high; ++i)
    if (tb_pool_alive(&w->chains, i)) {
      tb_chain* c = chain_at(w, i);
      tb_mem_free(c->shapes, (size_t)c->count * sizeof *c->shapes);
    }
}

size_t tb_chains_bytes(const tb_world* w) {
  size_t bytes = 0;
  for (int i = 0; i < w->chains.high; ++i)
    if (tb_pool_alive(&w->chains, i)) bytes += (size_t)chain_at(w, i)->count * sizeof *chain_at(w, i)->shapes;
  return bytes;
}

/* ---- manifolds ---------------------------------------------------------- */

static const tb_manifold no_contact = {.point_count = 0};

/* A chain segment as the public functions check it: its segment as a
 * segment shape, and ghost vertices that are finite points. */
static const char* check_chain_segment(const tb_chain_segment* cs) {
  const char* why = tb_check_segment(&cs->segment);
  if (why == NULL && !(tb_point_ok(cs->ghost1) && tb_point_ok(cs->ghost2)))
    why = "chain segment ghost vertices are not finite or beyond TB_MAX_LENGTH";
  return why;
}

/* Whether the chain runs on past a segment end without a convex corner (flat
 * or concave joint): the neighbour's face takes over from this one there.
 * turn: the cross product of the earlier and the later edge at the joint. */
static bool runs_on(tb_vec2 neighbour, float turn) { return tb_length_sq(neighbour) > 0.0f && turn >= 0.0f; }

/* The filter described at the top, in the chain segment's frame. center_b is
 * B's centre (world). A face contact's patch (tb_patch) does not end at a
 * flat or concave joint: what slides past it is on the neighbour's face.
 *
 * *on_face is set where the manifold's normal is not the face's and the end
 * it lies at is a flat or concave joint: a vertex contact there belongs to
 * the neighbour's face, but so does not a face of B that rests tilted on
 * this segment (B's face separates more than the segment's where the segment
 * is short against B: on a curve of short segments, no segment is flush with
 * a box, and dropping every tilted face let boxes of a pile sink through a
 * concave chain). The caller collides B on this face instead (its points
 * within this segment's extent). */
static tb_manifold one_sided(const tb_chain_segment* cs, tb_transform xfa, tb_vec2 center_b, tb_manifold m,
                             tb_patch* patch, bool* on_face) {
  *on_face = false;
  tb_vec2 p1 = cs->segment.point1, p2 = cs->segment.point2;
  tb_vec2 e = tb_sub(p2, p1);
  tb_vec2 n = tb_normalize(tb_left_perp(e));
  if (tb_dot(tb_sub(tb_inv_transform_point(xfa, center_b), p1), n) < 0.0f) return no_contact;
  if (m.point_count == 0) return m;
  tb_vec2 nm = tb_inv_rotate(xfa.q, m.normal);
  float face = tb_dot(nm, n);
  if (face <= 0.0f) return no_contact;
  if (face >= 1.0f - 1.0e-4f) {
    /* the patch's tangent right_perp(n) runs along e: slide_max at p2 */
    tb_vec2 before = tb_sub(p1, cs->ghost1), after = tb_sub(cs->ghost2, p2);
    if (patch != NULL && runs_on(before, tb_cross(before, e))) patch->slide_min = -FLT_MAX;
    if (patch != NULL && runs_on(after, tb_cross(e, after))) patch->slide_max = FLT_MAX;
    return m;
  }
  /* a vertex region: which end is it at? */
  tb_vec2 local = tb_inv_transform_point(xfa, m.points[0].point);
  bool at_start = tb_dot(tb_sub(local, p1), e) < 0.5f * tb_dot(e, e);
  tb_vec2 neighbour = at_start ? tb_sub(p1, cs->ghost1) : tb_sub(cs->ghost2, p2);
  if (tb_length_sq(neighbour) == 0.0f) return m; /* the open end of a chain: a real corner */
  /* convex for a left-facing chain: the path turns clockwise at the joint */
  float turn = at_start ? tb_cross(neighbour, e) : tb_cross(e, neighbour);
  if (runs_on(neighbour, turn)) { /* flat or concave: the neighbour's face, or this one (see on_face) */
    *on_face = true;
    return no_contact;
  }
  tb_vec2 nn = tb_normalize(tb_left_perp(neighbour));
  float other = tb_dot(nm, nn);
  bool mine = at_start ? face > other : face >= other; /* ties go to the earlier segment */
  return mine ? m : no_contact;
}

tb_manifold tb_collide_chain_segment_and_circle_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                          const tb_circle* b, tb_transform xfb, tb_patch* patch) {
  tb_manifold m = tb_collide_segment_and_circle_unchecked(&a->segment, xfa, b, xfb, patch);
  if (m.point_count == 0) return m;
  /* a circle off the face's normal touches an end: on_face has no points */
  bool on_face;
  return one_sided(a, xfa, tb_transform_point(xfb, b->center), m, patch, &on_face);
}

tb_manifold tb_collide_chain_segment_and_capsule_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                           const tb_capsule* b, tb_transform xfb, tb_patch* patch) {
  tb_manifold m = tb_collide_segment_and_capsule_unchecked(&a->segment, xfa, b, xfb, patch);
  if (m.point_count == 0) return m;
  tb_vec2 center = tb_transform_point(xfb, tb_lerp(b->center1, b->center2, 0.5f));
  bool on_face;
  m = one_sided(a, xfa, center, m, patch, &on_face);
  if (!on_face) return m;
  m = tb_collide_segment_face_and_capsule_unchecked(&a->segment, xfa, b, xfb, patch);
  return m.point_count == 0 ? m : one_sided(a, xfa, center, m, patch, &on_face);
}

tb_manifold tb_collide_chain_segment_and_polygon_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                           const tb_polygon* b, tb_transform xfb, tb_patch* patch) {
  tb_manifold m = tb_collide_segment_and_polygon_unchecked(&a->segment, xfa, b, xfb, patch);
  if (m.point_count == 0) return m;
  tb_vec2 center = tb_transform_point(xfb, b->centroid);
  bool on_face;
  m = one_sided(a, xfa, center, m, patch, &on_face);
  if (!on_face) return m;
  m = tb_collide_segment_face_and_polygon_unchecked(&a->segment, xfa, b, xfb, patch);
  return m.point_count == 0 ? m : one_sided(a, xfa, center, m, patch, &on_face);
}

/* The public forms check their arguments as the other tb_collide_* do (see
 * tb_collide_args_ok) and give an empty manifold on bad input. */

tb_manifold tb_collide_chain_segment_and_circle(const tb_chain_segment* a, tb_transform xfa, const tb_circle* b,
                                                tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(check_chain_segment, a), xfa, b,
                          TB_COLLIDE_WHY(tb_check_circle, b), xfb))
    return no_contact;
  return tb_collide_chain_segment_and_circle_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_chain_segment_and_capsule(const tb_chain_segment* a, tb_transform xfa, const tb_capsule* b,
                                                 tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(check_chain_segment, a), xfa, b,
                          TB_COLLIDE_WHY(tb_check_capsule, b), xfb))
    return no_contact;
  return tb_collide_chain_segment_and_capsule_unchecked(a, xfa, b, xfb, NULL);
}

tb_manifold tb_collide_chain_segment_and_polygon(const tb_chain_segment* a, tb_transform xfa, const tb_polygon* b,
                                                 tb_transform xfb) {
  if (!tb_collide_args_ok(__func__, a, TB_COLLIDE_WHY(check_chain_segment, a), xfa, b,
                          TB_COLLIDE_WHY(tb_check_polygon, b), xfb))
    return no_contact;
  return tb_collide_chain_segment_and_polygon_unchecked(a, xfa, b, xfb, NULL);
}
