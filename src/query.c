/* World queries: rays, boxes, points, shapes and shape casts through the
 * broad-phase trees, then the exact test against each candidate shape. */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "memory.h"
#include "distance.h"
#include "geometry.h"
#include "math_internal.h"
#include "world.h"

tb_query_filter tb_default_query_filter(void) { return (tb_query_filter){1u, UINT64_MAX, false}; }

static bool visible(const tb_shape* s, tb_query_filter f) {
  return (s->filter.category_bits & f.mask_bits) != 0 && (s->filter.mask_bits & f.category_bits) != 0 &&
         !(f.skip_sensors && s->sensor);
}

/* Copied as tb_make_*_proxy build it (unused points zero), without their
 * checks: a world's shape was vetted when it was made, and the continuous
 * pass takes a proxy for every shape it sweeps and every shape it sweeps
 * against (tb_check_polygon there was 4.7% of junkyard's instructions). */
static tb_shape_proxy proxy_of(const tb_vec2* points, int count, float radius) {
  tb_shape_proxy proxy;
  memset(&proxy, 0, sizeof proxy);
  memcpy(proxy.points, points, (size_t)count * sizeof *points);
  proxy.count = count;
  proxy.radius = radius;
  return proxy;
}

tb_shape_proxy tb_shape_geom_proxy(const tb_shape* s) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return proxy_of(&s->geom.circle.center, 1, s->geom.circle.radius);
    case TB_SHAPE_CAPSULE: {
      tb_vec2 centers[2] = {s->geom.capsule.center1, s->geom.capsule.center2};
      return proxy_of(centers, 2, s->geom.capsule.radius);
    }
    case TB_SHAPE_SEGMENT: {
      tb_vec2 ends[2] = {s->geom.segment.point1, s->geom.segment.point2};
      return proxy_of(ends, 2, 0.0f);
    }
    case TB_SHAPE_CHAIN_SEGMENT: {
      tb_vec2 ends[2] = {s->geom.chain_segment.segment.point1, s->geom.chain_segment.segment.point2};
      return proxy_of(ends, 2, 0.0f);
    }
    case TB_SHAPE_POLYGON: break;
  }
  return proxy_of(s->geom.polygon.vertices, s->geom.polygon.count, s->geom.polygon.radius);
}

void tb_shape_geom_ray_cast(const tb_shape* s, tb_transform xf, const tb_ray_input* ray, tb_cast_output* out) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: tb_ray_cast_circle(ray, &s->geom.circle, xf, out); return;
    case TB_SHAPE_CAPSULE: tb_ray_cast_capsule(ray, &s->geom.capsule, xf, out); return;
    case TB_SHAPE_SEGMENT: tb_ray_cast_segment(ray, &s->geom.segment, xf, out); return;
    case TB_SHAPE_POLYGON: tb_ray_cast_polygon(ray, &s->geom.polygon, xf, out); return;
    case TB_SHAPE_CHAIN_SEGMENT: { /* one-sided: only from the left of point1 -> point2 */
      const tb_segment* g = &s->geom.chain_segment.segment;
      tb_vec2 left = tb_rotate(xf.q, tb_left_perp(tb_sub(g->point2, g->point1)));
      if (tb_dot(ray->translation, left) < 0.0f) tb_ray_cast_segment(ray, g, xf, out);
      return;
    }
  }
}

static tb_result check_callback(tb_world* w, const char* fn, bool present) {
  if (!present) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: fn is NULL", fn);
  return TB_OK;
}

/* User callbacks run with the world locked: the trees are being walked, so a
 * change from inside one (destroying or creating a shape, moving a body) is
 * refused with TB_ERR_LOCKED instead of freeing or moving nodes under the walk.
 * Reading the world, and nested queries, stay allowed. */
static float call_cast(tb_world* w, tb_cast_fn* fn, tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction,
                       void* context) {
  bool was_locked = w->locked;
  w->locked = true;
  float r = fn(shape, point, normal, fraction, context);
  w->locked = was_locked;
  return r;
}

static bool call_overlap(tb_world* w, tb_overlap_fn* fn, tb_shape_id shape, void* context) {
  bool was_locked = w->locked;
  w->locked = true;
  bool r = fn(shape, context);
  w->locked = was_locked;
  return r;
}

/* ---- rays ---------------------------------------------------------------- */

typedef struct ray_context {
  tb_world* w;
  tb_query_filter filter;
  tb_cast_fn* fn;
  void* context;
  float fraction; /* the current clip, carried from tree to tree */
} ray_context;

static float ray_callback(const tb_tree_ray_input* input, int32_t proxy, int32_t shape, void* context) {
  (void)proxy;
  ray_context* rc = context;
  const tb_shape* s = tb_shape_at(rc->w, shape);
  if (!visible(s, rc->filter)) return -1.0f;
  tb_ray_input ray = {input->origin, input->translation, input->max_fraction};
  tb_cast_output out = {0};
  tb_shape_geom_ray_cast(s, tb_body_at(rc->w, s->body)->transform, &ray, &out);
  if (!out.hit) return -1.0f;
  float r = call_cast(rc->w, rc->fn, tb_make_shape_id(rc->w, shape), out.point, out.normal, out.fraction, rc->context);
  if (r >= 0.0f && r < rc->fraction) rc->fraction = r;
  return r;
}

tb_result tb_check_ray(struct tb_world* w, const char* fn, tb_vec2 origin, tb_vec2 translation) {
  if (!tb_point_ok(origin))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: origin (%g, %g) is not finite or beyond TB_MAX_LENGTH", fn,
                   (double)origin.x, (double)origin.y);
  if (!tb_point_ok(translation))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: translation (%g, %g) is not finite or beyond TB_MAX_LENGTH", fn,
                   (double)translation.x, (double)translation.y);
  if (translation.x == 0.0f && translation.y == 0.0f)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: translation is zero (a ray needs a direction)", fn);
  return TB_OK;
}

static void cast_ray(tb_world* w, tb_vec2 origin, tb_vec2 translation, ray_context* rc) {
  rc->fraction = 1.0f;
  for (int t = 0; t < 3 && rc->fraction > 0.0f; ++t) {
    tb_tree_ray_input input = {origin, translation, rc->fraction};
    tb_tree_ray_cast(&w->broad_phase.trees[t], &input, UINT64_MAX, ray_callback, rc);
  }
}

tb_result tb_world_cast_ray(tb_world_id id, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter, tb_cast_fn* fn,
                            void* context) {
  const char* name = "tb_world_cast_ray";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  tb_result r = tb_check_ray(w, name, origin, translation);
  if (r == TB_OK) r = check_callback(w, name, fn != NULL);
  if (r != TB_OK) return r;
  ray_context rc = {w, filter, fn, context, 1.0f};
  cast_ray(w, origin, translation, &rc);
  return TB_OK;
}

static float closest_callback(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  tb_ray_result* best = context;
  *best = (tb_ray_result){shape, point, normal, fraction, true};
  return fraction;
}

tb_ray_result tb_world_cast_ray_closest(tb_world_id id, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter) {
  const char* name = "tb_world_cast_ray_closest";
  tb_ray_result best = {{0, 0, 0}, {0.0f, 0.0f}, {0.0f, 0.0f}, 1.0f, false};
  tb_world* w = tb_world_get(id, name);
  if (w == NULL || tb_check_ray(w, name, origin, translation) != TB_OK) return best;
  ray_context rc = {w, filter, closest_callback, &best, 1.0f};
  cast_ray(w, origin, translation, &rc);
  return best;
}

typedef struct hit_list {
  tb_ray_result* hits;
  int count, capacity;
  bool failed;
} hit_list;

static float all_callback(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  hit_list* list = context;
  if (!tb_array_reserve((void**)&list->hits, &list->capacity, list->count + 1, sizeof *list->hits)) {
    list->failed = true;
    return 0.0f;
  }
  list->hits[list->count++] = (tb_ray_result){shape, point, normal, fraction, true};
  return 1.0f;
}

static int by_fraction(const void* pa, const void* pb) {
  const tb_ray_result *a = pa, *b = pb;
  if (a->fraction != b->fraction) return a->fraction < b->fraction ? -1 : 1;
  return a->shape.index1 - b->shape.index1; /* ties in a fixed order */
}

tb_result tb_world_cast_ray_all(tb_world_id id, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter,
                                tb_ray_result* out, int capacity, int* count) {
  const char* name = "tb_world_cast_ray_all";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  tb_result r = tb_check_ray(w, name, origin, translation);
  if (r != TB_OK) return r;
  if (count == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: count is NULL", name);
  if (capacity < 0 || (out == NULL && capacity > 0))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: out is NULL or capacity %d < 0", name, capacity);
  hit_list list = {NULL, 0, 0, false};
  ray_context rc = {w, filter, all_callback, &list, 1.0f};
  cast_ray(w, origin, translation, &rc);
  const size_t bytes = (size_t)list.capacity * sizeof *list.hits;
  if (list.failed) {
    tb_mem_free(list.hits, bytes);
    return tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the hits", name);
  }
  if (list.count > 1) qsort(list.hits, (size_t)list.count, sizeof *list.hits, by_fraction);
  for (int i = 0; i < list.count && i < capacity; ++i) out[i] = list.hits[i];
  *count = list.count;
  tb_mem_free(list.hits, bytes);
  return TB_OK;
}

/* ---- overlaps ------------------------------------------------------------ */

typedef enum overlap_kind { OVERLAP_AABB, OVERLAP_POINT, OVERLAP_SHAPE } overlap_kind;

typedef struct overlap_context {
  tb_world* w;
  tb_query_filter filter;
  overlap_kind kind;
  tb_aabb aabb;
  tb_vec2 point;
  const tb_shape_proxy* proxy;
  tb_transform transform;
  tb_overlap_fn* fn;
  void* context;
  bool stopped;
} overlap_context;

static bool aabb_overlap(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

static bool overlap_callback(int32_t proxy, int32_t shape, void* context) {
  (void)proxy;
  overlap_context* oc = context;
  const tb_shape* s = tb_shape_at(oc->w, shape);
  if (!visible(s, oc->filter)) return true;
  tb_transform xf = tb_body_at(oc->w, s->body)->transform;
  bool hit = false;
  switch (oc->kind) {
    case OVERLAP_AABB: hit = aabb_overlap(s->aabb, oc->aabb); break;
    case OVERLAP_POINT: hit = tb_shape_geom_contains(s, xf, oc->point); break;
    case OVERLAP_SHAPE: {
      tb_distance_input in = {tb_shape_geom_proxy(s), *oc->proxy, xf, oc->transform};
      tb_distance_output out;
      hit = tb_shape_distance(&in, NULL, &out) == TB_OK && out.distance <= 0.0f;
      break;
    }
  }
  if (hit && !call_overlap(oc->w, oc->fn, tb_make_shape_id(oc->w, shape), oc->context)) {
    oc->stopped = true;
    return false;
  }
  return true;
}

static tb_result overlap(tb_world* w, overlap_context* oc) {
  for (int t = 0; t < 3 && !oc->stopped; ++t)
    tb_tree_query(&w->broad_phase.trees[t], oc->aabb, UINT64_MAX, overlap_callback, oc);
  return TB_OK;
}

static bool aabb_ok(tb_aabb a) {
  return tb_point_ok(a.lower) && tb_point_ok(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y;
}

tb_result tb_world_overlap_aabb(tb_world_id id, tb_aabb aabb, tb_query_filter filter, tb_overlap_fn* fn,
                                void* context) {
  const char* name = "tb_world_overlap_aabb";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  if (!aabb_ok(aabb)) return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: aabb is not finite or has lower > upper", name);
  tb_result r = check_callback(w, name, fn != NULL);
  if (r != TB_OK) return r;
  overlap_context oc = {w, filter, OVERLAP_AABB, aabb, {0, 0}, NULL, {{0, 0}, {1, 0}}, fn, context, false};
  return overlap(w, &oc);
}

tb_result tb_world_overlap_point(tb_world_id id, tb_vec2 point, tb_query_filter filter, tb_overlap_fn* fn,
                                 void* context) {
  const char* name = "tb_world_overlap_point";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  if (!tb_point_ok(point))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: point (%g, %g) is not finite or beyond TB_MAX_LENGTH", name,
                   (double)point.x, (double)point.y);
  tb_result r = check_callback(w, name, fn != NULL);
  if (r != TB_OK) return r;
  overlap_context oc = {w, filter, OVERLAP_POINT, {point, point}, point, NULL, {{0, 0}, {1, 0}}, fn, context, false};
  return overlap(w, &oc);
}

static tb_result check_proxy(tb_world* w, const char* fn, const tb_shape_proxy* proxy, tb_transform xf) {
  if (proxy == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: proxy is NULL", fn);
  if (proxy->count < 1 || proxy->count > TB_MAX_POLYGON_VERTICES)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: proxy count %d must be 1..%d", fn, proxy->count,
                   TB_MAX_POLYGON_VERTICES);
  if (!(proxy->radius >= 0.0f) || !tb_length_ok(proxy->radius))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: proxy radius must be >= 0 and finite", fn);
  for (int i = 0; i < proxy->count; ++i)
    if (!tb_point_ok(proxy->points[i]))
      return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: proxy point %d is not finite", fn, i);
  if (!tb_point_ok(xf.p) || !tb_finite(xf.q.c) || !tb_finite(xf.q.s) ||
      fabsf(xf.q.c * xf.q.c + xf.q.s * xf.q.s - 1.0f) > 1e-3f)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: transform is not finite or its rotation is not unit", fn);
  return TB_OK;
}

static tb_aabb proxy_aabb(const tb_shape_proxy* proxy, tb_transform xf) {
  tb_vec2 lo = tb_transform_point(xf, proxy->points[0]), hi = lo;
  for (int i = 1; i < proxy->count; ++i) {
    tb_vec2 p = tb_transform_point(xf, proxy->points[i]);
    lo = tb_vmin(lo, p);
    hi = tb_vmax(hi, p);
  }
  float r = proxy->radius;
  return (tb_aabb){{lo.x - r, lo.y - r}, {hi.x + r, hi.y + r}};
}

tb_result tb_world_overlap_shape(tb_world_id id, const tb_shape_proxy* proxy, tb_transform transform,
                                 tb_query_filter filter, tb_overlap_fn* fn, void* context) {
  const char* name = "tb_world_overlap_shape";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  tb_result r = check_proxy(w, name, proxy, transform);
  if (r == TB_OK) r = check_callback(w, name, fn != NULL);
  if (r != TB_OK) return r;
  overlap_context oc = {w,  filter,  OVERLAP_SHAPE, proxy_aabb(proxy, transform), {0, 0}, proxy, transform,
                        fn, context, false};
  return overlap(w, &oc);
}

/* ---- shape cast ---------------------------------------------------------- */

typedef struct shape_cast_context {
  tb_world* w;
  tb_query_filter filter;
  const tb_shape_proxy* proxy;
  tb_transform transform;
  tb_vec2 translation;
  float fraction; /* clip */
  tb_cast_fn* fn;
  void* context;
  bool stopped;
} shape_cast_context;

/* Candidates come from the swept box; each is cast exactly, with the cast
 * clipped to the closest hit the callback has accepted so far. */
static bool shape_cast_callback(int32_t proxy, int32_t shape, void* context) {
  (void)proxy;
  shape_cast_context* sc = context;
  const tb_shape* s = tb_shape_at(sc->w, shape);
  if (!visible(s, sc->filter)) return true;
  tb_shape_cast_input in = {tb_shape_geom_proxy(s), *sc->proxy, tb_body_at(sc->w, s->body)->transform, sc->transform,
                            tb_scale(sc->fraction, sc->translation)};
  tb_cast_output out;
  if (tb_shape_cast(&in, &out) != TB_OK || !out.hit) return true;
  float fraction = out.fraction * sc->fraction;
  float r = call_cast(sc->w, sc->fn, tb_make_shape_id(sc->w, shape), out.point, out.normal, fraction, sc->context);
  if (r == 0.0f) {
    sc->stopped = true;
    return false;
  }
  if (r > 0.0f && r < sc->fraction) sc->fraction = r;
  return true;
}

tb_result tb_world_cast_shape(tb_world_id id, const tb_shape_proxy* proxy, tb_transform transform, tb_vec2 translation,
                              tb_query_filter filter, tb_cast_fn* fn, void* context) {
  const char* name = "tb_world_cast_shape";
  tb_world* w = tb_world_get(id, name);
  if (w == NULL) return tb_last_result();
  tb_result r = check_proxy(w, name, proxy, transform);
  if (r == TB_OK && !tb_point_ok(translation))
    r = tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: translation is not finite or beyond TB_MAX_LENGTH", name);
  if (r == TB_OK) r = check_callback(w, name, fn != NULL);
  if (r != TB_OK) return r;
  tb_aabb start = proxy_aabb(proxy, transform);
  tb_aabb end = {tb_add(start.lower, translation), tb_add(start.upper, translation)};
  tb_aabb swept = {tb_vmin(start.lower, end.lower), tb_vmax(start.upper, end.upper)};
  shape_cast_context sc = {w, filter, proxy, transform, translation, 1.0f, fn, context, false};
  for (int t = 0; t < 3 && !sc.stopped; ++t)
    tb_tree_query(&w->broad_phase.trees[t], swept, UINT64_MAX, shape_cast_callback, &sc);
  return TB_OK;
}
