/* Shared helpers of the check suites. Each tests/test_*.c file is one suite
 * (one concept) built into its own executable with TB_TEST_MAIN. */
#ifndef TB_TEST_UTIL_H
#define TB_TEST_UTIL_H

#include <check.h>
#include <math.h>

#include "tumble.h"

/* |a - b| <= tol * max(|b|, floor): a relative error with an absolute floor. */
#define ck_assert_rel(a, b, tol) ck_assert_rel_floor((a), (b), (tol), 1e-30)
#define ck_assert_rel_floor(a, b, tol, floor)                                                                          \
  do {                                                                                                                 \
    double a_ = (double)(a), b_ = (double)(b), t_ = (double)(tol);                                                     \
    double s_ = fabs(b_) > (floor) ? fabs(b_) : (floor);                                                               \
    ck_assert_msg(isfinite(a_) && fabs(a_ - b_) <= t_ * s_, "%s = %.9g, expected %s = %.9g (rel %.3g > %.3g)", #a, a_, \
                  #b, b_, fabs(a_ - b_) / s_, t_);                                                                     \
  } while (0)
#define ck_assert_near(a, b, tol)                                                                                    \
  do {                                                                                                               \
    double a_ = (double)(a), b_ = (double)(b), t_ = (double)(tol);                                                   \
    ck_assert_msg(isfinite(a_) && fabs(a_ - b_) <= t_, "%s = %.9g, expected %s = %.9g (|diff| %.3g > %.3g)", #a, a_, \
                  #b, b_, fabs(a_ - b_), t_);                                                                        \
  } while (0)

/* A world with default settings but the given gravity. */
tb_world_id tbt_world(float gx, float gy);
/* A dynamic body at (x, y) with one box of half extents hx, hy and density 1. */
tb_body_id tbt_box_body(tb_world_id w, float x, float y, float hx, float hy);
/* Deterministic random numbers for tests (xorshift), uniform in [lo, hi]: float
 * rounding can return hi itself, so do not cast to an index without clamping. */
float tbt_rand(unsigned* state, float lo, float hi);
/* Prints one line of measured figures to stderr when the environment
 * variable env is set to 1 (e.g. TB_JOINT_VERBOSE=1). */
void tbt_report(const char* env, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

#define TB_TEST_MAIN(suite_fn)                \
  int main(void) {                            \
    SRunner* sr = srunner_create(suite_fn()); \
    srunner_run_all(sr, CK_NORMAL);           \
    int failed = srunner_ntests_failed(sr);   \
    srunner_free(sr);                         \
    return failed == 0 ? 0 : 1;               \
  }

#endif
