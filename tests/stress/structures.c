/* Stacks and structures: columns of 15 and 30 boxes, pyramids of base 20 and
 * 100, a 5-level house of 2 mm cards and a friction-only arch, each standing
 * for 30 s of simulated time with sleep off (a sleeping structure is frozen
 * and would hide any drift; here the solver holds it every step).
 *
 * Rigid bodies would not move at all. Soft contacts hold a load with a small
 * overlap (a damped spring of 115 Hz at 4 substeps: about g / (2 pi 115 Hz)^2
 * = 0.02 mm per body weight on a contact), so a standing structure's top
 * sinks by the sum of its interfaces' overlaps (closed form below for the
 * columns and pyramids); one that buckles, topples or slides moves it by its
 * own size. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

#define PI_F 3.14159265358979f
#define STAND_STEPS 1800 /* 30 s at 60 Hz */

/* How far the body at `tracked` wanders over `steps` steps: the largest
 * horizontal distance from its start and its final sinking. */
typedef struct drift {
  double sideways, sank, angle;
  bool finite;
} drift;

static drift track(tb_world_id w, tb_body_id tracked, int steps) {
  tb_vec2 p0 = tb_body_get_world_center(tracked);
  drift d = {0.0, 0.0, 0.0, true};
  for (int i = 0; i < steps && d.finite; ++i) {
    if (!stress_step(w)) d.finite = false;
    tb_vec2 p = tb_body_get_world_center(tracked);
    d.finite = d.finite && isfinite(p.x) && isfinite(p.y);
    d.sideways = fmax(d.sideways, fabs((double)p.x - p0.x));
  }
  d.sank = (double)p0.y - tb_body_get_world_center(tracked).y;
  d.angle = tb_body_get_angle(tracked);
  return d;
}

/* Passes when the top stays within `limit` of its start both ways. */
static void judge(stress_result* out, drift d, double limit) {
  out->pass = d.finite && d.sideways < limit && fabs(d.sank) < limit;
  stress_note(out, "top drift %.3g m sideways (max), sank %.3g m, angle %.2g rad%s", d.sideways, d.sank, d.angle,
              d.finite ? "" : ", NOT FINITE");
}

/* ---- columns and pyramids ---------------------------------------------- */

/* How far a soft contact closes under load, in closed form. A contact point
 * is a spring k = m_n omega^2; at rest the points' loads F (N) close it by
 * (K F)_i / omega^2, K the contact's 2x2 inverse mass matrix (the fixed point
 * of the soft update, see contact_solver.c). For boxes of mass m and half
 * size a (I = 2 m a^2 / 3, so a^2 / I = 1.5 / m), points at the face ends:
 *   box on the ground (static, points at +-a):   K11 = 2.5/m, K12 = -0.5/m
 *   box on a box, face to face (+-a on both):    K11 = 5/m,   K12 = -1/m
 *   box on half a box (pyramid: each point at a
 *   face end of one box, the middle of the other): K11 = 3.5/m, K12 = 2/m
 * so with the load W split evenly over the two points a contact closes by
 * c W / (m omega^2) with c = 1, 2 and 2.75 (omega: stress_contact_omegas).
 * The sums below are the tops' sinking; the test allows 10 % more. Columns
 * match it to 0.1 %; pyramids sink about 20 % less, as the touching
 * neighbours of a row also carry some of the load. */

/* The top of a column of `count` boxes: the box k from the top carries k
 * weights on the one below (c = 2), the bottom one count weights on the
 * ground (c = 1). */
static double column_sinking(int count) {
  double w, ws;
  stress_contact_omegas(&w, &ws);
  double sink = (double)count * STRESS_G / (ws * ws);
  for (int k = 1; k < count; ++k) sink += 2.0 * k * STRESS_G / (w * w);
  return sink;
}

/* The top of a pyramid: each box passes its load (its own weight and what
 * rests on it) half to each box below; a box sinks by the mean of its two
 * supports' sinking plus its own contacts' closing, each carrying half its
 * load (c = 2.75), or by its ground contact's (c = 1) in the bottom row. */
static double pyramid_sinking(int base) {
  double w, ws;
  stress_contact_omegas(&w, &ws);
  /* loads in weights, row t from the top (t + 1 boxes) stored at t(t+1)/2:
   * a box's own weight and half of each box above it */
  double* load = calloc((size_t)base * (size_t)(base + 1) / 2, sizeof(double));
  double* sink = calloc((size_t)base, sizeof(double));
  if (!load || !sink) abort();
  for (int t = 0; t < base; ++t) {
    double *row = &load[(size_t)t * (size_t)(t + 1) / 2], *above = row - t;
    for (int j = 0; j <= t; ++j) row[j] = 1.0 + (j > 0 ? above[j - 1] / 2.0 : 0.0) + (j < t ? above[j] / 2.0 : 0.0);
  }
  /* sinking, row by row upwards */
  const double* bottom = &load[(size_t)(base - 1) * (size_t)base / 2];
  for (int j = 0; j < base; ++j) sink[j] = bottom[j] * STRESS_G / (ws * ws);
  for (int t = base - 2; t >= 0; --t) {
    const double* row = &load[(size_t)t * (size_t)(t + 1) / 2];
    for (int j = 0; j <= t; ++j) sink[j] = 0.5 * (sink[j] + sink[j + 1]) + 1.375 * row[j] * STRESS_G / (w * w);
  }
  double top = sink[0];
  free(load);
  free(sink);
  return top;
}

/* Passes when the top stays within 5 cm sideways (1/20 of a box: a lean
 * anyone would see) and sinks no more than the contacts' closing in closed
 * form plus 10 %: a structure that creeps, buckles or slides goes further. */
static void judge_soft(stress_result* out, drift d, double predicted) {
  out->pass = d.finite && d.sideways < 0.05 && fabs(d.sank) <= 1.1 * predicted;
  stress_note(out, "top drift %.3g m sideways (max), sank %.3g m (closed form %.3g m), angle %.2g rad%s", d.sideways,
              d.sank, predicted, d.angle, d.finite ? "" : ", NOT FINITE");
}

tb_world_id stress_new_stack(int count) {
  tb_world_id w = stress_world(false);
  stress_ground(w, 0.0f, 0.0f, 20.0f);
  stress_column(w, 0.0f, 0.0f, count, 0.5f);
  return w;
}

tb_world_id stress_new_pyramid(float x0, float y0, int base, float h) {
  tb_world_id w = stress_world(false);
  stress_ground(w, x0, y0, 2.0f * h * (float)base);
  stress_pyramid(w, x0, y0, base, h);
  return w;
}

/* The top of a structure is its last body (each builder creates it last). */
static tb_body_id last_body(tb_world_id w) {
  int n = 0;
  tb_body_id* all = stress_bodies(w, &n);
  tb_body_id top = all[n - 1];
  free(all);
  return top;
}

static void run_stack(stress_result* out, int count) {
  tb_world_id w = stress_new_stack(count);
  judge_soft(out, track(w, last_body(w), STAND_STEPS), column_sinking(count));
  tb_destroy_world(w);
}

void stress_stack_15(stress_result* out) { run_stack(out, 15); }
void stress_stack_30(stress_result* out) { run_stack(out, 30); }

static void run_pyramid(stress_result* out, int base) {
  tb_world_id w = stress_new_pyramid(0.0f, 0.0f, base, 0.5f);
  judge_soft(out, track(w, last_body(w), STAND_STEPS), pyramid_sinking(base));
  tb_destroy_world(w);
}

void stress_pyramid_20(stress_result* out) { run_pyramid(out, 20); }
void stress_pyramid_100(stress_result* out) { run_pyramid(out, 100); }

/* ---- house of cards ------------------------------------------------------ */

/* Cards 2 mm thick and 40 cm long, density 1, friction 0.6. Each level is a
 * row of A-frames (two cards leaning 20 deg from vertical, their top ends
 * 1 mm apart at the start); a flat card lies across each pair of
 * neighbouring apexes and carries one A-frame of the next level on its
 * middle. Levels of 5, 4, 3, 2, 1 frames: 30 leaning and 10 flat cards. A
 * card leaning at 20 deg needs a friction coefficient of about tan(20 deg)/2
 * = 0.18 at its foot and tan(20 deg) = 0.36 at the apex, where the contact
 * normal is one card's face normal while the force is horizontal (the two
 * cards' moment balances about their feet leave no vertical share). The
 * frames stand a card length plus 1 mm apart, so that the flat cards lie end
 * to end, each end 0.5 mm short of an apex's axis and 1.9 mm past the
 * leaning card's outer top corner it rests on: a start a rigid world holds
 * as it is. (Frames closer together make neighbouring flat cards start
 * overlapping at the same height; the push-out then lifts one of each pair
 * and the jolt topples the house, whatever the solver settings.) */
#define CARD_HALF_T 0.001f
#define CARD_HALF_L 0.2f
#define CARD_TILT (20.0f * PI_F / 180.0f)
#define CARD_GAP 0.0005f /* each card's top 0.5 mm short of the frame's axis */
#define CARD_LEVELS 5
#define CARD_FLAT_GAP 0.0005f /* each flat card's end 0.5 mm short of an apex's axis */

tb_world_id stress_new_card_house(void) {
  tb_world_id w = stress_world(false);
  stress_ground(w, 0.0f, 0.0f, 5.0f);
  float s = sinf(CARD_TILT), c = cosf(CARD_TILT);
  /* a leaning card's centre relative to its frame's axis and floor */
  float cx = CARD_HALF_L * s + CARD_HALF_T * c + CARD_GAP;
  float cy = CARD_HALF_L * c + CARD_HALF_T * s;
  /* height of a leaning card's outer top corner above the floor */
  float apex = 2.0f * CARD_HALF_L * c + 2.0f * CARD_HALF_T * s;
  float pitch = 2.0f * CARD_HALF_L + 2.0f * CARD_FLAT_GAP; /* flat cards end to end */
  float floor_y = 0.0f;
  for (int level = 0; level < CARD_LEVELS; ++level) {
    int frames = CARD_LEVELS - level;
    float x0 = -0.5f * pitch * (float)(frames - 1);
    for (int i = 0; i < frames; ++i) {
      float x = x0 + pitch * (float)i;
      stress_box(w, (tb_vec2){x - cx, floor_y + cy}, -CARD_TILT, CARD_HALF_T, CARD_HALF_L, NULL);
      stress_box(w, (tb_vec2){x + cx, floor_y + cy}, CARD_TILT, CARD_HALF_T, CARD_HALF_L, NULL);
    }
    if (frames == 1) break;
    /* flat cards on the apexes; the next level stands on them */
    float top = floor_y + apex;
    for (int i = 0; i + 1 < frames; ++i) {
      float x = x0 + pitch * ((float)i + 0.5f);
      stress_box(w, (tb_vec2){x, top + CARD_HALF_T}, 0.0f, CARD_HALF_L, CARD_HALF_T, NULL);
    }
    floor_y = top + 2.0f * CARD_HALF_T;
  }
  return w;
}

/* The top frame's right card: a collapse drops it by up to its 40 cm length.
 * 1 cm (2.5 % of a card) allows the frames to settle onto each other from
 * their 1 mm start gaps and the soft contacts' overlap under a few grams. */
void stress_card_house(stress_result* out) {
  tb_world_id w = stress_new_card_house();
  judge(out, track(w, last_body(w), STAND_STEPS), 0.01);
  tb_destroy_world(w);
}

/* ---- friction-only arch ---------------------------------------------------- */

/* A semicircular arch of 11 voussoirs (inner radius 4 m, outer 5 m, density 1,
 * friction 0.6) with radial joints, no mortar and no joints: only contact and
 * friction hold it. Its springings stand on the ground (y = 0). A ring of
 * thickness / mean radius = 0.22 is twice Heyman's minimum for a semicircular
 * arch under its own weight (0.107), so it stands with a rigid solver. The
 * keystone is created last. */
#define ARCH_BLOCKS 11
#define ARCH_R_IN 4.0f
#define ARCH_R_OUT 5.0f

tb_world_id stress_new_arch(void) {
  tb_world_id w = stress_world(false);
  stress_ground(w, 0.0f, 0.0f, 20.0f);
  int order[ARCH_BLOCKS];
  /* keystone last, so that the tracked top is the last body */
  for (int k = 0, n = 0; k < ARCH_BLOCKS; ++k)
    if (k != ARCH_BLOCKS / 2) order[n++] = k;
  order[ARCH_BLOCKS - 1] = ARCH_BLOCKS / 2;
  for (int n = 0; n < ARCH_BLOCKS; ++n) {
    int k = order[n];
    float a0 = PI_F * (float)k / ARCH_BLOCKS, a1 = PI_F * (float)(k + 1) / ARCH_BLOCKS;
    if (k == 0) a0 = 0.0f;
    if (k == ARCH_BLOCKS - 1) a1 = PI_F;
    tb_vec2 v[4] = {{ARCH_R_IN * cosf(a0), ARCH_R_IN * sinf(a0)},
                    {ARCH_R_OUT * cosf(a0), ARCH_R_OUT * sinf(a0)},
                    {ARCH_R_OUT * cosf(a1), ARCH_R_OUT * sinf(a1)},
                    {ARCH_R_IN * cosf(a1), ARCH_R_IN * sinf(a1)}};
    /* the springings' bottom faces lie exactly on the ground */
    if (k == 0) v[0].y = v[1].y = 0.0f;
    if (k == ARCH_BLOCKS - 1) v[2].y = v[3].y = 0.0f;
    tb_vec2 c = {0.25f * (v[0].x + v[1].x + v[2].x + v[3].x), 0.25f * (v[0].y + v[1].y + v[2].y + v[3].y)};
    for (int j = 0; j < 4; ++j) v[j] = (tb_vec2){v[j].x - c.x, v[j].y - c.y};
    tb_polygon block;
    if (tb_make_polygon(v, 4, 0.0f, &block) != TB_OK) continue;
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = c;
    tb_body_id b = tb_create_body(w, &bd);
    tb_shape_def sd = tb_default_shape_def();
    tb_create_polygon_shape(b, &sd, &block);
  }
  return w;
}

/* A collapsing arch drops its keystone by metres; 5 cm is 5 % of the ring's
 * 1 m thickness, room for the soft contacts' overlap at 10 joints. */
void stress_arch(stress_result* out) {
  tb_world_id w = stress_new_arch();
  judge(out, track(w, last_body(w), STAND_STEPS), 0.05);
  tb_destroy_world(w);
}
