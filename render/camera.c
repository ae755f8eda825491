#include "camera.h"

static float aspect(int width, int height) { return (float)width / (float)height; }

tbr_camera tbr_camera_fit(tb_aabb box, float margin, int width, int height) {
  float w = box.upper.x - box.lower.x, h = box.upper.y - box.lower.y;
  float half_h = 0.5f * h, half_w = 0.5f * w;
  /* the half height that shows the whole width at this aspect */
  float needed = half_w / aspect(width, height);
  float half = needed > half_h ? needed : half_h;
  tbr_camera c = {{0.5f * (box.lower.x + box.upper.x), 0.5f * (box.lower.y + box.upper.y)},
                  half * (1.0f + 2.0f * margin),
                  width,
                  height};
  if (!(c.half_height > 0.0f)) c.half_height = 1.0f; /* an empty box: one metre up and down */
  return c;
}

static float clamp_axis(float centre, float half, float lo, float hi) {
  if (hi - lo <= 2.0f * half) return 0.5f * (lo + hi); /* the view is wider than the bounds */
  if (centre - half < lo) return lo + half;
  if (centre + half > hi) return hi - half;
  return centre;
}

tbr_camera tbr_camera_follow(tb_vec2 target, float view_width, tb_aabb bounds, int width, int height) {
  float half_w = 0.5f * view_width, half_h = half_w / aspect(width, height);
  tb_vec2 c = {clamp_axis(target.x, half_w, bounds.lower.x, bounds.upper.x),
               clamp_axis(target.y, half_h, bounds.lower.y, bounds.upper.y)};
  return (tbr_camera){c, half_h, width, height};
}

float tbr_camera_pixels_per_metre(const tbr_camera* camera) {
  return 0.5f * (float)camera->height / camera->half_height;
}

tb_aabb tbr_camera_view(const tbr_camera* camera) {
  float half_w = camera->half_height * aspect(camera->width, camera->height);
  return (tb_aabb){{camera->center.x - half_w, camera->center.y - camera->half_height},
                   {camera->center.x + half_w, camera->center.y + camera->half_height}};
}

tb_vec2 tbr_camera_to_pixel(const tbr_camera* camera, tb_vec2 world) {
  float ppm = tbr_camera_pixels_per_metre(camera);
  return (tb_vec2){0.5f * (float)camera->width + (world.x - camera->center.x) * ppm,
                   0.5f * (float)camera->height - (world.y - camera->center.y) * ppm};
}

tbr_camera tbr_camera_fit_below(tb_aabb box, float margin, int width, int height, int top) {
  if (top > height / 2) top = height / 2;
  if (top <= 0) return tbr_camera_fit(box, margin, width, height);
  tbr_camera c = tbr_camera_fit(box, margin, width, height - top);
  float metres_per_pixel = 2.0f * c.half_height / (float)(height - top);
  c.center.y += 0.5f * (float)top * metres_per_pixel; /* the box's centre moves down by half the band */
  c.half_height = 0.5f * (float)height * metres_per_pixel;
  c.height = height;
  return c;
}
