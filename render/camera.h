/* A 2D camera for the renderers: which rectangle of the world fills the image.
 * Pixel coordinates have their origin at the top-left corner, y down. */
#ifndef TBR_CAMERA_H
#define TBR_CAMERA_H

#include "tumble.h"

typedef struct tbr_camera {
  tb_vec2 center;    /* world point at the centre of the image */
  float half_height; /* metres from the centre to the top edge */
  int width, height; /* image size in pixels */
} tbr_camera;

/* The whole box in view, centred, with margin (a fraction of its size, e.g.
 * 0.04) on the tighter side; the other side shows more to keep the aspect. */
tbr_camera tbr_camera_fit(tb_aabb box, float margin, int width, int height);
/* The same fit into the part of the image below its top rows (e.g. under a
 * caption panel); the camera still covers the whole image. top is clamped
 * to half the height. */
tbr_camera tbr_camera_fit_below(tb_aabb box, float margin, int width, int height, int top);
/* Centred on target with view_width metres across, but kept inside bounds
 * along each axis where the view is smaller than bounds (no empty space
 * beyond the scene's edge). */
tbr_camera tbr_camera_follow(tb_vec2 target, float view_width, tb_aabb bounds, int width, int height);
float tbr_camera_pixels_per_metre(const tbr_camera* camera);
/* The world rectangle the image shows. */
tb_aabb tbr_camera_view(const tbr_camera* camera);
/* World point to pixel coordinates (x right, y down, pixel centres at +0.5). */
tb_vec2 tbr_camera_to_pixel(const tbr_camera* camera, tb_vec2 world);

#endif
