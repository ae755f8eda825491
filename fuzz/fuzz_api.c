/* libFuzzer harness: the whole API driven by a command stream.
 *
 * Each input is a sequence of commands (create and destroy bodies, shapes,
 * joints and chains; step; forces, impulses, velocities, transforms; body and
 * shape settings; queries), with numbers that are now and then NaN, infinite,
 * huge, zero or negative, and handles that are now and then stale. After every
 * command:
 * - a call that failed left the world's hash as it was;
 * - the counts of the world equal the objects the harness knows to be alive,
 *   and every one of their handles is valid, every destroyed one invalid;
 * - every body's position, angle and velocities are finite;
 * - hashing twice gives the same value.
 * At the end the same stream is replayed in a second world: same hash
 * (determinism). */
#include "fuzz_common.h"

#define MAX_BODIES 24
#define MAX_SHAPES 48
#define MAX_JOINTS 16
#define MAX_CHAINS 4
#define MAX_STEPS 40

typedef struct model {
  tb_world_id world;
  tb_body_id bodies[MAX_BODIES];
  int body_count;
  tb_shape_id shapes[MAX_SHAPES];
  int shape_count;
  tb_joint_id joints[MAX_JOINTS];
  int joint_count;
  tb_chain_id chains[MAX_CHAINS];
  int chain_count;
  tb_body_id dead_body;
  tb_shape_id dead_shape;
  tb_joint_id dead_joint;
  int steps;
} model;

static int pick(fuzz_input* in, int n) { return n > 0 ? fuzz_u8(in) % n : -1; }

/* Forget handles that died with their body (shapes, joints, chains). */
static void prune(model* m) {
  int k = 0;
  for (int i = 0; i < m->shape_count; ++i)
    if (tb_shape_is_valid(m->shapes[i]))
      m->shapes[k++] = m->shapes[i];
    else
      m->dead_shape = m->shapes[i];
  m->shape_count = k;
  k = 0;
  for (int i = 0; i < m->joint_count; ++i)
    if (tb_joint_is_valid(m->joints[i]))
      m->joints[k++] = m->joints[i];
    else
      m->dead_joint = m->joints[i];
  m->joint_count = k;
  k = 0;
  for (int i = 0; i < m->chain_count; ++i)
    if (tb_chain_is_valid(m->chains[i])) m->chains[k++] = m->chains[i];
  m->chain_count = k;
}

static bool count_overlap(tb_shape_id shape, void* context) {
  FUZZ_CHECK(tb_shape_is_valid(shape), "a query reported a dead shape");
  *(int*)context += 1;
  return *(int*)context < 100;
}

static float cast(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  FUZZ_CHECK(tb_shape_is_valid(shape) && fuzz_vec_finite(point) && fuzz_vec_finite(normal) && fraction >= 0.0f &&
                 fraction <= 1.0f,
             "bad cast hit");
  *(int*)context += 1;
  return fraction;
}

static void add_shape(model* m, tb_shape_id s) {
  if (!tb_shape_id_is_null(s) && m->shape_count < MAX_SHAPES) m->shapes[m->shape_count++] = s;
}

/* One command; returns the result of the call that changes the world (TB_OK
 * for reads). */
static tb_result command(model* m, fuzz_input* in) {
  tb_world_id w = m->world;
  uint8_t op = fuzz_u8(in) % 16;
  int bi = pick(in, m->body_count);
  tb_body_id body = bi >= 0 ? m->bodies[bi] : m->dead_body;
  if ((fuzz_u8(in) & 31) == 0) body = m->dead_body; /* now and then a stale handle */
  switch (op) {
    case 0: { /* create a body */
      if (m->body_count >= MAX_BODIES) return TB_OK;
      tb_body_def bd = tb_default_body_def();
      bd.type = (tb_body_type)(fuzz_u8(in) % 3);
      bd.position = (tb_vec2){fuzz_real(in, -20, 20), fuzz_real(in, -5, 30)};
      bd.angle = fuzz_real(in, -4, 4);
      bd.linear_velocity = (tb_vec2){fuzz_real(in, -50, 50), fuzz_real(in, -50, 50)};
      bd.angular_velocity = fuzz_real(in, -20, 20);
      bd.is_bullet = fuzz_u8(in) & 1;
      tb_body_id b = tb_create_body(w, &bd);
      if (tb_body_id_is_null(b)) return tb_last_result();
      m->bodies[m->body_count++] = b;
      return TB_OK;
    }
    case 1: { /* destroy a body */
      tb_result r = tb_destroy_body(body);
      if (r == TB_OK) {
        m->bodies[bi] = m->bodies[--m->body_count];
        m->dead_body = body;
        prune(m);
      }
      return r;
    }
    case 2: { /* a shape of each type */
      tb_shape_def sd = tb_default_shape_def();
      sd.density = fuzz_real(in, 0, 5);
      sd.friction = fuzz_range(in, 0, 1);
      sd.restitution = fuzz_range(in, 0, 1);
      sd.is_sensor = (fuzz_u8(in) & 7) == 0;
      sd.enable_hit_events = true;
      tb_shape_id s = {0, 0, 0};
      switch (fuzz_u8(in) % 4) {
        case 0: {
          tb_circle c = {{fuzz_real(in, -1, 1), fuzz_real(in, -1, 1)}, fuzz_real(in, 0.02f, 2)};
          s = tb_create_circle_shape(body, &sd, &c);
          break;
        }
        case 1: {
          tb_capsule c = {{fuzz_real(in, -1, 1), 0}, {fuzz_real(in, -1, 1), 0.5f}, fuzz_real(in, 0.02f, 1)};
          s = tb_create_capsule_shape(body, &sd, &c);
          break;
        }
        case 2: {
          tb_segment g = {{fuzz_real(in, -2, 2), fuzz_real(in, -2, 2)}, {fuzz_real(in, -2, 2), fuzz_real(in, -2, 2)}};
          s = tb_create_segment_shape(body, &sd, &g);
          break;
        }
        default: {
          tb_polygon p;
          tb_vec2 pts[6];
          int n = 3 + fuzz_u8(in) % 4;
          for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){fuzz_real(in, -1.5f, 1.5f), fuzz_real(in, -1.5f, 1.5f)};
          tb_result r = tb_make_polygon(pts, n, fuzz_u8(in) & 1 ? 0.05f : 0.0f, &p);
          if (r != TB_OK) return TB_OK; /* refused geometry: nothing to add */
          s = tb_create_polygon_shape(body, &sd, &p);
        }
      }
      if (tb_shape_id_is_null(s)) return tb_last_result();
      add_shape(m, s);
      return TB_OK;
    }
    case 3: { /* destroy a shape */
      int si = pick(in, m->shape_count);
      tb_shape_id s = si >= 0 ? m->shapes[si] : m->dead_shape;
      tb_result r = tb_destroy_shape(s);
      if (r == TB_OK) {
        m->shapes[si] = m->shapes[--m->shape_count];
        m->dead_shape = s;
      }
      return r;
    }
    case 4: { /* a joint between two bodies */
      if (m->joint_count >= MAX_JOINTS || m->body_count < 2) return TB_OK;
      tb_body_id other = m->bodies[pick(in, m->body_count)];
      tb_vec2 anchor = {fuzz_real(in, -1, 1), fuzz_real(in, -1, 1)};
      tb_joint_id j = {0, 0, 0};
      switch (fuzz_u8(in) % 7) {
        case 0: {
          tb_distance_joint_def d = tb_default_distance_joint_def();
          d.body_a = body, d.body_b = other, d.local_anchor_a = anchor, d.length = fuzz_real(in, 0.1f, 5);
          d.enable_spring = fuzz_u8(in) & 1, d.hertz = fuzz_real(in, 0, 10);
          j = tb_create_distance_joint(w, &d);
          break;
        }
        case 1: {
          tb_revolute_joint_def d = tb_default_revolute_joint_def();
          d.body_a = body, d.body_b = other, d.local_anchor_b = anchor, d.enable_motor = true;
          d.motor_speed = fuzz_real(in, -10, 10), d.max_motor_torque = fuzz_real(in, 0, 100);
          d.enable_limit = fuzz_u8(in) & 1, d.lower_angle = -0.5f, d.upper_angle = fuzz_real(in, -1, 1);
          j = tb_create_revolute_joint(w, &d);
          break;
        }
        case 2: {
          tb_prismatic_joint_def d = tb_default_prismatic_joint_def();
          d.body_a = body, d.body_b = other, d.local_axis_a = anchor, d.enable_limit = true;
          d.lower_translation = -1, d.upper_translation = fuzz_real(in, -2, 2);
          j = tb_create_prismatic_joint(w, &d);
          break;
        }
        case 3: {
          tb_weld_joint_def d = tb_default_weld_joint_def();
          d.body_a = body, d.body_b = other, d.local_anchor_a = anchor, d.linear_hertz = fuzz_real(in, 0, 20);
          j = tb_create_weld_joint(w, &d);
          break;
        }
        case 4: {
          tb_wheel_joint_def d = tb_default_wheel_joint_def();
          d.body_a = body, d.body_b = other, d.local_axis_a = anchor, d.enable_motor = true;
          d.max_motor_torque = fuzz_real(in, 0, 50), d.motor_speed = fuzz_real(in, -20, 20);
          j = tb_create_wheel_joint(w, &d);
          break;
        }
        case 5: {
          tb_mouse_joint_def d = tb_default_mouse_joint_def();
          d.body_a = body, d.body_b = other, d.target = (tb_vec2){fuzz_real(in, -20, 20), fuzz_real(in, -5, 30)};
          j = tb_create_mouse_joint(w, &d);
          break;
        }
        default: {
          tb_motor_joint_def d = tb_default_motor_joint_def();
          d.body_a = body, d.body_b = other, d.linear_offset = anchor, d.max_force = fuzz_real(in, 0, 1000);
          d.correction_factor = fuzz_real(in, 0, 1);
          j = tb_create_motor_joint(w, &d);
        }
      }
      if (tb_joint_id_is_null(j)) return tb_last_result();
      m->joints[m->joint_count++] = j;
      return TB_OK;
    }
    case 5: { /* destroy a joint */
      int ji = pick(in, m->joint_count);
      tb_joint_id j = ji >= 0 ? m->joints[ji] : m->dead_joint;
      tb_result r = tb_destroy_joint(j);
      if (r == TB_OK) {
        m->joints[ji] = m->joints[--m->joint_count];
        m->dead_joint = j;
      }
      return r;
    }
    case 6:
    case 7: { /* step (the most common command) */
      static const float steps[8] = {1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 120.0f, 0.1f, 0.0f, -1.0f / 60.0f, NAN, 2.0f};
      static const int subs[8] = {4, 1, 8, 2, 0, 65, -3, 64};
      float dt = steps[fuzz_u8(in) % 8];
      int sub = subs[fuzz_u8(in) % 8];
      if (m->steps >= MAX_STEPS) return TB_OK;
      m->steps += 1;
      tb_result r = tb_world_step(w, dt, sub);
      /* TB_ERR_NUMERIC: a body got a non-finite state and was contained (kept
       * as before the step); check_invariants still holds every body finite.
       * Accepted inputs can still combine into it: forces of up to 1e18 N on a
       * gram body overflow its acceleration, and joints driven that hard by
       * 0.1 s steps diverge. Seed fuzz/corpus/api/numeric_weld_to_spinning_kinematic
       * was a real solver bug (a weld's 2x2 determinant overflowing a float;
       * fixed, and test_joint holds it). */
      FUZZ_CHECK(r == TB_OK || r == TB_ERR_INVALID_ARGUMENT || r == TB_ERR_NUMERIC, "step: %s", tb_last_error());
      return r;
    }
    case 8: { /* forces and impulses */
      tb_vec2 v = {fuzz_real(in, -1000, 1000), fuzz_real(in, -1000, 1000)};
      tb_vec2 p = {fuzz_real(in, -20, 20), fuzz_real(in, -5, 30)};
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
      tb_vec2 v = {fuzz_real(in, -50, 50), fuzz_real(in, -50, 50)};
      switch (fuzz_u8(in) % 3) {
        case 0: return tb_body_set_linear_velocity(body, v);
        case 1: return tb_body_set_angular_velocity(body, v.x);
        default: return tb_body_set_transform(body, v, fuzz_real(in, -4, 4));
      }
    }
    case 10: { /* body settings */
      switch (fuzz_u8(in) % 8) {
        case 0: return tb_body_set_type(body, (tb_body_type)(fuzz_u8(in) % 4));
        case 1: return tb_body_set_enabled(body, fuzz_u8(in) & 1);
        case 2: return tb_body_set_awake(body, fuzz_u8(in) & 1);
        case 3: return tb_body_set_bullet(body, fuzz_u8(in) & 1);
        case 4: return tb_body_set_fixed_rotation(body, fuzz_u8(in) & 1);
        case 5: return tb_body_set_linear_damping(body, fuzz_real(in, 0, 5));
        case 6: return tb_body_set_gravity_scale(body, fuzz_real(in, -2, 2));
        default: {
          tb_mass_data md = {fuzz_real(in, 0, 10), {fuzz_real(in, -1, 1), 0}, fuzz_real(in, 0, 10)};
          return fuzz_u8(in) & 1 ? tb_body_set_mass_data(body, md) : tb_body_reset_mass_data(body);
        }
      }
    }
    case 11: { /* shape settings */
      int si = pick(in, m->shape_count);
      tb_shape_id s = si >= 0 ? m->shapes[si] : m->dead_shape;
      switch (fuzz_u8(in) % 4) {
        case 0: return tb_shape_set_density(s, fuzz_real(in, 0, 10));
        case 1: return tb_shape_set_friction(s, fuzz_real(in, 0, 2));
        case 2: {
          tb_filter f = tb_default_filter();
          f.group_index = (int8_t)fuzz_u8(in) % 3;
          f.mask_bits = fuzz_u8(in) & 1 ? UINT64_MAX : 2;
          return tb_shape_set_filter(s, f);
        }
        default: return tb_shape_set_tangent_speed(s, fuzz_real(in, -5, 5));
      }
    }
    case 12: { /* queries */
      tb_query_filter f = tb_default_query_filter();
      int hits = 0;
      tb_vec2 o = {fuzz_real(in, -20, 20), fuzz_real(in, -5, 30)}, t = {fuzz_real(in, -30, 30), fuzz_real(in, -30, 30)};
      switch (fuzz_u8(in) % 5) {
        case 0: return tb_world_cast_ray(w, o, t, f, cast, &hits) == TB_OK ? TB_OK : tb_last_result();
        case 1: {
          tb_ray_result rr[4];
          int n = 0;
          tb_result r = tb_world_cast_ray_all(w, o, t, f, rr, 4, &n);
          for (int i = 0; r == TB_OK && i < n && i < 4; ++i)
            FUZZ_CHECK(tb_shape_is_valid(rr[i].shape) && fuzz_vec_finite(rr[i].point), "ray_all hit");
          return r;
        }
        case 2: {
          tb_aabb box = {{fminf(o.x, t.x), fminf(o.y, t.y)}, {fmaxf(o.x, t.x), fmaxf(o.y, t.y)}};
          return tb_world_overlap_aabb(w, box, f, count_overlap, &hits);
        }
        case 3: return tb_world_overlap_point(w, o, f, count_overlap, &hits);
        default: {
          tb_shape_proxy proxy = {{{0, 0}, {0.5f, 0}, {0, 0.5f}}, 3, fuzz_range(in, 0, 0.5f)};
          return tb_world_cast_shape(w, &proxy, (tb_transform){o, {1, 0}}, t, f, cast, &hits);
        }
      }
    }
    case 13: { /* chains */
      if (m->chain_count > 0 && (fuzz_u8(in) & 1)) {
        int ci = pick(in, m->chain_count);
        tb_result r = tb_destroy_chain(m->chains[ci]);
        if (r == TB_OK) m->chains[ci] = m->chains[--m->chain_count], prune(m);
        return r;
      }
      if (m->chain_count >= MAX_CHAINS) return TB_OK;
      tb_vec2 pts[6];
      int n = 2 + fuzz_u8(in) % 5;
      for (int i = 0; i < n; ++i) pts[i] = (tb_vec2){-20.0f + 8.0f * i, fuzz_real(in, -2, 2)};
      tb_chain_def cd = tb_default_chain_def();
      cd.points = pts;
      cd.count = n;
      cd.is_loop = n >= 3 && (fuzz_u8(in) & 1);
      tb_chain_id c = tb_create_chain(body, &cd);
      if (tb_chain_id_is_null(c)) return tb_last_result();
      m->chains[m->chain_count++] = c;
      return TB_OK;
    }
    case 14: { /* world settings */
      switch (fuzz_u8(in) % 6) {
        case 0: return tb_world_set_gravity(w, (tb_vec2){fuzz_real(in, -20, 20), fuzz_real(in, -20, 20)});
        case 1: return tb_world_set_integrator(w, (tb_integrator)(fuzz_u8(in) % 4));
        case 2: return tb_world_enable_sleeping(w, fuzz_u8(in) & 1);
        case 3: return tb_world_enable_continuous(w, fuzz_u8(in) & 1);
        case 4: return tb_world_set_relax_iterations(w, 1 + fuzz_u8(in) % TB_MAX_RELAX_ITERATIONS);
        default: return tb_world_set_contact_tuning(w, fuzz_real(in, 1, 60), fuzz_real(in, 0, 20), 3.0f);
      }
    }
    default: { /* reads: must not change anything */
      tb_contact_data cd[4];
      tb_body_get_contact_data(body, cd, 4);
      tb_body_get_kinetic_energy(body);
      tb_world_get_contact_events(w);
      tb_world_get_sensor_events(w);
      for (int i = 0; i < m->joint_count; ++i) tb_joint_get_constraint_force(m->joints[i]);
      return TB_OK;
    }
  }
}

static void check_invariants(const model* m) {
  tb_counts c = tb_world_get_counts(m->world);
  int chain_shapes = 0;
  for (int i = 0; i < m->chain_count; ++i) chain_shapes += tb_chain_get_segment_count(m->chains[i]);
  FUZZ_CHECK(c.body_count == m->body_count, "bodies: world %d, alive %d", c.body_count, m->body_count);
  FUZZ_CHECK(c.shape_count == m->shape_count + chain_shapes, "shapes: world %d, alive %d + %d chain segments",
             c.shape_count, m->shape_count, chain_shapes);
  FUZZ_CHECK(c.joint_count == m->joint_count, "joints: world %d, alive %d", c.joint_count, m->joint_count);
  FUZZ_CHECK(c.awake_body_count >= 0 && c.awake_body_count <= c.body_count, "awake %d", c.awake_body_count);
  FUZZ_CHECK(c.touching_count <= c.contact_count, "touching %d > contacts %d", c.touching_count, c.contact_count);
  for (int i = 0; i < m->body_count; ++i) {
    tb_body_id b = m->bodies[i];
    FUZZ_CHECK(tb_body_is_valid(b), "body %d invalid", i);
    tb_vec2 p = tb_body_get_position(b), v = tb_body_get_linear_velocity(b);
    FUZZ_CHECK(fuzz_vec_finite(p) && fuzz_vec_finite(v) && isfinite(tb_body_get_angle(b)) &&
                   isfinite(tb_body_get_angular_velocity(b)),
               "body %d state not finite", i);
    FUZZ_CHECK(fuzz_vec_finite(tb_body_get_world_center(b)), "body %d centre", i);
  }
  for (int i = 0; i < m->shape_count; ++i) FUZZ_CHECK(tb_shape_is_valid(m->shapes[i]), "shape %d invalid", i);
  for (int i = 0; i < m->joint_count; ++i) FUZZ_CHECK(tb_joint_is_valid(m->joints[i]), "joint %d invalid", i);
  FUZZ_CHECK(!tb_body_is_valid(m->dead_body) && !tb_shape_is_valid(m->dead_shape) && !tb_joint_is_valid(m->dead_joint),
             "a destroyed handle is valid again");
  FUZZ_CHECK(tb_world_hash(m->world) == tb_world_hash(m->world), "hash not stable");
}

static uint64_t run(const uint8_t* data, size_t size, bool check) {
  model m;
  memset(&m, 0, sizeof m);
  tb_world_def wd = tb_default_world_def();
  m.world = tb_create_world(&wd);
  FUZZ_CHECK(!tb_world_id_is_null(m.world), "world: %s", tb_last_error());
  fuzz_input in = {data, size, 0};
  int commands = 0;
  while (in.at < in.size && commands < 200) {
    commands += 1;
    uint64_t before = tb_world_hash(m.world);
    tb_clear_error();
    tb_result r = command(&m, &in);
    if (!check) continue;
    if (r != TB_OK && r != TB_ERR_NUMERIC) {
      FUZZ_CHECK(tb_world_hash(m.world) == before, "a refused call (%s) changed the world", tb_last_error());
      FUZZ_CHECK(strlen(tb_last_error()) > 0, "refused without a message");
    }
    check_invariants(&m);
  }
  uint64_t h = tb_world_hash(m.world);
  FUZZ_CHECK(tb_destroy_world(m.world) == TB_OK, "destroy world");
  return h;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  uint64_t h1 = run(data, size, true);
  uint64_t h2 = run(data, size, false);
  FUZZ_CHECK(h1 == h2, "the same commands gave different worlds");
  return 0;
}
