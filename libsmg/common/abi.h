/*
 * abi.h - the one rule for struct_size in public structs (smg.h, and
 * smg_bake.h through libsmg/bake/bake_desc.c): a caller may pass an older,
 * smaller struct, but it must at least hold the struct_size field itself
 * and never claim more than this build knows.
 * Input descriptors are copied over zeroed defaults; output structs get
 * only the prefix the caller knows about.
 */
#ifndef SMG_ABI_H
#define SMG_ABI_H

#include <stddef.h>
#include <stdint.h>

static inline int smgi_struct_size_ok(uint32_t struct_size, size_t full) {
  return struct_size >= sizeof(uint32_t) && struct_size <= full;
}

#endif /* SMG_ABI_H */
