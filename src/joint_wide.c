/* Revolute joints, four at a time (joint_wide.h).
 *
 * The angle rows of revolute_solve in joint.c (spring, motor, lower and
 * upper limit, in that order, on wB - wA with mass 1 / (iA + iB)), with a
 * lane mask per row, then the point. A joint a tree holds keeps its point
 * in the tree (its impulse stays in the joint record, which the tree
 * updates); the block solves its angle rows. The point constraint C = d = pB - pA of a revolute joint (joint.c), with
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
 * here holds what the point passes read (208 bytes for four joints; the
 * angle rows beside it, 256 bytes, only where a lane has them). Rain's
 * ragdolls (10,000 joints with springs, friction motors and limits, in
 * trees) spent 21% of their step in the angle rows one at a time. Within one
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
  int32_t a[4], b[4];       /* solver bodies */
  int32_t joint[4];         /* the joint of each lane, -1 for an unused one */
  int32_t angles;           /* any lane with a spring, motor or limit */
  int32_t tree;             /* any lane whose point a joint tree solves */
  int32_t points;           /* lanes whose point this block solves (none and no angles: only the warm start) */
  int32_t unused;           /* (the lanes' fields start on 16 bytes) */
  tb_f4 fax, fay, fbx, fby; /* anchors from the centres of mass, world axes, step start */
  tb_f4 dcx, dcy;           /* centre of B minus centre of A at the step start */
  tb_f4 px, py;             /* the accumulated impulse (in a tree's lanes the tree keeps it, in the joint) */
  tb_f4 point;              /* 1 where this block solves the point: the joint is in no tree */
} tb_wide_joint;

/* The angle rows of a block's lanes, as revolute_solve in joint.c, beside
 * the blocks (set only for blocks with angles: a grid of plain joints
 * streams none of it). */
typedef struct tb_wide_angles {
  tb_f4 angle0; /* angle_b - angle_a - reference angle at the step start */
  tb_f4 spring, spring_bias, spring_mass_scale, spring_impulse_scale, spring_impulse;
  tb_f4 motor, motor_speed, max_motor, motor_impulse; /* max_motor: the largest impulse in a substep */
  tb_f4 limit, lower, upper, lower_impulse, upper_impulse;
} tb_wide_angles;

#define TB_WIDE_MASS_MIN 1e-12f
#define TB_WIDE_MASS_MAX 1e12f

void tb_wide_joints_free(tb_wide_joints* wj) {
  tb_mem_free(wj->blocks, (size_t)wj->block_capacity * sizeof *wj->blocks);
  tb_mem_free(wj->angles, (size_t)wj->angle_capacity * sizeof *wj->angles);
  *wj = (tb_wide_joints){0};
}

size_t tb_wide_joints_bytes(const tb_wide_joints* wj) {
  return (size_t)wj->block_capacity * sizeof *wj->blocks + (size_t)wj->angle_capacity * sizeof *wj->angles;
}

bool tb_wide_joint_fits(const tb_joint* j, const tb_step_context* ctx) {
  if (j->type != TB_JOINT_REVOLUTE || j->skip) return false;
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
  int count = w->step_joint_count - w->tree_joint_count, bodies = ctx->static_index + 1;
  wj->block_count = 0;
  w->scalar_joint_count = count;
  if (w->joints_one_at_a_time) return;
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
    if (!info[k].wide) continue;
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
  if (!tb_array_reserve((void**)&wj->blocks, &wj->block_capacity, blocks, sizeof *wj->blocks) ||
      !tb_array_reserve((void**)&wj->angles, &wj->angle_capacity, blocks, sizeof *wj->angles))
    return;

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
    if (i + 8 < taken) { /* the records lie all over memory: two thirds of this loop waited on them */
      const char* r = (const char*)tb_joint_at(w, w->step_joints[others + i + 8]);
      for (size_t line = 0; line < sizeof(tb_joint); line += 64) __builtin_prefetch(r + line);
    }
    int lane = lane_of[i], index = w->step_joints[others + i];
    tb_wide_joint* wb = &wj->blocks[lane / 4];
    tb_wide_angles* an = &wj->angles[lane / 4];
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
    wb->point[lane] = j->in_tree ? 0.0f : 1.0f;
    wb->tree |= j->in_tree;
    wb->points += !j->in_tree;
    if (tb_joint_point_only(j)) continue;
    bool spring = j->enable_spring && j->hertz > 0.0f;
    if (!wb->angles) memset(an, 0, sizeof *an); /* the block's first lane with angle rows */
    wb->angles = 1;
    an->angle0[lane] = j->delta_angle;
    an->spring[lane] = spring ? 1.0f : 0.0f;
    an->spring_bias[lane] = j->spring_softness.bias_rate;
    an->spring_mass_scale[lane] = j->spring_softness.mass_scale;
    an->spring_impulse_scale[lane] = j->spring_softness.impulse_scale;
    an->spring_impulse[lane] = j->spring_impulse;
    an->motor[lane] = j->enable_motor ? 1.0f : 0.0f;
    an->motor_speed[lane] = j->motor_speed;
    an->max_motor[lane] = j->max_motor * ctx->h;
    an->motor_impulse[lane] = j->motor_impulse;
    an->limit[lane] = j->enable_limit ? 1.0f : 0.0f;
    an->lower[lane] = j->lower;
    an->upper[lane] = j->upper;
    an->lower_impulse[lane] = j->lower_impulse;
    an->upper_impulse[lane] = j->upper_impulse;
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

/* The point impulses the joint trees keep for their lanes (in the joints). */
static void tree_impulses(const tb_world* w, const tb_wide_joint* j, tb_f4* px, tb_f4* py) {
  for (int lane = 0; lane < 4; ++lane)
    if (j->joint[lane] >= 0 && j->point[lane] == 0.0f) {
      tb_vec2 p = tb_joint_at(w, j->joint[lane])->linear_impulse;
      (*px)[lane] = p.x;
      (*py)[lane] = p.y;
    }
}

void tb_wide_joints_warm_start(tb_world* w, tb_step_context* ctx) {
  tb_wide_joints* wj = &w->wide_joints;
  for (int b = 0; b < wj->block_count; ++b) {
    tb_wide_joint* j = &wj->blocks[b];
    wide_body A = gather(ctx->states, j->a), B = gather(ctx->states, j->b);
    wide_frame f = arms(j, ctx->states);
    if (j->angles) { /* revolute_warm_start: the angle rows' impulses, then the point's */
      const tb_wide_angles* an = &wj->angles[b];
      tb_f4 axial = an->spring_impulse + an->motor_impulse + an->lower_impulse - an->upper_impulse;
      A.w -= A.inv_inertia * axial;
      B.w += B.inv_inertia * axial;
    }
    tb_f4 px = j->px, py = j->py;
    if (j->tree) tree_impulses(w, j, &px, &py);
    apply(&f, px, py, &A, &B);
    scatter(ctx->states, j->a, &A);
    scatter(ctx->states, j->b, &B);
  }
}

/* Notes the lanes' bodies that the pass moved (relax_activity.h): the speed
 * change at a body's farthest point, |dv.x| + |dv.y| + |dw| reach. */
static void note_moved(tb_step_context* ctx, const int32_t* s, const wide_body* before, const wide_body* after) {
  tb_f4 dvx = after->vx - before->vx, dvy = after->vy - before->vy, dw = after->w - before->w;
  const float* reach = ctx->reach;
  tb_f4 speed = fabs4(dvx) + fabs4(dvy) + fabs4(dw) * (tb_f4){reach[s[0]], reach[s[1]], reach[s[2]], reach[s[3]]};
  tb_relax_note_lanes(ctx, s, speed > splat(TB_RELAX_TOLERANCE));
}

/* Without warm starting: every impulse of the lanes from zero, the trees'
 * points' too (as zero_impulses in joint.c; the trees solve after). */
static void zero_impulses(const tb_world* w, tb_wide_joint* j, tb_wide_angles* an) {
  const tb_f4 zero = splat(0.0f);
  j->px = j->py = zero;
  if (j->angles) an->spring_impulse = an->motor_impulse = an->lower_impulse = an->upper_impulse = zero;
  if (!j->tree) return;
  for (int lane = 0; lane < 4; ++lane)
    if (j->joint[lane] >= 0 && j->point[lane] == 0.0f) tb_joint_at(w, j->joint[lane])->linear_impulse = (tb_vec2){0, 0};
}

/* One soft angle row, C = angle rows of revolute_solve: the impulse
 * -mass mass_scale (cdot + bias_rate c) - impulse_scale accumulated. */
static inline tb_f4 soft_row(tb_f4 mass, tb_f4 mass_scale, tb_f4 bias_rate, tb_f4 impulse_scale, tb_f4 cdot, tb_f4 c,
                             tb_f4 accumulated) {
  return -mass * mass_scale * (cdot + bias_rate * c) - impulse_scale * accumulated;
}

/* A one-sided limit row C = c >= 0 (limit_part and limit_impulse of
 * joint.c): while c > 0 it may only stop the closing within the substep,
 * once reached it is rigid (the joint softness when biased). Returns the
 * increment, keeping the accumulated impulse >= 0. */
static inline tb_f4 limit_row(const tb_step_context* ctx, bool use_bias, tb_f4 mass, tb_f4 cdot, tb_f4 c,
                              tb_f4* accumulated) {
  const tb_f4 zero = splat(0.0f), one = splat(1.0f);
  tb_softness reached = use_bias ? ctx->joint_softness : tb_rigid_softness();
  tb_i4 open = c > zero;
  tb_f4 bias = blend(open, splat(ctx->inv_h), splat(reached.bias_rate));
  tb_f4 mass_scale = blend(open, one, splat(reached.mass_scale));
  tb_f4 impulse_scale = blend(open, zero, splat(reached.impulse_scale));
  tb_f4 impulse = soft_row(mass, mass_scale, bias, impulse_scale, cdot, c, *accumulated);
  tb_f4 next = max4(*accumulated + impulse, zero);
  impulse = next - *accumulated;
  *accumulated = next;
  return impulse;
}

/* The angle rows of revolute_solve in joint.c, in its order: spring, motor,
 * lower and upper limit; a row that is off in a lane applies nothing there. */
static inline __attribute__((always_inline)) void solve_angles(tb_wide_angles* j, const tb_step_context* ctx,
                                                               bool use_bias, wide_body* A, wide_body* B) {
  const tb_f4 zero = splat(0.0f);
  tb_f4 ia = A->inv_inertia, ib = B->inv_inertia;
  tb_f4 mass = inverse_or_zero(ia + ib);
  tb_f4 angle = j->angle0 + (B->da - A->da);
  tb_f4 impulse = soft_row(mass, j->spring_mass_scale, j->spring_bias, j->spring_impulse_scale, B->w - A->w, angle,
                           j->spring_impulse);
  impulse = blend(j->spring > zero, impulse, zero);
  j->spring_impulse += impulse;
  A->w -= ia * impulse;
  B->w += ib * impulse;
  /* the motor: towards motor_speed, within its largest impulse */
  impulse = -mass * (B->w - A->w - j->motor_speed);
  tb_f4 old = j->motor_impulse;
  tb_f4 next = min4(max4(old + impulse, -j->max_motor), j->max_motor);
  next = blend(j->motor > zero, next, old);
  j->motor_impulse = next;
  impulse = next - old;
  A->w -= ia * impulse;
  B->w += ib * impulse;
  tb_i4 limit = j->limit > zero;
  tb_f4 lower = j->lower_impulse, upper = j->upper_impulse;
  impulse = limit_row(ctx, use_bias, mass, B->w - A->w, angle - j->lower, &lower);
  impulse = blend(limit, impulse, zero);
  j->lower_impulse = blend(limit, lower, j->lower_impulse);
  A->w -= ia * impulse;
  B->w += ib * impulse;
  impulse = limit_row(ctx, use_bias, mass, A->w - B->w, j->upper - angle, &upper);
  impulse = blend(limit, impulse, zero);
  j->upper_impulse = blend(limit, upper, j->upper_impulse);
  A->w -= ia * -impulse;
  B->w += ib * -impulse;
}

/* The point rows of a block's lanes that no tree holds. */
static inline __attribute__((always_inline)) void solve_point(tb_wide_joint* j, const tb_solver_body* states,
                                                              tb_softness s, bool use_bias, wide_body* A,
                                                              wide_body* B) {
  wide_frame f = arms(j, states);
  tb_f4 rx = (B->vx + -B->w * f.rby) - (A->vx + -A->w * f.ray);
  tb_f4 ry = (B->vy + B->w * f.rbx) - (A->vy + A->w * f.rax);
  if (use_bias) { /* C = (dpB - dpA + (cB - cA)) + (rB - rA) */
    tb_f4 bias = splat(s.bias_rate);
    rx += bias * (((B->dpx - A->dpx) + j->dcx) + (f.rbx - f.rax));
    ry += bias * (((B->dpy - A->dpy) + j->dcy) + (f.rby - f.ray));
  }
  tb_f4 m = A->inv_mass + B->inv_mass, ia = A->inv_inertia, ib = B->inv_inertia;
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
  if (j->tree) { /* a tree solves those lanes' points */
    tb_i4 point = j->point > splat(0.0f);
    Px = blend(point, Px, splat(0.0f));
    Py = blend(point, Py, splat(0.0f));
  }
  j->px += Px;
  j->py += Py;
  apply(&f, Px, Py, A, B);
}

static inline __attribute__((always_inline)) void solve_block(const tb_world* w, tb_wide_joint* j, tb_wide_angles* an,
                                                              tb_step_context* ctx, tb_softness s, bool use_bias,
                                                              bool zero_first) {
  tb_solver_body* states = ctx->states;
  wide_body A = gather(states, j->a), B = gather(states, j->b);
  wide_body A0 = A, B0 = B;
  if (zero_first) zero_impulses(w, j, an);
  if (j->angles) solve_angles(an, ctx, use_bias, &A, &B);
  if (j->points > 0) solve_point(j, states, s, use_bias, &A, &B); /* (none: trees hold every lane's point) */
  scatter(states, j->a, &A);
  scatter(states, j->b, &B);
  if (!use_bias && ctx->relax_record) {
    note_moved(ctx, j->a, &A0, &A);
    note_moved(ctx, j->b, &B0, &B);
  }
}

/* Whether a block has rows to solve: a joint that a tree holds and that has
 * no spring, motor or limit (a chain, a pendulum) is here for its warm start
 * only. */
static bool has_rows(const tb_wide_joint* j) { return j->angles || j->points > 0; }

void tb_wide_joints_solve(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_wide_joints* wj = &w->wide_joints;
  /* Without warm starting every substep accumulates from zero (its biased
   * solve comes first), as joint.c does. */
  bool zero_first = use_bias && !ctx->enable_warm_starting;
  if (use_bias)
    for (int b = 0; b < wj->block_count; ++b) {
      if (has_rows(&wj->blocks[b]))
        solve_block(w, &wj->blocks[b], &wj->angles[b], ctx, ctx->joint_softness, true, zero_first);
      else if (zero_first)
        zero_impulses(w, &wj->blocks[b], &wj->angles[b]); /* the trees' points start from zero too */
    }
  else if (ctx->relax_all)
    for (int b = 0; b < wj->block_count; ++b) {
      if (has_rows(&wj->blocks[b]))
        solve_block(w, &wj->blocks[b], &wj->angles[b], ctx, tb_rigid_softness(), false, false);
    }
  else
    for (int b = 0; b < wj->block_count; ++b)
      if (has_rows(&wj->blocks[b]) && tb_relax_lanes_active(ctx, wj->blocks[b].a, wj->blocks[b].b))
        solve_block(w, &wj->blocks[b], &wj->angles[b], ctx, tb_rigid_softness(), false, false);
}

void tb_wide_joints_store(tb_world* w, const tb_step_context* ctx) {
  const tb_wide_joints* wj = &w->wide_joints;
  for (int b = 0; b < wj->block_count; ++b) {
    const tb_wide_joint* j = &wj->blocks[b];
    for (int lane = 0; lane < 4; ++lane) {
      if (j->joint[lane] < 0) continue;
      tb_joint* joint = tb_joint_at(w, j->joint[lane]);
      if (!j->angles && !j->tree) {
        tb_joint_store_point(joint, (tb_vec2){j->px[lane], j->py[lane]}, ctx);
        continue;
      }
      if (j->point[lane] != 0.0f) joint->linear_impulse = (tb_vec2){j->px[lane], j->py[lane]};
      if (j->angles) {
        const tb_wide_angles* an = &wj->angles[b];
        joint->spring_impulse = an->spring_impulse[lane];
        joint->motor_impulse = an->motor_impulse[lane];
        joint->lower_impulse = an->lower_impulse[lane];
        joint->upper_impulse = an->upper_impulse[lane];
      }
      tb_joint_store(w, j->joint[lane], ctx);
    }
  }
}
