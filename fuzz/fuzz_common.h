/* Shared helpers of the libFuzzer harnesses (see fuzz/README.md). */
#ifndef TB_FUZZ_COMMON_H
#define TB_FUZZ_COMMON_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tumble.h"

/* A failed invariant: print it and abort, which libFuzzer reports as a crash
 * and saves the input that caused it. */
#define FUZZ_CHECK(cond, ...)                                                      \
  do {                                                                             \
    if (!(cond)) {                                                                 \
      fprintf(stderr, "%s:%d: invariant failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                                \
      fprintf(stderr, "\n");                                                       \
      abort();                                                                     \
    }                                                                              \
  } while (0)

/* Reads the fuzzer's bytes; past the end every read gives zero. */
typedef struct fuzz_input {
  const uint8_t* data;
  size_t size, at;
} fuzz_input;

static inline uint8_t fuzz_u8(fuzz_input* in) { return in->at < in->size ? in->data[in->at++] : 0; }

static inline uint16_t fuzz_u16(fuzz_input* in) {
  uint16_t lo = fuzz_u8(in);
  return (uint16_t)(lo | (uint16_t)(fuzz_u8(in) << 8));
}

/* A float in [lo, hi] on a grid of 65536 steps. */
static inline float fuzz_range(fuzz_input* in, float lo, float hi) {
  return lo + (hi - lo) * (float)fuzz_u16(in) / 65535.0f;
}

/* Usually a float in [lo, hi]; one time in 64 a value no call may accept. */
static inline float fuzz_real(fuzz_input* in, float lo, float hi) {
  static const float bad[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, -1.0f, 0.0f, 1e-30f};
  uint8_t k = fuzz_u8(in);
  if (k >= 248) return bad[k - 248];
  return fuzz_range(in, lo, hi);
}

static inline bool fuzz_vec_finite(tb_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

#endif
