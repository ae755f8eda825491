/* Rigid bodies: state X (centre of mass), angle, V, w; mass properties. */
#ifndef TB_BODY_H
#define TB_BODY_H

#include "tumble.h"

typedef struct tb_body {
  tb_body_type type;
  /* Placement. The centre of mass and the angle are the integrated state; the
   * origin transform is derived from them: origin = center - R local_center. */
  tb_vec2 center;
  /* What the float center cannot hold of the true centre (compensated
   * summation, |residual| <= half a float step of center): far from the origin
   * a step's displacement is often below that step (0.49 mm at 8 km), and
   * rounding it away every step would freeze slow bodies and make the scene
   * solve differently from one at the origin. Zero wherever the centre is set. */
  tb_vec2 center_residual;
  float angle;
  /* The same for the angle (|residual| <= half a float step of angle): a
   * spin's turn per step, added to the float angle, would round once per
   * step (2e-5 rad after 2 s at 3 rad/s); with the residual the angle is the
   * float nearest the exact sum. Zero wherever the angle is set. */
  float angle_residual;
  tb_transform transform;
  tb_vec2 local_center;

  /* Kinematics and dynamics. */
  tb_vec2 linear_velocity; /* of the centre of mass */
  float angular_velocity;
  tb_vec2 force; /* accumulated at the centre of mass for the next step */
  float torque;
  float mass, inv_mass;
  float inertia, inv_inertia; /* about the centre of mass; 0 inverse = infinite */

  float linear_damping, angular_damping, gravity_scale;
  bool fixed_rotation;
  bool enabled;
  bool mass_overridden; /* set by tb_body_set_mass_data until the shapes change */
  bool is_bullet;
  bool enable_sleep;
  bool is_fast; /* moved far for its size last step: swept by the continuous pass */

  /* Sleep and the awake set. awake_index is the body's place in world->awake
   * (and its solver body); -1 when static, disabled or asleep. A sleeping body
   * belongs to a sleeping island (sleep_island >= 0), linked by island_next. */
  int awake_index;
  int sleep_island;
  int island_next;
  float sleep_time;      /* seconds spent below sleep_threshold */
  float sleep_threshold; /* m/s */
  float max_extent;      /* largest distance from the centre of mass to a shape's surface */
  float min_extent;      /* smallest half-thickness of its shapes (continuous collision) */
  tb_vec2 center0;       /* centre and angle when the step began (continuous collision) */
  float angle0;

  int shape_list; /* first shape index, -1 when none */
  int shape_count;
  int contact_list; /* first contact edge key (contact * 2 + side), -1 when none */
  int contact_count;
  int new_contact_count; /* contacts at the head of the list that tb_contacts_sort_new has yet to sort */
  int joint_list;        /* first joint edge key (joint * 2 + side), -1 when none */
  int joint_count;
  void* user_data;
} tb_body;

struct tb_world;
struct tb_shape;

/* Recomputes mass, centre and inertia from the shapes (parallel-axis theorem),
 * keeping the body origin fixed and the centre-of-mass velocity consistent. */
void tb_body_update_mass(struct tb_world* world, tb_body* body);
/* tb_body_update_mass after `shape` joined the body's shapes: the same, in
 * time independent of its other shapes where the body has no mass. */
void tb_body_add_shape_mass(struct tb_world* world, tb_body* body, const struct tb_shape* shape);
/* angle + *residual + turned, rounded to the nearest float; *residual gets
 * what the rounding dropped (the sum is formed in double: exact to far below
 * a float step for any angle within the accepted 1e6 rad). */
static inline float tb_body_turn(float angle, float* residual, double turned) {
  double exact = (double)angle + (double)*residual + turned;
  float rounded = (float)exact;
  *residual = (float)(exact - (double)rounded);
  return rounded;
}
/* origin transform from centre of mass and angle */
void tb_body_sync_transform(tb_body* body);
/* The gravity the body feels: gravity_scale times the world's, no longer
 * than TB_MAX_GRAVITY. */
tb_vec2 tb_body_gravity(const struct tb_world* world, const tb_body* body);
/* Keeps a body that moved inside the world: its origin and its shapes within
 * TB_MAX_LENGTH on each axis. A body past the edge is moved back onto it and
 * loses its velocity outwards. Call before its proxies are updated. */
void tb_body_keep_in_world(tb_body* body);

#endif
