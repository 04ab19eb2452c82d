/*
 * gltf_file.c - the glTF writer's byte buffer and file container: .glb
 * (12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with
 * zeros) or .gltf (the buffer as a base64 data URI), written to a
 * temporary file beside the target, flushed to the disk and only then
 * renamed over it, so readers see the old file or the whole new one.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "file_replace.h"
#include "gltf_bytes.h"

static int reserve(gltf_bytes* b, size_t extra) {
  size_t want;
  unsigned char* p;
  if (b->failed) return 0;
  if (extra > ((size_t)-1) / 2 - b->size) {
    b->failed = 1;
    return 0;
  }
  want = b->size + extra;
  if (want <= b->capacity) return 1;
  if (want < 2 * b->capacity) want = 2 * b->capacity;
  if (want < 4096) want = 4096;
  p = (unsigned char*)realloc(b->data, want);
  if (!p) {
    b->failed = 1;
    return 0;
  }
  b->data = p;
  b->capacity = want;
  return 1;
}

void gltf_bytes_append(gltf_bytes* b, const void* data, size_t size) {
  if (!size || !reserve(b, size)) return;
  memcpy(b->data + b->size, data, size);
  b->size += size;
}

void gltf_bytes_printf(gltf_bytes* b, const char* fmt, ...) {
  va_list ap;
  int n;
  va_start(ap, fmt);
  n = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  if (n < 0) {
    b->failed = 1;
    return;
  }
  /* one byte more for vsnprintf's terminator, which is not kept */
  if (!reserve(b, (size_t)n + 1)) return;
  va_start(ap, fmt);
  vsnprintf((char*)b->data + b->size, (size_t)n + 1, fmt, ap);
  va_end(ap);
  b->size += (size_t)n;
}

void gltf_bytes_json_string(gltf_bytes* b, const char* s) {
  gltf_bytes_append(b, "\"", 1);
  for (; *s; ++s) {
    unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\')
      gltf_bytes_printf(b, "\\%c", c);
    else if (c < 0x20)
      gltf_bytes_printf(b, "\\u%04x", c);
    else
      gltf_bytes_append(b, &c, 1);
  }
  gltf_bytes_append(b, "\"", 1);
}

void gltf_bytes_pad(gltf_bytes* b, size_t align, unsigned char fill) {
  while (!b->failed && b->size % align) gltf_bytes_append(b, &fill, 1);
}

void gltf_bytes_free(gltf_bytes* b) {
  free(b->data);
  memset(b, 0, sizeof *b);
}

static void put_u32(unsigned char* p, uint32_t v) {
  p[0] = (unsigned char)(v & 255u);
  p[1] = (unsigned char)((v >> 8) & 255u);
  p[2] = (unsigned char)((v >> 16) & 255u);
  p[3] = (unsigned char)(v >> 24);
}

static void base64(gltf_bytes* out, const gltf_bytes* in) {
  static const char k[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  size_t i;
  for (i = 0; i < in->size; i += 3) {
    unsigned long v = (unsigned long)in->data[i] << 16;
    char q[4];
    if (i + 1 < in->size) v |= (unsigned long)in->data[i + 1] << 8;
    if (i + 2 < in->size) v |= in->data[i + 2];
    q[0] = k[(v >> 18) & 63];
    q[1] = k[(v >> 12) & 63];
    q[2] = i + 1 < in->size ? k[(v >> 6) & 63] : '=';
    q[3] = i + 2 < in->size ? k[v & 63] : '=';
    gltf_bytes_append(out, q, 4);
  }
}

/* The finished file in memory: .glb container or .gltf text. */
static void assemble(gltf_bytes* file, gltf_bytes* json, const gltf_bytes* bin,
                     uint32_t format) {
  if (format == GLTF_BINARY) {
    unsigned char head[20];
    gltf_bytes_printf(json, ",\"buffers\":[{\"byteLength\":%zu}]}", bin->size);
    gltf_bytes_pad(json, 4, ' ');
    if (json->failed || json->size > 0xffffffffu - bin->size - 28u) {
      file->failed = 1;
      return;
    }
    put_u32(head, 0x46546C67u); /* "glTF" */
    put_u32(head + 4, 2u);
    put_u32(head + 8, (uint32_t)(12u + 8u + json->size + 8u + bin->size));
    put_u32(head + 12, (uint32_t)json->size);
    put_u32(head + 16, 0x4E4F534Au); /* "JSON" */
    gltf_bytes_append(file, head, 20);
    gltf_bytes_append(file, json->data, json->size);
    put_u32(head, (uint32_t)bin->size);
    put_u32(head + 4, 0x004E4942u); /* "BIN\0" */
    gltf_bytes_append(file, head, 8);
    gltf_bytes_append(file, bin->data, bin->size);
  } else {
    gltf_bytes_append(file, json->data, json->size);
    gltf_bytes_printf(file,
                      ",\"buffers\":[{\"byteLength\":%zu,\"uri\":\"data:"
                      "application/octet-stream;base64,",
                      bin->size);
    base64(file, bin);
    gltf_bytes_printf(file, "\"}]}\n");
  }
}

static void say(char* error, size_t error_size, const char* fmt,
                const char* a, const char* b) {
  if (error && error_size) snprintf(error, error_size, fmt, a, b);
}

smg_result gltf_file_write(const char* path, gltf_bytes* json,
                           const gltf_bytes* bin, uint32_t format,
                           char* error, size_t error_size) {
  gltf_bytes file = {NULL, 0, 0, 0};
  char tmp[4096];
  const char* base = smg_file_base(path);
  FILE* f;
  int fd, ok;
  assemble(&file, json, bin, format);
  if (file.failed || json->failed || bin->failed) {
    gltf_bytes_free(&file);
    say(error, error_size, "%s: out of memory assembling the file%s", path,
        "");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  if (snprintf(tmp, sizeof tmp, "%.*s.%s.XXXXXX", (int)(base - path), path,
               base) >= (int)sizeof tmp) {
    gltf_bytes_free(&file);
    say(error, error_size, "%s: path too long%s", path, "");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  fd = mkstemp(tmp);
  if (fd < 0) {
    gltf_bytes_free(&file);
    say(error, error_size, "%s: cannot create a file beside it (%s)", path,
        strerror(errno));
    return SMG_ERROR_IO;
  }
  if (smg_file_keep_mode(fd, path) != 0 ||
      !(f = fdopen(fd, "wb"))) {
    close(fd);
    remove(tmp);
    gltf_bytes_free(&file);
    say(error, error_size, "%s: cannot open for writing%s", tmp, "");
    return SMG_ERROR_IO;
  }
  ok = fwrite(file.data, 1, file.size, f) == file.size && fflush(f) == 0 &&
       smg_file_sync(fd) == 0;
  gltf_bytes_free(&file);
  if (fclose(f) != 0 || !ok) {
    remove(tmp);
    say(error, error_size, "%s: write failed (disk full?); %s is unchanged",
        tmp, path);
    return SMG_ERROR_IO;
  }
  if (smg_file_replace(tmp, path) != 0) {
    remove(tmp);
    say(error, error_size, "%s: cannot rename to %s", tmp, path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
