/* tumble behind the bench engine interface (tools/bench/engine.h). */
#include <math.h>
#include <stdlib.h>

#include "bench/engine.h"
#include "tumble.h"

typedef struct tumble_world {
  tb_world_id id;
  bench_setting setting;
  double spring_k;
  tb_body_id* bodies;
  int count, capacity;
} tumble_world;

static void spring_field(double time, const tb_body_state* state, void* context, tb_vec2* force, float* torque) {
  (void)time;
  double k = *(const double*)context;
  force->x = (float)(-k * (double)state->center.x);
  force->y = (float)(-k * (double)state->center.y);
  *torque = 0.0f;
}

static void* tumble_create(const bench_world_def* def, const bench_setting* setting) {
  tumble_world* w = calloc(1, sizeof *w);
  if (w == NULL) return NULL;
  w->setting = *setting;
  w->spring_k = def->spring_k;
  tb_world_def wd = tb_default_world_def();
  wd.gravity = (tb_vec2){(float)def->gravity_x, (float)def->gravity_y};
  wd.enable_sleep = def->enable_sleep;
  wd.restitution_threshold = (float)def->restitution_threshold;
  wd.integrator = (tb_integrator)setting->integrator;
  if (def->spring_k > 0.0) {
    wd.force_field = spring_field;
    wd.force_field_context = &w->spring_k;
  }
  w->id = tb_create_world(&wd);
  if (tb_world_id_is_null(w->id)) {
    free(w);
    return NULL;
  }
  return w;
}

static void tumble_destroy(void* world) {
  tumble_world* w = world;
  if (w == NULL) return;
  tb_destroy_world(w->id);
  free(w->bodies);
  free(w);
}

static int tumble_add_body(void* world, const bench_body_def* def) {
  tumble_world* w = world;
  if (w->count == w->capacity) {
    int capacity = w->capacity ? 2 * w->capacity : 64;
    tb_body_id* bodies = realloc(w->bodies, sizeof *bodies * (size_t)capacity);
    if (bodies == NULL) return -1;
    w->bodies = bodies;
    w->capacity = capacity;
  }
  tb_body_def bd = tb_default_body_def();
  bd.type = def->type == BENCH_STATIC      ? TB_STATIC_BODY
            : def->type == BENCH_KINEMATIC ? TB_KINEMATIC_BODY
                                           : TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){(float)def->x, (float)def->y};
  bd.angle = (float)def->angle;
  bd.linear_velocity = (tb_vec2){(float)def->vx, (float)def->vy};
  bd.angular_velocity = (float)def->w;
  bd.is_bullet = def->bullet;
  bd.is_awake = def->awake;
  tb_body_id b = tb_create_body(w->id, &bd);
  if (tb_body_id_is_null(b)) return -1;
  w->bodies[w->count] = b;
  return w->count++;
}

static tb_shape_def shape_def(const bench_material* m) {
  tb_shape_def sd = tb_default_shape_def();
  sd.density = (float)m->density;
  sd.friction = (float)m->friction;
  sd.restitution = (float)m->restitution;
  sd.filter.group_index = m->group;
  return sd;
}

static int tumble_add_box(void* world, int body, double hx, double hy, double cx, double cy, double angle,
                          const bench_material* m) {
  tumble_world* w = world;
  tb_polygon box;
  if (tb_make_offset_box((float)hx, (float)hy, (tb_vec2){(float)cx, (float)cy}, (float)angle, &box) != TB_OK) return 1;
  tb_shape_def sd = shape_def(m);
  return tb_shape_id_is_null(tb_create_polygon_shape(w->bodies[body], &sd, &box)) ? 1 : 0;
}

static int tumble_add_circle(void* world, int body, double radius, double cx, double cy, const bench_material* m) {
  tumble_world* w = world;
  tb_circle c = {{(float)cx, (float)cy}, (float)radius};
  tb_shape_def sd = shape_def(m);
  return tb_shape_id_is_null(tb_create_circle_shape(w->bodies[body], &sd, &c)) ? 1 : 0;
}

static int tumble_add_revolute(void* world, int a, int b, double x, double y) {
  tumble_world* w = world;
  tb_vec2 p = {(float)x, (float)y};
  tb_revolute_joint_def jd = tb_default_revolute_joint_def();
  jd.body_a = w->bodies[a];
  jd.body_b = w->bodies[b];
  jd.local_anchor_a = tb_body_get_local_point(w->bodies[a], p);
  jd.local_anchor_b = tb_body_get_local_point(w->bodies[b], p);
  return tb_joint_id_is_null(tb_create_revolute_joint(w->id, &jd)) ? 1 : 0;
}

static int tumble_step(void* world) {
  tumble_world* w = world;
  return tb_world_step(w->id, (float)w->setting.dt, w->setting.substeps) == TB_OK ? 0 : 1;
}

static void tumble_get_state(void* world, int body, bench_state* out) {
  tumble_world* w = world;
  tb_body_id b = w->bodies[body];
  tb_vec2 p = tb_body_get_position(b), c = tb_body_get_world_center(b), v = tb_body_get_linear_velocity(b);
  out->x = p.x;
  out->y = p.y;
  out->angle = tb_body_get_angle(b);
  out->cx = c.x;
  out->cy = c.y;
  out->vx = v.x;
  out->vy = v.y;
  out->w = tb_body_get_angular_velocity(b);
  out->awake = tb_body_is_awake(b);
}

static double tumble_mass(void* world, int body) { return tb_body_get_mass(((tumble_world*)world)->bodies[body]); }

static double tumble_inertia(void* world, int body) {
  return tb_body_get_rotational_inertia(((tumble_world*)world)->bodies[body]);
}

static void tumble_counts(void* world, int* bodies, int* contacts, int* joints) {
  tb_counts c = tb_world_get_counts(((tumble_world*)world)->id);
  *bodies = c.body_count;
  *contacts = c.touching_count;
  *joints = c.joint_count;
}

const bench_engine bench_tumble_engine = {
    "tumble",          0.0,
    tumble_create,     tumble_destroy,
    tumble_add_body,   tumble_add_box,
    tumble_add_circle, tumble_add_revolute,
    tumble_step,       tumble_get_state,
    tumble_mass,       tumble_inertia,
    tumble_counts,
};
