#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "test_util.h"

tb_world_id tbt_world(float gx, float gy) {
  tb_world_def def = tb_default_world_def();
  def.gravity = (tb_vec2){gx, gy};
  tb_world_id w = tb_create_world(&def);
  ck_assert(!tb_world_id_is_null(w));
  return w;
}

tb_body_id tbt_box_body(tb_world_id w, float x, float y, float hx, float hy) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){x, y};
  tb_body_id b = tb_create_body(w, &bd);
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(hx, hy, &box), TB_OK);
  tb_shape_def sd = tb_default_shape_def();
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(b, &sd, &box)));
  return b;
}

float tbt_rand(unsigned* state, float lo, float hi) {
  unsigned x = *state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return lo + (hi - lo) * (float)((double)x / 4294967296.0);
}

void tbt_report(const char* env, const char* fmt, ...) {
  const char* on = getenv(env);
  if (on == NULL || on[0] != '1') return;
  va_list args;
  va_start(args, fmt);
  vfprintf(stderr, fmt, args);
  va_end(args);
  fputc('\n', stderr);
}
