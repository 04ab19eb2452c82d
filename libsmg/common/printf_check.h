/*
 * printf_check.h - the attribute that has the compiler check printf-style
 * format strings against their arguments.
 *
 * MinGW's compiler checks the `printf` archetype against the Microsoft C
 * library's rules (no %zu). The Windows build uses MinGW's own C99 printf
 * (__USE_MINGW_ANSI_STDIO, mk/windows.mk), whose rules are `gnu_printf`.
 */
#ifndef SMG_PRINTF_CHECK_H
#define SMG_PRINTF_CHECK_H

#if defined(__MINGW32__)
#define SMG_PRINTF_CHECK(fmt, first) \
  __attribute__((format(gnu_printf, fmt, first)))
#elif defined(__GNUC__)
#define SMG_PRINTF_CHECK(fmt, first) __attribute__((format(printf, fmt, first)))
#else
#define SMG_PRINTF_CHECK(fmt, first)
#endif

#endif
