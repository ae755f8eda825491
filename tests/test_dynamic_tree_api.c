/* The public dynamic AABB tree (tb_dynamic_tree, issue 24): queries and ray
 * casts against brute force through inserts, moves, removals and a rebuild;
 * user data and category bits; fat boxes and re-insertion; the height bound;
 * the lock against changes from callbacks; bad trees, ids and boxes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

#define N 600
#define WORLD 100.0f

typedef struct item {
  tb_aabb box;   /* the tight box the game gave */
  int32_t proxy; /* TB_NULL_PROXY: destroyed */
  uint64_t bits;
} item;

static item items[N];

static tb_aabb random_box(unsigned* rng) {
  float x = tbt_rand(rng, -WORLD, WORLD), y = tbt_rand(rng, -WORLD, WORLD);
  float w = tbt_rand(rng, 0.1f, 4.0f), h = tbt_rand(rng, 0.1f, 4.0f);
  return (tb_aabb){{x, y}, {x + w, y + h}};
}

static bool overlaps(tb_aabb a, tb_aabb b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

static bool contains(tb_aabb outer, tb_aabb inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y;
}

/* Entry fraction of the segment o + t d, t in [0, tmax], into box b (the
 * test's own slab test, in double); negative when it misses. */
static double segment_enters(tb_vec2 o, tb_vec2 d, double tmax, tb_aabb b) {
  double lo = 0.0, hi = tmax;
  const double os[2] = {o.x, o.y}, ds[2] = {d.x, d.y}, l[2] = {b.lower.x, b.lower.y}, u[2] = {b.upper.x, b.upper.y};
  for (int k = 0; k < 2; ++k) {
    if (ds[k] == 0.0) {
      if (os[k] < l[k] || os[k] > u[k]) return -1.0;
      continue;
    }
    double t1 = (l[k] - os[k]) / ds[k], t2 = (u[k] - os[k]) / ds[k];
    if (t1 > t2) {
      double s = t1;
      t1 = t2;
      t2 = s;
    }
    if (t1 > lo) lo = t1;
    if (t2 < hi) hi = t2;
    if (lo > hi) return -1.0;
  }
  return lo;
}

/* ---- query and ray cast against brute force --------------------------------- */

typedef struct found {
  int count, wrong_data;
  bool seen[N];
} found;

static bool collect(int32_t proxy, void* user_data, void* context) {
  found* f = context;
  item* it = user_data;
  if (it < items || it >= items + N || it->proxy != proxy) {
    f->wrong_data += 1;
    return true;
  }
  f->seen[it - items] = true;
  f->count += 1;
  return true;
}

/* Every query box finds exactly the live items whose fat box overlaps it and
 * whose bits pass the mask; with margin 0 the fat box is the item's box. */
static void check_queries(tb_dynamic_tree* t, unsigned* rng, float margin) {
  for (int q = 0; q < 100; ++q) {
    tb_aabb box = random_box(rng);
    box.upper.x += 10.0f;
    uint64_t mask = (q & 1) ? UINT64_MAX : 2u;
    static found f;
    memset(&f, 0, sizeof f);
    ck_assert_int_eq(tb_dynamic_tree_query(t, box, mask, collect, &f), TB_OK);
    ck_assert_int_eq(f.wrong_data, 0);
    int want = 0;
    for (int i = 0; i < N; ++i) {
      if (items[i].proxy == TB_NULL_PROXY) continue;
      tb_aabb fat = {{items[i].box.lower.x - margin, items[i].box.lower.y - margin},
                     {items[i].box.upper.x + margin, items[i].box.upper.y + margin}};
      bool in = overlaps(fat, box) && (items[i].bits & mask) != 0;
      /* a moved proxy's fat box may be larger than this one: it must
       * contain it, and the query sees at least the items we expect */
      if (in) {
        want += 1;
        ck_assert_msg(f.seen[i], "query %d missed item %d", q, i);
      } else if (f.seen[i]) {
        ck_assert(overlaps(tb_dynamic_tree_get_fat_aabb(t, items[i].proxy), box));
        want += 1;
      }
    }
    ck_assert_int_eq(f.count, want);
  }
}

typedef struct closest {
  double fraction;
  int32_t proxy;
  int calls, wrong_data;
} closest;

/* Casts against the item's own box and clips the ray to the hit. */
static float clip_to_item(const tb_dynamic_tree_ray_input* in, int32_t proxy, void* user_data, void* context) {
  closest* c = context;
  item* it = user_data;
  c->calls += 1;
  if (it->proxy != proxy) c->wrong_data += 1;
  double f = segment_enters(in->origin, in->translation, in->max_fraction, it->box);
  if (f < 0.0) return -1.0f;
  if (f < c->fraction) {
    c->fraction = f;
    c->proxy = proxy;
  }
  return (float)f;
}

static void check_rays(tb_dynamic_tree* t, unsigned* rng) {
  for (int q = 0; q < 100; ++q) {
    tb_vec2 o = {tbt_rand(rng, -WORLD, WORLD), tbt_rand(rng, -WORLD, WORLD)};
    tb_vec2 d = {tbt_rand(rng, -80, 80), tbt_rand(rng, -80, 80)};
    closest c = {2.0, TB_NULL_PROXY, 0, 0};
    tb_dynamic_tree_ray_input in = {o, d, 1.0f};
    ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, UINT64_MAX, clip_to_item, &c), TB_OK);
    ck_assert_int_eq(c.wrong_data, 0);
    double best = 2.0;
    for (int i = 0; i < N; ++i) {
      if (items[i].proxy == TB_NULL_PROXY) continue;
      double f = segment_enters(o, d, 1.0, items[i].box);
      if (f >= 0.0 && f < best) best = f;
    }
    /* the clip is a float of the double fraction: equal within its rounding */
    if (best > 1.0)
      ck_assert_msg(c.proxy == TB_NULL_PROXY, "ray %d hit something brute force misses", q);
    else
      ck_assert_msg(c.proxy != TB_NULL_PROXY && fabs(c.fraction - best) <= 1e-6, "ray %d: %g, brute force %g", q,
                    c.fraction, best);
  }
}

static void insert_all(tb_dynamic_tree* t, unsigned* rng) {
  for (int i = 0; i < N; ++i) {
    items[i].box = random_box(rng);
    items[i].bits = (i % 3 == 0) ? 2u : 1u;
    items[i].proxy = tb_dynamic_tree_create_proxy(t, items[i].box, items[i].bits, &items[i]);
    ck_assert_int_ge(items[i].proxy, 0);
  }
}

START_TEST(queries_and_rays_match_brute_force) {
  unsigned rng = 12345u;
  tb_dynamic_tree* t = tb_dynamic_tree_create(0.0f);
  ck_assert_ptr_nonnull(t);
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), 0);
  ck_assert_int_eq(tb_dynamic_tree_get_height(t), 0);
  insert_all(t, &rng);
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), N);
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  /* AVL: height <= 1.44 log2(n + 2) - 0.33 (Adelson-Velsky and Landis) */
  ck_assert_int_le(tb_dynamic_tree_get_height(t), (int)(1.4405 * log2(N + 2.0) - 0.328));
  for (int i = 0; i < N; ++i) {
    ck_assert_ptr_eq(tb_dynamic_tree_get_user_data(t, items[i].proxy), &items[i]);
    ck_assert(tb_dynamic_tree_get_category_bits(t, items[i].proxy) == items[i].bits);
    tb_aabb fat = tb_dynamic_tree_get_fat_aabb(t, items[i].proxy);
    ck_assert(memcmp(&fat, &items[i].box, sizeof fat) == 0); /* margin 0: the box itself */
  }
  check_queries(t, &rng, 0.0f);
  check_rays(t, &rng);
  /* remove a third, move a third far away (teleports) */
  for (int i = 0; i < N; i += 3) {
    ck_assert_int_eq(tb_dynamic_tree_destroy_proxy(t, items[i].proxy), TB_OK);
    items[i].proxy = TB_NULL_PROXY;
  }
  for (int i = 1; i < N; i += 3) {
    items[i].box = random_box(&rng);
    bool reinserted = false;
    ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, items[i].proxy, items[i].box, (tb_vec2){0, 0}, &reinserted), TB_OK);
  }
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), N - (N + 2) / 3);
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  check_queries(t, &rng, 0.0f);
  check_rays(t, &rng);
  /* a rebuild keeps ids, boxes and user data, and lowers (or keeps) the cost */
  float before = tb_dynamic_tree_get_area_ratio(t);
  ck_assert_int_eq(tb_dynamic_tree_rebuild(t), TB_OK);
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  ck_assert(tb_dynamic_tree_get_area_ratio(t) <= before * 1.05f);
  for (int i = 0; i < N; ++i)
    if (items[i].proxy != TB_NULL_PROXY) ck_assert_ptr_eq(tb_dynamic_tree_get_user_data(t, items[i].proxy), &items[i]);
  check_queries(t, &rng, 0.0f);
  check_rays(t, &rng);
  ck_assert_int_eq(tb_dynamic_tree_destroy(t), TB_OK);
}
END_TEST

/* With a margin, small moves stay inside the fat box (no re-insertion); a
 * move out of it re-inserts with a new fat box around the new one. */
START_TEST(fat_boxes_and_moves) {
  const float margin = 0.25f;
  tb_dynamic_tree* t = tb_dynamic_tree_create(margin);
  tb_aabb box = {{0, 0}, {1, 1}};
  int32_t p = tb_dynamic_tree_create_proxy(t, box, 1, NULL);
  int32_t other = tb_dynamic_tree_create_proxy(t, (tb_aabb){{5, 5}, {6, 6}}, 1, NULL);
  ck_assert(p >= 0 && other >= 0 && p != other);
  tb_aabb fat = tb_dynamic_tree_get_fat_aabb(t, p);
  ck_assert_near(fat.lower.x, -0.25, 0.0);
  ck_assert_near(fat.upper.y, 1.25, 0.0);
  bool reinserted = true;
  tb_aabb moved = {{0.2f, 0.2f}, {1.2f, 1.2f}}; /* within the fat box */
  ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, p, moved, (tb_vec2){0, 0}, &reinserted), TB_OK);
  ck_assert(!reinserted);
  fat = tb_dynamic_tree_get_fat_aabb(t, p);
  ck_assert_near(fat.lower.x, -0.25, 0.0);
  moved = (tb_aabb){{0.3f, 0.0f}, {1.3f, 1.0f}}; /* out by 0.05 on the right */
  ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, p, moved, (tb_vec2){2, 0}, &reinserted), TB_OK);
  ck_assert(reinserted);
  fat = tb_dynamic_tree_get_fat_aabb(t, p);
  /* grown by the margin and stretched 2 m along +x, the predicted motion */
  ck_assert_near(fat.lower.x, 0.05, 1e-6);
  ck_assert_near(fat.upper.x, 3.55, 1e-6);
  ck_assert(contains(fat, moved));
  ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, p, moved, (tb_vec2){0, 0}, NULL), TB_OK);
  /* the id stays; ids of live proxies never collide */
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), 2);
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  /* user data and bits can be changed */
  int x;
  ck_assert_int_eq(tb_dynamic_tree_set_user_data(t, p, &x), TB_OK);
  ck_assert_ptr_eq(tb_dynamic_tree_get_user_data(t, p), &x);
  ck_assert_int_eq(tb_dynamic_tree_set_category_bits(t, p, 4), TB_OK);
  ck_assert(tb_dynamic_tree_get_category_bits(t, p) == 4);
  found f;
  memset(&f, 0, sizeof f);
  ck_assert_int_eq(tb_dynamic_tree_query(t, (tb_aabb){{-10, -10}, {10, 10}}, 4, collect, &f), TB_OK);
  ck_assert_int_eq(f.count + f.wrong_data, 1); /* only p passes the mask */
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  tb_dynamic_tree_destroy(t);
}
END_TEST

/* ---- the lock and bad input ------------------------------------------------- */

typedef struct attack {
  tb_dynamic_tree* t;
  int32_t proxy;
  tb_result create, destroy, move, rebuild, destroy_tree, set_data, set_bits, nested;
  int calls;
} attack;

static bool count_all(int32_t proxy, void* user_data, void* context) {
  (void)proxy, (void)user_data;
  *(int*)context += 1;
  return true;
}

static bool attack_tree(int32_t proxy, void* user_data, void* context) {
  (void)user_data;
  attack* a = context;
  a->calls += 1;
  a->create = tb_dynamic_tree_create_proxy(a->t, (tb_aabb){{0, 0}, {1, 1}}, 1, NULL) == TB_NULL_PROXY ? tb_last_result()
                                                                                                      : TB_OK;
  a->destroy = tb_dynamic_tree_destroy_proxy(a->t, proxy);
  a->move = tb_dynamic_tree_move_proxy(a->t, proxy, (tb_aabb){{50, 50}, {51, 51}}, (tb_vec2){0, 0}, NULL);
  a->rebuild = tb_dynamic_tree_rebuild(a->t);
  a->destroy_tree = tb_dynamic_tree_destroy(a->t);
  a->set_data = tb_dynamic_tree_set_user_data(a->t, proxy, a);
  a->set_bits = tb_dynamic_tree_set_category_bits(a->t, proxy, 8);
  int n = 0;
  a->nested = tb_dynamic_tree_query(a->t, (tb_aabb){{-100, -100}, {100, 100}}, UINT64_MAX, count_all, &n);
  if (n != 3) a->nested = TB_ERR_NUMERIC;
  return true;
}

static float attack_ray(const tb_dynamic_tree_ray_input* in, int32_t proxy, void* user_data, void* context) {
  attack_tree(proxy, user_data, context);
  return in->max_fraction;
}

static void assert_refused(const attack* a, int calls) {
  ck_assert_int_eq(a->calls, calls);
  ck_assert_int_eq(a->create, TB_ERR_LOCKED);
  ck_assert_int_eq(a->destroy, TB_ERR_LOCKED);
  ck_assert_int_eq(a->move, TB_ERR_LOCKED);
  ck_assert_int_eq(a->rebuild, TB_ERR_LOCKED);
  ck_assert_int_eq(a->destroy_tree, TB_ERR_LOCKED);
  ck_assert_int_eq(a->set_data, TB_ERR_LOCKED);
  ck_assert_int_eq(a->set_bits, TB_ERR_LOCKED);
  ck_assert_int_eq(a->nested, TB_OK);
}

START_TEST(changes_from_callbacks_are_refused) {
  tb_dynamic_tree* t = tb_dynamic_tree_create(0.1f);
  int32_t ids[3];
  for (int i = 0; i < 3; ++i)
    ids[i] = tb_dynamic_tree_create_proxy(t, (tb_aabb){{i * 3.0f, 0}, {i * 3.0f + 1, 1}}, 1, NULL);
  tb_aabb fat[3];
  for (int i = 0; i < 3; ++i) fat[i] = tb_dynamic_tree_get_fat_aabb(t, ids[i]);
  attack a = {.t = t};
  ck_assert_int_eq(tb_dynamic_tree_query(t, (tb_aabb){{-1, -1}, {10, 2}}, UINT64_MAX, attack_tree, &a), TB_OK);
  assert_refused(&a, 3);
  a = (attack){.t = t};
  tb_dynamic_tree_ray_input in = {{-5, 0.5f}, {20, 0}, 1.0f};
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, UINT64_MAX, attack_ray, &a), TB_OK);
  assert_refused(&a, 3);
  /* nothing changed, and the tree is usable again */
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), 3);
  for (int i = 0; i < 3; ++i) {
    tb_aabb now = tb_dynamic_tree_get_fat_aabb(t, ids[i]);
    ck_assert(memcmp(&now, &fat[i], sizeof now) == 0);
    ck_assert_ptr_null(tb_dynamic_tree_get_user_data(t, ids[i]));
    ck_assert(tb_dynamic_tree_get_category_bits(t, ids[i]) == 1);
  }
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  ck_assert_int_eq(tb_dynamic_tree_destroy_proxy(t, ids[0]), TB_OK);
  ck_assert_int_eq(tb_dynamic_tree_destroy(t), TB_OK);
}
END_TEST

static bool stop_at_once(int32_t proxy, void* user_data, void* context) {
  (void)proxy, (void)user_data;
  *(int*)context += 1;
  return false;
}

static float stop_ray(const tb_dynamic_tree_ray_input* in, int32_t proxy, void* user_data, void* context) {
  (void)in, (void)proxy, (void)user_data;
  *(int*)context += 1;
  return 0.0f;
}

START_TEST(callbacks_stop_the_traversal) {
  tb_dynamic_tree* t = tb_dynamic_tree_create(0.0f);
  for (int i = 0; i < 10; ++i) tb_dynamic_tree_create_proxy(t, (tb_aabb){{(float)i, 0}, {i + 0.5f, 1}}, 1, NULL);
  int n = 0;
  ck_assert_int_eq(tb_dynamic_tree_query(t, (tb_aabb){{-1, -1}, {20, 2}}, UINT64_MAX, stop_at_once, &n), TB_OK);
  ck_assert_int_eq(n, 1);
  n = 0;
  tb_dynamic_tree_ray_input in = {{-1, 0.5f}, {20, 0}, 1.0f};
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, UINT64_MAX, stop_ray, &n), TB_OK);
  ck_assert_int_eq(n, 1);
  /* a mask no proxy passes sees nothing */
  n = 0;
  ck_assert_int_eq(tb_dynamic_tree_query(t, (tb_aabb){{-1, -1}, {20, 2}}, 2, count_all, &n), TB_OK);
  ck_assert_int_eq(n, 0);
  tb_dynamic_tree_destroy(t);
}
END_TEST

START_TEST(bad_trees_ids_and_boxes) {
  tb_dynamic_tree* t = tb_dynamic_tree_create(0.1f);
  int32_t p = tb_dynamic_tree_create_proxy(t, (tb_aabb){{0, 0}, {1, 1}}, 1, NULL);
  int32_t dead = tb_dynamic_tree_create_proxy(t, (tb_aabb){{3, 0}, {4, 1}}, 1, NULL);
  ck_assert_int_eq(tb_dynamic_tree_destroy_proxy(t, dead), TB_OK);
  tb_aabb fat = tb_dynamic_tree_get_fat_aabb(t, p);
  const int32_t bad_ids[] = {TB_NULL_PROXY, -7, dead, 1000000, INT32_MAX};
  for (int i = 0; i < 5; ++i) {
    int32_t id = bad_ids[i];
    ck_assert_int_eq(tb_dynamic_tree_destroy_proxy(t, id), TB_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "proxy"));
    ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, id, fat, (tb_vec2){0, 0}, NULL), TB_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(tb_dynamic_tree_set_user_data(t, id, t), TB_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(tb_dynamic_tree_set_category_bits(t, id, 3), TB_ERR_INVALID_ARGUMENT);
    tb_clear_error();
    ck_assert_ptr_null(tb_dynamic_tree_get_user_data(t, id));
    ck_assert_int_eq(tb_last_result(), TB_ERR_INVALID_ARGUMENT);
    tb_aabb z = tb_dynamic_tree_get_fat_aabb(t, id);
    ck_assert(z.lower.x == 0 && z.upper.y == 0);
    ck_assert(tb_dynamic_tree_get_category_bits(t, id) == 0);
  }
  const tb_aabb bad_boxes[] = {
      {{NAN, 0}, {1, 1}}, {{0, 0}, {INFINITY, 1}}, {{2, 0}, {1, 1}}, {{0, 0}, {1.1e7f, 1}}, {{-2e7f, 0}, {1, 1}}};
  for (int i = 0; i < 5; ++i) {
    ck_assert_int_eq(tb_dynamic_tree_create_proxy(t, bad_boxes[i], 1, NULL), TB_NULL_PROXY);
    ck_assert_int_eq(tb_last_result(), TB_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "aabb"));
    ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, p, bad_boxes[i], (tb_vec2){0, 0}, NULL), TB_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(tb_dynamic_tree_query(t, bad_boxes[i], 1, count_all, NULL), TB_ERR_INVALID_ARGUMENT);
  }
  ck_assert_int_eq(tb_dynamic_tree_move_proxy(t, p, fat, (tb_vec2){NAN, 0}, NULL), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "displacement"));
  /* rays: NULL input or callback, bad numbers */
  tb_dynamic_tree_ray_input in = {{0, 0}, {1, 0}, 1.0f};
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, NULL, 1, stop_ray, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, 1, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_query(t, fat, 1, NULL, NULL), TB_ERR_NULL_ARGUMENT);
  const float bad_fractions[] = {-0.5f, NAN, INFINITY, 2e7f};
  for (int i = 0; i < 4; ++i) {
    in.max_fraction = bad_fractions[i];
    ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, 1, stop_ray, NULL), TB_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "max_fraction"));
  }
  in = (tb_dynamic_tree_ray_input){{NAN, 0}, {1, 0}, 1.0f};
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, 1, stop_ray, NULL), TB_ERR_INVALID_ARGUMENT);
  in = (tb_dynamic_tree_ray_input){{0, 0}, {1e30f, 0}, 1.0f};
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(t, &in, 1, stop_ray, NULL), TB_ERR_INVALID_ARGUMENT);
  /* margins */
  const float bad_margins[] = {-0.1f, NAN, INFINITY, 2e7f};
  for (int i = 0; i < 4; ++i) {
    ck_assert_ptr_null(tb_dynamic_tree_create(bad_margins[i]));
    ck_assert_int_eq(tb_last_result(), TB_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(tb_last_error(), "margin"));
  }
  /* a NULL tree everywhere */
  ck_assert_int_eq(tb_dynamic_tree_destroy(NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_create_proxy(NULL, fat, 1, NULL), TB_NULL_PROXY);
  ck_assert_int_eq(tb_last_result(), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_destroy_proxy(NULL, p), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_move_proxy(NULL, p, fat, (tb_vec2){0, 0}, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_rebuild(NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_query(NULL, fat, 1, count_all, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_ray_cast(NULL, &in, 1, stop_ray, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_validate(NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_get_height(NULL), 0);
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(NULL), 0);
  ck_assert(tb_dynamic_tree_get_area_ratio(NULL) == 0.0f);
  ck_assert_ptr_null(tb_dynamic_tree_get_user_data(NULL, p));
  ck_assert_int_eq(tb_dynamic_tree_set_user_data(NULL, p, NULL), TB_ERR_NULL_ARGUMENT);
  ck_assert_int_eq(tb_dynamic_tree_set_category_bits(NULL, p, 1), TB_ERR_NULL_ARGUMENT);
  ck_assert(tb_dynamic_tree_get_category_bits(NULL, p) == 0);
  /* none of it changed the tree */
  ck_assert_int_eq(tb_dynamic_tree_get_proxy_count(t), 1);
  tb_aabb after = tb_dynamic_tree_get_fat_aabb(t, p);
  ck_assert(memcmp(&after, &fat, sizeof fat) == 0);
  ck_assert_int_eq(tb_dynamic_tree_validate(t), TB_OK);
  tb_dynamic_tree_destroy(t);
}
END_TEST

/* Same calls, same tree: two trees built alike answer a query in the same order. */
typedef struct order {
  int32_t ids[N];
  int count;
} order;

static bool record(int32_t proxy, void* user_data, void* context) {
  (void)user_data;
  order* o = context;
  if (o->count < N) o->ids[o->count++] = proxy;
  return true;
}

START_TEST(same_calls_same_tree) {
  static order a, b;
  memset(&a, 0, sizeof a);
  memset(&b, 0, sizeof b);
  tb_dynamic_tree* t[2] = {tb_dynamic_tree_create(0.1f), tb_dynamic_tree_create(0.1f)};
  for (int k = 0; k < 2; ++k) {
    unsigned rng = 777u;
    int32_t ids[300];
    for (int i = 0; i < 300; ++i) ids[i] = tb_dynamic_tree_create_proxy(t[k], random_box(&rng), 1, NULL);
    for (int i = 0; i < 300; i += 2)
      ck_assert_int_eq(tb_dynamic_tree_move_proxy(t[k], ids[i], random_box(&rng), (tb_vec2){0, 0}, NULL), TB_OK);
    ck_assert_int_eq(tb_dynamic_tree_validate(t[k]), TB_OK);
  }
  tb_aabb all = {{-WORLD, -WORLD}, {WORLD + 10, WORLD + 10}};
  tb_dynamic_tree_query(t[0], all, UINT64_MAX, record, &a);
  tb_dynamic_tree_query(t[1], all, UINT64_MAX, record, &b);
  ck_assert_int_eq(a.count, 300);
  ck_assert_int_eq(b.count, 300);
  ck_assert(memcmp(a.ids, b.ids, sizeof a.ids) == 0);
  ck_assert_int_eq(tb_dynamic_tree_get_height(t[0]), tb_dynamic_tree_get_height(t[1]));
  tb_dynamic_tree_destroy(t[0]);
  tb_dynamic_tree_destroy(t[1]);
}
END_TEST

static Suite* dynamic_tree_api_suite(void) {
  Suite* s = suite_create("dynamic_tree_api");
  TCase* tc = tcase_create("dynamic_tree_api");
  tcase_add_test(tc, queries_and_rays_match_brute_force);
  tcase_add_test(tc, fat_boxes_and_moves);
  tcase_add_test(tc, changes_from_callbacks_are_refused);
  tcase_add_test(tc, callbacks_stop_the_traversal);
  tcase_add_test(tc, bad_trees_ids_and_boxes);
  tcase_add_test(tc, same_calls_same_tree);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(dynamic_tree_api_suite)
