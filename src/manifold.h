/* Contact manifolds (the narrow phase): the feature-id layout and the
 * narrow phase's form of a collide function (not public).
 *
 * A manifold point's id names the pair of features that made it, one byte each:
 *   bits 0-7   index of the feature on shape A (vertex or edge index)
 *   bits 8-15  index of the feature on shape B
 *   bit  16    the feature on A is an edge (face), else a vertex
 *   bit  24    the feature on B is an edge (face), else a vertex
 * An edge i runs from vertex i to vertex i + 1. A circle's centre is vertex 0; a
 * capsule or segment is a two-vertex polygon whose edge 0 faces its right side
 * (the side of right_perp(point2 - point1)) and edge 1 the other.
 *
 * The id depends only on which features touch, never on which shape supplied the
 * reference face: "vertex k of B on edge f of A" is the same id whether B's edge
 * was clipped by A or A's face was the one clipped. So when two parallel faces
 * swap roles between steps (a box resting flat on another), the ids stay put.
 * One-point contacts of a circle always use id 0: the point is the same contact
 * whether the circle touches a face or a corner, so its impulse carries over as
 * it rolls over the corner. */
#ifndef TB_MANIFOLD_H
#define TB_MANIFOLD_H

#include <stdbool.h>
#include <stdint.h>

#include "tumble.h"

#define TB_FEATURE_VERTEX 0u
#define TB_FEATURE_EDGE 1u

static inline uint32_t tb_make_feature_id(uint32_t index_a, uint32_t type_a, uint32_t index_b, uint32_t type_b) {
  return (index_a & 0xffu) | (index_b & 0xffu) << 8 | type_a << 16 | type_b << 24;
}

/* Where the touching features of a manifold end (the narrow phase's extra
 * output; the solver uses it between collisions). Let d be how far B's core
 * has slid relative to A's along the tangent t = right_perp(normal) since
 * the collision, measured at offset_a and offset_b along the normal from the
 * manifold points (on the cores: a rolling ball's centre moves, its contact
 * point does not). While slide_min <= d <= slide_max the contact is the
 * one collided; beyond, by x, what touches is the two cores' ends, x apart
 * along t, whose gap is sqrt(x^2 + core_gap^2) - radius (radius: the two
 * cores' radii). A face contact ends where its features stop overlapping
 * (slide_min <= 0 <= slide_max; both offsets at the incident core); a vertex
 * against a vertex, apart and with a rounding (a circle on a corner), has
 * slide_min = slide_max = 0, offsets at each core, so its gap follows the
 * rounding's curvature (two sharp corners do not: sliding, a corner meets
 * the other's edge, not a growing gap); contacts that do not end (a chain
 * face that runs on into its neighbour) have -FLT_MAX, FLT_MAX.
 * A face contact also gives the reference face's ends (in A's frame, on its core):
 * end_max is where the patch ends for d > 0, end_min for d < 0, and the
 * face's normal points towards the incident shape (reference_normal). */
typedef struct tb_patch {
  float slide_min, slide_max;
  float offset_a, offset_b;
  float radius;
  bool face;
  tb_vec2 end_min, end_max, reference_normal;
} tb_patch;

/* The public functions' checks: false (and the error recorded, naming fn and
 * the argument) for a NULL shape, a shape that tb_check_* refused (why_a,
 * why_b: its answer, NULL when the shape is fine or NULL) or a transform that
 * is not finite, beyond TB_MAX_LENGTH or not a unit rotation. */
bool tb_collide_args_ok(const char* fn, const void* a, const char* why_a, tb_transform xfa, const void* b,
                        const char* why_b, tb_transform xfb);
/* why_a / why_b for tb_collide_args_ok: check's answer, NULL for a NULL shape
 * (tb_collide_args_ok reports that one itself). */
#define TB_COLLIDE_WHY(check, shape) ((shape) != NULL ? check(shape) : NULL)

/* The narrow phase's collide functions: the public ones without their checks.
 * The world's shapes were vetted when they were made and its transforms come
 * from the solver, so the step pays nothing per contact for the checks.
 * patch (may be NULL) receives where the touching features end.
 * These trust what they get: a polygon of count 100 overflows the stack. */
tb_manifold tb_collide_circles_unchecked(const tb_circle* a, tb_transform xfa, const tb_circle* b, tb_transform xfb,
                                         tb_patch* patch);
tb_manifold tb_collide_capsule_and_circle_unchecked(const tb_capsule* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_capsules_unchecked(const tb_capsule* a, tb_transform xfa, const tb_capsule* b, tb_transform xfb,
                                          tb_patch* patch);
tb_manifold tb_collide_segment_and_circle_unchecked(const tb_segment* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_segment_and_capsule_unchecked(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                                     tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_segment_and_polygon_unchecked(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                                     tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_polygon_and_circle_unchecked(const tb_polygon* a, tb_transform xfa, const tb_circle* b,
                                                    tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_polygon_and_capsule_unchecked(const tb_polygon* a, tb_transform xfa, const tb_capsule* b,
                                                     tb_transform xfb, tb_patch* patch);
/* B on the left face of segment A (normal left_perp(point2 - point1)), that
 * face the reference even where a face of B separates more (chain.c). */
tb_manifold tb_collide_segment_face_and_capsule_unchecked(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                                          tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_segment_face_and_polygon_unchecked(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                                          tb_transform xfb, tb_patch* patch);
/* chain.c */
tb_manifold tb_collide_chain_segment_and_circle_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                          const tb_circle* b, tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_chain_segment_and_capsule_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                           const tb_capsule* b, tb_transform xfb, tb_patch* patch);
tb_manifold tb_collide_chain_segment_and_polygon_unchecked(const tb_chain_segment* a, tb_transform xfa,
                                                           const tb_polygon* b, tb_transform xfb, tb_patch* patch);

/* Two polygons, unchecked, for the narrow phase, which keeps the manifold in
 * the contact: written there field by field (copied from a returned one, it
 * would be read back wider than it was just written, a stall; see manifold.c). */
void tb_collide_polygons_into(const tb_polygon* a, tb_transform xfa, const tb_polygon* b, tb_transform xfb,
                              tb_manifold* out, tb_patch* patch);

#endif
