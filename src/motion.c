/* Free motion (of bodies without contacts or joints in this step, when the
 * world's integrator is midpoint or RK4): the lecture's ODE  y = (X, theta, V, w),
 *   dy/dt = (V, w, g s + (F + F_field)/M - c_v V, (T + T_field)/I - c_w w),
 * integrated per substep h = dt / substeps.
 *
 * Semi-implicit (symplectic) Euler is the default and matches the constraint
 * solver: V += h a; V /= (1 + h c_v) (damping like Box2D); X += h V. The angle
 * is a scalar integrated the same way, summed in double and kept with a
 * residual (tb_body_turn), so constant spin is exact up to the rounding of
 * the float angle. Midpoint (RK2) and RK4 evaluate the ODE at intermediate states,
 * with damping as the linear term above; they pay off for smooth force fields.
 *
 * Every state, the stages' included, keeps its velocities within the step's
 * speed caps (solver.h), so a substep moves a body no further than the solver
 * would. A stage that is not finite (an acceleration that overflowed: a force
 * on a tiny mass) ends the body's step before the force field could see it:
 * the body keeps its state from before the step, as in the solver. */
#include <stddef.h>

#include "math_internal.h"
#include "world.h"

typedef struct state {
  tb_vec2 x; /* displacement from the centre at the step start (see center_residual) */
  double a;  /* angle turned since the step start, summed in double (see tb_body_turn) */
  tb_vec2 v;
  float w;
} state;

/* dy/dt */
typedef struct rate {
  tb_vec2 dx; /* = V */
  double da;  /* = w (double: the Runge-Kutta sums of it stay exact) */
  tb_vec2 dv; /* acceleration */
  float dw;   /* angular acceleration */
} rate;

typedef struct body_ctx {
  const tb_world* world;
  const tb_body* body;
  tb_body_id id;
  tb_vec2 gravity; /* g times the body's gravity scale */
  float max_linear_speed, max_angular_speed;
} body_ctx;

static inline __attribute__((always_inline)) bool state_finite(const state* y) {
  return tb_vec_finite(y->x) && isfinite(y->a) && tb_vec_finite(y->v) && isfinite(y->w);
}

static inline __attribute__((always_inline)) void cap_speeds(const body_ctx* c, state* y) {
  y->v = tb_cap_linear_speed(y->v, c->max_linear_speed);
  y->w = tb_cap_angular_speed(y->w, c->max_angular_speed);
}

/* The applied force plus the field's, at time t and state y. */
static inline __attribute__((always_inline)) void total_load(const body_ctx* c, double t, const state* y,
                                                             tb_vec2* force, float* torque) {
  *force = c->body->force;
  *torque = c->body->torque;
  if (c->world->force_field != NULL) {
    const tb_body* b = c->body;
    tb_body_state s = {c->id,       tb_add(b->center, y->x), b->angle + (float)y->a, y->v, y->w, b->mass, b->inertia,
                       b->user_data};
    tb_vec2 f = {0.0f, 0.0f};
    float tq = 0.0f;
    c->world->force_field(t, &s, c->world->force_field_context, &f, &tq);
    *force = tb_add(*force, f);
    *torque += tq;
  }
}

/* dy/dt of the damped equations of motion (used by the Runge-Kutta schemes) at
 * a finite state y; false when y is not finite (the field is not called).
 * Without a field the stage is not checked: a stage that is not finite makes
 * every later stage and the substep's end not finite (the caps leave a
 * non-finite velocity as it is), and the end is checked, so the body's step
 * ends at the same substep (elastic_balls: the checks were a tenth of its
 * instructions). */
static inline __attribute__((always_inline)) bool derivative(const body_ctx* c, double t, const state* y, rate* out) {
  if (c->world->force_field != NULL && !state_finite(y)) return false;
  tb_vec2 f;
  float tq;
  total_load(c, t, y, &f, &tq);
  const tb_body* b = c->body;
  tb_vec2 acc = tb_sub(tb_mul_add(c->gravity, b->inv_mass, f), tb_scale(b->linear_damping, y->v));
  float alpha = b->inv_inertia * tq - b->angular_damping * y->w;
  *out = (rate){y->v, y->w, acc, alpha};
  return true;
}

/* y + h d, within the speed caps (h exact in double for the angle, rounded to
 * float for the rest) */
static inline __attribute__((always_inline)) state advance(const body_ctx* c, const state* y, double h, const rate* d) {
  float hf = (float)h;
  state next = {tb_mul_add(y->x, hf, d->dx), y->a + h * d->da, tb_mul_add(y->v, hf, d->dv), y->w + hf * d->dw};
  cap_speeds(c, &next);
  return next;
}

static inline __attribute__((always_inline)) bool step_euler(const body_ctx* c, double t, double exact_h, state* y) {
  float h = (float)exact_h;
  tb_vec2 f;
  float tq;
  total_load(c, t, y, &f, &tq);
  const tb_body* b = c->body;
  y->v = tb_mul_add(y->v, h, tb_mul_add(c->gravity, b->inv_mass, f));
  y->w += h * b->inv_inertia * tq;
  y->v = tb_scale(1.0f / (1.0f + h * b->linear_damping), y->v);
  y->w *= 1.0f / (1.0f + h * b->angular_damping);
  cap_speeds(c, y);
  y->x = tb_mul_add(y->x, h, y->v);
  y->a += exact_h * (double)y->w;
  return state_finite(y);
}

static inline __attribute__((always_inline)) bool step_midpoint(const body_ctx* c, double t, double h, state* y) {
  rate k1, k2;
  if (!derivative(c, t, y, &k1)) return false;
  state mid = advance(c, y, 0.5 * h, &k1);
  if (!derivative(c, t + 0.5 * h, &mid, &k2)) return false;
  *y = advance(c, y, h, &k2);
  return state_finite(y);
}

/* step_midpoint without a force field, where the load is the body's own and
 * no stage is checked: the same float operations, without the stage
 * positions and angles that only a field reads (elastic_balls: the free
 * bodies' integration was a fifth of its instructions). Not checked per
 * substep either: a state that is not finite stays so through the caps and
 * the stages (as in derivative), and tb_integrate_free_body checks the end.
 * capped: whether the speed caps are applied (below_caps tells where they
 * cannot change anything). */
static inline __attribute__((always_inline)) void step_midpoint_unforced(const body_ctx* c, double h, state* y,
                                                                         bool capped) {
  const tb_body* b = c->body;
  tb_vec2 load = tb_mul_add(c->gravity, b->inv_mass, b->force);
  float torque = b->inv_inertia * b->torque;
  float half = (float)(0.5 * h), hf = (float)h;
  tb_vec2 a1 = tb_sub(load, tb_scale(b->linear_damping, y->v));
  float alpha1 = torque - b->angular_damping * y->w;
  state mid = {{0.0f, 0.0f}, 0.0, tb_mul_add(y->v, half, a1), y->w + half * alpha1};
  if (capped) cap_speeds(c, &mid);
  tb_vec2 a2 = tb_sub(load, tb_scale(b->linear_damping, mid.v));
  float alpha2 = torque - b->angular_damping * mid.w;
  state next = {tb_mul_add(y->x, hf, mid.v), y->a + h * mid.w, tb_mul_add(y->v, hf, a2), y->w + hf * alpha2};
  if (capped) cap_speeds(c, &next);
  *y = next;
}

/* Whether no state of an undamped, unforced step can reach the speed caps,
 * which then change nothing: each stage's velocity is the start's plus at
 * most the step's time times the constant acceleration, |v_k| <= |v| + dt
 * |a| (the 1-norm bounds the length; a thousandth kept for rounding). A
 * ball in flight at 3 m/s is 0.3% of the 1,000 m/s cap. */
static bool below_caps(const body_ctx* c, const state* y, float dt) {
  const tb_body* b = c->body;
  if (b->linear_damping != 0.0f || b->angular_damping != 0.0f) return false;
  tb_vec2 a = tb_mul_add(c->gravity, b->inv_mass, b->force);
  float alpha = b->inv_inertia * b->torque;
  float v = fabsf(y->v.x) + fabsf(y->v.y) + dt * (fabsf(a.x) + fabsf(a.y));
  float w = fabsf(y->w) + dt * fabsf(alpha);
  return v < 0.999f * c->max_linear_speed && w < 0.999f * c->max_angular_speed;
}

static inline __attribute__((always_inline)) bool step_rk4(const body_ctx* c, double t, double h, state* y) {
  rate k1, k2, k3, k4;
  if (!derivative(c, t, y, &k1)) return false;
  state y2 = advance(c, y, 0.5 * h, &k1);
  if (!derivative(c, t + 0.5 * h, &y2, &k2)) return false;
  state y3 = advance(c, y, 0.5 * h, &k2);
  if (!derivative(c, t + 0.5 * h, &y3, &k3)) return false;
  state y4 = advance(c, y, h, &k3);
  if (!derivative(c, t + h, &y4, &k4)) return false;
  /* y += h/6 (k1 + 2 k2 + 2 k3 + k4) */
  rate sum = {
      {k1.dx.x + 2.0f * k2.dx.x + 2.0f * k3.dx.x + k4.dx.x, k1.dx.y + 2.0f * k2.dx.y + 2.0f * k3.dx.y + k4.dx.y},
      k1.da + 2.0 * k2.da + 2.0 * k3.da + k4.da,
      {k1.dv.x + 2.0f * k2.dv.x + 2.0f * k3.dv.x + k4.dv.x, k1.dv.y + 2.0f * k2.dv.y + 2.0f * k3.dv.y + k4.dv.y},
      k1.dw + 2.0f * k2.dw + 2.0f * k3.dw + k4.dw};
  *y = advance(c, y, h / 6.0, &sum);
  return state_finite(y);
}

bool tb_integrate_free_body(tb_world* w, int index, const tb_step_context* ctx) {
  double h = ctx->exact_h;
  tb_body* b = tb_body_at(w, index);
  body_ctx c = {w, b, tb_make_body_id(w, index), tb_body_gravity(w, b), ctx->max_linear_speed, ctx->max_angular_speed};
  state y = {{0.0f, 0.0f}, 0.0, b->linear_velocity, b->angular_velocity};
  cap_speeds(&c, &y); /* a velocity set beyond the caps */
  bool unforced = w->integrator == TB_INTEGRATOR_MIDPOINT && w->force_field == NULL;
  bool capped = !unforced || !below_caps(&c, &y, ctx->dt);
  bool ok = true;
  for (int k = 0; k < ctx->substeps && ok; ++k) {
    if (unforced) {
      if (capped)
        step_midpoint_unforced(&c, h, &y, true);
      else
        step_midpoint_unforced(&c, h, &y, false);
      continue;
    }
    double t = w->time + (double)k * h;
    switch (w->integrator) {
      case TB_INTEGRATOR_SEMI_IMPLICIT_EULER: ok = step_euler(&c, t, h, &y); break;
      case TB_INTEGRATOR_MIDPOINT: ok = step_midpoint(&c, t, h, &y); break;
      case TB_INTEGRATOR_RK4: ok = step_rk4(&c, t, h, &y); break;
    }
  }
  if (unforced) ok = state_finite(&y);
  if (b->fixed_rotation) y.w = 0.0f;
  if (!ok) return false; /* contain the NaN: this body keeps its old state */
  b->center = tb_two_sum(b->center, tb_add(b->center_residual, y.x), &b->center_residual);
  b->angle = tb_body_turn(b->angle, &b->angle_residual, y.a);
  b->linear_velocity = y.v;
  b->angular_velocity = y.w;
  tb_body_sync_transform(b);
  return true;
}
