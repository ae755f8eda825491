/* A headless OpenGL target: an OSMesa context (software rendering, no display,
 * no GPU) with a multisampled framebuffer that is resolved into the OSMesa
 * buffer for anti-aliased images. */
#ifndef TBR_OFFSCREEN_H
#define TBR_OFFSCREEN_H

#include <stddef.h>
#include <stdint.h>

typedef struct tbr_offscreen tbr_offscreen;

/* width and height in 1 to 8192 pixels. Makes the context current. NULL on
 * failure, with the reason in error. */
tbr_offscreen* tbr_offscreen_create(int width, int height, char* error, size_t error_size);
void tbr_offscreen_destroy(tbr_offscreen* target);
/* Makes the context current and binds the multisampled framebuffer: draw the
 * frame after this (e.g. with gl_draw.h). */
void tbr_offscreen_begin(tbr_offscreen* target);
/* Resolves the samples and returns the image: width * height RGBA pixels, 8
 * bits each, rows from the top. Valid until the next begin or destroy. */
const uint8_t* tbr_offscreen_finish(tbr_offscreen* target);
/* Samples per pixel of the framebuffer (1 when multisampling is unavailable). */
int tbr_offscreen_samples(const tbr_offscreen* target);

#endif
