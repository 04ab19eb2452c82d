/*
 * bake_scc.c - pruning to strongly connected components (Kovar et al.
 * 2002: no dead ends, no sinks), with an iterative Tarjan (no recursion:
 * graphs of 10^5 nodes must not overflow the stack).
 *
 * Lower graph: the largest SCC is kept; every style must survive in it (an
 * SCC holding walk and run nodes necessarily contains walk->run and
 * run->walk paths). Upper graph: each action keeps its own largest SCC
 * (transitions never cross actions; the runtime changes action by
 * splicing).
 */
#include <stdlib.h>
#include <string.h>

#include "bake_scc.h"

int32_t smgb_scc(const smgb_graph* g, uint32_t* comp) {
  uint32_t N = g->node_count, E = g->edge_count, n, e;
  uint32_t *off = NULL, *adj = NULL, *index = NULL, *low = NULL;
  uint32_t *stack = NULL, *cstack = NULL, *cedge = NULL;
  uint8_t* on = NULL;
  uint32_t next_index = 0, sp = 0, csp = 0;
  int32_t ncomp = 0;
  if (N == 0) return 0;
  off = calloc(N + 1, sizeof *off);
  adj = malloc((E ? E : 1) * sizeof *adj);
  index = malloc(N * sizeof *index);
  low = malloc(N * sizeof *low);
  stack = malloc(N * sizeof *stack);
  cstack = malloc(N * sizeof *cstack);
  cedge = malloc(N * sizeof *cedge);
  on = calloc(N, 1);
  if (!off || !adj || !index || !low || !stack || !cstack || !cedge || !on) {
    ncomp = -1;
    goto done;
  }
  for (e = 0; e < E; ++e) off[g->edges[e].from + 1]++;
  for (n = 0; n < N; ++n) off[n + 1] += off[n];
  {
    uint32_t* fill = malloc(N * sizeof *fill);
    if (!fill) { ncomp = -1; goto done; }
    memcpy(fill, off, N * sizeof *fill);
    for (e = 0; e < E; ++e) adj[fill[g->edges[e].from]++] = g->edges[e].to;
    free(fill);
  }
  for (n = 0; n < N; ++n) index[n] = SMGI_NONE;
  for (n = 0; n < N; ++n) {
    if (index[n] != SMGI_NONE) continue;
    /* simulated recursion: cstack holds the DFS path, cedge the next
     * out-edge to look at for each node on it */
    cstack[csp] = n;
    cedge[csp] = off[n];
    ++csp;
    index[n] = low[n] = next_index++;
    stack[sp++] = n;
    on[n] = 1;
    while (csp > 0) {
      uint32_t v = cstack[csp - 1];
      if (cedge[csp - 1] < off[v + 1]) {
        uint32_t w = adj[cedge[csp - 1]++];
        if (index[w] == SMGI_NONE) {
          index[w] = low[w] = next_index++;
          stack[sp++] = w;
          on[w] = 1;
          cstack[csp] = w;
          cedge[csp] = off[w];
          ++csp;
        } else if (on[w] && index[w] < low[v]) {
          low[v] = index[w];
        }
      } else {
        --csp;
        if (low[v] == index[v]) {
          uint32_t w;
          do {
            w = stack[--sp];
            on[w] = 0;
            comp[w] = (uint32_t)ncomp;
          } while (w != v);
          ++ncomp;
        }
        if (csp > 0) {
          uint32_t u = cstack[csp - 1];
          if (low[v] < low[u]) low[u] = low[v];
        }
      }
    }
  }
done:
  free(off);
  free(adj);
  free(index);
  free(low);
  free(stack);
  free(cstack);
  free(cedge);
  free(on);
  return ncomp;
}

smg_result smgb_graph_keep(smgb_graph* g, const uint8_t* keep) {
  uint32_t* remap = malloc((g->node_count ? g->node_count : 1) * sizeof *remap);
  uint32_t n, e, nn = 0, ne = 0;
  if (!remap) return SMG_ERROR_OUT_OF_MEMORY;
  for (n = 0; n < g->node_count; ++n) {
    if (keep[n]) {
      remap[n] = nn;
      g->nodes[nn++] = g->nodes[n];
    } else {
      remap[n] = SMGI_NONE;
    }
  }
  for (e = 0; e < g->edge_count; ++e) {
    smgb_edge ed = g->edges[e];
    if (remap[ed.from] == SMGI_NONE || remap[ed.to] == SMGI_NONE) continue;
    ed.from = remap[ed.from];
    ed.to = remap[ed.to];
    g->edges[ne++] = ed;
  }
  g->node_count = nn;
  g->edge_count = ne;
  free(remap);
  smgb_graph_sort_edges(g);
  return SMG_OK;
}

smg_result smgb_prune(smgb_bake* b, uint32_t role) {
  smgb_graph* g = role == SMGI_CLIP_LOWER ? &b->lower : &b->upper;
  uint32_t N = g->node_count, n, l;
  uint32_t* comp = malloc((N ? N : 1) * sizeof *comp);
  uint32_t* size = NULL;
  uint8_t* keep = calloc(N ? N : 1, 1);
  int32_t nc;
  smg_result r = SMG_OK;
  if (!comp || !keep) goto oom;
  nc = smgb_scc(g, comp);
  if (nc < 0) goto oom;
  size = calloc((size_t)nc + 1, sizeof *size);
  if (!size) goto oom;
  for (n = 0; n < N; ++n) size[comp[n]]++;
  if (role == SMGI_CLIP_LOWER) {
    /* largest component; ties go to the one holding the lowest node */
    uint32_t best = SMGI_NONE;
    for (n = 0; n < N; ++n)
      if (best == SMGI_NONE || size[comp[n]] > size[best]) best = comp[n];
    for (n = 0; n < N; ++n) keep[n] = best != SMGI_NONE && comp[n] == best;
    for (l = 0; l < b->style_count; ++l) {
      int found = 0;
      for (n = 0; n < N && !found; ++n) found = keep[n] && g->nodes[n].label == l;
      if (!found) {
        smgb_fail(&b->report, "lower graph: style '%s' is lost when pruning to the "
                     "largest strongly connected component (no transitions "
                     "into and out of it were found; raise "
                     "transition_percentile or add %s clips)",
                  b->styles[l], b->styles[l]);
        r = SMG_ERROR_NOT_FOUND;
        goto done;
      }
    }
  } else {
    for (l = 1; l < b->action_count; ++l) {
      uint32_t best = SMGI_NONE;
      for (n = 0; n < N; ++n) {
        if (g->nodes[n].label != l || size[comp[n]] < 2) continue;
        if (best == SMGI_NONE || size[comp[n]] > size[best]) best = comp[n];
      }
      if (best == SMGI_NONE) {
        if (!(b->upper_phase_free >> l & 1u)) {
          /* the phase rule may have taken the only loops: rebuild this
           * action without it (the pipeline retries) */
          b->upper_phase_free |= (uint64_t)1 << l;
        }
        smgb_fail(&b->report, "upper graph: action '%s' has no cycle (no transition "
                     "candidates loop back inside its clips; use longer "
                     "clips or raise transition_percentile)",
                  b->actions[l]);
        r = SMG_ERROR_NOT_FOUND;
        goto done;
      }
      for (n = 0; n < N; ++n)
        if (comp[n] == best) keep[n] = 1;
    }
  }
  r = smgb_graph_keep(g, keep);
  if (r != SMG_OK) goto oom;
  goto done;
oom:
  smgb_fail(&b->report, "out of memory pruning the %s graph",
            role == SMGI_CLIP_LOWER ? "lower" : "upper");
  r = SMG_ERROR_OUT_OF_MEMORY;
done:
  free(comp);
  free(size);
  free(keep);
  return r;
}
