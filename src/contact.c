/* Contacts: creation from broad-phase pairs, the narrow phase and its events. */
#include "contact.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "broad_phase.h"
#include "geometry.h"
#include "manifold.h"
#include "math_internal.h"
#include "world.h"
#include "units.h"

/* ---- manifold dispatch ----------------------------------------------------
 * One function per unordered pair of types, with the shape that comes first
 * in the function's name as A. A contact stores its shapes in that order.
 * Each writes the manifold into the contact; polygon pairs, the bulk of a
 * box scene, write it in place (tb_collide_polygons_into), the others copy
 * the returned one. These are the unchecked forms of the public tb_collide_*
 * functions: the shapes were vetted when they were made. */

typedef void collide_fn(const tb_shape* a, tb_transform xfa, const tb_shape* b, tb_transform xfb, tb_manifold* out,
                        tb_patch* patch);

#define COLLIDE(name, fa, fb, call)                                                                            \
  static void name(const tb_shape* a, tb_transform xfa, const tb_shape* b, tb_transform xfb, tb_manifold* out, \
                   tb_patch* patch) {                                                                          \
    *out = call(&a->geom.fa, xfa, &b->geom.fb, xfb, patch);                                                    \
  }
COLLIDE(circles, circle, circle, tb_collide_circles_unchecked)
COLLIDE(capsule_circle, capsule, circle, tb_collide_capsule_and_circle_unchecked)
COLLIDE(capsules, capsule, capsule, tb_collide_capsules_unchecked)
COLLIDE(segment_circle, segment, circle, tb_collide_segment_and_circle_unchecked)
COLLIDE(segment_capsule, segment, capsule, tb_collide_segment_and_capsule_unchecked)
COLLIDE(segment_polygon, segment, polygon, tb_collide_segment_and_polygon_unchecked)
COLLIDE(polygon_circle, polygon, circle, tb_collide_polygon_and_circle_unchecked)
COLLIDE(polygon_capsule, polygon, capsule, tb_collide_polygon_and_capsule_unchecked)
COLLIDE(chain_circle, chain_segment, circle, tb_collide_chain_segment_and_circle_unchecked)
COLLIDE(chain_capsule, chain_segment, capsule, tb_collide_chain_segment_and_capsule_unchecked)
COLLIDE(chain_polygon, chain_segment, polygon, tb_collide_chain_segment_and_polygon_unchecked)
#undef COLLIDE

static void polygons(const tb_shape* a, tb_transform xfa, const tb_shape* b, tb_transform xfb, tb_manifold* out,
                     tb_patch* patch) {
  tb_collide_polygons_into(&a->geom.polygon, xfa, &b->geom.polygon, xfb, out, patch);
}

/* [type of A][type of B]; NULL where the pair is taken the other way round */
static collide_fn* const collide_table[5][5] = {
    [TB_SHAPE_CIRCLE] = {[TB_SHAPE_CIRCLE] = circles},
    [TB_SHAPE_CAPSULE] = {[TB_SHAPE_CIRCLE] = capsule_circle, [TB_SHAPE_CAPSULE] = capsules},
    [TB_SHAPE_SEGMENT] = {[TB_SHAPE_CIRCLE] = segment_circle,
                          [TB_SHAPE_CAPSULE] = segment_capsule,
                          [TB_SHAPE_POLYGON] = segment_polygon},
    [TB_SHAPE_POLYGON] =
        {[TB_SHAPE_CIRCLE] = polygon_circle, [TB_SHAPE_CAPSULE] = polygon_capsule, [TB_SHAPE_POLYGON] = polygons},
    [TB_SHAPE_CHAIN_SEGMENT] =
        {[TB_SHAPE_CIRCLE] = chain_circle, [TB_SHAPE_CAPSULE] = chain_capsule, [TB_SHAPE_POLYGON] = chain_polygon},
};

bool tb_shape_types_collide(tb_shape_type a, tb_shape_type b) {
  return collide_table[a][b] != NULL || collide_table[b][a] != NULL;
}

/* ---- body contact lists ------------------------------------------------ */

static tb_contact* contact_at(tb_world* w, int i) { return (tb_contact*)tb_pool_at(&w->contacts, i); }

/* A contact's place in its bodies' lists: by its shapes' indices, which do
 * not depend on where the scene is. */
static uint64_t shape_pair_key(const tb_contact* c) {
  uint32_t lo = (uint32_t)(c->shape_a < c->shape_b ? c->shape_a : c->shape_b);
  uint32_t hi = (uint32_t)(c->shape_a < c->shape_b ? c->shape_b : c->shape_a);
  return (uint64_t)lo << 32 | hi;
}

/* The solver takes the contacts of the awake bodies in list order, and
 * Gauss-Seidel's result depends on the order: a moving body's list is kept
 * sorted (shape_pair_key), so that the same scene solves the same way
 * wherever it is, not in the order the broad phase happened to find its
 * pairs (which depends on the rounding of the coordinates). A static body's
 * list, never walked by the solver, takes new contacts at its head.
 * A new contact goes to the head of a moving body's list too, and the body
 * is noted; tb_contacts_sort_new then sorts the new ones and merges them into
 * the sorted rest. Sorted insertion, one walk down the list per contact, made
 * a pile-up quadratic: 1,000 bodies created at one point find 499,500 pairs
 * in one step, each walking a list of up to 999. */
static int edge_next(const tb_world* w, int key) { return contact_at((tb_world*)w, key >> 1)->edges[key & 1].next; }
static void set_edge_next(tb_world* w, int key, int next) { contact_at(w, key >> 1)->edges[key & 1].next = next; }
static uint64_t edge_order(tb_world* w, int key) { return shape_pair_key(contact_at(w, key >> 1)); }

static void link_edge(tb_world* w, int contact, int side) {
  tb_contact* c = contact_at(w, contact);
  tb_body* b = tb_body_at(w, c->edges[side].body);
  int key = contact * 2 + side;
  int prev = -1, next = b->contact_list;
  if (b->type != TB_STATIC_BODY) {
    bool noted = b->new_contact_count > 0 || tb_array_reserve((void**)&w->new_contact_bodies, &w->new_contact_capacity,
                                                              w->new_contact_body_count + 1, sizeof(int));
    if (noted) {
      if (b->new_contact_count == 0) w->new_contact_bodies[w->new_contact_body_count++] = c->edges[side].body;
      b->new_contact_count += 1;
    } else { /* out of memory: sorted insertion, as slow as it is correct */
      uint64_t order = shape_pair_key(c);
      while (next >= 0 && edge_order(w, next) < order) {
        prev = next;
        next = edge_next(w, next);
      }
    }
  }
  c->edges[side].prev = prev;
  c->edges[side].next = next;
  if (next >= 0) contact_at(w, next >> 1)->edges[next & 1].prev = key;
  if (prev >= 0)
    set_edge_next(w, prev, key);
  else
    b->contact_list = key;
  b->contact_count += 1;
}

/* Merges two sorted lists; returns the head and leaves the tail in *tail. */
static int merge_edges(tb_world* w, int p, int q, int* tail) {
  int head = -1, last = -1;
  while (p >= 0 || q >= 0) {
    int take;
    if (q < 0 || (p >= 0 && edge_order(w, p) < edge_order(w, q))) {
      take = p;
      p = edge_next(w, p);
    } else {
      take = q;
      q = edge_next(w, q);
    }
    if (last >= 0)
      set_edge_next(w, last, take);
    else
      head = take;
    last = take;
  }
  if (last >= 0) set_edge_next(w, last, -1);
  *tail = last;
  return head;
}

/* Merges the sorted new edges into the sorted rest of a body's list, links
 * both ways; returns the head. Past the last new edge the rest stays as it
 * was, links and all: the walk stops there (a spinning bar with hundreds of
 * contacts takes a few new ones a step). */
static int merge_into_rest(tb_world* w, int fresh, int rest) {
  int head = -1, last = -1;
  while (fresh >= 0) {
    int take;
    if (rest >= 0 && edge_order(w, rest) < edge_order(w, fresh)) {
      take = rest;
      rest = edge_next(w, rest);
    } else {
      take = fresh;
      fresh = edge_next(w, fresh);
    }
    if (last >= 0)
      set_edge_next(w, last, take);
    else
      head = take;
    contact_at(w, take >> 1)->edges[take & 1].prev = last;
    last = take;
  }
  set_edge_next(w, last, rest); /* there was at least one new edge */
  if (rest >= 0) contact_at(w, rest >> 1)->edges[rest & 1].prev = last;
  return head;
}

/* Sorts the first `count` edges of a list (bottom-up merge sort on the list
 * itself: O(count log count), no memory) and merges them into the sorted
 * rest. The keys are unique (one contact per pair of shapes), so the result
 * is the one sorted insertion gave. */
static int sort_new_edges(tb_world* w, int list, int count) {
  if (count <= 0) return list;
  int rest = list;
  for (int i = 0; i < count; ++i) rest = edge_next(w, rest);
  for (int width = 1; width < count; width *= 2) {
    int p = list, head = -1, tail = -1;
    for (int done = 0; done < count; done += 2 * width) {
      /* runs p (width long) and q (up to width long) at position done */
      int q = p, p_end = -1;
      for (int i = 0; i < width && done + i < count; ++i) {
        p_end = q;
        q = edge_next(w, q);
      }
      int q_len = count - done - width < width ? count - done - width : width, q_end = -1, after = q;
      for (int i = 0; i < q_len; ++i) {
        q_end = after;
        after = edge_next(w, after);
      }
      set_edge_next(w, p_end, -1);
      if (q_end >= 0) set_edge_next(w, q_end, -1);
      int merged_tail;
      int merged = merge_edges(w, p, q_len > 0 ? q : -1, &merged_tail);
      if (tail >= 0)
        set_edge_next(w, tail, merged);
      else
        head = merged;
      tail = merged_tail;
      p = after;
    }
    set_edge_next(w, tail, p); /* p: the rest, past the new edges */
    list = head;
  }
  /* cut the sorted new edges from the rest and merge the two */
  int last = list;
  for (int i = 1; i < count; ++i) last = edge_next(w, last);
  set_edge_next(w, last, -1);
  return merge_into_rest(w, list, rest);
}

void tb_contacts_sort_new(tb_world* w) {
  for (int i = 0; i < w->new_contact_body_count; ++i) {
    tb_body* b = tb_body_at(w, w->new_contact_bodies[i]);
    /* at most the whole list: sorting more than the new edges and merging
     * gives the same sorted list */
    int count = b->new_contact_count < b->contact_count ? b->new_contact_count : b->contact_count;
    b->contact_list = sort_new_edges(w, b->contact_list, count);
    b->new_contact_count = 0;
  }
  w->new_contact_body_count = 0;
}

static void unlink_edge(tb_world* w, int contact, int side) {
  tb_contact* c = contact_at(w, contact);
  tb_contact_edge* e = &c->edges[side];
  tb_body* b = tb_body_at(w, e->body);
  if (e->prev >= 0)
    contact_at(w, e->prev >> 1)->edges[e->prev & 1].next = e->next;
  else
    b->contact_list = e->next;
  if (e->next >= 0) contact_at(w, e->next >> 1)->edges[e->next & 1].prev = e->prev;
  b->contact_count -= 1;
}

/* ---- creation and destruction ------------------------------------------- */

/* A mix callback's result outside the range of its material (NaN, negative,
 * a friction above TB_MAX_VALUE, a restitution above 1) is not used: the
 * contact takes the default rule, and tb_world_step reports it. */
static float checked_mix(tb_world* w, const char* name, float value, float max, float rule) {
  if (value >= 0.0f && value <= max) return value; /* false for NaN */
  if (w->bad_mix_count++ == 0) {
    w->bad_mix_value = value;
    w->bad_mix_name = name;
  }
  return rule;
}

static float mix_friction(tb_world* w, float a, float b) {
  float rule = sqrtf(a * b);
  if (w->friction_mix == NULL) return rule;
  return checked_mix(w, "friction_mix", w->friction_mix(a, b, w->mix_context), TB_MAX_VALUE, rule);
}

static float mix_restitution(tb_world* w, float a, float b) {
  float rule = a > b ? a : b;
  if (w->restitution_mix == NULL) return rule;
  return checked_mix(w, "restitution_mix", w->restitution_mix(a, b, w->mix_context), 1.0f, rule);
}

/* The lever arm of rolling resistance: the rounding radius of a shape. */
static float shape_rolling_radius(const tb_shape* s) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return s->geom.circle.radius;
    case TB_SHAPE_CAPSULE: return s->geom.capsule.radius;
    case TB_SHAPE_POLYGON: return s->geom.polygon.radius;
    default: return 0.0f;
  }
}

bool tb_contact_create(tb_world* w, int ia, int ib) {
  const tb_shape* sa = tb_shape_at(w, ia);
  const tb_shape* sb = tb_shape_at(w, ib);
  if (collide_table[sa->type][sb->type] == NULL || (sa->type == sb->type && ib < ia)) {
    int t = ia;
    ia = ib;
    ib = t;
  }
  int index = tb_pool_alloc(&w->contacts);
  if (index < 0) return false;
  if (!tb_pair_add(&w->broad_phase, ia, ib)) {
    tb_pool_release(&w->contacts, index);
    return false;
  }
  sa = tb_shape_at(w, ia);
  sb = tb_shape_at(w, ib);
  tb_contact* c = contact_at(w, index);
  c->shape_a = ia;
  c->shape_b = ib;
  c->edges[0].body = sa->body;
  c->edges[1].body = sb->body;
  c->friction = mix_friction(w, sa->friction, sb->friction);
  c->restitution = mix_restitution(w, sa->restitution, sb->restitution);
  float rra = sa->rolling_resistance * shape_rolling_radius(sa),
        rrb = sb->rolling_resistance * shape_rolling_radius(sb);
  c->rolling_resistance = rra > rrb ? rra : rrb;
  c->tangent_speed = sa->tangent_speed + sb->tangent_speed;
  c->flags = TB_CONTACT_ENABLED;
  c->walk_stamp = 0;
  if (sa->sensor || sb->sensor) c->flags |= TB_CONTACT_SENSOR;
  if (sa->enable_contact_events || sb->enable_contact_events) c->flags |= TB_CONTACT_EVENTS;
  if (sa->enable_hit_events || sb->enable_hit_events) c->flags |= TB_CONTACT_HIT_EVENTS;
  if (sa->enable_pre_solve_events || sb->enable_pre_solve_events) c->flags |= TB_CONTACT_PRE_SOLVE;
  link_edge(w, index, 0);
  link_edge(w, index, 1);
  w->layout_valid = false; /* (a pool slot may now hold another pair) */
  return true;
}

static void push_event(void** data, int* count, int* capacity, const void* event, size_t size) {
  if (!tb_array_reserve(data, capacity, *count + 1, size)) return; /* out of memory: the event is dropped */
  memcpy((char*)*data + (size_t)*count * size, event, size);
  *count += 1;
}

static void report_end(tb_world* w, const tb_contact* c) {
  if (!(c->flags & TB_CONTACT_TOUCHING)) return;
  tb_shape_id a = tb_make_shape_id(w, c->shape_a), b = tb_make_shape_id(w, c->shape_b);
  if (c->flags & TB_CONTACT_SENSOR) {
    bool a_is_sensor = tb_shape_at(w, c->shape_a)->sensor;
    tb_sensor_event e = {a_is_sensor ? a : b, a_is_sensor ? b : a};
    push_event((void**)&w->sensor_end_events, &w->sensor_end_count, &w->sensor_end_capacity, &e, sizeof e);
  } else if (c->flags & TB_CONTACT_EVENTS) {
    tb_contact_end_event e = {a, b};
    push_event((void**)&w->end_events, &w->end_count, &w->end_capacity, &e, sizeof e);
  }
}

void tb_contact_destroy(tb_world* w, int index) {
  tb_contact* c = contact_at(w, index);
  report_end(w, c);
  tb_pair_remove(&w->broad_phase, c->shape_a, c->shape_b);
  unlink_edge(w, index, 0);
  unlink_edge(w, index, 1);
  tb_pool_release(&w->contacts, index);
  w->layout_valid = false;
}

void tb_contacts_destroy_of_body(tb_world* w, int body, int shape) {
  int key = tb_body_at(w, body)->contact_list;
  while (key >= 0) {
    tb_contact* c = contact_at(w, key >> 1);
    int next = c->edges[key & 1].next;
    if (shape < 0 || c->shape_a == shape || c->shape_b == shape) tb_contact_destroy(w, key >> 1);
    key = next;
  }
}

/* ---- narrow phase ---------------------------------------------------------- */

static bool aabbs_overlap(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

/* Whether two shapes' boxes are so far apart that their collision keeps no
 * point. A manifold keeps the points closer than the speculative distance,
 * and a gap between the tight boxes along an axis is at most the shapes'
 * distance; twice that distance leaves room for the boxes' rounding. Most
 * contacts of a heap of debris are pairs whose fat boxes overlap while the
 * shapes are a hand's width apart, and this skips their collision. */
static bool boxes_apart(tb_aabb a, tb_aabb b) {
  float reach = 2.0f * tb_units.speculative_distance;
  return b.lower.x - a.upper.x > reach || a.lower.x - b.upper.x > reach || b.lower.y - a.upper.y > reach ||
         a.lower.y - b.upper.y > reach;
}

/* Approach speed: the largest -(v_B - v_A) . n over the manifold's points. */
static float approach_speed(const tb_world* w, const tb_contact* c, tb_vec2* where) {
  const tb_body* a = tb_body_at(w, c->edges[0].body);
  const tb_body* b = tb_body_at(w, c->edges[1].body);
  float best = 0.0f;
  for (int i = 0; i < c->manifold.point_count; ++i) {
    tb_vec2 p = c->manifold.points[i].point;
    tb_vec2 va = tb_add(a->linear_velocity, tb_cross_sv(a->angular_velocity, tb_sub(p, a->center)));
    tb_vec2 vb = tb_add(b->linear_velocity, tb_cross_sv(b->angular_velocity, tb_sub(p, b->center)));
    float s = -tb_dot(tb_sub(vb, va), c->manifold.normal);
    if (s > best || i == 0) {
      best = s;
      *where = p;
    }
  }
  return best;
}

/* Events of a contact that starts touching: sensor begin, or contact begin and hit. */
static void report_begin(tb_world* w, const tb_contact* c) {
  tb_shape_id a = tb_make_shape_id(w, c->shape_a), b = tb_make_shape_id(w, c->shape_b);
  if (c->flags & TB_CONTACT_SENSOR) {
    bool a_is_sensor = tb_shape_at(w, c->shape_a)->sensor;
    tb_sensor_event e = {a_is_sensor ? a : b, a_is_sensor ? b : a};
    push_event((void**)&w->sensor_begin_events, &w->sensor_begin_count, &w->sensor_begin_capacity, &e, sizeof e);
    return;
  }
  if (c->flags & TB_CONTACT_EVENTS) {
    tb_contact_begin_event e = {a, b, c->manifold};
    push_event((void**)&w->begin_events, &w->begin_count, &w->begin_capacity, &e, sizeof e);
  }
  if (c->flags & TB_CONTACT_HIT_EVENTS) {
    tb_vec2 point = {0.0f, 0.0f};
    float speed = approach_speed(w, c, &point);
    if (speed > w->hit_event_threshold) {
      tb_contact_hit_event e = {a, b, point, c->manifold.normal, speed};
      push_event((void**)&w->hit_events, &w->hit_count, &w->hit_capacity, &e, sizeof e);
    }
  }
}

/* The new manifold keeps the impulses of the points with the same feature id.
 * A point whose id is new but that lies within TB_LINEAR_SLOP of an old point
 * that found no successor is the same patch of contact under another name:
 * where two faces are flush (a box on a box of its width), the end of a
 * contact edge is the reference face's corner or the incident box's corner
 * depending on a rounding-level offset, so its id flips from step to step.
 * Starting such a point cold drops its share of the load for a substep, and
 * in a tall column the kick grows into a topple; it inherits instead. */
static void inherit(tb_manifold_point* p, const tb_manifold_point* from) {
  p->normal_impulse = from->normal_impulse;
  p->tangent_impulse = from->tangent_impulse;
}

static void carry_impulses(const tb_manifold* old, tb_manifold* m) {
  bool taken[2] = {false, false};
  bool found[2] = {false, false};
  for (int i = 0; i < m->point_count; ++i) {
    tb_manifold_point* p = &m->points[i];
    p->normal_impulse = p->tangent_impulse = 0.0f;
    for (int k = 0; k < old->point_count && !found[i]; ++k)
      if (!taken[k] && old->points[k].id == p->id) {
        inherit(p, &old->points[k]);
        taken[k] = found[i] = true;
      }
  }
  for (int i = 0; i < m->point_count; ++i)
    for (int k = 0; k < old->point_count && !found[i]; ++k) {
      tb_vec2 d = tb_sub(old->points[k].point, m->points[i].point);
      if (!taken[k] && tb_dot(d, d) < tb_units.linear_slop * tb_units.linear_slop) {
        inherit(&m->points[i], &old->points[k]);
        taken[k] = found[i] = true;
      }
    }
}

/* ---- where a face runs on ------------------------------------------------------
 * A face contact's patch ends where its reference face ends (tb_patch), and a
 * body that slides past that within a step is let go by the solver. Where
 * another solid shape continues the face (tiles laid side by side) or closes
 * the corner (walls that meet), the body could only get past the end by
 * going through that shape, which may not be among its contacts yet (a
 * bullet along a wall, 3 m from the corner, moves 3 m a step): letting go
 * there would let it out of the corner. So a patch end that the bodies can
 * reach this step, once a body slides past it (the solver asks, see ask_ends
 * in contact_solver.c), is kept only if no other solid shape that the
 * incident shape collides with holds either of two points one slop from it:
 * back along the face and off it (where the incident passes to reach the
 * end), or past it and under the face line (where a floor would run on).
 * Chains decide their joints themselves. */

typedef struct cover_query {
  const tb_world* w;
  const tb_contact* c;
  const tb_shape* incident;
  tb_vec2 point[2];
  bool covered;
} cover_query;

static bool cover_callback(int32_t proxy, int32_t index, void* context) {
  (void)proxy;
  cover_query* q = context;
  if (index == q->c->shape_a || index == q->c->shape_b) return true;
  const tb_shape* s = tb_shape_at(q->w, index);
  if (s->sensor || !tb_filters_collide(s->filter, q->incident->filter)) return true;
  tb_transform xf = tb_body_at(q->w, s->body)->transform;
  q->covered = tb_shape_geom_contains(s, xf, q->point[0]) || tb_shape_geom_contains(s, xf, q->point[1]);
  return !q->covered;
}

/* Whether the face runs on at its end `local_end` (A's frame), which lies
 * along `out` (world) from the patch (see above). */
static __attribute__((noinline)) bool face_runs_on(const tb_world* w, const tb_contact* c, tb_vec2 local_end,
                                                   tb_vec2 out) {
  tb_transform xfa = tb_body_at(w, c->edges[0].body)->transform;
  tb_vec2 end = tb_transform_point(xfa, local_end), normal = tb_rotate(xfa.q, c->patch.reference_normal);
  /* the incident shape: B's when A's face is the reference */
  bool b_incident = tb_dot(normal, c->manifold.normal) > 0.0f;
  const tb_shape* incident = tb_shape_at(w, b_incident ? c->shape_b : c->shape_a);
  const float e = tb_units.linear_slop;
  cover_query q = {w,
                   c,
                   incident,
                   {tb_add(end, tb_add(tb_scale(-e, out), tb_scale(e, normal))),
                    tb_add(end, tb_add(tb_scale(e, out), tb_scale(-e, normal)))},
                   false};
  tb_aabb box = {{tb_minf(q.point[0].x, q.point[1].x), tb_minf(q.point[0].y, q.point[1].y)},
                 {tb_maxf(q.point[0].x, q.point[1].x), tb_maxf(q.point[0].y, q.point[1].y)}};
  for (int t = 0; t < 3 && !q.covered; ++t)
    tb_tree_query(&w->broad_phase.trees[t], box, UINT64_MAX, cover_callback, &q);
  return q.covered;
}

bool tb_contact_face_runs_on(tb_world* w, int contact, bool max_end) {
  tb_contact* c = contact_at(w, contact);
  tb_patch* p = &c->patch;
  if (!p->face || c->manifold.point_count == 0) return false;
  tb_vec2 t = tb_right_perp(c->manifold.normal);
  if (!face_runs_on(w, c, max_end ? p->end_max : p->end_min, max_end ? t : tb_neg(t))) return false;
  if (max_end)
    p->slide_max = FLT_MAX;
  else
    p->slide_min = -FLT_MAX;
  return true;
}

/* Updates one contact; false when it was destroyed (bounding boxes apart). */
static bool update_contact(tb_world* w, int i) {
  tb_contact* c = contact_at(w, i);
  const tb_shape* sa = tb_shape_at(w, c->shape_a);
  const tb_shape* sb = tb_shape_at(w, c->shape_b);
  if (!aabbs_overlap(sa->fat_aabb, sb->fat_aabb)) {
    tb_contact_destroy(w, i);
    return false;
  }
  const tb_body *ba = tb_body_at(w, sa->body), *bb = tb_body_at(w, sb->body);
  if (boxes_apart(sa->aabb, sb->aabb)) { /* what the collision returns for no point */
    c->manifold = (tb_manifold){.point_count = 0};
    c->patch = (tb_patch){.slide_min = -FLT_MAX, .slide_max = FLT_MAX};
    c->cache.point_count = 0;
  } else if (!tb_manifold_cache_reuse(&c->cache, &c->manifold, ba, bb)) {
    tb_manifold old = c->manifold;
    collide_table[sa->type][sb->type](sa, ba->transform, sb, bb->transform, &c->manifold, &c->patch);
    carry_impulses(&old, &c->manifold);
    tb_manifold_cache_store(&c->cache, &c->manifold, ba, bb);
  }
  bool touching = c->manifold.point_count > 0;
  if (c->flags & TB_CONTACT_SENSOR) { /* a sensor needs a real overlap, not a speculative point */
    touching = false;
    for (int k = 0; k < c->manifold.point_count; ++k) touching |= c->manifold.points[k].separation < 0.0f;
  }
  bool was_touching = (c->flags & TB_CONTACT_TOUCHING) != 0;
  if (touching && !was_touching) {
    c->flags |= TB_CONTACT_TOUCHING;
    report_begin(w, c);
  } else if (!touching && was_touching) {
    report_end(w, c); /* reads the touching flag: clear it after */
    c->flags &= ~(uint32_t)TB_CONTACT_TOUCHING;
  }
  c->flags |= TB_CONTACT_ENABLED;
  if (touching && (c->flags & TB_CONTACT_PRE_SOLVE) && !(c->flags & TB_CONTACT_SENSOR) && w->pre_solve != NULL &&
      !w->pre_solve(tb_make_shape_id(w, c->shape_a), tb_make_shape_id(w, c->shape_b), &c->manifold,
                    w->pre_solve_context))
    c->flags &= ~(uint32_t)TB_CONTACT_ENABLED;
  return true;
}

void tb_contacts_update(tb_world* w) {
  w->step_contact_count = 0;
  uint32_t stamp = ++w->walk_stamp;
  if (stamp == 0) stamp = w->walk_stamp = 1;
  /* each contact once, from the body with the lower awake index (or the only
   * awake one): the first of its bodies the walk meets, which stamps it, so
   * that meeting it again from the other needs no look at that body's record
   * (a cache miss per contact between two awake bodies); the set grows when a
   * touch wakes an island, and the loop bound follows it so the woken bodies
   * are handled in this same step */
  for (int i = 0; i < w->awake_count; ++i) {
    /* The lists lie all over the contact pool: ask ahead for the next body's
     * record and the first contact of the one after it, and for each
     * contact's successor before its manifold is computed (the walk's misses
     * were 40% of this loop on washer). */
    if (i + 2 < w->awake_count) __builtin_prefetch(tb_body_at(w, w->awake[i + 2]));
    if (i + 1 < w->awake_count) {
      int head = tb_body_at(w, w->awake[i + 1])->contact_list;
      if (head >= 0) __builtin_prefetch(contact_at(w, head >> 1));
    }
    for (int key = tb_body_at(w, w->awake[i])->contact_list; key >= 0;) {
      int index = key >> 1;
      tb_contact* c = contact_at(w, index);
      int next = c->edges[key & 1].next;
      int other = c->edges[(key & 1) ^ 1].body;
      if (next >= 0) __builtin_prefetch(contact_at(w, next >> 1));
      key = next;
      if (c->walk_stamp == stamp) continue;
      c->walk_stamp = stamp;
      if (!update_contact(w, index)) continue;
      c = contact_at(w, index);
      const uint32_t need = TB_CONTACT_TOUCHING | TB_CONTACT_ENABLED;
      if ((c->flags & need) != need || (c->flags & TB_CONTACT_SENSOR)) continue;
      const tb_body* ob = tb_body_at(w, other);
      if (ob->sleep_island >= 0) tb_wake_body(w, other);
      const tb_body* ba = tb_body_at(w, c->edges[0].body);
      const tb_body* bb = tb_body_at(w, c->edges[1].body);
      if (ba->type != TB_DYNAMIC_BODY && bb->type != TB_DYNAMIC_BODY) continue;
      if (w->step_contact_count == w->step_contact_capacity &&
          !tb_array_reserve((void**)&w->step_contacts, &w->step_contact_capacity, w->step_contact_count + 1,
                            sizeof(int)))
        continue; /* out of memory: this contact does not push this step */
      w->step_contacts[w->step_contact_count++] = index;
    }
  }
}
