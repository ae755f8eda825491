/* What the camera fits need to know about a renderer (renderer.c). */
#ifndef TBR_RENDERER_H
#define TBR_RENDERER_H

#include "tumble_render.h"

/* The picture's size and the caption panel's height in pixels (0 without a
 * caption). */
void tbr_renderer_layout(const tb_renderer* renderer, int* width, int* height, int* caption_height);

#endif
