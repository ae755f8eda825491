/* Manifold reuse (see manifold_reuse.h).
 *
 * In A's frame (about its centre of mass) the collided manifold has a normal
 * n, midway points p_i and separations s_i; A's surface point of p_i is
 * p_i - s_i n / 2 and B's is b_i = p_i + s_i n / 2. A's point stays put in
 * A's frame; B's moves with B, whose centre went from c0 to c and which
 * turned by dq (B's rotation relative to A, now against then):
 *   b_i' = c + dq (b_i - c0),   d_i = b_i' - b_i.
 * Carried along, the point's separation is s_i + d_i . n and its midway point
 * p_i + d_i / 2, both exact for the two material points; the features stay
 * the same while they move by far less than their size. The manifold is
 * reused while every d_i plus the turn at the smaller body's extent,
 * |dq| min(extent_A, extent_B), stays below TB_REUSE_DISTANCE: a collision of
 * the moved bodies would give the same points to within that (a point of the
 * incident face is a vertex of one body; carried, it is a material point of B
 * that was there), the patch's ends move by less than that, and the solver
 * still follows the motion within each step. Box2D v3 recycles up to 10
 * linear slops and 11.5 degrees. Here 0.02 linear slops (0.1 mm): resting
 * piles reuse most manifolds (many_pyramids 99%, the still settling
 * large_pyramid 74%), while the stress
 * suite's most sensitive rows stay as they were (at 0.1 slops card_house's
 * top drifted 0.84 mm instead of 0.59 and mass_ratio_1000's plank slid 8.1 um
 * instead of 5.3; at 0.02, 0.59 mm and 2.9 um). Fast bodies (swept by
 * continuous collision) always collide. */
#include "manifold_reuse.h"

#include <math.h>

#include "body.h"
#include "math_internal.h"
#include "units.h"

#define TB_REUSE_DISTANCE (0.02f * tb_units.linear_slop)

/* B's rotation in A's frame. */
static tb_rot relative_rot(const tb_body* a, const tb_body* b) {
  tb_rot qa = a->transform.q, qb = b->transform.q;
  return (tb_rot){qa.c * qb.c + qa.s * qb.s, qa.c * qb.s - qa.s * qb.c};
}

void tb_manifold_cache_store(tb_manifold_cache* cache, const tb_manifold* m, const tb_body* a, const tb_body* b) {
  cache->point_count = 0;
  if (m->point_count == 0 || a->is_fast || b->is_fast) return;
  tb_rot qa = a->transform.q;
  cache->normal = tb_inv_rotate(qa, m->normal);
  for (int i = 0; i < m->point_count; ++i) {
    cache->points[i] = tb_inv_rotate(qa, tb_sub(m->points[i].point, a->center));
    cache->separation[i] = m->points[i].separation;
  }
  cache->relative_center = tb_inv_rotate(qa, tb_sub(b->center, a->center));
  cache->relative_rot = relative_rot(a, b);
  cache->point_count = m->point_count;
}

bool tb_manifold_cache_reuse(const tb_manifold_cache* cache, tb_manifold* m, const tb_body* a, const tb_body* b) {
  if (cache->point_count == 0 || cache->point_count != m->point_count || a->is_fast || b->is_fast) return false;
  tb_rot qa = a->transform.q, q = relative_rot(a, b);
  tb_vec2 center = tb_inv_rotate(qa, tb_sub(b->center, a->center));
  /* the turn since the collision: q against the stored angle */
  tb_rot q0 = cache->relative_rot;
  tb_rot dq = {q.c * q0.c + q.s * q0.s, q.s * q0.c - q.c * q0.s};
  float turn = fabsf(dq.s) + (dq.c < 0.0f ? 2.0f : 0.0f);
  float reach = tb_minf(a->max_extent, b->max_extent) * turn;
  tb_vec2 moved[2];
  for (int i = 0; i < cache->point_count; ++i) {
    tb_vec2 anchor = tb_mul_add(cache->points[i], 0.5f * cache->separation[i], cache->normal);
    tb_vec2 now = tb_add(center, tb_rotate(dq, tb_sub(anchor, cache->relative_center)));
    moved[i] = tb_sub(now, anchor);
    if (!(tb_length(moved[i]) + reach < TB_REUSE_DISTANCE)) return false;
  }
  m->normal = tb_rotate(qa, cache->normal);
  for (int i = 0; i < cache->point_count; ++i) {
    tb_manifold_point* p = &m->points[i];
    p->point = tb_add(a->center, tb_rotate(qa, tb_mul_add(cache->points[i], 0.5f, moved[i])));
    p->separation = cache->separation[i] + tb_dot(moved[i], cache->normal);
  }
  return true;
}
