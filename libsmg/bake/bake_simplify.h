/*
 * bake_simplify.h - chain merging of a working graph (bake_simplify.c).
 */
#ifndef BAKE_SIMPLIFY_H
#define BAKE_SIMPLIFY_H

#include "bake_state.h"
#include "bake_workgraph.h"

smg_result smgb_simplify(smgb_bake* b, smgb_graph* g);

#endif /* BAKE_SIMPLIFY_H */
