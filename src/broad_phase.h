/* Broad phase: one AABB tree per body type (static, kinematic, dynamic) so the
 * static world is only ever walked on behalf of something that moved; a move
 * buffer of proxies re-inserted since the last pair update; and the set of
 * existing pairs. */
#ifndef TB_BROAD_PHASE_H
#define TB_BROAD_PHASE_H

#include <stdint.h>

#include "tree.h"

/* The largest fat AABB margin (a shape's own is an eighth of its half-extent,
 * broad_phase.c: shape_margin): a proxy moving less than its margin is not
 * re-inserted. 5 cm, Box2D v3's cap: at 10 cm the bodies of a falling column
 * 0.25 m apart paired with the ones above and below them (compounds: 23,600
 * pairs against 4,200 at 5 cm, 100 steps in), and every accuracy and stress
 * row is the same at either. */
#define TB_AABB_MARGIN 0.05f

/* What the pair query asks of each shape its box meets, by shape slot, kept
 * beside the trees: read from the shape records, each candidate was a cache
 * miss, and most candidates are a pair that exists or the other side of a
 * pair whose two proxies both moved. Set with the proxy; moved mirrors the
 * shape's in_move_buffer. */
typedef struct tb_proxy_key {
  int32_t body;  /* the shape's body slot */
  int32_t group; /* its filter's group_index */
  uint8_t tree;  /* which tree holds its proxy */
  uint8_t moved; /* queued in the move buffer */
} tb_proxy_key;

typedef struct tb_broad_phase {
  tb_tree trees[3]; /* indexed by tb_body_type */
  int* move_buffer; /* shape indices; -1 for a proxy destroyed since */
  int move_count, move_capacity;
  tb_proxy_key* keys; /* by shape slot: room for every slot of the shape pool plus those reserved */
  int key_capacity;
  /* open-addressing hash set of the shape pairs that have a contact: key (low
   * shape << 32 | high shape) + 1. Keys only: the pair query asks whether a
   * pair exists, never which contact it is (a second array for that cost
   * every found pair a second cache miss). */
  uint64_t* pair_keys; /* 0 = empty slot, UINT64_MAX = deleted */
  int pair_capacity, pair_count, pair_used;
} tb_broad_phase;

struct tb_world;

tb_result tb_broad_phase_init(tb_broad_phase* bp);
void tb_broad_phase_free(tb_broad_phase* bp);
/* Bytes held: the trees, the move buffer and the proxies' keys; the pair set. */
size_t tb_broad_phase_tree_bytes(const tb_broad_phase* bp);
size_t tb_broad_phase_pair_bytes(const tb_broad_phase* bp);
/* Proxies follow their shapes: create (and queue for pair finding), destroy,
 * and move (queued again only when given a new fat box). false when out of
 * memory. A move with enlarge keeps the proxy's place in its tree until
 * tb_broad_phase_rebuild (tb_tree_enlarge_proxy). */
bool tb_broad_phase_create_proxy(struct tb_world* w, int shape);
void tb_broad_phase_destroy_proxy(struct tb_world* w, int shape);
void tb_broad_phase_move_proxy(struct tb_world* w, int shape, tb_vec2 displacement, bool enlarge);
/* Rebuilds the parts of the trees that moves with enlarge marked. */
void tb_broad_phase_rebuild(struct tb_world* w);
/* Room for proxies more in one tree and in the move buffer, so that the
 * inserts (and queueing) that follow cannot fail; false when out of memory. */
bool tb_broad_phase_reserve(struct tb_world* w, tb_body_type tree, int proxies);
/* Before a shape (with its body at xf) enters the tree: its box must lie within
 * TB_MAX_LENGTH (a body that flew beyond keeps its last proxy) and room for
 * proxies is reserved, so the insert cannot fail half-way through a change.
 * Sets the error, naming fn, otherwise. */
struct tb_shape;
tb_result tb_broad_phase_prepare_insert(struct tb_world* w, const struct tb_shape* s, tb_transform xf,
                                        tb_body_type tree, int proxies, const char* fn);
/* Queue a proxy for pair finding without moving it (pairs that may exist anew,
 * e.g. after a joint that kept two bodies apart is gone). Never fails after
 * tb_broad_phase_reserve(w, tree, 1). */
bool tb_broad_phase_touch_proxy(struct tb_world* w, int shape);
/* The shape's category bits changed: update the tree and queue the proxy. */
bool tb_broad_phase_refilter_proxy(struct tb_world* w, int shape);
/* New contacts for the pairs of the queued proxies; clears the queue. */
void tb_broad_phase_update_pairs(struct tb_world* w);

bool tb_pair_exists(const tb_broad_phase* bp, int shape_a, int shape_b);
bool tb_pair_add(tb_broad_phase* bp, int shape_a, int shape_b);
void tb_pair_remove(tb_broad_phase* bp, int shape_a, int shape_b);

/* Filter bits and groups (see tb_filter in tumble.h). */
bool tb_filters_collide(tb_filter a, tb_filter b);

#endif
