/* The fast subset of the stress suite, run by `make test` (no arguments). */
#include "stress_runner.h"

int main(void) {
  stress_options options = {.fast_only = true};
  return stress_run(&options);
}
