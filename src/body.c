/* Bodies: creation, state access, forces and impulses, mass properties. */
#include "body.h"

#include <stddef.h>

#include "geometry.h"
#include "math_internal.h"
#include "world.h"
#include "units.h"

/* Resolve a body handle or return `fallback` from the calling function. */
#define GET_BODY(id, fallback)                  \
  tb_world* w = NULL;                           \
  tb_body* b = tb_body_get((id), &w, __func__); \
  if (b == NULL) return (fallback);             \
  (void)w
#define GET_BODY_FOR_CHANGE(id)                          \
  tb_world* w = NULL;                                    \
  tb_body* b = tb_body_get_unlocked((id), &w, __func__); \
  if (b == NULL) return tb_last_result()

static const tb_vec2 zero2 = {0.0f, 0.0f};

tb_body_def tb_default_body_def(void) {
  return (tb_body_def){.type = TB_STATIC_BODY,
                       .gravity_scale = 1.0f,
                       .enabled = true,
                       .enable_sleep = true,
                       .is_awake = true,
                       .sleep_threshold = tb_meters(0.05f)};
}

void tb_body_sync_transform(tb_body* b) {
  b->transform.q = tb_make_rot(b->angle);
  b->transform.p = tb_sub(b->center, tb_rotate(b->transform.q, b->local_center));
}

tb_vec2 tb_body_gravity(const tb_world* w, const tb_body* b) {
  tb_vec2 g = tb_scale(b->gravity_scale, w->gravity);
  float length = tb_length(g); /* inf when the product overflows: then the clamp keeps g's direction */
  const float max_gravity = tb_units.max_gravity;
  if (length <= max_gravity) return g;
  float scale = b->gravity_scale < 0.0f ? -max_gravity : max_gravity;
  return tb_scale(scale, tb_normalize(w->gravity));
}

/* How far x lies beyond [-limit, limit], signed like x; 0 inside. */
static float past(float x, float limit) {
  if (x > limit) return x - limit;
  if (x < -limit) return x + limit;
  return 0.0f;
}

void tb_body_keep_in_world(tb_body* b) {
  /* The shapes lie within max_extent of the centre. Floats near TB_MAX_LENGTH
   * are 1 m apart: two of those spacings absorb the rounding of their boxes,
   * so a shape that was inside stays insertable. */
  float inner = tb_maxf(TB_MAX_LENGTH - b->max_extent - 2.0f, 0.0f), edge = TB_MAX_LENGTH - 2.0f;
  tb_vec2 old = b->center;
  if (past(old.x, inner) == 0.0f && past(old.y, inner) == 0.0f && past(b->transform.p.x, TB_MAX_LENGTH) == 0.0f &&
      past(b->transform.p.y, TB_MAX_LENGTH) == 0.0f)
    return;
  /* Set the centre at the edge rather than subtract the overshoot: a body
   * flung to 1e12 m has an overshoot whose float rounding (65 km there) would
   * leave it beyond. Then the origin (which may lie off the shapes) likewise. */
  tb_vec2 c = {tb_minf(tb_maxf(old.x, -inner), inner), tb_minf(tb_maxf(old.y, -inner), inner)};
  tb_vec2 p = tb_sub(c, tb_rotate(b->transform.q, b->local_center));
  tb_vec2 shift = {past(p.x, edge), past(p.y, edge)};
  b->center = tb_sub(c, shift);
  b->center_residual = (tb_vec2){0.0f, 0.0f};
  b->transform.p = tb_sub(p, shift);
  /* the edge holds it like a wall: no speed outwards */
  tb_vec2 back = tb_sub(old, b->center);
  if (back.x * b->linear_velocity.x > 0.0f) b->linear_velocity.x = 0.0f;
  if (back.y * b->linear_velocity.y > 0.0f) b->linear_velocity.y = 0.0f;
}

/* Extents about the centre of mass: the farthest surface point (rotation seen
 * as speed, for sleep and sweeps) and the thinnest half-thickness (how far the
 * body may move in a step before it could pass through something); one
 * shape's here, the body's the largest far and the least thin of its shapes. */
static void shape_extents(const tb_body* b, const tb_shape* s, float* far_out, float* thin_out) {
  float far = 0.0f, thin = tb_units.linear_slop;
  switch (s->type) {
    case TB_SHAPE_CIRCLE:
      far = tb_length(tb_sub(s->geom.circle.center, b->local_center)) + s->geom.circle.radius;
      thin = s->geom.circle.radius;
      break;
    case TB_SHAPE_CAPSULE:
      far = tb_maxf(tb_length(tb_sub(s->geom.capsule.center1, b->local_center)),
                    tb_length(tb_sub(s->geom.capsule.center2, b->local_center))) +
            s->geom.capsule.radius;
      thin = s->geom.capsule.radius;
      break;
    case TB_SHAPE_SEGMENT:
      far = tb_maxf(tb_length(tb_sub(s->geom.segment.point1, b->local_center)),
                    tb_length(tb_sub(s->geom.segment.point2, b->local_center)));
      break;
    case TB_SHAPE_CHAIN_SEGMENT:
      far = tb_maxf(tb_length(tb_sub(s->geom.chain_segment.segment.point1, b->local_center)),
                    tb_length(tb_sub(s->geom.chain_segment.segment.point2, b->local_center)));
      break;
    case TB_SHAPE_POLYGON: {
      const tb_polygon* p = &s->geom.polygon;
      thin = TB_MAX_LENGTH;
      for (int k = 0; k < p->count; ++k) {
        far = tb_maxf(far, tb_length(tb_sub(p->vertices[k], b->local_center)));
        thin = tb_minf(thin, tb_dot(p->normals[k], tb_sub(p->vertices[k], p->centroid))); /* centroid to edge */
      }
      far += p->radius;
      thin += p->radius;
      break;
    }
  }
  *far_out = far;
  *thin_out = thin;
}

static void update_extents(tb_world* w, tb_body* b) {
  float max_extent = 0.0f, min_extent = TB_MAX_LENGTH;
  for (int i = b->shape_list; i >= 0; i = tb_shape_at(w, i)->next) {
    float far, thin;
    shape_extents(b, tb_shape_at(w, i), &far, &thin);
    max_extent = tb_maxf(max_extent, far);
    min_extent = tb_minf(min_extent, thin);
  }
  b->max_extent = max_extent;
  b->min_extent = min_extent;
}

void tb_body_add_shape_mass(tb_world* w, tb_body* b, const tb_shape* s) {
  /* A static body has no mass, no velocity and its centre at its origin, so
   * a new shape changes only its extents, and only by its own (a level of
   * thousands of boxes on one static body was built in time quadratic in its
   * shapes). */
  if (b->type == TB_STATIC_BODY && !b->mass_overridden && b->local_center.x == 0.0f && b->local_center.y == 0.0f) {
    float far, thin;
    shape_extents(b, s, &far, &thin);
    b->max_extent = tb_maxf(b->max_extent, far);
    b->min_extent = tb_minf(b->min_extent, thin);
    return;
  }
  tb_body_update_mass(w, b);
}

void tb_body_update_mass(tb_world* w, tb_body* b) {
  tb_vec2 old_center = b->center;
  b->mass = b->inv_mass = b->inertia = b->inv_inertia = 0.0f;
  b->local_center = zero2;
  b->mass_overridden = false;
  if (b->type == TB_DYNAMIC_BODY) {
    /* M = sum m_i; c = sum m_i c_i / M; I = sum (I_i + m_i |c_i - c|^2) */
    double m = 0.0, cx = 0.0, cy = 0.0;
    for (int s = b->shape_list; s >= 0; s = tb_shape_at(w, s)->next) {
      tb_mass_data md = tb_shape_geom_mass(tb_shape_at(w, s));
      m += md.mass;
      cx += (double)md.mass * md.center.x;
      cy += (double)md.mass * md.center.y;
    }
    if (m > 0.0) {
      cx /= m;
      cy /= m;
      double inertia = 0.0;
      for (int s = b->shape_list; s >= 0; s = tb_shape_at(w, s)->next) {
        tb_mass_data md = tb_shape_geom_mass(tb_shape_at(w, s));
        double dx = md.center.x - cx, dy = md.center.y - cy;
        inertia += md.rotational_inertia + md.mass * (dx * dx + dy * dy);
      }
      /* each shape's mass is within TB_MAX_VALUE, their sum and the parallel-axis
       * terms need not be: saturate, so tb_body_set_mass_data takes what the
       * getters report */
      b->mass = tb_saturate(m);
      b->local_center = (tb_vec2){(float)cx, (float)cy};
      b->inertia = tb_saturate(inertia);
    } else {
      b->mass = 1.0f; /* a dynamic body without area still needs a finite mass */
    }
    b->inv_mass = 1.0f / b->mass;
    if (b->inertia > 0.0f && !b->fixed_rotation) b->inv_inertia = 1.0f / b->inertia;
  }
  /* keep the origin in place; the new centre moves with the body's rotation */
  b->center = tb_transform_point(b->transform, b->local_center);
  b->center_residual = (tb_vec2){0.0f, 0.0f};
  b->linear_velocity = tb_add(b->linear_velocity, tb_cross_sv(b->angular_velocity, tb_sub(b->center, old_center)));
  if (b->fixed_rotation) b->angular_velocity = 0.0f;
  update_extents(w, b);
}

static tb_result check_type(tb_world* w, const char* fn, tb_body_type t) {
  if ((int)t < (int)TB_STATIC_BODY || (int)t > (int)TB_DYNAMIC_BODY)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: type %d is not a tb_body_type", fn, (int)t);
  return TB_OK;
}

static tb_result check_vector(tb_world* w, const char* fn, const char* name, tb_vec2 v) {
  if (!tb_vector_ok(v))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = (%g, %g) is not finite or beyond TB_MAX_VALUE", fn, name,
                   (double)v.x, (double)v.y);
  return TB_OK;
}

static tb_result check_value(tb_world* w, const char* fn, const char* name, float v) {
  if (!tb_value_ok(v))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g is not finite or beyond TB_MAX_VALUE", fn, name, (double)v);
  return TB_OK;
}

static tb_result check_point(tb_world* w, const char* fn, const char* name, tb_vec2 p) {
  if (!tb_point_ok(p))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = (%g, %g) is not finite or beyond TB_MAX_LENGTH", fn, name,
                   (double)p.x, (double)p.y);
  return TB_OK;
}

tb_body_id tb_create_body(tb_world_id world_id, const tb_body_def* def) {
  const tb_body_id null_id = {0, 0, 0};
  const char* fn = "tb_create_body";
  tb_world* w = tb_world_get_unlocked(world_id, fn);
  if (w == NULL) return null_id;
  if (def == NULL) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: def is NULL", fn);
    return null_id;
  }
  if (check_type(w, fn, def->type) || check_point(w, fn, "def->position", def->position) ||
      tb_check_angle(w, fn, "def->angle", def->angle) ||
      check_vector(w, fn, "def->linear_velocity", def->linear_velocity) ||
      check_value(w, fn, "def->angular_velocity", def->angular_velocity) ||
      tb_check_non_negative(w, fn, "def->linear_damping", def->linear_damping) ||
      tb_check_non_negative(w, fn, "def->angular_damping", def->angular_damping) ||
      check_value(w, fn, "def->gravity_scale", def->gravity_scale) ||
      tb_check_non_negative(w, fn, "def->sleep_threshold", def->sleep_threshold))
    return null_id;
  int index = tb_pool_alloc(&w->bodies);
  if (index < 0) {
    tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for another body", fn);
    return null_id;
  }
  tb_body* b = tb_body_at(w, index);
  b->type = def->type;
  b->center = def->position;
  b->center_residual = (tb_vec2){0.0f, 0.0f};
  b->angle = def->angle;
  b->angle_residual = 0.0f;
  if (def->type != TB_STATIC_BODY) {
    b->linear_velocity = def->linear_velocity;
    b->angular_velocity = def->fixed_rotation ? 0.0f : def->angular_velocity;
  }
  b->linear_damping = def->linear_damping;
  b->angular_damping = def->angular_damping;
  b->gravity_scale = def->gravity_scale;
  b->fixed_rotation = def->fixed_rotation;
  b->enabled = def->enabled;
  b->is_bullet = def->is_bullet;
  b->enable_sleep = def->enable_sleep;
  b->sleep_threshold = def->sleep_threshold;
  b->user_data = def->user_data;
  b->shape_list = -1;
  b->contact_list = -1;
  b->joint_list = -1;
  tb_body_sync_transform(b);
  tb_body_update_mass(w, b);
  b->center0 = b->center;
  b->angle0 = b->angle;
  if (!tb_add_body_to_sets(w, index, def->is_awake)) {
    tb_pool_release(&w->bodies, index);
    tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for another body", fn);
    return null_id;
  }
  return tb_make_body_id(w, index);
}

/* Shapes leave the broad phase (their contacts end) or join it again. */
static void remove_proxies(tb_world* w, int body) {
  tb_contacts_destroy_of_body(w, body, -1);
  for (int s = tb_body_at(w, body)->shape_list; s >= 0; s = tb_shape_at(w, s)->next) tb_broad_phase_destroy_proxy(w, s);
}

/* Checked before anything changes, so that add_proxies cannot fail after. */
static tb_result prepare_proxies(tb_world* w, int body, tb_body_type type, const char* fn) {
  const tb_body* b = tb_body_at(w, body);
  for (int s = b->shape_list; s >= 0; s = tb_shape_at(w, s)->next) {
    tb_result r = tb_broad_phase_prepare_insert(w, tb_shape_at(w, s), b->transform, type, b->shape_count, fn);
    if (r != TB_OK) return r;
  }
  return TB_OK;
}

static void add_proxies(tb_world* w, int body) {
  for (int s = tb_body_at(w, body)->shape_list; s >= 0; s = tb_shape_at(w, s)->next)
    (void)tb_broad_phase_create_proxy(w, s);
}

void tb_body_update_proxies(tb_world* w, int body, tb_vec2 displacement, bool enlarge) {
  const tb_body* b = tb_body_at(w, body);
  for (int i = b->shape_list; i >= 0; i = tb_shape_at(w, i)->next) {
    tb_shape* s = tb_shape_at(w, i);
    s->aabb = tb_shape_geom_aabb(s, b->transform);
    tb_broad_phase_move_proxy(w, i, displacement, enlarge);
  }
}

/* Wakes the bodies a body touches (it is about to vanish or change). */
static void wake_touching(tb_world* w, int body) {
  for (int key = tb_body_at(w, body)->contact_list; key >= 0;) {
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, key >> 1);
    if (c->flags & TB_CONTACT_TOUCHING) tb_wake_body(w, c->edges[(key & 1) ^ 1].body);
    key = c->edges[key & 1].next;
  }
}

tb_result tb_destroy_body(tb_body_id id) {
  GET_BODY_FOR_CHANGE(id);
  wake_touching(w, id.index1 - 1);
  tb_joints_destroy_of_body(w, id.index1 - 1);
  tb_remove_body_from_sets(w, id.index1 - 1);
  remove_proxies(w, id.index1 - 1);
  tb_chains_destroy_of_body(w, id.index1 - 1);
  for (int s = b->shape_list; s >= 0;) {
    int next = tb_shape_at(w, s)->next;
    tb_pool_release(&w->shapes, s);
    s = next;
  }
  tb_pool_release(&w->bodies, id.index1 - 1);
  return TB_OK;
}

bool tb_body_is_valid(tb_body_id id) { return tb_body_get(id, NULL, NULL) != NULL; }

tb_world_id tb_body_get_world(tb_body_id id) {
  GET_BODY(id, ((tb_world_id){0, 0}));
  return (tb_world_id){(uint16_t)(w->index + 1), w->generation};
}

tb_body_type tb_body_get_type(tb_body_id id) {
  GET_BODY(id, TB_STATIC_BODY);
  return b->type;
}

tb_result tb_body_set_type(tb_body_id id, tb_body_type type) {
  GET_BODY_FOR_CHANGE(id);
  tb_result r = check_type(w, __func__, type);
  if (r != TB_OK) return r;
  if (b->type == type) return TB_OK;
  if (b->enabled) {
    r = prepare_proxies(w, id.index1 - 1, type, __func__);
    if (r != TB_OK) return r;
  }
  /* the shapes move to the tree of the new type; contacts are found anew */
  wake_touching(w, id.index1 - 1);
  tb_remove_body_from_sets(w, id.index1 - 1);
  if (b->enabled) remove_proxies(w, id.index1 - 1);
  b->type = type;
  if (b->enabled) add_proxies(w, id.index1 - 1);
  if (type == TB_STATIC_BODY) {
    b->linear_velocity = zero2;
    b->angular_velocity = 0.0f;
  }
  b->force = zero2;
  b->torque = 0.0f;
  tb_body_update_mass(w, b);
  (void)tb_add_body_to_sets(w, id.index1 - 1, true);
  return TB_OK;
}

tb_vec2 tb_body_get_position(tb_body_id id) {
  GET_BODY(id, zero2);
  return b->transform.p;
}

float tb_body_get_angle(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->angle;
}

tb_rot tb_body_get_rotation(tb_body_id id) {
  GET_BODY(id, ((tb_rot){1.0f, 0.0f}));
  return b->transform.q;
}

tb_transform tb_body_get_transform(tb_body_id id) {
  GET_BODY(id, ((tb_transform){{0.0f, 0.0f}, {1.0f, 0.0f}}));
  return b->transform;
}

tb_result tb_body_set_transform(tb_body_id id, tb_vec2 position, float angle) {
  GET_BODY_FOR_CHANGE(id);
  if (check_point(w, __func__, "position", position) || tb_check_angle(w, __func__, "angle", angle))
    return tb_last_result();
  b->angle = angle;
  b->angle_residual = 0.0f;
  b->transform.q = tb_make_rot(angle);
  b->transform.p = position;
  b->center = tb_transform_point(b->transform, b->local_center);
  b->center_residual = (tb_vec2){0.0f, 0.0f};
  b->center0 = b->center;
  b->angle0 = b->angle;
  tb_body_update_proxies(w, id.index1 - 1, (tb_vec2){0.0f, 0.0f}, false);
  wake_touching(w, id.index1 - 1);
  tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

tb_vec2 tb_body_get_local_center(tb_body_id id) {
  GET_BODY(id, zero2);
  return b->local_center;
}

tb_vec2 tb_body_get_world_center(tb_body_id id) {
  GET_BODY(id, zero2);
  return b->center;
}

tb_vec2 tb_body_get_linear_velocity(tb_body_id id) {
  GET_BODY(id, zero2);
  return b->linear_velocity;
}

tb_result tb_body_set_linear_velocity(tb_body_id id, tb_vec2 v) {
  GET_BODY_FOR_CHANGE(id);
  if (check_vector(w, __func__, "v", v)) return tb_last_result();
  if (b->type == TB_STATIC_BODY) return TB_OK;
  b->linear_velocity = v;
  if (v.x != 0.0f || v.y != 0.0f) tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

float tb_body_get_angular_velocity(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->angular_velocity;
}

tb_result tb_body_set_angular_velocity(tb_body_id id, float omega) {
  GET_BODY_FOR_CHANGE(id);
  if (check_value(w, __func__, "w", omega)) return tb_last_result();
  if (b->type == TB_STATIC_BODY || b->fixed_rotation) return TB_OK;
  b->angular_velocity = omega;
  if (omega != 0.0f) tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

tb_vec2 tb_body_get_point_velocity(tb_body_id id, tb_vec2 world_point) {
  GET_BODY(id, zero2);
  if (check_point(w, __func__, "world_point", world_point)) return zero2;
  double omega = b->angular_velocity, rx = (double)world_point.x - b->center.x,
         ry = (double)world_point.y - b->center.y;
  return tb_saturate2(b->linear_velocity.x - omega * ry, b->linear_velocity.y + omega * rx);
}

float tb_body_get_linear_damping(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->linear_damping;
}

tb_result tb_body_set_linear_damping(tb_body_id id, float damping) {
  GET_BODY_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "damping", damping)) return tb_last_result();
  b->linear_damping = damping;
  return TB_OK;
}

float tb_body_get_angular_damping(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->angular_damping;
}

tb_result tb_body_set_angular_damping(tb_body_id id, float damping) {
  GET_BODY_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "damping", damping)) return tb_last_result();
  b->angular_damping = damping;
  return TB_OK;
}

float tb_body_get_gravity_scale(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->gravity_scale;
}

tb_result tb_body_set_gravity_scale(tb_body_id id, float scale) {
  GET_BODY_FOR_CHANGE(id);
  if (check_value(w, __func__, "scale", scale)) return tb_last_result();
  b->gravity_scale = scale;
  return TB_OK;
}

bool tb_body_is_fixed_rotation(tb_body_id id) {
  GET_BODY(id, false);
  return b->fixed_rotation;
}

tb_result tb_body_set_fixed_rotation(tb_body_id id, bool fixed) {
  GET_BODY_FOR_CHANGE(id);
  if (b->fixed_rotation == fixed) return TB_OK;
  b->fixed_rotation = fixed;
  if (fixed) b->angular_velocity = 0.0f;
  if (b->type == TB_DYNAMIC_BODY) {
    b->inv_inertia = (!fixed && b->inertia > 0.0f) ? 1.0f / b->inertia : 0.0f;
  }
  return TB_OK;
}

bool tb_body_is_enabled(tb_body_id id) {
  GET_BODY(id, false);
  return b->enabled;
}

/* A disabled body leaves the broad phase: no contacts, no queries, no cost. */
tb_result tb_body_set_enabled(tb_body_id id, bool enabled) {
  GET_BODY_FOR_CHANGE(id);
  if (b->enabled == enabled) return TB_OK;
  if (enabled) {
    tb_result r = prepare_proxies(w, id.index1 - 1, b->type, __func__);
    if (r != TB_OK) return r;
    add_proxies(w, id.index1 - 1);
  } else {
    wake_touching(w, id.index1 - 1);
    tb_remove_body_from_sets(w, id.index1 - 1);
    remove_proxies(w, id.index1 - 1);
  }
  b->enabled = enabled;
  if (enabled) (void)tb_add_body_to_sets(w, id.index1 - 1, true);
  return TB_OK;
}

void* tb_body_get_user_data(tb_body_id id) {
  GET_BODY(id, NULL);
  return b->user_data;
}

tb_result tb_body_set_user_data(tb_body_id id, void* user_data) {
  GET_BODY_FOR_CHANGE(id);
  b->user_data = user_data;
  return TB_OK;
}

/* F at a world point p adds F and the torque T = r x F, r = p - X. */
tb_result tb_body_apply_force(tb_body_id id, tb_vec2 force, tb_vec2 world_point) {
  GET_BODY_FOR_CHANGE(id);
  if (check_vector(w, __func__, "force", force) || check_point(w, __func__, "world_point", world_point))
    return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  b->force = tb_add(b->force, force);
  b->torque += tb_cross(tb_sub(world_point, b->center), force);
  tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

tb_result tb_body_apply_force_to_center(tb_body_id id, tb_vec2 force) {
  GET_BODY_FOR_CHANGE(id);
  if (check_vector(w, __func__, "force", force)) return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  b->force = tb_add(b->force, force);
  tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

tb_result tb_body_apply_torque(tb_body_id id, float torque) {
  GET_BODY_FOR_CHANGE(id);
  if (check_value(w, __func__, "torque", torque)) return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  b->torque += torque;
  tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

/* J at a world point changes V by J / M and w by (r x J) / I. The new state is
 * checked before it is stored, so an overflowing impulse changes nothing. */
static tb_result apply_impulse(tb_world* w, tb_body* b, const char* fn, tb_vec2 impulse, float angular) {
  tb_vec2 v = tb_mul_add(b->linear_velocity, b->inv_mass, impulse);
  float omega = b->angular_velocity + b->inv_inertia * angular;
  if (!tb_vector_ok(v) || !tb_value_ok(omega))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: the impulse would make the velocity overflow", fn);
  b->linear_velocity = v;
  b->angular_velocity = omega;
  tb_wake_body(w, (int)(b - (tb_body*)w->bodies.items));
  return TB_OK;
}

tb_result tb_body_apply_linear_impulse(tb_body_id id, tb_vec2 impulse, tb_vec2 world_point) {
  GET_BODY_FOR_CHANGE(id);
  if (check_vector(w, __func__, "impulse", impulse) || check_point(w, __func__, "world_point", world_point))
    return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  return apply_impulse(w, b, __func__, impulse, tb_cross(tb_sub(world_point, b->center), impulse));
}

tb_result tb_body_apply_linear_impulse_to_center(tb_body_id id, tb_vec2 impulse) {
  GET_BODY_FOR_CHANGE(id);
  if (check_vector(w, __func__, "impulse", impulse)) return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  return apply_impulse(w, b, __func__, impulse, 0.0f);
}

tb_result tb_body_apply_angular_impulse(tb_body_id id, float impulse) {
  GET_BODY_FOR_CHANGE(id);
  if (check_value(w, __func__, "impulse", impulse)) return tb_last_result();
  if (b->type != TB_DYNAMIC_BODY) return TB_OK;
  return apply_impulse(w, b, __func__, zero2, impulse);
}

tb_vec2 tb_body_get_force(tb_body_id id) {
  GET_BODY(id, zero2);
  return b->force;
}

float tb_body_get_torque(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->torque;
}

float tb_body_get_mass(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->mass;
}

float tb_body_get_rotational_inertia(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->inertia;
}

tb_mass_data tb_body_get_mass_data(tb_body_id id) {
  GET_BODY(id, ((tb_mass_data){0.0f, {0.0f, 0.0f}, 0.0f}));
  return (tb_mass_data){b->mass, b->local_center, b->inertia};
}

tb_result tb_body_set_mass_data(tb_body_id id, tb_mass_data md) {
  GET_BODY_FOR_CHANGE(id);
  if (b->type != TB_DYNAMIC_BODY)
    return tb_fail(w, TB_ERR_WRONG_BODY_TYPE, "%s: only a dynamic body has a mass to set", __func__);
  if (!tb_value_ok(md.mass) || md.mass <= 0.0f)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: mass_data.mass = %g must be > 0 and finite", __func__,
                   (double)md.mass);
  if (!tb_value_ok(md.rotational_inertia) || md.rotational_inertia < 0.0f)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: mass_data.rotational_inertia = %g must be >= 0 and finite",
                   __func__, (double)md.rotational_inertia);
  if (check_point(w, __func__, "mass_data.center", md.center)) return tb_last_result();
  tb_vec2 old_center = b->center;
  b->mass = md.mass;
  b->inv_mass = 1.0f / md.mass;
  b->inertia = md.rotational_inertia;
  b->inv_inertia = (md.rotational_inertia > 0.0f && !b->fixed_rotation) ? 1.0f / md.rotational_inertia : 0.0f;
  b->local_center = md.center;
  b->mass_overridden = true;
  b->center = tb_transform_point(b->transform, b->local_center);
  b->center_residual = (tb_vec2){0.0f, 0.0f};
  b->linear_velocity = tb_add(b->linear_velocity, tb_cross_sv(b->angular_velocity, tb_sub(b->center, old_center)));
  update_extents(w, b); /* about the new centre (sleep, relax passes and sweeps read them) */
  return TB_OK;
}

tb_result tb_body_reset_mass_data(tb_body_id id) {
  GET_BODY_FOR_CHANGE(id);
  tb_body_update_mass(w, b);
  tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

tb_vec2 tb_body_get_world_point(tb_body_id id, tb_vec2 p) {
  GET_BODY(id, zero2);
  if (check_point(w, __func__, "local_point", p)) return zero2;
  return tb_transform_point(b->transform, p);
}

tb_vec2 tb_body_get_local_point(tb_body_id id, tb_vec2 p) {
  GET_BODY(id, zero2);
  if (check_point(w, __func__, "world_point", p)) return zero2;
  return tb_inv_transform_point(b->transform, p);
}

tb_vec2 tb_body_get_world_vector(tb_body_id id, tb_vec2 v) {
  GET_BODY(id, zero2);
  if (check_vector(w, __func__, "local_vector", v)) return zero2;
  return tb_rotate(b->transform.q, v);
}

tb_vec2 tb_body_get_local_vector(tb_body_id id, tb_vec2 v) {
  GET_BODY(id, zero2);
  if (check_vector(w, __func__, "world_vector", v)) return zero2;
  return tb_inv_rotate(b->transform.q, v);
}

/* Only dynamic bodies carry momentum and energy; the infinite mass of static and
 * kinematic bodies makes them zero by convention. */
float tb_body_get_kinetic_energy(tb_body_id id) {
  GET_BODY(id, 0.0f);
  double vx = b->linear_velocity.x, vy = b->linear_velocity.y, omega = b->angular_velocity;
  return tb_saturate(0.5 * (b->mass * (vx * vx + vy * vy) + b->inertia * omega * omega));
}

tb_vec2 tb_body_get_linear_momentum(tb_body_id id) {
  GET_BODY(id, zero2);
  return tb_saturate2((double)b->mass * b->linear_velocity.x, (double)b->mass * b->linear_velocity.y);
}

float tb_body_get_angular_momentum(tb_body_id id, tb_vec2 p) {
  GET_BODY(id, 0.0f);
  if (check_point(w, __func__, "world_point", p)) return 0.0f;
  double rx = (double)b->center.x - p.x, ry = (double)b->center.y - p.y;
  double px = (double)b->mass * b->linear_velocity.x, py = (double)b->mass * b->linear_velocity.y;
  return tb_saturate((double)b->inertia * b->angular_velocity + (rx * py - ry * px));
}

int tb_body_get_shape_count(tb_body_id id) {
  GET_BODY(id, 0);
  return b->shape_count;
}

int tb_body_get_shapes(tb_body_id id, tb_shape_id* out, int capacity) {
  GET_BODY(id, 0);
  if (out == NULL && capacity > 0) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", __func__);
    return 0;
  }
  if (capacity < 0) {
    tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: capacity = %d is negative", __func__, capacity);
    return 0;
  }
  int n = 0;
  for (int s = b->shape_list; s >= 0 && n < capacity; s = tb_shape_at(w, s)->next) out[n++] = tb_make_shape_id(w, s);
  return n;
}

static tb_contact* edge_contact(const tb_world* w, int key) { return (tb_contact*)tb_pool_at(&w->contacts, key >> 1); }

int tb_body_get_contact_capacity(tb_body_id id) {
  GET_BODY(id, 0);
  int n = 0;
  for (int k = b->contact_list; k >= 0; k = edge_contact(w, k)->edges[k & 1].next)
    n += (edge_contact(w, k)->flags & TB_CONTACT_SENSOR) == 0;
  return n;
}

int tb_body_get_contact_data(tb_body_id id, tb_contact_data* out, int capacity) {
  GET_BODY(id, 0);
  if (out == NULL && capacity > 0) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", __func__);
    return 0;
  }
  if (capacity < 0) {
    tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: capacity = %d is negative", __func__, capacity);
    return 0;
  }
  int n = 0;
  for (int k = b->contact_list; k >= 0 && n < capacity; k = edge_contact(w, k)->edges[k & 1].next) {
    const tb_contact* c = edge_contact(w, k);
    if (c->flags & TB_CONTACT_SENSOR) continue;
    out[n++] = (tb_contact_data){tb_make_shape_id(w, c->shape_a),
                                 tb_make_shape_id(w, c->shape_b),
                                 c->manifold,
                                 c->friction,
                                 c->restitution,
                                 (c->flags & TB_CONTACT_TOUCHING) != 0,
                                 (c->flags & TB_CONTACT_ENABLED) != 0};
  }
  return n;
}

/* ---- sleep, bullets, joints -------------------------------------------------- */

bool tb_body_is_awake(tb_body_id id) {
  GET_BODY(id, false);
  return b->awake_index >= 0;
}

tb_result tb_body_set_awake(tb_body_id id, bool awake) {
  GET_BODY_FOR_CHANGE(id);
  if (awake) {
    tb_wake_body(w, id.index1 - 1);
  } else if (b->awake_index >= 0) {
    tb_sleep_island_of(w, id.index1 - 1);
  }
  return TB_OK;
}

bool tb_body_is_sleep_enabled(tb_body_id id) {
  GET_BODY(id, false);
  return b->enable_sleep;
}

tb_result tb_body_enable_sleep(tb_body_id id, bool enable) {
  GET_BODY_FOR_CHANGE(id);
  b->enable_sleep = enable;
  if (!enable) tb_wake_body(w, id.index1 - 1);
  return TB_OK;
}

float tb_body_get_sleep_threshold(tb_body_id id) {
  GET_BODY(id, 0.0f);
  return b->sleep_threshold;
}

tb_result tb_body_set_sleep_threshold(tb_body_id id, float speed) {
  GET_BODY_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "speed", speed)) return tb_last_result();
  b->sleep_threshold = speed;
  return TB_OK;
}

bool tb_body_is_bullet(tb_body_id id) {
  GET_BODY(id, false);
  return b->is_bullet;
}

tb_result tb_body_set_bullet(tb_body_id id, bool bullet) {
  GET_BODY_FOR_CHANGE(id);
  b->is_bullet = bullet;
  return TB_OK;
}

int tb_body_get_joint_count(tb_body_id id) {
  GET_BODY(id, 0);
  return b->joint_count;
}

int tb_body_get_joints(tb_body_id id, tb_joint_id* out, int capacity) {
  GET_BODY(id, 0);
  if (out == NULL || capacity < 0) {
    tb_fail(w, out == NULL ? TB_ERR_NULL_ARGUMENT : TB_ERR_INVALID_ARGUMENT, "%s: %s", __func__,
            out == NULL ? "out is NULL" : "capacity is negative");
    return 0;
  }
  int n = 0;
  for (int key = b->joint_list; key >= 0 && n < capacity;) {
    out[n++] = tb_make_joint_id(w, key >> 1);
    key = tb_joint_at(w, key >> 1)->edges[key & 1].next;
  }
  return n;
}
