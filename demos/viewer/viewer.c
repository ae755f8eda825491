/* tumble-viewer: the scene catalogue (demos/scenes/) in an SDL2 window with an
 * OpenGL (compatibility) context, drawn through the debug draw by
 * render/gl_draw.c. Pick a scene, pause, single-step, drag bodies with
 * a mouse joint, zoom and pan, switch what the debug draw shows. Run with
 * --help for the options and keys. Prints what happens on stdout (one line per
 * action), which the smoke test (tools/viewer_smoke.sh) reads. */
#define SDL_MAIN_HANDLED
#include <SDL.h>
#include <SDL_opengl.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "render/camera.h"
#include "render/gl_draw.h"
#include "scenes/scenes.h"
#include "script.h"
#include "tumble.h"

#define STEP_HZ 60
#define SUBSTEPS 4
/* The follow camera shows at most this many metres across. */
#define FOLLOW_VIEW_WIDTH 40.0f
#define ZOOM_STEP 1.2f

/* The debug-draw switches, on keys 1 to 7. */
enum { SHOW_SHAPES, SHOW_JOINTS, SHOW_AABBS, SHOW_CONTACTS, SHOW_NORMALS, SHOW_COM, SHOW_MASSES, SHOW_COUNT };
static const char* const k_show_names[SHOW_COUNT] = {"shapes",  "joints", "aabbs", "contacts",
                                                     "normals", "com",    "masses"};

typedef struct options {
  const char* scene;
  float scale;
  int width, height;
  int frames; /* 0: until quit */
  bool script;
  const char* screenshot; /* NULL, or where the last of the --frames goes (PPM) */
} options;

typedef struct app {
  const tb_scene* scenes;
  int scene_count, scene_index;
  float scale;
  tb_world_id world;
  tb_body_id ground; /* a static body without shapes: the mouse joint's reference */
  tb_body_id followed;
  int step; /* steps taken since the scene was built */
  bool paused, quit;
  /* the view */
  tb_vec2 center;
  float half_height;
  bool follow;
  int width, height;    /* drawable size in pixels */
  float pixel_ratio;    /* drawable pixels per window coordinate */
  int mouse_x, mouse_y; /* last known mouse position, window coordinates */
  bool panning;
  /* dragging */
  tb_joint_id mouse_joint;
  tb_body_id dragged;
  tb_vec2 drag_start; /* the dragged body's centre of mass when grabbed */
  bool show[SHOW_COUNT];
  float step_ms, step_avg_ms;
} app;

static void usage(FILE* to) {
  fprintf(to,
          "usage: tumble-viewer [options]\n"
          "Shows scenes of the catalogue in a window (SDL2, OpenGL), stepped at %d Hz with %d substeps.\n"
          "\n"
          "  --list          print the scenes and exit\n"
          "  --scene NAME    the scene to start with (default: the first gallery scene)\n"
          "  --scale S       shrink the six performance scenes, 0 < S <= 1 (default 1)\n"
          "  --size WxH      window size (default 1280x720)\n"
          "  --frames N      quit after N frames (for tests)\n"
          "  --script        play a fixed sequence of input events (for tests)\n"
          "  --screenshot F  write the last of the --frames N to F (binary PPM)\n"
          "  --help          this text\n"
          "\n"
          "keys: space pause, s or right arrow single step (paused), n / p (or page down / up) next / previous\n"
          "      scene, r restart, c fit the camera, 1..7 shapes joints aabbs contacts normals centres masses,\n"
          "      Esc or q quit. Mouse: left drag a body, wheel zoom, right or middle drag pan.\n",
          STEP_HZ, SUBSTEPS);
}

static int bad_usage(const char* fmt, const char* arg) {
  fprintf(stderr, "tumble-viewer: ");
  fprintf(stderr, fmt, arg == NULL ? "(missing)" : arg);
  fprintf(stderr, "\n(try tumble-viewer --help)\n");
  return 2;
}

/* ---- the view ---------------------------------------------------------------------- */

static const tb_scene* scene(const app* a) { return &a->scenes[a->scene_index]; }

static float aspect(const app* a) { return (float)a->width / (float)a->height; }

/* The camera of this frame; a following view moves with its body. */
static tbr_camera camera(app* a) {
  if (a->follow && tb_body_is_valid(a->followed)) {
    tbr_camera c = tbr_camera_follow(tb_body_get_position(a->followed), 2.0f * a->half_height * aspect(a),
                                     scene(a)->bounds, a->width, a->height);
    a->center = c.center;
    return c;
  }
  return (tbr_camera){a->center, a->half_height, a->width, a->height};
}

/* Window coordinates to a world point. */
static tb_vec2 to_world(app* a, int x, int y) {
  tbr_camera c = camera(a);
  float ppm = tbr_camera_pixels_per_metre(&c);
  float px = ((float)x + 0.5f) * a->pixel_ratio, py = ((float)y + 0.5f) * a->pixel_ratio;
  return (tb_vec2){c.center.x + (px - 0.5f * (float)c.width) / ppm, c.center.y - (py - 0.5f * (float)c.height) / ppm};
}

/* The box of every shape, clipped to the scene's bounds. */
static tb_aabb content_box(tb_world_id world, tb_aabb bounds) {
  int n = tb_scene_collect_bodies(world, NULL, 0);
  tb_body_id* bodies = malloc(sizeof *bodies * (size_t)(n > 0 ? n : 1));
  if (bodies == NULL) return bounds;
  tb_aabb box = {{bounds.upper.x, bounds.upper.y}, {bounds.lower.x, bounds.lower.y}}; /* empty */
  n = tb_scene_collect_bodies(world, bodies, n);
  for (int i = 0; i < n; ++i) {
    tb_shape_id shapes[64];
    int count = tb_body_get_shapes(bodies[i], shapes, 64);
    for (int k = 0; k < count; ++k) {
      tb_aabb s = tb_shape_get_aabb(shapes[k]);
      box.lower.x = fminf(box.lower.x, s.lower.x);
      box.lower.y = fminf(box.lower.y, s.lower.y);
      box.upper.x = fmaxf(box.upper.x, s.upper.x);
      box.upper.y = fmaxf(box.upper.y, s.upper.y);
    }
  }
  free(bodies);
  box.lower.x = fmaxf(box.lower.x, bounds.lower.x);
  box.lower.y = fmaxf(box.lower.y, bounds.lower.y);
  box.upper.x = fminf(box.upper.x, bounds.upper.x);
  box.upper.y = fminf(box.upper.y, bounds.upper.y);
  return box.lower.x < box.upper.x && box.lower.y < box.upper.y ? box : bounds;
}

/* Follows the scene's tagged body, or fits what the scene holds now. */
static void fit_camera(app* a) {
  if (tb_body_is_valid(a->followed)) {
    float span = scene(a)->bounds.upper.x - scene(a)->bounds.lower.x;
    a->half_height = 0.5f * fminf(span, FOLLOW_VIEW_WIDTH) / aspect(a);
    a->follow = true;
    camera(a);
    return;
  }
  tb_aabb box = content_box(a->world, scene(a)->bounds);
  box.upper.y += 0.3f * (box.upper.y - box.lower.y); /* room for the overlay panel */
  tbr_camera c = tbr_camera_fit(box, 0.04f, a->width, a->height);
  a->center = c.center;
  a->half_height = c.half_height;
  a->follow = false;
}

static void zoom(app* a, int notches) {
  float f = powf(ZOOM_STEP, (float)-notches);
  float h = fminf(fmaxf(a->half_height * f, 0.05f), 1.0e5f);
  f = h / a->half_height;
  /* the world point under the mouse stays there */
  tb_vec2 p = to_world(a, a->mouse_x, a->mouse_y);
  if (!a->follow) a->center = (tb_vec2){p.x + (a->center.x - p.x) * f, p.y + (a->center.y - p.y) * f};
  a->half_height = h;
  tbr_camera c = camera(a);
  printf("zoom %s: %.1f pixels per metre\n", notches > 0 ? "in" : "out", (double)tbr_camera_pixels_per_metre(&c));
}

/* ---- the scene ---------------------------------------------------------------------- */

static void end_drag(app* a, bool report) {
  if (tb_joint_id_is_null(a->mouse_joint)) return;
  if (tb_joint_is_valid(a->mouse_joint)) tb_destroy_joint(a->mouse_joint);
  if (report && tb_body_is_valid(a->dragged)) {
    tb_vec2 p = tb_body_get_world_center(a->dragged);
    float dx = p.x - a->drag_start.x, dy = p.y - a->drag_start.y;
    printf("released body %d: moved by (%.3f, %.3f) m, %.3f m\n", (int)a->dragged.index1, (double)dx, (double)dy,
           (double)sqrtf(dx * dx + dy * dy));
  }
  a->mouse_joint = (tb_joint_id){0, 0, 0};
  a->dragged = (tb_body_id){0, 0, 0};
}

static bool load_scene(app* a, int index) {
  end_drag(a, false);
  a->panning = false;
  if (!tb_world_id_is_null(a->world)) tb_destroy_world(a->world);
  a->scene_index = (index % a->scene_count + a->scene_count) % a->scene_count;
  const tb_scene* s = scene(a);
  a->world = tb_scene_create_world(s);
  tb_world_enable_profile(a->world, true); /* the step time shown */
  if (tb_world_id_is_null(a->world)) {
    fprintf(stderr, "tumble-viewer: %s: %s\n", s->name, tb_last_error());
    return false;
  }
  s->build(a->world, a->scale);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_STATIC_BODY;
  a->ground = tb_create_body(a->world, &bd);
  a->followed = tb_scene_find_body(a->world, s->follow_tag);
  a->step = 0;
  a->step_ms = a->step_avg_ms = 0.0f;
  fit_camera(a);
  printf("scene %d/%d: %s: %s (%d bodies)\n", a->scene_index + 1, a->scene_count, s->name, s->description,
         tb_world_get_counts(a->world).body_count);
  return !tb_body_id_is_null(a->ground);
}

static bool step_world(app* a) {
  const tb_scene* s = scene(a);
  if (s->update != NULL) s->update(a->world, a->step);
  if (tb_world_step(a->world, 1.0f / STEP_HZ, SUBSTEPS) != TB_OK) {
    fprintf(stderr, "tumble-viewer: %s, step %d: %s\n", s->name, a->step, tb_last_error());
    a->paused = true;
    return false;
  }
  ++a->step;
  a->step_ms = tb_world_get_profile(a->world).step;
  a->step_avg_ms = a->step == 1 ? a->step_ms : 0.95f * a->step_avg_ms + 0.05f * a->step_ms;
  return true;
}

typedef struct pick {
  tb_body_id body;
} pick;

static bool pick_dynamic(tb_shape_id shape, void* context) {
  tb_body_id body = tb_shape_get_body(shape);
  if (tb_body_get_type(body) != TB_DYNAMIC_BODY) return true;
  ((pick*)context)->body = body;
  return false;
}

static void start_drag(app* a, int x, int y) {
  end_drag(a, true);
  tb_vec2 p = to_world(a, x, y);
  tb_query_filter filter = tb_default_query_filter();
  filter.skip_sensors = true;
  pick found = {{0, 0, 0}};
  tb_world_overlap_point(a->world, p, filter, pick_dynamic, &found);
  if (tb_body_id_is_null(found.body)) {
    printf("no dynamic body at (%.2f, %.2f)\n", (double)p.x, (double)p.y);
    return;
  }
  float mass = tb_body_get_mass(found.body);
  tb_mouse_joint_def def = tb_default_mouse_joint_def();
  def.body_a = a->ground;
  def.body_b = found.body;
  def.target = p;
  def.max_force = 1000.0f * mass;
  a->mouse_joint = tb_create_mouse_joint(a->world, &def);
  if (tb_joint_id_is_null(a->mouse_joint)) {
    fprintf(stderr, "tumble-viewer: %s\n", tb_last_error());
    return;
  }
  tb_body_set_awake(found.body, true);
  a->dragged = found.body;
  a->drag_start = tb_body_get_world_center(found.body);
  const char* tag = tb_body_get_user_data(found.body);
  printf("dragging body %d%s%s%s (%.3f kg) at (%.2f, %.2f)\n", (int)found.body.index1, tag ? " '" : "", tag ? tag : "",
         tag ? "'" : "", (double)mass, (double)p.x, (double)p.y);
}

/* The script's grab: the highest dynamic body's centre, in window coordinates. */
static bool grab_point(void* context, int* x, int* y) {
  app* a = context;
  int n = tb_scene_collect_bodies(a->world, NULL, 0);
  tb_body_id* bodies = malloc(sizeof *bodies * (size_t)(n > 0 ? n : 1));
  if (bodies == NULL) return false;
  n = tb_scene_collect_bodies(a->world, bodies, n);
  bool found = false;
  tb_vec2 best = {0.0f, 0.0f};
  for (int i = 0; i < n; ++i) {
    if (tb_body_get_type(bodies[i]) != TB_DYNAMIC_BODY) continue;
    tb_vec2 c = tb_body_get_world_center(bodies[i]);
    if (!found || c.y > best.y) best = c;
    found = true;
  }
  free(bodies);
  if (!found) return false;
  tbr_camera c = camera(a);
  tb_vec2 px = tbr_camera_to_pixel(&c, best);
  *x = (int)floorf(px.x / a->pixel_ratio);
  *y = (int)floorf(px.y / a->pixel_ratio);
  return true;
}

/* ---- input ---------------------------------------------------------------------------- */

static void on_key(app* a, SDL_Keycode key, bool repeat) {
  switch (key) {
    case SDLK_ESCAPE:
    case SDLK_q: a->quit = true; break;
    case SDLK_SPACE:
      if (repeat) break;
      a->paused = !a->paused;
      printf("%s at t = %.3f s\n", a->paused ? "paused" : "running", (double)tb_world_get_time(a->world));
      break;
    case SDLK_s:
    case SDLK_RIGHT:
      if (!a->paused) break;
      if (step_world(a))
        printf("step %d: t = %.3f s, step time %.3f ms\n", a->step, (double)tb_world_get_time(a->world),
               (double)a->step_ms);
      break;
    case SDLK_n:
    case SDLK_PAGEDOWN:
      if (!repeat) a->quit |= !load_scene(a, a->scene_index + 1);
      break;
    case SDLK_p:
    case SDLK_PAGEUP:
      if (!repeat) a->quit |= !load_scene(a, a->scene_index - 1);
      break;
    case SDLK_r:
      if (repeat) break;
      printf("restart %s\n", scene(a)->name);
      a->quit |= !load_scene(a, a->scene_index);
      break;
    case SDLK_c:
      fit_camera(a);
      printf("camera fitted: centre (%.2f, %.2f), %.2f m high\n", (double)a->center.x, (double)a->center.y,
             (double)(2.0f * a->half_height));
      break;
    default:
      if (key >= SDLK_1 && key < SDLK_1 + SHOW_COUNT && !repeat) {
        int k = (int)(key - SDLK_1);
        a->show[k] = !a->show[k];
        printf("%s %s\n", k_show_names[k], a->show[k] ? "on" : "off");
      }
      break;
  }
}

static void on_event(app* a, const SDL_Event* e) {
  switch (e->type) {
    case SDL_QUIT: a->quit = true; break;
    case SDL_KEYDOWN: on_key(a, e->key.keysym.sym, e->key.repeat != 0); break;
    case SDL_MOUSEBUTTONDOWN:
      a->mouse_x = e->button.x;
      a->mouse_y = e->button.y;
      if (e->button.button == SDL_BUTTON_LEFT) start_drag(a, e->button.x, e->button.y);
      if (e->button.button == SDL_BUTTON_RIGHT || e->button.button == SDL_BUTTON_MIDDLE) a->panning = true;
      break;
    case SDL_MOUSEBUTTONUP:
      if (e->button.button == SDL_BUTTON_LEFT) end_drag(a, true);
      if ((e->button.button == SDL_BUTTON_RIGHT || e->button.button == SDL_BUTTON_MIDDLE) && a->panning) {
        a->panning = false;
        printf("pan: centre (%.2f, %.2f)\n", (double)a->center.x, (double)a->center.y);
      }
      break;
    case SDL_MOUSEMOTION: {
      int dx = e->motion.x - a->mouse_x, dy = e->motion.y - a->mouse_y;
      a->mouse_x = e->motion.x;
      a->mouse_y = e->motion.y;
      if (a->panning && (dx != 0 || dy != 0)) {
        tbr_camera c = camera(a);
        float ppm = tbr_camera_pixels_per_metre(&c) / a->pixel_ratio;
        a->center = (tb_vec2){c.center.x - (float)dx / ppm, c.center.y + (float)dy / ppm};
        a->follow = false;
      }
      if (!tb_joint_id_is_null(a->mouse_joint) && tb_joint_is_valid(a->mouse_joint))
        tb_mouse_joint_set_target(a->mouse_joint, to_world(a, e->motion.x, e->motion.y));
      break;
    }
    case SDL_MOUSEWHEEL: {
      int notches = e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e->wheel.y : e->wheel.y;
      if (notches != 0) zoom(a, notches);
      break;
    }
    default: break;
  }
}

/* ---- drawing ------------------------------------------------------------------------ */

static void draw(app* a, tbr_gl* gl) {
  tbr_camera c = camera(a);
  tbr_gl_begin(gl, &c, TBR_BACKGROUND);
  tb_debug_draw d = tbr_gl_debug_draw(gl);
  d.draw_shapes = a->show[SHOW_SHAPES];
  d.draw_joints = a->show[SHOW_JOINTS];
  d.draw_aabbs = a->show[SHOW_AABBS];
  d.draw_contact_points = a->show[SHOW_CONTACTS];
  d.draw_contact_normals = a->show[SHOW_NORMALS];
  d.draw_centers_of_mass = a->show[SHOW_COM];
  d.draw_masses = a->show[SHOW_MASSES];
  if (tb_world_draw(a->world, &d) != TB_OK) fprintf(stderr, "tumble-viewer: %s\n", tb_last_error());

  char title[96], stats[160], shows[160], help1[128], help2[128];
  snprintf(title, sizeof title, "%s  (%d/%d)%s", scene(a)->name, a->scene_index + 1, a->scene_count,
           a->paused ? "  PAUSED" : "");
  tb_counts counts = tb_world_get_counts(a->world);
  snprintf(stats, sizeof stats, "t = %.2f s   step %.2f ms (avg %.2f)   %d bodies   %d awake",
           (double)tb_world_get_time(a->world), (double)a->step_ms, (double)a->step_avg_ms, counts.body_count,
           counts.awake_body_count);
  int n = 0;
  for (int k = 0; k < SHOW_COUNT; ++k)
    n += snprintf(shows + n, sizeof shows - (size_t)n, "%s%d %s %s", k ? "  " : "", k + 1, k_show_names[k],
                  a->show[k] ? "on" : "off");
  snprintf(help1, sizeof help1, "space pause  s step  n/p scene  r restart  c camera  esc quit");
  snprintf(help2, sizeof help2, "left drag body  wheel zoom  right drag pan");
  const char* lines[6] = {title, scene(a)->description, stats, shows, help1, help2};
  tbr_gl_overlay(gl, lines, 6);
  if (!tbr_gl_flush(gl)) fprintf(stderr, "tumble-viewer: out of memory, the frame is incomplete\n");
}

/* Reads the frame back from the back buffer, writes it as a binary PPM and
 * reports how many pixels differ from the background (a blank frame has 0). */
static bool screenshot(const app* a, const char* path) {
  size_t row = 3 * (size_t)a->width, size = row * (size_t)a->height;
  uint8_t* pixels = malloc(size);
  if (pixels == NULL) return false;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, a->width, a->height, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  const uint8_t bg[3] = {(uint8_t)lroundf(255.0f * TBR_BACKGROUND.r), (uint8_t)lroundf(255.0f * TBR_BACKGROUND.g),
                         (uint8_t)lroundf(255.0f * TBR_BACKGROUND.b)};
  long drawn = 0;
  for (size_t i = 0; i < size; i += 3) {
    for (int k = 0; k < 3; ++k) {
      if (abs((int)pixels[i + (size_t)k] - (int)bg[k]) > 2) {
        ++drawn;
        break;
      }
    }
  }
  FILE* f = fopen(path, "wb");
  bool ok = f != NULL && fprintf(f, "P6\n%d %d\n255\n", a->width, a->height) > 0;
  for (int y = a->height - 1; ok && y >= 0; --y)
    ok = fwrite(pixels + row * (size_t)y, 1, row, f) == row; /* top row first */
  if (f != NULL && fclose(f) != 0) ok = false;
  free(pixels);
  if (!ok) {
    fprintf(stderr, "tumble-viewer: cannot write %s: %s\n", path, strerror(errno));
    return false;
  }
  printf("screenshot %s: %dx%d, %ld pixels differ from the background\n", path, a->width, a->height, drawn);
  return true;
}

/* ---- main ---------------------------------------------------------------------------- */

static SDL_Window* open_window(const options* o, SDL_GLContext* context) {
  /* 4x multisampling when the driver has it, else without */
  for (int samples = 4; samples >= 0; samples -= 4) {
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_COMPATIBILITY);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, samples > 0);
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, samples);
    SDL_Window* w = SDL_CreateWindow("tumble viewer", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, o->width,
                                     o->height, SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (w == NULL) continue;
    *context = SDL_GL_CreateContext(w);
    if (*context != NULL) return w;
    SDL_DestroyWindow(w);
  }
  return NULL;
}

int main(int argc, char** argv) {
  options o = {NULL, 1.0f, 1280, 720, 0, false, NULL};
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(arg, "--list") == 0) {
      int count = 0;
      const tb_scene* scenes = tb_scenes(&count);
      for (int k = 0; k < count; ++k) printf("%-18s %s\n", scenes[k].name, scenes[k].description);
      return 0;
    } else if (strcmp(arg, "--scene") == 0) {
      if (v == NULL) return bad_usage("--scene needs a scene name %s", v);
      if (tb_scene_find(v) == NULL) return bad_usage("unknown scene '%s' (tumble-viewer --list shows them)", v);
      o.scene = v;
      ++i;
    } else if (strcmp(arg, "--frames") == 0) {
      if (!demo_parse_int(v, 1, 100000000, &o.frames))
        return bad_usage("--frames needs a whole number 1 to 100000000, not %s", v);
      ++i;
    } else if (strcmp(arg, "--size") == 0) {
      if (!demo_parse_size(v, 64, 8192, &o.width, &o.height))
        return bad_usage("--size needs WxH with each 64 to 8192 (e.g. 1280x720), not %s", v);
      ++i;
    } else if (strcmp(arg, "--scale") == 0) {
      char* end = NULL;
      float s = v == NULL ? 0.0f : strtof(v, &end);
      if (v == NULL || *end != '\0' || !(s > 0.0f && s <= 1.0f))
        return bad_usage("--scale needs a number in (0, 1], not %s", v);
      o.scale = s;
      ++i;
    } else if (strcmp(arg, "--screenshot") == 0) {
      if (v == NULL || *v == '\0') return bad_usage("--screenshot needs a file name %s", v);
      o.screenshot = v;
      ++i;
    } else if (strcmp(arg, "--script") == 0) {
      o.script = true;
    } else {
      return bad_usage("unknown option '%s'", arg);
    }
  }
  setvbuf(stdout, NULL, _IOLBF, 0); /* the smoke test reads the log as it comes */

  app a = {0};
  a.scenes = tb_scenes(&a.scene_count);
  a.scale = o.scale;
  a.scene_index = 0;
  for (int k = 0; k < a.scene_count; ++k) {
    if (o.scene != NULL ? strcmp(o.scene, a.scenes[k].name) == 0 : !tb_scene_is_performance(&a.scenes[k])) {
      a.scene_index = k;
      break;
    }
  }
  a.show[SHOW_SHAPES] = a.show[SHOW_JOINTS] = true;
  a.pixel_ratio = 1.0f;

  SDL_SetMainReady();
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    fprintf(stderr, "tumble-viewer: SDL_Init: %s\n", SDL_GetError());
    return 1;
  }
  SDL_GLContext context = NULL;
  SDL_Window* window = open_window(&o, &context);
  tbr_gl* gl = tbr_gl_create();
  if (window == NULL || gl == NULL) {
    fprintf(stderr, "tumble-viewer: %s\n", window == NULL ? SDL_GetError() : "out of memory");
    tbr_gl_destroy(gl);
    SDL_Quit();
    return 1;
  }
  bool vsync = SDL_GL_SetSwapInterval(1) == 0;
  SDL_GL_GetDrawableSize(window, &a.width, &a.height);
  int window_w = 0, window_h = 0;
  SDL_GetWindowSize(window, &window_w, &window_h);
  a.pixel_ratio = window_w > 0 ? (float)a.width / (float)window_w : 1.0f;
  printf("video driver %s, OpenGL %s (%s), %dx%d pixels%s\n", SDL_GetCurrentVideoDriver(),
         (const char*)glGetString(GL_VERSION), (const char*)glGetString(GL_RENDERER), a.width, a.height,
         vsync ? ", vsync" : "");

  int status = load_scene(&a, a.scene_index) ? 0 : 1;
  viewer_script script = {SDL_GetWindowID(window), window_w, window_h, grab_point, &a, 0, 0, false};
  int frame = 0;
  const uint64_t frequency = SDL_GetPerformanceFrequency();
  while (status == 0 && !a.quit && (o.frames == 0 || frame < o.frames)) {
    uint64_t start = SDL_GetPerformanceCounter();
    SDL_GL_GetDrawableSize(window, &a.width, &a.height);
    SDL_GetWindowSize(window, &window_w, &window_h);
    if (a.width < 1 || a.height < 1) a.width = a.height = 1;
    a.pixel_ratio = window_w > 0 ? (float)a.width / (float)window_w : 1.0f;
    script.width = window_w;
    script.height = window_h;
    if (o.script && !viewer_script_push(&script, frame)) status = 1;
    SDL_Event e;
    while (SDL_PollEvent(&e)) on_event(&a, &e);
    if (a.quit || status != 0) break;
    if (!a.paused) step_world(&a);
    draw(&a, gl);
    if (o.screenshot != NULL && frame + 1 == o.frames && !screenshot(&a, o.screenshot)) status = 1;
    SDL_GL_SwapWindow(window);
    ++frame;
    if (!vsync && !o.script) {
      /* about 60 frames a second without vsync */
      double spent = (double)(SDL_GetPerformanceCounter() - start) / (double)frequency;
      if (spent < 1.0 / STEP_HZ) SDL_Delay((uint32_t)((1.0 / STEP_HZ - spent) * 1000.0));
    }
  }
  if (!tb_world_id_is_null(a.world)) {
    printf("exit after %d frames: scene %s, t = %.3f s\n", frame, scene(&a)->name, (double)tb_world_get_time(a.world));
    end_drag(&a, false);
    tb_destroy_world(a.world);
  }
  tbr_gl_destroy(gl);
  SDL_GL_DeleteContext(context);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return status;
}
