/* The scene catalogue (see scenes.h). Every scene is built from the public API
 * only, with the standard parameters listed at each builder. Ground and walls
 * are static bodies made of boxes (or segments for the pyramid shelves).
 * Unless a builder says otherwise: density 1 kg/m^2, friction 0.6, restitution
 * 0 (tb_default_shape_def()), gravity (0, -10). */
#include "scenes.h"

#include <stdlib.h>
#include <string.h>

#include "gallery.h"
#include "scene_build.h"
#include "v3_scenes.h"

/* ------------------------------------------------ performance scenes -- */

/* large_pyramid: a pyramid of base 100 (5,050 boxes of half-size 0.5, density
 * 1, friction 0.6) on a static ground box 200 m wide whose top is y = 0. The top
 * box ("top") starts at (0, 99.5). */
static void build_large_pyramid(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 100.0f, 1.0f);
  pyramid(world, scaled(100, scale, 1), 0.5f, 0.0f, 0.0f, "top");
}

/* many_pyramids: 20 rows of 20 pyramids of base 10 (55 boxes of half-size 0.5
 * each: 22,000 boxes). Each row stands on its own static shelf, a segment 220 m
 * long; shelves are 11 m apart (y = 0, 11, ..., 209), pyramids 11 m apart
 * (centres at x = -104.5, -93.5, ..., 104.5). The first row's shelf is y = 0. */
static void build_many_pyramids(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  const int base = 10;
  const float h = 0.5f;
  int rows = scaled(20, scale, 1), columns = scaled(20, scale, 1);
  float slot = 2.0f * h * (float)(base + 1); /* 11 m: a pyramid and a 1 m gap */
  float width = slot * (float)columns;
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  for (int r = 0; r < rows; ++r) {
    float y = slot * (float)r;
    tb_segment s = {{-0.5f * width, y}, {0.5f * width, y}};
    tb_create_segment_shape(g, &sd, &s);
  }
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      float cx = -0.5f * width + ((float)c + 0.5f) * slot;
      pyramid(world, base, h, cx, slot * (float)r, NULL);
    }
  }
}

/* joint_grid: 100 x 100 circles (radius 0.4, density 1) 1 m apart, column i
 * at x = i - 49.5, row j at y = -j, each linked by a revolute joint to its
 * right and lower neighbour (anchor midway). The circles do not collide with
 * each other (category 2, mask ~2). The top-row circles of columns 47 to 53
 * (N/2 - 3 to N/2 + 3) are static anchors. 19,800 joints. */
static void build_joint_grid(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  int n = scaled(100, scale, 2);
  tb_body_id* bodies = malloc(sizeof *bodies * (size_t)n * (size_t)n);
  if (bodies == NULL) return;
  tb_shape_def sd = tb_default_shape_def();
  sd.filter.category_bits = 2u;
  sd.filter.mask_bits = ~(uint64_t)2u;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      bool anchor = j == 0 && i >= n / 2 - 3 && i <= n / 2 + 3;
      float x = (float)i - 0.5f * (float)(n - 1), y = -(float)j;
      tb_body_id b = body_at(world, anchor ? TB_STATIC_BODY : TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
      add_circle(b, &sd, 0.4f);
      bodies[i * n + j] = b;
      tb_revolute_joint_def jd = tb_default_revolute_joint_def();
      if (i > 0) {
        jd.body_a = bodies[(i - 1) * n + j];
        jd.body_b = b;
        jd.local_anchor_a = (tb_vec2){0.5f, 0.0f};
        jd.local_anchor_b = (tb_vec2){-0.5f, 0.0f};
        tb_create_revolute_joint(world, &jd);
      }
      if (j > 0) {
        jd.body_a = bodies[i * n + j - 1];
        jd.body_b = b;
        jd.local_anchor_a = (tb_vec2){0.0f, -0.5f};
        jd.local_anchor_b = (tb_vec2){0.0f, 0.5f};
        tb_create_revolute_joint(world, &jd);
      }
    }
  }
  free(bodies);
}

/* rain_2000: 2,000 bodies spawned at once (the world starts with all of them in the
 * air; they land over the first ~5 s) into a static container: floor top at
 * y = 0, inner walls at x = +-20, walls 50 m high. Bodies sit on a 25-column
 * lattice (cells 1.52 m wide, 1.125 m tall; rows from y = 10 to 100), each
 * jittered inside its cell so that no two overlap at the start. Per body, in
 * order, five draws of the xorshift32 generator (seed 20240601): kind (< 0.5 a
 * circle, else a box), size s in [0.15, 0.35) (radius or half-extent), angle in
 * [-pi, pi), x and y jitter in [-1, 1) times the cell's free room. */
static void build_rain_2000(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def gd = tb_default_shape_def();
  add_offset_box(g, &gd, 21.0f, 1.0f, 0.0f, -1.0f, 0.0f);
  add_offset_box(g, &gd, 1.0f, 25.0f, -21.0f, 25.0f, 0.0f);
  add_offset_box(g, &gd, 1.0f, 25.0f, 21.0f, 25.0f, 0.0f);

  if (!(scale > 0.0f && scale <= 1.0f)) scale = 1.0f;
  int count = (int)lroundf(2000.0f * scale * scale);
  if (count < 1) count = 1;
  const int columns = 25;
  const float cell_w = 38.0f / (float)columns, cell_h = 1.125f;
  uint32_t rng = 20240601u;
  tb_shape_def sd = tb_default_shape_def();
  for (int k = 0; k < count; ++k) {
    int c = k % columns, r = k / columns;
    bool circle = scene_rnd(&rng, 0.0f, 1.0f) < 0.5f;
    float s = scene_rnd(&rng, 0.15f, 0.35f);
    float angle = scene_rnd(&rng, -PI_F, PI_F);
    float jx = scene_rnd(&rng, -1.0f, 1.0f), jy = scene_rnd(&rng, -1.0f, 1.0f);
    float extent = circle ? s : 1.41421356f * s;
    float x = -19.0f + ((float)c + 0.5f) * cell_w + jx * (0.5f * cell_w - extent);
    float y = 10.0f + ((float)r + 0.5f) * cell_h + jy * (0.5f * cell_h - extent);
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, circle ? 0.0f : angle, NULL);
    if (circle) {
      add_circle(b, &sd, s);
    } else {
      add_box(b, &sd, s, s);
    }
  }
}

/* smash: zero gravity. An 8 x 8 m box ("projectile", density 8) starts at
 * (-20, 0) moving at 40 m/s along +x into a grid of 120 x 80 boxes of 0.4 m
 * (density 1), edge to edge, created asleep: column i at x = 30 + 0.4 i, row j
 * at y = 0.4 (j - 40). */
static void build_smash(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, 0.0f});
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){-20.0f, 0.0f};
  bd.linear_velocity = (tb_vec2){40.0f, 0.0f};
  bd.user_data = (void*)"projectile";
  tb_body_id p = tb_create_body(world, &bd);
  tb_shape_def heavy = shape_def(8.0f, 0.6f, 0.0f);
  add_box(p, &heavy, 4.0f, 4.0f);

  int columns = scaled(120, scale, 1), rows = scaled(80, scale, 1);
  const float d = 0.4f;
  tb_polygon box;
  if (tb_make_box(0.5f * d, 0.5f * d, &box) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.is_awake = false;
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      bd.position = (tb_vec2){30.0f + (float)i * d, ((float)j - 0.5f * (float)rows) * d};
      tb_body_id b = tb_create_body(world, &bd);
      tb_create_polygon_shape(b, &sd, &box);
    }
  }
}

/* tumbler_kinematic: a kinematic hollow box ("container") centred at (0, 10), turning at
 * 25 deg/s: four walls 1 m thick whose centre lines form a 20 m square (inner
 * space 19 m). Inside, a 45 x 45 grid of boxes of 0.25 m (half 0.125, density
 * 1), 0.4 m apart, from (-9, 1). */
static void build_tumbler_kinematic(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_KINEMATIC_BODY;
  bd.position = (tb_vec2){0.0f, 10.0f};
  bd.angular_velocity = 25.0f * PI_F / 180.0f;
  bd.user_data = (void*)"container";
  tb_body_id c = tb_create_body(world, &bd);
  tb_shape_def wall = shape_def(50.0f, 0.6f, 0.0f);
  add_offset_box(c, &wall, 0.5f, 10.0f, 10.0f, 0.0f, 0.0f);
  add_offset_box(c, &wall, 0.5f, 10.0f, -10.0f, 0.0f, 0.0f);
  add_offset_box(c, &wall, 10.0f, 0.5f, 0.0f, 10.0f, 0.0f);
  add_offset_box(c, &wall, 10.0f, 0.5f, 0.0f, -10.0f, 0.0f);

  const int full = 45;
  int n = scaled(full, scale, 1);
  tb_polygon box;
  if (tb_make_box(0.125f, 0.125f, &box) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  float y = -0.2f * (float)full + 10.0f;
  for (int i = 0; i < n; ++i) {
    float x = -0.2f * (float)full;
    for (int j = 0; j < n; ++j) {
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
      tb_create_polygon_shape(b, &sd, &box);
      x += 0.4f;
    }
    y += 0.4f;
  }
}

/* ---------------------------------------------------- structure scenes -- */

/* vertical_stack: 15 boxes of half-size 0.5 stacked edge to edge at x = 0
 * (centres y = 0.5 ... 14.5; the top one is "top") on a ground 40 m wide. */
static void build_vertical_stack(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 20.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  for (int i = 0; i < 15; ++i) {
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, 0.0f, 0.5f + (float)i, 0.0f, i == 14 ? "top" : NULL);
    add_box(b, &sd, 0.5f, 0.5f);
  }
}

/* pyramid_20: the large pyramid's layout with base 20 (210 boxes); the top box
 * "top" starts at (0, 19.5). */
static void build_pyramid_20(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 40.0f, 1.0f);
  pyramid(world, 20, 0.5f, 0.0f, 0.0f, "top");
}

/* mass_ratio: a 20 m box ("heavy", half 10, 400 kg) resting on two 1 m boxes
 * ("small_left" at x = -9.5, "small_right" at x = 9.5, 1 kg each): a 400:1
 * mass ratio. The heavy box starts at (0, 11), edge to edge. */
static void build_mass_ratio(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  ground(world, 40.0f, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_body_id l = body_at(world, TB_DYNAMIC_BODY, -9.5f, 0.5f, 0.0f, "small_left");
  add_box(l, &sd, 0.5f, 0.5f);
  tb_body_id r = body_at(world, TB_DYNAMIC_BODY, 9.5f, 0.5f, 0.0f, "small_right");
  add_box(r, &sd, 0.5f, 0.5f);
  tb_body_id h = body_at(world, TB_DYNAMIC_BODY, 0.0f, 11.0f, 0.0f, "heavy");
  add_box(h, &sd, 10.0f, 10.0f);
}

/* newtons_cradle: 5 balls (radius 0.5, density 1, friction 0, restitution 1)
 * hang 4 m below a static bar at y = 10 on rigid distance joints, centres 1 m
 * apart (touching) at x = -2 ... 2. The first ball ("ball_first", pivot at
 * x = -2) starts raised 45 degrees to the left; the last is "ball_last". */
static void build_newtons_cradle(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  const int count = 5;
  const float radius = 0.5f, length = 4.0f, top = 10.0f;
  tb_body_id bar = body_at(world, TB_STATIC_BODY, 0.0f, top, 0.0f, NULL);
  tb_shape_def bd = tb_default_shape_def();
  add_offset_box(bar, &bd, 4.0f, 0.1f, 0.0f, 0.1f, 0.0f);
  tb_shape_def sd = shape_def(1.0f, 0.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    float px = (float)(i - count / 2) * 2.0f * radius;
    float x = px, y = top - length;
    if (i == 0) {
      x = px - length * sinf(0.25f * PI_F);
      y = top - length * cosf(0.25f * PI_F);
    }
    const char* tag = i == 0 ? "ball_first" : i == count - 1 ? "ball_last" : NULL;
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, tag);
    add_circle(b, &sd, radius);
    tb_distance_joint_def jd = tb_default_distance_joint_def();
    jd.body_a = bar;
    jd.body_b = b;
    jd.local_anchor_a = (tb_vec2){px, 0.0f};
    jd.local_anchor_b = (tb_vec2){0.0f, 0.0f};
    jd.length = length;
    tb_create_distance_joint(world, &jd);
  }
}

/* chain_100: 100 links (boxes of half 0.6 x 0.125, density 20, friction 0.2)
 * start horizontal to the right of a static pivot at the origin, link i centred
 * at (i + 0.5, 0); revolute joints at x = 0, 1, ..., 99 (the first to the
 * pivot body). Neighbouring links overlap and do not collide; the last link is
 * "link_last". It swings down under gravity. */
static void build_chain_100(tb_world_id world, float scale) {
  (void)scale;
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id prev = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = shape_def(20.0f, 0.2f, 0.0f);
  for (int i = 0; i < 100; ++i) {
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, (float)i + 0.5f, 0.0f, 0.0f, i == 99 ? "link_last" : NULL);
    add_box(b, &sd, 0.6f, 0.125f);
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = prev;
    jd.body_b = b;
    jd.local_anchor_a = (tb_vec2){i == 0 ? 0.0f : 0.5f, 0.0f};
    jd.local_anchor_b = (tb_vec2){-0.5f, 0.0f};
    tb_create_revolute_joint(world, &jd);
    prev = b;
  }
}

/* -------------------------------------------------------------- catalogue -- */

#define BOX(x0, y0, x1, y1)      \
  {                              \
    {(x0), (y0)}, { (x1), (y1) } \
  }

static const tb_scene k_scenes[] = {
    /* the performance scenes: first Box2D v3's benchmark, its ten scenes under
     * its names, built as v3 builds them (v3_scenes.c for those only it has);
     * large_pyramid, many_pyramids, joint_grid and smash are also the Box2D
     * 2.4.1 bench's, with rain_2000 and tumbler_kinematic: keep those six in
     * step with tools/bench_dynamics_b2.cpp */
    {"compounds", "3,000 bodies of two triangles each dropped into an 80 m container", build_compounds, 500,
     BOX(-820.0f, -100.0f, 820.0f, 360.0f), NULL, NULL, NULL},
    {"joint_grid", "100 x 100 circles in a grid of revolute joints hanging from 7 anchors", build_joint_grid, 500,
     BOX(-160.0f, -160.0f, 160.0f, 10.0f), NULL, NULL, NULL},
    {"junkyard", "8,000 pentagons in a 160 m container, stirred by a kinematic pusher", build_junkyard, 800,
     BOX(-85.0f, -5.0f, 85.0f, 60.0f), update_junkyard, NULL, NULL},
    {"large_pyramid", "5,050 boxes in a pyramid of base 100 on the ground", build_large_pyramid, 500,
     BOX(-105.0f, -5.0f, 105.0f, 105.0f), NULL, NULL, NULL},
    {"many_pyramids", "20 x 20 pyramids of base 10 on 20 shelves (22,000 boxes)", build_many_pyramids, 200,
     BOX(-115.0f, -5.0f, 115.0f, 225.0f), NULL, NULL, NULL},
    {"rain", "ragdoll humans rained in columns onto five shelves, the oldest column re-spawned every 8 steps",
     build_rain, 1000, BOX(-130.0f, -50.0f, 130.0f, 230.0f), update_rain, NULL, NULL},
    {"smash", "an 8 m box at 40 m/s into a sleeping 120 x 80 grid of 0.4 m boxes, no gravity", build_smash, 300,
     BOX(-100.0f, -300.0f, 400.0f, 300.0f), NULL, NULL, NULL},
    {"spinner", "6,076 capsules, circles and boxes stirred by a motored bar inside a 40 m ring", build_spinner, 500,
     BOX(-45.0f, -13.0f, 45.0f, 77.0f), NULL, NULL, NULL},
    {"tumbler", "2,025 boxes of 0.25 m in a 20 m box turned at 25 deg/s by a revolute motor", build_tumbler, 750,
     BOX(-16.0f, -6.0f, 16.0f, 26.0f), NULL, NULL, NULL},
    {"washer", "8,100 small squares in a kinematic drum of radius 18 m with paddles, turning at 25 deg/s", build_washer,
     500, BOX(-20.0f, -10.0f, 20.0f, 30.0f), NULL, NULL, NULL},
    {"rain_2000", "2,000 circles and boxes dropped at once from 10 to 100 m into a container", build_rain_2000, 1000,
     BOX(-25.0f, -5.0f, 25.0f, 110.0f), NULL, NULL, NULL},
    {"tumbler_kinematic", "2,025 boxes of 0.25 m in a kinematic 20 m box turning at 25 deg/s", build_tumbler_kinematic,
     750, BOX(-16.0f, -6.0f, 16.0f, 26.0f), NULL, NULL, NULL},
    /* the gallery: structure scenes */
    {"vertical_stack", "15 boxes stacked on the ground", build_vertical_stack, 600, BOX(-20.0f, -2.0f, 20.0f, 20.0f),
     NULL, NULL, NULL},
    {"pyramid_20", "210 boxes in a pyramid of base 20", build_pyramid_20, 600, BOX(-40.0f, -2.0f, 40.0f, 25.0f), NULL,
     NULL, NULL},
    {"mass_ratio", "a 20 m box (400 kg) resting on two 1 m boxes (1 kg)", build_mass_ratio, 600,
     BOX(-40.0f, -2.0f, 40.0f, 25.0f), NULL, NULL, NULL},
    {"newtons_cradle", "5 touching balls on distance joints, restitution 1, the first raised 45 deg",
     build_newtons_cradle, 600, BOX(-10.0f, 0.0f, 10.0f, 12.0f), NULL, NULL, NULL},
    {"chain_100", "a 100-link chain swinging down from a pivot", build_chain_100, 600,
     BOX(-105.0f, -105.0f, 105.0f, 5.0f), NULL, NULL, NULL},
    /* the gallery: demo scenes (gallery.c) */
    {"bullet_block", "two blocks shot from below, at the centre and 0.25 m off: same rise, one spins",
     build_bullet_block, 150, BOX(-10.0f, -1.0f, 10.0f, 10.0f), update_bullet_block, NULL, NULL},
    {"card_house", "a house of cards four storeys high: leaning pairs under flat cards", build_card_house, 600,
     BOX(-6.0f, -1.0f, 6.0f, 8.0f), NULL, NULL, NULL},
    {"pendulum", "a rod and bob on a revolute joint, released horizontal", build_pendulum, 600,
     BOX(-6.0f, -1.0f, 6.0f, 11.0f), NULL, NULL, NULL},
    {"double_pendulum", "two rods on revolute joints, released horizontal: chaotic", build_double_pendulum, 900,
     BOX(-7.0f, -1.0f, 7.0f, 12.0f), NULL, NULL, NULL},
    {"chain_bridge", "a bridge of 20 planks on revolute joints, loaded with falling boxes and balls",
     build_chain_bridge, 600, BOX(-14.0f, -1.0f, 14.0f, 14.0f), NULL, NULL, NULL},
    {"ragdolls", "6 ragdolls of capsules on revolute joints with limits, falling down a staircase", build_ragdolls, 600,
     BOX(-16.0f, -1.0f, 16.0f, 20.0f), NULL, NULL, NULL},
    {"car", "a car with sprung, motored wheel joints driving over hilly chain terrain", build_car, 1200,
     BOX(-25.0f, -10.0f, 205.0f, 25.0f), NULL, "car", NULL},
    {"dominoes", "a pendulum knocks over a row of 30 dominoes", build_dominoes, 600, BOX(-12.0f, -1.0f, 16.0f, 6.0f),
     NULL, NULL, NULL},
    {"tumbler_mixed", "a 10 m box turning at 30 deg/s, full of circles, capsules, boxes and polygons",
     build_tumbler_mixed, 900, BOX(-10.0f, -4.0f, 10.0f, 16.0f), NULL, NULL, NULL},
    {"rain_over_time", "circles, boxes and capsules spawned one per step into a container (600 in 10 s)",
     build_rain_over_time, 900, BOX(-13.0f, -1.0f, 13.0f, 32.0f), update_rain_over_time, NULL, NULL},
    {"conveyor", "boxes carried by two conveyor belts (tangent speed 2 m/s), right then left", build_conveyor, 900,
     BOX(-13.0f, -1.0f, 13.0f, 12.0f), update_conveyor, NULL, NULL},
    {"one_way_platform", "bodies jump up through a one-way platform (pre-solve callback) and land on it",
     build_one_way_platform, 600, BOX(-8.0f, -1.0f, 8.0f, 12.0f), NULL, NULL, configure_one_way_platform},
    {"sensors", "balls roll down a ramp through five sensor boxes that light up while occupied", build_sensors, 900,
     BOX(-14.0f, -1.0f, 14.0f, 10.0f), update_sensors, NULL, NULL},
};

#define SCENE_COUNT ((int)(sizeof k_scenes / sizeof k_scenes[0]))
#define PERFORMANCE_COUNT 12

const tb_scene* tb_scenes(int* count) {
  if (count != NULL) *count = SCENE_COUNT;
  return k_scenes;
}

const tb_scene* tb_scene_find(const char* name) {
  if (name == NULL) return NULL;
  for (int i = 0; i < SCENE_COUNT; ++i) {
    if (strcmp(k_scenes[i].name, name) == 0) return &k_scenes[i];
  }
  return NULL;
}

int tb_scene_is_performance(const tb_scene* scene) { return scene >= k_scenes && scene < k_scenes + PERFORMANCE_COUNT; }

tb_world_id tb_scene_create_world(const tb_scene* scene) {
  tb_world_def def = tb_default_world_def();
  if (scene != NULL && scene->configure != NULL) scene->configure(&def);
  return tb_create_world(&def);
}

/* ---------------------------------------------------------------- checks -- */

typedef struct body_list {
  tb_body_id* items;
  int count, capacity;
  bool failed;
} body_list;

static bool collect_shape(tb_shape_id shape, void* context) {
  body_list* list = context;
  if (list->count == list->capacity) {
    int capacity = list->capacity ? 2 * list->capacity : 1024;
    tb_body_id* items = realloc(list->items, sizeof *items * (size_t)capacity);
    if (items == NULL) {
      list->failed = true;
      return false;
    }
    list->items = items;
    list->capacity = capacity;
  }
  list->items[list->count++] = tb_shape_get_body(shape);
  return true;
}

static int compare_bodies(const void* a, const void* b) {
  const tb_body_id* x = a;
  const tb_body_id* y = b;
  return (x->index1 > y->index1) - (x->index1 < y->index1);
}

/* Every body with a shape, sorted by handle index, each once. */
static body_list all_bodies(tb_world_id world) {
  body_list list = {0};
  tb_query_filter filter = tb_default_query_filter();
  filter.category_bits = UINT64_MAX;
  filter.mask_bits = UINT64_MAX;
  const float far = 0.5f * TB_MAX_LENGTH;
  tb_world_overlap_aabb(world, (tb_aabb){{-far, -far}, {far, far}}, filter, collect_shape, &list);
  if (list.count == 0) return list;
  qsort(list.items, (size_t)list.count, sizeof list.items[0], compare_bodies);
  int unique = 1;
  for (int i = 1; i < list.count; ++i) {
    if (list.items[i].index1 != list.items[unique - 1].index1) list.items[unique++] = list.items[i];
  }
  list.count = unique;
  return list;
}

tb_body_id tb_scene_find_body(tb_world_id world, const char* tag) {
  tb_body_id found = {0};
  if (tag == NULL) return found;
  body_list list = all_bodies(world);
  for (int i = 0; i < list.count; ++i) {
    const char* t = tb_body_get_user_data(list.items[i]);
    if (t != NULL && strcmp(t, tag) == 0) {
      found = list.items[i];
      break;
    }
  }
  free(list.items);
  return found;
}

int tb_scene_collect_bodies(tb_world_id world, tb_body_id* out, int capacity) {
  body_list list = all_bodies(world);
  for (int i = 0; i < list.count && i < capacity; ++i) out[i] = list.items[i];
  free(list.items);
  return list.count;
}

int tb_scene_count_outside(tb_world_id world, tb_aabb bounds) {
  body_list list = all_bodies(world);
  int outside = 0;
  for (int i = 0; i < list.count; ++i) {
    if (tb_body_get_type(list.items[i]) == TB_STATIC_BODY) continue;
    tb_vec2 p = tb_body_get_position(list.items[i]);
    if (!(p.x >= bounds.lower.x && p.x <= bounds.upper.x && p.y >= bounds.lower.y && p.y <= bounds.upper.y)) {
      outside += 1;
    }
  }
  free(list.items);
  return outside;
}

static uint64_t fnv_float(uint64_t h, float f) {
  uint32_t bits;
  memcpy(&bits, &f, sizeof bits);
  for (int k = 0; k < 4; ++k) {
    h ^= (bits >> (8 * k)) & 0xffu;
    h *= 1099511628211ull;
  }
  return h;
}

uint64_t tb_scene_state_hash(tb_world_id world) {
  body_list list = all_bodies(world);
  uint64_t h = 14695981039346656037ull;
  for (int i = 0; i < list.count; ++i) {
    tb_body_id b = list.items[i];
    tb_vec2 p = tb_body_get_position(b), v = tb_body_get_linear_velocity(b);
    h = fnv_float(h, p.x);
    h = fnv_float(h, p.y);
    h = fnv_float(h, tb_body_get_angle(b));
    h = fnv_float(h, v.x);
    h = fnv_float(h, v.y);
    h = fnv_float(h, tb_body_get_angular_velocity(b));
  }
  free(list.items);
  return h;
}
