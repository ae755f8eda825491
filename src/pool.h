/* A slot pool: items in one array, reached by index, with a generation per slot
 * so that handles to freed slots are detected. */
#ifndef TB_POOL_H
#define TB_POOL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* What a world's pool leaves to the next world in the same world slot: the
 * generation each slot starts at (UINT16_MAX: retired, never handed out). Handles
 * carry the world slot but not the world's life, so the next world must not hand
 * out a (slot, generation) pair that a handle from an earlier world holds. */
typedef struct tb_pool_history {
  uint16_t* generations;
  int count; /* slots the earlier worlds handed out */
} tb_pool_history;

typedef struct tb_pool {
  void* items;
  uint16_t* generations; /* bumped on free; a handle matches only its own life */
  int32_t* next_free;    /* -2: in use; -3: retired; -1: end of free list; else next free slot */
  size_t item_size;
  int capacity;
  int count; /* slots in use */
  int high;  /* slots ever handed out */
  int free_head;
  tb_pool_history inherited; /* where slots not yet handed out start */
} tb_pool;

void tb_pool_init(tb_pool* pool, size_t item_size);
/* Bytes the pool's arrays hold (capacity, not count), and a history's. */
size_t tb_pool_bytes(const tb_pool* pool);
size_t tb_pool_history_bytes(const tb_pool_history* history);
void tb_pool_history_free(tb_pool_history* history);
void tb_pool_free(tb_pool* pool);
/* Starts an empty pool from the history an earlier world left (moved in). */
void tb_pool_inherit(tb_pool* pool, tb_pool_history* history);
/* Frees the pool and leaves its history: every slot ever handed out starts past
 * the generations of the handles to it. false when out of memory, or when a
 * slot has used up half its generations (TB_POOL_WORN): then the history is
 * freed and the world slot must not be used again. A world whose slot starts
 * that far on would retire slots, and so lay out its objects, differently
 * from the same world in a fresh slot; below it only a world reusing one
 * object slot 32,768 times does. */
#define TB_POOL_WORN 32768
bool tb_pool_end_life(tb_pool* pool, tb_pool_history* history);
/* Returns a zeroed slot index, or -1 when out of memory. */
int tb_pool_alloc(tb_pool* pool);
void tb_pool_release(tb_pool* pool, int index);
static inline bool tb_pool_alive(const tb_pool* pool, int index) {
  return index >= 0 && index < pool->high && pool->next_free[index] == -2;
}
static inline void* tb_pool_at(const tb_pool* pool, int index) {
  return (char*)pool->items + (size_t)index * pool->item_size;
}

/* Grows *data (of *capacity items of item_size) to hold at least `need` items,
 * doubling. false when out of memory (then nothing changed). Allocated
 * through the hooks: *capacity * item_size is the block's size. */
bool tb_array_reserve(void** data, int* capacity, int need, size_t item_size);

#endif
