/* Continuous collision: fast bodies and bullets are moved back to their time of
 * impact so that they cannot pass through thin shapes within one step. */
#ifndef TB_CONTINUOUS_H
#define TB_CONTINUOUS_H

#include "tumble.h"
#include "units.h"

struct tb_world;

/* Gap between the surfaces (length units) at which a swept body is stopped. */
#define TB_TOI_TARGET tb_units.linear_slop
/* Accepted error of that gap: the body stops with a gap of target +- this. */
#define TB_TOI_TOLERANCE (0.25f * tb_units.linear_slop)

/* Called by the step after the solver has moved every awake body from
 * (center0, angle0) to (center, angle) and before the shapes' proxies follow.
 *
 * Every awake dynamic body that is fast (body->is_fast, set by the solver) or a
 * bullet has each non-sensor shape swept from its start to its end pose
 * against static shapes and, for bullets, also against the shapes of kinematic
 * and non-bullet dynamic bodies held at their end-of-step pose. Pairs follow
 * the contact rules: filter bits and groups, the custom filter, joints with
 * collide_connected false, shape types that have a manifold; chain segments
 * only when the shape starts on their front (left) side and closes in on it.
 * Pairs of shapes with pre-solve events (while a pre-solve callback is set) are
 * left to the contact solver, which may disable them (one-way platforms).
 *
 * At the earliest time of impact t < 1 (gap TB_TOI_TARGET) the body is put
 * back on its sweep at t (centre and angle interpolated) and keeps its
 * velocity: the speculative contact of the next step stops it. A pair that
 * already touches at t = 0 is left to the contact solver, except that the
 * shape's core (a disc of a quarter of its thinnest half-width around its
 * centroid) is still swept, so a body grazing a thin wall cannot go through it.
 *
 * Non-bullet fast bodies go first, in awake order, then bullets in awake order
 * (so bullets see where fast bodies ended); candidates come in tree order and
 * ties keep the first: same inputs, same result. Bodies neither fast nor
 * bullets cost one flag test each. */

#endif
