/*
 * bake_import_util.h - small helpers shared by the importers and clip
 * processing (bake_bvh.c, bake_assimp.c, bake_import.c, bake_roles.c,
 * bake_retarget.c, bake_manifest.c, ...): error formatting, names compared
 * without case, file extensions. static inline: no symbols exported.
 */
#ifndef BAKE_IMPORT_UTIL_H
#define BAKE_IMPORT_UTIL_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "bake_report.h"
#include "printf_check.h"

/* Printf into err->message (err may be NULL). */
static inline void smgb_imp_errorf(smgb_error* err, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;
static inline void smgb_imp_errorf(smgb_error* err, const char* fmt, ...) {
  va_list ap;
  if (!err) return;
  va_start(ap, fmt);
  vsnprintf(err->message, sizeof err->message, fmt, ap);
  va_end(ap);
}

/* ASCII case-insensitive equality: exporters disagree on "End Site" vs
 * "End site", "Xrotation" vs "XRotation", rigs on "Hips" vs "hips". */
static inline int smgb_name_ieq(const char* a, const char* b) {
  for (; *a && *b; ++a, ++b) {
    char x = *a, y = *b;
    if (x >= 'A' && x <= 'Z') x = (char)(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = (char)(y - 'A' + 'a');
    if (x != y) return 0;
  }
  return *a == *b;
}

/* Whether `path` ends in `ext` (".bvh"), in any case. */
static inline int smgb_has_ext(const char* path, const char* ext) {
  size_t n = strlen(path), e = strlen(ext);
  return n >= e && smgb_name_ieq(path + n - e, ext);
}

/* File units -> metres: the common unit (m, cm, mm, inch, CMU's 1/0.45
 * inch) that makes `leg` (a leg's length, or near it the hips height, in
 * file units) closest to a human's ~0.85 m in log scale; 1 when unknown. */
static inline double smgb_unit_from_leg(double leg) {
  static const double units[5] = {1.0, 0.01, 0.001, 0.0254, 0.056444};
  double best = 1.0, best_err = 1e300;
  int i;
  if (!(leg > 0.0)) return 1.0;
  for (i = 0; i < 5; ++i) {
    double e = fabs(log(leg * units[i] / 0.85));
    if (e < best_err) {
      best_err = e;
      best = units[i];
    }
  }
  return best;
}

#endif /* BAKE_IMPORT_UTIL_H */
