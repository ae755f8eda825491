/* The dynamic AABB tree (src/tree.c): queries and ray casts against brute force
 * through inserts, moves, removals and a rebuild; ray clipping; fat AABBs;
 * height bounds; determinism; bad input. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../src/tree.h"
#include "test_util.h"

#define N_PROXIES 10000
#define MARGIN 0.1f
#define WORLD 200.0f

/* ------------------------------------------------------------- helpers -- */

static tb_aabb box_at(float x, float y, float w, float h) { return (tb_aabb){{x, y}, {x + w, y + h}}; }

static tb_aabb random_box(unsigned* rng) {
  float x = tbt_rand(rng, 0.0f, WORLD), y = tbt_rand(rng, 0.0f, WORLD);
  float w = tbt_rand(rng, 0.05f, 2.0f), h = tbt_rand(rng, 0.05f, 2.0f);
  /* a few large ones, as a level's static geometry would have */
  if (tbt_rand(rng, 0.0f, 1.0f) < 0.01f) w *= 20.0f;
  return box_at(x, y, w, h);
}

static bool overlaps(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

static bool contains(tb_aabb outer, tb_aabb inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y;
}

static bool same_box(tb_aabb a, tb_aabb b) {
  return a.lower.x == b.lower.x && a.lower.y == b.lower.y && a.upper.x == b.upper.x && a.upper.y == b.upper.y;
}

static int cmp_i32(const void* a, const void* b) {
  int32_t x = *(const int32_t*)a, y = *(const int32_t*)b;
  return (x > y) - (x < y);
}

/* A growable list of proxy ids, reported by a query or found by brute force. */
typedef struct id_list {
  int32_t* ids;
  int count, capacity;
} id_list;

static void list_add(id_list* l, int32_t id) {
  if (l->count == l->capacity) {
    l->capacity = l->capacity ? 2 * l->capacity : 256;
    l->ids = realloc(l->ids, (size_t)l->capacity * sizeof *l->ids);
    if (l->ids == NULL) abort();
  }
  l->ids[l->count++] = id;
}

static void expect_same_sets(id_list* got, id_list* want, const char* what, int index) {
  qsort(got->ids, (size_t)got->count, sizeof *got->ids, cmp_i32);
  qsort(want->ids, (size_t)want->count, sizeof *want->ids, cmp_i32);
  ck_assert_msg(got->count == want->count, "%s %d: %d proxies reported, brute force finds %d", what, index, got->count,
                want->count);
  int first_diff = -1;
  for (int i = 0; i < got->count && first_diff < 0; ++i)
    if (got->ids[i] != want->ids[i]) first_diff = i;
  ck_assert_msg(first_diff < 0, "%s %d: id sets differ at %d", what, index, first_diff);
}

/* The test's own record of the live proxies: id -> user id, tight box. */
typedef struct model {
  int32_t proxy[2 * N_PROXIES];
  tb_aabb tight[2 * N_PROXIES];
  int32_t key[2 * N_PROXIES]; /* apart key */
  int count;                  /* slots used; proxy -1: destroyed */
} model;

/* check's assertions are costly in hot loops (each marks a point through a
 * pipe), so the callbacks count problems and the caller asserts once. */
typedef struct collect_ctx {
  id_list* list;
  const tb_tree* tree;
  int bad_user_ids;
} collect_ctx;

static bool collect_query(int32_t proxy, int32_t user_id, void* context) {
  collect_ctx* c = context;
  c->bad_user_ids += user_id != tb_tree_get_user_id(c->tree, proxy);
  list_add(c->list, proxy);
  return true;
}

static float collect_ray(const tb_tree_ray_input* input, int32_t proxy, int32_t user_id, void* context) {
  collect_ctx* c = context;
  c->bad_user_ids += user_id != tb_tree_get_user_id(c->tree, proxy);
  list_add(c->list, proxy);
  return input->max_fraction; /* no clipping */
}

static tb_tree_ray_input random_ray(unsigned* rng) {
  tb_tree_ray_input ray;
  ray.origin = (tb_vec2){tbt_rand(rng, -10.0f, WORLD + 10.0f), tbt_rand(rng, -10.0f, WORLD + 10.0f)};
  float angle = tbt_rand(rng, 0.0f, 6.2831853f), len = tbt_rand(rng, 1.0f, 150.0f);
  ray.translation = (tb_vec2){len * cosf(angle), len * sinf(angle)};
  /* some axis-aligned rays exercise the parallel-slab path */
  float pick = tbt_rand(rng, 0.0f, 1.0f);
  if (pick < 0.1f)
    ray.translation.x = 0.0f;
  else if (pick < 0.2f)
    ray.translation.y = 0.0f;
  ray.max_fraction = tbt_rand(rng, 0.2f, 1.0f);
  return ray;
}

/* 100 box queries (some with a category mask), 100 of them again keeping apart
 * the key of a proxy near the box, and 100 ray casts, each compared with a scan
 * of every live proxy's fat AABB. */
static void check_against_brute_force(const tb_tree* tree, const model* m, unsigned seed) {
  ck_assert(tb_tree_validate(tree));
  unsigned rng = seed;
  id_list got = {0}, want = {0};
  int live = 0, outside = 0, wrong_id = 0;
  for (int i = 0; i < m->count; ++i) {
    if (m->proxy[i] < 0) continue;
    live += 1;
    outside += !contains(tb_tree_get_fat_aabb(tree, m->proxy[i]), m->tight[i]);
    wrong_id += tb_tree_get_user_id(tree, m->proxy[i]) != i;
  }
  ck_assert_int_eq(tb_tree_get_proxy_count(tree), live);
  ck_assert_int_eq(outside, 0); /* every tight box inside its fat box */
  ck_assert_int_eq(wrong_id, 0);
  for (int q = 0; q < 100; ++q) {
    float size = q % 10 == 0 ? 60.0f : tbt_rand(&rng, 0.1f, 15.0f);
    float x = tbt_rand(&rng, -5.0f, WORLD), y = tbt_rand(&rng, -5.0f, WORLD);
    tb_aabb query = box_at(x, y, size, tbt_rand(&rng, 0.1f, 15.0f));
    uint64_t mask = q % 4 == 0 ? (uint64_t)1 << (q % 3) : UINT64_MAX;
    got.count = want.count = 0;
    collect_ctx ctx = {&got, tree, 0};
    ck_assert_int_eq(tb_tree_query(tree, query, mask, collect_query, &ctx), TB_OK);
    ck_assert_int_eq(ctx.bad_user_ids, 0);
    for (int i = 0; i < m->count; ++i) {
      int32_t p = m->proxy[i];
      if (p < 0) continue;
      tb_aabb fat = tb_tree_get_fat_aabb(tree, p);
      if ((tb_tree_get_category_bits(tree, p) & mask) != 0 && overlaps(fat, query)) list_add(&want, p);
    }
    expect_same_sets(&got, &want, "query", q);
    /* the same box, without the proxies of one key (the first found's, or a
     * key held by none): as many subtrees as hold that key alone are skipped */
    int32_t key = want.count > 0 ? m->key[tb_tree_get_user_id(tree, want.ids[0])] : 1000;
    got.count = want.count = 0;
    ck_assert_int_eq(tb_tree_query_apart(tree, query, mask, key, collect_query, &ctx), TB_OK);
    ck_assert_int_eq(ctx.bad_user_ids, 0);
    for (int i = 0; i < m->count; ++i) {
      int32_t p = m->proxy[i];
      if (p < 0 || m->key[i] == key) continue;
      if ((tb_tree_get_category_bits(tree, p) & mask) != 0 && overlaps(tb_tree_get_fat_aabb(tree, p), query))
        list_add(&want, p);
    }
    expect_same_sets(&got, &want, "apart query", q);
  }
  for (int r = 0; r < 100; ++r) {
    tb_tree_ray_input ray = random_ray(&rng);
    got.count = want.count = 0;
    collect_ctx ctx = {&got, tree, 0};
    ck_assert_int_eq(tb_tree_ray_cast(tree, &ray, UINT64_MAX, collect_ray, &ctx), TB_OK);
    ck_assert_int_eq(ctx.bad_user_ids, 0);
    /* The brute force uses the tree's own segment-box predicate: this checks
     * the traversal (pruning never loses a hit), not the predicate. */
    for (int i = 0; i < m->count; ++i)
      if (m->proxy[i] >= 0 && tb_tree_ray_hits_aabb(&ray, tb_tree_get_fat_aabb(tree, m->proxy[i]), NULL))
        list_add(&want, m->proxy[i]);
    expect_same_sets(&got, &want, "ray", r);
  }
  free(got.ids);
  free(want.ids);
}

/* Apart keys by where a proxy was made (bands 20 m wide, negative in the upper
 * half), so that whole subtrees share one (as a ragdoll's limbs do). */
static void model_add(tb_tree* tree, model* m, tb_aabb box, uint64_t bits) {
  int slot = m->count++;
  m->tight[slot] = box;
  int32_t band = 1 + (int32_t)(box.lower.x / 20.0f);
  m->key[slot] = box.lower.y > 0.5f * WORLD ? -band : band;
  m->proxy[slot] = tb_tree_create_proxy_with_margin(tree, box, MARGIN, bits, m->key[slot], slot);
  if (m->proxy[slot] < 0) ck_abort_msg("create_proxy failed");
}

/* Largest height of a tree whose every internal node has children heights within
 * one (AVL): such a tree of height h has at least Fib(h + 2) leaves. */
static int avl_height_bound(int n) {
  long a = 1, b = 2; /* Fib(2), Fib(3): least leaves at heights 0 and 1 */
  int h = 0;
  while (b <= n) {
    long c = a + b;
    a = b;
    b = c;
    ++h;
  }
  return h;
}

/* The bound the brief asks for: ceil(2 log2 n). */
static int log_height_bound(int n) { return (int)ceil(2.0 * log2((double)n)); }

/* For incrementally built trees (not after a rebuild). */
static void check_height(const tb_tree* tree, const char* what) {
  int n = tb_tree_get_proxy_count(tree), h = tb_tree_get_height(tree);
  ck_assert(tb_tree_validate(tree));
  int unbalanced = 0;
  for (int32_t i = 0; i < tree->capacity; ++i) {
    const tb_tree_node* a = &tree->nodes[i];
    if (a->height > 0) unbalanced += abs(tree->nodes[a->child1].height - tree->nodes[a->child2].height) > 1;
  }
  ck_assert_msg(unbalanced == 0, "%s: %d nodes with children heights more than one apart", what, unbalanced);
  ck_assert_msg(h <= log_height_bound(n), "%s: height %d > ceil(2 log2 %d) = %d", what, h, n, log_height_bound(n));
  ck_assert_msg(h <= avl_height_bound(n), "%s: height %d > AVL bound %d for %d proxies", what, h, avl_height_bound(n),
                n);
  ck_assert_int_ge(h, (int)ceil(log2((double)n))); /* no binary tree does better */
}

/* --------------------------------------------------------------- tests -- */

START_TEST(queries_match_brute_force) {
  static model m; /* large: keep it off the stack */
  memset(&m, 0, sizeof m);
  tb_tree tree;
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  unsigned rng = 0x1234567u;
  for (int i = 0; i < N_PROXIES; ++i) model_add(&tree, &m, random_box(&rng), (uint64_t)1 << (i % 3));
  check_against_brute_force(&tree, &m, 11);

  /* 5,000 moves: mostly small steps (many stay in their fat AABB), some jumps */
  int reinserted = 0;
  for (int k = 0; k < 5000; ++k) {
    int i = (int)tbt_rand(&rng, 0.0f, (float)m.count);
    tb_aabb b = m.tight[i];
    if (k % 5 == 0) {
      b = random_box(&rng);
    } else {
      tb_vec2 d = {tbt_rand(&rng, -0.3f, 0.3f), tbt_rand(&rng, -0.3f, 0.3f)};
      b = (tb_aabb){{b.lower.x + d.x, b.lower.y + d.y}, {b.upper.x + d.x, b.upper.y + d.y}};
    }
    m.tight[i] = b;
    tb_vec2 disp = k % 7 == 0 ? (tb_vec2){tbt_rand(&rng, -1.0f, 1.0f), 0.5f} : (tb_vec2){0.0f, 0.0f};
    reinserted += tb_tree_move_proxy(&tree, m.proxy[i], b, disp);
  }
  ck_assert_int_gt(reinserted, 1000);
  ck_assert_int_lt(reinserted, 5000);
  check_against_brute_force(&tree, &m, 12);
  check_height(&tree, "after moves");

  /* 3,000 removals, then 1,000 new proxies (reusing freed nodes), more moves */
  int failed = 0;
  for (int k = 0; k < 3000; ++k) {
    int i = (int)tbt_rand(&rng, 0.0f, (float)m.count);
    if (m.proxy[i] < 0) continue;
    failed += !tb_tree_destroy_proxy(&tree, m.proxy[i]);
    failed += tb_tree_is_proxy(&tree, m.proxy[i]);
    m.proxy[i] = -1;
  }
  ck_assert_int_eq(failed, 0);
  for (int k = 0; k < 1000; ++k) model_add(&tree, &m, random_box(&rng), 1u);
  check_against_brute_force(&tree, &m, 13);
  for (int k = 0; k < 2000; ++k) {
    int i = (int)tbt_rand(&rng, 0.0f, (float)m.count);
    if (m.proxy[i] < 0) continue;
    m.tight[i] = random_box(&rng); /* a jump: searched for like a new proxy */
    tb_tree_move_proxy(&tree, m.proxy[i], m.tight[i], (tb_vec2){0.0f, 0.0f});
  }
  check_against_brute_force(&tree, &m, 14);
  check_height(&tree, "after removals");

  /* category bits and apart keys changed in place keep the internal ORs and
   * shared keys right */
  for (int i = 0; i < m.count; i += 7)
    if (m.proxy[i] >= 0) failed += !tb_tree_set_category_bits(&tree, m.proxy[i], 4u);
  for (int i = 3; i < m.count; i += 5)
    if (m.proxy[i] >= 0) failed += !tb_tree_set_apart_key(&tree, m.proxy[i], m.key[i] = m.key[i] > 0 ? 77 : -77);
  ck_assert_int_eq(failed, 0);
  check_against_brute_force(&tree, &m, 15);

  /* a rebuild keeps ids, boxes and user ids */
  float ratio_before = tb_tree_get_area_ratio(&tree);
  ck_assert_int_eq(tb_tree_rebuild(&tree), TB_OK);
  check_against_brute_force(&tree, &m, 16);
  ck_assert(tb_tree_get_area_ratio(&tree) < 1.5f * ratio_before);
  /* and the tree keeps working incrementally afterwards */
  for (int k = 0; k < 1000; ++k) {
    int i = (int)tbt_rand(&rng, 0.0f, (float)m.count);
    if (m.proxy[i] < 0) continue;
    m.tight[i] = random_box(&rng);
    tb_tree_move_proxy(&tree, m.proxy[i], m.tight[i], (tb_vec2){0.0f, 0.0f});
  }
  check_against_brute_force(&tree, &m, 17);
  tb_tree_destroy(&tree);
}
END_TEST

static int marked_nodes(const tb_tree* tree) {
  int marked = 0;
  for (int32_t i = 0; i < tree->capacity; ++i) marked += tree->nodes[i].height > 0 && tree->nodes[i].enlarged;
  return marked;
}

/* Moves that enlarge in place (as the world's step moves its proxies) keep
 * every query right before the rebuild, and the partial rebuild leaves an
 * exact tree of about the quality of a full rebuild; other changes made
 * while nodes are marked rebuild first. */
START_TEST(enlarged_moves_and_partial_rebuild) {
  static model m;
  memset(&m, 0, sizeof m);
  tb_tree tree;
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  unsigned rng = 0x5eed5u;
  for (int i = 0; i < N_PROXIES; ++i) model_add(&tree, &m, random_box(&rng), (uint64_t)1 << (i % 3));
  ck_assert_int_eq(tb_tree_get_proxy_count(&tree), N_PROXIES);
  for (int round = 0; round < 6; ++round) {
    /* a step: every proxy drifts, a tenth of them fast and stretched along
     * their motion, a hundredth jump; round 3 moves all of them back to
     * unstretched boxes (a stretch that shrinks leaves larger ancestors) */
    int enlarged = 0;
    for (int i = 0; i < m.count; ++i) {
      tb_aabb b = m.tight[i];
      float r = tbt_rand(&rng, 0.0f, 1.0f);
      tb_vec2 disp = {0.0f, 0.0f};
      if (r < 0.01f) {
        b = random_box(&rng);
      } else {
        float speed = r < 0.11f ? 1.0f : 0.05f;
        tb_vec2 d = {tbt_rand(&rng, -speed, speed), tbt_rand(&rng, -speed, speed)};
        b = (tb_aabb){{b.lower.x + d.x, b.lower.y + d.y}, {b.upper.x + d.x, b.upper.y + d.y}};
        if (round != 3) disp = d;
      }
      m.tight[i] = b;
      enlarged += tb_tree_enlarge_proxy(&tree, m.proxy[i], b, MARGIN, disp);
    }
    ck_assert_int_gt(enlarged, N_PROXIES / 20);
    ck_assert_int_lt(enlarged, N_PROXIES);
    ck_assert(tree.enlarged);
    ck_assert_int_gt(marked_nodes(&tree), 0);
    check_against_brute_force(&tree, &m, 30 + (unsigned)round); /* loose but right */
    int nodes = tree.node_count;
    tb_tree_rebuild_enlarged(&tree);
    ck_assert(!tree.enlarged);
    ck_assert_int_eq(marked_nodes(&tree), 0);
    ck_assert_int_eq(tree.node_count, nodes);                   /* the freed internal nodes are taken back */
    check_against_brute_force(&tree, &m, 40 + (unsigned)round); /* exact again */
  }
  /* a box still inside its fat box marks nothing */
  ck_assert(!tb_tree_enlarge_proxy(&tree, m.proxy[0], m.tight[0], MARGIN, (tb_vec2){0.0f, 0.0f}));
  ck_assert(!tree.enlarged);
  /* the partial rebuilds (middle splits) kept about the quality of a full
   * one (binned perimeter heuristic): 10.0% more area here; within 15% */
  float partial = tb_tree_get_area_ratio(&tree);
  ck_assert_int_eq(tb_tree_rebuild(&tree), TB_OK);
  float full = tb_tree_get_area_ratio(&tree);
  ck_assert_msg(partial < 1.15f * full, "area ratio %g after partial rebuilds, %g after a full one", (double)partial,
                (double)full);
  /* create, destroy and move with marked nodes: each rebuilds first */
  for (int k = 0; k < 200; ++k) {
    int i = k * 37 % m.count;
    if (m.proxy[i] < 0) continue;
    m.tight[i] = random_box(&rng);
    ck_assert(tb_tree_enlarge_proxy(&tree, m.proxy[i], m.tight[i], MARGIN, (tb_vec2){0.0f, 0.0f}));
    if (k % 3 == 0) {
      ck_assert(tb_tree_destroy_proxy(&tree, m.proxy[i]));
      m.proxy[i] = -1;
      model_add(&tree, &m, random_box(&rng), 1u);
    } else if (k % 3 == 1) {
      m.tight[i] = random_box(&rng);
      ck_assert(tb_tree_move_proxy(&tree, m.proxy[i], m.tight[i], (tb_vec2){0.0f, 0.0f}));
    }
    ck_assert(tb_tree_validate(&tree));
  }
  check_against_brute_force(&tree, &m, 50);
  tb_tree_rebuild_enlarged(&tree);
  check_against_brute_force(&tree, &m, 51);
  tb_tree_destroy(&tree);
}
END_TEST

typedef struct clip_ctx {
  const tb_tree* tree;
  tb_tree_ray_input original;
  float closest;
  int32_t closest_proxy;
  int calls;
  float last_max;
  int mode; /* 0: clip, 1: stop at once, 2: ignore all, 3: return more than max */
  int problems;
} clip_ctx;

static float clip_ray(const tb_tree_ray_input* input, int32_t proxy, int32_t user_id, void* context) {
  (void)user_id;
  clip_ctx* c = context;
  c->calls += 1;
  c->problems += input->max_fraction > c->last_max; /* clipping only shortens */
  c->last_max = input->max_fraction;
  if (c->mode == 1) return 0.0f;
  if (c->mode == 2) return -1.0f;
  if (c->mode == 3) return 2.0f * input->max_fraction + 1.0f;
  /* The fat box stands in for the shape: the hit is where the ray enters it. */
  float t = INFINITY;
  c->problems += !tb_tree_ray_hits_aabb(&c->original, tb_tree_get_fat_aabb(c->tree, proxy), &t);
  c->problems += t > input->max_fraction;
  if (t < c->closest || (t == c->closest && proxy < c->closest_proxy)) {
    c->closest = t;
    c->closest_proxy = proxy;
  }
  return t > 0.0f ? t : 0.0f; /* a ray starting inside can stop at once */
}

START_TEST(ray_cast_clipping) {
  tb_tree tree;
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  unsigned rng = 99u;
  static tb_aabb tight[N_PROXIES];
  static int32_t proxy[N_PROXIES];
  for (int i = 0; i < N_PROXIES; ++i) {
    tight[i] = random_box(&rng);
    proxy[i] = tb_tree_create_proxy(&tree, tight[i], 1u, i);
  }
  int clipped_calls = 0, all_hits = 0, rays_with_hits = 0;
  for (int r = 0; r < 200; ++r) {
    tb_tree_ray_input ray = random_ray(&rng);
    /* brute force: every hit, and the nearest entry */
    float best = INFINITY;
    int hits = 0;
    for (int i = 0; i < N_PROXIES; ++i) {
      float t;
      if (tb_tree_ray_hits_aabb(&ray, tb_tree_get_fat_aabb(&tree, proxy[i]), &t)) {
        hits += 1;
        if (t < best) best = t;
      }
    }
    clip_ctx c = {&tree, ray, INFINITY, -1, 0, ray.max_fraction, 0, 0};
    ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, UINT64_MAX, clip_ray, &c), TB_OK);
    ck_assert_int_eq(c.problems, 0);
    ck_assert_int_le(c.calls, hits);
    if (hits == 0) {
      ck_assert_int_eq(c.calls, 0);
      continue;
    }
    rays_with_hits += 1;
    ck_assert_msg(c.closest == best, "ray %d: nearest %.9g, brute force %.9g", r, c.closest, best);
    clipped_calls += c.calls;
    all_hits += hits;

    /* 0 stops at the first proxy */
    clip_ctx stop = {&tree, ray, INFINITY, -1, 0, ray.max_fraction, 1, 0};
    ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, UINT64_MAX, clip_ray, &stop), TB_OK);
    ck_assert_int_eq(stop.calls, 1);
    /* < 0 ignores and > max changes nothing: every hit is reported */
    clip_ctx ignore = {&tree, ray, INFINITY, -1, 0, ray.max_fraction, 2, 0};
    ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, UINT64_MAX, clip_ray, &ignore), TB_OK);
    ck_assert_int_eq(ignore.calls, hits);
    clip_ctx more = {&tree, ray, INFINITY, -1, 0, ray.max_fraction, 3, 0};
    ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, UINT64_MAX, clip_ray, &more), TB_OK);
    ck_assert_int_eq(more.calls, hits);
  }
  ck_assert_int_gt(rays_with_hits, 100);
  /* near-first order plus clipping skips most of the boxes behind the nearest */
  ck_assert_int_lt(2 * clipped_calls, all_hits);

  /* the predicate on hand-made cases */
  tb_aabb unit = box_at(0.0f, 0.0f, 1.0f, 1.0f);
  tb_tree_ray_input r1 = {{-1.0f, 0.5f}, {4.0f, 0.0f}, 1.0f};
  float t = -1.0f;
  ck_assert(tb_tree_ray_hits_aabb(&r1, unit, &t));
  ck_assert_float_eq(t, 0.25f);
  r1.max_fraction = 0.2f; /* stops short */
  ck_assert(!tb_tree_ray_hits_aabb(&r1, unit, NULL));
  tb_tree_ray_input r2 = {{0.5f, 0.5f}, {0.0f, 0.0f}, 1.0f}; /* a point inside */
  ck_assert(tb_tree_ray_hits_aabb(&r2, unit, &t));
  ck_assert_float_eq(t, 0.0f);
  tb_tree_ray_input r3 = {{-1.0f, 1.0f}, {4.0f, 0.0f}, 1.0f}; /* grazes the top edge */
  ck_assert(tb_tree_ray_hits_aabb(&r3, unit, &t));
  tb_tree_ray_input r4 = {{-1.0f, 1.01f}, {4.0f, 0.0f}, 1.0f};
  ck_assert(!tb_tree_ray_hits_aabb(&r4, unit, &t));
  tb_tree_destroy(&tree);
}
END_TEST

START_TEST(fat_aabb_reinserts_only_when_left) {
  tb_tree tree;
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  int32_t other = tb_tree_create_proxy(&tree, box_at(5.0f, 5.0f, 1.0f, 1.0f), 1u, 7);
  int32_t p = tb_tree_create_proxy(&tree, box_at(0.0f, 0.0f, 1.0f, 1.0f), 2u, 42);
  ck_assert_int_ge(p, 0);
  ck_assert_int_ne(p, other);
  tb_aabb fat = tb_tree_get_fat_aabb(&tree, p);
  ck_assert_float_eq(fat.lower.x, -MARGIN);
  ck_assert_float_eq(fat.lower.y, -MARGIN);
  ck_assert_float_eq(fat.upper.x, 1.0f + MARGIN);
  ck_assert_float_eq(fat.upper.y, 1.0f + MARGIN);

  /* inside the margin: nothing happens */
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(0.05f, -0.05f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));
  ck_assert(same_box(fat, tb_tree_get_fat_aabb(&tree, p)));
  /* out of it: re-inserted with a new fat box around the new tight box, same id */
  ck_assert(tb_tree_move_proxy(&tree, p, box_at(0.15f, 0.0f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));
  fat = tb_tree_get_fat_aabb(&tree, p);
  ck_assert_float_eq(fat.lower.x, 0.15f - MARGIN);
  ck_assert_float_eq(fat.upper.x, (0.15f + 1.0f) + MARGIN);
  ck_assert_int_eq(tb_tree_get_user_id(&tree, p), 42);
  ck_assert_uint_eq(tb_tree_get_category_bits(&tree, p), 2u);
  ck_assert(tb_tree_validate(&tree));

  /* a predicted displacement stretches the fat box along it */
  ck_assert(tb_tree_move_proxy(&tree, p, box_at(10.0f, 0.0f, 1.0f, 1.0f), (tb_vec2){4.0f, -1.0f}));
  fat = tb_tree_get_fat_aabb(&tree, p);
  ck_assert_float_eq(fat.lower.x, 10.0f - MARGIN);
  ck_assert_float_eq(fat.upper.x, 11.0f + MARGIN + 4.0f);
  ck_assert_float_eq(fat.lower.y, -MARGIN - 1.0f);
  ck_assert_float_eq(fat.upper.y, 1.0f + MARGIN);
  /* moving along the prediction stays inside */
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(12.0f, -0.5f, 1.0f, 1.0f), (tb_vec2){4.0f, -1.0f}));
  /* stopping: the stretched box is more than twice the needed one, so it shrinks */
  ck_assert(tb_tree_move_proxy(&tree, p, box_at(12.0f, -0.5f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));
  fat = tb_tree_get_fat_aabb(&tree, p);
  ck_assert_float_eq(fat.upper.x, 13.0f + MARGIN);
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(12.0f, -0.5f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));

  /* a tree with no margin re-inserts on any move out of the box */
  tb_tree tight;
  ck_assert_int_eq(tb_tree_create(&tight, 0.0f), TB_OK);
  int32_t q = tb_tree_create_proxy(&tight, box_at(0.0f, 0.0f, 1.0f, 1.0f), 1u, 0);
  ck_assert(!tb_tree_move_proxy(&tight, q, box_at(0.0f, 0.0f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));
  ck_assert(tb_tree_move_proxy(&tight, q, box_at(0.001f, 0.0f, 1.0f, 1.0f), (tb_vec2){0.0f, 0.0f}));
  tb_tree_destroy(&tight);
  tb_tree_destroy(&tree);
}
END_TEST

START_TEST(height_bounds) {
  tb_tree tree;
  unsigned rng = 7u;
  /* random */
  static int32_t ids[N_PROXIES];
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i) ids[i] = tb_tree_create_proxy(&tree, random_box(&rng), 1u, i);
  check_height(&tree, "random");
  /* remove every other one, in creation order */
  int failed = 0;
  for (int i = 0; i < N_PROXIES; i += 2) failed += !tb_tree_destroy_proxy(&tree, ids[i]);
  ck_assert_int_eq(failed, 0);
  ck_assert_int_eq(tb_tree_get_proxy_count(&tree), N_PROXIES / 2);
  check_height(&tree, "random, half removed");
  tb_tree_destroy(&tree);

  /* sorted: along a line, left to right */
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i) tb_tree_create_proxy(&tree, box_at((float)i, 0.0f, 0.5f, 0.5f), 1u, i);
  check_height(&tree, "sorted line");
  tb_tree_destroy(&tree);
  /* sorted: right to left, overlapping neighbours */
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i) tb_tree_create_proxy(&tree, box_at(-0.1f * (float)i, 0.0f, 0.5f, 0.5f), 1u, i);
  check_height(&tree, "sorted overlapping line");
  tb_tree_destroy(&tree);
  /* sorted: a grid, row by row */
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i)
    tb_tree_create_proxy(&tree, box_at((float)(i % 100), (float)(i / 100), 0.8f, 0.8f), 1u, i);
  check_height(&tree, "sorted grid");
  tb_tree_destroy(&tree);
  /* identical boxes: every sibling choice costs the same */
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i) tb_tree_create_proxy(&tree, box_at(0.0f, 0.0f, 1.0f, 1.0f), 1u, i);
  check_height(&tree, "identical");
  tb_tree_destroy(&tree);
  /* outward spiral: each new box outside all others */
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);
  for (int i = 0; i < N_PROXIES; ++i) {
    float a = 0.3f * sqrtf((float)i) * 6.0f, r = 2.0f + 0.5f * sqrtf((float)i);
    tb_tree_create_proxy(&tree, box_at(r * cosf(a), r * sinf(a), 0.5f, 0.5f), 1u, i);
  }
  check_height(&tree, "spiral");
  tb_tree_destroy(&tree);
}
END_TEST

static void build_sequence(tb_tree* tree, unsigned seed) {
  ck_assert_int_eq(tb_tree_create(tree, MARGIN), TB_OK);
  unsigned rng = seed;
  int32_t ids[3000];
  for (int i = 0; i < 3000; ++i) ids[i] = tb_tree_create_proxy(tree, random_box(&rng), (uint64_t)i, i);
  for (int k = 0; k < 3000; ++k) {
    int i = (int)tbt_rand(&rng, 0.0f, 3000.0f);
    if (ids[i] < 0) continue;
    if (k % 10 == 0) {
      tb_tree_destroy_proxy(tree, ids[i]);
      ids[i] = -1;
    } else {
      tb_tree_move_proxy(tree, ids[i], random_box(&rng), (tb_vec2){tbt_rand(&rng, -1.0f, 1.0f), 0.0f});
    }
  }
  for (int i = 0; i < 300; ++i) tb_tree_create_proxy(tree, random_box(&rng), 1u, 5000 + i);
}

START_TEST(deterministic) {
  tb_tree a, b;
  build_sequence(&a, 2024u);
  build_sequence(&b, 2024u);
  ck_assert(tb_tree_validate(&a));
  ck_assert_int_eq(a.root, b.root);
  ck_assert_int_eq(a.capacity, b.capacity);
  ck_assert_int_eq(a.node_count, b.node_count);
  ck_assert_int_eq(a.free_list, b.free_list);
  ck_assert_int_eq(a.proxy_count, b.proxy_count);
  int differences = 0;
  for (int32_t i = 0; i < a.capacity; ++i) {
    const tb_tree_node *x = &a.nodes[i], *y = &b.nodes[i];
    differences += x->height != y->height || x->parent != y->parent;
    if (x->height < 0) continue;
    differences += x->child1 != y->child1 || x->child2 != y->child2 || x->user_id != y->user_id ||
                   x->category_bits != y->category_bits || !same_box(x->aabb, y->aabb);
  }
  ck_assert_int_eq(differences, 0);
  /* rebuild is deterministic too */
  ck_assert_int_eq(tb_tree_rebuild(&a), TB_OK);
  ck_assert_int_eq(tb_tree_rebuild(&b), TB_OK);
  ck_assert_int_eq(a.root, b.root);
  for (int32_t i = 0; i < a.capacity; ++i)
    differences += a.nodes[i].parent != b.nodes[i].parent || a.nodes[i].child1 != b.nodes[i].child1;
  ck_assert_int_eq(differences, 0);
  tb_tree_destroy(&a);
  tb_tree_destroy(&b);
}
END_TEST

static bool count_query(int32_t proxy, int32_t user_id, void* context) {
  (void)proxy;
  (void)user_id;
  *(int*)context += 1;
  return true;
}

static bool stop_query(int32_t proxy, int32_t user_id, void* context) {
  (void)proxy;
  (void)user_id;
  *(int*)context += 1;
  return false;
}

static float count_ray(const tb_tree_ray_input* input, int32_t proxy, int32_t user_id, void* context) {
  (void)proxy;
  (void)user_id;
  *(int*)context += 1;
  return input->max_fraction;
}

START_TEST(small_trees_and_bad_input) {
  const float nan = NAN;
  tb_tree tree;
  ck_assert_int_eq(tb_tree_create(NULL, MARGIN), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_create(&tree, nan), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_tree_create(&tree, -0.1f), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_tree_create(&tree, INFINITY), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_tree_create(&tree, MARGIN), TB_OK);

  /* empty */
  tb_aabb everything = box_at(-1e6f, -1e6f, 2e6f, 2e6f);
  int calls = 0;
  ck_assert(tb_tree_validate(&tree));
  ck_assert_int_eq(tb_tree_get_height(&tree), 0);
  ck_assert_float_eq(tb_tree_get_area_ratio(&tree), 0.0f);
  ck_assert_int_eq(tb_tree_query(&tree, everything, UINT64_MAX, count_query, &calls), TB_OK);
  ck_assert_int_eq(calls, 0);
  ck_assert_int_eq(tb_tree_rebuild(&tree), TB_OK);

  /* bad proxies change nothing */
  ck_assert_int_eq(tb_tree_create_proxy(NULL, box_at(0, 0, 1, 1), 1u, 0), TB_TREE_NULL);
  ck_assert_int_eq(tb_tree_create_proxy(&tree, box_at(nan, 0, 1, 1), 1u, 0), TB_TREE_NULL);
  ck_assert_int_eq(tb_tree_create_proxy(&tree, box_at(0, 0, INFINITY, 1), 1u, 0), TB_TREE_NULL);
  ck_assert_int_eq(tb_tree_create_proxy(&tree, box_at(0, 0, -1, 1), 1u, 0), TB_TREE_NULL); /* inverted */
  ck_assert_int_eq(tb_tree_create_proxy(&tree, box_at(2e7f, 0, 1, 1), 1u, 0), TB_TREE_NULL);
  ck_assert_int_eq(tb_tree_get_proxy_count(&tree), 0);
  ck_assert(tb_tree_validate(&tree));

  /* one proxy, then two */
  int32_t p = tb_tree_create_proxy(&tree, box_at(0, 0, 1, 1), 1u, 10);
  ck_assert(tb_tree_validate(&tree));
  ck_assert_int_eq(tb_tree_get_height(&tree), 0);
  int32_t q = tb_tree_create_proxy(&tree, box_at(3, 0, 1, 1), 2u, 11);
  ck_assert(tb_tree_validate(&tree));
  ck_assert_int_eq(tb_tree_get_height(&tree), 1);
  ck_assert_float_eq(tb_tree_get_area_ratio(&tree), 1.0f);
  ck_assert(tb_tree_move_proxy(&tree, p, box_at(-5, 0, 1, 1), (tb_vec2){0, 0}));
  ck_assert(tb_tree_validate(&tree));

  /* bad moves and ids */
  tb_aabb before = tb_tree_get_fat_aabb(&tree, p);
  ck_assert(!tb_tree_move_proxy(NULL, p, box_at(9, 9, 1, 1), (tb_vec2){0, 0}));
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(nan, 9, 1, 1), (tb_vec2){0, 0}));
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(9, 9, 1, 1), (tb_vec2){nan, 0}));
  ck_assert(!tb_tree_move_proxy(&tree, p, box_at(9, 9, 1, -1), (tb_vec2){0, 0}));
  ck_assert(same_box(before, tb_tree_get_fat_aabb(&tree, p)));
  int32_t internal = tree.nodes[p].parent; /* an internal node is not a proxy */
  const int32_t bad_ids[] = {-1, -7, internal, 1000000};
  for (size_t k = 0; k < sizeof bad_ids / sizeof bad_ids[0]; ++k) {
    int32_t id = bad_ids[k];
    ck_assert(!tb_tree_is_proxy(&tree, id));
    ck_assert(!tb_tree_move_proxy(&tree, id, box_at(9, 9, 1, 1), (tb_vec2){0, 0}));
    ck_assert(!tb_tree_destroy_proxy(&tree, id));
    ck_assert_int_eq(tb_tree_get_user_id(&tree, id), TB_TREE_NULL);
    ck_assert(tb_tree_get_category_bits(&tree, id) == 0);
    ck_assert(!tb_tree_set_category_bits(&tree, id, 1u));
    ck_assert(!tb_tree_set_apart_key(&tree, id, 3));
    ck_assert_float_eq(tb_tree_get_fat_aabb(&tree, id).upper.x, 0.0f);
  }
  ck_assert(tb_tree_validate(&tree));

  /* bad queries: NULL callbacks are errors, never calls */
  tb_tree_ray_input ray = {{-10, 0.5f}, {20, 0}, 1.0f};
  ck_assert_int_eq(tb_tree_query(&tree, everything, UINT64_MAX, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_query(NULL, everything, UINT64_MAX, count_query, &calls), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_query(&tree, box_at(nan, 0, 1, 1), UINT64_MAX, count_query, &calls),
                   TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_tree_query_apart(&tree, everything, UINT64_MAX, 5, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_query_apart(&tree, box_at(0, nan, 1, 1), UINT64_MAX, 5, count_query, &calls),
                   TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, UINT64_MAX, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_ray_cast(&tree, NULL, UINT64_MAX, count_ray, &calls), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_tree_ray_cast(NULL, &ray, UINT64_MAX, count_ray, &calls), TB_ERR_NULL_ARGUMENT);
  tb_tree_ray_input bad = ray;
  bad.max_fraction = -1.0f;
  ck_assert_int_eq(tb_tree_ray_cast(&tree, &bad, UINT64_MAX, count_ray, &calls), TB_ERR_INVALID_ARGUMENT);
  bad = ray;
  bad.translation.y = nan;
  ck_assert_int_eq(tb_tree_ray_cast(&tree, &bad, UINT64_MAX, count_ray, &calls), TB_ERR_INVALID_ARGUMENT);
  ck_assert(!tb_tree_ray_hits_aabb(&bad, everything, NULL));
  ck_assert(!tb_tree_ray_hits_aabb(NULL, everything, NULL));
  ck_assert_int_eq(calls, 0);

  /* good ones: stop, masks */
  ck_assert_int_eq(tb_tree_query(&tree, everything, UINT64_MAX, count_query, &calls), TB_OK);
  ck_assert_int_eq(calls, 2);
  calls = 0;
  ck_assert_int_eq(tb_tree_query(&tree, everything, UINT64_MAX, stop_query, &calls), TB_OK);
  ck_assert_int_eq(calls, 1);
  calls = 0;
  ck_assert_int_eq(tb_tree_query(&tree, everything, 2u, count_query, &calls), TB_OK);
  ck_assert_int_eq(calls, 1);
  calls = 0;
  ck_assert_int_eq(tb_tree_query(&tree, everything, 4u, count_query, &calls), TB_OK);
  ck_assert_int_eq(calls, 0);
  ck_assert_int_eq(tb_tree_ray_cast(&tree, &ray, 2u, count_ray, &calls), TB_OK);
  ck_assert_int_eq(calls, 1);

  /* back to empty and reuse */
  ck_assert(tb_tree_destroy_proxy(&tree, p));
  ck_assert(!tb_tree_destroy_proxy(&tree, p));
  ck_assert(tb_tree_validate(&tree));
  ck_assert(tb_tree_destroy_proxy(&tree, q));
  ck_assert(tb_tree_validate(&tree));
  ck_assert_int_eq(tb_tree_get_proxy_count(&tree), 0);
  ck_assert_int_eq(tb_tree_get_height(&tree), 0);
  ck_assert_int_ge(tb_tree_create_proxy(&tree, box_at(0, 0, 1, 1), 1u, 12), 0);
  ck_assert(tb_tree_validate(&tree));
  tb_tree_destroy(&tree);
  ck_assert(tb_tree_validate(&tree)); /* destroyed: empty and usable */
  ck_assert_int_ge(tb_tree_create_proxy(&tree, box_at(0, 0, 1, 1), 1u, 12), 0);
  tb_tree_destroy(&tree);
  tb_tree_destroy(&tree);
  tb_tree_destroy(NULL);
}
END_TEST

static Suite* tree_suite(void) {
  Suite* s = suite_create("tree");
  TCase* tc = tcase_create("tree");
  tcase_set_timeout(tc, 120); /* generous for sanitizer builds; about a second at -O2 */
  tcase_add_test(tc, queries_match_brute_force);
  tcase_add_test(tc, enlarged_moves_and_partial_rebuild);
  tcase_add_test(tc, ray_cast_clipping);
  tcase_add_test(tc, fat_aabb_reinserts_only_when_left);
  tcase_add_test(tc, height_bounds);
  tcase_add_test(tc, deterministic);
  tcase_add_test(tc, small_trees_and_bad_input);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(tree_suite)
