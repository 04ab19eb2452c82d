/*
 * bake_simplify.c - merge chains of nodes without branches (the paper,
 * III.B.1: "merging nodes without branch edges").
 *
 * A node is removable when it has exactly one in-edge and one out-edge and
 * both are original motion of the same clip: then the two edges are one
 * contiguous run of clip frames in one coordinate space and can be played
 * as one edge. Every maximal chain (from a branching node to the next) is
 * re-cut into the fewest pieces no longer than max_edge_seconds, evenly,
 * so that a runtime that only decides at nodes can still react to path
 * edits within about that time. Long original edges are split the same way
 * even when they had no removable node. Transitions are never merged.
 */
#include <stdlib.h>
#include <string.h>

#include "bake_simplify.h"

static int node_cmp(const void* pa, const void* pb) {
  const smgb_node* a = pa;
  const smgb_node* b = pb;
  return a->frame < b->frame ? -1 : a->frame > b->frame ? 1 : 0;
}

smg_result smgb_simplify(smgb_bake* b, smgb_graph* g) {
  uint32_t N = g->node_count, E = g->edge_count, n, e;
  uint32_t *in = calloc(N ? N : 1, sizeof *in), *out = NULL;
  uint32_t *in_e = NULL, *out_e = NULL, *remap = NULL;
  uint8_t* removable = NULL;
  smgb_graph ng;
  uint32_t cap = b->opt.max_edge_frames ? b->opt.max_edge_frames : 1;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  memset(&ng, 0, sizeof ng);
  out = calloc(N ? N : 1, sizeof *out);
  in_e = malloc((N ? N : 1) * sizeof *in_e);
  out_e = malloc((N ? N : 1) * sizeof *out_e);
  remap = malloc((N ? N : 1) * sizeof *remap);
  removable = calloc(N ? N : 1, 1);
  if (!in || !out || !in_e || !out_e || !remap || !removable) goto done;
  for (e = 0; e < E; ++e) {
    in[g->edges[e].to]++;
    in_e[g->edges[e].to] = e;
    out[g->edges[e].from]++;
    out_e[g->edges[e].from] = e;
  }
  for (n = 0; n < N; ++n)
    removable[n] = in[n] == 1 && out[n] == 1 &&
                   g->edges[in_e[n]].kind == SMGB_EDGE_ORIGINAL &&
                   g->edges[out_e[n]].kind == SMGB_EDGE_ORIGINAL;
  /* kept nodes first (their order is restored by the sort below) */
  for (n = 0; n < N; ++n) {
    remap[n] = SMGI_NONE;
    if (!removable[n] &&
        smgb_graph_add_node(&ng, g->nodes[n].frame, g->nodes[n].label, NULL))
      goto done;
  }
  for (e = 0; e < E; ++e) {
    const smgb_edge* ed = &g->edges[e];
    uint32_t end, s = ed->from, L, pieces, q, prev_frame;
    if (removable[s]) continue; /* interior of a chain, handled below */
    if (ed->kind != SMGB_EDGE_ORIGINAL) continue;
    end = ed->to;
    while (removable[end]) end = g->edges[out_e[end]].to;
    L = g->nodes[end].frame - g->nodes[s].frame;
    pieces = (L + cap - 1) / cap;
    if (pieces < 1) pieces = 1;
    prev_frame = g->nodes[s].frame;
    for (q = 1; q < pieces; ++q) {
      uint32_t fr = g->nodes[s].frame +
                    (uint32_t)(((uint64_t)L * q + pieces / 2) / pieces);
      if (fr <= prev_frame || fr >= g->nodes[end].frame) continue;
      if (smgb_graph_add_node(&ng, fr, g->nodes[s].label, NULL)) goto done;
      prev_frame = fr;
    }
  }
  if (ng.node_count > 1)
    qsort(ng.nodes, ng.node_count, sizeof *ng.nodes, node_cmp);
  /* map old kept nodes to new indices */
  {
    uint32_t j = 0;
    for (n = 0; n < N; ++n) {
      if (removable[n]) continue;
      while (j < ng.node_count && ng.nodes[j].frame != g->nodes[n].frame) ++j;
      remap[n] = j;
    }
  }
  /* transitions keep their ends */
  for (e = 0; e < E; ++e) {
    smgb_edge ed = g->edges[e];
    if (ed.kind != SMGB_EDGE_TRANSITION) continue;
    ed.from = remap[ed.from];
    ed.to = remap[ed.to];
    if (smgb_graph_add_edge(&ng, &ed)) goto done;
  }
  /* original edges: consecutive new nodes inside each chain */
  for (e = 0; e < E; ++e) {
    const smgb_edge* ed = &g->edges[e];
    uint32_t end, s = ed->from, cur;
    if (removable[s] || ed->kind != SMGB_EDGE_ORIGINAL) continue;
    end = ed->to;
    while (removable[end]) end = g->edges[out_e[end]].to;
    cur = remap[s];
    while (cur != remap[end]) {
      smgb_edge ne;
      memset(&ne, 0, sizeof ne);
      ne.kind = SMGB_EDGE_ORIGINAL;
      ne.from = cur;
      ne.to = cur + 1; /* nodes sorted by frame; chain frames contiguous */
      ne.a = ng.nodes[cur].frame;
      ne.b = ng.nodes[cur + 1].frame;
      if (smgb_graph_add_edge(&ng, &ne)) goto done;
      ++cur;
    }
  }
  smgb_graph_sort_edges(&ng);
  smgb_graph_free(g);
  *g = ng;
  memset(&ng, 0, sizeof ng);
  r = SMG_OK;
done:
  if (r != SMG_OK) smgb_fail(&b->report, "out of memory simplifying a graph");
  smgb_graph_free(&ng);
  free(in);
  free(out);
  free(in_e);
  free(out_e);
  free(remap);
  free(removable);
  return r;
}
