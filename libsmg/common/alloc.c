/*
 * alloc.c - resolve optional allocator hooks to malloc-based defaults.
 */
#include "alloc.h"

#include <stdint.h>
#include <stdlib.h>
#ifdef _WIN32
#include <malloc.h> /* _aligned_malloc: Windows has no posix_memalign */
#endif

static void* default_alloc(size_t size, size_t align, void* user) {
  void* p = NULL;
  (void)user;
  /* posix_memalign needs a multiple of sizeof(void*). */
  if (align < sizeof(void*)) align = sizeof(void*);
#ifdef _WIN32
  p = _aligned_malloc(size ? size : 1, align);
#else
  if (posix_memalign(&p, align, size ? size : 1) != 0) return NULL;
#endif
  return p;
}

static void default_free(void* ptr, void* user) {
  (void)user;
#ifdef _WIN32
  _aligned_free(ptr);
#else
  free(ptr);
#endif
}

smg_result smgi_allocator_resolve(const smg_allocator* in,
                                  smg_allocator* out) {
  if (!out) return SMG_ERROR_INVALID_ARGUMENT;
  if (!in || (!in->alloc && !in->free)) {
    out->alloc = default_alloc;
    out->free = default_free;
    out->user = NULL;
    return SMG_OK;
  }
  if (!in->alloc || !in->free) return SMG_ERROR_INVALID_ARGUMENT;
  *out = *in;
  return SMG_OK;
}

void* smgi_alloc(const smg_allocator* a, size_t size, size_t align) {
  void* p;
  smg_allocator resolved;
  if (align == 0 || (align & (align - 1)) != 0 || align > 64) return NULL;
  if (!a || !a->alloc || !a->free) {
    if (smgi_allocator_resolve(NULL, &resolved) != SMG_OK) return NULL;
    a = &resolved;
  }
  p = a->alloc(size ? size : 1, align, a->user);
  /* A hook that ignores `align` would make every later aligned access
   * undefined; refuse its memory rather than trust it. */
  if (p && ((uintptr_t)p & (uintptr_t)(align - 1)) != 0) {
    a->free(p, a->user);
    return NULL;
  }
  return p;
}

void smgi_free(const smg_allocator* a, void* ptr) {
  if (!ptr) return;
  if (!a || !a->free) {
    free(ptr);
    return;
  }
  a->free(ptr, a->user);
}
