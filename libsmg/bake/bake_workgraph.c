/*
 * bake_workgraph.c - the working graph's container operations
 * (bake_workgraph.h).
 */
#include <stdlib.h>
#include <string.h>

#include "bake_workgraph.h"

smg_result smgb_graph_add_node(smgb_graph* g, uint32_t frame, uint32_t label,
                               uint32_t* out_index) {
  if (g->node_count == g->node_cap) {
    uint32_t cap = g->node_cap ? g->node_cap * 2 : 64;
    smgb_node* n = realloc(g->nodes, cap * sizeof *n);
    if (!n) return SMG_ERROR_OUT_OF_MEMORY;
    g->nodes = n;
    g->node_cap = cap;
  }
  g->nodes[g->node_count].frame = frame;
  g->nodes[g->node_count].label = label;
  if (out_index) *out_index = g->node_count;
  ++g->node_count;
  return SMG_OK;
}

smg_result smgb_graph_add_edge(smgb_graph* g, const smgb_edge* e) {
  if (g->edge_count == g->edge_cap) {
    uint32_t cap = g->edge_cap ? g->edge_cap * 2 : 64;
    smgb_edge* n = realloc(g->edges, cap * sizeof *n);
    if (!n) return SMG_ERROR_OUT_OF_MEMORY;
    g->edges = n;
    g->edge_cap = cap;
  }
  g->edges[g->edge_count++] = *e;
  return SMG_OK;
}

void smgb_graph_free(smgb_graph* g) {
  free(g->nodes);
  free(g->edges);
  memset(g, 0, sizeof *g);
}

static int edge_cmp(const void* pa, const void* pb) {
  const smgb_edge* a = pa;
  const smgb_edge* b = pb;
  if (a->from != b->from) return a->from < b->from ? -1 : 1;
  if (a->kind != b->kind) return a->kind < b->kind ? -1 : 1;
  if (a->to != b->to) return a->to < b->to ? -1 : 1;
  if (a->a != b->a) return a->a < b->a ? -1 : 1;
  if (a->b != b->b) return a->b < b->b ? -1 : 1;
  return 0;
}

void smgb_graph_sort_edges(smgb_graph* g) {
  /* keys are unique per edge (from, kind, to, a, b), so qsort's
   * instability cannot reorder equal elements */
  if (g->edge_count > 1) qsort(g->edges, g->edge_count, sizeof *g->edges,
                               edge_cmp);
}
