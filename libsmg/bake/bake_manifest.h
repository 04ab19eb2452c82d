/*
 * bake_manifest.h - the baker's input description: which clips feed which
 * graph, with which label, frame range and mirroring (docs/manifest.md).
 *
 * A manifest file is parsed into an smgb_manifest; the smg-bake CLI can also
 * build one from command-line arguments with smgb_manifest_init +
 * smgb_manifest_add, then turn it into smg_bake_clip_desc records with
 * smgb_manifest_descs (the strings stay owned by the manifest).
 */
#ifndef BAKE_MANIFEST_H
#define BAKE_MANIFEST_H

#include <stdint.h>

#include "bake_clip.h"
#include "smg_bake.h"

#define SMGB_PATH_MAX 1024
#define SMGB_MANIFEST_MAX_CLIPS 4096
#define SMGB_BONES_MAX 2048 /* bone map text: every role once fits */

typedef struct smgb_manifest_clip {
  uint32_t role;              /* SMG_BAKE_ROLE_LOWER / _UPPER */
  char label[SMGB_NAME_MAX];  /* style or action */
  char name[SMGB_NAME_MAX];   /* "" = the file name */
  char path[SMGB_PATH_MAX];   /* resolved: root joined unless absolute */
  uint32_t first_frame;       /* after the skipped T-pose (desc semantics) */
  uint32_t frame_count;       /* 0 = to the end */
  uint32_t mirror;            /* SMG_BAKE_MIRROR_* */
  uint32_t skip_first_frame;  /* 1: drop a T-pose frame 0 */
  float unit_scale;           /* 0 = guess */
  uint32_t animation_index;   /* assimp files */
  int32_t line;               /* manifest line (0: not from a file) */
  uint32_t from_folder;       /* 1: one of a pattern's files (a bake skips
                                 it with a warning when unusable) */
  char bones[SMGB_BONES_MAX]; /* bone map, "role=joint" lines ("" = by
                                 name; bake_roles.h) */
} smgb_manifest_clip;

typedef struct smgb_manifest {
  char path[SMGB_PATH_MAX];   /* the manifest file ("" when built in code) */
  char root[SMGB_PATH_MAX];   /* folder clip paths are relative to */
  float frame_rate;           /* working frame rate; 0 = baker default */
  uint32_t clip_count;
  uint32_t clip_capacity;
  smgb_manifest_clip* clips;
  char target[SMGB_PATH_MAX]; /* `target` rig ("" = first clip's skeleton) */
  float target_unit;          /* its unit, 0 = guess */
  uint32_t target_animation;  /* its animation (assimp rigs) */
} smgb_manifest;

/* Empty manifest whose relative clip paths resolve against `root` (NULL or
 * "" = the current directory). */
smg_result smgb_manifest_init(smgb_manifest* m, const char* root);

/* Append a clip. `file` is resolved against m->root unless absolute; label
 * must be 1-63 characters of [A-Za-z0-9_.-:], and an upper label may not be
 * "none". check_exists: fail with SMG_ERROR_IO when the file is not
 * readable. Errors name the manifest file and clip->line when known. */
smg_result smgb_manifest_add(smgb_manifest* m, const smgb_manifest_clip* clip,
                             const char* file, int check_exists,
                             smgb_error* err);

/* Parse a manifest file. data_dir_override (may be NULL) replaces the
 * file's `root`. Every referenced clip must exist. On failure *out is left
 * empty (nothing to free). */
smg_result smgb_manifest_load(const char* path, const char* data_dir_override,
                              smgb_manifest* out, smgb_error* err);

/* Fill `descs` (capacity m->clip_count) for smg_bake_run; the strings point
 * into the manifest, which must outlive the descriptors. */
smg_result smgb_manifest_descs(const smgb_manifest* m,
                               smg_bake_clip_desc* descs, uint32_t capacity);

void smgb_manifest_free(smgb_manifest* m);

#endif /* BAKE_MANIFEST_H */
