/*
 * posix_memalign.h - posix_memalign for the tests' allocators on Windows,
 * force-included into the Windows test builds (mk/windows.mk).
 *
 * 64-bit Windows' malloc returns 16-byte aligned blocks that free()
 * releases, which covers every alignment up to 16. A larger one is refused
 * (EINVAL), so a test asking for it fails instead of getting a misaligned
 * block.
 */
#ifndef SMG_TESTS_WINDOWS_POSIX_MEMALIGN_H
#define SMG_TESTS_WINDOWS_POSIX_MEMALIGN_H

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>

static inline int posix_memalign(void** out, size_t align, size_t size) {
  void* p;
  if (align == 0 || (align & (align - 1)) != 0 || align > 16) return EINVAL;
  p = malloc(size ? size : 1);
  if (!p) return ENOMEM;
  if (((uintptr_t)p & (align - 1)) != 0) {
    free(p);
    return EINVAL;
  }
  *out = p;
  return 0;
}

#endif
