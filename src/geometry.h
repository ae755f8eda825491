/* Mass properties and bounding boxes of bare geometry (not public beyond tumble.h). */
#ifndef TB_GEOMETRY_H
#define TB_GEOMETRY_H

#include "shape.h"

tb_mass_data tb_shape_geom_mass(const tb_shape* shape);
tb_aabb tb_shape_geom_aabb(const tb_shape* shape, tb_transform xf);
/* Whether a world point lies in the shape (boundary included; segments contain nothing). */
bool tb_shape_geom_contains(const tb_shape* shape, tb_transform xf, tb_vec2 point);
/* NULL when valid, else a message naming what is wrong with the geometry. */
const char* tb_check_circle(const tb_circle* c);
const char* tb_check_capsule(const tb_capsule* c);
const char* tb_check_segment(const tb_segment* s);
const char* tb_check_polygon(const tb_polygon* p);

#endif
