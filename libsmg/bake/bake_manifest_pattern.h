/*
 * bake_manifest_pattern.h - file name patterns of manifest clip lines
 * (bake_manifest_pattern.c, docs/manifest.md "Folders").
 *
 * A pattern is a file name in which `*` stands for any run of characters
 * (no `/`); each `*` captures what it matched, leftmost-shortest first, and
 * a label template names the captures `{1}` .. `{9}`:
 *   pattern  dataset-2_walk*_*_*.bvh
 *   file     dataset-2_walk-turn-left_active_001.bvh
 *   captures "-turn-left", "active", "001";  "walk:{2}" -> "walk:active"
 */
#ifndef BAKE_MANIFEST_PATTERN_H
#define BAKE_MANIFEST_PATTERN_H

#include <stddef.h>
#include <stdint.h>

#include "bake_import_util.h"
#include "smg.h"

#define SMGB_PATTERN_CAPTURES 9

typedef struct smgb_pattern_match {
  const char* start[SMGB_PATTERN_CAPTURES];
  size_t length[SMGB_PATTERN_CAPTURES];
  int count;
} smgb_pattern_match;

/* 1 when `name` matches `pattern` (captures in *m), else 0. */
int smgb_pattern_matches(const char* pattern, const char* name,
                         smgb_pattern_match* m);

/* Replace {1}..{9} in `tmpl` by the captures. 0 when a brace names a
 * capture the pattern does not have, is malformed, or out is too small. */
int smgb_pattern_label(const char* tmpl, const smgb_pattern_match* m,
                       char* out, size_t size);

/* The names in folder `dir` matching `pattern` (regular files only),
 * sorted byte-wise, as one malloc'd array of *count strings of
 * SMGB_PATTERN_NAME_MAX bytes. SMG_ERROR_IO (err names the folder) when
 * the folder cannot be read. */
#define SMGB_PATTERN_NAME_MAX 256
smg_result smgb_pattern_list(const char* dir, const char* pattern,
                             char (**names)[SMGB_PATTERN_NAME_MAX],
                             uint32_t* count, smgb_error* err);

#endif /* BAKE_MANIFEST_PATTERN_H */
