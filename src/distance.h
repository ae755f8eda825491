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

/* tb_time_of_impact without the checks, for the engine's own sweeps (valid
 * proxies, finite sweeps within the world, target and tolerance as the
 * continuous pass sets them); *start_distance receives the distance between
 * the two cores at t = 0 (0 where they overlap), from the search's first
 * step. */
void tb_time_of_impact_unchecked(const tb_toi_input* input, tb_toi_output* output, float* start_distance);

/* A transform within the world (finite, p within TB_MAX_LENGTH) whose
 * rotation is unit to 1e-3 (a non-unit one would silently scale shapes). */
bool tb_transform_ok(tb_transform xf);

#endif
