/* A small C interface to Box2D 2.4.1's distance queries for the reference suite
 * of tumble's distance module: b2Distance, b2ShapeCast, b2TimeOfImpact and the
 * ray casts of b2CircleShape, b2PolygonShape and b2EdgeShape.
 *
 * Proxies are passed by value (points and an explicit radius) and handed to
 * b2DistanceProxy::Set(vertices, count, radius), so a polygon is compared with
 * the radius the caller chooses, not Box2D's b2_polygonRadius of 0.01 m that
 * b2DistanceProxy::Set(shape) would add. Box2D has no error path (bad input
 * trips an assert), so every function checks its input first and reports a
 * rejection by returning 0. */
#ifndef TB_B2_DISTANCE_SHIM_H
#define TB_B2_DISTANCE_SHIM_H

#ifdef __cplusplus
extern "C" {
#endif

/* Box2D's b2_maxPolygonVertices. */
#define B2D_MAX_VERTICES 8

typedef struct b2d_proxy {
  float x[B2D_MAX_VERTICES], y[B2D_MAX_VERTICES];
  int count; /* 1..B2D_MAX_VERTICES */
  float radius;
} b2d_proxy;

/* A b2Transform, with the rotation given as (cos, sin) so it is bit-identical to
 * the caller's. */
typedef struct b2d_transform {
  float px, py, c, s;
} b2d_transform;

typedef struct b2d_distance_output {
  float ax, ay, bx, by; /* b2DistanceOutput::pointA, pointB */
  float distance;
  int iterations;
} b2d_distance_output;

/* b2Distance from a cold cache (count 0). use_radii as b2DistanceInput::useRadii. */
int b2d_distance(const b2d_proxy* a, b2d_transform xa, const b2d_proxy* b, b2d_transform xb, int use_radii,
                 b2d_distance_output* out);

typedef struct b2d_cast_output {
  float px, py, nx, ny; /* b2ShapeCastOutput::point, normal */
  float fraction;       /* lambda */
  int iterations;
  int hit; /* b2ShapeCast's return value */
} b2d_cast_output;

/* b2ShapeCast of B translating by (tx, ty) against A. */
int b2d_shape_cast(const b2d_proxy* a, b2d_transform xa, const b2d_proxy* b, b2d_transform xb, float tx, float ty,
                   b2d_cast_output* out);

/* A b2Sweep with alpha0 = 0: centre of mass from c1 to c2, angle from a1 to a2. */
typedef struct b2d_sweep {
  float lcx, lcy;
  float c1x, c1y, c2x, c2y;
  float a1, a2;
} b2d_sweep;

/* b2TOIOutput::State, same order. */
enum { B2D_TOI_UNKNOWN = 0, B2D_TOI_FAILED, B2D_TOI_OVERLAPPED, B2D_TOI_TOUCHING, B2D_TOI_SEPARATED };

typedef struct b2d_toi_output {
  int state;
  float t;
} b2d_toi_output;

/* b2TimeOfImpact over [0, t_max]. Box2D picks its own target and tolerance:
 * target = max(b2_linearSlop, ra + rb - 3 b2_linearSlop) on the distance of the
 * cores, tolerance = 0.25 b2_linearSlop. */
int b2d_time_of_impact(const b2d_proxy* a, const b2d_sweep* sa, const b2d_proxy* b, const b2d_sweep* sb, float t_max,
                       b2d_toi_output* out);

/* Box2D's b2_linearSlop. */
float b2d_linear_slop(void);

/* A b2RayCastInput: from p1 towards p2, up to max_fraction of p2 - p1. */
typedef struct b2d_ray {
  float p1x, p1y, p2x, p2y;
  float max_fraction;
} b2d_ray;

typedef struct b2d_ray_output {
  float nx, ny;
  float fraction;
} b2d_ray_output;

/* Shape ray casts; return 1 on a hit (and fill out), 0 on a miss or bad input. */
int b2d_ray_cast_circle(float cx, float cy, float radius, b2d_transform xf, const b2d_ray* ray, b2d_ray_output* out);
/* xy: count (3..8) counter-clockwise convex vertices (x0, y0, x1, y1, ...), taken as
 * they are (no hull, no welding); the normals are computed as Box2D does. */
int b2d_ray_cast_polygon(const float* xy, int count, b2d_transform xf, const b2d_ray* ray, b2d_ray_output* out);
/* A two-sided edge (b2EdgeShape::SetTwoSided). */
int b2d_ray_cast_edge(float x1, float y1, float x2, float y2, b2d_transform xf, const b2d_ray* ray,
                      b2d_ray_output* out);

#ifdef __cplusplus
}
#endif

#endif
