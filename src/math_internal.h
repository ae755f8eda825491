/* Small vector and rotation helpers used across the engine (not public). */
#ifndef TB_MATH_INTERNAL_H
#define TB_MATH_INTERNAL_H

#include <math.h>
#include <stdbool.h>

#include "tumble.h"
#include "tumble_math.h"

/* 2 pi in float: hertz to angular frequency (softness of contacts and joints) */
#define TB_TWO_PI_F (2.0f * 3.14159265358979f)

static inline tb_vec2 tb_v2(float x, float y) { return (tb_vec2){x, y}; }
static inline tb_vec2 tb_add(tb_vec2 a, tb_vec2 b) { return (tb_vec2){a.x + b.x, a.y + b.y}; }
static inline tb_vec2 tb_sub(tb_vec2 a, tb_vec2 b) { return (tb_vec2){a.x - b.x, a.y - b.y}; }
static inline tb_vec2 tb_neg(tb_vec2 a) { return (tb_vec2){-a.x, -a.y}; }
static inline tb_vec2 tb_scale(float s, tb_vec2 a) { return (tb_vec2){s * a.x, s * a.y}; }
/* a + s b */
static inline tb_vec2 tb_mul_add(tb_vec2 a, float s, tb_vec2 b) { return (tb_vec2){a.x + s * b.x, a.y + s * b.y}; }
static inline float tb_dot(tb_vec2 a, tb_vec2 b) { return a.x * b.x + a.y * b.y; }
/* 2D cross product a x b: the z of the 3D cross product. */
static inline float tb_cross(tb_vec2 a, tb_vec2 b) { return a.x * b.y - a.y * b.x; }
/* w x v for a scalar angular velocity w (z axis): (-w v.y, w v.x). */
static inline tb_vec2 tb_cross_sv(float w, tb_vec2 v) { return (tb_vec2){-w * v.y, w * v.x}; }
/* v x s: (s v.y, -s v.x). */
static inline tb_vec2 tb_cross_vs(tb_vec2 v, float s) { return (tb_vec2){s * v.y, -s * v.x}; }
static inline tb_vec2 tb_left_perp(tb_vec2 v) { return (tb_vec2){-v.y, v.x}; }
static inline tb_vec2 tb_right_perp(tb_vec2 v) { return (tb_vec2){v.y, -v.x}; }
static inline float tb_length_sq(tb_vec2 v) { return v.x * v.x + v.y * v.y; }
static inline float tb_length(tb_vec2 v) { return sqrtf(v.x * v.x + v.y * v.y); }
static inline float tb_distance_sq(tb_vec2 a, tb_vec2 b) { return tb_length_sq(tb_sub(a, b)); }
static inline tb_vec2 tb_vmin(tb_vec2 a, tb_vec2 b) { return (tb_vec2){a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y}; }
static inline tb_vec2 tb_vmax(tb_vec2 a, tb_vec2 b) { return (tb_vec2){a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y}; }
/* fminf and fmaxf as glibc's x86-64 ones answer (a NaN operand loses; of two
 * zeros the second is returned), inline: libm's are calls (1.9% of
 * junkyard's instructions), and other C libraries return +0 where glibc
 * returns -0, which would change the bits across platforms. */
static inline float tb_minf(float a, float b) { return a < b || b != b ? a : b; }
static inline float tb_maxf(float a, float b) { return a > b || b != b ? a : b; }
static inline double tb_maxd(double a, double b) { return a > b || b != b ? a : b; }
/* Knuth's TwoSum per component: returns fl(a + b) and sets *error to the
 * part the rounding dropped, a + b - fl(a + b), exactly (any magnitudes; needs
 * no fused or reassociated arithmetic, which -ffp-contract=off and no
 * -ffast-math keep). */
static inline float tb_two_sum_f(float a, float b, float* error) {
  float s = a + b, bb = s - a;
  *error = (a - (s - bb)) + (b - bb);
  return s;
}
static inline tb_vec2 tb_two_sum(tb_vec2 a, tb_vec2 b, tb_vec2* error) {
  return (tb_vec2){tb_two_sum_f(a.x, b.x, &error->x), tb_two_sum_f(a.y, b.y, &error->y)};
}

static inline tb_vec2 tb_lerp(tb_vec2 a, tb_vec2 b, float t) {
  return (tb_vec2){a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}
/* Unit vector along v, or zero for a (near) zero vector. */
static inline tb_vec2 tb_normalize(tb_vec2 v) {
  float len = tb_length(v);
  if (len < 1e-20f) return (tb_vec2){0.0f, 0.0f};
  float inv = 1.0f / len;
  return (tb_vec2){inv * v.x, inv * v.y};
}

static inline bool tb_finite(float a) { return isfinite(a); }
static inline bool tb_vec_finite(tb_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

/* Accepted input: finite and within the documented limits of tumble.h. */
static inline bool tb_length_ok(float a) { return isfinite(a) && fabsf(a) <= TB_MAX_LENGTH; }
static inline bool tb_point_ok(tb_vec2 p) { return tb_length_ok(p.x) && tb_length_ok(p.y); }
static inline bool tb_value_ok(float a) { return isfinite(a) && fabsf(a) <= TB_MAX_VALUE; }
static inline bool tb_vector_ok(tb_vec2 v) { return tb_value_ok(v.x) && tb_value_ok(v.y); }
/* What the engine reports stays within its own limit: x (computed in double,
 * so the product of two accepted values cannot overflow) saturated to
 * [-TB_MAX_VALUE, TB_MAX_VALUE]. */
static inline float tb_saturate(double x) {
  return x > TB_MAX_VALUE ? TB_MAX_VALUE : x < -TB_MAX_VALUE ? -TB_MAX_VALUE : (float)x;
}
static inline tb_vec2 tb_saturate2(double x, double y) { return (tb_vec2){tb_saturate(x), tb_saturate(y)}; }

/* no C library call: the same bits on every platform (tumble_math.h) */
static inline tb_rot tb_make_rot(float angle) { return tb_rot_from_angle(angle); }
static inline tb_vec2 tb_rotate(tb_rot q, tb_vec2 v) { return (tb_vec2){q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
static inline tb_vec2 tb_inv_rotate(tb_rot q, tb_vec2 v) {
  return (tb_vec2){q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}
static inline tb_vec2 tb_transform_point(tb_transform t, tb_vec2 p) { return tb_add(t.p, tb_rotate(t.q, p)); }
static inline tb_vec2 tb_inv_transform_point(tb_transform t, tb_vec2 p) { return tb_inv_rotate(t.q, tb_sub(p, t.p)); }

#endif
