/* Overlap recovery: bodies created overlapping must separate without being
 * launched. The contact solver pushes overlapping shapes apart no faster than
 * tb_world_def.contact_push_max_velocity (default 3 m/s) and keeps no momentum
 * from that push, so no body should move faster than the cap plus what gravity
 * adds while the overlap clears: at the capped speed, an overlap d takes
 * d / cap to clear, during which gravity adds g d / cap. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

#define RECOVERY_STEPS 180 /* 3 s */

/* A grid of 1 m boxes, 4 wide and 5 high, centres 0.75 m apart both ways (each
 * overlaps its neighbours by 25 %), the bottom row sunk 25 cm into the ground. */
#define BOX_OVERLAP 0.25f
tb_world_id stress_new_overlap_boxes(void) {
  tb_world_id w = stress_world(true);
  stress_ground(w, 0.0f, 0.0f, 20.0f);
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 4; ++col)
      stress_box(w, (tb_vec2){0.75f * ((float)col - 1.5f), 0.25f + 0.75f * (float)row}, 0.0f, 0.5f, 0.5f, NULL);
  return w;
}

/* A pile of 256 circles of radius 0.25 in a static U of inner width 6 m:
 * 16 rows of 16 on a lattice 0.375 m apart (each overlaps its neighbours by
 * 25 % of its diameter), the bottom row sunk 12.5 cm into the floor. */
#define CIRCLE_OVERLAP 0.125f
tb_world_id stress_new_overlap_circles(void) {
  tb_world_id w = stress_world(true);
  tb_body_def bd = tb_default_body_def();
  tb_body_id u = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon wall;
  tb_make_offset_box(4.0f, 0.5f, (tb_vec2){0.0f, -0.5f}, 0.0f, &wall);
  tb_create_polygon_shape(u, &sd, &wall);
  tb_make_offset_box(0.5f, 6.0f, (tb_vec2){-3.5f, 6.0f}, 0.0f, &wall);
  tb_create_polygon_shape(u, &sd, &wall);
  tb_make_offset_box(0.5f, 6.0f, (tb_vec2){3.5f, 6.0f}, 0.0f, &wall);
  tb_create_polygon_shape(u, &sd, &wall);
  for (int row = 0; row < 16; ++row)
    for (int col = 0; col < 16; ++col)
      stress_circle(w, (tb_vec2){-2.8125f + 0.375f * (float)col, 0.125f + 0.375f * (float)row}, 0.25f, NULL);
  return w;
}

/* Steps the world for 3 s: the peak speed of any body, checked after every
 * step, must stay below the cap plus g d / cap, and at the end no overlap
 * may be more than one linear slop (5 mm) deeper than its contact force
 * explains. */
static void recover(stress_result* out, tb_world_id (*make)(void), double overlap) {
  tb_world_def defaults = tb_default_world_def();
  double cap = defaults.contact_push_max_velocity;
  double bound = cap + STRESS_G * overlap / cap;
  tb_world_id w = make();
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n);
  double peak = 0.0, start = 0.0;
  bool finite = true;
  for (int i = 0; i < RECOVERY_STEPS && finite; ++i) {
    finite = stress_step(w) && stress_all_finite(b, n);
    peak = fmax(peak, stress_peak_speed(b, n));
    if (i == 0) start = stress_deepest_overlap(b, n);
  }
  double left = stress_deepest_overlap(b, n), excess = stress_deepest_excess_overlap(b, n);
  out->pass = finite && peak <= bound && excess < TB_LINEAR_SLOP;
  stress_note(out,
              "peak speed %.3g m/s (bound %.3g); overlap %.3g m after the first step, %.3g m at 3 s, of which "
              "%.3g m beyond the depth its force explains%s",
              peak, bound, start, left, excess, finite ? "" : ", NOT FINITE");
  free(b);
  tb_destroy_world(w);
}

void stress_overlap_boxes(stress_result* out) { recover(out, stress_new_overlap_boxes, BOX_OVERLAP); }
void stress_overlap_circles(stress_result* out) { recover(out, stress_new_overlap_circles, CIRCLE_OVERLAP); }
