#define _POSIX_C_SOURCE 200809L /* fork, execvp, waitpid, access */
#include "video.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

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
