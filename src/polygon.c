/* Polygons from hulls, placed polygons (tumble.h, "geometry"): tb_compute_hull,
 * tb_make_polygon_from_hull, tb_make_offset_polygon and its rounded variant,
 * tb_transform_polygon. The hull itself is tb_make_polygon's (src/hull.c):
 * these functions call it and take its vertices, so there is one hull
 * algorithm with one set of rules. */
#include <stdio.h>
#include <string.h>

#include "distance.h"
#include "error.h"
#include "geometry.h"
#include "math_internal.h"

/* tb_make_polygon's error again, named for fn: its message reads
 * "CODE: tb_make_polygon: why"; the caller asked fn, so say "fn: why". */
static tb_result make_polygon_as(const char* fn, const tb_vec2* points, int count, float radius, tb_polygon* out) {
  tb_result r = tb_make_polygon(points, count, radius, out);
  if (r == TB_OK) return r;
  static const char from[] = "tb_make_polygon: ";
  char why[TB_ERROR_MESSAGE_CAPACITY];
  const char* at = strstr(tb_last_error(), from);
  snprintf(why, sizeof why, "%s", at != NULL ? at + sizeof from - 1 : tb_last_error());
  return tb_fail(NULL, r, "%s: %s", fn, why);
}

tb_result tb_compute_hull(const tb_vec2* points, int count, tb_hull* out) {
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_compute_hull: out is NULL");
  out->count = 0;
  tb_polygon polygon;
  tb_result r = make_polygon_as(__func__, points, count, 0.0f, &polygon);
  if (r != TB_OK) return r;
  memcpy(out->points, polygon.vertices, sizeof out->points);
  out->count = polygon.count;
  return TB_OK;
}

/* A hull is the hull of its own points: tb_make_polygon keeps every one of
 * them (welded, collinear or interior points would be dropped). */
static tb_result polygon_from_hull(const char* fn, const tb_hull* hull, float radius, tb_polygon* out) {
  if (hull == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: hull is NULL", fn);
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", fn);
  if (hull->count < 3 || hull->count > TB_MAX_POLYGON_VERTICES)
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: hull count %d is not in 3..TB_MAX_POLYGON_VERTICES", fn,
                   hull->count);
  tb_polygon polygon;
  tb_result r = make_polygon_as(fn, hull->points, hull->count, radius, &polygon);
  if (r != TB_OK) return r;
  if (polygon.count != hull->count)
    return tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON,
                   "%s: the hull's %d points are not a hull (only %d of them are; build it with tb_compute_hull)", fn,
                   hull->count, polygon.count);
  *out = polygon;
  return TB_OK;
}

/* Places a valid polygon; the result must still be one (far from the origin a
 * small polygon can collapse to fewer distinct float points). */
static tb_result place_polygon(const char* fn, const tb_polygon* polygon, tb_transform xf, tb_polygon* out) {
  tb_polygon placed = *polygon;
  for (int i = 0; i < polygon->count; ++i) {
    placed.vertices[i] = tb_transform_point(xf, polygon->vertices[i]);
    placed.normals[i] = tb_rotate(xf.q, polygon->normals[i]);
  }
  placed.centroid = tb_transform_point(xf, polygon->centroid);
  const char* why = tb_check_polygon(&placed);
  if (why != NULL) return tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "%s: the placed polygon is refused: %s", fn, why);
  *out = placed;
  return TB_OK;
}

tb_result tb_make_polygon_from_hull(const tb_hull* hull, float radius, tb_polygon* out) {
  return polygon_from_hull(__func__, hull, radius, out);
}

static tb_result offset_polygon(const char* fn, const tb_hull* hull, tb_vec2 position, float angle, float radius,
                                tb_polygon* out) {
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", fn);
  if (!tb_point_ok(position))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: position is not finite or beyond TB_MAX_LENGTH", fn);
  if (tb_check_angle(NULL, fn, "angle", angle) != TB_OK) return tb_last_result();
  tb_polygon local;
  tb_result r = polygon_from_hull(fn, hull, radius, &local);
  if (r != TB_OK) return r;
  tb_transform xf = {position, angle == 0.0f ? (tb_rot){1.0f, 0.0f} : tb_make_rot(angle)};
  return place_polygon(fn, &local, xf, out);
}

tb_result tb_make_offset_polygon(const tb_hull* hull, tb_vec2 position, float angle, tb_polygon* out) {
  return offset_polygon(__func__, hull, position, angle, 0.0f, out);
}

tb_result tb_make_offset_rounded_polygon(const tb_hull* hull, tb_vec2 position, float angle, float radius,
                                         tb_polygon* out) {
  return offset_polygon(__func__, hull, position, angle, radius, out);
}

tb_result tb_transform_polygon(const tb_polygon* polygon, tb_transform xf, tb_polygon* out) {
  const char* fn = __func__;
  if (polygon == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: polygon is NULL", fn);
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", fn);
  const char* why = tb_check_polygon(polygon);
  if (why != NULL) return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: %s", fn, why);
  if (!tb_transform_ok(xf))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                   "%s: transform xf is not finite, beyond TB_MAX_LENGTH or not a unit rotation", fn);
  return place_polygon(fn, polygon, xf, out);
}
