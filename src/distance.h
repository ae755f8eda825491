/* Distance queries between convex shapes: closest points of two segments, GJK
 * distance with warm starting, linear shape cast, time of impact of two moving
 * shapes, and ray casts against single shapes. Their types and functions are
 * public (include/tumble.h, sections "geometry" and "distance"); this header
 * adds what only the engine uses. */
#ifndef TB_DISTANCE_H
#define TB_DISTANCE_H

#include <stdbool.h>
#include <stdint.h>

#include "tumble.h"

/* tb_segment_distance without the checks, for the engine's own vetted input
 * (a query point in a shape's frame may lie beyond TB_MAX_LENGTH). */
tb_segment_distance_output tb_segment_distance_unchecked(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2);

/* A transform within the world (finite, p within TB_MAX_LENGTH) whose
 * rotation is unit to 1e-3 (a non-unit one would silently scale shapes). */
bool tb_transform_ok(tb_transform xf);

#endif
