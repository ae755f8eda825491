/* Distance queries between convex shapes (not public yet): closest points of two
 * segments, GJK distance with warm starting, linear shape cast, time of impact of
 * two moving shapes, and ray casts against single shapes.
 *
 * Every shape is seen as a tb_shape_proxy: a convex core (1 to
 * TB_MAX_POLYGON_VERTICES points, in body coordinates) inflated by a radius.
 * The queries return tb_result: TB_OK, or TB_ERR_NULL_ARGUMENT /
 * TB_ERR_INVALID_ARGUMENT with the message in tb_last_error() (bad proxies, NaN
 * or infinite numbers). The output is always written; on error it is a miss
 * (no hit, state TB_TOI_FAILED, distance FLT_MAX). */
#ifndef TB_DISTANCE_H
#define TB_DISTANCE_H

#include <stdbool.h>
#include <stdint.h>

#include "tumble.h"

/* ---------------------------------------------------------------- proxies -- */

/* A proxy of count points (1..TB_MAX_POLYGON_VERTICES, finite) and radius >= 0.
 * The points need not be a hull: GJK only takes support points, so interior and
 * repeated points are harmless. On bad input returns a proxy with count 0 (which
 * every query rejects) and records the error. */
tb_shape_proxy tb_make_proxy(const tb_vec2* points, int count, float radius);
/* Proxies of the shape types, in the shape's own (body) coordinates. */
tb_shape_proxy tb_make_circle_proxy(const tb_circle* circle);
tb_shape_proxy tb_make_capsule_proxy(const tb_capsule* capsule);
tb_shape_proxy tb_make_segment_proxy(const tb_segment* segment);
tb_shape_proxy tb_make_polygon_proxy(const tb_polygon* polygon);

/* ------------------------------------------------------ segment distance -- */

typedef struct tb_segment_distance_output {
  tb_vec2 closest1, closest2; /* closest points on segment 1 and segment 2 */
  float fraction1, fraction2; /* closest_i = p_i + fraction_i (q_i - p_i), in [0, 1] */
  float distance_sq;
} tb_segment_distance_output;

/* Closest points of segments p1-q1 and p2-q2. Either may have zero length. For
 * parallel overlapping segments (a whole family of closest pairs) the pair in
 * the middle of the overlap is returned, so it does not jump between ends. */
tb_segment_distance_output tb_segment_distance(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2);

/* ----------------------------------------------------------- GJK distance -- */

/* Warm start of tb_shape_distance: the vertex indices of the last simplex.
 * Zero it (count = 0) before the first call for a pair; the call updates it. */
typedef struct tb_simplex_cache {
  uint8_t count;
  uint8_t index_a[3];
  uint8_t index_b[3];
} tb_simplex_cache;

typedef struct tb_distance_input {
  tb_shape_proxy proxy_a, proxy_b; /* body coordinates */
  tb_transform xf_a, xf_b;
} tb_distance_input;

/* Distance between the rounded shapes, clamped at 0 like Box2D. With separated
 * surfaces, point_a and point_b lie on the two rounded surfaces. When the rounded
 * surfaces overlap but the cores do not, both points are the midpoint of the two
 * surface points and normal is still the direction between the cores; when the
 * cores overlap, both points are a common point of the cores and normal is zero. */
typedef struct tb_distance_output {
  tb_vec2 point_a, point_b; /* world */
  tb_vec2 normal;           /* unit, from A to B; zero when the cores overlap */
  float distance;           /* >= 0 */
  int iterations;           /* support point evaluations */
  int simplex_count;        /* 1 vertex, 2 edge, 3 overlap of the cores */
} tb_distance_output;

/* GJK on the cores, computed in A's frame (so far from the origin only the
 * relative placement matters), then the radii. cache may be NULL. */
tb_result tb_shape_distance(const tb_distance_input* input, tb_simplex_cache* cache, tb_distance_output* output);

/* ------------------------------------------------------------ shape cast -- */

/* The tolerance to which casts and the fractions they report converge: at the
 * reported fraction the gap between the rounded surfaces is in [0, tolerance]. */
#define TB_CAST_TOLERANCE 1.0e-4f

typedef struct tb_shape_cast_input {
  tb_shape_proxy proxy_a, proxy_b; /* body coordinates */
  tb_transform xf_a, xf_b;
  tb_vec2 translation_b; /* world translation of B over the cast; A stays fixed */
} tb_shape_cast_input;

/* Result of a ray or shape cast. */
typedef struct tb_cast_output {
  tb_vec2 point;  /* world: where the ray enters, or the contact point on A's surface */
  tb_vec2 normal; /* unit surface normal at the hit (of the shape, or of A towards B) */
  float fraction; /* of the translation, in [0, max_fraction] */
  int iterations;
  bool hit;
} tb_cast_output;

/* B moves by fraction * translation_b (no rotation). Conservative advancement on
 * the GJK simplex (GJK ray cast): hit is the first fraction in [0, 1] at which the
 * rounded shapes come within TB_CAST_TOLERANCE; the normal there is exact to
 * rounding where the contact has one (a vertex meeting an edge, or a rounded
 * shape), and a separating axis where two vertices meet. Shapes that already
 * touch or overlap report a hit at fraction 0 (normal zero if their cores
 * overlap). The fraction is never past the true contact; in the rare case that
 * the iterations run out it is reported as a hit at the safe fraction reached. */
tb_result tb_shape_cast(const tb_shape_cast_input* input, tb_cast_output* output);

/* --------------------------------------------------------- time of impact -- */

/* The motion of a body over a step, by its centre of mass: linear in position and
 * angle between t = 0 and t = 1. */
typedef struct tb_sweep {
  tb_vec2 local_center; /* centre of mass in body coordinates */
  tb_vec2 c1, c2;       /* world centre of mass at t = 0 and t = 1 */
  float a1, a2;         /* angle at t = 0 and t = 1 */
} tb_sweep;

/* The body transform (of the body origin) at time t of the sweep. */
tb_transform tb_sweep_transform(const tb_sweep* sweep, float t);

typedef struct tb_toi_input {
  tb_shape_proxy proxy_a, proxy_b; /* body coordinates */
  tb_sweep sweep_a, sweep_b;
  float t_max;     /* the interval searched is [0, t_max], t_max in [0, 1] */
  float target;    /* gap between the rounded surfaces to stop at, e.g. TB_LINEAR_SLOP;
                      may be negative down to -(radius_a + radius_b) */
  float tolerance; /* > 0; accepted gap at the hit: target +- tolerance */
} tb_toi_input;

typedef enum tb_toi_state {
  TB_TOI_HIT = 0,    /* gap reaches target (within tolerance) at t */
  TB_TOI_SEPARATED,  /* the gap stays above target over [0, t_max]; t = t_max */
  TB_TOI_OVERLAPPED, /* already closer than target - tolerance at t = 0; t = 0 */
  TB_TOI_FAILED      /* bad input, or no convergence: t is still a safe time
                        (the gap stays above target up to it) */
} tb_toi_state;

typedef struct tb_toi_output {
  tb_toi_state state;
  float t;
  int iterations; /* advancement steps (one GJK call each) */
} tb_toi_output;

/* Conservative advancement: never steps past the first time the gap falls to the
 * target, including contacts caused by rotation that end again before t_max. */
tb_result tb_time_of_impact(const tb_toi_input* input, tb_toi_output* output);

/* ------------------------------------------------------------- ray casts -- */

typedef struct tb_ray_input {
  tb_vec2 origin;      /* world */
  tb_vec2 translation; /* the ray is origin + fraction * translation */
  float max_fraction;  /* >= 0; usually 1 */
} tb_ray_input;

/* Ray casts against a shape placed by xf. The ray hits where it enters the shape:
 * a ray that starts inside (strictly) a circle, capsule or polygon reports no
 * hit, as Box2D 2.4.1 does; one that starts on the surface and goes in hits at
 * fraction 0. A segment is hit from either side, with the normal facing the ray
 * origin; a ray along the segment's line does not hit it. A zero-length ray hits
 * nothing (TB_OK); a non-finite ray is an error. Rounded polygons are supported. */
tb_result tb_ray_cast_circle(const tb_ray_input* ray, const tb_circle* circle, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_capsule(const tb_ray_input* ray, const tb_capsule* capsule, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_segment(const tb_ray_input* ray, const tb_segment* segment, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_polygon(const tb_ray_input* ray, const tb_polygon* polygon, tb_transform xf, tb_cast_output* out);

#endif
