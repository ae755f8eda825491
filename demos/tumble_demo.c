/* tumble-demo: renders the scene catalogue (demos/scenes/) headless with
 * OSMesa into PNG images, frame sequences and, with ffmpeg, MP4 and GIF.
 * Run with --help for the options. */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_args.h"
#include "scenes/scenes.h"
#include "tumble.h"
#include "tumble_render.h"

#define STEP_HZ 60
#define SUBSTEPS 4
/* The follow camera shows at most this many metres across: the car (4 m)
 * and a stretch of the road ahead and behind. */
#define FOLLOW_VIEW_WIDTH 12.0f
/* Room around what the camera fits, a fraction of its size. */
#define FIT_MARGIN 0.04f

typedef struct options {
  const char* scene; /* NULL: every scene of the catalogue */
  int frames;
  int every; /* steps per frame */
  int width, height;
  float scale;
  const char* out;
  bool video;
  bool overlay;
} options;

static void usage(FILE* to) {
  fprintf(to,
          "usage: tumble-demo [options]\n"
          "Steps scenes of the catalogue at %d Hz (%d substeps) and renders them headless (OSMesa).\n"
          "\n"
          "  --list          print the scenes with a one-line description and exit\n"
          "  --scene NAME    render only this scene (default: every scene, the gallery)\n"
          "  --frames N      frames to write per scene (default 1)\n"
          "  --every K       steps between frames; frame i shows the world after (i + 1) K steps\n"
          "                  (default 90, i.e. 1.5 s, for one frame; 1 for a sequence)\n"
          "  --size WxH      image size in pixels (default 1280x720)\n"
          "  --scale S       shrink the performance scenes, 0 < S <= 1 (default 1)\n"
          "  --out DIR       output folder (default out), created when missing\n"
          "  --video         also make DIR/NAME.mp4 and DIR/NAME.gif with ffmpeg (needs N >= 2)\n"
          "  --no-overlay    no scene name, simulated time and step time in the corner\n"
          "  --help          this text\n"
          "\n"
          "One frame goes to DIR/NAME.png; a sequence to DIR/NAME/frame_00000.png ...\n",
          STEP_HZ, SUBSTEPS);
}

static int bad_usage(const char* fmt, const char* arg) {
  fprintf(stderr, "tumble-demo: ");
  fprintf(stderr, fmt, arg == NULL ? "(missing)" : arg);
  fprintf(stderr, "\n(try tumble-demo --help)\n");
  return 2;
}

static void list_scenes(void) {
  int count = 0;
  const tb_scene* scenes = tb_scenes(&count);
  for (int i = 0; i < count; ++i) printf("%-18s %s\n", scenes[i].name, scenes[i].description);
}

/* mkdir -p */
static bool make_dirs(const char* path) {
  char buf[PATH_MAX];
  if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf) return false;
  for (char* p = buf + 1; *p != '\0'; ++p) {
    if (*p != '/') continue;
    *p = '\0';
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return false;
    *p = '/';
  }
  return mkdir(buf, 0777) == 0 || errno == EEXIST;
}

/* The box the bodies fill (tb_render_world_bounds: moving bodies and the
 * static shapes near them), clipped to the scene's bounds so that a body
 * flung far away does not shrink the rest; the bounds when nothing is left. */
static tb_aabb content_box(tb_world_id world, tb_aabb bounds) {
  tb_aabb box;
  if (tb_render_world_bounds(world, &box) != TB_RENDER_OK) return bounds;
  box.lower.x = fmaxf(box.lower.x, bounds.lower.x);
  box.lower.y = fmaxf(box.lower.y, bounds.lower.y);
  box.upper.x = fminf(box.upper.x, bounds.upper.x);
  box.upper.y = fminf(box.upper.y, bounds.upper.y);
  return box.lower.x < box.upper.x && box.lower.y < box.upper.y ? box : bounds;
}

/* The camera fits what the scene has shown so far (the union of the content
 * boxes of every frame: it zooms out as things spread, never in, so a video
 * does not wobble), or follows the scene's tagged body. */
static tb_render_result scene_camera(tb_renderer* r, const tb_scene* scene, tb_world_id world, tb_body_id followed,
                                     tb_aabb* seen, tb_render_camera* camera) {
  if (!tb_body_id_is_null(followed) && tb_body_is_valid(followed)) {
    float span = scene->bounds.upper.x - scene->bounds.lower.x;
    float view = span < FOLLOW_VIEW_WIDTH ? span : FOLLOW_VIEW_WIDTH;
    return tb_render_camera_follow(r, followed, view, &scene->bounds, camera);
  }
  tb_aabb box = content_box(world, scene->bounds);
  if (seen->lower.x <= seen->upper.x) {
    box.lower.x = fminf(box.lower.x, seen->lower.x);
    box.lower.y = fminf(box.lower.y, seen->lower.y);
    box.upper.x = fmaxf(box.upper.x, seen->upper.x);
    box.upper.y = fmaxf(box.upper.y, seen->upper.y);
  }
  *seen = box;
  return tb_render_camera_fit(r, box, FIT_MARGIN, camera); /* kept clear of the caption */
}

/* Scene name, description and the step's numbers in the top-left corner. */
static tb_render_result set_caption(tb_renderer* r, const options* o, const tb_scene* scene, tb_world_id world,
                                    double step_ms) {
  if (!o->overlay) return TB_RENDER_OK;
  char stats[160];
  tb_counts counts = tb_world_get_counts(world);
  snprintf(stats, sizeof stats, "t = %.2f s   step %.2f ms   %d bodies   %d awake", tb_world_get_time(world), step_ms,
           counts.body_count, counts.awake_body_count);
  /* The description gives the full-size scene; say when --scale shrank it,
   * so the caption and the body count below it agree. */
  char description[256];
  if (o->scale < 1.0f && tb_scene_is_performance(scene))
    snprintf(description, sizeof description, "%s, shrunk with --scale %.2g", scene->description, (double)o->scale);
  else
    snprintf(description, sizeof description, "%s", scene->description);
  const char* lines[3] = {scene->name, description, stats};
  return tb_render_set_caption(r, lines, 3);
}

static bool render_frame(tb_renderer* r, const options* o, const tb_scene* scene, tb_world_id world,
                         tb_body_id followed, tb_aabb* seen, double step_ms, const char* path) {
  tb_render_camera camera;
  if (set_caption(r, o, scene, world, step_ms) != TB_RENDER_OK ||
      scene_camera(r, scene, world, followed, seen, &camera) != TB_RENDER_OK ||
      tb_render_world(r, world, &camera, NULL) != TB_RENDER_OK || tb_render_write_png(r, path) != TB_RENDER_OK) {
    fprintf(stderr, "tumble-demo: %s\n", tb_render_last_error());
    return false;
  }
  return true;
}

/* The MP4 and the GIF of a sequence (--video); both NULL, with a note, when
 * ffmpeg is missing: the PNG frames are still written. */
enum { VIDEO_KINDS = 2 };
static bool open_videos(const tb_renderer* r, const char* dir, double fps, tb_render_video* videos[VIDEO_KINDS]) {
  static const char* const kinds[VIDEO_KINDS] = {"mp4", "gif"};
  for (int k = 0; k < VIDEO_KINDS; ++k) {
    char path[PATH_MAX + 8];
    snprintf(path, sizeof path, "%s.%s", dir, kinds[k]);
    videos[k] = tb_render_video_open(r, path, fps);
    if (videos[k] != NULL) continue;
    if (k == 1) tb_render_video_discard(videos[0]);
    videos[0] = videos[1] = NULL;
    if (tb_render_last_result() != TB_RENDER_ERR_NO_FFMPEG) {
      fprintf(stderr, "tumble-demo: %s\n", tb_render_last_error());
      return false;
    }
    fprintf(stderr,
            "tumble-demo: ffmpeg is not on PATH: no MP4 or GIF, the PNG frames are in %s "
            "(install it with tools/deps.sh video)\n",
            dir);
    return true;
  }
  return true;
}

static bool run_scene(tb_renderer* r, const options* o, const tb_scene* scene) {
  tb_world_id world = tb_scene_create_world(scene);
  tb_world_enable_profile(world, true); /* the step time printed on each frame */
  if (tb_world_id_is_null(world)) {
    fprintf(stderr, "tumble-demo: %s: %s\n", scene->name, tb_last_error());
    return false;
  }
  scene->build(world, o->scale);
  tb_body_id followed = tb_scene_find_body(world, scene->follow_tag);
  if (scene->follow_tag != NULL && tb_body_id_is_null(followed))
    fprintf(stderr, "tumble-demo: %s: no body tagged '%s' to follow; the camera fits the bodies\n", scene->name,
            scene->follow_tag);

  bool sequence = o->frames > 1;
  char dir[PATH_MAX], path[PATH_MAX + 32];
  snprintf(dir, sizeof dir, "%s/%s", o->out, scene->name);
  if (sequence && !make_dirs(dir)) {
    fprintf(stderr, "tumble-demo: cannot create %s: %s\n", dir, strerror(errno));
    tb_destroy_world(world);
    return false;
  }
  tb_render_video* videos[VIDEO_KINDS] = {NULL, NULL};
  bool ok = !(sequence && o->video) || open_videos(r, dir, (double)STEP_HZ / o->every, videos);
  int step = 0;
  tb_aabb seen = {{1.0f, 1.0f}, {-1.0f, -1.0f}}; /* nothing seen yet */
  for (int frame = 0; frame < o->frames && ok; ++frame) {
    double step_ms = 0.0;
    for (int k = 0; k < o->every; ++k, ++step) {
      if (scene->update != NULL) scene->update(world, step);
      if (tb_world_step(world, 1.0f / STEP_HZ, SUBSTEPS) != TB_OK) {
        fprintf(stderr, "tumble-demo: %s, step %d: %s\n", scene->name, step, tb_last_error());
        ok = false;
        break;
      }
      step_ms += tb_world_get_profile(world).step;
    }
    if (!ok) break;
    if (sequence) {
      snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frame);
    } else {
      snprintf(path, sizeof path, "%s.png", dir);
    }
    ok = render_frame(r, o, scene, world, followed, &seen, step_ms / o->every, path);
    for (int k = 0; k < VIDEO_KINDS && ok; ++k) {
      if (videos[k] == NULL) continue;
      if (tb_render_video_add_frame(videos[k], r) != TB_RENDER_OK) {
        fprintf(stderr, "tumble-demo: %s\n", tb_render_last_error());
        ok = false;
      }
    }
    if (ok && !sequence) printf("%s\n", path);
  }
  tb_destroy_world(world);
  if (ok && sequence) printf("%s/frame_00000.png ... frame_%05d.png (%d frames)\n", dir, o->frames - 1, o->frames);
  for (int k = 0; k < VIDEO_KINDS; ++k) {
    if (videos[k] == NULL) continue;
    if (!ok) {
      tb_render_video_discard(videos[k]);
    } else if (tb_render_video_close(videos[k]) != TB_RENDER_OK) {
      fprintf(stderr, "tumble-demo: %s\n", tb_render_last_error());
      ok = false;
    } else {
      printf("%s.%s\n", dir, k == 0 ? "mp4" : "gif");
    }
  }
  return ok;
}

int main(int argc, char** argv) {
  options o = {NULL, 1, 0, 1280, 720, 1.0f, "out", false, true};
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(a, "--list") == 0) {
      list_scenes();
      return 0;
    } else if (strcmp(a, "--scene") == 0) {
      if (v == NULL) return bad_usage("--scene needs a scene name %s", v);
      if (tb_scene_find(v) == NULL) return bad_usage("unknown scene '%s' (tumble-demo --list shows them)", v);
      o.scene = v;
      ++i;
    } else if (strcmp(a, "--frames") == 0) {
      if (!demo_parse_int(v, 1, 100000, &o.frames))
        return bad_usage("--frames needs a whole number 1 to 100000, not %s", v);
      ++i;
    } else if (strcmp(a, "--every") == 0) {
      if (!demo_parse_int(v, 1, 100000, &o.every))
        return bad_usage("--every needs a whole number 1 to 100000, not %s", v);
      ++i;
    } else if (strcmp(a, "--size") == 0) {
      if (!demo_parse_size(v, 16, 8192, &o.width, &o.height))
        return bad_usage("--size needs WxH with each 16 to 8192 (e.g. 1280x720), not %s", v);
      ++i;
    } else if (strcmp(a, "--scale") == 0) {
      char* end = NULL;
      float s = v == NULL ? 0.0f : strtof(v, &end);
      if (v == NULL || *end != '\0' || !(s > 0.0f && s <= 1.0f))
        return bad_usage("--scale needs a number in (0, 1], not %s", v);
      o.scale = s;
      ++i;
    } else if (strcmp(a, "--out") == 0) {
      if (v == NULL || *v == '\0') return bad_usage("--out needs a folder %s", v);
      o.out = v;
      ++i;
    } else if (strcmp(a, "--video") == 0) {
      o.video = true;
    } else if (strcmp(a, "--no-overlay") == 0) {
      o.overlay = false;
    } else {
      return bad_usage("unknown option '%s'", a);
    }
  }
  if (o.every == 0) o.every = o.frames > 1 ? 1 : 90;
  if (o.video && o.frames < 2) return bad_usage("%s", "--video needs --frames 2 or more");
  if (!make_dirs(o.out)) {
    fprintf(stderr, "tumble-demo: cannot create %s: %s\n", o.out, strerror(errno));
    return 1;
  }
  tb_renderer* r = tb_render_create(o.width, o.height);
  if (r == NULL) {
    fprintf(stderr, "tumble-demo: %s\n", tb_render_last_error());
    return 1;
  }
  int count = 0;
  const tb_scene* scenes = tb_scenes(&count);
  int failed = 0;
  for (int i = 0; i < count; ++i) {
    if (o.scene != NULL && strcmp(o.scene, scenes[i].name) != 0) continue;
    failed += !run_scene(r, &o, &scenes[i]);
  }
  tb_render_destroy(r);
  return failed == 0 ? 0 : 1;
}
