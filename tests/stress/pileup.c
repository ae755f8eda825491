/* Pile-up (issue 23, item 10): bodies created at one point, half 0.5 m boxes
 * and half circles of radius 0.25 m, all 1 m above the floor of a static U
 * 30 m wide inside with 20 m walls, stepped 10 s at the defaults. Every pair
 * overlaps: 1,000 bodies start with 499,500 touching contacts. The test
 * checks what that costs in memory, that the pile spreads without being
 * thrown about and that the bodies end separated. */
#include <math.h>
#include <stdlib.h>

#include "../../src/contact.h"
#include "stress.h"

#define PILE_STEPS 600     /* 10 s, as the run */
#define PILE_HALF_WIDTH 15 /* inside of the U (m) */
#define PILE_WALL 20.0f    /* height of its walls (m) */
#define PILE_SPOT_Y 1.0f

tb_world_id stress_new_pileup(int count) {
  tb_world_id w = stress_world(true);
  tb_body_def bd = tb_default_body_def();
  tb_body_id u = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon part;
  tb_make_offset_box(PILE_HALF_WIDTH + 1.0f, 0.5f, (tb_vec2){0.0f, -0.5f}, 0.0f, &part);
  tb_create_polygon_shape(u, &sd, &part);
  for (int side = -1; side <= 1; side += 2) {
    tb_make_offset_box(0.5f, 0.5f * PILE_WALL, (tb_vec2){(float)side * (PILE_HALF_WIDTH + 0.5f), 0.5f * PILE_WALL},
                       0.0f, &part);
    tb_create_polygon_shape(u, &sd, &part);
  }
  for (int i = 0; i < count; ++i) {
    if (i % 2 == 0)
      stress_box(w, (tb_vec2){0.0f, PILE_SPOT_Y}, 0.0f, 0.25f, 0.25f, NULL);
    else
      stress_circle(w, (tb_vec2){0.0f, PILE_SPOT_Y}, 0.25f, NULL);
  }
  return w;
}

/* Bytes a touching pair may take. What one needs for a step: its contact
 * (tb_contact, with its manifold, and the pool's 6 B of generation and free
 * link); its share of the contact solver: one lane of a block of four
 * (tb_wide_contact in contact_solver.c, 720 B: 180 B a lane), its constraint
 * (20 B), its places in the step list (4 B), the deep list (124 B: where
 * the contact is, and a copy of what the push-out's sweeps read) and the
 * colouring scratch (16 B); its begin event (contact events are on by
 * default); and its slots in the pair set, 12 B each, 4 to 8 a pair (the set
 * doubles when a quarter full). Arrays grow by doubling, so they may hold
 * twice what they need. Before issue 23, the contacts beyond the solver's 24
 * colours each took a whole block of four: 1,048 B a pair. */
static double pair_budget(void) {
  double records = (double)sizeof(tb_contact) + 6.0 + 180.0 + 20.0 + 4.0 + 124.0 + 16.0;
  records += (double)sizeof(tb_contact_begin_event);
  return 2.0 * records + 8.0 * 12.0;
}

/* Whether a body's centre lies inside the U (a body that left it was thrown
 * over a wall or through one). */
static bool inside(tb_body_id b) {
  tb_vec2 p = tb_body_get_position(b);
  return fabsf(p.x) < (float)PILE_HALF_WIDTH && p.y > 0.0f && p.y < 4.0f * PILE_WALL;
}

/* The run: memory per pair after the first step (the live heap is highest
 * then, with every pair touching) against pair_budget; the peak speed,
 * checked after every step, against the push cap plus a fall from the
 * highest point any body reached (the push-out moves bodies without
 * momentum, so all the speed a body may have is a fall's and one soft push
 * capped at contact_push_max_velocity); at 10 s every body finite and inside
 * the U, and no overlap more than one linear slop deeper than its contact
 * force explains (as the overlap tests). */
static void pileup(stress_result* out, int count) {
  tb_world_def defaults = tb_default_world_def();
  double cap = defaults.contact_push_max_velocity;
  tb_world_id w = stress_new_pileup(count);
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n);
  long long before = stress_heap_live_bytes();
  stress_heap_reset_peak();
  double peak_speed = 0.0, top = PILE_SPOT_Y, deep_1s = 0.0, deep_3s = 0.0;
  bool ok = true;
  int pairs = 0;
  long long after_first = 0, peak = 0;
  for (int i = 0; i < PILE_STEPS && ok; ++i) {
    ok = stress_step(w) && stress_all_finite(b, n);
    if (i == 0) {
      after_first = stress_heap_live_bytes() - before;
      peak = stress_heap_peak_bytes() - before;
      pairs = tb_world_get_counts(w).contact_count;
    }
    peak_speed = fmax(peak_speed, stress_peak_speed(b, n));
    for (int k = 0; k < n; ++k)
      if (tb_body_get_type(b[k]) == TB_DYNAMIC_BODY) top = fmax(top, tb_body_get_position(b[k]).y);
    if (i == 59) deep_1s = stress_deepest_overlap(b, n);
    if (i == 179) deep_3s = stress_deepest_overlap(b, n);
  }
  int lost = 0;
  for (int k = 0; k < n; ++k) lost += tb_body_get_type(b[k]) == TB_DYNAMIC_BODY && !inside(b[k]);
  double speed_bound = cap + sqrt(2.0 * STRESS_G * (top - 0.25)); /* 0.25: the lowest a centre rests */
  double per_pair = pairs > 0 ? (double)after_first / pairs : 0.0, budget = pair_budget();
  double deep_end = stress_deepest_overlap(b, n), excess = stress_deepest_excess_overlap(b, n);
  out->pass = ok && lost == 0 && pairs == count * (count - 1) / 2 && per_pair <= budget && peak_speed <= speed_bound &&
              excess < TB_LINEAR_SLOP;
  stress_note(out,
              "%d pairs; engine heap %.0f B a pair after the first step (budget %.0f), peak %.0f MB; peak speed "
              "%.3g m/s (bound %.3g, top %.3g m); deepest overlap %.3g m at 1 s, %.3g at 3 s, %.3g at 10 s, "
              "%.3g m beyond its force; %d left the U%s",
              pairs, per_pair, budget, (double)peak / 1e6, peak_speed, speed_bound, top, deep_1s, deep_3s, deep_end,
              excess, lost, ok ? "" : ", NOT FINITE or step failed");
  free(b);
  tb_destroy_world(w);
}

void stress_pileup_300(stress_result* out) { pileup(out, 300); }
void stress_pileup_1000(stress_result* out) { pileup(out, 1000); }
