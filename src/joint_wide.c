/* Point joints, four at a time (joint_wide.h).
 *
 * The point constraint C = d = pB - pA of a revolute joint (joint.c), with
 * the arms r = dq f turned by each body's rotation since the step began and
 *   Cdot = vB + wB x rB - vA - wA x rA,
 *   K = (mA + mB) I + iA perp(rA) perp(rA)^T + iB perp(rB) perp(rB)^T,
 * the impulse -mass_scale K^-1 (Cdot + bias_rate C) - impulse_scale P.
 * joint.c solves K in double: K's entries are inverse masses times squared
 * arms, and k11 k22 - k12^2 in float overflows or cancels for a light body
 * far from its anchor. Here the determinant is summed from terms that are
 * all >= 0 (det(m I + A) = m^2 + m tr A + det A for the two rank-one terms A,
 * and det A = iA iB (rA x rB)^2), so it has no cancellation and is accurate
 * to a few ulps in float; and a joint is taken only while each of m and
 * iA |fA|^2, iB |fB|^2 lies within [1e-12, 1e12] (the first) or below 1e12,
 * so no term can overflow. Others stay with joint.c.
 *
 * A joint grid (Box2D v3's joint_grid benchmark: 19,800 of them) spent 45%
 * of its step in the one-at-a-time path: a 256-byte joint record behind an
 * index, both solver bodies copied in and out, a switch on the type. A block
 * here holds what the passes read (176 bytes for four joints). Within one
 * colour no two lanes share a moving body, so the lanes, and the blocks of
 * a colour, may be solved in any order; blocks are laid out colour by colour
 * in step order, which makes the result deterministic. */
#include "joint_wide.h"

#include <math.h>
#include <string.h>

#include "color.h"
#include "joint.h"
#include "memory.h"
#include "relax_activity.h"
#include "wide.h"
#include "world.h"

typedef struct tb_wide_joint {
  int32_t a[4], b[4]; /* solver bodies */
  int32_t joint[4];   /* the joint of each lane, -1 for an unused one */
  int32_t unused[4];  /* (the lanes' fields start on 16 bytes) */
  tb_f4 fax, fay, fbx, fby; /* anchors from the centres of mass, world axes, step start */
  tb_f4 dcx, dcy;           /* centre of B minus centre of A at the step start */
  tb_f4 px, py;             /* the accumulated impulse */
} tb_wide_joint;

#define TB_WIDE_MASS_MIN 1e-12f
#define TB_WIDE_MASS_MAX 1e12f

void tb_wide_joints_free(tb_wide_joints* wj) {
  tb_mem_free(wj->blocks, (size_t)wj->block_capacity * sizeof *wj->blocks);
  *wj = (tb_wide_joints){0};
}

size_t tb_wide_joints_bytes(const tb_wide_joints* wj) { return (size_t)wj->block_capacity * sizeof *wj->blocks; }

bool tb_wide_joint_fits(const tb_joint* j, const tb_step_context* ctx) {
  if (j->type != TB_JOINT_REVOLUTE || j->skip || (j->enable_spring && j->hertz > 0.0f) || j->enable_motor ||
      j->enable_limit)
    return false;
  const tb_solver_body *a = &ctx->states[j->solver_a], *b = &ctx->states[j->solver_b];
  float m = a->inv_mass + b->inv_mass;
  float turn_a = a->inv_inertia * (j->frame_a.x * j->frame_a.x + j->frame_a.y * j->frame_a.y);
  float turn_b = b->inv_inertia * (j->frame_b.x * j->frame_b.x + j->frame_b.y * j->frame_b.y);
  return m >= TB_WIDE_MASS_MIN && m <= TB_WIDE_MASS_MAX && turn_a <= TB_WIDE_MASS_MAX && turn_b <= TB_WIDE_MASS_MAX;
}

/* A moving solver body's index, or -1 (static, kinematic: shared freely). */
static int moving(const tb_step_context* ctx, int s) { return ctx->states[s].inv_mass > 0.0f ? s : -1; }

void tb_wide_joints_build(tb_world* w, const tb_step_context* ctx) {
  tb_wide_joints* wj = &w->wide_joints;
  int count = w->step_joint_count, bodies = ctx->static_index + 1;
  wj->block_count = 0;
  w->scalar_joint_count = count;
  /* scratch: per body the colour bits, (step joint, a, b) per taken joint,
   * the colour of each step joint (-1: not taken), then per colour its next
   * lane */
  if (!tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, bodies + 4 * count, sizeof(int))) return;
  int32_t* waiting = w->scratch + bodies;
  int32_t* color = w->scratch + bodies + 3 * count;
  tb_step_joint* info = w->step_joint_info;
  int taken = 0;
  for (int k = 0; k < count; ++k) {
    color[k] = -1;
    if (!info[k].point_only || info[k].in_tree) continue;
    waiting[3 * taken] = k;
    waiting[3 * taken + 1] = moving(ctx, info[k].solver_a);
    waiting[3 * taken + 2] = moving(ctx, info[k].solver_b);
    taken += 1;
  }
  if (taken == 0) return;
  int colors = tb_color_rounds(bodies, (uint32_t*)w->scratch, waiting, taken, 0, color);
  if (!tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, bodies + 4 * count + colors, sizeof(int))) return;
  color = w->scratch + bodies + 3 * count;
  int32_t* next = w->scratch + bodies + 4 * count;
  memset(next, 0, (size_t)colors * sizeof *next);
  for (int k = 0; k < count; ++k)
    if (color[k] >= 0) next[color[k]] += 1;
  int blocks = 0;
  for (int c = 0; c < colors; ++c) {
    int in_color = next[c];
    next[c] = 4 * blocks;
    blocks += (in_color + 3) / 4;
  }
  if (!tb_array_reserve((void**)&wj->blocks, &wj->block_capacity, blocks, sizeof *wj->blocks)) return;

  /* the lane of each taken step joint (in waiting's room: the colouring is
   * done with it), and the step joints and their info: the others first in
   * their order, then the taken ones (their info in the blocks' room, free
   * until the blocks are filled) */
  int32_t* lane_of = w->scratch + bodies;
  int32_t* moved = w->scratch + bodies + count;
  tb_step_joint* moved_info = (tb_step_joint*)wj->blocks;
  _Static_assert(sizeof(tb_wide_joint) >= 4 * sizeof(tb_step_joint), "a block holds the info of its four joints");
  int others = 0, t = 0;
  for (int k = 0; k < count; ++k) {
    int index = w->step_joints[k];
    if (color[k] >= 0) {
      lane_of[t] = next[color[k]]++;
      moved_info[t] = info[k];
      moved[t++] = index;
    } else {
      info[others] = info[k];
      w->step_joints[others++] = index;
    }
  }
  memcpy(w->step_joints + others, moved, (size_t)taken * sizeof *moved);
  memcpy(info + others, moved_info, (size_t)taken * sizeof *moved_info);
  w->scalar_joint_count = others;

  wj->block_count = blocks;
  for (int b = 0; b < blocks; ++b) {
    tb_wide_joint* wb = &wj->blocks[b];
    memset(wb, 0, sizeof *wb);
    for (int lane = 0; lane < 4; ++lane) {
      wb->a[lane] = wb->b[lane] = ctx->static_index;
      wb->joint[lane] = -1;
    }
  }
  for (int i = 0; i < taken; ++i) {
    int lane = lane_of[i], index = w->step_joints[others + i];
    tb_wide_joint* wb = &wj->blocks[lane / 4];
    lane %= 4;
    const tb_joint* j = tb_joint_at(w, index);
    wb->a[lane] = j->solver_a;
    wb->b[lane] = j->solver_b;
    wb->joint[lane] = index;
    wb->fax[lane] = j->frame_a.x;
    wb->fay[lane] = j->frame_a.y;
    wb->fbx[lane] = j->frame_b.x;
    wb->fby[lane] = j->frame_b.y;
    wb->dcx[lane] = j->delta_center.x;
    wb->dcy[lane] = j->delta_center.y;
    wb->px[lane] = j->linear_impulse.x;
    wb->py[lane] = j->linear_impulse.y;
  }
}

/* The arms now: the step start's, turned with each body (dq). */
typedef struct wide_frame {
  tb_f4 rax, ray, rbx, rby;
} wide_frame;

static inline __attribute__((always_inline)) wide_frame arms(const tb_wide_joint* j, const tb_solver_body* states) {
  const tb_solver_body *a0 = &states[j->a[0]], *a1 = &states[j->a[1]], *a2 = &states[j->a[2]], *a3 = &states[j->a[3]];
  const tb_solver_body *b0 = &states[j->b[0]], *b1 = &states[j->b[1]], *b2 = &states[j->b[2]], *b3 = &states[j->b[3]];
  tb_f4 qac = {a0->dq.c, a1->dq.c, a2->dq.c, a3->dq.c}, qas = {a0->dq.s, a1->dq.s, a2->dq.s, a3->dq.s};
  tb_f4 qbc = {b0->dq.c, b1->dq.c, b2->dq.c, b3->dq.c}, qbs = {b0->dq.s, b1->dq.s, b2->dq.s, b3->dq.s};
  return (wide_frame){qac * j->fax - qas * j->fay, qas * j->fax + qac * j->fay, qbc * j->fbx - qbs * j->fby,
                      qbs * j->fbx + qbc * j->fby};
}

/* The impulse P at the anchors: -P on A at rA, +P on B at rB. */
static inline __attribute__((always_inline)) void apply(const wide_frame* f, tb_f4 Px, tb_f4 Py, wide_body* A,
                                                        wide_body* B) {
  A->vx -= A->inv_mass * Px;
  A->vy -= A->inv_mass * Py;
  A->w -= A->inv_inertia * (f->rax * Py - f->ray * Px);
  B->vx += B->inv_mass * Px;
  B->vy += B->inv_mass * Py;
  B->w += B->inv_inertia * (f->rbx * Py - f->rby * Px);
}

void tb_wide_joints_warm_start(tb_world* w, tb_step_context* ctx) {
  tb_wide_joints* wj = &w->wide_joints;
  for (int b = 0; b < wj->block_count; ++b) {
    tb_wide_joint* j = &wj->blocks[b];
    wide_body A = gather(ctx->states, j->a), B = gather(ctx->states, j->b);
    wide_frame f = arms(j, ctx->states);
    apply(&f, j->px, j->py, &A, &B);
    scatter(ctx->states, j->a, &A);
    scatter(ctx->states, j->b, &B);
  }
}

/* Notes the lanes' bodies that the pass moved (relax_activity.h): the speed
 * change at a body's farthest point, |dv.x| + |dv.y| + |dw| reach. */
static void note_moved(tb_step_context* ctx, const int32_t* s, const wide_body* before, const wide_body* after) {
  tb_f4 dvx = after->vx - before->vx, dvy = after->vy - before->vy, dw = after->w - before->w;
  for (int lane = 0; lane < 4; ++lane)
    tb_relax_note(ctx, s[lane], fabsf(dvx[lane]) + fabsf(dvy[lane]) + fabsf(dw[lane]) * ctx->reach[s[lane]]);
}

static inline __attribute__((always_inline)) void solve_block(tb_wide_joint* j, tb_step_context* ctx, tb_softness s,
                                                              bool use_bias, bool zero_first) {
  tb_solver_body* states = ctx->states;
  wide_body A = gather(states, j->a), B = gather(states, j->b);
  wide_body A0 = A, B0 = B;
  wide_frame f = arms(j, states);
  if (zero_first) j->px = j->py = splat(0.0f);
  tb_f4 rx = (B.vx + -B.w * f.rby) - (A.vx + -A.w * f.ray);
  tb_f4 ry = (B.vy + B.w * f.rbx) - (A.vy + A.w * f.rax);
  if (use_bias) { /* C = (dpB - dpA + (cB - cA)) + (rB - rA) */
    tb_f4 bias = splat(s.bias_rate);
    rx += bias * (((B.dpx - A.dpx) + j->dcx) + (f.rbx - f.rax));
    ry += bias * (((B.dpy - A.dpy) + j->dcy) + (f.rby - f.ray));
  }
  tb_f4 m = A.inv_mass + B.inv_mass, ia = A.inv_inertia, ib = B.inv_inertia;
  tb_f4 k11 = m + ia * f.ray * f.ray + ib * f.rby * f.rby;
  tb_f4 k12 = -ia * f.rax * f.ray - ib * f.rbx * f.rby;
  tb_f4 k22 = m + ia * f.rax * f.rax + ib * f.rbx * f.rbx;
  tb_f4 cross = f.rax * f.rby - f.ray * f.rbx;
  tb_f4 det = m * m + m * (ia * (f.rax * f.rax + f.ray * f.ray) + ib * (f.rbx * f.rbx + f.rby * f.rby)) +
              ia * ib * cross * cross;
  tb_f4 inv = inverse_or_zero(det); /* 0 in an unused lane */
  tb_f4 xx = inv * (k22 * rx - k12 * ry), xy = inv * (k11 * ry - k12 * rx);
  tb_f4 ms = splat(s.mass_scale), is = splat(s.impulse_scale);
  tb_f4 Px = -ms * xx - is * j->px, Py = -ms * xy - is * j->py;
  j->px += Px;
  j->py += Py;
  apply(&f, Px, Py, &A, &B);
  scatter(states, j->a, &A);
  scatter(states, j->b, &B);
  if (!use_bias) {
    note_moved(ctx, j->a, &A0, &A);
    note_moved(ctx, j->b, &B0, &B);
  }
}

void tb_wide_joints_solve(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_wide_joints* wj = &w->wide_joints;
  /* Without warm starting every substep accumulates from zero (its biased
   * solve comes first), as joint.c does. */
  bool zero_first = use_bias && !ctx->enable_warm_starting;
  if (use_bias)
    for (int b = 0; b < wj->block_count; ++b) solve_block(&wj->blocks[b], ctx, ctx->joint_softness, true, zero_first);
  else if (ctx->relax_all)
    for (int b = 0; b < wj->block_count; ++b) solve_block(&wj->blocks[b], ctx, tb_rigid_softness(), false, false);
  else
    for (int b = 0; b < wj->block_count; ++b)
      if (tb_relax_lanes_active(ctx, wj->blocks[b].a, wj->blocks[b].b))
        solve_block(&wj->blocks[b], ctx, tb_rigid_softness(), false, false);
}

void tb_wide_joints_store(tb_world* w, const tb_step_context* ctx) {
  const tb_wide_joints* wj = &w->wide_joints;
  for (int b = 0; b < wj->block_count; ++b) {
    const tb_wide_joint* j = &wj->blocks[b];
    for (int lane = 0; lane < 4; ++lane)
      if (j->joint[lane] >= 0)
        tb_joint_store_point(tb_joint_at(w, j->joint[lane]), (tb_vec2){j->px[lane], j->py[lane]}, ctx);
  }
}
