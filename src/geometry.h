/* Mass properties and bounding boxes of bare geometry (not public beyond tumble.h). */
#ifndef TB_GEOMETRY_H
#define TB_GEOMETRY_H

#include "distance.h"
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
/* The shape as GJK sees it, in body coordinates, unchecked (query.c). */
tb_shape_proxy tb_shape_geom_proxy(const tb_shape* shape);
/* A ray against the shape placed by xf, as the world's ray casts see it (chain
 * segments only from their front side) (query.c). */
void tb_shape_geom_ray_cast(const tb_shape* shape, tb_transform xf, const tb_ray_input* ray, tb_cast_output* out);
struct tb_world;
/* A ray's origin and translation: finite, within TB_MAX_LENGTH, translation
 * not zero; else the error, naming fn (query.c). */
tb_result tb_check_ray(struct tb_world* w, const char* fn, tb_vec2 origin, tb_vec2 translation);

#endif
