/* Manifold reuse: a touching contact whose two bodies have barely moved
 * relative to each other since its manifold was collided keeps that manifold,
 * carried along with the bodies, instead of colliding again (the idea of Box2D
 * v3's contact recycling, with a tighter bound; see manifold_reuse.c). A
 * resting pile then skips its narrow phase. */
#ifndef TB_MANIFOLD_REUSE_H
#define TB_MANIFOLD_REUSE_H

#include <stdbool.h>

#include "tumble.h"

struct tb_body;

/* The manifold as collided, in A's frame (about A's centre of mass), and where
 * B was in that frame then. */
typedef struct tb_manifold_cache {
  tb_vec2 normal;          /* A's frame */
  tb_vec2 points[2];       /* midway points, A's frame, from A's centre of mass */
  float separation[2];     /* as collided */
  tb_vec2 relative_center; /* B's centre of mass in A's frame */
  tb_rot relative_rot;     /* B's rotation in A's frame */
  int point_count;         /* 0: nothing kept (not touching, or never collided) */
} tb_manifold_cache;

/* Keeps m (just collided at the bodies' present placements) for reuse. */
void tb_manifold_cache_store(tb_manifold_cache* cache, const tb_manifold* m, const struct tb_body* a,
                             const struct tb_body* b);

/* When B has moved by less than TB_REUSE_DISTANCE relative to A since the
 * cache was stored (at every point of B within its extent), writes the cached
 * manifold carried to the bodies' present placements into m (normal, points
 * and separations; ids and impulses are left as they are) and returns true. */
bool tb_manifold_cache_reuse(const tb_manifold_cache* cache, tb_manifold* m, const struct tb_body* a,
                             const struct tb_body* b);

#endif
