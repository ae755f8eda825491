#include "pool.h"

#include <stdlib.h>
#include <string.h>

void tb_pool_init(tb_pool* pool, size_t item_size) {
  memset(pool, 0, sizeof *pool);
  pool->item_size = item_size;
  pool->free_head = -1;
}

void tb_pool_free(tb_pool* pool) {
  free(pool->inherited.generations);
  free(pool->items);
  free(pool->generations);
  free(pool->next_free);
  tb_pool_init(pool, pool->item_size);
}

static bool grow(tb_pool* pool) {
  int cap = pool->capacity < 16 ? 16 : pool->capacity * 2;
  void* items = realloc(pool->items, (size_t)cap * pool->item_size);
  if (items == NULL) return false;
  pool->items = items;
  uint16_t* gens = realloc(pool->generations, (size_t)cap * sizeof *gens);
  if (gens == NULL) return false;
  pool->generations = gens;
  int32_t* next = realloc(pool->next_free, (size_t)cap * sizeof *next);
  if (next == NULL) return false;
  pool->next_free = next;
  pool->capacity = cap;
  return true;
}

int tb_pool_alloc(tb_pool* pool) {
  int index;
  if (pool->free_head >= 0) {
    index = pool->free_head;
    pool->free_head = pool->next_free[index];
  } else {
    /* a fresh slot starts where earlier worlds left it; one they retired is skipped */
    for (;;) {
      if (pool->high == pool->capacity && !grow(pool)) return -1;
      index = pool->high++;
      const tb_pool_history* h = &pool->inherited;
      pool->generations[index] = index < h->count ? h->generations[index] : 0;
      if (pool->generations[index] != UINT16_MAX) break;
      pool->next_free[index] = -3;
    }
  }
  pool->next_free[index] = -2;
  pool->count += 1;
  memset(tb_pool_at(pool, index), 0, pool->item_size);
  return index;
}

/* LIFO reuse: the layout depends only on the sequence of calls. A slot whose
 * generation would wrap is retired instead of reused, so an old handle can never
 * match a new object. */
void tb_pool_release(tb_pool* pool, int index) {
  pool->count -= 1;
  if (pool->generations[index] == UINT16_MAX) {
    pool->next_free[index] = -3; /* retired: never alive again */
    return;
  }
  pool->generations[index] += 1;
  pool->next_free[index] = pool->free_head;
  pool->free_head = index;
}

void tb_pool_inherit(tb_pool* pool, tb_pool_history* history) {
  free(pool->inherited.generations);
  pool->inherited = *history;
  *history = (tb_pool_history){NULL, 0};
}

/* A live slot's handles hold its generation, a free slot's handles one less
 * (release bumped it): the next world starts a live slot one past its
 * generation and a free one at it. UINT16_MAX marks a retired slot, so a slot
 * that would start there is retired one life early. */
bool tb_pool_end_life(tb_pool* pool, tb_pool_history* history) {
  tb_pool_history h = pool->inherited;
  pool->inherited = (tb_pool_history){NULL, 0};
  bool ok = true;
  if (pool->high > h.count) {
    uint16_t* grown = realloc(h.generations, (size_t)pool->high * sizeof *grown);
    if (grown == NULL) {
      free(h.generations);
      h = (tb_pool_history){NULL, 0};
      ok = false;
    } else {
      h.generations = grown;
      h.count = pool->high;
    }
  }
  for (int i = 0; ok && i < pool->high; ++i) {
    uint16_t g = pool->generations[i];
    if (pool->next_free[i] == -3)
      g = UINT16_MAX;
    else if (pool->next_free[i] == -2 && g < UINT16_MAX)
      g += 1;
    h.generations[i] = g;
    if (g >= TB_POOL_WORN) ok = false;
  }
  if (!ok) {
    free(h.generations);
    h = (tb_pool_history){NULL, 0};
  }
  *history = h;
  tb_pool_free(pool);
  return ok;
}

bool tb_array_reserve(void** data, int* capacity, int need, size_t item_size) {
  if (need <= *capacity) return true;
  int cap = *capacity < 16 ? 16 : *capacity;
  while (cap < need) cap *= 2;
  void* grown = realloc(*data, (size_t)cap * item_size);
  if (grown == NULL) return false;
  *data = grown;
  *capacity = cap;
  return true;
}
