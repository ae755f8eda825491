#include "png_write.h"

#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool tbr_write_png(const char* path, const uint8_t* rgba, int width, int height, char* error, size_t error_size) {
  FILE* file = fopen(path, "wb");
  if (file == NULL) {
    snprintf(error, error_size, "cannot write %s: %s", path, strerror(errno));
    return false;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png == NULL ? NULL : png_create_info_struct(png);
  uint8_t* row = malloc((size_t)width * 3u);
  /* volatile: read after longjmp from libpng's error handler */
  volatile bool ok = png != NULL && info != NULL && row != NULL;
  if (ok && setjmp(png_jmpbuf(png))) {
    ok = false;
  } else if (ok) {
    png_init_io(png, file);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) {
      const uint8_t* src = rgba + (size_t)y * (size_t)width * 4u;
      for (int x = 0; x < width; ++x) memcpy(row + 3 * x, src + 4 * x, 3);
      png_write_row(png, row);
    }
    png_write_end(png, NULL);
  }
  png_destroy_write_struct(&png, &info);
  free(row);
  if (fclose(file) != 0) ok = false;
  if (!ok) snprintf(error, error_size, "libpng could not write %s", path);
  return ok;
}
