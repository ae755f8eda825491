/* Reference suite of the foundation (issue 2): tumble against Box2D 2.4.1.
 *
 * - mass properties (area, centroid, inertia about the centroid) of 1,000 random
 *   convex polygons;
 * - free motion over 600 steps of 1/60 s: free fall, projectile, damping, and a
 *   force applied at a fixed world point off the centre of a box.
 *
 * tumble runs one substep per step, which is exactly Box2D's island integration
 * for a body without contacts:
 *   v += h invM (gs M g + F); w += h invI T; v *= 1/(1 + h c_v); w *= 1/(1 + h c_w);
 *   x += h v; a += h w
 * except that tumble's x += h v keeps the part rounding drops (see
 * run_ballistic).
 * The one difference in operation order: tumble computes the velocity increment
 * as h (gs g + invM F), Box2D as (h invM)(gs M g + F). They agree bit for bit
 * when M and gs are powers of two (M invM = 1 and every product is exact).
 * Otherwise Box2D's increment can be an ulp of the increment off, far below an
 * ulp of the velocity it is added to, so the sums mostly round alike; measured
 * differences stay at one ulp of the velocity or the position. The ballistic
 * scenes therefore fly two balls: one whose mass is exactly 1 in both engines
 * (bit-for-bit agreement expected) and a plain one (radius 0.5, density 1) that
 * shows the rounding. The measured maxima are printed on stderr.
 *
 * Box2D clamps a step's translation to 2 m and rotation to pi/2: every scene
 * stays well below (at most 0.84 m and 0.43 rad per step). */
#include <math.h>
#include <stdio.h>

#include "../test_util.h"
#include "b2_shim.h"

#define STEPS 600
#define DT (1.0f / 60.0f)
#define VEL_ITERS 8
#define POS_ITERS 3

/* ---------------------------------------------------------------- helpers -- */

static double dmax(double a, double b) { return a > b ? a : b; }

/* Relative difference with an absolute floor for values near zero. */
static double rel_diff(double a, double b, double floor) { return fabs(a - b) / dmax(fabs(b), floor); }

typedef struct scene_body {
  float x, y, angle, vx, vy, w;
  float linear_damping, angular_damping, gravity_scale;
} scene_body;

static tb_body_def tumble_def(const scene_body* s) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){s->x, s->y};
  bd.angle = s->angle;
  bd.linear_velocity = (tb_vec2){s->vx, s->vy};
  bd.angular_velocity = s->w;
  bd.linear_damping = s->linear_damping;
  bd.angular_damping = s->angular_damping;
  bd.gravity_scale = s->gravity_scale;
  return bd;
}

static b2s_body_def box2d_def(const scene_body* s) {
  b2s_body_def bd = b2s_default_body_def();
  bd.x = s->x;
  bd.y = s->y;
  bd.angle = s->angle;
  bd.vx = s->vx;
  bd.vy = s->vy;
  bd.w = s->w;
  bd.linear_damping = s->linear_damping;
  bd.angular_damping = s->angular_damping;
  bd.gravity_scale = s->gravity_scale;
  return bd;
}

/* The same body in both engines: one circle (radius > 0) or one centred box. */
typedef struct pair {
  tb_world_id tw;
  tb_body_id tb;
  b2s_world* bw;
  b2s_body* bb;
} pair;

static pair make_pair(tb_vec2 gravity, const scene_body* s, float radius, float hx, float hy, float density) {
  pair p;
  p.tw = tbt_world(gravity.x, gravity.y);
  tb_world_set_integrator(p.tw, TB_INTEGRATOR_SEMI_IMPLICIT_EULER); /* Box2D's scheme */
  tb_body_def bd = tumble_def(s);
  p.tb = tb_create_body(p.tw, &bd);
  ck_assert_msg(!tb_body_id_is_null(p.tb), "tb_create_body: %s", tb_last_error());
  tb_shape_def sd = tb_default_shape_def();
  sd.density = density;
  p.bw = b2s_world_create(gravity.x, gravity.y);
  ck_assert_ptr_nonnull(p.bw);
  b2s_body_def b2d = box2d_def(s);
  p.bb = b2s_body_create(p.bw, &b2d);
  ck_assert_ptr_nonnull(p.bb);
  if (radius > 0.0f) {
    tb_circle c = {{0.0f, 0.0f}, radius};
    ck_assert_msg(!tb_shape_id_is_null(tb_create_circle_shape(p.tb, &sd, &c)), "%s", tb_last_error());
    ck_assert_int_eq(b2s_body_add_circle(p.bb, 0.0f, 0.0f, radius, density), 1);
  } else {
    tb_polygon box;
    ck_assert_int_eq(tb_make_box(hx, hy, &box), TB_OK);
    ck_assert_msg(!tb_shape_id_is_null(tb_create_polygon_shape(p.tb, &sd, &box)), "%s", tb_last_error());
    ck_assert_int_eq(b2s_body_add_box(p.bb, hx, hy, 0.0f, 0.0f, 0.0f, density), 1);
  }
  /* Same mass properties to start with (each engine's own rounding only). */
  b2s_mass bm;
  b2s_body_get_mass(p.bb, &bm);
  ck_assert_rel(tb_body_get_mass(p.tb), bm.mass, 1e-6);
  ck_assert_rel(tb_body_get_rotational_inertia(p.tb), bm.inertia, 1e-6);
  return p;
}

static void free_pair(pair* p) {
  ck_assert_int_eq(tb_destroy_world(p->tw), TB_OK);
  b2s_world_destroy(p->bw);
}

static void step_pair(pair* p) {
  ck_assert_int_eq(tb_world_step(p->tw, DT, 1), TB_OK);
  b2s_world_step(p->bw, DT, VEL_ITERS, POS_ITERS);
}

/* Largest per-step differences seen over a run. */
typedef struct errors {
  double pos;   /* |origin difference|, m */
  double vel;   /* |velocity difference|, m/s */
  double omega; /* |w difference|, rad/s */
  double angle; /* |angle difference|, rad */
} errors;

/* Compares the two bodies after a step; returns this step's differences and
 * raises the running maxima. */
static errors compare_pair(const pair* p, errors* max) {
  b2s_body_state s;
  b2s_body_get_state(p->bb, &s);
  tb_vec2 x = tb_body_get_position(p->tb), v = tb_body_get_linear_velocity(p->tb);
  errors e = {hypot((double)x.x - s.x, (double)x.y - s.y), hypot((double)v.x - s.vx, (double)v.y - s.vy),
              fabs((double)tb_body_get_angular_velocity(p->tb) - s.w),
              fabs((double)tb_body_get_angle(p->tb) - s.angle)};
  max->pos = dmax(max->pos, e.pos);
  max->vel = dmax(max->vel, e.vel);
  max->omega = dmax(max->omega, e.omega);
  max->angle = dmax(max->angle, e.angle);
  return e;
}

/* The balls of the ballistic scenes. The unit ball's density is 1 / (pi 0.4^2)
 * rounded to the float for which both engines' circle mass, Box2D's
 * ((rho b2_pi) r) r in float and tumble's rho pi r^2 in double, is exactly 1. */
typedef struct ball {
  const char* name;
  float radius, density;
  float mass; /* expected in both engines, or 0 if not a power of two */
} ball;

static const ball balls[] = {{"unit-mass ball", 0.4f, 0x1.fd4bbap+0f, 1.0f}, {"plain ball", 0.5f, 1.0f, 0.0f}};

/* Ballistic flight: every step, the velocities within 1e-5 m/s of Box2D's.
 * Positions: both engines add the same float displacement dt v each step, but
 * Box2D rounds the sum to a float every step while tumble keeps what the
 * rounding drops (center_residual), so its position is the float nearest the
 * exact sum of its displacements, X (summed here in double), where Box2D's
 * drifts from X by its accumulated rounding (measured over 600 steps: 6.2e-6 m
 * in free fall, 1.5e-4 m for the projectile; tumble 9.5e-7 and 2.1e-6 m).
 * So: tumble within 1e-5 m of X (half an ulp of the position and the rounding
 * of the small sums), and within 1e-5 m of Box2D beyond Box2D's own distance
 * from X. Returns the maxima (pos: against Box2D). */
static errors run_ballistic(tb_vec2 gravity, const scene_body* s, const ball* b) {
  pair p = make_pair(gravity, s, b->radius, 0.0f, 0.0f, b->density);
  if (b->mass > 0.0f) {
    b2s_mass bm;
    b2s_body_get_mass(p.bb, &bm);
    ck_assert_float_eq(tb_body_get_mass(p.tb), b->mass);
    ck_assert_double_eq(bm.mass, b->mass);
  }
  errors max = {0, 0, 0, 0};
  double X = s->x, Y = s->y, off_exact = 0.0, box2d_off_exact = 0.0;
  for (int i = 0; i < STEPS; ++i) {
    step_pair(&p);
    errors e = compare_pair(&p, &max);
    tb_vec2 x = tb_body_get_position(p.tb), v = tb_body_get_linear_velocity(p.tb);
    X += (double)(DT * v.x); /* the float displacement tumble's one substep adds */
    Y += (double)(DT * v.y);
    b2s_body_state bs;
    b2s_body_get_state(p.bb, &bs);
    double tumble_off = hypot((double)x.x - X, (double)x.y - Y), box2d_off = hypot((double)bs.x - X, (double)bs.y - Y);
    off_exact = dmax(off_exact, tumble_off);
    box2d_off_exact = dmax(box2d_off_exact, box2d_off);
    ck_assert_msg(tumble_off <= 1e-5, "%s, step %d: %.3g m from the exact sum of its steps", b->name, i + 1,
                  tumble_off);
    ck_assert_msg(e.pos <= 1e-5 + box2d_off, "%s, step %d: positions differ by %.3g m (Box2D %.3g m from exact)",
                  b->name, i + 1, e.pos, box2d_off);
    ck_assert_msg(e.vel <= 1e-5, "%s, step %d: velocities differ by %.3g m/s", b->name, i + 1, e.vel);
  }
  fprintf(stderr, "reference_foundation: %s: from the exact sum of the steps: tumble %.3g m, Box2D %.3g m\n", b->name,
          off_exact, box2d_off_exact);
  free_pair(&p);
  return max;
}

static void run_ballistic_balls(const char* scene, tb_vec2 gravity, const scene_body* s) {
  for (size_t i = 0; i < sizeof balls / sizeof balls[0]; ++i) {
    errors e = run_ballistic(gravity, s, &balls[i]);
    fprintf(stderr, "reference_foundation: %s, %s: max |dx| %.3g m, |dv| %.3g m/s\n", scene, balls[i].name, e.pos,
            e.vel);
  }
}

/* ------------------------------------------------------- polygon mass data -- */

#define POLYGONS 1000
#define MASS_TOL 1e-5

/* Convex polygons from random points: 3..8 points around an ellipse (half axes
 * extent/2 and 0.2..1 of that, random rotation), either all on the ellipse (at
 * angles spread over the turn: a hull of all of them) or at 0.3..1 of its radius
 * (interior points drop out of the hull). extent is log-uniform in 0.05..50 m,
 * the size range tumble is tuned for. The polygon's size D is the diameter of
 * its points (that of the hull, unless welding drops an extreme point).
 *
 * Three quarters of the polygons are moved off the origin by an offset o of up to
 * 50 D in each coordinate; tumble gets the points p = o + q. Box2D gets
 * q' = p - o, computed in float and checked to be exact, i.e. the same point set
 * in a frame at the polygon: Box2D's float ComputeMass loses precision with the
 * distance from the origin (it shifts the inertia to the origin,
 * I += m (|c|^2 - |c - v0|^2), a cancellation of relative size
 * 2^-24 |c|^2 / (I / m)), and the point here is to check that tumble does not.
 * The other quarter sits at the origin, where both get literally the same points.
 *
 * Tolerances (MASS_TOL = 1e-5):
 * - area (the mass at density 1): relative. tumble integrates in double; Box2D
 *   sums at most 8 fan triangles (all of positive area) in float, an error of a
 *   few 2^-24 (measured: up to 3.5e-7).
 * - inertia about the centroid: relative. Box2D's float inertia about vertex 0
 *   loses m |c - v0|^2 to the parallel-axis shift, which amplifies its rounding
 *   by (k^2 + |c - v0|^2) / k^2 (k the radius of gyration), up to about 10 for
 *   the thinnest polygons here (measured: up to 3e-6 over several seeds).
 * - centroid: relative to the polygon's size, i.e. an absolute tolerance of
 *   MASS_TOL * D. A relative error of the centroid's coordinates would mean
 *   nothing for a polygon around the origin (centroid near 0), and tumble's
 *   float centroid c is rounded by up to half an ulp, 2^-24 |c|: with
 *   |c| <= 51 D per coordinate that is 3.0e-6 D, 4.3e-6 D as a distance, within
 *   the tolerance together with Box2D's own float error (a few 2^-24 D).
 *   (Measured: up to 3.3e-6 D.) */
typedef struct poly_stats {
  int compared, rejected, hull_differs, offset_moved;
  int hull_counts[TB_MAX_POLYGON_VERTICES + 1];
  double area, centroid, inertia;
} poly_stats;

/* Does Box2D's hull (in its frame, shifted by o) have exactly tumble's vertices? */
static bool same_hull(const tb_polygon* poly, const float* hull, int count, tb_vec2 o) {
  if (count != poly->count) return false;
  for (int i = 0; i < count; ++i) {
    bool found = false;
    for (int j = 0; j < count && !found; ++j)
      found = (double)hull[2 * j] + o.x == (double)poly->vertices[i].x &&
              (double)hull[2 * j + 1] + o.y == (double)poly->vertices[i].y;
    if (!found) return false;
  }
  return true;
}

static double diameter(const tb_vec2* v, int n) {
  double d = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) d = dmax(d, hypot((double)v[i].x - v[j].x, (double)v[i].y - v[j].y));
  return d;
}

/* body: a body of a scratch world, to check that tumble takes each polygon as a
 * shape with the same mass data. */
static void compare_polygon(int trial, unsigned* seed, tb_body_id body, poly_stats* st) {
  int n = 3 + trial % 6;
  float extent = 0.05f * powf(1000.0f, tbt_rand(seed, 0.0f, 1.0f));
  float a = 0.5f * extent, b = a * tbt_rand(seed, 0.2f, 1.0f);
  float rot = tbt_rand(seed, 0.0f, 6.2831853f), phase = tbt_rand(seed, 0.0f, 6.2831853f);
  bool interior = tbt_rand(seed, 0.0f, 1.0f) < 0.5f;
  tb_vec2 q[TB_MAX_POLYGON_VERTICES], pts[TB_MAX_POLYGON_VERTICES];
  for (int i = 0; i < n; ++i) {
    float t = 6.2831853f * ((float)i + tbt_rand(seed, 0.0f, 0.8f)) / (float)n + phase;
    float r = interior ? tbt_rand(seed, 0.3f, 1.0f) : 1.0f;
    float ex = a * r * cosf(t), ey = b * r * sinf(t);
    q[i] = (tb_vec2){cosf(rot) * ex - sinf(rot) * ey, sinf(rot) * ex + cosf(rot) * ey};
  }
  double size = diameter(q, n);
  tb_vec2 o = {0.0f, 0.0f};
  if (tbt_rand(seed, 0.0f, 1.0f) < 0.75f)
    o = (tb_vec2){(float)size * tbt_rand(seed, -50.0f, 50.0f), (float)size * tbt_rand(seed, -50.0f, 50.0f)};

  float local[2 * TB_MAX_POLYGON_VERTICES];
  bool exact = true;
  for (int i = 0; i < n; ++i) {
    pts[i] = (tb_vec2){o.x + q[i].x, o.y + q[i].y};
    local[2 * i] = pts[i].x - o.x;
    local[2 * i + 1] = pts[i].y - o.y;
    exact =
        exact && (double)local[2 * i] == (double)pts[i].x - o.x && (double)local[2 * i + 1] == (double)pts[i].y - o.y;
  }
  if (!exact) { /* p - o was rounded (rare): use the points at the origin instead */
    st->offset_moved += 1;
    o = (tb_vec2){0.0f, 0.0f};
    for (int i = 0; i < n; ++i) {
      pts[i] = q[i];
      local[2 * i] = q[i].x;
      local[2 * i + 1] = q[i].y;
    }
  }

  tb_polygon poly;
  tb_result r = tb_make_polygon(pts, n, 0.0f, &poly);
  b2s_mass bm;
  float hull[2 * B2S_MAX_POLYGON_VERTICES];
  int hull_count = 0;
  int ok = b2s_polygon_mass(local, n, 1.0f, &bm, hull, &hull_count);
  if (r != TB_OK || !ok) {
    /* these points can only be degenerate, never invalid */
    ck_assert_msg(r == TB_OK || r == TB_ERR_DEGENERATE_POLYGON, "polygon %d: %s", trial, tb_result_name(r));
    st->rejected += 1;
    return;
  }
  if (!same_hull(&poly, hull, hull_count, o)) {
    /* Box2D welds at 0.5 slop (tumble at 1 slop) and keeps nearly collinear
     * vertices (tumble drops those within 0.5 slop of their neighbours' line):
     * give Box2D tumble's hull, which it must take as it is. */
    st->hull_differs += 1;
    for (int i = 0; i < poly.count; ++i) {
      local[2 * i] = poly.vertices[i].x - o.x;
      local[2 * i + 1] = poly.vertices[i].y - o.y;
    }
    ck_assert_int_eq(b2s_polygon_mass(local, poly.count, 1.0f, &bm, hull, &hull_count), 1);
    ck_assert_msg(same_hull(&poly, hull, hull_count, o), "polygon %d: Box2D changed tumble's hull", trial);
  }

  tb_mass_data md = tb_compute_polygon_mass(&poly, 1.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id shape = tb_create_polygon_shape(body, &sd, &poly);
  ck_assert_msg(!tb_shape_id_is_null(shape), "polygon %d: %s", trial, tb_last_error());
  tb_mass_data smd = tb_shape_get_mass_data(shape);
  ck_assert(smd.mass == md.mass && smd.center.x == md.center.x && smd.center.y == md.center.y &&
            smd.rotational_inertia == md.rotational_inertia);
  ck_assert_int_eq(tb_destroy_shape(shape), TB_OK);
  double e_area = rel_diff(md.mass, bm.mass, 0.0);
  double e_c = hypot((double)md.center.x - (bm.cx + o.x), (double)md.center.y - (bm.cy + o.y)) / size;
  double e_pc = hypot((double)poly.centroid.x - (bm.cx + o.x), (double)poly.centroid.y - (bm.cy + o.y)) / size;
  double e_i = rel_diff(md.rotational_inertia, bm.inertia, 0.0);
  ck_assert_msg(e_area <= MASS_TOL, "polygon %d (%d vertices, extent %g): area %.9g vs Box2D %.9g, rel %.3g", trial,
                poly.count, (double)extent, (double)md.mass, bm.mass, e_area);
  ck_assert_msg(e_c <= MASS_TOL, "polygon %d (size %g, offset %g %g): centroid off by %.3g sizes", trial, size,
                (double)o.x, (double)o.y, e_c);
  ck_assert_msg(e_pc <= MASS_TOL, "polygon %d: tb_polygon.centroid off by %.3g sizes", trial, e_pc);
  ck_assert_msg(e_i <= MASS_TOL, "polygon %d (%d vertices, extent %g): inertia %.9g vs Box2D %.9g, rel %.3g", trial,
                poly.count, (double)extent, (double)md.rotational_inertia, bm.inertia, e_i);
  st->area = dmax(st->area, e_area);
  st->centroid = dmax(st->centroid, dmax(e_c, e_pc));
  st->inertia = dmax(st->inertia, e_i);
  st->hull_counts[poly.count] += 1;
  st->compared += 1;
}

START_TEST(test_polygon_mass_matches_box2d) {
  unsigned seed = 0x9E3779B9u;
  poly_stats st = {0};
  tb_world_id world = tbt_world(0.0f, 0.0f);
  tb_world_set_integrator(world, TB_INTEGRATOR_SEMI_IMPLICIT_EULER); /* Box2D's scheme */
  tb_body_def bd = tb_default_body_def();
  tb_body_id body = tb_create_body(world, &bd);
  ck_assert(!tb_body_id_is_null(body));
  for (int i = 0; i < POLYGONS; ++i) compare_polygon(i, &seed, body, &st);
  ck_assert_int_eq(tb_destroy_world(world), TB_OK);
  fprintf(stderr,
          "reference_foundation: %d polygons compared (%d rejected, %d with Box2D given tumble's hull, %d moved to "
          "the origin); max rel error: area %.3g, centroid %.3g (of the size), inertia %.3g\n",
          st.compared, st.rejected, st.hull_differs, st.offset_moved, st.area, st.centroid, st.inertia);
  ck_assert_int_ge(st.compared, 990);
  for (int k = 3; k <= TB_MAX_POLYGON_VERTICES; ++k)
    ck_assert_msg(st.hull_counts[k] >= 50, "only %d hulls of %d vertices", st.hull_counts[k], k);
}
END_TEST

/* ------------------------------------------------------------ free motion -- */

/* Free fall from rest. Gravity -10 with gravity scale 1/8 (a power of two: Box2D
 * multiplies gs * M * g, tumble gs * g, both exact) drops the ball 62.5 m in
 * 10 s, from y = 31.25 to about -31.25: |y| <= 32 keeps a float's ulp at
 * 3.8e-6 m, so the engines' positions can be compared to 1e-5 m. (Without the
 * scale the ball would fall 500 m, where one ulp is 3e-5 m.) */
START_TEST(test_free_fall_matches_box2d) {
  scene_body s = {.x = 1.5f, .y = 31.25f, .gravity_scale = 0.125f};
  run_ballistic_balls("free fall", (tb_vec2){0.0f, -10.0f}, &s);
}
END_TEST

/* A projectile under full gravity: launched at (6, 50) m/s from (-30, -62.5) it
 * rises to y = 62.5 at t = 5 s and is back near -62.5 at t = 10 s, while x goes
 * from -30 to 30: |x|, |y| <= 63 (an ulp of at most 7.6e-6 m) and a speed of at
 * most 50.4 m/s (0.84 m per step, below Box2D's 2 m clamp). */
START_TEST(test_projectile_matches_box2d) {
  scene_body s = {.x = -30.0f, .y = -62.5f, .vx = 6.0f, .vy = 50.0f, .gravity_scale = 1.0f};
  run_ballistic_balls("projectile", (tb_vec2){0.0f, -10.0f}, &s);
}
END_TEST

/* Linear and angular damping on a spinning 1 x 0.5 m box (0.5 kg: a power of two)
 * under gravity, so that damping acts on a velocity that gravity changes every
 * step (both engines add gravity first, then damp). The velocity tends to
 * g / c = (0, -20) m/s; the spin decays as 2.5 / (1 + h 0.4)^n to 0.046 rad/s.
 * Tolerance: relative 1e-5 on the velocity, the spin and the angle, with
 * floors of 1 m/s, 1 rad/s and 1 rad (below them, 1e-5 absolute); the position
 * (y reaches about -152 m, where an ulp is 1.5e-5 m) is compared relative 1e-5
 * too (floor 1 m). */
START_TEST(test_damping_matches_box2d) {
  scene_body s = {.x = 0.0f,
                  .y = 0.0f,
                  .angle = 0.3f,
                  .vx = 3.0f,
                  .vy = 4.0f,
                  .w = 2.5f,
                  .linear_damping = 0.5f,
                  .angular_damping = 0.4f,
                  .gravity_scale = 1.0f};
  pair p = make_pair((tb_vec2){0.0f, -10.0f}, &s, 0.0f, 0.5f, 0.25f, 1.0f);
  ck_assert_float_eq(tb_body_get_mass(p.tb), 0.5f);
  errors max = {0, 0, 0, 0};
  double max_rel_v = 0.0, max_rel_w = 0.0, max_rel_a = 0.0, max_rel_x = 0.0;
  for (int i = 0; i < STEPS; ++i) {
    step_pair(&p);
    errors e = compare_pair(&p, &max);
    b2s_body_state b;
    b2s_body_get_state(p.bb, &b);
    double rv = e.vel / dmax(hypot(b.vx, b.vy), 1.0), rw = e.omega / dmax(fabs(b.w), 1.0);
    double ra = e.angle / dmax(fabs(b.angle), 1.0), rx = e.pos / dmax(hypot(b.x, b.y), 1.0);
    ck_assert_msg(rv <= 1e-5, "step %d: velocity rel diff %.3g", i + 1, rv);
    ck_assert_msg(rw <= 1e-5, "step %d: angular velocity rel diff %.3g", i + 1, rw);
    ck_assert_msg(ra <= 1e-5, "step %d: angle rel diff %.3g", i + 1, ra);
    ck_assert_msg(rx <= 1e-5, "step %d: position rel diff %.3g", i + 1, rx);
    max_rel_v = dmax(max_rel_v, rv);
    max_rel_w = dmax(max_rel_w, rw);
    max_rel_a = dmax(max_rel_a, ra);
    max_rel_x = dmax(max_rel_x, rx);
  }
  /* the scene did what it claims: damped towards g / c */
  tb_vec2 v = tb_body_get_linear_velocity(p.tb);
  ck_assert_float_eq_tol(v.x, 0.0f, 0.1f);
  ck_assert_float_eq_tol(v.y, -20.0f, 0.5f);
  ck_assert_float_eq_tol(tb_body_get_angular_velocity(p.tb), 0.046f, 0.005f);
  fprintf(stderr,
          "reference_foundation: damping: max rel diff v %.3g, w %.3g, angle %.3g, position %.3g "
          "(abs %.3g m/s, %.3g rad/s, %.3g rad, %.3g m)\n",
          max_rel_v, max_rel_w, max_rel_a, max_rel_x, max.vel, max.omega, max.angle, max.pos);
  free_pair(&p);
}
END_TEST

/* A constant force F = (0.3, 1) N applied every step at the fixed world point
 * P = (0.8, 0.2) of a 2 x 1 m box (2 kg, I = 5/6 kg m^2) that starts at the
 * origin with velocity (0.5, -0.25) m/s, no gravity. The torque (P - X) x F
 * changes as the box drifts (0.74 - 0.575 t N m), so w rises, turns and reaches
 * about -25.6 rad/s (0.43 rad per step), the angle about -71 rad.
 * Tolerance: relative 1e-5 on w and the angle after the 600 steps (floors 1 rad/s
 * and 1 rad for the per-step checks). The two engines differ only in the rounding
 * of the box's inertia (Box2D: float sums with 1/3 in float), a few 2^-24. */
START_TEST(test_offset_force_matches_box2d) {
  scene_body s = {.vx = 0.5f, .vy = -0.25f, .gravity_scale = 1.0f};
  pair p = make_pair((tb_vec2){0.0f, 0.0f}, &s, 0.0f, 1.0f, 0.5f, 1.0f);
  ck_assert_float_eq(tb_body_get_mass(p.tb), 2.0f);
  b2s_mass bm;
  b2s_body_get_mass(p.bb, &bm);
  const tb_vec2 force = {0.3f, 1.0f}, point = {0.8f, 0.2f};
  errors max = {0, 0, 0, 0};
  double max_rel_w = 0.0, max_rel_a = 0.0;
  for (int i = 0; i < STEPS; ++i) {
    ck_assert_int_eq(tb_body_apply_force(p.tb, force, point), TB_OK);
    b2s_body_apply_force(p.bb, force.x, force.y, point.x, point.y);
    step_pair(&p);
    errors e = compare_pair(&p, &max);
    b2s_body_state b;
    b2s_body_get_state(p.bb, &b);
    double rw = e.omega / dmax(fabs(b.w), 1.0), ra = e.angle / dmax(fabs(b.angle), 1.0);
    ck_assert_msg(rw <= 1e-5, "step %d: angular velocity rel diff %.3g", i + 1, rw);
    ck_assert_msg(ra <= 1e-5, "step %d: angle rel diff %.3g", i + 1, ra);
    max_rel_w = dmax(max_rel_w, rw);
    max_rel_a = dmax(max_rel_a, ra);
  }
  b2s_body_state b;
  b2s_body_get_state(p.bb, &b);
  float w = tb_body_get_angular_velocity(p.tb), angle = tb_body_get_angle(p.tb);
  ck_assert_rel(w, b.w, 1e-5);
  ck_assert_rel(angle, b.angle, 1e-5);
  ck_assert_float_eq_tol(w, -25.6f, 0.5f); /* the scene did what it claims */
  fprintf(stderr,
          "reference_foundation: offset force: inertia %.9g vs %.9g kg m^2; final w %.9g vs %.9g rad/s, angle %.9g "
          "vs %.9g rad; max rel diff w %.3g, angle %.3g; max |dx| %.3g m\n",
          (double)tb_body_get_rotational_inertia(p.tb), bm.inertia, (double)w, (double)b.w, (double)angle,
          (double)b.angle, max_rel_w, max_rel_a, max.pos);
  free_pair(&p);
}
END_TEST

static Suite* reference_foundation_suite(void) {
  Suite* s = suite_create("reference_foundation");
  TCase* tc = tcase_create("box2d");
  tcase_add_test(tc, test_polygon_mass_matches_box2d);
  tcase_add_test(tc, test_free_fall_matches_box2d);
  tcase_add_test(tc, test_projectile_matches_box2d);
  tcase_add_test(tc, test_damping_matches_box2d);
  tcase_add_test(tc, test_offset_force_matches_box2d);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(reference_foundation_suite)
