/* MP4 and GIF from a numbered PNG sequence, by running ffmpeg when it is on
 * PATH (the `video` group of tools/deps.sh installs it). */
#ifndef TBR_VIDEO_H
#define TBR_VIDEO_H

#include <stdbool.h>
#include <stddef.h>

/* Whether an executable `ffmpeg` is in a directory of PATH. */
bool tbr_ffmpeg_available(void);
/* Encodes pattern (printf style, e.g. "out/pyramid/frame_%05d.png", numbered
 * from 0) at fps frames per second into output: an .mp4 (H.264 when ffmpeg has
 * it, yuv420p so that players accept it) or a .gif (own palette, gif_width
 * pixels wide, at most 30 frames per second). false on failure, with the
 * reason in error. */
bool tbr_encode_video(const char* pattern, double fps, const char* output, int gif_width, char* error,
                      size_t error_size);

#endif
