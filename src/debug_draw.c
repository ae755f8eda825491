/* Debug draw: walks the world's bodies, shapes, joints and contacts and hands
 * them to the game's drawing callbacks (see tb_debug_draw in tumble.h). Reads
 * the world only. */
#include <math.h>
#include <stdio.h>

#include "math_internal.h"
#include "world.h"
#include "units.h"

static tb_color rgb(float r, float g, float b) { return (tb_color){r, g, b, 1.0f}; }

tb_debug_draw tb_default_debug_draw(void) {
  tb_debug_draw d = {0};
  d.draw_shapes = true;
  d.draw_joints = true;
  d.normal_length = tb_meters(0.3f);
  d.point_size = 5.0f;
  /* Hues far apart so that each state reads at a glance, also when shrunk. */
  d.colors = (tb_debug_colors){
      .static_body = rgb(0.50f, 0.80f, 0.50f),
      .kinematic_body = rgb(0.45f, 0.55f, 0.95f),
      .awake_body = rgb(0.95f, 0.60f, 0.30f),
      .asleep_body = rgb(0.60f, 0.60f, 0.65f),
      .bullet_body = rgb(0.95f, 0.30f, 0.55f),
      .disabled_body = rgb(0.35f, 0.35f, 0.35f),
      .sensor = (tb_color){0.95f, 0.85f, 0.25f, 0.35f},
      .sensor_active = (tb_color){1.00f, 0.95f, 0.30f, 0.80f},
      .joint = rgb(0.40f, 0.80f, 0.85f),
      .aabb = rgb(0.85f, 0.35f, 0.85f),
      .contact_point = rgb(0.95f, 0.25f, 0.20f),
      .speculative_point = rgb(0.40f, 0.45f, 0.95f),
      .contact_normal = rgb(0.90f, 0.90f, 0.30f),
      .text = rgb(0.95f, 0.95f, 0.95f),
  };
  return d;
}

/* ---- helpers ------------------------------------------------------------------ */

static bool aabb_overlaps(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

static bool visible(const tb_debug_draw* d, tb_aabb box) {
  return !d->use_drawing_bounds || aabb_overlaps(box, d->drawing_bounds);
}

static tb_aabb segment_box(tb_vec2 a, tb_vec2 b) { return (tb_aabb){tb_vmin(a, b), tb_vmax(a, b)}; }

static tb_color body_color(const tb_debug_colors* c, const tb_body* b) {
  if (!b->enabled) return c->disabled_body;
  if (b->type == TB_STATIC_BODY) return c->static_body;
  if (b->type == TB_KINEMATIC_BODY) return c->kinematic_body;
  if (b->awake_index < 0) return c->asleep_body;
  if (b->is_bullet) return c->bullet_body;
  return c->awake_body;
}

static const tb_contact* edge_contact(const tb_world* w, int key) {
  return (const tb_contact*)tb_pool_at(&w->contacts, key >> 1);
}

/* Whether some shape overlaps the sensor shape now (a touching sensor contact). */
static bool sensor_is_active(const tb_world* w, const tb_body* body, int shape) {
  for (int k = body->contact_list; k >= 0; k = edge_contact(w, k)->edges[k & 1].next) {
    const tb_contact* c = edge_contact(w, k);
    uint32_t need = TB_CONTACT_SENSOR | TB_CONTACT_TOUCHING;
    if ((c->flags & need) == need && (c->shape_a == shape || c->shape_b == shape)) return true;
  }
  return false;
}

static void draw_shape(const tb_world* w, const tb_debug_draw* d, const tb_body* body, int index, tb_color color) {
  const tb_shape* s = tb_shape_at(w, index);
  if (!visible(d, s->aabb)) return;
  if (s->sensor) color = sensor_is_active(w, body, index) ? d->colors.sensor_active : d->colors.sensor;
  tb_transform xf = body->transform;
  switch (s->type) {
    case TB_SHAPE_CIRCLE: {
      const tb_circle* c = &s->geom.circle;
      tb_transform at = {tb_transform_point(xf, c->center), xf.q};
      if (d->draw_solid_circle != NULL) d->draw_solid_circle(at, c->radius, color, d->context);
      break;
    }
    case TB_SHAPE_CAPSULE: {
      const tb_capsule* c = &s->geom.capsule;
      if (d->draw_solid_capsule != NULL)
        d->draw_solid_capsule(tb_transform_point(xf, c->center1), tb_transform_point(xf, c->center2), c->radius, color,
                              d->context);
      break;
    }
    case TB_SHAPE_SEGMENT: {
      const tb_segment* g = &s->geom.segment;
      if (d->draw_segment != NULL)
        d->draw_segment(tb_transform_point(xf, g->point1), tb_transform_point(xf, g->point2), color, d->context);
      break;
    }
    case TB_SHAPE_CHAIN_SEGMENT: {
      const tb_segment* g = &s->geom.chain_segment.segment;
      if (d->draw_segment != NULL)
        d->draw_segment(tb_transform_point(xf, g->point1), tb_transform_point(xf, g->point2), color, d->context);
      break;
    }
    case TB_SHAPE_POLYGON: {
      const tb_polygon* p = &s->geom.polygon;
      if (d->draw_solid_polygon != NULL) d->draw_solid_polygon(xf, p->vertices, p->count, p->radius, color, d->context);
      break;
    }
  }
}

/* Static bodies first, so that moving bodies are drawn over the ground. */
static void draw_shapes(const tb_world* w, const tb_debug_draw* d) {
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < w->bodies.high; ++i) {
      if (!tb_pool_alive(&w->bodies, i)) continue;
      const tb_body* b = tb_body_at(w, i);
      if ((b->type == TB_STATIC_BODY) != (pass == 0)) continue;
      tb_color color = body_color(&d->colors, b);
      for (int s = b->shape_list; s >= 0; s = tb_shape_at(w, s)->next) draw_shape(w, d, b, s, color);
    }
  }
}

static void segment(const tb_debug_draw* d, tb_vec2 a, tb_vec2 b, tb_color color) {
  if (d->draw_segment != NULL) d->draw_segment(a, b, color, d->context);
}

static void point(const tb_debug_draw* d, tb_vec2 p, tb_color color) {
  if (d->draw_point != NULL) d->draw_point(p, d->point_size, color, d->context);
}

static void draw_joint(const tb_world* w, const tb_debug_draw* d, const tb_joint* j) {
  const tb_body* ba = tb_body_at(w, j->edges[0].body);
  const tb_body* bb = tb_body_at(w, j->edges[1].body);
  tb_transform xa = ba->transform, xb = bb->transform;
  tb_vec2 pa = tb_transform_point(xa, j->local_anchor_a), pb = tb_transform_point(xb, j->local_anchor_b);
  tb_aabb box = {tb_vmin(tb_vmin(xa.p, pa), tb_vmin(xb.p, pb)), tb_vmax(tb_vmax(xa.p, pa), tb_vmax(xb.p, pb))};
  if (j->type == TB_JOINT_MOUSE) box = segment_box(j->target, pb);
  if (!visible(d, box)) return;
  tb_color c = d->colors.joint;
  switch (j->type) {
    case TB_JOINT_DISTANCE:
      segment(d, pa, pb, c);
      point(d, pa, c);
      point(d, pb, c);
      break;
    case TB_JOINT_PRISMATIC:
    case TB_JOINT_WHEEL: {
      /* the axis through A's anchor, one normal_length either way, and the offset to B */
      tb_vec2 axis = tb_rotate(xa.q, j->local_axis_a);
      float half = d->normal_length;
      segment(d, tb_mul_add(pa, -half, axis), tb_mul_add(pa, half, axis), c);
      segment(d, pa, pb, c);
      point(d, pa, c);
      point(d, pb, c);
      break;
    }
    case TB_JOINT_MOUSE:
      segment(d, j->target, pb, c);
      point(d, j->target, c);
      point(d, pb, c);
      break;
    case TB_JOINT_MOTOR: segment(d, xa.p, xb.p, c); break;
    case TB_JOINT_REVOLUTE:
    case TB_JOINT_WELD:
      /* body origins to the shared anchor: shows both the pin and what it holds */
      segment(d, xa.p, pa, c);
      segment(d, pa, pb, c);
      segment(d, xb.p, pb, c);
      point(d, pa, c);
      break;
  }
}

static void draw_joints(const tb_world* w, const tb_debug_draw* d) {
  for (int i = 0; i < w->joints.high; ++i) {
    if (tb_pool_alive(&w->joints, i)) draw_joint(w, d, tb_joint_at(w, i));
  }
}

static void draw_aabbs(const tb_world* w, const tb_debug_draw* d) {
  tb_color c = d->colors.aabb;
  for (int i = 0; i < w->shapes.high; ++i) {
    if (!tb_pool_alive(&w->shapes, i)) continue;
    tb_aabb a = tb_shape_at(w, i)->aabb;
    if (!visible(d, a)) continue;
    tb_vec2 v[4] = {a.lower, {a.upper.x, a.lower.y}, a.upper, {a.lower.x, a.upper.y}};
    for (int k = 0; k < 4; ++k) segment(d, v[k], v[(k + 1) % 4], c);
  }
}

static void draw_contacts(const tb_world* w, const tb_debug_draw* d) {
  for (int i = 0; i < w->contacts.high; ++i) {
    if (!tb_pool_alive(&w->contacts, i)) continue;
    const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, i);
    if ((c->flags & TB_CONTACT_SENSOR) || !(c->flags & TB_CONTACT_TOUCHING)) continue;
    for (int k = 0; k < c->manifold.point_count; ++k) {
      const tb_manifold_point* mp = &c->manifold.points[k];
      if (!visible(d, segment_box(mp->point, mp->point))) continue;
      if (d->draw_contact_points)
        point(d, mp->point, mp->separation < 0.0f ? d->colors.contact_point : d->colors.speculative_point);
      if (d->draw_contact_normals)
        segment(d, mp->point, tb_mul_add(mp->point, d->normal_length, c->manifold.normal), d->colors.contact_normal);
    }
  }
}

static void draw_bodies(const tb_world* w, const tb_debug_draw* d) {
  for (int i = 0; i < w->bodies.high; ++i) {
    if (!tb_pool_alive(&w->bodies, i)) continue;
    const tb_body* b = tb_body_at(w, i);
    if (b->type == TB_STATIC_BODY || !visible(d, segment_box(b->center, b->center))) continue;
    if (d->draw_centers_of_mass && d->draw_transform != NULL)
      d->draw_transform((tb_transform){b->center, b->transform.q}, d->context);
    if (d->draw_masses && d->draw_string != NULL && b->type == TB_DYNAMIC_BODY) {
      char text[32];
      snprintf(text, sizeof text, "%.3g kg", (double)b->mass);
      d->draw_string(b->center, text, d->colors.text, d->context);
    }
  }
}

static bool positive_finite(float x) { return isfinite(x) && x > 0.0f; }

/* Every colour component in [0, 1]: what reaches the game's callbacks is a
 * colour a renderer can use. */
static tb_result check_colors(tb_world* w, const char* fn, const tb_debug_colors* c) {
  const struct {
    const char* name;
    tb_color color;
  } all[] = {{"static_body", c->static_body},
             {"kinematic_body", c->kinematic_body},
             {"awake_body", c->awake_body},
             {"asleep_body", c->asleep_body},
             {"bullet_body", c->bullet_body},
             {"disabled_body", c->disabled_body},
             {"sensor", c->sensor},
             {"sensor_active", c->sensor_active},
             {"joint", c->joint},
             {"aabb", c->aabb},
             {"contact_point", c->contact_point},
             {"speculative_point", c->speculative_point},
             {"contact_normal", c->contact_normal},
             {"text", c->text}};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) {
    const float parts[4] = {all[i].color.r, all[i].color.g, all[i].color.b, all[i].color.a};
    for (int k = 0; k < 4; ++k)
      if (!(parts[k] >= 0.0f && parts[k] <= 1.0f)) /* false for NaN */
        return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: draw->colors.%s.%c = %g must be in [0, 1]", fn, all[i].name,
                       "rgba"[k], (double)parts[k]);
  }
  return TB_OK;
}

tb_result tb_world_draw(tb_world_id world, const tb_debug_draw* draw) {
  const char* fn = "tb_world_draw";
  tb_world* w = tb_world_get_unlocked(world, fn);
  if (w == NULL) return tb_last_result();
  if (draw == NULL) return tb_fail(w, TB_ERR_NULL_ARGUMENT, "%s: draw is NULL", fn);
  if (!positive_finite(draw->normal_length) || draw->normal_length > TB_MAX_LENGTH)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: draw->normal_length = %g must be > 0 and finite", fn,
                   (double)draw->normal_length);
  if (!positive_finite(draw->point_size) || draw->point_size > TB_MAX_VALUE)
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: draw->point_size = %g must be > 0 and finite", fn,
                   (double)draw->point_size);
  if (draw->use_drawing_bounds) {
    tb_aabb b = draw->drawing_bounds;
    if (!tb_point_ok(b.lower) || !tb_point_ok(b.upper) || b.lower.x > b.upper.x || b.lower.y > b.upper.y)
      return tb_fail(w, TB_ERR_INVALID_ARGUMENT,
                     "%s: draw->drawing_bounds must be finite, within TB_MAX_LENGTH, with lower <= upper (got (%g, %g) "
                     "to (%g, %g))",
                     fn, (double)b.lower.x, (double)b.lower.y, (double)b.upper.x, (double)b.upper.y);
  }
  if (check_colors(w, fn, &draw->colors) != TB_OK) return tb_last_result();
  /* The callbacks run with the world locked, as a query's do: the pools are
   * being walked, so a change from inside one is refused (TB_ERR_LOCKED)
   * instead of freeing what the walk reads next. Reading stays allowed. */
  w->locked = true;
  if (draw->draw_shapes) draw_shapes(w, draw);
  if (draw->draw_joints) draw_joints(w, draw);
  if (draw->draw_aabbs) draw_aabbs(w, draw);
  if (draw->draw_contact_points || draw->draw_contact_normals) draw_contacts(w, draw);
  if (draw->draw_centers_of_mass || draw->draw_masses) draw_bodies(w, draw);
  w->locked = false;
  return TB_OK;
}
