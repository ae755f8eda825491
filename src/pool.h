/* A slot pool: items in one array, reached by index, with a generation per slot
 * so that handles to freed slots are detected. */
#ifndef TB_POOL_H
#define TB_POOL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct tb_pool {
  void* items;
  uint16_t* generations; /* bumped on free; a handle matches only its own life */
  int32_t* next_free;    /* -2: in use; -3: retired; -1: end of free list; else next free slot */
  size_t item_size;
  int capacity;
  int count; /* slots in use */
  int high;  /* slots ever handed out */
  int free_head;
} tb_pool;

void tb_pool_init(tb_pool* pool, size_t item_size);
void tb_pool_free(tb_pool* pool);
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
 * doubling. false when out of memory (then nothing changed). */
bool tb_array_reserve(void** data, int* capacity, int need, size_t item_size);

#endif
