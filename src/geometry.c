/* Mass properties and bounding boxes of circles, capsules, segments and
 * (rounded) convex polygons.
 *
 * Everything is integrated in double about a local reference point near the
 * shape, then shifted: I_center = I_ref - m |c - ref|^2 (parallel-axis theorem).
 * That keeps precision for shapes far from their body origin. */
#include "geometry.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "distance.h"
#include "error.h"
#include "math_internal.h"

#define TB_PI 3.14159265358979323846

/* A mass element: mass, centroid (relative to the reference) and inertia about
 * its own centroid. Elements add up by the parallel-axis theorem. */
typedef struct part {
  double m, cx, cy, i;
} part;

static part part_add(part a, part b) {
  double m = a.m + b.m;
  if (m <= 0.0) return (part){0, 0, 0, 0};
  double cx = (a.m * a.cx + b.m * b.cx) / m;
  double cy = (a.m * a.cy + b.m * b.cy) / m;
  double da = (a.cx - cx) * (a.cx - cx) + (a.cy - cy) * (a.cy - cy);
  double db = (b.cx - cx) * (b.cx - cx) + (b.cy - cy) * (b.cy - cy);
  return (part){m, cx, cy, a.i + a.m * da + b.i + b.m * db};
}

static tb_mass_data part_to_mass(part p, tb_vec2 ref) {
  return (tb_mass_data){(float)p.m, {(float)(ref.x + p.cx), (float)(ref.y + p.cy)}, (float)p.i};
}

/* Disc: m = rho pi r^2, I = m r^2 / 2. */
static tb_mass_data circle_mass(const tb_circle* c, float density) {
  double r = c->radius, m = density * TB_PI * r * r;
  return (tb_mass_data){(float)m, c->center, (float)(0.5 * m * r * r)};
}

/* Capsule of length L = |c2 - c1| and radius r: a 2r x L rectangle,
 * I = m_rect (L^2 + 4 r^2) / 12, plus two half discs. A half disc of mass m_h has
 * its centroid d = 4r/(3 pi) from its flat side and I = m_h r^2/2 - m_h d^2 about
 * that centroid, which sits L/2 + d from the capsule centre. */
static tb_mass_data capsule_mass(const tb_capsule* c, float density) {
  double r = c->radius;
  double dx = (double)c->center2.x - c->center1.x, dy = (double)c->center2.y - c->center1.y;
  double len = sqrt(dx * dx + dy * dy);
  double m_rect = density * 2.0 * r * len;
  double m_half = density * 0.5 * TB_PI * r * r;
  double d = 4.0 * r / (3.0 * TB_PI);
  double off = 0.5 * len + d;
  double i_half = m_half * (0.5 * r * r - d * d + off * off);
  double inertia = m_rect * (len * len + 4.0 * r * r) / 12.0 + 2.0 * i_half;
  tb_vec2 center = {(float)(0.5 * ((double)c->center1.x + c->center2.x)),
                    (float)(0.5 * ((double)c->center1.y + c->center2.y))};
  return (tb_mass_data){(float)(m_rect + 2.0 * m_half), center, (float)inertia};
}

/* Polygon core by a triangle fan about the vertex average `ref`: a triangle
 * (ref, ref+e1, ref+e2) has area D/2 with D = e1 x e2, centroid (e1+e2)/3 and
 * second moment about ref D/12 (e1.e1 + e1.e2 + e2.e2).
 * Rounding radius R adds, exactly, a rectangle L x R on each edge and a circular
 * sector at each corner (the sectors' angles sum to 2 pi). A sector of angle phi
 * has area phi R^2/2, centroid 4 R sin(phi/2) / (3 phi) from its apex along the
 * bisector, and second moment about the apex area R^2/2. */
static tb_mass_data polygon_mass(const tb_polygon* poly, float density) {
  int n = poly->count;
  double rx = 0.0, ry = 0.0;
  for (int i = 0; i < n; ++i) {
    rx += poly->vertices[i].x;
    ry += poly->vertices[i].y;
  }
  tb_vec2 ref = {(float)(rx / n), (float)(ry / n)};

  double area = 0.0, sx = 0.0, sy = 0.0, second = 0.0;
  for (int i = 0; i < n; ++i) {
    double ax = (double)poly->vertices[i].x - ref.x, ay = (double)poly->vertices[i].y - ref.y;
    int j = i + 1 < n ? i + 1 : 0;
    double bx = (double)poly->vertices[j].x - ref.x, by = (double)poly->vertices[j].y - ref.y;
    double d = ax * by - ay * bx;
    area += 0.5 * d;
    sx += 0.5 * d * (ax + bx) / 3.0;
    sy += 0.5 * d * (ay + by) / 3.0;
    second += d / 12.0 * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by);
  }
  double rho = density;
  double cx = sx / area, cy = sy / area;
  part total = {rho * area, cx, cy, rho * (second - area * (cx * cx + cy * cy))};

  double R = poly->radius;
  if (R > 0.0) {
    for (int i = 0; i < n; ++i) {
      int j = i + 1 < n ? i + 1 : 0;
      double ax = (double)poly->vertices[i].x - ref.x, ay = (double)poly->vertices[i].y - ref.y;
      double bx = (double)poly->vertices[j].x - ref.x, by = (double)poly->vertices[j].y - ref.y;
      double ex = bx - ax, ey = by - ay, len = sqrt(ex * ex + ey * ey);
      double nx = ey / len, ny = -ex / len; /* outward for counter-clockwise order */
      double m_rect = rho * len * R;
      part rect = {m_rect, 0.5 * (ax + bx) + 0.5 * R * nx, 0.5 * (ay + by) + 0.5 * R * ny,
                   m_rect * (len * len + R * R) / 12.0};
      total = part_add(total, rect);

      /* the sector at vertex j, between this edge's normal and the next one's */
      int k = j + 1 < n ? j + 1 : 0;
      double fx = (double)poly->vertices[k].x - ref.x - bx, fy = (double)poly->vertices[k].y - ref.y - by;
      double flen = sqrt(fx * fx + fy * fy);
      double mx = fy / flen, my = -fx / flen;
      double phi = atan2(nx * my - ny * mx, nx * mx + ny * my);
      double hx = nx + mx, hy = ny + my, hlen = sqrt(hx * hx + hy * hy);
      double m_sec = rho * 0.5 * phi * R * R;
      double dist = 4.0 * R * sin(0.5 * phi) / (3.0 * phi);
      part sector = {m_sec, bx + dist * hx / hlen, by + dist * hy / hlen, m_sec * (0.5 * R * R - dist * dist)};
      total = part_add(total, sector);
    }
  }
  return part_to_mass(total, ref);
}

/* The public entry points check what they are given (the shapes' own masses
 * above trust the shape, vetted when it was created). */
static bool mass_input_ok(const char* fn, const char* name, const void* geom, const char* why, float density) {
  if (geom == NULL) {
    tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, name);
    return false;
  }
  if (why != NULL) {
    tb_fail(NULL, name[0] == 'p' ? TB_ERR_DEGENERATE_POLYGON : TB_ERR_INVALID_ARGUMENT, "%s: %s", fn, why);
    return false;
  }
  return tb_check_non_negative(NULL, fn, "density", density) == TB_OK;
}

tb_mass_data tb_compute_circle_mass(const tb_circle* circle, float density) {
  const char* why = circle != NULL ? tb_check_circle(circle) : NULL;
  if (!mass_input_ok("tb_compute_circle_mass", "circle", circle, why, density)) return (tb_mass_data){0};
  return circle_mass(circle, density);
}

tb_mass_data tb_compute_capsule_mass(const tb_capsule* capsule, float density) {
  const char* why = capsule != NULL ? tb_check_capsule(capsule) : NULL;
  if (!mass_input_ok("tb_compute_capsule_mass", "capsule", capsule, why, density)) return (tb_mass_data){0};
  return capsule_mass(capsule, density);
}

tb_mass_data tb_compute_polygon_mass(const tb_polygon* polygon, float density) {
  const char* why = polygon != NULL ? tb_check_polygon(polygon) : NULL;
  if (!mass_input_ok("tb_compute_polygon_mass", "polygon", polygon, why, density)) return (tb_mass_data){0};
  return polygon_mass(polygon, density);
}

tb_mass_data tb_shape_geom_mass(const tb_shape* s) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return circle_mass(&s->geom.circle, s->density);
    case TB_SHAPE_CAPSULE: return capsule_mass(&s->geom.capsule, s->density);
    case TB_SHAPE_POLYGON: return polygon_mass(&s->geom.polygon, s->density);
    case TB_SHAPE_SEGMENT: break;
    case TB_SHAPE_CHAIN_SEGMENT: {
      const tb_segment* g = &s->geom.chain_segment.segment;
      return (tb_mass_data){0.0f, tb_lerp(g->point1, g->point2, 0.5f), 0.0f};
    }
  }
  /* a segment has no area: no mass; its midpoint keeps the centre well defined */
  return (tb_mass_data){0.0f, tb_lerp(s->geom.segment.point1, s->geom.segment.point2, 0.5f), 0.0f};
}

/* The point against the core (a point, segment or polygon) plus the radius. */
bool tb_shape_geom_contains(const tb_shape* s, tb_transform xf, tb_vec2 point) {
  tb_vec2 p = tb_inv_transform_point(xf, point);
  switch (s->type) {
    case TB_SHAPE_CIRCLE: {
      float r = s->geom.circle.radius;
      return tb_distance_sq(p, s->geom.circle.center) <= r * r;
    }
    case TB_SHAPE_CAPSULE: {
      const tb_capsule* c = &s->geom.capsule;
      return tb_segment_distance_unchecked(p, p, c->center1, c->center2).distance_sq <= c->radius * c->radius;
    }
    case TB_SHAPE_SEGMENT:
    case TB_SHAPE_CHAIN_SEGMENT: return false;
    case TB_SHAPE_POLYGON: break;
  }
  const tb_polygon* poly = &s->geom.polygon;
  float separation = -FLT_MAX;
  for (int i = 0; i < poly->count; ++i) {
    float d = tb_dot(poly->normals[i], tb_sub(p, poly->vertices[i]));
    if (d > separation) separation = d;
  }
  if (separation <= 0.0f) return true;
  if (separation > poly->radius) return false;
  /* outside the core but within the rounding: the nearest edge decides */
  float r2 = poly->radius * poly->radius;
  for (int i = 0; i < poly->count; ++i) {
    tb_vec2 a = poly->vertices[i], b = poly->vertices[i + 1 < poly->count ? i + 1 : 0];
    if (tb_segment_distance_unchecked(p, p, a, b).distance_sq <= r2) return true;
  }
  return false;
}

static tb_aabb aabb_of_points(const tb_vec2* pts, int n, tb_transform xf, float r) {
  tb_vec2 lo = tb_transform_point(xf, pts[0]), hi = lo;
  for (int i = 1; i < n; ++i) {
    tb_vec2 p = tb_transform_point(xf, pts[i]);
    lo = tb_vmin(lo, p);
    hi = tb_vmax(hi, p);
  }
  return (tb_aabb){{lo.x - r, lo.y - r}, {hi.x + r, hi.y + r}};
}

tb_aabb tb_shape_geom_aabb(const tb_shape* s, tb_transform xf) {
  switch (s->type) {
    case TB_SHAPE_CIRCLE: return aabb_of_points(&s->geom.circle.center, 1, xf, s->geom.circle.radius);
    case TB_SHAPE_CAPSULE: return aabb_of_points(&s->geom.capsule.center1, 2, xf, s->geom.capsule.radius);
    case TB_SHAPE_SEGMENT: return aabb_of_points(&s->geom.segment.point1, 2, xf, 0.0f);
    case TB_SHAPE_CHAIN_SEGMENT: return aabb_of_points(&s->geom.chain_segment.segment.point1, 2, xf, 0.0f);
    case TB_SHAPE_POLYGON:
      return aabb_of_points(s->geom.polygon.vertices, s->geom.polygon.count, xf, s->geom.polygon.radius);
  }
  return (tb_aabb){{0, 0}, {0, 0}};
}

const char* tb_check_circle(const tb_circle* c) {
  if (!tb_point_ok(c->center)) return "circle center is not finite or beyond TB_MAX_LENGTH";
  if (!(c->radius > 0.0f) || !tb_length_ok(c->radius)) return "circle radius must be > 0, finite and <= TB_MAX_LENGTH";
  return NULL;
}

const char* tb_check_capsule(const tb_capsule* c) {
  if (!tb_point_ok(c->center1) || !tb_point_ok(c->center2))
    return "capsule centers are not finite or beyond TB_MAX_LENGTH";
  if (!(c->radius > 0.0f) || !tb_length_ok(c->radius)) return "capsule radius must be > 0, finite and <= TB_MAX_LENGTH";
  if (tb_distance_sq(c->center1, c->center2) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
    return "capsule centers coincide (use a circle)";
  return NULL;
}

const char* tb_check_segment(const tb_segment* s) {
  if (!tb_point_ok(s->point1) || !tb_point_ok(s->point2))
    return "segment points are not finite or beyond TB_MAX_LENGTH";
  if (tb_distance_sq(s->point1, s->point2) < TB_LINEAR_SLOP * TB_LINEAR_SLOP) return "segment points coincide";
  return NULL;
}

/* A polygon handed to a shape must be one tb_make_polygon could have made:
 * 3..max vertices, finite, counter-clockwise and strictly convex, unit normals. */
/* Edge directions in the half turn [0, pi) (y > 0, or y == 0 pointing +x). */
static bool upper_half(tb_vec2 e) { return e.y > 0.0f || (e.y == 0.0f && e.x > 0.0f); }

const char* tb_check_polygon(const tb_polygon* p) {
  if (p->count < 3 || p->count > TB_MAX_POLYGON_VERTICES) return "polygon count must be 3..TB_MAX_POLYGON_VERTICES";
  if (!(p->radius >= 0.0f) || !tb_length_ok(p->radius))
    return "polygon radius must be >= 0, finite and <= TB_MAX_LENGTH";
  int n = p->count, wraps = 0;
  for (int i = 0; i < n; ++i) {
    if (!tb_point_ok(p->vertices[i])) return "polygon vertex is not finite or beyond TB_MAX_LENGTH";
  }
  for (int i = 0; i < n; ++i) {
    tb_vec2 a = p->vertices[i], b = p->vertices[(i + 1) % n], c = p->vertices[(i + 2) % n];
    tb_vec2 e = tb_sub(b, a), f = tb_sub(c, b);
    if (tb_cross(e, f) <= 0.0f) return "polygon is not convex and counter-clockwise (build it with tb_make_polygon)";
    /* left turns everywhere and one full turn of the edge direction: a star
     * polygon (pentagram) turns left at every corner but winds twice */
    if (!upper_half(e) && upper_half(f)) wraps += 1;
    tb_vec2 nrm = p->normals[i];
    if (!tb_vec_finite(nrm) || fabsf(tb_length_sq(nrm) - 1.0f) > 1e-4f)
      return "polygon normals are not unit (build it with tb_make_polygon)";
    /* the outward normal of edge i: perpendicular to it, on its right */
    float len = tb_length(e);
    if (fabsf(tb_dot(nrm, e)) > 1e-3f * len || tb_cross(e, nrm) >= 0.0f)
      return "polygon normals are not the outward normals of their edges (build it with tb_make_polygon)";
  }
  if (wraps != 1) return "polygon is not convex: its edges wind more than once (build it with tb_make_polygon)";
  /* the centroid lies inside (the continuous pass and the chain manifolds use
   * it); in double: a float difference rounds by half a step of the
   * coordinates, more than a sliver's width far out (0.25 m at 4e6 m), and
   * refused polygons tb_make_polygon had made */
  if (!tb_vec_finite(p->centroid)) return "polygon centroid is not finite (build it with tb_make_polygon)";
  for (int i = 0; i < n; ++i) {
    double side = (double)p->normals[i].x * ((double)p->centroid.x - p->vertices[i].x) +
                  (double)p->normals[i].y * ((double)p->centroid.y - p->vertices[i].y);
    if (!(side < 0.0)) return "polygon centroid lies outside the polygon (build it with tb_make_polygon)";
  }
  return NULL;
}
