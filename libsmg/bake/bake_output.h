/*
 * bake_output.h - the blob from the finished state (bake_output.c).
 */
#ifndef BAKE_OUTPUT_H
#define BAKE_OUTPUT_H

#include <stddef.h>

#include "bake_state.h"

smg_result smgb_write_blob(smgb_bake* b, void** out_blob, size_t* out_size);

#endif /* BAKE_OUTPUT_H */
