/*
 * settle.h - the settling step a character makes when it stops
 * (settle.c): which foot steps up beside the other, to where, and where
 * the hips come to stand. The rest stage makes that step (rest.c); the
 * steering chooses the frame to stop on by where it would leave the hips
 * (steer.c). Geometry of the graph's data only, below both stages.
 */
#ifndef SMG_SETTLE_H
#define SMG_SETTLE_H

#include <stdint.h>

#include "graph_data.h"
#include "rmath.h"

/* The settling step from a pose with its toes at toe[2] (x, z), its hips'
 * ground point at (gx, gz) facing h and its hips `width` apart: which
 * foot steps, to where, the standing motion's placement G (idle graphs)
 * and the hips' glide (others). */
typedef struct smgi_settle {
  uint32_t step;     /* the rear foot */
  float to[2];       /* where it steps */
  smgi_xform2 G;     /* the standing motion's first ground frame */
  float glide[2];    /* the shown hips' shift (no standing motion) */
  float end[2];      /* where the hips come to stand */
} smgi_settle;

void smgi_settle_plan(const smg_graph* g, const float (*toe)[2], float gx,
                      float gz, float h, float width, smgi_settle* sp);

/* Where the settling step would take the hips of a character stopping on
 * pool frame `frame`, relative to that frame's ground point, in its clip
 * space (the steering chooses the frame to stop on with it). */
void smgi_settle_shift(const smg_graph* g, uint32_t frame, float* dx,
                       float* dz);

/* How high the higher toe of pool frame `frame` is above the lower one
 * (m): the foot the settling step must still bring down when a stop is
 * made on that frame (a run's swinging foot, 15-50 cm up). */
float smgi_settle_lift(const smg_graph* g, uint32_t frame);

#endif /* SMG_SETTLE_H */
