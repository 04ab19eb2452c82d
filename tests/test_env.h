/*
 * test_env.h - the test suites' view of their environment, in one place:
 * quick mode (set by `make test-valgrind`) and where the CMU clips are.
 * Header-only.
 */
#ifndef SMG_TEST_ENV_H
#define SMG_TEST_ENV_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef SMG_SHARED_DIR
#define SMG_SHARED_DIR "../shared"
#endif

/* SMG_TEST_QUICK set to anything but "" or "0" (valgrind runs): heavy
 * tests shrink their data. */
static inline int smgt_quick(void) {
  const char* q = getenv("SMG_TEST_QUICK");
  return q && q[0] && strcmp(q, "0") != 0;
}

/* The shared folder: $SMG_SHARED, else the build's SMG_SHARED_DIR. */
static inline const char* smgt_shared_dir(void) {
  const char* env = getenv("SMG_SHARED");
  return env && env[0] ? env : SMG_SHARED_DIR;
}

/* Folder of the CMU clips, or NULL after printing why the caller skips. */
static inline const char* smgt_cmu_dir(void) {
  static char dir[1024];
  char probe[1100];
  FILE* fp;
  snprintf(dir, sizeof dir, "%s/mocap/cmu", smgt_shared_dir());
  snprintf(probe, sizeof probe, "%s/09_12.bvh", dir);
  fp = fopen(probe, "rb");
  if (!fp) {
    printf("SKIP: CMU clips not found in %s (set SMG_SHARED to the folder "
           "holding mocap/cmu)\n", dir);
    return NULL;
  }
  fclose(fp);
  return dir;
}

#endif /* SMG_TEST_ENV_H */
