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
 * and the accumulated P_n stays >= 0. The two points of a manifold are solved
 * together (a 2x2 block, see solve_wide), so that neither is favoured: solved
 * one after the other, the first takes more of the load and a symmetric stack
 * starts to rock. Friction clamps |P_t| <= mu P_n per
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
 * find no free colour are solved one by one after the coloured ones, each in
 * a block of its own. */
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
  /* both points' normal impulses solved together: K (symmetric) and its inverse */
  float k11, k12, k22, n11, n12, n22;
  bool block;
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
  tb_f4 bias_rate, mass_scale;
  tb_f4 k11, k12, k22, n11, n12, n22, block; /* block: 1 where both points are solved together */
  tb_wide_point p[2];
  int32_t a[4], b[4];
  int32_t source[4]; /* scalar constraint index, -1 for an empty lane */
  int32_t rolling;   /* any lane with rolling resistance */
} tb_wide_contact;

/* ---- scratch --------------------------------------------------------------- */

static tb_contact_constraint* constraints(tb_world* w) { return (tb_contact_constraint*)w->constraints; }

/* ---- prepare ------------------------------------------------------------------ */

/* The stiffness of a contact. A soft point is a damped spring k = m_n omega^2
 * (m_n its effective mass), so under a force F it sinks F / k. With one
 * hertz for all, k does not grow with the load while the toppling moment of a
 * column does: the interface of a column of n boxes that carries i of them
 * must resist a moment of about (i m g)(i/2 box heights) per radian of tilt
 * with its rotational stiffness 2 k a^2 (points at +-a), and summed over the
 * column the load wins near n = 12 at 30 Hz: tall stacks buckle slowly. So a
 * point carrying F (its last impulse over h: the warm start) is stiffened
 * until F compresses it at most TB_LOAD_COMPRESSION, which keeps the sum
 * below 1 past 30 boxes, up to h omega = TB_MAX_H_OMEGA, where the soft
 * constraint is nearly rigid with a position bias of about a sixth of the
 * error per substep (the Baumgarte factor Box2D 2.4 uses). Against a static or
 * kinematic body the base stiffness is twice as high. */
#define TB_LOAD_COMPRESSION 0.002f
#define TB_MAX_H_OMEGA 1.5f
static tb_softness load_softness(const tb_step_context* ctx, bool rigid_other, const tb_contact_constraint* cc) {
  tb_softness base = rigid_other ? ctx->static_softness : ctx->contact_softness;
  float omega = 2.0f * 3.14159265358979f * (rigid_other ? 2.0f : 1.0f) * ctx->contact_hertz;
  float need = omega * omega;
  for (int p = 0; p < cc->point_count; ++p) {
    const tb_constraint_point* cp = &cc->points[p];
    float force = cp->normal_impulse * ctx->inv_h;
    if (cp->normal_mass > 0.0f) need = fmaxf(need, force / (cp->normal_mass * TB_LOAD_COMPRESSION));
  }
  if (!(need > omega * omega)) return base;
  float stiff = fminf(sqrtf(need), TB_MAX_H_OMEGA * ctx->inv_h);
  if (!(stiff > omega)) return base;
  return tb_make_softness(stiff / (2.0f * 3.14159265358979f), ctx->contact_damping_ratio, ctx->h);
}

/* The 2x2 effective mass of the two normal impulses, K_ij = J_i M^-1 J_j^T,
 * and its inverse. Like Box2D 2.4, points so close together that K is near
 * singular (condition number over ~1000) are solved one after the other. */
static void block_terms(tb_contact_constraint* cc, float ma, float mb, float ja, float jb) {
  cc->block = false;
  cc->k11 = cc->k12 = cc->k22 = cc->n11 = cc->n12 = cc->n22 = 0.0f;
  tb_vec2 n = cc->normal;
  const tb_constraint_point *p1 = &cc->points[0], *p2 = &cc->points[1];
  float r1a = tb_cross(p1->ra, n), r1b = tb_cross(p1->rb, n);
  float r2a = tb_cross(p2->ra, n), r2b = tb_cross(p2->rb, n);
  if (cc->point_count >= 1) cc->k11 = ma + mb + ja * r1a * r1a + jb * r1b * r1b;
  if (cc->point_count < 2) return;
  cc->k22 = ma + mb + ja * r2a * r2a + jb * r2b * r2b;
  cc->k12 = ma + mb + ja * r1a * r2a + jb * r1b * r2b;
  float det = cc->k11 * cc->k22 - cc->k12 * cc->k12;
  if (!(cc->k11 * cc->k11 < 1000.0f * det)) return;
  float inv = 1.0f / det;
  cc->block = true;
  cc->n11 = inv * cc->k22;
  cc->n12 = -inv * cc->k12;
  cc->n22 = inv * cc->k11;
}

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
  bool rigid_other = ba->type != TB_DYNAMIC_BODY || bb->type != TB_DYNAMIC_BODY;
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
  block_terms(cc, ma, mb, ja, jb);
  cc->softness = load_softness(ctx, rigid_other, cc);
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
  wc->k11[lane] = cc->k11;
  wc->k12[lane] = cc->k12;
  wc->k22[lane] = cc->k22;
  wc->n11[lane] = cc->n11;
  wc->n12[lane] = cc->n12;
  wc->n22[lane] = cc->n22;
  wc->block[lane] = cc->block ? 1.0f : 0.0f;
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
   * constraint in the int scratch */
  if (!tb_array_reserve((void**)&w->constraints, &w->constraint_capacity, count + 1, sizeof(tb_contact_constraint)) ||
      !tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, n + count + 1, sizeof(int)))
    return false;
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < count; ++k) prepare_one(w, ctx, w->step_contacts[k], &cs[k]);

  int* color_of = w->scratch + n;
  int color_count[TB_COLORS + 1];
  color_constraints(w, ctx, color_of, color_count);

  /* Blocks of four per colour, in constraint order (deterministic), then one
   * block per contact that found no colour (one live lane each, solved one
   * after the other). */
  int block_start[TB_COLORS + 1];
  int blocks = 0;
  for (int c = 0; c < TB_COLORS; ++c) {
    block_start[c] = blocks;
    blocks += (color_count[c] + 3) / 4;
  }
  block_start[TB_COLORS] = blocks;
  blocks += color_count[TB_COLORS];
  if (!tb_array_reserve((void**)&w->wide, &w->wide_capacity, blocks + 1, sizeof(tb_wide_contact))) return false;
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  w->wide_count = blocks;
  const tb_contact_constraint empty = {.a = ctx->static_index,
                                       .b = ctx->static_index,
                                       .point_count = 0,
                                       .points = {{.base_separation = 1.0f}, {.base_separation = 1.0f}}};
  for (int b = 0; b < blocks; ++b) {
    wide[b].rolling = 0;
    for (int lane = 0; lane < 4; ++lane) fill_lane(&wide[b], lane, &empty, -1);
  }
  int filled[TB_COLORS + 1];
  memset(filled, 0, sizeof filled);
  for (int k = 0; k < count; ++k) {
    int c = color_of[k];
    int slot = filled[c]++;
    if (c == TB_COLORS)
      fill_lane(&wide[block_start[c] + slot], 0, &cs[k], k);
    else
      fill_lane(&wide[block_start[c] + slot / 4], slot % 4, &cs[k], k);
  }
  return true;
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
  /* Per point: the soft terms and r = v0 + bias, where v0 is the normal speed
   * the point would have without its accumulated impulse a (v0 = v_n - K a).
   * Since mass_scale + impulse_scale = 1, the soft update of one point,
   * a - m_n mass_scale (v_n + bias) - impulse_scale a, is the same as
   * x = -mass_scale m_n r: a new total that does not depend on a. */
  tb_f4 r[2], ms[2], a[2];
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    /* da x r = (-da r.y, da r.x), as tb_cross_sv */
    tb_f4 prax = -A.da * cp->ray, pray = A.da * cp->rax;
    tb_f4 prbx = -B.da * cp->rby, prby = B.da * cp->rbx;
    tb_f4 s = (dpx + (prbx - prax)) * c->nx + (dpy + (prby - pray)) * c->ny + cp->base_separation;
    tb_i4 speculative = s > zero;
    tb_f4 bias;
    if (use_bias) {
      bias = blend(speculative, s * inv_h, max4(c->bias_rate * s, splat(-push)));
      ms[p] = blend(speculative, one, c->mass_scale);
    } else {
      bias = blend(speculative, s * inv_h, zero);
      ms[p] = one;
    }
    tb_f4 dvx = (B.vx + -B.w * cp->rby) - (A.vx + -A.w * cp->ray);
    tb_f4 dvy = (B.vy + B.w * cp->rbx) - (A.vy + A.w * cp->rax);
    r[p] = dvx * c->nx + dvy * c->ny + bias;
    a[p] = cp->normal_impulse;
  }
  /* Both points at once (Box2D 2.4's block solver for the mixed LCP
   * x >= 0, K x + r0 >= 0, complementary; here scaled by mass_scale): the
   * first case that holds wins: both push; only 1; only 2; neither. Lanes
   * with one point (or a near-singular K) take the one-point case. */
  tb_i4 two = c->block > zero;
  tb_f4 r1 = r[0] - c->k11 * a[0] - c->k12 * a[1]; /* v0_1 + bias_1 */
  tb_f4 r2 = r[1] - c->k12 * a[0] - c->k22 * a[1];
  tb_f4 x1 = a[0], x2 = a[1]; /* no case holds (round-off): keep the impulses */
  tb_i4 none = (r1 >= zero) & (~two | (r2 >= zero));
  x1 = blend(none, zero, x1);
  x2 = blend(none, zero, x2);
  tb_f4 only2 = -ms[1] * c->p[1].normal_mass * r2;
  tb_i4 second = two & (only2 >= zero) & (r1 + c->k12 * only2 >= zero);
  x1 = blend(second, zero, x1);
  x2 = blend(second, only2, x2);
  tb_f4 only1 = -ms[0] * c->p[0].normal_mass * r1;
  tb_i4 first = (only1 >= zero) & (~two | (r2 + c->k12 * only1 >= zero));
  x1 = blend(first, only1, x1);
  x2 = blend(first, zero, x2);
  tb_f4 both1 = -ms[0] * (c->n11 * r1 + c->n12 * r2), both2 = -ms[1] * (c->n12 * r1 + c->n22 * r2);
  tb_i4 both = two & (both1 >= zero) & (both2 >= zero);
  x1 = blend(both, both1, x1);
  x2 = blend(both, both2, x2);
  tb_f4 total_normal = x1 + x2;
  tb_f4 x[2] = {x1, x2};
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    tb_f4 impulse = x[p] - a[p];
    cp->normal_impulse = x[p];
    cp->max_normal_impulse = max4(cp->max_normal_impulse, x[p]);
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
}

void tb_contact_solver_solve(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  for (int b = 0; b < w->wide_count; ++b)
    solve_wide(&wide[b], ctx->states, ctx->inv_h, ctx->contact_push_max_velocity, use_bias);
}

/* Newton's restitution on the points that approached faster than the
 * threshold and pushed during the step: v_n' = -e v_n(before). */
#define TB_RESTITUTION_PASSES 8
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
  /* Restitution is iterated like the velocity solve: a ball that strikes two
   * others at once (or a row of touching balls) only bounces off all of them
   * with e when each contact sees the others' impulses; one pass would leave
   * the first contact's bounce undone by the second and lose energy. */
  for (int pass = 0; pass < TB_RESTITUTION_PASSES; ++pass)
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
