/*
 * import_helpers.h - shared helpers for the baker import tests (BVH, clips,
 * manifest, synthetic, assimp): temp files, the CMU data folder, quick mode.
 * Header-only; include after <cmocka.h>.
 */
#ifndef IMPORT_HELPERS_H
#define IMPORT_HELPERS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake_clip.h"
#include "test_env.h"


/* A fresh private temp folder (removed by imp_rmdir). */
static inline void imp_tempdir(char* out, size_t n) {
  snprintf(out, n, "/tmp/smg-import-test-XXXXXX");
  if (!mkdtemp(out)) out[0] = '\0';
}

static inline void imp_rmdir(const char* dir) {
  char cmd[1200];
  if (!dir || strncmp(dir, "/tmp/smg-import-test-", 21) != 0) return;
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

static inline int imp_write_file(const char* path, const char* text) {
  FILE* fp = fopen(path, "wb");
  if (!fp) return 0;
  fputs(text, fp);
  return fclose(fp) == 0;
}

/* Largest absolute difference between two clips' poses (frame counts and
 * joint counts must match, else returns 1e30). */
static inline double imp_pose_diff(const smgb_clip* a, const smgb_clip* b) {
  size_t n, i;
  double m = 0.0;
  if (a->frame_count != b->frame_count ||
      a->skeleton.joint_count != b->skeleton.joint_count)
    return 1e30;
  n = (size_t)a->frame_count * SMGB_STRIDE(a->skeleton.joint_count);
  for (i = 0; i < n; ++i) {
    double d = a->poses[i] - b->poses[i];
    if (d < 0) d = -d;
    if (d > m) m = d;
  }
  return m;
}

/* Rotation-aware difference: max over frames/joints of 1 - |dot(qa, qb)|
 * plus max translation difference (q and -q are the same rotation). */
static inline double imp_rot_diff(const smgb_clip* a, const smgb_clip* b) {
  uint32_t f, j, J = a->skeleton.joint_count, S = SMGB_STRIDE(J);
  double m = 0.0;
  if (a->frame_count != b->frame_count || J != b->skeleton.joint_count)
    return 1e30;
  for (f = 0; f < a->frame_count; ++f) {
    const float* p = a->poses + (size_t)f * S;
    const float* q = b->poses + (size_t)f * S;
    for (j = 0; j < 3; ++j) {
      double d = p[j] - q[j];
      if (d < 0) d = -d;
      if (d > m) m = d;
    }
    for (j = 0; j < J; ++j) {
      const float* x = p + 3 + 4 * j;
      const float* y = q + 3 + 4 * j;
      double dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3];
      double d = 1.0 - (dot < 0 ? -dot : dot);
      if (d > m) m = d;
    }
  }
  return m;
}

#endif /* IMPORT_HELPERS_H */
