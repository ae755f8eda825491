/* The contact constraints of one step: prepared once from the manifolds, then
 * warm-started and solved in every substep, restitution and impulse storage
 * after the substeps.
 *
 * Soft contact (Catto, "Solver2D"; see solver.h for the softness terms). For
 * a point with current separation s the normal impulse increment is
 *   s > 0 (speculative):  -m_n (v_n + s / h)            (close the gap, no more)
 *   s <= 0, biased pass:  -m_n mass_scale (v_n + max(bias_rate max(s, -d_push), -push_max))
 *                         - impulse_scale P_n
 *   s <= 0, relax pass:   -m_n v_n
 * and the accumulated P_n stays >= 0. d_push is the depth the point's load
 * explains plus TB_DEEP_OVERLAP; an overlap deeper than that (bodies created
 * or moved into each other) is pushed out without momentum, see
 * tb_contact_solver_push_out. The two points of a manifold are solved
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
 * dynamic body, and each colour is prepared and solved four contacts at a
 * time with GCC vector extensions (SSE on x86-64; plain scalar code
 * elsewhere), straight into the blocks the solve reads. The lanes do the same
 * float operations in the same order as one contact alone, so results are
 * deterministic and independent of the optimiser. A body with more contacts
 * than one round of colours has (a pile-up) gets more rounds of them. */
#include <math.h>
#include <stddef.h>
#include <float.h>
#include <string.h>

#include "color.h"
#include "contact.h"
#include "math_internal.h"
#include "memory.h"
#include "relax_activity.h"
#include "solver.h"
#include "world.h"
#include "units.h"
#include "wide.h"

/* eight lanes at a time where the processor has AVX2 (see solve_pair) */
#if defined(__x86_64__) && defined(__GNUC__) && (defined(__clang__) || __GNUC__ >= 12)
#include <immintrin.h>
#define TB_EIGHT_LANES 1
#endif

/* Deep overlap (bodies created or moved into each other): the soft push of a
 * point only grows down to the depth its load explains plus TB_DEEP_OVERLAP;
 * deeper than that, a separate momentum-free push-out moves the bodies apart
 * (see tb_contact_solver_push_out). The soft push is real momentum, and in a
 * pile the pushes of the contacts under a body add up: with 1 cm of soft
 * push per contact, a 16-row pile of overlapping circles threw its top
 * circles at 6 to 8 m/s (stress overlap_circles); with 2.5 mm, 1.6 m/s. The
 * push-out then does most of the separating, and its Gauss-Seidel sweeps
 * must reach through the pile: with 4 per substep the pile stayed 0.4 m deep
 * after 3 s, with 16 it separates. Ordinary scenes have no deep contacts and
 * never sweep. */
#define TB_DEEP_OVERLAP (0.5f * tb_units.linear_slop)
#define TB_PUSH_OUT_RATE 0.2f /* share of the excess depth removed per substep */
#define TB_PUSH_OUT_SWEEPS 16

/* Four contacts of one colour, field by field. A lane holds one contact
 * constraint; a contact with one point has an inert second point (no mass,
 * far apart) so that every lane has two. Each contact block has a hot part,
 * what every pass reads (tb_wide_contact: the header, and per point a
 * tb_wide_point), and a cold part, what only the first pass after a position
 * update, the push-out, restitution and prepare read (tb_wide_cold, with per
 * point a tb_wide_anchor), in two arrays: a relax pass streams only the hot
 * one (large_pyramid holds 4.7 MB of blocks, beyond L2). */
typedef struct tb_wide_point {
  tb_f4 now_rax, now_ray, now_rbx, now_rby; /* the arms to the common point now (see arms_now) */
  tb_f4 separation;                         /* s at the last position update (see tb_contact_solver_solve) */
  tb_f4 push_depth;                         /* the soft push acts down to this depth, the push-out beyond */
  tb_f4 normal_mass, tangent_mass;
  tb_f4 normal_impulse, tangent_impulse;
} tb_wide_point;

typedef struct tb_wide_anchor {
  tb_f4 rax, ray, rbx, rby;  /* anchors from each centre of mass, world-oriented, at step start */
  tb_f4 live;                /* 1 for a point of the manifold, 0 for an inert one */
  tb_f4 base_separation;     /* s0, the separation at the step start */
  tb_f4 shift_a, shift_b;    /* the common point's share of the relative displacement, per arm (see arms_now) */
  tb_f4 collided_separation; /* s0 as collided; base_separation differs past the patch's end (measure_slide) */
} tb_wide_anchor;

/* A point's record for restitution: the normal impulses applied in the
 * step, summed, and summed times the arms they were applied at
 * (restitution's J_e), and the largest normal impulse of the step. */
typedef struct tb_wide_record {
  tb_f4 applied, applied_rax, applied_ray, applied_rbx, applied_rby;
  tb_f4 max_normal_impulse;
} tb_wide_record;

typedef struct tb_wide_contact {
  int32_t a[4], b[4];  /* solver bodies */
  int32_t rolling;     /* any lane with rolling resistance */
  int32_t bouncy;      /* any lane with restitution (which needs the arms the impulses acted at) */
  int32_t slid_off;    /* any lane past its patch by more than TB_SLIDE_TOLERANCE */
  int32_t ends_near;   /* bit 2 lane + end (0: min, 1: max): the end lies within reach of this step */
  int32_t ends_asked;  /* the same bits: tb_contact_face_runs_on answered this step */
  int32_t pair;        /* +1: solved with the next block, -1: with the one before, 0: alone (see solve_pair) */
  int32_t isolated;    /* every lane's moving bodies have this contact alone: its relax solve iterates (solve_wide) */
  int32_t cold_offset; /* bytes from this block to its cold part (cold_of) */
  tb_f4 nx, ny, friction, tangent_speed;
  tb_f4 ma, ja, mb, jb; /* inverse masses and inertias of the solver bodies */
  tb_f4 bias_rate, mass_scale;
  /* both points' normal impulses solved together: K (symmetric) and its inverse */
  tb_f4 k11, k12, k22, n11, n12, n22, block; /* block: 1 where both points are solved together */
  tb_wide_point p[2];
} tb_wide_contact;

/* A block's cold part: what only the first pass after a position update, the
 * push-out, restitution, rolling resistance and prepare read. The cold parts
 * lie in an array of their own after the hot blocks (one allocation, w->wide:
 * capacity hot blocks, then capacity cold ones), so that a relax pass streams
 * only the hot blocks: with the cold half between them, the hardware
 * prefetchers pulled it in too (cold parts padded by 640 bytes more made
 * many_pyramids 1.25 times slower). A block finds its cold part
 * cold_offset bytes on, and the cold part its extra part (tb_wide_extra)
 * extra_offset bytes on. */
typedef struct tb_wide_cold {
  tb_f4 shift_limit; /* how far (per axis) the arms follow the relative displacement (see arms_now) */
  /* the contact patch (tb_patch): how far B's incident core may slide along
   * the tangent before the features part, the normal distances from each
   * centre of mass to where that slide is measured, and the cores' radii */
  tb_f4 slide_min, slide_max, lever_a, lever_b, core_radius;
  int32_t contact[4];   /* each lane's contact (pool index), -1 in an unused lane */
  int32_t extra_offset; /* bytes from this cold part to the block's extra part (extra_of) */
  tb_wide_anchor q[2];
} tb_wide_cold;

/* What only blocks with rolling resistance (rolling) or restitution
 * (bouncy) read, in a third array: prepare writes it for those blocks alone.
 * Kept in the cold part, these 240 bytes a block were written by prepare and
 * streamed by every measuring pass for every block of a pile without either
 * (many_pyramids' solver stage 0.93 to 0.96x without them). */
typedef struct tb_wide_extra {
  tb_f4 rolling_resistance, rolling_mass, rolling_impulse;
  tb_wide_record q[2];
} tb_wide_extra;

static inline __attribute__((always_inline)) tb_wide_cold* cold_of(const tb_wide_contact* c) {
  return (tb_wide_cold*)(void*)((char*)(void*)c + c->cold_offset);
}

/* A block's three parts, in bytes (w->wide holds capacity of each). */
#define BLOCK_BYTES (sizeof(tb_wide_contact) + sizeof(tb_wide_cold) + sizeof(tb_wide_extra))

static inline __attribute__((always_inline)) tb_wide_extra* extra_of(const tb_wide_contact* c) {
  tb_wide_cold* cold = cold_of(c);
  return (tb_wide_extra*)(void*)((char*)cold + cold->extra_offset);
}

/* What a contact constraint keeps besides its lane: where the lane is, and
 * what restitution needs after the substeps. One per step contact, in step
 * order. */
typedef struct tb_contact_constraint {
  int lane; /* 4 * block + lane in the wide contacts (the colour while they are laid out) */
  int point_count;
  float restitution;
  float relative_velocity[2]; /* normal speed of the points at the step start */
  float spin_a, spin_b;       /* the bodies' angular velocities at the step start (see restitution_targets) */
} tb_contact_constraint;

/* A point that bounces this step, copied out of its block for the
 * restitution passes, which then stream through these in step order instead
 * of chasing each contact's block (the positions, and so its arms and K, do
 * not change during the passes). */
typedef struct tb_bounce {
  int32_t a, b; /* solver bodies */
  float nx, ny, ma, ja, mb, jb;
  float rax, ray, rbx, rby, k; /* the arms at the common point now, and K there */
  float target;                /* normal speed after the bounce */
  float impulse;               /* the point's accumulated normal impulse */
} tb_bounce;

/* Up to four contacts with a point deeper than its push depth (less half
 * TB_DEEP_OVERLAP) at the step start, which share no body but the static
 * dummy: where each lane's contact is in the wide contacts, its points'
 * push-out impulses in the current substep, and the lane's terms the
 * push-out reads, copied out of its block at the start of each push-out (its
 * 16 sweeps then stream through these instead of a dozen cache lines of the
 * block per contact and sweep). The deep contacts are grouped in the order
 * they are found, a group closed when the next contact shares a body with
 * one in it: the group's lanes are then solved at once, which gives what
 * solving them one after the other in that order gives. An unused lane has
 * the static dummy on both sides and no mass. */
typedef struct tb_deep_block {
  int32_t block[4], lane[4];
  int32_t a[4], b[4]; /* solver bodies */
  tb_i4 two;          /* both points solved together (block > 0) */
  tb_f4 impulse[2];
  tb_f4 nx, ny, ma, ja, mb, jb;
  tb_f4 k11, k12, k22, n11, n12, n22;
  tb_f4 rax[2], ray[2], rbx[2], rby[2]; /* step start anchors */
  tb_f4 target[2], normal_mass[2];      /* target: the push speed each point is after */
} tb_deep_block;
_Static_assert(sizeof(tb_deep_block) == 4 * 124,
               "the stress pile-up's memory budget counts 124 B a deep contact (tests/stress/pileup.c)");

/* ---- scratch --------------------------------------------------------------- */

static tb_contact_constraint* constraints(tb_world* w) { return (tb_contact_constraint*)w->constraints; }

/* tb_solver_index of a body already at hand */
static inline int solver_index(const tb_step_context* ctx, const tb_body* b) {
  return b->awake_index >= 0 ? b->awake_index : ctx->static_index;
}

/* The k-th contact of the step. The step contacts lie all over the contact
 * pool, so each pass over them asks for the one TB_PREFETCH_AHEAD further on. */
#define TB_PREFETCH_AHEAD 8
static inline tb_contact* step_contact(tb_world* w, int k) {
  if (k + TB_PREFETCH_AHEAD < w->step_contact_count)
    __builtin_prefetch(tb_pool_at(&w->contacts, w->step_contacts[k + TB_PREFETCH_AHEAD]));
  return (tb_contact*)tb_pool_at(&w->contacts, w->step_contacts[k]);
}

/* ---- prepare ------------------------------------------------------------------ */

/* The effective masses of a block's points at their arms now: normal and
 * tangent mass of each point, and the 2x2 effective mass of the two normal
 * impulses, K_ij = J_i M^-1 J_j^T, with its inverse. Like Box2D 2.4, points
 * so close together that K is near singular (condition number over ~1000)
 * are solved one after the other. */
static inline void set_masses(tb_wide_contact* wc) {
  const tb_f4 zero = splat(0.0f), one = splat(1.0f);
  tb_f4 ma = wc->ma, mb = wc->mb, ja = wc->ja, jb = wc->jb, nx = wc->nx, ny = wc->ny, tx = ny, ty = -nx;
  tb_f4 rn[2][2]; /* r x n of each point at A and B, for the block terms */
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* wp = &wc->p[p];
    tb_i4 live = cold_of(wc)->q[p].live > zero;
    tb_f4 rax = wp->now_rax, ray = wp->now_ray, rbx = wp->now_rbx, rby = wp->now_rby;
    tb_f4 rna = rax * ny - ray * nx, rnb = rbx * ny - rby * nx;
    tb_f4 rta = rax * ty - ray * tx, rtb = rbx * ty - rby * tx;
    wp->normal_mass = blend(live, inverse_or_zero(ma + mb + ja * rna * rna + jb * rnb * rnb), zero);
    wp->tangent_mass = blend(live, inverse_or_zero(ma + mb + ja * rta * rta + jb * rtb * rtb), zero);
    rn[p][0] = blend(live, rna, zero);
    rn[p][1] = blend(live, rnb, zero);
  }
  tb_f4 r1a = rn[0][0], r1b = rn[0][1], r2a = rn[1][0], r2b = rn[1][1];
  tb_i4 two = cold_of(wc)->q[1].live > zero;
  tb_f4 k11 = ma + mb + ja * r1a * r1a + jb * r1b * r1b;
  tb_f4 k22 = blend(two, ma + mb + ja * r2a * r2a + jb * r2b * r2b, zero);
  tb_f4 k12 = blend(two, ma + mb + ja * r1a * r2a + jb * r1b * r2b, zero);
  tb_f4 det = k11 * k22 - k12 * k12;
  tb_i4 block = two & (k11 * k11 < splat(1000.0f) * det);
  tb_f4 inv = one / det;
  wc->k11 = k11;
  wc->k12 = k12;
  wc->k22 = k22;
  wc->n11 = blend(block, inv * k22, zero);
  wc->n12 = blend(block, -inv * k12, zero);
  wc->n22 = blend(block, inv * k11, zero);
  wc->block = blend(block, one, zero);
}

/* Prepares the constraints of one block's contacts, four lanes at a time
 * (the same float operations for each lane as for one contact alone).
 * k[lane] is the step contact of a lane, -1 for an unused one, which comes
 * out inert: read as a contact of no points between two static dummies, its
 * fields are zero but the separations (1: far apart), and the few that would
 * not be are blended to zero (in_use). Clearing every field of a partly
 * used block afterwards was 1.7% of a one-contact scene's instructions. */
static void prepare_block(tb_world* w, const tb_step_context* ctx, const int32_t* k, tb_wide_contact* wc) {
  static const tb_contact no_contact;
  static const tb_body no_body;
  const tb_contact* c[4];
  const tb_body *ba[4], *bb[4];
  { /* the three parts' arrays, one after the other (see tb_wide_cold) */
    tb_wide_contact* hot = (tb_wide_contact*)w->wide;
    tb_wide_cold* cold = (tb_wide_cold*)(void*)(hot + w->wide_capacity);
    tb_wide_extra* extra = (tb_wide_extra*)(void*)(cold + w->wide_capacity);
    ptrdiff_t b = wc - hot;
    wc->cold_offset = (int32_t)((char*)&cold[b] - (char*)wc);
    cold[b].extra_offset = (int32_t)((char*)&extra[b] - (char*)&cold[b]);
  }
  for (int lane = 0; lane < 4; ++lane) {
    cold_of(wc)->contact[lane] = k[lane] >= 0 ? w->step_contacts[k[lane]] : -1;
    c[lane] = k[lane] >= 0 ? (const tb_contact*)tb_pool_at(&w->contacts, cold_of(wc)->contact[lane]) : &no_contact;
    ba[lane] = k[lane] >= 0 ? tb_body_at(w, c[lane]->edges[0].body) : &no_body;
    bb[lane] = k[lane] >= 0 ? tb_body_at(w, c[lane]->edges[1].body) : &no_body;
    wc->a[lane] = k[lane] >= 0 ? solver_index(ctx, ba[lane]) : ctx->static_index;
    wc->b[lane] = k[lane] >= 0 ? solver_index(ctx, bb[lane]) : ctx->static_index;
  }
  const tb_f4 zero = splat(0.0f), one = splat(1.0f);
  const tb_i4 in_use = {k[0] >= 0 ? -1 : 0, k[1] >= 0 ? -1 : 0, k[2] >= 0 ? -1 : 0, k[3] >= 0 ? -1 : 0};
  wide_body A = gather(ctx->states, wc->a), B = gather(ctx->states, wc->b);
  tb_f4 ma = A.inv_mass, mb = B.inv_mass, ja = A.inv_inertia, jb = B.inv_inertia;
  tb_f4 nx = LANES(c, manifold.normal.x), ny = LANES(c, manifold.normal.y);
  tb_i4 point_count = INT_LANES(c, manifold.point_count);
  tb_f4 rolling_resistance = LANES(c, rolling_resistance);
  wc->nx = nx;
  wc->ny = ny;
  wc->friction = LANES(c, friction);
  wc->tangent_speed = LANES(c, tangent_speed);
  tb_f4 restitution = LANES(c, restitution);
  wc->bouncy =
      (restitution[0] != 0.0f) | (restitution[1] != 0.0f) | (restitution[2] != 0.0f) | (restitution[3] != 0.0f);
  wc->rolling = (rolling_resistance[0] > 0.0f) | (rolling_resistance[1] > 0.0f) | (rolling_resistance[2] > 0.0f) |
                (rolling_resistance[3] > 0.0f);
  if (wc->rolling) {
    extra_of(wc)->rolling_resistance = rolling_resistance;
    extra_of(wc)->rolling_mass = inverse_or_zero(ja + jb);
    extra_of(wc)->rolling_impulse = ctx->enable_warm_starting ? LANES(c, rolling_impulse) : zero;
  }
  wc->ma = ma;
  wc->ja = ja;
  wc->mb = mb;
  wc->jb = jb;
  tb_f4 mass_share = mb * inverse_or_zero(ma + mb); /* beta by the inverse masses (see arms_now) */
  tb_i4 both_move = (ma > zero) & (mb > zero);
  tb_f4 extent_a = LANES(ba, max_extent), extent_b = LANES(bb, max_extent);
  cold_of(wc)->shift_limit = min4(extent_a, extent_b);
  cold_of(wc)->slide_min = LANES(c, patch.slide_min);
  cold_of(wc)->slide_max = LANES(c, patch.slide_max);
  cold_of(wc)->core_radius = LANES(c, patch.radius);
  wc->slid_off = 0; /* nothing has moved yet: within every patch */
  /* A patch end within reach of this step (how far the bodies can slide:
   * |dv|_1 >= |dv| bounds their relative speed without a square root) may lie
   * where the face runs on into another shape (see ask_ends). */
  tb_f4 speed = (fabs4(B.vx - A.vx) + fabs4(B.vy - A.vy)) + (fabs4(A.w) * extent_a + fabs4(B.w) * extent_b);
  tb_f4 reach = speed * splat(ctx->dt) + splat(tb_units.linear_slop);
  tb_i4 near_min = cold_of(wc)->slide_min > -reach, near_max = cold_of(wc)->slide_max < reach;
  tb_i4 end_bits = (near_min & (tb_i4){1, 4, 16, 64}) | (near_max & (tb_i4){2, 8, 32, 128});
  wc->ends_near = (end_bits[0] | end_bits[1]) | (end_bits[2] | end_bits[3]);
  wc->ends_asked = 0;
  tb_f4 cax = LANES(ba, center.x), cay = LANES(ba, center.y), cbx = LANES(bb, center.x), cby = LANES(bb, center.y);
  const tb_i4 dynamic = {TB_DYNAMIC_BODY, TB_DYNAMIC_BODY, TB_DYNAMIC_BODY, TB_DYNAMIC_BODY};
  tb_i4 rigid_other = (INT_LANES(ba, type) != dynamic) | (INT_LANES(bb, type) != dynamic);
  tb_f4 omega = blend(rigid_other, splat(TB_TWO_PI_F * ctx->static_hertz), splat(TB_TWO_PI_F * ctx->contact_hertz));
  wc->bias_rate = blend(
      in_use, blend(rigid_other, splat(ctx->static_softness.bias_rate), splat(ctx->contact_softness.bias_rate)), zero);
  wc->mass_scale =
      blend(in_use, blend(rigid_other, splat(ctx->static_softness.mass_scale), splat(ctx->contact_softness.mass_scale)),
            zero);
  tb_f4 approach[2]; /* normal speed of each point at the step start, for restitution */
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* wp = &wc->p[p];
    tb_wide_anchor* wq = &cold_of(wc)->q[p];
    tb_i4 used = point_count > (tb_i4){p, p, p, p};
    /* ra = point - centre of A, rb likewise; r x n and r x t (tb_cross) */
    tb_f4 rax = LANES(c, manifold.points[p].point.x) - cax, ray = LANES(c, manifold.points[p].point.y) - cay;
    tb_f4 rbx = LANES(c, manifold.points[p].point.x) - cbx, rby = LANES(c, manifold.points[p].point.y) - cby;
    tb_f4 normal_impulse = ctx->enable_warm_starting ? LANES(c, manifold.points[p].normal_impulse) : zero;
    tb_f4 tangent_impulse = ctx->enable_warm_starting ? LANES(c, manifold.points[p].tangent_impulse) : zero;
    if (p == 0) { /* the points lie on one line across the normal: the first one's levers serve both */
      cold_of(wc)->lever_a = rax * nx + ray * ny + LANES(c, patch.offset_a);
      cold_of(wc)->lever_b = rbx * nx + rby * ny + LANES(c, patch.offset_b);
    }
    wq->rax = blend(used, rax, zero);
    wq->ray = blend(used, ray, zero);
    wq->rbx = blend(used, rbx, zero);
    wq->rby = blend(used, rby, zero);
    wp->now_rax = wq->rax;
    wp->now_ray = wq->ray;
    wp->now_rbx = wq->rbx;
    wp->now_rby = wq->rby;
    wq->live = blend(used, one, zero);
    /* the manifold is of the float centres; the true gap adds the bodies'
     * center_residual along the normal */
    tb_f4 residual_gap = (LANES(bb, center_residual.x) - LANES(ba, center_residual.x)) * nx +
                         (LANES(bb, center_residual.y) - LANES(ba, center_residual.y)) * ny;
    wq->base_separation = blend(used, LANES(c, manifold.points[p].separation) + residual_gap, one);
    wp->normal_impulse = blend(used, normal_impulse, zero);
    wp->tangent_impulse = blend(used, tangent_impulse, zero);
    if (wc->bouncy) {
      tb_wide_record* r = &extra_of(wc)->q[p];
      r->max_normal_impulse = zero;
      r->applied = r->applied_rax = r->applied_ray = r->applied_rbx = r->applied_rby = zero;
    }
    /* the common point (see arms_now): a vertex of B on an edge of A moves
     * with B (beta = 1), a vertex of A on an edge of B with A (beta = 0);
     * else, and against a body that impulses do not move, by the inverse
     * masses */
    tb_i4 id = INT_LANES(c, manifold.points[p].id);
    const tb_i4 bit = {1, 1, 1, 1};
    tb_i4 edge_a = (id >> 16) & bit, edge_b = (id >> 24) & bit;
    tb_i4 vertex_b = both_move & (edge_a == bit) & (edge_b != bit);
    tb_i4 vertex_a = both_move & (edge_a != bit) & (edge_b == bit);
    tb_f4 beta = blend(vertex_b, one, blend(vertex_a, zero, mass_share));
    wq->shift_a = beta;
    wq->shift_b = blend(in_use, beta - one, zero);
    wq->collided_separation = wq->base_separation;
    /* (v_B + w_B x rb - v_A - w_A x ra) . n */
    tb_f4 vax = A.vx + -A.w * ray, vay = A.vy + A.w * rax;
    tb_f4 vbx = B.vx + -B.w * rby, vby = B.vy + B.w * rbx;
    approach[p] = blend(used, nx * (vbx - vax) + ny * (vby - vay), zero);
  }
  set_masses(wc);
  tb_f4 k11 = wc->k11, k12 = wc->k12, k22 = wc->k22;
  tb_i4 block = wc->block > zero;
  /* The soft push acts down to the depth at which the points' load (their
   * warm start) rests on the springs, plus TB_DEEP_OVERLAP; what lies deeper,
   * an overlap the load does not explain, is the push-out's. The springs hold
   * impulses a = F h at K a = h omega^2 (-s) (the soft update's fixed point at
   * v_n = 0; K the points' mass matrix inverse, diagonal where they are solved
   * one by one; one point alone: -s = F / (m_n omega^2)). */
  tb_f4 per_depth = splat(ctx->inv_h) / (omega * omega);
  tb_f4 a1 = wc->p[0].normal_impulse, a2 = wc->p[1].normal_impulse, k12_block = blend(block, k12, zero);
  /* max4 with zero also turns 0 * inf (a tiny contact_hertz) into 0 */
  /* Between two dynamic bodies, an overlap that their approach drove in is
   * the soft push's too: its impulses keep the momenta, where the push-out
   * moved the bodies without momentum and so turned two bodies sliding past
   * each other (angular momentum changed by up to 0.4%). The contact keeps
   * the depth so explained: what remains of the last step's, plus what the
   * approach (speed x dt) can drive in during this one. Bodies created or
   * moved into each other have no approach, and a pile is still pushed out;
   * against static and kinematic bodies nothing changes (no momentum to keep). */
  tb_f4 depth = max4(max4(-cold_of(wc)->q[0].base_separation, -cold_of(wc)->q[1].base_separation), zero);
  tb_f4 driven = blend(rigid_other, zero, max4(max4(-approach[0], -approach[1]), zero) * splat(ctx->dt));
  tb_f4 impact_depth = min4(depth, LANES(c, impact_depth)) + driven;
  wc->p[0].push_depth = blend(
      in_use, max4(max4((k11 * a1 + k12_block * a2) * per_depth, zero), impact_depth) + splat(TB_DEEP_OVERLAP), zero);
  wc->p[1].push_depth = blend(
      in_use, max4(max4((k12_block * a1 + k22 * a2) * per_depth, zero), impact_depth) + splat(TB_DEEP_OVERLAP), zero);
  for (int lane = 0; lane < 4; ++lane) {
    if (k[lane] < 0) continue;
    tb_contact_constraint* cc = &constraints(w)[k[lane]];
    cc->spin_a = A.w[lane];
    cc->spin_b = B.w[lane];
    ((tb_contact*)c[lane])->impact_depth = impact_depth[lane];
    cc->point_count = point_count[lane];
    cc->restitution = c[lane]->restitution;
    cc->relative_velocity[0] = approach[0][lane];
    cc->relative_velocity[1] = approach[1][lane];
  }
}

/* The contacts' colours: first those between two moving bodies, then, in
 * colours of their own from *fixed_from on, those with a body that does not
 * move (static or kinematic), so that every pass solves them last (see
 * tb_contact_solver_solve). Returns the number of colours, each contact's
 * in its lane field, and each moving solver body's contact_degree. Needs
 * scratch for bodies + 4 x contacts ints. */
static int color_constraints(tb_world* w, const tb_step_context* ctx, int* fixed_from) {
  int bodies = ctx->static_index + 1, count = w->step_contact_count;
  uint32_t* bits = (uint32_t*)w->scratch;
  /* (step contact, body a, body b), -1 for a body that does not move: the
   * pairs from the front, the others from the back */
  int32_t* waiting = w->scratch + bodies;
  int pairs = 0, end = count;
  uint8_t* degree = w->contact_degree;
  memset(degree, 0, (size_t)bodies);
  for (int k = 0; k < count; ++k) {
    const tb_contact* c = step_contact(w, k);
    const tb_body *body_a = tb_body_at(w, c->edges[0].body), *body_b = tb_body_at(w, c->edges[1].body);
    int a = solver_index(ctx, body_a);
    int b = solver_index(ctx, body_b);
    a = ctx->states[a].inv_mass > 0.0f ? a : -1;
    b = ctx->states[b].inv_mass > 0.0f ? b : -1;
    if (a >= 0) degree[a] = degree[a] > 0 || body_a->joint_count > 0 ? 2 : 1;
    if (b >= 0) degree[b] = degree[b] > 0 || body_b->joint_count > 0 ? 2 : 1;
    int32_t* e = a < 0 || b < 0 ? &waiting[3 * --end] : &waiting[3 * pairs++];
    e[0] = k;
    e[1] = a;
    e[2] = b;
  }
  for (int i = end, j = count - 1; i < j; ++i, --j) /* the others back in step order */
    for (int f = 0; f < 3; ++f) {
      int32_t t = waiting[3 * i + f];
      waiting[3 * i + f] = waiting[3 * j + f];
      waiting[3 * j + f] = t;
    }
  int32_t* color = waiting + 3 * count;
  *fixed_from = tb_color_rounds(bodies, bits, waiting, pairs, 0, color);
  int colors = tb_color_rounds(bodies, bits, waiting + 3 * end, count - end, *fixed_from, color);
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < count; ++k) cs[k].lane = color[k];
  return colors;
}

/* The lanes of a block with a point deeper than its push depth (less half
 * TB_DEEP_OVERLAP) at the step start, all four at once (a lane at a time,
 * this look over every block was 1% of a small pyramid's step). */
static tb_i4 deep_lanes(const tb_wide_contact* c) {
  tb_i4 deep = {0, 0, 0, 0};
  for (int p = 0; p < 2; ++p) {
    const tb_wide_point* wp = &c->p[p];
    deep |= (cold_of(c)->q[p].base_separation + wp->push_depth < splat(0.5f * TB_DEEP_OVERLAP)) &
            (wp->normal_mass > splat(0.0f));
  }
  return deep;
}

/* Adds lane `lane` of wide block b to the deep groups (tb_deep_block). */
static bool add_deep(tb_world* w, const tb_step_context* ctx, int b, int lane) {
  const tb_wide_contact* c = &((const tb_wide_contact*)w->wide)[b];
  int32_t a_body = c->a[lane], b_body = c->b[lane], stat = ctx->static_index;
  tb_deep_block* g = w->deep_count > 0 ? &((tb_deep_block*)w->deep_contacts)[w->deep_count - 1] : NULL;
  int used = 0;
  if (g != NULL) {
    while (used < 4 && g->block[used] >= 0) ++used;
    for (int k = 0; k < used; ++k) {
      bool shares = (a_body != stat && (a_body == g->a[k] || a_body == g->b[k])) ||
                    (b_body != stat && (b_body == g->a[k] || b_body == g->b[k]));
      if (shares) used = 4;
    }
  }
  if (g == NULL || used == 4) {
    if (!tb_array_reserve(&w->deep_contacts, &w->deep_capacity, w->deep_count + 1, sizeof(tb_deep_block))) return false;
    g = &((tb_deep_block*)w->deep_contacts)[w->deep_count++];
    memset(g, 0, sizeof *g);
    for (int k = 0; k < 4; ++k) g->block[k] = g->lane[k] = -1, g->a[k] = g->b[k] = stat;
    g->k11 = g->k22 = splat(1.0f); /* (an unused lane divides by them) */
    used = 0;
  }
  g->block[used] = b;
  g->lane[used] = lane;
  g->a[used] = a_body;
  g->b[used] = b_body;
  return true;
}

/* The contacts the push-out solves, and room for the push velocities when
 * there are any: the deep contacts between two moving bodies, then (their
 * blocks come last, see color_constraints) every contact with a body that
 * does not move (static or kinematic) of a body that has a deep one. With
 * those left out, the push-out pushed bodies into the static world: in a
 * pile-up of 1,000 bodies at one point the bottom ones were pushed into the
 * floor, up to 0.2 m a step, and 45 left through its far side within 10
 * steps. Such a contact's target is no push (its excess depth is 0), so the
 * push velocities may not close it; and solved last in each sweep, it holds
 * whatever the deep contacts before it did to the body. */
static bool collect_deep_contacts(tb_world* w, tb_step_context* ctx) {
  const tb_wide_contact* wide = (const tb_wide_contact*)w->wide;
  w->deep_count = 0;
  ctx->push_velocities = NULL;
  int bodies = ctx->static_index + 1;
  if (!tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, bodies, sizeof(int))) return false;
  int32_t* pushed = w->scratch; /* per solver body: 1 when a deep contact moves it */
  memset(pushed, 0, (size_t)bodies * sizeof *pushed);
  bool any = false;
  for (int b = 0; b < w->wide_count; ++b) {
    tb_i4 deep = deep_lanes(&wide[b]);
    if (!(deep[0] | deep[1] | deep[2] | deep[3])) continue;
    for (int lane = 0; lane < 4; ++lane) {
      if (!deep[lane]) continue;
      any = true;
      if (wide[b].ma[lane] > 0.0f) pushed[wide[b].a[lane]] = 1;
      if (wide[b].mb[lane] > 0.0f) pushed[wide[b].b[lane]] = 1;
    }
  }
  if (!any) return true;
  for (int b = 0; b < w->wide_count; ++b) {
    const tb_wide_contact* c = &wide[b];
    tb_i4 deep = deep_lanes(c);
    for (int lane = 0; lane < 4; ++lane) {
      bool live = c->p[0].normal_mass[lane] > 0.0f || c->p[1].normal_mass[lane] > 0.0f;
      /* the static dummy and kinematic bodies are never marked pushed */
      if (b < w->wide_fixed_from ? !deep[lane] : !(live && (pushed[c->a[lane]] || pushed[c->b[lane]]))) continue;
      if (!add_deep(w, ctx, b, lane)) return false;
    }
  }
  if (!tb_array_reserve((void**)&w->push_velocities, &w->push_capacity, 4 * bodies, sizeof(float))) return false;
  ctx->push_velocities = w->push_velocities;
  return true;
}

/* Whether each lane's moving bodies (inverse mass > 0) have no constraint
 * but this contact: a box alone on the ground, two balls meeting in the air.
 * Such a block's relax solve is the whole of its bodies' relax problem, so
 * solve_wide iterates it to convergence within one pass (no gather, scatter
 * or sweep between the rounds) instead of the passes repeating over
 * everything; an unused lane (the static dummy on both sides) qualifies. */
static int32_t lanes_isolated(const uint8_t* degree, const tb_wide_contact* c) {
  int32_t isolated = 1;
  for (int lane = 0; lane < 4; ++lane)
    isolated &=
        ((c->ma[lane] == 0.0f) | (degree[c->a[lane]] == 1)) & ((c->mb[lane] == 0.0f) | (degree[c->b[lane]] == 1));
  return isolated;
}

/* Pairs of blocks of one colour, which a pass solves eight lanes at a time
 * where the processor can (solve_pair). end_lane[c] is the lane after colour
 * c's last contact. An isolated block stays alone: its relax solve iterates
 * (solve_wide). */
static void pair_blocks(tb_wide_contact* wide, const int* end_lane, int colors) {
  int from = 0;
  for (int c = 0; c < colors; ++c) {
    int to = (end_lane[c] + 3) / 4;
    for (int b = from; b < to; ++b) wide[b].pair = 0;
    for (int b = from; b + 1 < to; ++b) {
      if (wide[b].isolated || wide[b + 1].isolated) continue;
      wide[b].pair = 1;
      wide[b + 1].pair = -1;
      ++b;
    }
    from = to;
  }
}

/* The blocks' layout: each contact's colour and lane, each lane's step
 * contact (lane_contacts), the moving bodies' contact degrees, and the first
 * block of the fixed colours. Needs scratch for bodies + 4 x contacts ints. */
static bool lay_out_blocks(tb_world* w, const tb_step_context* ctx) {
  int count = w->step_contact_count;
  int fixed_from = 0;
  int colors = color_constraints(w, ctx, &fixed_from);

  /* Blocks of four per colour, in constraint order (deterministic). */
  /* at least one: with no contacts there are no colours, and memset must not get a NULL */
  if (!tb_array_reserve((void**)&w->color_lanes, &w->color_capacity, colors + 1, sizeof(int))) return false;
  int* next_lane = w->color_lanes; /* the contacts of each colour, then the next lane of each */
  memset(next_lane, 0, (size_t)colors * sizeof(int));
  tb_contact_constraint* cs = constraints(w);
  for (int k = 0; k < count; ++k) next_lane[cs[k].lane] += 1;
  int blocks = 0;
  for (int c = 0; c < colors; ++c) {
    if (c == fixed_from) w->wide_fixed_from = blocks;
    int in_color = next_lane[c];
    next_lane[c] = 4 * blocks;
    blocks += (in_color + 3) / 4;
  }
  if (!tb_array_reserve((void**)&w->wide, &w->wide_capacity, blocks + 1, BLOCK_BYTES) ||
      !tb_array_reserve((void**)&w->lane_contacts, &w->lane_contact_capacity, 4 * blocks + 1, sizeof(int32_t)) ||
      !tb_array_reserve((void**)&w->laid_out_contacts, &w->laid_out_capacity, count, sizeof(int32_t)))
    return false;
  w->wide_count = blocks;
  if (fixed_from == colors) w->wide_fixed_from = blocks;
  int32_t* lane_contact = w->lane_contacts;
  memset(lane_contact, 0xff, (size_t)(4 * blocks) * sizeof *lane_contact);
  for (int k = 0; k < count; ++k) {
    int lane = next_lane[cs[k].lane]++;
    cs[k].lane = lane;
    lane_contact[lane] = k;
  }
  memcpy(w->laid_out_contacts, w->step_contacts, (size_t)count * sizeof *w->step_contacts);
  w->laid_out_count = count;
  w->laid_out_colors = colors;
  w->layout_valid = true;
  return true;
}

/* Whether the last layout holds for this step's contacts. A resting pile
 * keeps its contacts, and so its colours and lanes, step after step: the
 * colouring's walk over the contacts and their bodies (scattered in memory)
 * is then not repeated. The layout depends on the step contacts in their
 * order (compared here), which contact each pool slot holds, the solver
 * bodies and which of them have joints (any change of those clears
 * layout_valid). */
static bool layout_holds(const tb_world* w) {
  return w->layout_valid && w->laid_out_count == w->step_contact_count &&
         memcmp(w->laid_out_contacts, w->step_contacts, (size_t)w->laid_out_count * sizeof *w->step_contacts) == 0;
}

bool tb_contact_solver_prepare(tb_world* w, tb_step_context* ctx) {
  int count = w->step_contact_count;
  if (count == 0) { /* a pendulum, bodies in flight: what the path below leaves, without its walks */
    if (!tb_array_reserve((void**)&w->contact_degree, &w->degree_capacity, ctx->static_index + 1, 1)) return false;
    memset(w->contact_degree, 0, (size_t)ctx->static_index + 1);
    w->wide_count = w->wide_fixed_from = w->deep_count = 0;
    w->layout_valid = false;
    ctx->push_velocities = NULL;
    return true;
  }
  if (!tb_array_reserve((void**)&w->constraints, &w->constraint_capacity, count + 1, sizeof(tb_contact_constraint)) ||
      !tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, ctx->static_index + 1 + 4 * count, sizeof(int)) ||
      !tb_array_reserve((void**)&w->contact_degree, &w->degree_capacity, ctx->static_index + 1, 1))
    return false;
  if (!layout_holds(w) && !lay_out_blocks(w, ctx)) {
    w->layout_valid = false;
    return false;
  }
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  int blocks = w->wide_count;
  const int32_t* lane_contact = w->lane_contacts;
  for (int b = 0; b < blocks; ++b) {
    const int32_t* k = &lane_contact[4 * b];
    if (b + 1 < blocks) /* the next block's contacts, ahead of their turn */
      for (int lane = 0; lane < 4; ++lane)
        if (k[4 + lane] >= 0) __builtin_prefetch(tb_pool_at(&w->contacts, w->step_contacts[k[4 + lane]]));
    prepare_block(w, ctx, k, &wide[b]);
    wide[b].isolated = lanes_isolated(w->contact_degree, &wide[b]);
  }
  pair_blocks(wide, w->color_lanes, w->laid_out_colors);
  return collect_deep_contacts(w, ctx);
}

/* ---- wide solve ------------------------------------------------------------ */

/* The arms of one point now, from each body's centre to one common world
 * point. The arms of the step start (the manifold point) stay fixed in world
 * orientation, but the centres move with the substeps: arms fixed to the
 * bodies put the two bodies' ends of an impulse d = dp_B - dp_A apart, and
 * each impulse P added the torque d x P that nothing pays for (two boxes
 * sliding past each other changed their angular momentum by 4 to 15%). The
 * common point is the manifold point moved by (1 - beta) dp_A + beta dp_B:
 *   r_A = r_A0 + beta d,  r_B = r_B0 - (1 - beta) d,
 * so x_A + r_A = x_B + r_B and P at r_A, -P at r_B turn nothing. Where the
 * point is a vertex of one dynamic body on an edge of the other (feature
 * id), it moves with that vertex's body: beta = 1 for a vertex of B, 0 for
 * one of A (with the mass-weighted beta below, the two-point bounces of a
 * capsule on a polygon lost 1.6% of their energy). Elsewhere (round shapes,
 * and against a static or kinematic body) beta = m_B / (m_A + m_B) by the
 * inverse masses: against a body that does not move the point keeps the
 * dynamic body's step start arm, as a box sliding on the ground needs. The
 * arms' turn with their bodies is left out, as in the separation (see the
 * top of this file; with it, fast spinning debris blew up). The effective
 * masses follow the arms (refresh_arms). d is followed only
 * up to the smaller body's extent (per axis): a body that slides further
 * than its own size in one step (a bullet along a plank) has left the step
 * start's manifold point, and arms that followed it off the other body's
 * surface spun the plank out of the bullet's way. */
typedef struct wide_arms {
  tb_f4 rax, ray, rbx, rby;
} wide_arms;

static inline __attribute__((always_inline)) wide_arms arms_now(const tb_wide_contact* c, const tb_wide_anchor* cp,
                                                                const wide_body* A, const wide_body* B) {
  tb_f4 dx = min4(max4(B->dpx - A->dpx, -cold_of(c)->shift_limit), cold_of(c)->shift_limit);
  tb_f4 dy = min4(max4(B->dpy - A->dpy, -cold_of(c)->shift_limit), cold_of(c)->shift_limit);
  return (wide_arms){cp->rax + cp->shift_a * dx, cp->ray + cp->shift_a * dy, cp->rbx + cp->shift_b * dx,
                     cp->rby + cp->shift_b * dy};
}

/* The arms stored by refresh_arms (or prepare). */
static inline __attribute__((always_inline)) wide_arms stored_arms(const tb_wide_point* cp) {
  return (wide_arms){cp->now_rax, cp->now_ray, cp->now_rbx, cp->now_rby};
}

/* Keeps count of a normal impulse applied at these arms (see restitution_targets). */
static inline __attribute__((always_inline)) void count_normal(tb_wide_record* cp, const wide_arms* arms,
                                                               tb_f4 impulse) {
  cp->applied += impulse;
  cp->applied_rax += impulse * arms->rax;
  cp->applied_ray += impulse * arms->ray;
  cp->applied_rbx += impulse * arms->rbx;
  cp->applied_rby += impulse * arms->rby;
}

/* An impulse P at each end of one point: -P on A, +P on B. */
static inline __attribute__((always_inline)) void apply_impulse(const tb_wide_contact* c, const wide_arms* cp, tb_f4 Px,
                                                                tb_f4 Py, wide_body* A, wide_body* B) {
  A->vx -= c->ma * Px;
  A->vy -= c->ma * Py;
  A->w -= c->ja * (cp->rax * Py - cp->ray * Px);
  B->vx += c->mb * Px;
  B->vy += c->mb * Py;
  B->w += c->jb * (cp->rbx * Py - cp->rby * Px);
}

/* (v_B + w_B x r_B) - (v_A + w_A x r_A) at one point */
static inline __attribute__((always_inline)) void relative_velocity(const wide_arms* cp, const wide_body* A,
                                                                    const wide_body* B, tb_f4* dvx, tb_f4* dvy) {
  *dvx = (B->vx + -B->w * cp->rby) - (A->vx + -A->w * cp->ray);
  *dvy = (B->vy + B->w * cp->rbx) - (A->vy + A->w * cp->rax);
}

static void warm_start_wide(tb_wide_contact* c, tb_solver_body* states) {
  wide_body A = gather_velocities(states, c->a), B = gather_velocities(states, c->b);
  tb_f4 tx = c->ny, ty = -c->nx;
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    wide_arms arms = stored_arms(cp);
    if (c->bouncy) count_normal(&extra_of(c)->q[p], &arms, cp->normal_impulse);
    tb_f4 Px = cp->normal_impulse * c->nx + cp->tangent_impulse * tx;
    tb_f4 Py = cp->normal_impulse * c->ny + cp->tangent_impulse * ty;
    apply_impulse(c, &arms, Px, Py, &A, &B);
  }
  if (c->rolling) { /* (a block without rolling resistance holds no rolling impulse) */
    A.w -= c->ja * extra_of(c)->rolling_impulse;
    B.w += c->jb * extra_of(c)->rolling_impulse;
  }
  scatter(states, c->a, &A);
  scatter(states, c->b, &B);
}

/* How far one point's anchors have moved apart along the normal since the
 * step began, to first order in the angles (see the top); the separation
 * now is this plus base_separation. */
static inline __attribute__((always_inline)) tb_f4 normal_motion(const tb_wide_contact* c, const tb_wide_anchor* cp,
                                                                 const wide_body* A, const wide_body* B) {
  /* da x r = (-da r.y, da r.x), as tb_cross_sv */
  tb_f4 prax = -A->da * cp->ray, pray = A->da * cp->rax;
  tb_f4 prbx = -B->da * cp->rby, prby = B->da * cp->rbx;
  tb_f4 dpx = B->dpx - A->dpx, dpy = B->dpy - A->dpy;
  return (dpx + (prbx - prax)) * c->nx + (dpy + (prby - pray)) * c->ny;
}

/* Leaving an edge. The manifold is collided once per step, but within the
 * step a body can slide off the end of the face that holds it up (a ball
 * rolling off a table, a box sliding off a ledge): its face points would go
 * on pushing along the face normal for the rest of the step, as if the face
 * ran on, and hold it up for up to a whole step (the ball then lands up to
 * v dt further out). So after each position update the solver measures how
 * far B's core has slid along the tangent relative to A since the step
 * began (to first order in the angles, on the cores: a rolling ball's centre
 * moves, its contact point does not),
 *   d = t . (dp_B - dp_A) - da_B lever_B + da_A lever_A,
 * and how far x that is past the patch (see tb_patch). Past it, what is left
 * of the contact is the two cores' ends, x apart along t, whose gap is
 *   sqrt(x^2 + (s + R)^2) - R     (R the cores' radii, s + R their gap along n):
 * a ball that has rolled past a corner by x is held by it only where it
 * would sink below x^2 / 2R, a sharp corner hardly at all; a ball on a ball
 * (a patch of one point) sees their curvature. The points' base separations
 * are set so that their separations are that gap until the next position
 * update (the passes in between, and the push-out, cost nothing more). Below
 * TB_SLIDE_TOLERANCE past the patch (m) the contact is left as collided: a
 * resting ball's jitter on another ball changes its gap by x^2 / 2R, far
 * below float rounding, and a face point goes on for at most that much of
 * slide (0.17 ms at 3 m/s). */
#define TB_SLIDE_TOLERANCE (0.1f * tb_units.linear_slop)

/* A lane past an end of its patch that lay within reach of the step (see
 * prepare_block) asks, once per end and step, whether another shape
 * continues the face there (tb_contact_face_runs_on); where one does, the
 * end is gone for as long as the manifold lasts (the contact keeps that) and
 * the lane is within its patch again. Asked of every end within reach before
 * the substeps, the tree queries were 12% of compounds' step: the ends of
 * flush columns are always within reach and never passed. The bodies'
 * transforms and the broad phase stay the step start's until the step ends,
 * so the answer is the one asking before the substeps gave; the one change
 * is that an end found covered in an earlier step, and not passed then, is
 * asked again when it is passed. */
static __attribute__((noinline)) tb_f4 ask_ends(tb_wide_contact* c, const tb_step_context* ctx, tb_f4 d, tb_f4 beyond) {
  for (int lane = 0; lane < 4; ++lane) {
    if (!(beyond[lane] > TB_SLIDE_TOLERANCE) || cold_of(c)->contact[lane] < 0) continue;
    bool max_end = d[lane] - cold_of(c)->slide_max[lane] >= cold_of(c)->slide_min[lane] - d[lane];
    int bit = 1 << (2 * lane + (max_end ? 1 : 0));
    if ((c->ends_asked & bit) || !(c->ends_near & bit)) continue;
    c->ends_asked |= bit;
    if (!tb_contact_face_runs_on(ctx->world, cold_of(c)->contact[lane], max_end)) continue;
    if (max_end)
      cold_of(c)->slide_max[lane] = FLT_MAX;
    else
      cold_of(c)->slide_min[lane] = -FLT_MAX;
    beyond[lane] = tb_maxf(cold_of(c)->slide_min[lane] - d[lane], d[lane] - cold_of(c)->slide_max[lane]);
  }
  return beyond;
}

/* the base separations of a block with a lane past its patch, or that had one */
static __attribute__((noinline)) void set_slide_gaps(tb_wide_contact* c, const wide_body* A, const wide_body* B,
                                                     tb_f4 beyond) {
  tb_i4 off = beyond > splat(TB_SLIDE_TOLERANCE);
  c->slid_off = off[0] | off[1] | off[2] | off[3];
  for (int p = 0; p < 2; ++p) {
    tb_wide_anchor* cp = &cold_of(c)->q[p];
    tb_f4 moved = normal_motion(c, cp, A, B), s = moved + cp->collided_separation;
    tb_f4 gap = max4(s + cold_of(c)->core_radius, splat(0.0f)), squared = beyond * beyond + gap * gap, ends;
    for (int lane = 0; lane < 4; ++lane) ends[lane] = sqrtf(squared[lane]);
    cp->base_separation = blend(off, (ends - cold_of(c)->core_radius) - moved, cp->collided_separation);
  }
}

static inline __attribute__((always_inline)) void measure_slide(tb_wide_contact* c, const tb_step_context* ctx,
                                                                const wide_body* A, const wide_body* B) {
  tb_f4 d =
      c->ny * (B->dpx - A->dpx) - c->nx * (B->dpy - A->dpy) - B->da * cold_of(c)->lever_b + A->da * cold_of(c)->lever_a;
  tb_f4 beyond = max4(cold_of(c)->slide_min - d, d - cold_of(c)->slide_max);
  tb_i4 off = beyond > splat(TB_SLIDE_TOLERANCE);
  if (off[0] | off[1] | off[2] | off[3]) {
    beyond = ask_ends(c, ctx, d, beyond);
    off = beyond > splat(TB_SLIDE_TOLERANCE);
  }
  /* the common case: nothing past its patch now or before */
  if ((off[0] | off[1] | off[2] | off[3]) || c->slid_off) set_slide_gaps(c, A, B, beyond);
}

/* The soft terms of one point's normal impulse: its mass scale, and
 * r = v_n + bias, at separation s. */
static inline __attribute__((always_inline)) tb_f4 normal_target(const tb_wide_contact* c, const tb_wide_point* cp,
                                                                 const wide_arms* arms, const wide_body* A,
                                                                 const wide_body* B, tb_f4 s, float inv_h, float push,
                                                                 bool use_bias, tb_f4* mass_scale) {
  const tb_f4 zero = splat(0.0f), one = splat(1.0f);
  tb_i4 speculative = s > zero;
  tb_f4 bias;
  if (use_bias) {
    bias = blend(speculative, s * inv_h, max4(c->bias_rate * max4(s, -cp->push_depth), splat(-push)));
    *mass_scale = blend(speculative, one, c->mass_scale);
  } else {
    bias = blend(speculative, s * inv_h, zero);
    *mass_scale = one;
  }
  tb_f4 dvx, dvy;
  relative_velocity(arms, A, B, &dvx, &dvy);
  return dvx * c->nx + dvy * c->ny + bias;
}

/* Friction at one point: the tangent impulse, clamped by mu times the
 * point's normal impulse, towards the surfaces' tangent speed. Returns the
 * impulse applied. */
static inline __attribute__((always_inline)) tb_f4 solve_friction(tb_wide_contact* c, tb_wide_point* cp,
                                                                  const wide_arms* arms, wide_body* A, wide_body* B) {
  tb_f4 tx = c->ny, ty = -c->nx;
  tb_f4 dvx, dvy;
  relative_velocity(arms, A, B, &dvx, &dvy);
  tb_f4 vt = dvx * tx + dvy * ty;
  tb_f4 impulse = -cp->tangent_mass * (vt - c->tangent_speed);
  tb_f4 limit = c->friction * cp->normal_impulse;
  tb_f4 total = min4(max4(cp->tangent_impulse + impulse, -limit), limit);
  impulse = total - cp->tangent_impulse;
  cp->tangent_impulse = total;
  apply_impulse(c, arms, impulse * tx, impulse * ty, A, B);
  return impulse;
}

/* After the positions moved: each point's arms to its common point now, and
 * the effective masses there once an arm has moved by more than
 * TB_ARM_MASS_SHIFT since the step began (the passes' impulses must not
 * overshoot where the arms grew; the masses of arms that moved less are off
 * by under 2 TB_ARM_MASS_SHIFT / r, 4% for 5 cm arms, which the passes
 * absorb, and a resting structure does not pay for them). Done block by
 * block in the first pass after each position update (the arms depend on
 * the positions only), which saves a pass of its own over all the blocks
 * (pyramids: 6% of the step). */
#define TB_ARM_MASS_SHIFT (0.2f * tb_units.linear_slop)
static inline __attribute__((always_inline)) void refresh_arms(tb_wide_contact* c, const wide_body* A,
                                                               const wide_body* B) {
  tb_f4 moved = splat(0.0f);
  for (int p = 0; p < 2; ++p) {
    tb_wide_point* cp = &c->p[p];
    const tb_wide_anchor* cq = &cold_of(c)->q[p];
    wide_arms arms = arms_now(c, cq, A, B);
    tb_f4 dx = arms.rax - cq->rax, dy = arms.ray - cq->ray, ex = arms.rbx - cq->rbx, ey = arms.rby - cq->rby;
    moved = max4(moved, max4(max4(max4(dx, -dx), max4(dy, -dy)), max4(max4(ex, -ex), max4(ey, -ey))));
    cp->now_rax = arms.rax;
    cp->now_ray = arms.ray;
    cp->now_rbx = arms.rbx;
    cp->now_rby = arms.rby;
  }
  /* any lane beyond the shift, by one compare: the largest lane (max_lane)
   * took three branches on the data, mispredicted in about every other block
   * (large_pyramid 0.94x); a NaN lane is beyond neither way */
  tb_i4 shifted = moved > splat(TB_ARM_MASS_SHIFT);
  if (shifted[0] | shifted[1] | shifted[2] | shifted[3]) set_masses(c);
}

/* The relax passes' record of a block's lanes (relax_activity.h): the
 * bodies of the lanes noted changed in this pass. */
static inline __attribute__((always_inline)) void note_lanes(tb_step_context* ctx, const tb_wide_contact* c,
                                                             tb_i4 noted) {
  tb_relax_note_lanes(ctx, c->a, noted);
  tb_relax_note_lanes(ctx, c->b, noted);
}

/* An isolated block's relax solve in one go, where it has one: a box
 * resting on the ground, held on a slope or sliding down one. Gauss-Seidel
 * over its rows converges slowly there, because each normal impulse turns
 * the box and so moves the friction rows' velocity and back (the box on a 20
 * degree slope: 5 rounds a substep to 1e-5 m/s). With both points pushing
 * and friction sticking, the solution is the linear solve of the contact's
 * rows together,
 *   K x = -r,  K = J M^-1 J^T,  r = J v + (s / h where a point is still apart),
 * with J the two normal rows and one tangent row: the two points' tangent
 * rows are one row (their levers r x t = -(r . n) are the face's lever at
 * both, apart from the points' separations), so friction is solved as one
 * total T and shared between the points by their normal impulses, which
 * keeps each within its cone when the total is within mu (N1 + N2). 3 x 3,
 * symmetric, by Cramer's rule, four lanes at once. A lane whose solution
 * pulls, leaves the cone, or is ill-conditioned (one point, points too close
 * together) keeps its impulses, and the rounds then see every lane and stop
 * as before at 1e-5 m/s. Returns whether every lane with a contact was
 * solved here: the block's relax problem is then solved (a further round
 * changes its speeds by rounding only) and needs no rounds, no record (its
 * bodies have no other constraint) and no further pass (its change is 0). A
 * box held on a slope took 5 rounds a substep before, one sliding down one
 * 1.3, now none. Where sticking would leave the cone, the sliding case below
 * is the solve instead. */
static inline __attribute__((always_inline)) bool solve_isolated_direct(tb_wide_contact* c, const wide_arms* arms1,
                                                                        const wide_arms* arms2, wide_body* A,
                                                                        wide_body* B, tb_f4 s1, tb_f4 s2, float inv_h) {
  const tb_f4 zero = splat(0.0f), half = splat(0.5f), one = splat(1.0f);
  /* A lane of one point (a ball, a corner) has its normal and tangent rows
   * only: the second normal row becomes the identity with nothing to do.
   * Without friction such a lane is one row, which the rounds solve at once:
   * it stays theirs (the same bits; solved here, the division in place of
   * the stored normal mass moved 40 bouncing balls' energy error from 4.2e-4
   * to 1.7e-3: their collisions are chaotic). */
  tb_i4 two = cold_of(c)->q[1].live > zero, single = (cold_of(c)->q[0].live > zero) & ~two & (c->friction > zero);
  tb_f4 nx = c->nx, ny = c->ny, tx = ny, ty = -nx;
  tb_f4 m = c->ma + c->mb, ja = c->ja, jb = c->jb;
  tb_f4 rna1 = arms1->rax * ny - arms1->ray * nx, rnb1 = arms1->rbx * ny - arms1->rby * nx;
  tb_f4 rna2 = arms2->rax * ny - arms2->ray * nx, rnb2 = arms2->rbx * ny - arms2->rby * nx;
  tb_f4 rta1 = arms1->rax * ty - arms1->ray * tx, rtb1 = arms1->rbx * ty - arms1->rby * tx;
  tb_f4 rta = blend(two, half * (rta1 + (arms2->rax * ty - arms2->ray * tx)), rta1);
  tb_f4 rtb = blend(two, half * (rtb1 + (arms2->rbx * ty - arms2->rby * tx)), rtb1);
  tb_f4 k11 = m + ja * rna1 * rna1 + jb * rnb1 * rnb1;
  tb_f4 k22 = blend(single, one, m + ja * rna2 * rna2 + jb * rnb2 * rnb2);
  tb_f4 k12 = blend(single, zero, m + ja * rna1 * rna2 + jb * rnb1 * rnb2);
  tb_f4 k1t = ja * rna1 * rta + jb * rnb1 * rtb, k2t = blend(single, zero, ja * rna2 * rta + jb * rnb2 * rtb);
  tb_f4 ktt = m + ja * rta * rta + jb * rtb * rtb;
  tb_f4 dvx, dvy;
  relative_velocity(arms1, A, B, &dvx, &dvy);
  tb_f4 r1 = dvx * nx + dvy * ny + blend(s1 > zero, s1 * splat(inv_h), zero), vt1 = dvx * tx + dvy * ty;
  relative_velocity(arms2, A, B, &dvx, &dvy);
  tb_f4 r2 = blend(single, zero, dvx * nx + dvy * ny + blend(s2 > zero, s2 * splat(inv_h), zero));
  tb_f4 vt2 = dvx * tx + dvy * ty;
  tb_f4 r3 = blend(two, half * (vt1 + vt2), vt1) - c->tangent_speed;
  tb_f4 c11 = k22 * ktt - k2t * k2t, c12 = k1t * k2t - k12 * ktt, c13 = k12 * k2t - k22 * k1t;
  tb_f4 c22 = k11 * ktt - k1t * k1t, c23 = k12 * k1t - k11 * k2t, c33 = k11 * k22 - k12 * k12;
  tb_f4 det = k11 * c11 + k12 * c12 + k1t * c13;
  tb_f4 inv = splat(1.0f) / det;
  tb_wide_point *p1 = &c->p[0], *p2 = &c->p[1];
  tb_f4 a1 = p1->normal_impulse, a2 = p2->normal_impulse, b1 = p1->tangent_impulse, b2 = p2->tangent_impulse;
  tb_f4 n1 = a1 - (c11 * r1 + c12 * r2 + c13 * r3) * inv;
  tb_f4 n2 = a2 - (c12 * r1 + c22 * r2 + c23 * r3) * inv;
  tb_f4 total = (b1 + b2) - (c13 * r1 + c23 * r2 + c33 * r3) * inv;
  tb_f4 load = n1 + n2;
  tb_i4 solvable = ((c->block > zero) | single) & (det > splat(1e-3f) * k11 * k22 * ktt);
  tb_i4 stick = solvable & (n1 >= zero) & (n2 >= zero) & (load > zero) & (fabs4(total) <= c->friction * load);
  /* Sliding, where sticking would leave the cone: each point's friction at
   * its limit, T_i = f N_i with f = +-mu the side the sticking total pushed,
   * so the normal rows alone are unknown:
   *   (k_ij + f k_it) dN_j = -(r_i + k_it (f (a1 + a2) - (b1 + b2))),
   * and the slide must go on the way friction opposes: after it the mean
   * tangent speed r3 + k_1t dN1 + k_2t dN2 + k_tt dT is not of the sign of f. */
  tb_f4 f = blend(total < zero, -c->friction, c->friction);
  tb_f4 held = f * (a1 + a2) - (b1 + b2);
  tb_f4 s11 = k11 + f * k1t, s12 = k12 + f * k1t, s21 = k12 + f * k2t, s22 = k22 + f * k2t;
  tb_f4 g1 = -(r1 + k1t * held), g2 = -(r2 + k2t * held);
  tb_f4 det2 = s11 * s22 - s12 * s21;
  tb_f4 inv2 = splat(1.0f) / det2;
  tb_f4 dm1 = (s22 * g1 - s12 * g2) * inv2, dm2 = (s11 * g2 - s21 * g1) * inv2;
  tb_f4 m1 = a1 + dm1, m2 = a2 + dm2;
  tb_f4 slip = r3 + k1t * dm1 + k2t * dm2 + ktt * (f * (m1 + m2) - (b1 + b2));
  tb_i4 slide = solvable & ~stick & (fabs4(det2) > splat(1e-3f) * fabs4(s11 * s22)) & (m1 >= zero) & (m2 >= zero) &
                (m1 + m2 > zero) & (slip * f <= zero);
  tb_i4 ok = stick | slide;
  if (!(ok[0] | ok[1] | ok[2] | ok[3])) return false;
  n1 = blend(slide, m1, n1);
  n2 = blend(slide, m2, n2);
  tb_f4 t1 = blend(slide, f * m1, total * n1 / load);
  tb_f4 t2 = blend(single, zero, blend(slide, f * m2, total - t1)); /* (a lone point's partner is inert) */
  tb_f4 dn1 = blend(ok, n1 - a1, zero), dn2 = blend(ok, n2 - a2, zero);
  tb_f4 dt1 = blend(ok, t1 - b1, zero), dt2 = blend(ok, t2 - b2, zero);
  p1->normal_impulse = blend(ok, n1, a1);
  p2->normal_impulse = blend(ok, n2, a2);
  p1->tangent_impulse = blend(ok, t1, b1);
  p2->tangent_impulse = blend(ok, t2, b2);
  apply_impulse(c, arms1, dn1 * nx + dt1 * tx, dn1 * ny + dt1 * ty, A, B);
  apply_impulse(c, arms2, dn2 * nx + dt2 * tx, dn2 * ny + dt2 * ty, A, B);
  if (c->bouncy) { /* restitution's record of the normal impulses (see solve_wide) */
    tb_wide_record* r = extra_of(c)->q;
    count_normal(&r[0], arms1, dn1);
    count_normal(&r[1], arms2, dn2);
    r[0].max_normal_impulse = max4(r[0].max_normal_impulse, p1->normal_impulse);
    r[1].max_normal_impulse = max4(r[1].max_normal_impulse, p2->normal_impulse);
  }
  tb_i4 rest = ~ok & (cold_of(c)->q[0].live > zero); /* lanes with a contact left to the rounds */
  return !(rest[0] | rest[1] | rest[2] | rest[3]);
}

/* Always inlined: each kind of pass gets a copy without the others'
 * branches. measure: the first pass after a position update, which measures
 * the slides and keeps the points' separations; stored: a later pass at the
 * same positions, which reads those and so needs only the bodies' velocities. */
static inline __attribute__((always_inline)) void solve_wide(tb_wide_contact* c, tb_step_context* ctx, bool use_bias,
                                                             bool measure, bool stored, bool record, tb_f4* change) {
  tb_solver_body* states = ctx->states;
  float inv_h = ctx->inv_h, push = ctx->contact_push_max_velocity;
  wide_body A = stored ? gather_velocities(states, c->a) : gather(states, c->a);
  wide_body B = stored ? gather_velocities(states, c->b) : gather(states, c->b);
  const tb_f4 zero = splat(0.0f);
  tb_wide_point *p1 = &c->p[0], *p2 = &c->p[1];
  /* Per point: the soft terms and r = v0 + bias, where v0 is the normal speed
   * the point would have without its accumulated impulse a (v0 = v_n - K a).
   * Since mass_scale + impulse_scale = 1, the soft update of one point,
   * a - m_n mass_scale (v_n + bias) - impulse_scale a, is the same as
   * x = -mass_scale m_n r: a new total that does not depend on a. */
  if (measure) refresh_arms(c, &A, &B); /* once per position update: later passes see the same positions */
  wide_arms arms1 = stored_arms(p1), arms2 = stored_arms(p2);
  tb_f4 ms1, ms2;
  if (measure) measure_slide(c, ctx, &A, &B);
  tb_f4 s1 = stored ? p1->separation : normal_motion(c, &cold_of(c)->q[0], &A, &B) + cold_of(c)->q[0].base_separation;
  tb_f4 s2 = stored ? p2->separation : normal_motion(c, &cold_of(c)->q[1], &A, &B) + cold_of(c)->q[1].base_separation;
  if (measure) p1->separation = s1, p2->separation = s2;
  /* An isolated block's relax solve (lanes_isolated) repeats, up to
   * relax_iterations rounds, until no point's speed changes by more than
   * TB_RELAX_TOLERANCE: what the passes would do over it, without their
   * sweeps over everything else. Its stop and record see the last round.
   * Where the direct solve took every lane, there is no round (rolling
   * resistance adds a row it does not have). */
  int rounds = !use_bias && c->isolated ? ctx->world->relax_iterations : 1;
  bool solved =
      !use_bias && c->isolated && !c->rolling && solve_isolated_direct(c, &arms1, &arms2, &A, &B, s1, s2, inv_h);
  tb_f4 normal_change = splat(0.0f), moved = splat(0.0f);
  for (int round = 1; !solved; ++round) {
    tb_f4 t1 = normal_target(c, p1, &arms1, &A, &B, s1, inv_h, push, use_bias, &ms1);
    tb_f4 t2 = normal_target(c, p2, &arms2, &A, &B, s2, inv_h, push, use_bias, &ms2);
    tb_f4 a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    /* Both points at once (Box2D 2.4's block solver for the mixed LCP
     * x >= 0, K x + r0 >= 0, complementary; here scaled by mass_scale): the
     * first case that holds wins: both push; only 1; only 2; neither. Lanes
     * with one point (or a near-singular K) take the one-point case. */
    tb_i4 two = c->block > zero;
    tb_f4 r1 = t1 - c->k11 * a1 - c->k12 * a2; /* v0_1 + bias_1 */
    tb_f4 r2 = t2 - c->k12 * a1 - c->k22 * a2;
    tb_f4 x1 = a1, x2 = a2; /* no case holds (round-off): keep the impulses */
    tb_i4 none = (r1 >= zero) & (~two | (r2 >= zero));
    x1 = blend(none, zero, x1);
    x2 = blend(none, zero, x2);
    tb_f4 only2 = -ms2 * p2->normal_mass * r2;
    tb_i4 second = two & (only2 >= zero) & (r1 + c->k12 * only2 >= zero);
    x1 = blend(second, zero, x1);
    x2 = blend(second, only2, x2);
    tb_f4 only1 = -ms1 * p1->normal_mass * r1;
    tb_i4 first = (only1 >= zero) & (~two | (r2 + c->k12 * only1 >= zero));
    x1 = blend(first, only1, x1);
    x2 = blend(first, zero, x2);
    tb_f4 both1 = -ms1 * (c->n11 * r1 + c->n12 * r2), both2 = -ms2 * (c->n12 * r1 + c->n22 * r2);
    tb_i4 both = two & (both1 >= zero) & (both2 >= zero);
    x1 = blend(both, both1, x1);
    x2 = blend(both, both2, x2);
    p1->normal_impulse = x1;
    tb_f4 d1 = x1 - a1;
    apply_impulse(c, &arms1, d1 * c->nx, d1 * c->ny, &A, &B);
    if (c->bouncy) {
      count_normal(&extra_of(c)->q[0], &arms1, d1);
      extra_of(c)->q[0].max_normal_impulse = max4(extra_of(c)->q[0].max_normal_impulse, x1);
    }
    p2->normal_impulse = x2;
    tb_f4 d2 = x2 - a2;
    apply_impulse(c, &arms2, d2 * c->nx, d2 * c->ny, &A, &B);
    if (c->bouncy) {
      count_normal(&extra_of(c)->q[1], &arms2, d2);
      extra_of(c)->q[1].max_normal_impulse = max4(extra_of(c)->q[1].max_normal_impulse, x2);
    }
    /* the normal speed each point's change made (its own K_ii; the coupling
     * term is left out), for the relax passes' stop */
    normal_change = max4(max4(d1, -d1) * c->k11, max4(d2, -d2) * c->k22);
    tb_f4 f1 = solve_friction(c, p1, &arms1, &A, &B);
    tb_f4 f2 = solve_friction(c, p2, &arms2, &A, &B);
    /* the points' speed changes, friction's taken at the normal K (the same
     * order as the tangent one): the relax passes' record (relax_activity.h) */
    moved = max4(normal_change, max4(max4(f1, -f1) * c->k11, max4(f2, -f2) * c->k22));
    if (c->rolling) {
      tb_wide_extra* e = extra_of(c);
      tb_f4 limit = e->rolling_resistance * (x1 + x2);
      tb_f4 impulse = -e->rolling_mass * (B.w - A.w);
      tb_f4 total = min4(max4(e->rolling_impulse + impulse, -limit), limit);
      impulse = total - e->rolling_impulse;
      e->rolling_impulse = total;
      A.w -= c->ja * impulse;
      B.w += c->jb * impulse;
    }
    if (round >= rounds) break;
    tb_i4 moving = moved > splat(TB_RELAX_TOLERANCE);
    if (!(moving[0] | moving[1] | moving[2] | moving[3])) break;
  }
  if (!use_bias) *change = max4(*change, normal_change);
  if (record) note_lanes(ctx, c, moved > splat(TB_RELAX_TOLERANCE));
  scatter(states, c->a, &A);
  scatter(states, c->b, &B);
}

/* ---- eight lanes at a time ----------------------------------------------------
 * Where the processor has AVX2, the passes that read the stored separations
 * (the biased pass after the first substep, the later relax passes) solve two
 * blocks of one colour at once, eight lanes, from the same blocks. Within a
 * colour no two lanes share a moving body, so two blocks solved at once give
 * what the two give one after the other, and each lane does the float
 * operations of solve_wide in the same order: the results are the same bits
 * as with four lanes, on any processor. */
#if defined(TB_EIGHT_LANES)
#define AVX2 __attribute__((target("avx2")))
#define AVX2_INLINE static inline __attribute__((target("avx2"), always_inline))

typedef float tb_f8 __attribute__((vector_size(32)));
typedef int32_t tb_i8 __attribute__((vector_size(32)));

AVX2_INLINE tb_f8 join(tb_f4 lo, tb_f4 hi) { return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7); }
AVX2_INLINE tb_f4 low_half(tb_f8 v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
AVX2_INLINE tb_f4 high_half(tb_f8 v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }
AVX2_INLINE tb_i4 low_mask(tb_i8 v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
AVX2_INLINE tb_i4 high_mask(tb_i8 v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }
AVX2_INLINE tb_f8 splat8(float x) { return (tb_f8){x, x, x, x, x, x, x, x}; }
AVX2_INLINE tb_f8 blend8(tb_i8 mask, tb_f8 a, tb_f8 b) { return (tb_f8)(((tb_i8)a & mask) | ((tb_i8)b & ~mask)); }
/* as max4 and min4, lane by lane */
AVX2_INLINE tb_f8 max8(tb_f8 a, tb_f8 b) { return (tb_f8)_mm256_max_ps((__m256)a, (__m256)b); }
AVX2_INLINE tb_f8 min8(tb_f8 a, tb_f8 b) { return (tb_f8)_mm256_min_ps((__m256)a, (__m256)b); }

typedef struct wide_body8 {
  tb_f8 vx, vy, w, inv_mass;
} wide_body8;

typedef struct wide_arms8 {
  tb_f8 rax, ray, rbx, rby;
} wide_arms8;

AVX2_INLINE wide_body8 gather8(const tb_solver_body* states, const int32_t* lo, const int32_t* hi) {
  wide_body a = gather_velocities(states, lo), b = gather_velocities(states, hi);
  return (wide_body8){join(a.vx, b.vx), join(a.vy, b.vy), join(a.w, b.w), join(a.inv_mass, b.inv_mass)};
}

AVX2_INLINE void scatter8(tb_solver_body* states, const int32_t* lo, const int32_t* hi, const wide_body8* v) {
  wide_body a = {.vx = low_half(v->vx), .vy = low_half(v->vy), .w = low_half(v->w), .inv_mass = low_half(v->inv_mass)};
  wide_body b = {
      .vx = high_half(v->vx), .vy = high_half(v->vy), .w = high_half(v->w), .inv_mass = high_half(v->inv_mass)};
  scatter(states, lo, &a);
  scatter(states, hi, &b);
}

/* apply_impulse, eight lanes */
AVX2_INLINE void apply8(tb_f8 ma, tb_f8 ja, tb_f8 mb, tb_f8 jb, const wide_arms8* r, tb_f8 Px, tb_f8 Py, wide_body8* A,
                        wide_body8* B) {
  A->vx -= ma * Px;
  A->vy -= ma * Py;
  A->w -= ja * (r->rax * Py - r->ray * Px);
  B->vx += mb * Px;
  B->vy += mb * Py;
  B->w += jb * (r->rbx * Py - r->rby * Px);
}

/* relative_velocity, eight lanes */
AVX2_INLINE void relative_velocity8(const wide_arms8* r, const wide_body8* A, const wide_body8* B, tb_f8* dvx,
                                    tb_f8* dvy) {
  *dvx = (B->vx + -B->w * r->rby) - (A->vx + -A->w * r->ray);
  *dvy = (B->vy + B->w * r->rbx) - (A->vy + A->w * r->rax);
}

/* solve_wide at the stored separations for blocks c0 and c1 of one colour */
AVX2_INLINE void solve_pair(tb_wide_contact* c0, tb_wide_contact* c1, tb_step_context* ctx, bool use_bias, bool record,
                            tb_f8* change) {
#define BOTH(field) join(c0->field, c1->field)
#define STORE(field, v) (c0->field = low_half(v), c1->field = high_half(v))
  tb_solver_body* states = ctx->states;
  float inv_h = ctx->inv_h, push = ctx->contact_push_max_velocity;
  wide_body8 A = gather8(states, c0->a, c1->a), B = gather8(states, c0->b, c1->b);
  const tb_f8 zero = splat8(0.0f), one = splat8(1.0f);
  tb_f8 nx = BOTH(nx), ny = BOTH(ny), ma = BOTH(ma), ja = BOTH(ja), mb = BOTH(mb), jb = BOTH(jb);
  wide_arms8 arms[2];
  tb_f8 t[2], ms[2], a[2];
  for (int q = 0; q < 2; ++q) { /* normal_target */
    arms[q] = (wide_arms8){BOTH(p[q].now_rax), BOTH(p[q].now_ray), BOTH(p[q].now_rbx), BOTH(p[q].now_rby)};
    tb_f8 s = BOTH(p[q].separation), bias;
    tb_i8 speculative = s > zero;
    if (use_bias) {
      bias = blend8(speculative, s * inv_h, max8(BOTH(bias_rate) * max8(s, -BOTH(p[q].push_depth)), splat8(-push)));
      ms[q] = blend8(speculative, one, BOTH(mass_scale));
    } else {
      bias = blend8(speculative, s * inv_h, zero);
      ms[q] = one;
    }
    tb_f8 dvx, dvy;
    relative_velocity8(&arms[q], &A, &B, &dvx, &dvy);
    t[q] = dvx * nx + dvy * ny + bias;
    a[q] = BOTH(p[q].normal_impulse);
  }
  tb_f8 k11 = BOTH(k11), k12 = BOTH(k12), k22 = BOTH(k22);
  tb_i8 two = BOTH(block) > zero;
  tb_f8 r1 = t[0] - k11 * a[0] - k12 * a[1];
  tb_f8 r2 = t[1] - k12 * a[0] - k22 * a[1];
  tb_f8 x1 = a[0], x2 = a[1];
  tb_i8 none = (r1 >= zero) & (~two | (r2 >= zero));
  x1 = blend8(none, zero, x1);
  x2 = blend8(none, zero, x2);
  tb_f8 only2 = -ms[1] * BOTH(p[1].normal_mass) * r2;
  tb_i8 second = two & (only2 >= zero) & (r1 + k12 * only2 >= zero);
  x1 = blend8(second, zero, x1);
  x2 = blend8(second, only2, x2);
  tb_f8 only1 = -ms[0] * BOTH(p[0].normal_mass) * r1;
  tb_i8 first = (only1 >= zero) & (~two | (r2 + k12 * only1 >= zero));
  x1 = blend8(first, only1, x1);
  x2 = blend8(first, zero, x2);
  tb_f8 both1 = -ms[0] * (BOTH(n11) * r1 + BOTH(n12) * r2), both2 = -ms[1] * (BOTH(n12) * r1 + BOTH(n22) * r2);
  tb_i8 both = two & (both1 >= zero) & (both2 >= zero);
  x1 = blend8(both, both1, x1);
  x2 = blend8(both, both2, x2);
  tb_f8 x[2] = {x1, x2}, d[2];
  for (int q = 0; q < 2; ++q) {
    STORE(p[q].normal_impulse, x[q]);
    d[q] = x[q] - a[q];
    apply8(ma, ja, mb, jb, &arms[q], d[q] * nx, d[q] * ny, &A, &B);
    if (c0->bouncy | c1->bouncy) { /* count_normal, in the blocks that bounce */
      wide_arms now[2] = {
          {low_half(arms[q].rax), low_half(arms[q].ray), low_half(arms[q].rbx), low_half(arms[q].rby)},
          {high_half(arms[q].rax), high_half(arms[q].ray), high_half(arms[q].rbx), high_half(arms[q].rby)}};
      tb_f4 step[2] = {low_half(d[q]), high_half(d[q])}, total[2] = {low_half(x[q]), high_half(x[q])};
      tb_wide_contact* half[2] = {c0, c1};
      for (int h = 0; h < 2; ++h)
        if (half[h]->bouncy) {
          tb_wide_record* r = &extra_of(half[h])->q[q];
          count_normal(r, &now[h], step[h]);
          r->max_normal_impulse = max4(r->max_normal_impulse, total[h]);
        }
    }
  }
  tb_f8 normal_change = max8(max8(d[0], -d[0]) * k11, max8(d[1], -d[1]) * k22);
  if (!use_bias) *change = max8(*change, normal_change);
  tb_f8 f[2], tx = ny, ty = -nx, tangent_speed = BOTH(tangent_speed), friction = BOTH(friction);
  for (int q = 0; q < 2; ++q) { /* solve_friction */
    tb_f8 dvx, dvy;
    relative_velocity8(&arms[q], &A, &B, &dvx, &dvy);
    tb_f8 vt = dvx * tx + dvy * ty;
    tb_f8 impulse = -BOTH(p[q].tangent_mass) * (vt - tangent_speed);
    tb_f8 limit = friction * x[q], held = BOTH(p[q].tangent_impulse);
    tb_f8 total = min8(max8(held + impulse, -limit), limit);
    impulse = total - held;
    STORE(p[q].tangent_impulse, total);
    apply8(ma, ja, mb, jb, &arms[q], impulse * tx, impulse * ty, &A, &B);
    f[q] = impulse;
  }
  if (record) {
    tb_f8 moved = max8(normal_change, max8(max8(f[0], -f[0]) * k11, max8(f[1], -f[1]) * k22));
    tb_i8 noted = moved > splat8(TB_RELAX_TOLERANCE);
    note_lanes(ctx, c0, low_mask(noted));
    note_lanes(ctx, c1, high_mask(noted));
  }
  if (c0->rolling | c1->rolling) { /* in the blocks that roll, as solve_wide, each half on its own */
    tb_wide_contact* half[2] = {c0, c1};
    tb_f4 aw[2] = {low_half(A.w), high_half(A.w)}, bw[2] = {low_half(B.w), high_half(B.w)};
    tb_f4 load[2] = {low_half(x1 + x2), high_half(x1 + x2)};
    for (int h = 0; h < 2; ++h) {
      if (!half[h]->rolling) continue;
      tb_wide_extra* e = extra_of(half[h]);
      tb_f4 limit = e->rolling_resistance * load[h];
      tb_f4 impulse = -e->rolling_mass * (bw[h] - aw[h]);
      tb_f4 total = min4(max4(e->rolling_impulse + impulse, -limit), limit);
      impulse = total - e->rolling_impulse;
      e->rolling_impulse = total;
      aw[h] -= half[h]->ja * impulse;
      bw[h] += half[h]->jb * impulse;
    }
    A.w = join(aw[0], aw[1]);
    B.w = join(bw[0], bw[1]);
  }
  scatter8(states, c0->a, c1->a, &A);
  scatter8(states, c0->b, c1->b, &B);
#undef BOTH
#undef STORE
}

/* warm_start_wide for blocks c0 and c1 of one colour */
static AVX2 void warm_start_pair(tb_wide_contact* c0, tb_wide_contact* c1, tb_solver_body* states) {
  wide_body8 A = gather8(states, c0->a, c1->a), B = gather8(states, c0->b, c1->b);
  tb_f8 nx = join(c0->nx, c1->nx), ny = join(c0->ny, c1->ny), tx = ny, ty = -nx;
  tb_f8 ma = join(c0->ma, c1->ma), ja = join(c0->ja, c1->ja), mb = join(c0->mb, c1->mb), jb = join(c0->jb, c1->jb);
  for (int q = 0; q < 2; ++q) {
    const tb_wide_point *p0 = &c0->p[q], *p1 = &c1->p[q];
    wide_arms8 arms = {join(p0->now_rax, p1->now_rax), join(p0->now_ray, p1->now_ray), join(p0->now_rbx, p1->now_rbx),
                       join(p0->now_rby, p1->now_rby)};
    if (c0->bouncy)
      count_normal(&extra_of(c0)->q[q], &(wide_arms){p0->now_rax, p0->now_ray, p0->now_rbx, p0->now_rby},
                   p0->normal_impulse);
    if (c1->bouncy)
      count_normal(&extra_of(c1)->q[q], &(wide_arms){p1->now_rax, p1->now_ray, p1->now_rbx, p1->now_rby},
                   p1->normal_impulse);
    tb_f8 normal = join(p0->normal_impulse, p1->normal_impulse),
          tangent = join(p0->tangent_impulse, p1->tangent_impulse);
    tb_f8 Px = normal * nx + tangent * tx;
    tb_f8 Py = normal * ny + tangent * ty;
    apply8(ma, ja, mb, jb, &arms, Px, Py, &A, &B);
  }
  if (c0->rolling | c1->rolling) {
    /* (a block without rolling resistance holds no rolling impulse) */
    tb_f4 none = splat(0.0f);
    tb_f8 rolling =
        join(c0->rolling ? extra_of(c0)->rolling_impulse : none, c1->rolling ? extra_of(c1)->rolling_impulse : none);
    A.w -= ja * rolling;
    B.w += jb * rolling;
  }
  scatter8(states, c0->a, c1->a, &A);
  scatter8(states, c0->b, c1->b, &B);
}

static AVX2 void warm_start_pairs(tb_wide_contact* wide, int count, tb_solver_body* states) {
  for (int b = 0; b < count; ++b)
    if (wide[b].pair == 1)
      warm_start_pair(&wide[b], &wide[b + 1], states), ++b;
    else
      warm_start_wide(&wide[b], states);
}

/* What solve_wide does before its normal targets where it does not read
 * the stored separations: the separations at the positions now, and in the
 * first pass after a position update (measure) the arms and the slides. */
AVX2_INLINE void separations_now(tb_wide_contact* c, const tb_step_context* ctx, bool measure) {
  wide_body A = gather(ctx->states, c->a), B = gather(ctx->states, c->b);
  if (measure) {
    refresh_arms(c, &A, &B);
    measure_slide(c, ctx, &A, &B);
  }
  for (int q = 0; q < 2; ++q)
    c->p[q].separation = normal_motion(c, &cold_of(c)->q[q], &A, &B) + cold_of(c)->q[q].base_separation;
}

/* One group's sweep, pairs eight lanes at a time. stored: the pass reads the
 * stored separations (else a pair measures them first, measure as in
 * solve_wide); skip: a later relax pass, which solves only blocks with a
 * body that still moves, each half of a pair as its own block would be. */
AVX2_INLINE void sweep_pairs(tb_wide_contact* wide, int lo, int hi, bool backward, tb_step_context* ctx, bool use_bias,
                             bool stored, bool measure, bool skip, tb_f4* change) {
  tb_f8 change8 = splat8(0.0f);
  int step = backward ? -1 : 1;
  bool record = skip || measure;
  for (int i = lo, b = backward ? hi - 1 : lo; i < hi; ++i, b += step) {
    tb_wide_contact* c = &wide[b];
    bool paired = c->pair == step; /* its partner is the next block of the sweep */
    tb_wide_contact* partner = paired ? &wide[b + step] : NULL;
    if (paired) ++i, b += step;
    if (!skip) {
      if (paired) {
        if (!stored) {
          separations_now(c, ctx, measure);
          separations_now(partner, ctx, measure);
        }
        solve_pair(c, partner, ctx, use_bias, record, &change8);
      } else {
        solve_wide(c, ctx, use_bias, measure, stored, record, change);
      }
      continue;
    }
    bool on = tb_relax_lanes_active(ctx, c->a, c->b);
    bool partner_on = paired && tb_relax_lanes_active(ctx, partner->a, partner->b);
    ctx->relax_solved += (int)on + (int)partner_on;
    if (on && partner_on)
      solve_pair(c, partner, ctx, false, true, &change8);
    else if (on)
      solve_wide(c, ctx, false, false, true, true, change);
    else if (partner_on)
      solve_wide(partner, ctx, false, false, true, true, change);
  }
  *change = max4(max4(*change, low_half(change8)), high_half(change8));
}

/* The pass kinds of tb_contact_solver_solve, each a copy of its own. */
static AVX2 void sweep_pairs_by_kind(tb_wide_contact* wide, int lo, int hi, bool backward, tb_step_context* ctx,
                                     bool use_bias, bool stored, bool measure, tb_f4* change) {
  if (use_bias && stored)
    sweep_pairs(wide, lo, hi, backward, ctx, true, true, false, false, change);
  else if (use_bias)
    sweep_pairs(wide, lo, hi, backward, ctx, true, false, false, false, change);
  else if (measure)
    sweep_pairs(wide, lo, hi, backward, ctx, false, false, true, false, change);
  else if (ctx->relax_all)
    sweep_pairs(wide, lo, hi, backward, ctx, false, true, false, false, change);
  else
    sweep_pairs(wide, lo, hi, backward, ctx, false, true, false, true, change);
}

static bool eight_lanes(void) { return __builtin_cpu_supports("avx2"); }
#else
static bool eight_lanes(void) { return false; }
#endif

bool tb_contact_solver_eight_lanes(void) { return eight_lanes(); }

/* ---- deep overlap push-out ----------------------------------------------------- */

/* Copies what the push-out's sweeps read of a group's lanes out of their
 * blocks, and into base_separation and push_depth what its targets are
 * computed from. */
static void load_deep(tb_deep_block* d, const tb_wide_contact* wide, tb_f4 base_separation[2], tb_f4 push_depth[2]) {
  for (int k = 0; k < 4 && d->block[k] >= 0; ++k) {
    const tb_wide_contact* c = &wide[d->block[k]];
    int lane = d->lane[k];
    d->two[k] = c->block[lane] > 0.0f ? -1 : 0;
    d->nx[k] = c->nx[lane];
    d->ny[k] = c->ny[lane];
    d->ma[k] = c->ma[lane];
    d->ja[k] = c->ja[lane];
    d->mb[k] = c->mb[lane];
    d->jb[k] = c->jb[lane];
    d->k11[k] = c->k11[lane];
    d->k12[k] = c->k12[lane];
    d->k22[k] = c->k22[lane];
    d->n11[k] = c->n11[lane];
    d->n12[k] = c->n12[lane];
    d->n22[k] = c->n22[lane];
    for (int p = 0; p < 2; ++p) {
      d->rax[p][k] = cold_of(c)->q[p].rax[lane];
      d->ray[p][k] = cold_of(c)->q[p].ray[lane];
      d->rbx[p][k] = cold_of(c)->q[p].rbx[lane];
      d->rby[p][k] = cold_of(c)->q[p].rby[lane];
      base_separation[p][k] = cold_of(c)->q[p].base_separation[lane];
      push_depth[p][k] = c->p[p].push_depth[lane];
      d->normal_mass[p][k] = c->p[p].normal_mass[lane];
    }
  }
}

/* The push velocities (x, y, angle) of four bodies, a row of four floats each. */
typedef struct wide_push {
  tb_f4 x, y, w, unused;
} wide_push;

static inline wide_push gather_push(const float* u, const int32_t* idx) {
  tb_f4 m[4];
  for (int k = 0; k < 4; ++k) memcpy(&m[k], &u[4 * idx[k]], sizeof m[k]);
  transpose(m);
  return (wide_push){m[0], m[1], m[2], m[3]};
}

static inline void scatter_push(float* u, const int32_t* idx, const wide_push* p) {
  tb_f4 m[4] = {p->x, p->y, p->w, p->unused};
  transpose(m);
  for (int k = 0; k < 4; ++k) memcpy(&u[4 * idx[k]], &m[k], sizeof m[k]);
}

/* The push velocity of B relative to A at a point, along n. */
static inline tb_f4 push_speed(const wide_push* ua, const wide_push* ub, tb_f4 rax, tb_f4 ray, tb_f4 rbx, tb_f4 rby,
                               tb_f4 nx, tb_f4 ny) {
  tb_f4 dux = (ub->x + -ub->w * rby) - (ua->x + -ua->w * ray);
  tb_f4 duy = (ub->y + ub->w * rbx) - (ua->y + ua->w * rax);
  return dux * nx + duy * ny;
}

/* Split impulse (Catto, GDC 2006; Bullet): each deep point is pushed apart in
 * velocities of its own, u, that move the bodies in this substep's position
 * update and are then dropped, so the push leaves no momentum. The velocity
 * solve's soft push would: its impulse is real, and in a pile the relative
 * pushes add up body by body (a fifth box up a column rises at five times
 * the cap) faster than the one relax sweep takes them back out. The target is
 * the share TB_PUSH_OUT_RATE of the depth beyond the push depth per substep,
 * at most contact_push_max_velocity apart, with impulses >= 0 (Gauss-Seidel,
 * accumulated over the sweeps of one substep; a group's four lanes at once). */
void tb_contact_solver_push_out(tb_world* w, tb_step_context* ctx) {
  if (!ctx->push_velocities) return;
  float* u = ctx->push_velocities;
  memset(u, 0, (size_t)(4 * (ctx->static_index + 1)) * sizeof(float));
  tb_deep_block* deep = (tb_deep_block*)w->deep_contacts;
  const tb_wide_contact* wide = (const tb_wide_contact*)w->wide;
  const tb_solver_body* states = ctx->states;
  const tb_f4 zero = splat(0.0f), push = splat(ctx->contact_push_max_velocity);
  const tb_f4 rate = splat(TB_PUSH_OUT_RATE * ctx->inv_h);
  /* The targets depend on the positions, which the sweeps do not move (they
   * move the push velocities u): once per substep, not once per sweep. */
  for (int i = 0; i < w->deep_count; ++i) {
    tb_deep_block* d = &deep[i];
    tb_f4 base_separation[2] = {zero, zero}, push_depth[2] = {zero, zero}; /* unused lanes stay 0 */
    load_deep(d, wide, base_separation, push_depth); /* the base separations move with the slides */
    d->impulse[0] = d->impulse[1] = zero;
    tb_f4 m[4];
    load_rows(states, d->a, 1, m); /* (inv_inertia, da, dp.x, dp.y) */
    tb_f4 da_a = m[1], dpx_a = m[2], dpy_a = m[3];
    load_rows(states, d->b, 1, m);
    tb_f4 da_b = m[1], dpx_b = m[2], dpy_b = m[3];
    for (int p = 0; p < 2; ++p) {
      tb_f4 rax = d->rax[p], ray = d->ray[p], rbx = d->rbx[p], rby = d->rby[p];
      /* the separation now, to first order in the angles (as normal_target) */
      tb_f4 mx = (dpx_b + -da_b * rby) - (dpx_a + -da_a * ray);
      tb_f4 my = (dpy_b + da_b * rbx) - (dpy_a + da_a * rax);
      tb_f4 sep = base_separation[p] + (mx * d->nx + my * d->ny);
      d->target[p] = min4(rate * max4(-push_depth[p] - sep, zero), push);
    }
  }
  for (int sweep = 0; sweep < TB_PUSH_OUT_SWEEPS; ++sweep)
    for (int i = 0; i < w->deep_count; ++i) {
      tb_deep_block* d = &deep[i];
      wide_push ua = gather_push(u, d->a), ub = gather_push(u, d->b);
      tb_f4 nx = d->nx, ny = d->ny;
      /* r = (push speed without this contact's impulses) - target; an inert
       * second point (no mass) gets r = 0 and never moves */
      tb_f4 r[2];
      for (int p = 0; p < 2; ++p)
        r[p] = blend(d->normal_mass[p] > zero,
                     push_speed(&ua, &ub, d->rax[p], d->ray[p], d->rbx[p], d->rby[p], nx, ny) - d->target[p], zero);
      tb_f4* acc = d->impulse;
      r[0] -= d->k11 * acc[0] + d->k12 * acc[1];
      r[1] -= d->k12 * acc[0] + d->k22 * acc[1];
      /* the mixed LCP x >= 0, K x + r >= 0, complementary, as solve_wide:
       * both points; else only the first; else only the second; else none */
      tb_f4 both0 = -(d->n11 * r[0] + d->n12 * r[1]), both1 = -(d->n12 * r[0] + d->n22 * r[1]);
      tb_f4 only0 = -r[0] / d->k11, only1 = -r[1] / d->k22;
      tb_i4 second = (only1 >= zero) & (r[0] + d->k12 * only1 >= zero);
      tb_i4 first = (only0 >= zero) & (r[1] + d->k12 * only0 >= zero);
      tb_i4 both = (both0 >= zero) & (both1 >= zero);
      tb_f4 x0 = blend(both, both0, blend(first, only0, zero));
      tb_f4 x1 = blend(both, both1, blend(first, zero, blend(second, only1, zero)));
      /* one point, or two too close together: one after the other */
      tb_f4 one0 = blend(d->normal_mass[0] > zero, max4(-d->normal_mass[0] * (r[0] + zero), zero), zero);
      tb_f4 one1 = blend(d->normal_mass[1] > zero, max4(-d->normal_mass[1] * (r[1] + d->k12 * one0), zero), zero);
      x0 = blend(d->two, x0, one0);
      x1 = blend(d->two, x1, one1);
      tb_f4 x[2] = {x0, x1};
      for (int p = 0; p < 2; ++p) {
        tb_f4 step = x[p] - acc[p];
        tb_f4 px = step * nx, py = step * ny;
        acc[p] = x[p];
        ua.x -= d->ma * px;
        ua.y -= d->ma * py;
        ua.w -= d->ja * (d->rax[p] * py - d->ray[p] * px);
        ub.x += d->mb * px;
        ub.y += d->mb * py;
        ub.w += d->jb * (d->rbx[p] * py - d->rby[p] * px);
      }
      scatter_push(u, d->a, &ua);
      scatter_push(u, d->b, &ub);
    }
}

/* ---- entry points ----------------------------------------------------------------- */

void tb_contact_solver_warm_start(tb_world* w, tb_step_context* ctx) {
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
#if defined(TB_EIGHT_LANES)
  if (!ctx->four_lanes && eight_lanes()) {
    warm_start_pairs(wide, w->wide_count, ctx->states);
    return;
  }
#endif
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
    if (wide[b].rolling) extra_of(&wide[b])->rolling_impulse = zero;
  }
}

/* A pass solves the blocks of contacts between two moving bodies, then
 * those with a body that does not move (from wide_fixed_from on), each group
 * in the pass's direction. Within one Gauss-Seidel pass the contact solved last
 * has the last word on a body's speed. Solved before a contact that loads
 * the body, a contact with the static world was undone by it: a heavy box
 * (0.25 kg) knocked down at 1.2 m/s onto a light one (0.01 kg) on a 1 cm
 * floor gave the light one its own speed into the floor after the floor's
 * contact had stopped it, and with one substep the position update carried
 * it 2 cm into the floor in one step, 5.5 cm in four: past the point where
 * the floor's normal flips, which then pushed it out below. Solved last, the
 * floor's contact stops the light box, and what the heavy one still closes
 * goes into the contact between the two boxes, which can push both apart
 * again; the static world cannot move out of the way. */
float tb_contact_solver_solve(tb_world* w, tb_step_context* ctx, bool use_bias, bool backward) {
  if (w->wide_count == 0) return 0.0f; /* (a world in free flight calls this twice a substep) */
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  tb_f4 change = splat(0.0f);
  int n = w->wide_count, fixed_from = w->wide_fixed_from;
  /* The patches are measured in the first pass after a position update (the
   * first relax pass); the biased pass of the next substep sees the same
   * positions, and the first substep's the step start, where every contact
   * is within its patch. */
  bool measure = !use_bias && ctx->bodies_moved;
  if (measure) ctx->bodies_moved = false;
  /* The separations measured there hold until the next position update: for
   * the later relax passes and the next substep's biased pass (only velocities
   * change in between). The first substep's biased pass computes its own. */
  bool stored = !measure && ctx->position_updates > 0;
  bool pairs = !ctx->four_lanes && eight_lanes();
  /* one loop per pass kind, each with solve_wide specialised for it */
  for (int group = 0; group < 2; ++group) {
    int lo = group == 0 ? 0 : fixed_from, hi = group == 0 ? fixed_from : n;
    if (lo == hi) continue; /* (a small scene has one of the two) */
    int first = backward ? hi - 1 : lo, step = backward ? -1 : 1;
#if defined(TB_EIGHT_LANES)
    if (pairs) {
      sweep_pairs_by_kind(wide, lo, hi, backward, ctx, use_bias, stored, measure, &change);
      continue;
    }
#endif
    if (use_bias && stored)
      for (int i = lo, b = first; i < hi; ++i, b += step) solve_wide(&wide[b], ctx, true, false, true, false, &change);
    else if (use_bias)
      for (int i = lo, b = first; i < hi; ++i, b += step) solve_wide(&wide[b], ctx, true, false, false, false, &change);
    else if (measure)
      for (int i = lo, b = first; i < hi; ++i, b += step) solve_wide(&wide[b], ctx, false, true, false, true, &change);
    else if (ctx->relax_all)
      for (int i = lo, b = first; i < hi; ++i, b += step) solve_wide(&wide[b], ctx, false, false, true, false, &change);
    else /* a later relax pass: only blocks with a body that still moves */
      for (int i = lo, b = first; i < hi; ++i, b += step)
        if (tb_relax_lanes_active(ctx, wide[b].a, wide[b].b)) {
          solve_wide(&wide[b], ctx, false, false, true, true, &change);
          ctx->relax_solved += 1;
        }
  }
  return max_lane(change);
}

#define TB_RESTITUTION_PASSES 16
#define TB_RESTITUTION_TOLERANCE tb_meters(1e-5f) /* m/s, as the relax passes' stop */

/* K = J M^-1 J^T of a point's normal impulse at arms ra, rb */
static float normal_k(const tb_wide_contact* wc, int lane, tb_vec2 ra, tb_vec2 rb) {
  tb_vec2 n = {wc->nx[lane], wc->ny[lane]};
  float rna = tb_cross(ra, n), rnb = tb_cross(rb, n);
  return wc->ma[lane] + wc->mb[lane] + wc->ja[lane] * rna * rna + wc->jb[lane] * rnb * rnb;
}

/* The arms of a point now (stored by refresh_arms), and their K. */
static float arms_at(const tb_wide_contact* wc, const tb_wide_point* cp, int lane, tb_vec2* ra, tb_vec2* rb) {
  *ra = (tb_vec2){cp->now_rax[lane], cp->now_ray[lane]};
  *rb = (tb_vec2){cp->now_rbx[lane], cp->now_rby[lane]};
  return normal_k(wc, lane, *ra, *rb);
}

static float normal_speed(const tb_solver_body* sa, const tb_solver_body* sb, tb_vec2 ra, tb_vec2 rb, tb_vec2 n) {
  return tb_dot(tb_sub(tb_add(sb->v, tb_cross_sv(sb->w, rb)), tb_add(sa->v, tb_cross_sv(sa->w, ra))), n);
}

/* Each point's normal speed after the bounce, from the velocities after the
 * substeps (before any restitution impulse). The impulses of the substeps
 * acted along J_e, at the impulse-weighted mean of the arms they were applied
 * at; the bounce acts along J, at the common point now (so that it turns
 * nothing). Newton's rule at J_e, v_n' = -e before with before the step
 * start's approach seen there (J v is affine in the arms),
 *   before = J_e v0 = v_n0 + n . (w_B0 x (r_Be - r_B0) - w_A0 x (r_Ae - r_A0)),
 * would add the energy ((e before)^2 - vn_e^2) / (2 k_e); the bounce along J
 * adds the same when it reaches
 *   v_n'^2 = vn^2 + (k / k_e) ((e before)^2 - vn_e^2)
 * (vn, k: normal speed and K along J; vn_e, k_e along J_e). Without drift
 * (J = J_e) this is Newton's rule itself; with it, a frictionless e = 1
 * impact of bodies sliding past each other keeps its energy (Newton's rule
 * with the approach at J lost 2.6%; the bounce along J_e turned the bodies).
 * The arms of the substeps lie within the shift limit of the step start's
 * on each axis (arms_now), and so does any mean of them with weights >= 0;
 * but the passes' corrections are signed, and where they nearly cancel (a
 * ball pressed into a wall and pulled back off it within the step) their
 * mean ran off to metres: elastic_balls' before came out at -308 m/s and the
 * ball between that wall and another left the step 5.8 J richer. The mean is
 * kept within that box. */
static inline tb_vec2 within_shift(tb_vec2 r, tb_vec2 r0, float limit) {
  return (tb_vec2){tb_minf(tb_maxf(r.x, r0.x - limit), r0.x + limit),
                   tb_minf(tb_maxf(r.y, r0.y - limit), r0.y + limit)};
}

static int restitution_targets(const tb_contact_constraint* cc, const tb_wide_contact* wc, const tb_solver_body* states,
                               float threshold, tb_bounce* out) {
  int lane = cc->lane % 4, count = 0;
  const tb_solver_body* sa = &states[wc->a[lane]];
  const tb_solver_body* sb = &states[wc->b[lane]];
  tb_vec2 n = {wc->nx[lane], wc->ny[lane]};
  for (int p = 0; p < cc->point_count; ++p) {
    const tb_wide_point* cp = &wc->p[p];
    const tb_wide_record* cq = &extra_of(wc)->q[p];
    if (cq->max_normal_impulse[lane] == 0.0f || !(cp->normal_mass[lane] > 0.0f)) continue;
    const tb_wide_anchor* anchor = &cold_of(wc)->q[p];
    tb_vec2 ra0 = {anchor->rax[lane], anchor->ray[lane]}, rb0 = {anchor->rbx[lane], anchor->rby[lane]};
    float applied = cq->applied[lane];
    tb_vec2 rea = ra0, reb = rb0;
    if (applied > 0.0f) {
      float limit = cold_of(wc)->shift_limit[lane];
      rea = within_shift(tb_scale(1.0f / applied, (tb_vec2){cq->applied_rax[lane], cq->applied_ray[lane]}), ra0, limit);
      reb = within_shift(tb_scale(1.0f / applied, (tb_vec2){cq->applied_rbx[lane], cq->applied_rby[lane]}), rb0, limit);
    }
    float before = cc->relative_velocity[p] + tb_dot(n, tb_sub(tb_cross_sv(cc->spin_b, tb_sub(reb, rb0)),
                                                               tb_cross_sv(cc->spin_a, tb_sub(rea, ra0))));
    if (fabsf(before) < threshold) continue;
    tb_vec2 ra, rb;
    float k = arms_at(wc, cp, lane, &ra, &rb), k_e = normal_k(wc, lane, rea, reb);
    float vn = normal_speed(sa, sb, ra, rb, n), vn_e = normal_speed(sa, sb, rea, reb, n);
    float eb = cc->restitution * before;
    float target = sqrtf(tb_maxf(vn * vn + k / k_e * (eb * eb - vn_e * vn_e), 0.0f));
    out[count++] = (tb_bounce){.a = wc->a[lane],
                               .b = wc->b[lane],
                               .nx = n.x,
                               .ny = n.y,
                               .ma = wc->ma[lane],
                               .ja = wc->ja[lane],
                               .mb = wc->mb[lane],
                               .jb = wc->jb[lane],
                               .rax = ra.x,
                               .ray = ra.y,
                               .rbx = rb.x,
                               .rby = rb.y,
                               .k = k,
                               /* struck from behind: it approaches at e before */
                               .target = before > 0.0f ? -target : target,
                               .impulse = cp->normal_impulse[lane]};
  }
  return count;
}

/* Newton's restitution on the points that pushed during the step:
 * v_n' = -e v_n(before), with v_n(before) the normal speed at the step start
 * (as restitution_targets corrects it for the drift of the arms).
 * Points whose speed was below the threshold either way are left alone: slow
 * approaches do not bounce. A point that was separating at the step start
 * and pushed all the same was struck from behind within the step (a ball
 * knocked into a wall it was leaving): it takes the same rule, which lets it
 * approach at e v_n(before). With the rule at every point that pushed, e = 1
 * turns the step-start velocities into their reflection off the contacts
 * (in the mass metric), which keeps the kinetic energy and the momentum;
 * leaving such a point out let its neighbour's bounce drive the struck body
 * through it unopposed, after the substeps had stopped it inelastically.
 * One bouncing point (tb_bounce); returns the normal speed change it made. */
static float apply_restitution(tb_bounce* r, tb_solver_body* states) {
  tb_solver_body* sa = &states[r->a];
  tb_solver_body* sb = &states[r->b];
  tb_vec2 n = {r->nx, r->ny}, ra = {r->rax, r->ray}, rb = {r->rbx, r->rby};
  float impulse = (r->target - normal_speed(sa, sb, ra, rb, n)) / r->k;
  float total = tb_maxf(r->impulse + impulse, 0.0f);
  impulse = total - r->impulse;
  r->impulse = total;
  tb_vec2 P = tb_scale(impulse, n);
  sa->v = tb_mul_add(sa->v, -r->ma, P);
  sa->w -= r->ja * tb_cross(ra, P);
  sb->v = tb_mul_add(sb->v, r->mb, P);
  sb->w += r->jb * tb_cross(rb, P);
  return fabsf(impulse) * r->k;
}

void tb_contact_solver_finish(tb_world* w, tb_step_context* ctx) {
  tb_contact_constraint* cs = constraints(w);
  tb_wide_contact* wide = (tb_wide_contact*)w->wide;
  /* Restitution is iterated like the velocity solve: a ball that strikes two
   * others at once (or a row of touching balls) only bounces off all of them
   * with e when each contact sees the others' impulses; one pass would leave
   * the first contact's bounce undone by the second and lose energy. A
   * struck row next to a heavy body (balls against a wall) converges slowly:
   * up to TB_RESTITUTION_PASSES, stopping once no point's speed changes by
   * more than TB_RESTITUTION_TOLERANCE (one pass for lone contacts). */
  bool bouncy = false; /* most scenes have no restitution: one look instead of the passes */
  for (int k = 0; k < w->step_contact_count; ++k) bouncy |= cs[k].restitution != 0.0f;
  /* The passes visit only the points that bounce, copied in step order: in a
   * churning pile most contacts have restitution but few approach faster than
   * the threshold (spinner: 2,900 of 14,400, with all 16 passes a step). Out
   * of memory, the points not copied do not bounce this step (the step
   * reports it). */
  tb_bounce* bounces = (tb_bounce*)w->bounces;
  int count = 0;
  for (int k = 0; bouncy && k < w->step_contact_count; ++k) {
    if (cs[k].restitution == 0.0f) continue;
    if (count + 2 > w->bounce_capacity) {
      if (!tb_array_reserve(&w->bounces, &w->bounce_capacity, count + 2, sizeof(tb_bounce))) break;
      bounces = (tb_bounce*)w->bounces;
    }
    count +=
        restitution_targets(&cs[k], &wide[cs[k].lane / 4], ctx->states, ctx->restitution_threshold, &bounces[count]);
  }
  for (int pass = 0; count > 0 && pass < TB_RESTITUTION_PASSES; ++pass) {
    float change = 0.0f;
    for (int i = 0; i < count; ++i) change = tb_maxf(change, apply_restitution(&bounces[i], ctx->states));
    if (change <= TB_RESTITUTION_TOLERANCE) break;
  }
  /* The lanes' accumulated impulses of the last substep are kept for the
   * next step's warm start, without the bounce: a bounce is an impulse of one
   * instant that the next step does not repeat, and warm started it pushed
   * the separating bodies apart again at the next step's start, which in a
   * row (a ball between two others) the neighbour's contact answered before
   * this one took the push back (elastic_balls' largest energy error over 41
   * perturbed starts 0.138, 0.062 without it; the rest was restitution's
   * mean arms, restitution_targets). The blocks are read in their order, and the contacts, all over the pool,
   * are only written: both points (a lane's second point, when its manifold
   * has one only, holds the zeros that the collision left there), so that no
   * read waits on a contact's record (in step order each lane's read waited
   * on its block, and a read of the point count on the record). */
  const int32_t* lane_contact = w->lane_contacts;
  int lanes = 4 * w->wide_count;
  for (int at = 0; at < lanes; ++at) {
    if (lane_contact[at] < 0) continue;
    const tb_wide_contact* wc = &wide[at / 4];
    int lane = at % 4;
    tb_contact* c = (tb_contact*)tb_pool_at(&w->contacts, w->step_contacts[lane_contact[at]]);
    for (int p = 0; p < 2; ++p) {
      c->manifold.points[p].normal_impulse = wc->p[p].normal_impulse[lane];
      c->manifold.points[p].tangent_impulse = wc->p[p].tangent_impulse[lane];
    }
    /* A block without rolling resistance changed no rolling impulse: prepare
     * took the contact's, which stays, or zero without warm starting. (Read
     * back to be stored again, the contact's value was a load from another
     * cache line of a record the loop only writes otherwise: 3% of
     * large_pyramid's samples waited on it.) */
    if (wc->rolling)
      c->rolling_impulse = extra_of(wc)->rolling_impulse[lane];
    else if (!ctx->enable_warm_starting)
      c->rolling_impulse = 0.0f;
  }
}

/* ---- memory ------------------------------------------------------------- */

size_t tb_contact_solver_bytes(const tb_world* w) {
  return (size_t)w->constraint_capacity * sizeof(tb_contact_constraint) +
         (size_t)w->color_capacity * sizeof *w->color_lanes + (size_t)w->degree_capacity +
         (size_t)w->lane_contact_capacity * sizeof *w->lane_contacts +
         (size_t)w->laid_out_capacity * sizeof *w->laid_out_contacts + (size_t)w->wide_capacity * BLOCK_BYTES +
         (size_t)w->deep_capacity * sizeof(tb_deep_block) + (size_t)w->bounce_capacity * sizeof(tb_bounce) +
         (size_t)w->push_capacity * sizeof *w->push_velocities;
}

void tb_contact_solver_free(tb_world* w) {
  tb_mem_free(w->constraints, (size_t)w->constraint_capacity * sizeof(tb_contact_constraint));
  tb_mem_free(w->color_lanes, (size_t)w->color_capacity * sizeof *w->color_lanes);
  tb_mem_free(w->lane_contacts, (size_t)w->lane_contact_capacity * sizeof *w->lane_contacts);
  tb_mem_free(w->laid_out_contacts, (size_t)w->laid_out_capacity * sizeof *w->laid_out_contacts);
  tb_mem_free(w->contact_degree, (size_t)w->degree_capacity);
  tb_mem_free(w->wide, (size_t)w->wide_capacity * BLOCK_BYTES);
  tb_mem_free(w->deep_contacts, (size_t)w->deep_capacity * sizeof(tb_deep_block));
  tb_mem_free(w->bounces, (size_t)w->bounce_capacity * sizeof(tb_bounce));
  tb_mem_free(w->push_velocities, (size_t)w->push_capacity * sizeof *w->push_velocities);
}
