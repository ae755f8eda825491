/* PNG files from RGBA images, with libpng. */
#ifndef TBR_PNG_WRITE_H
#define TBR_PNG_WRITE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Writes width * height RGBA pixels (rows from the top) as an 8-bit RGB PNG
 * (alpha dropped: the images are opaque). false on failure, with the reason
 * in error. */
bool tbr_write_png(const char* path, const uint8_t* rgba, int width, int height, char* error, size_t error_size);

#endif
