/* tumble_render: headless pictures of tumble worlds.
 *
 * A second library (libtumble-render, pkg-config tumble-render) beside the
 * engine: it draws a world through the engine's debug draw (tb_world_draw)
 * with software OpenGL (OSMesa: no display, no GPU), 4x anti-aliased, and
 * writes PNG files (libpng) or MP4 and GIF videos (by running ffmpeg when it
 * is on PATH). The engine itself depends on none of this.
 *
 *   tb_renderer* r = tb_render_create(640, 360);
 *   tb_render_camera camera;
 *   tb_render_camera_fit_world(r, world, 0.1f, &camera);
 *   tb_render_world(r, world, &camera, NULL);        // NULL: default options
 *   tb_render_write_png(r, "world.png");
 *   tb_render_destroy(r);
 *
 * Errors: every function checks what it is given (NULL, sizes, NaN or
 * infinite numbers, destroyed worlds and bodies, paths that cannot be
 * written). A rejected call returns an error code (creators return NULL),
 * changes nothing and leaves a message naming the function and the argument
 * in tb_render_last_error(). The engine's own tb_last_error() is not touched
 * except by the engine calls made on your behalf.
 *
 * Not thread-safe: use one renderer from one thread at a time. Renderers are
 * independent: several may exist at once.
 */
#ifndef TUMBLE_RENDER_H
#define TUMBLE_RENDER_H

#include "tumble.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tb_render_result {
  TB_RENDER_OK = 0,
  TB_RENDER_ERR_NULL_ARGUMENT,    /* a required pointer was NULL */
  TB_RENDER_ERR_INVALID_ARGUMENT, /* NaN, infinite or out-of-range value, bad file name, nothing rendered yet */
  TB_RENDER_ERR_STALE_HANDLE,     /* the world or body was destroyed (or the handle is garbage) */
  TB_RENDER_ERR_OUT_OF_MEMORY,
  TB_RENDER_ERR_CONTEXT,   /* OSMesa could not make an OpenGL context */
  TB_RENDER_ERR_WORLD,     /* tb_world_draw refused (e.g. called from a step callback); the message says why */
  TB_RENDER_ERR_IO,        /* a file or folder could not be written */
  TB_RENDER_ERR_NO_FFMPEG, /* no executable ffmpeg on PATH (Debian: apt-get install ffmpeg) */
  TB_RENDER_ERR_ENCODE     /* ffmpeg ran and failed */
} tb_render_result;

/* The short name of a result code, e.g. "TB_RENDER_ERR_IO". */
const char* tb_render_result_name(tb_render_result r);
/* The message of the last rejected call on this thread ("" when none). */
const char* tb_render_last_error(void);
tb_render_result tb_render_last_result(void);

/* ---------------------------------------------------------------- renderer -- */

/* Largest picture side and area (8K UHD) a renderer takes. */
#define TB_RENDER_MAX_SIDE 8192
#define TB_RENDER_MAX_PIXELS (7680 * 4320)

typedef struct tb_renderer tb_renderer;

/* An off-screen picture of width x height pixels (each 1 to
 * TB_RENDER_MAX_SIDE, area at most TB_RENDER_MAX_PIXELS). NULL on error. */
tb_renderer* tb_render_create(int width, int height);
/* NULL is fine. */
void tb_render_destroy(tb_renderer* renderer);

/* Text drawn on every later picture in a panel at the top-left corner: the
 * first line large (a title), the others smaller, each wrapped at spaces to the
 * picture's width. Copies the text. count 0 to TB_RENDER_MAX_CAPTION_LINES
 * (0 removes the caption), each line at most TB_RENDER_MAX_CAPTION_CHARS
 * characters; characters outside printable ASCII show as '?'. The camera
 * fits (below) keep what they frame out from under the panel. */
#define TB_RENDER_MAX_CAPTION_LINES 8
#define TB_RENDER_MAX_CAPTION_CHARS 512
tb_render_result tb_render_set_caption(tb_renderer* renderer, const char* const* lines, int count);

/* ------------------------------------------------------------------ camera -- */

/* Which part of the world fills the picture: center is the world point at the
 * picture's centre, half_height the metres from it to the top edge (the zoom;
 * the width follows from the picture's aspect). Set both for an explicit view
 * (finite, 0 < half_height <= TB_MAX_LENGTH), or let a function below fill it. */
typedef struct tb_render_camera {
  tb_vec2 center;
  float half_height;
} tb_render_camera;

/* The whole of bounds in view, centred below the caption, with margin (a
 * fraction of the bounds' size, 0 to 10; e.g. 0.05) around it on the tighter
 * side. A bounds of zero size gets a 2 m view. */
tb_render_result tb_render_camera_fit(const tb_renderer* renderer, tb_aabb bounds, float margin, tb_render_camera* out);
/* tb_render_camera_fit to tb_render_world_bounds(world). */
tb_render_result tb_render_camera_fit_world(const tb_renderer* renderer, tb_world_id world, float margin,
                                            tb_render_camera* out);
/* Centred on the body's position with view_width metres across (finite, > 0,
 * at most TB_MAX_LENGTH); when bounds is not NULL, moved back inside it along
 * each axis the view is smaller than bounds, so the picture never shows what
 * lies beyond them. */
tb_render_result tb_render_camera_follow(const tb_renderer* renderer, tb_body_id body, float view_width,
                                         const tb_aabb* bounds, tb_render_camera* out);

/* The box the world's bodies fill: the bounding boxes of the shapes of every
 * dynamic and kinematic body, of every sensor and of those bodies' joint
 * anchors, and of the other static shapes only the parts that lie near them
 * (within a quarter of the box's larger side, at least 0.5 m), so that a
 * 200 m ground does not shrink a 2 m scene to a speck. A world with only
 * static shapes: all of them; one with no shape at all: a 20 m square around
 * the origin. Shapes of disabled bodies are not counted. */
tb_render_result tb_render_world_bounds(tb_world_id world, tb_aabb* out);

/* ----------------------------------------------------------------- drawing -- */

typedef struct tb_render_options {
  bool draw_shapes;          /* default true */
  bool draw_joints;          /* default true */
  bool draw_aabbs;           /* each shape's bounding box; default false */
  bool draw_contacts;        /* contact points and normals; default false */
  bool draw_centers_of_mass; /* a small frame at each moving body's centre of mass; default false */
  tb_color background;       /* default a dark blue-grey */
  /* The colour of each body state (static, kinematic, awake dynamic, asleep,
   * ...), joints, contacts: tb_default_debug_draw().colors by default. Shapes
   * are filled with a darker shade and outlined with the colour itself. */
  tb_debug_colors colors;
} tb_render_options;

tb_render_options tb_render_default_options(void);

/* Draws the world as the camera sees it into the renderer's picture, with
 * the caption on top. options NULL: tb_render_default_options(). Errors: NULL
 * renderer or camera, a camera that is not finite or has half_height <= 0 or
 * > TB_MAX_LENGTH, a colour component outside [0, 1], a null or destroyed
 * world (TB_RENDER_ERR_STALE_HANDLE), a call from inside the world's step or
 * callbacks (TB_RENDER_ERR_WORLD). On error the picture is undefined until
 * the next successful call. */
tb_render_result tb_render_world(tb_renderer* renderer, tb_world_id world, const tb_render_camera* camera,
                                 const tb_render_options* options);

/* The last picture: width * height pixels, RGBA 8 bits each, rows from the
 * top. NULL before the first successful tb_render_world. Valid until the next
 * tb_render_world or tb_render_destroy. */
const uint8_t* tb_render_pixels(const tb_renderer* renderer);
/* The picture's size; 0 and 0 for a NULL renderer. Either pointer may be NULL. */
void tb_render_get_size(const tb_renderer* renderer, int* width, int* height);

/* Writes the last picture as an 8-bit RGB PNG file (created or replaced). */
tb_render_result tb_render_write_png(const tb_renderer* renderer, const char* path);

/* ------------------------------------------------------------------- video -- */

/* A video made from a renderer's pictures by ffmpeg: open it, add the picture
 * after each tb_render_world, close it to encode. The frames wait as PNG
 * files in a fresh folder under $TMPDIR (or /tmp), removed by close. */
typedef struct tb_render_video tb_render_video;

/* path ends in .mp4 (H.264 when ffmpeg has it, yuv420p, sides padded to even)
 * or .gif (its own palette, at most 640 pixels wide and 30 frames per
 * second); fps in (0, 1000]. Checks at once that ffmpeg is on PATH
 * (TB_RENDER_ERR_NO_FFMPEG) and that path can be written (TB_RENDER_ERR_IO).
 * The video has the renderer's size. NULL on error. */
tb_render_video* tb_render_video_open(const tb_renderer* renderer, const char* path, double fps);
/* Adds the renderer's last picture (the renderer must have the video's size). */
tb_render_result tb_render_video_add_frame(tb_render_video* video, const tb_renderer* renderer);
/* Encodes the frames into the file (at least one frame), removes them and frees
 * the video, also on error. NULL is an error (TB_RENDER_ERR_NULL_ARGUMENT). */
tb_render_result tb_render_video_close(tb_render_video* video);
/* Frees the video without encoding (e.g. after an error); NULL is fine. */
void tb_render_video_discard(tb_render_video* video);

#ifdef __cplusplus
}
#endif

#endif /* TUMBLE_RENDER_H */
