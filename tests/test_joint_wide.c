/* Revolute joints solved four at a time (src/joint_wide.c): in loops (so
 * not in a joint tree, the point solved there too) and with springs, motors
 * and limits, against closed forms and against the same joints solved one
 * at a time (joint.c; the world's internal joints_one_at_a_time switch, the
 * tests' reference). 60 Hz, 4 substeps, the default world tuning. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "../src/world.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define DT (1.0f / 60.0f)
#define SUBSTEPS 4

/* Set TB_JOINT_VERBOSE=1 to print the measured figures. */
#define report(...) tbt_report("TB_JOINT_VERBOSE", __VA_ARGS__)

static void step(tb_world_id w, int n) {
  for (int i = 0; i < n; ++i) ck_assert_int_eq(tb_world_step(w, DT, SUBSTEPS), TB_OK);
}

static tb_body_id disc(tb_world_id w, tb_body_type type, tb_vec2 pos, float radius) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = pos;
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, radius};
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  return b;
}

/* Solve the world's joints one at a time (the reference) or not. */
static void one_at_a_time(tb_world_id id, bool on) {
  tb_world* w = tb_world_get(id, "test");
  ck_assert_ptr_nonnull(w);
  w->joints_one_at_a_time = on;
}

/* A revolute joint at the world point p; with rows: a 5 Hz spring, a friction
 * motor of 0.05 N m and limits at +-0.5 rad (as the ragdolls of rain). */
static tb_joint_id pin(tb_world_id w, tb_body_id a, tb_body_id b, tb_vec2 p, bool rows) {
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = a;
  jd.body_b = b;
  jd.local_anchor_a = tb_body_get_local_point(a, p);
  jd.local_anchor_b = tb_body_get_local_point(b, p);
  jd.enable_spring = rows;
  jd.hertz = 5.0f;
  jd.damping_ratio = 0.5f;
  jd.enable_motor = rows;
  jd.max_motor_torque = 0.05f;
  jd.enable_limit = rows;
  jd.lower_angle = -0.5f;
  jd.upper_angle = 0.5f;
  tb_joint_id j = tb_create_revolute_joint(w, &jd);
  ck_assert(!tb_joint_id_is_null(j));
  return j;
}

static double joint_gap(tb_joint_id j) {
  tb_vec2 pa = tb_body_get_world_point(tb_joint_get_body_a(j), tb_joint_get_local_anchor_a(j));
  tb_vec2 pb = tb_body_get_world_point(tb_joint_get_body_b(j), tb_joint_get_local_anchor_b(j));
  return hypot((double)pb.x - pa.x, (double)pb.y - pa.y);
}

/* A ring of N discs at radius R, pinned to each other at the chords'
 * midpoints, spinning rigidly at OMEGA in zero gravity. */
#define N 8
#define R 1.0
#define OMEGA 2.0

typedef struct ring {
  tb_world_id w;
  tb_body_id body[N];
  tb_joint_id joint[N];
} ring;

static ring make_ring(bool reference, bool warm) {
  ring r;
  r.w = tbt_world(0.0f, 0.0f);
  one_at_a_time(r.w, reference);
  tb_world_enable_warm_starting(r.w, warm);
  for (int i = 0; i < N; ++i) {
    double a = 2.0 * PI * i / N;
    tb_vec2 p = {(float)(R * cos(a)), (float)(R * sin(a))};
    r.body[i] = disc(r.w, TB_DYNAMIC_BODY, p, 0.1f);
    tb_body_set_linear_velocity(r.body[i], (tb_vec2){(float)(-OMEGA * p.y), (float)(OMEGA * p.x)});
    tb_body_set_angular_velocity(r.body[i], (float)OMEGA);
  }
  for (int i = 0; i < N; ++i) {
    tb_vec2 pa = tb_body_get_position(r.body[i]), pb = tb_body_get_position(r.body[(i + 1) % N]);
    r.joint[i] = pin(r.w, r.body[i], r.body[(i + 1) % N], (tb_vec2){0.5f * (pa.x + pb.x), 0.5f * (pa.y + pb.y)}, false);
  }
  return r;
}

/* Angular momentum about the origin: sum m (x cross v) + I w. */
static double angular_momentum(const ring* r) {
  double l = 0.0;
  for (int i = 0; i < N; ++i) {
    tb_vec2 c = tb_body_get_world_center(r->body[i]), v = tb_body_get_linear_velocity(r->body[i]);
    l += tb_body_get_mass(r->body[i]) * ((double)c.x * v.y - (double)c.y * v.x) +
         tb_body_get_rotational_inertia(r->body[i]) * tb_body_get_angular_velocity(r->body[i]);
  }
  return l;
}

/* What one run of the ring measures over 2 s. */
typedef struct ring_errors {
  double gap;     /* the largest joint gap (m) */
  double tension; /* the largest relative error of a joint's force, after the first 10 steps */
  double spin;    /* the largest relative error of a disc's angular velocity */
  double l;       /* the relative change of the angular momentum */
} ring_errors;

static ring_errors run_ring(bool reference, bool warm) {
  ring r = make_ring(reference, warm);
  double m = tb_body_get_mass(r.body[0]);
  double tension = m * OMEGA * OMEGA * R / (2.0 * sin(PI / N));
  double l0 = angular_momentum(&r);
  ring_errors e = {0.0, 0.0, 0.0, 0.0};
  for (int s = 0; s < 120; ++s) {
    step(r.w, 1);
    for (int i = 0; i < N; ++i) {
      e.gap = fmax(e.gap, joint_gap(r.joint[i]));
      tb_vec2 f = tb_joint_get_constraint_force(r.joint[i]);
      if (s >= 10) e.tension = fmax(e.tension, fabs(hypot(f.x, f.y) - tension) / tension);
      e.spin = fmax(e.spin, fabs(tb_body_get_angular_velocity(r.body[i]) - OMEGA) / OMEGA);
    }
  }
  e.l = fabs(angular_momentum(&r) - l0) / l0;
  report("ring (%s, warm %d): gap %.3g m, tension off by %.3g, spin off by %.3g, L off by %.3g",
         reference ? "one at a time" : "wide", warm, e.gap, e.tension, e.spin, e.l);
  tb_destroy_world(r.w);
  return e;
}

/* The ring turns as a rigid body: each disc moves on its circle, held by the
 * tension T of the two joints beside it, whose pulls along the chords add up
 * to the centripetal force, 2 T sin(pi / N) = m OMEGA^2 R (0.164 N here).
 * Bounds from the physics:
 * - gap: a soft joint (joint_hertz 60) stretches T / (m_eff (2 pi 60)^2),
 *   m_eff = m / 2, by 7.4e-5 m; the one relax pass over a loop leaves up to
 *   twice that: 3e-4 m.
 * - angular momentum: the joints' forces are internal, but the gap puts the
 *   two ends of each impulse that far apart, a torque of at most gap T per
 *   joint: over 2 s, N 3e-4 m T 2 s against L = N (m R^2 + I) OMEGA is
 *   1.6e-3 of L.
 * - tension to 1% once warm-started (the first steps build it up).
 * These with warm starting (the default); without it every substep builds
 * the tension up again from zero, and the gap is 5e-4 m either way.
 * - And the wide solve at least as good as the one-at-a-time one (within 10%,
 *   or 1e-6) on each of the four. */
START_TEST(spinning_ring_keeps_its_momentum_and_tension) {
  for (int warm = 1; warm >= 0; --warm) {
    ring_errors wide = run_ring(false, warm), one = run_ring(true, warm);
    if (warm) {
      ck_assert_msg(wide.gap < 3e-4, "gap %g m", wide.gap);
      ck_assert_msg(wide.l < 1.6e-3, "angular momentum off by %g", wide.l);
      ck_assert_msg(wide.tension < 0.01, "tension off by %g", wide.tension);
    }
    ck_assert_msg(wide.gap <= 1.1 * one.gap + 1e-6, "gap %g m against %g m", wide.gap, one.gap);
    ck_assert_msg(wide.l <= 1.1 * one.l + 1e-6, "angular momentum off by %g against %g", wide.l, one.l);
    ck_assert_msg(wide.spin <= 1.1 * one.spin + 1e-6, "spin off by %g against %g", wide.spin, one.spin);
    ck_assert_msg(wide.tension <= 1.1 * one.tension + 1e-6, "tension off by %g against %g", wide.tension, one.tension);
  }
}
END_TEST

/* A 10 x 10 grid of discs 1 m apart, each pinned to its right and lower
 * neighbour at the midpoint (loops everywhere, so Gauss-Seidel), hanging from
 * three static discs in its top row, as Box2D v3's joint_grid benchmark at a
 * tenth of the size. It falls from rest and swings; the wide and the
 * one-at-a-time solve must hang it alike: the two grids' discs within 2 cm
 * of each other after 1 s (the Gauss-Seidel order differs, and so does the
 * round-off; a joint drifts by up to a few mm under the grid's weight), and
 * no joint drifts further apart than in the reference by more than 1 mm. */
#define G 10
typedef struct grid {
  tb_world_id w;
  tb_body_id body[G * G];
  tb_joint_id joint[2 * G * G];
  int joints;
} grid;

static grid make_grid(bool reference, bool rows) {
  grid g;
  g.w = tbt_world(0.0f, -10.0f);
  one_at_a_time(g.w, reference);
  g.joints = 0;
  for (int k = 0; k < G; ++k)
    for (int i = 0; i < G; ++i) {
      bool fixed = i == 0 && k >= G / 2 - 1 && k <= G / 2 + 1;
      tb_body_id b = disc(g.w, fixed ? TB_STATIC_BODY : TB_DYNAMIC_BODY, (tb_vec2){(float)k, (float)-i}, 0.4f);
      g.body[k * G + i] = b;
      if (i > 0) g.joint[g.joints++] = pin(g.w, g.body[k * G + i - 1], b, (tb_vec2){(float)k, -i + 0.5f}, rows);
      if (k > 0) g.joint[g.joints++] = pin(g.w, g.body[(k - 1) * G + i], b, (tb_vec2){k - 0.5f, (float)-i}, rows);
    }
  return g;
}

START_TEST(hanging_grid_matches_the_one_at_a_time_solve) {
  for (int rows = 0; rows < 2; ++rows) {
    grid wide = make_grid(false, rows), one = make_grid(true, rows);
    step(wide.w, 60);
    step(one.w, 60);
    double apart = 0.0, gap_wide = 0.0, gap_one = 0.0;
    for (int i = 0; i < G * G; ++i) {
      tb_vec2 a = tb_body_get_position(wide.body[i]), b = tb_body_get_position(one.body[i]);
      ck_assert(isfinite(a.x) && isfinite(a.y));
      apart = fmax(apart, hypot((double)a.x - b.x, (double)a.y - b.y));
    }
    for (int j = 0; j < wide.joints; ++j) {
      gap_wide = fmax(gap_wide, joint_gap(wide.joint[j]));
      gap_one = fmax(gap_one, joint_gap(one.joint[j]));
    }
    report("grid (rows %d): %.3g m apart; largest joint gap %.3g m wide, %.3g m one at a time", rows, apart, gap_wide,
           gap_one);
    ck_assert_msg(apart < 0.02, "%g m apart", apart);
    ck_assert_msg(gap_wide < gap_one + 1e-3, "gap %g m against %g m", gap_wide, gap_one);
    tb_destroy_world(wide.w);
    tb_destroy_world(one.w);
  }
}
END_TEST

/* A chain of ten discs (0.5 kg each, radius 0.2 m, 1 m apart) hanging from a
 * static pin, started `tilt` rad from the vertical: every joint is a point
 * and the chain a joint tree, which solves the joints whole; they take no
 * lane of the wide blocks and no one-at-a-time pass (solver.c:
 * set_apart_tree_joints), only their warm start and store. */
#define LINKS 10
typedef struct chain {
  tb_world_id w;
  tb_body_id body[LINKS];
  tb_joint_id joint[LINKS];
} chain;

static chain make_chain(bool reference, bool warm, float tilt) {
  chain c;
  c.w = tbt_world(0.0f, -10.0f);
  one_at_a_time(c.w, reference);
  ck_assert_int_eq(tb_world_enable_warm_starting(c.w, warm), TB_OK);
  ck_assert_int_eq(tb_world_enable_sleeping(c.w, false), TB_OK); /* (the hanging chain would sleep) */
  tb_body_id top = disc(c.w, TB_STATIC_BODY, (tb_vec2){0.0f, 0.0f}, 0.1f);
  tb_vec2 down = {sinf(tilt), -cosf(tilt)};
  for (int i = 0; i < LINKS; ++i) {
    c.body[i] = disc(c.w, TB_DYNAMIC_BODY, (tb_vec2){(float)(i + 1) * down.x, (float)(i + 1) * down.y}, 0.2f);
    tb_body_set_mass_data(c.body[i], (tb_mass_data){0.5f, {0.0f, 0.0f}, 0.01f});
    c.joint[i] = pin(c.w, i == 0 ? top : c.body[i - 1], c.body[i],
                     (tb_vec2){((float)i + 0.5f) * down.x, ((float)i + 0.5f) * down.y}, false);
  }
  return c;
}

/* At rest, the top joint carries the whole chain (5 kg: 50 N) and the bottom
 * one its last disc (5 N), with warm starting and without (each substep from
 * zero then), as with the joints solved one at a time. */
START_TEST(tree_joints_carry_the_chain) {
  for (int reference = 0; reference < 2; ++reference)
    for (int warm = 0; warm < 2; ++warm) {
      chain c = make_chain(reference, warm, 0.0f);
      step(c.w, 60);
      tb_world* w = tb_world_get(c.w, "test");
      ck_assert_int_eq(w->tree_joint_count, (reference ? 0 : LINKS));
      double top = tb_joint_get_constraint_force(c.joint[0]).y;
      double bottom = tb_joint_get_constraint_force(c.joint[LINKS - 1]).y;
      report("chain (reference %d, warm %d): top %.5f N, bottom %.5f N", reference, warm, top, bottom);
      ck_assert_msg(fabs(top - 50.0) < 0.5 && fabs(bottom - 5.0) < 0.05, "top %g N, bottom %g N", top, bottom);
      tb_destroy_world(c.w);
    }
}
END_TEST

/* Swinging from 0.5 rad for a second, the chain follows the one-at-a-time
 * solve's (which warm-starts the same impulses through joint.c, in another
 * order: the sums round differently, nothing else). */
START_TEST(swinging_tree_chain_matches_the_one_at_a_time_solve) {
  chain set_apart = make_chain(false, true, 0.5f), one = make_chain(true, true, 0.5f);
  step(set_apart.w, 60);
  step(one.w, 60);
  double apart = 0.0;
  for (int i = 0; i < LINKS; ++i) {
    tb_vec2 a = tb_body_get_position(set_apart.body[i]), b = tb_body_get_position(one.body[i]);
    ck_assert(isfinite(a.x) && isfinite(a.y));
    apart = fmax(apart, hypot((double)a.x - b.x, (double)a.y - b.y));
  }
  report("swinging chain: %.3g m apart", apart);
  ck_assert_msg(apart < 1e-4, "%g m apart", apart);
  tb_destroy_world(set_apart.w);
  tb_destroy_world(one.w);
}
END_TEST

static Suite* joint_wide_suite(void) {
  Suite* s = suite_create("joint_wide");
  TCase* tc = tcase_create("physics");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, spinning_ring_keeps_its_momentum_and_tension);
  tcase_add_test(tc, hanging_grid_matches_the_one_at_a_time_solve);
  tcase_add_test(tc, tree_joints_carry_the_chain);
  tcase_add_test(tc, swinging_tree_chain_matches_the_one_at_a_time_solve);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(joint_wide_suite)
