/*
 * bake_transition.h - blended transition frames (bake_transition.c).
 */
#ifndef BAKE_TRANSITION_H
#define BAKE_TRANSITION_H

#include <stdint.h>

#include "bake_state.h"
#include "bake_workgraph.h"

/* Blend weight of A at window step t (Kovar: 2s^3 - 3s^2 + 1, s=(t+1)/k). */
double smgb_blend_alpha(uint32_t t, uint32_t k);
/* Write blended pose t of a transition into out (stride floats). */
void smgb_blend_pose(const smgb_bake* b, const smgb_edge* e, uint32_t t,
                     float* out);
/* A pose of b's clip space placed by ground transform g. */
void smgb_pose_transform(const float* pose, const double g[3], float* out,
                         uint32_t stride);
/* Append blend frames of every transition edge of both graphs. */
smg_result smgb_materialize_transitions(smgb_bake* b);

#endif /* BAKE_TRANSITION_H */
