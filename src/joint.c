/* Joints: definitions and their checks, creation and destruction, the bodies'
 * joint lists, and the soft-step constraint solver of every joint type.
 *
 * Solver conventions (see solver.h). Within a step every joint works from the
 * state of its bodies when the step began, plus the motion of each body since
 * then (dp, dq, da of its solver body), so nothing is summed into world
 * coordinates inside the step. tb_joint_prepare stores, for each body, the
 * anchor relative to the centre of mass in world axes (frame_a, frame_b), the
 * vector between the centres (delta_center) and the relative angle
 * (delta_angle). In a substep the current anchors are rA = dqA frame_a,
 * rB = dqB frame_b and the current anchor separation is
 *   d = (dpB - dpA) + delta_center + (rB - rA).
 *
 * Every constraint row C(x) with velocity Cdot = J v is solved the same way:
 * with effective mass m = 1 / (J M^-1 J^T) and a softness (bias_rate,
 * mass_scale, impulse_scale), the impulse increment is
 *   lambda = -m mass_scale (Cdot + bias_rate C) - impulse_scale lambda_acc,
 * applied as M^-1 J^T lambda. Rigid parts use the world's joint softness in the
 * biased pass and (0, 1, 0) in the relax pass; springs use their own softness
 * in both; limits push at C / h while the limit is not reached (speculative)
 * and are rigid otherwise; motors drive Cdot to the motor speed and clamp the
 * accumulated impulse to max * h. Accumulated impulses are those of one
 * substep, so a force is impulse / h. */
#include "joint.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "broad_phase.h"
#include "math_internal.h"
#include "world.h"
#include "units.h"

static const tb_joint_id null_joint = {0, 0, 0};

static const char* const type_names[] = {
    [TB_JOINT_DISTANCE] = "distance",   [TB_JOINT_MOTOR] = "motor",       [TB_JOINT_MOUSE] = "mouse",
    [TB_JOINT_PRISMATIC] = "prismatic", [TB_JOINT_REVOLUTE] = "revolute", [TB_JOINT_WELD] = "weld",
    [TB_JOINT_WHEEL] = "wheel"};

/* ==== solver helpers ========================================================= */

static inline float inv_or_zero(float k) { return k > 0.0f ? 1.0f / k : 0.0f; }

/* Drift correction of a rigid part: the world's joint softness when biased,
 * exact (no bias, full mass, no impulse decay) in the relax pass. */
static inline tb_softness rigid_part(const tb_step_context* ctx, bool use_bias) {
  return use_bias ? ctx->joint_softness : tb_rigid_softness();
}

/* A one-sided limit C >= 0. While C > 0 the limit is not reached: it may only
 * stop the bodies from closing more than C within the substep (bias C / h,
 * full mass). Once reached it is a rigid part. */
static inline tb_softness limit_part(const tb_step_context* ctx, bool use_bias, float c) {
  if (c > 0.0f) return (tb_softness){ctx->inv_h, 1.0f, 0.0f};
  return rigid_part(ctx, use_bias);
}

static inline float soft_impulse(float mass, tb_softness s, float cdot, float c, float accumulated) {
  return -mass * s.mass_scale * (cdot + s.bias_rate * c) - s.impulse_scale * accumulated;
}

/* The increment of a one-sided limit impulse, keeping the accumulated one >= 0. */
static inline float limit_impulse(float mass, tb_softness s, float cdot, float c, float* accumulated) {
  float impulse = soft_impulse(mass, s, cdot, c, *accumulated);
  float next = tb_maxf(*accumulated + impulse, 0.0f);
  impulse = next - *accumulated;
  *accumulated = next;
  return impulse;
}

/* The increment that keeps the accumulated impulse within [-max, max]. */
static inline float clamp_accumulate(float* accumulated, float impulse, float max) {
  float old = *accumulated;
  float next = tb_minf(tb_maxf(old + impulse, -max), max);
  *accumulated = next;
  return next - old;
}

/* The same for a vector impulse, by length. */
static inline tb_vec2 clamp_accumulate2(tb_vec2* accumulated, tb_vec2 impulse, float max) {
  tb_vec2 old = *accumulated;
  tb_vec2 next = tb_add(old, impulse);
  float len_sq = tb_length_sq(next);
  if (len_sq > max * max) next = tb_scale(max / sqrtf(len_sq), next);
  *accumulated = next;
  return tb_sub(next, old);
}

/* Where the joint stands inside the step (see the file comment). */
typedef struct frame {
  tb_vec2 ra, rb; /* anchors relative to the centres of mass */
  tb_vec2 d;      /* anchor B minus anchor A */
  float angle;    /* angle_b - angle_a - reference angle */
} frame;

static inline frame current_frame(const tb_joint* j, const tb_solver_body* a, const tb_solver_body* b) {
  frame f;
  tb_joint_arms(j->frame_a, j->frame_b, j->delta_center, a, b, &f.ra, &f.rb, &f.d);
  f.angle = j->delta_angle + (b->da - a->da);
  return f;
}

/* Velocity of anchor B minus that of anchor A: vB + wB x rB - vA - wA x rA. */
static inline tb_vec2 relative_velocity(const tb_solver_body* a, const tb_solver_body* b, tb_vec2 ra, tb_vec2 rb) {
  return tb_sub(tb_add(b->v, tb_cross_sv(b->w, rb)), tb_add(a->v, tb_cross_sv(a->w, ra)));
}

/* The impulse p at the anchors: -p on A at rA, +p on B at rB. */
static inline void apply_linear(tb_solver_body* a, tb_solver_body* b, tb_vec2 ra, tb_vec2 rb, tb_vec2 p) {
  a->v = tb_mul_add(a->v, -a->inv_mass, p);
  a->w -= a->inv_inertia * tb_cross(ra, p);
  b->v = tb_mul_add(b->v, b->inv_mass, p);
  b->w += b->inv_inertia * tb_cross(rb, p);
}

/* The angular impulse l: -l on A, +l on B. */
static inline void apply_angular(tb_solver_body* a, tb_solver_body* b, float l) {
  a->w -= a->inv_inertia * l;
  b->w += b->inv_inertia * l;
}

/* M^-1 J^T lambda for a row J = [-n, -arm_a, n, arm_b]. */
static inline void apply_row(tb_solver_body* a, tb_solver_body* b, tb_vec2 n, float arm_a, float arm_b, float lambda) {
  a->v = tb_mul_add(a->v, -a->inv_mass * lambda, n);
  a->w -= a->inv_inertia * arm_a * lambda;
  b->v = tb_mul_add(b->v, b->inv_mass * lambda, n);
  b->w += b->inv_inertia * arm_b * lambda;
}

/* J v of the row [-n, -arm_a, n, arm_b]. */
static inline float row_velocity(const tb_solver_body* a, const tb_solver_body* b, tb_vec2 n, float arm_a,
                                 float arm_b) {
  return tb_dot(n, tb_sub(b->v, a->v)) + arm_b * b->w - arm_a * a->w;
}

/* 1 / (J M^-1 J^T) of that row. */
static inline float row_mass(const tb_solver_body* a, const tb_solver_body* b, float arm_a, float arm_b) {
  return inv_or_zero(a->inv_mass + b->inv_mass + a->inv_inertia * arm_a * arm_a + b->inv_inertia * arm_b * arm_b);
}

/* A symmetric 2x2 matrix. */
typedef struct sym22 {
  float a11, a12, a22;
} sym22;

/* K = J M^-1 J^T of the point constraint C = pB - pA. The velocity of an
 * anchor is v + w x r = v + w (-r.y, r.x), so each body contributes its inverse
 * mass times the identity plus i (-r.y, r.x)(-r.y, r.x)^T. */
static inline sym22 point_mass(const tb_solver_body* a, const tb_solver_body* b, tb_vec2 ra, tb_vec2 rb) {
  float m = a->inv_mass + b->inv_mass;
  float ia = a->inv_inertia, ib = b->inv_inertia;
  return (sym22){m + ia * ra.y * ra.y + ib * rb.y * rb.y, -ia * ra.x * ra.y - ib * rb.x * rb.y,
                 m + ia * ra.x * ra.x + ib * rb.x * rb.x};
}

/* K^-1 r, or zero for a singular K. In double: K's entries are inverse masses
 * times squared arms, and for a light body far from its anchor (a 1e-30 kg
 * body is accepted input) their products overflow a float, inf - inf = NaN. */
static inline tb_vec2 solve22(sym22 k, tb_vec2 r) {
  double det = (double)k.a11 * k.a22 - (double)k.a12 * k.a12;
  if (!(det != 0.0) || !isfinite(det)) return (tb_vec2){0.0f, 0.0f};
  double inv = 1.0 / det;
  return (tb_vec2){(float)(inv * ((double)k.a22 * r.x - (double)k.a12 * r.y)),
                   (float)(inv * ((double)k.a11 * r.y - (double)k.a12 * r.x))};
}

/* The point constraint C = d (two rows) with softness s: revolute, weld. */
static void solve_point(tb_joint* j, tb_solver_body* a, tb_solver_body* b, const frame* f, tb_softness s) {
  tb_vec2 cdot = relative_velocity(a, b, f->ra, f->rb);
  tb_vec2 x = solve22(point_mass(a, b, f->ra, f->rb), tb_mul_add(cdot, s.bias_rate, f->d));
  tb_vec2 impulse = {-s.mass_scale * x.x - s.impulse_scale * j->linear_impulse.x,
                     -s.mass_scale * x.y - s.impulse_scale * j->linear_impulse.y};
  j->linear_impulse = tb_add(j->linear_impulse, impulse);
  apply_linear(a, b, f->ra, f->rb, impulse);
}

/* ==== distance joint ==========================================================
 * C = |d| - L with u = d / |d|. Differentiating |d|: Cdot = u . (vB + wB x rB
 * - vA - wA x rA), and u . (w x r) = w (r x u), so J = [-u, -(rA x u), u,
 * (rB x u)]. Limits are the same row with C = |d| - min and C = max - |d| (the
 * latter with J negated); the motor drives Cdot to motor_speed. Rigid when the
 * spring is off; otherwise the spring, motor and limits act between the limits. */

static void distance_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b,
                           bool use_bias) {
  frame f = current_frame(j, a, b);
  float len = tb_length(f.d);
  tb_vec2 u = tb_normalize(f.d);
  float arm_a = tb_cross(f.ra, u), arm_b = tb_cross(f.rb, u);
  float mass = row_mass(a, b, arm_a, arm_b);
  if (!j->enable_spring) {
    if (j->in_tree) return;
    float cdot = row_velocity(a, b, u, arm_a, arm_b);
    float impulse = soft_impulse(mass, rigid_part(ctx, use_bias), cdot, len - j->length, j->axial_impulse);
    j->axial_impulse += impulse;
    apply_row(a, b, u, arm_a, arm_b, impulse);
    return;
  }
  if (j->hertz > 0.0f) {
    float cdot = row_velocity(a, b, u, arm_a, arm_b);
    float impulse = soft_impulse(mass, j->spring_softness, cdot, len - j->length, j->spring_impulse);
    j->spring_impulse += impulse;
    apply_row(a, b, u, arm_a, arm_b, impulse);
  }
  if (j->enable_motor) {
    float cdot = row_velocity(a, b, u, arm_a, arm_b);
    float impulse = clamp_accumulate(&j->motor_impulse, mass * (j->motor_speed - cdot), j->max_motor * ctx->h);
    apply_row(a, b, u, arm_a, arm_b, impulse);
  }
  if (j->enable_limit) {
    float c = len - j->lower;
    float cdot = row_velocity(a, b, u, arm_a, arm_b);
    float impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->lower_impulse);
    apply_row(a, b, u, arm_a, arm_b, impulse);
    c = j->upper - len;
    cdot = -row_velocity(a, b, u, arm_a, arm_b);
    impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->upper_impulse);
    apply_row(a, b, u, arm_a, arm_b, -impulse);
  }
}

static float distance_axial(const tb_joint* j) {
  return j->axial_impulse + j->spring_impulse + j->motor_impulse + j->lower_impulse - j->upper_impulse;
}

static void distance_warm_start(tb_joint* j, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  tb_vec2 u = tb_normalize(f.d);
  apply_row(a, b, u, tb_cross(f.ra, u), tb_cross(f.rb, u), distance_axial(j));
}

/* ==== revolute joint ==========================================================
 * Point: C = d = pB - pA (two rows), Cdot = vB + wB x rB - vA - wA x rA, with K
 * from point_mass. Angle: C = angle_b - angle_a - reference, Cdot = wB - wA,
 * J = [0, -1, 0, 1], effective mass 1 / (iA + iB); the spring pulls it to 0,
 * the motor drives Cdot to motor_speed, the limits keep lower <= C <= upper.
 * The point is solved last: it matters most. */

static void revolute_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b,
                           bool use_bias) {
  float angle = j->delta_angle + (b->da - a->da); /* current_frame's angle; the arms only for the point */
  float k_angular = a->inv_inertia + b->inv_inertia;
  float angular_mass = inv_or_zero(k_angular);
  if (j->enable_spring && j->hertz > 0.0f) {
    float impulse = soft_impulse(angular_mass, j->spring_softness, b->w - a->w, angle, j->spring_impulse);
    j->spring_impulse += impulse;
    apply_angular(a, b, impulse);
  }
  if (j->enable_motor) {
    float impulse = -angular_mass * (b->w - a->w - j->motor_speed);
    apply_angular(a, b, clamp_accumulate(&j->motor_impulse, impulse, j->max_motor * ctx->h));
  }
  if (j->enable_limit) {
    float c = angle - j->lower;
    float impulse = limit_impulse(angular_mass, limit_part(ctx, use_bias, c), b->w - a->w, c, &j->lower_impulse);
    apply_angular(a, b, impulse);
    c = j->upper - angle;
    impulse = limit_impulse(angular_mass, limit_part(ctx, use_bias, c), a->w - b->w, c, &j->upper_impulse);
    apply_angular(a, b, -impulse);
  }
  if (!j->in_tree) {
    frame f = current_frame(j, a, b);
    solve_point(j, a, b, &f, rigid_part(ctx, use_bias));
  }
}

static float revolute_axial(const tb_joint* j) {
  return j->spring_impulse + j->motor_impulse + j->lower_impulse - j->upper_impulse;
}

static void revolute_warm_start(tb_joint* j, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  apply_angular(a, b, revolute_axial(j));
  apply_linear(a, b, f.ra, f.rb, j->linear_impulse);
}

/* ==== prismatic joint =========================================================
 * The axis n turns with A: n = dqA n0. Translation x = n . d. Differentiating
 * (n' = wA x n, and (wA x n) . d = wA (n x d) = -wA (d x n)):
 *   xdot = n . (vB - vA) + wB (rB x n) - wA ((d + rA) x n),
 * so the row is J = [-n, -(d + rA) x n, n, rB x n]. The perpendicular
 * constraint is the same row with p = left_perp(n) in place of n, and C = p . d;
 * the angular one is C = angle, J = [0, -1, 0, 1]. Both rigid rows are solved
 * together as a 2x2 block: K = [[kp, iA sa + iB sb], [., iA + iB]] with
 * kp = mA + mB + iA sa^2 + iB sb^2, sa = (d + rA) x p, sb = rB x p. Spring,
 * motor and limits act along n. */

static void prismatic_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b,
                            bool use_bias) {
  frame f = current_frame(j, a, b);
  tb_vec2 n = tb_rotate(a->dq, j->axis);
  tb_vec2 dra = tb_add(f.d, f.ra);
  float x = tb_dot(n, f.d);
  float arm_a = tb_cross(dra, n), arm_b = tb_cross(f.rb, n);
  float mass = row_mass(a, b, arm_a, arm_b);
  if (j->enable_spring && j->hertz > 0.0f) {
    float cdot = row_velocity(a, b, n, arm_a, arm_b);
    float impulse = soft_impulse(mass, j->spring_softness, cdot, x, j->spring_impulse);
    j->spring_impulse += impulse;
    apply_row(a, b, n, arm_a, arm_b, impulse);
  }
  if (j->enable_motor) {
    float cdot = row_velocity(a, b, n, arm_a, arm_b);
    float impulse = clamp_accumulate(&j->motor_impulse, mass * (j->motor_speed - cdot), j->max_motor * ctx->h);
    apply_row(a, b, n, arm_a, arm_b, impulse);
  }
  if (j->enable_limit) {
    float c = x - j->lower;
    float cdot = row_velocity(a, b, n, arm_a, arm_b);
    float impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->lower_impulse);
    apply_row(a, b, n, arm_a, arm_b, impulse);
    c = j->upper - x;
    cdot = -row_velocity(a, b, n, arm_a, arm_b);
    impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->upper_impulse);
    apply_row(a, b, n, arm_a, arm_b, -impulse);
  }
  if (j->in_tree) return;
  /* perpendicular and angular rows as one block */
  tb_vec2 p = tb_left_perp(n);
  float sa = tb_cross(dra, p), sb = tb_cross(f.rb, p);
  float ia = a->inv_inertia, ib = b->inv_inertia;
  sym22 k = {a->inv_mass + b->inv_mass + ia * sa * sa + ib * sb * sb, ia * sa + ib * sb, ia + ib};
  if (k.a22 == 0.0f) k.a22 = 1.0f; /* no rotation on either side: the angular row is idle */
  tb_softness s = rigid_part(ctx, use_bias);
  tb_vec2 c = {tb_dot(p, f.d), f.angle};
  tb_vec2 cdot = {row_velocity(a, b, p, sa, sb), b->w - a->w};
  tb_vec2 sol = solve22(k, tb_mul_add(cdot, s.bias_rate, c));
  tb_vec2 impulse = {-s.mass_scale * sol.x - s.impulse_scale * j->axial_impulse,
                     -s.mass_scale * sol.y - s.impulse_scale * j->angular_impulse};
  j->axial_impulse += impulse.x;
  j->angular_impulse += impulse.y;
  apply_row(a, b, p, sa, sb, impulse.x);
  apply_angular(a, b, impulse.y);
}

static float slider_axial(const tb_joint* j) {
  return j->spring_impulse + j->motor_impulse + j->lower_impulse - j->upper_impulse;
}

static void prismatic_warm_start(tb_joint* j, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  tb_vec2 n = tb_rotate(a->dq, j->axis), p = tb_left_perp(n);
  tb_vec2 dra = tb_add(f.d, f.ra);
  apply_row(a, b, n, tb_cross(dra, n), tb_cross(f.rb, n), slider_axial(j));
  apply_row(a, b, p, tb_cross(dra, p), tb_cross(f.rb, p), j->axial_impulse);
  apply_angular(a, b, j->angular_impulse);
}

/* ==== wheel joint =============================================================
 * The prismatic rows without the angular one: the perpendicular row p . d = 0
 * is rigid; along n a spring (to translation 0), limits; the motor acts on the
 * relative rotation (Cdot = wB - wA, mass 1 / (iA + iB)). */

static void wheel_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b, bool use_bias) {
  frame f = current_frame(j, a, b);
  tb_vec2 n = tb_rotate(a->dq, j->axis);
  tb_vec2 dra = tb_add(f.d, f.ra);
  float x = tb_dot(n, f.d);
  float arm_a = tb_cross(dra, n), arm_b = tb_cross(f.rb, n);
  float mass = row_mass(a, b, arm_a, arm_b);
  if (j->enable_motor) {
    float angular_mass = inv_or_zero(a->inv_inertia + b->inv_inertia);
    float impulse = -angular_mass * (b->w - a->w - j->motor_speed);
    apply_angular(a, b, clamp_accumulate(&j->motor_impulse, impulse, j->max_motor * ctx->h));
  }
  if (j->enable_spring && j->hertz > 0.0f) {
    float cdot = row_velocity(a, b, n, arm_a, arm_b);
    float impulse = soft_impulse(mass, j->spring_softness, cdot, x, j->spring_impulse);
    j->spring_impulse += impulse;
    apply_row(a, b, n, arm_a, arm_b, impulse);
  }
  if (j->enable_limit) {
    float c = x - j->lower;
    float cdot = row_velocity(a, b, n, arm_a, arm_b);
    float impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->lower_impulse);
    apply_row(a, b, n, arm_a, arm_b, impulse);
    c = j->upper - x;
    cdot = -row_velocity(a, b, n, arm_a, arm_b);
    impulse = limit_impulse(mass, limit_part(ctx, use_bias, c), cdot, c, &j->upper_impulse);
    apply_row(a, b, n, arm_a, arm_b, -impulse);
  }
  if (j->in_tree) return;
  tb_vec2 p = tb_left_perp(n);
  float sa = tb_cross(dra, p), sb = tb_cross(f.rb, p);
  float cdot = row_velocity(a, b, p, sa, sb);
  float impulse =
      soft_impulse(row_mass(a, b, sa, sb), rigid_part(ctx, use_bias), cdot, tb_dot(p, f.d), j->axial_impulse);
  j->axial_impulse += impulse;
  apply_row(a, b, p, sa, sb, impulse);
}

static float wheel_axial(const tb_joint* j) { return j->spring_impulse + j->lower_impulse - j->upper_impulse; }

static void wheel_warm_start(tb_joint* j, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  tb_vec2 n = tb_rotate(a->dq, j->axis), p = tb_left_perp(n);
  tb_vec2 dra = tb_add(f.d, f.ra);
  apply_row(a, b, n, tb_cross(dra, n), tb_cross(f.rb, n), wheel_axial(j));
  apply_row(a, b, p, tb_cross(dra, p), tb_cross(f.rb, p), j->axial_impulse);
  apply_angular(a, b, j->motor_impulse);
}

/* ==== weld joint ==============================================================
 * The revolute point constraint plus the angle C = angle (J = [0, -1, 0, 1])
 * held rigid; each part becomes a spring when its hertz is positive. */

static void weld_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b, bool use_bias) {
  frame f = current_frame(j, a, b);
  if (j->angular_hertz > 0.0f || !j->in_tree) {
    float angular_mass = inv_or_zero(a->inv_inertia + b->inv_inertia);
    tb_softness s = j->angular_hertz > 0.0f ? j->angular_softness : rigid_part(ctx, use_bias);
    float impulse = soft_impulse(angular_mass, s, b->w - a->w, f.angle, j->angular_impulse);
    j->angular_impulse += impulse;
    apply_angular(a, b, impulse);
  }
  if (j->hertz > 0.0f || !j->in_tree)
    solve_point(j, a, b, &f, j->hertz > 0.0f ? j->spring_softness : rigid_part(ctx, use_bias));
}

static void weld_warm_start(tb_joint* j, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  apply_angular(a, b, j->angular_impulse);
  apply_linear(a, b, f.ra, f.rb, j->linear_impulse);
}

/* ==== mouse joint =============================================================
 * C = pB - target (A is only a reference and is never moved: its solver body is
 * the static dummy, so the frame above gives d = pB - target with
 * delta_center = cB - target). Cdot = vB + wB x rB, K from point_mass with A's
 * terms zero. A soft spring (hertz 0: the rigid joint softness) whose
 * accumulated impulse is at most max_force h. */

static void mouse_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b, bool use_bias) {
  frame f = current_frame(j, a, b);
  tb_softness s = j->hertz > 0.0f ? j->spring_softness : rigid_part(ctx, use_bias);
  tb_vec2 cdot = relative_velocity(a, b, f.ra, f.rb);
  tb_vec2 x = solve22(point_mass(a, b, f.ra, f.rb), tb_mul_add(cdot, s.bias_rate, f.d));
  tb_vec2 impulse = {-s.mass_scale * x.x - s.impulse_scale * j->linear_impulse.x,
                     -s.mass_scale * x.y - s.impulse_scale * j->linear_impulse.y};
  impulse = clamp_accumulate2(&j->linear_impulse, impulse, j->max_force * ctx->h);
  apply_linear(a, b, f.ra, f.rb, impulse);
}

/* ==== motor joint =============================================================
 * Anchor A is linear_offset (in A's frame), anchor B is B's centre (frame_b =
 * 0), so d = cB - (xA + qA linear_offset) is the pose error and angle =
 * angle_b - angle_a - angular_offset. Both are velocity drives: the rows of
 * the point and angle constraints with Cdot + rate C driven to zero, where rate
 * corrects correction_factor of the error per step (spread over the substeps),
 * and the accumulated impulses are clamped to max_force h and max_torque h. */

static void motor_solve(tb_joint* j, const tb_step_context* ctx, tb_solver_body* a, tb_solver_body* b) {
  frame f = current_frame(j, a, b);
  float angular_mass = inv_or_zero(a->inv_inertia + b->inv_inertia);
  float impulse = -angular_mass * (b->w - a->w + j->correction_rate * f.angle);
  apply_angular(a, b, clamp_accumulate(&j->angular_impulse, impulse, j->max_torque * ctx->h));
  tb_vec2 cdot = tb_mul_add(relative_velocity(a, b, f.ra, f.rb), j->correction_rate, f.d);
  tb_vec2 x = solve22(point_mass(a, b, f.ra, f.rb), cdot);
  tb_vec2 linear = clamp_accumulate2(&j->linear_impulse, tb_neg(x), j->max_force * ctx->h);
  apply_linear(a, b, f.ra, f.rb, linear);
}

/* ==== rigid rows for the exact tree solve ========================================
 * The same rows as the solvers above, written out as Jacobians (see joint.h):
 * a point constraint is the rows x and y of vB + wB x rB - vA - wA x rA, so
 * jb = (1, 0, -rB.y) and (0, 1, rB.x); an angle row is (0, 0, 1) on both; a
 * slider's perpendicular row is (p, (d + rA) x p) on A and (p, rB x p) on B;
 * a rigid distance is (u, rA x u) and (u, rB x u). */

int tb_joint_rigid_row_count(const tb_joint* j) {
  switch (j->type) {
    case TB_JOINT_DISTANCE: return j->enable_spring ? 0 : 1;
    case TB_JOINT_REVOLUTE: return 2;
    case TB_JOINT_PRISMATIC: return 2;
    case TB_JOINT_WHEEL: return 1;
    case TB_JOINT_WELD: return (j->hertz > 0.0f ? 0 : 2) + (j->angular_hertz > 0.0f ? 0 : 1);
    case TB_JOINT_MOUSE:
    case TB_JOINT_MOTOR: return 0;
  }
  return 0;
}

static void set_row(tb_rigid_rows* out, float** impulses, tb_vec2 n, float arm_a, float arm_b, float c,
                    float* impulse) {
  int r = out->count++;
  out->ja[r][0] = out->jb[r][0] = n.x;
  out->ja[r][1] = out->jb[r][1] = n.y;
  out->ja[r][2] = arm_a;
  out->jb[r][2] = arm_b;
  out->c[r] = c;
  impulses[r] = impulse;
}

static void set_point_rows(tb_rigid_rows* out, float** impulses, const frame* f, tb_vec2* impulse) {
  tb_joint_add_point_rows(out, f->ra, f->rb, f->d);
  impulses[out->point] = &impulse->x;
  impulses[out->point + 1] = &impulse->y;
}

void tb_joint_rigid_rows(tb_joint* j, const tb_solver_body* a, const tb_solver_body* b, tb_rigid_rows* out,
                         float* impulse[3]) {
  out->count = 0;
  out->point = -1;
  frame f = current_frame(j, a, b);
  const tb_vec2 zero = {0.0f, 0.0f};
  switch (j->type) {
    case TB_JOINT_DISTANCE: {
      float len = tb_length(f.d);
      tb_vec2 u = tb_normalize(f.d);
      if (!j->enable_spring)
        set_row(out, impulse, u, tb_cross(f.ra, u), tb_cross(f.rb, u), len - j->length, &j->axial_impulse);
      break;
    }
    case TB_JOINT_REVOLUTE: set_point_rows(out, impulse, &f, &j->linear_impulse); break;
    case TB_JOINT_PRISMATIC:
    case TB_JOINT_WHEEL: {
      tb_vec2 p = tb_left_perp(tb_rotate(a->dq, j->axis));
      set_row(out, impulse, p, tb_cross(tb_add(f.d, f.ra), p), tb_cross(f.rb, p), tb_dot(p, f.d), &j->axial_impulse);
      if (j->type == TB_JOINT_PRISMATIC) set_row(out, impulse, zero, 1.0f, 1.0f, f.angle, &j->angular_impulse);
      break;
    }
    case TB_JOINT_WELD:
      if (j->angular_hertz == 0.0f) set_row(out, impulse, zero, 1.0f, 1.0f, f.angle, &j->angular_impulse);
      if (j->hertz == 0.0f) set_point_rows(out, impulse, &f, &j->linear_impulse);
      break;
    case TB_JOINT_MOUSE:
    case TB_JOINT_MOTOR: break;
  }
}

/* ==== solver entry points ===================================================== */

static void zero_impulses(tb_joint* j) {
  j->linear_impulse = (tb_vec2){0.0f, 0.0f};
  j->angular_impulse = j->axial_impulse = 0.0f;
  j->spring_impulse = j->motor_impulse = j->lower_impulse = j->upper_impulse = 0.0f;
}

void tb_joint_zero_impulses(tb_joint* j) { zero_impulses(j); }

bool tb_joint_point_only(const tb_joint* j) {
  bool spring = j->enable_spring && j->hertz > 0.0f;
  return j->type == TB_JOINT_REVOLUTE && !j->skip && !spring && !j->enable_motor && !j->enable_limit;
}

static void scale_impulses(tb_joint* j, float s) {
  j->linear_impulse = tb_scale(s, j->linear_impulse);
  j->angular_impulse *= s;
  j->axial_impulse *= s;
  j->spring_impulse *= s;
  j->motor_impulse *= s;
  j->lower_impulse *= s;
  j->upper_impulse *= s;
}

static bool impulses_finite(const tb_joint* j) {
  return tb_vec_finite(j->linear_impulse) && isfinite(j->angular_impulse) && isfinite(j->axial_impulse) &&
         isfinite(j->spring_impulse) && isfinite(j->motor_impulse) && isfinite(j->lower_impulse) &&
         isfinite(j->upper_impulse);
}

/* a^(1/n) for a in [0, 1] and n >= 1, without the C library's pow (whose
 * rounding differs between libraries; the step's results must not): Newton's
 * method on y^n = a from y = 1, in double. y^n - a is convex and increasing on
 * y > 0, so from above the root every iterate stays above it and decreases;
 * the iteration stops when rounding ends the decrease. From 1 it closes in by
 * a factor (1 - 1/n) a step until y^n nears a, then doubles its digits: about
 * 20 steps for a = 2^-24 (a correction factor of nearly 1) at 64 substeps. */
static double nth_root_unit(double a, int n) {
  if (n == 1 || a <= 0.0 || a >= 1.0) return a <= 0.0 ? 0.0 : a >= 1.0 ? 1.0 : a;
  double y = 1.0;
  for (int step = 0; step < 200; ++step) {
    double p = 1.0, base = y; /* y^(n-1) by squaring */
    for (int e = n - 1; e > 0; e >>= 1, base *= base)
      if (e & 1) p *= base;
    double next = y - (p * y - a) / ((double)n * p);
    if (!(next < y)) break;
    y = next;
  }
  return y;
}

void tb_joint_prepare(tb_world* w, int index, tb_step_context* ctx) {
  tb_joint* j = tb_joint_at(w, index);
  const tb_body* a = tb_body_at(w, j->edges[0].body);
  const tb_body* b = tb_body_at(w, j->edges[1].body);
  bool mouse = j->type == TB_JOINT_MOUSE;
  j->solver_a = mouse ? ctx->static_index : tb_solver_index(w, j->edges[0].body);
  j->solver_b = tb_solver_index(w, j->edges[1].body);
  if (mouse)
    j->skip = !b->enabled || b->type != TB_DYNAMIC_BODY;
  else
    j->skip = !a->enabled || !b->enabled || (a->type != TB_DYNAMIC_BODY && b->type != TB_DYNAMIC_BODY);
  j->in_tree = false; /* until tb_joint_tree_build takes it */

  /* frames at the step start */
  j->frame_b = tb_rotate(b->transform.q, tb_sub(j->local_anchor_b, b->local_center));
  if (mouse) {
    j->frame_a = (tb_vec2){0.0f, 0.0f};
    j->delta_center = tb_sub(b->center, j->target);
  } else {
    j->frame_a = tb_rotate(a->transform.q, tb_sub(j->local_anchor_a, a->local_center));
    j->delta_center = tb_sub(b->center, a->center);
  }
  if (j->type == TB_JOINT_MOTOR) j->frame_b = (tb_vec2){0.0f, 0.0f}; /* B's centre, whatever its mass */
  j->delta_angle = (b->angle - a->angle) - j->reference_angle;
  j->axis = tb_rotate(a->transform.q, j->local_axis_a);

  if (j->hertz > 0.0f) j->spring_softness = tb_make_softness(j->hertz, j->damping_ratio, ctx->h);
  if (j->angular_hertz > 0.0f)
    j->angular_softness = tb_make_softness(j->angular_hertz, j->angular_damping_ratio, ctx->h);
  if (j->type == TB_JOINT_MOTOR) {
    /* correct the fraction c of the error per step: (1 - f)^n = 1 - c per substep */
    float c = j->correction_factor;
    float per_substep = c >= 1.0f ? 1.0f : (float)(1.0 - nth_root_unit(1.0 - (double)c, ctx->substeps));
    j->correction_rate = per_substep * ctx->inv_h;
  }

  /* impulses of features that are off are not carried over */
  if (!j->enable_spring) j->spring_impulse = 0.0f;
  if (!j->enable_motor) j->motor_impulse = 0.0f;
  if (!j->enable_limit) j->lower_impulse = j->upper_impulse = 0.0f;
  if (j->type == TB_JOINT_DISTANCE && j->enable_spring) j->axial_impulse = 0.0f;
  if (!ctx->enable_warm_starting || j->skip || !impulses_finite(j))
    zero_impulses(j);
  else if (j->last_h > 0.0f && j->last_h != ctx->h)
    scale_impulses(j, ctx->h / j->last_h); /* impulses are per substep */
  j->last_h = ctx->h;
}

/* Works on copies of the two solver bodies and writes back the velocities of
 * real bodies only (the static dummy stays at rest, whatever happens). */
typedef struct body_pair {
  tb_solver_body a, b;
} body_pair;

static inline body_pair load_pair(const tb_joint* j, const tb_step_context* ctx) {
  return (body_pair){ctx->states[j->solver_a], ctx->states[j->solver_b]};
}

static inline void save_pair(const tb_joint* j, tb_step_context* ctx, const body_pair* p) {
  if (j->solver_a != ctx->static_index) {
    ctx->states[j->solver_a].v = p->a.v;
    ctx->states[j->solver_a].w = p->a.w;
  }
  if (j->solver_b != ctx->static_index) {
    ctx->states[j->solver_b].v = p->b.v;
    ctx->states[j->solver_b].w = p->b.w;
  }
}

void tb_joint_warm_start_point(const tb_joint* j, tb_step_context* ctx) {
  /* revolute_warm_start without the copies of load_pair; the static dummy
   * stays at rest (save_pair's rule): its writes go to a copy */
  tb_solver_body sink_a = ctx->states[ctx->static_index], sink_b = sink_a;
  tb_solver_body* a = j->solver_a != ctx->static_index ? &ctx->states[j->solver_a] : &sink_a;
  tb_solver_body* b = j->solver_b != ctx->static_index ? &ctx->states[j->solver_b] : &sink_b;
  apply_linear(a, b, tb_rotate(a->dq, j->frame_a), tb_rotate(b->dq, j->frame_b), j->linear_impulse);
}

void tb_joint_warm_start(tb_world* w, int index, tb_step_context* ctx) {
  tb_joint* j = tb_joint_at(w, index);
  if (j->skip || !ctx->enable_warm_starting) return;
  body_pair p = load_pair(j, ctx);
  switch (j->type) {
    case TB_JOINT_DISTANCE: distance_warm_start(j, &p.a, &p.b); break;
    case TB_JOINT_REVOLUTE: revolute_warm_start(j, &p.a, &p.b); break;
    case TB_JOINT_PRISMATIC: prismatic_warm_start(j, &p.a, &p.b); break;
    case TB_JOINT_WHEEL: wheel_warm_start(j, &p.a, &p.b); break;
    case TB_JOINT_WELD: weld_warm_start(j, &p.a, &p.b); break;
    case TB_JOINT_MOUSE:
    case TB_JOINT_MOTOR: {
      frame f = current_frame(j, &p.a, &p.b);
      apply_angular(&p.a, &p.b, j->angular_impulse);
      apply_linear(&p.a, &p.b, f.ra, f.rb, j->linear_impulse);
      break;
    }
  }
  save_pair(j, ctx, &p);
}

void tb_joint_solve(tb_world* w, int index, tb_step_context* ctx, bool use_bias) {
  tb_joint* j = tb_joint_at(w, index);
  if (j->skip) return;
  /* Without warm starting every substep accumulates from zero (its biased
   * solve comes first), so that the impulses stay those of one substep. */
  if (use_bias && !ctx->enable_warm_starting) zero_impulses(j);
  body_pair p = load_pair(j, ctx);
  switch (j->type) {
    case TB_JOINT_DISTANCE: distance_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_REVOLUTE: revolute_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_PRISMATIC: prismatic_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_WHEEL: wheel_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_WELD: weld_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_MOUSE: mouse_solve(j, ctx, &p.a, &p.b, use_bias); break;
    case TB_JOINT_MOTOR: motor_solve(j, ctx, &p.a, &p.b); break;
  }
  save_pair(j, ctx, &p);
}

void tb_joint_store(tb_world* w, int index, const tb_step_context* ctx) {
  tb_joint* j = tb_joint_at(w, index);
  if (!impulses_finite(j)) zero_impulses(j); /* a contained blow-up must not come back next step */
  j->force = (tb_vec2){0.0f, 0.0f};
  j->torque = j->motor_output = 0.0f;
  if (j->skip) return;
  float inv_h = ctx->inv_h;
  const tb_solver_body* a = &ctx->states[j->solver_a];
  const tb_solver_body* b = &ctx->states[j->solver_b];
  frame f = current_frame(j, a, b);
  tb_vec2 n = tb_rotate(a->dq, j->axis), p = tb_left_perp(n);
  tb_vec2 force = {0.0f, 0.0f};
  float torque = 0.0f, motor = 0.0f;
  switch (j->type) {
    case TB_JOINT_DISTANCE:
      force = tb_scale(distance_axial(j), tb_normalize(f.d));
      motor = j->motor_impulse;
      break;
    case TB_JOINT_REVOLUTE:
      force = j->linear_impulse;
      torque = revolute_axial(j);
      motor = j->motor_impulse;
      break;
    case TB_JOINT_PRISMATIC:
      force = tb_add(tb_scale(slider_axial(j), n), tb_scale(j->axial_impulse, p));
      torque = j->angular_impulse;
      motor = j->motor_impulse;
      break;
    case TB_JOINT_WHEEL:
      force = tb_add(tb_scale(wheel_axial(j), n), tb_scale(j->axial_impulse, p));
      torque = j->motor_impulse;
      motor = j->motor_impulse;
      break;
    case TB_JOINT_WELD:
    case TB_JOINT_MOUSE:
    case TB_JOINT_MOTOR:
      force = j->linear_impulse;
      torque = j->angular_impulse;
      break;
  }
  /* A body whose step was contained (a non-finite state, TB_ERR_NUMERIC)
   * leaves its solver state non-finite: its joints report no force for the
   * step rather than NaN (their impulses were reset above if they blew up). */
  if (!(tb_vec_finite(force) && isfinite(torque) && isfinite(motor)))
    force = (tb_vec2){0.0f, 0.0f}, torque = motor = 0.0f;
  j->force = tb_saturate2((double)inv_h * force.x, (double)inv_h * force.y);
  j->torque = tb_saturate((double)inv_h * torque);
  j->motor_output = tb_saturate((double)inv_h * motor);
}

void tb_joint_store_point(tb_joint* j, tb_vec2 impulse, const tb_step_context* ctx) {
  j->linear_impulse = impulse;
  if (!impulses_finite(j)) zero_impulses(j); /* as tb_joint_store */
  /* the spring, motor and limit impulses are off, so zero (tb_joint_prepare) */
  j->force = tb_saturate2((double)ctx->inv_h * j->linear_impulse.x, (double)ctx->inv_h * j->linear_impulse.y);
  j->torque = j->motor_output = 0.0f;
}

/* ==== body joint lists ======================================================== */

static void link_edge(tb_world* w, int joint, int side) {
  tb_joint* j = tb_joint_at(w, joint);
  tb_body* b = tb_body_at(w, j->edges[side].body);
  int key = joint * 2 + side;
  j->edges[side].prev = -1;
  j->edges[side].next = b->joint_list;
  if (b->joint_list >= 0) tb_joint_at(w, b->joint_list >> 1)->edges[b->joint_list & 1].prev = key;
  b->joint_list = key;
  b->joint_count += 1;
  w->walked_joints_valid = false; /* (collect_joints walks the joint lists) */
  w->layout_valid = false;        /* (a jointed body's contact is never solved alone) */
}

static void unlink_edge(tb_world* w, int joint, int side) {
  tb_joint* j = tb_joint_at(w, joint);
  tb_joint_edge* e = &j->edges[side];
  tb_body* b = tb_body_at(w, e->body);
  if (e->prev >= 0)
    tb_joint_at(w, e->prev >> 1)->edges[e->prev & 1].next = e->next;
  else
    b->joint_list = e->next;
  if (e->next >= 0) tb_joint_at(w, e->next >> 1)->edges[e->next & 1].prev = e->prev;
  b->joint_count -= 1;
  w->walked_joints_valid = false;
  w->layout_valid = false;
}

bool tb_joints_allow_collision(const tb_world* w, int body_a, int body_b) {
  const tb_body* a = tb_body_at(w, body_a);
  const tb_body* b = tb_body_at(w, body_b);
  int from = a->joint_count <= b->joint_count ? body_a : body_b;
  int other = from == body_a ? body_b : body_a;
  for (int key = tb_body_at(w, from)->joint_list; key >= 0;) {
    const tb_joint* j = tb_joint_at(w, key >> 1);
    if (j->edges[(key & 1) ^ 1].body == other && !j->collide_connected) return false;
    key = j->edges[key & 1].next;
  }
  return true;
}

/* Ends the contacts between two bodies (walking the shorter contact list). */
static void destroy_contacts_between(tb_world* w, int body_a, int body_b) {
  const tb_body* a = tb_body_at(w, body_a);
  const tb_body* b = tb_body_at(w, body_b);
  int from = a->contact_count <= b->contact_count ? body_a : body_b;
  int other = from == body_a ? body_b : body_a;
  int key = tb_body_at(w, from)->contact_list;
  while (key >= 0) {
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, key >> 1);
    int next = c->edges[key & 1].next;
    if (c->edges[(key & 1) ^ 1].body == other) tb_contact_destroy(w, key >> 1);
    key = next;
  }
}

/* Two bodies may collide again: queue the shapes of the one with fewer shapes
 * for pair finding, so that the contacts between
 * them come back at the next step even if nothing moves. */
static void refind_pairs(tb_world* w, int body_a, int body_b) {
  if (!tb_joints_allow_collision(w, body_a, body_b)) return;
  const tb_body* a = tb_body_at(w, body_a);
  const tb_body* b = tb_body_at(w, body_b);
  int body = a->shape_count <= b->shape_count ? body_a : body_b;
  for (int s = tb_body_at(w, body)->shape_list; s >= 0; s = tb_shape_at(w, s)->next) {
    /* out of memory: the pair is found when the shape next moves out of its box */
    (void)tb_broad_phase_touch_proxy(w, s);
  }
}

static void wake_joint_bodies(tb_world* w, const tb_joint* j) {
  int a = j->edges[0].body, b = j->edges[1].body;
  tb_wake_body(w, a);
  tb_wake_body(w, b);
}

/* dying: a body being destroyed (not woken, nothing re-paired), or -1. */
static void destroy_joint(tb_world* w, int index, int dying) {
  tb_joint* j = tb_joint_at(w, index);
  int a = j->edges[0].body, b = j->edges[1].body;
  bool refilter = !j->collide_connected && dying < 0;
  if (a != dying) tb_wake_body(w, a);
  if (b != dying) tb_wake_body(w, b);
  unlink_edge(w, index, 0);
  unlink_edge(w, index, 1);
  tb_pool_release(&w->joints, index);
  if (refilter) refind_pairs(w, a, b);
}

void tb_joints_destroy_of_body(tb_world* w, int body) {
  while (tb_body_at(w, body)->joint_list >= 0) destroy_joint(w, tb_body_at(w, body)->joint_list >> 1, body);
}

/* ==== argument checks ========================================================= */

#define TRY(expr)               \
  do {                          \
    tb_result r_ = (expr);      \
    if (r_ != TB_OK) return r_; \
  } while (0)

static tb_result check_point(tb_world* w, const char* fn, const char* name, tb_vec2 p) {
  if (tb_point_ok(p)) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = (%g, %g) must be finite and within TB_MAX_LENGTH", fn, name,
                 (double)p.x, (double)p.y);
}

static tb_result check_real(tb_world* w, const char* fn, const char* name, float x) {
  if (tb_value_ok(x)) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be finite (at most TB_MAX_VALUE)", fn, name, (double)x);
}

/* A signed distance (translation limits). */
static tb_result check_translation(tb_world* w, const char* fn, const char* name, float x) {
  if (tb_length_ok(x)) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be finite and within TB_MAX_LENGTH", fn, name,
                 (double)x);
}

static tb_result check_length(tb_world* w, const char* fn, const char* name, float x, float min) {
  if (tb_length_ok(x) && x >= min) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be >= %g and at most TB_MAX_LENGTH", fn, name, (double)x,
                 (double)min);
}

static tb_result check_order(tb_world* w, const char* fn, const char* lo_name, float lo, const char* hi_name,
                             float hi) {
  if (lo <= hi) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g > %s = %g", fn, lo_name, (double)lo, hi_name, (double)hi);
}

static tb_result check_axis(tb_world* w, const char* fn, const char* name, tb_vec2 v) {
  TRY(check_point(w, fn, name, v));
  if (tb_length(v) >= 1e-6f) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = (%g, %g) has (near) zero length", fn, name, (double)v.x,
                 (double)v.y);
}

static tb_result check_spring(tb_world* w, const char* fn, const char* hertz_name, float hertz, const char* zeta_name,
                              float zeta) {
  TRY(tb_check_non_negative(w, fn, hertz_name, hertz));
  return tb_check_non_negative(w, fn, zeta_name, zeta);
}

/* A body of the joint's definition: alive, unlocked, of world w. */
static tb_result resolve_body(tb_world* w, tb_body_id id, const char* fn, const char* name, int* index) {
  char where[128];
  snprintf(where, sizeof where, "%s: %s", fn, name);
  tb_world* bw = NULL;
  if (tb_body_get_unlocked(id, &bw, where) == NULL) return tb_last_result();
  if (bw != w) return tb_fail(w, TB_ERR_FOREIGN_HANDLE, "%s: %s belongs to another world", fn, name);
  *index = id.index1 - 1;
  return TB_OK;
}

/* The world, the definition and both bodies of a creation call. */
static tb_result begin_create(tb_world_id world, const void* def, tb_body_id body_a, tb_body_id body_b, const char* fn,
                              tb_world** out, int* ia, int* ib) {
  tb_world* w = tb_world_get_unlocked(world, fn);
  if (w == NULL) return tb_last_result();
  *out = w;
  if (def == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: def is NULL", fn);
  TRY(resolve_body(w, body_a, fn, "def->body_a", ia));
  TRY(resolve_body(w, body_b, fn, "def->body_b", ib));
  if (*ia == *ib) return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->body_a and def->body_b are the same body", fn);
  return TB_OK;
}

/* Allocates, links and wakes: the only part of a creation that changes the world. */
static tb_joint_id finish_create(tb_world* w, const tb_joint* proto, int ia, int ib, const char* fn) {
  int index = tb_pool_alloc(&w->joints);
  if (index < 0) {
    tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the joint", fn);
    return null_joint;
  }
  tb_joint* j = tb_joint_at(w, index);
  *j = *proto;
  j->edges[0].body = ia;
  j->edges[1].body = ib;
  link_edge(w, index, 0);
  link_edge(w, index, 1);
  tb_wake_body(w, ia);
  tb_wake_body(w, ib);
  if (!proto->collide_connected) destroy_contacts_between(w, ia, ib);
  return tb_make_joint_id(w, index);
}

static tb_joint new_joint(tb_joint_type type, bool collide_connected, void* user_data) {
  tb_joint j;
  memset(&j, 0, sizeof j);
  j.type = type;
  j.collide_connected = collide_connected;
  j.user_data = user_data;
  j.solver_a = j.solver_b = -1;
  j.skip = true;
  return j;
}

/* ==== definitions and creation ================================================ */

tb_distance_joint_def tb_default_distance_joint_def(void) {
  return (tb_distance_joint_def){.length = tb_meters(1.0f), .min_length = 0.0f, .max_length = TB_MAX_LENGTH};
}

tb_revolute_joint_def tb_default_revolute_joint_def(void) { return (tb_revolute_joint_def){.enable_limit = false}; }

tb_prismatic_joint_def tb_default_prismatic_joint_def(void) {
  return (tb_prismatic_joint_def){.local_axis_a = {1.0f, 0.0f}};
}

tb_weld_joint_def tb_default_weld_joint_def(void) { return (tb_weld_joint_def){.linear_hertz = 0.0f}; }

tb_wheel_joint_def tb_default_wheel_joint_def(void) {
  return (tb_wheel_joint_def){
      .local_axis_a = {0.0f, 1.0f}, .enable_spring = true, .hertz = 1.0f, .damping_ratio = 0.7f};
}

tb_mouse_joint_def tb_default_mouse_joint_def(void) {
  /* a force is kg units/s^2, a torque kg units^2/s^2 (tb_set_length_units_per_meter) */
  return (tb_mouse_joint_def){
      .hertz = 5.0f, .damping_ratio = 0.7f, .max_force = tb_meters(1000.0f), .collide_connected = true};
}

tb_motor_joint_def tb_default_motor_joint_def(void) {
  return (tb_motor_joint_def){
      .max_force = tb_meters(1.0f), .max_torque = tb_meters(tb_meters(1.0f)), .correction_factor = 0.3f};
}

static tb_result check_anchors(tb_world* w, const char* fn, tb_vec2 a, tb_vec2 b) {
  TRY(check_point(w, fn, "def->local_anchor_a", a));
  return check_point(w, fn, "def->local_anchor_b", b);
}

static tb_result check_distance_def(tb_world* w, const char* fn, const tb_distance_joint_def* d) {
  TRY(check_anchors(w, fn, d->local_anchor_a, d->local_anchor_b));
  TRY(check_length(w, fn, "def->length", d->length, tb_units.linear_slop));
  TRY(check_spring(w, fn, "def->hertz", d->hertz, "def->damping_ratio", d->damping_ratio));
  TRY(check_length(w, fn, "def->min_length", d->min_length, 0.0f));
  TRY(check_length(w, fn, "def->max_length", d->max_length, 0.0f));
  TRY(check_order(w, fn, "def->min_length", d->min_length, "def->max_length", d->max_length));
  TRY(tb_check_non_negative(w, fn, "def->max_motor_force", d->max_motor_force));
  return check_real(w, fn, "def->motor_speed", d->motor_speed);
}

tb_joint_id tb_create_distance_joint(tb_world_id world, const tb_distance_joint_def* def) {
  const char* fn = "tb_create_distance_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_distance_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_DISTANCE, def->collide_connected, def->user_data);
  j.local_anchor_a = def->local_anchor_a;
  j.local_anchor_b = def->local_anchor_b;
  j.length = def->length;
  j.enable_spring = def->enable_spring;
  j.hertz = def->hertz;
  j.damping_ratio = def->damping_ratio;
  j.enable_limit = def->enable_limit;
  j.lower = def->min_length;
  j.upper = def->max_length;
  j.enable_motor = def->enable_motor;
  j.max_motor = def->max_motor_force;
  j.motor_speed = def->motor_speed;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_revolute_def(tb_world* w, const char* fn, const tb_revolute_joint_def* d) {
  TRY(check_anchors(w, fn, d->local_anchor_a, d->local_anchor_b));
  TRY(tb_check_angle(w, fn, "def->reference_angle", d->reference_angle));
  TRY(tb_check_angle(w, fn, "def->lower_angle", d->lower_angle));
  TRY(tb_check_angle(w, fn, "def->upper_angle", d->upper_angle));
  TRY(check_order(w, fn, "def->lower_angle", d->lower_angle, "def->upper_angle", d->upper_angle));
  TRY(tb_check_non_negative(w, fn, "def->max_motor_torque", d->max_motor_torque));
  TRY(check_real(w, fn, "def->motor_speed", d->motor_speed));
  return check_spring(w, fn, "def->hertz", d->hertz, "def->damping_ratio", d->damping_ratio);
}

tb_joint_id tb_create_revolute_joint(tb_world_id world, const tb_revolute_joint_def* def) {
  const char* fn = "tb_create_revolute_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_revolute_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_REVOLUTE, def->collide_connected, def->user_data);
  j.local_anchor_a = def->local_anchor_a;
  j.local_anchor_b = def->local_anchor_b;
  j.reference_angle = def->reference_angle;
  j.enable_limit = def->enable_limit;
  j.lower = def->lower_angle;
  j.upper = def->upper_angle;
  j.enable_motor = def->enable_motor;
  j.max_motor = def->max_motor_torque;
  j.motor_speed = def->motor_speed;
  j.enable_spring = def->enable_spring;
  j.hertz = def->hertz;
  j.damping_ratio = def->damping_ratio;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_prismatic_def(tb_world* w, const char* fn, const tb_prismatic_joint_def* d) {
  TRY(check_anchors(w, fn, d->local_anchor_a, d->local_anchor_b));
  TRY(check_axis(w, fn, "def->local_axis_a", d->local_axis_a));
  TRY(tb_check_angle(w, fn, "def->reference_angle", d->reference_angle));
  TRY(check_translation(w, fn, "def->lower_translation", d->lower_translation));
  TRY(check_translation(w, fn, "def->upper_translation", d->upper_translation));
  TRY(check_order(w, fn, "def->lower_translation", d->lower_translation, "def->upper_translation",
                  d->upper_translation));
  TRY(tb_check_non_negative(w, fn, "def->max_motor_force", d->max_motor_force));
  TRY(check_real(w, fn, "def->motor_speed", d->motor_speed));
  return check_spring(w, fn, "def->hertz", d->hertz, "def->damping_ratio", d->damping_ratio);
}

tb_joint_id tb_create_prismatic_joint(tb_world_id world, const tb_prismatic_joint_def* def) {
  const char* fn = "tb_create_prismatic_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_prismatic_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_PRISMATIC, def->collide_connected, def->user_data);
  j.local_anchor_a = def->local_anchor_a;
  j.local_anchor_b = def->local_anchor_b;
  j.local_axis_a = tb_normalize(def->local_axis_a);
  j.reference_angle = def->reference_angle;
  j.enable_limit = def->enable_limit;
  j.lower = def->lower_translation;
  j.upper = def->upper_translation;
  j.enable_motor = def->enable_motor;
  j.max_motor = def->max_motor_force;
  j.motor_speed = def->motor_speed;
  j.enable_spring = def->enable_spring;
  j.hertz = def->hertz;
  j.damping_ratio = def->damping_ratio;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_weld_def(tb_world* w, const char* fn, const tb_weld_joint_def* d) {
  TRY(check_anchors(w, fn, d->local_anchor_a, d->local_anchor_b));
  TRY(tb_check_angle(w, fn, "def->reference_angle", d->reference_angle));
  TRY(check_spring(w, fn, "def->linear_hertz", d->linear_hertz, "def->linear_damping_ratio", d->linear_damping_ratio));
  return check_spring(w, fn, "def->angular_hertz", d->angular_hertz, "def->angular_damping_ratio",
                      d->angular_damping_ratio);
}

tb_joint_id tb_create_weld_joint(tb_world_id world, const tb_weld_joint_def* def) {
  const char* fn = "tb_create_weld_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_weld_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_WELD, def->collide_connected, def->user_data);
  j.local_anchor_a = def->local_anchor_a;
  j.local_anchor_b = def->local_anchor_b;
  j.reference_angle = def->reference_angle;
  j.hertz = def->linear_hertz;
  j.damping_ratio = def->linear_damping_ratio;
  j.angular_hertz = def->angular_hertz;
  j.angular_damping_ratio = def->angular_damping_ratio;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_wheel_def(tb_world* w, const char* fn, const tb_wheel_joint_def* d) {
  TRY(check_anchors(w, fn, d->local_anchor_a, d->local_anchor_b));
  TRY(check_axis(w, fn, "def->local_axis_a", d->local_axis_a));
  TRY(check_spring(w, fn, "def->hertz", d->hertz, "def->damping_ratio", d->damping_ratio));
  TRY(check_translation(w, fn, "def->lower_translation", d->lower_translation));
  TRY(check_translation(w, fn, "def->upper_translation", d->upper_translation));
  TRY(check_order(w, fn, "def->lower_translation", d->lower_translation, "def->upper_translation",
                  d->upper_translation));
  TRY(tb_check_non_negative(w, fn, "def->max_motor_torque", d->max_motor_torque));
  return check_real(w, fn, "def->motor_speed", d->motor_speed);
}

tb_joint_id tb_create_wheel_joint(tb_world_id world, const tb_wheel_joint_def* def) {
  const char* fn = "tb_create_wheel_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_wheel_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_WHEEL, def->collide_connected, def->user_data);
  j.local_anchor_a = def->local_anchor_a;
  j.local_anchor_b = def->local_anchor_b;
  j.local_axis_a = tb_normalize(def->local_axis_a);
  j.enable_spring = def->enable_spring;
  j.hertz = def->hertz;
  j.damping_ratio = def->damping_ratio;
  j.enable_limit = def->enable_limit;
  j.lower = def->lower_translation;
  j.upper = def->upper_translation;
  j.enable_motor = def->enable_motor;
  j.max_motor = def->max_motor_torque;
  j.motor_speed = def->motor_speed;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_mouse_def(tb_world* w, const char* fn, const tb_mouse_joint_def* d) {
  TRY(check_point(w, fn, "def->target", d->target));
  TRY(check_spring(w, fn, "def->hertz", d->hertz, "def->damping_ratio", d->damping_ratio));
  return tb_check_non_negative(w, fn, "def->max_force", d->max_force);
}

tb_joint_id tb_create_mouse_joint(tb_world_id world, const tb_mouse_joint_def* def) {
  const char* fn = "tb_create_mouse_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_mouse_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_MOUSE, def->collide_connected, def->user_data);
  j.target = def->target;
  j.local_anchor_a = tb_inv_transform_point(tb_body_at(w, ia)->transform, def->target);
  j.local_anchor_b = tb_inv_transform_point(tb_body_at(w, ib)->transform, def->target);
  j.hertz = def->hertz;
  j.damping_ratio = def->damping_ratio;
  j.max_force = def->max_force;
  j.enable_spring = true;
  return finish_create(w, &j, ia, ib, fn);
}

static tb_result check_motor_def(tb_world* w, const char* fn, const tb_motor_joint_def* d) {
  TRY(check_point(w, fn, "def->linear_offset", d->linear_offset));
  TRY(tb_check_angle(w, fn, "def->angular_offset", d->angular_offset));
  TRY(tb_check_non_negative(w, fn, "def->max_force", d->max_force));
  TRY(tb_check_non_negative(w, fn, "def->max_torque", d->max_torque));
  if (isfinite(d->correction_factor) && d->correction_factor >= 0.0f && d->correction_factor <= 1.0f) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->correction_factor = %g must be in [0, 1]", fn,
                 (double)d->correction_factor);
}

tb_joint_id tb_create_motor_joint(tb_world_id world, const tb_motor_joint_def* def) {
  const char* fn = "tb_create_motor_joint";
  tb_world* w = NULL;
  int ia = -1, ib = -1;
  const tb_body_id none = {0, 0, 0};
  if (begin_create(world, def, def ? def->body_a : none, def ? def->body_b : none, fn, &w, &ia, &ib) != TB_OK ||
      check_motor_def(w, fn, def) != TB_OK)
    return null_joint;
  tb_joint j = new_joint(TB_JOINT_MOTOR, def->collide_connected, def->user_data);
  j.local_anchor_a = def->linear_offset;
  j.local_anchor_b = tb_body_at(w, ib)->local_center;
  j.reference_angle = def->angular_offset;
  j.max_force = def->max_force;
  j.max_torque = def->max_torque;
  j.correction_factor = def->correction_factor;
  return finish_create(w, &j, ia, ib, fn);
}

/* ==== handles, common getters and setters ===================================== */

#define GET_JOINT(id, fallback)                   \
  tb_world* w = NULL;                             \
  tb_joint* j = tb_joint_get((id), &w, __func__); \
  if (j == NULL) return (fallback);               \
  (void)w
#define GET_JOINT_FOR_CHANGE(id)                           \
  tb_world* w = NULL;                                      \
  tb_joint* j = tb_joint_get_unlocked((id), &w, __func__); \
  if (j == NULL) return tb_last_result()

/* A joint of the given type (an error naming both types otherwise). */
static tb_joint* get_typed(tb_joint_id id, tb_joint_type type, bool change, tb_world** w, const char* fn) {
  tb_joint* j = change ? tb_joint_get_unlocked(id, w, fn) : tb_joint_get(id, w, fn);
  if (j == NULL) return NULL;
  if (j->type != type) {
    tb_fail(*w, TB_ERR_INVALID_ARGUMENT, "%s: the joint is a %s joint, not a %s joint", fn, type_names[j->type],
            type_names[type]);
    return NULL;
  }
  return j;
}

#define GET_TYPED(id, type, fallback)                         \
  tb_world* w = NULL;                                         \
  tb_joint* j = get_typed((id), (type), false, &w, __func__); \
  if (j == NULL) return (fallback);                           \
  (void)w
#define GET_TYPED_FOR_CHANGE(id, type)                       \
  tb_world* w = NULL;                                        \
  tb_joint* j = get_typed((id), (type), true, &w, __func__); \
  if (j == NULL) return tb_last_result()

tb_result tb_destroy_joint(tb_joint_id id) {
  GET_JOINT_FOR_CHANGE(id);
  (void)j;
  destroy_joint(w, id.index1 - 1, -1);
  return TB_OK;
}

bool tb_joint_is_valid(tb_joint_id id) { return tb_joint_get(id, NULL, NULL) != NULL; }

tb_joint_type tb_joint_get_type(tb_joint_id id) {
  GET_JOINT(id, TB_JOINT_DISTANCE);
  return j->type;
}

tb_body_id tb_joint_get_body_a(tb_joint_id id) {
  GET_JOINT(id, ((tb_body_id){0, 0, 0}));
  return tb_make_body_id(w, j->edges[0].body);
}

tb_body_id tb_joint_get_body_b(tb_joint_id id) {
  GET_JOINT(id, ((tb_body_id){0, 0, 0}));
  return tb_make_body_id(w, j->edges[1].body);
}

tb_vec2 tb_joint_get_local_anchor_a(tb_joint_id id) {
  GET_JOINT(id, ((tb_vec2){0.0f, 0.0f}));
  return j->local_anchor_a;
}

tb_vec2 tb_joint_get_local_anchor_b(tb_joint_id id) {
  GET_JOINT(id, ((tb_vec2){0.0f, 0.0f}));
  return j->local_anchor_b;
}

bool tb_joint_get_collide_connected(tb_joint_id id) {
  GET_JOINT(id, false);
  return j->collide_connected;
}

tb_result tb_joint_set_collide_connected(tb_joint_id id, bool collide) {
  GET_JOINT_FOR_CHANGE(id);
  if (j->collide_connected == collide) return TB_OK;
  j->collide_connected = collide;
  int a = j->edges[0].body, b = j->edges[1].body;
  tb_wake_body(w, a);
  tb_wake_body(w, b);
  if (collide)
    refind_pairs(w, a, b);
  else
    destroy_contacts_between(w, a, b);
  return TB_OK;
}

void* tb_joint_get_user_data(tb_joint_id id) {
  GET_JOINT(id, NULL);
  return j->user_data;
}

tb_result tb_joint_set_user_data(tb_joint_id id, void* user_data) {
  GET_JOINT_FOR_CHANGE(id);
  j->user_data = user_data;
  return TB_OK;
}

tb_vec2 tb_joint_get_constraint_force(tb_joint_id id) {
  GET_JOINT(id, ((tb_vec2){0.0f, 0.0f}));
  return j->force;
}

float tb_joint_get_constraint_torque(tb_joint_id id) {
  GET_JOINT(id, 0.0f);
  return j->torque;
}

/* World anchor points of a joint at the bodies' current transforms. */
static void world_anchors(const tb_world* w, const tb_joint* j, tb_vec2* pa, tb_vec2* pb) {
  *pa = tb_transform_point(tb_body_at(w, j->edges[0].body)->transform, j->local_anchor_a);
  *pb = tb_transform_point(tb_body_at(w, j->edges[1].body)->transform, j->local_anchor_b);
}

/* ---- distance ---- */

tb_result tb_distance_joint_set_length(tb_joint_id id, float length) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_DISTANCE);
  TRY(check_length(w, __func__, "length", length, tb_units.linear_slop));
  j->length = length;
  wake_joint_bodies(w, j);
  return TB_OK;
}

float tb_distance_joint_get_length(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_DISTANCE, 0.0f);
  return j->length;
}

float tb_distance_joint_get_current_length(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_DISTANCE, 0.0f);
  tb_vec2 pa, pb;
  world_anchors(w, j, &pa, &pb);
  return tb_length(tb_sub(pb, pa));
}

tb_result tb_distance_joint_set_spring(tb_joint_id id, bool enable, float hertz, float damping_ratio) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_DISTANCE);
  TRY(check_spring(w, __func__, "hertz", hertz, "damping_ratio", damping_ratio));
  j->enable_spring = enable;
  j->hertz = hertz;
  j->damping_ratio = damping_ratio;
  wake_joint_bodies(w, j);
  return TB_OK;
}

tb_result tb_distance_joint_set_limits(tb_joint_id id, bool enable, float min_length, float max_length) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_DISTANCE);
  TRY(check_length(w, __func__, "min_length", min_length, 0.0f));
  TRY(check_length(w, __func__, "max_length", max_length, 0.0f));
  TRY(check_order(w, __func__, "min_length", min_length, "max_length", max_length));
  j->enable_limit = enable;
  j->lower = min_length;
  j->upper = max_length;
  wake_joint_bodies(w, j);
  return TB_OK;
}

/* ---- revolute ---- */

float tb_revolute_joint_get_angle(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_REVOLUTE, 0.0f);
  /* from the integrated angles, so it is continuous past +-pi */
  return (tb_body_at(w, j->edges[1].body)->angle - tb_body_at(w, j->edges[0].body)->angle) - j->reference_angle;
}

static tb_result set_limits(tb_world* w, tb_joint* j, const char* fn, bool enable, float lower, float upper,
                            bool translation) {
  if (translation) {
    TRY(check_translation(w, fn, "lower", lower));
    TRY(check_translation(w, fn, "upper", upper));
  } else {
    TRY(tb_check_angle(w, fn, "lower", lower));
    TRY(tb_check_angle(w, fn, "upper", upper));
  }
  TRY(check_order(w, fn, "lower", lower, "upper", upper));
  if (enable != j->enable_limit) j->lower_impulse = j->upper_impulse = 0.0f;
  j->enable_limit = enable;
  j->lower = lower;
  j->upper = upper;
  wake_joint_bodies(w, j);
  return TB_OK;
}

static tb_result set_motor(tb_world* w, tb_joint* j, const char* fn, bool enable, float speed, float max,
                           const char* max_name) {
  TRY(check_real(w, fn, "speed", speed));
  TRY(tb_check_non_negative(w, fn, max_name, max));
  if (!enable) j->motor_impulse = 0.0f;
  j->enable_motor = enable;
  j->motor_speed = speed;
  j->max_motor = max;
  wake_joint_bodies(w, j);
  return TB_OK;
}

static tb_result set_spring(tb_world* w, tb_joint* j, const char* fn, bool enable, float hertz, float zeta) {
  TRY(check_spring(w, fn, "hertz", hertz, "damping_ratio", zeta));
  if (!enable) j->spring_impulse = 0.0f;
  j->enable_spring = enable;
  j->hertz = hertz;
  j->damping_ratio = zeta;
  wake_joint_bodies(w, j);
  return TB_OK;
}

tb_result tb_revolute_joint_set_limits(tb_joint_id id, bool enable, float lower, float upper) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_REVOLUTE);
  return set_limits(w, j, __func__, enable, lower, upper, false);
}

tb_result tb_revolute_joint_set_motor(tb_joint_id id, bool enable, float speed, float max_torque) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_REVOLUTE);
  return set_motor(w, j, __func__, enable, speed, max_torque, "max_torque");
}

tb_result tb_revolute_joint_set_spring(tb_joint_id id, bool enable, float hertz, float damping_ratio) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_REVOLUTE);
  return set_spring(w, j, __func__, enable, hertz, damping_ratio);
}

float tb_revolute_joint_get_motor_torque(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_REVOLUTE, 0.0f);
  return j->motor_output;
}

/* ---- prismatic ---- */

float tb_prismatic_joint_get_translation(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_PRISMATIC, 0.0f);
  tb_vec2 pa, pb;
  world_anchors(w, j, &pa, &pb);
  tb_vec2 n = tb_rotate(tb_body_at(w, j->edges[0].body)->transform.q, j->local_axis_a);
  return tb_dot(n, tb_sub(pb, pa));
}

float tb_prismatic_joint_get_speed(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_PRISMATIC, 0.0f);
  /* xdot = n . (vB + wB x rB - vA - wA x rA) + (wA x n) . d (see prismatic_solve) */
  const tb_body* a = tb_body_at(w, j->edges[0].body);
  const tb_body* b = tb_body_at(w, j->edges[1].body);
  tb_vec2 pa, pb;
  world_anchors(w, j, &pa, &pb);
  tb_vec2 ra = tb_sub(pa, a->center), rb = tb_sub(pb, b->center);
  tb_vec2 n = tb_rotate(a->transform.q, j->local_axis_a);
  tb_vec2 va = tb_add(a->linear_velocity, tb_cross_sv(a->angular_velocity, ra));
  tb_vec2 vb = tb_add(b->linear_velocity, tb_cross_sv(b->angular_velocity, rb));
  return tb_dot(n, tb_sub(vb, va)) + tb_dot(tb_cross_sv(a->angular_velocity, n), tb_sub(pb, pa));
}

tb_result tb_prismatic_joint_set_limits(tb_joint_id id, bool enable, float lower, float upper) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_PRISMATIC);
  return set_limits(w, j, __func__, enable, lower, upper, true);
}

tb_result tb_prismatic_joint_set_motor(tb_joint_id id, bool enable, float speed, float max_force) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_PRISMATIC);
  return set_motor(w, j, __func__, enable, speed, max_force, "max_force");
}

tb_result tb_prismatic_joint_set_spring(tb_joint_id id, bool enable, float hertz, float damping_ratio) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_PRISMATIC);
  return set_spring(w, j, __func__, enable, hertz, damping_ratio);
}

float tb_prismatic_joint_get_motor_force(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_PRISMATIC, 0.0f);
  return j->motor_output;
}

/* ---- weld ---- */

tb_result tb_weld_joint_set_stiffness(tb_joint_id id, float linear_hertz, float linear_damping_ratio,
                                      float angular_hertz, float angular_damping_ratio) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_WELD);
  TRY(check_spring(w, __func__, "linear_hertz", linear_hertz, "linear_damping_ratio", linear_damping_ratio));
  TRY(check_spring(w, __func__, "angular_hertz", angular_hertz, "angular_damping_ratio", angular_damping_ratio));
  j->hertz = linear_hertz;
  j->damping_ratio = linear_damping_ratio;
  j->angular_hertz = angular_hertz;
  j->angular_damping_ratio = angular_damping_ratio;
  wake_joint_bodies(w, j);
  return TB_OK;
}

/* ---- wheel ---- */

tb_result tb_wheel_joint_set_motor(tb_joint_id id, bool enable, float speed, float max_torque) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_WHEEL);
  return set_motor(w, j, __func__, enable, speed, max_torque, "max_torque");
}

tb_result tb_wheel_joint_set_spring(tb_joint_id id, bool enable, float hertz, float damping_ratio) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_WHEEL);
  return set_spring(w, j, __func__, enable, hertz, damping_ratio);
}

float tb_wheel_joint_get_motor_torque(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_WHEEL, 0.0f);
  return j->motor_output;
}

/* ---- mouse ---- */

tb_result tb_mouse_joint_set_target(tb_joint_id id, tb_vec2 target) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_MOUSE);
  TRY(check_point(w, __func__, "target", target));
  j->target = target;
  tb_wake_body(w, j->edges[1].body);
  return TB_OK;
}

tb_vec2 tb_mouse_joint_get_target(tb_joint_id id) {
  GET_TYPED(id, TB_JOINT_MOUSE, ((tb_vec2){0.0f, 0.0f}));
  return j->target;
}

/* ---- motor ---- */

tb_result tb_motor_joint_set_offsets(tb_joint_id id, tb_vec2 linear_offset, float angular_offset) {
  GET_TYPED_FOR_CHANGE(id, TB_JOINT_MOTOR);
  TRY(check_point(w, __func__, "linear_offset", linear_offset));
  TRY(tb_check_angle(w, __func__, "angular_offset", angular_offset));
  j->local_anchor_a = linear_offset;
  j->reference_angle = angular_offset;
  wake_joint_bodies(w, j);
  return TB_OK;
}
