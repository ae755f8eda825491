/* Accuracy benchmark: run time against error, tumble and Box2D 2.4.1 side by
 * side (issue 6), and Box2D v3 too in make bench-v3's build (issue 21). Every
 * scene is written once against tools/bench/engine.h and built with the same
 * parameters in each engine; each error metric is
 * taken against a closed form (or, for far_pyramid, against the same engine's
 * run at the origin), defined at each scene below and in results/scenes.tsv.
 *
 *   build/bench/bench_accuracy [--quick] [--scene NAME] [--runs N]
 *       [--defaults] [--perturb N] [--csv FILE] [--meta FILE]
 *                                           accuracy sweep
 *   build/bench/bench_accuracy --scaling [--quick] [--runs N] [--csv FILE]
 *                                           pyramids of base 10 to 140
 *
 * Sweep: tumble at substeps 1, 2, 4, 8, 16 and time steps 1/30, 1/60, 1/120,
 * 1/240 s (and each integrator for the scenes moved only by gravity and
 * forces); Box2D at velocity/position iterations 4/2, 8/3, 16/6, 32/12 and the
 * same time steps (pyramid_100, 5,050 boxes, stops at 120 Hz so that
 * `make bench` fits in 15 minutes). Defaults: tumble 60 Hz, 4 substeps,
 * midpoint (its library default); Box2D 60 Hz, 8/3. Sleep is off in every scene (they
 * measure the solver).
 *
 * Cost: only the engine's step call is timed (CLOCK_MONOTONIC). A setting is
 * run --runs times (default 3; fewer when a run takes over 2 s, more, up to 9,
 * while all runs took under 0.2 s); the row has
 * the minimum and median ms per step, and ms per 1/60 s of simulated time
 * (ms per step * (1/60) / dt), the cost axis of the plots, so that time steps
 * compare at equal simulated time. Runs are deterministic: the error metrics
 * are the last run's.
 *
 * --defaults: each engine's default setting only.
 *
 * --perturb N: after each row, the same setting N more times with every
 * dynamic body's start moved by up to PERTURB_METERS in x and y (a seeded
 * draw per run, the same in each engine and in both runs of far_pyramid),
 * printing the median and the largest of each error over those N runs (not
 * in the CSV). Some errors are one draw of a chaotic spread (40 bouncing
 * balls' energy, a column's sideways wander of micrometres): a change that
 * only moves rounding moves them as much as a micrometre at the start does,
 * and is judged against that spread, not against one draw. Errors of one or
 * two bodies against a closed form (collision_1d, bullet_block) move with the
 * offsets themselves: their unperturbed row is the one to compare.
 *
 * --quick: fewer settings (tumble 1, 4, 8 substeps at 60 Hz and 4 substeps at
 * 30 and 120 Hz; Box2D 4/2, 8/3, 16/6 at 60 Hz and 8/3 at 30 and 120 Hz), one
 * run, shorter and smaller large scenes. Exit status 1 when a step fails or a
 * metric is not finite (NaN), so CI catches a broken engine or bench.
 *
 * Built with -DBENCH_WITH_V3 (build/bench/bench_accuracy_v3, make bench-v3
 * only, linked with tools/bench_engine_v3.c and a v3 libbox2d.a), the sweep
 * also runs Box2D v3 ("box2d_v3") at substeps 1, 2, 4, 8 and the same time
 * steps; its default is 60 Hz, 4 substeps; --quick keeps the substeps and
 * rates tumble keeps. Without it nothing of v3 is compiled or run. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench/engine.h"

#define PI 3.14159265358979323846
#define G 10.0
#define METRICS 3
#define MAX_RUNS 9
#define MAX_PERTURB 99

/* ------------------------------------------------------------ running -- */

typedef struct sim {
  const bench_engine* e;
  void* w;
  bench_setting s;
  double step_ms; /* timed engine steps, summed */
  int steps;
  bool failed;
  int bodies, contacts, joints; /* when the world was closed */
} sim;

static bool g_quick = false;
static int g_perturb_runs = 0; /* --perturb */
/* the run's draw of start offsets (0: none) and its xorshift32 state */
static uint32_t g_perturb_seed = 0, g_perturb_state = 0;
#define PERTURB_METERS 1e-6

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static bench_world_def world_def(double gravity_y) {
  bench_world_def d = {0.0, gravity_y, false, 1.0, 0.0};
  return d;
}

/* xorshift32, uniform in [0, 1) */
static double xorshift(uint32_t* state) {
  uint32_t x = *state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return (double)x / 4294967296.0;
}

/* An offset in [-PERTURB_METERS, PERTURB_METERS) (--perturb). */
static double perturbation(void) { return PERTURB_METERS * (2.0 * xorshift(&g_perturb_state) - 1.0); }

static void sim_open(sim* s, const bench_world_def* def) {
  g_perturb_state = g_perturb_seed * 2654435761u + 1u; /* each world of a run draws the same offsets */
  s->w = s->e->create(def, &s->s);
  if (s->w == NULL) {
    fprintf(stderr, "%s: cannot create a world\n", s->e->name);
    exit(1);
  }
}

static void sim_close(sim* s) {
  s->e->counts(s->w, &s->bodies, &s->contacts, &s->joints);
  s->e->destroy(s->w);
  s->w = NULL;
}

static void sim_step(sim* s) {
  double t0 = now_ms();
  int r = s->e->step(s->w);
  s->step_ms += now_ms() - t0;
  s->steps += 1;
  if (r != 0) s->failed = true;
}

/* Whole steps that cover the given simulated time. */
static int steps_for(const sim* s, double seconds) { return (int)lround(seconds / s->s.dt); }
/* The simulated time after n steps (the engines step with a float dt). */
static double time_of(const sim* s, int n) { return n * (double)(float)s->s.dt; }

static bench_state state(const sim* s, int body) {
  bench_state st;
  s->e->get_state(s->w, body, &st);
  return st;
}

static int body(sim* s, bench_body_def d) {
  if (g_perturb_seed != 0 && d.type == BENCH_DYNAMIC) {
    d.x += perturbation();
    d.y += perturbation();
  }
  int b = s->e->add_body(s->w, &d);
  if (b < 0) {
    fprintf(stderr, "%s: add_body failed\n", s->e->name);
    exit(1);
  }
  return b;
}

static void box(sim* s, int b, double hx, double hy, bench_material m) {
  if (s->e->add_box(s->w, b, hx, hy, 0.0, 0.0, 0.0, &m) != 0) s->failed = true;
}

static void circle(sim* s, int b, double r, bench_material m) {
  if (s->e->add_circle(s->w, b, r, 0.0, 0.0, &m) != 0) s->failed = true;
}

/* A static box [-hx, hx] x [-1, 0] (core): its surface is at y = skin. */
static void ground(sim* s, double x, double hx, double friction) {
  int g = body(s, bench_body(BENCH_STATIC, x, -0.5));
  box(s, g, hx, 0.5, bench_mat(1.0, friction, 0.0));
}

static double kinetic_energy(const sim* s, int b) {
  bench_state st = state(s, b);
  return 0.5 * s->e->mass(s->w, b) * (st.vx * st.vx + st.vy * st.vy) + 0.5 * s->e->inertia(s->w, b) * st.w * st.w;
}

/* --------------------------------------------------------------- scenes -- */

/* projectile: a disc (radius 0.1) launched at (10, 10) m/s under g = 10,
 * nothing to hit. Error after 1 s against p = v0 t + g t^2 / 2 (m); velocity
 * error against v0 + g t. */
static void run_projectile(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  bench_body_def bd = bench_body(BENCH_DYNAMIC, 0.0, 0.0);
  bd.vx = 10.0, bd.vy = 10.0;
  int b = body(s, bd);
  circle(s, b, 0.1, bench_mat(1.0, 0.6, 0.0));
  int n = steps_for(s, 1.0);
  for (int i = 0; i < n; ++i) sim_step(s);
  double t = time_of(s, n);
  bench_state st = state(s, b);
  m[0] = hypot(st.cx - 10.0 * t, st.cy - (10.0 * t - 0.5 * G * t * t));
  m[1] = hypot(st.vx - 10.0, st.vy - (10.0 - G * t));
  sim_close(s);
}

/* constant_spin: a 2 x 1 m box spinning at 3 rad/s, no gravity, for 2 s.
 * Error |angle - 3 t| (rad); spin-rate error |w - 3|. */
static void run_constant_spin(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(0.0);
  sim_open(s, &d);
  bench_body_def bd = bench_body(BENCH_DYNAMIC, 0.0, 0.0);
  bd.w = 3.0;
  int b = body(s, bd);
  box(s, b, 1.0, 0.5, bench_mat(1.0, 0.6, 0.0));
  int n = steps_for(s, 2.0);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state st = state(s, b);
  m[0] = fabs(st.angle - 3.0 * time_of(s, n));
  m[1] = fabs(st.w - 3.0);
  sim_close(s);
}

/* Complete elliptic integral of the first kind by the AGM. */
static double elliptic_k(double k) {
  double a = 1.0, b = sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; ++i) {
    double mid = 0.5 * (a + b);
    b = sqrt(a * b);
    a = mid;
  }
  return PI / (2.0 * a);
}

/* pendulum: a disc (radius 0.1, density 1) on a revolute joint 1 m below a
 * static pivot, released at rest from theta0. It swings like a point mass on
 * L_eq = L + r^2 / (2 L), period T = 4 sqrt(L_eq / g) K(sin(theta0 / 2))
 * exactly. Error: relative period error, the period timed between downward
 * zero crossings of the angle (interpolated linearly) over about 5 periods;
 * energy lost by the end over the swing energy m g L_eq (1 - cos theta0)
 * (|dE| / E_swing); largest joint gap (m) over the run. */
static void run_pendulum(sim* s, double m[METRICS], double theta0) {
  const double len = 1.0, r = 0.1;
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  int pivot = body(s, bench_body(BENCH_STATIC, 0.0, 0.0));
  int bob = body(s, bench_body(BENCH_DYNAMIC, len * sin(theta0), -len * cos(theta0)));
  circle(s, bob, r, bench_mat(1.0, 0.6, 0.0));
  if (s->e->add_revolute(s->w, pivot, bob, 0.0, 0.0) != 0) s->failed = true;
  double l_eq = len + r * r / (2.0 * len);
  double period = 4.0 * sqrt(l_eq / G) * elliptic_k(sin(0.5 * theta0));
  double mass = s->e->mass(s->w, bob);
  double e0 = mass * G * state(s, bob).cy, swing = mass * G * l_eq * (1.0 - cos(theta0));
  double prev = theta0, first = 0.0, last = 0.0, gap = 0.0;
  int crossings = 0, n = steps_for(s, 5.4 * period);
  for (int i = 1; i <= n; ++i) {
    sim_step(s);
    bench_state st = state(s, bob);
    double th = atan2(st.cx, -st.cy), t = time_of(s, i);
    if (prev > 0.0 && th <= 0.0) {
      double tc = t - s->s.dt + s->s.dt * prev / (prev - th);
      if (crossings == 0) first = tc;
      last = tc;
      crossings += 1;
    }
    prev = th;
    gap = fmax(gap, fabs(hypot(st.cx, st.cy) - len));
  }
  m[0] = crossings >= 2 ? fabs((last - first) / (crossings - 1) - period) / period : 1.0;
  m[1] = fabs(kinetic_energy(s, bob) + mass * G * state(s, bob).cy - e0) / swing;
  m[2] = gap;
  sim_close(s);
}

static void run_pendulum_5(sim* s, double m[METRICS]) { run_pendulum(s, m, 5.0 * PI / 180.0); }
static void run_pendulum_90(sim* s, double m[METRICS]) { run_pendulum(s, m, 0.5 * PI); }

/* An incline: a static 40 x 1 m box turned by -theta about the origin. A
 * body resting on it with its centre `height` above the core surface sits at
 * height * n - 8 d (n the surface normal, d pointing down the slope). */
typedef struct incline {
  double nx, ny, dx, dy;
} incline;

static incline make_incline(sim* s, double theta, double friction) {
  incline in = {sin(theta), cos(theta), cos(theta), -sin(theta)};
  bench_body_def g = bench_body(BENCH_STATIC, 0.0, 0.0);
  g.angle = -theta;
  int b = body(s, g);
  box(s, b, 20.0, 0.5, bench_mat(1.0, friction, 0.0));
  return in;
}

static int on_incline(sim* s, const incline* in, double height, double angle) {
  bench_body_def bd = bench_body(BENCH_DYNAMIC, height * in->nx - 8.0 * in->dx, height * in->ny - 8.0 * in->dy);
  bd.angle = angle;
  return body(s, bd);
}

/* rolling_disc: a disc (radius 0.5) rolls from rest down a 30 deg incline,
 * friction 0.6 (enough to roll: tan 30 / 3 = 0.19). Without slipping
 * a = g sin(theta) / (1 + I / (m r^2)) = (2/3) g sin(theta): distance in 1.5 s
 * s = a t^2 / 2 = 3.75 m. Error: relative distance error; slip |v + w r| / |v|. */
static void run_rolling_disc(sim* s, double m[METRICS]) {
  const double th = PI / 6.0, r = 0.5;
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  incline in = make_incline(s, th, 0.6);
  int b = on_incline(s, &in, 0.5 + s->e->polygon_skin + r, 0.0);
  circle(s, b, r, bench_mat(1.0, 0.6, 0.0));
  bench_state s0 = state(s, b);
  int n = steps_for(s, 1.5);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state st = state(s, b);
  double t = time_of(s, n), exact = 0.5 * (2.0 / 3.0) * G * sin(th) * t * t;
  double dist = (st.cx - s0.cx) * in.dx + (st.cy - s0.cy) * in.dy, v = st.vx * in.dx + st.vy * in.dy;
  m[0] = fabs(dist - exact) / exact;
  m[1] = fabs(v + st.w * r) / fmax(fabs(v), 1e-9);
  sim_close(s);
}

/* sliding_box: a unit box (half 0.5) slides from rest down a 30 deg incline,
 * friction 0.3 both: s = g (sin - mu cos) t^2 / 2 = 2.7022 m in 1.5 s. Error:
 * relative distance error; largest tilt |angle + 30 deg| (rad). */
static void run_sliding_box(sim* s, double m[METRICS]) {
  const double th = PI / 6.0, mu = 0.3;
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  incline in = make_incline(s, th, mu);
  int b = on_incline(s, &in, 1.0 + 2.0 * s->e->polygon_skin, -th);
  box(s, b, 0.5, 0.5, bench_mat(1.0, mu, 0.0));
  bench_state s0 = state(s, b);
  int n = steps_for(s, 1.5);
  double tilt = 0.0;
  for (int i = 0; i < n; ++i) {
    sim_step(s);
    tilt = fmax(tilt, fabs(state(s, b).angle + th));
  }
  bench_state st = state(s, b);
  double t = time_of(s, n), exact = 0.5 * G * (sin(th) - mu * cos(th)) * t * t;
  m[0] = fabs((st.x - s0.x) * in.dx + (st.y - s0.y) * in.dy - exact) / exact;
  m[1] = tilt;
  sim_close(s);
}

/* sticking_box: a unit box at rest on a 20 deg incline with friction 0.6
 * (> tan 20 = 0.36): static friction holds it, it should not move. Error: how
 * far it crept down the slope in 5 s (m); how far it moved along the normal. */
static void run_sticking_box(sim* s, double m[METRICS]) {
  const double th = 20.0 * PI / 180.0;
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  incline in = make_incline(s, th, 0.6);
  int b = on_incline(s, &in, 1.0 + 2.0 * s->e->polygon_skin, -th);
  box(s, b, 0.5, 0.5, bench_mat(1.0, 0.6, 0.0));
  bench_state s0 = state(s, b);
  int n = steps_for(s, 5.0);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state st = state(s, b);
  m[0] = fabs((st.x - s0.x) * in.dx + (st.y - s0.y) * in.dy);
  m[1] = fabs((st.x - s0.x) * in.nx + (st.y - s0.y) * in.ny);
  sim_close(s);
}

/* bounce: a ball (radius 0.25) dropped from rest with its bottom 2 m above a
 * static ground (restitution 0) rises to e^2 h0 after the first bounce
 * (restitution mixes by max in both engines). Error |apex - e^2 h0| (m), the
 * apex being the highest bottom between the bounce and the next descent. */
static void run_bounce(sim* s, double m[METRICS], double e) {
  const double h0 = 2.0, r = 0.25;
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  ground(s, 0.0, 10.0, 0.6);
  double surface = s->e->polygon_skin;
  int b = body(s, bench_body(BENCH_DYNAMIC, 0.0, surface + h0 + r));
  circle(s, b, r, bench_mat(1.0, 0.6, e));
  int phase = 0, n = steps_for(s, 3.0);
  double apex = 0.0;
  for (int i = 0; i < n && phase < 2; ++i) {
    sim_step(s);
    bench_state st = state(s, b);
    if (phase == 0 && st.vy > 0.0) phase = 1;
    if (phase == 1) {
      apex = fmax(apex, st.y - r - surface);
      if (st.vy < 0.0) phase = 2;
    }
  }
  m[0] = fabs(apex - e * e * h0);
  sim_close(s);
}

static void run_bounce_050(sim* s, double m[METRICS]) { run_bounce(s, m, 0.5); }
static void run_bounce_100(sim* s, double m[METRICS]) { run_bounce(s, m, 1.0); }

/* collision_1d: two frictionless discs (radius 0.5, densities 1 and 3) meet
 * head on at 4 and -2 m/s, restitution 1, no gravity. Closed form after the
 * impact: v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2), and symmetrically.
 * Error after 1 s: largest velocity error over the approach speed; momentum
 * error |P - P0| / sum m |v0|; energy error |E - E0| / E0. */
static void run_collision_1d(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(0.0);
  sim_open(s, &d);
  bench_body_def da = bench_body(BENCH_DYNAMIC, -2.0, 0.0), db = bench_body(BENCH_DYNAMIC, 2.0, 0.0);
  da.vx = 4.0;
  db.vx = -2.0;
  int a = body(s, da), b = body(s, db);
  circle(s, a, 0.5, bench_mat(1.0, 0.0, 1.0));
  circle(s, b, 0.5, bench_mat(3.0, 0.0, 1.0));
  double ma = s->e->mass(s->w, a), mb = s->e->mass(s->w, b);
  double va = ((ma - mb) * 4.0 + 2.0 * mb * -2.0) / (ma + mb), vb = ((mb - ma) * -2.0 + 2.0 * ma * 4.0) / (ma + mb);
  double p0 = ma * 4.0 + mb * -2.0, e0 = 0.5 * ma * 16.0 + 0.5 * mb * 4.0;
  int n = steps_for(s, 1.0);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state sa = state(s, a), sb = state(s, b);
  m[0] = fmax(hypot(sa.vx - va, sa.vy), hypot(sb.vx - vb, sb.vy)) / 6.0;
  m[1] = hypot(ma * sa.vx + mb * sb.vx - p0, ma * sa.vy + mb * sb.vy) / (ma * 4.0 + mb * 2.0);
  m[2] = fabs(kinetic_energy(s, a) + kinetic_energy(s, b) - e0) / e0;
  sim_close(s);
}

/* bullet_block: a bullet (disc radius 0.05, density 5, a bullet in both
 * engines) at 100 m/s into a resting unit box (1 kg), centred, no gravity,
 * restitution 0: afterwards both move at V = m v0 / (m + M). Error after
 * 0.5 s: relative block-speed error; momentum error |P - P0| / P0; relative
 * speed left between bullet and block (m/s; ~100 if it tunnelled). */
static void run_bullet_block(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(0.0);
  sim_open(s, &d);
  int blk = body(s, bench_body(BENCH_DYNAMIC, 0.0, 0.0));
  box(s, blk, 0.5, 0.5, bench_mat(1.0, 0.6, 0.0));
  bench_body_def bd = bench_body(BENCH_DYNAMIC, -2.5, 0.0);
  bd.vx = 100.0;
  bd.bullet = true;
  int bul = body(s, bd);
  circle(s, bul, 0.05, bench_mat(5.0, 0.6, 0.0));
  double mb = s->e->mass(s->w, bul), mk = s->e->mass(s->w, blk);
  double p0 = mb * 100.0, v = p0 / (mb + mk);
  int n = steps_for(s, 0.5);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state sk = state(s, blk), sb = state(s, bul);
  m[0] = hypot(sk.vx - v, sk.vy) / v;
  m[1] = hypot(mk * sk.vx + mb * sb.vx - p0, mk * sk.vy + mb * sb.vy) / p0;
  m[2] = hypot(sb.vx - sk.vx, sb.vy - sk.vy);
  sim_close(s);
}

/* A box of half h resting in row i (from 0) of a stack on the ground: its
 * centre height, each interface holding two skins in Box2D. */
static double rest_height(const sim* s, int row, double h) {
  return (2 * row + 1) * h + (2 * row + 2) * s->e->polygon_skin;
}

/* stack: n unit boxes (friction 0.6) placed where rigid boxes rest, for 10 s.
 * Rigid bodies stay put, so error: the top box's distance from its rest place
 * at the end (m); the top's largest sideways wander over the run (m); the
 * largest rest-height error over the stack at the end (m). */
static void run_stack(sim* s, double m[METRICS], int count) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  ground(s, 0.0, 20.0, 0.6);
  int top = -1;
  for (int i = 0; i < count; ++i) {
    top = body(s, bench_body(BENCH_DYNAMIC, 0.0, rest_height(s, i, 0.5)));
    box(s, top, 0.5, 0.5, bench_mat(1.0, 0.6, 0.0));
  }
  int n = steps_for(s, 10.0);
  double wander = 0.0;
  for (int i = 0; i < n; ++i) {
    sim_step(s);
    wander = fmax(wander, fabs(state(s, top).x));
  }
  bench_state st = state(s, top);
  m[0] = hypot(st.x, st.y - rest_height(s, count - 1, 0.5));
  m[1] = wander;
  m[2] = 0.0;
  for (int i = 0; i < count; ++i) m[2] = fmax(m[2], fabs(state(s, top - count + 1 + i).y - rest_height(s, i, 0.5)));
  sim_close(s);
}

static void run_stack_15(sim* s, double m[METRICS]) { run_stack(s, m, 15); }
static void run_stack_30(sim* s, double m[METRICS]) { run_stack(s, m, 30); }

/* A pyramid of unit boxes with its base centred at x = cx on the ground,
 * placed at the rigid rest places (Box2D's skins included). Returns the
 * first box's index; the top box is the last. */
static int pyramid(sim* s, int base, double cx) {
  const double h = 0.5, pitch = 2.0 * (h + s->e->polygon_skin);
  int first = -1;
  for (int i = 0; i < base; ++i) {
    for (int j = i; j < base; ++j) {
      double x = cx + 0.5 * pitch * (2 * (j - i) + i + 1 - base);
      int b = body(s, bench_body(BENCH_DYNAMIC, x, rest_height(s, i, h)));
      box(s, b, h, h, bench_mat(1.0, 0.6, 0.0));
      if (first < 0) first = b;
    }
  }
  return first;
}

/* pyramid: a pyramid of `base` unit boxes (friction 0.6) at its rigid rest
 * places, for `seconds`. Error: the largest displacement of any box at the
 * end (m; 0 for rigid bodies at rest); the top's sag (m); the largest
 * sideways displacement (m). */
static void run_pyramid(sim* s, double m[METRICS], int base, double seconds) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  ground(s, 0.0, base + 10.0, 0.6);
  int first = pyramid(s, base, 0.0), count = base * (base + 1) / 2;
  double* start = malloc(sizeof *start * 2 * (size_t)count);
  if (start == NULL) exit(1);
  for (int k = 0; k < count; ++k) {
    bench_state st = state(s, first + k);
    start[2 * k] = st.x, start[2 * k + 1] = st.y;
  }
  int n = steps_for(s, seconds);
  for (int i = 0; i < n; ++i) sim_step(s);
  m[0] = m[2] = 0.0;
  for (int k = 0; k < count; ++k) {
    bench_state st = state(s, first + k);
    m[0] = fmax(m[0], hypot(st.x - start[2 * k], st.y - start[2 * k + 1]));
    m[2] = fmax(m[2], fabs(st.x - start[2 * k]));
  }
  m[1] = start[2 * count - 1] - state(s, first + count - 1).y;
  free(start);
  sim_close(s);
}

static void run_pyramid_20(sim* s, double m[METRICS]) { run_pyramid(s, m, 20, 5.0); }
static void run_pyramid_100(sim* s, double m[METRICS]) { run_pyramid(s, m, g_quick ? 40 : 100, 1.0); }

/* mass_ratio: a 20 m box (400 kg) resting on two unit boxes (1 kg) at
 * x = +-9.5 on the ground, a 400:1 mass ratio, for 5 s. Error: how far the
 * heavy box is from its rigid rest height at the end (m); the small boxes'
 * largest tilt (rad); the heavy box's sideways drift (m). */
static void run_mass_ratio(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  ground(s, 0.0, 40.0, 0.6);
  double skin = s->e->polygon_skin;
  int l = body(s, bench_body(BENCH_DYNAMIC, -9.5, 0.5 + 2.0 * skin));
  box(s, l, 0.5, 0.5, bench_mat(1.0, 0.6, 0.0));
  int r = body(s, bench_body(BENCH_DYNAMIC, 9.5, 0.5 + 2.0 * skin));
  box(s, r, 0.5, 0.5, bench_mat(1.0, 0.6, 0.0));
  double rest = 11.0 + 4.0 * skin;
  int h = body(s, bench_body(BENCH_DYNAMIC, 0.0, rest));
  box(s, h, 10.0, 10.0, bench_mat(1.0, 0.6, 0.0));
  int n = steps_for(s, 5.0);
  double tilt = 0.0;
  for (int i = 0; i < n; ++i) {
    sim_step(s);
    tilt = fmax(tilt, fmax(fabs(state(s, l).angle), fabs(state(s, r).angle)));
  }
  bench_state st = state(s, h);
  m[0] = fabs(st.y - rest);
  m[1] = tilt;
  m[2] = fabs(st.x);
  sim_close(s);
}

/* chain_ball: 40 links (boxes 1.2 x 0.25, density 20, friction 0.2, 1 m
 * apart, ~6 kg each) on revolute joints from a static pivot, start
 * horizontal; a heavy ball (radius 1, density 100: 314 kg, ~50:1) hangs on
 * the last joint. Nothing in the chain collides (group -1). It swings down
 * for 5 s. Error: the joint gap (distance between each joint's two anchors)
 * summed over the 41 joints, averaged over the steps (m); its largest value
 * (m); its value at the end (m). */
#define CHAIN_LINKS 40
typedef struct anchor_pair {
  int a, b;
  double ax, ay, bx, by; /* body-local anchors */
} anchor_pair;

static void local_point(const bench_state* st, double x, double y, double* lx, double* ly) {
  double c = cos(st->angle), sn = sin(st->angle), dx = x - st->x, dy = y - st->y;
  *lx = c * dx + sn * dy;
  *ly = -sn * dx + c * dy;
}

static double anchor_gap(const sim* s, const anchor_pair* p) {
  bench_state a = state(s, p->a), b = state(s, p->b);
  double ca = cos(a.angle), sa = sin(a.angle), cb = cos(b.angle), sb = sin(b.angle);
  double ax = a.x + ca * p->ax - sa * p->ay, ay = a.y + sa * p->ax + ca * p->ay;
  double bx = b.x + cb * p->bx - sb * p->by, by = b.y + sb * p->bx + cb * p->by;
  return hypot(ax - bx, ay - by);
}

static void pin(sim* s, anchor_pair* p, int a, int b, double x, double y) {
  if (s->e->add_revolute(s->w, a, b, x, y) != 0) s->failed = true;
  bench_state sa = state(s, a), sb = state(s, b);
  p->a = a, p->b = b;
  local_point(&sa, x, y, &p->ax, &p->ay);
  local_point(&sb, x, y, &p->bx, &p->by);
}

static void run_chain_ball(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  anchor_pair joints[CHAIN_LINKS + 1];
  int prev = body(s, bench_body(BENCH_STATIC, 0.0, 0.0));
  bench_material link = bench_mat(20.0, 0.2, 0.0), heavy = bench_mat(100.0, 0.2, 0.0);
  link.group = heavy.group = -1;
  for (int i = 0; i < CHAIN_LINKS; ++i) {
    int b = body(s, bench_body(BENCH_DYNAMIC, i + 0.5, 0.0));
    box(s, b, 0.6, 0.125, link);
    pin(s, &joints[i], prev, b, i, 0.0);
    prev = b;
  }
  int ball = body(s, bench_body(BENCH_DYNAMIC, CHAIN_LINKS, 0.0));
  circle(s, ball, 1.0, heavy);
  pin(s, &joints[CHAIN_LINKS], prev, ball, CHAIN_LINKS, 0.0);
  int n = steps_for(s, 5.0);
  double sum_mean = 0.0, sum_max = 0.0, sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sim_step(s);
    sum = 0.0;
    for (int k = 0; k <= CHAIN_LINKS; ++k) sum += anchor_gap(s, &joints[k]);
    sum_mean += sum / n;
    sum_max = fmax(sum_max, sum);
  }
  m[0] = sum_mean;
  m[1] = sum_max;
  m[2] = sum;
  sim_close(s);
}

/* elastic_balls: no gravity; a free square box (inner 10 m, walls 0.5 m
 * thick, density 5) holds 40 balls (radius 0.3, density 1) moving at 3 m/s
 * in random directions (xorshift32, seed 7). Everything frictionless with
 * restitution 1 and no restitution threshold, so energy and momentum are
 * conserved exactly. Error over 10 s: |E - E0| / E0 at the end; momentum
 * error |P - P0| / sum m |v0|; the largest |E - E0| / E0 over the run. */
#define BALLS 40
static double total_energy(const sim* s, int count) {
  double e = 0.0;
  for (int k = 0; k < count; ++k) e += kinetic_energy(s, k);
  return e;
}

static void run_elastic_balls(sim* s, double m[METRICS]) {
  bench_world_def d = world_def(0.0);
  d.restitution_threshold = 0.0;
  sim_open(s, &d);
  bench_material wall = bench_mat(5.0, 0.0, 1.0), ball = bench_mat(1.0, 0.0, 1.0);
  int c = body(s, bench_body(BENCH_DYNAMIC, 0.0, 0.0));
  const double half = 5.0, t = 0.25;
  const double walls[4][4] = {{t, half + 2 * t, half + t, 0.0},
                              {t, half + 2 * t, -half - t, 0.0},
                              {half + 2 * t, t, 0.0, half + t},
                              {half + 2 * t, t, 0.0, -half - t}};
  for (int k = 0; k < 4; ++k) {
    if (s->e->add_box(s->w, c, walls[k][0], walls[k][1], walls[k][2], walls[k][3], 0.0, &wall) != 0) s->failed = true;
  }
  uint32_t rng = 7u;
  double scale = 0.0;
  for (int k = 0; k < BALLS; ++k) {
    double a = 2.0 * PI * xorshift(&rng);
    bench_body_def bd = bench_body(BENCH_DYNAMIC, -4.2 + 1.2 * (k % 8), -2.4 + 1.2 * (k / 8));
    bd.vx = 3.0 * cos(a), bd.vy = 3.0 * sin(a);
    int b = body(s, bd);
    circle(s, b, 0.3, ball);
    scale += s->e->mass(s->w, b) * 3.0;
  }
  int count = BALLS + 1;
  double e0 = total_energy(s, count), px0 = 0.0, py0 = 0.0;
  for (int k = 0; k < count; ++k) {
    bench_state st = state(s, k);
    px0 += s->e->mass(s->w, k) * st.vx, py0 += s->e->mass(s->w, k) * st.vy;
  }
  int n = steps_for(s, 10.0);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    sim_step(s);
    worst = fmax(worst, fabs(total_energy(s, count) - e0) / e0);
  }
  double px = 0.0, py = 0.0;
  for (int k = 0; k < count; ++k) {
    bench_state st = state(s, k);
    px += s->e->mass(s->w, k) * st.vx, py += s->e->mass(s->w, k) * st.vy;
  }
  m[0] = fabs(total_energy(s, count) - e0) / e0;
  m[1] = hypot(px - px0, py - py0) / scale;
  m[2] = worst;
  sim_close(s);
}

/* mass_spring: a 1 kg disc pulled to the origin by F = -k x with
 * k = 4 pi^2 N/m (period 1 s), released at x = 1 m, no gravity, nothing to
 * touch. In tumble the spring is a force field, so each integrator applies;
 * Box2D applies the force before each step. Box2D v3 has no hook inside its
 * n substeps, so the force is held over them: a step then moves
 * x += dt v + (n + 1) / (2 n) dt^2 a, and the energy grows by
 * 1 + (n - 1) / (2 n) (w dt)^2 per step (x11.7 in 10 s at 60 Hz, n = 4;
 * n = 1 is 2.4.1's semi-implicit Euler). Closed form x = cos(w t),
 * w = sqrt(k / m). Error after 10 s: |x - x_exact| (m, the amplitude is 1 m);
 * energy error |E - E0| / E0 with E = m v^2 / 2 + k x^2 / 2. */
static void run_mass_spring(sim* s, double m[METRICS]) {
  const double k = 4.0 * PI * PI, r = 0.5;
  bench_world_def d = world_def(0.0);
  d.spring_k = k;
  sim_open(s, &d);
  int b = body(s, bench_body(BENCH_DYNAMIC, 1.0, 0.0));
  circle(s, b, r, bench_mat(1.0 / (PI * r * r), 0.0, 0.0));
  double mass = s->e->mass(s->w, b), w = sqrt(k / mass), e0 = 0.5 * k;
  int n = steps_for(s, 10.0);
  for (int i = 0; i < n; ++i) sim_step(s);
  bench_state st = state(s, b);
  double t = time_of(s, n);
  m[0] = hypot(st.cx - cos(w * t), st.cy);
  m[1] = fabs(0.5 * mass * (st.vx * st.vx + st.vy * st.vy) + 0.5 * k * (st.cx * st.cx + st.cy * st.cy) - e0) / e0;
  sim_close(s);
}

/* far_pyramid: a pyramid of base 10 at the origin and the same pyramid on its
 * own ground at x = 65,000 m, for 3 s each. Physics does not depend on where
 * it happens, so each box's displacement should be the same in both; the
 * reference is the same engine and setting at the origin. Error: the largest
 * difference of a box's displacement between the two runs in float ULPs at
 * 65 km (2^-8 m = 3.9 mm); the same in metres. The time is the far run's. */
static void far_run(sim* s, double x0, double seconds, double* out) {
  bench_world_def d = world_def(-G);
  sim_open(s, &d);
  ground(s, x0, 20.0, 0.6);
  int first = pyramid(s, 10, x0);
  int n = steps_for(s, seconds);
  double* start = out + 110;
  for (int k = 0; k < 55; ++k) {
    bench_state st = state(s, first + k);
    start[2 * k] = st.x - x0, start[2 * k + 1] = st.y;
  }
  for (int i = 0; i < n; ++i) sim_step(s);
  for (int k = 0; k < 55; ++k) {
    bench_state st = state(s, first + k);
    out[2 * k] = st.x - x0 - start[2 * k];
    out[2 * k + 1] = st.y - start[2 * k + 1];
  }
  sim_close(s);
}

static void run_far_pyramid(sim* s, double m[METRICS]) {
  const double far = 65000.0, ulp = 1.0 / 256.0;
  double near_d[220], far_d[220];
  sim ref = {s->e, NULL, s->s, 0.0, 0, false, 0, 0, 0};
  far_run(&ref, 0.0, 3.0, near_d);
  if (ref.failed) s->failed = true;
  far_run(s, far, 3.0, far_d);
  double worst = 0.0;
  for (int k = 0; k < 55; ++k) {
    worst = fmax(worst, hypot(far_d[2 * k] - near_d[2 * k], far_d[2 * k + 1] - near_d[2 * k + 1]));
  }
  m[0] = worst / ulp;
  m[1] = worst;
}

typedef struct scene {
  const char* name;
  void (*run)(sim* s, double m[METRICS]);
  bool integrators;            /* moved only by gravity and forces: sweep tumble's integrators */
  int max_hz;                  /* 0, or the highest rate swept (pyramid_100: 120, to fit in 15 minutes) */
  const char* metric[METRICS]; /* name (unit); the first is the error plotted */
  const char* definition;
} scene;

static const scene k_scenes[] = {
    {"projectile",
     run_projectile,
     true,
     0,
     {"position error (m)", "velocity error (m/s)", NULL},
     "disc launched at (10, 10) m/s, g = 10: |p - (v0 t + g t^2/2)| after 1 s"},
    {"constant_spin",
     run_constant_spin,
     true,
     0,
     {"angle error (rad)", "spin error (rad/s)", NULL},
     "2 x 1 m box spinning at 3 rad/s, no gravity: |angle - 3 t| after 2 s"},
    {"pendulum_5",
     run_pendulum_5,
     false,
     0,
     {"period error (rel)", "energy change (rel)", "max joint gap (m)"},
     "disc on a revolute joint 1 m below a pivot from 5 deg: period against 4 sqrt(L/g) K(sin(theta0/2))"},
    {"pendulum_90",
     run_pendulum_90,
     false,
     0,
     {"period error (rel)", "energy change (rel)", "max joint gap (m)"},
     "the same pendulum released from 90 deg"},
    {"rolling_disc",
     run_rolling_disc,
     false,
     0,
     {"distance error (rel)", "slip (rel)", NULL},
     "disc rolling down a 30 deg incline: distance in 1.5 s against (1/3) g sin(theta) t^2"},
    {"sliding_box",
     run_sliding_box,
     false,
     0,
     {"distance error (rel)", "max tilt (rad)", NULL},
     "box sliding down a 30 deg incline, mu 0.3: distance in 1.5 s against g (sin - mu cos) t^2 / 2"},
    {"sticking_box",
     run_sticking_box,
     false,
     0,
     {"creep (m)", "normal motion (m)", NULL},
     "box resting on a 20 deg incline, mu 0.6: distance crept in 5 s (0 exactly)"},
    {"bounce_050",
     run_bounce_050,
     false,
     0,
     {"apex error (m)", NULL, NULL},
     "ball dropped from 2 m, e = 0.5: first apex against e^2 h0"},
    {"bounce_100",
     run_bounce_100,
     false,
     0,
     {"apex error (m)", NULL, NULL},
     "ball dropped from 2 m, e = 1: first apex against e^2 h0"},
    {"collision_1d",
     run_collision_1d,
     false,
     0,
     {"velocity error (rel)", "momentum error (rel)", "energy error (rel)"},
     "head-on elastic collision of discs of mass ratio 3: velocities against the closed form"},
    {"bullet_block",
     run_bullet_block,
     false,
     0,
     {"block speed error (rel)", "momentum error (rel)", "bullet-block speed (m/s)"},
     "0.039 kg bullet at 100 m/s into a 1 kg block, e = 0: block speed against m v0 / (m + M)"},
    {"stack_15",
     run_stack_15,
     false,
     0,
     {"top displacement (m)", "max top wander (m)", "max height error (m)"},
     "15 unit boxes stacked at their rest places for 10 s: top box's distance from its rest place"},
    {"stack_30",
     run_stack_30,
     false,
     0,
     {"top displacement (m)", "max top wander (m)", "max height error (m)"},
     "30 unit boxes stacked for 10 s: top box's distance from its rest place"},
    {"pyramid_20",
     run_pyramid_20,
     false,
     0,
     {"max drift (m)", "top sag (m)", "max sideways drift (m)"},
     "pyramid of base 20 (210 boxes) at rest places for 5 s: largest box displacement"},
    {"pyramid_100",
     run_pyramid_100,
     false,
     120,
     {"max drift (m)", "top sag (m)", "max sideways drift (m)"},
     "pyramid of base 100 (5,050 boxes) for 1 s, 30 to 120 Hz only (base 40 with --quick): largest box displacement"},
    {"mass_ratio",
     run_mass_ratio,
     false,
     0,
     {"sink (m)", "small box tilt (rad)", "sideways drift (m)"},
     "20 m box (400 kg) on two 1 kg boxes for 5 s: distance from its rigid rest height"},
    {"chain_ball",
     run_chain_ball,
     false,
     0,
     {"mean summed joint gap (m)", "max summed gap (m)", "final summed gap (m)"},
     "40-link chain (6 kg links) with a 314 kg ball swinging down for 5 s: joint gaps summed over 41 joints"},
    {"elastic_balls",
     run_elastic_balls,
     false,
     0,
     {"energy drift (rel)", "momentum drift (rel)", "max energy drift (rel)"},
     "40 elastic balls in a free box, no gravity, no friction, for 10 s: |E - E0| / E0"},
    {"mass_spring",
     run_mass_spring,
     true,
     0,
     {"position error (m)", "energy error (rel)", NULL},
     "1 kg on a 4 pi^2 N/m spring from 1 m: |x - cos(w t)| after 10 s"},
    {"far_pyramid",
     run_far_pyramid,
     false,
     0,
     {"drift (ULP at 65 km)", "drift (m)", NULL},
     "pyramid of base 10 at x = 65 km against the same at the origin, 3 s: displacement difference"},
};
#define SCENE_COUNT ((int)(sizeof k_scenes / sizeof k_scenes[0]))

/* ------------------------------------------------------------- settings -- */

typedef struct engine_setting {
  const bench_engine* e;
  bench_setting s;
  bool is_default;
} engine_setting;

static const char* k_integrators[3] = {"euler", "midpoint", "rk4"};

/* --quick's substep settings (tumble's, and v3's in bench_accuracy_v3) */
static bool quick_substeps(int hz, int substeps) {
  return (hz == 60 && (substeps == 1 || substeps == 4 || substeps == 8)) || ((hz == 30 || hz == 120) && substeps == 4);
}

static int make_settings(engine_setting* out, bool integrators, int max_hz) {
  static const int hz_full[4] = {30, 60, 120, 240};
  static const int substeps_full[5] = {1, 2, 4, 8, 16};
  static const int iters[4][2] = {{4, 2}, {8, 3}, {16, 6}, {32, 12}};
  int n = 0, kinds = integrators ? 3 : 1;
  for (int h = 0; h < 4; ++h) {
    if (max_hz > 0 && hz_full[h] > max_hz) continue;
    double dt = 1.0 / hz_full[h];
    for (int k = 0; k < kinds; ++k) {
      for (int q = 0; q < 5; ++q) {
        int ss = substeps_full[q];
        if (g_quick && !quick_substeps(hz_full[h], ss)) continue;
        /* integrator index = tb_integrator; scenes without the sweep use
         * tumble's default, midpoint (1), which is also the default row */
        int integrator = integrators ? k : 1;
        engine_setting es = {
            &bench_tumble_engine, {dt, ss, integrator, 0, 0}, hz_full[h] == 60 && ss == 4 && integrator == 1};
        out[n++] = es;
      }
    }
    for (int q = 0; q < 4; ++q) {
      if (g_quick && !((hz_full[h] == 60 && q < 3) || ((hz_full[h] == 30 || hz_full[h] == 120) && q == 1))) continue;
      engine_setting es = {&bench_box2d_engine, {dt, 0, 0, iters[q][0], iters[q][1]}, hz_full[h] == 60 && q == 1};
      out[n++] = es;
    }
#ifdef BENCH_WITH_V3
    /* v3 at substeps 1, 2, 4, 8; its default is 4 at 60 Hz */
    for (int q = 0; q < 4; ++q) {
      int ss = substeps_full[q];
      if (g_quick && !quick_substeps(hz_full[h], ss)) continue;
      engine_setting es = {&bench_box2d_v3_engine, {dt, ss, 0, 0, 0}, hz_full[h] == 60 && ss == 4};
      out[n++] = es;
    }
#endif
  }
  return n;
}

static int compare_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static const char* k_csv_header =
    "scene,engine,hz,substeps,velocity_iterations,position_iterations,integrator,is_default,steps,runs,"
    "ms_step_min,ms_step_median,ms_per_60hz_frame,error,metric2,metric3,bodies,contacts,joints,ok\n";

/* --perturb: the setting's errors over g_perturb_runs draws of start offsets,
 * their median and largest. */
static bool run_perturbed(const scene* sc, const engine_setting* es, const char* label) {
  double e[METRICS][MAX_PERTURB];
  bool ok = true;
  for (int r = 0; r < g_perturb_runs; ++r) {
    sim s = {es->e, NULL, es->s, 0.0, 0, false, 0, 0, 0};
    double m[METRICS] = {0.0, 0.0, 0.0};
    g_perturb_seed = (uint32_t)r + 1u;
    sc->run(&s, m);
    g_perturb_seed = 0;
    ok = ok && !s.failed;
    for (int k = 0; k < METRICS; ++k) e[k][r] = m[k], ok = ok && isfinite(m[k]);
  }
  double median[METRICS], most[METRICS];
  for (int k = 0; k < METRICS; ++k) {
    qsort(e[k], (size_t)g_perturb_runs, sizeof e[k][0], compare_double);
    int n = g_perturb_runs;
    median[k] = n % 2 == 1 ? e[k][n / 2] : 0.5 * (e[k][n / 2 - 1] + e[k][n / 2]);
    most[k] = e[k][n - 1];
  }
  printf("%-14s %-32s perturbed x%d: median %.3e  %.3e  %.3e  largest %.3e  %.3e  %.3e%s\n", sc->name, label,
         g_perturb_runs, median[0], median[1], median[2], most[0], most[1], most[2], ok ? "" : "  BROKEN");
  fflush(stdout);
  return ok;
}

/* Runs one scene at one setting; writes a CSV row; returns false when broken. */
static bool run_setting(const scene* sc, const engine_setting* es, int runs, FILE* csv) {
  double ms[MAX_RUNS], m[METRICS] = {0.0, 0.0, 0.0};
  int done = 0, steps = 0, bodies = 0, contacts = 0, joints = 0;
  bool failed = false;
  double spent = 0.0;
  for (int r = 0; r < runs; ++r) {
    sim s = {es->e, NULL, es->s, 0.0, 0, false, 0, 0, 0};
    for (int k = 0; k < METRICS; ++k) m[k] = 0.0;
    double t0 = now_ms();
    sc->run(&s, m);
    spent += now_ms() - t0;
    ms[done++] = s.steps > 0 ? s.step_ms / s.steps : 0.0;
    steps = s.steps, bodies = s.bodies, contacts = s.contacts, joints = s.joints;
    failed = failed || s.failed;
    if (spent > 2000.0) break; /* long scenes: the spread is small next to a 2 s run */
    /* tiny scenes run in microseconds: more runs (up to MAX_RUNS) until 0.2 s */
    if (r == runs - 1 && runs > 1 && runs < MAX_RUNS && spent < 200.0) runs += 1;
  }
  qsort(ms, (size_t)done, sizeof ms[0], compare_double);
  bool ok = !failed;
  for (int k = 0; k < METRICS; ++k) ok = ok && isfinite(m[k]);
  double frame = ms[0] * (1.0 / 60.0) / es->s.dt;
  int hz = (int)lround(1.0 / es->s.dt);
  bool tumble = es->e == &bench_tumble_engine;
  const char* integrator = tumble ? k_integrators[es->s.integrator] : "";
  char label[64];
  if (tumble) {
    snprintf(label, sizeof label, "tumble %3d Hz %2d sub %s", hz, es->s.substeps, integrator);
#ifdef BENCH_WITH_V3
  } else if (es->e == &bench_box2d_v3_engine) {
    snprintf(label, sizeof label, "v3     %3d Hz %2d sub", hz, es->s.substeps);
#endif
  } else {
    snprintf(label, sizeof label, "box2d  %3d Hz %2d/%-2d", hz, es->s.velocity_iterations, es->s.position_iterations);
  }
  printf("%-14s %-32s %8.4f ms/step %8.4f ms/frame  err %.3e  %.3e  %.3e%s%s\n", sc->name, label, ms[0], frame, m[0],
         m[1], m[2], es->is_default ? "  [default]" : "", ok ? "" : "  BROKEN");
  fflush(stdout);
  if (g_perturb_runs > 0) ok = run_perturbed(sc, es, label) && ok;
  if (csv != NULL) {
    fprintf(csv, "%s,%s,%d,%d,%d,%d,%s,%d,%d,%d,%.6f,%.6f,%.6f,%.6e,%.6e,%.6e,%d,%d,%d,%d\n", sc->name, es->e->name, hz,
            es->s.substeps, es->s.velocity_iterations, es->s.position_iterations, integrator, es->is_default ? 1 : 0,
            steps, done, ms[0], ms[done / 2], frame, m[0], m[1], m[2], bodies, contacts, joints, ok ? 1 : 0);
    fflush(csv);
  }
  return ok;
}

/* -------------------------------------------------------------- scaling -- */

/* Step time against body count: a pyramid of `base` unit boxes on the ground,
 * tumble at 60 Hz / 4 substeps and Box2D at 60 Hz / 8-3, sleep off. 30
 * untimed steps (the first contacts), then `timed` steps; min and median of
 * the runs' mean ms per step. */
static bool run_scaling(int runs, FILE* csv) {
  static const int bases_full[] = {10, 20, 40, 60, 80, 100, 120, 140};
  static const int bases_quick[] = {10, 20, 40};
  const int* bases = g_quick ? bases_quick : bases_full;
  int count = g_quick ? 3 : 8, timed = g_quick ? 20 : 60;
  const engine_setting settings[2] = {{&bench_tumble_engine, {1.0 / 60.0, 4, 0, 0, 0}, true},
                                      {&bench_box2d_engine, {1.0 / 60.0, 0, 0, 8, 3}, true}};
  if (csv != NULL) fprintf(csv, "engine,base,bodies,contacts,steps,runs,ms_step_min,ms_step_median\n");
  printf("%-8s %5s %7s %8s %10s %10s\n", "engine", "base", "bodies", "contacts", "min ms", "median ms");
  bool ok = true;
  for (int b = 0; b < count; ++b) {
    for (int k = 0; k < 2; ++k) {
      double ms[MAX_RUNS];
      int bodies = 0, contacts = 0;
      for (int r = 0; r < runs; ++r) {
        sim s = {settings[k].e, NULL, settings[k].s, 0.0, 0, false, 0, 0, 0};
        bench_world_def d = world_def(-G);
        sim_open(&s, &d);
        ground(&s, 0.0, bases[b] + 10.0, 0.6);
        pyramid(&s, bases[b], 0.0);
        for (int i = 0; i < 30; ++i) sim_step(&s);
        s.step_ms = 0.0, s.steps = 0;
        for (int i = 0; i < timed; ++i) sim_step(&s);
        ms[r] = s.step_ms / s.steps;
        sim_close(&s);
        bodies = s.bodies, contacts = s.contacts;
        ok = ok && !s.failed && isfinite(ms[r]);
      }
      qsort(ms, (size_t)runs, sizeof ms[0], compare_double);
      printf("%-8s %5d %7d %8d %10.3f %10.3f\n", settings[k].e->name, bases[b], bodies, contacts, ms[0], ms[runs / 2]);
      fflush(stdout);
      if (csv != NULL) {
        fprintf(csv, "%s,%d,%d,%d,%d,%d,%.6f,%.6f\n", settings[k].e->name, bases[b], bodies, contacts, timed, runs,
                ms[0], ms[runs / 2]);
        fflush(csv);
      }
    }
  }
  return ok;
}

/* ----------------------------------------------------------------- main -- */

static void usage(const char* argv0) {
  fprintf(stderr,
          "usage: %s [--quick] [--scaling] [--scene NAME] [--runs N] [--defaults] [--perturb N (1..%d)] [--csv FILE]"
          " [--meta FILE]\n",
          argv0, MAX_PERTURB);
}

int main(int argc, char** argv) {
  const char *only = NULL, *csv_path = NULL, *meta_path = NULL;
  int runs = -1;
  bool scaling = false, defaults = false;
  for (int i = 1; i < argc; ++i) {
    bool has_value = i + 1 < argc;
    if (strcmp(argv[i], "--quick") == 0) {
      g_quick = true;
    } else if (strcmp(argv[i], "--scaling") == 0) {
      scaling = true;
    } else if (strcmp(argv[i], "--scene") == 0 && has_value) {
      only = argv[++i];
    } else if (strcmp(argv[i], "--runs") == 0 && has_value) {
      runs = atoi(argv[++i]);
    } else if (strcmp(argv[i], "--defaults") == 0) {
      defaults = true;
    } else if (strcmp(argv[i], "--perturb") == 0 && has_value) {
      g_perturb_runs = atoi(argv[++i]);
      if (g_perturb_runs < 1 || g_perturb_runs > MAX_PERTURB) {
        usage(argv[0]);
        return 2;
      }
    } else if (strcmp(argv[i], "--csv") == 0 && has_value) {
      csv_path = argv[++i];
    } else if (strcmp(argv[i], "--meta") == 0 && has_value) {
      meta_path = argv[++i];
    } else {
      usage(argv[0]);
      return 2;
    }
  }
  if (runs < 0) runs = g_quick ? 1 : 3;
  if (runs < 1 || runs > MAX_RUNS) {
    usage(argv[0]);
    return 2;
  }
  FILE* csv = NULL;
  if (csv_path != NULL) {
    csv = fopen(csv_path, "w");
    if (csv == NULL) {
      perror(csv_path);
      return 1;
    }
  }
  bool ok = true;
  if (scaling) {
    ok = run_scaling(runs, csv);
  } else {
    if (meta_path != NULL) {
      FILE* meta = fopen(meta_path, "w");
      if (meta == NULL) {
        perror(meta_path);
        return 1;
      }
      fprintf(meta, "scene\terror\tmetric2\tmetric3\tdefinition\n");
      for (int k = 0; k < SCENE_COUNT; ++k) {
        const scene* sc = &k_scenes[k];
        fprintf(meta, "%s\t%s\t%s\t%s\t%s\n", sc->name, sc->metric[0], sc->metric[1] ? sc->metric[1] : "",
                sc->metric[2] ? sc->metric[2] : "", sc->definition);
      }
      fclose(meta);
    }
    if (csv != NULL) fputs(k_csv_header, csv);
    engine_setting settings[128];
    bool found = only == NULL;
    for (int k = 0; k < SCENE_COUNT; ++k) {
      const scene* sc = &k_scenes[k];
      if (only != NULL && strcmp(only, sc->name) != 0) continue;
      found = true;
      int n = make_settings(settings, sc->integrators, sc->max_hz);
      for (int i = 0; i < n; ++i)
        if (!defaults || settings[i].is_default) ok = run_setting(sc, &settings[i], runs, csv) && ok;
    }
    if (!found) {
      fprintf(stderr, "unknown scene '%s'\n", only);
      ok = false;
    }
  }
  if (csv != NULL) fclose(csv);
  if (!ok) fprintf(stderr, "bench_accuracy: a step failed or a metric is not finite (see BROKEN above)\n");
  return ok ? 0 : 1;
}
