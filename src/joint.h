/* Joints: the pool, body joint lists and the constraint functions the solver
 * calls (prepare once per step, then warm start and solve in each substep). */
#ifndef TB_JOINT_H
#define TB_JOINT_H

#include "solver.h"
#include "tumble.h"

typedef struct tb_joint_edge {
  int body;
  int prev, next; /* edge keys (joint * 2 + side) in the body's list, -1 at the ends */
} tb_joint_edge;

typedef struct tb_joint {
  tb_joint_type type;
  tb_joint_edge edges[2]; /* [0] body A, [1] body B */
  bool collide_connected;
  void* user_data;
  /* the joint module's own fields follow (type parameters, solver scratch, impulses) */

  /* Definition. Anchors are relative to each body's origin. */
  tb_vec2 local_anchor_a, local_anchor_b;
  tb_vec2 local_axis_a;                       /* prismatic, wheel: unit axis in A */
  float reference_angle;                      /* revolute, prismatic, weld; motor joint: angular_offset */
  float length;                               /* distance: rest length */
  float lower, upper;                         /* limits: angle, translation, or min/max length */
  float hertz, damping_ratio;                 /* the spring (weld: linear; mouse: its pull) */
  float angular_hertz, angular_damping_ratio; /* weld */
  float motor_speed;
  float max_motor;         /* force (N) or torque (N m) of the motor */
  float max_force;         /* mouse, motor joint */
  float max_torque;        /* motor joint */
  float correction_factor; /* motor joint */
  tb_vec2 target;          /* mouse: world target */
  bool enable_spring, enable_limit, enable_motor;

  /* Accumulated impulses of the last substep, kept for warm starting. */
  tb_vec2 linear_impulse; /* point constraints (revolute, weld, mouse, motor joint) */
  float angular_impulse;  /* weld, prismatic, motor joint */
  float axial_impulse;    /* distance: rigid length; prismatic, wheel: perpendicular */
  float spring_impulse, motor_impulse, lower_impulse, upper_impulse;
  float last_h; /* substep of the impulses (rescaled when the step size changes) */

  /* Step scratch, set by tb_joint_prepare. */
  int solver_a, solver_b;   /* indices into ctx->states */
  bool skip;                /* no dynamic body, or a body is disabled */
  bool in_tree;             /* its rigid rows are solved exactly by joint_tree.c */
  tb_vec2 frame_a, frame_b; /* anchors relative to the centres, world axes, step start */
  tb_vec2 delta_center;     /* centre of B minus centre of A (mouse: minus target) */
  float delta_angle;        /* angle_b - angle_a - reference angle at step start */
  tb_vec2 axis;             /* world axis of A at step start */
  tb_softness spring_softness, angular_softness;
  float correction_rate; /* motor joint: bias per unit error per second */

  /* What the getters report about the last step. */
  tb_vec2 force;
  float torque;
  float motor_output; /* motor torque (N m) or force (N) */
} tb_joint;

/* What the step's later passes need of a step joint (joint_tree.c,
 * joint_wide.c), kept compact beside the step joints so that those passes
 * do not read the 256-byte joint records again. Filled after prepare. */
typedef struct tb_step_joint {
  int32_t solver_a, solver_b;
  int8_t rigid_rows; /* tb_joint_rigid_row_count, 0 for a skipped joint */
  bool wide;         /* joint_wide.c takes it (tb_wide_joint_fits) */
  bool in_tree;      /* set by tb_joint_tree_build */
  bool point_only;   /* a revolute joint without spring, motor or limit (tb_joint_point_only) */
} tb_step_joint;

struct tb_world;

/* Removes every joint of a body (when the body is destroyed). */
void tb_joints_destroy_of_body(struct tb_world* w, int body);
/* false when a joint with collide_connected == false links the two bodies. */
bool tb_joints_allow_collision(const struct tb_world* w, int body_a, int body_b);

/* Solver entry points, for joints with at least one awake body.
 * prepare: anchors, effective masses, softness (once per step);
 * warm_start: apply the accumulated impulses (each substep);
 * solve: one iteration; use_bias = false in the relax pass;
 * store: after the substeps, keep what the getters report. */
void tb_joint_prepare(struct tb_world* w, int joint, tb_step_context* ctx);
void tb_joint_warm_start(struct tb_world* w, int joint, tb_step_context* ctx);
/* tb_joint_warm_start of a joint with nothing but its point (tb_joint_point_only). */
void tb_joint_warm_start_point(const tb_joint* j, tb_step_context* ctx);
void tb_joint_solve(struct tb_world* w, int joint, tb_step_context* ctx, bool use_bias);
/* The rigid rows of a joint (the parts the world's joint softness holds, at
 * most three), for the exact solve of joint trees (joint_tree.c). Row r has
 * velocity Cdot_r = jb[r] . (vB, wB) - ja[r] . (vA, wA) and position error c[r];
 * its accumulated impulse is *impulse[r] of tb_joint_rigid_rows (applied as
 * +jb on B, -ja on A; apart, because the tree's passes never read them). */
typedef struct tb_rigid_rows {
  int count;
  int point; /* the first of the point's two rows (x, then y), -1 without a point */
  float ja[3][3], jb[3][3];
  float c[3];
} tb_rigid_rows;
/* How many rigid rows the joint has (0: none, e.g. a mouse or motor joint). */
int tb_joint_rigid_row_count(const tb_joint* j);
void tb_joint_rigid_rows(tb_joint* j, const tb_solver_body* a, const tb_solver_body* b, tb_rigid_rows* out,
                         float* impulse[3]);
/* A joint's arms ra, rb (anchor minus centre, world axes) and anchor gap d
 * (B minus A) now, from its anchors and the centres' offset at the step start
 * (tb_joint's frame_a, frame_b, delta_center), the bodies moved since by dp
 * and turned by dq. Inline: the joint trees build a point's rows from it in
 * their hot loop (a call there cost 1.5% of a ragdoll scene). */
static inline void tb_joint_arms(tb_vec2 frame_a, tb_vec2 frame_b, tb_vec2 delta_center, const tb_solver_body* a,
                                 const tb_solver_body* b, tb_vec2* ra, tb_vec2* rb, tb_vec2* d) {
  *ra = tb_rotate(a->dq, frame_a);
  *rb = tb_rotate(b->dq, frame_b);
  *d = tb_add(tb_add(tb_sub(b->dp, a->dp), delta_center), tb_sub(*rb, *ra));
}
/* A point's two rows, x then y, from row out->count on (out->point their
 * first): unit directions, the arms' levers and the gap. */
static inline void tb_joint_add_point_rows(tb_rigid_rows* out, tb_vec2 ra, tb_vec2 rb, tb_vec2 d) {
  int r = out->count;
  out->point = r;
  out->count = r + 2;
  out->ja[r][0] = out->jb[r][0] = 1.0f;
  out->ja[r][1] = out->jb[r][1] = 0.0f;
  out->ja[r][2] = -ra.y;
  out->jb[r][2] = -rb.y;
  out->c[r] = d.x;
  out->ja[r + 1][0] = out->jb[r + 1][0] = 0.0f;
  out->ja[r + 1][1] = out->jb[r + 1][1] = 1.0f;
  out->ja[r + 1][2] = ra.x;
  out->jb[r + 1][2] = rb.x;
  out->c[r + 1] = d.y;
}
void tb_joint_store(struct tb_world* w, int joint, const tb_step_context* ctx);
/* A revolute joint with nothing but its point: no spring, motor or limit
 * (its other impulses are zero, tb_joint_prepare). */
bool tb_joint_point_only(const tb_joint* j);
/* Zeroes the accumulated impulses, as a biased solve does without warm
 * starting (for joints that no solve pass reaches but a joint tree's). */
void tb_joint_zero_impulses(tb_joint* j);
/* tb_joint_store of a revolute joint with nothing but its point, whose
 * accumulated impulse the wide joints kept (joint_wide.c). */
void tb_joint_store_point(tb_joint* j, tb_vec2 impulse, const tb_step_context* ctx);

#endif
