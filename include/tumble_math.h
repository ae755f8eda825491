/* tumble_math: small inline helpers on tumble's vectors, rotations, transforms
 * and boxes, for games that embed tumble (issue 24).
 *
 * Header only (every function is static inline); it includes tumble.h for the
 * types and links against nothing beyond libm. Where a helper does what the
 * engine does inside its step (add, dot, cross, rotate, transform a point,
 * normalize, lerp, rotation from an angle), it computes the same expression
 * in the same order, so it gives bit-identical results to the engine's own
 * (tests/test_math_api.c holds them to it) when both are built with
 * -ffp-contract=off and without -ffast-math, as tumble is: a compiler that
 * fuses a * b + c into one rounding changes the last bit.
 *
 * Angles: tb_rot_from_angle computes its cosine and sine itself, in double
 * arithmetic only (no C library call), and the engine turns body angles into
 * rotations with this very function: the same bits on every platform with
 * IEEE double arithmetic (C libraries' cosf and sinf may round differently).
 * tb_rot_get_angle uses the C library's atan2f, and the engine never does.
 *
 * Nothing here checks its input: these are the building blocks, NaN in gives
 * NaN out. The _is_valid functions tell what the engine's entry points accept. */
#ifndef TUMBLE_MATH_H
#define TUMBLE_MATH_H

#include <math.h>
#include <stdbool.h>

#include "tumble.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- vectors -- */

static inline tb_vec2 tb_vec2_make(float x, float y) {
  tb_vec2 out = {x, y};
  return out;
}
static inline tb_vec2 tb_vec2_add(tb_vec2 a, tb_vec2 b) {
  tb_vec2 out = {a.x + b.x, a.y + b.y};
  return out;
}
static inline tb_vec2 tb_vec2_sub(tb_vec2 a, tb_vec2 b) {
  tb_vec2 out = {a.x - b.x, a.y - b.y};
  return out;
}
static inline tb_vec2 tb_vec2_neg(tb_vec2 a) {
  tb_vec2 out = {-a.x, -a.y};
  return out;
}
/* s a */
static inline tb_vec2 tb_vec2_scale(float s, tb_vec2 a) {
  tb_vec2 out = {s * a.x, s * a.y};
  return out;
}
/* a + s b */
static inline tb_vec2 tb_vec2_mul_add(tb_vec2 a, float s, tb_vec2 b) {
  tb_vec2 out = {a.x + s * b.x, a.y + s * b.y};
  return out;
}
/* a - s b */
static inline tb_vec2 tb_vec2_mul_sub(tb_vec2 a, float s, tb_vec2 b) {
  tb_vec2 out = {a.x - s * b.x, a.y - s * b.y};
  return out;
}
static inline float tb_vec2_dot(tb_vec2 a, tb_vec2 b) { return a.x * b.x + a.y * b.y; }
/* a x b: the z of the 3D cross product; > 0 when b lies counter-clockwise of a. */
static inline float tb_vec2_cross(tb_vec2 a, tb_vec2 b) { return a.x * b.y - a.y * b.x; }
/* v x s = (s v.y, -s v.x): v turned a quarter clockwise, scaled by s. */
static inline tb_vec2 tb_vec2_cross_vs(tb_vec2 v, float s) {
  tb_vec2 out = {s * v.y, -s * v.x};
  return out;
}
/* s x v = (-s v.y, s v.x): e.g. the velocity w x r of a point at r on a body
 * turning at w rad/s. */
static inline tb_vec2 tb_vec2_cross_sv(float s, tb_vec2 v) {
  tb_vec2 out = {-s * v.y, s * v.x};
  return out;
}
/* v turned a quarter counter-clockwise (left) or clockwise (right). */
static inline tb_vec2 tb_vec2_left_perp(tb_vec2 v) {
  tb_vec2 out = {-v.y, v.x};
  return out;
}
static inline tb_vec2 tb_vec2_right_perp(tb_vec2 v) {
  tb_vec2 out = {v.y, -v.x};
  return out;
}
static inline float tb_vec2_length_squared(tb_vec2 v) { return v.x * v.x + v.y * v.y; }
static inline float tb_vec2_length(tb_vec2 v) { return sqrtf(v.x * v.x + v.y * v.y); }
static inline float tb_vec2_distance_squared(tb_vec2 a, tb_vec2 b) { return tb_vec2_length_squared(tb_vec2_sub(a, b)); }
static inline float tb_vec2_distance(tb_vec2 a, tb_vec2 b) { return tb_vec2_length(tb_vec2_sub(a, b)); }
/* The unit vector along v, or (0, 0) when v is shorter than 1e-20 (zero
 * included): never NaN for a finite v. */
static inline tb_vec2 tb_vec2_normalize(tb_vec2 v) {
  float len = tb_vec2_length(v);
  tb_vec2 out = {0.0f, 0.0f};
  if (len < 1e-20f) return out;
  float inv = 1.0f / len;
  out.x = inv * v.x;
  out.y = inv * v.y;
  return out;
}
/* a + t (b - a): a at t = 0, b at t = 1. */
static inline tb_vec2 tb_vec2_lerp(tb_vec2 a, tb_vec2 b, float t) {
  tb_vec2 out = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  return out;
}
static inline tb_vec2 tb_vec2_min(tb_vec2 a, tb_vec2 b) {
  tb_vec2 out = {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y};
  return out;
}
static inline tb_vec2 tb_vec2_max(tb_vec2 a, tb_vec2 b) {
  tb_vec2 out = {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y};
  return out;
}
/* Finite and within TB_MAX_LENGTH: a point the engine accepts. */
static inline bool tb_vec2_is_valid(tb_vec2 v) {
  return isfinite(v.x) && isfinite(v.y) && fabsf(v.x) <= TB_MAX_LENGTH && fabsf(v.y) <= TB_MAX_LENGTH;
}

/* -------------------------------------------------------------- rotations -- */

static inline tb_rot tb_rot_identity(void) {
  tb_rot out = {1.0f, 0.0f};
  return out;
}
/* (cos angle, sin angle) within one unit in the last place (correctly
 * rounded but for about one angle in ten thousand), the same bits on every
 * platform; NaN for an infinite or NaN angle. The engine computes a body's
 * rotation from its angle with it (see the top of this file).
 *
 * How: angle = k pi/2 + r with |r| <= pi/4, in double, pi/2 split into a
 * 33-bit head (so that k times it is exact for |k| < 2^20: every angle the
 * engine accepts, |angle| <= TB_MAX_ANGLE) and a tail; then the Taylor series
 * of sin r to r^11 and of cos r to r^12, whose first omitted terms are below
 * 7e-12 on |r| <= pi/4 against a float's half unit of at least 3e-8 (relative).
 * Beyond 2^20 rad the angle is first folded into [0, 2 pi) exactly (steps of
 * the double nearest 2 pi times powers of two, each subtraction exact): the
 * fold's own error, the angle over 2 pi times 2.45e-16, stays below 2e-7 rad
 * up to 2^32 rad, where a float angle is already 512 rad coarse. */
static inline tb_rot tb_rot_from_angle(float angle) {
  const double two_pi = 6.283185307179586232; /* the double nearest 2 pi */
  const double two_over_pi = 0.63661977236758134308;
  const double half_pi_head = 1.57079632673412561417;     /* pi/2 to 33 bits */
  const double half_pi_tail = 6.07710050650619224932e-11; /* pi/2 - half_pi_head */
  double x = (double)angle;
  if (!isfinite(x) || x == 0.0) { /* NaN; and +-0, whose sine keeps the sign */
    tb_rot ends = {x == 0.0 ? 1.0f : NAN, x == 0.0 ? angle : NAN};
    return ends;
  }
  double sign = 1.0;
  if (fabs(x) > 1048576.0) { /* 2^20: fold |x| into [0, 2 pi) */
    sign = x < 0.0 ? -1.0 : 1.0;
    x = fabs(x);
    double m = two_pi;
    while (m * 2.0 <= x) m *= 2.0;
    for (; m >= two_pi; m *= 0.5) /* x < 2 m, so x - m is exact */
      if (x >= m) x -= m;
  }
  /* nearest k (ties away from zero; |k| < 2^20 here) */
  double kd = x * two_over_pi;
  long k = (long)(kd < 0.0 ? kd - 0.5 : kd + 0.5);
  double r = (x - (double)k * half_pi_head) - (double)k * half_pi_tail, r2 = r * r, r4 = r2 * r2;
  /* the series in r^2 grouped in pairs (Estrin), a shorter chain than Horner's */
  double sin_r = r + r * r2 *
                         ((-1.0 / 6.0 + r2 * (1.0 / 120.0)) +
                          r4 * ((-1.0 / 5040.0 + r2 * (1.0 / 362880.0)) + r4 * (-1.0 / 39916800.0)));
  double cos_r = 1.0 + r2 * ((-0.5 + r2 * (1.0 / 24.0)) + r4 * ((-1.0 / 720.0 + r2 * (1.0 / 40320.0)) +
                                                                r4 * (-1.0 / 3628800.0 + r2 * (1.0 / 479001600.0))));
  /* the quadrant k mod 4 (also for k < 0): cos, sin turned k quarter turns */
  unsigned long q = (unsigned long)k;
  double c = (q & 1u) ? sin_r : cos_r, s = (q & 1u) ? cos_r : sin_r;
  c = ((q + 1u) & 2u) ? -c : c;
  s = (q & 2u) ? -s : s;
  tb_rot out = {(float)c, (float)(sign * s)};
  return out;
}
/* The angle of a rotation in [-pi, pi] (atan2f). */
static inline float tb_rot_get_angle(tb_rot q) { return atan2f(q.s, q.c); }
/* q scaled to unit length; the identity for q shorter than 1e-20. */
static inline tb_rot tb_rot_normalize(tb_rot q) {
  tb_vec2 v = {q.c, q.s}, u = tb_vec2_normalize(v);
  tb_rot out = {u.x, u.y};
  if (u.x == 0.0f && u.y == 0.0f) out.c = 1.0f;
  return out;
}
/* Unit length within 1e-3 (|c^2 + s^2 - 1| <= 1e-3) and finite: what the
 * engine accepts as a transform's rotation. */
static inline bool tb_rot_is_valid(tb_rot q) {
  return isfinite(q.c) && isfinite(q.s) && fabsf(q.c * q.c + q.s * q.s - 1.0f) <= 1e-3f;
}
/* v turned by q, and by the inverse of q. */
static inline tb_vec2 tb_rot_rotate(tb_rot q, tb_vec2 v) {
  tb_vec2 out = {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
  return out;
}
static inline tb_vec2 tb_rot_inv_rotate(tb_rot q, tb_vec2 v) {
  tb_vec2 out = {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
  return out;
}
/* q r: turn by r, then by q (angles add). */
static inline tb_rot tb_rot_mul(tb_rot q, tb_rot r) {
  tb_rot out = {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s};
  return out;
}
/* q^-1 r: the rotation from q to r (angle of r minus angle of q). */
static inline tb_rot tb_rot_inv_mul(tb_rot q, tb_rot r) {
  tb_rot out = {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c};
  return out;
}
/* Normalized linear interpolation from q1 (t = 0) to q2 (t = 1), to
 * rounding: the shorter way round, not at constant angular speed (the middle
 * of the turn at t = 0.5, and faster there than at the ends). Opposite rotations have no shorter way: at their midpoint
 * the result is q1 for t < 0.5 and q2 otherwise. */
static inline tb_rot tb_rot_nlerp(tb_rot q1, tb_rot q2, float t) {
  tb_vec2 a = {q1.c, q1.s}, b = {q2.c, q2.s}, u = tb_vec2_normalize(tb_vec2_lerp(a, b, t));
  tb_rot out = {u.x, u.y};
  if (u.x == 0.0f && u.y == 0.0f) return t < 0.5f ? q1 : q2;
  return out;
}

/* ------------------------------------------------------------- transforms -- */

static inline tb_transform tb_transform_identity(void) {
  tb_transform out = {{0.0f, 0.0f}, {1.0f, 0.0f}};
  return out;
}
/* The world point of a point given in the frame xf (a body's transform):
 * xf.p + xf.q local. */
static inline tb_vec2 tb_transform_world_point(tb_transform xf, tb_vec2 local) {
  return tb_vec2_add(xf.p, tb_rot_rotate(xf.q, local));
}
/* The inverse: a world point in the frame xf, xf.q^-1 (world - xf.p). */
static inline tb_vec2 tb_transform_local_point(tb_transform xf, tb_vec2 world) {
  return tb_rot_inv_rotate(xf.q, tb_vec2_sub(world, xf.p));
}
/* a b: the frame b given in frame a, as a world frame (b first, then a). */
static inline tb_transform tb_transform_mul(tb_transform a, tb_transform b) {
  tb_transform out = {tb_vec2_add(tb_rot_rotate(a.q, b.p), a.p), tb_rot_mul(a.q, b.q)};
  return out;
}
/* a^-1 b: the world frame b seen from frame a (e.g. one body relative to another). */
static inline tb_transform tb_transform_inv_mul(tb_transform a, tb_transform b) {
  tb_transform out = {tb_rot_inv_rotate(a.q, tb_vec2_sub(b.p, a.p)), tb_rot_inv_mul(a.q, b.q)};
  return out;
}

/* ------------------------------------------------------------------ boxes -- */

/* The smallest box holding both. */
static inline tb_aabb tb_aabb_union(tb_aabb a, tb_aabb b) {
  tb_aabb out = {tb_vec2_min(a.lower, b.lower), tb_vec2_max(a.upper, b.upper)};
  return out;
}
/* outer holds inner (touching sides count). */
static inline bool tb_aabb_contains(tb_aabb outer, tb_aabb inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y;
}
static inline bool tb_aabb_contains_point(tb_aabb a, tb_vec2 p) {
  return a.lower.x <= p.x && p.x <= a.upper.x && a.lower.y <= p.y && p.y <= a.upper.y;
}
/* The boxes share a point (touching counts), as the engine's queries test. */
static inline bool tb_aabb_overlaps(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}
static inline tb_vec2 tb_aabb_center(tb_aabb a) {
  tb_vec2 out = {0.5f * (a.lower.x + a.upper.x), 0.5f * (a.lower.y + a.upper.y)};
  return out;
}
/* Half the width and half the height. */
static inline tb_vec2 tb_aabb_extents(tb_aabb a) {
  tb_vec2 out = {0.5f * (a.upper.x - a.lower.x), 0.5f * (a.upper.y - a.lower.y)};
  return out;
}
/* Finite, within TB_MAX_LENGTH and lower <= upper: a box the engine accepts. */
static inline bool tb_aabb_is_valid(tb_aabb a) {
  return tb_vec2_is_valid(a.lower) && tb_vec2_is_valid(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y;
}

/* ---------------------------------------------------------- spring-damper -- */

/* One step of a damped spring x'' = -k x - c v (per unit mass: k = w^2 and
 * c = 2 zeta w for a spring of frequency f hertz, w = 2 pi f, and damping
 * ratio zeta), from position x and velocity v over h seconds, by implicit
 * (backward) Euler: v1 = v + h (-k x1 - c v1) and x1 = x + h v1. Putting the
 * second into the first,
 *     v1 = (v - h k x) / (1 + h c + h^2 k),
 * the new velocity this returns; then x1 = x + h v1. For k, c, h >= 0 the
 * step never gains energy, however stiff the spring or long the step (an
 * explicit step blows up once h w > 2): the amplification of a mode is
 * 1 / sqrt(1 + h c + h^2 k) < 1 per step for an undamped spring. It loses
 * some energy every step (about h^2 k / 2 of it, relative, per step when h w
 * is small), so lightly damped springs ring down a little faster than exact.
 * Per axis for vectors; e.g. a camera following a target t:
 *     v = tb_spring_damper_velocity(k, c, x - t, v, h); x += h * v; */
static inline float tb_spring_damper_velocity(float k, float c, float x, float v, float h) {
  return (v - h * k * x) / (1.0f + h * c + h * h * k);
}

#ifdef __cplusplus
}
#endif

#endif /* TUMBLE_MATH_H */
