/* The public dynamic AABB tree (tb_dynamic_tree in tumble.h): the engine's own
 * tree (tree.c) behind an opaque handle, with the checks and messages of the
 * public API, a user data pointer per proxy and a lock against changes from
 * inside its callbacks. */
#include <string.h>

#include "error.h"
#include "math_internal.h"
#include "memory.h"
#include "tree.h"

/* Trees alive: the allocator may not change under them (tb_set_allocator). */
static int live_trees;

int tb_dynamic_tree_live_count(void) { return live_trees; }

struct tb_dynamic_tree {
  tb_tree tree;
  void** user_data; /* by proxy id (a node index of tree); capacity slots */
  int32_t capacity;
  int locked; /* queries and ray casts running (they nest) */
};

static tb_result check_tree(const tb_dynamic_tree* t, const char* fn) {
  if (t == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: tree is NULL", fn);
  return TB_OK;
}

static tb_result check_change(const tb_dynamic_tree* t, const char* fn) {
  if (check_tree(t, fn) != TB_OK) return tb_last_result();
  if (t->locked > 0)
    return tb_fail(NULL, TB_ERR_LOCKED, "%s: the tree is being queried (a change from inside its callback)", fn);
  return TB_OK;
}

static tb_result check_proxy(const tb_dynamic_tree* t, int32_t proxy, const char* fn) {
  if (check_tree(t, fn) != TB_OK) return tb_last_result();
  if (!tb_tree_is_proxy(&t->tree, proxy))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: proxy %d is not a live proxy of the tree", fn, (int)proxy);
  return TB_OK;
}

static tb_result check_box(tb_aabb a, const char* fn, const char* name) {
  if (tb_point_ok(a.lower) && tb_point_ok(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y) return TB_OK;
  return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                 "%s: %s = ((%g, %g), (%g, %g)) is not finite, beyond TB_MAX_LENGTH or has lower > upper", fn, name,
                 (double)a.lower.x, (double)a.lower.y, (double)a.upper.x, (double)a.upper.y);
}

tb_dynamic_tree* tb_dynamic_tree_create(float margin) {
  const char* fn = "tb_dynamic_tree_create";
  if (!tb_length_ok(margin) || margin < 0.0f) {
    tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: margin = %g must be >= 0, finite and <= TB_MAX_LENGTH", fn,
            (double)margin);
    return NULL;
  }
  tb_dynamic_tree* t = tb_mem_alloc(sizeof *t); /* through the game's allocator, as the nodes */
  if (t == NULL) {
    tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the tree", fn);
    return NULL;
  }
  memset(t, 0, sizeof *t);
  (void)tb_tree_create(&t->tree, margin); /* margin checked */
  live_trees += 1;
  return t;
}

tb_result tb_dynamic_tree_destroy(tb_dynamic_tree* t) {
  if (check_change(t, __func__) != TB_OK) return tb_last_result();
  tb_tree_destroy(&t->tree);
  tb_mem_free(t->user_data, (size_t)t->capacity * sizeof *t->user_data);
  tb_mem_free(t, sizeof *t);
  live_trees -= 1;
  return TB_OK;
}

int32_t tb_dynamic_tree_create_proxy(tb_dynamic_tree* t, tb_aabb aabb, uint64_t category_bits, void* user_data) {
  const char* fn = "tb_dynamic_tree_create_proxy";
  if (check_change(t, fn) != TB_OK || check_box(aabb, fn, "aabb") != TB_OK) return TB_NULL_PROXY;
  /* room first (nodes, then a user data slot per node), so the insert cannot fail */
  if (!tb_tree_reserve(&t->tree, 1)) {
    tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the tree's nodes", fn);
    return TB_NULL_PROXY;
  }
  if (t->capacity < t->tree.capacity) {
    void** slots =
        tb_mem_grow(t->user_data, (size_t)t->capacity * sizeof *slots, (size_t)t->tree.capacity * sizeof *slots);
    if (slots == NULL) {
      tb_fail(NULL, TB_ERR_OUT_OF_MEMORY, "%s: no memory for the proxies' user data", fn);
      return TB_NULL_PROXY;
    }
    t->user_data = slots;
    t->capacity = t->tree.capacity;
  }
  int32_t proxy = tb_tree_create_proxy(&t->tree, aabb, category_bits, 0);
  t->user_data[proxy] = user_data;
  return proxy;
}

tb_result tb_dynamic_tree_destroy_proxy(tb_dynamic_tree* t, int32_t proxy) {
  if (check_change(t, __func__) != TB_OK || check_proxy(t, proxy, __func__) != TB_OK) return tb_last_result();
  (void)tb_tree_destroy_proxy(&t->tree, proxy);
  t->user_data[proxy] = NULL;
  return TB_OK;
}

tb_result tb_dynamic_tree_move_proxy(tb_dynamic_tree* t, int32_t proxy, tb_aabb aabb, tb_vec2 displacement,
                                     bool* reinserted) {
  const char* fn = __func__;
  if (check_change(t, fn) != TB_OK || check_proxy(t, proxy, fn) != TB_OK || check_box(aabb, fn, "aabb") != TB_OK)
    return tb_last_result();
  if (!tb_point_ok(displacement))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: displacement = (%g, %g) is not finite or beyond TB_MAX_LENGTH",
                   fn, (double)displacement.x, (double)displacement.y);
  bool moved = tb_tree_move_proxy(&t->tree, proxy, aabb, displacement);
  if (reinserted != NULL) *reinserted = moved;
  return TB_OK;
}

tb_result tb_dynamic_tree_rebuild(tb_dynamic_tree* t) {
  if (check_change(t, __func__) != TB_OK) return tb_last_result();
  return tb_tree_rebuild(&t->tree); /* never allocates: its work space grew with the nodes */
}

/* ---- queries ---------------------------------------------------------------- */

/* The callbacks run with the tree locked; the lock counts, so a nested query
 * does not unlock the outer one. */
typedef struct query_context {
  tb_dynamic_tree* t;
  tb_dynamic_tree_query_fn* query;
  tb_dynamic_tree_ray_fn* ray;
  void* context;
} query_context;

static bool query_callback(int32_t proxy, int32_t user_id, void* context) {
  (void)user_id;
  query_context* q = context;
  return q->query(proxy, q->t->user_data[proxy], q->context);
}

static float ray_callback(const tb_tree_ray_input* input, int32_t proxy, int32_t user_id, void* context) {
  (void)user_id;
  query_context* q = context;
  tb_dynamic_tree_ray_input in = {input->origin, input->translation, input->max_fraction};
  return q->ray(&in, proxy, q->t->user_data[proxy], q->context);
}

static tb_result traversal_result(tb_result r, const char* fn) {
  if (r == TB_OK) return TB_OK;
  return tb_fail(NULL, r, "%s: no memory for the traversal stack (the query stopped early)", fn);
}

tb_result tb_dynamic_tree_query(const tb_dynamic_tree* tree, tb_aabb aabb, uint64_t mask_bits,
                                tb_dynamic_tree_query_fn* fn, void* context) {
  const char* name = __func__;
  if (check_tree(tree, name) != TB_OK || check_box(aabb, name, "aabb") != TB_OK) return tb_last_result();
  if (fn == NULL) return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: fn is NULL", name);
  tb_dynamic_tree* t = (tb_dynamic_tree*)tree; /* the lock is the one thing a query writes */
  query_context q = {t, fn, NULL, context};
  t->locked += 1;
  tb_result r = tb_tree_query(&t->tree, aabb, mask_bits, query_callback, &q);
  t->locked -= 1;
  return traversal_result(r, name);
}

tb_result tb_dynamic_tree_ray_cast(const tb_dynamic_tree* tree, const tb_dynamic_tree_ray_input* input,
                                   uint64_t mask_bits, tb_dynamic_tree_ray_fn* fn, void* context) {
  const char* name = __func__;
  if (check_tree(tree, name) != TB_OK) return tb_last_result();
  if (input == NULL || fn == NULL)
    return tb_fail(NULL, TB_ERR_NULL_ARGUMENT, "%s: %s is NULL", name, input == NULL ? "input" : "fn");
  if (!tb_point_ok(input->origin) || !tb_point_ok(input->translation))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                   "%s: input origin (%g, %g) or translation (%g, %g) is not finite or beyond TB_MAX_LENGTH", name,
                   (double)input->origin.x, (double)input->origin.y, (double)input->translation.x,
                   (double)input->translation.y);
  if (!tb_length_ok(input->max_fraction) || input->max_fraction < 0.0f)
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: input max_fraction = %g must be >= 0, finite and <= %g", name,
                   (double)input->max_fraction, (double)TB_MAX_LENGTH);
  tb_dynamic_tree* t = (tb_dynamic_tree*)tree;
  query_context q = {t, NULL, fn, context};
  tb_tree_ray_input ray = {input->origin, input->translation, input->max_fraction};
  t->locked += 1;
  tb_result r = tb_tree_ray_cast(&t->tree, &ray, mask_bits, ray_callback, &q);
  t->locked -= 1;
  return traversal_result(r, name);
}

/* ---- state ------------------------------------------------------------------ */

tb_result tb_dynamic_tree_validate(const tb_dynamic_tree* t) {
  if (check_tree(t, __func__) != TB_OK) return tb_last_result();
  if (!tb_tree_validate(&t->tree))
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: the hierarchy is broken (links, counts, heights or boxes)",
                   __func__);
  if (t->capacity < t->tree.capacity || (t->capacity > 0 && t->user_data == NULL) || t->locked < 0)
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT, "%s: the user data slots do not cover the tree's %d nodes", __func__,
                   (int)t->tree.capacity);
  return TB_OK;
}

size_t tb_dynamic_tree_get_byte_count(const tb_dynamic_tree* t) {
  if (check_tree(t, __func__) != TB_OK) return 0;
  return sizeof *t + tb_tree_bytes(&t->tree) + (size_t)t->capacity * sizeof *t->user_data;
}

int tb_dynamic_tree_get_height(const tb_dynamic_tree* t) {
  return check_tree(t, __func__) == TB_OK ? tb_tree_get_height(&t->tree) : 0;
}

int tb_dynamic_tree_get_proxy_count(const tb_dynamic_tree* t) {
  return check_tree(t, __func__) == TB_OK ? (int)tb_tree_get_proxy_count(&t->tree) : 0;
}

float tb_dynamic_tree_get_area_ratio(const tb_dynamic_tree* t) {
  return check_tree(t, __func__) == TB_OK ? tb_tree_get_area_ratio(&t->tree) : 0.0f;
}

void* tb_dynamic_tree_get_user_data(const tb_dynamic_tree* t, int32_t proxy) {
  return check_proxy(t, proxy, __func__) == TB_OK ? t->user_data[proxy] : NULL;
}

tb_aabb tb_dynamic_tree_get_fat_aabb(const tb_dynamic_tree* t, int32_t proxy) {
  if (check_proxy(t, proxy, __func__) != TB_OK) return (tb_aabb){{0.0f, 0.0f}, {0.0f, 0.0f}};
  return tb_tree_get_fat_aabb(&t->tree, proxy);
}

uint64_t tb_dynamic_tree_get_category_bits(const tb_dynamic_tree* t, int32_t proxy) {
  return check_proxy(t, proxy, __func__) == TB_OK ? tb_tree_get_category_bits(&t->tree, proxy) : 0u;
}

tb_result tb_dynamic_tree_set_user_data(tb_dynamic_tree* t, int32_t proxy, void* user_data) {
  if (check_change(t, __func__) != TB_OK || check_proxy(t, proxy, __func__) != TB_OK) return tb_last_result();
  t->user_data[proxy] = user_data;
  return TB_OK;
}

tb_result tb_dynamic_tree_set_category_bits(tb_dynamic_tree* t, int32_t proxy, uint64_t category_bits) {
  if (check_change(t, __func__) != TB_OK || check_proxy(t, proxy, __func__) != TB_OK) return tb_last_result();
  (void)tb_tree_set_category_bits(&t->tree, proxy, category_bits);
  return TB_OK;
}
