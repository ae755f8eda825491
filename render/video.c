#define _POSIX_C_SOURCE 200809L /* fork, execvp, waitpid, access, mkdtemp */
#include "video.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "error.h"

bool tbr_ffmpeg_available(void) {
  const char* path = getenv("PATH");
  if (path == NULL) return false;
  char candidate[4096];
  while (*path != '\0') {
    size_t n = strcspn(path, ":");
    if (n > 0 && n + sizeof "/ffmpeg" < sizeof candidate) {
      memcpy(candidate, path, n);
      memcpy(candidate + n, "/ffmpeg", sizeof "/ffmpeg");
      if (access(candidate, X_OK) == 0) return true;
    }
    path += n;
    if (*path == ':') ++path;
  }
  return false;
}

static bool ends_with(const char* s, const char* suffix) {
  size_t n = strlen(s), k = strlen(suffix);
  return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* Runs argv (no shell, so paths need no quoting); true when it exits with 0. */
static bool run(char* const argv[]) {
  fflush(stdout);
  pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    execvp(argv[0], argv);
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool tbr_encode_video(const char* pattern, double fps, const char* output, int gif_width, char* error,
                      size_t error_size) {
  if (!(fps > 0.0 && fps <= 1000.0)) {
    snprintf(error, error_size, "frame rate %g is outside (0, 1000]", fps);
    return false;
  }
  char rate[32], filter[256];
  snprintf(rate, sizeof rate, "%.6g", fps);
  if (ends_with(output, ".gif")) {
    /* one palette for the whole clip; Bayer dithering keeps flat colours flat */
    double gif_fps = fps < 30.0 ? fps : 30.0;
    snprintf(filter, sizeof filter,
             "fps=%.6g,scale=%d:-1:flags=lanczos,split[a][b];[a]palettegen=stats_mode=full[p];"
             "[b][p]paletteuse=dither=bayer:bayer_scale=3",
             gif_fps, gif_width > 0 ? gif_width : 480);
    char* const argv[] = {"ffmpeg",       "-y",  "-nostdin", "-loglevel", "error", "-framerate",  rate, "-i",
                          (char*)pattern, "-vf", filter,     "-loop",     "0",     (char*)output, NULL};
    if (run(argv)) return true;
  } else if (ends_with(output, ".mp4")) {
    /* even sizes: yuv420p halves the chroma resolution */
    char* const argv[] = {"ffmpeg",
                          "-y",
                          "-nostdin",
                          "-loglevel",
                          "error",
                          "-framerate",
                          rate,
                          "-i",
                          (char*)pattern,
                          "-vf",
                          "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                          "-pix_fmt",
                          "yuv420p",
                          "-movflags",
                          "+faststart",
                          (char*)output,
                          NULL};
    if (run(argv)) return true;
  } else {
    snprintf(error, error_size, "%s: the output must end in .mp4 or .gif", output);
    return false;
  }
  snprintf(error, error_size, "ffmpeg failed to make %s from %s", output, pattern);
  return false;
}

/* ---- tb_render_video (tumble_render.h) ------------------------------------------- */

struct tb_render_video {
  char dir[4096];    /* the frames' folder, made by mkdtemp */
  char output[4096]; /* the video file */
  double fps;
  int width, height;
  int frames;
};

tb_render_video* tb_render_video_open(const tb_renderer* renderer, const char* path, double fps) {
  static const char fn[] = "tb_render_video_open";
  if (renderer == NULL || path == NULL) {
    tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, renderer == NULL ? "renderer" : "path");
    return NULL;
  }
  if (!ends_with(path, ".mp4") && !ends_with(path, ".gif")) {
    tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: %s: the file name must end in .mp4 or .gif", fn, path);
    return NULL;
  }
  if (strlen(path) >= sizeof((tb_render_video*)NULL)->output) {
    tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: the path is too long", fn);
    return NULL;
  }
  if (!(fps > 0.0 && fps <= 1000.0)) {
    tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: fps %g is outside (0, 1000]", fn, fps);
    return NULL;
  }
  if (!tbr_ffmpeg_available()) {
    tbr_fail(TB_RENDER_ERR_NO_FFMPEG, "%s: no ffmpeg on PATH to encode %s (Debian: apt-get install ffmpeg)", fn, path);
    return NULL;
  }
  /* fail now rather than after the whole clip: can the file be written? */
  bool existed = access(path, F_OK) == 0;
  FILE* probe = fopen(path, existed ? "r+b" : "wb");
  if (probe == NULL) {
    tbr_fail(TB_RENDER_ERR_IO, "%s: cannot write %s: %s", fn, path, strerror(errno));
    return NULL;
  }
  fclose(probe);
  if (!existed) remove(path);
  tb_render_video* v = calloc(1, sizeof *v);
  if (v == NULL) {
    tbr_fail(TB_RENDER_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    return NULL;
  }
  const char* tmp = getenv("TMPDIR");
  snprintf(v->dir, sizeof v->dir, "%s/tumble_video_XXXXXX", tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp");
  if (mkdtemp(v->dir) == NULL) {
    tbr_fail(TB_RENDER_ERR_IO, "%s: cannot make a folder for the frames (%s): %s", fn, v->dir, strerror(errno));
    free(v);
    return NULL;
  }
  snprintf(v->output, sizeof v->output, "%s", path);
  v->fps = fps;
  tb_render_get_size(renderer, &v->width, &v->height);
  return v;
}

tb_render_result tb_render_video_add_frame(tb_render_video* video, const tb_renderer* renderer) {
  static const char fn[] = "tb_render_video_add_frame";
  if (video == NULL || renderer == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, video == NULL ? "video" : "renderer");
  int width, height;
  tb_render_get_size(renderer, &width, &height);
  if (width != video->width || height != video->height)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: the renderer is %dx%d, the video %dx%d", fn, width, height,
                    video->width, video->height);
  if (video->frames >= 9999999)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: a video holds at most 9,999,999 frames", fn);
  char path[4096 + 32];
  snprintf(path, sizeof path, "%s/frame_%07d.png", video->dir, video->frames);
  tb_render_result r = tb_render_write_png(renderer, path);
  if (r != TB_RENDER_OK) return r;
  video->frames += 1;
  return TB_RENDER_OK;
}

void tb_render_video_discard(tb_render_video* video) {
  if (video == NULL) return;
  char path[4096 + 32];
  for (int i = 0; i < video->frames; ++i) {
    snprintf(path, sizeof path, "%s/frame_%07d.png", video->dir, i);
    remove(path);
  }
  rmdir(video->dir);
  free(video);
}

tb_render_result tb_render_video_close(tb_render_video* video) {
  static const char fn[] = "tb_render_video_close";
  if (video == NULL) return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: video is NULL", fn);
  tb_render_result r = TB_RENDER_OK;
  if (video->frames == 0) {
    r = tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: %s has no frames", fn, video->output);
  } else {
    char pattern[4096 + 32], error[512];
    snprintf(pattern, sizeof pattern, "%s/frame_%%07d.png", video->dir);
    int gif_width = video->width < 640 ? video->width : 640;
    if (!tbr_encode_video(pattern, video->fps, video->output, gif_width, error, sizeof error))
      r = tbr_fail(TB_RENDER_ERR_ENCODE, "%s: %s", fn, error);
  }
  tb_render_video_discard(video);
  return r;
}
