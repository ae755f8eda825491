/* Runs the stress tests and writes the report (see stress_main.c). */
#ifndef TB_STRESS_RUNNER_H
#define TB_STRESS_RUNNER_H

#include <stdbool.h>

typedef struct stress_options {
  bool fast_only;        /* only the tests marked fast (the `make test` subset) */
  const char* only;      /* NULL, or the name of the one test to run */
  const char* report;    /* NULL, or the path of the Markdown report to write */
  const char* o0_hashes; /* NULL, or the -O0 build's `--hashes` output to compare */
} stress_options;

/* 0 when every test run passed, 1 otherwise. */
int stress_run(const stress_options* options);

#endif
