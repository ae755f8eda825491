/* libFuzzer harness: the whole API of include/tumble.h driven by a command
 * stream, over several worlds at once.
 *
 * Each input is a sequence of commands: create and destroy worlds (with
 * callbacks: force field, custom filter, pre-solve, friction and restitution
 * mix), bodies, shapes, joints and chains; step; forces, impulses,
 * velocities, transforms; every body, shape, joint and world setter; every
 * getter; queries; debug draw; the collide and mass functions, and the
 * geometry and distance queries, on the worlds' own shapes. Numbers are now
 * and then NaN, infinite, huge, zero or negative, and now and then legal
 * extremes (TB_MAX_VALUE, positions at TB_MAX_LENGTH, 1 mm and 1 km shapes,
 * the smallest and largest steps); handles are now and then stale (of
 * destroyed objects and of destroyed worlds) or foreign. Every callback
 * attacks its world (create, destroy, step, set, draw: each must get
 * TB_ERR_LOCKED and change nothing) and nests queries.
 *
 * After every command:
 * - a refused call left every live world's hash as it was, with a message;
 * - the counts of each world equal the objects the harness knows to be alive,
 *   every one of their handles is valid, every destroyed one (also of a
 *   destroyed world, whatever was created since) invalid and refused with
 *   TB_ERR_STALE_HANDLE;
 * - after a step, every body state is finite and within the engine's limits
 *   (TB_MAX_LENGTH, TB_MAX_VALUE, the world's speed caps).
 * Determinism: the stream is replayed with dummy worlds occupying the first
 * world slots, so every world lands in another slot; the hashes of all worlds
 * after every command must be the same.
 *
 * fuzz/api_coverage.sh lists the functions of the header this file never
 * names (it must list none); make fuzz-coverage measures what the corpus
 * really calls. */
#include <float.h>

#include "fuzz_common.h"

/* Invariants that fail on defects of issue 23 that other branches fix. Each is
 * on by default; mk/fuzz.mk turns off (-D...=0) the ones whose fix is not
 * merged yet, so that make fuzz-smoke tests the rest. The reproducers are in
 * fuzz/known_bugs/. */
#ifndef FUZZ_CHECK_SPEED_CAP /* issue 23 items 3 and 5: free bodies ignore the speed caps; 1 s steps explode */
#define FUZZ_CHECK_SPEED_CAP 1
#endif
#ifndef FUZZ_CHECK_TINY_STEP /* issue 23 item 6: a 1e-45 s step is accepted, then fails as TB_ERR_NUMERIC */
#define FUZZ_CHECK_TINY_STEP 1
#endif
#ifndef FUZZ_CHECK_ENGINE_LIMITS /* item 7: states beyond TB_MAX_LENGTH / TB_MAX_VALUE, inf energy */
#define FUZZ_CHECK_ENGINE_LIMITS 1
#endif
#ifndef FUZZ_CHECK_REFUSED_CHAIN /* item 4: a refused tb_create_chain changes the hash */
#define FUZZ_CHECK_REFUSED_CHAIN 1
#endif
#ifndef FUZZ_CHECK_DRAW_VALUES /* item 9: draw bounds of 1e30 and NaN colours accepted */
#define FUZZ_CHECK_DRAW_VALUES 1
#endif
#ifndef FUZZ_CHECK_MIX_RESULTS /* item 9: mix callbacks returning -1 or NaN used without a check */
#define FUZZ_CHECK_MIX_RESULTS 1
#endif
#ifndef FUZZ_CHECK_FIELD_STATE /* item 8: the force field sees non-finite states */
#define FUZZ_CHECK_FIELD_STATE 1
#endif

#ifndef FUZZ_CHECK_USER_DATA_LOCKED /* new: world, shape and joint user data can be set from a callback */
#define FUZZ_CHECK_USER_DATA_LOCKED 1
#endif

#define MAX_WORLDS 3          /* live at once in one run */
#define MAX_WORLD_CREATIONS 6 /* per run: each world slot holds 65,536 worlds in its life */
#define MAX_BODIES 16
#define MAX_SHAPES 32
#define MAX_JOINTS 12
#define MAX_CHAINS 3
#define MAX_STEPS 40
#define MAX_COMMANDS 200
#define GRAVE 8 /* destroyed handles kept per kind */

struct model;

typedef struct world_model {
  bool alive;
  tb_world_id id;
  tb_body_id bodies[MAX_BODIES];
  int body_count;
  tb_shape_id shapes[MAX_SHAPES];
  int shape_count;
  tb_joint_id joints[MAX_JOINTS];
  int joint_count;
  tb_chain_id chains[MAX_CHAINS];
  int chain_count;
  float max_speed; /* the world's maximum_linear_speed (no getter) */
  uint32_t rng;    /* the callbacks' choices: the same on every replay */
  tb_vec2 field;   /* the force field's acceleration, or force when field_is_force */
  bool field_is_force;
  int mix_mode; /* 0 sane, 1..3: the mix callbacks return bad values */
  struct model* owner;
} world_model;

typedef struct graveyard {
  tb_world_id worlds[GRAVE];
  tb_body_id bodies[GRAVE];
  tb_shape_id shapes[GRAVE];
  tb_joint_id joints[GRAVE];
  tb_chain_id chains[GRAVE];
  int world_count, body_count, shape_count, joint_count, chain_count; /* total ever buried */
} graveyard;

#define MAX_TREE_PROXIES 24

/* The game's own dynamic tree (tb_dynamic_tree) and what the harness knows of it. */
typedef struct tree_model {
  tb_dynamic_tree* tree;
  int32_t ids[MAX_TREE_PROXIES];
  int32_t dead[GRAVE]; /* destroyed ids (ids may be handed out again: only until then) */
  int count, dead_count;
  int depth; /* nested queries */
  struct model* owner;
} tree_model;

typedef struct model {
  world_model worlds[MAX_WORLDS];
  tree_model tree;
  graveyard dead;
  int world_creations;
  int steps;
  int attack_budget; /* callback attacks left in this command (they hash the world twice) */
  int depth;         /* nesting of queries inside callbacks */
  bool check;
} model;

/* ---- input ---------------------------------------------------------------- */

static int pick(fuzz_input* in, int n) { return n > 0 ? fuzz_u8(in) % n : -1; }

/* A coordinate: usually in [lo, hi], now and then at or just inside
 * +-TB_MAX_LENGTH (legal), and now and then a value no call may accept. */
static float fuzz_pos(fuzz_input* in, float lo, float hi) {
  static const float edge[] = {TB_MAX_LENGTH, -TB_MAX_LENGTH, 0.999f * TB_MAX_LENGTH, -0.5f * TB_MAX_LENGTH,
                               1.0e6f,        -1.0e3f,        1.001f * TB_MAX_LENGTH, 1.0e-3f};
  uint8_t k = fuzz_u8(in);
  if (k >= 248) return edge[k - 248];
  return fuzz_real(in, lo, hi);
}

/* A size (radius, half extent, length): now and then 1 mm, 1 km or the limits. */
static float fuzz_size(fuzz_input* in, float lo, float hi) {
  static const float edge[] = {1.0e-3f, 1.0e3f, TB_MAX_LENGTH, 1.0e-3f, 1.0e3f, 0.5f * TB_LINEAR_SLOP, 1.0e-6f, 2e3f};
  uint8_t k = fuzz_u8(in);
  if (k >= 248) return edge[k - 248];
  return fuzz_real(in, lo, hi);
}

/* Any other quantity (velocity, force, density, hertz...): now and then at
 * TB_MAX_VALUE, the largest legal magnitude, or just beyond it. */
static float fuzz_value(fuzz_input* in, float lo, float hi) {
  static const float edge[] = {TB_MAX_VALUE, -TB_MAX_VALUE,       1.0e9f, -1.0e9f, 1.0e-20f,
                               1.0e12f,      1.5f * TB_MAX_VALUE, FLT_MIN};
  uint8_t k = fuzz_u8(in);
  if (k >= 248) return edge[k - 248];
  return fuzz_real(in, lo, hi);
}

static tb_vec2 fuzz_point(fuzz_input* in) { return (tb_vec2){fuzz_pos(in, -20, 20), fuzz_pos(in, -5, 30)}; }

static tb_vec2 fuzz_vector(fuzz_input* in, float m) { return (tb_vec2){fuzz_value(in, -m, m), fuzz_value(in, -m, m)}; }

static bool fuzz_bool(fuzz_input* in) { return fuzz_u8(in) & 1; }

/* xorshift32: the callbacks' choices, seeded from the input at world creation. */
static uint32_t next_rng(world_model* wm) {
  uint32_t x = wm->rng;
  x ^= x << 13, x ^= x >> 17, x ^= x << 5;
  return wm->rng = x ? x : 0x9e3779b9u;
}

/* ---- bookkeeping --------------------------------------------------------- */

static void bury_body(graveyard* g, tb_body_id b) { g->bodies[g->body_count++ % GRAVE] = b; }
static void bury_shape(graveyard* g, tb_shape_id s) { g->shapes[g->shape_count++ % GRAVE] = s; }
static void bury_joint(graveyard* g, tb_joint_id j) { g->joints[g->joint_count++ % GRAVE] = j; }
static void bury_chain(graveyard* g, tb_chain_id c) { g->chains[g->chain_count++ % GRAVE] = c; }
static int buried(int total) { return total < GRAVE ? total : GRAVE; }

/* Forget handles that died with their body (shapes, joints, chains). */
static void prune(world_model* wm, graveyard* g) {
  int k = 0;
  for (int i = 0; i < wm->shape_count; ++i)
    if (tb_shape_is_valid(wm->shapes[i]))
      wm->shapes[k++] = wm->shapes[i];
    else
      bury_shape(g, wm->shapes[i]);
  wm->shape_count = k;
  k = 0;
  for (int i = 0; i < wm->joint_count; ++i)
    if (tb_joint_is_valid(wm->joints[i]))
      wm->joints[k++] = wm->joints[i];
    else
      bury_joint(g, wm->joints[i]);
  wm->joint_count = k;
  k = 0;
  for (int i = 0; i < wm->chain_count; ++i)
    if (tb_chain_is_valid(wm->chains[i]))
      wm->chains[k++] = wm->chains[i];
    else
      bury_chain(g, wm->chains[i]);
  wm->chain_count = k;
}

/* The hashes of all worlds, in the model's order (not the slots'). */
static void hash_all(const model* m, uint64_t out[MAX_WORLDS]) {
  for (int i = 0; i < MAX_WORLDS; ++i) out[i] = m->worlds[i].alive ? tb_world_hash(m->worlds[i].id) : 0;
}

/* ---- callbacks ----------------------------------------------------------- */

static void nested_query(world_model* wm);

/* A change of the world from inside one of its callbacks: refused with
 * TB_ERR_LOCKED, and nothing changes. */
static void attack(world_model* wm, const char* where) {
  model* m = wm->owner;
  if (m->attack_budget <= 0) return;
  m->attack_budget -= 1;
  tb_world_id w = wm->id;
  uint64_t before = tb_world_hash(w);
  tb_body_id body = wm->body_count > 0 ? wm->bodies[next_rng(wm) % wm->body_count] : (tb_body_id){0, 0, 0};
  tb_shape_id shape = wm->shape_count > 0 ? wm->shapes[next_rng(wm) % wm->shape_count] : (tb_shape_id){0, 0, 0};
  tb_joint_id joint = wm->joint_count > 0 ? wm->joints[next_rng(wm) % wm->joint_count] : (tb_joint_id){0, 0, 0};
  tb_chain_id chain = wm->chain_count > 0 ? wm->chains[next_rng(wm) % wm->chain_count] : (tb_chain_id){0, 0, 0};
  bool have = true; /* the target exists: a null handle is refused as stale first */
  tb_result r = TB_ERR_LOCKED;
  const char* what = "";
  /* 25..27 (user data) only while their check is on: a refused-or-not call
   * that changes the hash would fail the hash check below */
  uint32_t op = next_rng(wm) % (FUZZ_CHECK_USER_DATA_LOCKED ? 28 : 25);
  switch (op) {
    case 0: {
      tb_body_def bd = tb_default_body_def();
      bd.type = TB_DYNAMIC_BODY;
      what = "tb_create_body";
      r = tb_body_id_is_null(tb_create_body(w, &bd)) ? tb_last_result() : TB_OK;
      break;
    }
    case 1: what = "tb_destroy_body", have = wm->body_count > 0, r = tb_destroy_body(body); break;
    case 2: what = "tb_world_step", r = tb_world_step(w, 1.0f / 60.0f, 4); break;
    case 3: what = "tb_world_set_gravity", r = tb_world_set_gravity(w, (tb_vec2){0, 10}); break;
    case 4: what = "tb_destroy_world", r = tb_destroy_world(w); break;
    case 5: {
      tb_shape_def sd = tb_default_shape_def();
      tb_circle c = {{0, 0}, 0.5f};
      what = "tb_create_circle_shape", have = wm->body_count > 0;
      r = tb_shape_id_is_null(tb_create_circle_shape(body, &sd, &c)) ? tb_last_result() : TB_OK;
      break;
    }
    case 6: what = "tb_destroy_shape", have = wm->shape_count > 0, r = tb_destroy_shape(shape); break;
    case 7:
      what = "tb_body_set_transform", have = wm->body_count > 0, r = tb_body_set_transform(body, (tb_vec2){1, 1}, 1);
      break;
    case 8: {
      what = "tb_create_revolute_joint", have = wm->body_count > 1;
      tb_revolute_joint_def d = tb_default_revolute_joint_def();
      if (!have) break;
      d.body_a = wm->bodies[0], d.body_b = wm->bodies[wm->body_count - 1];
      r = tb_joint_id_is_null(tb_create_revolute_joint(w, &d)) ? tb_last_result() : TB_OK;
      break;
    }
    case 9: what = "tb_destroy_joint", have = wm->joint_count > 0, r = tb_destroy_joint(joint); break;
    case 10: {
      tb_vec2 pts[3] = {{-5, 0}, {0, 1}, {5, 0}};
      tb_chain_def cd = tb_default_chain_def();
      cd.points = pts, cd.count = 3;
      what = "tb_create_chain", have = wm->body_count > 0;
      r = tb_chain_id_is_null(tb_create_chain(body, &cd)) ? tb_last_result() : TB_OK;
      break;
    }
    case 11: what = "tb_destroy_chain", have = wm->chain_count > 0, r = tb_destroy_chain(chain); break;
    case 12: what = "tb_shape_set_friction", have = wm->shape_count > 0, r = tb_shape_set_friction(shape, 0.1f); break;
    case 13: what = "tb_shape_set_density", have = wm->shape_count > 0, r = tb_shape_set_density(shape, 3); break;
    case 14:
      what = "tb_body_apply_linear_impulse_to_center", have = wm->body_count > 0;
      r = tb_body_apply_linear_impulse_to_center(body, (tb_vec2){1, 0});
      break;
    case 15: what = "tb_body_set_type", have = wm->body_count > 0, r = tb_body_set_type(body, TB_STATIC_BODY); break;
    case 16:
      what = "tb_joint_set_collide_connected", have = wm->joint_count > 0;
      r = tb_joint_set_collide_connected(joint, true);
      break;
    case 17:
      what = "tb_mouse_joint_set_target", have = wm->joint_count > 0;
      r = tb_mouse_joint_set_target(joint, (tb_vec2){0, 0});
      if (have && tb_joint_get_type(joint) != TB_JOINT_MOUSE) r = TB_ERR_LOCKED; /* wrong type may be checked first */
      break;
    case 18: {
      tb_debug_draw dd = tb_default_debug_draw();
      what = "tb_world_draw", r = tb_world_draw(w, &dd);
      break;
    }
    case 19: what = "tb_world_set_pre_solve", r = tb_world_set_pre_solve(w, NULL, NULL); break;
    case 20: what = "tb_world_set_force_field", r = tb_world_set_force_field(w, NULL, NULL); break;
    case 21: what = "tb_world_enable_sleeping", r = tb_world_enable_sleeping(w, false); break;
    case 22: what = "tb_body_set_awake", have = wm->body_count > 0, r = tb_body_set_awake(body, false); break;
    case 23: what = "tb_world_set_maximum_linear_speed", r = tb_world_set_maximum_linear_speed(w, 1.0f); break;
    case 24: {
      tb_circle c = {{0, 0}, 0.3f};
      what = "tb_shape_set_circle", have = wm->shape_count > 0, r = tb_shape_set_circle(shape, &c);
      break;
    }
    case 25:
      what = "tb_world_set_user_data", r = tb_world_set_user_data(w, tb_world_get_user_data(w) ? NULL : wm);
      break;
    case 26:
      what = "tb_shape_set_user_data", have = wm->shape_count > 0;
      r = tb_shape_set_user_data(shape, tb_shape_get_user_data(shape) ? NULL : wm);
      break;
    default:
      what = "tb_joint_set_user_data", have = wm->joint_count > 0;
      r = tb_joint_set_user_data(joint, tb_joint_get_user_data(joint) ? NULL : wm);
  }
  if (m->check && have)
    FUZZ_CHECK(r == TB_ERR_LOCKED, "%s from the %s callback: %s (%s)", what, where, tb_result_name(r), tb_last_error());
  if (m->check)
    FUZZ_CHECK(tb_world_hash(w) == before, "%s from the %s callback changed the world (%s)", what, where,
               tb_result_name(r));
  tb_clear_error();
}

/* Force field: a uniform acceleration; it checks what it is shown. */
static void field_fn(double time, const tb_body_state* st, void* context, tb_vec2* force, float* torque) {
  world_model* wm = context;
  (void)time;
#if FUZZ_CHECK_FIELD_STATE
  if (wm->owner->check)
    FUZZ_CHECK(fuzz_vec_finite(st->center) && fuzz_vec_finite(st->linear_velocity) && isfinite(st->angle) &&
                   isfinite(st->angular_velocity) && st->mass > 0 && isfinite(st->mass),
               "the force field saw a non-finite state: v = (%g, %g), w = %g", (double)st->linear_velocity.x,
               (double)st->linear_velocity.y, (double)st->angular_velocity);
#endif
  if ((next_rng(wm) & 7) == 0) attack(wm, "force field");
  float scale = wm->field_is_force ? 1.0f : st->mass;
  *force = (tb_vec2){scale * wm->field.x, scale * wm->field.y};
  *torque = -0.01f * st->angular_velocity;
}

static bool filter_fn(tb_shape_id a, tb_shape_id b, void* context) {
  world_model* wm = context;
  if (wm->owner->check) FUZZ_CHECK(tb_shape_is_valid(a) && tb_shape_is_valid(b), "custom filter: a dead shape");
  uint32_t k = next_rng(wm);
  if ((k & 3) == 0) attack(wm, "custom filter");
  if ((k & 12) == 0) nested_query(wm);
  return (k & 0xf0) != 0;
}

static bool pre_solve_fn(tb_shape_id a, tb_shape_id b, const struct tb_manifold* mf, void* context) {
  world_model* wm = context;
  if (wm->owner->check) {
    FUZZ_CHECK(tb_shape_is_valid(a) && tb_shape_is_valid(b), "pre-solve: a dead shape");
    FUZZ_CHECK(mf != NULL && mf->point_count >= 0 && mf->point_count <= 2 && fuzz_vec_finite(mf->normal),
               "pre-solve: bad manifold");
  }
  uint32_t k = next_rng(wm);
  if ((k & 3) == 0) attack(wm, "pre-solve");
  if ((k & 12) == 0) nested_query(wm);
  return (k & 0x30) != 0;
}

/* Mixing rules; mix_mode makes them return what no contact can use. */
static float mix(world_model* wm, float sane, const char* where) {
  if ((next_rng(wm) & 7) == 0) attack(wm, where);
  static const float bad[] = {0, -1.0f, NAN, 1.0e30f};
  return wm->mix_mode == 0 || (next_rng(wm) & 3) ? sane : bad[wm->mix_mode];
}
static float friction_mix_fn(float a, float b, void* context) { return mix(context, sqrtf(a * b), "friction mix"); }
static float restitution_mix_fn(float a, float b, void* context) {
  return mix(context, a > b ? a : b, "restitution mix");
}

static bool overlap_fn(tb_shape_id shape, void* context) {
  world_model* wm = context;
  if (wm->owner->check) FUZZ_CHECK(tb_shape_is_valid(shape), "a query reported a dead shape");
  uint32_t k = next_rng(wm);
  if ((k & 3) == 0) attack(wm, "overlap");
  if ((k & 12) == 0) nested_query(wm);
  return (k & 0x70) != 0;
}

static float cast_fn(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  world_model* wm = context;
  if (wm->owner->check)
    FUZZ_CHECK(tb_shape_is_valid(shape) && fuzz_vec_finite(point) && fuzz_vec_finite(normal) && fraction >= 0.0f &&
                   fraction <= 1.0f,
               "bad cast hit: fraction %g", (double)fraction);
  uint32_t k = next_rng(wm);
  if ((k & 3) == 0) attack(wm, "cast");
  if ((k & 12) == 0) nested_query(wm);
  static const float answers[4] = {-1.0f, 0.0f, 1.0f, 0.5f};
  return (k & 0x30) == 0x30 ? answers[(k >> 8) & 3] : fraction;
}

/* A query from inside a callback: reads are allowed at any depth. */
static void nested_query(world_model* wm) {
  model* m = wm->owner;
  if (m->depth >= 2) return;
  m->depth += 1;
  tb_query_filter f = tb_default_query_filter();
  tb_vec2 o = {(float)(next_rng(wm) % 40) - 20.0f, (float)(next_rng(wm) % 30) - 5.0f};
  tb_vec2 t = {(float)(next_rng(wm) % 20) - 10.0f, -10.0f};
  tb_result r = TB_OK;
  switch (next_rng(wm) % 4) {
    case 0: r = tb_world_cast_ray(wm->id, o, t, f, cast_fn, wm); break;
    case 1: r = tb_world_overlap_aabb(wm->id, (tb_aabb){o, {o.x + 3, o.y + 3}}, f, overlap_fn, wm); break;
    case 2: r = tb_world_overlap_point(wm->id, o, f, overlap_fn, wm); break;
    default: {
      tb_shape_proxy proxy = {{{0, 0}, {1, 0}, {0, 1}}, 3, 0.1f};
      r = tb_world_overlap_shape(wm->id, &proxy, (tb_transform){o, {1, 0}}, f, overlap_fn, wm);
    }
  }
  if (m->check) FUZZ_CHECK(r == TB_OK, "a nested query was refused: %s", tb_last_error());
  m->depth -= 1;
}

/* Debug draw callbacks: what they are handed must be drawable. */
static void check_color(world_model* wm, tb_color c) {
#if FUZZ_CHECK_DRAW_VALUES
  if (wm->owner->check)
    FUZZ_CHECK(c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1 && c.a >= 0 && c.a <= 1,
               "draw: colour (%g, %g, %g, %g)", (double)c.r, (double)c.g, (double)c.b, (double)c.a);
#else
  (void)wm, (void)c;
#endif
}
static void check_drawn(world_model* wm, bool ok, const char* what) {
  if (wm->owner->check) FUZZ_CHECK(ok, "draw: %s", what);
  uint32_t k = next_rng(wm);
  if ((k & 7) == 0) attack(wm, "draw");
  if ((k & 24) == 0) nested_query(wm);
}
static bool xf_finite(tb_transform x) { return fuzz_vec_finite(x.p) && isfinite(x.q.c) && isfinite(x.q.s); }
static void draw_polygon(tb_transform x, const tb_vec2* v, int n, float radius, tb_color c, void* ctx) {
  bool ok = xf_finite(x) && n >= 3 && n <= TB_MAX_POLYGON_VERTICES && radius >= 0 && isfinite(radius);
  for (int i = 0; ok && i < n; ++i) ok = fuzz_vec_finite(v[i]);
  check_color(ctx, c);
  check_drawn(ctx, ok, "polygon");
}
static void draw_circle(tb_transform x, float radius, tb_color c, void* ctx) {
  check_color(ctx, c);
  check_drawn(ctx, xf_finite(x) && radius > 0 && isfinite(radius), "circle");
}
static void draw_capsule(tb_vec2 p1, tb_vec2 p2, float radius, tb_color c, void* ctx) {
  check_color(ctx, c);
  check_drawn(ctx, fuzz_vec_finite(p1) && fuzz_vec_finite(p2) && radius > 0 && isfinite(radius), "capsule");
}
static void draw_segment(tb_vec2 p1, tb_vec2 p2, tb_color c, void* ctx) {
  check_color(ctx, c);
  check_drawn(ctx, fuzz_vec_finite(p1) && fuzz_vec_finite(p2), "segment");
}
static void draw_point(tb_vec2 p, float size, tb_color c, void* ctx) {
  check_color(ctx, c);
  check_drawn(ctx, fuzz_vec_finite(p) && size > 0 && isfinite(size), "point");
}
static void draw_transform(tb_transform x, void* ctx) { check_drawn(ctx, xf_finite(x), "transform"); }
static void draw_string(tb_vec2 p, const char* text, tb_color c, void* ctx) {
  check_color(ctx, c);
  check_drawn(ctx, fuzz_vec_finite(p) && text != NULL && strlen(text) < 256, "string");
}

/* ---- worlds -------------------------------------------------------------- */

static void bury_world(model* m, world_model* wm) {
  graveyard* g = &m->dead;
  g->worlds[g->world_count++ % GRAVE] = wm->id;
  for (int i = 0; i < wm->body_count; ++i) bury_body(g, wm->bodies[i]);
  for (int i = 0; i < wm->shape_count; ++i) bury_shape(g, wm->shapes[i]);
  for (int i = 0; i < wm->joint_count; ++i) bury_joint(g, wm->joints[i]);
  for (int i = 0; i < wm->chain_count; ++i) bury_chain(g, wm->chains[i]);
  memset(wm, 0, sizeof *wm);
}

/* A world from the input: settings, extremes and callbacks. Returns the result
 * of tb_create_world. */
static tb_result create_world(model* m, world_model* wm, fuzz_input* in, bool plain) {
  if (m->world_creations >= MAX_WORLD_CREATIONS) return TB_OK;
  tb_world_def wd = tb_default_world_def();
  memset(wm, 0, sizeof *wm);
  wm->owner = m;
  wm->rng = 0x2545f491u ^ fuzz_u16(in);
  if (!plain) {
    uint8_t set = fuzz_u8(in), callbacks = fuzz_u8(in);
    if (set & 1) wd.gravity = fuzz_vector(in, 30);
    if (set & 2) wd.integrator = (tb_integrator)(fuzz_u8(in) % 4);
    if (set & 4) {
      wd.contact_hertz = fuzz_value(in, 1, 240);
      wd.contact_damping_ratio = fuzz_value(in, 0, 20);
      wd.contact_push_max_velocity = fuzz_value(in, 0, 10);
    }
    if (set & 8) wd.relax_iterations = (int)fuzz_u8(in) % (TB_MAX_RELAX_ITERATIONS + 2);
    if (set & 16) wd.joint_hertz = fuzz_value(in, 0, 120), wd.joint_damping_ratio = fuzz_value(in, 0, 5);
    if (set & 32) wd.restitution_threshold = fuzz_value(in, 0, 5), wd.hit_event_threshold = fuzz_value(in, 0, 5);
    if (set & 64) wd.maximum_linear_speed = fuzz_value(in, 0.1f, 2000);
    if (set & 128) {
      uint8_t b = fuzz_u8(in);
      wd.enable_sleep = b & 1, wd.enable_continuous = b & 2, wd.enable_warm_starting = b & 4;
      wd.enable_profile = b & 8;
    }
    wd.user_data = (callbacks & 128) ? wm : NULL;
    if (callbacks & 1) {
      wd.force_field = field_fn, wd.force_field_context = wm;
      wm->field = (tb_vec2){fuzz_value(in, -20, 20), fuzz_value(in, -20, 20)};
      wm->field_is_force = set & 64;
    }
    if (callbacks & 2) wd.custom_filter = filter_fn, wd.custom_filter_context = wm;
    if (callbacks & 4) wd.pre_solve = pre_solve_fn, wd.pre_solve_context = wm;
    if (callbacks & 8) wd.friction_mix = friction_mix_fn, wd.mix_context = wm;
    if (callbacks & 16) wd.restitution_mix = restitution_mix_fn, wd.mix_context = wm;
    if (callbacks & 32) wm->mix_mode = 1 + (callbacks >> 6) % 3;
  }
  m->world_creations += 1;
  tb_world_id id = tb_create_world(&wd);
  if (tb_world_id_is_null(id)) {
    tb_result r = tb_last_result();
    if (r == TB_ERR_CAPACITY) { /* every world slot retired: some 1.5 million inputs in one process */
      static bool told = false;
      if (!told) fprintf(stderr, "fuzz_api: all world slots are retired, inputs test nothing more: restart\n");
      told = true;
      return TB_OK;
    }
    if (m->check) FUZZ_CHECK(r != TB_OK && strlen(tb_last_error()) > 0, "tb_create_world refused without a message");
    return r;
  }
  wm->alive = true;
  wm->id = id;
  wm->max_speed = wd.maximum_linear_speed;
  if (m->check) {
    FUZZ_CHECK(tb_world_is_valid(id), "a new world is invalid");
    for (int i = 0; i < buried(m->dead.world_count); ++i)
      FUZZ_CHECK(memcmp(&m->dead.worlds[i], &id, sizeof id) != 0, "a world handle was handed out twice");
  }
  return TB_OK;
}

static world_model* pick_world(model* m, fuzz_input* in) {
  int k = pick(in, MAX_WORLDS);
  for (int i = 0; i < MAX_WORLDS; ++i) {
    world_model* wm = &m->worlds[(k + i) % MAX_WORLDS];
    if (wm->alive) return wm;
  }
  return NULL;
}

/* ---- commands ------------------------------------------------------------ */

static void add_shape(world_model* wm, tb_shape_id s) {
  if (!tb_shape_id_is_null(s) && wm->shape_count < MAX_SHAPES) wm->shapes[wm->shape_count++] = s;
}

static tb_shape_def shape_def(fuzz_input* in) {
  tb_shape_def sd = tb_default_shape_def();
  uint8_t b = fuzz_u8(in);
  sd.density = fuzz_value(in, 0, 5);
  sd.friction = fuzz_real(in, 0, 1);
  sd.restitution = (b & 64) ? fuzz_value(in, 0, 2) : fuzz_range(in, 0, 1);
  sd.rolling_resistance = (b & 32) ? fuzz_real(in, 0, 0.5f) : 0.0f;
  sd.tangent_speed = (b & 16) ? fuzz_value(in, -5, 5) : 0.0f;
  sd.is_sensor = (b & 7) == 0;
  sd.enable_hit_events = b & 8;
  sd.enable_pre_solve_events = !(b & 128);
  sd.enable_sensor_events = b & 2;
  sd.filter.group_index = (int8_t)fuzz_u8(in) % 3;
  return sd;
}

/* Geometry of any type from the input, now and then bad or degenerate. */
typedef struct fuzz_geometry {
  tb_shape_type type;
  tb_circle circle;
  tb_capsule capsule;
  tb_segment segment;
  tb_polygon polygon;
} fuzz_geometry;

/* false when tb_make_* refused the polygon (no world is involved then). */
static bool make_geometry(fuzz_input* in, fuzz_geometry* g) {
  tb_result made = TB_OK;
  g->type = TB_SHAPE_POLYGON;
  switch (fuzz_u8(in) % 7) {
    case 0:
      g->type = TB_SHAPE_CIRCLE;
      g->circle = (tb_circle){{fuzz_pos(in, -1, 1), fuzz_pos(in, -1, 1)}, fuzz_size(in, 0.02f, 2)};
      break;
    case 1: {
      float r = fuzz_size(in, 0.02f, 1);
      g->type = TB_SHAPE_CAPSULE;
      g->capsule = (tb_capsule){{fuzz_pos(in, -1, 1), 0}, {fuzz_pos(in, -1, 1), fuzz_size(in, 0, 1)}, r};
      break;
    }
    case 2:
      g->type = TB_SHAPE_SEGMENT;
      g->segment = (tb_segment){{fuzz_pos(in, -2, 2), fuzz_pos(in, -2, 2)}, {fuzz_pos(in, -2, 2), fuzz_pos(in, -2, 2)}};
      break;
    case 3: {
      tb_vec2 pts[TB_MAX_POLYGON_VERTICES + 1];
      int n = 3 + fuzz_u8(in) % (TB_MAX_POLYGON_VERTICES - 1);
      float scale = fuzz_size(in, 0.1f, 2);
      for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){scale * fuzz_range(in, -1, 1), scale * fuzz_range(in, -1, 1)};
      made = tb_make_polygon(pts, n, fuzz_u8(in) & 1 ? fuzz_size(in, 0, 0.1f) : 0.0f, &g->polygon);
      break;
    }
    case 4: made = tb_make_box(fuzz_size(in, 0.05f, 2), fuzz_size(in, 0.05f, 2), &g->polygon); break;
    case 5:
      made =
          tb_make_offset_box(fuzz_size(in, 0.05f, 1), fuzz_size(in, 0.05f, 1),
                             (tb_vec2){fuzz_pos(in, -1, 1), fuzz_pos(in, -1, 1)}, fuzz_value(in, -4, 4), &g->polygon);
      break;
    default:
      made = tb_make_rounded_box(fuzz_size(in, 0.05f, 1), fuzz_size(in, 0.05f, 1), fuzz_size(in, 0, 0.2f), &g->polygon);
  }
  return made == TB_OK;
}

static tb_result create_shape(world_model* wm, fuzz_input* in, tb_body_id body) {
  tb_shape_def sd = shape_def(in);
  fuzz_geometry g;
  if (!make_geometry(in, &g)) return TB_OK; /* refused geometry: nothing to add, no world involved */
  tb_shape_id s = {0, 0, 0};
  switch (g.type) {
    case TB_SHAPE_CIRCLE: s = tb_create_circle_shape(body, &sd, &g.circle); break;
    case TB_SHAPE_CAPSULE: s = tb_create_capsule_shape(body, &sd, &g.capsule); break;
    case TB_SHAPE_SEGMENT: s = tb_create_segment_shape(body, &sd, &g.segment); break;
    default: s = tb_create_polygon_shape(body, &sd, &g.polygon);
  }
  if (tb_shape_id_is_null(s)) return tb_last_result();
  add_shape(wm, s);
  return TB_OK;
}

/* A shape's geometry replaced in place (tb_shape_set_*): on success the shape
 * has the new type and geometry, its body a finite mass. */
static tb_result set_geometry(tb_shape_id s, fuzz_input* in) {
  fuzz_geometry g, back;
  if (!make_geometry(in, &g)) return tb_shape_set_polygon(s, NULL); /* refused: a NULL polygon then */
  tb_result r, got = TB_OK;
  switch (g.type) {
    case TB_SHAPE_CIRCLE:
      r = tb_shape_set_circle(s, &g.circle);
      if (r == TB_OK) got = tb_shape_get_circle(s, &back.circle);
      if (r == TB_OK) FUZZ_CHECK(memcmp(&back.circle, &g.circle, sizeof g.circle) == 0, "set circle: not kept");
      break;
    case TB_SHAPE_CAPSULE:
      r = tb_shape_set_capsule(s, &g.capsule);
      if (r == TB_OK) got = tb_shape_get_capsule(s, &back.capsule);
      if (r == TB_OK) FUZZ_CHECK(memcmp(&back.capsule, &g.capsule, sizeof g.capsule) == 0, "set capsule: not kept");
      break;
    case TB_SHAPE_SEGMENT:
      r = tb_shape_set_segment(s, &g.segment);
      if (r == TB_OK) got = tb_shape_get_segment(s, &back.segment);
      if (r == TB_OK) FUZZ_CHECK(memcmp(&back.segment, &g.segment, sizeof g.segment) == 0, "set segment: not kept");
      break;
    default:
      r = tb_shape_set_polygon(s, &g.polygon);
      if (r == TB_OK) got = tb_shape_get_polygon(s, &back.polygon);
      if (r == TB_OK) FUZZ_CHECK(memcmp(&back.polygon, &g.polygon, sizeof g.polygon) == 0, "set polygon: not kept");
  }
  if (r != TB_OK) return r;
  tb_body_id body = tb_shape_get_body(s);
  float mass = tb_body_get_mass(body);
  FUZZ_CHECK(got == TB_OK && tb_shape_get_type(s) == g.type, "set geometry: type %d, want %d",
             (int)tb_shape_get_type(s), (int)g.type);
  FUZZ_CHECK(isfinite(mass) && mass >= 0 && isfinite(tb_body_get_rotational_inertia(body)) &&
                 (tb_body_get_type(body) != TB_DYNAMIC_BODY || mass > 0),
             "set geometry: body mass %g", (double)mass);
  return r;
}

/* One shape's own queries (tb_shape_test_point, _ray_cast, _get_closest_point):
 * a contained point is its own closest point, hits lie on the ray. Returns the
 * last refusal (TB_OK when none). */
static tb_result shape_queries(tb_shape_id s, fuzz_input* in) {
  tb_vec2 p = fuzz_point(in), t = {fuzz_pos(in, -30, 30), fuzz_pos(in, -30, 30)};
  tb_clear_error();
  bool inside = tb_shape_test_point(s, p);
  bool point_ok = tb_last_result() == TB_OK;
  tb_vec2 c = tb_shape_get_closest_point(s, p);
  if (point_ok && tb_shape_is_valid(s)) {
    float scale = 1e-4f * (1.0f + fmaxf(fabsf(p.x), fabsf(p.y)));
    FUZZ_CHECK(fuzz_vec_finite(c), "closest point not finite");
    if (inside)
      FUZZ_CHECK(fabsf(c.x - p.x) <= scale && fabsf(c.y - p.y) <= scale,
                 "a contained point (%g, %g) has another closest point (%g, %g)", (double)p.x, (double)p.y, (double)c.x,
                 (double)c.y);
  }
  tb_ray_result rr = tb_shape_ray_cast(s, p, t);
  if (rr.hit) {
    FUZZ_CHECK(tb_shape_id_equal(rr.shape, s) && rr.fraction >= 0.0f && rr.fraction <= 1.0f &&
                   fuzz_vec_finite(rr.point) && fuzz_vec_finite(rr.normal),
               "shape ray hit: fraction %g", (double)rr.fraction);
  } else {
    FUZZ_CHECK(rr.fraction == 1.0f && tb_shape_id_is_null(rr.shape), "shape ray miss");
  }
  return tb_last_result();
}

static tb_body_id pick_body(world_model* wm, model* m, fuzz_input* in) {
  int bi = pick(in, wm->body_count);
  uint8_t k = fuzz_u8(in);
  if (bi < 0 || (k & 31) == 0) { /* now and then a dead one, maybe of a dead world */
    int n = buried(m->dead.body_count);
    return n > 0 ? m->dead.bodies[k % n] : (tb_body_id){0, 0, 0};
  }
  return wm->bodies[bi];
}
static tb_shape_id pick_shape(world_model* wm, model* m, fuzz_input* in) {
  int si = pick(in, wm->shape_count);
  uint8_t k = fuzz_u8(in);
  if (si < 0 || (k & 31) == 0) {
    int n = buried(m->dead.shape_count);
    return n > 0 ? m->dead.shapes[k % n] : (tb_shape_id){0, 0, 0};
  }
  return wm->shapes[si];
}
static tb_joint_id pick_joint(world_model* wm, model* m, fuzz_input* in) {
  int ji = pick(in, wm->joint_count);
  uint8_t k = fuzz_u8(in);
  if (ji < 0 || (k & 31) == 0) {
    int n = buried(m->dead.joint_count);
    return n > 0 ? m->dead.joints[k % n] : (tb_joint_id){0, 0, 0};
  }
  return wm->joints[ji];
}

static tb_result create_joint(world_model* wm, model* m, fuzz_input* in, tb_body_id body) {
  if (wm->joint_count >= MAX_JOINTS || wm->body_count < 1) return TB_OK;
  tb_body_id other = wm->bodies[pick(in, wm->body_count)];
  uint8_t flags = fuzz_u8(in);
  if ((flags & 15) == 0) { /* a body of another world: foreign */
    world_model* ow = &m->worlds[(wm - m->worlds + 1) % MAX_WORLDS];
    if (ow->alive && ow->body_count > 0) other = ow->bodies[0];
  }
  tb_vec2 anchor = {fuzz_pos(in, -1, 1), fuzz_pos(in, -1, 1)};
  bool spring = flags & 16, limit = flags & 32, motor = flags & 64, collide = flags & 128;
  tb_joint_id j = {0, 0, 0};
  switch (fuzz_u8(in) % 7) {
    case 0: {
      tb_distance_joint_def d = tb_default_distance_joint_def();
      d.body_a = body, d.body_b = other, d.local_anchor_a = anchor, d.length = fuzz_size(in, 0.1f, 5);
      d.enable_spring = spring, d.hertz = fuzz_value(in, 0, 10), d.damping_ratio = fuzz_value(in, 0, 2);
      d.enable_limit = limit, d.min_length = fuzz_size(in, 0, 1), d.max_length = fuzz_size(in, 1, 6);
      d.enable_motor = motor, d.max_motor_force = fuzz_value(in, 0, 100), d.motor_speed = fuzz_value(in, -5, 5);
      d.collide_connected = collide;
      j = tb_create_distance_joint(wm->id, &d);
      break;
    }
    case 1: {
      tb_revolute_joint_def d = tb_default_revolute_joint_def();
      d.body_a = body, d.body_b = other, d.local_anchor_b = anchor, d.reference_angle = fuzz_value(in, -1, 1);
      d.enable_motor = motor, d.motor_speed = fuzz_value(in, -10, 10), d.max_motor_torque = fuzz_value(in, 0, 100);
      d.enable_limit = limit, d.lower_angle = -0.5f, d.upper_angle = fuzz_real(in, -1, 1);
      d.enable_spring = spring, d.hertz = fuzz_value(in, 0, 10), d.damping_ratio = fuzz_value(in, 0, 2);
      d.collide_connected = collide;
      j = tb_create_revolute_joint(wm->id, &d);
      break;
    }
    case 2: {
      tb_prismatic_joint_def d = tb_default_prismatic_joint_def();
      d.body_a = body, d.body_b = other, d.local_axis_a = anchor, d.enable_limit = limit;
      d.lower_translation = -1, d.upper_translation = fuzz_pos(in, -2, 2);
      d.enable_motor = motor, d.motor_speed = fuzz_value(in, -5, 5), d.max_motor_force = fuzz_value(in, 0, 100);
      d.enable_spring = spring, d.hertz = fuzz_value(in, 0, 10), d.damping_ratio = fuzz_value(in, 0, 2);
      d.collide_connected = collide;
      j = tb_create_prismatic_joint(wm->id, &d);
      break;
    }
    case 3: {
      tb_weld_joint_def d = tb_default_weld_joint_def();
      d.body_a = body, d.body_b = other, d.local_anchor_a = anchor, d.linear_hertz = fuzz_value(in, 0, 20);
      d.angular_hertz = spring ? fuzz_value(in, 0, 20) : 0.0f, d.reference_angle = fuzz_value(in, -1, 1);
      d.linear_damping_ratio = fuzz_value(in, 0, 2), d.angular_damping_ratio = fuzz_value(in, 0, 2);
      d.collide_connected = collide;
      j = tb_create_weld_joint(wm->id, &d);
      break;
    }
    case 4: {
      tb_wheel_joint_def d = tb_default_wheel_joint_def();
      d.body_a = body, d.body_b = other, d.local_axis_a = anchor, d.enable_motor = motor;
      d.max_motor_torque = fuzz_value(in, 0, 50), d.motor_speed = fuzz_value(in, -20, 20);
      d.enable_spring = spring, d.hertz = fuzz_value(in, 0, 10), d.damping_ratio = fuzz_value(in, 0, 2);
      d.enable_limit = limit, d.lower_translation = -0.5f, d.upper_translation = fuzz_pos(in, -1, 1);
      d.collide_connected = collide;
      j = tb_create_wheel_joint(wm->id, &d);
      break;
    }
    case 5: {
      tb_mouse_joint_def d = tb_default_mouse_joint_def();
      d.body_a = body, d.body_b = other, d.target = fuzz_point(in);
      d.hertz = fuzz_value(in, 0, 10), d.damping_ratio = fuzz_value(in, 0, 2), d.max_force = fuzz_value(in, 0, 1e4f);
      j = tb_create_mouse_joint(wm->id, &d);
      break;
    }
    default: {
      tb_motor_joint_def d = tb_default_motor_joint_def();
      d.body_a = body, d.body_b = other, d.linear_offset = anchor, d.max_force = fuzz_value(in, 0, 1000);
      d.angular_offset = fuzz_value(in, -3, 3), d.max_torque = fuzz_value(in, 0, 1000);
      d.correction_factor = fuzz_real(in, 0, 1);
      j = tb_create_motor_joint(wm->id, &d);
    }
  }
  if (tb_joint_id_is_null(j)) return tb_last_result();
  wm->joints[wm->joint_count++] = j;
  return TB_OK;
}

static tb_result joint_setter(tb_joint_id j, fuzz_input* in) {
  bool on = fuzz_bool(in);
  float a = fuzz_value(in, -5, 5), b = fuzz_value(in, 0, 10), c = fuzz_value(in, 0, 2);
  switch (fuzz_u8(in) % 17) {
    case 0: return tb_joint_set_collide_connected(j, on);
    case 1: return tb_joint_set_user_data(j, on ? &in->at : NULL);
    case 2: return tb_distance_joint_set_length(j, fuzz_size(in, 0, 5));
    case 3: return tb_distance_joint_set_spring(j, on, b, c);
    case 4: return tb_distance_joint_set_limits(j, on, fuzz_size(in, 0, 2), fuzz_size(in, 0, 6));
    case 5: return tb_revolute_joint_set_limits(j, on, -fabsf(a), fuzz_real(in, -1, 3));
    case 6: return tb_revolute_joint_set_motor(j, on, a, b);
    case 7: return tb_revolute_joint_set_spring(j, on, b, c);
    case 8: return tb_prismatic_joint_set_limits(j, on, -fabsf(a), fuzz_pos(in, -1, 3));
    case 9: return tb_prismatic_joint_set_motor(j, on, a, b);
    case 10: return tb_prismatic_joint_set_spring(j, on, b, c);
    case 11: return tb_weld_joint_set_stiffness(j, b, c, fuzz_value(in, 0, 10), fuzz_value(in, 0, 2));
    case 12: return tb_wheel_joint_set_motor(j, on, a, b);
    case 13: return tb_wheel_joint_set_spring(j, on, b, c);
    case 14: return tb_mouse_joint_set_target(j, fuzz_point(in));
    case 15: return tb_motor_joint_set_offsets(j, fuzz_vector(in, 2), a);
    default: return tb_destroy_joint(j);
  }
}

static tb_result world_setter(world_model* wm, fuzz_input* in) {
  tb_world_id w = wm->id;
  switch (fuzz_u8(in) % 14) {
    case 0: return tb_world_set_gravity(w, fuzz_vector(in, 30));
    case 1: return tb_world_set_integrator(w, (tb_integrator)(fuzz_u8(in) % 4));
    case 2: return tb_world_enable_sleeping(w, fuzz_bool(in));
    case 3: return tb_world_enable_continuous(w, fuzz_bool(in));
    case 4: return tb_world_set_relax_iterations(w, (int)(fuzz_u8(in) % (TB_MAX_RELAX_ITERATIONS + 2)));
    case 5: return tb_world_set_contact_tuning(w, fuzz_value(in, 1, 240), fuzz_value(in, 0, 20), fuzz_value(in, 0, 10));
    case 6: return tb_world_enable_warm_starting(w, fuzz_bool(in));
    case 7: return tb_world_set_joint_tuning(w, fuzz_value(in, 0, 120), fuzz_value(in, 0, 5));
    case 8: return tb_world_set_restitution_threshold(w, fuzz_value(in, 0, 5));
    case 9: {
      float s = fuzz_value(in, 0.1f, 2000);
      tb_result r = tb_world_set_maximum_linear_speed(w, s);
      if (r == TB_OK) wm->max_speed = s;
      return r;
    }
    case 10: return tb_world_set_user_data(w, fuzz_bool(in) ? wm : NULL);
    case 11: {
      bool on = fuzz_bool(in);
      if (on) wm->field = (tb_vec2){fuzz_value(in, -20, 20), fuzz_value(in, -20, 20)};
      return tb_world_set_force_field(w, on ? field_fn : NULL, wm);
    }
    case 12: return tb_world_set_pre_solve(w, fuzz_bool(in) ? pre_solve_fn : NULL, wm);
    default: { /* a bad integrator or gravity, to be refused; the profile switch (not in the hash) flips */
      (void)tb_world_enable_profile(w, !tb_world_is_profile_enabled(w));
      tb_result r = tb_world_set_integrator(w, (tb_integrator)-1);
      return r != TB_OK ? r : tb_world_set_gravity(w, (tb_vec2){NAN, 0});
    }
  }
}

static tb_result body_setter(tb_body_id body, fuzz_input* in) {
  switch (fuzz_u8(in) % 14) {
    case 0: return tb_body_set_type(body, (tb_body_type)(fuzz_u8(in) % 4));
    case 1: return tb_body_set_enabled(body, fuzz_bool(in));
    case 2: return tb_body_set_awake(body, fuzz_bool(in));
    case 3: return tb_body_set_bullet(body, fuzz_bool(in));
    case 4: return tb_body_set_fixed_rotation(body, fuzz_bool(in));
    case 5: return tb_body_set_linear_damping(body, fuzz_value(in, 0, 5));
    case 6: return tb_body_set_angular_damping(body, fuzz_value(in, 0, 5));
    case 7: return tb_body_set_gravity_scale(body, fuzz_value(in, -2, 2));
    case 8: return tb_body_enable_sleep(body, fuzz_bool(in));
    case 9: return tb_body_set_sleep_threshold(body, fuzz_value(in, 0, 1));
    case 10: return tb_body_set_user_data(body, fuzz_bool(in) ? &in->at : NULL);
    case 11: {
      tb_mass_data md = {fuzz_value(in, 0, 10), {fuzz_pos(in, -1, 1), 0}, fuzz_value(in, 0, 10)};
      return tb_body_set_mass_data(body, md);
    }
    case 12: return tb_body_reset_mass_data(body);
    default: return tb_body_set_transform(body, fuzz_point(in), fuzz_value(in, -4, 4));
  }
}

static tb_result shape_setter(tb_shape_id s, fuzz_input* in) {
  switch (fuzz_u8(in) % 9) {
    case 7: return set_geometry(s, in);
    case 8: return shape_queries(s, in);
    case 0: return tb_shape_set_density(s, fuzz_value(in, 0, 10));
    case 1: return tb_shape_set_friction(s, fuzz_value(in, 0, 2));
    case 2: return tb_shape_set_restitution(s, fuzz_value(in, 0, 1));
    case 3: return tb_shape_set_rolling_resistance(s, fuzz_value(in, 0, 1));
    case 4: {
      tb_filter f = tb_default_filter();
      f.group_index = (int8_t)fuzz_u8(in) % 3;
      f.mask_bits = fuzz_u8(in) & 1 ? UINT64_MAX : 2;
      f.category_bits = fuzz_u8(in) & 1 ? 1 : 3;
      return tb_shape_set_filter(s, f);
    }
    case 5: return tb_shape_set_user_data(s, fuzz_bool(in) ? &in->at : NULL);
    default: return tb_shape_set_tangent_speed(s, fuzz_value(in, -5, 5));
  }
}

static tb_result query(world_model* wm, fuzz_input* in) {
  tb_world_id w = wm->id;
  tb_query_filter f = tb_default_query_filter();
  f.skip_sensors = fuzz_bool(in);
  tb_vec2 o = fuzz_point(in), t = {fuzz_pos(in, -30, 30), fuzz_pos(in, -30, 30)};
  switch (fuzz_u8(in) % 7) {
    case 0: return tb_world_cast_ray(w, o, t, f, cast_fn, wm);
    case 1: {
      tb_ray_result rr = tb_world_cast_ray_closest(w, o, t, f);
      if (rr.hit)
        FUZZ_CHECK(tb_shape_is_valid(rr.shape) && fuzz_vec_finite(rr.point) && rr.fraction >= 0 && rr.fraction <= 1,
                   "ray closest hit");
      return rr.hit ? TB_OK : tb_last_result();
    }
    case 2: {
      tb_ray_result rr[4];
      int n = 0;
      tb_result r = tb_world_cast_ray_all(w, o, t, f, rr, 4, &n);
      for (int i = 0; r == TB_OK && i < n && i < 4; ++i)
        FUZZ_CHECK(tb_shape_is_valid(rr[i].shape) && fuzz_vec_finite(rr[i].point), "ray_all hit");
      return r;
    }
    case 3: {
      tb_aabb box = {{fminf(o.x, t.x), fminf(o.y, t.y)}, {fmaxf(o.x, t.x), fmaxf(o.y, t.y)}};
      return tb_world_overlap_aabb(w, box, f, overlap_fn, wm);
    }
    case 4: return tb_world_overlap_point(w, o, f, overlap_fn, wm);
    case 5: {
      tb_shape_proxy proxy = {{{0, 0}, {fuzz_size(in, 0, 2), 0}, {0, 0.5f}}, 1 + fuzz_u8(in) % 3, fuzz_size(in, 0, 1)};
      float a = fuzz_value(in, -3, 3);
      return tb_world_overlap_shape(w, &proxy, (tb_transform){o, {cosf(a), sinf(a)}}, f, overlap_fn, wm);
    }
    default: {
      tb_shape_proxy proxy = {{{0, 0}, {0.5f, 0}, {0, 0.5f}}, 3, fuzz_range(in, 0, 0.5f)};
      return tb_world_cast_shape(w, &proxy, (tb_transform){o, {1, 0}}, t, f, cast_fn, wm);
    }
  }
}

static tb_result draw(world_model* wm, fuzz_input* in) {
  tb_debug_draw dd = tb_default_debug_draw();
  uint8_t b = fuzz_u8(in), c = fuzz_u8(in);
  if (c & 1) dd.draw_solid_polygon = draw_polygon;
  if (c & 2) dd.draw_solid_circle = draw_circle;
  if (c & 4) dd.draw_solid_capsule = draw_capsule;
  if (c & 8) dd.draw_segment = draw_segment;
  if (c & 16) dd.draw_point = draw_point;
  if (c & 32) dd.draw_transform = draw_transform;
  if (c & 64) dd.draw_string = draw_string;
  dd.context = wm;
  dd.draw_shapes = b & 1, dd.draw_joints = b & 2, dd.draw_aabbs = b & 4, dd.draw_contact_points = b & 8;
  dd.draw_contact_normals = b & 16, dd.draw_centers_of_mass = b & 32, dd.draw_masses = b & 64;
  dd.use_drawing_bounds = b & 128;
  tb_vec2 lo = fuzz_point(in);
  dd.drawing_bounds = (tb_aabb){lo, {lo.x + fuzz_size(in, 0, 50), lo.y + fuzz_size(in, 0, 50)}};
  if (c & 128) {
    dd.normal_length = fuzz_value(in, 0, 1), dd.point_size = fuzz_value(in, 0, 10);
    dd.colors.awake_body.r = fuzz_real(in, 0, 1), dd.colors.joint.a = fuzz_real(in, 0, 1);
  }
  tb_result r = tb_world_draw(wm->id, (c & 127) == 127 && (b & 1) == 0 ? NULL : &dd);
#if FUZZ_CHECK_DRAW_VALUES
  bool bad_bounds =
      dd.use_drawing_bounds &&
      !(fabsf(dd.drawing_bounds.lower.x) <= TB_MAX_LENGTH && fabsf(dd.drawing_bounds.lower.y) <= TB_MAX_LENGTH &&
        fabsf(dd.drawing_bounds.upper.x) <= TB_MAX_LENGTH && fabsf(dd.drawing_bounds.upper.y) <= TB_MAX_LENGTH);
  if (bad_bounds) FUZZ_CHECK(r != TB_OK, "tb_world_draw accepted bounds beyond TB_MAX_LENGTH");
#endif
  return r;
}

/* The geometry and distance API (issue 24) on one of the world's own shapes,
 * placed by its body, against fuzzed points, rays, proxies, sweeps and hulls.
 * Refused calls must leave a message; accepted ones must give answers within
 * their documented ranges. */
static void expect_refusal_or(bool ok, const char* what) {
  FUZZ_CHECK(tb_last_result() == TB_OK || strlen(tb_last_error()) > 0, "%s refused without a message", what);
  FUZZ_CHECK(tb_last_result() != TB_OK || ok, "%s: an answer out of its range", what);
}

/* A point test's answer, right after it: a refused test answers false. */
static bool point_test(bool inside) {
  FUZZ_CHECK(!inside || tb_last_result() == TB_OK, "a refused point test answered true");
  return inside;
}

static bool box_ok(tb_aabb b) {
  return fuzz_vec_finite(b.lower) && fuzz_vec_finite(b.upper) && b.lower.x <= b.upper.x && b.lower.y <= b.upper.y;
}

static bool cast_ok(const tb_cast_output* o, float max_fraction) {
  if (!o->hit) return o->fraction == 0.0f;
  return o->fraction >= 0.0f && o->fraction <= max_fraction && fuzz_vec_finite(o->point) && fuzz_vec_finite(o->normal);
}

static void geometry_queries(fuzz_input* in, tb_shape_type t, const tb_circle* ci, const tb_capsule* ca,
                             const tb_segment* se, const tb_polygon* po, const tb_chain_segment* ch, tb_transform x) {
  tb_vec2 p = fuzz_point(in);
  tb_ray_input ray = {fuzz_point(in), fuzz_vector(in, 40), fuzz_real(in, 0, 1)};
  if (fuzz_u8(in) < 16) x.q = (tb_rot){fuzz_real(in, -1, 1), fuzz_real(in, -1, 1)}; /* now and then not a rotation */
  tb_aabb box = {{0, 0}, {0, 0}};
  tb_vec2 closest = {0, 0};
  tb_cast_output hit;
  tb_shape_proxy proxy;
  tb_clear_error();
  switch (t) {
    case TB_SHAPE_CIRCLE:
      (void)point_test(tb_point_in_circle(ci, x, p)), box = tb_compute_circle_aabb(ci, x);
      closest = tb_closest_point_on_circle(ci, x, p), tb_ray_cast_circle(&ray, ci, x, &hit);
      proxy = tb_make_circle_proxy(ci);
      break;
    case TB_SHAPE_CAPSULE:
      (void)point_test(tb_point_in_capsule(ca, x, p)), box = tb_compute_capsule_aabb(ca, x);
      closest = tb_closest_point_on_capsule(ca, x, p), tb_ray_cast_capsule(&ray, ca, x, &hit);
      proxy = tb_make_capsule_proxy(ca);
      break;
    case TB_SHAPE_POLYGON:
      (void)point_test(tb_point_in_polygon(po, x, p)), box = tb_compute_polygon_aabb(po, x);
      closest = tb_closest_point_on_polygon(po, x, p), tb_ray_cast_polygon(&ray, po, x, &hit);
      proxy = tb_make_polygon_proxy(po);
      break;
    default: {
      const tb_segment* g = t == TB_SHAPE_SEGMENT ? se : &ch->segment;
      (void)point_test(tb_point_in_segment(g, x, p)), box = tb_compute_segment_aabb(g, x);
      closest = tb_closest_point_on_segment(g, x, p), tb_ray_cast_segment(&ray, g, x, &hit);
      proxy = tb_make_segment_proxy(g);
    }
  }
  expect_refusal_or(box_ok(box) && fuzz_vec_finite(closest) && cast_ok(&hit, ray.max_fraction), "geometry query");
  FUZZ_CHECK(proxy.count >= 1, "the proxy of a live shape: %s", tb_last_error());

  /* distance, cast and time of impact against a fuzzed offset proxy */
  tb_vec2 pts[3] = {fuzz_point(in), fuzz_point(in), fuzz_point(in)};
  tb_clear_error();
  tb_shape_proxy other =
      tb_make_offset_proxy(pts, 1 + pick(in, 3), fuzz_size(in, 0, 1), fuzz_point(in), fuzz_real(in, -7, 7));
  expect_refusal_or(other.count >= 1, "tb_make_offset_proxy");
  tb_clear_error();
  other = tb_make_proxy(pts, 1 + pick(in, 3), fuzz_size(in, 0, 1));
  expect_refusal_or(other.count >= 1, "tb_make_proxy");
  tb_transform xo = {fuzz_point(in), {1, 0}};
  tb_distance_input din = {proxy, other, x, xo};
  tb_simplex_cache cache = {0};
  tb_distance_output d;
  for (int k = 0; k < 2; ++k) { /* cold, then warm */
    tb_clear_error();
    tb_shape_distance(&din, &cache, &d);
    expect_refusal_or(d.distance >= 0.0f && isfinite(d.distance) && fuzz_vec_finite(d.point_a) &&
                          fuzz_vec_finite(d.point_b) && d.simplex_count >= 1 && d.simplex_count <= 3,
                      "tb_shape_distance");
  }
  tb_shape_cast_input cin = {proxy, other, x, xo, fuzz_vector(in, 50)};
  tb_clear_error();
  tb_shape_cast(&cin, &hit);
  expect_refusal_or(cast_ok(&hit, 1.0f), "tb_shape_cast");
  tb_sweep sa = {fuzz_point(in), x.p, fuzz_point(in), fuzz_real(in, -3, 3), fuzz_real(in, -3, 3)};
  tb_sweep sb = {{0, 0}, xo.p, fuzz_point(in), 0.0f, fuzz_real(in, -30, 30)};
  tb_toi_input tin = {proxy, other, sa, sb, fuzz_real(in, 0, 1), fuzz_size(in, 0, 0.05f), fuzz_size(in, 0, 0.01f)};
  tb_toi_output toi;
  tb_clear_error();
  tb_time_of_impact(&tin, &toi);
  expect_refusal_or(toi.state <= TB_TOI_FAILED && toi.fraction >= 0.0f && toi.fraction <= tin.max_fraction,
                    "tb_time_of_impact");
  if (tb_last_result() == TB_OK) /* an accepted sweep places its body within reach of floats */
    FUZZ_CHECK(fuzz_vec_finite(tb_sweep_transform(&sa, toi.fraction).p), "tb_sweep_transform not finite");
  tb_clear_error();
  tb_segment_distance_output sd = tb_segment_distance(pts[0], pts[1], pts[2], p);
  expect_refusal_or(sd.distance_sq >= 0.0f && sd.fraction1 >= 0.0f && sd.fraction1 <= 1.0f && sd.fraction2 >= 0.0f &&
                        sd.fraction2 <= 1.0f,
                    "tb_segment_distance");

  /* hulls and placed polygons: a hull tb_compute_hull made is always accepted */
  tb_vec2 cloud[TB_MAX_POLYGON_VERTICES + 2];
  int n = 3 + pick(in, TB_MAX_POLYGON_VERTICES);
  for (int i = 0; i < n; ++i) {
    tb_vec2 q = fuzz_point(in);
    cloud[i] = (tb_vec2){0.2f * q.x, 0.2f * q.y};
  }
  tb_hull hull;
  tb_polygon made;
  tb_clear_error();
  if (tb_compute_hull(cloud, n, &hull) == TB_OK) {
    FUZZ_CHECK(hull.count >= 3 && hull.count <= TB_MAX_POLYGON_VERTICES, "hull count %d", hull.count);
    FUZZ_CHECK(tb_make_polygon_from_hull(&hull, 0.0f, &made) == TB_OK, "a computed hull refused: %s", tb_last_error());
  } else {
    expect_refusal_or(hull.count == 0, "tb_compute_hull");
  }
  tb_clear_error();
  tb_make_offset_rounded_polygon(&hull, fuzz_point(in), fuzz_real(in, -7, 7), fuzz_size(in, 0, 0.2f), &made);
  expect_refusal_or(true, "tb_make_offset_rounded_polygon");
  tb_clear_error();
  tb_make_offset_polygon(&hull, fuzz_point(in), fuzz_real(in, -7, 7), &made);
  expect_refusal_or(true, "tb_make_offset_polygon");
  tb_clear_error();
  tb_make_offset_rounded_box(fuzz_size(in, 0.01f, 2), fuzz_size(in, 0.01f, 2), fuzz_point(in), fuzz_real(in, -7, 7),
                             fuzz_size(in, 0, 0.2f), &made);
  expect_refusal_or(true, "tb_make_offset_rounded_box");
  if (t == TB_SHAPE_POLYGON) {
    tb_clear_error();
    tb_polygon placed;
    if (tb_transform_polygon(po, x, &placed) == TB_OK) {
      tb_aabb pb = tb_compute_polygon_aabb(&placed, (tb_transform){{0, 0}, {1, 0}});
      FUZZ_CHECK(box_ok(pb), "the box of a placed polygon");
    }
    expect_refusal_or(true, "tb_transform_polygon");
  }
}

/* The collide and mass functions on two of the world's own shapes, placed by
 * their bodies. */
static void collide(world_model* wm, fuzz_input* in) {
  if (wm->shape_count == 0 && wm->chain_count == 0) return;
  tb_shape_id s[2];
  for (int k = 0; k < 2; ++k) {
    if (wm->chain_count > 0 && (fuzz_u8(in) & 3) == 0) {
      tb_shape_id seg[4];
      int n = tb_chain_get_segments(wm->chains[pick(in, wm->chain_count)], seg, 4);
      s[k] = n > 0 ? seg[pick(in, n)] : wm->shapes[0];
    } else {
      s[k] = wm->shape_count > 0 ? wm->shapes[pick(in, wm->shape_count)] : (tb_shape_id){0, 0, 0};
    }
  }
  if (!tb_shape_is_valid(s[0]) || !tb_shape_is_valid(s[1])) return;
  tb_circle ci[2];
  tb_capsule ca[2];
  tb_segment se[2];
  tb_polygon po[2];
  tb_chain_segment ch[2];
  tb_transform x[2];
  tb_shape_type t[2];
  for (int k = 0; k < 2; ++k) {
    t[k] = tb_shape_get_type(s[k]);
    x[k] = tb_body_get_transform(tb_shape_get_body(s[k]));
    tb_result r = TB_OK;
    float density = tb_shape_get_density(s[k]);
    tb_mass_data md = {0, {0, 0}, 0};
    switch (t[k]) {
      case TB_SHAPE_CIRCLE: r = tb_shape_get_circle(s[k], &ci[k]), md = tb_compute_circle_mass(&ci[k], density); break;
      case TB_SHAPE_CAPSULE:
        r = tb_shape_get_capsule(s[k], &ca[k]), md = tb_compute_capsule_mass(&ca[k], density);
        break;
      case TB_SHAPE_SEGMENT: r = tb_shape_get_segment(s[k], &se[k]); break;
      case TB_SHAPE_POLYGON:
        r = tb_shape_get_polygon(s[k], &po[k]), md = tb_compute_polygon_mass(&po[k], density);
        break;
      default: r = tb_shape_get_chain_segment(s[k], &ch[k]);
    }
    FUZZ_CHECK(r == TB_OK, "geometry of a live shape: %s", tb_last_error());
    tb_mass_data own = tb_shape_get_mass_data(s[k]);
    FUZZ_CHECK(isfinite(md.mass) && isfinite(own.mass) && isfinite(own.rotational_inertia), "shape mass not finite");
    /* asking for another type is refused */
    FUZZ_CHECK(t[k] == TB_SHAPE_CIRCLE || tb_shape_get_circle(s[k], &ci[k]) != TB_OK, "circle of a non-circle");
  }
  /* order the pair as the functions are named: A has the lower rank */
  static const int rank[5] = {0, 1, 3, 2, 4}; /* circle, capsule, polygon, segment, chain segment */
  int a = rank[t[0]] >= rank[t[1]] ? 0 : 1, b = 1 - a;
  tb_manifold mf = {{0, 0}, {{{0, 0}, 0, 0, 0, 0}, {{0, 0}, 0, 0, 0, 0}}, 0};
  switch (t[a] * 8 + t[b]) {
    case TB_SHAPE_CIRCLE * 8 + TB_SHAPE_CIRCLE: mf = tb_collide_circles(&ci[a], x[a], &ci[b], x[b]); break;
    case TB_SHAPE_CAPSULE * 8 + TB_SHAPE_CIRCLE: mf = tb_collide_capsule_and_circle(&ca[a], x[a], &ci[b], x[b]); break;
    case TB_SHAPE_CAPSULE * 8 + TB_SHAPE_CAPSULE: mf = tb_collide_capsules(&ca[a], x[a], &ca[b], x[b]); break;
    case TB_SHAPE_SEGMENT * 8 + TB_SHAPE_CIRCLE: mf = tb_collide_segment_and_circle(&se[a], x[a], &ci[b], x[b]); break;
    case TB_SHAPE_SEGMENT * 8 + TB_SHAPE_CAPSULE:
      mf = tb_collide_segment_and_capsule(&se[a], x[a], &ca[b], x[b]);
      break;
    case TB_SHAPE_SEGMENT * 8 + TB_SHAPE_POLYGON:
      mf = tb_collide_segment_and_polygon(&se[a], x[a], &po[b], x[b]);
      break;
    case TB_SHAPE_POLYGON * 8 + TB_SHAPE_CIRCLE: mf = tb_collide_polygon_and_circle(&po[a], x[a], &ci[b], x[b]); break;
    case TB_SHAPE_POLYGON * 8 + TB_SHAPE_CAPSULE:
      mf = tb_collide_polygon_and_capsule(&po[a], x[a], &ca[b], x[b]);
      break;
    case TB_SHAPE_POLYGON * 8 + TB_SHAPE_POLYGON: mf = tb_collide_polygons(&po[a], x[a], &po[b], x[b]); break;
    case TB_SHAPE_CHAIN_SEGMENT * 8 + TB_SHAPE_CIRCLE:
      mf = tb_collide_chain_segment_and_circle(&ch[a], x[a], &ci[b], x[b]);
      break;
    case TB_SHAPE_CHAIN_SEGMENT * 8 + TB_SHAPE_CAPSULE:
      mf = tb_collide_chain_segment_and_capsule(&ch[a], x[a], &ca[b], x[b]);
      break;
    case TB_SHAPE_CHAIN_SEGMENT * 8 + TB_SHAPE_POLYGON:
      mf = tb_collide_chain_segment_and_polygon(&ch[a], x[a], &po[b], x[b]);
      break;
    default: break; /* segment or chain against segment or chain: no contact */
  }
  FUZZ_CHECK(mf.point_count >= 0 && mf.point_count <= 2, "collide: %d points", mf.point_count);
  for (int i = 0; i < mf.point_count; ++i)
    FUZZ_CHECK(fuzz_vec_finite(mf.points[i].point) && isfinite(mf.points[i].separation) && fuzz_vec_finite(mf.normal),
               "collide: a point not finite");
  geometry_queries(in, t[0], &ci[0], &ca[0], &se[0], &po[0], &ch[0], x[0]);
}

/* Every getter of a body, shape, joint, chain and world: finite values for
 * live objects; stale ones are refused without a crash. */
static void read_all(world_model* wm, model* m, fuzz_input* in) {
  tb_world_id w = wm->id;
  tb_body_id b = pick_body(wm, m, in);
  tb_shape_id s = pick_shape(wm, m, in);
  tb_joint_id j = pick_joint(wm, m, in);
  tb_vec2 p = fuzz_point(in);
  bool live = tb_body_is_valid(b);
  float values[] = {tb_body_get_angle(b),
                    tb_body_get_angular_velocity(b),
                    tb_body_get_linear_damping(b),
                    tb_body_get_angular_damping(b),
                    tb_body_get_gravity_scale(b),
                    tb_body_get_sleep_threshold(b),
                    tb_body_get_mass(b),
                    tb_body_get_rotational_inertia(b),
                    tb_body_get_torque(b),
                    tb_body_get_kinetic_energy(b),
                    tb_body_get_angular_momentum(b, p),
                    tb_body_get_mass_data(b).mass,
                    tb_body_get_rotation(b).c,
                    tb_body_get_transform(b).q.s};
  tb_vec2 vectors[] = {tb_body_get_position(b),        tb_body_get_local_center(b),      tb_body_get_world_center(b),
                       tb_body_get_linear_velocity(b), tb_body_get_point_velocity(b, p), tb_body_get_force(b),
                       tb_body_get_world_point(b, p),  tb_body_get_local_point(b, p),    tb_body_get_world_vector(b, p),
                       tb_body_get_local_vector(b, p), tb_body_get_linear_momentum(b)};
  (void)tb_body_get_type(b), (void)tb_body_is_fixed_rotation(b), (void)tb_body_is_enabled(b);
  (void)tb_body_get_user_data(b), (void)tb_body_is_awake(b), (void)tb_body_is_sleep_enabled(b);
  (void)tb_body_is_bullet(b);
  tb_world_id bw = tb_body_get_world(b);
  if (live) {
    FUZZ_CHECK(memcmp(&bw, &w, sizeof w) == 0, "tb_body_get_world");
    /* item 7: legal forces drive bodies far beyond TB_MAX_LENGTH (4e21 m), and
     * then the torque of a legal force there, the energy and the momentum
     * getters overflow (fuzz/known_bugs/api_torque_overflow_item7) */
    int checked = FUZZ_CHECK_ENGINE_LIMITS ? (int)(sizeof values / sizeof values[0]) : 8;
    for (int i = 0; i < checked; ++i) FUZZ_CHECK(isfinite(values[i]), "body getter %d not finite", i);
    int checked_vectors = FUZZ_CHECK_ENGINE_LIMITS ? (int)(sizeof vectors / sizeof vectors[0]) : 4;
    for (int i = 0; i < checked_vectors; ++i) FUZZ_CHECK(fuzz_vec_finite(vectors[i]), "body vector getter %d", i);
  } else {
    FUZZ_CHECK(tb_world_id_is_null(bw) && tb_body_get_mass(b) == 0, "a dead body's getters give values");
  }
  tb_joint_id js[MAX_JOINTS];
  tb_shape_id ss[MAX_SHAPES];
  tb_contact_data cd[4];
  int nj = tb_body_get_joints(b, js, MAX_JOINTS), ns = tb_body_get_shapes(b, ss, MAX_SHAPES);
  int nc = tb_body_get_contact_data(b, cd, 4);
  int joint_count = tb_body_get_joint_count(b);
  FUZZ_CHECK(nj == (joint_count < MAX_JOINTS ? joint_count : MAX_JOINTS), "tb_body_get_joints: %d", nj);
  FUZZ_CHECK(ns <= tb_body_get_shape_count(b) && nc <= tb_body_get_contact_capacity(b), "shape or contact count");
  for (int i = 0; i < nj; ++i) FUZZ_CHECK(tb_joint_is_valid(js[i]), "a body's joint is dead");
  for (int i = 0; i < ns && i < MAX_SHAPES; ++i) FUZZ_CHECK(tb_shape_is_valid(ss[i]), "a body's shape is dead");
  for (int i = 0; i < nc; ++i) {
    FUZZ_CHECK(cd[i].manifold.point_count >= 0 && cd[i].manifold.point_count <= 2, "contact data points");
#if FUZZ_CHECK_MIX_RESULTS
    FUZZ_CHECK(isfinite(cd[i].friction) && cd[i].friction >= 0 && isfinite(cd[i].restitution) && cd[i].restitution >= 0,
               "contact friction %g, restitution %g", (double)cd[i].friction, (double)cd[i].restitution);
#endif
  }
  /* shape */
  float sv[] = {tb_shape_get_density(s),       tb_shape_get_friction(s),
                tb_shape_get_restitution(s),   tb_shape_get_rolling_resistance(s),
                tb_shape_get_tangent_speed(s), tb_shape_get_aabb(s).lower.x,
                tb_shape_get_aabb(s).upper.y};
  (void)tb_shape_get_filter(s), (void)tb_shape_is_sensor(s), (void)tb_shape_get_user_data(s);
  (void)tb_shape_get_body(s), (void)tb_shape_get_type(s);
  if (tb_shape_is_valid(s))
    for (int i = 0; i < (int)(sizeof sv / sizeof sv[0]); ++i) FUZZ_CHECK(isfinite(sv[i]), "shape getter %d", i);
  /* joint */
  float jv[] = {tb_joint_get_constraint_torque(j),       tb_distance_joint_get_length(j),
                tb_distance_joint_get_current_length(j), tb_revolute_joint_get_angle(j),
                tb_revolute_joint_get_motor_torque(j),   tb_prismatic_joint_get_translation(j),
                tb_prismatic_joint_get_speed(j),         tb_prismatic_joint_get_motor_force(j),
                tb_wheel_joint_get_motor_torque(j),      tb_joint_get_constraint_force(j).x,
                tb_joint_get_local_anchor_a(j).x,        tb_joint_get_local_anchor_b(j).y,
                tb_mouse_joint_get_target(j).x};
  (void)tb_joint_get_type(j), (void)tb_joint_get_body_a(j), (void)tb_joint_get_body_b(j);
  (void)tb_joint_get_collide_connected(j), (void)tb_joint_get_user_data(j);
  if (tb_joint_is_valid(j) && FUZZ_CHECK_ENGINE_LIMITS)
    for (int i = 0; i < (int)(sizeof jv / sizeof jv[0]); ++i) FUZZ_CHECK(isfinite(jv[i]), "joint getter %d", i);
  /* chains */
  for (int i = 0; i < wm->chain_count; ++i) {
    tb_shape_id seg[8];
    int n = tb_chain_get_segments(wm->chains[i], seg, 8);
    FUZZ_CHECK(n == (tb_chain_get_segment_count(wm->chains[i]) < 8 ? tb_chain_get_segment_count(wm->chains[i]) : 8),
               "chain segments");
    tb_chain_segment cs;
    if (n > 0) FUZZ_CHECK(tb_shape_get_chain_segment(seg[0], &cs) == TB_OK, "chain segment geometry");
  }
  /* world */
  tb_vec2 g = tb_world_get_gravity(w);
  tb_profile prof = tb_world_get_profile(w);
  FUZZ_CHECK(fuzz_vec_finite(g) && isfinite(tb_world_get_time(w)) && prof.awake_body_count >= 0, "world getters");
  FUZZ_CHECK((int)tb_world_get_integrator(w) <= TB_INTEGRATOR_RK4 && tb_world_get_relax_iterations(w) >= 1,
             "integrator or relax iterations");
  (void)tb_world_is_sleeping_enabled(w), (void)tb_world_is_continuous_enabled(w), (void)tb_world_get_user_data(w);
  tb_contact_events ce = tb_world_get_contact_events(w);
  tb_sensor_events se = tb_world_get_sensor_events(w);
  FUZZ_CHECK(ce.begin_count >= 0 && ce.end_count >= 0 && ce.hit_count >= 0 && se.begin_count >= 0 && se.end_count >= 0,
             "event counts");
  for (int i = 0; i < ce.hit_count; ++i)
    FUZZ_CHECK(fuzz_vec_finite(ce.hit_events[i].point) && ce.hit_events[i].approach_speed > 0, "hit event");
  (void)tb_world_last_error(w);
}

/* Calls on handles of destroyed objects and worlds: refused as stale, and no
 * world changes. */
static tb_result stale_call(model* m, fuzz_input* in) {
  graveyard* g = &m->dead;
  uint8_t k = fuzz_u8(in);
  tb_result r = TB_OK;
  const char* what = "";
  switch (k % 6) {
    case 0:
      if (buried(g->world_count) == 0) return TB_OK;
      what = "world", r = tb_world_step(g->worlds[(k >> 3) % buried(g->world_count)], 1.0f / 60.0f, 1);
      break;
    case 1: {
      if (buried(g->world_count) == 0) return TB_OK;
      tb_body_def bd = tb_default_body_def();
      what = "world (create body)";
      r = tb_body_id_is_null(tb_create_body(g->worlds[(k >> 3) % buried(g->world_count)], &bd)) ? tb_last_result()
                                                                                                : TB_OK;
      break;
    }
    case 2:
      if (buried(g->body_count) == 0) return TB_OK;
      what = "body", r = body_setter(g->bodies[(k >> 3) % buried(g->body_count)], in);
      break;
    case 3:
      if (buried(g->shape_count) == 0) return TB_OK;
      what = "shape", r = shape_setter(g->shapes[(k >> 3) % buried(g->shape_count)], in);
      break;
    case 4:
      if (buried(g->joint_count) == 0) return TB_OK;
      what = "joint", r = joint_setter(g->joints[(k >> 3) % buried(g->joint_count)], in);
      break;
    default:
      if (buried(g->chain_count) == 0) return TB_OK;
      what = "chain", r = tb_destroy_chain(g->chains[(k >> 3) % buried(g->chain_count)]);
  }
  if (m->check) FUZZ_CHECK(r == TB_ERR_STALE_HANDLE, "a dead %s handle: %s", what, tb_result_name(r));
  return r;
}

/* The library's error reporting. */
static void errors(world_model* wm) {
  for (int r = TB_OK; r <= TB_ERR_NUMERIC; ++r) FUZZ_CHECK(strlen(tb_result_name((tb_result)r)) > 0, "result name");
  tb_result last = tb_last_result();
  FUZZ_CHECK((last == TB_OK) == (strlen(tb_last_error()) == 0), "last result and message disagree");
  FUZZ_CHECK(tb_world_last_error(wm->id) != NULL, "tb_world_last_error");
  tb_clear_error();
  FUZZ_CHECK(tb_last_result() == TB_OK && strlen(tb_last_error()) == 0, "tb_clear_error");
}

/* ---- the game's own dynamic tree ------------------------------------------- */

static bool tree_has(const tree_model* tm, int32_t id) {
  for (int i = 0; i < tm->count; ++i)
    if (tm->ids[i] == id) return true;
  return false;
}

/* A box from the input, now and then bad (NaN, beyond TB_MAX_LENGTH, lower > upper). */
static tb_aabb fuzz_box(fuzz_input* in) {
  tb_vec2 lo = fuzz_point(in);
  float w = fuzz_size(in, 0, 10), h = fuzz_size(in, 0, 10);
  if ((fuzz_u8(in) & 15) == 0) w = -w;
  return (tb_aabb){lo, {lo.x + w, lo.y + h}};
}

/* Any id: a live one, a destroyed one, or garbage. */
static int32_t fuzz_proxy(tree_model* tm, fuzz_input* in) {
  uint8_t k = fuzz_u8(in);
  if (tm->count > 0 && (k & 3) != 0) return tm->ids[k % tm->count];
  if (tm->dead_count > 0 && (k & 3) == 0) return tm->dead[k % buried(tm->dead_count)];
  static const int32_t garbage[] = {TB_NULL_PROXY, -1000, 1, 7, 1 << 20, INT32_MAX};
  return garbage[k % 6];
}

/* Callbacks check what they are handed, try to change the tree (refused) and
 * nest queries (allowed). */
static void tree_attack(tree_model* tm, int32_t proxy, void* user_data) {
  model* m = tm->owner;
  if (m->check) {
    FUZZ_CHECK(tree_has(tm, proxy), "the tree reported proxy %d, which is not live", (int)proxy);
    FUZZ_CHECK(user_data == &tm->ids[0] + (proxy & 7), "the tree handed proxy %d another's user data", (int)proxy);
  }
  tb_dynamic_tree* t = tm->tree;
  int count = tb_dynamic_tree_get_proxy_count(t);
  tb_result r[5] = {
      tb_dynamic_tree_create_proxy(t, (tb_aabb){{0, 0}, {1, 1}}, 1, NULL) == TB_NULL_PROXY ? tb_last_result() : TB_OK,
      tb_dynamic_tree_destroy_proxy(t, proxy),
      tb_dynamic_tree_move_proxy(t, proxy, (tb_aabb){{5, 5}, {6, 6}}, (tb_vec2){0, 0}, NULL),
      tb_dynamic_tree_rebuild(t), tb_dynamic_tree_destroy(t)};
  if (m->check) {
    for (int i = 0; i < 5; ++i)
      FUZZ_CHECK(r[i] == TB_ERR_LOCKED, "tree change %d from a callback: %s", i, tb_result_name(r[i]));
    FUZZ_CHECK(tb_dynamic_tree_get_proxy_count(t) == count, "a refused change altered the tree");
  }
  tb_clear_error();
}

static bool tree_query_fn(int32_t proxy, void* user_data, void* context) {
  tree_model* tm = context;
  tree_attack(tm, proxy, user_data);
  if (tm->depth < 1) {
    tm->depth += 1;
    tb_aabb box = tb_dynamic_tree_get_fat_aabb(tm->tree, proxy);
    tb_result r = tb_dynamic_tree_query(tm->tree, box, UINT64_MAX, tree_query_fn, tm);
    if (tm->owner->check) FUZZ_CHECK(r == TB_OK, "a nested tree query was refused: %s", tb_last_error());
    tm->depth -= 1;
  }
  return (proxy & 3) != 3;
}

static float tree_ray_fn(const tb_dynamic_tree_ray_input* input, int32_t proxy, void* user_data, void* context) {
  tree_model* tm = context;
  tree_attack(tm, proxy, user_data);
  if (tm->owner->check) FUZZ_CHECK(input->max_fraction >= 0.0f && fuzz_vec_finite(input->origin), "tree ray input");
  static const float answers[4] = {-1.0f, 0.0f, 0.5f, 1.0f};
  return proxy % 5 == 0 ? NAN : answers[proxy & 3] * input->max_fraction;
}

/* One call on the tree; then its invariants: it validates, and it holds
 * exactly the proxies the harness created and did not destroy, each with its
 * user data. */
static tb_result dynamic_tree(model* m, fuzz_input* in) {
  tree_model* tm = &m->tree;
  if (tm->tree == NULL) return TB_OK;
  tb_dynamic_tree* t = tm->tree;
  tb_result r = TB_OK;
  switch (fuzz_u8(in) % 8) {
    case 0:
    case 1: {
      tb_aabb box = fuzz_box(in);
      if (tm->count >= MAX_TREE_PROXIES) return TB_OK;
      int32_t id = tb_dynamic_tree_create_proxy(t, box, fuzz_u8(in) & 1 ? 1 : 3, NULL);
      if (id == TB_NULL_PROXY) return tb_last_result();
      r = tb_dynamic_tree_set_user_data(t, id, &tm->ids[0] + (id & 7));
      tm->ids[tm->count++] = id;
      for (int i = 0; i < buried(tm->dead_count); ++i) /* handed out again: no longer dead */
        if (tm->dead[i] == id) tm->dead[i] = TB_NULL_PROXY;
      break;
    }
    case 2: {
      int32_t id = fuzz_proxy(tm, in);
      r = tb_dynamic_tree_destroy_proxy(t, id);
      if (m->check) FUZZ_CHECK((r == TB_OK) == tree_has(tm, id), "destroying proxy %d: %s", (int)id, tb_result_name(r));
      if (r == TB_OK) {
        for (int i = 0; i < tm->count; ++i)
          if (tm->ids[i] == id) tm->ids[i] = tm->ids[--tm->count];
        tm->dead[tm->dead_count++ % GRAVE] = id;
      }
      break;
    }
    case 3: {
      int32_t id = fuzz_proxy(tm, in);
      tb_aabb box = fuzz_box(in);
      bool reinserted = false;
      r = tb_dynamic_tree_move_proxy(t, id, box, fuzz_vector(in, 3), &reinserted);
      if (r == TB_OK) FUZZ_CHECK(tree_has(tm, id), "moved a proxy %d that is not live", (int)id);
      if (r == TB_OK && m->check) {
        tb_aabb fat = tb_dynamic_tree_get_fat_aabb(t, id);
        FUZZ_CHECK(fat.lower.x <= box.lower.x && fat.lower.y <= box.lower.y && box.upper.x <= fat.upper.x &&
                       box.upper.y <= fat.upper.y,
                   "a moved proxy's fat box does not hold its box");
      }
      break;
    }
    case 4: {
      tb_aabb box = fuzz_box(in);
      r = tb_dynamic_tree_query(t, box, fuzz_u8(in) & 1 ? UINT64_MAX : 2, tree_query_fn, tm);
      break;
    }
    case 5: {
      tb_dynamic_tree_ray_input ray = {fuzz_point(in), fuzz_vector(in, 30), fuzz_value(in, 0, 2)};
      r = tb_dynamic_tree_ray_cast(t, &ray, UINT64_MAX, tree_ray_fn, tm);
      break;
    }
    case 6: r = tb_dynamic_tree_rebuild(t); break;
    default: {
      int32_t id = fuzz_proxy(tm, in);
      r = tb_dynamic_tree_set_category_bits(t, id, fuzz_u8(in));
      (void)tb_dynamic_tree_get_category_bits(t, id);
    }
  }
  if (m->check) {
    FUZZ_CHECK(tb_dynamic_tree_validate(t) == TB_OK, "tree invalid: %s", tb_last_error());
    FUZZ_CHECK(tb_dynamic_tree_get_proxy_count(t) == tm->count, "tree holds %d proxies, the harness %d",
               tb_dynamic_tree_get_proxy_count(t), tm->count);
    for (int i = 0; i < tm->count; ++i)
      FUZZ_CHECK(tb_dynamic_tree_get_user_data(t, tm->ids[i]) == &tm->ids[0] + (tm->ids[i] & 7), "tree user data");
    int height = tb_dynamic_tree_get_height(t);
    FUZZ_CHECK(height >= 0 && height <= 2 * MAX_TREE_PROXIES && tb_dynamic_tree_get_area_ratio(t) >= 0.0f,
               "tree height %d", height);
  }
  return r;
}

/* Checks after a step of world wm (dt, result r). */
static void check_step(const world_model* wm, float dt, tb_result r) {
  FUZZ_CHECK(r == TB_OK || r == TB_ERR_INVALID_ARGUMENT || r == TB_ERR_NUMERIC, "step: %s", tb_last_error());
#if FUZZ_CHECK_TINY_STEP
  FUZZ_CHECK(!(dt < 1.0e-30f && r == TB_ERR_NUMERIC), "a %g s step was accepted and failed: %s", (double)dt,
             tb_last_error());
#endif
  if (r != TB_OK) return;
  for (int i = 0; i < wm->body_count; ++i) {
    tb_body_id b = wm->bodies[i];
    tb_vec2 p = tb_body_get_position(b), v = tb_body_get_linear_velocity(b);
    float w = tb_body_get_angular_velocity(b);
    FUZZ_CHECK(fuzz_vec_finite(p) && fuzz_vec_finite(v) && isfinite(w) && isfinite(tb_body_get_angle(b)),
               "body %d state not finite", i);
    (void)dt;
#if FUZZ_CHECK_MIX_RESULTS
    tb_contact_data cd[8];
    int nc = tb_body_get_contact_data(b, cd, 8);
    for (int k = 0; k < nc; ++k)
      FUZZ_CHECK(
          isfinite(cd[k].friction) && cd[k].friction >= 0 && isfinite(cd[k].restitution) && cd[k].restitution >= 0,
          "a contact of body %d: friction %g, restitution %g (mix callbacks)", i, (double)cd[k].friction,
          (double)cd[k].restitution);
#endif
#if FUZZ_CHECK_ENGINE_LIMITS
    FUZZ_CHECK(fabsf(p.x) <= TB_MAX_LENGTH && fabsf(p.y) <= TB_MAX_LENGTH, "body %d at (%g, %g): beyond TB_MAX_LENGTH",
               i, (double)p.x, (double)p.y);
    FUZZ_CHECK(fabsf(v.x) <= TB_MAX_VALUE && fabsf(v.y) <= TB_MAX_VALUE && fabsf(w) <= TB_MAX_VALUE,
               "body %d velocity beyond TB_MAX_VALUE", i);
#endif
#if FUZZ_CHECK_SPEED_CAP
    /* The solver scales v to the cap and clamps w to half a turn per step;
     * 1e-4 relative allows the rounding of that scaling. */
    if (tb_body_get_type(b) == TB_DYNAMIC_BODY && tb_body_is_enabled(b) && tb_body_is_awake(b)) {
      float speed = sqrtf(v.x * v.x + v.y * v.y);
      FUZZ_CHECK(speed <= wm->max_speed * 1.0001f, "body %d at %g m/s, over the cap %g", i, (double)speed,
                 (double)wm->max_speed);
      FUZZ_CHECK(fabsf(w) <= 0.5f * 3.14159265f / dt * 1.0001f, "body %d at %g rad/s, over half a turn per %g s step",
                 i, (double)w, (double)dt);
    }
#endif
  }
}

static tb_result command(model* m, fuzz_input* in, int* stepped, float* step_dt) {
  uint8_t op = fuzz_u8(in) % 24;
  world_model* wm = pick_world(m, in);
  if (wm == NULL || op == 18) { /* create a world */
    for (int i = 0; i < MAX_WORLDS; ++i)
      if (!m->worlds[i].alive) return create_world(m, &m->worlds[i], in, false);
    if (wm == NULL) return TB_OK;
    op = 19; /* all slots of the model taken: destroy one instead */
  }
  tb_world_id w = wm->id;
  tb_body_id body = pick_body(wm, m, in);
  switch (op) {
    case 0: { /* create a body */
      if (wm->body_count >= MAX_BODIES) return TB_OK;
      tb_body_def bd = tb_default_body_def();
      uint8_t f = fuzz_u8(in);
      bd.type = (tb_body_type)(f % 3);
      bd.position = fuzz_point(in);
      bd.angle = fuzz_value(in, -4, 4);
      bd.linear_velocity = fuzz_vector(in, 50);
      bd.angular_velocity = fuzz_value(in, -20, 20);
      bd.is_bullet = f & 4, bd.fixed_rotation = (f & 24) == 24, bd.enabled = (f & 96) != 96;
      bd.enable_sleep = !(f & 128), bd.is_awake = (f & 0x41) != 0x41;
      if (f & 32) bd.linear_damping = fuzz_value(in, 0, 2), bd.angular_damping = fuzz_value(in, 0, 2);
      if (f & 64) bd.gravity_scale = fuzz_value(in, -2, 2), bd.sleep_threshold = fuzz_value(in, 0, 1);
      tb_body_id b = tb_create_body(w, &bd);
      if (tb_body_id_is_null(b)) return tb_last_result();
      wm->bodies[wm->body_count++] = b;
      return TB_OK;
    }
    case 1: { /* destroy a body */
      tb_result r = tb_destroy_body(body);
      if (r == TB_OK) {
        for (int i = 0; i < wm->body_count; ++i)
          if (memcmp(&wm->bodies[i], &body, sizeof body) == 0) wm->bodies[i] = wm->bodies[--wm->body_count];
        bury_body(&m->dead, body);
        prune(wm, &m->dead);
      }
      return r;
    }
    case 2: return create_shape(wm, in, body);
    case 3: { /* destroy a shape */
      tb_shape_id s = pick_shape(wm, m, in);
      tb_result r = tb_destroy_shape(s);
      if (r == TB_OK) {
        for (int i = 0; i < wm->shape_count; ++i)
          if (memcmp(&wm->shapes[i], &s, sizeof s) == 0) wm->shapes[i] = wm->shapes[--wm->shape_count];
        bury_shape(&m->dead, s);
      }
      return r;
    }
    case 4: return create_joint(wm, m, in, body);
    case 5:
    case 16: { /* joint setters; one of them destroys */
      tb_joint_id j = pick_joint(wm, m, in);
      tb_result r = joint_setter(j, in);
      if (r == TB_OK && !tb_joint_is_valid(j)) prune(wm, &m->dead);
      return r;
    }
    case 6:
    case 7: { /* step (the most common command), from the smallest to the largest step */
      static const float steps[16] = {1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 120.0f, 0.1f,  0.0f,   -1.0f / 60.0f,
                                      NAN,          2.0f,         1.0f,          1e-6f, 1e-45f, FLT_MIN,
                                      1.0f / 60.0f, 1.0f / 60.0f, 0.5f,          1e-3f};
      static const int subs[8] = {4, 1, 8, 2, 0, 65, -3, 64};
      float dt = steps[fuzz_u8(in) % 16];
      int sub = subs[fuzz_u8(in) % 8];
      if (m->steps >= MAX_STEPS) return TB_OK;
      m->steps += 1;
      tb_result r = tb_world_step(w, dt, sub);
      /* TB_ERR_NUMERIC: a body got a non-finite state and was contained (kept
       * as before the step). Accepted inputs can still combine into it: forces
       * of up to 1e18 N on a gram body overflow its acceleration. Seed
       * fuzz/corpus/api/numeric_weld_to_spinning_kinematic was a real solver
       * bug (a weld's 2x2 determinant overflowing a float; fixed, and
       * test_joint holds it). */
      *stepped = (int)(wm - m->worlds);
      *step_dt = dt;
      return r;
    }
    case 8: { /* forces and impulses, up to TB_MAX_VALUE */
      tb_vec2 v = fuzz_vector(in, 1000), p = fuzz_point(in);
      switch (fuzz_u8(in) % 6) {
        case 0: return tb_body_apply_force(body, v, p);
        case 1: return tb_body_apply_force_to_center(body, v);
        case 2: return tb_body_apply_torque(body, v.x);
        case 3: return tb_body_apply_linear_impulse(body, v, p);
        case 4: return tb_body_apply_linear_impulse_to_center(body, v);
        default: return tb_body_apply_angular_impulse(body, v.y);
      }
    }
    case 9: { /* velocities and placement */
      tb_vec2 v = fuzz_vector(in, 50);
      switch (fuzz_u8(in) % 3) {
        case 0: return tb_body_set_linear_velocity(body, v);
        case 1: return tb_body_set_angular_velocity(body, v.x);
        default: return tb_body_set_transform(body, fuzz_point(in), fuzz_value(in, -4, 4));
      }
    }
    case 10: return body_setter(body, in);
    case 11: return shape_setter(pick_shape(wm, m, in), in);
    case 12: return query(wm, in);
    case 13: { /* chains */
      if (wm->chain_count > 0 && (fuzz_u8(in) & 1)) {
        int ci = pick(in, wm->chain_count);
        tb_result r = tb_destroy_chain(wm->chains[ci]);
        if (r == TB_OK) bury_chain(&m->dead, wm->chains[ci]), wm->chains[ci] = wm->chains[--wm->chain_count];
        prune(wm, &m->dead);
        return r;
      }
      if (wm->chain_count >= MAX_CHAINS) return TB_OK;
      tb_vec2 pts[8];
      int n = 2 + fuzz_u8(in) % 7;
      float spacing = fuzz_size(in, 0.5f, 10);
      for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){-20.0f + spacing * (float)i, fuzz_pos(in, -2, 2)};
      tb_chain_def cd = tb_default_chain_def();
      cd.points = pts;
      cd.count = n;
      cd.is_loop = n >= 3 && (fuzz_u8(in) & 1);
      cd.friction = fuzz_value(in, 0, 1), cd.restitution = fuzz_real(in, 0, 1);
      cd.enable_sensor_events = fuzz_bool(in);
      tb_chain_id c = tb_create_chain(body, &cd);
      if (tb_chain_id_is_null(c)) return tb_last_result();
      wm->chains[wm->chain_count++] = c;
      return TB_OK;
    }
    case 14: return world_setter(wm, in);
    case 15: read_all(wm, m, in); return TB_OK;
    case 17: return draw(wm, in);
    case 19: { /* destroy a world: all its handles die with it */
      tb_result r = tb_destroy_world(w);
      FUZZ_CHECK(r == TB_OK, "tb_destroy_world: %s", tb_last_error());
      bury_world(m, wm);
      return r;
    }
    case 20: return stale_call(m, in);
    case 21: collide(wm, in); return TB_OK;
    case 22: errors(wm); return dynamic_tree(m, in);
    default: { /* a foreign body in a shape or joint call is refused */
      world_model* ow = &m->worlds[(wm - m->worlds + 1) % MAX_WORLDS];
      if (!ow->alive || ow->body_count == 0 || wm->body_count == 0) return TB_OK;
      tb_distance_joint_def d = tb_default_distance_joint_def();
      d.body_a = wm->bodies[0], d.body_b = ow->bodies[0];
      tb_joint_id j = tb_create_distance_joint(w, &d);
      if (m->check) FUZZ_CHECK(tb_joint_id_is_null(j), "a joint between bodies of two worlds");
      return tb_last_result();
    }
  }
}

/* ---- memory: a counting allocator, set once while no world exists -------- */

/* Each block carries its size in a header of one alignment unit, so the free
 * hook can check the size tumble passes back. */
typedef struct fuzz_counter {
  size_t live_bytes;
  bool installed;
} fuzz_counter;
static fuzz_counter counter;

static void* counting_alloc(size_t size, size_t alignment, void* context) {
  FUZZ_CHECK(context == &counter && size > 0 && alignment >= TB_ALLOCATION_ALIGNMENT, "alloc(%zu, %zu)", size,
             alignment);
  unsigned char* block = tb_default_alloc(size + TB_ALLOCATION_ALIGNMENT, alignment, NULL);
  if (block == NULL) return NULL;
  memcpy(block, &size, sizeof size);
  counter.live_bytes += size;
  return block + TB_ALLOCATION_ALIGNMENT;
}

static void counting_free(void* memory, size_t size, void* context) {
  unsigned char* block = (unsigned char*)memory - TB_ALLOCATION_ALIGNMENT;
  size_t allocated;
  memcpy(&allocated, block, sizeof allocated);
  FUZZ_CHECK(context == &counter && allocated == size, "free told %zu bytes, allocated %zu", size, allocated);
  counter.live_bytes -= size;
  tb_default_free(block, size + TB_ALLOCATION_ALIGNMENT, NULL);
}

/* Between inputs (no world exists): the global setters take effect, and
 * tumble holds only what it keeps between worlds. */
static void check_memory_between_inputs(void) {
  if (!counter.installed) {
    FUZZ_CHECK(tb_set_allocator(counting_alloc, counting_free, &counter) == TB_OK, "%s", tb_last_error());
    counter.installed = true;
  }
  FUZZ_CHECK(tb_set_length_units_per_meter(1.0f) == TB_OK && tb_set_log_function(NULL, NULL) == TB_OK &&
                 tb_set_assert_function(NULL, NULL) == TB_OK,
             "a global setter refused while no world exists: %s", tb_last_error());
  FUZZ_CHECK(counter.live_bytes == tb_get_retained_byte_count(), "%zu bytes live, %zu retained between worlds",
             counter.live_bytes, tb_get_retained_byte_count());
}

/* While worlds exist: each world's parts add up to its byte count, the
 * worlds and the kept history are every byte the allocator holds, and the
 * global setters are refused. */
static void check_memory(const model* m) {
  size_t held = tb_get_retained_byte_count();
  int alive = 0;
  for (int k = 0; k < MAX_WORLDS; ++k) {
    if (!m->worlds[k].alive) continue;
    alive += 1;
    tb_memory_stats s;
    FUZZ_CHECK(tb_world_get_memory_stats(m->worlds[k].id, &s) == TB_OK, "%s", tb_last_error());
    FUZZ_CHECK(s.world + s.bodies + s.shapes + s.contacts + s.joints + s.broad_phase + s.islands + s.solver + s.events +
                       s.handle_history ==
                   s.total,
               "memory parts do not add up to %zu", s.total);
    FUZZ_CHECK(tb_world_get_byte_count(m->worlds[k].id) == s.total, "byte count");
    held += s.total;
  }
  held += tb_dynamic_tree_get_byte_count(m->tree.tree); /* the harness's own tree (0 when it has none) */
  tb_clear_error();
  FUZZ_CHECK(held == counter.live_bytes, "the worlds and the tree hold %zu bytes, the allocator %zu", held,
             counter.live_bytes);
  FUZZ_CHECK(tb_set_length_units_per_meter(1.0f) == (alive > 0 ? TB_ERR_LOCKED : TB_OK) &&
                 tb_get_length_units_per_meter() == 1.0f,
             "units refused or changed wrongly (%d worlds)", alive);
  tb_clear_error();
}

static void check_invariants(const model* m) {
  for (int k = 0; k < MAX_WORLDS; ++k) {
    const world_model* wm = &m->worlds[k];
    if (!wm->alive) continue;
    FUZZ_CHECK(tb_world_is_valid(wm->id), "world %d invalid", k);
    tb_counts c = tb_world_get_counts(wm->id);
    int chain_shapes = 0;
    for (int i = 0; i < wm->chain_count; ++i) chain_shapes += tb_chain_get_segment_count(wm->chains[i]);
    FUZZ_CHECK(c.body_count == wm->body_count, "bodies: world %d, alive %d", c.body_count, wm->body_count);
    FUZZ_CHECK(c.shape_count == wm->shape_count + chain_shapes, "shapes: world %d, alive %d + %d chain segments",
               c.shape_count, wm->shape_count, chain_shapes);
    FUZZ_CHECK(c.joint_count == wm->joint_count, "joints: world %d, alive %d", c.joint_count, wm->joint_count);
    FUZZ_CHECK(c.awake_body_count >= 0 && c.awake_body_count <= c.body_count, "awake %d", c.awake_body_count);
    FUZZ_CHECK(c.touching_count <= c.contact_count, "touching %d > contacts %d", c.touching_count, c.contact_count);
    for (int i = 0; i < wm->body_count; ++i) {
      tb_body_id b = wm->bodies[i];
      FUZZ_CHECK(tb_body_is_valid(b), "body %d invalid", i);
      FUZZ_CHECK(fuzz_vec_finite(tb_body_get_position(b)) && fuzz_vec_finite(tb_body_get_linear_velocity(b)) &&
                     isfinite(tb_body_get_angle(b)) && isfinite(tb_body_get_angular_velocity(b)) &&
                     fuzz_vec_finite(tb_body_get_world_center(b)),
                 "body %d state not finite", i);
    }
    for (int i = 0; i < wm->shape_count; ++i) FUZZ_CHECK(tb_shape_is_valid(wm->shapes[i]), "shape %d invalid", i);
    for (int i = 0; i < wm->joint_count; ++i) FUZZ_CHECK(tb_joint_is_valid(wm->joints[i]), "joint %d invalid", i);
    for (int i = 0; i < wm->chain_count; ++i) FUZZ_CHECK(tb_chain_is_valid(wm->chains[i]), "chain %d invalid", i);
    FUZZ_CHECK(tb_world_hash(wm->id) == tb_world_hash(wm->id), "hash not stable");
    /* handles survive packing, and distinct objects never pack alike */
    FUZZ_CHECK(tb_world_id_equal(wm->id, tb_world_id_from_u64(tb_world_id_to_u64(wm->id))), "world id packing");
    for (int i = 0; i < wm->body_count; ++i) {
      tb_body_id b = wm->bodies[i], next = wm->bodies[(i + 1) % wm->body_count];
      FUZZ_CHECK(tb_body_id_equal(b, tb_body_id_from_u64(tb_body_id_to_u64(b))), "body id packing");
      FUZZ_CHECK(wm->body_count == 1 || (!tb_body_id_equal(b, next) && tb_body_id_to_u64(b) != tb_body_id_to_u64(next)),
                 "two bodies with one handle");
    }
    for (int i = 0; i < wm->shape_count; ++i)
      FUZZ_CHECK(tb_shape_id_equal(wm->shapes[i], tb_shape_id_from_u64(tb_shape_id_to_u64(wm->shapes[i]))),
                 "shape id packing");
    for (int i = 0; i < wm->joint_count; ++i)
      FUZZ_CHECK(tb_joint_id_equal(wm->joints[i], tb_joint_id_from_u64(tb_joint_id_to_u64(wm->joints[i]))),
                 "joint id packing");
    for (int i = 0; i < wm->chain_count; ++i)
      FUZZ_CHECK(tb_chain_id_equal(wm->chains[i], tb_chain_id_from_u64(tb_chain_id_to_u64(wm->chains[i]))),
                 "chain id packing");
  }
  const graveyard* g = &m->dead;
  for (int i = 0; i < buried(g->world_count); ++i)
    FUZZ_CHECK(!tb_world_is_valid(g->worlds[i]), "a dead world is valid");
  for (int i = 0; i < buried(g->body_count); ++i) FUZZ_CHECK(!tb_body_is_valid(g->bodies[i]), "a dead body is valid");
  for (int i = 0; i < buried(g->shape_count); ++i)
    FUZZ_CHECK(!tb_shape_is_valid(g->shapes[i]), "a dead shape is valid");
  for (int i = 0; i < buried(g->joint_count); ++i)
    FUZZ_CHECK(!tb_joint_is_valid(g->joints[i]), "a dead joint is valid");
  for (int i = 0; i < buried(g->chain_count); ++i)
    FUZZ_CHECK(!tb_chain_is_valid(g->chains[i]), "a dead chain is valid");
}

/* FNV-1a over the trace of a run. */
static uint64_t mix_trace(uint64_t h, uint64_t v) {
  for (int i = 0; i < 8; ++i) h = (h ^ ((v >> (8 * i)) & 0xff)) * 0x100000001b3ull;
  return h;
}

/* One run of the stream in m. Returns the trace: every command's result and
 * the hashes of all worlds. The worlds stay alive (see LLVMFuzzerTestOneInput). */
static uint64_t run(model* m, const uint8_t* data, size_t size, bool check) {
  memset(m, 0, sizeof *m);
  m->check = check;
  m->tree.owner = m;
  m->tree.tree = tb_dynamic_tree_create(fuzz_u8(&(fuzz_input){data, size, 0}) & 1 ? 0.0f : 0.1f);
  fuzz_input in = {data, size, 0};
  uint64_t trace = 0xcbf29ce484222325ull;
  create_world(m, &m->worlds[0], &in, true);
  create_world(m, &m->worlds[1], &in, false);
  int commands = 0;
  uint64_t before[MAX_WORLDS], after[MAX_WORLDS];
  hash_all(m, before);
  while (in.at < in.size && commands < MAX_COMMANDS) {
    commands += 1;
    tb_clear_error();
    m->attack_budget = 8;
    int stepped = -1;
    float dt = 0;
    size_t at = in.at;
    tb_result r = command(m, &in, &stepped, &dt);
    if (in.at == at) break; /* nothing read: the input has ended */
#ifdef FUZZ_TRACE           /* -DFUZZ_TRACE: what each command of a reproducer did */
    if (check)
      fprintf(stderr, "command %d (op %u, bytes %zu..%zu): %s %s\n", commands, data[at] % 24u, at, in.at,
              tb_result_name(r), r != TB_OK ? tb_last_error() : "");
#endif
    hash_all(m, after);
    trace = mix_trace(trace, (uint64_t)r);
    for (int i = 0; i < MAX_WORLDS; ++i) trace = mix_trace(trace, after[i]);
    if (check) {
      if (r != TB_OK && r != TB_ERR_NUMERIC) {
        FUZZ_CHECK(strlen(tb_last_error()) > 0, "refused without a message");
        bool chain = strstr(tb_last_error(), "tb_create_chain") != NULL;
        if (FUZZ_CHECK_REFUSED_CHAIN || !chain)
          for (int i = 0; i < MAX_WORLDS; ++i)
            FUZZ_CHECK(after[i] == before[i] || !m->worlds[i].alive, "a refused call (%s) changed world %d: %s",
                       tb_result_name(r), i, tb_last_error());
      }
      if (stepped >= 0) check_step(&m->worlds[stepped], dt, r);
      check_invariants(m);
      check_memory(m);
    }
    memcpy(before, after, sizeof before);
  }
  return trace;
}

static void destroy_worlds(model* m) {
  if (m->tree.tree != NULL) FUZZ_CHECK(tb_dynamic_tree_destroy(m->tree.tree) == TB_OK, "destroy tree");
  m->tree.tree = NULL;
  for (int i = 0; i < MAX_WORLDS; ++i)
    if (m->worlds[i].alive) FUZZ_CHECK(tb_destroy_world(m->worlds[i].id) == TB_OK, "destroy world");
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static model first, second; /* large: not on the stack */
  check_memory_between_inputs();
  uint64_t t1 = run(&first, data, size, true);
  /* The replay: the first run's worlds, and a dummy world when fewer than two
   * are left, still hold the lowest slots (tb_create_world takes the lowest
   * free one), so every world of the replay lands in another slot. No more
   * worlds than that: the library has 128 slots of 65,536 worlds each, about
   * 8.4 million worlds per process, and each input uses about 5.6 (1.5 million inputs). */
  int alive = 0;
  for (int i = 0; i < MAX_WORLDS; ++i) alive += first.worlds[i].alive;
  tb_world_def wd = tb_default_world_def();
  tb_world_id dummy = alive < 2 ? tb_create_world(&wd) : (tb_world_id){0, 0};
  uint64_t t2 = run(&second, data, size, false);
  FUZZ_CHECK(t1 == t2, "the same commands gave different worlds in other world slots");
  destroy_worlds(&first);
  destroy_worlds(&second);
  if (!tb_world_id_is_null(dummy)) tb_destroy_world(dummy);
  return 0;
}
