/*
 * cli_testutil.h - for tests that drive the command-line tools through a
 * shell: run a command, and a scratch folder under the build for their
 * outputs (removed by the test's teardown). POSIX (mkdtemp, the shell's
 * exit status). Header-only.
 */
#ifndef SMG_CLI_TESTUTIL_H
#define SMG_CLI_TESTUTIL_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#ifndef SMG_BUILD_DIR
#define SMG_BUILD_DIR "build"
#endif

/* Runs the printf-formatted shell command; its exit status, -1 when it
 * did not exit normally. */
static inline int smgt_run(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static inline int smgt_run(const char* fmt, ...) {
  char cmd[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(cmd, sizeof cmd, fmt, ap);
  va_end(ap);
  int rc = system(cmd);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/* A fresh folder SMG_BUILD_DIR/tests/SUB-XXXXXX in dir (size n), once the
 * default graph the tools run on is there; 0 on success, -1 (after saying
 * why, for `test`) otherwise. */
static inline int smgt_scratch_dir(const char* test, const char* sub,
                                   char* dir, size_t n) {
  struct stat st;
  char blob[1024];
  snprintf(blob, sizeof blob, "%s/default.smg", SMG_BUILD_DIR);
  if (stat(blob, &st) != 0) {
    fprintf(stderr, "%s: %s missing: run `make` first\n", test, blob);
    return -1;
  }
  if (snprintf(dir, n, "%s/tests/%s-XXXXXX", SMG_BUILD_DIR, sub) >= (int)n)
    return -1;
  return mkdtemp(dir) ? 0 : -1;
}

#endif /* SMG_CLI_TESTUTIL_H */
