/* Shared helpers of the stress suite: worlds, bodies, structures and the
 * measurements the tests report. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stress.h"

void stress_note(stress_result* out, const char* fmt, ...) {
  size_t used = strlen(out->figure);
  if (used + 1 >= sizeof out->figure) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(out->figure + used, sizeof out->figure - used, fmt, ap);
  va_end(ap);
}

uint32_t stress_perturb_seed = 0;
static uint32_t perturb_state = 0; /* xorshift32, reset by stress_world */

static float perturb_draw(void) {
  uint32_t x = perturb_state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  perturb_state = x;
  return STRESS_PERTURB_METERS * (2.0f * ((float)(x >> 8) / 16777215.0f) - 1.0f);
}

void stress_perturb(tb_vec2* p) {
  if (stress_perturb_seed == 0) return;
  p->x += perturb_draw();
  p->y += perturb_draw();
}

tb_world_id stress_world(bool enable_sleep) {
  perturb_state = stress_perturb_seed * 2654435761u + 1u;
  tb_world_def wd = tb_default_world_def();
  wd.enable_sleep = enable_sleep;
  return tb_create_world(&wd);
}

bool stress_step(tb_world_id w) {
  tb_result r = tb_world_step(w, STRESS_DT, STRESS_SUBSTEPS);
  if (r != TB_OK) {
    fprintf(stderr, "tb_world_step: %s: %s\n", tb_result_name(r), tb_world_last_error(w));
    return false;
  }
  return true;
}

tb_body_id stress_ground(tb_world_id w, float x0, float top, float half_width) {
  tb_body_def bd = tb_default_body_def();
  bd.position = (tb_vec2){x0, top - 1.0f};
  tb_body_id g = tb_create_body(w, &bd);
  tb_polygon box;
  tb_make_box(half_width, 1.0f, &box);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(g, &sd, &box);
  return g;
}

static tb_body_id dynamic_body(tb_world_id w, tb_vec2 p, float angle) {
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = p;
  bd.angle = angle;
  stress_perturb(&bd.position);
  return tb_create_body(w, &bd);
}

tb_body_id stress_box(tb_world_id w, tb_vec2 p, float angle, float hx, float hy, const tb_shape_def* sd) {
  tb_shape_def def = sd != NULL ? *sd : tb_default_shape_def();
  tb_body_id b = dynamic_body(w, p, angle);
  tb_polygon box;
  if (tb_make_box(hx, hy, &box) == TB_OK) tb_create_polygon_shape(b, &def, &box);
  return b;
}

tb_body_id stress_circle(tb_world_id w, tb_vec2 p, float r, const tb_shape_def* sd) {
  tb_shape_def def = sd != NULL ? *sd : tb_default_shape_def();
  tb_body_id b = dynamic_body(w, p, 0.0f);
  tb_circle c = {{0.0f, 0.0f}, r};
  tb_create_circle_shape(b, &def, &c);
  return b;
}

tb_body_id stress_column(tb_world_id w, float x0, float y0, int count, float h) {
  tb_body_id top = {0, 0, 0};
  for (int i = 0; i < count; ++i) top = stress_box(w, (tb_vec2){x0, y0 + (float)(2 * i + 1) * h}, 0.0f, h, h, NULL);
  return top;
}

tb_body_id stress_pyramid(tb_world_id w, float x0, float y0, int base, float h) {
  tb_body_id top = {0, 0, 0};
  for (int row = 0; row < base; ++row) {
    int n = base - row;
    for (int i = 0; i < n; ++i) {
      /* offsets are exact multiples of h, added to x0 last */
      float dx = (float)(2 * i - (n - 1)) * h;
      top = stress_box(w, (tb_vec2){x0 + dx, y0 + (float)(2 * row + 1) * h}, 0.0f, h, h, NULL);
    }
  }
  return top;
}

/* The body list is gathered with a world-wide AABB query (every body here has
 * a shape), then sorted by handle index and made unique. The scene catalogue
 * (demos/scenes) has the same helper; it is not linked here so that the
 * stress suite builds while the catalogue is being extended. */
typedef struct body_list {
  tb_body_id* items;
  int count, capacity;
} body_list;

static bool collect(tb_shape_id shape, void* context) {
  body_list* list = context;
  if (list->count == list->capacity) {
    int capacity = list->capacity > 0 ? 2 * list->capacity : 256;
    tb_body_id* items = realloc(list->items, sizeof *items * (size_t)capacity);
    if (items == NULL) return false;
    list->items = items;
    list->capacity = capacity;
  }
  list->items[list->count++] = tb_shape_get_body(shape);
  return true;
}

static int by_index(const void* a, const void* b) {
  const tb_body_id* x = a;
  const tb_body_id* y = b;
  return (x->index1 > y->index1) - (x->index1 < y->index1);
}

tb_body_id* stress_bodies(tb_world_id w, int* count) {
  body_list list = {0};
  tb_query_filter filter = tb_default_query_filter();
  filter.category_bits = UINT64_MAX;
  filter.mask_bits = UINT64_MAX;
  const float far = 0.5f * TB_MAX_LENGTH;
  tb_world_overlap_aabb(w, (tb_aabb){{-far, -far}, {far, far}}, filter, collect, &list);
  int unique = 0;
  if (list.count > 0) {
    qsort(list.items, (size_t)list.count, sizeof list.items[0], by_index);
    unique = 1;
    for (int i = 1; i < list.count; ++i)
      if (list.items[i].index1 != list.items[unique - 1].index1) list.items[unique++] = list.items[i];
  }
  *count = unique;
  return list.items;
}

double stress_energy(const tb_body_id* bodies, int count) {
  double e = 0.0;
  for (int i = 0; i < count; ++i) {
    if (tb_body_get_type(bodies[i]) != TB_DYNAMIC_BODY) continue;
    tb_vec2 c = tb_body_get_world_center(bodies[i]);
    e += (double)tb_body_get_kinetic_energy(bodies[i]) + (double)tb_body_get_mass(bodies[i]) * STRESS_G * c.y;
  }
  return e;
}

bool stress_all_finite(const tb_body_id* bodies, int count) {
  for (int i = 0; i < count; ++i) {
    tb_vec2 p = tb_body_get_position(bodies[i]), v = tb_body_get_linear_velocity(bodies[i]);
    float a = tb_body_get_angle(bodies[i]), wv = tb_body_get_angular_velocity(bodies[i]);
    if (!(isfinite(p.x) && isfinite(p.y) && isfinite(v.x) && isfinite(v.y) && isfinite(a) && isfinite(wv)))
      return false;
  }
  return true;
}

double stress_peak_speed(const tb_body_id* bodies, int count) {
  double peak = 0.0;
  for (int i = 0; i < count; ++i) {
    if (tb_body_get_type(bodies[i]) != TB_DYNAMIC_BODY) continue;
    tb_vec2 v = tb_body_get_linear_velocity(bodies[i]);
    peak = fmax(peak, hypot(v.x, v.y));
  }
  return peak;
}

double stress_deepest_overlap(const tb_body_id* bodies, int count) {
  double deepest = 0.0;
  tb_contact_data contacts[64];
  for (int i = 0; i < count; ++i) {
    int n = tb_body_get_contact_data(bodies[i], contacts, 64);
    for (int k = 0; k < n; ++k) {
      if (!contacts[k].touching) continue;
      for (int j = 0; j < contacts[k].manifold.point_count; ++j)
        deepest = fmax(deepest, -(double)contacts[k].manifold.points[j].separation);
    }
  }
  return deepest;
}

/* How far the deepest overlap at a touching point goes beyond the depth its
 * contact force F explains. A soft contact holds F at a closing of
 * F (K n) / omega^2 (see structures.c); K's translational part
 * 1/m_a + 1/m_b is all of it for circles (the normal runs through their
 * centres) and a lower bound for boxes, so the excess is exact for the
 * circles and an upper bound for the boxes. In a pile squeezed into its
 * container the force chains press row-mates together like a flat arch, with
 * many times a circle's weight: their resting overlaps are millimetres deep
 * and hold, as the springs' rest state, not an overlap left unresolved. */
double stress_deepest_excess_overlap(const tb_body_id* bodies, int count) {
  double w, ws, deepest = 0.0;
  stress_contact_omegas(&w, &ws);
  double substep = (double)STRESS_DT / STRESS_SUBSTEPS;
  tb_contact_data contacts[64];
  for (int i = 0; i < count; ++i) {
    int n = tb_body_get_contact_data(bodies[i], contacts, 64);
    for (int k = 0; k < n; ++k) {
      if (!contacts[k].touching) continue;
      tb_body_id a = tb_shape_get_body(contacts[k].shape_a), b = tb_shape_get_body(contacts[k].shape_b);
      bool rigid_other = tb_body_get_type(a) != TB_DYNAMIC_BODY || tb_body_get_type(b) != TB_DYNAMIC_BODY;
      double omega = rigid_other ? ws : w;
      double inv_mass = 0.0;
      if (tb_body_get_type(a) == TB_DYNAMIC_BODY) inv_mass += 1.0 / tb_body_get_mass(a);
      if (tb_body_get_type(b) == TB_DYNAMIC_BODY) inv_mass += 1.0 / tb_body_get_mass(b);
      for (int j = 0; j < contacts[k].manifold.point_count; ++j) {
        const tb_manifold_point* p = &contacts[k].manifold.points[j];
        double explained = p->normal_impulse / substep * inv_mass / (omega * omega);
        deepest = fmax(deepest, -(double)p->separation - explained);
      }
    }
  }
  return deepest;
}

void stress_contact_omegas(double* dynamic, double* against_static) {
  tb_world_def wd = tb_default_world_def();
  const double two_pi = 6.283185307179586;
  double most = 3.0 * STRESS_SUBSTEPS / STRESS_DT;
  *dynamic = fmin(two_pi * wd.contact_hertz, most);
  *against_static = fmin(two_pi * 2.0 * wd.contact_hertz, most);
}

double stress_ulp(float x) {
  float a = fabsf(x);
  return (double)nextafterf(a, INFINITY) - (double)a;
}

long long stress_rss_bytes(void) {
  FILE* f = fopen("/proc/self/statm", "r");
  if (f == NULL) return -1;
  long long size = 0, resident = 0;
  int n = fscanf(f, "%lld %lld", &size, &resident);
  fclose(f);
  return n == 2 ? resident * 4096 : -1;
}
