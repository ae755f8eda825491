/* Dynamic AABB tree (see tree.h).
 *
 * Cost model (2D surface-area heuristic). By Cauchy-Crofton, a random line meets
 * a convex region with probability proportional to its perimeter, so the
 * expected work of a query is proportional to the sum of the perimeters of the
 * internal nodes it may visit: cost(tree) = sum over internal nodes of P(node).
 * We use the half perimeter P(b) = width + height (the factor 2 cancels).
 * Inserting a leaf L as the sibling of node S adds a new parent of perimeter
 * P(S u L) and grows every ancestor A of S by dP(A) = P(A u L) - P(A) >= 0:
 *   cost(S) = P(S u L) + sum over ancestors A of S of dP(A).
 * For any node T below S, P(T u L) >= P(L) and its ancestors include S and S's
 * ancestors, so cost(T) >= P(L) + dP(S) + sum over ancestors of S of dP(A):
 * a lower bound that prunes S's subtree once it reaches the best cost found
 * (branch and bound, after Bittner et al., "Fast insertion-based optimization
 * of bounding volume hierarchies", 2013). */
#include "tree.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "memory.h"

#include "math_internal.h"

/* Nodes expanded per insertion at most; beyond it the best sibling found so far
 * is taken, which also bounds the worst case (a small leaf inside many large
 * boxes, where nothing prunes). A new proxy gets a thorough search: with 64 the
 * cost of a 10,000-proxy tree built by inserts is within 1% of the exact search,
 * with 16 it is 18% higher. A proxy moved to a box overlapping its old one starts
 * from its old sibling's cost, a tight bound: 16 then gives the cost of the full
 * search (within 1% in tests/test_tree.c and tools/bench_tree.c) for about 10%
 * less time per step. */
#ifndef TB_TREE_CREATE_BUDGET
#define TB_TREE_CREATE_BUDGET 64
#endif
#ifndef TB_TREE_MOVE_BUDGET
#define TB_TREE_MOVE_BUDGET 16
#endif

/* ------------------------------------------------------------------ boxes -- */

static inline float half_perimeter(tb_aabb a) { return (a.upper.x - a.lower.x) + (a.upper.y - a.lower.y); }

static inline tb_aabb aabb_union(tb_aabb a, tb_aabb b) {
  return (tb_aabb){tb_vmin(a.lower, b.lower), tb_vmax(a.upper, b.upper)};
}

static inline bool aabb_contains(tb_aabb outer, tb_aabb inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y;
}

static inline bool aabb_overlaps(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

static inline bool aabb_ok(tb_aabb a) {
  return tb_point_ok(a.lower) && tb_point_ok(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y;
}

static inline bool aabb_equal(tb_aabb a, tb_aabb b) {
  return a.lower.x == b.lower.x && a.lower.y == b.lower.y && a.upper.x == b.upper.x && a.upper.y == b.upper.y;
}

static tb_aabb fat_aabb(tb_aabb tight, float margin, tb_vec2 displacement) {
  const tb_vec2 r = {margin, margin}, zero = {0.0f, 0.0f};
  tb_aabb fat = {tb_sub(tight.lower, r), tb_add(tight.upper, r)};
  fat.lower = tb_add(fat.lower, tb_vmin(displacement, zero));
  fat.upper = tb_add(fat.upper, tb_vmax(displacement, zero));
  return fat;
}

/* ------------------------------------------------------------------ nodes -- */

static inline bool is_leaf(const tb_tree_node* n) { return n->height == 0; }

/* Makes sure at least `extra` nodes are on the free list. New slots go to the
 * front of the list in ascending order, so allocation order is deterministic. */
static bool reserve_nodes(tb_tree* t, int32_t extra) {
  if (t->capacity - t->node_count >= extra) return true;
  int64_t cap = t->capacity < 16 ? 16 : t->capacity;
  while (cap - t->node_count < extra) cap *= 2;
  if (cap > INT32_MAX) return false;
  /* the rebuild's work space first, so that it always covers the nodes */
  if (t->scratch_capacity < cap) {
    int32_t* scratch =
        tb_mem_grow(t->scratch, (size_t)t->scratch_capacity * sizeof *scratch, (size_t)cap * sizeof *scratch);
    if (scratch == NULL) return false;
    t->scratch = scratch;
    t->scratch_capacity = (int32_t)cap;
  }
  if (t->unit_capacity < cap / 2 + 1) {
    int64_t units_cap = cap / 2 + 1;
    tb_tree_build_unit* units =
        tb_mem_grow(t->units, (size_t)t->unit_capacity * sizeof *units, (size_t)units_cap * sizeof *units);
    if (units == NULL) return false;
    t->units = units;
    t->unit_capacity = (int32_t)units_cap;
  }
  tb_tree_node* nodes = tb_mem_grow(t->nodes, (size_t)t->capacity * sizeof *nodes, (size_t)cap * sizeof *nodes);
  if (nodes == NULL) return false;
  int32_t old = t->capacity, new_cap = (int32_t)cap;
  for (int32_t i = old; i < new_cap; ++i) {
    memset(&nodes[i], 0, sizeof nodes[i]);
    nodes[i].parent = i + 1 < new_cap ? i + 1 : t->free_list;
    nodes[i].height = -1;
  }
  t->free_list = old;
  t->nodes = nodes;
  t->capacity = new_cap;
  return true;
}

/* Precondition: the free list is not empty (reserve_nodes). */
static int32_t alloc_node(tb_tree* t) {
  int32_t i = t->free_list;
  tb_tree_node* n = &t->nodes[i];
  t->free_list = n->parent;
  memset(n, 0, sizeof *n);
  n->parent = n->child1 = n->child2 = TB_TREE_NULL;
  n->user_id = TB_TREE_NULL;
  t->node_count += 1;
  return i;
}

static void free_node(tb_tree* t, int32_t i) {
  t->nodes[i].height = -1;
  t->nodes[i].parent = t->free_list;
  t->free_list = i;
  t->node_count -= 1;
}

static inline void refit(tb_tree_node* n, int32_t i) {
  tb_tree_node* a = &n[i];
  const tb_tree_node* c1 = &n[a->child1];
  const tb_tree_node* c2 = &n[a->child2];
  a->aabb = aabb_union(c1->aabb, c2->aabb);
  a->height = 1 + (c1->height > c2->height ? c1->height : c2->height);
  a->category_bits = c1->category_bits | c2->category_bits;
  a->apart_key = c1->apart_key == c2->apart_key ? c1->apart_key : 0;
}

static inline void replace_child(tb_tree_node* n, int32_t parent, int32_t old_child, int32_t new_child) {
  if (n[parent].child1 == old_child)
    n[parent].child1 = new_child;
  else
    n[parent].child2 = new_child;
}

/* Exchanges the places of x and y, which hang under different parents and
 * neither of which is an ancestor of the other. */
static void swap_nodes(tb_tree_node* n, int32_t x, int32_t y) {
  int32_t px = n[x].parent, py = n[y].parent;
  replace_child(n, px, x, y);
  replace_child(n, py, y, x);
  n[x].parent = py;
  n[y].parent = px;
}

static inline int max_i(int a, int b) { return a > b ? a : b; }
static inline int abs_i(int a) { return a < 0 ? -a : a; }

/* --------------------------------------------------------------- rotations -- */

/* tall, the sibling of short_, is at least two levels higher. Swap short_ with
 * the taller child of tall: the AVL rotation of a tree whose children are
 * unordered (between equal grandchildren, the one leaving the smaller box stays).
 * The node short_ joins can still be unbalanced (short_ may be a leaf next to a
 * tall subtree the insertion chose by cost), so short_ keeps sinking until its
 * new sibling is at most one level higher. */
static void rotate_height(tb_tree_node* n, int32_t short_, int32_t tall) {
  int32_t chain[64];
  int k = 0;
  for (;;) {
    int32_t f = n[tall].child1, g = n[tall].child2, up;
    if (n[f].height != n[g].height) {
      up = n[f].height > n[g].height ? f : g;
    } else {
      float keep_g = half_perimeter(aabb_union(n[short_].aabb, n[g].aabb)); /* f goes up */
      float keep_f = half_perimeter(aabb_union(n[short_].aabb, n[f].aabb)); /* g goes up */
      up = keep_f < keep_g ? g : f;
    }
    int32_t stay = up == f ? g : f;
    swap_nodes(n, short_, up);
    chain[k++] = tall;
    if (n[stay].height <= n[short_].height + 1 || k == 64) break;
    tall = stay;
  }
  while (k > 0) refit(n, chain[--k]);
}

/* The best swap found under a node: x and y trade places. */
typedef struct swap_pick {
  float gain;
  int32_t x, y;
} swap_pick;

static inline bool balanced(int h1, int h2) { return abs_i(h1 - h2) <= 1; }

/* A swap is allowed when it leaves node a (new children heights h1, h2) no
 * higher, and a and the two nodes below it that it touches (children heights
 * (l1, r1), (l2, r2)) balanced, so the AVL invariant and its height bound hold. */
static inline bool swap_allowed(int old_height, int h1, int h2, int l1, int r1, int l2, int r2) {
  return 1 + max_i(h1, h2) <= old_height && balanced(h1, h2) && balanced(l1, r1) && balanced(l2, r2);
}

static inline void consider(swap_pick* best, float gain, int32_t x, int32_t y) {
  if (gain > best->gain) *best = (swap_pick){gain, x, y};
}

/* b and c are a's children, heights within one. Try the swaps of Bittner et al.
 * that keep a's box: b with a child of c, c with a child of b, or a child of b
 * with a child of c; apply the one that shrinks the perimeter sum most. */
static void rotate_area(tb_tree_node* n, int32_t a, int32_t b, int32_t c) {
  const int ha = n[a].height, hb = n[b].height, hc = n[c].height;
  swap_pick best = {0.0f, TB_TREE_NULL, TB_TREE_NULL};
  if (hc > 0) { /* b <-> f: c becomes (b, g); b <-> g: c becomes (b, f) */
    int32_t f = n[c].child1, g = n[c].child2;
    int hf = n[f].height, hg = n[g].height;
    float pc = half_perimeter(n[c].aabb);
    if (swap_allowed(ha, hf, 1 + max_i(hb, hg), hb, hg, 0, 0))
      consider(&best, pc - half_perimeter(aabb_union(n[b].aabb, n[g].aabb)), b, f);
    if (swap_allowed(ha, hg, 1 + max_i(hb, hf), hb, hf, 0, 0))
      consider(&best, pc - half_perimeter(aabb_union(n[b].aabb, n[f].aabb)), b, g);
  }
  if (hb > 0) { /* c <-> d: b becomes (c, e); c <-> e: b becomes (c, d) */
    int32_t d = n[b].child1, e = n[b].child2;
    int hd = n[d].height, he = n[e].height;
    float pb = half_perimeter(n[b].aabb);
    if (swap_allowed(ha, hd, 1 + max_i(hc, he), hc, he, 0, 0))
      consider(&best, pb - half_perimeter(aabb_union(n[c].aabb, n[e].aabb)), c, d);
    if (swap_allowed(ha, he, 1 + max_i(hc, hd), hc, hd, 0, 0))
      consider(&best, pb - half_perimeter(aabb_union(n[c].aabb, n[d].aabb)), c, e);
  }
  if (hb > 0 && hc > 0) { /* d <-> f: b = (f, e), c = (d, g); d <-> g: b = (g, e), c = (f, d) */
    int32_t d = n[b].child1, e = n[b].child2, f = n[c].child1, g = n[c].child2;
    int hd = n[d].height, he = n[e].height, hf = n[f].height, hg = n[g].height;
    float pbc = half_perimeter(n[b].aabb) + half_perimeter(n[c].aabb);
    if (swap_allowed(ha, 1 + max_i(hf, he), 1 + max_i(hd, hg), hf, he, hd, hg))
      consider(
          &best,
          pbc - half_perimeter(aabb_union(n[f].aabb, n[e].aabb)) - half_perimeter(aabb_union(n[d].aabb, n[g].aabb)), d,
          f);
    if (swap_allowed(ha, 1 + max_i(hg, he), 1 + max_i(hf, hd), hg, he, hf, hd))
      consider(
          &best,
          pbc - half_perimeter(aabb_union(n[g].aabb, n[e].aabb)) - half_perimeter(aabb_union(n[f].aabb, n[d].aabb)), d,
          g);
  }
  if (best.x == TB_TREE_NULL) return;
  int32_t px = n[best.x].parent, py = n[best.y].parent;
  swap_nodes(n, best.x, best.y);
  if (px != a) refit(n, px);
  if (py != a) refit(n, py);
}

/* Keeps the AVL invariant (children heights within one) at a, else improves the
 * area. a's children are up to date; a itself is refit by the caller. */
static void rotate(tb_tree_node* n, int32_t a) {
  int32_t b = n[a].child1, c = n[a].child2;
  int hb = n[b].height, hc = n[c].height;
  if (hc > hb + 1)
    rotate_height(n, b, c);
  else if (hb > hc + 1)
    rotate_height(n, c, b);
  else
    rotate_area(n, a, b, c);
}

/* Rebalances and refits i and its ancestors. Above a node that comes out with
 * the same box, height, category bits and apart key, nothing changed: stop there (the
 * ancestors keep their balance; they only miss an optional area rotation). */
static void walk_up(tb_tree* t, int32_t i) {
  tb_tree_node* n = t->nodes;
  bool first = true; /* a new parent has no old values to compare with */
  while (i != TB_TREE_NULL) {
    tb_aabb box = n[i].aabb;
    int height = n[i].height;
    uint64_t bits = n[i].category_bits;
    int32_t key = n[i].apart_key;
    rotate(n, i);
    refit(n, i);
    if (!first && aabb_equal(box, n[i].aabb) && height == n[i].height && bits == n[i].category_bits &&
        key == n[i].apart_key)
      break;
    first = false;
    i = n[i].parent;
  }
}

/* ---------------------------------------------------- insertion, removal -- */

typedef struct candidate {
  int32_t node;
  float inherited; /* sum of dP over the node's ancestors */
  float joined;    /* P(node u L) */
  float grow;      /* P(node u L) - P(node) */
} candidate;

static inline candidate make_candidate(const tb_tree_node* n, int32_t i, tb_aabb box, float inherited) {
  float own = half_perimeter(n[i].aabb);
  float joined = half_perimeter(aabb_union(n[i].aabb, box));
  return (candidate){i, inherited, joined, joined - own};
}

/* Ties in cost go to the lower sibling (identical boxes would otherwise all
 * pair with the root), so a bound equal to the best still explores until the
 * best is a leaf. */
static inline bool below_can_win(float bound, float best_cost, int best_height) {
  return bound < best_cost || (bound == best_cost && best_height > 0);
}

/* Could the candidate or a node below it beat the best? */
static inline bool can_win(const tb_tree_node* n, const candidate* c, float leaf_p, float best_cost, int best_height) {
  float own = c->joined + c->inherited;
  if (own < best_cost || (own == best_cost && n[c->node].height < best_height)) return true;
  return n[c->node].height > 0 && below_can_win(leaf_p + c->inherited + c->grow, best_cost, best_height);
}

/* The node whose sibling a leaf of this box should become: branch and bound,
 * depth first, the child that grows less first (it reaches a good bound early). */
static int32_t find_sibling(const tb_tree* t, tb_aabb box, int budget, int32_t hint) {
  const tb_tree_node* n = t->nodes;
  const float leaf_p = half_perimeter(box);
  candidate stack[TB_TREE_STACK_SIZE];
  int count = 0;
  stack[count++] = make_candidate(n, t->root, box, 0.0f);
  int32_t best = t->root;
  float best_cost = stack[0].joined;
  int best_height = n[t->root].height;
  if (hint != TB_TREE_NULL && hint != t->root) {
    /* The exact cost of the hint (a moved proxy's old sibling, likely close to
     * the answer) is a tight first bound: it prunes most of the search. */
    float cost = half_perimeter(aabb_union(n[hint].aabb, box));
    for (int32_t a = n[hint].parent; a != TB_TREE_NULL; a = n[a].parent)
      cost += half_perimeter(aabb_union(n[a].aabb, box)) - half_perimeter(n[a].aabb);
    if (cost < best_cost || (cost == best_cost && n[hint].height < best_height)) {
      best = hint;
      best_cost = cost;
      best_height = n[hint].height;
    }
  }
  while (count > 0) {
    candidate cand = stack[--count];
    if (!can_win(n, &cand, leaf_p, best_cost, best_height)) continue;
    float cost = cand.joined + cand.inherited;
    int height = n[cand.node].height;
    if (cost < best_cost || (cost == best_cost && height < best_height)) {
      best = cand.node;
      best_cost = cost;
      best_height = height;
    }
    if (height == 0) continue;
    float inherited = cand.inherited + cand.grow;
    if (!below_can_win(leaf_p + inherited, best_cost, best_height)) continue;
    if (count + 2 > TB_TREE_STACK_SIZE) continue; /* too deep: prune (quality only) */
    if (budget-- == 0) break;
    candidate c1 = make_candidate(n, n[cand.node].child1, box, inherited);
    candidate c2 = make_candidate(n, n[cand.node].child2, box, inherited);
    bool first1 = c1.grow < c2.grow || (c1.grow == c2.grow && c1.joined <= c2.joined);
    /* pushed worse first, popped better first */
    candidate lo = first1 ? c1 : c2, hi = first1 ? c2 : c1;
    if (can_win(n, &hi, leaf_p, best_cost, best_height)) stack[count++] = hi;
    if (can_win(n, &lo, leaf_p, best_cost, best_height)) stack[count++] = lo;
  }
  return best;
}

/* Precondition: one free node (when the tree is not empty). */
static void insert_leaf(tb_tree* t, int32_t leaf, int budget, int32_t hint) {
  if (t->root == TB_TREE_NULL) {
    t->root = leaf;
    t->nodes[leaf].parent = TB_TREE_NULL;
    return;
  }
  int32_t sibling = find_sibling(t, t->nodes[leaf].aabb, budget, hint);
  int32_t parent = alloc_node(t);
  tb_tree_node* n = t->nodes;
  int32_t old_parent = n[sibling].parent;
  n[parent].parent = old_parent;
  n[parent].child1 = sibling;
  n[parent].child2 = leaf;
  n[sibling].parent = parent;
  n[leaf].parent = parent;
  if (old_parent == TB_TREE_NULL)
    t->root = parent;
  else
    replace_child(n, old_parent, sibling, parent);
  walk_up(t, parent);
}

static void remove_leaf(tb_tree* t, int32_t leaf) {
  tb_tree_node* n = t->nodes;
  if (leaf == t->root) {
    t->root = TB_TREE_NULL;
    return;
  }
  int32_t parent = n[leaf].parent, grand = n[parent].parent;
  int32_t sibling = n[parent].child1 == leaf ? n[parent].child2 : n[parent].child1;
  n[sibling].parent = grand;
  if (grand == TB_TREE_NULL)
    t->root = sibling;
  else
    replace_child(n, grand, parent, sibling);
  free_node(t, parent);
  n[leaf].parent = TB_TREE_NULL;
  if (grand != TB_TREE_NULL) walk_up(t, grand);
}

/* -------------------------------------------------------------- lifecycle -- */

tb_result tb_tree_create(tb_tree* tree, float margin) {
  if (tree == NULL) return TB_ERR_NULL_ARGUMENT;
  if (!tb_length_ok(margin) || margin < 0.0f) return TB_ERR_INVALID_ARGUMENT;
  *tree = (tb_tree){.nodes = NULL, .free_list = TB_TREE_NULL, .root = TB_TREE_NULL, .margin = margin};
  return TB_OK;
}

void tb_tree_destroy(tb_tree* tree) {
  if (tree == NULL) return;
  tb_mem_free(tree->nodes, (size_t)tree->capacity * sizeof *tree->nodes);
  tb_mem_free(tree->scratch, (size_t)tree->scratch_capacity * sizeof *tree->scratch);
  tb_mem_free(tree->units, (size_t)tree->unit_capacity * sizeof *tree->units);
  float margin = tree->margin;
  *tree = (tb_tree){.nodes = NULL, .free_list = TB_TREE_NULL, .root = TB_TREE_NULL, .margin = margin};
}

bool tb_tree_is_proxy(const tb_tree* tree, int32_t proxy) {
  return tree != NULL && proxy >= 0 && proxy < tree->capacity && tree->nodes[proxy].height == 0;
}

int32_t tb_tree_create_proxy(tb_tree* tree, tb_aabb aabb, uint64_t category_bits, int32_t user_id) {
  if (tree == NULL) return TB_TREE_NULL;
  return tb_tree_create_proxy_with_margin(tree, aabb, tree->margin, category_bits, 0, user_id);
}

int32_t tb_tree_create_proxy_with_margin(tb_tree* tree, tb_aabb aabb, float margin, uint64_t category_bits,
                                         int32_t apart_key, int32_t user_id) {
  if (tree == NULL || !aabb_ok(aabb) || !tb_length_ok(margin) || margin < 0.0f) return TB_TREE_NULL;
  tb_tree_rebuild_enlarged(tree); /* insertions and rotations need exact boxes */
  if (!reserve_nodes(tree, 2)) return TB_TREE_NULL;
  int32_t leaf = alloc_node(tree);
  tb_tree_node* n = &tree->nodes[leaf];
  n->aabb = fat_aabb(aabb, margin, (tb_vec2){0.0f, 0.0f});
  n->category_bits = category_bits;
  n->apart_key = apart_key;
  n->user_id = user_id;
  n->height = 0;
  insert_leaf(tree, leaf, TB_TREE_CREATE_BUDGET, TB_TREE_NULL);
  tree->proxy_count += 1;
  return leaf;
}

bool tb_tree_reserve(tb_tree* tree, int32_t proxies) {
  /* each insert takes a leaf and a new parent */
  return proxies <= INT32_MAX / 2 && reserve_nodes(tree, 2 * proxies);
}

bool tb_tree_destroy_proxy(tb_tree* tree, int32_t proxy) {
  if (!tb_tree_is_proxy(tree, proxy)) return false;
  tb_tree_rebuild_enlarged(tree);
  remove_leaf(tree, proxy);
  free_node(tree, proxy);
  tree->proxy_count -= 1;
  return true;
}

bool tb_tree_move_proxy(tb_tree* tree, int32_t proxy, tb_aabb aabb, tb_vec2 displacement) {
  if (tree == NULL) return false;
  return tb_tree_move_proxy_with_margin(tree, proxy, aabb, tree->margin, displacement);
}

bool tb_tree_move_proxy_with_margin(tb_tree* tree, int32_t proxy, tb_aabb aabb, float margin, tb_vec2 displacement) {
  if (!tb_tree_is_proxy(tree, proxy) || !aabb_ok(aabb) || !tb_point_ok(displacement) || !tb_length_ok(margin) ||
      margin < 0.0f)
    return false;
  tb_tree_node* n = &tree->nodes[proxy];
  tb_aabb fat = fat_aabb(aabb, margin, displacement);
  if (aabb_contains(n->aabb, aabb) && half_perimeter(n->aabb) <= 2.0f * half_perimeter(fat)) return false;
  tb_tree_rebuild_enlarged(tree);
  /* A proxy still touching its old box lands near its old place: its old
   * sibling bounds the search and a short one does. One that jumped (teleport)
   * is searched for like a new one. */
  int budget = TB_TREE_CREATE_BUDGET;
  int32_t hint = TB_TREE_NULL;
  if (aabb_overlaps(n->aabb, fat) && n->parent != TB_TREE_NULL) {
    const tb_tree_node* p = &tree->nodes[n->parent];
    hint = p->child1 == proxy ? p->child2 : p->child1;
    budget = TB_TREE_MOVE_BUDGET;
  }
  /* Removal frees one internal node and insertion takes one back: no allocation;
   * the hint survives (only the parent is freed). */
  remove_leaf(tree, proxy);
  tree->nodes[proxy].aabb = fat;
  insert_leaf(tree, proxy, budget, hint);
  return true;
}

bool tb_tree_enlarge_proxy(tb_tree* tree, int32_t proxy, tb_aabb aabb, float margin, tb_vec2 displacement) {
  if (!tb_tree_is_proxy(tree, proxy) || !aabb_ok(aabb) || !tb_point_ok(displacement) || !tb_length_ok(margin) ||
      margin < 0.0f)
    return false;
  tb_tree_node* n = tree->nodes;
  tb_aabb fat = fat_aabb(aabb, margin, displacement);
  if (aabb_contains(n[proxy].aabb, aabb) && half_perimeter(n[proxy].aabb) <= 2.0f * half_perimeter(fat)) return false;
  n[proxy].aabb = fat;
  /* Every ancestor is marked (a shrunk box leaves them larger than their
   * children, to be refitted). Above an ancestor already marked and not
   * grown, all are marked and contain the box. */
  for (int32_t i = n[proxy].parent; i != TB_TREE_NULL; i = n[i].parent) {
    bool grows = !aabb_contains(n[i].aabb, fat);
    if (!grows && n[i].enlarged) break;
    if (grows) n[i].aabb = aabb_union(n[i].aabb, fat);
    n[i].enlarged = 1;
    tree->enlarged = true;
  }
  return true;
}

tb_aabb tb_tree_get_fat_aabb(const tb_tree* tree, int32_t proxy) {
  if (!tb_tree_is_proxy(tree, proxy)) return (tb_aabb){{0.0f, 0.0f}, {0.0f, 0.0f}};
  return tree->nodes[proxy].aabb;
}

int32_t tb_tree_get_user_id(const tb_tree* tree, int32_t proxy) {
  return tb_tree_is_proxy(tree, proxy) ? tree->nodes[proxy].user_id : TB_TREE_NULL;
}

uint64_t tb_tree_get_category_bits(const tb_tree* tree, int32_t proxy) {
  return tb_tree_is_proxy(tree, proxy) ? tree->nodes[proxy].category_bits : 0u;
}

bool tb_tree_set_category_bits(tb_tree* tree, int32_t proxy, uint64_t category_bits) {
  if (!tb_tree_is_proxy(tree, proxy)) return false;
  tb_tree_node* n = tree->nodes;
  n[proxy].category_bits = category_bits;
  /* Ancestors hold the OR of their leaves; stop where nothing changes. */
  for (int32_t i = n[proxy].parent; i != TB_TREE_NULL; i = n[i].parent) {
    uint64_t bits = n[n[i].child1].category_bits | n[n[i].child2].category_bits;
    if (bits == n[i].category_bits) break;
    n[i].category_bits = bits;
  }
  return true;
}

bool tb_tree_set_apart_key(tb_tree* tree, int32_t proxy, int32_t apart_key) {
  if (!tb_tree_is_proxy(tree, proxy)) return false;
  tb_tree_node* n = tree->nodes;
  n[proxy].apart_key = apart_key;
  for (int32_t i = n[proxy].parent; i != TB_TREE_NULL; i = n[i].parent) {
    int32_t k1 = n[n[i].child1].apart_key, key = k1 == n[n[i].child2].apart_key ? k1 : 0;
    if (key == n[i].apart_key) break;
    n[i].apart_key = key;
  }
  return true;
}

/* ---------------------------------------------------------------- queries -- */

/* A stack of node indices in the caller's array (local, on the C stack)
 * that moves to the heap when full. Its address is never taken outside the
 * inlined push, so that the count stays in a register: in memory, each push
 * and pop waited on the store of the one before (the queries' inner loop). */
typedef struct node_stack {
  int32_t* items; /* local until it grows; NULL once a growth failed */
  int32_t count, capacity;
} node_stack;

static node_stack stack_on(int32_t* local) { return (node_stack){local, 0, TB_TREE_STACK_SIZE}; }

static void stack_free(node_stack s, const int32_t* local) {
  if (s.items != NULL && s.items != local) tb_mem_free(s.items, (size_t)s.capacity * sizeof *s.items);
}

/* The stack with twice the room, on the heap; items NULL when out of memory
 * (what it held freed). Kept out of line: queries push in their innermost
 * loop and almost never spill. */
static __attribute__((noinline)) node_stack stack_grown(node_stack s, const int32_t* local) {
  int32_t cap = s.capacity * 2;
  int32_t* items = tb_mem_alloc((size_t)cap * sizeof *items);
  if (items != NULL) memcpy(items, s.items, (size_t)s.count * sizeof *items);
  stack_free(s, local);
  return (node_stack){items, s.count, cap};
}

static inline __attribute__((always_inline)) bool stack_push(node_stack* s, const int32_t* local, int32_t v) {
  if (__builtin_expect(s->count == s->capacity, 0)) {
    *s = stack_grown(*s, local);
    if (s->items == NULL) return false;
  }
  s->items[s->count++] = v;
  return true;
}

/* Whether a query that keeps apart the proxies of `key` (when apart) takes node c. */
#define KEPT(c) (!apart || (c)->apart_key != key)

/* The query; apart is a constant in each caller. The apart key is tested on
 * the nodes the walk takes (popped, or a leaf reported at once), not on every
 * child it looks at: half the tests, for the scenes with nothing to skip. */
static inline __attribute__((always_inline)) tb_result query(const tb_tree* tree, tb_aabb aabb, uint64_t mask,
                                                             bool apart, int32_t key, tb_tree_query_fn* fn,
                                                             void* context) {
  if (tree == NULL || fn == NULL) return TB_ERR_NULL_ARGUMENT;
  if (!tb_vec_finite(aabb.lower) || !tb_vec_finite(aabb.upper)) return TB_ERR_INVALID_ARGUMENT;
  if (tree->root == TB_TREE_NULL) return TB_OK;
  const tb_tree_node* n = tree->nodes;
  const tb_tree_node* root = &n[tree->root];
  if ((root->category_bits & mask) == 0 || !KEPT(root) || !aabb_overlaps(root->aabb, aabb)) return TB_OK;
  if (is_leaf(root)) {
    (void)fn(tree->root, root->user_id, context);
    return TB_OK;
  }
  /* The stack holds nodes already found to overlap. An internal node's two
   * children are loaded and tested together, so that their two loads (cache
   * misses in a large tree) overlap instead of each waiting on its turn, and
   * a child that misses is never pushed. The leaves come in the same order as
   * a depth-first walk that tests each node as it is popped, child1's subtree
   * before child2's: a leaf child1 is reported at once, before child2 (pushed
   * first, so popped after anything child1 pushes). */
  tb_result result = TB_OK;
  int32_t local[TB_TREE_STACK_SIZE];
  node_stack stack = stack_on(local);
  stack_push(&stack, local, tree->root);
  while (stack.count > 0) {
    int32_t index = stack.items[--stack.count];
    const tb_tree_node* node = &n[index];
    if (!KEPT(node)) continue;
    if (is_leaf(node)) {
      if (!fn(index, node->user_id, context)) break;
      continue;
    }
    int32_t i1 = node->child1, i2 = node->child2;
    const tb_tree_node *c1 = &n[i1], *c2 = &n[i2];
    bool in1 = (c1->category_bits & mask) != 0 && aabb_overlaps(c1->aabb, aabb);
    bool in2 = (c2->category_bits & mask) != 0 && aabb_overlaps(c2->aabb, aabb);
    if (in2 && !stack_push(&stack, local, i2)) {
      result = TB_ERR_OUT_OF_MEMORY;
      break;
    }
    if (!in1) continue;
    if (is_leaf(c1)) {
      if (KEPT(c1) && !fn(i1, c1->user_id, context)) break;
    } else if (!stack_push(&stack, local, i1)) {
      result = TB_ERR_OUT_OF_MEMORY;
      break;
    }
  }
  stack_free(stack, local);
  return result;
}
#undef KEPT

tb_result tb_tree_query(const tb_tree* tree, tb_aabb aabb, uint64_t mask, tb_tree_query_fn* fn, void* context) {
  return query(tree, aabb, mask, false, 0, fn, context);
}

tb_result tb_tree_query_apart(const tb_tree* tree, tb_aabb aabb, uint64_t mask, int32_t apart_key, tb_tree_query_fn* fn,
                              void* context) {
  if (apart_key == 0) return tb_tree_query(tree, aabb, mask, fn, context);
  return query(tree, aabb, mask, true, apart_key, fn, context);
}

/* The segment with the reciprocals of its direction precomputed. An axis along
 * which it does not move, or by a subnormal amount (1/d would overflow), is
 * handled as parallel: no division by zero, no 0 * inf. */
typedef struct ray_setup {
  tb_vec2 origin, inv;
  bool flat_x, flat_y;
} ray_setup;

static ray_setup make_ray_setup(const tb_tree_ray_input* in) {
  ray_setup s;
  s.origin = in->origin;
  s.flat_x = !(fabsf(in->translation.x) >= FLT_MIN);
  s.flat_y = !(fabsf(in->translation.y) >= FLT_MIN);
  s.inv.x = s.flat_x ? 0.0f : 1.0f / in->translation.x;
  s.inv.y = s.flat_y ? 0.0f : 1.0f / in->translation.y;
  return s;
}

/* One axis of the slab test: narrows [lo, hi] to where the ray is between the
 * box's planes on this axis; false when that leaves nothing. */
static inline bool ray_slab(float origin, float inv, bool flat, float lower, float upper, float* lo, float* hi) {
  if (flat) return origin >= lower && origin <= upper;
  float t1 = (lower - origin) * inv, t2 = (upper - origin) * inv;
  if (t1 > t2) {
    float tmp = t1;
    t1 = t2;
    t2 = tmp;
  }
  if (t1 > *lo) *lo = t1;
  if (t2 < *hi) *hi = t2;
  return *lo <= *hi;
}

/* Slab test. Monotone in the box: a box containing another is hit whenever that
 * one is (rounding is monotone), so pruning by a parent's box never loses a leaf. */
static inline bool ray_box(const ray_setup* s, float max_fraction, tb_aabb b, float* enter) {
  float lo = 0.0f, hi = max_fraction;
  if (!ray_slab(s->origin.x, s->inv.x, s->flat_x, b.lower.x, b.upper.x, &lo, &hi)) return false;
  if (!ray_slab(s->origin.y, s->inv.y, s->flat_y, b.lower.y, b.upper.y, &lo, &hi)) return false;
  *enter = lo;
  return true;
}

static bool ray_input_ok(const tb_tree_ray_input* in) {
  return tb_point_ok(in->origin) && tb_point_ok(in->translation) && tb_length_ok(in->max_fraction) &&
         in->max_fraction >= 0.0f;
}

bool tb_tree_ray_hits_aabb(const tb_tree_ray_input* input, tb_aabb box, float* fraction) {
  if (input == NULL || !ray_input_ok(input)) return false;
  ray_setup s = make_ray_setup(input);
  float enter;
  if (!ray_box(&s, input->max_fraction, box, &enter)) return false;
  if (fraction != NULL) *fraction = enter;
  return true;
}

typedef struct ray_entry {
  int32_t node;
  float enter;
} ray_entry;

/* Stack of (node, entry fraction), as node_stack. */
typedef struct ray_stack {
  ray_entry* items;
  int32_t count, capacity;
  ray_entry local[TB_TREE_STACK_SIZE];
} ray_stack;

static bool ray_push(ray_stack* s, int32_t node, float enter) {
  if (s->count == s->capacity) {
    int32_t cap = s->capacity * 2;
    ray_entry* items = tb_mem_alloc((size_t)cap * sizeof *items);
    if (items == NULL) return false;
    memcpy(items, s->items, (size_t)s->count * sizeof *items);
    if (s->items != s->local) tb_mem_free(s->items, (size_t)s->capacity * sizeof *s->items);
    s->items = items;
    s->capacity = cap;
  }
  s->items[s->count++] = (ray_entry){node, enter};
  return true;
}

/* Children are tested when their parent is expanded and pushed far first, so the
 * near one is visited first and clips the ray early; an entry whose box starts
 * beyond the (since clipped) max fraction is dropped when popped, which is the
 * same as testing it again. */
tb_result tb_tree_ray_cast(const tb_tree* tree, const tb_tree_ray_input* input, uint64_t mask, tb_tree_ray_fn* fn,
                           void* context) {
  if (tree == NULL || input == NULL || fn == NULL) return TB_ERR_NULL_ARGUMENT;
  if (!ray_input_ok(input)) return TB_ERR_INVALID_ARGUMENT;
  if (tree->root == TB_TREE_NULL) return TB_OK;
  const tb_tree_node* n = tree->nodes;
  tb_tree_ray_input ray = *input;
  ray_setup s = make_ray_setup(&ray);
  tb_result result = TB_OK;
  ray_stack stack = {.items = NULL, .count = 0, .capacity = TB_TREE_STACK_SIZE};
  stack.items = stack.local;
  float enter;
  if ((n[tree->root].category_bits & mask) != 0 && ray_box(&s, ray.max_fraction, n[tree->root].aabb, &enter))
    ray_push(&stack, tree->root, enter);
  while (stack.count > 0) {
    ray_entry e = stack.items[--stack.count];
    if (e.enter > ray.max_fraction) continue;
    const tb_tree_node* node = &n[e.node];
    if (is_leaf(node)) {
      float value = fn(&ray, e.node, node->user_id, context);
      if (value == 0.0f) break;
      if (value > 0.0f && value < ray.max_fraction) ray.max_fraction = value;
      continue;
    }
    int32_t c1 = node->child1, c2 = node->child2;
    float e1 = 0.0f, e2 = 0.0f;
    bool hit1 = (n[c1].category_bits & mask) != 0 && ray_box(&s, ray.max_fraction, n[c1].aabb, &e1);
    bool hit2 = (n[c2].category_bits & mask) != 0 && ray_box(&s, ray.max_fraction, n[c2].aabb, &e2);
    if (hit1 && hit2 && e2 < e1) { /* visit c2 first */
      int32_t ti = c1;
      c1 = c2;
      c2 = ti;
      float tf = e1;
      e1 = e2;
      e2 = tf;
    } else if (!hit1) {
      c1 = c2;
      e1 = e2;
      hit1 = hit2;
      hit2 = false;
    }
    bool ok = true;
    if (hit2) ok = ray_push(&stack, c2, e2);
    if (ok && hit1) ok = ray_push(&stack, c1, e1);
    if (!ok) {
      result = TB_ERR_OUT_OF_MEMORY;
      break;
    }
  }
  if (stack.items != stack.local) tb_mem_free(stack.items, (size_t)stack.capacity * sizeof *stack.items);
  return result;
}

/* ------------------------------------------------------------- statistics -- */

int32_t tb_tree_get_proxy_count(const tb_tree* tree) { return tree == NULL ? 0 : tree->proxy_count; }

int tb_tree_get_height(const tb_tree* tree) {
  if (tree == NULL || tree->root == TB_TREE_NULL) return 0;
  return tree->nodes[tree->root].height;
}

float tb_tree_get_area_ratio(const tb_tree* tree) {
  if (tree == NULL || tree->root == TB_TREE_NULL) return 0.0f;
  float root = half_perimeter(tree->nodes[tree->root].aabb);
  if (!(root > 0.0f)) return 0.0f;
  double total = 0.0;
  for (int32_t i = 0; i < tree->capacity; ++i)
    if (tree->nodes[i].height > 0) total += half_perimeter(tree->nodes[i].aabb);
  return (float)(total / root);
}

bool tb_tree_validate(const tb_tree* tree) {
  if (tree == NULL) return false;
  const tb_tree_node* n = tree->nodes;
  if (tree->capacity < 0 || tree->node_count < 0 || tree->node_count > tree->capacity) return false;
  if (tree->capacity > 0 && n == NULL) return false;
  /* Free list: every entry free, no more than the free slots (so no cycle). */
  int32_t free_count = 0;
  for (int32_t i = tree->free_list; i != TB_TREE_NULL; i = n[i].parent) {
    if (i < 0 || i >= tree->capacity || n[i].height != -1) return false;
    if (++free_count > tree->capacity - tree->node_count) return false;
  }
  if (free_count != tree->capacity - tree->node_count) return false;
  if (tree->root == TB_TREE_NULL) return tree->node_count == 0 && tree->proxy_count == 0;
  if (tree->root < 0 || tree->root >= tree->capacity || n[tree->root].parent != TB_TREE_NULL) return false;
  /* Walk from the root; a node reached twice or a cycle breaks a parent link. */
  int32_t reached = 0, leaves = 0;
  bool ok = true;
  int32_t local[TB_TREE_STACK_SIZE];
  node_stack stack = stack_on(local);
  if (!stack_push(&stack, local, tree->root)) ok = false;
  while (ok && stack.count > 0) {
    int32_t i = stack.items[--stack.count];
    const tb_tree_node* a = &n[i];
    if (++reached > tree->node_count)
      ok = false;
    else if (a->height == 0) {
      leaves += 1;
      ok = a->child1 == TB_TREE_NULL && a->child2 == TB_TREE_NULL && tb_vec_finite(a->aabb.lower) &&
           tb_vec_finite(a->aabb.upper) && a->aabb.lower.x <= a->aabb.upper.x && a->aabb.lower.y <= a->aabb.upper.y;
    } else if (a->height < 0) {
      ok = false;
    } else {
      int32_t c1 = a->child1, c2 = a->child2;
      ok = c1 >= 0 && c1 < tree->capacity && c2 >= 0 && c2 < tree->capacity && c1 != c2 && n[c1].parent == i &&
           n[c2].parent == i && n[c1].height >= 0 && n[c2].height >= 0 &&
           a->height == 1 + max_i(n[c1].height, n[c2].height) &&
           a->category_bits == (n[c1].category_bits | n[c2].category_bits) &&
           a->apart_key == (n[c1].apart_key == n[c2].apart_key ? n[c1].apart_key : 0) &&
           (a->enlarged || aabb_equal(a->aabb, aabb_union(n[c1].aabb, n[c2].aabb))) &&
           aabb_contains(a->aabb, n[c1].aabb) && aabb_contains(a->aabb, n[c2].aabb);
      /* a marked node's ancestors are marked (tb_tree_enlarge_proxy stops there) */
      if (ok && a->enlarged) ok = tree->enlarged && (a->parent == TB_TREE_NULL || n[a->parent].enlarged);
      if (ok) ok = stack_push(&stack, local, c1) && stack_push(&stack, local, c2);
    }
  }
  stack_free(stack, local);
  return ok && reached == tree->node_count && leaves == tree->proxy_count;
}

/* ---------------------------------------------------------------- rebuild -- */

#define TB_TREE_BINS 16

typedef struct build_task {
  int32_t begin, end, parent; /* units[begin, end); parent TB_TREE_NULL: the root */
} build_task;

static inline float centroid_axis(const tb_tree_build_unit* u, int axis) {
  return axis == 0 ? u->box.lower.x + u->box.upper.x : u->box.lower.y + u->box.upper.y; /* twice the centre */
}

static inline int bin_of(float c, float lo, float scale) {
  int k = (int)((c - lo) * scale);
  return k < 0 ? 0 : (k >= TB_TREE_BINS ? TB_TREE_BINS - 1 : k);
}

static inline void swap_units(tb_tree_build_unit* units, int32_t i, int32_t j) {
  tb_tree_build_unit tmp = units[i];
  units[i] = units[j];
  units[j] = tmp;
}

/* The bounds of units[begin, end)'s centres (twice the centres) per axis. */
static void centre_bounds(const tb_tree_build_unit* units, int32_t begin, int32_t end, float lo[2], float hi[2]) {
  /* in locals: through lo and hi (which might be the units' floats, for all
   * the compiler knows) each comparison waited on the last one's store */
  float lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (int32_t k = begin; k < end; ++k) {
    float cx = centroid_axis(&units[k], 0), cy = centroid_axis(&units[k], 1);
    if (cx < lo_x) lo_x = cx;
    if (cx > hi_x) hi_x = cx;
    if (cy < lo_y) lo_y = cy;
    if (cy > hi_y) hi_y = cy;
  }
  lo[0] = lo_x, lo[1] = lo_y, hi[0] = hi_x, hi[1] = hi_y;
}

/* Splits units[begin, end) (two or more) in two non-empty parts; returns the
 * first index of the second part. */
static int32_t split_units(tb_tree_build_unit* units, int32_t begin, int32_t end) {
  float lo[2], hi[2];
  centre_bounds(units, begin, end, lo, hi);
  int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  float extent = hi[axis] - lo[axis];
  if (!(extent >= FLT_MIN)) return begin + (end - begin) / 2; /* all centres (nearly) equal */
  float scale = (float)TB_TREE_BINS / extent;
  tb_aabb bin_box[TB_TREE_BINS];
  int32_t bin_count[TB_TREE_BINS] = {0};
  for (int32_t k = begin; k < end; ++k) {
    int b = bin_of(centroid_axis(&units[k], axis), lo[axis], scale);
    bin_box[b] = bin_count[b] == 0 ? units[k].box : aabb_union(bin_box[b], units[k].box);
    bin_count[b] += 1;
  }
  /* cost(split after bin s) = P(left) n_left + P(right) n_right */
  float right_cost[TB_TREE_BINS];
  tb_aabb acc = {{0.0f, 0.0f}, {0.0f, 0.0f}};
  int32_t acc_n = 0;
  for (int b = TB_TREE_BINS - 1; b > 0; --b) {
    if (bin_count[b] > 0) acc = acc_n == 0 ? bin_box[b] : aabb_union(acc, bin_box[b]);
    acc_n += bin_count[b];
    right_cost[b - 1] = acc_n == 0 ? INFINITY : half_perimeter(acc) * (float)acc_n;
  }
  int best_split = -1;
  float best_cost = INFINITY;
  acc_n = 0;
  for (int b = 0; b < TB_TREE_BINS - 1; ++b) {
    if (bin_count[b] > 0) acc = acc_n == 0 ? bin_box[b] : aabb_union(acc, bin_box[b]);
    acc_n += bin_count[b];
    if (acc_n == 0) continue;
    float cost = half_perimeter(acc) * (float)acc_n + right_cost[b];
    if (cost < best_cost) {
      best_cost = cost;
      best_split = b;
    }
  }
  if (best_split < 0) return begin + (end - begin) / 2;
  int32_t i = begin, j = end - 1;
  while (i <= j) {
    if (bin_of(centroid_axis(&units[i], axis), lo[axis], scale) <= best_split) {
      ++i;
    } else {
      swap_units(units, i, j);
      --j;
    }
  }
  if (i == begin || i == end) return begin + (end - begin) / 2;
  return i;
}

/* Splits units[begin, end) (two or more) at the middle of their centres
 * along the axis where the centres spread most (Box2D v3's partial rebuild):
 * two passes over the units against split_units' three with bins, for a
 * tree a little less tight. Returns the first index of the second part. */
static int32_t split_units_mid(tb_tree_build_unit* units, int32_t begin, int32_t end) {
  float lo[2], hi[2];
  centre_bounds(units, begin, end, lo, hi);
  int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  float middle = 0.5f * (lo[axis] + hi[axis]);
  int32_t i = begin, j = end - 1;
  while (i <= j) {
    if (centroid_axis(&units[i], axis) < middle) {
      ++i;
    } else {
      swap_units(units, i, j);
      --j;
    }
  }
  if (i == begin || i == end) return begin + (end - begin) / 2; /* all centres (nearly) equal */
  return i;
}

/* Joins nodes[0, count) (leaves, or subtrees kept whole) under count - 1
 * internal nodes built top-down (split over the units, tree->units, their
 * copies with their boxes); the caller freed at least that many. order
 * receives the new internal nodes (count - 1 entries) for the refit. The
 * larger part is pushed first, so the stack holds at most log2(count) + 1
 * tasks. */
static void build_over(tb_tree* tree, const int32_t* nodes, int32_t count, int32_t* order, bool binned) {
  tb_tree_node* n = tree->nodes;
  tb_tree_build_unit* units = tree->units;
  for (int32_t k = 0; k < count; ++k) units[k] = (tb_tree_build_unit){n[nodes[k]].aabb, nodes[k]};
  build_task tasks[64];
  int ntasks = 0, created = 0;
  tasks[ntasks++] = (build_task){0, count, TB_TREE_NULL};
  while (ntasks > 0) {
    build_task task = tasks[--ntasks];
    int32_t node;
    if (task.end - task.begin == 1) {
      node = units[task.begin].node;
    } else {
      node = alloc_node(tree);
      order[created++] = node;
      int32_t mid = binned ? split_units(units, task.begin, task.end) : split_units_mid(units, task.begin, task.end);
      build_task left = {task.begin, mid, node}, right = {mid, task.end, node};
      bool left_larger = mid - task.begin >= task.end - mid;
      tasks[ntasks++] = left_larger ? left : right;
      tasks[ntasks++] = left_larger ? right : left;
      n[node].height = 1; /* internal until refit */
    }
    n[node].parent = task.parent;
    if (task.parent == TB_TREE_NULL) {
      tree->root = node;
    } else if (n[task.parent].child1 == TB_TREE_NULL) {
      n[task.parent].child1 = node;
    } else {
      n[task.parent].child2 = node;
    }
  }
  for (int32_t k = created - 1; k >= 0; --k) refit(n, order[k]);
}

tb_result tb_tree_rebuild(tb_tree* tree) {
  if (tree == NULL) return TB_ERR_NULL_ARGUMENT;
  int32_t count = tree->proxy_count;
  if (count < 3) { /* nothing to reorder; marked boxes are still refitted */
    tb_tree_rebuild_enlarged(tree);
    return TB_OK;
  }
  /* count leaves and count - 1 internal nodes: the work space holds both */
  int32_t* leaves = tree->scratch;
  int32_t* order = leaves + count;
  tb_tree_node* n = tree->nodes;
  int32_t found = 0;
  for (int32_t i = 0; i < tree->capacity; ++i)
    if (n[i].height == 0) leaves[found++] = i;
  for (int32_t i = 0; i < tree->capacity; ++i)
    if (n[i].height > 0) free_node(tree, i);
  tree->enlarged = false;
  build_over(tree, leaves, count, order, true);
  return TB_OK;
}

void tb_tree_rebuild_enlarged(tb_tree* tree) {
  if (!tree->enlarged) return;
  tree->enlarged = false;
  /* Gather the units: the root's subtree cut below its marked nodes. The
   * units fill the work space from the front, the pending nodes from the
   * back; together they are disjoint subtrees, no more than the leaves,
   * and the work space has a slot per node. */
  int32_t* units = tree->scratch;
  int32_t count = 0, pending = tree->scratch_capacity;
  tb_tree_node* n = tree->nodes;
  tree->scratch[--pending] = tree->root;
  while (pending < tree->scratch_capacity) {
    int32_t i = tree->scratch[pending++];
    if (n[i].height == 0 || !n[i].enlarged) {
      units[count++] = i;
      continue;
    }
    tree->scratch[--pending] = n[i].child2;
    tree->scratch[--pending] = n[i].child1;
    free_node(tree, i);
  }
  for (int32_t k = 0; k < count; ++k) n[units[k]].parent = TB_TREE_NULL;
  build_over(tree, units, count, units + count, false);
}
