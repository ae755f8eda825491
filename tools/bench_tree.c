/* Micro benchmark of the dynamic AABB tree (src/tree.c), the broad phase's hot path.
 *
 * Build and run (after `make`):
 *   cc -std=c17 -O2 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off -Iinclude tools/bench_tree.c build/libtumble.a
 * -lm -o build/bench_tree && build/bench_tree
 *
 * 10,000 boxes (0.2 to 1 m) in a 200 m square do a random walk (speed up to
 * 3 m/s, 60 Hz). Each step moves every proxy (fat margin 0.1 m), then queries the
 * fat AABB of each re-inserted proxy for pairs, as the broad phase does. A run is
 * 60 warm-up steps and 200 timed steps from the same start; the figure is the
 * median over 7 runs of the mean time per step. A second scenario adds
 * predictive enlargement (displacement = 4 v dt). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../src/tree.h"

#define N 10000
#define AREA 200.0f
#define MAX_SPEED 3.0f
#define DT (1.0f / 60.0f)
#define WARMUP 60
#define STEPS 200
#define RUNS 7

static unsigned rng_state;

static float rnd(float lo, float hi) {
  unsigned x = rng_state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  rng_state = x;
  return lo + (hi - lo) * (float)((double)x / 4294967296.0);
}

static double now_ms(void) {
  struct timespec t;
  timespec_get(&t, TIME_UTC);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

typedef struct body {
  tb_vec2 p, v;
  float size;
  int32_t proxy;
} body;

static body bodies[N];
static unsigned char moved[N];
static int32_t move_buffer[N];

static tb_aabb body_box(const body* b) { return (tb_aabb){b->p, {b->p.x + b->size, b->p.y + b->size}}; }

typedef struct pair_ctx {
  int32_t self;
  long pairs;
} pair_ctx;

/* A pair is counted once: when both moved, by the lower id. */
static bool pair_callback(int32_t proxy, int32_t user_id, void* context) {
  (void)proxy;
  pair_ctx* c = context;
  if (user_id == c->self || (moved[user_id] && user_id < c->self)) return true;
  c->pairs += 1;
  return true;
}

typedef struct run_result {
  double ms_per_step;
  double reinserts_per_step, pairs_per_step;
  int height;
  float area_ratio;
} run_result;

static int step(tb_tree* tree, bool predictive, long* pairs) {
  int count = 0;
  for (int i = 0; i < N; ++i) {
    body* b = &bodies[i];
    b->v.x += rnd(-0.5f, 0.5f);
    b->v.y += rnd(-0.5f, 0.5f);
    if (b->v.x > MAX_SPEED) b->v.x = MAX_SPEED;
    if (b->v.x < -MAX_SPEED) b->v.x = -MAX_SPEED;
    if (b->v.y > MAX_SPEED) b->v.y = MAX_SPEED;
    if (b->v.y < -MAX_SPEED) b->v.y = -MAX_SPEED;
    b->p.x += DT * b->v.x;
    b->p.y += DT * b->v.y;
    if (b->p.x < 0.0f || b->p.x > AREA) b->v.x = -b->v.x;
    if (b->p.y < 0.0f || b->p.y > AREA) b->v.y = -b->v.y;
    tb_vec2 d = predictive ? (tb_vec2){4.0f * DT * b->v.x, 4.0f * DT * b->v.y} : (tb_vec2){0.0f, 0.0f};
    if (tb_tree_move_proxy(tree, b->proxy, body_box(b), d)) {
      moved[i] = 1;
      move_buffer[count++] = i;
    }
  }
  for (int k = 0; k < count; ++k) {
    int i = move_buffer[k];
    pair_ctx c = {i, 0};
    tb_tree_query(tree, tb_tree_get_fat_aabb(tree, bodies[i].proxy), UINT64_MAX, pair_callback, &c);
    *pairs += c.pairs;
  }
  for (int k = 0; k < count; ++k) moved[move_buffer[k]] = 0;
  return count;
}

static run_result run(bool predictive) {
  tb_tree tree;
  if (tb_tree_create(&tree, 0.1f) != TB_OK) abort();
  rng_state = 12345u;
  for (int i = 0; i < N; ++i) {
    body* b = &bodies[i];
    b->p = (tb_vec2){rnd(0.0f, AREA), rnd(0.0f, AREA)};
    b->v = (tb_vec2){rnd(-2.0f, 2.0f), rnd(-2.0f, 2.0f)};
    b->size = rnd(0.2f, 1.0f);
    b->proxy = tb_tree_create_proxy(&tree, body_box(b), 1u, i);
    if (b->proxy < 0) abort();
  }
  memset(moved, 0, sizeof moved);
  long pairs = 0, reinserts = 0;
  for (int s = 0; s < WARMUP; ++s) step(&tree, predictive, &pairs);
  pairs = 0;
  double t0 = now_ms();
  for (int s = 0; s < STEPS; ++s) reinserts += step(&tree, predictive, &pairs);
  double t1 = now_ms();
  if (!tb_tree_validate(&tree)) {
    fprintf(stderr, "tree invalid\n");
    exit(1);
  }
  run_result r = {(t1 - t0) / STEPS, (double)reinserts / STEPS, (double)pairs / STEPS, tb_tree_get_height(&tree),
                  tb_tree_get_area_ratio(&tree)};
  tb_tree_destroy(&tree);
  return r;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static void scenario(const char* name, bool predictive) {
  double ms[RUNS];
  run_result r = {0};
  for (int k = 0; k < RUNS; ++k) {
    r = run(predictive);
    ms[k] = r.ms_per_step;
  }
  qsort(ms, RUNS, sizeof ms[0], cmp_double);
  printf(
      "%-11s %.3f ms/step median (min %.3f, max %.3f) | %.0f re-inserts, %.0f new-pair candidates per step | "
      "height %d, area ratio %.1f\n",
      name, ms[RUNS / 2], ms[0], ms[RUNS - 1], r.reinserts_per_step, r.pairs_per_step, r.height, r.area_ratio);
}

/* Building from scratch: incremental inserts, then a rebuild. */
static void build_figures(void) {
  tb_tree tree;
  if (tb_tree_create(&tree, 0.1f) != TB_OK) abort();
  rng_state = 777u;
  double t0 = now_ms();
  for (int i = 0; i < N; ++i) {
    float x = rnd(0.0f, AREA), y = rnd(0.0f, AREA), s = rnd(0.2f, 1.0f);
    tb_tree_create_proxy(&tree, (tb_aabb){{x, y}, {x + s, y + s}}, 1u, i);
  }
  double t1 = now_ms();
  int h_insert = tb_tree_get_height(&tree);
  float ratio_insert = tb_tree_get_area_ratio(&tree);
  tb_tree_rebuild(&tree);
  double t2 = now_ms();
  printf("build       %d inserts %.2f ms (height %d, area ratio %.1f); rebuild %.2f ms (height %d, area ratio %.1f)\n",
         N, t1 - t0, h_insert, ratio_insert, t2 - t1, tb_tree_get_height(&tree), tb_tree_get_area_ratio(&tree));
  tb_tree_destroy(&tree);
}

int main(void) {
  printf("tumble tree bench: %d proxies, %d runs of %d steps\n", N, RUNS, STEPS);
  scenario("walk", false);
  scenario("predictive", true);
  build_figures();
  return 0;
}
