/* A ragdoll human of eleven capsule bones on ten revolute joints, built as
 * Box2D v3's benchmark builds its humans (its shared/human.c): the rain scene
 * of v3's benchmark drops rows of them. Private to demos/scenes/. */
#ifndef TUMBLE_HUMAN_H
#define TUMBLE_HUMAN_H

#include "tumble.h"

#define HUMAN_BONES 11

typedef struct human {
  tb_body_id bones[HUMAN_BONES];   /* hip, torso, head, legs (upper, lower; left, right), arms likewise */
  tb_joint_id joints[HUMAN_BONES]; /* joints[i] joins bone i to its parent; joints[0] is null */
} human;

/* A human standing with its feet at `feet` (scale 1: 1.6 m tall). Its joints
 * resist with friction_torque * scale (a motor at speed 0, scaled per joint)
 * and a spring of spring_hertz / spring_damping_ratio towards the rest pose
 * (none when spring_hertz is 0). group > 0: the bones of one human never
 * collide with each other (filter group -group); feet touch only the ground
 * (category 1). */
human human_create(tb_world_id world, tb_vec2 feet, float scale, float friction_torque, float spring_hertz,
                   float spring_damping_ratio, int group);
/* Destroys the joints, then the bones. */
void human_destroy(human* h);

#endif /* TUMBLE_HUMAN_H */
