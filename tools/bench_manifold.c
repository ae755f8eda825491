/* Narrow-phase throughput: ns per contact manifold for every pair type, tumble
 * and Box2D 2.4.1 in the same run, on the same configurations. `make bench`
 * builds and runs it; by hand (after `make lib`, from the repository root):
 *
 *   cc -std=c17 -O2 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off -Iinclude \
 *      -c tools/bench_manifold.c -o build/bench_manifold.o
 *   c++ -std=c++17 -O2 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off \
 *      -c tools/bench_manifold_b2.cpp -o build/bench_manifold_b2.o
 *   c++ -o build/bench_manifold build/bench_manifold.o build/bench_manifold_b2.o \
 *      build/libtumble.a -lbox2d -lm
 *   build/bench_manifold
 *
 * Configurations: random shapes of game sizes (0.1 to 2 m) whose B is moved
 * along a random direction from A's centre to a random fraction (0.6 to 1.03)
 * of the distance at which tumble's manifold empties: mostly touching, some in
 * the speculative band, a few apart, as a narrow phase sees them after the
 * broad phase. Box2D gets the same cores (its polygons keep their 0.01 m skin,
 * tumble's polygons are given radius 0.01 to match). tumble's result holds world
 * points and separations, so the fair Box2D figure is b2Collide* followed by
 * b2WorldManifold::Initialize; b2Collide* alone is shown too. Each figure is the
 * best of 7 timed sweeps over 2048 configurations. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../tests/reference/b2_collide_shim.h"
#include "tumble.h"

#define N 2048
#define TRIALS 7

/* In tools/bench_manifold_b2.cpp. pair: 0 circles, 1 polygon-circle, 2 polygons,
 * 3 edge-circle, 4 edge-polygon; see there for the layout of a and b. */
double b2bench_run(int pair, const void* a, const void* b, const b2c_transform* xfa, const b2c_transform* xfb, int n,
                   int repeat, int with_world, double* checksum);

static unsigned rng = 2463534242u;
static float frand(float lo, float hi) {
  rng ^= rng << 13;
  rng ^= rng >> 17;
  rng ^= rng << 5;
  return lo + (hi - lo) * (float)((double)rng / 4294967296.0);
}

static tb_transform xf_make(float x, float y, float a) { return (tb_transform){{x, y}, {cosf(a), sinf(a)}}; }

typedef enum kind { CIRCLE, CAPSULE, SEGMENT, POLYGON, BOX } kind;

typedef struct shape {
  kind k;
  tb_circle circle;
  tb_capsule capsule;
  tb_segment segment;
  tb_polygon polygon;
} shape;

static shape make_shape(kind k) {
  shape s;
  memset(&s, 0, sizeof s);
  s.k = k;
  if (k == CIRCLE) s.circle = (tb_circle){{frand(-0.1f, 0.1f), frand(-0.1f, 0.1f)}, frand(0.1f, 0.6f)};
  if (k == CAPSULE) {
    float h = frand(0.1f, 0.6f), a = frand(0.0f, 6.28f);
    s.capsule = (tb_capsule){{-h * cosf(a), -h * sinf(a)}, {h * cosf(a), h * sinf(a)}, frand(0.05f, 0.3f)};
  }
  if (k == SEGMENT) {
    float h = frand(0.25f, 1.5f), a = frand(0.0f, 6.28f);
    s.segment = (tb_segment){{-h * cosf(a), -h * sinf(a)}, {h * cosf(a), h * sinf(a)}};
  }
  if (k == BOX) tb_make_rounded_box(frand(0.1f, 1.0f), frand(0.1f, 1.0f), 0.01f, &s.polygon);
  if (k == POLYGON) {
    float scale = frand(0.2f, 1.0f);
    for (;;) {
      tb_vec2 p[8];
      int n = 3 + (int)frand(0.0f, 5.99f);
      for (int i = 0; i < n; ++i) {
        float a = frand(0.0f, 6.28f), r = scale * frand(0.5f, 1.0f);
        p[i] = (tb_vec2){r * cosf(a), r * sinf(a)};
      }
      if (tb_make_polygon(p, n, 0.01f, &s.polygon) == TB_OK) break;
    }
  }
  return s;
}

static tb_manifold collide(const shape* a, tb_transform xa, const shape* b, tb_transform xb) {
  kind ka = a->k == BOX ? POLYGON : a->k, kb = b->k == BOX ? POLYGON : b->k;
  if (ka == CIRCLE) return tb_collide_circles(&a->circle, xa, &b->circle, xb);
  if (ka == CAPSULE && kb == CIRCLE) return tb_collide_capsule_and_circle(&a->capsule, xa, &b->circle, xb);
  if (ka == CAPSULE) return tb_collide_capsules(&a->capsule, xa, &b->capsule, xb);
  if (ka == SEGMENT && kb == CIRCLE) return tb_collide_segment_and_circle(&a->segment, xa, &b->circle, xb);
  if (ka == SEGMENT && kb == CAPSULE) return tb_collide_segment_and_capsule(&a->segment, xa, &b->capsule, xb);
  if (ka == SEGMENT) return tb_collide_segment_and_polygon(&a->segment, xa, &b->polygon, xb);
  if (kb == CIRCLE) return tb_collide_polygon_and_circle(&a->polygon, xa, &b->circle, xb);
  if (kb == CAPSULE) return tb_collide_polygon_and_capsule(&a->polygon, xa, &b->capsule, xb);
  return tb_collide_polygons(&a->polygon, xa, &b->polygon, xb);
}

typedef struct pair_def {
  const char* name;
  kind a, b;
  int b2pair; /* -1: Box2D has no such pair */
} pair_def;

static const pair_def pairs[] = {
    {"circle-circle", CIRCLE, CIRCLE, 0},      {"capsule-circle", CAPSULE, CIRCLE, -1},
    {"capsule-capsule", CAPSULE, CAPSULE, -1}, {"segment-circle", SEGMENT, CIRCLE, 3},
    {"segment-capsule", SEGMENT, CAPSULE, -1}, {"segment-polygon", SEGMENT, POLYGON, 4},
    {"polygon-circle", POLYGON, CIRCLE, 1},    {"polygon-capsule", POLYGON, CAPSULE, -1},
    {"polygon-polygon", POLYGON, POLYGON, 2},  {"box-box", BOX, BOX, 2},
};

static shape sa[N], sb[N];
static tb_transform xa[N], xb[N];
static b2c_transform ba[N], bb[N];
static b2c_polygon pa[N], pb[N];
static float fa[4 * N], fb[4 * N];

static double now_ns(void) {
  struct timespec t; /* C11's clock: -std=c17 hides POSIX's clock_gettime */
  timespec_get(&t, TIME_UTC);
  return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

static b2c_polygon to_b2c(const tb_polygon* p) {
  b2c_polygon b;
  memset(&b, 0, sizeof b);
  b.count = p->count;
  for (int i = 0; i < p->count; ++i) {
    b.vertices[i][0] = p->vertices[i].x, b.vertices[i][1] = p->vertices[i].y;
    b.normals[i][0] = p->normals[i].x, b.normals[i][1] = p->normals[i].y;
  }
  b.centroid[0] = p->centroid.x, b.centroid[1] = p->centroid.y;
  return b;
}

/* Fills the configurations of a pair; returns the share that has points. */
static double make_configs(const pair_def* p) {
  int touching = 0;
  for (int i = 0; i < N; ++i) {
    sa[i] = make_shape(p->a);
    sb[i] = make_shape(p->b);
    xa[i] = xf_make(frand(-20.0f, 20.0f), frand(-20.0f, 20.0f), frand(-3.2f, 3.2f));
    float dir = frand(-3.2f, 3.2f), angle = frand(-3.2f, 3.2f), lo = 0.0f, hi = 8.0f;
    for (int k = 0; k < 30; ++k) { /* the distance at which the manifold empties */
      float mid = 0.5f * (lo + hi);
      tb_transform t = xf_make(xa[i].p.x + mid * cosf(dir), xa[i].p.y + mid * sinf(dir), angle);
      if (collide(&sa[i], xa[i], &sb[i], t).point_count > 0)
        lo = mid;
      else
        hi = mid;
    }
    float d = lo * frand(0.6f, 1.03f);
    xb[i] = xf_make(xa[i].p.x + d * cosf(dir), xa[i].p.y + d * sinf(dir), angle);
    touching += collide(&sa[i], xa[i], &sb[i], xb[i]).point_count > 0;
    ba[i] = (b2c_transform){xa[i].p.x, xa[i].p.y, xa[i].q.c, xa[i].q.s};
    bb[i] = (b2c_transform){xb[i].p.x, xb[i].p.y, xb[i].q.c, xb[i].q.s};
    if (p->a == CIRCLE) {
      const tb_circle* c = &sa[i].circle;
      memcpy(fa + 3 * i, (const float[3]){c->center.x, c->center.y, c->radius}, 3 * sizeof(float));
    }
    if (p->a == SEGMENT) {
      const tb_segment* e = &sa[i].segment;
      memcpy(fa + 4 * i, (const float[4]){e->point1.x, e->point1.y, e->point2.x, e->point2.y}, 4 * sizeof(float));
    }
    if (p->a == POLYGON || p->a == BOX) pa[i] = to_b2c(&sa[i].polygon);
    if (p->b == CIRCLE) {
      const tb_circle* c = &sb[i].circle;
      memcpy(fb + 3 * i, (const float[3]){c->center.x, c->center.y, c->radius}, 3 * sizeof(float));
    }
    if (p->b == POLYGON || p->b == BOX) pb[i] = to_b2c(&sb[i].polygon);
  }
  return (double)touching / N;
}

/* One timed sweep calling fn directly (no dispatch in the loop). */
#define SWEEP(fn, ga, gb)                                                  \
  for (int r = 0; r < repeat; ++r)                                         \
    for (int i = 0; i < N; ++i) {                                          \
      tb_manifold m = fn(&sa[i].ga, xa[i], &sb[i].gb, xb[i]);              \
      sum += m.point_count + m.points[0].separation + m.points[0].point.x; \
    }

static double bench_tumble(const pair_def* p, int repeat, double* checksum) {
  kind ka = p->a == BOX ? POLYGON : p->a, kb = p->b == BOX ? POLYGON : p->b;
  double best = 1e30;
  for (int t = 0; t < TRIALS; ++t) {
    double sum = 0.0, start = now_ns();
    if (ka == CIRCLE) {
      SWEEP(tb_collide_circles, circle, circle)
    } else if (ka == CAPSULE && kb == CIRCLE) {
      SWEEP(tb_collide_capsule_and_circle, capsule, circle)
    } else if (ka == CAPSULE) {
      SWEEP(tb_collide_capsules, capsule, capsule)
    } else if (ka == SEGMENT && kb == CIRCLE) {
      SWEEP(tb_collide_segment_and_circle, segment, circle)
    } else if (ka == SEGMENT && kb == CAPSULE) {
      SWEEP(tb_collide_segment_and_capsule, segment, capsule)
    } else if (ka == SEGMENT) {
      SWEEP(tb_collide_segment_and_polygon, segment, polygon)
    } else if (kb == CIRCLE) {
      SWEEP(tb_collide_polygon_and_circle, polygon, circle)
    } else if (kb == CAPSULE) {
      SWEEP(tb_collide_polygon_and_capsule, polygon, capsule)
    } else {
      SWEEP(tb_collide_polygons, polygon, polygon)
    }
    double ns = (now_ns() - start) / ((double)N * repeat);
    best = ns < best ? ns : best;
    *checksum += sum;
  }
  return best;
}

static double bench_box2d(const pair_def* p, int repeat, int with_world, double* checksum) {
  const void* a = p->a == CIRCLE || p->a == SEGMENT ? (const void*)fa : (const void*)pa;
  const void* b = p->b == CIRCLE ? (const void*)fb : (const void*)pb;
  double best = 1e30;
  for (int t = 0; t < TRIALS; ++t) {
    double ns = b2bench_run(p->b2pair, a, b, ba, bb, N, repeat, with_world, checksum);
    best = ns < best ? ns : best;
  }
  return best;
}

int main(void) {
  double checksum = 0.0;
  const int repeat = 50;
  printf("ns per manifold (best of %d sweeps of %d configurations x %d)\n", TRIALS, N, repeat);
  printf("%-17s %9s %8s %14s %18s %8s\n", "pair", "touching", "tumble", "Box2D collide", "Box2D +world mf.", "ratio");
  for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; ++k) {
    const pair_def* p = &pairs[k];
    double share = make_configs(p);
    double t = bench_tumble(p, repeat, &checksum);
    if (p->b2pair < 0) {
      printf("%-17s %8.0f%% %8.1f %14s %18s %8s\n", p->name, 100.0 * share, t, "-", "-", "-");
      continue;
    }
    double c = bench_box2d(p, repeat, 0, &checksum), w = bench_box2d(p, repeat, 1, &checksum);
    printf("%-17s %8.0f%% %8.1f %14.1f %18.1f %7.2fx\n", p->name, 100.0 * share, t, c, w, w / t);
  }
  printf("(ratio: Box2D collide + world manifold over tumble; checksum %g)\n", checksum);
  return 0;
}
