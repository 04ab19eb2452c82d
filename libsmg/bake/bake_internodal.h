/*
 * bake_internodal.h - per-edge frames, displacement and arc length
 * (bake_internodal.c).
 */
#ifndef BAKE_INTERNODAL_H
#define BAKE_INTERNODAL_H

#include "bake_state.h"
#include "bake_workgraph.h"

/* Fill first_frame/frame_count (transitions must be materialised) and
 * compute displacement, arc length. */
void smgb_edge_internodal(const smgb_bake* b, const smgb_graph* g,
                          const smgb_edge* e, float disp[3], float* arc);

#endif /* BAKE_INTERNODAL_H */
