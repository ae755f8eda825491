/* What a scene does not use must cost nothing (issue 6), measured on tumble:
 *
 * 1. sleeping: 10 awake boxes (sleep off for them) resting on the ground,
 *    alone and next to 10,000 boxes created asleep (100 walls of 10 x 10
 *    boxes, 15 m apart on the same ground). Bound: the second world steps
 *    within 1.5 x the first's time.
 * 2. idle features: a pyramid of base 20 (210 boxes, kept awake) alone, and
 *    the same with features present but idle far away: two bodies on a
 *    revolute joint and a bullet, created asleep on the ground, a static
 *    sensor nothing enters, and the game reading contact and sensor events
 *    after every step. Bound: within 3% (the run-to-run spread on a shared
 *    machine), also printed.
 *
 * Worlds alternate (A B A B ...) so that a slow spell of the machine hits
 * both; 60 untimed steps, then `steps` timed ones; the minimum over the runs.
 *
 *   build/bench/bench_skip [--quick] [--runs N] [--csv FILE]
 * Exit status 1 when a world cannot be built or a step fails; a missed bound
 * is reported (and in skip.csv), not an error: timings on a shared CI machine
 * are not a pass/fail test. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "tumble.h"

#define WARMUP_STEPS 60

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static void fail(const char* what) {
  fprintf(stderr, "bench_skip: %s: %s\n", what, tb_last_error());
  exit(1);
}

static tb_body_id make_body(tb_world_id w, tb_body_type type, float x, float y, bool awake, bool can_sleep) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = (tb_vec2){x, y};
  bd.is_awake = awake;
  bd.enable_sleep = can_sleep;
  tb_body_id b = tb_create_body(w, &bd);
  if (tb_body_id_is_null(b)) fail("tb_create_body");
  return b;
}

static void add_box(tb_body_id b, float h, const tb_shape_def* sd) {
  tb_polygon box;
  if (tb_make_box(h, h, &box) != TB_OK || tb_shape_id_is_null(tb_create_polygon_shape(b, sd, &box))) {
    fail("box shape");
  }
}

static tb_world_id new_world(float ground_half_width) {
  tb_world_def wd = tb_default_world_def();
  tb_world_id w = tb_create_world(&wd);
  if (tb_world_id_is_null(w)) fail("tb_create_world");
  tb_body_id g = make_body(w, TB_STATIC_BODY, 0.0f, 0.0f, true, true);
  tb_polygon box;
  tb_shape_def sd = tb_default_shape_def();
  if (tb_make_offset_box(ground_half_width, 1.0f, (tb_vec2){0.0f, -1.0f}, 0.0f, &box) != TB_OK ||
      tb_shape_id_is_null(tb_create_polygon_shape(g, &sd, &box)))
    fail("ground");
  return w;
}

/* ------------------------------------------------------------- worlds -- */

static tb_world_id sleeping_world(bool with_sleepers) {
  tb_world_id w = new_world(1000.0f);
  tb_shape_def sd = tb_default_shape_def();
  for (int i = 0; i < 10; ++i)
    add_box(make_body(w, TB_DYNAMIC_BODY, -50.0f + 2.0f * (float)i, 0.5f, true, false), 0.5f, &sd);
  if (with_sleepers) {
    for (int k = 0; k < 100; ++k) {
      for (int row = 0; row < 10; ++row) {
        for (int col = 0; col < 10; ++col) {
          float x = 20.0f + 15.0f * (float)k + (float)col, y = 0.5f + (float)row;
          add_box(make_body(w, TB_DYNAMIC_BODY, x, y, false, true), 0.5f, &sd);
        }
      }
    }
  }
  return w;
}

typedef struct feature_world {
  tb_world_id w;
  bool read_events;
} feature_world;

static feature_world feature_world_make(bool with_features) {
  feature_world fw = {new_world(1100.0f), with_features};
  tb_world_id w = fw.w;
  tb_shape_def sd = tb_default_shape_def();
  const int base = 20;
  for (int i = 0; i < base; ++i) {
    for (int j = i; j < base; ++j) {
      float x = (float)(2 * (j - i) + i + 1 - base) * 0.5f, y = 0.5f + (float)i;
      add_box(make_body(w, TB_DYNAMIC_BODY, x, y, true, false), 0.5f, &sd);
    }
  }
  if (with_features) {
    /* a jointed pair and a bullet, asleep on the ground 1 km away */
    tb_body_id a = make_body(w, TB_DYNAMIC_BODY, 1000.0f, 0.5f, false, true);
    tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 1001.0f, 0.5f, false, true);
    add_box(a, 0.5f, &sd);
    add_box(b, 0.5f, &sd);
    tb_revolute_joint_def jd = tb_default_revolute_joint_def();
    jd.body_a = a;
    jd.body_b = b;
    jd.local_anchor_a = (tb_vec2){0.5f, 0.0f};
    jd.local_anchor_b = (tb_vec2){-0.5f, 0.0f};
    if (tb_joint_id_is_null(tb_create_revolute_joint(w, &jd))) fail("joint");
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = (tb_vec2){1010.0f, 0.05f};
    bd.is_bullet = true;
    bd.is_awake = false;
    tb_body_id bullet = tb_create_body(w, &bd);
    tb_circle c = {{0.0f, 0.0f}, 0.05f};
    if (tb_body_id_is_null(bullet) || tb_shape_id_is_null(tb_create_circle_shape(bullet, &sd, &c))) fail("bullet");
    /* a sensor nothing enters, on a static body 1 km away */
    tb_body_id s = make_body(w, TB_STATIC_BODY, 1050.0f, 20.0f, true, true);
    tb_shape_def sensor = tb_default_shape_def();
    sensor.is_sensor = true;
    add_box(s, 2.0f, &sensor);
  }
  return fw;
}

/* ------------------------------------------------------------ measuring -- */

typedef struct timing {
  double min_ms, sum_ms;
  int runs;
  int awake; /* awake bodies after the last run */
} timing;

static volatile int g_event_sink;

static void timed_steps(tb_world_id w, bool read_events, int steps, timing* t) {
  for (int i = 0; i < WARMUP_STEPS; ++i) {
    if (tb_world_step(w, 1.0f / 60.0f, 4) != TB_OK) fail("tb_world_step");
  }
  double total = 0.0;
  for (int i = 0; i < steps; ++i) {
    double t0 = now_ms();
    if (tb_world_step(w, 1.0f / 60.0f, 4) != TB_OK) fail("tb_world_step");
    if (read_events) {
      tb_contact_events ce = tb_world_get_contact_events(w);
      tb_sensor_events se = tb_world_get_sensor_events(w);
      g_event_sink += ce.begin_count + ce.end_count + ce.hit_count + se.begin_count + se.end_count;
    }
    total += now_ms() - t0;
  }
  double ms = total / steps;
  if (t->runs == 0 || ms < t->min_ms) t->min_ms = ms;
  t->sum_ms += ms;
  t->runs += 1;
  t->awake = tb_world_get_counts(w).awake_body_count;
}

static void row(FILE* csv, const char* what, const timing* base, const timing* with, const char* bound, bool ok) {
  double ratio = with->min_ms / base->min_ms;
  printf("%-58s %9.4f %9.4f %7.3f  %-8s %s\n", what, base->min_ms, with->min_ms, ratio, bound, ok ? "met" : "MISSED");
  if (csv != NULL) {
    fprintf(csv, "%s,%.6f,%.6f,%.4f,%s,%s\n", what, base->min_ms, with->min_ms, ratio, bound, ok ? "met" : "missed");
  }
}

int main(int argc, char** argv) {
  int runs = 5, steps = 300;
  const char* csv_path = NULL;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--quick") == 0) {
      runs = 2, steps = 60;
    } else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
      runs = atoi(argv[++i]);
    } else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else {
      fprintf(stderr, "usage: %s [--quick] [--runs N] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  if (runs < 1) return 2;
  FILE* csv = NULL;
  if (csv_path != NULL) {
    csv = fopen(csv_path, "w");
    if (csv == NULL) {
      perror(csv_path);
      return 1;
    }
    fprintf(csv, "what,baseline_ms,with_ms,ratio,bound,result\n");
  }
  printf("tumble skip costs: 60 Hz, 4 substeps, %d runs of %d steps after %d untimed, min ms per step\n", runs, steps,
         WARMUP_STEPS);
  printf("%-58s %9s %9s %7s  %-8s %s\n", "measurement", "base ms", "with ms", "ratio", "bound", "result");

  timing alone = {0}, crowd = {0};
  for (int r = 0; r < runs; ++r) {
    tb_world_id a = sleeping_world(false);
    timed_steps(a, false, steps, &alone);
    tb_destroy_world(a);
    tb_world_id b = sleeping_world(true);
    timed_steps(b, false, steps, &crowd);
    tb_destroy_world(b);
  }
  bool ok1 = crowd.min_ms <= 1.5 * alone.min_ms && crowd.awake == alone.awake;
  char what[128];
  snprintf(what, sizeof what, "10 awake + 10000 asleep (awake after: %d) vs 10 awake", crowd.awake);
  row(csv, what, &alone, &crowd, "<= 1.5", ok1);

  timing plain = {0}, idle = {0};
  for (int r = 0; r < runs; ++r) {
    feature_world a = feature_world_make(false);
    timed_steps(a.w, a.read_events, steps, &plain);
    tb_destroy_world(a.w);
    feature_world b = feature_world_make(true);
    timed_steps(b.w, b.read_events, steps, &idle);
    tb_destroy_world(b.w);
  }
  bool ok2 = idle.min_ms <= 1.03 * plain.min_ms;
  row(csv, "pyramid 20 + idle joint; sensor; bullet; event reads vs plain", &plain, &idle, "<= 1.03", ok2);
  printf("run-to-run spread (mean / min - 1): plain %.1f%%, with features %.1f%%\n",
         100.0 * (plain.sum_ms / plain.runs / plain.min_ms - 1.0),
         100.0 * (idle.sum_ms / idle.runs / idle.min_ms - 1.0));
  if (csv != NULL) fclose(csv);
  return 0;
}
