/* tb_renderer (tumble_render.h): an OSMesa target, the GL batcher and the
 * caption, put together. */
#include "renderer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "error.h"
#include "gl_draw.h"
#include "offscreen.h"
#include "png_write.h"

struct tb_renderer {
  tbr_offscreen* target;
  tbr_gl* gl;
  int width, height;
  char* caption[TB_RENDER_MAX_CAPTION_LINES];
  int caption_count;
  int caption_height;    /* pixels the caption panel covers from the top */
  const uint8_t* pixels; /* the last picture; NULL before the first */
};

tb_renderer* tb_render_create(int width, int height) {
  if (width < 1 || height < 1 || width > TB_RENDER_MAX_SIDE || height > TB_RENDER_MAX_SIDE ||
      (long long)width * height > TB_RENDER_MAX_PIXELS) {
    tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "tb_render_create: size %dx%d is outside 1 to %d a side and %d pixels",
             width, height, TB_RENDER_MAX_SIDE, TB_RENDER_MAX_PIXELS);
    return NULL;
  }
  tb_renderer* r = calloc(1, sizeof *r);
  if (r == NULL || (r->gl = tbr_gl_create()) == NULL) {
    free(r);
    tbr_fail(TB_RENDER_ERR_OUT_OF_MEMORY, "tb_render_create: out of memory");
    return NULL;
  }
  char error[256];
  r->target = tbr_offscreen_create(width, height, error, sizeof error);
  if (r->target == NULL) {
    tbr_gl_destroy(r->gl);
    free(r);
    tbr_fail(TB_RENDER_ERR_CONTEXT, "tb_render_create: %s", error);
    return NULL;
  }
  r->width = width;
  r->height = height;
  return r;
}

static void clear_caption(tb_renderer* r) {
  for (int i = 0; i < r->caption_count; ++i) free(r->caption[i]);
  r->caption_count = 0;
  r->caption_height = 0;
}

void tb_render_destroy(tb_renderer* renderer) {
  if (renderer == NULL) return;
  clear_caption(renderer);
  tbr_gl_destroy(renderer->gl);
  tbr_offscreen_destroy(renderer->target);
  free(renderer);
}

void tbr_renderer_layout(const tb_renderer* renderer, int* width, int* height, int* caption_height) {
  *width = renderer->width;
  *height = renderer->height;
  *caption_height = renderer->caption_height;
}

tb_render_result tb_render_set_caption(tb_renderer* renderer, const char* const* lines, int count) {
  static const char fn[] = "tb_render_set_caption";
  if (renderer == NULL) return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: renderer is NULL", fn);
  if (count < 0 || count > TB_RENDER_MAX_CAPTION_LINES)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: count %d is outside 0 to %d", fn, count,
                    TB_RENDER_MAX_CAPTION_LINES);
  if (count > 0 && lines == NULL) return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: lines is NULL", fn);
  for (int i = 0; i < count; ++i) {
    if (lines[i] == NULL) return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: lines[%d] is NULL", fn, i);
    if (strlen(lines[i]) > TB_RENDER_MAX_CAPTION_CHARS)
      return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: lines[%d] is longer than %d characters", fn, i,
                      TB_RENDER_MAX_CAPTION_CHARS);
  }
  char* copies[TB_RENDER_MAX_CAPTION_LINES];
  for (int i = 0; i < count; ++i) {
    size_t n = strlen(lines[i]) + 1;
    copies[i] = malloc(n);
    if (copies[i] == NULL) {
      while (i-- > 0) free(copies[i]);
      return tbr_fail(TB_RENDER_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    }
    memcpy(copies[i], lines[i], n);
  }
  clear_caption(renderer);
  for (int i = 0; i < count; ++i) renderer->caption[i] = copies[i];
  renderer->caption_count = count;
  renderer->caption_height =
      tbr_gl_overlay_height((const char* const*)renderer->caption, count, renderer->width, renderer->height);
  return TB_RENDER_OK;
}

tb_render_options tb_render_default_options(void) {
  tb_render_options o;
  memset(&o, 0, sizeof o);
  o.draw_shapes = true;
  o.draw_joints = true;
  o.background = TBR_BACKGROUND;
  o.colors = tb_default_debug_draw().colors;
  return o;
}

static bool unit_interval(float c) { return c >= 0.0f && c <= 1.0f; }

tb_render_result tb_render_world(tb_renderer* renderer, tb_world_id world, const tb_render_camera* camera,
                                 const tb_render_options* options) {
  static const char fn[] = "tb_render_world";
  if (renderer == NULL || camera == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, renderer == NULL ? "renderer" : "camera");
  if (!isfinite(camera->center.x) || !isfinite(camera->center.y) || fabsf(camera->center.x) > TB_MAX_LENGTH ||
      fabsf(camera->center.y) > TB_MAX_LENGTH)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: camera centre (%g, %g) is not finite or beyond TB_MAX_LENGTH",
                    fn, (double)camera->center.x, (double)camera->center.y);
  if (!(camera->half_height > 0.0f && camera->half_height <= TB_MAX_LENGTH))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: camera half_height %g is outside (0, TB_MAX_LENGTH]", fn,
                    (double)camera->half_height);
  tb_render_options o = options != NULL ? *options : tb_render_default_options();
  tb_color bg = o.background;
  if (!unit_interval(bg.r) || !unit_interval(bg.g) || !unit_interval(bg.b) || !unit_interval(bg.a))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: a background component is outside [0, 1]", fn);
  if (!tb_world_is_valid(world))
    return tbr_fail(TB_RENDER_ERR_STALE_HANDLE, "%s: the world is null or was destroyed", fn);
  tbr_camera view = {camera->center, camera->half_height, renderer->width, renderer->height};
  /* the whole view must stay within tumble's limits for the drawing bounds */
  tb_aabb seen = tbr_camera_view(&view);
  if (!(fabsf(seen.lower.x) <= TB_MAX_LENGTH && fabsf(seen.upper.x) <= TB_MAX_LENGTH &&
        fabsf(seen.lower.y) <= TB_MAX_LENGTH && fabsf(seen.upper.y) <= TB_MAX_LENGTH))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: the camera's view reaches beyond TB_MAX_LENGTH", fn);

  renderer->pixels = NULL;
  tbr_offscreen_begin(renderer->target);
  tbr_gl_begin(renderer->gl, &view, bg);
  tb_debug_draw draw = tbr_gl_debug_draw(renderer->gl);
  draw.draw_shapes = o.draw_shapes;
  draw.draw_joints = o.draw_joints;
  draw.draw_aabbs = o.draw_aabbs;
  draw.draw_contact_points = o.draw_contacts;
  draw.draw_contact_normals = o.draw_contacts;
  draw.draw_centers_of_mass = o.draw_centers_of_mass;
  draw.colors = o.colors;
  tb_result drawn = tb_world_draw(world, &draw);
  tbr_gl_overlay(renderer->gl, (const char* const*)renderer->caption, renderer->caption_count);
  bool complete = tbr_gl_flush(renderer->gl);
  const uint8_t* pixels = tbr_offscreen_finish(renderer->target);
  if (drawn != TB_OK) {
    return tbr_fail(drawn == TB_ERR_STALE_HANDLE       ? TB_RENDER_ERR_STALE_HANDLE
                    : drawn == TB_ERR_INVALID_ARGUMENT ? TB_RENDER_ERR_INVALID_ARGUMENT
                                                       : TB_RENDER_ERR_WORLD,
                    "%s: %s", fn, tb_last_error());
  }
  if (!complete) return tbr_fail(TB_RENDER_ERR_OUT_OF_MEMORY, "%s: out of memory, the picture is incomplete", fn);
  renderer->pixels = pixels;
  return TB_RENDER_OK;
}

const uint8_t* tb_render_pixels(const tb_renderer* renderer) { return renderer == NULL ? NULL : renderer->pixels; }

void tb_render_get_size(const tb_renderer* renderer, int* width, int* height) {
  if (width != NULL) *width = renderer == NULL ? 0 : renderer->width;
  if (height != NULL) *height = renderer == NULL ? 0 : renderer->height;
}

tb_render_result tb_render_write_png(const tb_renderer* renderer, const char* path) {
  static const char fn[] = "tb_render_write_png";
  if (renderer == NULL || path == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, renderer == NULL ? "renderer" : "path");
  if (path[0] == '\0') return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: path is empty", fn);
  if (renderer->pixels == NULL)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: nothing rendered yet (call tb_render_world first)", fn);
  char error[512];
  if (!tbr_write_png(path, renderer->pixels, renderer->width, renderer->height, error, sizeof error))
    return tbr_fail(TB_RENDER_ERR_IO, "%s: %s", fn, error);
  return TB_RENDER_OK;
}
