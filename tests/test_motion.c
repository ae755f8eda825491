/* Free motion against closed forms: the ODE dy/dt = (V, w, F/M, T/I). */
#include <string.h>

#include "test_util.h"

static tb_body_id dynamic_disc(tb_world_id w, tb_vec2 pos, tb_vec2 vel, float omega) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = pos;
  bd.linear_velocity = vel;
  bd.angular_velocity = omega;
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, 0.5f};
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  return b;
}

/* Semi-implicit Euler with k substeps of h: v_k = v0 + k h g and
 * x_k = x0 + k h v0 + h^2 g k (k + 1) / 2. With dyadic numbers (h = 1/256,
 * g = -8, v0 = (2, 16)) every float operation is exact, so equality is exact. */
START_TEST(discrete_projectile_is_exact) {
  tb_world_id w = tbt_world(0.0f, -8.0f);
  tb_world_set_integrator(w, TB_INTEGRATOR_SEMI_IMPLICIT_EULER);
  tb_body_id b = dynamic_disc(w, (tb_vec2){1.0f, 2.0f}, (tb_vec2){2.0f, 16.0f}, 0.0f);
  const int substeps = 4;
  const double h = 1.0 / 256.0;
  for (int step = 1; step <= 600; ++step) {
    ck_assert_int_eq(tb_world_step(w, 1.0f / 64.0f, substeps), TB_OK);
    double k = (double)step * substeps;
    tb_vec2 p = tb_body_get_position(b);
    tb_vec2 v = tb_body_get_linear_velocity(b);
    ck_assert_double_eq((double)p.x, 1.0 + k * h * 2.0);
    ck_assert_double_eq((double)p.y, 2.0 + k * h * 16.0 - 8.0 * h * h * k * (k + 1.0) / 2.0);
    ck_assert_double_eq((double)v.y, 16.0 - 8.0 * k * h);
  }
  tb_destroy_world(w);
}
END_TEST

/* The semi-implicit scheme lags the continuous parabola by g h t / 2; the
 * midpoint and RK4 schemes are exact for constant acceleration, up to float
 * rounding: 960 substeps each add h v to |x| <= 16 m, rounded by <= ulp/2 =
 * 4.8e-7 m, so 4.6e-4 m at worst. */
START_TEST(runge_kutta_projectile_matches_parabola) {
  const tb_integrator schemes[2] = {TB_INTEGRATOR_MIDPOINT, TB_INTEGRATOR_RK4};
  for (int s = 0; s < 2; ++s) {
    tb_world_id w = tbt_world(0.0f, -10.0f);
    ck_assert_int_eq(tb_world_set_integrator(w, schemes[s]), TB_OK);
    tb_body_id b = dynamic_disc(w, (tb_vec2){0.0f, 0.0f}, (tb_vec2){3.0f, 20.0f}, 0.0f);
    for (int i = 0; i < 240; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    double t = tb_world_get_time(w);
    ck_assert_near(tb_body_get_position(b).y, 20.0 * t - 5.0 * t * t, 4.6e-4);
    ck_assert_near(tb_body_get_position(b).x, 3.0 * t, 4.6e-4);
    tb_destroy_world(w);
  }
  /* and the semi-implicit error is the predicted g h t / 2 */
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_world_set_integrator(w, TB_INTEGRATOR_SEMI_IMPLICIT_EULER);
  tb_body_id b = dynamic_disc(w, (tb_vec2){0.0f, 0.0f}, (tb_vec2){3.0f, 20.0f}, 0.0f);
  for (int i = 0; i < 60; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  double t = 1.0, h = 1.0 / 240.0;
  /* 240 float additions at |y| <= 20: <= 240 * ulp/2 = 2.3e-4 of rounding */
  ck_assert_near(tb_body_get_position(b).y - (20.0 * t - 5.0 * t * t), -10.0 * h * t / 2.0, 2.3e-4);
  tb_destroy_world(w);
}
END_TEST

/* theta(t) = theta0 + w t. The float angle can hold theta only to half a
 * float step (ulp), so the best it can be after any step is the float nearest
 * theta: |error| <= ulp/2 (plus 1e-16 relative of the double sums it is
 * formed from, and of the world's double time). The bound checked is two ulps
 * of the exact angle at every step, for every integrator (the solver's Euler
 * and the free-flight midpoint and RK4), substep counts whose h = dt / n is
 * and is not a float (3, 7), and spins of either sign: 1e-6 rad at 6 rad,
 * 1.5e-5 rad at 100 rad. Summing h w into the float angle instead rounds once
 * per substep with a bias (a constant increment), 2e-5 rad after 2 s at 3 rad/s. */
static double float_ulp(double x) { return ldexp(1.0, ilogb(x) - 23); }

START_TEST(constant_spin) {
  const tb_integrator schemes[3] = {TB_INTEGRATOR_SEMI_IMPLICIT_EULER, TB_INTEGRATOR_MIDPOINT, TB_INTEGRATOR_RK4};
  const int substeps[6] = {1, 2, 3, 4, 7, 8};
  const struct {
    float theta0, omega, seconds;
  } spins[3] = {{0.0f, 3.0f, 2.0f}, {0.25f, 10.0f, 10.0f}, {-1.0f, -7.3f, 5.0f}};
  for (int s = 0; s < 3; ++s) {
    for (int n = 0; n < 6; ++n) {
      for (int k = 0; k < 3; ++k) {
        tb_world_id w = tbt_world(0.0f, 0.0f);
        ck_assert_int_eq(tb_world_set_integrator(w, schemes[s]), TB_OK);
        tb_body_id b = dynamic_disc(w, (tb_vec2){0.0f, 0.0f}, (tb_vec2){0.0f, 0.0f}, spins[k].omega);
        tb_body_set_transform(b, (tb_vec2){0.0f, 0.0f}, spins[k].theta0);
        int steps = (int)(spins[k].seconds * 60.0f + 0.5f);
        for (int i = 1; i <= steps; ++i) {
          ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, substeps[n]), TB_OK);
          double expected = (double)spins[k].theta0 + (double)spins[k].omega * tb_world_get_time(w);
          double err = fabs((double)tb_body_get_angle(b) - expected);
          ck_assert_msg(err <= 2.0 * float_ulp(expected), "integrator %d, %d substeps, spin %d, step %d: error %g > %g",
                        (int)schemes[s], substeps[n], k, i, err, 2.0 * float_ulp(expected));
        }
        ck_assert_float_eq(tb_body_get_angular_velocity(b), spins[k].omega);
        /* the rotation stays unit length: it is recomputed from the angle */
        tb_rot q = tb_body_get_rotation(b);
        ck_assert_near(q.c * q.c + q.s * q.s, 1.0, 1e-6);
        tb_destroy_world(w);
      }
    }
  }
}
END_TEST

/* A force F at a world point p: torque T = r x F with r = p - X; after one
 * substep from rest V = h F / M and w = h T / I (h = 1/32 s). */
START_TEST(force_at_point_gives_torque) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id b = tbt_box_body(w, 1.0f, 2.0f, 1.0f, 0.5f);
  tb_vec2 force = {3.0f, -4.0f}, point = {1.5f, 2.5f};
  ck_assert_int_eq(tb_body_apply_force(b, force, point), TB_OK);
  double rx = 0.5, ry = 0.5, torque = rx * force.y - ry * force.x;
  ck_assert_rel(tb_body_get_torque(b), torque, 1e-6);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 32.0f, 1), TB_OK);
  const double h = 1.0 / 32.0, m = 2.0, inertia = m * (4.0 + 1.0) / 12.0;
  ck_assert_rel(tb_body_get_angular_velocity(b), h * torque / inertia, 1e-6);
  ck_assert_rel(tb_body_get_linear_velocity(b).x, h * 3.0 / m, 1e-6);
  ck_assert_rel(tb_body_get_linear_velocity(b).y, h * -4.0 / m, 1e-6);
  /* forces act over one step, then are cleared */
  ck_assert_float_eq(tb_body_get_torque(b), 0.0f);
  ck_assert_float_eq(tb_body_get_force(b).x, 0.0f);
  tb_vec2 v = tb_body_get_linear_velocity(b);
  tb_world_step(w, 1.0f / 32.0f, 1);
  ck_assert_float_eq(tb_body_get_linear_velocity(b).x, v.x);
  /* a pure torque and a force at the centre */
  tb_body_id c = tbt_box_body(w, -5.0f, 0.0f, 1.0f, 0.5f);
  tb_body_apply_torque(c, 2.0f);
  tb_body_apply_force_to_center(c, (tb_vec2){1.0f, 0.0f});
  tb_world_step(w, 1.0f / 32.0f, 1);
  ck_assert_rel(tb_body_get_angular_velocity(c), h * 2.0 / inertia, 1e-6);
  ck_assert_rel(tb_body_get_linear_velocity(c).x, h / m, 1e-6);
  tb_destroy_world(w);
}
END_TEST

/* The lecture's bullet-block principle with impulses: the same impulse J at the
 * centre and off the centre of two identical blocks gives the same V = J / M
 * (so both rise the same), and the off-centre block spins with w = (r x J) / I. */
START_TEST(bullet_block_impulses) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_id a = tbt_box_body(w, -2.0f, 0.0f, 0.5f, 0.25f);
  tb_body_id b = tbt_box_body(w, 2.0f, 0.0f, 0.5f, 0.25f);
  tb_vec2 J = {0.0f, 3.0f};
  ck_assert_int_eq(tb_body_apply_linear_impulse(a, J, (tb_vec2){-2.0f, -0.25f}), TB_OK);
  ck_assert_int_eq(tb_body_apply_linear_impulse(b, J, (tb_vec2){2.4f, -0.25f}), TB_OK);
  double m = 0.5, inertia = m * (1.0 + 0.25) / 12.0;
  ck_assert_float_eq(tb_body_get_linear_velocity(a).y, tb_body_get_linear_velocity(b).y);
  ck_assert_rel(tb_body_get_linear_velocity(a).y, 3.0 / m, 1e-6);
  ck_assert_float_eq(tb_body_get_angular_velocity(a), 0.0f);
  ck_assert_rel(tb_body_get_angular_velocity(b), 0.4 * 3.0 / inertia, 1e-6);
  float top_a = 0.0f, top_b = 0.0f;
  for (int i = 0; i < 120; ++i) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    float ya = tb_body_get_world_center(a).y, yb = tb_body_get_world_center(b).y;
    top_a = ya > top_a ? ya : top_a;
    top_b = yb > top_b ? yb : top_b;
    ck_assert_float_eq(ya, yb); /* the centres move identically */
  }
  /* apex V^2 / 2g = 36 / 20 = 1.8 m, less the Euler lag g h t / 2 = 0.013 m
   * and the 60 Hz sampling (<= g dt^2 / 8 = 3.5e-4 m) */
  ck_assert_near(top_a, 1.8, 0.02);
  ck_assert_float_eq(top_a, top_b);
  /* angular impulse */
  tb_body_apply_angular_impulse(a, 1.0f);
  ck_assert_rel(tb_body_get_angular_velocity(a), 1.0 / inertia, 1e-6);
  tb_destroy_world(w);
}
END_TEST

/* Damping v <- v / (1 + h c) per substep: after n substeps v0 f^n with
 * f = 1 / (1 + h c). f is compared as the float the engine computes (its
 * rounding, 6e-8, would compound to 3e-5 over 480 substeps); what is left is
 * one rounding per substep, so 480 * 6e-8 = 2.9e-5 at worst. */
START_TEST(damping_is_discrete_geometric) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_world_set_integrator(w, TB_INTEGRATOR_SEMI_IMPLICIT_EULER);
  tb_body_id b = dynamic_disc(w, (tb_vec2){0, 0}, (tb_vec2){5.0f, 0.0f}, 2.0f);
  tb_body_set_linear_damping(b, 0.5f);
  tb_body_set_angular_damping(b, 2.0f);
  for (int i = 0; i < 120; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  float h = (1.0f / 60.0f) / 4.0f;
  double fv = 1.0f / (1.0f + h * 0.5f), fw = 1.0f / (1.0f + h * 2.0f);
  ck_assert_rel(tb_body_get_linear_velocity(b).x, 5.0 * pow(fv, 480), 3e-5);
  ck_assert_rel(tb_body_get_angular_velocity(b), 2.0 * pow(fw, 480), 3e-5);
  ck_assert_rel(tb_body_get_linear_velocity(b).x, 5.0 * pow(1.0 + h * 0.5, -480), 1e-4);
  tb_destroy_world(w);
}
END_TEST

START_TEST(kinematic_and_static_bodies) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_KINEMATIC_BODY;
  bd.linear_velocity = (tb_vec2){1.0f, 0.5f};
  bd.angular_velocity = 1.0f;
  tb_body_id k = tb_create_body(w, &bd);
  tb_polygon box;
  tb_make_box(1.0f, 1.0f, &box);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(k, &sd, &box);
  tb_body_apply_force_to_center(k, (tb_vec2){100.0f, 100.0f}); /* ignored */
  tb_body_apply_linear_impulse_to_center(k, (tb_vec2){100.0f, 100.0f});
  bd = tb_default_body_def(); /* static */
  bd.position = (tb_vec2){3.0f, 3.0f};
  tb_body_id s = tb_create_body(w, &bd);
  tb_create_polygon_shape(s, &sd, &box);
  tb_body_set_linear_velocity(s, (tb_vec2){1.0f, 1.0f}); /* a static body never moves */
  for (int i = 0; i < 60; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_near(tb_body_get_position(k).x, 1.0, 1e-5);
  ck_assert_near(tb_body_get_position(k).y, 0.5, 1e-5);
  ck_assert_near(tb_body_get_angle(k), 1.0, 1e-5);
  ck_assert_float_eq(tb_body_get_mass(k), 0.0f);
  ck_assert_float_eq(tb_body_get_position(s).x, 3.0f);
  ck_assert_float_eq(tb_body_get_linear_velocity(s).x, 0.0f);
  tb_destroy_world(w);
}
END_TEST

START_TEST(gravity_scale_fixed_rotation_and_disabled) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_id floating = dynamic_disc(w, (tb_vec2){0, 0}, (tb_vec2){0, 0}, 0.0f);
  tb_body_set_gravity_scale(floating, 0.0f);
  tb_body_id heavy = dynamic_disc(w, (tb_vec2){5, 0}, (tb_vec2){0, 0}, 0.0f);
  tb_body_set_gravity_scale(heavy, 2.0f);
  tb_body_id fixed = tbt_box_body(w, 10.0f, 0.0f, 1.0f, 1.0f);
  ck_assert_int_eq(tb_body_set_fixed_rotation(fixed, true), TB_OK);
  tb_body_id off = dynamic_disc(w, (tb_vec2){15, 0}, (tb_vec2){1, 0}, 0.0f);
  tb_body_set_enabled(off, false);
  tb_body_apply_torque(fixed, 50.0f);
  ck_assert_int_eq(tb_body_set_angular_velocity(fixed, 3.0f), TB_OK);
  for (int i = 0; i < 16; ++i) tb_world_step(w, 1.0f / 32.0f, 1); /* 0.5 s */
  ck_assert_float_eq(tb_body_get_position(floating).y, 0.0f);
  ck_assert_rel(tb_body_get_linear_velocity(heavy).y, -10.0, 1e-6);
  ck_assert_float_eq(tb_body_get_angle(fixed), 0.0f);
  ck_assert_float_eq(tb_body_get_angular_velocity(fixed), 0.0f);
  ck_assert_float_eq(tb_body_get_position(off).x, 15.0f);
  /* the weightless disc rested for TB_TIME_TO_SLEEP (0.5 s of steps) and fell
   * asleep; the disabled one is in no set */
  ck_assert_int_eq(tb_world_get_counts(w).awake_body_count, 2);
  ck_assert(!tb_body_is_awake(floating));
  tb_destroy_world(w);
}
END_TEST

/* A harmonic oscillator driven by the force field F = -k x. The exact energy is
 * constant; semi-implicit Euler conserves a nearby "shadow" energy, so its
 * error is O(w h) and oscillates; RK4's error is O((w h)^4) per unit time. */
static void spring_field(double t, const tb_body_state* s, void* ctx, tb_vec2* force, float* torque) {
  (void)t;
  float k = *(const float*)ctx;
  force->x = -k * s->center.x;
  force->y = -k * s->center.y;
  *torque = 0.0f;
}

static double oscillator_energy_error(tb_integrator scheme) {
  float k = 40.0f;
  tb_world_def def = tb_default_world_def();
  def.gravity = (tb_vec2){0.0f, 0.0f};
  def.integrator = scheme;
  def.force_field = spring_field;
  def.force_field_context = &k;
  tb_world_id w = tb_create_world(&def);
  tb_body_id b = dynamic_disc(w, (tb_vec2){1.0f, 0.0f}, (tb_vec2){0.0f, 0.0f}, 0.0f);
  double m = tb_body_get_mass(b), e0 = 0.5 * k * 1.0, max_err = 0.0;
  for (int i = 0; i < 600; ++i) {
    ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 1), TB_OK);
    tb_vec2 x = tb_body_get_position(b), v = tb_body_get_linear_velocity(b);
    double e = 0.5 * m * ((double)v.x * v.x + (double)v.y * v.y) + 0.5 * k * ((double)x.x * x.x + (double)x.y * x.y);
    double err = fabs(e - e0) / e0;
    if (err > max_err) max_err = err;
  }
  tb_destroy_world(w);
  return max_err;
}

START_TEST(rk4_oscillator_energy) {
  double euler = oscillator_energy_error(TB_INTEGRATOR_SEMI_IMPLICIT_EULER);
  double mid = oscillator_energy_error(TB_INTEGRATOR_MIDPOINT);
  double rk4 = oscillator_energy_error(TB_INTEGRATOR_RK4);
  ck_assert_msg(rk4 * 100.0 <= euler, "RK4 energy error %g, Euler %g: need a 100x gap", rk4, euler);
  ck_assert_msg(mid < euler * 10.0, "midpoint %g", mid);
  ck_assert(euler > 0.0 && euler < 0.2); /* bounded: symplectic, w h = 0.1 */
}
END_TEST

/* A NaN from the force field stays with its body: the body keeps its state from
 * before the step, the step reports it, and the other bodies move on. */
static void poison_field(double t, const tb_body_state* s, void* ctx, tb_vec2* force, float* torque) {
  (void)t;
  (void)ctx;
  *force = (tb_vec2){0.0f, 0.0f};
  *torque = 0.0f;
  if (s->user_data != NULL) force->x = NAN;
}

START_TEST(nan_from_force_field_is_contained) {
  tb_world_def def = tb_default_world_def();
  def.force_field = poison_field;
  tb_world_id w = tb_create_world(&def);
  tb_body_id good = dynamic_disc(w, (tb_vec2){0, 0}, (tb_vec2){1, 0}, 0.0f);
  tb_body_id bad = dynamic_disc(w, (tb_vec2){5, 0}, (tb_vec2){1, 0}, 0.5f);
  static int marker;
  tb_body_set_user_data(bad, &marker);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_NUMERIC);
  ck_assert_ptr_nonnull(strstr(tb_world_last_error(w), "1 bodies"));
  ck_assert_float_eq(tb_body_get_position(bad).x, 5.0f);
  ck_assert_float_eq(tb_body_get_linear_velocity(bad).x, 1.0f);
  ck_assert_float_eq(tb_body_get_angle(bad), 0.0f);
  ck_assert(tb_body_get_position(good).x > 0.0f);
  ck_assert(isfinite(tb_body_get_position(good).y));
  tb_destroy_world(w);
}
END_TEST

/* A callback that tries to change the world is refused, and changes nothing. */
static tb_result locked_result;
static void meddling_field(double t, const tb_body_state* s, void* ctx, tb_vec2* force, float* torque) {
  (void)t;
  (void)ctx;
  *force = (tb_vec2){0.0f, 0.0f};
  *torque = 0.0f;
  locked_result = tb_destroy_body(s->body);
}

START_TEST(callbacks_cannot_change_the_world) {
  tb_world_def def = tb_default_world_def();
  def.force_field = meddling_field;
  tb_world_id w = tb_create_world(&def);
  tb_body_id b = dynamic_disc(w, (tb_vec2){0, 0}, (tb_vec2){0, 0}, 0.0f);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 1), TB_OK);
  ck_assert_int_eq(locked_result, TB_ERR_LOCKED);
  ck_assert(tb_body_is_valid(b));
  tb_destroy_world(w);
}
END_TEST

/* The speed caps hold for every body on every path (issue 23): a free body
 * (no contact, no joint) under midpoint and RK4 kept 5,000 m/s and 1e5 rad/s,
 * and a kinematic body any velocity. After one step each moves at most
 * maximum_linear_speed and a quarter turn per step (pi / 2 / dt rad/s), and
 * its centre moved at most dt times the cap. The cap scales v by cap / |v|:
 * float rounding leaves |v| within a few ulps of the cap, so 1e-6 relative. */
START_TEST(speed_caps_hold_for_free_and_kinematic_bodies) {
  const float dt = 1.0f / 60.0f, cap = 1000.0f;
  const double max_w = 0.5 * 3.14159265358979 / dt, slack = 1.0 + 1e-6;
  for (int scheme = TB_INTEGRATOR_SEMI_IMPLICIT_EULER; scheme <= TB_INTEGRATOR_RK4; ++scheme) {
    tb_world_id w = tbt_world(0.0f, -10.0f);
    ck_assert_int_eq(tb_world_set_integrator(w, (tb_integrator)scheme), TB_OK);
    tb_body_id free_disc = dynamic_disc(w, (tb_vec2){0, 0}, (tb_vec2){3000.0f, -4000.0f}, 1e5f);
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_KINEMATIC_BODY;
    bd.position = (tb_vec2){50.0f, 0.0f};
    bd.linear_velocity = (tb_vec2){-5000.0f, 0.0f};
    bd.angular_velocity = -1e5f;
    tb_body_id kinematic = tb_create_body(w, &bd);
    const tb_body_id bodies[2] = {free_disc, kinematic};
    for (int step = 0; step < 3; ++step) {
      tb_vec2 before[2] = {tb_body_get_position(free_disc), tb_body_get_position(kinematic)};
      ck_assert_int_eq(tb_world_step(w, dt, 4), TB_OK);
      for (int i = 0; i < 2; ++i) {
        tb_vec2 v = tb_body_get_linear_velocity(bodies[i]), p = tb_body_get_position(bodies[i]);
        double speed = hypot(v.x, v.y), moved = hypot(p.x - before[i].x, p.y - before[i].y);
        ck_assert_msg(speed <= cap * slack, "scheme %d body %d: %g m/s", scheme, i, speed);
        ck_assert_msg(speed >= cap / slack, "scheme %d body %d slowed to %g m/s", scheme, i, speed);
        ck_assert_msg(moved <= cap * dt * slack, "scheme %d body %d moved %g m", scheme, i, moved);
        ck_assert_msg(fabs(tb_body_get_angular_velocity(bodies[i])) <= max_w * slack, "scheme %d body %d: %g rad/s",
                      scheme, i, (double)tb_body_get_angular_velocity(bodies[i]));
      }
    }
    tb_destroy_world(w);
  }
}
END_TEST

/* The force field only ever sees finite states (issue 23). A force of 1e18 N
 * on a body of 1e-30 kg is an acceleration of 1e48 m/s^2, beyond float: under
 * midpoint and RK4 the first stage's velocity overflowed and the field was
 * called with v = (inf, inf). Now the step stops at the stage, reports
 * TB_ERR_NUMERIC and leaves the body as it was, as the solver does for a
 * non-finite acceleration. */
static int non_finite_states_seen;
static void huge_push_field(double t, const tb_body_state* s, void* ctx, tb_vec2* force, float* torque) {
  (void)t;
  (void)ctx;
  if (!isfinite(s->center.x) || !isfinite(s->center.y) || !isfinite(s->angle) || !isfinite(s->linear_velocity.x) ||
      !isfinite(s->linear_velocity.y) || !isfinite(s->angular_velocity))
    non_finite_states_seen += 1;
  *force = (tb_vec2){1e18f, 1e18f};
  *torque = 0.0f;
}

/* A body of 1e-30 kg pushed by 1e18 N, by the force field or by an applied
 * force, under every scheme: the step fails and the body keeps its state. */
static void overflowing_push_leaves_body(bool by_field) {
  for (int scheme = TB_INTEGRATOR_SEMI_IMPLICIT_EULER; scheme <= TB_INTEGRATOR_RK4; ++scheme) {
    tb_world_def def = tb_default_world_def();
    def.integrator = (tb_integrator)scheme;
    if (by_field) def.force_field = huge_push_field;
    tb_world_id w = tb_create_world(&def);
    tb_body_id b = dynamic_disc(w, (tb_vec2){1.0f, 2.0f}, (tb_vec2){3.0f, 0.0f}, 0.5f);
    ck_assert_int_eq(tb_body_set_mass_data(b, (tb_mass_data){1e-30f, {0.0f, 0.0f}, 1e-30f}), TB_OK);
    if (!by_field) ck_assert_int_eq(tb_body_apply_force_to_center(b, (tb_vec2){1e18f, 1e18f}), TB_OK);
    non_finite_states_seen = 0;
    ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_NUMERIC);
    ck_assert_int_eq(non_finite_states_seen, 0);
    ck_assert_float_eq(tb_body_get_position(b).x, 1.0f);
    ck_assert_float_eq(tb_body_get_position(b).y, 2.0f);
    ck_assert_float_eq(tb_body_get_linear_velocity(b).x, 3.0f);
    ck_assert_float_eq(tb_body_get_angular_velocity(b), 0.5f);
    tb_destroy_world(w);
  }
}

START_TEST(force_field_sees_only_finite_states) { overflowing_push_leaves_body(true); }
END_TEST

/* Without a field the stages are not checked one by one (motion.c,
 * derivative): an applied force that overflows a stage's velocity must still
 * fail the step (TB_ERR_NUMERIC) and leave the body as it was. (An end to end
 * check: the step's own check of the bodies' end states would also catch a
 * non-finite integration, so this does not isolate the substeps' check.) */
START_TEST(overflowing_force_without_field_leaves_body) { overflowing_push_leaves_body(false); }
END_TEST

/* The shortest accepted substep, TB_MIN_SUBSTEP, is usable (issue 23: 1e-45
 * and FLT_MIN were accepted, then every step failed with TB_ERR_NUMERIC): a
 * box resting on the ground and one sliding into it at the speed cap step
 * without error, as one substep and as 64. */
START_TEST(shortest_step_is_usable) {
  const int substeps[2] = {1, 64};
  for (int k = 0; k < 2; ++k) {
    tb_world_id w = tbt_world(0.0f, -10.0f);
    tb_body_def bd = tb_default_body_def();
    tb_body_id ground = tb_create_body(w, &bd);
    tb_polygon slab;
    tb_make_offset_box(20.0f, 0.5f, (tb_vec2){0.0f, -0.5f}, 0.0f, &slab);
    tb_shape_def sd = tb_default_shape_def();
    tb_create_polygon_shape(ground, &sd, &slab);
    tb_body_id resting = tbt_box_body(w, 0.0f, 0.49f, 0.5f, 0.5f); /* 1 cm deep */
    tb_body_id sliding = tbt_box_body(w, 1.0f, 0.5f, 0.5f, 0.5f);  /* touching it */
    tb_body_set_linear_velocity(sliding, (tb_vec2){-1000.0f, 0.0f});
    for (int i = 0; i < 10; ++i)
      ck_assert_int_eq(tb_world_step(w, TB_MIN_SUBSTEP * (float)substeps[k], substeps[k]), TB_OK);
    ck_assert(isfinite(tb_body_get_position(resting).y) && isfinite(tb_body_get_position(sliding).x));
    tb_destroy_world(w);
  }
}
END_TEST

static Suite* motion_suite(void) {
  Suite* s = suite_create("motion");
  TCase* tc = tcase_create("closed_forms");
  tcase_add_test(tc, discrete_projectile_is_exact);
  tcase_add_test(tc, runge_kutta_projectile_matches_parabola);
  tcase_add_test(tc, constant_spin);
  tcase_add_test(tc, force_at_point_gives_torque);
  tcase_add_test(tc, bullet_block_impulses);
  tcase_add_test(tc, damping_is_discrete_geometric);
  tcase_add_test(tc, kinematic_and_static_bodies);
  tcase_add_test(tc, gravity_scale_fixed_rotation_and_disabled);
  tcase_add_test(tc, rk4_oscillator_energy);
  tcase_add_test(tc, nan_from_force_field_is_contained);
  tcase_add_test(tc, callbacks_cannot_change_the_world);
  tcase_add_test(tc, speed_caps_hold_for_free_and_kinematic_bodies);
  tcase_add_test(tc, force_field_sees_only_finite_states);
  tcase_add_test(tc, overflowing_force_without_field_leaves_body);
  tcase_add_test(tc, shortest_step_is_usable);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(motion_suite)
