/*
 * bake_workgraph.h - the working motion graph every graph stage edits:
 * nodes at pool frames, ORIGINAL and TRANSITION edges, and the container
 * operations (bake_workgraph.c).
 */
#ifndef BAKE_WORKGRAPH_H
#define BAKE_WORKGRAPH_H

#include <stdint.h>

#include "smg.h"

/* A working-graph edge. ORIGINAL edges play pool frames
 * [from.frame, to.frame) of one clip; TRANSITION edges blend window frames
 * a..a+k-1 with b..b+k-1 (b aligned by `align`, a 2-D transform taking b's
 * clip space into a's) and arrive at pool frame b+k. */
#define SMGB_EDGE_ORIGINAL 0u
#define SMGB_EDGE_TRANSITION 1u
typedef struct smgb_edge {
  uint32_t from, to;           /* node indices */
  uint32_t kind;
  uint32_t a, b;               /* transition: window starts (pool frames) */
  double align[3];             /* transition: x, z, heading */
  float cost;                  /* transition RMS distance, metres */
  /* filled at output */
  uint32_t first_frame, frame_count;
} smgb_edge;

typedef struct smgb_node {
  uint32_t frame;              /* pool frame */
  uint32_t label;
} smgb_node;

typedef struct smgb_graph {
  smgb_node* nodes;
  uint32_t node_count, node_cap;
  smgb_edge* edges;
  uint32_t edge_count, edge_cap;
} smgb_graph;

smg_result smgb_graph_add_node(smgb_graph* g, uint32_t frame, uint32_t label,
                               uint32_t* out_index);
smg_result smgb_graph_add_edge(smgb_graph* g, const smgb_edge* e);
void smgb_graph_free(smgb_graph* g);
/* Sort edges by (from, to, kind, a, b), stable and deterministic. */
void smgb_graph_sort_edges(smgb_graph* g);

#endif /* BAKE_WORKGRAPH_H */
