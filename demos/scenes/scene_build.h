/* Helpers shared by the catalogue's builders (scenes.c and gallery.c): short
 * ways to place a body and attach the usual shapes. Private to demos/scenes/.
 * Unless a builder says otherwise: density 1 kg/m^2, friction 0.6, restitution
 * 0 (tb_default_shape_def()). Each helper ignores a failed make (the sizes are
 * constants of the scenes, so a failure would be a bug caught by the tests'
 * body counts and bounds). */
#ifndef TUMBLE_SCENE_BUILD_H
#define TUMBLE_SCENE_BUILD_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "tumble.h"

#define PI_F 3.14159265358979f

/* full * scale rounded, at least minimum; a scale outside (0, 1] is taken as 1. */
static inline int scaled(int full, float scale, int minimum) {
  if (!(scale > 0.0f && scale <= 1.0f)) scale = 1.0f;
  int n = (int)lroundf((float)full * scale);
  return n < minimum ? minimum : n;
}

static inline tb_body_id body_at(tb_world_id world, tb_body_type type, float x, float y, float angle, const char* tag) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = (tb_vec2){x, y};
  bd.angle = angle;
  bd.user_data = (void*)tag;
  return tb_create_body(world, &bd);
}

static inline tb_shape_def shape_def(float density, float friction, float restitution) {
  tb_shape_def sd = tb_default_shape_def();
  sd.density = density;
  sd.friction = friction;
  sd.restitution = restitution;
  return sd;
}

static inline tb_shape_id add_box(tb_body_id body, const tb_shape_def* sd, float hx, float hy) {
  tb_polygon box;
  if (tb_make_box(hx, hy, &box) != TB_OK) return (tb_shape_id){0};
  return tb_create_polygon_shape(body, sd, &box);
}

static inline tb_shape_id add_offset_box(tb_body_id body, const tb_shape_def* sd, float hx, float hy, float cx,
                                         float cy, float angle) {
  tb_polygon box;
  if (tb_make_offset_box(hx, hy, (tb_vec2){cx, cy}, angle, &box) != TB_OK) return (tb_shape_id){0};
  return tb_create_polygon_shape(body, sd, &box);
}

static inline tb_shape_id add_circle(tb_body_id body, const tb_shape_def* sd, float radius) {
  tb_circle c = {{0.0f, 0.0f}, radius};
  return tb_create_circle_shape(body, sd, &c);
}

/* A capsule along the body's local x axis (-half_length .. half_length). */
static inline tb_shape_id add_capsule_x(tb_body_id body, const tb_shape_def* sd, float half_length, float radius) {
  tb_capsule c = {{-half_length, 0.0f}, {half_length, 0.0f}, radius};
  return tb_create_capsule_shape(body, sd, &c);
}

/* A capsule along the body's local y axis. */
static inline tb_shape_id add_capsule_y(tb_body_id body, const tb_shape_def* sd, float half_length, float radius) {
  tb_capsule c = {{0.0f, -half_length}, {0.0f, half_length}, radius};
  return tb_create_capsule_shape(body, sd, &c);
}

/* A static ground: the box [-hx, hx] x [-2 hy, 0] (its top surface at y = 0). */
static inline tb_body_id ground(tb_world_id world, float hx, float hy) {
  tb_body_id g = body_at(world, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f, NULL);
  tb_shape_def sd = tb_default_shape_def();
  add_offset_box(g, &sd, hx, hy, 0.0f, -hy, 0.0f);
  return g;
}

/* A pyramid of base boxes of half-size h, its base centred at (cx, y0): row i
 * (from the bottom) holds base - i boxes at height (2 i + 1) h. The top box is
 * tagged. */
static inline void pyramid(tb_world_id world, int base, float h, float cx, float y0, const char* top_tag) {
  tb_shape_def sd = tb_default_shape_def(); /* density 1, friction 0.6 */
  tb_polygon box;
  if (tb_make_box(h, h, &box) != TB_OK) return;
  for (int i = 0; i < base; ++i) {
    float y = y0 + (float)(2 * i + 1) * h;
    for (int j = i; j < base; ++j) {
      float x = cx + (float)(2 * (j - i) + i + 1 - base) * h;
      tb_body_id b = body_at(world, TB_DYNAMIC_BODY, x, y, 0.0f, i == base - 1 ? top_tag : NULL);
      tb_create_polygon_shape(b, &sd, &box);
    }
  }
}

/* xorshift32 mapped to [lo, hi) through a double (the arithmetic of the rain
 * scene, tools/bench_tree.c and tools/bench_dynamics_b2.cpp). */
static inline float scene_rnd(uint32_t* state, float lo, float hi) {
  uint32_t x = *state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return lo + (hi - lo) * (float)((double)x / 4294967296.0);
}

#endif /* TUMBLE_SCENE_BUILD_H */
