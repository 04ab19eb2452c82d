/*
 * blob.h - the graph blob container: deterministic writer and validating
 * reader, shared by the baker (writes) and the runtime (reads).
 * Format: docs/blob-format.md; records: smg_format.h.
 */
#ifndef SMG_BLOB_H
#define SMG_BLOB_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"
#include "smg_format.h"

/* The payload checksum (SMG-WH64: FNV-1a steps on 64-bit little-endian
 * words in eight lanes; see checksum.c and docs/blob-format.md). */
uint64_t smgi_blob_checksum(const void* data, size_t size);

/* The same checksum in pieces, so that a reader can check records while
 * their bytes are still in the cache: begin, then blocks of whole 64-byte
 * blocks in order, then end with the last size % 64 bytes and the total
 * size. Gives exactly smgi_blob_checksum's value. */
typedef struct smgi_wh64 {
  uint64_t lane[8];
} smgi_wh64;
void smgi_wh64_begin(smgi_wh64* h);
void smgi_wh64_blocks(smgi_wh64* h, const void* data, size_t size);
uint64_t smgi_wh64_end(smgi_wh64* h, const void* tail, size_t tail_size,
                       size_t total_size);

/* Serialise `graph` into one freshly allocated, 16-byte aligned buffer
 * (through `allocator`, NULL = malloc). Same input -> byte-identical output
 * (padding is zeroed). The writer validates what it writes with the same
 * checks as the reader, so a baker bug cannot produce a blob the runtime
 * rejects. Free with smgi_blob_free. */
smg_result smgi_blob_write(const smgi_graph_data* graph,
                           const smg_allocator* allocator, void** out_data,
                           size_t* out_size, char* error, size_t error_size);
void smgi_blob_free(void* data, const smg_allocator* allocator);

/* Validate `data` (size bytes, 16-byte aligned) completely and fill `out`
 * with pointers into it. On failure returns the specific SMG_ERROR_BLOB_*
 * code and writes a one-line reason (section, record, field) into `error`
 * (may be NULL). flags: SMG_GRAPH_SKIP_CHECKSUM. Never reads outside
 * [data, data + size). */
smg_result smgi_blob_read(const void* data, size_t size, uint32_t flags,
                          smgi_graph_data* out, char* error,
                          size_t error_size);

#endif /* SMG_BLOB_H */
