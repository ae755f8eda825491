/* Queries on bare geometry placed by a transform (tumble.h, "geometry"):
 * bounding boxes, point tests and closest points. The boxes and point tests
 * are the ones the engine's shapes use (src/geometry.c), reached through a
 * stand-in shape; the ray casts live with the other casts in src/distance.c. */
#include <float.h>
#include <string.h>

#include "distance.h"
#include "error.h"
#include "geometry.h"
#include "math_internal.h"
#include "shape.h"

/* Checks a query's arguments; on success fills *shape with a stand-in shape
 * of the geometry (only its type and geometry are set: what the geometry
 * functions of src/geometry.c read). name is the argument's name, why what
 * tb_check_* found wrong with it (NULL when nothing). */
static bool query_ok(const char* fn, const char* name, const void* geom, const char* why, tb_transform xf,
                     const tb_vec2* point, tb_shape* shape) {
  if (geom == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, name);
    return false;
  }
  if (why != NULL) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: %s", fn, why);
    return false;
  }
  if (!tb_transform_ok(xf)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
            "%s: transform xf is not finite, beyond TB_MAX_LENGTH or not a unit rotation", fn);
    return false;
  }
  if (point != NULL && !tb_point_ok(*point)) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: point (%g, %g) is not finite or beyond TB_MAX_LENGTH", fn,
            (double)point->x, (double)point->y);
    return false;
  }
  memset(shape, 0, sizeof *shape);
  return true;
}

/* A geometry of the given type as a stand-in shape, after query_ok. */
static bool stand_in(const char* fn, tb_shape_type type, const void* geom, tb_transform xf, const tb_vec2* point,
                     tb_shape* s) {
  static const char* const names[] = {"circle", "capsule", "segment", "polygon"};
  const char* why = NULL;
  if (geom != NULL) {
    switch (type) {
      case TB_SHAPE_CIRCLE: why = tb_check_circle(geom); break;
      case TB_SHAPE_CAPSULE: why = tb_check_capsule(geom); break;
      case TB_SHAPE_SEGMENT: why = tb_check_segment(geom); break;
      default: why = tb_check_polygon(geom); break;
    }
  }
  if (!query_ok(fn, names[type], geom, why, xf, point, s)) return false;
  s->type = type;
  switch (type) {
    case TB_SHAPE_CIRCLE: s->geom.circle = *(const tb_circle*)geom; break;
    case TB_SHAPE_CAPSULE: s->geom.capsule = *(const tb_capsule*)geom; break;
    case TB_SHAPE_SEGMENT: s->geom.segment = *(const tb_segment*)geom; break;
    default: s->geom.polygon = *(const tb_polygon*)geom; break;
  }
  return true;
}

/* ------------------------------------------------------------ bounding boxes -- */

static const tb_aabb zero_box = {{0.0f, 0.0f}, {0.0f, 0.0f}};

tb_aabb tb_compute_circle_aabb(const tb_circle* circle, tb_transform xf) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_CIRCLE, circle, xf, NULL, &s) ? tb_shape_geom_aabb(&s, xf) : zero_box;
}

tb_aabb tb_compute_capsule_aabb(const tb_capsule* capsule, tb_transform xf) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_CAPSULE, capsule, xf, NULL, &s) ? tb_shape_geom_aabb(&s, xf) : zero_box;
}

tb_aabb tb_compute_segment_aabb(const tb_segment* segment, tb_transform xf) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_SEGMENT, segment, xf, NULL, &s) ? tb_shape_geom_aabb(&s, xf) : zero_box;
}

tb_aabb tb_compute_polygon_aabb(const tb_polygon* polygon, tb_transform xf) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_POLYGON, polygon, xf, NULL, &s) ? tb_shape_geom_aabb(&s, xf) : zero_box;
}

/* --------------------------------------------------------------- point tests -- */

bool tb_point_in_circle(const tb_circle* circle, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_CIRCLE, circle, xf, &point, &s) && tb_shape_geom_contains(&s, xf, point);
}

bool tb_point_in_capsule(const tb_capsule* capsule, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_CAPSULE, capsule, xf, &point, &s) && tb_shape_geom_contains(&s, xf, point);
}

bool tb_point_in_segment(const tb_segment* segment, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_SEGMENT, segment, xf, &point, &s) && tb_shape_geom_contains(&s, xf, point);
}

bool tb_point_in_polygon(const tb_polygon* polygon, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  return stand_in(__func__, TB_SHAPE_POLYGON, polygon, xf, &point, &s) && tb_shape_geom_contains(&s, xf, point);
}

/* ------------------------------------------------------------ closest points -- */

/* The closest point of a rounded core: `core` is the core's point closest to
 * the local point p. Within radius of the core p is inside (its own closest
 * point: the world point is returned unchanged, free of the round trip's
 * rounding); beyond, the surface point on the way from core to p. */
static tb_vec2 round_out(tb_transform xf, tb_vec2 point, tb_vec2 p, tb_vec2 core, float radius) {
  tb_vec2 d = tb_sub(p, core);
  float len = tb_length(d);
  if (len <= radius) return point;
  return tb_transform_point(xf, tb_mul_add(core, radius / len, d));
}

/* The point of segment a-b closest to p. */
static tb_vec2 closest_on_edge(tb_vec2 p, tb_vec2 a, tb_vec2 b) {
  return tb_segment_distance_unchecked(p, p, a, b).closest2;
}

tb_vec2 tb_closest_point_on_circle(const tb_circle* circle, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  if (!stand_in(__func__, TB_SHAPE_CIRCLE, circle, xf, &point, &s)) return (tb_vec2){0.0f, 0.0f};
  tb_vec2 p = tb_inv_transform_point(xf, point);
  return round_out(xf, point, p, circle->center, circle->radius);
}

tb_vec2 tb_closest_point_on_capsule(const tb_capsule* capsule, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  if (!stand_in(__func__, TB_SHAPE_CAPSULE, capsule, xf, &point, &s)) return (tb_vec2){0.0f, 0.0f};
  tb_vec2 p = tb_inv_transform_point(xf, point);
  return round_out(xf, point, p, closest_on_edge(p, capsule->center1, capsule->center2), capsule->radius);
}

tb_vec2 tb_closest_point_on_segment(const tb_segment* segment, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  if (!stand_in(__func__, TB_SHAPE_SEGMENT, segment, xf, &point, &s)) return (tb_vec2){0.0f, 0.0f};
  tb_vec2 p = tb_inv_transform_point(xf, point);
  return tb_transform_point(xf, closest_on_edge(p, segment->point1, segment->point2));
}

/* Inside the core when behind every edge's plane; else the nearest point of
 * the nearest edge (for a convex polygon the nearest point of the boundary). */
tb_vec2 tb_closest_point_on_polygon(const tb_polygon* polygon, tb_transform xf, tb_vec2 point) {
  tb_shape s;
  if (!stand_in(__func__, TB_SHAPE_POLYGON, polygon, xf, &point, &s)) return (tb_vec2){0.0f, 0.0f};
  tb_vec2 p = tb_inv_transform_point(xf, point);
  const int n = polygon->count;
  bool inside = true;
  for (int i = 0; i < n && inside; ++i) inside = tb_dot(polygon->normals[i], tb_sub(p, polygon->vertices[i])) <= 0.0f;
  if (inside) return point;
  tb_vec2 best = polygon->vertices[0];
  float best_sq = FLT_MAX;
  for (int i = 0; i < n; ++i) {
    tb_vec2 q = closest_on_edge(p, polygon->vertices[i], polygon->vertices[i + 1 < n ? i + 1 : 0]);
    float dsq = tb_distance_sq(p, q);
    if (dsq < best_sq) {
      best_sq = dsq;
      best = q;
    }
  }
  return round_out(xf, point, p, best, polygon->radius);
}
