/* Prints the world hash of a busy scene after 1,000 steps. `make test` builds
 * this at -O0 and at -O3 and requires the same hash from both: tumble's
 * results must not depend on the optimiser (no FMA contraction, no
 * address-dependent order). */
#include <inttypes.h>
#include <stdio.h>

#include "tumble.h"

static tb_body_id dynamic_body(tb_world_id w, float x, float y) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){x, y};
  return tb_create_body(w, &bd);
}

int main(void) {
  tb_world_def wd = tb_default_world_def();
  tb_world_id w = tb_create_world(&wd);
  tb_body_def gd = tb_default_body_def();
  tb_body_id ground = tb_create_body(w, &gd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon floor;
  tb_make_offset_box(40.0f, 1.0f, (tb_vec2){0.0f, -1.0f}, 0.0f, &floor);
  tb_create_polygon_shape(ground, &sd, &floor);
  /* a pyramid of base 12 */
  tb_polygon box;
  tb_make_box(0.5f, 0.5f, &box);
  for (int row = 0; row < 12; ++row)
    for (int i = 0; i < 12 - row; ++i)
      tb_create_polygon_shape(dynamic_body(w, -10.0f + (float)i + 0.5f * (float)row, 0.5f + (float)row), &sd, &box);
  /* circles and capsules raining on it */
  unsigned seed = 12345u;
  for (int i = 0; i < 40; ++i) {
    seed = seed * 1664525u + 1013904223u;
    float x = -12.0f + (float)(seed >> 8) * (24.0f / 16777216.0f);
    tb_body_id b = dynamic_body(w, x, 15.0f + 0.7f * (float)i);
    if (i % 2 == 0) {
      tb_circle c = {{0.0f, 0.0f}, 0.3f};
      tb_create_circle_shape(b, &sd, &c);
    } else {
      tb_capsule c = {{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.2f};
      tb_create_capsule_shape(b, &sd, &c);
    }
  }
  /* a chain of 12 links hanging from the ground body */
  tb_body_id prev = ground;
  for (int i = 0; i < 12; ++i) {
    tb_body_id link = dynamic_body(w, 10.0f + 0.5f * (float)i + 0.25f, 12.0f);
    tb_capsule c = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.08f};
    tb_create_capsule_shape(link, &sd, &c);
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = prev;
    jd.body_b = link;
    jd.local_anchor_a = i == 0 ? (tb_vec2){10.0f, 12.0f} : (tb_vec2){0.25f, 0.0f};
    jd.local_anchor_b = (tb_vec2){-0.25f, 0.0f};
    tb_create_revolute_joint(w, &jd);
    prev = link;
  }
  /* a bullet */
  tb_body_id bullet = dynamic_body(w, -30.0f, 3.0f);
  tb_body_set_bullet(bullet, true);
  tb_circle bc = {{0.0f, 0.0f}, 0.1f};
  tb_create_circle_shape(bullet, &sd, &bc);
  tb_body_set_linear_velocity(bullet, (tb_vec2){200.0f, 0.0f});
  for (int i = 0; i < 1000; ++i) {
    if (tb_world_step(w, 1.0f / 60.0f, 4) != TB_OK) {
      fprintf(stderr, "step %d: %s\n", i, tb_last_error());
      return 1;
    }
  }
  printf("%016" PRIx64 "\n", tb_world_hash(w));
  tb_destroy_world(w);
  return 0;
}
