/* Draws a tumble world with OpenGL through the debug-draw callbacks, into
 * whatever GL context and framebuffer are current: the OSMesa context of the
 * headless demos (offscreen.h) or a window's context in a viewer. Uses the
 * compatibility profile's client-side vertex arrays (OpenGL 1.1), so any
 * context that OSMesa, SDL2 or a desktop driver gives will do.
 *
 * Everything is batched as coloured triangles: shapes are filled with a darker
 * shade of their state colour and outlined with the colour itself (the outline
 * lies inside the shape, so a shape covers exactly its own area). Lines are
 * quads of a fixed pixel width, so they look the same at every zoom.
 *
 *   tbr_gl* gl = tbr_gl_create();
 *   tbr_gl_begin(gl, &camera, background);          // clears the framebuffer
 *   tb_debug_draw draw = tbr_gl_debug_draw(gl);     // switches as you like
 *   tb_world_draw(world, &draw);
 *   tbr_gl_text(gl, 10, 10, 2, "hello", colour);    // screen pixels
 *   tbr_gl_flush(gl);                               // issues the GL calls
 */
#ifndef TBR_GL_DRAW_H
#define TBR_GL_DRAW_H

#include "camera.h"
#include "tumble.h"

typedef struct tbr_gl tbr_gl;

/* The demos' background: a dark blue-grey. */
#define TBR_BACKGROUND ((tb_color){0.105f, 0.115f, 0.145f, 1.0f})

/* NULL when out of memory. */
tbr_gl* tbr_gl_create(void);
void tbr_gl_destroy(tbr_gl* gl);

/* Starts a frame: empties the batch, sets the camera (its width and height are
 * the viewport) and clears the current framebuffer to background. */
void tbr_gl_begin(tbr_gl* gl, const tbr_camera* camera, tb_color background);
/* tb_default_debug_draw() with this renderer's callbacks (context = gl), the
 * drawing bounds set to the camera's view, and sizes in pixels of the view. */
tb_debug_draw tbr_gl_debug_draw(tbr_gl* gl);

/* Screen-space drawing, in pixels from the top-left corner. */
void tbr_gl_rect(tbr_gl* gl, float x, float y, float width, float height, tb_color color);
/* Text with its top-left corner at (x, y); pixel is the size of one font pixel. */
void tbr_gl_text(tbr_gl* gl, float x, float y, float pixel, const char* text, tb_color color);

/* A panel in the top-left corner: the first line large (a title), the others
 * smaller; font pixels scale with the image height. Lines longer than the
 * image is wide are wrapped at spaces (or cut where a word alone is too long). */
void tbr_gl_overlay(tbr_gl* gl, const char* const* lines, int count);
/* The pixel rows from the top of a width x height image that the panel of
 * tbr_gl_overlay covers (0 when count is 0). */
int tbr_gl_overlay_height(const char* const* lines, int count, int width, int height);

/* Draws what was batched (world first, then screen) and empties the batch.
 * false when the batch ran out of memory and some of it was dropped. */
bool tbr_gl_flush(tbr_gl* gl);

/* The fill colour of a shape drawn in colour c (the outline is c itself). */
tb_color tbr_gl_fill_color(tb_color c);

#endif
