/* Four constraints at a time: the lanes of GCC vector extensions (SSE on
 * x86-64, plain scalar code elsewhere) and the solver bodies of four lanes
 * gathered into columns and scattered back. The contact solver and the
 * wide joints (joint_wide.c) solve their coloured blocks with these; within
 * one colour no two lanes share a moving body. */
#ifndef TB_WIDE_H
#define TB_WIDE_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "solver.h"

#if !defined(__GNUC__)
#error "tumble's solver needs GCC-style vector extensions (GCC or Clang)"
#endif

typedef float tb_f4 __attribute__((vector_size(16)));
typedef int32_t tb_i4 __attribute__((vector_size(16)));

static inline tb_f4 splat(float x) { return (tb_f4){x, x, x, x}; }
static inline tb_f4 blend(tb_i4 mask, tb_f4 a, tb_f4 b) { return (tb_f4)(((tb_i4)a & mask) | ((tb_i4)b & ~mask)); }
/* max4(a, b) = a > b ? a : b and min4(a, b) = a < b ? a : b, lane by lane
 * (b where either is NaN, and b of two zeros): what SSE's maxps and minps do,
 * one instruction each where the compare and blend take five. */
#if defined(__SSE__)
static inline tb_f4 max4(tb_f4 a, tb_f4 b) { return (tb_f4)_mm_max_ps((__m128)a, (__m128)b); }
static inline tb_f4 min4(tb_f4 a, tb_f4 b) { return (tb_f4)_mm_min_ps((__m128)a, (__m128)b); }
#else
static inline tb_f4 max4(tb_f4 a, tb_f4 b) { return blend(a > b, a, b); }
static inline tb_f4 min4(tb_f4 a, tb_f4 b) { return blend(a < b, a, b); }
#endif
/* The largest lane, NaN lanes left out (what fmaxf over the lanes gives,
 * without four calls into libm). */
static inline float max_lane(tb_f4 v) {
  float m = v[0];
  for (int lane = 1; lane < 4; ++lane) m = v[lane] > m || m != m ? v[lane] : m;
  return m;
}
static inline tb_f4 fabs4(tb_f4 a) { return (tb_f4)((tb_i4)a & (tb_i4){INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX}); }

/* Four solver bodies, field by field. A solver body begins with two rows of
 * four floats, (v.x, v.y, w, inv_mass) and (inv_inertia, da, dp.x, dp.y):
 * four bodies' rows are loaded whole and transposed into columns, and the
 * first rows are transposed back and stored whole (inv_mass as it was read). */
_Static_assert(offsetof(tb_solver_body, v) == 0 && offsetof(tb_solver_body, w) == 8 &&
                   offsetof(tb_solver_body, inv_mass) == 12 && offsetof(tb_solver_body, inv_inertia) == 16 &&
                   offsetof(tb_solver_body, da) == 20 && offsetof(tb_solver_body, dp) == 24 &&
                   sizeof(tb_solver_body) >= 32,
               "the wide gather reads a solver body as two rows of four floats");

typedef struct wide_body {
  tb_f4 vx, vy, w, inv_mass;
  tb_f4 inv_inertia, da, dpx, dpy;
} wide_body;

/* lane k of the result: lane i_k of a (0-3) or of b (4-7) */
#if defined(__clang__) || __GNUC__ >= 12
#define SHUFFLE(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
#define SHUFFLE(a, b, i0, i1, i2, i3) __builtin_shuffle(a, b, (tb_i4){i0, i1, i2, i3})
#endif

/* rows <-> columns of a 4x4 matrix */
static inline void transpose(tb_f4 m[4]) {
  tb_f4 t0 = SHUFFLE(m[0], m[1], 0, 4, 1, 5), t1 = SHUFFLE(m[2], m[3], 0, 4, 1, 5);
  tb_f4 t2 = SHUFFLE(m[0], m[1], 2, 6, 3, 7), t3 = SHUFFLE(m[2], m[3], 2, 6, 3, 7);
  m[0] = SHUFFLE(t0, t1, 0, 1, 4, 5);
  m[1] = SHUFFLE(t0, t1, 2, 3, 6, 7);
  m[2] = SHUFFLE(t2, t3, 0, 1, 4, 5);
  m[3] = SHUFFLE(t2, t3, 2, 3, 6, 7);
}

/* row 0 or 1 of the solver bodies idx[0..3], transposed */
static inline void load_rows(const tb_solver_body* states, const int32_t* idx, int row, tb_f4 m[4]) {
  memcpy(&m[0], (const float*)&states[idx[0]] + 4 * row, sizeof m[0]);
  memcpy(&m[1], (const float*)&states[idx[1]] + 4 * row, sizeof m[1]);
  memcpy(&m[2], (const float*)&states[idx[2]] + 4 * row, sizeof m[2]);
  memcpy(&m[3], (const float*)&states[idx[3]] + 4 * row, sizeof m[3]);
  transpose(m);
}

static inline wide_body gather_velocities(const tb_solver_body* states, const int32_t* idx) {
  tb_f4 m[4];
  load_rows(states, idx, 0, m);
  return (wide_body){.vx = m[0], .vy = m[1], .w = m[2], .inv_mass = m[3]};
}

/* always inlined: a call would return the eight columns through memory */
static inline __attribute__((always_inline)) wide_body gather(const tb_solver_body* states, const int32_t* idx) {
  wide_body b = gather_velocities(states, idx);
  tb_f4 m[4];
  load_rows(states, idx, 1, m);
  b.inv_inertia = m[0];
  b.da = m[1];
  b.dpx = m[2];
  b.dpy = m[3];
  return b;
}

static inline __attribute__((always_inline)) void scatter(tb_solver_body* states, const int32_t* idx,
                                                          const wide_body* b) {
  tb_f4 m[4] = {b->vx, b->vy, b->w, b->inv_mass};
  transpose(m);
  memcpy(&states[idx[0]], &m[0], sizeof m[0]);
  memcpy(&states[idx[1]], &m[1], sizeof m[1]);
  memcpy(&states[idx[2]], &m[2], sizeof m[2]);
  memcpy(&states[idx[3]], &m[3], sizeof m[3]);
}

/* Four lanes of bodies or contacts, field by field. */
#define LANES(p, field) ((tb_f4){(p)[0]->field, (p)[1]->field, (p)[2]->field, (p)[3]->field})
#define INT_LANES(p, field) ((tb_i4){(p)[0]->field, (p)[1]->field, (p)[2]->field, (p)[3]->field})

/* 1 / x where x > 0, else 0 */
static inline tb_f4 inverse_or_zero(tb_f4 x) {
  const tb_f4 zero = splat(0.0f);
  return blend(x > zero, splat(1.0f) / x, zero);
}

#endif
