/*
 * cmocka.h - the part of cmocka's API the runtime and core unit tests use,
 * for the Windows builds (Debian ships cmocka for Linux only; mk/windows.mk
 * puts this folder first on the include path there). The Linux builds use
 * the real cmocka.
 *
 * Same meaning as cmocka: a failed assertion ends its test (longjmp back to
 * the runner) and counts as a failure; skip() ends it as skipped; the group
 * runners return the number of failed tests; a group's setup state is each
 * test's initial state. Not provided: mocks, expectations and the leak
 * checking allocators (the tests do not use them; the Linux runs under
 * valgrind check leaks).
 */
#ifndef SMG_TESTS_WINDOWS_CMOCKA_H
#define SMG_TESTS_WINDOWS_CMOCKA_H

#include <stddef.h>
#include <stdint.h>

typedef void (*CMUnitTestFunction)(void** state);
typedef int (*CMFixtureFunction)(void** state);

struct CMUnitTest {
  const char* name;
  CMUnitTestFunction test_func;
  CMFixtureFunction setup_func;
  CMFixtureFunction teardown_func;
  void* initial_state;
};

#define cmocka_unit_test(f) \
  { #f, f, NULL, NULL, NULL }
#define cmocka_unit_test_setup_teardown(f, setup, teardown) \
  { #f, f, setup, teardown, NULL }

int smgw_run_group(const char* name, const struct CMUnitTest* tests,
                   size_t count, CMFixtureFunction setup,
                   CMFixtureFunction teardown);
#define cmocka_run_group_tests(group, setup, teardown) \
  smgw_run_group(#group, group, sizeof(group) / sizeof((group)[0]), setup, \
                 teardown)
#define cmocka_run_group_tests_name(name, group, setup, teardown)            \
  smgw_run_group(name, group, sizeof(group) / sizeof((group)[0]), setup, \
                 teardown)

void smgw_fail(const char* file, int line, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(gnu_printf, 3, 4), noreturn))
#endif
    ;
void smgw_skip(const char* file, int line)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;
void smgw_int_equal(uintmax_t a, uintmax_t b, int want_equal, const char* as,
                    const char* bs, const char* file, int line);
void smgw_float_equal(double a, double b, double epsilon, const char* as,
                      const char* bs, const char* file, int line);
void smgw_memory_equal(const void* a, const void* b, size_t size,
                       const char* as, const char* bs, const char* file,
                       int line);
void smgw_string_equal(const char* a, const char* b, const char* as,
                       const char* bs, const char* file, int line);
void print_message(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(gnu_printf, 1, 2)))
#endif
    ;
void print_error(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(gnu_printf, 1, 2)))
#endif
    ;

#define assert_true(c) \
  ((c) ? (void)0 : smgw_fail(__FILE__, __LINE__, "%s is false", #c))
#define assert_false(c) \
  ((c) ? smgw_fail(__FILE__, __LINE__, "%s is true", #c) : (void)0)
#define assert_non_null(p) \
  ((p) != NULL ? (void)0 : smgw_fail(__FILE__, __LINE__, "%s is NULL", #p))
#define assert_null(p)                                                   \
  ((p) == NULL ? (void)0                                                 \
               : smgw_fail(__FILE__, __LINE__, "%s is %p, not NULL", #p, \
                           (const void*)(p)))
#define assert_ptr_equal(a, b)                                                \
  ((const void*)(a) == (const void*)(b)                                       \
       ? (void)0                                                              \
       : smgw_fail(__FILE__, __LINE__, "%s (%p) != %s (%p)", #a,              \
                   (const void*)(a), #b, (const void*)(b)))
/* cmocka compares integers as its largest integral type, as here */
#define assert_int_equal(a, b) \
  smgw_int_equal((uintmax_t)(a), (uintmax_t)(b), 1, #a, #b, __FILE__, __LINE__)
#define assert_int_not_equal(a, b) \
  smgw_int_equal((uintmax_t)(a), (uintmax_t)(b), 0, #a, #b, __FILE__, __LINE__)
#define assert_float_equal(a, b, epsilon) \
  smgw_float_equal((a), (b), (epsilon), #a, #b, __FILE__, __LINE__)
#define assert_memory_equal(a, b, size) \
  smgw_memory_equal((a), (b), (size), #a, #b, __FILE__, __LINE__)
#define assert_string_equal(a, b) \
  smgw_string_equal((a), (b), #a, #b, __FILE__, __LINE__)
#define fail() smgw_fail(__FILE__, __LINE__, "fail()")
#define fail_msg(...) smgw_fail(__FILE__, __LINE__, __VA_ARGS__)
#define skip() smgw_skip(__FILE__, __LINE__)

#endif
