/* A C interface to Box2D 2.4.1's contact manifolds for the reference suites
 * and the manifold benchmark (implemented in b2_collide_shim.cpp).
 *
 * Each b2c_collide_* runs the Box2D collide function and then
 * b2WorldManifold::Initialize with the shapes' own radii, and reports the result
 * the way tumble does: world normal from A to B, world points midway between the
 * surfaces, separations. Box2D's shapes carry their skins: a polygon or an edge
 * has radius b2c_polygon_radius() (b2_polygonRadius, 0.01 m) around its core.
 *
 * Polygons are handed over vertex for vertex (vertices, normals, centroid as
 * tumble computed them), so both engines see bit-identical cores. */
#ifndef TB_B2_COLLIDE_SHIM_H
#define TB_B2_COLLIDE_SHIM_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define B2C_MAX_POLYGON_VERTICES 8

typedef struct b2c_transform {
  float x, y; /* position */
  float c, s; /* rotation: cos, sin */
} b2c_transform;

typedef struct b2c_polygon {
  float vertices[B2C_MAX_POLYGON_VERTICES][2]; /* counter-clockwise, convex */
  float normals[B2C_MAX_POLYGON_VERTICES][2];  /* outward unit normals */
  float centroid[2];
  int count; /* 3..8 */
} b2c_polygon;

/* Box2D's b2Manifold::Type */
enum { B2C_CIRCLES = 0, B2C_FACE_A = 1, B2C_FACE_B = 2 };

typedef struct b2c_manifold {
  int point_count;
  int type;              /* B2C_*: which shape held the reference face (with points only) */
  float local_normal[2]; /* b2Manifold::localNormal (in the reference shape's frame) */
  float local_point[2];  /* b2Manifold::localPoint */
  float normal[2];       /* world, A to B */
  float points[2][2];    /* world, midway */
  float separations[2];  /* negative when overlapping */
  uint32_t ids[2];       /* b2ContactID::key */
} b2c_manifold;

/* b2_polygonRadius: the skin of Box2D polygons and edges. */
float b2c_polygon_radius(void);

void b2c_collide_circles(float ax, float ay, float ar, b2c_transform xfa, float bx, float by, float br,
                         b2c_transform xfb, b2c_manifold* out);
void b2c_collide_polygon_and_circle(const b2c_polygon* a, b2c_transform xfa, float bx, float by, float br,
                                    b2c_transform xfb, b2c_manifold* out);
void b2c_collide_polygons(const b2c_polygon* a, b2c_transform xfa, const b2c_polygon* b, b2c_transform xfb,
                          b2c_manifold* out);
/* A two-sided edge v1-v2 (b2EdgeShape::SetTwoSided). */
void b2c_collide_edge_and_circle(float x1, float y1, float x2, float y2, b2c_transform xfa, float bx, float by,
                                 float br, b2c_transform xfb, b2c_manifold* out);
void b2c_collide_edge_and_polygon(float x1, float y1, float x2, float y2, b2c_transform xfa, const b2c_polygon* b,
                                  b2c_transform xfb, b2c_manifold* out);

#ifdef __cplusplus
}
#endif

#endif
