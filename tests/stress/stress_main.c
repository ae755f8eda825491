/* The stress suite's command line (`make stress`):
 *   stress [--fast] [--only NAME] [--report FILE] [--o0-hashes FILE] [--perturb SEED]
 *   stress --hashes       prints each stress scene's hash, each scene run
 *                         twice (exits 1 when the two runs differ)
 *   stress --hashes-once  the same from one run (the -O0 build's side of the
 *                         -O0/-O3 check, as -O0 is slow)
 * --perturb SEED starts the helpers' dynamic bodies up to 1 um off (stress.h),
 * a draw per seed, to show the spread of a chaotic figure.
 * --only NAME runs one test ("determinism": the hash check alone); an unknown
 * NAME is an error that lists the tests. Exits non-zero when a test fails. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stress.h"
#include "stress_runner.h"

int main(int argc, char** argv) {
  stress_options options = {0};
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--hashes") == 0) return stress_print_hashes(stdout, 2) ? 0 : 1;
    if (strcmp(argv[i], "--hashes-once") == 0) return stress_print_hashes(stdout, 1) ? 0 : 1;
    if (strcmp(argv[i], "--fast") == 0) {
      options.fast_only = true;
    } else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      options.only = argv[++i];
    } else if (strcmp(argv[i], "--report") == 0 && i + 1 < argc) {
      options.report = argv[++i];
    } else if (strcmp(argv[i], "--o0-hashes") == 0 && i + 1 < argc) {
      options.o0_hashes = argv[++i];
    } else if (strcmp(argv[i], "--perturb") == 0 && i + 1 < argc && atoi(argv[i + 1]) > 0) {
      stress_perturb_seed = (uint32_t)atoi(argv[++i]);
      printf("start positions perturbed: seed %u\n", (unsigned)stress_perturb_seed);
    } else {
      fprintf(stderr,
              "usage: %s [--fast] [--only NAME] [--report FILE] [--o0-hashes FILE] [--perturb SEED (> 0)] | --hashes"
              " | --hashes-once\n",
              argv[0]);
      return 2;
    }
  }
  return stress_run(&options);
}
