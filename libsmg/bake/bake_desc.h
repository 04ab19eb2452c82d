/*
 * bake_desc.h - smg_bake.h's structs read with the one struct_size rule
 * (libsmg/common/abi.h), as smg.h's are: a caller may pass an older,
 * smaller struct; inputs are copied over zeroed defaults, outputs get only
 * the prefix the caller knows about.
 */
#ifndef SMG_BAKE_DESC_H
#define SMG_BAKE_DESC_H

#include <stddef.h>

#include "smg_bake.h"

/* Copy `in`, its options and every clip desc into full-size structs
 * (missing fields zero). The clip array is read with the caller's element
 * size, clips[0].struct_size, which every clip must repeat. On success
 * out->clips points to *clips (free() it); on failure *clips is NULL and
 * `error` says which struct_size or field is wrong. */
smg_result smgb_desc_resolve(const smg_bake_desc* in, smg_bake_desc* out,
                             smg_bake_clip_desc** clips, char* error,
                             size_t error_size);

/* Whether a result of this struct_size holds the blob and its size (the
 * fields smg_bake_result_free and smg_bake_write_file read). */
int smgb_result_holds_blob(uint32_t struct_size);

#endif /* SMG_BAKE_DESC_H */
