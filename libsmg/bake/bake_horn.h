/*
 * bake_horn.h - Horn's 1987 closed-form absolute orientation
 * (bake_horn.c), used for the splice spine correction and mirroring.
 */
#ifndef BAKE_HORN_H
#define BAKE_HORN_H

#include <stdint.h>

/* Rotation q (x,y,z,w) minimising sum w_i |q a_i q* - b_i|^2 (points
 * already relative to their centres of rotation). */
void smgb_horn(const double* a, const double* b, const double* w,
               uint32_t n, double q[4]);

#endif /* BAKE_HORN_H */
