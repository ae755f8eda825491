/* Fast motion: bullets at 500 m/s against thin static walls, and a body
 * spinning at 50 rad/s. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

/* A closed square room of static walls 1 cm thick whose centre lines are at
 * x, y = +-10 m. 1,000 bullets (circles of radius 2.5 cm, density 10,
 * is_bullet, a shared negative group so they never hit each other) start at
 * random points inside (|x|, |y| <= 9 m) with random directions at 500 m/s:
 * 8.3 m per step, 830 times the wall thickness. Created in this order: the
 * room, then the bullets. */
#define ROOM_HALF 10.0f
#define WALL_HALF_T 0.005f
#define BULLET_SPEED 500.0f
#define BULLET_COUNT 1000
#define BULLET_SEED 20240607u

tb_world_id stress_new_bullets(void) {
  tb_world_id w = stress_world(true);
  unsigned seed = BULLET_SEED;
  tb_body_def rd = tb_default_body_def();
  tb_body_id room = tb_create_body(w, &rd);
  tb_shape_def wd = tb_default_shape_def();
  tb_polygon wall;
  const float L = ROOM_HALF + WALL_HALF_T;
  tb_make_offset_box(L, WALL_HALF_T, (tb_vec2){0.0f, -ROOM_HALF}, 0.0f, &wall);
  tb_create_polygon_shape(room, &wd, &wall);
  tb_make_offset_box(L, WALL_HALF_T, (tb_vec2){0.0f, ROOM_HALF}, 0.0f, &wall);
  tb_create_polygon_shape(room, &wd, &wall);
  tb_make_offset_box(WALL_HALF_T, L, (tb_vec2){-ROOM_HALF, 0.0f}, 0.0f, &wall);
  tb_create_polygon_shape(room, &wd, &wall);
  tb_make_offset_box(WALL_HALF_T, L, (tb_vec2){ROOM_HALF, 0.0f}, 0.0f, &wall);
  tb_create_polygon_shape(room, &wd, &wall);

  tb_shape_def bsd = tb_default_shape_def();
  bsd.density = 10.0f;
  bsd.filter.group_index = -1;
  tb_circle c = {{0.0f, 0.0f}, 0.025f};
  for (int i = 0; i < BULLET_COUNT; ++i) {
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.is_bullet = true;
    bd.position = (tb_vec2){stress_uniform(&seed, -9.0f, 9.0f), stress_uniform(&seed, -9.0f, 9.0f)};
    float a = stress_uniform(&seed, -3.14159265f, 3.14159265f);
    bd.linear_velocity = (tb_vec2){BULLET_SPEED * cosf(a), BULLET_SPEED * sinf(a)};
    tb_body_id b = tb_create_body(w, &bd);
    tb_create_circle_shape(b, &bsd, &c);
  }
  return w;
}

/* 2 s (120 steps): every bullet hits a wall in its first or second step and
 * then rattles along the walls into the corners. A bullet whose centre is ever
 * past a wall's centre line has tunnelled: zero allowed. */
void stress_bullets(stress_result* out) {
  tb_world_id w = stress_new_bullets();
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n); /* the room first */
  bool* escaped = calloc((size_t)n, sizeof *escaped);
  int tunnelled = 0;
  bool finite = escaped != NULL;
  for (int step = 0; step < 120 && finite; ++step) {
    finite = stress_step(w) && stress_all_finite(b, n);
    for (int i = 1; i < n; ++i) {
      tb_vec2 p = tb_body_get_position(b[i]);
      if (!escaped[i] && (fabsf(p.x) > ROOM_HALF || fabsf(p.y) > ROOM_HALF)) {
        escaped[i] = true;
        tunnelled += 1;
      }
    }
  }
  out->pass = finite && n == BULLET_COUNT + 1 && tunnelled == 0;
  stress_note(out, "%d of %d shots tunnelled%s", tunnelled, n - 1, finite ? "" : ", NOT FINITE");
  free(escaped);
  free(b);
  tb_destroy_world(w);
}

/* A 2 x 0.2 m plank (density 1, friction 0.6) spinning at 50 rad/s: its tips
 * move at 50 m/s, 0.83 m per step, and it turns 48 deg per step.
 * - In free fall (no torque) the angular velocity must stay 50 rad/s: in 2D
 *   there is no gyroscopic term, so any change is integration error; 10 s,
 *   bound 1e-4 relative (rounding of 2,400 substeps).
 * - Dropped from 2 m onto the ground while spinning: contacts and friction can
 *   only take energy out, so its total energy may never exceed the start's by
 *   more than 1 % (the symplectic step's energy error on a bounce), 10 s. */
tb_world_id stress_new_spinner(tb_body_id* free_plank, tb_body_id* dropped) {
  tb_world_id w = stress_world(false);
  tb_body_id f = stress_box(w, (tb_vec2){100.0f, 1000.0f}, 0.0f, 1.0f, 0.1f, NULL);
  tb_body_set_angular_velocity(f, 50.0f);
  stress_ground(w, 0.0f, 0.0f, 200.0f);
  tb_body_id d = stress_box(w, (tb_vec2){0.0f, 2.0f}, 0.0f, 1.0f, 0.1f, NULL);
  tb_body_set_angular_velocity(d, 50.0f);
  if (free_plank != NULL) *free_plank = f;
  if (dropped != NULL) *dropped = d;
  return w;
}

void stress_spinner(stress_result* out) {
  tb_body_id free_plank, dropped;
  tb_world_id w = stress_new_spinner(&free_plank, &dropped);
  double e0 = stress_energy(&dropped, 1), e_max = e0;
  bool finite = true;
  for (int i = 0; i < 600 && finite; ++i) {
    finite = stress_step(w) && stress_all_finite(&dropped, 1) && stress_all_finite(&free_plank, 1);
    e_max = fmax(e_max, stress_energy(&dropped, 1));
  }
  double w_err = fabs(tb_body_get_angular_velocity(free_plank) - 50.0) / 50.0;
  double e_gain = (e_max - e0) / e0;
  out->pass = finite && w_err < 1e-4 && e_gain < 0.01;
  stress_note(out, "free spin: |dw|/w = %.2g; dropped: peak energy %+.2g %% of the start's, ends at %.3g rad/s%s",
              w_err, 100.0 * e_gain, tb_body_get_angular_velocity(dropped), finite ? "" : ", NOT FINITE");
  tb_destroy_world(w);
}
