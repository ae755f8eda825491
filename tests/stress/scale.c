/* Scale: the same pyramid far from the origin, and tiny and large boxes.
 *
 * tumble moves bodies in displacements from the step start (README), so a
 * scene far away should solve like one at the origin: only the rounding of
 * the stored coordinate, one float step (ULP) of it, may differ. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

#define SCALE_STEPS 600 /* 10 s */

/* Runs a pyramid of base 20 (1 m boxes) with its base centred at (x0, x0),
 * sleep off, and returns its bodies' positions relative to (x0, x0). */
static tb_vec2* run_offset_pyramid(float x0, int* count) {
  tb_world_id w = stress_new_pyramid(x0, x0, 20, 0.5f);
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n);
  for (int i = 0; i < SCALE_STEPS; ++i)
    if (!stress_step(w)) break;
  tb_vec2* rel = malloc(sizeof *rel * (size_t)n);
  for (int i = 0; rel != NULL && i < n; ++i) {
    tb_vec2 p = tb_body_get_position(b[i]);
    rel[i] = (tb_vec2){p.x - x0, p.y - x0}; /* exact: Sterbenz, p within a factor 2 of x0 */
  }
  free(b);
  tb_destroy_world(w);
  *count = n;
  return rel;
}

/* 8 km and 65 km: the ULP there is 0.49 mm and 3.9 mm. The top box's drift
 * (its position relative to the pyramid's origin; it starts exactly where the
 * origin run's does) must match the origin run's to one ULP of the
 * coordinate. The worst of all 210 bodies is reported too. */
void stress_scale_offset(stress_result* out) {
  int n0 = 0;
  tb_vec2* at_origin = run_offset_pyramid(0.0f, &n0);
  const float offsets[2] = {8000.0f, 65000.0f};
  out->pass = at_origin != NULL;
  for (int k = 0; k < 2; ++k) {
    int n = 0;
    tb_vec2* far = run_offset_pyramid(offsets[k], &n);
    double ulp = stress_ulp(offsets[k]), worst = 0.0, top = INFINITY;
    if (far != NULL && at_origin != NULL && n == n0 && n > 0)
      top = fmax(fabs((double)far[n - 1].x - at_origin[n - 1].x), fabs((double)far[n - 1].y - at_origin[n - 1].y));
    for (int i = 0; far != NULL && at_origin != NULL && i < n && n == n0; ++i) {
      double dx = fabs((double)far[i].x - at_origin[i].x), dy = fabs((double)far[i].y - at_origin[i].y);
      worst = fmax(worst, fmax(dx, dy));
    }
    bool ok = far != NULL && n == n0 && isfinite(top) && isfinite(worst) && top <= ulp;
    out->pass = out->pass && ok;
    stress_note(out, "%s%.0f km: top off by %.3g m = %.2f ULP (worst body %.2f ULP)", k ? "; " : "",
                offsets[k] / 1000.0, top, top / ulp, worst / ulp);
    free(far);
  }
  free(at_origin);
}

/* A pyramid of base 10 of boxes of half-size h stands 10 s with sleep off; its
 * top may drift 5 % of a box size (the 1 m pyramids' 5 cm, scaled); a toppled
 * top moves by its own size. The soft contacts' stiffness is capped at
 * h omega = 3 per substep, where a point carrying F sinks F h^2 / (9 m_n)
 * whatever the size (about 0.02 mm per body weight at 4 substeps): the
 * 2.5 cm pyramid's top sinks about 0.1 mm per level (measured 0.9 mm in all,
 * 3.6 % of a box), the 50 m one's nothing. */
static void run_sized_pyramid(stress_result* out, float h) {
  tb_world_id w = stress_new_pyramid(0.0f, 0.0f, 10, h);
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n);
  tb_body_id top = b[n - 1];
  tb_vec2 p0 = tb_body_get_position(top);
  double drift = 0.0;
  bool finite = true;
  for (int i = 0; i < SCALE_STEPS && finite; ++i) {
    finite = stress_step(w) && stress_all_finite(b, n);
    tb_vec2 p = tb_body_get_position(top);
    drift = fmax(drift, hypot((double)p.x - p0.x, (double)p.y - p0.y));
  }
  double size = 2.0 * h;
  out->pass = finite && drift < 0.05 * size;
  stress_note(out, "box %.3g m: top drift %.3g m = %.2g %% of a box%s", size, drift, 100.0 * drift / size,
              finite ? "" : ", NOT FINITE");
  free(b);
  tb_destroy_world(w);
}

void stress_tiny_boxes(stress_result* out) { run_sized_pyramid(out, 0.0125f); }
void stress_large_boxes(stress_result* out) { run_sized_pyramid(out, 25.0f); }
