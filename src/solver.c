/* The soft step (Catto, "Solver2D" and Box2D v3's design; written from the
 * published description): collide once per step, then per substep h
 *   integrate velocities -> warm start -> solve (soft, with position bias)
 *   -> integrate positions -> relax (solve without bias),
 * and after the substeps apply restitution and keep the impulses for the next
 * step's warm start.
 *
 * Contacts are soft constraints. For a point with current separation s < 0 the
 * normal impulse is  -m_n (mass_scale (v_n + bias) ) - impulse_scale P_n  with
 * bias = max(bias_rate s, -push_max): a damped spring that pushes overlap out
 * at a bounded speed, unconditionally stable for any h. A point still apart
 * (s > 0) is speculative: it only removes the approach speed that would close
 * the gap within the substep (bias = s / h), which stops fast bodies without
 * sweeping. The separation is not recomputed by collision inside the step: it
 * is s = s0 + n . ((dp_B + q_B r_B) - (dp_A + q_A r_A) - (r_B - r_A)), from
 * the motion (dp, dq) of each body since the step began. */
#include "solver.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "contact.h"
#include "math_internal.h"
#include "world.h"

tb_softness tb_make_softness(float hertz, float zeta, float h) {
  if (hertz == 0.0f) return tb_rigid_softness();
  float omega = 2.0f * 3.14159265358979f * hertz;
  float a1 = 2.0f * zeta + h * omega;
  float a2 = h * omega * a1;
  float a3 = 1.0f / (1.0f + a2);
  return (tb_softness){omega / a1, a2 * a3, a3};
}

int tb_solver_index(const tb_world* w, int body) {
  int i = tb_body_at(w, body)->awake_index;
  return i >= 0 ? i : w->awake_count;
}

typedef struct tb_constraint_point {
  tb_vec2 ra, rb;        /* anchors from each centre of mass, world-oriented, at step start */
  float base_separation; /* s0 - n . (rb - ra) */
  float relative_velocity;
  float normal_mass, tangent_mass;
  float normal_impulse, tangent_impulse, max_normal_impulse;
} tb_constraint_point;

typedef struct tb_contact_constraint {
  int a, b; /* solver bodies */
  int contact;
  int point_count;
  tb_vec2 normal;
  float friction, restitution, rolling_resistance, tangent_speed;
  float inv_mass_a, inv_i_a, inv_mass_b, inv_i_b;
  float rolling_mass, rolling_impulse;
  tb_softness softness;
  tb_constraint_point points[2];
} tb_contact_constraint;

/* Per awake body, per step: what the velocity integration adds (constant over
 * the step unless a force field is set). */
typedef struct tb_body_motion {
  tb_vec2 accel;        /* g s + F / M */
  float alpha;          /* T / I */
  float linear_damping; /* 1 / (1 + h c) */
  float angular_damping;
  int flags;
} tb_body_motion;

enum { MOTION_FIELD = 1, MOTION_FREE = 2, MOTION_FAULT = 4, MOTION_DYNAMIC = 8 };

/* ---- velocity and position integration ------------------------------------ */

static void integrate_velocities(tb_world* w, tb_step_context* ctx, tb_body_motion* motions, double t) {
  tb_solver_body* states = ctx->states;
  float h = ctx->h;
  float max_speed = ctx->max_linear_speed;
  float max_angular = 0.25f * 3.14159265f * ctx->inv_h; /* a quarter turn per substep */
  for (int i = 0; i < w->awake_count; ++i) {
    tb_body_motion* m = &motions[i];
    if (!(m->flags & MOTION_DYNAMIC) || (m->flags & MOTION_FREE)) continue;
    tb_solver_body* s = &states[i];
    tb_vec2 accel = m->accel;
    float alpha = m->alpha;
    if (m->flags & MOTION_FIELD) { /* a force field: evaluated at the current state */
      int index = w->awake[i];
      const tb_body* b = tb_body_at(w, index);
      tb_body_state st = {tb_make_body_id(w, index), tb_add(b->center, s->dp), b->angle + s->da, s->v, s->w,
                          b->mass, b->inertia, b->user_data};
      tb_vec2 f = {0.0f, 0.0f};
      float tq = 0.0f;
      w->force_field(t, &st, w->force_field_context, &f, &tq);
      if (!tb_vec_finite(f) || !isfinite(tq)) {
        m->flags |= MOTION_FAULT; /* caught here, before it can reach a neighbour */
        continue;
      }
      accel = tb_mul_add(accel, s->inv_mass, f);
      alpha += s->inv_inertia * tq;
    }
    tb_vec2 v = tb_scale(m->linear_damping, tb_mul_add(s->v, h, accel));
    float av = m->angular_damping * (s->w + h * alpha);
    if (!tb_vec_finite(v) || !isfinite(av)) {
      m->flags |= MOTION_FAULT;
      continue;
    }
    float speed_sq = tb_length_sq(v);
    if (speed_sq > max_speed * max_speed) v = tb_scale(max_speed / sqrtf(speed_sq), v);
    if (av > max_angular) av = max_angular;
    if (av < -max_angular) av = -max_angular;
    s->v = v;
    s->w = av;
  }
}

static void integrate_positions(tb_world* w, tb_step_context* ctx, const tb_body_motion* motions) {
  tb_solver_body* states = ctx->states;
  float h = ctx->h;
  for (int i = 0; i < w->awake_count; ++i) {
    if (motions[i].flags & MOTION_FREE) continue;
    tb_solver_body* s = &states[i];
    s->dp = tb_mul_add(s->dp, h, s->v);
    float dw = h * s->w;
    s->da += dw;
    /* q <- normalise(q + h w perp(q)): the rotation the anchors see; the angle
     * itself is the exact scalar sum da */
    tb_rot q = {s->dq.c - dw * s->dq.s, s->dq.s + dw * s->dq.c};
    float inv = 1.0f / sqrtf(q.c * q.c + q.s * q.s);
    s->dq = (tb_rot){q.c * inv, q.s * inv};
  }
}

/* ---- contacts ---------------------------------------------------------------- */

static void prepare_contacts(tb_world* w, tb_step_context* ctx) {
  tb_contact_constraint* cs = w->constraints;
  const tb_solver_body* states = ctx->states;
  for (int k = 0; k < w->step_contact_count; ++k) {
    int index = w->step_contacts[k];
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, index);
    tb_contact_constraint* cc = &cs[k];
    const tb_body* ba = tb_body_at(w, c->edges[0].body);
    const tb_body* bb = tb_body_at(w, c->edges[1].body);
    int ia = tb_solver_index(w, c->edges[0].body), ib = tb_solver_index(w, c->edges[1].body);
    const tb_solver_body* sa = &states[ia];
    const tb_solver_body* sb = &states[ib];
    float ma = sa->inv_mass, mb = sb->inv_mass, ja = sa->inv_inertia, jb = sb->inv_inertia;
    cc->a = ia;
    cc->b = ib;
    cc->contact = index;
    cc->normal = c->manifold.normal;
    cc->friction = c->friction;
    cc->restitution = c->restitution;
    cc->rolling_resistance = c->rolling_resistance;
    cc->tangent_speed = c->tangent_speed;
    cc->inv_mass_a = ma;
    cc->inv_i_a = ja;
    cc->inv_mass_b = mb;
    cc->inv_i_b = jb;
    cc->rolling_mass = ja + jb > 0.0f ? 1.0f / (ja + jb) : 0.0f;
    cc->rolling_impulse = ctx->enable_warm_starting ? c->rolling_impulse : 0.0f;
    /* against a body that does not respond (static, kinematic) the contact is stiffer */
    bool rigid_other = ba->type != TB_DYNAMIC_BODY || bb->type != TB_DYNAMIC_BODY;
    cc->softness = rigid_other ? ctx->static_softness : ctx->contact_softness;
    cc->point_count = c->manifold.point_count;
    tb_vec2 n = cc->normal;
    tb_vec2 t = tb_right_perp(n);
    for (int p = 0; p < cc->point_count; ++p) {
      const tb_manifold_point* mp = &c->manifold.points[p];
      tb_constraint_point* cp = &cc->points[p];
      cp->ra = tb_sub(mp->point, ba->center);
      cp->rb = tb_sub(mp->point, bb->center);
      cp->base_separation = mp->separation - tb_dot(tb_sub(cp->rb, cp->ra), n);
      float rna = tb_cross(cp->ra, n), rnb = tb_cross(cp->rb, n);
      float kn = ma + mb + ja * rna * rna + jb * rnb * rnb;
      cp->normal_mass = kn > 0.0f ? 1.0f / kn : 0.0f;
      float rta = tb_cross(cp->ra, t), rtb = tb_cross(cp->rb, t);
      float kt = ma + mb + ja * rta * rta + jb * rtb * rtb;
      cp->tangent_mass = kt > 0.0f ? 1.0f / kt : 0.0f;
      tb_vec2 va = tb_add(sa->v, tb_cross_sv(sa->w, cp->ra));
      tb_vec2 vb = tb_add(sb->v, tb_cross_sv(sb->w, cp->rb));
      cp->relative_velocity = tb_dot(n, tb_sub(vb, va));
      cp->normal_impulse = ctx->enable_warm_starting ? mp->normal_impulse : 0.0f;
      cp->tangent_impulse = ctx->enable_warm_starting ? mp->tangent_impulse : 0.0f;
      cp->max_normal_impulse = 0.0f;
    }
  }
}

static void warm_start_contacts(tb_world* w, tb_step_context* ctx) {
  tb_solver_body* states = ctx->states;
  for (int k = 0; k < w->step_contact_count; ++k) {
    tb_contact_constraint* cc = &w->constraints[k];
    tb_solver_body* sa = &states[cc->a];
    tb_solver_body* sb = &states[cc->b];
    tb_vec2 va = sa->v, vb = sb->v;
    float wa = sa->w, wb = sb->w;
    tb_vec2 n = cc->normal, t = tb_right_perp(n);
    for (int p = 0; p < cc->point_count; ++p) {
      const tb_constraint_point* cp = &cc->points[p];
      tb_vec2 P = tb_add(tb_scale(cp->normal_impulse, n), tb_scale(cp->tangent_impulse, t));
      wa -= cc->inv_i_a * tb_cross(cp->ra, P);
      va = tb_mul_add(va, -cc->inv_mass_a, P);
      wb += cc->inv_i_b * tb_cross(cp->rb, P);
      vb = tb_mul_add(vb, cc->inv_mass_b, P);
    }
    wa -= cc->inv_i_a * cc->rolling_impulse;
    wb += cc->inv_i_b * cc->rolling_impulse;
    sa->v = va;
    sa->w = wa;
    sb->v = vb;
    sb->w = wb;
  }
}

static void solve_contacts(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_solver_body* states = ctx->states;
  float inv_h = ctx->inv_h;
  float push = ctx->contact_push_max_velocity;
  for (int k = 0; k < w->step_contact_count; ++k) {
    tb_contact_constraint* cc = &w->constraints[k];
    tb_solver_body* sa = &states[cc->a];
    tb_solver_body* sb = &states[cc->b];
    tb_vec2 va = sa->v, vb = sb->v;
    float wa = sa->w, wb = sb->w;
    const float ma = cc->inv_mass_a, mb = cc->inv_mass_b, ja = cc->inv_i_a, jb = cc->inv_i_b;
    tb_vec2 n = cc->normal, t = tb_right_perp(n);
    tb_vec2 dp = tb_sub(sb->dp, sa->dp);
    tb_rot qa = sa->dq, qb = sb->dq;
    float total_normal = 0.0f;

    /* non-penetration */
    for (int p = 0; p < cc->point_count; ++p) {
      tb_constraint_point* cp = &cc->points[p];
      tb_vec2 d = tb_add(dp, tb_sub(tb_rotate(qb, cp->rb), tb_rotate(qa, cp->ra)));
      float s = tb_dot(d, n) + cp->base_separation;
      float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
      if (s > 0.0f) {
        bias = s * inv_h; /* speculative: close the gap, no more */
      } else if (use_bias) {
        bias = cc->softness.bias_rate * s;
        if (bias < -push) bias = -push;
        mass_scale = cc->softness.mass_scale;
        impulse_scale = cc->softness.impulse_scale;
      }
      tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
      float vn = tb_dot(dv, n);
      float impulse = -cp->normal_mass * mass_scale * (vn + bias) - impulse_scale * cp->normal_impulse;
      float total = cp->normal_impulse + impulse;
      if (total < 0.0f) total = 0.0f;
      impulse = total - cp->normal_impulse;
      cp->normal_impulse = total;
      if (total > cp->max_normal_impulse) cp->max_normal_impulse = total;
      total_normal += total;
      tb_vec2 P = tb_scale(impulse, n);
      va = tb_mul_add(va, -ma, P);
      wa -= ja * tb_cross(cp->ra, P);
      vb = tb_mul_add(vb, mb, P);
      wb += jb * tb_cross(cp->rb, P);
    }

    /* Coulomb friction: |P_t| <= mu P_n per point, driving the relative
     * tangential speed towards the surfaces' own (conveyor) speed */
    for (int p = 0; p < cc->point_count; ++p) {
      tb_constraint_point* cp = &cc->points[p];
      tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
      float vt = tb_dot(dv, t);
      float impulse = -cp->tangent_mass * (vt - cc->tangent_speed);
      float limit = cc->friction * cp->normal_impulse;
      float total = cp->tangent_impulse + impulse;
      if (total < -limit) total = -limit;
      if (total > limit) total = limit;
      impulse = total - cp->tangent_impulse;
      cp->tangent_impulse = total;
      tb_vec2 P = tb_scale(impulse, t);
      va = tb_mul_add(va, -ma, P);
      wa -= ja * tb_cross(cp->ra, P);
      vb = tb_mul_add(vb, mb, P);
      wb += jb * tb_cross(cp->rb, P);
    }

    /* rolling resistance: an angular impulse up to rr * radius * normal impulse */
    if (cc->rolling_resistance > 0.0f) {
      float limit = cc->rolling_resistance * total_normal;
      float impulse = -cc->rolling_mass * (wb - wa);
      float total = cc->rolling_impulse + impulse;
      if (total < -limit) total = -limit;
      if (total > limit) total = limit;
      impulse = total - cc->rolling_impulse;
      cc->rolling_impulse = total;
      wa -= ja * impulse;
      wb += jb * impulse;
    }
    sa->v = va;
    sa->w = wa;
    sb->v = vb;
    sb->w = wb;
  }
}

/* Newton's restitution on the points that approached faster than the
 * threshold and pushed during the step: v_n' = -e v_n(before). */
static void apply_restitution(tb_world* w, tb_step_context* ctx) {
  tb_solver_body* states = ctx->states;
  float threshold = ctx->restitution_threshold;
  for (int k = 0; k < w->step_contact_count; ++k) {
    tb_contact_constraint* cc = &w->constraints[k];
    if (cc->restitution == 0.0f) continue;
    tb_solver_body* sa = &states[cc->a];
    tb_solver_body* sb = &states[cc->b];
    tb_vec2 va = sa->v, vb = sb->v;
    float wa = sa->w, wb = sb->w;
    tb_vec2 n = cc->normal;
    for (int p = 0; p < cc->point_count; ++p) {
      tb_constraint_point* cp = &cc->points[p];
      if (cp->relative_velocity > -threshold || cp->max_normal_impulse == 0.0f) continue;
      tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
      float vn = tb_dot(dv, n);
      float impulse = -cp->normal_mass * (vn + cc->restitution * cp->relative_velocity);
      float total = cp->normal_impulse + impulse;
      if (total < 0.0f) total = 0.0f;
      impulse = total - cp->normal_impulse;
      cp->normal_impulse = total;
      tb_vec2 P = tb_scale(impulse, n);
      va = tb_mul_add(va, -cc->inv_mass_a, P);
      wa -= cc->inv_i_a * tb_cross(cp->ra, P);
      vb = tb_mul_add(vb, cc->inv_mass_b, P);
      wb += cc->inv_i_b * tb_cross(cp->rb, P);
    }
    sa->v = va;
    sa->w = wa;
    sb->v = vb;
    sb->w = wb;
  }
}

static void store_impulses(tb_world* w) {
  for (int k = 0; k < w->step_contact_count; ++k) {
    const tb_contact_constraint* cc = &w->constraints[k];
    tb_contact* c = (tb_contact*)tb_pool_at(&w->contacts, cc->contact);
    for (int p = 0; p < cc->point_count; ++p) {
      c->manifold.points[p].normal_impulse = cc->points[p].normal_impulse;
      c->manifold.points[p].tangent_impulse = cc->points[p].tangent_impulse;
    }
    c->rolling_impulse = cc->rolling_impulse;
  }
}

/* ---- the step ------------------------------------------------------------------ */

/* Joints of the awake bodies, each once (from its lower awake index). */
static bool collect_joints(tb_world* w) {
  w->step_joint_count = 0;
  for (int i = 0; i < w->awake_count; ++i) {
    for (int key = tb_body_at(w, w->awake[i])->joint_list; key >= 0;) {
      const tb_joint* j = tb_joint_at(w, key >> 1);
      int next = j->edges[key & 1].next;
      int other = tb_body_at(w, j->edges[(key & 1) ^ 1].body)->awake_index;
      if (other < 0 || other > i || (other == i && (key & 1) == 0)) {
        if (!tb_array_reserve((void**)&w->step_joints, &w->step_joint_capacity, w->step_joint_count + 1,
                              sizeof(int)))
          return false;
        w->step_joints[w->step_joint_count++] = key >> 1;
      }
      key = next;
    }
  }
  return true;
}

static tb_body_motion* motions_of(tb_world* w) {
  return (tb_body_motion*)(void*)(w->states + w->awake_count + 1);
}

/* Room for the solver bodies (+1 static dummy) and, after them, the motions. */
static bool reserve_scratch(tb_world* w) {
  int n = w->awake_count + 1;
  size_t per = sizeof(tb_solver_body) + sizeof(tb_body_motion);
  int need = (int)(((size_t)n * per + sizeof(tb_solver_body) - 1) / sizeof(tb_solver_body));
  if (!tb_array_reserve((void**)&w->states, &w->state_capacity, need, sizeof(tb_solver_body))) return false;
  return tb_array_reserve((void**)&w->constraints, &w->constraint_capacity, w->step_contact_count + 1,
                          sizeof(tb_contact_constraint));
}

/* Whether a body has a joint or a touching contact the solver handles. */
static bool has_constraints(const tb_world* w, int body) {
  const tb_body* b = tb_body_at(w, body);
  if (b->joint_count > 0) return true;
  for (int key = b->contact_list; key >= 0;) {
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, key >> 1);
    const uint32_t need = TB_CONTACT_TOUCHING | TB_CONTACT_ENABLED;
    if ((c->flags & need) == need && !(c->flags & TB_CONTACT_SENSOR)) return true;
    key = c->edges[key & 1].next;
  }
  return false;
}

int tb_solve(tb_world* w, float dt, int substeps) {
  if (!reserve_scratch(w) || !collect_joints(w)) return 0; /* out of memory: the step is skipped */
  int n = w->awake_count;
  float h = dt / (float)substeps;
  tb_step_context ctx = {0};
  ctx.dt = dt;
  ctx.inv_dt = 1.0f / dt;
  ctx.h = h;
  ctx.inv_h = 1.0f / h;
  ctx.substeps = substeps;
  float contact_hertz = fminf(w->contact_hertz, 0.25f * ctx.inv_h);
  ctx.contact_softness = tb_make_softness(contact_hertz, w->contact_damping_ratio, h);
  ctx.static_softness = tb_make_softness(2.0f * contact_hertz, w->contact_damping_ratio, h);
  ctx.joint_softness = tb_make_softness(w->joint_hertz, w->joint_damping_ratio, h);
  ctx.contact_push_max_velocity = w->contact_push_max_velocity;
  ctx.restitution_threshold = w->restitution_threshold;
  ctx.max_linear_speed = w->maximum_linear_speed;
  ctx.enable_warm_starting = w->enable_warm_starting;
  ctx.states = w->states;
  ctx.static_index = n;

  /* solver bodies and per-step motion terms */
  tb_body_motion* motions = motions_of(w);
  bool field = w->force_field != NULL;
  for (int i = 0; i < n; ++i) {
    tb_body* b = tb_body_at(w, w->awake[i]);
    bool dynamic = b->type == TB_DYNAMIC_BODY;
    w->states[i] = (tb_solver_body){b->linear_velocity, b->angular_velocity, dynamic ? b->inv_mass : 0.0f,
                                    dynamic ? b->inv_inertia : 0.0f, 0.0f, {0.0f, 0.0f}, {1.0f, 0.0f}};
    tb_body_motion* m = &motions[i];
    m->flags = 0;
    if (dynamic) {
      m->flags = MOTION_DYNAMIC | (field ? MOTION_FIELD : 0);
      m->accel = tb_mul_add(tb_scale(b->gravity_scale, w->gravity), b->inv_mass, b->force);
      m->alpha = b->inv_inertia * b->torque;
      m->linear_damping = 1.0f / (1.0f + h * b->linear_damping);
      m->angular_damping = 1.0f / (1.0f + h * b->angular_damping);
      if (!tb_vec_finite(m->accel) || !isfinite(m->alpha)) m->flags |= MOTION_FAULT | MOTION_FREE;
    }
  }
  w->states[n] = (tb_solver_body){{0.0f, 0.0f}, 0.0f, 0.0f, 0.0f, 0.0f, {0.0f, 0.0f}, {1.0f, 0.0f}};

  /* Midpoint and RK4 are for free flight: bodies without contacts or joints
   * this step use them; constrained bodies use the solver's symplectic Euler. */
  if (w->integrator != TB_INTEGRATOR_SEMI_IMPLICIT_EULER) {
    for (int i = 0; i < n; ++i) {
      if (!(motions[i].flags & MOTION_DYNAMIC) || has_constraints(w, w->awake[i])) continue;
      motions[i].flags |= MOTION_FREE;
    }
  }

  prepare_contacts(w, &ctx);
  for (int k = 0; k < w->step_joint_count; ++k) tb_joint_prepare(w, w->step_joints[k], &ctx);

  for (int sub = 0; sub < substeps; ++sub) {
    integrate_velocities(w, &ctx, motions, w->time + (double)sub * h);
    if (ctx.enable_warm_starting) {
      for (int k = 0; k < w->step_joint_count; ++k) tb_joint_warm_start(w, w->step_joints[k], &ctx);
      warm_start_contacts(w, &ctx);
    }
    for (int k = 0; k < w->step_joint_count; ++k) tb_joint_solve(w, w->step_joints[k], &ctx, true);
    solve_contacts(w, &ctx, true);
    integrate_positions(w, &ctx, motions);
    for (int k = 0; k < w->step_joint_count; ++k) tb_joint_solve(w, w->step_joints[k], &ctx, false);
    solve_contacts(w, &ctx, false);
  }
  apply_restitution(w, &ctx);
  store_impulses(w);
  for (int k = 0; k < w->step_joint_count; ++k) tb_joint_store(w, w->step_joints[k], &ctx);

  /* finish: positions from the step start plus the motion; sleep clocks */
  int bad = 0;
  for (int i = 0; i < n; ++i) {
    int index = w->awake[i];
    tb_body* b = tb_body_at(w, index);
    const tb_solver_body* s = &w->states[i];
    const tb_body_motion* m = &motions[i];
    b->center0 = b->center;
    b->angle0 = b->angle;
    b->is_fast = false;
    if (m->flags & MOTION_FREE) {
      bool ok = !(m->flags & MOTION_FAULT) && tb_integrate_free_body(w, index, dt, substeps);
      b->force = (tb_vec2){0.0f, 0.0f};
      b->torque = 0.0f;
      if (!ok) {
        bad += 1;
        continue;
      }
    } else {
      b->force = (tb_vec2){0.0f, 0.0f};
      b->torque = 0.0f;
      tb_vec2 c = tb_add(b->center, s->dp);
      float a = b->angle + s->da;
      if ((m->flags & MOTION_FAULT) || !tb_vec_finite(c) || !isfinite(a) || !tb_vec_finite(s->v) || !isfinite(s->w)) {
        bad += 1; /* contained: the body keeps its state from before the step */
        continue;
      }
      b->center = c;
      b->angle = a;
      b->linear_velocity = s->v;
      b->angular_velocity = s->w;
      tb_body_sync_transform(b);
    }
    tb_vec2 moved = tb_sub(b->center, b->center0);
    float turned = b->angle - b->angle0;
    if (w->enable_sleep && b->enable_sleep) {
      float speed = fmaxf(tb_length(b->linear_velocity), b->max_extent * fabsf(b->angular_velocity));
      b->sleep_time = speed > b->sleep_threshold ? 0.0f : b->sleep_time + dt;
    } else {
      b->sleep_time = 0.0f;
    }
    /* continuous collision for bodies that moved more than half their
     * thinnest part this step (slower ones are caught by speculative points) */
    if (w->enable_continuous && b->type == TB_DYNAMIC_BODY)
      b->is_fast = b->is_bullet || tb_length(moved) + b->max_extent * fabsf(turned) > 0.5f * b->min_extent;
  }
  return bad;
}
