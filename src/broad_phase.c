/* Broad phase: trees per body type, the move buffer and the pair set. */
#include "broad_phase.h"

#include <string.h>

#include "geometry.h"
#include "math_internal.h"
#include "memory.h"
#include "world.h"
#include "units.h"

tb_result tb_broad_phase_init(tb_broad_phase* bp) {
  memset(bp, 0, sizeof *bp);
  for (int i = 0; i < 3; ++i) {
    tb_result r = tb_tree_create(&bp->trees[i], tb_units.aabb_margin);
    if (r != TB_OK) return r;
  }
  return TB_OK;
}

void tb_broad_phase_free(tb_broad_phase* bp) {
  for (int i = 0; i < 3; ++i) tb_tree_destroy(&bp->trees[i]);
  tb_mem_free(bp->move_buffer, (size_t)bp->move_capacity * sizeof *bp->move_buffer);
  tb_mem_free(bp->keys, (size_t)bp->key_capacity * sizeof *bp->keys);
  tb_mem_free(bp->pair_keys, (size_t)bp->pair_capacity * sizeof *bp->pair_keys);
  memset(bp, 0, sizeof *bp);
}

size_t tb_broad_phase_tree_bytes(const tb_broad_phase* bp) {
  size_t bytes = (size_t)bp->move_capacity * sizeof *bp->move_buffer + (size_t)bp->key_capacity * sizeof *bp->keys;
  for (int i = 0; i < 3; ++i) bytes += tb_tree_bytes(&bp->trees[i]);
  return bytes;
}

size_t tb_broad_phase_pair_bytes(const tb_broad_phase* bp) { return (size_t)bp->pair_capacity * sizeof *bp->pair_keys; }

bool tb_filters_collide(tb_filter a, tb_filter b) {
  if (a.group_index == b.group_index && a.group_index != 0) return a.group_index > 0;
  return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

/* ---- pair set: open addressing with linear probing ---------------------- */

static uint64_t pair_key(int a, int b) {
  uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
  return ((uint64_t)lo << 32 | hi) + 1; /* + 1 keeps 0 free as the empty mark */
}

static uint32_t pair_hash(uint64_t key) {
  key ^= key >> 33; /* a 64-bit finaliser (murmur3's) */
  key *= 0xff51afd7ed558ccdull;
  key ^= key >> 33;
  return (uint32_t)key;
}

static const uint64_t DELETED = UINT64_MAX;

bool tb_pair_exists(const tb_broad_phase* bp, int a, int b) {
  if (bp->pair_capacity == 0) return false;
  uint64_t key = pair_key(a, b);
  uint32_t mask = (uint32_t)bp->pair_capacity - 1;
  for (uint32_t i = pair_hash(key) & mask;; i = (i + 1) & mask) {
    if (bp->pair_keys[i] == key) return true;
    if (bp->pair_keys[i] == 0) return false;
  }
}

static bool pair_rehash(tb_broad_phase* bp, int capacity) {
  uint64_t* keys = tb_mem_alloc((size_t)capacity * sizeof *keys);
  if (keys == NULL) return false;
  memset(keys, 0, (size_t)capacity * sizeof *keys);
  uint32_t mask = (uint32_t)capacity - 1;
  for (int i = 0; i < bp->pair_capacity; ++i) {
    uint64_t key = bp->pair_keys[i];
    if (key == 0 || key == DELETED) continue;
    uint32_t j = pair_hash(key) & mask;
    while (keys[j] != 0) j = (j + 1) & mask;
    keys[j] = key;
  }
  tb_mem_free(bp->pair_keys, (size_t)bp->pair_capacity * sizeof *bp->pair_keys);
  bp->pair_keys = keys;
  bp->pair_capacity = capacity;
  bp->pair_used = bp->pair_count;
  return true;
}

bool tb_pair_add(tb_broad_phase* bp, int a, int b) {
  /* keep the load (live + deleted slots) under 1/2 */
  if (2 * (bp->pair_used + 1) > bp->pair_capacity) {
    int cap = bp->pair_capacity < 64 ? 64 : bp->pair_capacity;
    if (4 * (bp->pair_count + 1) > cap) cap *= 2; /* else only clear deleted slots */
    if (!pair_rehash(bp, cap)) return false;
  }
  uint64_t key = pair_key(a, b);
  uint32_t mask = (uint32_t)bp->pair_capacity - 1;
  uint32_t i = pair_hash(key) & mask;
  while (bp->pair_keys[i] != 0 && bp->pair_keys[i] != DELETED) i = (i + 1) & mask;
  if (bp->pair_keys[i] == 0) bp->pair_used += 1;
  bp->pair_keys[i] = key;
  bp->pair_count += 1;
  return true;
}

void tb_pair_remove(tb_broad_phase* bp, int a, int b) {
  if (bp->pair_capacity == 0) return;
  uint64_t key = pair_key(a, b);
  uint32_t mask = (uint32_t)bp->pair_capacity - 1;
  for (uint32_t i = pair_hash(key) & mask; bp->pair_keys[i] != 0; i = (i + 1) & mask) {
    if (bp->pair_keys[i] == key) {
      bp->pair_keys[i] = DELETED;
      bp->pair_count -= 1;
      return;
    }
  }
}

/* ---- proxies ------------------------------------------------------------- */

static bool queue_move(tb_world* w, int shape_index) {
  tb_shape* s = tb_shape_at(w, shape_index);
  if (s->in_move_buffer) return true;
  tb_broad_phase* bp = &w->broad_phase;
  if (!tb_array_reserve((void**)&bp->move_buffer, &bp->move_capacity, bp->move_count + 1, sizeof(int))) return false;
  bp->move_buffer[bp->move_count++] = shape_index;
  s->in_move_buffer = true;
  bp->keys[shape_index].moved = 1;
  return true;
}

/* A shape's fat margin. A pair is found while the two fat boxes overlap, and
 * a contact needs its pair before the shapes come within the speculative
 * distance, where its manifold gets points: margins of at least that
 * distance on either side always have the pair in time (the boxes are
 * refreshed after every step; world.c stretches them a little along the
 * motion). More margin means fewer
 * re-insertions of a moving proxy but more pairs: a fixed 0.1 m gave small
 * shapes several times the pairs their contacts need (spinner: 2.5 times Box2D
 * v3's). So a moving shape's margin grows with its size, an eighth of its
 * half-extent, from the speculative distance up to aabb_margin (5 cm, as Box2D
 * v3's, which scales its margin by shape likewise); a static shape never
 * moves and keeps the speculative distance. */
static float shape_margin(const tb_shape* s, tb_body_type type) {
  float floor = tb_units.speculative_distance;
  if (type == TB_STATIC_BODY) return floor;
  tb_aabb local = tb_shape_geom_aabb(s, (tb_transform){{0.0f, 0.0f}, {1.0f, 0.0f}});
  float extent = 0.5f * tb_maxf(local.upper.x - local.lower.x, local.upper.y - local.lower.y);
  return tb_minf(tb_maxf(0.125f * extent, floor), tb_units.aabb_margin);
}

/* The shape's apart key in the trees (tb_tree_query_apart): what never pairs
 * with it, whatever else it is. Shapes of one negative group never collide
 * (tb_filters_collide), nor do shapes of one body (should_pair): the group when
 * it is negative, else the body (+1, so that 0 stays "none"). */
static int32_t apart_key(const tb_shape* s) { return s->filter.group_index < 0 ? s->filter.group_index : s->body + 1; }

bool tb_broad_phase_create_proxy(tb_world* w, int shape_index) {
  tb_shape* s = tb_shape_at(w, shape_index);
  const tb_body* b = tb_body_at(w, s->body);
  s->aabb = tb_shape_geom_aabb(s, b->transform);
  s->tree = (int)b->type;
  s->margin = shape_margin(s, b->type);
  w->broad_phase.keys[shape_index] =
      (tb_proxy_key){.body = s->body, .group = s->filter.group_index, .tree = (uint8_t)s->tree, .moved = 0};
  s->proxy = tb_tree_create_proxy_with_margin(&w->broad_phase.trees[s->tree], s->aabb, s->margin,
                                              s->filter.category_bits, apart_key(s), shape_index);
  if (s->proxy == TB_TREE_NULL) return false;
  s->fat_aabb = tb_tree_get_fat_aabb(&w->broad_phase.trees[s->tree], s->proxy);
  if (!queue_move(w, shape_index)) {
    tb_broad_phase_destroy_proxy(w, shape_index);
    return false;
  }
  return true;
}

bool tb_broad_phase_reserve(tb_world* w, tb_body_type tree, int proxies) {
  tb_broad_phase* bp = &w->broad_phase;
  /* a new shape takes a free slot of the pool or the next one past it */
  return tb_tree_reserve(&bp->trees[tree], proxies) &&
         tb_array_reserve((void**)&bp->move_buffer, &bp->move_capacity, bp->move_count + proxies, sizeof(int)) &&
         tb_array_reserve((void**)&bp->keys, &bp->key_capacity, w->shapes.capacity + proxies, sizeof *bp->keys);
}

tb_result tb_broad_phase_prepare_insert(tb_world* w, const tb_shape* s, tb_transform xf, tb_body_type tree, int proxies,
                                        const char* fn) {
  tb_aabb box = tb_shape_geom_aabb(s, xf);
  if (!tb_point_ok(box.lower) || !tb_point_ok(box.upper))
    return tb_fail(w, TB_ERR_INVALID_ARGUMENT,
                   "%s: the shape's box reaches beyond TB_MAX_LENGTH (body at (%g, %g)); move the body back first", fn,
                   (double)xf.p.x, (double)xf.p.y);
  if (!tb_broad_phase_reserve(w, tree, proxies))
    return tb_fail(w, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the broad phase", fn);
  return TB_OK;
}

bool tb_broad_phase_touch_proxy(tb_world* w, int shape_index) {
  if (tb_shape_at(w, shape_index)->proxy < 0) return true;
  return queue_move(w, shape_index);
}

bool tb_broad_phase_refilter_proxy(tb_world* w, int shape_index) {
  tb_shape* s = tb_shape_at(w, shape_index);
  if (s->proxy < 0) return true;
  (void)tb_tree_set_category_bits(&w->broad_phase.trees[s->tree], s->proxy, s->filter.category_bits);
  (void)tb_tree_set_apart_key(&w->broad_phase.trees[s->tree], s->proxy, apart_key(s));
  w->broad_phase.keys[shape_index].group = s->filter.group_index;
  return queue_move(w, shape_index);
}

void tb_broad_phase_destroy_proxy(tb_world* w, int shape_index) {
  tb_shape* s = tb_shape_at(w, shape_index);
  if (s->proxy < 0) return;
  tb_broad_phase* bp = &w->broad_phase;
  if (s->in_move_buffer) {
    for (int i = 0; i < bp->move_count; ++i)
      if (bp->move_buffer[i] == shape_index) bp->move_buffer[i] = -1;
    s->in_move_buffer = false;
    bp->keys[shape_index].moved = 0;
  }
  tb_tree_destroy_proxy(&bp->trees[s->tree], s->proxy);
  s->proxy = -1;
}

void tb_broad_phase_move_proxy(tb_world* w, int shape_index, tb_vec2 displacement, bool enlarge) {
  tb_shape* s = tb_shape_at(w, shape_index);
  if (s->proxy < 0) return;
  tb_tree* tree = &w->broad_phase.trees[s->tree];
  /* The stretch along the predicted motion (world.c) is the body's own,
   * not its motion relative to its neighbours, which the broad phase does not
   * know: uncapped, the boxes of a column falling as one (compounds, 0.25 m
   * apart at 40 m/s) reached into each other and paired every body with the
   * ones above and below it (24,000 pairs 300 steps in, against 14,700 capped
   * and Box2D v3's 15,100). Capped at the margin, pileup_1000's depth beyond
   * its force stays at 3.7 mm (6.4 mm without any stretch: its bound is 5). */
  displacement.x = tb_minf(tb_maxf(displacement.x, -s->margin), s->margin);
  displacement.y = tb_minf(tb_maxf(displacement.y, -s->margin), s->margin);
  bool moved = enlarge ? tb_tree_enlarge_proxy(tree, s->proxy, s->aabb, s->margin, displacement)
                       : tb_tree_move_proxy_with_margin(tree, s->proxy, s->aabb, s->margin, displacement);
  if (!moved) return; /* (the fat box is as it was) */
  s->fat_aabb = tb_tree_get_fat_aabb(tree, s->proxy);
  /* out of memory here only delays pair finding to the proxy's next move */
  (void)queue_move(w, shape_index);
}

void tb_broad_phase_rebuild(tb_world* w) {
  for (int t = 0; t < 3; ++t) tb_tree_rebuild_enlarged(&w->broad_phase.trees[t]);
}

/* ---- pair finding -------------------------------------------------------- */

typedef struct pair_query {
  tb_world* w;
  int shape;
  tb_proxy_key key; /* the shape's */
} pair_query;

/* Whether two shapes may have a contact, before any contact exists. */
static bool should_pair(tb_world* w, int ia, int ib) {
  const tb_shape* a = tb_shape_at(w, ia);
  const tb_shape* b = tb_shape_at(w, ib);
  if (a->body == b->body) return false;
  if (!tb_shape_types_collide(a->type, b->type)) return false;
  if (a->sensor && b->sensor) return false;
  if ((a->sensor && !b->enable_sensor_events) || (b->sensor && !a->enable_sensor_events)) return false;
  if (!tb_filters_collide(a->filter, b->filter)) return false;
  const tb_body* ba = tb_body_at(w, a->body);
  const tb_body* bb = tb_body_at(w, b->body);
  if (ba->type != TB_DYNAMIC_BODY && bb->type != TB_DYNAMIC_BODY) return false;
  if ((ba->joint_count > 0 && bb->joint_count > 0) && !tb_joints_allow_collision(w, a->body, b->body)) return false;
  if (w->custom_filter != NULL &&
      !w->custom_filter(tb_make_shape_id(w, ia), tb_make_shape_id(w, ib), w->custom_filter_context))
    return false;
  return true;
}

static bool pair_callback(int32_t proxy, int32_t other, void* context) {
  (void)proxy;
  pair_query* q = context;
  tb_world* w = q->w;
  if (other == q->shape) return true;
  /* The pair set's slot and the other shape's record are both cache misses
   * in a scene of thousands of shapes: ask for the slot first, so that the
   * two loads overlap. */
  const tb_broad_phase* bp = &w->broad_phase;
  if (bp->pair_capacity > 0)
    __builtin_prefetch(&bp->pair_keys[pair_hash(pair_key(q->shape, other)) & (uint32_t)(bp->pair_capacity - 1)]);
  /* both moved and in the same tree: the pair is found from both sides; take
   * it once, from the higher index, so the order of creation is fixed */
  const tb_proxy_key o = bp->keys[other], s = q->key;
  if (o.moved && o.tree == s.tree && other > q->shape) return true;
  /* Shapes of one body, or of one negative group (a ragdoll's limbs), never
   * pair (should_pair): asked first, they need no look-up in the pair set,
   * which misses the cache (rain's ragdolls found their own limbs in most of
   * their queries, every step). */
  if (o.body == s.body || (o.group < 0 && o.group == s.group)) return true;
  if (tb_pair_exists(bp, q->shape, other)) return true;
  if (!should_pair(w, q->shape, other)) return true;
  (void)tb_contact_create(w, q->shape, other); /* out of memory: retried when it moves again */
  return true;
}

void tb_broad_phase_update_pairs(tb_world* w) {
  tb_broad_phase* bp = &w->broad_phase;
  for (int i = 0; i < bp->move_count; ++i) {
    int shape_index = bp->move_buffer[i];
    if (shape_index < 0) continue;
    const tb_shape* s = tb_shape_at(w, shape_index);
    tb_aabb fat = s->fat_aabb;
    pair_query q = {w, shape_index, bp->keys[shape_index]};
    /* A dynamic proxy looks everywhere; others only among dynamic proxies.
     * Only proxies whose category the shape's mask takes can pair with it
     * (tb_filters_collide), and the trees skip the subtrees with none (a
     * grid of shapes that never collide with each other finds nothing at
     * once); but a shared positive group collides whatever the bits say, so a
     * shape with a positive group looks at all. */
    uint64_t mask = s->filter.group_index > 0 ? UINT64_MAX : s->filter.mask_bits;
    int32_t key = apart_key(s);
    tb_tree_query_apart(&bp->trees[TB_DYNAMIC_BODY], fat, mask, key, pair_callback, &q);
    if (s->tree == TB_DYNAMIC_BODY) {
      tb_tree_query_apart(&bp->trees[TB_KINEMATIC_BODY], fat, mask, key, pair_callback, &q);
      tb_tree_query_apart(&bp->trees[TB_STATIC_BODY], fat, mask, key, pair_callback, &q);
    }
  }
  for (int i = 0; i < bp->move_count; ++i)
    if (bp->move_buffer[i] >= 0) {
      tb_shape_at(w, bp->move_buffer[i])->in_move_buffer = false;
      bp->keys[bp->move_buffer[i]].moved = 0;
    }
  bp->move_count = 0;
  tb_contacts_sort_new(w);
}
