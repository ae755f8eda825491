#include "cli_args.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

bool demo_parse_int(const char* text, int lo, int hi, int* out) {
  if (text == NULL || *text == '\0') return false;
  char* end = NULL;
  errno = 0;
  long v = strtol(text, &end, 10);
  if (errno != 0 || *end != '\0' || v < lo || v > hi) return false;
  *out = (int)v;
  return true;
}

bool demo_parse_size(const char* text, int lo, int hi, int* w, int* h) {
  if (text == NULL) return false;
  const char* x = strchr(text, 'x');
  if (x == NULL || x - text >= 16) return false;
  char first[16];
  memcpy(first, text, (size_t)(x - text));
  first[x - text] = '\0';
  return demo_parse_int(first, lo, hi, w) && demo_parse_int(x + 1, lo, hi, h);
}
