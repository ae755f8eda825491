/* The allocator, log and assert hooks (tumble.h, "memory, hooks and units"). */
#include "memory.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "tree.h"
#include "world.h"

void* tb_default_alloc(size_t size, size_t alignment, void* context) {
  (void)context;
  if (alignment == 0 || size > SIZE_MAX - alignment) return NULL;
  /* malloc where it aligns enough (x86-64, aarch64: 16), so that tools that
   * wrap malloc and free (tests/stress/heap_count.c) see every block */
  if (alignment <= _Alignof(max_align_t)) return malloc(size);
  /* aligned_alloc wants a multiple of the alignment */
  return aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}

void tb_default_free(void* memory, size_t size, void* context) {
  (void)size;
  (void)context;
  free(memory);
}

static tb_alloc_fn* alloc_hook = tb_default_alloc;
static tb_free_fn* free_hook = tb_default_free;
static void* alloc_context;
static tb_log_fn* log_hook;
static void* log_context;
static tb_assert_fn* assert_hook;
static void* assert_context;
static _Thread_local unsigned failures;

void* tb_mem_alloc(size_t size) {
  TB_ASSERT(size > 0);
  void* memory = alloc_hook(size, TB_ALLOCATION_ALIGNMENT, alloc_context);
  if (memory == NULL) failures += 1;
  return memory;
}

void tb_mem_free(void* memory, size_t size) {
  if (memory == NULL) return;
  TB_ASSERT(size > 0);
  free_hook(memory, size, alloc_context);
}

void* tb_mem_grow(void* memory, size_t old_size, size_t new_size) {
  void* grown = tb_mem_alloc(new_size);
  if (grown == NULL) return NULL;
  if (memory != NULL) memcpy(grown, memory, old_size < new_size ? old_size : new_size);
  tb_mem_free(memory, old_size);
  return grown;
}

unsigned tb_mem_failure_count(void) { return failures; }

/* The global settings change only while no world exists. */
tb_result tb_refuse_while_worlds_exist(const char* fn) {
  int n = tb_world_count();
  if (n == 0) return TB_OK;
  return tb_fail(NULL, TB_ERR_LOCKED,
                 "%s: %d world%s exist%s; the global settings change only while no world exists (destroy them first)",
                 fn, n, n == 1 ? "" : "s", n == 1 ? "s" : "");
}

tb_result tb_set_allocator(tb_alloc_fn* alloc, tb_free_fn* free_fn, void* context) {
  if (alloc == NULL || free_fn == NULL)
    return tb_fail(NULL, TB_ERR_NULL_ARGUMENT,
                   "tb_set_allocator: alloc and free are required (%s is NULL; tb_default_alloc and tb_default_free "
                   "restore the default)",
                   alloc == NULL ? "alloc" : "free");
  tb_result r = tb_refuse_while_worlds_exist("tb_set_allocator");
  if (r != TB_OK) return r;
  int trees = tb_dynamic_tree_live_count();
  if (trees > 0)
    return tb_fail(NULL, TB_ERR_LOCKED,
                   "tb_set_allocator: %d dynamic tree%s exist%s, with blocks from the allocator in place (destroy them "
                   "first)",
                   trees, trees == 1 ? "" : "s", trees == 1 ? "s" : "");
  if (!tb_world_histories_move(alloc, free_fn, context))
    return tb_fail(NULL, TB_ERR_OUT_OF_MEMORY,
                   "tb_set_allocator: the new allocator had no memory for the handle history (%zu bytes) that tumble "
                   "keeps between worlds; the old allocator stays",
                   tb_get_retained_byte_count());
  alloc_hook = alloc;
  free_hook = free_fn;
  alloc_context = context;
  return TB_OK;
}

tb_result tb_set_log_function(tb_log_fn* log, void* context) {
  tb_result r = tb_refuse_while_worlds_exist("tb_set_log_function");
  if (r != TB_OK) return r;
  log_hook = log;
  log_context = context;
  return TB_OK;
}

tb_result tb_set_assert_function(tb_assert_fn* assert_fn, void* context) {
  tb_result r = tb_refuse_while_worlds_exist("tb_set_assert_function");
  if (r != TB_OK) return r;
  assert_hook = assert_fn;
  assert_context = context;
  return TB_OK;
}

void tb_log(const char* message) {
  if (log_hook != NULL) log_hook(message, log_context);
}

void tb_assert_failed(const char* condition, const char* file, int line) {
  char message[TB_ERROR_MESSAGE_CAPACITY];
  snprintf(message, sizeof message, "tumble: internal check failed: %s (%s:%d)", condition, file, line);
  if (log_hook != NULL)
    log_hook(message, log_context);
  else if (assert_hook == NULL)
    fprintf(stderr, "%s\n", message);
  if (assert_hook != NULL) assert_hook(condition, file, line, assert_context);
  abort();
}
