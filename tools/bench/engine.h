/* One small interface over the engines, so that every accuracy scene of
 * tools/bench_accuracy.c is written once and built with the same parameters in
 * tumble (tools/bench_engine_tumble.c), Box2D 2.4.1
 * (tools/bench_engine_b2.cpp) and, in make bench-v3 only, Box2D v3
 * (tools/bench_engine_v3.c). Bodies are numbered 0, 1, ... in creation order.
 *
 * Box2D's polygons carry a skin of 0.01 m around their core
 * (b2_polygonRadius); `polygon_skin` says how far outside its vertices a
 * polygon's surface is, so that scenes place bodies where they rest in each
 * engine (tumble's and v3's are 0). */
#ifndef TUMBLE_BENCH_ENGINE_H
#define TUMBLE_BENCH_ENGINE_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum bench_body_type { BENCH_STATIC = 0, BENCH_KINEMATIC = 1, BENCH_DYNAMIC = 2 } bench_body_type;

/* How a world steps: tumble uses substeps and integrator (0 semi-implicit
 * Euler, 1 midpoint, 2 RK4: tb_integrator), Box2D 2.4.1 the two iteration
 * counts, Box2D v3 substeps. */
typedef struct bench_setting {
  double dt;
  int substeps;
  int integrator;
  int velocity_iterations, position_iterations;
} bench_setting;

typedef struct bench_world_def {
  double gravity_x, gravity_y;
  bool enable_sleep;
  /* restitution applies above this approach speed (m/s; both engines' default 1) */
  double restitution_threshold;
  /* > 0: every dynamic body is pulled to the origin by F = -k * centre (a
   * force field in tumble, so that its integrators apply; a force applied
   * before each step in Box2D) */
  double spring_k;
} bench_world_def;

typedef struct bench_material {
  double density, friction, restitution;
  int group; /* collision group: a shared negative group never collides */
} bench_material;

typedef struct bench_body_def {
  bench_body_type type;
  double x, y, angle;
  double vx, vy, w; /* velocity of the body origin (every scene puts the centre of mass there) */
  bool bullet;
  bool awake; /* false: created asleep */
} bench_body_def;

typedef struct bench_state {
  double x, y, angle; /* body origin */
  double cx, cy;      /* centre of mass, world */
  double vx, vy, w;   /* velocity of the centre of mass */
  bool awake;
} bench_state;

typedef struct bench_engine {
  const char* name; /* "tumble", "box2d" (2.4.1) or "box2d_v3" */
  double polygon_skin;
  void* (*create)(const bench_world_def* def, const bench_setting* setting);
  void (*destroy)(void* world);
  /* body index, or -1 on error */
  int (*add_body)(void* world, const bench_body_def* def);
  /* shapes: 0 on success */
  int (*add_box)(void* world, int body, double hx, double hy, double cx, double cy, double angle,
                 const bench_material* m);
  int (*add_circle)(void* world, int body, double radius, double cx, double cy, const bench_material* m);
  /* a revolute joint pinning a and b at a world point: 0 on success */
  int (*add_revolute)(void* world, int a, int b, double x, double y);
  /* one step at the setting's dt: 0 on success */
  int (*step)(void* world);
  void (*get_state)(void* world, int body, bench_state* out);
  double (*mass)(void* world, int body);
  double (*inertia)(void* world, int body); /* about the centre of mass */
  /* bodies, touching contacts, joints */
  void (*counts)(void* world, int* bodies, int* contacts, int* joints);
} bench_engine;

extern const bench_engine bench_tumble_engine;
extern const bench_engine bench_box2d_engine;
/* only in make bench-v3's build (tools/bench_engine_v3.c) */
extern const bench_engine bench_box2d_v3_engine;

static inline bench_body_def bench_body(bench_body_type type, double x, double y) {
  bench_body_def d = {type, x, y, 0.0, 0.0, 0.0, 0.0, false, true};
  return d;
}

static inline bench_material bench_mat(double density, double friction, double restitution) {
  bench_material m = {density, friction, restitution, 0};
  return m;
}

#ifdef __cplusplus
}
#endif

#endif
