/* Convex polygons: the hull of arbitrary points, and boxes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "memory.h"
#include "error.h"
#include "geometry.h"
#include "math_internal.h"
#include "units.h"

static int compare_points(const void* pa, const void* pb) {
  const tb_vec2 *a = pa, *b = pb;
  if (a->x != b->x) return a->x < b->x ? -1 : 1;
  if (a->y != b->y) return a->y < b->y ? -1 : 1;
  return 0;
}

/* (a - o) x (b - o), in double: > 0 when o, a, b turn left. In float the
 * products of a subnormal difference (points on a line x = 0, one of them at
 * x = -1e-45) underflowed to 0, a left turn read as collinear, and the hull
 * dropped a corner (fuzz_hull: a 0.19 m square lost its corner at the origin
 * and left the point 0.10 m outside). */
static double turn(tb_vec2 o, tb_vec2 a, tb_vec2 b) {
  return ((double)a.x - o.x) * ((double)b.y - o.y) - ((double)a.y - o.y) * ((double)b.x - o.x);
}

/* Distance of p from the line through a and b (a != b). */
static double line_distance(tb_vec2 a, tb_vec2 b, tb_vec2 p) {
  return fabs(turn(a, b, p)) / hypot((double)b.x - a.x, (double)b.y - a.y);
}

/* Fills normals and centroid from counter-clockwise vertices. */
static void finish_polygon(tb_polygon* out, const tb_vec2* v, int n, float radius) {
  memset(out, 0, sizeof *out);
  out->count = n;
  out->radius = radius;
  for (int i = 0; i < n; ++i) out->vertices[i] = v[i];
  for (int i = 0; i < n; ++i) {
    tb_vec2 e = tb_sub(v[i + 1 < n ? i + 1 : 0], v[i]);
    out->normals[i] = tb_normalize(tb_right_perp(e));
  }
  /* area centroid by a fan about the first vertex, in double */
  double area = 0.0, cx = 0.0, cy = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    double ax = (double)v[i].x - v[0].x, ay = (double)v[i].y - v[0].y;
    double bx = (double)v[i + 1].x - v[0].x, by = (double)v[i + 1].y - v[0].y;
    double d = ax * by - ay * bx;
    area += d;
    cx += d * (ax + bx);
    cy += d * (ay + by);
  }
  out->centroid = (tb_vec2){(float)(v[0].x + cx / (3.0 * area)), (float)(v[0].y + cy / (3.0 * area))};
}

/* Andrew's monotone chain on welded points, then removal of vertices that lie
 * within half a slop of the line through their neighbours. */
tb_result tb_make_polygon(const tb_vec2* points, int count, float radius, tb_polygon* out) {
  if (points == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_make_polygon: points is NULL");
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "tb_make_polygon: out is NULL");
  if (count < 3)
    return tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "tb_make_polygon: count is %d, need at least 3 points", count);
  if (radius < 0.0f || !tb_length_ok(radius))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "tb_make_polygon: radius %g must be >= 0 and finite", (double)radius);
  for (int i = 0; i < count; ++i) {
    tb_vec2 p = points[i];
    if (!tb_point_ok(p))
      return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                     "tb_make_polygon: points[%d] = (%g, %g) is not finite or beyond TB_MAX_LENGTH", i, (double)p.x,
                     (double)p.y);
  }

  /* the points, then room for both chains (up to 2n entries) */
  const size_t bytes = (size_t)count * 3 * sizeof(tb_vec2);
  tb_vec2* pts = tb_mem_alloc(bytes);
  const float slop = tb_units.linear_slop;
  if (pts == NULL) return tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "tb_make_polygon: no memory for %d points", count);
  tb_vec2* hull = pts + count;

  int n = 0; /* weld near-duplicates */
  for (int i = 0; i < count; ++i) {
    bool unique = true;
    for (int j = 0; j < n && unique; ++j) unique = tb_distance_sq(points[i], pts[j]) >= slop * slop;
    if (unique) pts[n++] = points[i];
  }
  if (n < 3) {
    tb_mem_free(pts, bytes);
    return tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON,
                   "tb_make_polygon: only %d distinct points after welding points closer than %g m", n, (double)slop);
  }
  qsort(pts, (size_t)n, sizeof *pts, compare_points);

  int h = 0;
  for (int i = 0; i < n; ++i) { /* lower chain */
    while (h >= 2 && turn(hull[h - 2], hull[h - 1], pts[i]) <= 0.0) --h;
    hull[h++] = pts[i];
  }
  for (int i = n - 2, lower = h + 1; i >= 0; --i) { /* upper chain */
    while (h >= lower && turn(hull[h - 2], hull[h - 1], pts[i]) <= 0.0) --h;
    hull[h++] = pts[i];
  }
  h -= 1; /* the last point repeats the first */

  bool removed = true;
  while (removed && h >= 3) {
    removed = false;
    for (int i = 0; i < h; ++i) {
      tb_vec2 a = hull[(i + h - 1) % h], b = hull[(i + 1) % h];
      if (line_distance(a, b, hull[i]) < 0.5 * (double)slop) {
        memmove(hull + i, hull + i + 1, (size_t)(h - i - 1) * sizeof *hull);
        --h;
        removed = true;
        break;
      }
    }
  }

  tb_result r = TB_OK;
  if (h < 3) {
    r = tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "tb_make_polygon: the points are collinear");
  } else if (h > TB_MAX_POLYGON_VERTICES) {
    r = tb_fail(NULL, TB_ERR_TOO_MANY_VERTICES, "tb_make_polygon: the hull has %d vertices, more than %d", h,
                TB_MAX_POLYGON_VERTICES);
  } else {
    double area = 0.0;
    for (int i = 1; i + 1 < h; ++i) area += 0.5 * turn(hull[0], hull[i], hull[i + 1]);
    tb_polygon made;
    if (area < (double)slop * slop) {
      r = tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "tb_make_polygon: hull area %g m^2 is near zero", area);
    } else {
      finish_polygon(&made, hull, h, radius);
      /* a sliver far out (7e6 m long, 0.4 m wide) can have its float centroid
       * rounded outside it: refuse what no shape would accept, as tb_make_box */
      const char* why = tb_check_polygon(&made);
      if (why == NULL)
        *out = made;
      else
        r = tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "tb_make_polygon: the hull is too thin for float precision: %s",
                    why);
    }
  }
  tb_mem_free(pts, bytes);
  return r;
}

static bool half_extent_ok(float h) { return h > 0.0f && tb_length_ok(h); }

/* The three box makers share this; fn names the one the caller called (each
 * message used to say "tb_make_box" whichever it was). */
static tb_result make_box(const char* fn, float hx, float hy, tb_vec2 center, float angle, tb_polygon* out) {
  if (out == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", fn);
  if (!half_extent_ok(hx))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: hx = %g must be > 0 and finite", fn, (double)hx);
  if (!half_extent_ok(hy))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: hy = %g must be > 0 and finite", fn, (double)hy);
  if (!tb_point_ok(center))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: center is not finite or beyond TB_MAX_LENGTH", fn);
  if (tb_check_angle(NULL, fn, "angle", angle) != TB_OK) return tb_last_result();
  tb_transform xf = {center, angle == 0.0f ? (tb_rot){1.0f, 0.0f} : tb_make_rot(angle)};
  const tb_vec2 corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  const tb_vec2 normals[4] = {{0.0f, -1.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}};
  tb_polygon box;
  memset(&box, 0, sizeof box);
  box.count = 4;
  for (int i = 0; i < 4; ++i) {
    box.vertices[i] = tb_transform_point(xf, corners[i]);
    box.normals[i] = tb_rotate(xf.q, normals[i]);
  }
  box.centroid = center;
  /* far from the origin a small box can collapse to fewer distinct float
   * points: refuse it rather than hand out a polygon no shape accepts */
  const char* why = tb_check_polygon(&box);
  if (why != NULL)
    return tb_fail(NULL, TB_ERR_DEGENERATE_POLYGON, "%s: a box of half-extents %g x %g at (%g, %g): %s", fn, (double)hx,
                   (double)hy, (double)center.x, (double)center.y, why);
  *out = box;
  return TB_OK;
}

tb_result tb_make_offset_box(float hx, float hy, tb_vec2 center, float angle, tb_polygon* out) {
  return make_box(__func__, hx, hy, center, angle, out);
}

tb_result tb_make_box(float hx, float hy, tb_polygon* out) {
  return make_box(__func__, hx, hy, (tb_vec2){0.0f, 0.0f}, 0.0f, out);
}

tb_result tb_make_rounded_box(float hx, float hy, float radius, tb_polygon* out) {
  if (radius < 0.0f || !tb_length_ok(radius))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: radius %g must be >= 0 and finite", __func__, (double)radius);
  tb_result r = make_box(__func__, hx, hy, (tb_vec2){0.0f, 0.0f}, 0.0f, out);
  if (r == TB_OK) out->radius = radius;
  return r;
}

tb_result tb_make_offset_rounded_box(float hx, float hy, tb_vec2 center, float angle, float radius, tb_polygon* out) {
  if (radius < 0.0f || !tb_length_ok(radius))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: radius %g must be >= 0 and finite", __func__, (double)radius);
  tb_result r = make_box(__func__, hx, hy, center, angle, out);
  if (r == TB_OK) out->radius = radius;
  return r;
}
