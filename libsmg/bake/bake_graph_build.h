/*
 * bake_graph_build.h - the lower or upper working graph from the pool
 * (bake_graph_build.c): transition candidates, nodes and edges.
 */
#ifndef BAKE_GRAPH_BUILD_H
#define BAKE_GRAPH_BUILD_H

#include <stdint.h>

#include "bake_state.h"

/* role: SMGI_CLIP_LOWER or SMGI_CLIP_UPPER. */
smg_result smgb_build_graph(smgb_bake* b, uint32_t role);

#endif /* BAKE_GRAPH_BUILD_H */
