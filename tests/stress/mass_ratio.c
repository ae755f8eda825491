/* Mass ratios: a heavy plank on two light boxes (100:1, 400:1, 1000:1) and a
 * heavy ball on a 40-link chain (670:1).
 *
 * Soft constraints whose stiffness follows each point's effective mass hold a
 * load F with an overlap F / (m_n (2 pi f)^2): the light body's small m_n makes
 * a heavy load sink, which is what these tests measure. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

/* Two 1 m boxes of 1 kg (density 1) at x = -9 and 9 under a 20 x 1 m plank of
 * `ratio` kg (density ratio / 20) at rest on them, on the ground y = 0. The
 * bodies are created left support, right support, plank. */
tb_world_id stress_new_mass_ratio(float ratio) {
  tb_world_id w = stress_world(false);
  stress_ground(w, 0.0f, 0.0f, 40.0f);
  stress_box(w, (tb_vec2){-9.0f, 0.5f}, 0.0f, 0.5f, 0.5f, NULL);
  stress_box(w, (tb_vec2){9.0f, 0.5f}, 0.0f, 0.5f, 0.5f, NULL);
  tb_shape_def heavy = tb_default_shape_def();
  heavy.density = ratio / 20.0f;
  stress_box(w, (tb_vec2){0.0f, 1.5f}, 0.0f, 10.0f, 0.5f, &heavy);
  return w;
}

/* 30 s with sleep off (the solver holds the load every step). Rigid contacts
 * would keep the plank at 1.5 m. The bounds are tests/test_solver.c's: the
 * plank may sink 5 cm (5 % of a support's height; the soft contacts at their
 * stiffest hold 400:1 with about 3.7 cm of overlap, see there); a support may
 * not be crushed into the ground by more than 5 cm (5 % of its size); the
 * plank may not slide off (3 cm sideways). A collapse through the supports
 * sinks it by 1 m. */
static void run_mass_ratio(stress_result* out, float ratio) {
  tb_world_id w = stress_new_mass_ratio(ratio);
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n); /* ground, left, right, plank */
  double measured = tb_body_get_mass(b[3]) / tb_body_get_mass(b[1]);
  double low_plank = 1.5, low_box = 0.5, slide = 0.0;
  bool finite = true;
  for (int i = 0; i < 1800 && finite; ++i) {
    finite = stress_step(w) && stress_all_finite(b, n);
    low_plank = fmin(low_plank, tb_body_get_position(b[3]).y);
    low_box = fmin(low_box, fmin(tb_body_get_position(b[1]).y, tb_body_get_position(b[2]).y));
    slide = fmax(slide, fabs(tb_body_get_position(b[3]).x));
  }
  out->pass = finite && 1.5 - low_plank < 0.05 && 0.5 - low_box < 0.05 && slide < 0.03;
  stress_note(out, "ratio %.0f:1; plank sank %.3g m (max), supports %.3g m, plank slid %.2g m%s", measured,
              1.5 - low_plank, 0.5 - low_box, slide, finite ? "" : ", NOT FINITE");
  free(b);
  tb_destroy_world(w);
}

void stress_mass_ratio_100(stress_result* out) { run_mass_ratio(out, 100.0f); }
void stress_mass_ratio_400(stress_result* out) { run_mass_ratio(out, 400.0f); }
void stress_mass_ratio_1000(stress_result* out) { run_mass_ratio(out, 1000.0f); }

/* ---- ball and chain --------------------------------------------------------- */

/* 40 capsule links (half-length 0.25, radius 0.05, density 1) jointed end to
 * end by revolute joints from a static anchor at (0, 25), laid out horizontally
 * to the right, and a ball of radius 1 m pinned at its rim to the last link,
 * its density set for 670 times a link's mass. Released, the ball swings down
 * on the 20 m chain. */
#define CHAIN_LINKS 40
#define LINK_HALF 0.25f
#define LINK_RADIUS 0.05f
#define BALL_RADIUS 1.0f
#define BALL_RATIO 670.0f

tb_world_id stress_new_ball_and_chain(void) {
  tb_world_id w = stress_world(true);
  tb_body_def sd = tb_default_body_def();
  sd.position = (tb_vec2){0.0f, 25.0f};
  tb_body_id prev = tb_create_body(w, &sd);
  tb_shape_def link_def = tb_default_shape_def();
  tb_capsule link = {{-LINK_HALF, 0.0f}, {LINK_HALF, 0.0f}, LINK_RADIUS};
  float link_mass = tb_compute_capsule_mass(&link, 1.0f).mass;
  for (int i = 0; i <= CHAIN_LINKS; ++i) {
    bool ball = i == CHAIN_LINKS;
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    float x = 2.0f * LINK_HALF * (float)i + (ball ? BALL_RADIUS : LINK_HALF);
    bd.position = (tb_vec2){x, 25.0f};
    tb_body_id b = tb_create_body(w, &bd);
    if (ball) {
      tb_shape_def ball_def = tb_default_shape_def();
      ball_def.density = BALL_RATIO * link_mass / (3.14159265f * BALL_RADIUS * BALL_RADIUS);
      tb_circle c = {{0.0f, 0.0f}, BALL_RADIUS};
      tb_create_circle_shape(b, &ball_def, &c);
    } else {
      tb_create_capsule_shape(b, &link_def, &link);
    }
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = prev;
    jd.body_b = b;
    jd.local_anchor_a = i == 0 ? (tb_vec2){0.0f, 0.0f} : (tb_vec2){LINK_HALF, 0.0f};
    jd.local_anchor_b = (tb_vec2){ball ? -BALL_RADIUS : -LINK_HALF, 0.0f};
    tb_create_revolute_joint(w, &jd);
    prev = b;
  }
  return w;
}

/* The largest distance between a revolute joint's two anchors: 0 for a rigid
 * pin. */
static double widest_gap(const tb_body_id* bodies, int count) {
  double gap = 0.0;
  tb_joint_id joints[4];
  for (int i = 0; i < count; ++i) {
    int n = tb_body_get_joints(bodies[i], joints, 4);
    for (int k = 0; k < n; ++k) {
      tb_body_id a = tb_joint_get_body_a(joints[k]), b = tb_joint_get_body_b(joints[k]);
      tb_vec2 pa = tb_body_get_world_point(a, tb_joint_get_local_anchor_a(joints[k]));
      tb_vec2 pb = tb_body_get_world_point(b, tb_joint_get_local_anchor_b(joints[k]));
      gap = fmax(gap, hypot((double)pa.x - pb.x, (double)pa.y - pb.y));
    }
  }
  return gap;
}

/* 30 s of swinging at default settings. The ball pulls with up to three times
 * its weight at the bottom of the swing, all of it through the light links.
 * A gap below the links' radius (5 cm) keeps the rounded ends of neighbouring
 * links overlapping: the chain looks and acts connected. */
void stress_ball_and_chain(stress_result* out) {
  tb_world_id w = stress_new_ball_and_chain();
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n); /* links, then the ball (the anchor has no shape) */
  double ratio = tb_body_get_mass(b[n - 1]) / tb_body_get_mass(b[0]);
  double gap = 0.0;
  bool finite = true;
  for (int i = 0; i < 1800 && finite; ++i) {
    finite = stress_step(w) && stress_all_finite(b, n);
    gap = fmax(gap, widest_gap(b, n));
  }
  out->pass = finite && gap < LINK_RADIUS;
  stress_note(out, "ratio %.0f:1; widest joint gap %.3g m%s", ratio, gap, finite ? "" : ", NOT FINITE");
  free(b);
  tb_destroy_world(w);
}

/* ---- where the mass ratio stops holding ------------------------------------ */

/* A 1 m box of `ratio` kg resting on a 1 m box of 1 kg on the ground y = 0
 * (created ground, light, heavy). */
tb_world_id stress_new_heavy_on_light(float ratio) {
  tb_world_id w = stress_world(false);
  stress_ground(w, 0.0f, 0.0f, 10.0f);
  stress_box(w, (tb_vec2){0.0f, 0.5f}, 0.0f, 0.5f, 0.5f, NULL);
  tb_shape_def heavy = tb_default_shape_def();
  heavy.density = ratio;
  stress_box(w, (tb_vec2){0.0f, 1.5f}, 0.0f, 0.5f, 0.5f, &heavy);
  return w;
}

/* A pendulum released level: a 1 m link of 1 kg (a 1 x 0.1 m box) pinned at
 * one end to a static anchor at (0, 10), and a ball of radius 0.25 m and
 * `ratio` kg pinned at its centre to the link's other end (joined bodies do
 * not collide). */
tb_world_id stress_new_heavy_pendulum(float ratio) {
  tb_world_id w = stress_world(false);
  tb_body_def sd = tb_default_body_def();
  sd.position = (tb_vec2){0.0f, 10.0f};
  tb_body_id anchor = tb_create_body(w, &sd);
  tb_shape_def link_def = tb_default_shape_def();
  link_def.density = 10.0f; /* 0.1 m^2: 1 kg */
  tb_body_id link = stress_box(w, (tb_vec2){0.5f, 10.0f}, 0.0f, 0.5f, 0.05f, &link_def);
  tb_shape_def ball_def = tb_default_shape_def();
  ball_def.density = ratio / (3.14159265f * 0.25f * 0.25f);
  tb_body_id ball = stress_circle(w, (tb_vec2){1.0f, 10.0f}, 0.25f, &ball_def);
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = anchor;
  jd.body_b = link;
  jd.local_anchor_b = (tb_vec2){-0.5f, 0.0f};
  tb_create_revolute_joint(w, &jd);
  jd.body_a = link;
  jd.body_b = ball;
  jd.local_anchor_a = (tb_vec2){0.5f, 0.0f};
  jd.local_anchor_b = (tb_vec2){0.0f, 0.0f};
  tb_create_revolute_joint(w, &jd);
  return w;
}

/* Over 3 s at `substeps`: the deeper of the light box's overlap with the
 * ground and the heavy box's with the light one (m; 1 m: crushed through),
 * and the widest gap of the pendulum's two joints (m). */
static void run_edge(float ratio, int substeps, double* sink, double* gap) {
  tb_world_id w = stress_new_heavy_on_light(ratio);
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n); /* ground, light, heavy */
  *sink = 0.0;
  for (int i = 0; i < 180; ++i) {
    tb_world_step(w, STRESS_DT, substeps);
    double light = tb_body_get_position(b[1]).y, heavy = tb_body_get_position(b[2]).y;
    *sink = fmax(*sink, fmax(0.5 - light, light + 1.0 - heavy));
  }
  free(b);
  tb_destroy_world(w);
  w = stress_new_heavy_pendulum(ratio);
  b = stress_bodies(w, &n); /* link, ball (the anchor has no shape) */
  *gap = 0.0;
  for (int i = 0; i < 180; ++i) {
    tb_world_step(w, STRESS_DT, substeps);
    *gap = fmax(*gap, widest_gap(b, n));
  }
  free(b);
  tb_destroy_world(w);
}

/* The soft contacts' closed form for the heavy-on-light stack: each contact's
 * two points share the load, a point of effective mass m_n being a spring
 * m_n omega^2. The light box's points at (+-0.5, -0.5) have m_n = 1 /
 * (1/m + 0.5^2 / I) = 0.4 kg (m = 1, I = 1/6) against the ground (omega at
 * static bodies), and 1 / (2.5 + 2.5 / ratio) kg under the heavy box (omega
 * between dynamic bodies); the ground carries (ratio + 1) g, the light box
 * ratio g. Both omegas are capped at h omega = 3 (tumble.h): at 4 substeps
 * both are 720 rad/s, at 8 the dynamic one is 2 pi 120 = 754. */
static double soft_sink(double ratio, int substeps) {
  tb_world_def wd = tb_default_world_def();
  const double two_pi = 6.283185307179586;
  double most = 3.0 * substeps / STRESS_DT;
  double dynamic = fmin(two_pi * wd.contact_hertz, most), against_static = fmin(two_pi * 2.0 * wd.contact_hertz, most);
  double ground = 0.5 * (ratio + 1.0) * STRESS_G / (0.4 * against_static * against_static);
  double under = 0.5 * ratio * STRESS_G * (2.5 + 2.5 / ratio) / (dynamic * dynamic);
  return fmax(ground, under);
}

#define EDGE_RATIOS 6       /* 1e1 .. 1e6 */
#define EDGE_SUPPORTED 3    /* up to 1e3: the range tumble.h states */
#define EDGE_GAP_BOUND 0.01 /* m: 1 % of the link */
static double edge_sink[EDGE_RATIOS][2], edge_gap[EDGE_RATIOS][2];

/* Mass ratios 1e1 to 1e6 at 4 and 8 substeps (3 s each, sleep off). Within
 * the supported range (to 1e3) the stack may sink at most twice the soft
 * contacts' closed form (a spring loaded at once overshoots to at most twice
 * its static deflection) and the joints may open by at most 1 cm; beyond it
 * the table shows how it fails (the light box crushed through, the joints
 * opening), with no assertion. */
void stress_mass_ratio_edge(stress_result* out) {
  out->pass = true;
  for (int r = 0; r < EDGE_RATIOS; ++r)
    for (int s = 0; s < 2; ++s) {
      double ratio = pow(10.0, r + 1);
      run_edge((float)ratio, 4 << s, &edge_sink[r][s], &edge_gap[r][s]);
      if (r < EDGE_SUPPORTED)
        out->pass &= edge_sink[r][s] <= 2.0 * soft_sink(ratio, 4 << s) && edge_gap[r][s] <= EDGE_GAP_BOUND;
      out->pass &= isfinite(edge_sink[r][s]) && isfinite(edge_gap[r][s]);
    }
  stress_note(out, "4 substeps, sink / joint gap (m):");
  for (int r = 0; r < EDGE_RATIOS; ++r)
    stress_note(out, " 1e%d %.2g / %.2g%s", r + 1, edge_sink[r][0], edge_gap[r][0], r + 1 < EDGE_RATIOS ? ";" : "");
  stress_note(out, " (8 substeps: see the table below)");
}

void stress_mass_ratio_edge_table(FILE* f) {
  fprintf(f,
          "\n## Mass ratio: where it stops holding\n\n"
          "`mass_ratio_edge`: a 1 m box of the ratio's mass on a 1 m box of 1 kg on the ground, and a pendulum of a "
          "1 m, 1 kg link and a ball of the ratio's mass, each 3 s at 60 Hz. Sink: the deeper overlap of the stack's "
          "two contacts (1 m: the heavy box went through the light one); soft closed form: the deflection of the "
          "contacts' springs under the load (tumble.h, contact_hertz); joint gap: the widest distance between a "
          "joint's two anchors. tumble.h states the supported range, up to 1e3:1.\n\n"
          "| mass ratio | sink, 4 substeps | closed form | joint gap, 4 substeps | sink, 8 substeps | closed form | "
          "joint gap, 8 substeps |\n| --- | --- | --- | --- | --- | --- | --- |\n");
  for (int r = 0; r < EDGE_RATIOS; ++r) {
    double ratio = pow(10.0, r + 1);
    fprintf(f, "| 1e%d | %.3g m | %.3g m | %.3g m | %.3g m | %.3g m | %.3g m |\n", r + 1, edge_sink[r][0],
            soft_sink(ratio, 4), edge_gap[r][0], edge_sink[r][1], soft_sink(ratio, 8), edge_gap[r][1]);
  }
}
