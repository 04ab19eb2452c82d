/*
 * gltf_bytes.h - a growable byte buffer for the glTF writer's JSON text and
 * binary chunk (an allocation failure is remembered and reported once at
 * the end, so the assembling code stays linear), and the file container.
 */
#ifndef SMG_GLTF_BYTES_H
#define SMG_GLTF_BYTES_H

#include <stddef.h>
#include <stdint.h>

#include "gltf_write.h"
#include "printf_check.h"

typedef struct gltf_bytes {
  unsigned char* data;
  size_t size, capacity;
  int failed; /* an allocation failed: contents are incomplete */
} gltf_bytes;

void gltf_bytes_append(gltf_bytes* b, const void* data, size_t size);
/* printf-style text (no terminating zero kept) */
void gltf_bytes_printf(gltf_bytes* b, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;
/* a JSON string literal, quotes and escapes included */
void gltf_bytes_json_string(gltf_bytes* b, const char* s);
void gltf_bytes_pad(gltf_bytes* b, size_t align, unsigned char fill);
void gltf_bytes_free(gltf_bytes* b);

/* Writes the finished document: `json` is the top-level object without its
 * closing brace and without a "buffers" entry (added here), `bin` the
 * binary buffer. GLTF_BINARY: a .glb container; GLTF_TEXT: JSON with the
 * buffer as a base64 data URI. Temporary file beside `path`, renamed over
 * it when complete. */
smg_result gltf_file_write(const char* path, gltf_bytes* json,
                           const gltf_bytes* bin, uint32_t format,
                           char* error, size_t error_size);

#endif /* SMG_GLTF_BYTES_H */
