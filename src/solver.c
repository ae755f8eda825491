/* The soft step (Catto, "Solver2D", and Box2D v3's design, written from their
 * published descriptions): collide once per step, then in each substep h
 *   integrate velocities -> warm start -> solve (soft, with position bias)
 *   -> integrate positions -> relax (solve again without bias, repeated until
 *   the velocities settle),
 * and after the substeps apply restitution and keep the impulses for the next
 * step's warm start (contact_solver.c holds the contact constraints, joint.c
 * the joints). Bodies move in delta positions from the step start and are
 * placed in world coordinates once, at the end. */
#include "solver.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "contact.h"
#include "joint.h"
#include "joint_wide.h"
#include "math_internal.h"
#include "memory.h"
#include "relax_activity.h"
#include "world.h"
#include "units.h"

tb_softness tb_make_softness(float hertz, float zeta, float h) {
  if (hertz == 0.0f) return tb_rigid_softness();
  float omega = TB_TWO_PI_F * hertz;
  float a1 = 2.0f * zeta + h * omega;
  float a2 = h * omega * a1;
  float a3 = 1.0f / (1.0f + a2);
  return (tb_softness){omega / a1, a2 * a3, a3};
}

int tb_solver_index(const tb_world* w, int body) {
  int i = tb_body_at(w, body)->awake_index;
  return i >= 0 ? i : w->awake_count;
}

/* Per awake body, per step: what the velocity integration adds (constant over
 * the step unless a force field is set). */
typedef struct tb_body_motion {
  tb_vec2 accel;        /* g s + F / M */
  float alpha;          /* T / I */
  float linear_damping; /* 1 / (1 + h c) */
  float angular_damping;
  int flags;
  /* the angle turned since the step began, as da but summed in double with
   * the exact substep dt / substeps: float da rounds once per substep (and
   * h = fl(dt / n) and h w round), which in a free spin adds up over the
   * steps; the body's angle takes this one (tb_body_turn). Kept here, not in
   * the solver body, whose layout the contact solver's gather reads. */
  double turned;
} tb_body_motion;

enum { MOTION_FIELD = 1, MOTION_FREE = 2, MOTION_FAULT = 4, MOTION_DYNAMIC = 8, MOTION_JOINTED = 16 };

/* ---- velocity and position integration ------------------------------------ */

static void integrate_velocities(tb_world* w, tb_step_context* ctx, tb_body_motion* motions, double t) {
  tb_solver_body* states = ctx->states;
  float h = ctx->h;
  for (int i = 0; i < w->awake_count; ++i) {
    tb_body_motion* m = &motions[i];
    if (!(m->flags & MOTION_DYNAMIC) || (m->flags & MOTION_FREE)) continue;
    tb_solver_body* s = &states[i];
    tb_vec2 accel = m->accel;
    float alpha = m->alpha;
    if (m->flags & MOTION_FIELD) { /* a force field: evaluated at the current state */
      int index = w->awake[i];
      const tb_body* b = tb_body_at(w, index);
      tb_body_state st = {tb_make_body_id(w, index),
                          tb_add(b->center, s->dp),
                          b->angle + s->da,
                          s->v,
                          s->w,
                          b->mass,
                          b->inertia,
                          b->user_data};
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
    s->v = tb_cap_linear_speed(v, ctx->max_linear_speed);
    s->w = tb_cap_angular_speed(av, ctx->max_angular_speed);
  }
}

static void integrate_positions(tb_world* w, tb_step_context* ctx, tb_body_motion* motions) {
  tb_solver_body* states = ctx->states;
  float h = ctx->h;
  for (int i = 0; i < w->awake_count; ++i) {
    if (motions[i].flags & MOTION_FREE) continue;
    tb_solver_body* s = &states[i];
    if (!(motions[i].flags & MOTION_JOINTED)) {
      /* A contact can speed a body up beyond the caps within the substep (it
       * spins a box that hits a wall at the speed cap): it moves within them,
       * or a corner swings through the wall. Not a jointed body: its joints
       * need their speeds (a limb swings faster than a quarter turn per long
       * step), and capping them mid-solve shook ragdolls apart at 15 Hz. */
      s->v = tb_cap_linear_speed(s->v, ctx->max_linear_speed);
      s->w = tb_cap_angular_speed(s->w, ctx->max_angular_speed);
    }
    tb_vec2 v = s->v;
    float omega = s->w;
    if (ctx->push_velocities) {
      const float* push = &ctx->push_velocities[4 * i];
      v = (tb_vec2){v.x + push[0], v.y + push[1]};
      omega += push[2];
    }
    s->dp = tb_mul_add(s->dp, h, v);
    float dw = h * omega;
    s->da += dw;
    motions[i].turned += ctx->exact_h * (double)omega;
    /* q <- normalise(q + h w perp(q)): the rotation the anchors see; the angle
     * itself is the exact scalar sum da */
    tb_rot q = {s->dq.c - dw * s->dq.s, s->dq.s + dw * s->dq.c};
    float inv = 1.0f / sqrtf(q.c * q.c + q.s * q.s);
    s->dq = (tb_rot){q.c * inv, q.s * inv};
  }
}

/* ---- the step ------------------------------------------------------------------ */

/* Joints of the awake bodies, each once (from its lower awake index). The
 * walk waits on every joint record and on each joint's other body, which lie
 * all over memory (9% of a joint grid's step); what it finds depends only on
 * the awake set and the bodies' joint lists, so it is kept (walked_joints)
 * until one of them changes (island.c, joint.c). */
static bool collect_joints(tb_world* w) {
  if (w->walked_joints_valid) {
    if (!tb_array_reserve((void**)&w->step_joints, &w->step_joint_capacity, w->walked_joint_count, sizeof(int)))
      return false;
    if (w->walked_joint_count > 0)
      memcpy(w->step_joints, w->walked_joints, (size_t)w->walked_joint_count * sizeof *w->step_joints);
    w->step_joint_count = w->walked_joint_count;
    return true;
  }
  w->step_joint_count = 0;
  for (int i = 0; i < w->awake_count; ++i) {
    for (int key = tb_body_at(w, w->awake[i])->joint_list; key >= 0;) {
      const tb_joint* j = tb_joint_at(w, key >> 1);
      int next = j->edges[key & 1].next;
      int other = tb_body_at(w, j->edges[(key & 1) ^ 1].body)->awake_index;
      if (other < 0 || other > i || (other == i && (key & 1) == 0)) {
        if (!tb_array_reserve((void**)&w->step_joints, &w->step_joint_capacity, w->step_joint_count + 1, sizeof(int)))
          return false;
        w->step_joints[w->step_joint_count++] = key >> 1;
      }
      key = next;
    }
  }
  if (tb_array_reserve((void**)&w->walked_joints, &w->walked_joint_capacity, w->step_joint_count, sizeof(int))) {
    if (w->step_joint_count > 0)
      memcpy(w->walked_joints, w->step_joints, (size_t)w->step_joint_count * sizeof *w->step_joints);
    w->walked_joint_count = w->step_joint_count;
    w->walked_joints_valid = true;
  } /* (out of memory: walked again next step) */
  return true;
}

/* Joints that a joint tree solves whole (a revolute joint with nothing but
 * its point: a chain's links, a pendulum's hinge) need only their warm start
 * and their store; no pass has a row of theirs to solve. They go to the end of
 * step_joints (tree_joint_count), in their order, out of the wide blocks and
 * the one-at-a-time passes: in the wide blocks, for their warm start only, a
 * pendulum's hinge spent 15% of its step building, warm-starting and
 * skipping its block. Their step info is not moved with them: nothing after
 * the wide build reads it. */
static void set_apart_tree_joints(tb_world* w) {
  int count = w->step_joint_count, kept = 0, apart = 0;
  w->tree_joint_count = 0;
  if (count == 0 || w->joints_one_at_a_time ||
      !tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, count, sizeof(int)))
    return; /* (out of memory: they stay in the passes, which solve them as well) */
  tb_step_joint* info = w->step_joint_info;
  for (int k = 0; k < count; ++k) {
    if (info[k].in_tree && info[k].point_only) {
      w->scratch[apart++] = w->step_joints[k];
      continue;
    }
    info[kept] = info[k];
    w->step_joints[kept++] = w->step_joints[k];
  }
  if (apart > 0) memcpy(w->step_joints + kept, w->scratch, (size_t)apart * sizeof *w->step_joints);
  w->tree_joint_count = apart;
}

/* Room for the solver bodies (+1 static dummy) and their motion terms. */
static bool reserve_scratch(tb_world* w) {
  int n = w->awake_count + 1;
  return tb_array_reserve((void**)&w->step_joint_info, &w->step_joint_info_capacity, w->step_joint_count,
                          sizeof(tb_step_joint)) &&
         tb_array_reserve((void**)&w->states, &w->state_capacity, n, sizeof(tb_solver_body)) &&
         tb_array_reserve(&w->motions, &w->motion_capacity, n, sizeof(tb_body_motion)) &&
         tb_array_reserve((void**)&w->changed_in, &w->changed_in_capacity, n + 1, sizeof(int32_t)) &&
         tb_array_reserve((void**)&w->reach, &w->reach_capacity, n, sizeof(float));
}

/* Contact stiffness. A soft contact point is a damped spring k = m_n omega^2
 * (m_n its effective mass) that sinks F / k under a force F. A column's
 * interfaces resist tilting with 2 k a^2 (points at +-a) while the toppling
 * moment grows with the weight above: at Box2D v3's 30 Hz a column of 1 m
 * boxes buckles slowly from about 12 boxes on. So contact_hertz (default 120)
 * is capped only at h omega = TB_CONTACT_MAX_H_OMEGA per substep (115 Hz at
 * 60 Hz and 4 substeps), where a point sinks F h^2 / (9 m_n), about 0.02 mm
 * per body weight on it at 60 Hz and 4 substeps. Stiffer still, the
 * contacts jitter. A stiff spring's bias leaves more velocity for the relax
 * pass to take out than one Gauss-Seidel pass can in a tall stack, which
 * then boils and buckles (stress suite: 30 boxes fall with one pass, stand
 * within 0.2 mm with up to 8); so the relax pass repeats, up to
 * relax_iterations times, while the last pass changed a point's normal speed
 * by more than TB_RELAX_TOLERANCE. A box resting on the ground needs no
 * second pass, a sliding one four (friction couples its two points); a
 * settled 30-box column's passes change speeds by float round-off (about
 * 6e-7 m/s) and stop after two. */
#define TB_CONTACT_MAX_H_OMEGA 3.0f
/* The drift correction of joints that close a loop (joint_hertz; trees are
 * solved exactly, joint_tree.c) is capped at the same h omega: a stiffer soft
 * row solved by Gauss-Seidel overshoots and feeds energy in. A ladder of ten
 * closed squares of bars at joint_hertz 1,000 Hz reached 150 m/s at 60 Hz and
 * 4 substeps (h omega = 26), 1,000 m/s with 64; capped at 3 it swings at
 * 27 m/s (24 m/s at the default 60 Hz); at 4, 75 m/s with 64 substeps, at 6,
 * 191. Softer is not safer: at 2 the ragdolls' limbs came apart at 1/30 s in
 * one substep. The default, h omega = 1.57 at 60 Hz and 4 substeps, is
 * below the cap and unchanged. */
#define TB_JOINT_MAX_H_OMEGA 3.0f

/* Sweep direction. Gauss-Seidel in one fixed order favours the constraints
 * solved first, and the colour order runs across a structure in the order
 * it was built: a symmetric pyramid of 100 rows got the same small sideways
 * share every pass, and its rows slid over each other until the top was
 * 1.2 m off centre. So the contact passes alternate direction (symmetric
 * Gauss-Seidel), and each substep starts in the direction opposite to the
 * last one's start: the pyramid's top stays within 2.4 cm, and a settled
 * structure needs fewer relax passes. */
static bool sweep_backward(int substep, int pass) { return ((substep + pass) & 1) != 0; }

/* A joint in a relax pass, when one of its bodies still moves (relax_activity.h). */
static void relax_joint(tb_world* w, tb_step_context* ctx, int index) {
  const tb_joint* j = tb_joint_at(w, index);
  int a = j->solver_a, b = j->solver_b;
  if (!tb_relax_active(ctx, a) && !tb_relax_active(ctx, b)) return;
  tb_solver_body before_a = ctx->states[a], before_b = ctx->states[b];
  tb_joint_solve(w, index, ctx, false);
  if (!ctx->relax_record) return;
  const tb_solver_body *sa = &ctx->states[a], *sb = &ctx->states[b];
  tb_relax_note(ctx, a, tb_relax_speed(ctx, a, tb_sub(sa->v, before_a.v), sa->w - before_a.w));
  tb_relax_note(ctx, b, tb_relax_speed(ctx, b, tb_sub(sb->v, before_b.v), sb->w - before_b.w));
}

/* One relax pass (pass 0, 1, ... of this substep): joints, contacts, the
 * joint trees, all without position bias; returns the contacts' largest
 * normal speed change. */
static float relax_pass(tb_world* w, tb_step_context* ctx, int substep, int pass) {
  ctx->relax_pass += 1;
  /* The first pass after a position update solves everything. Once a pass
   * has solved nearly every contact block, the record costs more than it
   * skips (a tumbling drum, a pyramid settling), and the substep's later
   * passes solve everything without it. */
  if (pass <= 1)
    ctx->relax_all = pass == 0;
  else if (!ctx->relax_all && (int64_t)ctx->relax_solved * 10 > (int64_t)w->wide_count * 9)
    ctx->relax_all = true;
  /* What this pass records is read by the next one only while that one
   * skips (not once every later pass solves everything), and only if there
   * is a next one: the passes repeat while a contact changes (a joint grid
   * without contacts relaxes once a substep, and its record of the joints'
   * bodies was 6% of its step). */
  ctx->relax_record = pass == 0 ? w->relax_iterations > 1 && w->wide_count > 0 : !ctx->relax_all;
  ctx->relax_solved = 0;
  bool joints = w->step_joint_count > 0; /* (calls that find nothing cost a small scene 3%) */
  for (int k = 0; k < w->scalar_joint_count; ++k) relax_joint(w, ctx, w->step_joints[k]);
  if (joints) tb_wide_joints_solve(w, ctx, false);
  float change = tb_contact_solver_solve(w, ctx, false, sweep_backward(substep, pass));
  if (joints) tb_joint_tree_solve(w, ctx, false);
  return change;
}

int tb_solve(tb_world* w, float dt, int substeps) {
  if (!collect_joints(w) || !reserve_scratch(w)) return 0; /* out of memory: the step is skipped */
  int n = w->awake_count;
  float h = dt / (float)substeps;
  tb_step_context ctx = {0};
  ctx.world = w;
  ctx.dt = dt;
  ctx.inv_dt = 1.0f / dt;
  ctx.h = h;
  ctx.inv_h = 1.0f / h;
  ctx.exact_h = (double)dt / (double)substeps;
  ctx.substeps = substeps;
  float most_hertz = TB_CONTACT_MAX_H_OMEGA / (TB_TWO_PI_F * h);
  ctx.contact_hertz = tb_minf(w->contact_hertz, most_hertz);
  ctx.static_hertz = tb_minf(2.0f * w->contact_hertz, most_hertz);
  ctx.contact_damping_ratio = w->contact_damping_ratio;
  ctx.contact_softness = tb_make_softness(ctx.contact_hertz, w->contact_damping_ratio, h);
  ctx.static_softness = tb_make_softness(ctx.static_hertz, w->contact_damping_ratio, h);
  ctx.joint_softness =
      tb_make_softness(tb_minf(w->joint_hertz, TB_JOINT_MAX_H_OMEGA / (TB_TWO_PI_F * h)), w->joint_damping_ratio, h);
  ctx.contact_push_max_velocity = w->contact_push_max_velocity;
  ctx.restitution_threshold = w->restitution_threshold;
  ctx.max_linear_speed = w->maximum_linear_speed;
  ctx.max_angular_speed = TB_QUARTER_TURN * ctx.inv_dt;
  ctx.enable_warm_starting = w->enable_warm_starting;
  ctx.states = w->states;
  ctx.static_index = n;
  ctx.changed_in = w->changed_in;
  ctx.reach = w->reach;
  ctx.four_lanes = w->contacts_four_lanes;

  /* solver bodies and per-step motion terms */
  tb_body_motion* motions = (tb_body_motion*)w->motions;
  bool field = w->force_field != NULL;
  for (int i = 0; i < n; ++i) {
    tb_body* b = tb_body_at(w, w->awake[i]);
    bool dynamic = b->type == TB_DYNAMIC_BODY;
    /* a kinematic body moves within the caps too (a dynamic one is capped
     * as its velocity is integrated) */
    tb_vec2 v = dynamic ? b->linear_velocity : tb_cap_linear_speed(b->linear_velocity, ctx.max_linear_speed);
    float omega = dynamic ? b->angular_velocity : tb_cap_angular_speed(b->angular_velocity, ctx.max_angular_speed);
    w->states[i] = (tb_solver_body){
        v, omega, dynamic ? b->inv_mass : 0.0f, dynamic ? b->inv_inertia : 0.0f, 0.0f, {0.0f, 0.0f}, {1.0f, 0.0f}};
    w->changed_in[i] = 0;
    w->reach[i] = b->max_extent;
    tb_body_motion* m = &motions[i];
    m->flags = b->joint_count > 0 ? MOTION_JOINTED : 0;
    m->turned = 0.0;
    if (dynamic) {
      m->flags |= MOTION_DYNAMIC | (field ? MOTION_FIELD : 0);
      m->accel = tb_mul_add(tb_body_gravity(w, b), b->inv_mass, b->force);
      m->alpha = b->inv_inertia * b->torque;
      m->linear_damping = 1.0f / (1.0f + h * b->linear_damping);
      m->angular_damping = 1.0f / (1.0f + h * b->angular_damping);
      if (!tb_vec_finite(m->accel) || !isfinite(m->alpha)) m->flags |= MOTION_FAULT | MOTION_FREE;
    }
  }
  w->states[n] = (tb_solver_body){{0.0f, 0.0f}, 0.0f, 0.0f, 0.0f, 0.0f, {0.0f, 0.0f}, {1.0f, 0.0f}};
  w->changed_in[n] = w->changed_in[n + 1] = 0; /* the static dummy's, and the sink of writes to skip */
  w->reach[n] = 0.0f;

  if (!tb_contact_solver_prepare(w, &ctx)) return 0; /* out of memory: the step is skipped */
  /* Midpoint and RK4 are for free flight: bodies without contacts or joints
   * this step use them; constrained bodies use the solver's symplectic Euler.
   * The prepare counted each moving body's contacts (contact_degree); a walk
   * of each body's contact list waited on a contact record per body (0.7% of
   * a pile's step). */
  if (w->integrator != TB_INTEGRATOR_SEMI_IMPLICIT_EULER) {
    const uint8_t* degree = w->contact_degree;
    for (int i = 0; i < n; ++i)
      if ((motions[i].flags & (MOTION_DYNAMIC | MOTION_JOINTED)) == MOTION_DYNAMIC && degree[i] == 0)
        motions[i].flags |= MOTION_FREE;
  }
  for (int k = 0; k < w->step_joint_count; ++k) {
    /* The joint records and their bodies lie all over memory (a grid's
     * joints were 11% of its step, waiting on them): ask for the record
     * eight joints ahead, and for the bodies of the one four ahead, whose
     * record was asked for four joints ago. */
    if (k + 8 < w->step_joint_count) {
      const char* r = (const char*)tb_joint_at(w, w->step_joints[k + 8]);
      for (size_t line = 0; line < sizeof(tb_joint); line += 64) __builtin_prefetch(r + line);
    }
    if (k + 4 < w->step_joint_count) {
      const tb_joint* ahead = tb_joint_at(w, w->step_joints[k + 4]);
      __builtin_prefetch(tb_body_at(w, ahead->edges[0].body));
      __builtin_prefetch(tb_body_at(w, ahead->edges[1].body));
    }
    int index = w->step_joints[k];
    tb_joint_prepare(w, index, &ctx);
    const tb_joint* j = tb_joint_at(w, index);
    w->step_joint_info[k] = (tb_step_joint){.solver_a = j->solver_a,
                                            .solver_b = j->solver_b,
                                            .rigid_rows = (int8_t)(j->skip ? 0 : tb_joint_rigid_row_count(j)),
                                            .wide = tb_wide_joint_fits(j, &ctx),
                                            .point_only = tb_joint_point_only(j)};
  }
  if (!tb_joint_tree_build(w, &ctx)) { /* out of memory: Gauss-Seidel solves every joint */
    for (int k = 0; k < w->step_joint_count; ++k) {
      tb_joint_at(w, w->step_joints[k])->in_tree = false;
      w->step_joint_info[k].in_tree = false;
    }
    w->joint_tree.node_count = 0;
  }
  set_apart_tree_joints(w);
  tb_wide_joints_build(w, &ctx);
  const int* tree_joints = /* (step_joints is null in a world that never had a joint) */
      w->tree_joint_count > 0 ? w->step_joints + (w->step_joint_count - w->tree_joint_count) : NULL;

  /* (the joint calls of a step without joints find nothing: 2% of a
   * one-contact scene's instructions) */
  bool joints = w->step_joint_count > 0;
  for (int sub = 0; sub < substeps; ++sub) {
    integrate_velocities(w, &ctx, motions, w->time + (double)sub * h);
    if (ctx.enable_warm_starting) {
      for (int k = 0; k < w->scalar_joint_count; ++k) tb_joint_warm_start(w, w->step_joints[k], &ctx);
      for (int k = 0; k < w->tree_joint_count; ++k) tb_joint_warm_start_point(tb_joint_at(w, tree_joints[k]), &ctx);
      if (joints) tb_wide_joints_warm_start(w, &ctx);
      tb_contact_solver_warm_start(w, &ctx);
    } else {
      tb_contact_solver_reset(w);
      for (int k = 0; k < w->tree_joint_count; ++k) tb_joint_zero_impulses(tb_joint_at(w, tree_joints[k]));
    }
    for (int k = 0; k < w->scalar_joint_count; ++k) tb_joint_solve(w, w->step_joints[k], &ctx, true);
    if (joints) tb_wide_joints_solve(w, &ctx, true);
    tb_contact_solver_solve(w, &ctx, true, sweep_backward(sub, 0));
    if (joints) tb_joint_tree_solve(w, &ctx, true);
    tb_contact_solver_push_out(w, &ctx);
    integrate_positions(w, &ctx, motions);
    ctx.bodies_moved = true;
    ctx.position_updates += 1;
    float change = relax_pass(w, &ctx, sub, 0);
    for (int pass = 1; pass < w->relax_iterations && change > TB_RELAX_TOLERANCE; ++pass)
      change = relax_pass(w, &ctx, sub, pass);
    if (joints) tb_joint_tree_store(w);
  }
  w->profile.relax_pass_count = ctx.relax_pass;
  tb_contact_solver_finish(w, &ctx);
  if (joints) tb_wide_joints_store(w, &ctx);
  for (int k = 0; k < w->scalar_joint_count; ++k) tb_joint_store(w, w->step_joints[k], &ctx);
  for (int k = 0; k < w->tree_joint_count; ++k) tb_joint_store(w, tree_joints[k], &ctx);

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
      bool ok = !(m->flags & MOTION_FAULT) && tb_integrate_free_body(w, index, &ctx);
      b->force = (tb_vec2){0.0f, 0.0f};
      b->torque = 0.0f;
      if (!ok) {
        bad += 1;
        continue;
      }
    } else {
      b->force = (tb_vec2){0.0f, 0.0f};
      b->torque = 0.0f;
      /* compensated: c + residual = center + (residual + dp) exactly */
      tb_vec2 residual;
      tb_vec2 c = tb_two_sum(b->center, tb_add(b->center_residual, s->dp), &residual);
      float angle_residual = b->angle_residual;
      float a = tb_body_turn(b->angle, &angle_residual, m->turned);
      if ((m->flags & MOTION_FAULT) || !tb_vec_finite(c) || !isfinite(a) || !tb_vec_finite(s->v) || !isfinite(s->w)) {
        bad += 1; /* contained: the body keeps its state from before the step */
        continue;
      }
      b->center = c;
      b->center_residual = residual;
      b->angle = a;
      b->angle_residual = angle_residual;
      /* restitution and the relax passes came after the last cap */
      b->linear_velocity = tb_cap_linear_speed(s->v, ctx.max_linear_speed);
      b->angular_velocity = tb_cap_angular_speed(s->w, ctx.max_angular_speed);
      tb_body_sync_transform(b);
    }
    tb_vec2 moved = tb_sub(b->center, b->center0);
    float turned = b->angle - b->angle0;
    if (w->enable_sleep && b->enable_sleep) {
      float speed = tb_maxf(tb_length(b->linear_velocity), b->max_extent * fabsf(b->angular_velocity));
      /* a kinematic body moves by script: while it moves at all it stays
       * awake (a shapeless one spinning has no extent, yet its joints turn) */
      bool scripted = b->type == TB_KINEMATIC_BODY && (speed > 0.0f || b->angular_velocity != 0.0f);
      b->sleep_time = speed > b->sleep_threshold || scripted ? 0.0f : b->sleep_time + dt;
    } else {
      b->sleep_time = 0.0f;
    }
    /* continuous collision for bodies that moved more than half their
     * thinnest part, or more than the speculative distance, this step: the
     * speculative points of slower ones stop them at the surface, faster ones
     * would sink into static geometry before the contact catches them */
    if (w->enable_continuous && b->type == TB_DYNAMIC_BODY)
      b->is_fast = b->is_bullet || tb_length(moved) + b->max_extent * fabsf(turned) >
                                       tb_minf(0.5f * b->min_extent, tb_units.speculative_distance);
  }
  return bad;
}

/* ---- memory ------------------------------------------------------------- */

size_t tb_solver_bytes(const tb_world* w) {
  return (size_t)w->state_capacity * sizeof *w->states + (size_t)w->motion_capacity * sizeof(tb_body_motion) +
         (size_t)w->changed_in_capacity * sizeof *w->changed_in + (size_t)w->reach_capacity * sizeof *w->reach;
}

void tb_solver_free(tb_world* w) {
  tb_mem_free(w->states, (size_t)w->state_capacity * sizeof *w->states);
  tb_mem_free(w->motions, (size_t)w->motion_capacity * sizeof(tb_body_motion));
  tb_mem_free(w->changed_in, (size_t)w->changed_in_capacity * sizeof *w->changed_in);
  tb_mem_free(w->reach, (size_t)w->reach_capacity * sizeof *w->reach);
}
