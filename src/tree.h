/* Dynamic AABB tree: the broad phase's bounding volume hierarchy (not public).
 *
 * Leaves are proxies: a fat AABB (the tight AABB grown by the tree's margin, and
 * optionally stretched along a predicted displacement), a user id and category
 * bits. A proxy id is the index of its leaf node and stays the same for the
 * proxy's life, re-insertions included. Nodes live in one growable array with a
 * free list; the tree links them by index.
 *
 * Insertion picks the sibling of least perimeter cost (2D surface-area heuristic)
 * by branch and bound; on the way back up, each ancestor is rebalanced by a
 * height rotation when its children's heights differ by more than one, else by
 * the child/grandchild swap that most reduces the perimeter (when it keeps the
 * node balanced). Every internal node thus keeps children heights within one
 * (AVL), so a tree of n proxies is at most about 1.44 log2 n high, whatever the
 * insertion order. Queries use an explicit stack, never recursion.
 *
 * Same sequence of calls, same tree: nothing depends on addresses or time.
 * Preconditions are checked, never asserted: bad input gives an error value and
 * leaves the tree unchanged. Proxy ids carry no generation: the owner (the broad
 * phase) must not use an id after destroying its proxy. */
#ifndef TB_TREE_H
#define TB_TREE_H

#include <stdbool.h>
#include <stdint.h>

#include "tumble.h"

#define TB_TREE_NULL (-1)

/* Entries of the traversal stacks kept on the C stack; deeper trees spill onto
 * the heap (queries) or prune the deepest candidates (insertion). */
#ifndef TB_TREE_STACK_SIZE
#define TB_TREE_STACK_SIZE 128
#endif

typedef struct tb_tree_node {
  tb_aabb aabb;           /* leaf: the fat AABB; internal: union of the children */
  uint64_t category_bits; /* leaf: the proxy's; internal: OR of the children's */
  int32_t parent;         /* TB_TREE_NULL at the root; next free node when free */
  int32_t child1, child2; /* TB_TREE_NULL in a leaf */
  int32_t user_id;        /* leaf only */
  /* leaf: the proxy's apart key (0: none); internal: the key all its leaves
   * share, else 0. A query with that key skips the subtree (tb_tree_query_apart). */
  int32_t apart_key;
  int16_t height;   /* 0: leaf, -1: free */
  uint8_t enlarged; /* internal: grown by tb_tree_enlarge_proxy since the last rebuild */
} tb_tree_node;

/* A unit of a rebuild: a leaf or a subtree kept whole, with its box copied
 * beside it so that the splits read one array instead of the nodes. */
typedef struct tb_tree_build_unit {
  tb_aabb box;
  int32_t node;
} tb_tree_build_unit;

typedef struct tb_tree {
  tb_tree_node* nodes;
  int32_t capacity;   /* slots in nodes */
  int32_t node_count; /* slots in use (leaves + internal nodes) */
  int32_t free_list;
  int32_t root;
  int32_t proxy_count;
  float margin;              /* fat AABB = tight AABB grown by this on every side (m) */
  int32_t* scratch;          /* rebuild work space, one entry per node slot (never allocated by a rebuild) */
  int32_t scratch_capacity;  /* >= capacity */
  tb_tree_build_unit* units; /* the rebuild's units: at most the leaves, half the node slots plus one */
  int32_t unit_capacity;     /* >= capacity / 2 + 1 */
  bool enlarged;             /* some internal node is marked enlarged */
} tb_tree;

/* Called per proxy whose fat AABB overlaps the query box; return false to stop.
 * It must not modify the tree. */
typedef bool tb_tree_query_fn(int32_t proxy, int32_t user_id, void* context);

/* The segment origin + t translation, 0 <= t <= max_fraction. */
typedef struct tb_tree_ray_input {
  tb_vec2 origin;
  tb_vec2 translation;
  float max_fraction;
} tb_tree_ray_input;

/* Called per proxy whose fat AABB the (clipped) segment touches, with the current
 * clipped input. Return 0 to stop, < 0 to ignore the proxy, else a new max
 * fraction (a value >= the current one changes nothing). Must not modify the tree. */
typedef float tb_tree_ray_fn(const tb_tree_ray_input* input, int32_t proxy, int32_t user_id, void* context);

/* An empty tree (allocates nothing yet). margin: finite, 0 <= margin <= TB_MAX_LENGTH.
 * Errors: TB_ERR_NULL_ARGUMENT, TB_ERR_INVALID_ARGUMENT. */
tb_result tb_tree_create(tb_tree* tree, float margin);
/* Frees all memory; the tree is left empty and usable (as if just created). */
void tb_tree_destroy(tb_tree* tree);
/* Bytes the tree's node array and rebuild work space hold. */
static inline size_t tb_tree_bytes(const tb_tree* tree) {
  return (size_t)tree->capacity * sizeof *tree->nodes + (size_t)tree->scratch_capacity * sizeof *tree->scratch +
         (size_t)tree->unit_capacity * sizeof *tree->units;
}

/* How many public trees (tb_dynamic_tree, dynamic_tree_api.c) exist. */
int tb_dynamic_tree_live_count(void);

/* Insert a proxy for a tight AABB (finite, lower <= upper, within TB_MAX_LENGTH).
 * Returns its id, or TB_TREE_NULL on bad input or when out of memory. */
int32_t tb_tree_create_proxy(tb_tree* tree, tb_aabb aabb, uint64_t category_bits, int32_t user_id);
/* The same with the proxy's own fattening margin (>= 0) instead of the tree's,
 * and an apart key (0: none; see tb_tree_query_apart). */
int32_t tb_tree_create_proxy_with_margin(tb_tree* tree, tb_aabb aabb, float margin, uint64_t category_bits,
                                         int32_t apart_key, int32_t user_id);
/* False (and nothing done) when proxy is not a live proxy of this tree. */
/* Room for proxies more, so that as many tb_tree_create_proxy calls cannot run
 * out of memory; false when out of memory. */
bool tb_tree_reserve(tb_tree* tree, int32_t proxies);
bool tb_tree_destroy_proxy(tb_tree* tree, int32_t proxy);
/* The proxy's tight AABB is now aabb, and it is expected to move by about
 * displacement before the next call ({0, 0}: no prediction). Re-inserts, with a
 * new fat AABB, only when aabb leaves the fat AABB or when the fat AABB is more
 * than twice (in perimeter) the one this call would build (a stretch no longer
 * needed). Returns whether it re-inserted; false on bad input (tree unchanged).
 * Never allocates. */
bool tb_tree_move_proxy(tb_tree* tree, int32_t proxy, tb_aabb aabb, tb_vec2 displacement);
/* The same with the proxy's own margin (the one it was created with). */
bool tb_tree_move_proxy_with_margin(tb_tree* tree, int32_t proxy, tb_aabb aabb, float margin, tb_vec2 displacement);
/* The same decision and fat AABB as tb_tree_move_proxy_with_margin, but the
 * proxy keeps its place: its ancestors grow to contain the new box and are
 * marked, and tb_tree_rebuild_enlarged later rebuilds the marked part. For
 * many proxies moved at once (a step): a re-insertion searches and rotates
 * per proxy, the rebuild sorts them all together (Box2D v3 does the same).
 * Queries stay correct in between (every box contains its children's);
 * tb_tree_validate accepts a marked node larger than its children's union.
 * A create, destroy or re-inserting move rebuilds the marked part first. */
bool tb_tree_enlarge_proxy(tb_tree* tree, int32_t proxy, tb_aabb aabb, float margin, tb_vec2 displacement);
/* Rebuilds what tb_tree_enlarge_proxy marked: the marked nodes are freed, and
 * the subtrees and leaves hanging from them are joined again top-down, each
 * part split at the middle of its centres (cheaper than the binned perimeter
 * heuristic of tb_tree_rebuild: the step rebuilds much of a moving tree every
 * time, and the tighter tree saved less in queries than it cost; tumbler
 * 0.95x, smash 0.94x). Never allocates. */
void tb_tree_rebuild_enlarged(tb_tree* tree);

bool tb_tree_is_proxy(const tb_tree* tree, int32_t proxy);
/* The stored (fat) AABB; a zero box for a bad proxy. */
tb_aabb tb_tree_get_fat_aabb(const tb_tree* tree, int32_t proxy);
/* TB_TREE_NULL for a bad proxy. */
int32_t tb_tree_get_user_id(const tb_tree* tree, int32_t proxy);
/* 0 for a bad proxy. */
uint64_t tb_tree_get_category_bits(const tb_tree* tree, int32_t proxy);
bool tb_tree_set_category_bits(tb_tree* tree, int32_t proxy, uint64_t category_bits);
/* False (nothing done) for a bad proxy. */
bool tb_tree_set_apart_key(tb_tree* tree, int32_t proxy, int32_t apart_key);

/* Calls fn for every proxy with (category_bits & mask) != 0 whose fat AABB
 * overlaps aabb (touching counts). Errors: TB_ERR_NULL_ARGUMENT (tree or fn),
 * TB_ERR_INVALID_ARGUMENT (bad box), TB_ERR_OUT_OF_MEMORY (the traversal stack
 * could not grow; the query stopped early). */
tb_result tb_tree_query(const tb_tree* tree, tb_aabb aabb, uint64_t mask, tb_tree_query_fn* fn, void* context);
/* tb_tree_query without the proxies whose apart key is apart_key (!= 0; 0
 * skips nothing): the subtrees whose leaves all carry it are not entered. The
 * broad phase keys a shape by what can never pair with it (its negative
 * group, else its body), so that a ragdoll's limb or a chain link does not
 * walk down to its own kind's leaves. */
tb_result tb_tree_query_apart(const tb_tree* tree, tb_aabb aabb, uint64_t mask, int32_t apart_key, tb_tree_query_fn* fn,
                              void* context);
/* Calls fn for the proxies (category_bits & mask) != 0 whose fat AABB the segment
 * touches, nearer boxes first (by entry fraction, per subtree; not a global
 * sort). Errors as tb_tree_query; also a non-finite input or max_fraction < 0. */
tb_result tb_tree_ray_cast(const tb_tree* tree, const tb_tree_ray_input* input, uint64_t mask, tb_tree_ray_fn* fn,
                           void* context);
/* The segment-box test the ray cast uses: true when the segment of input touches
 * box; *fraction (may be NULL) receives the entry fraction (0 when it starts inside). */
bool tb_tree_ray_hits_aabb(const tb_tree_ray_input* input, tb_aabb box, float* fraction);

int32_t tb_tree_get_proxy_count(const tb_tree* tree);
/* Edges on the longest root-to-leaf path: 0 for an empty or one-proxy tree. */
int tb_tree_get_height(const tb_tree* tree);
/* The 2D surface-area-heuristic cost: the sum of the perimeters of the internal
 * nodes over the root's perimeter (1 for two proxies; 0 when undefined). */
float tb_tree_get_area_ratio(const tb_tree* tree);
/* Full check: links, free list, counts, heights, category bits, every internal
 * AABB equal to the union of its children's (containing it, for a node marked
 * enlarged). */
bool tb_tree_validate(const tb_tree* tree);

/* Rebuilds the hierarchy over the current proxies, top-down with a binned
 * perimeter heuristic (for static or freshly loaded sets: about 5% lower cost
 * than inserts). Proxy ids and fat AABBs are kept. The result is not AVL
 * balanced (height follows the splits, typically log2 n + 3); later updates
 * rebalance the paths they touch. Never allocates (its work space grows with
 * the nodes). Errors: TB_ERR_NULL_ARGUMENT. */
tb_result tb_tree_rebuild(tb_tree* tree);

#endif
