/* Rigid bodies: state X (centre of mass), angle, V, w; mass properties. */
#ifndef TB_BODY_H
#define TB_BODY_H

#include "tumble.h"

typedef struct tb_body {
  tb_body_type type;
  /* Placement. The centre of mass and the angle are the integrated state; the
   * origin transform is derived from them: origin = center - R local_center. */
  tb_vec2 center;
  float angle;
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

  int shape_list; /* first shape index, -1 when none */
  int shape_count;
  int contact_list; /* first contact edge key (contact * 2 + side), -1 when none */
  int contact_count;
  void* user_data;
} tb_body;

struct tb_world;

/* Recomputes mass, centre and inertia from the shapes (parallel-axis theorem),
 * keeping the body origin fixed and the centre-of-mass velocity consistent. */
void tb_body_update_mass(struct tb_world* world, tb_body* body);
/* origin transform from centre of mass and angle */
void tb_body_sync_transform(tb_body* body);

#endif
