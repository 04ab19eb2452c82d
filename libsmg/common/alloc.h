/*
 * alloc.h - allocator hooks resolved to defaults, used by every part that
 * allocates (graph load, character create, blob writer).
 */
#ifndef SMG_ALLOC_H
#define SMG_ALLOC_H

#include <stddef.h>

#include "smg.h"

/* Copy `in` (may be NULL or all-zero) into `out`, filling malloc/free-based
 * defaults. Returns SMG_ERROR_INVALID_ARGUMENT if exactly one of alloc/free
 * is set. */
smg_result smgi_allocator_resolve(const smg_allocator* in, smg_allocator* out);
/* Aligned allocation through a resolved allocator (align: power of two). */
void* smgi_alloc(const smg_allocator* a, size_t size, size_t align);
void smgi_free(const smg_allocator* a, void* ptr);

#endif /* SMG_ALLOC_H */
