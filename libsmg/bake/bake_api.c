/*
 * bake_api.c - smg_bake_run and smg_bake_result_free: the public entry
 * points, which read the caller's structs with the struct_size rule
 * (bake_desc.h) and hand full-size ones to the stage driver.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "abi.h"
#include "bake_desc.h"
#include "bake_pipeline.h"
#include "blob.h"

smg_result smg_bake_run(const smg_bake_desc* desc, smg_bake_result* out) {
  smg_bake_result full; /* the caller gets the prefix it knows about */
  smg_bake_desc resolved;
  smg_bake_clip_desc* clips;
  smg_result r;
  uint32_t size;
  if (!out || !smgi_struct_size_ok(out->struct_size, sizeof *out))
    return SMG_ERROR_INVALID_ARGUMENT;
  size = out->struct_size;
  memset(&full, 0, sizeof full);
  r = smgb_desc_resolve(desc, &resolved, &clips, full.error,
                        sizeof full.error);
  if (r == SMG_OK) {
    r = smgb_pipeline_run(&resolved, &full);
  } else {
    full.error_count = 1;
    snprintf(full.problems, sizeof full.problems, "error: %s\n", full.error);
  }
  free(clips);
  /* a caller whose struct cannot hold the blob cannot free it either */
  if (!smgb_result_holds_blob(size) && full.blob) {
    smgi_blob_free(full.blob, NULL);
    full.blob = NULL;
  }
  full.struct_size = size;
  memcpy(out, &full, size);
  return r;
}

void smg_bake_result_free(smg_bake_result* result) {
  if (!result || !smgb_result_holds_blob(result->struct_size)) return;
  if (result->blob) smgi_blob_free(result->blob, NULL);
  result->blob = NULL;
  result->blob_size = 0;
}
