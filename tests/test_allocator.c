/* The allocator, log and assert hooks, and the per-world byte counts: every
 * byte tumble allocates comes from the game's allocator and goes back to it
 * with the size it was allocated with; a failed allocation never crashes,
 * leaks or half-changes a world; the byte counts are what the allocator sees.
 *
 * The hooks are global: every test leaves the default allocator and no world
 * behind (the suites also run in one process under make sanitize). */
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/memory.h"
#include "test_util.h"

int tb_world_count(void); /* src/world.h */

/* ---- a counting allocator -------------------------------------------------- */

/* Each block has a header of one alignment unit before it: its size and a
 * mark, so the free hook can check the size tumble passes. */
#define HEADER TB_ALLOCATION_ALIGNMENT
#define MARK 0x7b5eedull

typedef struct counter {
  size_t live_bytes; /* allocated and not yet freed */
  long allocations, frees, failures;
  long fail_at;    /* the allocation (1-based) that fails; 0: none */
  bool fail_after; /* and every one after it */
  long bad_frees;  /* a size or a pointer that does not match */
} counter;

static void* counting_alloc(size_t size, size_t alignment, void* context) {
  counter* c = context;
  ck_assert_uint_ge(alignment, TB_ALLOCATION_ALIGNMENT);
  ck_assert_uint_gt(size, 0);
  long n = ++c->allocations;
  if (c->fail_at > 0 && (n == c->fail_at || (c->fail_after && n > c->fail_at))) {
    c->allocations -= 1;
    c->failures += 1;
    return NULL;
  }
  unsigned char* block = tb_default_alloc(size + HEADER, alignment, NULL);
  ck_assert_ptr_nonnull(block);
  uint64_t header[2] = {size, MARK};
  memcpy(block, header, sizeof header);
  c->live_bytes += size;
  ck_assert_uint_eq((uintptr_t)(block + HEADER) % alignment, 0);
  return block + HEADER;
}

static void counting_free(void* memory, size_t size, void* context) {
  counter* c = context;
  ck_assert_ptr_nonnull(memory);
  unsigned char* block = (unsigned char*)memory - HEADER;
  uint64_t header[2];
  memcpy(header, block, sizeof header);
  if (header[1] != MARK || header[0] != size) c->bad_frees += 1;
  header[1] = 0;
  memcpy(block, header, sizeof header);
  c->live_bytes -= header[0];
  c->frees += 1;
  tb_default_free(block, size + HEADER, NULL);
}

static void use_counter(counter* c) { ck_assert_int_eq(tb_set_allocator(counting_alloc, counting_free, c), TB_OK); }

/* Back to the default: what tumble keeps between worlds moves out of the
 * counter, which must then hold nothing. */
static void stop_counting(counter* c) {
  ck_assert_int_eq(tb_world_count(), 0);
  ck_assert_int_eq(tb_set_allocator(tb_default_alloc, tb_default_free, NULL), TB_OK);
  ck_assert_uint_eq(c->live_bytes, 0);
  ck_assert_int_eq(c->allocations, c->frees);
  ck_assert_int_eq(c->bad_frees, 0);
}

/* ---- a scene that allocates in every part ---------------------------------- */

static float keep_hits(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context) {
  (void)shape, (void)point, (void)normal, (void)context;
  return fraction;
}

/* Builds and steps a scene through the public API, accepting out-of-memory
 * anywhere: every call either succeeds or fails with TB_ERR_OUT_OF_MEMORY
 * and leaves the world's hash as it was. Returns how many calls failed. */
static int run_scene(tb_world_id* out_world) {
  int failed = 0;
#define EXPECT_OOM_OR(ok_condition)                                        \
  do {                                                                     \
    if (!(ok_condition)) {                                                 \
      ck_assert_int_eq(tb_last_result(), TB_ERR_OUT_OF_MEMORY);            \
      if (tb_world_is_valid(w)) ck_assert_uint_eq(tb_world_hash(w), hash); \
      failed += 1;                                                         \
    }                                                                      \
  } while (0)
  tb_world_def wd = tb_default_world_def();
  tb_world_id w = tb_create_world(&wd);
  *out_world = w;
  uint64_t hash = 0;
  if (tb_world_id_is_null(w)) {
    ck_assert_int_eq(tb_last_result(), TB_ERR_OUT_OF_MEMORY);
    return 1;
  }
  tb_body_def gd = tb_default_body_def();
  hash = tb_world_hash(w);
  tb_body_id ground = tb_create_body(w, &gd);
  EXPECT_OOM_OR(!tb_body_id_is_null(ground));
  tb_chain_def cd = tb_default_chain_def();
  const tb_vec2 points[5] = {{-20.0f, 0.0f}, {-10.0f, 0.0f}, {0.0f, 0.0f}, {10.0f, 0.0f}, {20.0f, 0.0f}};
  cd.points = points;
  cd.count = 5;
  hash = tb_world_hash(w);
  if (!tb_body_id_is_null(ground)) EXPECT_OOM_OR(!tb_chain_id_is_null(tb_create_chain(ground, &cd)));
  tb_polygon box;
  hash = tb_world_hash(w);
  const tb_vec2 hull[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}};
  EXPECT_OOM_OR(tb_make_polygon(hull, 5, 0.0f, &box) == TB_OK);
  ck_assert_int_eq(tb_make_box(0.5f, 0.5f, &box), TB_OK);
  tb_body_id previous = {0, 0, 0};
  for (int i = 0; i < 40; ++i) {
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = (tb_vec2){(float)(i % 8) * 1.1f - 4.0f, 0.5f + (float)(i / 8) * 1.05f};
    hash = tb_world_hash(w);
    tb_body_id b = tb_create_body(w, &bd);
    EXPECT_OOM_OR(!tb_body_id_is_null(b));
    if (tb_body_id_is_null(b)) continue;
    tb_shape_def sd = tb_default_shape_def();
    sd.is_sensor = i == 7;
    hash = tb_world_hash(w);
    EXPECT_OOM_OR(!tb_shape_id_is_null(tb_create_polygon_shape(b, &sd, &box)));
    if (i % 5 == 1 && !tb_body_id_is_null(previous) && tb_body_is_valid(previous)) {
      tb_revolute_joint_def jd = tb_default_revolute_joint_def();
      jd.body_a = previous;
      jd.body_b = b;
      hash = tb_world_hash(w);
      EXPECT_OOM_OR(!tb_joint_id_is_null(tb_create_revolute_joint(w, &jd)));
    }
    previous = b;
  }
  for (int step = 0; step < 40; ++step) {
    tb_result r = tb_world_step(w, 1.0f / 60.0f, 4);
    ck_assert(r == TB_OK || r == TB_ERR_OUT_OF_MEMORY);
    failed += r != TB_OK;
  }
  int count = 0;
  hash = tb_world_hash(w);
  tb_ray_result hits[4];
  EXPECT_OOM_OR(tb_world_cast_ray_all(w, (tb_vec2){-10.0f, 1.0f}, (tb_vec2){20.0f, 0.0f}, tb_default_query_filter(),
                                      hits, 4, &count) == TB_OK);
  EXPECT_OOM_OR(tb_world_cast_ray(w, (tb_vec2){-10.0f, 1.0f}, (tb_vec2){20.0f, 0.0f}, tb_default_query_filter(),
                                  keep_hits, NULL) == TB_OK);
  if (!tb_body_id_is_null(previous)) ck_assert_int_eq(tb_destroy_body(previous), TB_OK);
  for (int step = 0; step < 5; ++step) failed += tb_world_step(w, 1.0f / 60.0f, 4) != TB_OK;
#undef EXPECT_OOM_OR
  return failed;
}

/* ---- the tests -------------------------------------------------------------- */

/* Every block is freed with its own size, and tumble's world bytes are what
 * the allocator holds for it, at every stage of a scene's life. */
START_TEST(counting_allocator_sees_every_byte_back) {
  counter c = {0};
  use_counter(&c);
  size_t retained = tb_get_retained_byte_count();
  ck_assert_uint_eq(c.live_bytes, retained); /* moved in from the default allocator */
  tb_world_id w;
  ck_assert_int_eq(run_scene(&w), 0);
  ck_assert_int_gt(c.allocations, 50);
  tb_memory_stats m;
  ck_assert_int_eq(tb_world_get_memory_stats(w, &m), TB_OK);
  /* the slot's history moved from tumble's keeping into the world */
  ck_assert_uint_eq(c.live_bytes, m.total + tb_get_retained_byte_count());
  ck_assert_uint_eq(tb_world_get_byte_count(w), m.total);
  ck_assert_uint_gt(m.solver, 0);
  ck_assert_uint_gt(m.contacts, 0);
  ck_assert_uint_gt(m.events, 0);
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  ck_assert_uint_eq(c.live_bytes, tb_get_retained_byte_count());
  ck_assert_uint_gt(tb_get_retained_byte_count(), retained); /* this world's slots */
  stop_counting(&c);
}
END_TEST

/* A standalone tree's blocks come from the allocator too: its byte count is
 * what the allocator holds for it as it grows, and the allocator cannot be
 * changed while it lives. */
START_TEST(dynamic_tree_bytes_come_from_the_allocator) {
  counter c = {0};
  use_counter(&c);
  size_t before = c.live_bytes;
  tb_dynamic_tree* t = tb_dynamic_tree_create(0.1f);
  ck_assert_ptr_nonnull(t);
  ck_assert_uint_eq(c.live_bytes - before, tb_dynamic_tree_get_byte_count(t));
  size_t empty = tb_dynamic_tree_get_byte_count(t);
  for (int k = 0; k < 100; ++k) {
    tb_aabb box = {{(float)k, 0.0f}, {(float)k + 0.5f, 0.5f}};
    ck_assert_int_ne(tb_dynamic_tree_create_proxy(t, box, 1, NULL), TB_NULL_PROXY);
    ck_assert_uint_eq(c.live_bytes - before, tb_dynamic_tree_get_byte_count(t));
  }
  ck_assert_uint_gt(tb_dynamic_tree_get_byte_count(t), empty);
  ck_assert_int_eq(tb_set_allocator(tb_default_alloc, tb_default_free, NULL), TB_ERR_LOCKED);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "dynamic tree"));
  ck_assert_uint_eq(tb_dynamic_tree_get_byte_count(NULL), 0);
  ck_assert_int_eq(tb_dynamic_tree_destroy(t), TB_OK);
  ck_assert_uint_eq(c.live_bytes, before);
  stop_counting(&c);
}
END_TEST

/* The parts add up to the total, and each part is what its objects hold. */
START_TEST(memory_stats_add_up_and_follow_the_bodies) {
  counter c = {0};
  use_counter(&c);
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_memory_stats before;
  ck_assert_int_eq(tb_world_get_memory_stats(w, &before), TB_OK);
  ck_assert_uint_eq(c.live_bytes, tb_get_retained_byte_count() + before.total);
  ck_assert_uint_ge(before.world, 100);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  for (int i = 0; i < 1000; ++i) {
    bd.position = (tb_vec2){(float)i, 0.0f};
    ck_assert(!tb_body_id_is_null(tb_create_body(w, &bd)));
  }
  tb_memory_stats after;
  ck_assert_int_eq(tb_world_get_memory_stats(w, &after), TB_OK);
  size_t sum = after.world + after.bodies + after.shapes + after.contacts + after.joints + after.broad_phase +
               after.islands + after.solver + after.events + after.handle_history;
  ck_assert_uint_eq(sum, after.total);
  /* 1,000 bodies without shapes: only the body part grows, by at least 1,000
   * awake-set entries and 1,000 pool slots (each more than a transform) */
  ck_assert_uint_ge(after.bodies, before.bodies + 1000 * (sizeof(int) + sizeof(tb_transform)));
  ck_assert_uint_eq(after.shapes, before.shapes);
  ck_assert_uint_eq(after.contacts, before.contacts);
  ck_assert_uint_eq(after.broad_phase, before.broad_phase);
  ck_assert_uint_eq(after.total - before.total, after.bodies - before.bodies);
  ck_assert_uint_eq(c.live_bytes - tb_get_retained_byte_count(), after.total);
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  stop_counting(&c);
}
END_TEST

/* Fail the Nth allocation, for every N the scene makes: no crash, no leak
 * (the counter, and LeakSanitizer under make sanitize), no half-made object,
 * and the world is still usable after. Then the same with every allocation
 * from the Nth on failing. */
START_TEST(failing_allocations_never_crash_or_leak) {
  counter probe = {0};
  use_counter(&probe);
  long moved = probe.allocations; /* the kept history, moving in */
  tb_world_id w;
  ck_assert_int_eq(run_scene(&w), 0);
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  long total = probe.allocations - moved;
  stop_counting(&probe);
  for (int after = 0; after < 2; ++after) {
    for (long n = 1; n <= total; ++n) {
      counter c = {.fail_after = after == 1};
      use_counter(&c);
      c.fail_at = c.allocations + n;
      int failed = run_scene(&w);
      ck_assert_msg(c.failures == 0 || failed > 0, "allocation %ld failed unreported", n);
      if (tb_world_is_valid(w)) {
        c.fail_at = 0; /* memory again: the world steps on */
        for (int step = 0; step < 5; ++step) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
        tb_memory_stats m;
        ck_assert_int_eq(tb_world_get_memory_stats(w, &m), TB_OK);
        ck_assert_uint_eq(c.live_bytes, m.total + tb_get_retained_byte_count());
        ck_assert_int_eq(tb_destroy_world(w), TB_OK);
      }
      stop_counting(&c);
    }
  }
}
END_TEST

/* A step that cannot allocate says so and leaves a world that steps on. */
START_TEST(a_step_without_memory_reports_it) {
  counter c = {0};
  use_counter(&c);
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_def gd = tb_default_body_def();
  tb_body_id ground = tb_create_body(w, &gd);
  tb_polygon floor;
  ck_assert_int_eq(tb_make_box(10.0f, 0.5f, &floor), TB_OK);
  tb_shape_def sd = tb_default_shape_def();
  ck_assert(!tb_shape_id_is_null(tb_create_polygon_shape(ground, &sd, &floor)));
  tb_body_id box = tbt_box_body(w, 0.0f, 0.9f, 0.5f, 0.5f);
  c.fail_at = c.allocations + 1;
  c.fail_after = true;
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_OUT_OF_MEMORY);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "tb_world_step"));
  ck_assert_str_eq(tb_world_last_error(w), tb_last_error());
  c.fail_at = 0;
  for (int i = 0; i < 60; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  ck_assert_float_lt(fabsf(tb_body_get_position(box).y - 1.0f), 0.05f); /* it rests on the floor */
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  stop_counting(&c);
}
END_TEST

static int log_calls;
static char last_logged[512];
static void remember_log(const char* message, void* context) {
  ck_assert_ptr_eq(context, &log_calls);
  log_calls += 1;
  snprintf(last_logged, sizeof last_logged, "%s", message);
}

/* The log function gets exactly what tb_last_error() records. */
START_TEST(log_function_gets_each_error) {
  ck_assert_int_eq(tb_set_log_function(remember_log, &log_calls), TB_OK);
  log_calls = 0;
  tb_world_id w = tbt_world(0.0f, -10.0f);
  ck_assert_int_eq(tb_world_step(w, -1.0f, 4), TB_ERR_INVALID_ARGUMENT);
  ck_assert_int_eq(log_calls, 1);
  ck_assert_str_eq(last_logged, tb_last_error());
  ck_assert(tb_body_id_is_null(tb_create_body(w, NULL)));
  ck_assert_int_eq(log_calls, 2);
  ck_assert_str_eq(last_logged, tb_last_error());
  /* refused while the world exists, and that is logged too */
  ck_assert_int_eq(tb_set_log_function(NULL, NULL), TB_ERR_LOCKED);
  ck_assert_int_eq(log_calls, 3);
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  ck_assert_int_eq(tb_set_log_function(NULL, NULL), TB_OK);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_ERR_STALE_HANDLE);
  ck_assert_int_eq(log_calls, 3);
}
END_TEST

/* While a world exists every global setter is refused and changes nothing. */
START_TEST(global_setters_refused_while_a_world_exists) {
  counter c = {0};
  tb_world_id w = tbt_world(0.0f, -10.0f);
  ck_assert_int_eq(tb_set_allocator(counting_alloc, counting_free, &c), TB_ERR_LOCKED);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "no world exists"));
  ck_assert_int_eq(tb_set_assert_function(NULL, NULL), TB_ERR_LOCKED);
  ck_assert_int_eq(tb_set_length_units_per_meter(100.0f), TB_ERR_LOCKED);
  ck_assert_float_eq(tb_get_length_units_per_meter(), 1.0f);
  tbt_box_body(w, 0.0f, 0.0f, 0.5f, 0.5f);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  ck_assert_int_eq(c.allocations, 0); /* the default allocator still serves */
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
}
END_TEST

/* The kept handle history moves to the new allocator and back; an allocator
 * without memory for it is refused and the old one stays. */
START_TEST(allocator_change_moves_the_kept_history) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  for (int i = 0; i < 20; ++i) tbt_box_body(w, (float)i, 0.0f, 0.5f, 0.5f);
  ck_assert_int_eq(tb_destroy_world(w), TB_OK);
  size_t retained = tb_get_retained_byte_count();
  ck_assert_uint_ge(retained, 20 * sizeof(uint16_t));
  counter broke = {.fail_at = 1, .fail_after = true};
  ck_assert_int_eq(tb_set_allocator(counting_alloc, counting_free, &broke), TB_ERR_OUT_OF_MEMORY);
  ck_assert_int_eq(broke.allocations, broke.frees);
  counter c = {0};
  use_counter(&c);
  ck_assert_uint_eq(c.live_bytes, retained);
  ck_assert_uint_eq(tb_get_retained_byte_count(), retained);
  stop_counting(&c);
}
END_TEST

static void exit_on_assert(const char* condition, const char* file, int line, void* context) {
  bool ok = strcmp(condition, "1 + 1 == 3") == 0 && strstr(file, "test_allocator.c") != NULL && line > 0 &&
            context == &log_calls && log_calls == 1 && strstr(last_logged, "1 + 1 == 3") != NULL;
  exit(ok ? 42 : 1);
}

/* An internal check that fails is logged, then handed to the assert function
 * (which here exits; one that returns would see tumble abort). */
START_TEST(assert_function_gets_internal_failures) {
  ck_assert_int_eq(tb_set_log_function(remember_log, &log_calls), TB_OK);
  ck_assert_int_eq(tb_set_assert_function(exit_on_assert, &log_calls), TB_OK);
  log_calls = 0;
  TB_ASSERT(1 + 1 == 3);
}
END_TEST

Suite* allocator_suite(void) {
  Suite* s = suite_create("allocator");
  TCase* tc = tcase_create("core");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, counting_allocator_sees_every_byte_back);
  tcase_add_test(tc, dynamic_tree_bytes_come_from_the_allocator);
  tcase_add_test(tc, memory_stats_add_up_and_follow_the_bodies);
  tcase_add_test(tc, failing_allocations_never_crash_or_leak);
  tcase_add_test(tc, a_step_without_memory_reports_it);
  tcase_add_test(tc, log_function_gets_each_error);
  tcase_add_test(tc, global_setters_refused_while_a_world_exists);
  tcase_add_test(tc, allocator_change_moves_the_kept_history);
  /* the process exits inside it: only where each test has its own process */
  const char* fork = getenv("CK_FORK");
  if (fork == NULL || strcmp(fork, "no") != 0) tcase_add_exit_test(tc, assert_function_gets_internal_failures, 42);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(allocator_suite)
