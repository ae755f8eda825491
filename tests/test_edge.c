/* Leaving an edge: bodies that roll or slide off the end of a face fall from
 * where the face ends, whatever part of a step that happens in; bodies that
 * roll over joints that do not end (a flat chain) are not let down there.
 *
 * The scene: a table top at y = 0 that ends at x = 0, made of a polygon, a
 * segment or a chain (which turns down the table's side there: a convex
 * joint). A body moves at V = 3 m/s along it and leaves it when its trailing
 * support passes x = 0: a rolling ball's centre (v^2 / r = 36 m/s^2 > g, so
 * the corner cannot hold it on a circle), the rear cap centre of a
 * frictionless capsule or the rear vertex of a frictionless box, both with
 * fixed rotation (a box free to turn tips over the edge: no closed form).
 * From there its centre falls freely: it has dropped by H after
 * T = sqrt(2 H / g), at V T beyond where it left. */
#include <math.h>

#include "test_util.h"

#define V 3.0
#define DROP 2.0
#define GRAVITY 10.0
#define DT (1.0 / 60.0)
#define LEAD_STEPS 10 /* steps from the start to the edge (whole ones; the phase adds a fraction) */

typedef enum mover { ROLLING_BALL, SLIDING_CAPSULE, SLIDING_BOX } mover;
typedef enum table { POLYGON_TABLE, SEGMENT_TABLE, CHAIN_TABLE } table;
static const char* const mover_name[] = {"rolling ball", "sliding capsule", "sliding box"};
static const char* const table_name[] = {"polygon", "segment", "chain"};

#define BALL_RADIUS 0.25f
#define HALF_LENGTH 0.3f /* the capsule's cap centres and the box's vertices at +-0.3 m */
#define HALF_HEIGHT 0.1f /* the capsule's radius, the box's half height */

static void add_table(tb_world_id w, table kind) {
  tb_body_def bd = tb_default_body_def();
  tb_body_id ground = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  if (kind == POLYGON_TABLE) {
    tb_polygon top;
    ck_assert_int_eq(tb_make_offset_box(10.0f, 0.5f, (tb_vec2){-10.0f, -0.5f}, 0.0f, &top), TB_OK);
    ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(ground, &sd, &top)));
  } else if (kind == SEGMENT_TABLE) {
    tb_segment top = {{-20.0f, 0.0f}, {0.0f, 0.0f}};
    ck_assert(!tb_shape_id_is_null(tb_create_segment_shape(ground, &sd, &top)));
  } else {
    /* a flat joint at x = -10 (the top runs on), a convex one at the edge */
    tb_vec2 points[4] = {{-20.0f, 0.0f}, {-10.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, -1.0f}};
    tb_chain_def cd = tb_default_chain_def();
    cd.points = points;
    cd.count = 4;
    ck_assert(!tb_chain_id_is_null(tb_create_chain(ground, &cd)));
  }
}

/* The body at rest height, its trailing support (LEAD_STEPS + phase) steps
 * of 1/60 s before the edge; returns the body and, in *behind, how far its
 * centre is ahead of its trailing support. */
static tb_body_id add_mover(tb_world_id w, mover kind, double phase, double* behind) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.linear_velocity = (tb_vec2){(float)V, 0.0f};
  tb_shape_def sd = tb_default_shape_def();
  double support = -((double)LEAD_STEPS + phase) * V * DT;
  *behind = kind == ROLLING_BALL ? 0.0 : HALF_LENGTH;
  float height = kind == ROLLING_BALL ? BALL_RADIUS : HALF_HEIGHT;
  bd.position = (tb_vec2){(float)(support + *behind), height};
  if (kind == ROLLING_BALL) {
    bd.angular_velocity = (float)(-V / BALL_RADIUS); /* rolling without slip: friction has nothing to do */
  } else {
    bd.fixed_rotation = true;
    sd.friction = 0.0f;
  }
  tb_body_id b = tb_create_body(w, &bd);
  if (kind == ROLLING_BALL) {
    tb_circle c = {{0.0f, 0.0f}, BALL_RADIUS};
    ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  } else if (kind == SLIDING_CAPSULE) {
    tb_capsule c = {{-HALF_LENGTH, 0.0f}, {HALF_LENGTH, 0.0f}, HALF_HEIGHT};
    ck_assert(!tb_shape_id_is_null(tb_create_capsule_shape(b, &sd, &c)));
  } else {
    tb_polygon box;
    ck_assert_int_eq(tb_make_box(HALF_LENGTH, HALF_HEIGHT, &box), TB_OK);
    ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(b, &sd, &box)));
  }
  return b;
}

/* How far beyond the edge the centre has travelled when it has dropped by
 * DROP below its start height, relative to V T: the centre's path between
 * two steps is taken as straight (off the parabola by g dt^2 / 8 = 0.35 mm
 * at a fall speed of 6 m/s: 1e-4 of the distance). */
static double landing_error(mover m, table t, double phase, int substeps) {
  tb_world_id w = tbt_world(0.0f, (float)-GRAVITY);
  add_table(w, t);
  double behind = 0.0;
  tb_body_id b = add_mover(w, m, phase, &behind);
  double level = (double)tb_body_get_position(b).y - DROP;
  tb_vec2 before = tb_body_get_position(b);
  double landed = NAN;
  for (int i = 0; i < 200 && isnan(landed); ++i) {
    ck_assert_int_eq(tb_world_step(w, (float)DT, substeps), TB_OK);
    tb_vec2 p = tb_body_get_position(b);
    if (p.y < level) {
      double f = ((double)before.y - level) / ((double)before.y - p.y);
      landed = before.x + f * ((double)p.x - before.x);
    }
    before = p;
  }
  tb_destroy_world(w);
  double closed = V * sqrt(2.0 * DROP / GRAVITY);
  return (landed - behind) / closed - 1.0;
}

/* Every body and table, with the edge passed at 10 phases of a step, at 4
 * and 8 substeps. The contact can only let go at a substep's end, and
 * semi-implicit Euler's fall from rest, y_k = -g h^2 k (k + 1) / 2, reaches
 * the drop at T - h/2 (plus O(h^2)): the fall starts and ends within a
 * substep h = dt / n of the closed form's times, so the landing is within
 * V h, h / T relative (0.66 % at 4 substeps, 0.33 % at 8). The solver
 * without the patch held the body up on the face for the rest of the step
 * it passed the edge in: up to 2.6 % further (rolling ball, 4 substeps). */
START_TEST(landing_matches_closed_form) {
  const double fall_time = sqrt(2.0 * DROP / GRAVITY);
  for (int n = 4; n <= 8; n *= 2) {
    double bound = DT / n / fall_time;
    for (int m = ROLLING_BALL; m <= SLIDING_BOX; ++m)
      for (int t = POLYGON_TABLE; t <= CHAIN_TABLE; ++t)
        for (int k = 0; k < 10; ++k) {
          double phase = (k + 0.5) / 10.0;
          double error = landing_error((mover)m, (table)t, phase, n);
          ck_assert_msg(fabs(error) <= bound,
                        "%s off a %s table, phase %.2f, %d substeps: lands %.3f %% off (> %.3f %%)", mover_name[m],
                        table_name[t], phase, n, 100.0 * error, 100.0 * bound);
        }
  }
}
END_TEST

/* ---- joints that do not end ---------------------------------------------------- */

/* A ball rolling at 3 m/s along a flat chain of 0.3 m segments for 1 s, past
 * 10 joints: at a joint the face it leaves ends, but the next one carries on
 * at the same height, so the ball neither dips nor hops (the chain's ghost
 * vertices say so). Resting, the soft contact holds it g / omega^2 deep
 * (0.02 mm at 60 Hz, see solver.c); a face that let go at the joint would
 * let it fall for the rest of the step, up to g dt^2 / 2 = 1.4 mm, and the
 * next face would push it back out: the bounds are 0.1 mm of dip and
 * 0.01 m/s of vertical speed (one substep of unheld fall gives g h = 0.04).
 * (Separate boxes side by side are another matter: the next box's corner
 * meets the ball with a normal tilted against its motion, a known ghost
 * collision that chains exist to avoid.) */
START_TEST(rolling_over_chain_joints) {
  tb_world_id w = tbt_world(0.0f, (float)-GRAVITY);
  tb_body_def gd = tb_default_body_def();
  tb_body_id ground = tb_create_body(w, &gd);
  enum { PIECES = 16 };
  tb_vec2 points[PIECES + 1];
  for (int i = 0; i <= PIECES; ++i) points[i] = (tb_vec2){-1.0f + 0.3f * (float)i, 0.0f};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = points;
  cd.count = PIECES + 1;
  ck_assert(!tb_chain_id_is_null(tb_create_chain(ground, &cd)));
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){-0.8f, BALL_RADIUS};
  bd.linear_velocity = (tb_vec2){(float)V, 0.0f};
  bd.angular_velocity = (float)(-V / BALL_RADIUS);
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0.0f, 0.0f}, BALL_RADIUS};
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  double dip = 0.0, hop = 0.0;
  for (int i = 0; i < 60; ++i) {
    ck_assert_int_eq(tb_world_step(w, (float)DT, 4), TB_OK);
    dip = fmax(dip, BALL_RADIUS - (double)tb_body_get_position(b).y);
    hop = fmax(hop, fabs((double)tb_body_get_linear_velocity(b).y));
  }
  ck_assert_msg(dip < 1e-4 && hop < 0.01, "ball dipped %.3g m, vertical speed up to %.3g m/s", dip, hop);
  ck_assert_rel(tb_body_get_position(b).x, -0.8 + V, 1e-3); /* rolled on at 3 m/s, over 10 joints */
  tb_destroy_world(w);
}
END_TEST

/* ---- corners that are closed ------------------------------------------------- */

/* A bullet (radius 2.5 cm) sliding at 200 m/s along a ceiling, pushed up
 * into it at 30 m/s, 0.5 m from where a wall closes the corner: ceiling and
 * wall are two 1 cm boxes of one static body that overlap at the corner.
 * The wall is 20 bullet radii away, far outside the contacts of the step
 * start (continuous collision is to stop the bullet there), and the ceiling
 * contact's face ends inside the wall: were it let go when the bullet passes
 * that end, the bullet would be out through the corner (the stress suite's
 * bullets did so, 52 of 1000). It must stay inside the room. */
START_TEST(closed_corner_holds_bullet) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_def rd = tb_default_body_def();
  tb_body_id room = tb_create_body(w, &rd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon wall;
  ck_assert_int_eq(tb_make_offset_box(10.005f, 0.005f, (tb_vec2){0.0f, 10.0f}, 0.0f, &wall), TB_OK);
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(room, &sd, &wall)));
  ck_assert_int_eq(tb_make_offset_box(0.005f, 10.005f, (tb_vec2){10.0f, 0.0f}, 0.0f, &wall), TB_OK);
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(room, &sd, &wall)));
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.is_bullet = true;
  bd.position = (tb_vec2){9.5f, 9.97f};
  bd.linear_velocity = (tb_vec2){200.0f, 30.0f};
  tb_body_id b = tb_create_body(w, &bd);
  tb_circle c = {{0.0f, 0.0f}, 0.025f};
  sd.density = 10.0f;
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  for (int i = 0; i < 10; ++i) {
    ck_assert_int_eq(tb_world_step(w, (float)DT, 4), TB_OK);
    tb_vec2 p = tb_body_get_position(b);
    ck_assert_msg(p.x < 10.0f && p.y < 10.0f, "step %d: bullet at (%g, %g), outside the room", i, (double)p.x,
                  (double)p.y);
  }
  tb_destroy_world(w);
}
END_TEST

static Suite* edge_suite(void) {
  Suite* s = suite_create("edge");
  TCase* tc = tcase_create("core");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, landing_matches_closed_form);
  tcase_add_test(tc, rolling_over_chain_joints);
  tcase_add_test(tc, closed_corner_holds_bullet);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(edge_suite)
