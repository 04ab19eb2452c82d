/*
 * bake_scc.h - strongly connected components and pruning of the working
 * graphs (bake_scc.c).
 */
#ifndef BAKE_SCC_H
#define BAKE_SCC_H

#include <stdint.h>

#include "bake_state.h"
#include "bake_workgraph.h"

/* Strongly connected components (iterative Tarjan). comp[n] gets a
 * component id; returns the number of components or -1 on OOM. */
int32_t smgb_scc(const smgb_graph* g, uint32_t* comp);
/* Keep only nodes with keep[n] != 0 and edges between kept nodes;
 * renumbers. */
smg_result smgb_graph_keep(smgb_graph* g, const uint8_t* keep);
/* Keep the lower graph's largest strongly connected component, and each
 * action's largest in the upper graph. SMG_ERROR_NOT_FOUND when a style or
 * action has none; for an action still built with the phase rule, its bit
 * in b->upper_phase_free is set first, so a rebuild can fall back. */
smg_result smgb_prune(smgb_bake* b, uint32_t role);

#endif /* BAKE_SCC_H */
