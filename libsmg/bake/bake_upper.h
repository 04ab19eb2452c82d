/*
 * bake_upper.h - upper-body segment centres of gravity of pool frames
 * (bake_upper.c), the quantity splice candidates are matched on.
 */
#ifndef BAKE_UPPER_H
#define BAKE_UPPER_H

#include <stdint.h>

#include "bake_state.h"

/* Upper-body segment COGs of pool frame f relative to its root ground frame
 * (x, y, z per upper segment) and the matching weights (mass ratios). */
void smgb_upper_cogs(const smgb_bake* b, uint32_t f, double* out_xyz);
void smgb_upper_weights(const smgb_bake* b, double* out_w);

#endif /* BAKE_UPPER_H */
