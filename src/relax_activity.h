/* Relax passes solve only what still moves.
 *
 * Each substep relaxes up to relax_iterations times, until no contact point's
 * normal speed changes by more than TB_RELAX_TOLERANCE; how many passes that
 * takes is set by the least settled part of the world (a pile being hit),
 * while a resting pyramid elsewhere, or a ragdoll falling free, was settled
 * after the first pass. So every relax pass records, per solver body, the
 * pass in which a constraint last changed the body's velocity by more than
 * the tolerance (at the body's farthest point: |dv| + |dw| reach), and a pass
 * after the first of its substep skips a constraint none of whose bodies
 * changed in the previous pass or so far in this one: solved again, it would
 * move them by less than the tolerance. The first relax pass after a position
 * update solves everything (the positions moved under every constraint).
 * Within one colour no two contacts share a moving body, so a colour's
 * blocks write different entries; the record never depends on how a pass is
 * split into ranges. */
#ifndef TB_RELAX_ACTIVITY_H
#define TB_RELAX_ACTIVITY_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "solver.h"
#include "units.h"
#include "wide.h"

#define TB_RELAX_TOLERANCE tb_meters(1e-5f) /* m/s: 10 um in a second */

/* Whether a constraint on solver body s is solved in the current relax pass. */
static inline bool tb_relax_active(const tb_step_context* ctx, int s) {
  return ctx->relax_all || ctx->changed_in[s] >= ctx->relax_pass - 1;
}

/* Records that solver body s changed by speed at its farthest point. */
static inline void tb_relax_note(tb_step_context* ctx, int s, float speed) {
  if (speed > TB_RELAX_TOLERANCE && s != ctx->static_index) ctx->changed_in[s] = ctx->relax_pass;
}

/* The speed at solver body s's farthest point that a velocity change makes. */
static inline float tb_relax_speed(const tb_step_context* ctx, int s, tb_vec2 dv, float dw) {
  return fabsf(dv.x) + fabsf(dv.y) + fabsf(dw) * ctx->reach[s];
}

/* Records the solver bodies s[] of the lanes where noted is set, without a
 * branch: a lane not noted, or the static dummy's, writes the sink entry
 * after the dummy's (tb_solve keeps both). */
static inline __attribute__((always_inline)) void tb_relax_note_lanes(tb_step_context* ctx, const int32_t* s,
                                                                      tb_i4 noted) {
  tb_i4 index, stat = {ctx->static_index, ctx->static_index, ctx->static_index, ctx->static_index};
  memcpy(&index, s, sizeof index);
  tb_i4 keep = noted & (index != stat);
  index = (index & keep) | ((stat + 1) & ~keep);
  int32_t* changed_in = ctx->changed_in;
  for (int lane = 0; lane < 4; ++lane) changed_in[index[lane]] = ctx->relax_pass;
}

/* Whether a later relax pass solves a block of four lanes with solver bodies
 * a[] and b[]: whether one of them is active (the static dummy's entry is
 * never written, 0). */
static inline __attribute__((always_inline)) bool tb_relax_lanes_active(const tb_step_context* ctx, const int32_t* a,
                                                                        const int32_t* b) {
  const int32_t* changed_in = ctx->changed_in;
  int32_t since = ctx->relax_pass - 1;
  int active = 0;
  for (int lane = 0; lane < 4; ++lane) active |= (changed_in[a[lane]] >= since) | (changed_in[b[lane]] >= since);
  return active != 0;
}

#endif
