/*
 * bake_desc.c - the struct_size rule for smg_bake.h (see bake_desc.h).
 */
#include "bake_desc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "abi.h"

smg_result smgb_desc_resolve(const smg_bake_desc* in, smg_bake_desc* out,
                             smg_bake_clip_desc** clips, char* error,
                             size_t error_size) {
  smg_bake_options given;
  uint32_t stride, i;
  *clips = NULL;
  memset(out, 0, sizeof *out);
  if (!in || !smgi_struct_size_ok(in->struct_size, sizeof *out)) {
    snprintf(error, error_size,
             "smg_bake_run: desc.struct_size must be sizeof(smg_bake_desc) "
             "(or an older, smaller size)");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  memcpy(out, in, in->struct_size);
  out->struct_size = sizeof *out;
  /* options: all zero (struct_size 0) means defaults, else the same rule */
  given = out->options;
  memset(&out->options, 0, sizeof out->options);
  if (given.struct_size != 0) {
    if (!smgi_struct_size_ok(given.struct_size, sizeof given)) {
      snprintf(error, error_size,
               "smg_bake_run: options.struct_size must be 0 (defaults) or "
               "sizeof(smg_bake_options) (or an older, smaller size)");
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    memcpy(&out->options, &given, given.struct_size);
  }
  out->options.struct_size = sizeof out->options;
  if (!out->clips || out->clip_count == 0) {
    snprintf(error, error_size,
             "smg_bake_run: at least one clip is required");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  stride = out->clips[0].struct_size;
  if (!smgi_struct_size_ok(stride, sizeof **clips)) {
    snprintf(error, error_size,
             "clip 0: struct_size must be sizeof(smg_bake_clip_desc) (or an "
             "older, smaller size)");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  *clips = (smg_bake_clip_desc*)calloc(out->clip_count, sizeof **clips);
  if (!*clips) {
    snprintf(error, error_size, "out of memory");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (i = 0; i < out->clip_count; ++i) {
    const char* src = (const char*)out->clips + (size_t)i * stride;
    uint32_t size;
    memcpy(&size, src, sizeof size);
    if (size != stride) {
      snprintf(error, error_size,
               "clip %u: struct_size %u differs from clip 0's %u (one array "
               "holds structs of one size)",
               (unsigned)i, (unsigned)size, (unsigned)stride);
      free(*clips);
      *clips = NULL;
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    memcpy(&(*clips)[i], src, stride);
    (*clips)[i].struct_size = sizeof **clips;
  }
  out->clips = *clips;
  return SMG_OK;
}

int smgb_result_holds_blob(uint32_t struct_size) {
  return smgi_struct_size_ok(struct_size, sizeof(smg_bake_result)) &&
         struct_size >= offsetof(smg_bake_result, blob_size) + sizeof(size_t);
}
