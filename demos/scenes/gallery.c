/* The demo scenes of the gallery (issue 5): small scenes chosen to look good
 * and to show one feature each. Public tumble API only; the catalogue
 * (scenes.c) lists them with their description, bounds and steps. Unless a
 * builder says otherwise: density 1 kg/m^2, friction 0.6, restitution 0,
 * gravity (0, -10). Update hooks keep no state of their own: what they do
 * follows from the step index and from the world (tagged bodies), so that any
 * number of worlds can run the same scene. */
#include "gallery.h"

#include <stddef.h>
#include <string.h>

#include "scene_build.h"
#include "scenes.h"

/* ----------------------------------------------------------- bullet_block -- */

/* The lecture's bullet-block experiment (a bullet fired up into a wooden block,
 * through its centre or off it: which block flies higher?). Two identical
 * blocks (1 m, half 0.5, density 1: 1 kg) rest on two thin static pillars each
 * (tops at y = 3, the blocks' centres at (-3, 3.5) "block_center" and (3, 3.5)
 * "block_offset"). A bullet of 0.01 kg (circle radius 0.05, is_bullet) starts
 * 2 m below each block's bottom face at 500 m/s straight up, through the gap
 * between the pillars: "bullet_center" at the block's centre line,
 * "bullet_offset" 0.25 m to its right. The bullet lodges in the block (the
 * update hook welds it there once it has lost half its speed), so the block
 * and bullet share the bullet's momentum m v = 5 N s: both rise by
 * (m v / (M + m))^2 / 2 g = 1.2 m, and the off-centre one spins with the
 * angular momentum r x m v = 1.25 N m s about its centre of mass. */
#define BULLET_SPEED 500.0f
static const char* const k_bullet_tags[2] = {"bullet_center", "bullet_offset"};
static const char* const k_block_tags[2] = {"block_center", "block_offset"};

void build_bullet_block(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 10.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  const float xs[2] = {-3.0f, 3.0f}, offsets[2] = {0.0f, 0.25f};
  const float bullet_radius = 0.05f;
  tb_shape_def bullet = shape_def(0.01f / (PI_F * bullet_radius * bullet_radius), 0.6f, 0.0f);
  for (int k = 0; k < 2; ++k) {
    /* pillars 0.08 m wide under the block's outer edges: the gap between them
     * (x - 0.42 .. x + 0.42) leaves both bullets' paths clear */
    add_offset_box(g, &sd, 0.04f, 1.5f, xs[k] - 0.46f, 1.5f, 0.0f);
    add_offset_box(g, &sd, 0.04f, 1.5f, xs[k] + 0.46f, 1.5f, 0.0f);
    tb_body_id block = body_at(world, TB_DYNAMIC_BODY, xs[k], 3.5f, 0.0f, k_block_tags[k]);
    add_box(block, &sd, 0.5f, 0.5f);
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = (tb_vec2){xs[k] + offsets[k], 1.0f};
    bd.linear_velocity = (tb_vec2){0.0f, BULLET_SPEED};
    bd.is_bullet = true;
    bd.user_data = (void*)k_bullet_tags[k];
    tb_body_id b = tb_create_body(world, &bd);
    add_circle(b, &bullet, bullet_radius);
  }
}

void update_bullet_block(tb_world_id world, int step) {
  (void)step;
  for (int k = 0; k < 2; ++k) {
    tb_body_id bullet = tb_scene_find_body(world, k_bullet_tags[k]);
    if (tb_body_get_joint_count(bullet) > 0) continue; /* already lodged */
    if (tb_body_get_linear_velocity(bullet).y > 0.5f * BULLET_SPEED) continue;
    tb_body_id block = tb_scene_find_body(world, k_block_tags[k]);
    tb_weld_joint_def wd = tb_default_weld_joint_def();
    wd.body_a = block;
    wd.body_b = bullet;
    wd.local_anchor_a = tb_body_get_local_point(block, tb_body_get_position(bullet));
    wd.reference_angle = tb_body_get_angle(bullet) - tb_body_get_angle(block);
    tb_create_weld_joint(world, &wd);
  }
}

/* ------------------------------------------------------------- card_house -- */

/* A house of cards, 4 storeys: storey i (from 0 at the bottom) has 4 - i
 * A-frames 1.1 m apart, each two cards (1.2 x 0.06 m, density 1, friction
 * 0.9) leaning 20 degrees from the vertical with their top inner corners
 * touching at the apex; a flat card spans each pair of neighbouring apexes and
 * carries the A-frame of the storey above. The left card of the top A-frame is
 * "card_top". A leaning card needs mu >= tan(20 deg) / 2 = 0.18 at its foot.
 * The house is touchy, like a real one: it settles and sleeps within 1 s at
 * 20 degrees, but the top storeys fall at 15 and 25 degrees. */
void build_card_house(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 6.0f, 1.0f);
  (void)g;
  const int storeys = 4;
  const float half_length = 0.6f, half_thick = 0.03f, spacing = 1.1f;
  const float lean = 20.0f * PI_F / 180.0f, sl = sinf(lean), cl = cosf(lean);
  tb_shape_def sd = shape_def(1.0f, 0.9f, 0.0f);
  float y0 = 0.0f;
  for (int i = 0; i < storeys; ++i) {
    int frames = storeys - i;
    /* the highest points of a leaning card are its top outer corner, 2 t sin
     * above the apex: the flat cards rest on those */
    float top_y = y0 + 2.0f * half_length * cl + 2.0f * half_thick * sl;
    for (int j = 0; j < frames; ++j) {
      float ax = ((float)j - 0.5f * (float)(frames - 1)) * spacing;
      /* the card's inner top corner at the apex, its lowest corner on y0 */
      float dx = half_length * sl + half_thick * cl;
      float cy = y0 + half_length * cl + half_thick * sl;
      const char* tag = i == storeys - 1 ? "card_top" : NULL;
      tb_body_id left = body_at(world, TB_DYNAMIC_BODY, ax - dx, cy, -lean, tag);
      add_box(left, &sd, half_thick, half_length);
      tb_body_id right = body_at(world, TB_DYNAMIC_BODY, ax + dx, cy, lean, NULL);
      add_box(right, &sd, half_thick, half_length);
      if (j + 1 < frames) {
        tb_body_id flat = body_at(world, TB_DYNAMIC_BODY, ax + 0.5f * spacing, top_y + half_thick, 0.0f, NULL);
        add_box(flat, &sd, half_length, half_thick);
      }
    }
    y0 = top_y + 2.0f * half_thick;
  }
}

/* ------------------------------------------------------- pendulums -- */

/* A rod (a box 0.1 m thick) with a bob (circle radius 0.3, density 5) at its
 * far end, from body-local (0, 0) to (length, 0); the body origin is the pin. */
static tb_body_id pendulum_link(tb_world_id world, float x, float y, float length, const char* tag) {
  tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, tag);
  tb_shape_def rod = shape_def(1.0f, 0.6f, 0.0f);
  add_offset_box(b, &rod, 0.5f * length, 0.05f, 0.5f * length, 0.0f, 0.0f);
  tb_shape_def bob = shape_def(5.0f, 0.6f, 0.0f);
  tb_circle c = {{length, 0.0f}, 0.3f};
  tb_create_circle_shape(b, &bob, &c);
  return b;
}

static void pin(tb_world_id world, tb_body_id a, tb_vec2 anchor_a, tb_body_id b) {
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = a;
  jd.body_b = b;
  jd.local_anchor_a = anchor_a;
  jd.local_anchor_b = (tb_vec2){0.0f, 0.0f};
  tb_create_revolute_joint(world, &jd);
}

/* pendulum: a 4 m rod-and-bob pendulum ("pendulum") pinned at (0, 9) to a
 * static bracket, released horizontal (pointing to +x) from rest. */
void build_pendulum(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 6.0f, 1.0f);
  tb_body_id bracket = body_at(world, TB_STATIC_BODY, 0.0f, 9.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(bracket, &sd, 0.6f, 0.1f, 0.0f, 0.2f, 0.0f);
  tb_body_id link = pendulum_link(world, 0.0f, 9.0f, 4.0f, "pendulum");
  pin(world, bracket, (tb_vec2){0.0f, 0.0f}, link);
}

/* double_pendulum: two 3 m rod-and-bob links, the first ("link_1") pinned at
 * (0, 9), the second ("link_2") pinned to the first's bob, both released
 * horizontal from rest. The links do not collide with each other (joined
 * bodies never do) and the bobs miss the ground (6.6 m of reach, 9 m up). */
void build_double_pendulum(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 7.0f, 1.0f);
  tb_body_id bracket = body_at(world, TB_STATIC_BODY, 0.0f, 9.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(bracket, &sd, 0.6f, 0.1f, 0.0f, 0.2f, 0.0f);
  tb_body_id first = pendulum_link(world, 0.0f, 9.0f, 3.0f, "link_1");
  pin(world, bracket, (tb_vec2){0.0f, 0.0f}, first);
  tb_body_id second = pendulum_link(world, 3.0f, 9.0f, 3.0f, "link_2");
  pin(world, first, (tb_vec2){3.0f, 0.0f}, second);
}

/* ----------------------------------------------------------- chain_bridge -- */

/* chain_bridge: 20 planks (1 m by 0.25 m, density 20, friction 0.6) pinned end
 * to end between two static towers whose tops are at (-10, 6) and (10, 6);
 * the plank in the middle is "plank_middle". Above it, 6 boxes (0.6 m) and 6
 * balls (radius 0.3) fall on it from 9 to 12 m. */
void build_chain_bridge(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 14.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(g, &sd, 1.0f, 3.0f, -11.0f, 3.0f, 0.0f);
  add_offset_box(g, &sd, 1.0f, 3.0f, 11.0f, 3.0f, 0.0f);
  const int planks = 20;
  tb_shape_def plank = shape_def(20.0f, 0.6f, 0.0f);
  tb_body_id prev = g;
  tb_vec2 prev_anchor = {-10.0f, 6.0f};
  for (int i = 0; i < planks; ++i) {
    float x = -10.0f + (float)i + 0.5f;
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, 6.0f, 0.0f, i == planks / 2 ? "plank_middle" : NULL);
    add_box(b, &plank, 0.5f, 0.125f);
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = prev;
    jd.body_b = b;
    jd.local_anchor_a = prev_anchor;
    jd.local_anchor_b = (tb_vec2){-0.5f, 0.0f};
    tb_create_revolute_joint(world, &jd);
    prev = b;
    prev_anchor = (tb_vec2){0.5f, 0.0f};
  }
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = prev;
  jd.body_b = g;
  jd.local_anchor_a = (tb_vec2){0.5f, 0.0f};
  jd.local_anchor_b = (tb_vec2){10.0f, 6.0f};
  tb_create_revolute_joint(world, &jd);

  tb_shape_def load = tb_default_shape_def();
  for (int k = 0; k < 12; ++k) {
    float x = -7.5f + 1.35f * (float)k, y = 9.0f + 1.0f * (float)(k % 4);
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
    if (k % 2 == 0) {
      add_box(b, &load, 0.3f, 0.3f);
    } else {
      add_circle(b, &load, 0.3f);
    }
  }
}

/* --------------------------------------------------------------- ragdolls -- */

/* One ragdoll 1.8 m tall standing with its feet at (x, y), turned by angle
 * about that point: head (circle), torso, upper and lower arms and legs
 * (capsules), 9 revolute joints with human-like limits and a little joint
 * friction (a motor of speed 0 and 0.5 N m at most) so that limbs do not flap.
 * Its parts share the negative group index group: they never collide with
 * each other, only with the world and other ragdolls. */
typedef struct ragdoll_part {
  float x, y, half_length, radius; /* capsule along y, or a circle if half_length is 0 */
} ragdoll_part;

enum { HEAD, TORSO, UPPER_ARM_L, LOWER_ARM_L, UPPER_ARM_R, LOWER_ARM_R, THIGH_L, SHIN_L, THIGH_R, SHIN_R, PARTS };

static void ragdoll(tb_world_id world, float x, float y, float angle, int group, const char* head_tag) {
  static const ragdoll_part parts[PARTS] = {
      [HEAD] = {0.0f, 1.68f, 0.0f, 0.12f},           [TORSO] = {0.0f, 1.2f, 0.2f, 0.14f},
      [UPPER_ARM_L] = {-0.22f, 1.32f, 0.13f, 0.06f}, [LOWER_ARM_L] = {-0.22f, 0.99f, 0.12f, 0.05f},
      [UPPER_ARM_R] = {0.22f, 1.32f, 0.13f, 0.06f},  [LOWER_ARM_R] = {0.22f, 0.99f, 0.12f, 0.05f},
      [THIGH_L] = {-0.1f, 0.7f, 0.17f, 0.08f},       [SHIN_L] = {-0.1f, 0.25f, 0.17f, 0.07f},
      [THIGH_R] = {0.1f, 0.7f, 0.17f, 0.08f},        [SHIN_R] = {0.1f, 0.25f, 0.17f, 0.07f},
  };
  /* joint: parent, child, anchor (standing pose, feet at the origin), limits */
  static const struct {
    int a, b;
    float x, y, lower, upper;
  } joints[] = {
      {TORSO, HEAD, 0.0f, 1.56f, -0.6f, 0.6f},
      {TORSO, UPPER_ARM_L, -0.22f, 1.45f, -3.0f, 1.0f},
      {UPPER_ARM_L, LOWER_ARM_L, -0.22f, 1.12f, 0.0f, 2.5f},
      {TORSO, UPPER_ARM_R, 0.22f, 1.45f, -1.0f, 3.0f},
      {UPPER_ARM_R, LOWER_ARM_R, 0.22f, 1.12f, 0.0f, 2.5f},
      {TORSO, THIGH_L, -0.1f, 0.9f, -0.5f, 2.0f},
      {THIGH_L, SHIN_L, -0.1f, 0.47f, -2.2f, 0.0f},
      {TORSO, THIGH_R, 0.1f, 0.9f, -0.5f, 2.0f},
      {THIGH_R, SHIN_R, 0.1f, 0.47f, -2.2f, 0.0f},
  };
  tb_rot q = {cosf(angle), sinf(angle)};
  tb_body_id bodies[PARTS];
  tb_shape_def sd = shape_def(1.0f, 0.6f, 0.0f);
  sd.filter.group_index = group;
  for (int i = 0; i < PARTS; ++i) {
    const ragdoll_part* p = &parts[i];
    float px = x + q.c * p->x - q.s * p->y, py = y + q.s * p->x + q.c * p->y;
    bodies[i] = body_at(world, TB_DYNAMIC_BODY, px, py, angle, i == HEAD ? head_tag : NULL);
    if (p->half_length > 0.0f) {
      add_capsule_y(bodies[i], &sd, p->half_length, p->radius);
    } else {
      add_circle(bodies[i], &sd, p->radius);
    }
  }
  for (size_t k = 0; k < sizeof joints / sizeof joints[0]; ++k) {
    const ragdoll_part* pa = &parts[joints[k].a];
    const ragdoll_part* pb = &parts[joints[k].b];
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = bodies[joints[k].a];
    jd.body_b = bodies[joints[k].b];
    jd.local_anchor_a = (tb_vec2){joints[k].x - pa->x, joints[k].y - pa->y};
    jd.local_anchor_b = (tb_vec2){joints[k].x - pb->x, joints[k].y - pb->y};
    jd.enable_limit = true;
    jd.lower_angle = joints[k].lower;
    jd.upper_angle = joints[k].upper;
    jd.enable_motor = true;
    jd.motor_speed = 0.0f;
    jd.max_motor_torque = 0.5f;
    tb_create_revolute_joint(world, &jd);
  }
}

/* ragdolls: a staircase of 8 steps (1.5 m deep, 0.75 m high) descending to the
 * right from x = -12, and 6 ragdolls dropped over its top at several tilts;
 * the first one's head is "head". */
void build_ragdolls(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 16.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  const int steps = 8;
  for (int i = 0; i < steps; ++i) {
    float top = 0.75f * (float)(steps - i);
    add_offset_box(g, &sd, 0.75f, 0.5f * top, -12.0f + 1.5f * (float)i + 0.75f, 0.5f * top, 0.0f);
  }
  static const float tilts[6] = {0.0f, 0.6f, -0.9f, 1.57f, -0.3f, 2.4f};
  for (int k = 0; k < 6; ++k) {
    float x = -10.5f + 1.6f * (float)k, y = 7.0f + 2.2f * (float)(k % 3);
    ragdoll(world, x, y, tilts[k], -(k + 1), k == 0 ? "head" : NULL);
  }
}

/* -------------------------------------------------------------------- car -- */

/* car: a chain terrain from x = -20 to 200 (points every 2 m; flat for the
 * first 25 m, then hills y = 1.5 sin(0.15 (x - 5)) + 0.6 sin(0.41 (x - 5)) and
 * a wall at the far end). The car ("car", the chassis: a 2.6 m hexagon-ish
 * polygon, density 2) starts at rest at (0, 1.3) on two wheels (radius 0.4,
 * density 1, friction 0.9), each on a wheel joint: vertical suspension
 * (4 Hz, damping ratio 0.7, travel limited to +-0.25 m) and a motor at
 * -12 rad/s (clockwise: forward along +x, 4.8 m/s) with at most 12 N m. */
static float terrain_height(float x) {
  if (x < 5.0f) return 0.0f;
  float u = x - 5.0f;
  float ramp = u < 20.0f ? u / 20.0f : 1.0f; /* the hills grow in over 20 m */
  return ramp * (1.5f * sinf(0.15f * u) + 0.6f * sinf(0.41f * u));
}

void build_car(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  enum { TERRAIN_POINTS = 113 };
  tb_vec2 points[TERRAIN_POINTS];
  points[0] = (tb_vec2){-20.0f, 8.0f}; /* a wall behind the start */
  for (int i = 1; i < TERRAIN_POINTS - 1; ++i) {
    float x = -20.0f + 2.0f * (float)(i - 1);
    points[i] = (tb_vec2){x, terrain_height(x)};
  }
  float end_x = points[TERRAIN_POINTS - 2].x;
  points[TERRAIN_POINTS - 1] = (tb_vec2){end_x, points[TERRAIN_POINTS - 2].y + 8.0f}; /* a wall at the end */
  tb_chain_def cd = tb_default_chain_def();
  cd.points = points;
  cd.count = TERRAIN_POINTS;
  cd.friction = 0.9f;
  tb_create_chain(g, &cd);

  const tb_vec2 hull[6] = {{-1.3f, -0.25f}, {1.3f, -0.25f}, {1.3f, 0.1f},
                           {0.4f, 0.45f},   {-0.6f, 0.45f}, {-1.3f, 0.15f}};
  tb_polygon chassis_shape;
  if (tb_make_polygon(hull, 6, 0.0f, &chassis_shape) != TB_OK) return;
  tb_body_id chassis = body_at(world, TB_DYNAMIC_BODY, 0.0f, 1.3f, 0.0f, "car");
  tb_shape_def body_sd = shape_def(2.0f, 0.6f, 0.0f);
  tb_create_polygon_shape(chassis, &body_sd, &chassis_shape);
  tb_shape_def wheel_sd = shape_def(1.0f, 0.9f, 0.0f);
  const float wheel_x[2] = {-0.85f, 0.85f};
  for (int k = 0; k < 2; ++k) {
    tb_body_id wheel = body_at(world, TB_DYNAMIC_BODY, wheel_x[k], 0.4f, 0.0f, k == 0 ? "wheel_rear" : "wheel_front");
    add_circle(wheel, &wheel_sd, 0.4f);
    tb_wheel_joint_def jd = tb_default_wheel_joint_def();
    jd.body_a = chassis;
    jd.body_b = wheel;
    jd.local_anchor_a = (tb_vec2){wheel_x[k], -0.9f};
    jd.local_anchor_b = (tb_vec2){0.0f, 0.0f};
    jd.local_axis_a = (tb_vec2){0.0f, 1.0f};
    jd.hertz = 4.0f;
    jd.damping_ratio = 0.7f;
    jd.enable_limit = true;
    jd.lower_translation = -0.25f;
    jd.upper_translation = 0.25f;
    jd.enable_motor = true;
    jd.motor_speed = -12.0f;
    jd.max_motor_torque = 12.0f;
    tb_create_wheel_joint(world, &jd);
  }
}

/* --------------------------------------------------------------- dominoes -- */

/* dominoes: 30 dominoes (0.2 x 1 m, density 1, friction 0.6) standing 0.6 m
 * apart from x = -8 ("domino_first") to 9.4 ("domino_last"). A striker (a
 * ball of radius 0.2, density 2, "striker" on a revolute joint 2.1 m below a
 * static pivot at (-8.3, 3)) is released horizontal to the left and swings
 * down into the top of the first domino at 6.5 m/s. */
void build_dominoes(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 14.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  const int count = 30;
  for (int i = 0; i < count; ++i) {
    const char* tag = i == 0 ? "domino_first" : i == count - 1 ? "domino_last" : NULL;
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, -8.0f + 0.6f * (float)i, 0.5f, 0.0f, tag);
    add_box(b, &sd, 0.1f, 0.5f);
  }
  /* at the bottom of its swing the ball (centre 0.9 m up) just touches the
   * first domino's left face, 0.1 m below its top */
  const tb_vec2 pivot = {-8.3f, 3.0f};
  const float length = 2.1f;
  add_offset_box(g, &sd, 0.3f, 0.1f, pivot.x, pivot.y + 0.1f, 0.0f);
  tb_body_id ball = body_at(world, TB_DYNAMIC_BODY, pivot.x - length, pivot.y, 0.0f, "striker");
  tb_shape_def heavy = shape_def(2.0f, 0.6f, 0.0f);
  add_circle(ball, &heavy, 0.2f);
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = g;
  jd.body_b = ball;
  jd.local_anchor_a = pivot;
  jd.local_anchor_b = (tb_vec2){length, 0.0f};
  tb_create_revolute_joint(world, &jd);
}

/* ---------------------------------------------------------- tumbler_mixed -- */

/* tumbler_mixed: a kinematic box ("drum", walls 0.5 m thick, inner space 9 m)
 * centred at (0, 6) turning at 30 deg/s, holding 150 bodies on a 10 x 15
 * lattice, cycling through circles, capsules, boxes, triangles and hexagons of
 * about 0.5 m. */
void build_tumbler_mixed(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_KINEMATIC_BODY;
  bd.position = (tb_vec2){0.0f, 6.0f};
  bd.angular_velocity = 30.0f * PI_F / 180.0f;
  bd.user_data = (void*)"drum";
  tb_body_id drum = tb_create_body(world, &bd);
  tb_shape_def wall = tb_default_shape_def();
  add_offset_box(drum, &wall, 0.25f, 5.0f, 4.75f, 0.0f, 0.0f);
  add_offset_box(drum, &wall, 0.25f, 5.0f, -4.75f, 0.0f, 0.0f);
  add_offset_box(drum, &wall, 5.0f, 0.25f, 0.0f, 4.75f, 0.0f);
  add_offset_box(drum, &wall, 5.0f, 0.25f, 0.0f, -4.75f, 0.0f);

  const tb_vec2 triangle[3] = {{-0.3f, -0.25f}, {0.3f, -0.25f}, {0.0f, 0.3f}};
  tb_vec2 hexagon[6];
  for (int k = 0; k < 6; ++k) {
    float a = (float)k * PI_F / 3.0f;
    hexagon[k] = (tb_vec2){0.28f * cosf(a), 0.28f * sinf(a)};
  }
  tb_polygon tri, hex;
  if (tb_make_polygon(triangle, 3, 0.0f, &tri) != TB_OK || tb_make_polygon(hexagon, 6, 0.0f, &hex) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 15; ++j) {
      float x = -4.05f + 0.9f * (float)i, y = 6.0f - 4.2f + 0.6f * (float)j;
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
      switch ((i + j) % 5) {
        case 0: add_circle(b, &sd, 0.25f); break;
        case 1: add_capsule_x(b, &sd, 0.2f, 0.12f); break;
        case 2: add_box(b, &sd, 0.25f, 0.2f); break;
        case 3: tb_create_polygon_shape(b, &sd, &tri); break;
        default: tb_create_polygon_shape(b, &sd, &hex); break;
      }
    }
  }
}

/* --------------------------------------------------------- rain_over_time -- */

/* rain_over_time: a container (floor at y = 0, inner walls at x = +-12, 16 m
 * high); the update hook spawns one body per step for the first 600 steps at
 * y = 28, at a random x in [-10, 10): a circle, a box or a capsule of random
 * size 0.15 to 0.35 m, random angle, falling at 5 m/s. The generator is seeded
 * from the step index, so a run needs no state and repeats exactly. */
#define RAIN_SPAWN_STEPS 600

void build_rain_over_time(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(g, &sd, 13.0f, 0.5f, 0.0f, -0.5f, 0.0f);
  add_offset_box(g, &sd, 0.5f, 8.0f, -12.5f, 8.0f, 0.0f);
  add_offset_box(g, &sd, 0.5f, 8.0f, 12.5f, 8.0f, 0.0f);
}

void update_rain_over_time(tb_world_id world, int step) {
  if (step < 0 || step >= RAIN_SPAWN_STEPS) return;
  uint32_t rng = 0x9e3779b9u ^ ((uint32_t)step * 2654435761u);
  if (rng == 0) rng = 1;
  for (int k = 0; k < 4; ++k) scene_rnd(&rng, 0.0f, 1.0f); /* mix the seed */
  float kind = scene_rnd(&rng, 0.0f, 3.0f);
  float s = scene_rnd(&rng, 0.15f, 0.35f);
  float x = scene_rnd(&rng, -10.0f, 10.0f);
  float angle = scene_rnd(&rng, -PI_F, PI_F);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){x, 28.0f};
  bd.angle = angle;
  bd.linear_velocity = (tb_vec2){0.0f, -5.0f};
  tb_body_id b = tb_create_body(world, &bd);
  tb_shape_def sd = tb_default_shape_def();
  if (kind < 1.0f) {
    add_circle(b, &sd, s);
  } else if (kind < 2.0f) {
    add_box(b, &sd, s, s);
  } else {
    add_capsule_x(b, &sd, s, 0.5f * s);
  }
}

/* --------------------------------------------------------------- conveyor -- */

/* conveyor: two static belts (boxes 10 m by 0.4 m, friction 0.8) with a
 * tangent speed of 2 m/s: the upper ("belt_upper" shape tag), top at y = 6,
 * spans x = -10 .. 0 and carries to the right; the lower one, top at y = 2.5,
 * spans x = -2 .. 8 and carries to the left. Boxes (0.6 m, friction 0.8) fall
 * onto the upper belt's left end, one every 45 steps (13 in all, the update
 * hook); the first ("box_first") is there from the start, resting on the belt.
 * They ride right, drop onto the lower belt, ride left and drop to the floor
 * of the container (walls at x = +-12). */
#define BELT_SPEED 2.0f
#define CONVEYOR_SPAWN_EVERY 45
#define CONVEYOR_SPAWN_COUNT 13

static void conveyor_box(tb_world_id world, float y, const char* tag) {
  tb_body_id b = body_at(world, TB_DYNAMIC_BODY, -9.0f, y, 0.0f, tag);
  tb_shape_def sd = shape_def(1.0f, 0.8f, 0.0f);
  add_box(b, &sd, 0.3f, 0.3f);
}

void build_conveyor(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 13.0f, 0.5f);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(g, &sd, 0.5f, 5.0f, -12.5f, 5.0f, 0.0f);
  add_offset_box(g, &sd, 0.5f, 5.0f, 12.5f, 5.0f, 0.0f);
  tb_shape_def belt = shape_def(1.0f, 0.8f, 0.0f);
  belt.tangent_speed = BELT_SPEED;
  belt.user_data = (void*)"belt_upper";
  add_offset_box(g, &belt, 5.0f, 0.2f, -5.0f, 5.8f, 0.0f);
  belt.tangent_speed = -BELT_SPEED;
  belt.user_data = (void*)"belt_lower";
  add_offset_box(g, &belt, 5.0f, 0.2f, 3.0f, 2.3f, 0.0f);
  conveyor_box(world, 6.3f, "box_first");
}

void update_conveyor(tb_world_id world, int step) {
  if (step <= 0 || step % CONVEYOR_SPAWN_EVERY != 0 || step / CONVEYOR_SPAWN_EVERY >= CONVEYOR_SPAWN_COUNT) return;
  conveyor_box(world, 8.0f, NULL);
}

/* ------------------------------------------------------- one_way_platform -- */

/* A contact with the platform (the shape tagged "platform") is enabled only
 * when the other body is on top: the normal, turned to point out of the
 * platform, points up, and the body is not on its way up through the platform
 * (rising faster than 0.5 m/s while sunk into it by more than 5 cm). The depth
 * alone would not do: a body falling at 8 m/s moves 13 cm per step, more than
 * the 2 cm speculative margin, and the continuous pass does not sweep against
 * pre-solve shapes, so it first touches the platform 9 cm deep. */
static bool is_platform(tb_shape_id shape) {
  const char* tag = tb_shape_get_user_data(shape);
  return tag != NULL && strcmp(tag, "platform") == 0;
}

static bool one_way_pre_solve(tb_shape_id a, tb_shape_id b, const tb_manifold* manifold, void* context) {
  (void)context;
  float sign = is_platform(a) ? 1.0f : is_platform(b) ? -1.0f : 0.0f;
  if (sign == 0.0f) return true;
  if (sign * manifold->normal.y < 0.7f) return false;
  tb_body_id other = tb_shape_get_body(sign > 0.0f ? b : a);
  if (tb_body_get_linear_velocity(other).y <= 0.5f) return true;
  for (int i = 0; i < manifold->point_count; ++i) {
    if (manifold->points[i].separation < -0.05f) return false;
  }
  return true;
}

void configure_one_way_platform(tb_world_def* def) {
  def->pre_solve = one_way_pre_solve;
  def->pre_solve_context = NULL;
}

/* one_way_platform: a static platform (8 m by 0.4 m, top at y = 4.2, shape
 * tagged "platform", pre-solve events on) over the ground. Three bodies start
 * on the ground under it and are thrown straight up at 11 m/s (6 m high): a
 * 1 m box ("jumper") at x = -3, a ball (radius 0.4) at -1 and a capsule at 1;
 * they pass up through the platform and land on it. A fourth box ("dropped",
 * 0.8 m) falls onto it from y = 9 at x = 2.4 and stays there. */
void build_one_way_platform(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 8.0f, 1.0f);
  tb_body_id p = body_at(world, TB_STATIC_BODY, 0.0f, 4.0f, 0.0f, NULL);
  tb_shape_def ps = tb_default_shape_def();
  ps.enable_pre_solve_events = true;
  ps.user_data = (void*)"platform";
  add_box(p, &ps, 4.0f, 0.2f);

  tb_shape_def sd = tb_default_shape_def();
  const float xs[3] = {-3.0f, -1.0f, 1.0f};
  for (int k = 0; k < 3; ++k) {
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = (tb_vec2){xs[k], 0.5f};
    bd.linear_velocity = (tb_vec2){0.0f, 11.0f};
    bd.user_data = k == 0 ? (void*)"jumper" : NULL;
    tb_body_id b = tb_create_body(world, &bd);
    if (k == 0) {
      add_box(b, &sd, 0.5f, 0.5f);
    } else if (k == 1) {
      add_circle(b, &sd, 0.4f);
    } else {
      add_capsule_x(b, &sd, 0.3f, 0.25f);
    }
  }
  tb_body_id dropped = body_at(world, TB_DYNAMIC_BODY, 2.4f, 9.0f, 0.3f, "dropped");
  add_box(dropped, &sd, 0.4f, 0.4f);
}

/* ---------------------------------------------------------------- sensors -- */

/* sensors: a ramp (a static box 10 m long tilted 15 degrees) leads down onto
 * the floor; five static sensor boxes (1.2 m by 2 m, shape user data
 * "sensor") stand on the floor at x = 0, 2.5, 5, 7.5, 10, and a wall at
 * x = 13 stops what rolls through them. The update hook releases a ball
 * (radius 0.3, density 1) at the top of the ramp every 40 steps, 15 in all;
 * each ball rolls through the sensors (which never push) and the debug draw
 * lights a sensor while something overlaps it. */
#define SENSOR_SPAWN_EVERY 40
#define SENSOR_SPAWN_COUNT 15

void build_sensors(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = ground(world, 14.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  const float tilt = 15.0f * PI_F / 180.0f;
  /* the ramp's top surface runs 10 m up to the left from (-2, 0) */
  float c = cosf(tilt), s = sinf(tilt);
  add_offset_box(g, &sd, 5.0f, 0.2f, -2.0f - 5.0f * c - 0.2f * s, 5.0f * s - 0.2f * c, -tilt);
  add_offset_box(g, &sd, 0.5f, 3.0f, 13.5f, 3.0f, 0.0f);
  tb_shape_def sensor = tb_default_shape_def();
  sensor.is_sensor = true;
  sensor.user_data = (void*)"sensor";
  for (int k = 0; k < 5; ++k) add_offset_box(g, &sensor, 0.6f, 1.0f, 2.5f * (float)k, 1.0f, 0.0f);
}

void update_sensors(tb_world_id world, int step) {
  if (step < 0 || step % SENSOR_SPAWN_EVERY != 0 || step / SENSOR_SPAWN_EVERY >= SENSOR_SPAWN_COUNT) return;
  /* on the ramp's surface 9 m from its foot, just clear of it */
  const float tilt = 15.0f * PI_F / 180.0f, c = cosf(tilt), s = sinf(tilt), lift = 0.31f;
  tb_body_id b = body_at(world, TB_DYNAMIC_BODY, -2.0f - 9.0f * c + lift * s, 9.0f * s + lift * c, 0.0f,
                         step == 0 ? "ball_first" : NULL);
  tb_shape_def sd = tb_default_shape_def();
  add_circle(b, &sd, 0.3f);
}
