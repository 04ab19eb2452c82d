/*
 * cmocka_harness.c - runs the unit tests on Windows with the meaning of
 * cmocka's runner (tests/windows/cmocka.h says which part).
 *
 * A failing assertion or skip() jumps back to the runner from the test's
 * own thread. From any other thread there is nowhere to jump to: the
 * failure is printed and the program exits with status 1, so it still
 * fails the run.
 */
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmocka.h"

enum { RUN_PASSED, RUN_FAILED, RUN_SKIPPED };

static jmp_buf g_jump;
static int g_in_test;
static pthread_t g_test_thread;

static void leave(int status) __attribute__((noreturn));
static void leave(int status) {
  fflush(stdout);
  if (!g_in_test || !pthread_equal(pthread_self(), g_test_thread)) {
    fprintf(stderr, "[  ERROR   ] %s outside the test's own thread\n",
            status == RUN_SKIPPED ? "skip()" : "failure");
    exit(1);
  }
  longjmp(g_jump, status);
}

void smgw_fail(const char* file, int line, const char* fmt, ...) {
  va_list ap;
  fprintf(stdout, "[  ERROR   ] --- ");
  va_start(ap, fmt);
  vfprintf(stdout, fmt, ap);
  va_end(ap);
  fprintf(stdout, "\n[   LINE   ] --- %s:%d: error: Failure!\n", file, line);
  leave(RUN_FAILED);
}

void smgw_skip(const char* file, int line) {
  (void)file;
  (void)line;
  leave(RUN_SKIPPED);
}

void smgw_int_equal(uintmax_t a, uintmax_t b, int want_equal, const char* as,
                    const char* bs, const char* file, int line) {
  if ((a == b) == (want_equal != 0)) return;
  smgw_fail(file, line, "%s (%ju, %#jx) %s %s (%ju, %#jx)", as, a, a,
            want_equal ? "!=" : "==", bs, b, b);
}

void smgw_float_equal(double a, double b, double epsilon, const char* as,
                      const char* bs, const char* file, int line) {
  if (a == b || fabs(a - b) <= epsilon) return;
  smgw_fail(file, line, "%s (%.9g) != %s (%.9g) within %g", as, a, bs, b,
            epsilon);
}

void smgw_memory_equal(const void* a, const void* b, size_t size,
                       const char* as, const char* bs, const char* file,
                       int line) {
  const unsigned char* pa = a;
  const unsigned char* pb = b;
  size_t i;
  if (!a || !b) smgw_fail(file, line, "%s or %s is NULL", as, bs);
  for (i = 0; i < size; ++i)
    if (pa[i] != pb[i])
      smgw_fail(file, line, "%s and %s differ at byte %zu of %zu (%#x, %#x)",
                as, bs, i, size, pa[i], pb[i]);
}

void smgw_string_equal(const char* a, const char* b, const char* as,
                       const char* bs, const char* file, int line) {
  if (a && b && strcmp(a, b) == 0) return;
  smgw_fail(file, line, "%s (\"%s\") != %s (\"%s\")", as, a ? a : "(null)",
            bs, b ? b : "(null)");
}

void print_message(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vfprintf(stdout, fmt, ap);
  va_end(ap);
}

void print_error(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
}

/* Runs f(state) (a test or fixture as a test); returns how it ended. */
static int run_guarded(void (*test)(void**), int (*fixture)(void**),
                       void** state) {
  volatile int status;
  g_in_test = 1;
  g_test_thread = pthread_self();
  status = setjmp(g_jump);
  if (status == 0) {
    if (test)
      test(state);
    else if (fixture(state) != 0)
      status = RUN_FAILED;
  }
  g_in_test = 0;
  fflush(stdout);
  return status;
}

int smgw_run_group(const char* name, const struct CMUnitTest* tests,
                   size_t count, CMFixtureFunction setup,
                   CMFixtureFunction teardown) {
  void* group_state = NULL;
  size_t i, passed = 0, skipped = 0, failed = 0;
  int status;
  printf("[==========] %s: Running %zu test(s).\n", name, count);
  if (setup) {
    status = run_guarded(NULL, setup, &group_state);
    if (status != RUN_PASSED) {
      printf("[  %s  ] %s: group setup\n",
             status == RUN_SKIPPED ? "SKIPPED" : " FAILED", name);
      return status == RUN_SKIPPED ? 0 : (int)count;
    }
  }
  for (i = 0; i < count; ++i) {
    const struct CMUnitTest* t = &tests[i];
    void* state = t->initial_state ? t->initial_state : group_state;
    printf("[ RUN      ] %s\n", t->name);
    fflush(stdout);
    status = RUN_PASSED;
    if (t->setup_func) status = run_guarded(NULL, t->setup_func, &state);
    if (status == RUN_PASSED) {
      status = run_guarded(t->test_func, NULL, &state);
      if (t->teardown_func &&
          run_guarded(NULL, t->teardown_func, &state) == RUN_FAILED)
        status = RUN_FAILED;
    }
    if (status == RUN_PASSED) {
      ++passed;
      printf("[       OK ] %s\n", t->name);
    } else if (status == RUN_SKIPPED) {
      ++skipped;
      printf("[  SKIPPED ] %s\n", t->name);
    } else {
      ++failed;
      printf("[  FAILED  ] %s\n", t->name);
    }
  }
  if (teardown && run_guarded(NULL, teardown, &group_state) == RUN_FAILED) {
    printf("[  FAILED  ] %s: group teardown\n", name);
    ++failed;
  }
  printf("[==========] %s: %zu test(s) run.\n[  PASSED  ] %zu test(s).\n",
         name, count, passed);
  if (skipped) printf("[  SKIPPED ] %zu test(s).\n", skipped);
  if (failed) printf("[  FAILED  ] %zu test(s).\n", failed);
  fflush(stdout);
  return (int)failed;
}
