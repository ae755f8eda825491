/* Box2D v3's benchmark scenes (v3_scenes.h), written from the description of
 * each in v3's shared/benchmarks.c with tumble's API. Defaults as v3's: density
 * 1, friction 0.6, restitution 0, gravity (0, -10). `scale` in (0, 1]
 * multiplies every count along a side (the body count goes as scale^2).
 *
 * rain and junkyard keep state between the build and the update hook (the
 * humans to destroy, the pusher to drive), as v3's do: one world of each at a
 * time; the hook does nothing for a world other than the last one built. */
#include "v3_scenes.h"

#include <math.h>

#include "human.h"
#include "scene_build.h"

/* A static body of boxes: a floor of `floor` boxes (half 0.55 x 0.5) centred
 * on y = 0 from x = -half_width, and walls of `wall` boxes (half 0.5 x 0.55)
 * from y = 1 up at x = -half_width and x = +half_width: the container of
 * compounds and junkyard. */
static tb_body_id box_container(tb_world_id world, float half_width, int floor, int wall) {
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  for (int i = 0; i < floor; ++i) add_offset_box(g, &sd, 0.55f, 0.5f, -half_width + (float)i, 0.0f, 0.0f);
  for (int side = -1; side <= 1; side += 2)
    for (int i = 0; i < wall; ++i) add_offset_box(g, &sd, 0.5f, 0.55f, (float)side * half_width, 1.0f + (float)i, 0.0f);
  return g;
}

/* ---------------------------------------------------------- compounds -- */

/* compounds: 20 columns x 150 rows of bodies made of two triangles each
 * (density 1, friction 0.5), 2 m apart across and 2.25 m up from y = 5.575,
 * shifted alternately 0.25 m right and left, into a container 80 m wide and
 * 100 m high (with a long segment 80 m below for what falls out). */
void build_compounds(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = box_container(world, 40.0f, 81, 100);
  tb_shape_def gd = tb_default_shape_def();
  tb_segment floor = {{-800.0f, -80.0f}, {800.0f, -80.0f}};
  tb_create_segment_shape(g, &gd, &floor);

  const tb_vec2 left_points[3] = {{-1.0f, 0.0f}, {0.5f, 1.0f}, {0.0f, 2.0f}};
  const tb_vec2 right_points[3] = {{1.0f, 0.0f}, {-0.5f, 1.0f}, {0.0f, 2.0f}};
  tb_polygon left, right;
  if (tb_make_polygon(left_points, 3, 0.0f, &left) != TB_OK || tb_make_polygon(right_points, 3, 0.0f, &right) != TB_OK)
    return;
  tb_shape_def sd = shape_def(1.0f, 0.5f, 0.0f);
  const int columns = scaled(20, scale, 1), rows = scaled(150, scale, 1);
  const float shift = 2.0f, extra_y = 0.25f;
  const float center_x = shift * (float)columns / 2.0f - 1.0f, center_y = 1.15f / 2.0f, y_start = 5.0f;
  float side = 0.25f;
  for (int i = 0; i < columns; ++i) {
    float x = (float)i * shift - center_x;
    for (int j = 0; j < rows; ++j) {
      float y = (float)j * (shift + extra_y) + center_y + y_start;
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x + side, y, 0.0f, NULL);
      side = -side;
      tb_create_polygon_shape(b, &sd, &left);
      tb_create_polygon_shape(b, &sd, &right);
    }
  }
}

/* ----------------------------------------------------------- junkyard -- */

static struct {
  tb_world_id world;
  tb_body_id pusher;
} g_junkyard;

/* junkyard: 200 columns x 40 rows of pentagons (radius 0.25: the hull of five
 * points at angles pi (sqrt 5 - 1) i) dropped from y = 15 into a container 160
 * m wide and 50 m high, and a kinematic pusher (a 4 x 8 m box standing on the
 * floor) driven to x = 60 sin(0.2 t). */
void build_junkyard(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  box_container(world, 80.0f, 161, 50);

  const float radius = 0.25f, phi = PI_F * (sqrtf(5.0f) - 1.0f);
  tb_vec2 points[5];
  for (int i = 0; i < 5; ++i) points[i] = (tb_vec2){radius * cosf(phi * (float)i), radius * sinf(phi * (float)i)};
  tb_polygon pentagon;
  if (tb_make_polygon(points, 5, 0.0f, &pentagon) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  const int columns = scaled(200, scale, 1), rows = scaled(40, scale, 1);
  float side = -0.1f;
  for (int i = 0; i < columns; ++i) {
    float x = 1.5f * (float)(2 * i - columns) * radius;
    for (int j = 0; j < rows; ++j) {
      float y = 4.0f * (float)j * radius + 15.0f;
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x + side, y, 0.0f, NULL);
      side = -side;
      tb_create_polygon_shape(b, &sd, &pentagon);
    }
  }
  g_junkyard.world = world;
  g_junkyard.pusher = body_at(world, TB_KINEMATIC_BODY, 0.0f, 0.0f, 0.0f, "pusher");
  add_offset_box(g_junkyard.pusher, &sd, 2.0f, 4.0f, 0.0f, 4.0f, 0.0f);
}

/* The pusher moves to its target of the next step within the step: its
 * velocity is the distance over the 1/60 s step. */
void update_junkyard(tb_world_id world, int step) {
  if (world.index1 != g_junkyard.world.index1 || world.generation != g_junkyard.world.generation) return;
  const float dt = 1.0f / 60.0f;
  float target_x = 60.0f * sinf(0.2f * dt * (float)step);
  tb_vec2 p = tb_body_get_position(g_junkyard.pusher);
  tb_body_set_linear_velocity(g_junkyard.pusher, (tb_vec2){(target_x - p.x) / dt, -p.y / dt});
}

/* --------------------------------------------------------------- rain -- */

#define RAIN_ROWS 5
#define RAIN_COLUMNS 40
#define RAIN_GROUP 5        /* humans per group */
#define RAIN_GRID_COUNT 500 /* ground boxes per shelf */
#define RAIN_GRID_SIZE 0.5f

static struct {
  tb_world_id world;
  int rows, columns;
  int columns_spawned, next_column;
  human humans[RAIN_ROWS * RAIN_COLUMNS][RAIN_GROUP];
} g_rain;

/* rain: five shelves 45 m apart (y = 0 ... 180), each a row of 501 static
 * boxes of 0.5 m (250 m wide). Every 8 steps a column of groups is spawned
 * 40 m above each shelf (groups of 5 humans, 0.5 m apart, 40 columns across
 * the 250 m): once all 40 columns are there, the oldest column is destroyed
 * and spawned anew, round and round. Humans: scale 1, joint friction 0.05 N m,
 * joint springs of 5 Hz and damping ratio 0.5; the i-th human of every group
 * is in filter group -(i + 1), so the i-th humans of all groups never touch
 * one another (as in v3). */
void build_rain(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  g_rain.rows = scaled(RAIN_ROWS, scale, 1);
  g_rain.columns = scaled(RAIN_COLUMNS, scale, 1);
  for (int i = 0; i < g_rain.rows; ++i) {
    float x = -0.5f * (float)RAIN_GRID_COUNT * RAIN_GRID_SIZE, y = 45.0f * (float)i;
    for (int j = 0; j <= RAIN_GRID_COUNT; ++j) {
      add_offset_box(g, &sd, 0.5f * RAIN_GRID_SIZE, 0.5f * RAIN_GRID_SIZE, x, y, 0.0f);
      x += RAIN_GRID_SIZE;
    }
  }
  g_rain.world = world;
  g_rain.columns_spawned = 0;
  g_rain.next_column = 0;
}

static void rain_spawn(tb_world_id world, int row, int column) {
  float span = (float)RAIN_GRID_COUNT * RAIN_GRID_SIZE;
  float x = -0.5f * span + span / (float)g_rain.columns * ((float)column + 0.5f);
  float y = 40.0f + 45.0f * (float)row;
  for (int i = 0; i < RAIN_GROUP; ++i) {
    g_rain.humans[row * RAIN_COLUMNS + column][i] =
        human_create(world, (tb_vec2){x, y}, 1.0f, 0.05f, 5.0f, 0.5f, i + 1);
    x += 0.5f;
  }
}

void update_rain(tb_world_id world, int step) {
  if (world.index1 != g_rain.world.index1 || world.generation != g_rain.world.generation) return;
  if ((step & 7) != 0) return;
  if (g_rain.columns_spawned < g_rain.columns) {
    for (int row = 0; row < g_rain.rows; ++row) rain_spawn(world, row, g_rain.columns_spawned);
    g_rain.columns_spawned += 1;
    return;
  }
  int column = g_rain.next_column;
  for (int row = 0; row < g_rain.rows; ++row) {
    for (int i = 0; i < RAIN_GROUP; ++i) human_destroy(&g_rain.humans[row * RAIN_COLUMNS + column][i]);
    rain_spawn(world, row, column);
  }
  g_rain.next_column = (column + 1) % g_rain.columns;
}

/* ------------------------------------------------------------ spinner -- */

#define SPINNER_POINTS 360

/* spinner: a static loop chain of 360 points on a circle of radius 40 centred
 * at (0, 32) (friction 0.1), inside it a rounded bar (core 0.8 x 40 m, radius
 * 0.2, friction 0, never sleeping) pinned at (0, 12) and driven by a revolute
 * motor at 5 rad/s with no torque limit worth the name, and 6,076 bodies
 * (capsules, circles and squares in turn; friction 0.1, restitution 0.1,
 * density 0.25) on a lattice 0.5 m apart from (-23, 2). v3 lists the circle
 * clockwise because its chains collide on their right; tumble's collide on
 * their left, so the same circle is listed counter-clockwise. */
void build_spinner(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_vec2 points[SPINNER_POINTS];
  const float step_angle = 2.0f * PI_F / (float)SPINNER_POINTS;
  const float c = cosf(step_angle), s = sinf(step_angle);
  tb_vec2 p = {40.0f, 0.0f};
  for (int i = 0; i < SPINNER_POINTS; ++i) {
    points[i] = (tb_vec2){p.x, p.y + 32.0f};
    p = (tb_vec2){c * p.x - s * p.y, s * p.x + c * p.y};
  }
  tb_chain_def cd = tb_default_chain_def();
  cd.points = points;
  cd.count = SPINNER_POINTS;
  cd.is_loop = true;
  cd.friction = 0.1f;
  tb_create_chain(g, &cd);

  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){0.0f, 12.0f};
  bd.enable_sleep = false;
  bd.user_data = (void*)"spinner";
  tb_body_id spinner = tb_create_body(world, &bd);
  tb_polygon bar;
  if (tb_make_rounded_box(0.4f, 20.0f, 0.2f, &bar) != TB_OK) return;
  tb_shape_def bar_def = shape_def(1.0f, 0.0f, 0.0f);
  tb_create_polygon_shape(spinner, &bar_def, &bar);
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = g;
  jd.body_b = spinner;
  jd.local_anchor_a = (tb_vec2){0.0f, 12.0f};
  jd.enable_motor = true;
  jd.motor_speed = 5.0f;
  jd.max_motor_torque = TB_MAX_VALUE;
  tb_create_revolute_joint(world, &jd);

  tb_capsule capsule = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f};
  tb_circle circle = {{0.0f, 0.0f}, 0.35f};
  tb_polygon square;
  if (tb_make_box(0.35f, 0.35f, &square) != TB_OK) return;
  tb_shape_def sd = shape_def(0.25f, 0.1f, 0.1f);
  float fscale = scale > 0.0f && scale <= 1.0f ? scale : 1.0f;
  int count = (int)lroundf(2.0f * 3038.0f * fscale * fscale);
  float x = -23.0f, y = 2.0f;
  for (int i = 0; i < count; ++i) {
    tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
    if (i % 3 == 0)
      tb_create_capsule_shape(b, &sd, &capsule);
    else if (i % 3 == 1)
      tb_create_circle_shape(b, &sd, &circle);
    else
      tb_create_polygon_shape(b, &sd, &square);
    x += 0.5f;
    if (x >= 23.0f) {
      x = -23.0f;
      y += 0.5f;
    }
  }
}

/* ------------------------------------------------------------ tumbler -- */

/* tumbler: a hollow box (four walls 1 m thick, density 50, centre lines on a
 * 20 m square) on a dynamic body at (0, 10), pinned there to the ground by a
 * revolute joint whose motor turns it at 25 deg/s (up to 1e8 N m). Inside, a
 * 45 x 45 grid of boxes of 0.25 m (half 0.125), 0.4 m apart, from (-9, 1). */
void build_tumbler(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_body_id c = body_at(world, TB_DYNAMIC_BODY, 0.0f, 10.0f, 0.0f, "container");
  tb_shape_def wall = shape_def(50.0f, 0.6f, 0.0f);
  add_offset_box(c, &wall, 0.5f, 10.0f, 10.0f, 0.0f, 0.0f);
  add_offset_box(c, &wall, 0.5f, 10.0f, -10.0f, 0.0f, 0.0f);
  add_offset_box(c, &wall, 10.0f, 0.5f, 0.0f, 10.0f, 0.0f);
  add_offset_box(c, &wall, 10.0f, 0.5f, 0.0f, -10.0f, 0.0f);
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = g;
  jd.body_b = c;
  jd.local_anchor_a = (tb_vec2){0.0f, 10.0f};
  jd.enable_motor = true;
  jd.motor_speed = 25.0f * PI_F / 180.0f;
  jd.max_motor_torque = 1e8f;
  tb_create_revolute_joint(world, &jd);

  int n = scaled(45, scale, 1);
  tb_polygon box;
  if (tb_make_box(0.125f, 0.125f, &box) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  float y = -0.2f * (float)n + 10.0f;
  for (int i = 0; i < n; ++i) {
    float x = -0.2f * (float)n;
    for (int j = 0; j < n; ++j) {
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
      tb_create_polygon_shape(b, &sd, &box);
      x += 0.4f;
    }
    y += 0.4f;
  }
}

/* ------------------------------------------------------------- washer -- */

/* washer: a kinematic drum at (0, 10) turning at 25 deg/s (and drifting at
 * (0.001, -0.002) m/s, as v3's does): 36 blocks of a ring between radii 16
 * and 18, each spanning its 10 degrees and 1 degree more on either side, and
 * 4 paddles (every 9th sector, radii 14 to 16). Inside, 90 x 90 squares of
 * 0.2 m (half 0.1) 0.21 m apart, with hit events on. */
void build_washer(tb_world_id world, float scale) {
  tb_world_set_gravity(world, (tb_vec2){0.0f, -10.0f});
  body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL); /* v3's ground body, without shapes */
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_KINEMATIC_BODY;
  bd.position = (tb_vec2){0.0f, 10.0f};
  bd.angular_velocity = 25.0f * PI_F / 180.0f;
  bd.linear_velocity = (tb_vec2){0.001f, -0.002f};
  bd.user_data = (void*)"drum";
  tb_body_id drum = tb_create_body(world, &bd);
  tb_shape_def wall = tb_default_shape_def();
  const float r0 = 14.0f, r1 = 16.0f, r2 = 18.0f, sector = PI_F / 18.0f;
  const float cq = cosf(sector), sq = sinf(sector), co = cosf(0.1f * sector), so = sinf(0.1f * sector);
  tb_vec2 u1 = {1.0f, 0.0f};
  for (int i = 0; i < 36; ++i) {
    tb_vec2 u2 = i == 35 ? (tb_vec2){1.0f, 0.0f} : (tb_vec2){cq * u1.x - sq * u1.y, sq * u1.x + cq * u1.y};
    tb_vec2 a1 = {co * u1.x + so * u1.y, -so * u1.x + co * u1.y}; /* u1 turned back a tenth of a sector */
    tb_vec2 a2 = {co * u2.x - so * u2.y, so * u2.x + co * u2.y};  /* u2 turned on a tenth */
    tb_vec2 block[4] = {{r1 * a1.x, r1 * a1.y}, {r2 * a1.x, r2 * a1.y}, {r1 * a2.x, r1 * a2.y}, {r2 * a2.x, r2 * a2.y}};
    tb_polygon polygon;
    if (tb_make_polygon(block, 4, 0.0f, &polygon) == TB_OK) tb_create_polygon_shape(drum, &wall, &polygon);
    if (i % 9 == 0) {
      tb_vec2 paddle[4] = {
          {r0 * u1.x, r0 * u1.y}, {r1 * u1.x, r1 * u1.y}, {r0 * u2.x, r0 * u2.y}, {r1 * u2.x, r1 * u2.y}};
      if (tb_make_polygon(paddle, 4, 0.0f, &polygon) == TB_OK) tb_create_polygon_shape(drum, &wall, &polygon);
    }
    u1 = u2;
  }

  const int n = scaled(90, scale, 1);
  const float a = 0.1f;
  tb_polygon square;
  if (tb_make_box(a, a, &square) != TB_OK) return;
  tb_shape_def sd = tb_default_shape_def();
  sd.enable_hit_events = true;
  float y = -1.1f * a * (float)n + 10.0f;
  for (int i = 0; i < n; ++i) {
    float x = -1.1f * a * (float)n;
    for (int j = 0; j < n; ++j) {
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, NULL);
      tb_create_polygon_shape(b, &sd, &square);
      x += 2.1f * a;
    }
    y += 2.1f * a;
  }
}
