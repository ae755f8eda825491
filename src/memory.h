/* Every allocation of the engine goes through here, to the game's hooks
 * (tb_set_allocator) or the default ones. Sizes are always known: the free
 * hook is told the size that was allocated. */
#ifndef TB_MEMORY_H
#define TB_MEMORY_H

#include <stdbool.h>
#include <stddef.h>

#include "tumble.h"

/* size > 0 bytes, aligned to TB_ALLOCATION_ALIGNMENT; NULL when out of memory
 * (counted in tb_mem_failure_count). */
void* tb_mem_alloc(size_t size);
/* memory (NULL is fine) of size bytes, as allocated. */
void tb_mem_free(void* memory, size_t size);
/* A block of new_size bytes holding the first min(old, new) bytes of
 * memory (which is freed); NULL when out of memory, then memory is untouched. */
void* tb_mem_grow(void* memory, size_t old_size, size_t new_size);
/* Allocations that failed on this thread so far (tb_world_step reports a step
 * in which this grew). */
unsigned tb_mem_failure_count(void);

/* TB_OK while no world exists; else records TB_ERR_LOCKED naming fn (the
 * global settings change only then). */
tb_result tb_refuse_while_worlds_exist(const char* fn);

/* Hands a message to the game's log function (nothing without one). */
void tb_log(const char* message);
/* An internal-consistency check failed: logs it and calls the assert hook
 * (the default aborts). */
void tb_assert_failed(const char* condition, const char* file, int line);
#define TB_ASSERT(condition) ((condition) ? (void)0 : tb_assert_failed(#condition, __FILE__, __LINE__))

#endif
