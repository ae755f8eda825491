/* The ragdoll human (human.h). Heights are metres above the feet at scale 1;
 * each bone is a capsule along the body's y axis. Limits are in units of pi,
 * of the joint angle (bone angle - parent angle - reference). */
#include "human.h"

#include "scene_build.h"

typedef struct bone_spec {
  int parent;               /* -1: the root (hip) */
  float y;                  /* body origin */
  float y1, y2, radius;     /* capsule, body-local */
  float linear_damping;     /* 1/s */
  float friction_scale;     /* of the joint's friction torque */
  float pivot_y;            /* the joint's anchor */
  float lower_pi, upper_pi; /* limits / pi */
  float reference_pi;       /* reference angle / pi */
  bool foot;                /* the lower leg carries a foot */
} bone_spec;

static const bone_spec k_bones[HUMAN_BONES] = {
    /* hip */ {-1, 0.95f, -0.02f, 0.02f, 0.095f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, false},
    /* torso */ {0, 1.2f, -0.135f, 0.135f, 0.09f, 0.0f, 0.5f, 1.0f, -0.25f, 0.0f, 0.0f, false},
    /* head */ {1, 1.475f, -0.038f, 0.039f, 0.075f, 0.1f, 0.25f, 1.4f, -0.3f, 0.1f, 0.0f, false},
    /* upper left leg */ {0, 0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 1.0f, 0.9f, -0.05f, 0.4f, 0.0f, false},
    /* lower left leg */ {3, 0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 0.5f, 0.625f, -0.5f, -0.02f, 0.0f, true},
    /* upper right leg */ {0, 0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 1.0f, 0.9f, -0.05f, 0.4f, 0.0f, false},
    /* lower right leg */ {5, 0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 0.5f, 0.625f, -0.5f, -0.02f, 0.0f, true},
    /* upper left arm */ {1, 1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 0.5f, 1.35f, -0.1f, 0.8f, 0.0f, false},
    /* lower left arm */ {7, 0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 0.1f, 1.1f, -0.2f, 0.3f, 0.25f, false},
    /* upper right arm */ {1, 1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 0.5f, 1.35f, -0.1f, 0.8f, 0.0f, false},
    /* lower right arm */ {9, 0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 0.1f, 1.1f, -0.2f, 0.3f, 0.25f, false},
};

/* The foot: a rounded quadrilateral under the lower leg, pointing forward. */
static tb_polygon foot_polygon(float s) {
  const tb_vec2 points[4] = {
      {-0.03f * s, -0.185f * s}, {0.11f * s, -0.185f * s}, {0.11f * s, -0.16f * s}, {-0.03f * s, -0.14f * s}};
  tb_polygon foot = {0};
  tb_make_polygon(points, 4, 0.015f * s, &foot);
  return foot;
}

human human_create(tb_world_id world, tb_vec2 feet, float scale, float friction_torque, float spring_hertz,
                   float spring_damping_ratio, int group) {
  human h = {0};
  const float s = scale;
  tb_shape_def sd = shape_def(1.0f, 0.2f, 0.0f);
  sd.filter.group_index = -group;
  sd.filter.category_bits = 2u;
  sd.filter.mask_bits = 1u | 2u;
  tb_shape_def foot_def = sd;
  foot_def.friction = 0.05f;
  foot_def.filter.mask_bits = 1u; /* feet touch the ground, not other humans */
  tb_polygon foot = foot_polygon(s);

  for (int i = 0; i < HUMAN_BONES; ++i) {
    const bone_spec* b = &k_bones[i];
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.sleep_threshold = 0.1f;
    bd.linear_damping = b->linear_damping;
    bd.position = (tb_vec2){feet.x, feet.y + b->y * s};
    h.bones[i] = tb_create_body(world, &bd);
    tb_capsule capsule = {{0.0f, b->y1 * s}, {0.0f, b->y2 * s}, b->radius * s};
    tb_create_capsule_shape(h.bones[i], &sd, &capsule);
    if (b->foot) tb_create_polygon_shape(h.bones[i], &foot_def, &foot);
    if (b->parent < 0) continue;

    const float pivot_y = b->pivot_y * s;
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = h.bones[b->parent];
    jd.body_b = h.bones[i];
    jd.local_anchor_a = (tb_vec2){0.0f, pivot_y - k_bones[b->parent].y * s};
    jd.local_anchor_b = (tb_vec2){0.0f, pivot_y - b->y * s};
    jd.reference_angle = b->reference_pi * PI_F;
    jd.enable_limit = true;
    jd.lower_angle = b->lower_pi * PI_F;
    jd.upper_angle = b->upper_pi * PI_F;
    jd.enable_motor = true; /* at speed 0: joint friction */
    jd.max_motor_torque = b->friction_scale * friction_torque * s;
    jd.enable_spring = spring_hertz > 0.0f;
    jd.hertz = spring_hertz;
    jd.damping_ratio = spring_damping_ratio;
    h.joints[i] = tb_create_revolute_joint(world, &jd);
  }
  return h;
}

void human_destroy(human* h) {
  for (int i = 0; i < HUMAN_BONES; ++i) {
    if (!tb_joint_id_is_null(h->joints[i])) tb_destroy_joint(h->joints[i]);
    h->joints[i] = (tb_joint_id){0};
  }
  for (int i = 0; i < HUMAN_BONES; ++i) {
    if (!tb_body_id_is_null(h->bones[i])) tb_destroy_body(h->bones[i]);
    h->bones[i] = (tb_body_id){0};
  }
}
