#include "pool.h"

#include <string.h>

#include "memory.h"

void tb_pool_init(tb_pool* pool, size_t item_size) {
  memset(pool, 0, sizeof *pool);
  pool->item_size = item_size;
  pool->free_head = -1;
}

size_t tb_pool_history_bytes(const tb_pool_history* history) {
  return (size_t)history->count * sizeof *history->generations;
}

void tb_pool_history_free(tb_pool_history* history) {
  tb_mem_free(history->generations, tb_pool_history_bytes(history));
  *history = (tb_pool_history){NULL, 0};
}

static size_t slot_bytes(const tb_pool* pool) {
  return pool->item_size + sizeof *pool->generations + sizeof *pool->next_free;
}

size_t tb_pool_bytes(const tb_pool* pool) { return (size_t)pool->capacity * slot_bytes(pool); }

void tb_pool_free(tb_pool* pool) {
  tb_pool_history_free(&pool->inherited);
  tb_mem_free(pool->items, (size_t)pool->capacity * pool->item_size);
  tb_mem_free(pool->generations, (size_t)pool->capacity * sizeof *pool->generations);
  tb_mem_free(pool->next_free, (size_t)pool->capacity * sizeof *pool->next_free);
  tb_pool_init(pool, pool->item_size);
}

/* All three arrays grow, or none does. */
static bool grow(tb_pool* pool) {
  if (pool->capacity > INT32_MAX / 2) return false;
  int old = pool->capacity, cap = old < 16 ? 16 : old * 2;
  void* items = tb_mem_alloc((size_t)cap * pool->item_size);
  uint16_t* gens = items != NULL ? tb_mem_alloc((size_t)cap * sizeof *gens) : NULL;
  int32_t* next = gens != NULL ? tb_mem_alloc((size_t)cap * sizeof *next) : NULL;
  if (next == NULL) {
    tb_mem_free(gens, (size_t)cap * sizeof *gens);
    tb_mem_free(items, (size_t)cap * pool->item_size);
    return false;
  }
  if (old > 0) {
    memcpy(items, pool->items, (size_t)old * pool->item_size);
    memcpy(gens, pool->generations, (size_t)old * sizeof *gens);
    memcpy(next, pool->next_free, (size_t)old * sizeof *next);
  }
  tb_mem_free(pool->items, (size_t)old * pool->item_size);
  tb_mem_free(pool->generations, (size_t)old * sizeof *gens);
  tb_mem_free(pool->next_free, (size_t)old * sizeof *next);
  pool->items = items;
  pool->generations = gens;
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
  TB_ASSERT(tb_pool_alive(pool, index));
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
  tb_pool_history_free(&pool->inherited);
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
    uint16_t* grown = tb_mem_grow(h.generations, tb_pool_history_bytes(&h), (size_t)pool->high * sizeof *grown);
    if (grown == NULL) {
      tb_pool_history_free(&h);
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
  if (!ok) tb_pool_history_free(&h);
  *history = h;
  tb_pool_free(pool);
  return ok;
}

bool tb_array_reserve(void** data, int* capacity, int need, size_t item_size) {
  if (need <= *capacity) return true;
  int cap = *capacity < 16 ? 16 : *capacity;
  while (cap < need) {
    if (cap > INT32_MAX / 2) return false;
    cap *= 2;
  }
  void* grown = tb_mem_grow(*data, (size_t)*capacity * item_size, (size_t)cap * item_size);
  if (grown == NULL) return false;
  *data = grown;
  *capacity = cap;
  return true;
}
