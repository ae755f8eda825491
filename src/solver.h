/* The soft-step solver's shared state: the awake bodies' solver data (one
 * contiguous array, indexed by the body's awake_index), soft-constraint
 * coefficients and the per-step context handed to contacts and joints. */
#ifndef TB_SOLVER_H
#define TB_SOLVER_H

#include <math.h>
#include <stdbool.h>

#include "math_internal.h"
#include "tumble.h"

/* What the solver moves: velocities plus the motion since the step began.
 * Positions are never summed into world coordinates inside the step, so a
 * scene at 65 km solves with the same precision as one at the origin. */
typedef struct tb_solver_body {
  tb_vec2 v;      /* linear velocity of the centre of mass */
  float w;        /* angular velocity */
  float inv_mass; /* 0 for static, kinematic */
  float inv_inertia;
  float da;   /* angle turned since the step began (exact scalar sum of h w) */
  tb_vec2 dp; /* displacement of the centre of mass since the step began */
  tb_rot dq;  /* rotation since the step began, as a unit complex number */
} tb_solver_body;

/* A soft constraint (Catto, "Solver2D"): a spring of frequency f and damping
 * ratio z over a substep h. With w = 2 pi f,
 *   bias_rate = w / (2 z + h w), mass_scale = h w (2 z + h w) / (1 + h w (2 z + h w)),
 *   impulse_scale = 1 / (1 + h w (2 z + h w)).
 * The impulse of a constraint with effective mass m, velocity error v_err and
 * position error C is  -m mass_scale (v_err + bias_rate C) - impulse_scale J_acc. */
typedef struct tb_softness {
  float bias_rate, mass_scale, impulse_scale;
} tb_softness;

tb_softness tb_make_softness(float hertz, float damping_ratio, float h);
/* The rigid limit (hertz 0 means rigid: no bias, full mass). */
static inline tb_softness tb_rigid_softness(void) { return (tb_softness){0.0f, 1.0f, 0.0f}; }

typedef struct tb_step_context {
  float dt, inv_dt; /* the whole step */
  float h, inv_h;   /* one substep */
  double exact_h;   /* dt / substeps in double (the angle's exact sum) */
  int substeps;
  float contact_hertz, static_hertz; /* dynamic against dynamic, against static/kinematic (after the cap) */
  float contact_damping_ratio;
  tb_softness contact_softness; /* dynamic against dynamic */
  tb_softness static_softness;  /* dynamic against static or kinematic: stiffer */
  tb_softness joint_softness;
  float contact_push_max_velocity;
  float restitution_threshold;
  float max_linear_speed;  /* the world's maximum_linear_speed */
  float max_angular_speed; /* a quarter turn per step: TB_QUARTER_TURN / dt */
  bool enable_warm_starting;
  /* Solver bodies: the awake bodies in awake order, then one static dummy
   * (zero velocity, zero inverse mass) at static_index that stands for every
   * body that is not awake (static, or asleep). */
  tb_solver_body* states;
  int static_index;
  /* (v.x, v.y, w) per solver body of the deep overlaps' push-out, added to
   * the velocity in the position update; NULL in a step without deep overlap */
  float* push_velocities;
  /* the position update moved the bodies since the contact solver last
   * measured how far they slid along their contacts (cleared by that) */
  bool bodies_moved;
  int position_updates; /* counts the position updates of this step */
  /* the relax passes' record of what still moves (relax_activity.h): per
   * solver body the last relax pass that changed it, and its reach (the
   * distance from its centre of mass to its farthest point) */
  int32_t* changed_in;
  const float* reach;
  int relax_pass;    /* the current relax pass, counted from 1 over the step */
  bool relax_all;    /* every constraint is solved in this relax pass (and nothing recorded) */
  bool relax_record; /* a later relax pass of this substep may read what this one records */
  int relax_solved;  /* contact blocks the last relax pass solved */
  bool four_lanes;   /* contacts four lanes at a time even where eight could be (tests' reference) */
  /* the world, for the contact solver's question whether a face runs on
   * (tb_contact_face_runs_on: a read of the broad phase and the bodies'
   * transforms, which stay the step start's during the substeps) */
  struct tb_world* world;
} tb_step_context;

/* The speed caps (tumble.h, maximum_linear_speed) hold for every moving body
 * on every path: the solver's velocity and position updates, free motion
 * under every integrator and its stages, kinematic bodies, and the velocities
 * a step leaves. At most a quarter turn per step: beyond it a corner can
 * swing through a thin wall between two collisions, and the sweep of the
 * continuous pass no longer describes the motion. */
#define TB_QUARTER_TURN 1.57079633f

/* v, shortened to max_speed when longer. A non-finite v is returned as it is
 * (the caller contains it); |v|^2 may overflow for a finite v, so the length
 * is then taken of v scaled by its largest component. */
static inline tb_vec2 tb_cap_linear_speed(tb_vec2 v, float max_speed) {
  float speed_sq = v.x * v.x + v.y * v.y;
  if (!(speed_sq > max_speed * max_speed) || !isfinite(v.x) || !isfinite(v.y)) return v;
  float scale;
  if (isfinite(speed_sq)) {
    scale = max_speed / sqrtf(speed_sq);
  } else {
    float big = tb_maxf(fabsf(v.x), fabsf(v.y));
    float ux = v.x / big, uy = v.y / big;
    scale = (max_speed / big) / sqrtf(ux * ux + uy * uy);
  }
  return (tb_vec2){scale * v.x, scale * v.y};
}

/* w within [-max, max]; a non-finite w is returned as it is. */
static inline float tb_cap_angular_speed(float w, float max_speed) {
  if (!isfinite(w)) return w;
  if (w > max_speed) return max_speed;
  if (w < -max_speed) return -max_speed;
  return w;
}

struct tb_world;
struct tb_body;

/* The solver index of a body: its awake_index, or the static dummy. */
int tb_solver_index(const struct tb_world* w, int body);

#endif
