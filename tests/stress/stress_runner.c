/* The table of stress tests, the runner and the Markdown report. */
#define _POSIX_C_SOURCE 200809L
#include "stress_runner.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "stress.h"

static const stress_test k_tests[] = {
    {"stack_15",
     "15 boxes of 1 m, 30 s, sleep off: top within 5 cm sideways; sinks <= 1.1 x the soft contacts' closing in closed "
     "form",
     true, stress_stack_15},
    {"stack_30", "30 boxes of 1 m, 30 s, sleep off: top within 5 cm sideways; sinks <= 1.1 x closed form", false,
     stress_stack_30},
    {"pyramid_20", "base 20 (210 boxes of 1 m), 30 s, sleep off: top within 5 cm sideways; sinks <= 1.1 x closed form",
     true, stress_pyramid_20},
    {"pyramid_100",
     "base 100 (5,050 boxes of 1 m), 30 s, sleep off: top within 5 cm sideways; sinks <= 1.1 x closed form", false,
     stress_pyramid_100},
    {"card_house", "5 levels, 40 cards 2 mm x 40 cm, 30 s, sleep off: top card within 1 cm of its start", true,
     stress_card_house},
    {"arch", "semicircular arch of 11 voussoirs, friction only, 30 s, sleep off: keystone within 5 cm", true,
     stress_arch},
    {"mass_ratio_100", "20 m plank on two 1 kg boxes, 100:1, 30 s: plank sinks < 5 cm, supports < 5 cm, slides < 3 cm",
     true, stress_mass_ratio_100},
    {"mass_ratio_400", "same, 400:1", true, stress_mass_ratio_400},
    {"mass_ratio_1000", "same, 1000:1", false, stress_mass_ratio_1000},
    {"ball_and_chain", "1 m ball of 670 link masses on 40 capsule links, swinging 30 s: joint gap < link radius 5 cm",
     true, stress_ball_and_chain},
    {"mass_ratio_edge",
     "heavy box on a 1 kg box, pendulum of a 1 kg link and a heavy ball, ratios 1e1-1e6 at 4 and 8 substeps, 3 s: "
     "to 1e3 sinks <= 2 x soft closed form, joint gap <= 1 cm (table below)",
     true, stress_mass_ratio_edge},
    {"overlap_boxes",
     "20 boxes overlapping 25 %: peak speed <= push cap + g d / cap; at 3 s no overlap 5 mm deeper than its force "
     "explains",
     true, stress_overlap_boxes},
    {"overlap_circles",
     "256 circles overlapping 25 % in a U: peak speed <= push cap + g d / cap; at 3 s as overlap_boxes", false,
     stress_overlap_circles},
    {"pileup_300",
     "300 boxes and circles created at one point in a U, 10 s: heap a pair <= budget; peak speed <= push cap + fall "
     "from the top; at 10 s all in the U, no overlap 5 mm deeper than its force explains",
     true, stress_pileup_300},
    {"pileup_1000", "same with 1,000 bodies (499,500 pairs)", false, stress_pileup_1000},
    {"bullets", "1,000 bullets at 500 m/s in a room of 1 cm walls, 2 s: zero tunnelled", true, stress_bullets},
    {"spinner", "plank at 50 rad/s: free |dw|/w < 1e-4 over 10 s; dropped: energy never above start + 1 %", true,
     stress_spinner},
    {"scale_offset",
     "pyramid of base 20 at 8 km and 65 km, 10 s, sleep off: top drift within 1 ULP of the origin run's", false,
     stress_scale_offset},
    {"tiny_boxes", "pyramid of base 10 of 2.5 cm boxes, 10 s, sleep off: top drift < 5 % of a box", false,
     stress_tiny_boxes},
    {"large_boxes", "pyramid of base 10 of 50 m boxes, 10 s, sleep off: top drift < 5 % of a box", true,
     stress_large_boxes},
    {"one_hour",
     "216,000 steps of 120 bodies in a turning drum, sleep off: finite, none lost, energy bounded, heap flat", false,
     stress_one_hour},
    {"churn", "100,000 steps creating/destroying bodies and joints: no stale handle resolves, no reissue, no leak",
     true, stress_churn},
};

#define TEST_COUNT ((int)(sizeof k_tests / sizeof k_tests[0]))

static double seconds_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Compares this build's scene hashes (two runs in-process) with the -O0
 * build's output; without one (`--only determinism` alone) only the two runs
 * are compared. */
static void determinism_row(const char* o0_path, stress_result* out) {
  /* a caller-owned buffer: memory libc allocates would bypass heap_count.c */
  char mine[4096] = "";
  FILE* m = fmemopen(mine, sizeof mine, "w");
  bool same_runs = m != NULL && stress_print_hashes(m, 2);
  if (m != NULL) fclose(m);
  FILE* f = o0_path != NULL ? fopen(o0_path, "r") : NULL;
  char other[4096] = "";
  size_t n = f != NULL ? fread(other, 1, sizeof other - 1, f) : 0;
  other[n] = '\0';
  if (f != NULL) fclose(f);
  int lines = 0;
  for (const char* c = mine; *c; ++c) lines += *c == '\n';
  bool same_builds = strcmp(mine, other) == 0;
  out->pass = same_runs && (same_builds || o0_path == NULL) && lines > 0;
  stress_note(out, "%d scenes: two runs %s; -O0 vs -O3 %s", lines, same_runs ? "equal" : "DIFFER",
              o0_path == NULL ? "not compared (no --o0-hashes)"
              : same_builds   ? "equal"
                              : "DIFFER");
  if (o0_path != NULL && !same_builds) fprintf(stderr, "-O3 hashes:\n%s-O0 hashes:\n%s", mine, other);
}

/* A table cell: '|' would end the cell, so it is escaped. */
static void cell(FILE* f, const char* text) {
  fputs("| ", f);
  for (const char* c = text; *c; ++c) {
    if (*c == '|') fputc('\\', f);
    fputc(*c, f);
  }
  fputc(' ', f);
}

/* Whether `name` is a test of the table or the determinism row. */
static bool known_test(const char* name) {
  for (int i = 0; i < TEST_COUNT; ++i)
    if (strcmp(name, k_tests[i].name) == 0) return true;
  return strcmp(name, "determinism") == 0;
}

int stress_run(const stress_options* options) {
  if (options->only != NULL && !known_test(options->only)) {
    fprintf(stderr, "stress: no test named \"%s\"; the tests are:", options->only);
    for (int i = 0; i < TEST_COUNT; ++i) fprintf(stderr, " %s", k_tests[i].name);
    fprintf(stderr, " determinism\n");
    return 2;
  }
  stress_result results[TEST_COUNT + 1];
  double seconds[TEST_COUNT + 1];
  bool ran[TEST_COUNT + 1];
  int failed = 0, count = 0;
  for (int i = 0; i < TEST_COUNT; ++i) {
    const stress_test* t = &k_tests[i];
    ran[i] = !(options->fast_only && !t->fast) && !(options->only != NULL && strcmp(options->only, t->name) != 0);
    if (!ran[i]) continue;
    memset(&results[i], 0, sizeof results[i]);
    double t0 = seconds_now();
    t->run(&results[i]);
    seconds[i] = seconds_now() - t0;
    count += 1;
    failed += !results[i].pass;
    printf("%-4s %-22s %6.1f s  %s\n", results[i].pass ? "ok" : "FAIL", t->name, seconds[i], results[i].figure);
    fflush(stdout);
  }
  /* the determinism row: with the -O0 build's hashes, or asked for by name */
  bool only_determinism = options->only != NULL && strcmp(options->only, "determinism") == 0;
  ran[TEST_COUNT] = options->only == NULL ? options->o0_hashes != NULL : only_determinism;
  if (ran[TEST_COUNT]) {
    memset(&results[TEST_COUNT], 0, sizeof results[TEST_COUNT]);
    double t0 = seconds_now();
    determinism_row(options->o0_hashes, &results[TEST_COUNT]);
    seconds[TEST_COUNT] = seconds_now() - t0;
    count += 1;
    failed += !results[TEST_COUNT].pass;
    printf("%-4s %-22s %6.1f s  %s\n", results[TEST_COUNT].pass ? "ok" : "FAIL", "determinism", seconds[TEST_COUNT],
           results[TEST_COUNT].figure);
  }
  printf("stress: %d tests run, %d failed\n", count, failed);

  if (options->report != NULL) {
    FILE* f = fopen(options->report, "w");
    if (f == NULL) {
      fprintf(stderr, "cannot write %s\n", options->report);
      return 1;
    }
    fprintf(f,
            "# Stress results\n\n"
            "Written by `make stress` (tests/stress/, issue 7): every test at the default settings "
            "(`tb_default_world_def()`, 60 Hz, 4 substeps) unless its criterion says otherwise. "
            "%d tests, %d failed.\n\n"
            "| test | criterion | measured | result | run time |\n| --- | --- | --- | --- | --- |\n",
            count, failed);
    for (int i = 0; i <= TEST_COUNT; ++i) {
      if (!ran[i]) continue;
      const char* name = i < TEST_COUNT ? k_tests[i].name : "determinism";
      const char* criterion = i < TEST_COUNT ? k_tests[i].criterion
                                             : "hash of every stress test's scene, built as its test builds it, "
                                               "after the test's run (the first 5 s of pyramid_100, the first "
                                               "minute of one_hour, the first 10 steps of pileup_1000 and 5,000 "
                                               "steps of churn): equal over two runs and between the -O0 and -O3 "
                                               "builds";
      cell(f, name);
      cell(f, criterion);
      cell(f, results[i].figure);
      fprintf(f, "| %s | %.1f s |\n", results[i].pass ? "pass" : "**FAIL**", seconds[i]);
    }
    /* sections of their own after the table */
    for (int i = 0; i < TEST_COUNT; ++i)
      if (ran[i] && k_tests[i].run == stress_mass_ratio_edge) stress_mass_ratio_edge_table(f);
    fclose(f);
  }
  return failed == 0 ? 0 : 1;
}
