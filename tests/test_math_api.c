/* The public math helpers (include/tumble_math.h) and handle helpers (issue
 * 24): bit-identical to the engine's own (src/math_internal.h) on many
 * inputs, special values included; rotations, transforms and boxes against
 * closed forms; the implicit spring-damper step's stability and decay; handle
 * equality and packing. */
#include <float.h>
#include <stdint.h>
#include <string.h>

#include "../src/math_internal.h"
#include "test_util.h"
#include "tumble_math.h"

#define PI_D 3.14159265358979323846

/* ---- bit-identical to the engine ------------------------------------------------ */

static bool same_f(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }
static bool same_v(tb_vec2 a, tb_vec2 b) { return same_f(a.x, b.x) && same_f(a.y, b.y); }

/* Inputs of every magnitude the engine meets and some it refuses: the same
 * expression in the same order gives the same bits whatever the value. */
static float any_float(unsigned* rng) {
  static const float special[] = {0.0f,     -0.0f,    1.0f,      -1.0f, FLT_MIN, -FLT_MIN, 1e-40f,        FLT_MAX,
                                  -FLT_MAX, INFINITY, -INFINITY, NAN,   1e-20f,  1e20f,    TB_MAX_LENGTH, 3.0e-21f};
  float pick = tbt_rand(rng, 0.0f, 1.0f);
  if (pick < 0.1f) {
    int k = (int)tbt_rand(rng, 0.0f, 15.99f);
    return special[k < 0 ? 0 : k > 15 ? 15 : k];
  }
  float e = tbt_rand(rng, -30.0f, 30.0f); /* magnitudes from 1e-30 to 1e30 */
  float m = tbt_rand(rng, -1.0f, 1.0f);
  return m * powf(10.0f, pick < 0.6f ? e / 10.0f : e);
}

static tb_vec2 any_vec(unsigned* rng) { return (tb_vec2){any_float(rng), any_float(rng)}; }

START_TEST(public_math_matches_the_engine_bit_for_bit) {
  unsigned rng = 2024u;
  int mismatches = 0, first = -1;
  for (int i = 0; i < 200000; ++i) {
    tb_vec2 a = any_vec(&rng), b = any_vec(&rng);
    float s = any_float(&rng);
    float angle = tbt_rand(&rng, 0.0f, 1.0f) < 0.9f ? tbt_rand(&rng, -10.0f, 10.0f) : any_float(&rng);
    tb_rot q = tb_make_rot(angle);
    tb_transform xf = {a, q};
    bool ok = same_v(tb_vec2_add(a, b), tb_add(a, b)) && same_v(tb_vec2_sub(a, b), tb_sub(a, b)) &&
              same_v(tb_vec2_neg(a), tb_neg(a)) && same_v(tb_vec2_scale(s, a), tb_scale(s, a)) &&
              same_v(tb_vec2_mul_add(a, s, b), tb_mul_add(a, s, b)) && same_f(tb_vec2_dot(a, b), tb_dot(a, b)) &&
              same_f(tb_vec2_cross(a, b), tb_cross(a, b)) && same_v(tb_vec2_cross_sv(s, a), tb_cross_sv(s, a)) &&
              same_v(tb_vec2_cross_vs(a, s), tb_cross_vs(a, s)) && same_v(tb_vec2_left_perp(a), tb_left_perp(a)) &&
              same_v(tb_vec2_right_perp(a), tb_right_perp(a)) && same_f(tb_vec2_length_squared(a), tb_length_sq(a)) &&
              same_f(tb_vec2_length(a), tb_length(a)) && same_f(tb_vec2_distance_squared(a, b), tb_distance_sq(a, b)) &&
              same_v(tb_vec2_normalize(a), tb_normalize(a)) && same_v(tb_vec2_lerp(a, b, s), tb_lerp(a, b, s)) &&
              same_v(tb_vec2_min(a, b), tb_vmin(a, b)) && same_v(tb_vec2_max(a, b), tb_vmax(a, b)) &&
              same_f(tb_rot_from_angle(angle).c, q.c) && same_f(tb_rot_from_angle(angle).s, q.s) &&
              same_v(tb_rot_rotate(q, b), tb_rotate(q, b)) && same_v(tb_rot_inv_rotate(q, b), tb_inv_rotate(q, b)) &&
              same_v(tb_transform_world_point(xf, b), tb_transform_point(xf, b)) &&
              same_v(tb_transform_local_point(xf, b), tb_inv_transform_point(xf, b)) &&
              tb_vec2_is_valid(a) == tb_point_ok(a);
    if (!ok) {
      mismatches += 1;
      if (first < 0) first = i;
    }
  }
  ck_assert_msg(mismatches == 0, "%d inputs differ from the engine's math, the first at %d", mismatches, first);
}
END_TEST

/* ---- rotations and transforms --------------------------------------------------- */

static int ulps_apart(float a, float b) {
  if (a == b) return 0;
  int32_t x, y;
  memcpy(&x, &a, sizeof x);
  memcpy(&y, &b, sizeof y);
  if (x < 0) x = INT32_MIN - x; /* sign-magnitude to a monotone integer line */
  if (y < 0) y = INT32_MIN - y;
  int64_t d = (int64_t)x - (int64_t)y;
  return d > 1000000 || d < -1000000 ? 1000000 : (int)(d < 0 ? -d : d);
}

/* tb_rot_from_angle computes cos and sin itself (the engine turns every body
 * angle into a rotation with it), so that C libraries' rounding cannot make
 * two platforms' worlds differ. Against the correctly rounded values (the C
 * library's double cos and sin, rounded to float): never more than one unit
 * in the last place apart, and rarely that. The series' own error is at most
 * 7e-12 (relative, at |r| = pi/4, tumble_math.h), which misrounds a value
 * only when the true value lies that close to the midpoint between two
 * floats, at most 2 x 7e-12 / 6e-8 = 2.3e-4 of them (measured: 6e-6). */
START_TEST(rotation_from_angle_is_correctly_rounded_but_rarely) {
  unsigned rng = 99u;
  long values = 0, off = 0;
  int worst = 0;
  for (int i = 0; i < 400000; ++i) {
    /* the angles bodies have (a few turns) and all the engine accepts */
    float range = i % 2 == 0 ? (float)(8.0 * PI_D) : TB_MAX_ANGLE;
    float x = tbt_rand(&rng, -range, range);
    tb_rot q = tb_rot_from_angle(x);
    int dc = ulps_apart(q.c, (float)cos((double)x)), ds = ulps_apart(q.s, (float)sin((double)x));
    worst = dc > worst ? dc : worst;
    worst = ds > worst ? ds : worst;
    off += (dc != 0) + (ds != 0);
    values += 2;
  }
  ck_assert_msg(worst <= 1, "%d ulp from the correctly rounded value", worst);
  ck_assert_msg((double)off <= 2.3e-4 * (double)values, "%ld of %ld values misrounded", off, values);

  /* the bits themselves, the same on every platform: these are the correctly
   * rounded values */
  static const float pinned[][3] = {
      {0.5f, 0x1.c1528p-1f, 0x1.eaee88p-2f},           {1.0f, 0x1.14a28p-1f, 0x1.aed548p-1f},
      {-2.0f, -0x1.aa2266p-2f, -0x1.d18f6ep-1f},       {3.0f, -0x1.fae04cp-1f, 0x1.210386p-3f},
      {100.0f, 0x1.b981dcp-1f, -0x1.03425cp-1f},       {-1234.5f, -0x1.fa8f2cp-1f, -0x1.29c532p-3f},
      {123456.703f, -0x1.17f18ap-5f, -0x1.ffb372p-1f}, {1.0e6f, 0x1.df9dfap-1f, -0x1.6664b2p-2f}};
  for (size_t k = 0; k < sizeof pinned / sizeof pinned[0]; ++k) {
    tb_rot q = tb_rot_from_angle(pinned[k][0]);
    ck_assert_msg(same_f(q.c, pinned[k][1]) && same_f(q.s, pinned[k][2]), "angle %g: (%a, %a)", (double)pinned[k][0],
                  (double)q.c, (double)q.s);
  }

  /* zeros keep the sine's sign, as the C library's do; no angle, no rotation */
  ck_assert(same_f(tb_rot_from_angle(-0.0f).s, -0.0f) && same_f(tb_rot_from_angle(0.0f).s, 0.0f));
  ck_assert(tb_rot_from_angle(-0.0f).c == 1.0f);
  const float none[] = {NAN, INFINITY, -INFINITY};
  for (int k = 0; k < 3; ++k) ck_assert(isnan(tb_rot_from_angle(none[k]).c) && isnan(tb_rot_from_angle(none[k]).s));

  /* beyond 2^20 rad (body angles after hours of spinning) the exact fold
   * into [0, 2 pi) by the double nearest 2 pi errs by the angle / 2 pi times
   * 2.45e-16: under 2e-7 rad up to 2^32 rad, plus the float's half unit */
  for (int i = 0; i < 20000; ++i) {
    float x = tbt_rand(&rng, -1.0f, 1.0f) * powf(2.0f, tbt_rand(&rng, 20.0f, 32.0f));
    tb_rot q = tb_rot_from_angle(x);
    ck_assert_near(q.c, cos((double)x), 2e-7 + 6e-8);
    ck_assert_near(q.s, sin((double)x), 2e-7 + 6e-8);
  }
  /* any finite angle, up to FLT_MAX, gives a rotation */
  const float huge[] = {FLT_MAX, -FLT_MAX, 1e30f, 0x1p100f};
  for (int k = 0; k < 4; ++k) ck_assert(tb_rot_is_valid(tb_rot_from_angle(huge[k])));
}
END_TEST

/* Rotations of unit length multiply with about 2 ulp of rounding per
 * component; 1e-6 covers a few products of values <= 1. */
#define ROT_TOL 1e-6

START_TEST(rotations_against_closed_forms) {
  unsigned rng = 7u;
  for (int i = 0; i < 1000; ++i) {
    float a = tbt_rand(&rng, -3.0f, 3.0f), b = tbt_rand(&rng, -3.0f, 3.0f);
    tb_rot qa = tb_rot_from_angle(a), qb = tb_rot_from_angle(b);
    tb_rot ab = tb_rot_mul(qa, qb), ba = tb_rot_inv_mul(qa, qb);
    ck_assert_near(ab.c, cos((double)a + b), ROT_TOL);
    ck_assert_near(ab.s, sin((double)a + b), ROT_TOL);
    ck_assert_near(ba.c, cos((double)b - a), ROT_TOL);
    ck_assert_near(ba.s, sin((double)b - a), ROT_TOL);
    /* the angle back, within atan2f's rounding (a few ulp of pi) */
    ck_assert_near(tb_rot_get_angle(qa), a, 2e-6);
    /* rotate then unrotate is the identity to rounding */
    tb_vec2 v = {tbt_rand(&rng, -5, 5), tbt_rand(&rng, -5, 5)};
    tb_vec2 back = tb_rot_inv_rotate(qa, tb_rot_rotate(qa, v));
    ck_assert_near(back.x, v.x, 5 * ROT_TOL);
    ck_assert_near(back.y, v.y, 5 * ROT_TOL);
    ck_assert(tb_rot_is_valid(qa));
  }
  /* nlerp: the ends, and the middle of a quarter turn is the eighth turn */
  tb_rot q0 = tb_rot_identity(), q1 = tb_rot_from_angle((float)(PI_D / 2.0));
  tb_rot m = tb_rot_nlerp(q0, q1, 0.5f);
  ck_assert_near(tb_rot_get_angle(m), PI_D / 4.0, 2e-6);
  ck_assert_near(tb_rot_nlerp(q0, q1, 0.0f).c, 1.0, 0.0);
  ck_assert_near(tb_rot_nlerp(q0, q1, 1.0f).s, 1.0, ROT_TOL);
  /* between 170 and -170 degrees it goes the short way, through 180 */
  tb_rot a = tb_rot_from_angle((float)(170.0 * PI_D / 180.0)), b = tb_rot_from_angle((float)(-170.0 * PI_D / 180.0));
  ck_assert_near(fabs(tb_rot_get_angle(tb_rot_nlerp(a, b, 0.5f))), PI_D, 2e-6);
  /* opposite rotations: no shorter way, and never a zero (invalid) rotation */
  tb_rot opposite = tb_rot_nlerp(q0, (tb_rot){-1.0f, 0.0f}, 0.5f);
  ck_assert(tb_rot_is_valid(opposite));
  /* normalize: a scaled rotation back to unit; zero to the identity */
  tb_rot n = tb_rot_normalize((tb_rot){3.0f, 4.0f});
  ck_assert_near(n.c, 0.6, ROT_TOL);
  ck_assert_near(n.s, 0.8, ROT_TOL);
  ck_assert(tb_rot_normalize((tb_rot){0.0f, 0.0f}).c == 1.0f);
  ck_assert(!tb_rot_is_valid((tb_rot){1.1f, 0.0f}) && !tb_rot_is_valid((tb_rot){NAN, 0.0f}));
}
END_TEST

START_TEST(transforms_compose_and_invert) {
  unsigned rng = 99u;
  for (int i = 0; i < 1000; ++i) {
    tb_transform a = {{tbt_rand(&rng, -10, 10), tbt_rand(&rng, -10, 10)}, tb_rot_from_angle(tbt_rand(&rng, -3, 3))};
    tb_transform b = {{tbt_rand(&rng, -10, 10), tbt_rand(&rng, -10, 10)}, tb_rot_from_angle(tbt_rand(&rng, -3, 3))};
    tb_vec2 p = {tbt_rand(&rng, -10, 10), tbt_rand(&rng, -10, 10)};
    /* (a b) p = a (b p); coordinates up to about 30 m: 1e-5 is ~8 ulp there */
    tb_vec2 lhs = tb_transform_world_point(tb_transform_mul(a, b), p);
    tb_vec2 rhs = tb_transform_world_point(a, tb_transform_world_point(b, p));
    ck_assert_near(lhs.x, rhs.x, 1e-5);
    ck_assert_near(lhs.y, rhs.y, 1e-5);
    /* a^-1 (a b) = b */
    tb_transform back = tb_transform_inv_mul(a, tb_transform_mul(a, b));
    ck_assert_near(back.p.x, b.p.x, 1e-5);
    ck_assert_near(back.p.y, b.p.y, 1e-5);
    ck_assert_near(back.q.c, b.q.c, ROT_TOL);
    ck_assert_near(back.q.s, b.q.s, ROT_TOL);
    /* local and world points are inverses */
    tb_vec2 round = tb_transform_local_point(a, tb_transform_world_point(a, p));
    ck_assert_near(round.x, p.x, 1e-5);
    ck_assert_near(round.y, p.y, 1e-5);
  }
  /* a quarter turn about (1, 2) takes local (1, 0) to (1, 3) */
  tb_transform q = {{1, 2}, tb_rot_from_angle((float)(PI_D / 2.0))};
  tb_vec2 w = tb_transform_world_point(q, (tb_vec2){1, 0});
  ck_assert_near(w.x, 1.0, ROT_TOL);
  ck_assert_near(w.y, 3.0, ROT_TOL);
  tb_transform id = tb_transform_identity();
  tb_vec2 same = tb_transform_world_point(id, (tb_vec2){5, -6});
  ck_assert(same.x == 5.0f && same.y == -6.0f);
}
END_TEST

START_TEST(vectors_and_boxes) {
  tb_vec2 a = tb_vec2_make(3, 4), b = tb_vec2_make(-1, 2);
  ck_assert(tb_vec2_length(a) == 5.0f && tb_vec2_length_squared(a) == 25.0f);
  ck_assert(tb_vec2_distance(a, b) == sqrtf(16.0f + 4.0f) && tb_vec2_distance_squared(a, b) == 20.0f);
  ck_assert(tb_vec2_dot(a, b) == 5.0f && tb_vec2_cross(a, b) == 10.0f);
  tb_vec2 n = tb_vec2_normalize(a);
  ck_assert_near(n.x, 0.6, 1e-7);
  ck_assert_near(n.y, 0.8, 1e-7);
  tb_vec2 z = tb_vec2_normalize(tb_vec2_make(0, 0));
  ck_assert(z.x == 0.0f && z.y == 0.0f);
  z = tb_vec2_normalize(tb_vec2_make(1e-30f, 0));
  ck_assert(z.x == 0.0f && z.y == 0.0f);
  /* w x r: a body turning at 2 rad/s, point at (1, 0): moves at (0, 2) */
  tb_vec2 v = tb_vec2_cross_sv(2.0f, tb_vec2_make(1, 0));
  ck_assert(v.x == 0.0f && v.y == 2.0f);
  v = tb_vec2_cross_vs(tb_vec2_make(0, 1), 3.0f);
  ck_assert(v.x == 3.0f && v.y == 0.0f);
  v = tb_vec2_mul_sub(a, 2.0f, b);
  ck_assert(v.x == 5.0f && v.y == 0.0f);
  v = tb_vec2_lerp(a, b, 0.25f);
  ck_assert(v.x == 2.0f && v.y == 3.5f);
  ck_assert(!tb_vec2_is_valid(tb_vec2_make(NAN, 0)) && !tb_vec2_is_valid(tb_vec2_make(0, 2e7f)));

  tb_aabb box = {{0, 0}, {2, 1}}, other = {{1.5f, 0.5f}, {4, 3}}, far = {{2.5f, 0}, {3, 1}};
  tb_aabb u = tb_aabb_union(box, other);
  ck_assert(u.lower.x == 0 && u.lower.y == 0 && u.upper.x == 4 && u.upper.y == 3);
  ck_assert(tb_aabb_contains(u, box) && tb_aabb_contains(u, other) && !tb_aabb_contains(box, u));
  ck_assert(tb_aabb_overlaps(box, other) && !tb_aabb_overlaps(box, far));
  ck_assert(tb_aabb_overlaps(box, (tb_aabb){{2, 1}, {3, 3}})); /* touching at a corner counts */
  ck_assert(tb_aabb_contains_point(box, (tb_vec2){2, 0.5f}) && !tb_aabb_contains_point(box, (tb_vec2){2.01f, 0.5f}));
  tb_vec2 c = tb_aabb_center(other), e = tb_aabb_extents(other);
  ck_assert(c.x == 2.75f && c.y == 1.75f && e.x == 1.25f && e.y == 1.25f);
  ck_assert(tb_aabb_is_valid(box) && !tb_aabb_is_valid((tb_aabb){{1, 0}, {0, 1}}) &&
            !tb_aabb_is_valid((tb_aabb){{0, 0}, {INFINITY, 1}}));
}
END_TEST

/* ---- the spring-damper step ------------------------------------------------------ */

START_TEST(spring_damper_step_is_implicit_and_stable) {
  /* it solves the implicit equations: v1 = v + h (-k x1 - c v1), x1 = x + h v1
   * (residual within float rounding of the terms, ~1e-7 of their size) */
  const float k = 400.0f, c = 5.0f, h = 0.05f, x = 0.7f, v = -2.0f;
  float v1 = tb_spring_damper_velocity(k, c, x, v, h);
  float x1 = x + h * v1;
  double residual = (double)v1 - ((double)v + h * (-(double)k * x1 - (double)c * v1));
  ck_assert_near(residual, 0.0, 1e-5);
  /* a stiff spring at a long step (h w = 333, where an explicit step
   * explodes): the energy v^2 + k x^2 never grows */
  const float stiff = 1e8f, step = 1.0f / 30.0f;
  float xs = 1.0f, vs = 0.0f;
  double energy = (double)vs * vs + (double)stiff * xs * xs;
  for (int i = 0; i < 1000; ++i) {
    vs = tb_spring_damper_velocity(stiff, 0.0f, xs, vs, step);
    xs += step * vs;
    double now = (double)vs * vs + (double)stiff * xs * xs;
    ck_assert_msg(now <= energy * (1.0 + 1e-6), "step %d: energy %g after %g", i, now, energy);
    energy = now;
  }
  /* an undamped 1 Hz spring over one period at h = 1 ms: back at x = 1,
   * shrunk by the scheme's damping (1 + h^2 k)^(-N/2) = 0.9805; the phase lag
   * N ((hw)^3 / 3) = 8e-5 rad changes cos by 3e-9, float rounding over 1000
   * steps adds < 1e-4: 1e-3 */
  const double w = 2.0 * PI_D;
  float xo = 1.0f, vo = 0.0f;
  for (int i = 0; i < 1000; ++i) {
    vo = tb_spring_damper_velocity((float)(w * w), 0.0f, xo, vo, 1e-3f);
    xo += 1e-3f * vo;
  }
  ck_assert_near(xo, pow(1.0 + 1e-6 * w * w, -500.0), 1e-3);
  /* critically damped (c = 2 w) from rest at x = 1: it returns to 0 without
   * crossing it, as the exact motion (1 + w t) e^(-w t) does */
  float xd = 1.0f, vd = 0.0f;
  for (int i = 0; i < 600; ++i) {
    vd = tb_spring_damper_velocity((float)(w * w), (float)(2.0 * w), xd, vd, 1.0f / 60.0f);
    xd += vd / 60.0f;
    ck_assert_msg(xd >= 0.0f, "step %d crossed zero: %g", i, (double)xd);
  }
  ck_assert_near(xd, 0.0, 1e-6);
}
END_TEST

/* ---- handles ---------------------------------------------------------------------- */

START_TEST(handles_compare_and_pack) {
  tb_world_id w = tbt_world(0, -10);
  tb_body_id b = tbt_box_body(w, 0, 0, 0.5f, 0.5f), b2 = tbt_box_body(w, 2, 0, 0.5f, 0.5f);
  tb_shape_id s;
  tb_body_get_shapes(b, &s, 1);
  ck_assert(tb_world_id_equal(w, tb_world_id_from_u64(tb_world_id_to_u64(w))));
  ck_assert(tb_body_id_equal(b, tb_body_id_from_u64(tb_body_id_to_u64(b))));
  ck_assert(tb_shape_id_equal(s, tb_shape_id_from_u64(tb_shape_id_to_u64(s))));
  ck_assert(!tb_body_id_equal(b, b2) && tb_body_id_to_u64(b) != tb_body_id_to_u64(b2));
  /* a handle that differs in its generation only is another handle */
  tb_body_id stale = b;
  stale.generation += 1;
  ck_assert(!tb_body_id_equal(b, stale) && tb_body_id_to_u64(b) != tb_body_id_to_u64(stale));
  /* the packed handle is the handle: it works once unpacked */
  ck_assert(tb_body_is_valid(tb_body_id_from_u64(tb_body_id_to_u64(b))));
  /* null packs to 0 and back */
  ck_assert(tb_joint_id_to_u64((tb_joint_id){0, 0, 0}) == 0 && tb_joint_id_is_null(tb_joint_id_from_u64(0)));
  ck_assert(tb_world_id_to_u64((tb_world_id){0, 0}) == 0 && tb_world_id_is_null(tb_world_id_from_u64(0)));
  /* extremes of every field survive */
  tb_chain_id c = {INT32_MAX, 0xffff, 0xffff};
  ck_assert(tb_chain_id_equal(c, tb_chain_id_from_u64(tb_chain_id_to_u64(c))));
  ck_assert(tb_chain_id_to_u64(c) == 0xffffffff7fffffffull);
  tb_joint_id j = {-5, 1, 2}; /* garbage handles (negative index) too */
  ck_assert(tb_joint_id_equal(j, tb_joint_id_from_u64(tb_joint_id_to_u64(j))));
  tb_world_id wx = {0xffff, 0xfffe};
  ck_assert(tb_world_id_equal(wx, tb_world_id_from_u64(tb_world_id_to_u64(wx))));
  tb_destroy_world(w);
}
END_TEST

static Suite* math_api_suite(void) {
  Suite* s = suite_create("math_api");
  TCase* tc = tcase_create("math_api");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, public_math_matches_the_engine_bit_for_bit);
  tcase_add_test(tc, rotation_from_angle_is_correctly_rounded_but_rarely);
  tcase_add_test(tc, rotations_against_closed_forms);
  tcase_add_test(tc, transforms_compose_and_invert);
  tcase_add_test(tc, vectors_and_boxes);
  tcase_add_test(tc, spring_damper_step_is_implicit_and_stable);
  tcase_add_test(tc, handles_compare_and_pack);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(math_api_suite)
