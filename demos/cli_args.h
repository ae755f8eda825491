/* Command-line numbers shared by tumble-demo and tumble-viewer. */
#ifndef TUMBLE_DEMO_CLI_ARGS_H
#define TUMBLE_DEMO_CLI_ARGS_H

#include <stdbool.h>

/* A whole decimal number in [lo, hi], nothing else in text. */
bool demo_parse_int(const char* text, int lo, int hi, int* out);
/* "WxH" with each side a whole number in [lo, hi]. */
bool demo_parse_size(const char* text, int lo, int hi, int* w, int* h);

#endif
