/* The contact constraints of one step: prepared once from the manifolds, then
 * warm-started and solved in every substep, restitution and impulse storage
 * after the substeps.
 *
 * Soft contact (Catto, "Solver2D"; see solver.h for the softness terms). For
 * a point with current separation s the normal impulse increment is
 *   s > 0 (speculative):  -m_n (v_n + s / h)            (close the gap, no more)
 *   s <= 0, biased pass:  -m_n mass_scale (v_n + max(bias_rate s, -push_max))
 *                         - impulse_scale P_n
 *   s <= 0, relax pass:   -m_n v_n
 * and the accumulated P_n stays >= 0. Friction clamps |P_t| <= mu P_n per
 * point and drives the tangential speed to the surfaces' own (conveyor)
 * speed; rolling resistance clamps an angular impulse to rr * sum P_n.
 * The separation is not collided again inside the step: with each body's
 * motion since the step began (displacement dp, angle da),
 *   s = s0 + n . ((dp_B + da_B x r_B) - (dp_A + da_A x r_A)),
 * the anchors' motion to first order in the angle. The exact rotation of the
 * anchor would be wrong for round shapes: a rolling ball's contact point is
 * not a material point, and rotating it (r (1 - cos da) upwards) would read as
 * separation and let the ball sink into what it rolls on.
 *
 * Speed: constraints are coloured so that no two of one colour share a
 * dynamic body, and each colour is solved four contacts at a time with GCC
 * vector extensions (SSE on x86-64; plain scalar code elsewhere). The lanes
 * do the same float operations in the same order as one contact alone, so
 * results are deterministic and independent of the optimiser. Contacts that
 * find no free colour are solved one by one after the coloured ones. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "contact.h"
#include "math_internal.h"
#include "solver.h"
#include "world.h"

#if !defined(__GNUC__)
#error "tumble's contact solver needs GCC-style vector extensions (GCC or Clang)"
#endif

typedef float tb_f4 __attribute__((vector_size(16)));
typedef int32_t tb_i4 __attribute__((vector_size(16)));

#define TB_COLORS 24

typedef struct tb_constraint_point {
  tb_vec2 ra, rb;        /* anchors from each centre of mass, world-oriented, at step start */
  float base_separation; /* s0, the separation at the step start */
  float relative_velocity;
  float normal_mass, tangent_mass;
  float normal_impulse, tangent_impulse, max_normal_impulse;
} tb_constraint_point;

typedef struct tb_contact_constraint {
  int a, b; /* solver bodies */
  int contact;
  int point_count;
  tb_vec2 normal;
  float friction, restitution, rolling_resistance, tangent_speed;
  float inv_mass_a, inv_i_a, inv_mass_b, inv_i_b;
  float rolling_mass, rolling_impulse;
  tb_softness softness;
  tb_constraint_point points[2];
} tb_contact_constraint;

/* Four contacts of one colour, field by field. */
typedef struct tb_wide_point {
  tb_f4 rax, ray, rbx, rby, base_separation, normal_mass, tangent_mass;
  tb_f4 normal_impulse, tangent_impulse, max_normal_impulse;
} tb_wide_point;

typedef struct tb_wide_contact {
  tb_f4 nx, ny, friction, tangent_speed, rolling_resistance, rolling_mass, rolling_impulse;
  tb_f4 ma, ja, mb, jb;
  tb_f4 bias_rate, mass_scale, impulse_scale;
  tb_wide_point p[2];
  int32_t a[4], b[4];
  int32_t source[4]; /* scalar constraint index, -1 for an empty lane */
  int32_t rolling;   /* any lane with rolling resistance */
} tb_wide_contact;

/* ---- scratch --------------------------------------------------------------- */

static tb_contact_constraint* constraints(tb_world* w) { return (tb_contact_constraint*)w->constraints; }

/* ---- prepare ------------------------------------------------------------------ */

static void prepare_one(tb_world* w, const tb_step_context* ctx, int index, tb_contact_constraint* cc) {
  const tb_solver_body* states = ctx->states;
  const tb_contact* c = (const tb_contact*)tb_pool_at(&w->contacts, index);
  const tb_body* ba = tb_body_at(w, c->edges[0].body);
  const tb_body* bb = tb_body_at(w, c->edges[1].body);
  int ia = tb_solver_index(w, c->edges[0].body), ib = tb_solver_index(w, c->edges[1].body);
  const tb_solver_body* sa = &states[ia];
  const tb_solver_body* sb = &states[ib];
  float ma = sa->inv_mass, mb = sb->inv_mass, ja = sa->inv_inertia, jb = sb->inv_inertia;
  cc->a = ia;
  cc->b = ib;
  cc->contact = index;
  cc->normal = c->manifold.normal;
  cc->friction = c->friction;
  cc->restitution = c->restitution;
  cc->rolling_resistance = c->rolling_resistance;
  cc->tangent_speed = c->tangent_speed;
  cc->inv_mass_a = ma;
  cc->inv_i_a = ja;
  cc->inv_mass_b = mb;
  cc->inv_i_b = jb;
  cc->rolling_mass = ja + jb > 0.0f ? 1.0f / (ja + jb) : 0.0f;
  cc->rolling_impulse = ctx->enable_warm_starting ? c->rolling_impulse : 0.0f;
  /* against a body that does not respond (static, kinematic) the contact is stiffer */
  bool rigid_other = ba->type != TB_DYNAMIC_BODY || bb->type != TB_DYNAMIC_BODY;
  cc->softness = rigid_other ? ctx->static_softness : ctx->contact_softness;
  cc->point_count = c->manifold.point_count;
  tb_vec2 n = cc->normal;
  tb_vec2 t = tb_right_perp(n);
  for (int p = 0; p < 2; ++p) {
    tb_constraint_point* cp = &cc->points[p];
    if (p >= cc->point_count) { /* an inert second point, so every contact has two */
      memset(cp, 0, sizeof *cp);
      cp->base_separation = 1.0f;
      continue;
    }
    const tb_manifold_point* mp = &c->manifold.points[p];
    cp->ra = tb_sub(mp->point, ba->center);
    cp->rb = tb_sub(mp->point, bb->center);
    cp->base_separation = mp->separation;
    float rna = tb_cross(cp->ra, n), rnb = tb_cross(cp->rb, n);
    float kn = ma + mb + ja * rna * rna + jb * rnb * rnb;
    cp->normal_mass = kn > 0.0f ? 1.0f / kn : 0.0f;
    float rta = tb_cross(cp->ra, t), rtb = tb_cross(cp->rb, t);
    float kt = ma + mb + ja * rta * rta + jb * rtb * rtb;
    cp->tangent_mass = kt > 0.0f ? 1.0f / kt : 0.0f;
    tb_vec2 va = tb_add(sa->v, tb_cross_sv(sa->w, cp->ra));
    tb_vec2 vb = tb_add(sb->v, tb_cross_sv(sb->w, cp->rb));
    cp->relative_velocity = tb_dot(n, tb_sub(vb, va));
    cp->normal_impulse = ctx->enable_warm_starting ? mp->normal_impulse : 0.0f;
    cp->tangent_impulse = ctx->enable_warm_starting ? mp->tangent_impulse : 0.0f;
    cp->max_normal_impulse = 0.0f;
  }
}

/* Greedy colouring: the first colour that neither dynamic body uses. Bodies
 * that never move under impulses (static, kinematic) are shared freely: their
 * velocity is written back unchanged. */
static void color_constraints(tb_world* w, const tb_step_context* ctx, int* color_of, int* color_count) {
  uint32_t* bits = (uint32_t*)w->scratch;
  memset(bits, 0, (size_t)(ctx->static_index + 1) * sizeof(uint32_t));
  memset(color_count, 0, (TB_COLORS + 1) * sizeof(int));
  const tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < w->step_contact_count; ++k) {
    const tb_contact_constraint* cc = &cs[k];
    bool da = cc->inv_mass_a > 0.0f, db = cc->inv_mass_b > 0.0f;
    uint32_t used = (da ? bits[cc->a] : 0u) | (db ? bits[cc->b] : 0u);
    int color = TB_COLORS; /* overflow */
    if (~used & ((1u << TB_COLORS) - 1u)) {
      color = __builtin_ctz(~used);
      if (da) bits[cc->a] |= 1u << color;
      if (db) bits[cc->b] |= 1u << color;
    }
    color_of[k] = color;
    color_count[color] += 1;
  }
}

static void fill_lane(tb_wide_contact* wc, int lane, const tb_contact_constraint* cc, int source) {
  wc->nx[lane] = cc->normal.x;
  wc->ny[lane] = cc->normal.y;
  wc->friction[lane] = cc->friction;
  wc->tangent_speed[lane] = cc->tangent_speed;
  wc->rolling_resistance[lane] = cc->rolling_resistance;
  wc->rolling_mass[lane] = cc->rolling_mass;
  wc->rolling_impulse[lane] = cc->rolling_impulse;
  wc->ma[lane] = cc->inv_mass_a;
  wc->ja[lane] = cc->inv_i_a;
  wc->mb[lane] = cc->inv_mass_b;
  wc->jb[lane] = cc->inv_i_b;
  wc->bias_rate[lane] = cc->softness.bias_rate;
  wc->mass_scale[lane] = cc->softness.mass_scale;
  wc->impulse_scale[lane] = cc->softness.impulse_scale;
  for (int p = 0; p < 2; ++p) {
    const tb_constraint_point* cp = &cc->points[p];
    tb_wide_point* wp = &wc->p[p];
    wp->rax[lane] = cp->ra.x;
    wp->ray[lane] = cp->ra.y;
    wp->rbx[lane] = cp->rb.x;
    wp->rby[lane] = cp->rb.y;
    wp->base_separation[lane] = cp->base_separation;
    wp->normal_mass[lane] = cp->normal_mass;
    wp->tangent_mass[lane] = cp->tangent_mass;
    wp->normal_impulse[lane] = cp->normal_impulse;
    wp->tangent_impulse[lane] = cp->tangent_impulse;
    wp->max_normal_impulse[lane] = cp->max_normal_impulse;
  }
  wc->a[lane] = cc->a;
  wc->b[lane] = cc->b;
  wc->source[lane] = source;
  if (cc->rolling_resistance > 0.0f) wc->rolling = 1;
}

bool tb_contact_solver_prepare(tb_world* w, tb_step_context* ctx) {
  int count = w->step_contact_count;
  int n = ctx->static_index + 1;
  /* scalar constraints; colour bits per solver body and the colour of each
   * constraint in the int scratch; wide blocks (at most count / 4 + one
   * partial block per colour) */
  int wide_need = count / 4 + TB_COLORS + 1;
  if (!tb_array_reserve((void**)&w->constraints, &w->constraint_capacity, count + 1, sizeof(tb_contact_constraint)) ||
      !tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, n + count + 1, sizeof(int)) ||
      !tb_array_reserve((void**)&w->wide, &w->wide_capacity, wide_need, sizeof(tb_wide_contact)))
    return false;
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < count; ++k) prepare_one(w, ctx, w->step_contacts[k], &cs[k]);

  int* color_of = w->scratch + n;
  int color_count[TB_COLORS + 1];
  color_constraints(w, ctx, color_of, color_count);

  /* blocks of four per colour, in constraint order (deterministic) */
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  int block_start[TB_COLORS + 1];
  int blocks = 0;
  for (int c = 0; c < TB_COLORS; ++c) {
    block_start[c] = blocks;
    blocks += (color_count[c] + 3) / 4;
  }
  block_start[TB_COLORS] = blocks;
  w->wide_count = blocks;
  const tb_contact_constraint empty = {.a = ctx->static_index,
                                       .b = ctx->static_index,
                                       .point_count = 0,
                                       .points = {{.base_separation = 1.0f}, {.base_separation = 1.0f}}};
  for (int b = 0; b < blocks; ++b) {
    wide[b].rolling = 0;
    for (int lane = 0; lane < 4; ++lane) fill_lane(&wide[b], lane, &empty, -1);
  }
  int filled[TB_COLORS];
  memset(filled, 0, sizeof filled);
  w->overflow_count = 0;
  int* overflow = color_of; /* reused in place: overflow indices never overtake k */
  for (int k = 0; k < count; ++k) {
    int c = color_of[k];
    if (c == TB_COLORS) {
      overflow[w->overflow_count++] = k;
      continue;
    }
    int slot = filled[c]++;
    fill_lane(&wide[block_start[c] + slot / 4], slot % 4, &cs[k], k);
  }
  w->overflow = overflow;
  return true;
}

/* ---- scalar solve (overflow contacts) -------------------------------------- */

static void warm_start_one(tb_contact_constraint* cc, tb_solver_body* states) {
  tb_solver_body* sa = &states[cc->a];
  tb_solver_body* sb = &states[cc->b];
  tb_vec2 va = sa->v, vb = sb->v;
  float wa = sa->w, wb = sb->w;
  tb_vec2 n = cc->normal, t = tb_right_perp(n);
  for (int p = 0; p < 2; ++p) {
    const tb_constraint_point* cp = &cc->points[p];
    tb_vec2 P = tb_add(tb_scale(cp->normal_impulse, n), tb_scale(cp->tangent_impulse, t));
    wa -= cc->inv_i_a * tb_cross(cp->ra, P);
    va = tb_mul_add(va, -cc->inv_mass_a, P);
    wb += cc->inv_i_b * tb_cross(cp->rb, P);
    vb = tb_mul_add(vb, cc->inv_mass_b, P);
  }
  wa -= cc->inv_i_a * cc->rolling_impulse;
  wb += cc->inv_i_b * cc->rolling_impulse;
  sa->v = va;
  sa->w = wa;
  sb->v = vb;
  sb->w = wb;
}

static void solve_one(tb_contact_constraint* cc, tb_solver_body* states, float inv_h, float push, bool use_bias) {
  tb_solver_body* sa = &states[cc->a];
  tb_solver_body* sb = &states[cc->b];
  tb_vec2 va = sa->v, vb = sb->v;
  float wa = sa->w, wb = sb->w;
  const float ma = cc->inv_mass_a, mb = cc->inv_mass_b, ja = cc->inv_i_a, jb = cc->inv_i_b;
  tb_vec2 n = cc->normal, t = tb_right_perp(n);
  tb_vec2 dp = tb_sub(sb->dp, sa->dp);
  float total_normal = 0.0f;
  for (int p = 0; p < 2; ++p) {
    tb_constraint_point* cp = &cc->points[p];
    tb_vec2 d = tb_add(dp, tb_sub(tb_cross_sv(sb->da, cp->rb), tb_cross_sv(sa->da, cp->ra)));
    float s = tb_dot(d, n) + cp->base_separation;
    float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
    if (s > 0.0f) {
      bias = s * inv_h;
    } else if (use_bias) {
      bias = fmaxf(cc->softness.bias_rate * s, -push);
      mass_scale = cc->softness.mass_scale;
      impulse_scale = cc->softness.impulse_scale;
    }
    tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
    float vn = tb_dot(dv, n);
    float impulse = -cp->normal_mass * mass_scale * (vn + bias) - impulse_scale * cp->normal_impulse;
    float total = fmaxf(cp->normal_impulse + impulse, 0.0f);
    impulse = total - cp->normal_impulse;
    cp->normal_impulse = total;
    cp->max_normal_impulse = fmaxf(cp->max_normal_impulse, total);
    total_normal += total;
    tb_vec2 P = tb_scale(impulse, n);
    va = tb_mul_add(va, -ma, P);
    wa -= ja * tb_cross(cp->ra, P);
    vb = tb_mul_add(vb, mb, P);
    wb += jb * tb_cross(cp->rb, P);
  }
  for (int p = 0; p < 2; ++p) {
    tb_constraint_point* cp = &cc->points[p];
    tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
    float vt = tb_dot(dv, t);
    float impulse = -cp->tangent_mass * (vt - cc->tangent_speed);
    float limit = cc->friction * cp->normal_impulse;
    float total = fminf(fmaxf(cp->tangent_impulse + impulse, -limit), limit);
    impulse = total - cp->tangent_impulse;
    cp->tangent_impulse = total;
    tb_vec2 P = tb_scale(impulse, t);
    va = tb_mul_add(va, -ma, P);
    wa -= ja * tb_cross(cp->ra, P);
    vb = tb_mul_add(vb, mb, P);
    wb += jb * tb_cross(cp->rb, P);
  }
  if (cc->rolling_resistance > 0.0f) {
    float limit = cc->rolling_resistance * total_normal;
    float impulse = -cc->rolling_mass * (wb - wa);
    float total = fminf(fmaxf(cc->rolling_impulse + impulse, -limit), limit);
    impulse = total - cc->rolling_impulse;
    cc->rolling_impulse = total;
    wa -= ja * impulse;
    wb += jb * impulse;
  }
  sa->v = va;
  sa->w = wa;
  sb->v = vb;
  sb->w = wb;
}

/* ---- wide solve ------------------------------------------------------------ */

static inline tb_f4 splat(float x) { return (tb_f4){x, x, x, x}; }
static inline tb_f4 blend(tb_i4 mask, tb_f4 a, tb_f4 b) { return (tb_f4)(((tb_i4)a & mask) | ((tb_i4)b & ~mask)); }
static inline tb_f4 max4(tb_f4 a, tb_f4 b) { return blend(a > b, a, b); }
static inline tb_f4 min4(tb_f4 a, tb_f4 b) { return blend(a < b, a, b); }

typedef struct wide_body {
  tb_f4 vx, vy, w, dpx, dpy, da;
} wide_body;

static inline wide_body gather(const tb_solver_body* states, const int32_t* idx) {
  const tb_solver_body *s0 = &states[idx[0]], *s1 = &states[idx[1]], *s2 = &states[idx[2]], *s3 = &states[idx[3]];
  return (wide_body){{s0->v.x, s1->v.x, s2->v.x, s3->v.x},
                     {s0->v.y, s1->v.y, s2->v.y, s3->v.y},
                     {s0->w, s1->w, s2->w, s3->w},
                     {s0->dp.x, s1->dp.x, s2->dp.x, s3->dp.x},
                     {s0->dp.y, s1->dp.y, s2->dp.y, s3->dp.y},
                     {s0->da, s1->da, s2->da, s3->da}};
}

static inline void scatter(tb_solver_body* states, const int32_t* idx, const wide_body* b) {
  for (int lane = 0; lane < 4; ++lane) {
    tb_solver_body* s = &states[idx[lane]];
    s->v.x = b->vx[lane];
    s->v.y = b->vy[lane];
    s->w = b->w[lane];
  }
}

static void warm_start_wide(tb_wide_contact* c, tb_solver_body* states) {
  wide_body A = gather(states, c->a), B = gather(states, c->b);
  tb_f4 tx = c->ny, ty = -c->nx;
  for (int p = 0; p < 2; ++p) {
    const tb_wide_point* cp = &c->p[p];
    tb_f4 Px = cp->normal_impulse * c->nx + cp->tangent_impulse * tx;
    tb_f4 Py = cp->normal_impulse * c->ny + cp->tangent_impulse * ty;
    A.w -= c->ja * (cp->rax * Py - cp->ray * Px);
    A.vx -= c->ma * Px;
    A.vy -= c->ma * Py;
    B.w += c->jb * (cp->rbx * Py - cp->rby * Px);
    B.vx += c->mb * Px;
    B.vy += c->mb * Py;
  }
  A.w -= c->ja * c->rolling_impulse;
  B.w += c->jb * c->rolling_impulse;
  scatter(states, c->a, &A);
  scatter(states, c->b, &B);
}

static void solve_wide(tb_wide_contact* c, tb_solver_body* states, float inv_h, float push, bool use_bias) {
  wide_body A = gather(states, c->a), B = gather(states, c->b);
  const tb_f4 zero = splat(0.0f), one = splat(1.0f);
  tb_f4 dpx = B.dpx - A.dpx, dpy = B.dpy - A.dpy;
  tb_f4 total_normal = zero;
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    /* da x r = (-da r.y, da r.x), as tb_cross_sv in the scalar path */
    tb_f4 prax = -A.da * cp->ray, pray = A.da * cp->rax;
    tb_f4 prbx = -B.da * cp->rby, prby = B.da * cp->rbx;
    tb_f4 s = (dpx + (prbx - prax)) * c->nx + (dpy + (prby - pray)) * c->ny + cp->base_separation;
    tb_i4 speculative = s > zero;
    tb_f4 bias, mass_scale, impulse_scale;
    if (use_bias) {
      bias = blend(speculative, s * inv_h, max4(c->bias_rate * s, splat(-push)));
      mass_scale = blend(speculative, one, c->mass_scale);
      impulse_scale = blend(speculative, zero, c->impulse_scale);
    } else {
      bias = blend(speculative, s * inv_h, zero);
      mass_scale = one;
      impulse_scale = zero;
    }
    tb_f4 dvx = (B.vx + -B.w * cp->rby) - (A.vx + -A.w * cp->ray);
    tb_f4 dvy = (B.vy + B.w * cp->rbx) - (A.vy + A.w * cp->rax);
    tb_f4 vn = dvx * c->nx + dvy * c->ny;
    tb_f4 impulse = -cp->normal_mass * mass_scale * (vn + bias) - impulse_scale * cp->normal_impulse;
    tb_f4 total = max4(cp->normal_impulse + impulse, zero);
    impulse = total - cp->normal_impulse;
    cp->normal_impulse = total;
    cp->max_normal_impulse = max4(cp->max_normal_impulse, total);
    total_normal += total;
    tb_f4 Px = impulse * c->nx, Py = impulse * c->ny;
    A.vx -= c->ma * Px;
    A.vy -= c->ma * Py;
    A.w -= c->ja * (cp->rax * Py - cp->ray * Px);
    B.vx += c->mb * Px;
    B.vy += c->mb * Py;
    B.w += c->jb * (cp->rbx * Py - cp->rby * Px);
  }
  tb_f4 tx = c->ny, ty = -c->nx;
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    tb_f4 dvx = (B.vx + -B.w * cp->rby) - (A.vx + -A.w * cp->ray);
    tb_f4 dvy = (B.vy + B.w * cp->rbx) - (A.vy + A.w * cp->rax);
    tb_f4 vt = dvx * tx + dvy * ty;
    tb_f4 impulse = -cp->tangent_mass * (vt - c->tangent_speed);
    tb_f4 limit = c->friction * cp->normal_impulse;
    tb_f4 total = min4(max4(cp->tangent_impulse + impulse, -limit), limit);
    impulse = total - cp->tangent_impulse;
    cp->tangent_impulse = total;
    tb_f4 Px = impulse * tx, Py = impulse * ty;
    A.vx -= c->ma * Px;
    A.vy -= c->ma * Py;
    A.w -= c->ja * (cp->rax * Py - cp->ray * Px);
    B.vx += c->mb * Px;
    B.vy += c->mb * Py;
    B.w += c->jb * (cp->rbx * Py - cp->rby * Px);
  }
  if (c->rolling) {
    tb_f4 limit = c->rolling_resistance * total_normal;
    tb_f4 impulse = -c->rolling_mass * (B.w - A.w);
    tb_f4 total = min4(max4(c->rolling_impulse + impulse, -limit), limit);
    impulse = total - c->rolling_impulse;
    c->rolling_impulse = total;
    A.w -= c->ja * impulse;
    B.w += c->jb * impulse;
  }
  scatter(states, c->a, &A);
  scatter(states, c->b, &B);
}

/* ---- entry points ----------------------------------------------------------------- */

void tb_contact_solver_warm_start(tb_world* w, tb_step_context* ctx) {
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  for (int b = 0; b < w->wide_count; ++b) warm_start_wide(&wide[b], ctx->states);
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < w->overflow_count; ++k) warm_start_one(&cs[w->overflow[k]], ctx->states);
}

/* Without warm starting every substep starts from zero impulses: clamping
 * against a total that was not applied in this substep could let a contact
 * pull. */
void tb_contact_solver_reset(tb_world* w) {
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  const tb_f4 zero = splat(0.0f);
  for (int b = 0; b < w->wide_count; ++b) {
    for (int p = 0; p < 2; ++p) wide[b].p[p].normal_impulse = wide[b].p[p].tangent_impulse = zero;
    wide[b].rolling_impulse = zero;
  }
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < w->overflow_count; ++k) {
    tb_contact_constraint* cc = &cs[w->overflow[k]];
    for (int p = 0; p < 2; ++p) cc->points[p].normal_impulse = cc->points[p].tangent_impulse = 0.0f;
    cc->rolling_impulse = 0.0f;
  }
}

void tb_contact_solver_solve(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  for (int b = 0; b < w->wide_count; ++b)
    solve_wide(&wide[b], ctx->states, ctx->inv_h, ctx->contact_push_max_velocity, use_bias);
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < w->overflow_count; ++k)
    solve_one(&cs[w->overflow[k]], ctx->states, ctx->inv_h, ctx->contact_push_max_velocity, use_bias);
}

/* Newton's restitution on the points that approached faster than the
 * threshold and pushed during the step: v_n' = -e v_n(before). */
static void apply_restitution(tb_contact_constraint* cc, tb_solver_body* states, float threshold) {
  tb_solver_body* sa = &states[cc->a];
  tb_solver_body* sb = &states[cc->b];
  tb_vec2 va = sa->v, vb = sb->v;
  float wa = sa->w, wb = sb->w;
  tb_vec2 n = cc->normal;
  for (int p = 0; p < cc->point_count; ++p) {
    tb_constraint_point* cp = &cc->points[p];
    if (cp->relative_velocity > -threshold || cp->max_normal_impulse == 0.0f) continue;
    tb_vec2 dv = tb_sub(tb_add(vb, tb_cross_sv(wb, cp->rb)), tb_add(va, tb_cross_sv(wa, cp->ra)));
    float vn = tb_dot(dv, n);
    float impulse = -cp->normal_mass * (vn + cc->restitution * cp->relative_velocity);
    float total = fmaxf(cp->normal_impulse + impulse, 0.0f);
    impulse = total - cp->normal_impulse;
    cp->normal_impulse = total;
    tb_vec2 P = tb_scale(impulse, n);
    va = tb_mul_add(va, -cc->inv_mass_a, P);
    wa -= cc->inv_i_a * tb_cross(cp->ra, P);
    vb = tb_mul_add(vb, cc->inv_mass_b, P);
    wb += cc->inv_i_b * tb_cross(cp->rb, P);
  }
  sa->v = va;
  sa->w = wa;
  sb->v = vb;
  sb->w = wb;
}

void tb_contact_solver_finish(tb_world* w, tb_step_context* ctx) {
  tb_contact_constraint* cs = constraints(w);
  /* the wide lanes hold the accumulated impulses: back to the scalar constraints */
  const tb_wide_contact* wide = (const tb_wide_contact*)w->wide;
  for (int b = 0; b < w->wide_count; ++b) {
    for (int lane = 0; lane < 4; ++lane) {
      int k = wide[b].source[lane];
      if (k < 0) continue;
      for (int p = 0; p < 2; ++p) {
        cs[k].points[p].normal_impulse = wide[b].p[p].normal_impulse[lane];
        cs[k].points[p].tangent_impulse = wide[b].p[p].tangent_impulse[lane];
        cs[k].points[p].max_normal_impulse = wide[b].p[p].max_normal_impulse[lane];
      }
      cs[k].rolling_impulse = wide[b].rolling_impulse[lane];
    }
  }
  for (int k = 0; k < w->step_contact_count; ++k)
    if (cs[k].restitution != 0.0f) apply_restitution(&cs[k], ctx->states, ctx->restitution_threshold);
  for (int k = 0; k < w->step_contact_count; ++k) {
    const tb_contact_constraint* cc = &cs[k];
    tb_contact* c = (tb_contact*)tb_pool_at(&w->contacts, cc->contact);
    for (int p = 0; p < cc->point_count; ++p) {
      c->manifold.points[p].normal_impulse = cc->points[p].normal_impulse;
      c->manifold.points[p].tangent_impulse = cc->points[p].tangent_impulse;
    }
    c->rolling_impulse = cc->rolling_impulse;
  }
}
