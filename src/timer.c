/* clock_gettime is POSIX, not C17: ask for it before any header. */
#define _POSIX_C_SOURCE 199309L
#include "timer.h"

#include <time.h>

double tb_clock_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}
