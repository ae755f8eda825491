/* Shapes: attaching geometry with a material to a body. */
#include "shape.h"

#include <stddef.h>

#include "geometry.h"
#include "math_internal.h"
#include "world.h"

#define GET_SHAPE(id, fallback)                   \
  tb_world* w = NULL;                             \
  tb_shape* s = tb_shape_get((id), &w, __func__); \
  if (s == NULL) return (fallback);               \
  (void)w
#define GET_SHAPE_FOR_CHANGE(id)                           \
  tb_world* w = NULL;                                      \
  tb_shape* s = tb_shape_get_unlocked((id), &w, __func__); \
  if (s == NULL) return tb_last_result()

tb_filter tb_default_filter(void) { return (tb_filter){1u, UINT64_MAX, 0}; }

tb_shape_def tb_default_shape_def(void) {
  return (tb_shape_def){.density = 1.0f,
                        .friction = 0.6f,
                        .restitution = 0.0f,
                        .filter = tb_default_filter(),
                        .enable_sensor_events = true,
                        .enable_contact_events = true};
}

/* Puts geometry of a type into proto after the checks of tb_create_*_shape:
 * valid geometry, and a mass and inertia within TB_MAX_VALUE at proto's
 * density. On error proto may be half changed (the caller drops it). */
static tb_result set_geometry_of(tb_world* w, tb_shape* proto, tb_shape_type type, const void* geom, const char* fn) {
  const char* problem = NULL;
  proto->type = type;
  switch (type) {
    case TB_SHAPE_CIRCLE:
      proto->geom.circle = *(const tb_circle*)geom;
      problem = tb_check_circle(geom);
      break;
    case TB_SHAPE_CAPSULE:
      proto->geom.capsule = *(const tb_capsule*)geom;
      problem = tb_check_capsule(geom);
      break;
    case TB_SHAPE_SEGMENT:
      proto->geom.segment = *(const tb_segment*)geom;
      problem = tb_check_segment(geom);
      break;
    case TB_SHAPE_POLYGON:
      proto->geom.polygon = *(const tb_polygon*)geom;
      problem = tb_check_polygon(geom);
      break;
    case TB_SHAPE_CHAIN_SEGMENT: problem = "chain segments are made by tb_create_chain"; break;
  }
  if (problem != NULL)
    return tb_fail(w, type == TB_SHAPE_POLYGON ? TB_ERR_DEGENERATE_POLYGON : TB_ERR_INVALID_ARGUMENT, "%s: %s", fn,
                   problem);
  tb_mass_data md = tb_shape_geom_mass(proto);
  if (!tb_value_ok(md.mass) || !tb_value_ok(md.rotational_inertia))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: the shape's mass or inertia overflows (density %g)", fn,
                   (double)proto->density);
  return TB_OK;
}

static tb_shape_id create_shape(tb_body_id body_id, const tb_shape_def* def, tb_shape_type type, const void* geom,
                                const char* fn) {
  const tb_shape_id null_id = {0, 0, 0};
  tb_world* w = NULL;
  tb_body* b = tb_body_get_unlocked(body_id, &w, fn);
  if (b == NULL) return null_id;
  if (def == NULL || geom == NULL) {
    tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, def == NULL ? "def" : "the geometry");
    return null_id;
  }
  if (tb_check_non_negative(w, fn, "def->density", def->density) ||
      tb_check_non_negative(w, fn, "def->friction", def->friction) ||
      tb_check_restitution(w, fn, "def->restitution", def->restitution) ||
      tb_check_non_negative(w, fn, "def->rolling_resistance", def->rolling_resistance))
    return null_id;
  if (!tb_value_ok(def->tangent_speed)) {
    tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: def->tangent_speed = %g is not finite", fn, (double)def->tangent_speed);
    return null_id;
  }
  tb_shape proto = {.type = type,
                    .density = def->density,
                    .friction = def->friction,
                    .restitution = def->restitution,
                    .rolling_resistance = def->rolling_resistance,
                    .tangent_speed = def->tangent_speed,
                    .filter = def->filter,
                    .sensor = def->is_sensor,
                    .enable_sensor_events = def->enable_sensor_events,
                    .enable_contact_events = def->enable_contact_events,
                    .enable_hit_events = def->enable_hit_events,
                    .enable_pre_solve_events = def->enable_pre_solve_events,
                    .proxy = -1,
                    .chain = -1,
                    .user_data = def->user_data};
  if (set_geometry_of(w, &proto, type, geom, fn) != TB_OK) return null_id;
  int index = tb_shape_attach(w, body_id.index1 - 1, &proto, fn);
  if (index < 0) return null_id;
  tb_body* owner = tb_body_at(w, body_id.index1 - 1);
  tb_body_add_shape_mass(w, owner, tb_shape_at(w, index));
  /* a new shape wakes a body that touches or is jointed to something; a body
   * created asleep and not yet linked keeps sleeping while it gets its shapes */
  if (owner->contact_count > 0 || owner->joint_count > 0) tb_wake_body(w, body_id.index1 - 1);
  return tb_make_shape_id(w, index);
}

tb_result tb_shape_prepare(tb_world* w, int body_index, const tb_shape* proto, int proxies, const char* fn) {
  const tb_body* b = tb_body_at(w, body_index);
  if (!b->enabled) return TB_OK;
  return tb_broad_phase_prepare_insert(w, proto, b->transform, b->type, proxies, fn);
}

void tb_shape_link(tb_world* w, int body_index, int index, const tb_shape* proto) {
  tb_body* b = tb_body_at(w, body_index);
  tb_shape* s = tb_shape_at(w, index);
  *s = *proto;
  s->body = body_index;
  s->proxy = -1;
  s->prev = -1;
  s->next = b->shape_list;
  if (b->shape_list >= 0) tb_shape_at(w, b->shape_list)->prev = index;
  b->shape_list = index;
  b->shape_count += 1;
  if (b->enabled) (void)tb_broad_phase_create_proxy(w, index); /* prepared: cannot fail */
}

int tb_shape_attach(tb_world* w, int body_index, const tb_shape* proto, const char* fn) {
  if (tb_shape_prepare(w, body_index, proto, 1, fn) != TB_OK) return -1;
  int index = tb_pool_alloc(&w->shapes);
  if (index < 0) {
    tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for another shape", fn);
    return -1;
  }
  tb_shape_link(w, body_index, index, proto);
  return index;
}

void tb_shape_detach(tb_world* w, int index) {
  tb_shape* s = tb_shape_at(w, index);
  tb_body* b = tb_body_at(w, s->body);
  tb_contacts_destroy_of_body(w, s->body, index);
  tb_broad_phase_destroy_proxy(w, index);
  if (s->prev >= 0)
    tb_shape_at(w, s->prev)->next = s->next;
  else
    b->shape_list = s->next;
  if (s->next >= 0) tb_shape_at(w, s->next)->prev = s->prev;
  b->shape_count -= 1;
  tb_pool_release(&w->shapes, index);
}

tb_shape_id tb_create_circle_shape(tb_body_id body, const tb_shape_def* def, const tb_circle* circle) {
  return create_shape(body, def, TB_SHAPE_CIRCLE, circle, __func__);
}
tb_shape_id tb_create_capsule_shape(tb_body_id body, const tb_shape_def* def, const tb_capsule* capsule) {
  return create_shape(body, def, TB_SHAPE_CAPSULE, capsule, __func__);
}
tb_shape_id tb_create_segment_shape(tb_body_id body, const tb_shape_def* def, const tb_segment* segment) {
  return create_shape(body, def, TB_SHAPE_SEGMENT, segment, __func__);
}
tb_shape_id tb_create_polygon_shape(tb_body_id body, const tb_shape_def* def, const tb_polygon* polygon) {
  return create_shape(body, def, TB_SHAPE_POLYGON, polygon, __func__);
}

tb_result tb_destroy_shape(tb_shape_id id) {
  GET_SHAPE_FOR_CHANGE(id);
  if (s->chain >= 0)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: the shape is a segment of a chain: destroy the chain", __func__);
  int body = s->body;
  tb_shape_detach(w, id.index1 - 1);
  tb_body_update_mass(w, tb_body_at(w, body));
  tb_wake_body(w, body);
  return TB_OK;
}

bool tb_shape_is_valid(tb_shape_id id) { return tb_shape_get(id, NULL, NULL) != NULL; }

tb_shape_type tb_shape_get_type(tb_shape_id id) {
  GET_SHAPE(id, TB_SHAPE_CIRCLE);
  return s->type;
}

tb_body_id tb_shape_get_body(tb_shape_id id) {
  GET_SHAPE(id, ((tb_body_id){0, 0, 0}));
  return tb_make_body_id(w, s->body);
}

float tb_shape_get_density(tb_shape_id id) {
  GET_SHAPE(id, 0.0f);
  return s->density;
}

tb_result tb_shape_set_density(tb_shape_id id, float density) {
  GET_SHAPE_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "density", density)) return tb_last_result();
  float old = s->density;
  s->density = density;
  tb_mass_data md = tb_shape_geom_mass(s);
  if (!tb_value_ok(md.mass) || !tb_value_ok(md.rotational_inertia)) {
    s->density = old;
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: density %g makes the mass overflow", __func__, (double)density);
  }
  tb_body_update_mass(w, tb_body_at(w, s->body));
  tb_wake_body(w, s->body);
  return TB_OK;
}

float tb_shape_get_friction(tb_shape_id id) {
  GET_SHAPE(id, 0.0f);
  return s->friction;
}

tb_result tb_shape_set_friction(tb_shape_id id, float friction) {
  GET_SHAPE_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "friction", friction)) return tb_last_result();
  s->friction = friction;
  return TB_OK;
}

float tb_shape_get_restitution(tb_shape_id id) {
  GET_SHAPE(id, 0.0f);
  return s->restitution;
}

tb_result tb_shape_set_restitution(tb_shape_id id, float restitution) {
  GET_SHAPE_FOR_CHANGE(id);
  if (tb_check_restitution(w, __func__, "restitution", restitution)) return tb_last_result();
  s->restitution = restitution;
  return TB_OK;
}

float tb_shape_get_rolling_resistance(tb_shape_id id) {
  GET_SHAPE(id, 0.0f);
  return s->rolling_resistance;
}

tb_result tb_shape_set_rolling_resistance(tb_shape_id id, float rolling_resistance) {
  GET_SHAPE_FOR_CHANGE(id);
  if (tb_check_non_negative(w, __func__, "rolling_resistance", rolling_resistance)) return tb_last_result();
  s->rolling_resistance = rolling_resistance;
  return TB_OK;
}

float tb_shape_get_tangent_speed(tb_shape_id id) {
  GET_SHAPE(id, 0.0f);
  return s->tangent_speed;
}

tb_result tb_shape_set_tangent_speed(tb_shape_id id, float speed) {
  GET_SHAPE_FOR_CHANGE(id);
  if (!tb_value_ok(speed))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: speed = %g is not finite", __func__, (double)speed);
  s->tangent_speed = speed;
  /* contacts hold the sum of their shapes' speeds: refresh this shape's */
  int index = id.index1 - 1;
  for (int key = tb_body_at(w, s->body)->contact_list; key >= 0;) {
    tb_contact* c = (tb_contact*)tb_pool_at(&w->contacts, key >> 1);
    if (c->shape_a == index || c->shape_b == index)
      c->tangent_speed = tb_shape_at(w, c->shape_a)->tangent_speed + tb_shape_at(w, c->shape_b)->tangent_speed;
    key = c->edges[key & 1].next;
  }
  tb_wake_body(w, s->body);
  return TB_OK;
}

tb_filter tb_shape_get_filter(tb_shape_id id) {
  GET_SHAPE(id, ((tb_filter){0, 0, 0}));
  return s->filter;
}

/* A new filter drops the shape's contacts; the broad phase finds the pairs the
 * filter now allows at the next step. */
tb_result tb_shape_set_filter(tb_shape_id id, tb_filter filter) {
  GET_SHAPE_FOR_CHANGE(id);
  int index = id.index1 - 1;
  if (s->proxy >= 0 && !tb_broad_phase_reserve(w, (tb_body_type)s->tree, 1))
    return tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the broad phase", __func__);
  /* contacts end; the proxy is queued so that pair finding runs on the new filter */
  tb_contacts_destroy_of_body(w, s->body, index);
  s->filter = filter;
  (void)tb_broad_phase_refilter_proxy(w, index);
  return TB_OK;
}

bool tb_shape_is_sensor(tb_shape_id id) {
  GET_SHAPE(id, false);
  return s->sensor;
}

void* tb_shape_get_user_data(tb_shape_id id) {
  GET_SHAPE(id, NULL);
  return s->user_data;
}

tb_result tb_shape_set_user_data(tb_shape_id id, void* user_data) {
  GET_SHAPE_FOR_CHANGE(id);
  s->user_data = user_data;
  return TB_OK;
}

tb_mass_data tb_shape_get_mass_data(tb_shape_id id) {
  GET_SHAPE(id, ((tb_mass_data){0.0f, {0.0f, 0.0f}, 0.0f}));
  return tb_shape_geom_mass(s);
}

tb_aabb tb_shape_get_aabb(tb_shape_id id) {
  GET_SHAPE(id, ((tb_aabb){{0.0f, 0.0f}, {0.0f, 0.0f}}));
  return tb_shape_geom_aabb(s, tb_body_at(w, s->body)->transform);
}

static tb_result get_geometry(tb_shape_id id, tb_shape_type type, void* out, const char* fn) {
  tb_world* w = NULL;
  tb_shape* s = tb_shape_get(id, &w, fn);
  if (s == NULL) return tb_last_result();
  if (out == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: out is NULL", fn);
  if (s->type != type) return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: the shape is of another type", fn);
  switch (type) {
    case TB_SHAPE_CIRCLE: *(tb_circle*)out = s->geom.circle; break;
    case TB_SHAPE_CAPSULE: *(tb_capsule*)out = s->geom.capsule; break;
    case TB_SHAPE_SEGMENT: *(tb_segment*)out = s->geom.segment; break;
    case TB_SHAPE_POLYGON: *(tb_polygon*)out = s->geom.polygon; break;
    case TB_SHAPE_CHAIN_SEGMENT: *(tb_chain_segment*)out = s->geom.chain_segment; break;
  }
  return TB_OK;
}

tb_result tb_shape_get_circle(tb_shape_id id, tb_circle* out) {
  return get_geometry(id, TB_SHAPE_CIRCLE, out, __func__);
}
tb_result tb_shape_get_capsule(tb_shape_id id, tb_capsule* out) {
  return get_geometry(id, TB_SHAPE_CAPSULE, out, __func__);
}
tb_result tb_shape_get_segment(tb_shape_id id, tb_segment* out) {
  return get_geometry(id, TB_SHAPE_SEGMENT, out, __func__);
}
tb_result tb_shape_get_polygon(tb_shape_id id, tb_polygon* out) {
  return get_geometry(id, TB_SHAPE_POLYGON, out, __func__);
}
tb_result tb_shape_get_chain_segment(tb_shape_id id, tb_chain_segment* out) {
  return get_geometry(id, TB_SHAPE_CHAIN_SEGMENT, out, __func__);
}

/* ---- one shape's geometry in the world ------------------------------------ */

static tb_result check_point_arg(tb_world* w, const char* fn, const char* name, tb_vec2 p) {
  if (tb_point_ok(p)) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = (%g, %g) is not finite or beyond TB_MAX_LENGTH", fn, name,
                 (double)p.x, (double)p.y);
}

bool tb_shape_test_point(tb_shape_id id, tb_vec2 point) {
  GET_SHAPE(id, false);
  if (check_point_arg(w, __func__, "point", point) != TB_OK) return false;
  return tb_shape_geom_contains(s, tb_body_at(w, s->body)->transform, point);
}

tb_ray_result tb_shape_ray_cast(tb_shape_id id, tb_vec2 origin, tb_vec2 translation) {
  const tb_ray_result miss = {{0, 0, 0}, {0.0f, 0.0f}, {0.0f, 0.0f}, 1.0f, false};
  GET_SHAPE(id, miss);
  if (tb_check_ray(w, __func__, origin, translation) != TB_OK) return miss;
  tb_ray_input ray = {origin, translation, 1.0f};
  tb_cast_output out = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, 0, false};
  tb_shape_geom_ray_cast(s, tb_body_at(w, s->body)->transform, &ray, &out);
  if (!out.hit) return miss;
  return (tb_ray_result){id, out.point, out.normal, out.fraction, true};
}

/* GJK between the shape's core (its points without the rounding radius r)
 * and the target: a target within r of the core is inside; otherwise the
 * nearest surface point lies r from the core's nearest point towards it. */
tb_vec2 tb_shape_get_closest_point(tb_shape_id id, tb_vec2 target) {
  const tb_vec2 zero = {0.0f, 0.0f};
  GET_SHAPE(id, zero);
  if (check_point_arg(w, __func__, "target", target) != TB_OK) return zero;
  tb_shape_proxy core = tb_shape_geom_proxy(s);
  float radius = core.radius;
  core.radius = 0.0f;
  tb_distance_input in = {core, {{target}, 1, 0.0f}, tb_body_at(w, s->body)->transform, {{0.0f, 0.0f}, {1.0f, 0.0f}}};
  tb_distance_output out;
  if (tb_shape_distance(&in, NULL, &out) != TB_OK || out.distance <= radius) return target;
  return tb_mul_add(out.point_a, radius, out.normal);
}

/* The checks of tb_create_*_shape on the new geometry and the body's broad
 * phase (room reserved) come first; then nothing can fail: the contacts end,
 * the proxy is made anew from the new box and queued for pair finding, and
 * the mass follows. */
static tb_result set_geometry(tb_shape_id id, tb_shape_type type, const void* geom, const char* name, const char* fn) {
  tb_world* w = NULL;
  tb_shape* s = tb_shape_get_unlocked(id, &w, fn);
  if (s == NULL) return tb_last_result();
  if (geom == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, name);
  if (s->chain >= 0)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: the shape is a segment of a chain: its geometry is the chain's",
                   fn);
  tb_shape proto = *s;
  if (set_geometry_of(w, &proto, type, geom, fn) != TB_OK) return tb_last_result();
  int index = id.index1 - 1, body = s->body;
  if (tb_shape_prepare(w, body, &proto, 1, fn) != TB_OK) return tb_last_result();
  for (int key = tb_body_at(w, body)->contact_list; key >= 0;) {
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, key >> 1);
    if ((c->shape_a == index || c->shape_b == index) && (c->flags & TB_CONTACT_TOUCHING))
      tb_wake_body(w, c->edges[(key & 1) ^ 1].body);
    key = c->edges[key & 1].next;
  }
  tb_contacts_destroy_of_body(w, body, index);
  bool had_proxy = s->proxy >= 0;
  tb_broad_phase_destroy_proxy(w, index);
  s->type = proto.type;
  s->geom = proto.geom;
  if (had_proxy) (void)tb_broad_phase_create_proxy(w, index); /* prepared: cannot fail */
  tb_body_update_mass(w, tb_body_at(w, body));
  tb_wake_body(w, body);
  return TB_OK;
}

tb_result tb_shape_set_circle(tb_shape_id id, const tb_circle* circle) {
  return set_geometry(id, TB_SHAPE_CIRCLE, circle, "circle", __func__);
}
tb_result tb_shape_set_capsule(tb_shape_id id, const tb_capsule* capsule) {
  return set_geometry(id, TB_SHAPE_CAPSULE, capsule, "capsule", __func__);
}
tb_result tb_shape_set_segment(tb_shape_id id, const tb_segment* segment) {
  return set_geometry(id, TB_SHAPE_SEGMENT, segment, "segment", __func__);
}
tb_result tb_shape_set_polygon(tb_shape_id id, const tb_polygon* polygon) {
  return set_geometry(id, TB_SHAPE_POLYGON, polygon, "polygon", __func__);
}
