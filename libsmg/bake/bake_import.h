/*
 * bake_import.h - the import stage (bake_import.c): every clip of a
 * description loaded, cropped, put on the blob's skeleton, resampled to
 * the working rate, grounded, mirrored and added to the frame pool.
 */
#ifndef BAKE_IMPORT_H
#define BAKE_IMPORT_H

#include "bake_state.h"
#include "smg_bake.h"

/* Import every clip of `desc` (resolved to full size, bake_desc.h) into
 * `b`, whose options are resolved. A clip that fails is reported and the
 * others are still imported, so one run names every broken clip; the
 * result is then the first failure. */
smg_result smgb_import_clips(smgb_bake* b, const smg_bake_desc* desc);

#endif /* BAKE_IMPORT_H */
