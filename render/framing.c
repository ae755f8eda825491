/* The public cameras of tumble_render.h (fit, fit to the world, follow) and
 * the box a world's bodies fill. The camera geometry itself is camera.c. */
#include <math.h>
#include <stddef.h>

#include "camera.h"
#include "error.h"
#include "renderer.h"

/* ---- the public cameras (tumble_render.h) ---------------------------------------- */

static bool finite_vec(tb_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

static tb_render_result check_box(const char* fn, const char* name, tb_aabb b) {
  if (!finite_vec(b.lower) || !finite_vec(b.upper))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: %s is not finite", fn, name);
  if (b.lower.x > b.upper.x || b.lower.y > b.upper.y)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: %s has lower > upper", fn, name);
  if (fabsf(b.lower.x) > TB_MAX_LENGTH || fabsf(b.lower.y) > TB_MAX_LENGTH || fabsf(b.upper.x) > TB_MAX_LENGTH ||
      fabsf(b.upper.y) > TB_MAX_LENGTH)
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: %s reaches beyond TB_MAX_LENGTH (%g m)", fn, name,
                    (double)TB_MAX_LENGTH);
  return TB_RENDER_OK;
}

static tb_render_camera public_camera(tbr_camera c) { return (tb_render_camera){c.center, c.half_height}; }

tb_render_result tb_render_camera_fit(const tb_renderer* renderer, tb_aabb bounds, float margin,
                                      tb_render_camera* out) {
  static const char fn[] = "tb_render_camera_fit";
  if (renderer == NULL || out == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, renderer == NULL ? "renderer" : "out");
  tb_render_result r = check_box(fn, "bounds", bounds);
  if (r != TB_RENDER_OK) return r;
  if (!(margin >= 0.0f && margin <= 10.0f))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: margin %g is outside [0, 10]", fn, (double)margin);
  int width, height, top;
  tbr_renderer_layout(renderer, &width, &height, &top);
  *out = public_camera(tbr_camera_fit_below(bounds, margin, width, height, top));
  return TB_RENDER_OK;
}

tb_render_result tb_render_camera_fit_world(const tb_renderer* renderer, tb_world_id world, float margin,
                                            tb_render_camera* out) {
  if (renderer == NULL || out == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "tb_render_camera_fit_world: %s is NULL",
                    renderer == NULL ? "renderer" : "out");
  tb_aabb box;
  tb_render_result r = tb_render_world_bounds(world, &box);
  return r != TB_RENDER_OK ? r : tb_render_camera_fit(renderer, box, margin, out);
}

tb_render_result tb_render_camera_follow(const tb_renderer* renderer, tb_body_id body, float view_width,
                                         const tb_aabb* bounds, tb_render_camera* out) {
  static const char fn[] = "tb_render_camera_follow";
  if (renderer == NULL || out == NULL)
    return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "%s: %s is NULL", fn, renderer == NULL ? "renderer" : "out");
  if (!tb_body_is_valid(body)) return tbr_fail(TB_RENDER_ERR_STALE_HANDLE, "%s: the body is null or was destroyed", fn);
  if (!(view_width > 0.0f && view_width <= TB_MAX_LENGTH))
    return tbr_fail(TB_RENDER_ERR_INVALID_ARGUMENT, "%s: view_width %g is outside (0, TB_MAX_LENGTH]", fn,
                    (double)view_width);
  const float far = TB_MAX_LENGTH;
  tb_aabb clamp = {{-far, -far}, {far, far}};
  if (bounds != NULL) {
    tb_render_result r = check_box(fn, "bounds", *bounds);
    if (r != TB_RENDER_OK) return r;
    clamp = *bounds;
  }
  int width, height, top;
  tbr_renderer_layout(renderer, &width, &height, &top);
  *out = public_camera(tbr_camera_follow(tb_body_get_position(body), view_width, clamp, width, height));
  return TB_RENDER_OK;
}

/* ---- the world's bounds ---------------------------------------------------------- */

typedef struct bounds_pass {
  bool moving; /* pass 1: the moving bodies' shapes; pass 2: static shapes, clipped to near */
  tb_aabb near;
  tb_aabb box;
  int count;
} bounds_pass;

static void grow(tb_aabb* box, tb_aabb a) {
  box->lower.x = fminf(box->lower.x, a.lower.x);
  box->lower.y = fminf(box->lower.y, a.lower.y);
  box->upper.x = fmaxf(box->upper.x, a.upper.x);
  box->upper.y = fmaxf(box->upper.y, a.upper.y);
}

/* A joint's anchors on both bodies: a pendulum's pivot is part of the scene. */
static void add_joint_anchors(bounds_pass* pass, tb_body_id body) {
  tb_joint_id joints[16];
  int count = tb_body_get_joints(body, joints, 16);
  for (int i = 0; i < count && i < 16; ++i) {
    tb_vec2 a = tb_body_get_world_point(tb_joint_get_body_a(joints[i]), tb_joint_get_local_anchor_a(joints[i]));
    tb_vec2 b = tb_body_get_world_point(tb_joint_get_body_b(joints[i]), tb_joint_get_local_anchor_b(joints[i]));
    grow(&pass->box, (tb_aabb){a, a});
    grow(&pass->box, (tb_aabb){b, b});
  }
}

/* Pass 1 takes the shapes of moving bodies and every sensor (what lights up
 * belongs in the picture), with the moving bodies' joint anchors; pass 2 the
 * other static shapes, clipped to near. */
static bool add_shape(tb_shape_id shape, void* context) {
  bounds_pass* pass = context;
  tb_body_id body = tb_shape_get_body(shape);
  bool is_static = tb_body_get_type(body) == TB_STATIC_BODY;
  bool first_pass = !is_static || tb_shape_is_sensor(shape);
  if (first_pass != pass->moving) return true;
  tb_aabb a = tb_shape_get_aabb(shape);
  if (!pass->moving) {
    a.lower.x = fmaxf(a.lower.x, pass->near.lower.x);
    a.lower.y = fmaxf(a.lower.y, pass->near.lower.y);
    a.upper.x = fminf(a.upper.x, pass->near.upper.x);
    a.upper.y = fminf(a.upper.y, pass->near.upper.y);
    if (a.lower.x > a.upper.x || a.lower.y > a.upper.y) return true;
  } else if (!is_static) {
    add_joint_anchors(pass, body);
  }
  grow(&pass->box, a);
  pass->count += 1;
  return true;
}

static void run_pass(tb_world_id world, bounds_pass* pass) {
  tb_query_filter filter = tb_default_query_filter();
  filter.category_bits = UINT64_MAX;
  filter.mask_bits = UINT64_MAX;
  pass->box = (tb_aabb){{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
  pass->count = 0;
  tb_world_overlap_aabb(world, pass->near, filter, add_shape, pass);
}

tb_render_result tb_render_world_bounds(tb_world_id world, tb_aabb* out) {
  if (out == NULL) return tbr_fail(TB_RENDER_ERR_NULL_ARGUMENT, "tb_render_world_bounds: out is NULL");
  if (!tb_world_is_valid(world))
    return tbr_fail(TB_RENDER_ERR_STALE_HANDLE, "tb_render_world_bounds: the world is null or was destroyed");
  const float far = TB_MAX_LENGTH;
  bounds_pass pass = {true, {{-far, -far}, {far, far}}, {{0.0f, 0.0f}, {0.0f, 0.0f}}, 0};
  run_pass(world, &pass);
  if (pass.count > 0) {
    tb_aabb moving = pass.box;
    float reach = 0.25f * fmaxf(moving.upper.x - moving.lower.x, moving.upper.y - moving.lower.y);
    if (reach < 0.5f) reach = 0.5f;
    pass.moving = false;
    pass.near =
        (tb_aabb){{moving.lower.x - reach, moving.lower.y - reach}, {moving.upper.x + reach, moving.upper.y + reach}};
    run_pass(world, &pass);
    if (pass.count > 0) grow(&moving, pass.box);
    *out = moving;
    return TB_RENDER_OK;
  }
  pass.moving = false; /* nothing moves: every static shape */
  run_pass(world, &pass);
  *out = pass.count > 0 ? pass.box : (tb_aabb){{-10.0f, -10.0f}, {10.0f, 10.0f}};
  return TB_RENDER_OK;
}
