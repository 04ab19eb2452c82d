/*
 * bake_splice.h - splice candidates and their Horn corrections
 * (bake_splice.c).
 */
#ifndef BAKE_SPLICE_H
#define BAKE_SPLICE_H

#include "bake_state.h"

smg_result smgb_find_splices(smgb_bake* b);

#endif /* BAKE_SPLICE_H */
