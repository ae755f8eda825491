/* Counts the heap in use, for the leak and "memory flat" checks. The stress
 * programs are linked with -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,
 * --wrap=free, so every call from libtumble.a and from these sources lands
 * here; each block carries its size in a header. Not thread-safe (neither is
 * a tumble world). */
#include <stddef.h>
#include <string.h>

#include "stress.h"

void* __real_malloc(size_t size);
void* __real_realloc(void* p, size_t size);
void __real_free(void* p);
void* __wrap_malloc(size_t size);
void* __wrap_calloc(size_t n, size_t size);
void* __wrap_realloc(void* p, size_t size);
void __wrap_free(void* p);

/* max_align_t keeps the user block aligned as malloc's would be */
typedef union block_header {
  size_t size;
  max_align_t align;
} block_header;

static long long g_live_bytes;
static long long g_alloc_calls;
static long long g_peak_bytes;

long long stress_heap_live_bytes(void) { return g_live_bytes; }
long long stress_heap_alloc_calls(void) { return g_alloc_calls; }
long long stress_heap_peak_bytes(void) { return g_peak_bytes; }
void stress_heap_reset_peak(void) { g_peak_bytes = g_live_bytes; }

void* __wrap_malloc(size_t size) {
  block_header* h = __real_malloc(sizeof *h + size);
  if (h == NULL) return NULL;
  h->size = size;
  g_live_bytes += (long long)size;
  if (g_live_bytes > g_peak_bytes) g_peak_bytes = g_live_bytes;
  g_alloc_calls += 1;
  return h + 1;
}

void* __wrap_calloc(size_t n, size_t size) {
  if (size != 0 && n > ((size_t)-1 - sizeof(block_header)) / size) return NULL;
  void* p = __wrap_malloc(n * size);
  if (p != NULL) memset(p, 0, n * size);
  return p;
}

void* __wrap_realloc(void* p, size_t size) {
  if (p == NULL) return __wrap_malloc(size);
  block_header* old = (block_header*)p - 1;
  size_t old_size = old->size;
  /* a moving realloc holds the old block and the new one at once */
  if (g_live_bytes + (long long)size > g_peak_bytes) g_peak_bytes = g_live_bytes + (long long)size;
  block_header* h = __real_realloc(old, sizeof *h + size);
  if (h == NULL) return NULL;
  h->size = size;
  g_live_bytes += (long long)size - (long long)old_size;
  g_alloc_calls += 1;
  return h + 1;
}

void __wrap_free(void* p) {
  if (p == NULL) return;
  block_header* h = (block_header*)p - 1;
  g_live_bytes -= (long long)h->size;
  __real_free(h);
}
