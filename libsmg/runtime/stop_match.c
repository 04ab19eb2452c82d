/*
 * stop_match.c - distance matching into stopping motion (stop_match.h).
 *
 * A depth-first walk over the edges from the plan's end, at most
 * SMGI_STOP_ROUTE_LEAD edges deep before the entry: every edge whose first
 * frame lies in a stop before its rest is an entry. The stop's remaining
 * travel from that frame (graph_derived.h, stop_left) added to the way
 * the route has come first rules out entries whose rest is clearly short
 * of the end or past it; for the others the route is followed on through
 * the stop's own frames (each node's natural continuation) to the edge
 * holding the rest, and where the hips rest is placed as the plan will
 * place it. The entry whose rest lands nearest the path's end wins.
 */
#include "stop_match.h"

#include <math.h>
#include <string.h>

#include "dmath.h"
#include "graph_derived.h"
#include "tuning.h"

typedef struct search {
  const smg_graph* g;
  const smgi_derived* dv;
  float ex, ez;   /* the path's end */
  float way;      /* path left from the route's start */
  float tol;      /* m: the miss allowed */
  uint32_t budget;
  uint32_t lead[SMGI_STOP_ROUTE_LEAD + 1u];
  smgi_stop_route best;
} search;

/* The first segment beginning after pool frame f. */
static uint32_t after(const smgi_derived* dv, uint32_t f) {
  uint32_t lo = 0, hi = dv->stop_count;
  while (lo < hi) { /* the first segment beginning after f */
    const uint32_t mid = lo + (hi - lo) / 2u;
    if (dv->stops[mid].first <= f) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

/* The segment of `kind` holding pool frame f within [first, rest] (a
 * stop before its rest, a start before it moves off; SMGI_NONE: none).
 * Segments are in order of their first frames and overlap little (a
 * stop and the start from the same rest), so a few steps back from the
 * binary search find it. */
static uint32_t segment_of(const smgi_derived* dv, uint32_t f, uint32_t kind) {
  for (uint32_t k = after(dv, f), n = 0; k > 0 && n < 4u; --k, ++n) {
    const smgi_stop_seg* s = &dv->stops[k - 1u];
    if (s->kind == kind && f <= s->rest) return k - 1u;
  }
  return SMGI_NONE;
}

int smgi_stop_still(const smg_graph* g, uint32_t f) {
  const smgi_derived* dv = smgi_derived_of(g);
  if (segment_of(dv, f, SMGI_STOP_KIND_START) != SMGI_NONE) return 1;
  for (uint32_t k = after(dv, f), n = 0; k > 0 && n < 4u; --k, ++n) {
    const smgi_stop_seg* s = &dv->stops[k - 1u];
    if (s->kind == SMGI_STOP_KIND_STOP && f >= s->rest && f <= s->last)
      return 1;
  }
  return 0;
}

/* Entering stop k by `edge` (placed at W, the route having come `u`
 * metres in `n` lead edges before it): follows the stop's frames to its
 * rest and keeps the route if the rest lands nearer the end. */
static void try_entry(search* S, uint32_t n, uint32_t edge, smgi_xform2 W,
                      float u, uint32_t k) {
  const smgi_graph_data* d = &S->g->data;
  const smgi_stop_seg* st = &S->dv->stops[k];
  const uint32_t f0 = d->lower_edges[edge].first_frame;
  const float left =
      S->dv->stop_left[S->dv->stop_left_first[k] + (f0 - st->first)];
  /* the rest this way lands clearly short of the end or past it (along
   * the travel: a route that strays sideways is judged below) */
  if (fabsf(u + left - S->way) > S->tol + left) return;
  uint32_t route[SMGI_STOP_ROUTE_CAP];
  uint32_t count = n;
  memcpy(route, S->lead, sizeof(uint32_t) * n);
  uint32_t cur = edge;
  for (;;) {
    const smgi_edge* e = &d->lower_edges[cur];
    if (count >= SMGI_STOP_ROUTE_CAP) return;
    route[count++] = cur;
    if (st->rest < e->first_frame + e->frame_count) break;
    /* on through the stop's own frames */
    const uint32_t next = S->dv->node_next[e->to].natural;
    if (next == SMGI_NONE ||
        d->lower_edges[next].first_frame != e->first_frame + e->frame_count ||
        (d->lower_edges[next].flags & SMGI_EDGE_TRANSITION))
      return;
    W = smgi_xf_mul(W, smgi_edge_displacement(e));
    cur = next;
  }
  const smgi_edge* e = &d->lower_edges[cur];
  const smgi_xform2 M = smgi_xf_mul(
      W, smgi_xf_inv(smgi_frame_ground(S->g, d->lower_nodes[e->from].frame)));
  float x, z;
  smgi_xf_point(M, d->frames[st->rest].root2d[0],
                d->frames[st->rest].root2d[1], &x, &z);
  const float miss = sqrtf((x - S->ex) * (x - S->ex) + (z - S->ez) * (z - S->ez));
  if (miss >= S->best.miss) return;
  memcpy(S->best.edges, route, sizeof(uint32_t) * count);
  S->best.count = count;
  S->best.rest_offset = st->rest - e->first_frame;
  S->best.miss = miss;
}

/* `edge`, the route's edge number `depth`, placed at W after `u` metres. */
static void visit(search* S, uint32_t depth, uint32_t edge, smgi_xform2 W,
                  float u) {
  if (S->budget == 0) return;
  S->budget--;
  const smgi_edge* e = &S->g->data.lower_edges[edge];
  const uint32_t k = segment_of(S->dv, e->first_frame, SMGI_STOP_KIND_STOP);
  if (k != SMGI_NONE) try_entry(S, depth, edge, W, u, k);
  if (depth >= SMGI_STOP_ROUTE_LEAD) return;
  /* past the end before entering a stop: nothing further on helps */
  if (u + e->arc_length > S->way + S->tol) return;
  S->lead[depth] = edge;
  const smgi_node* to = &S->g->data.lower_nodes[e->to];
  const smgi_xform2 W2 = smgi_xf_mul(W, smgi_edge_displacement(e));
  for (uint32_t i = 0; i < to->edge_count; ++i)
    visit(S, depth + 1u, to->first_edge + i, W2, u + e->arc_length);
}

int smgi_stop_match(const smg_graph* g, const smgi_path* path,
                    uint32_t node, smgi_xform2 W, float s,
                    smgi_stop_route* out) {
  const smgi_derived* dv = smgi_derived_of(g);
  if (dv->stop_count == 0 || path->count < 2u ||
      node >= g->data.lower_node_count)
    return 0;
  search S;
  S.g = g;
  S.dv = dv;
  S.ex = path->xz[2u * (path->count - 1u)];
  S.ez = path->xz[2u * (path->count - 1u) + 1u];
  S.way = path->length - s;
  S.tol = SMGI_STOP_MATCH * g->data.info->leg_length;
  S.budget = SMGI_STOP_ROUTE_BUDGET;
  S.best.count = 0;
  S.best.miss = INFINITY;
  const smgi_node* n = &g->data.lower_nodes[node];
  for (uint32_t i = 0; i < n->edge_count; ++i)
    visit(&S, 0, n->first_edge + i, W, 0.0f);
  if (S.best.count == 0 || S.best.miss > S.tol) return 0;
  *out = S.best;
  return 1;
}

/* ---- starts ---- */

typedef struct start_search {
  const smg_graph* g;
  const smgi_derived* dv;
  float dir;        /* the path's heading where the plan stands */
  uint32_t budget;
  uint32_t lead[SMGI_STOP_ROUTE_LEAD + 1u];
  float best_wait;  /* frames standing before the best route moves off */
  smgi_stop_route best;
} start_search;

/* Entering start k by `edge` (placed at W) after `n` lead edges and
 * `waited` frames: followed on to where it is back at speed, kept if it
 * sets off along the path sooner than the best so far. */
static void try_start(start_search* S, uint32_t n, uint32_t edge,
                      smgi_xform2 W, float waited, uint32_t k) {
  const smgi_graph_data* d = &S->g->data;
  const smgi_stop_seg* st = &S->dv->stops[k];
  const float wait =
      waited + (float)(st->rest - d->lower_edges[edge].first_frame);
  if (wait >= S->best_wait) return;
  uint32_t route[SMGI_STOP_ROUTE_CAP];
  uint32_t count = n;
  memcpy(route, S->lead, sizeof(uint32_t) * n);
  uint32_t cur = edge;
  smgi_xform2 M0 = smgi_xf_mul(
      W, smgi_xf_inv(smgi_frame_ground(S->g, d->lower_nodes[d->lower_edges[edge].from]
                                         .frame)));
  for (;;) {
    const smgi_edge* e = &d->lower_edges[cur];
    if (count >= SMGI_STOP_ROUTE_CAP) return;
    route[count++] = cur;
    if (st->last < e->first_frame + e->frame_count) break;
    const uint32_t next = S->dv->node_next[e->to].natural;
    if (next == SMGI_NONE ||
        d->lower_edges[next].first_frame != e->first_frame + e->frame_count ||
        (d->lower_edges[next].flags & SMGI_EDGE_TRANSITION))
      return;
    cur = next;
  }
  /* the way it sets off: from its rest to where it is back at speed, in
   * the placement of the entry (a natural chain keeps it) */
  float x0, z0, x1, z1;
  smgi_xf_point(M0, d->frames[st->rest].root2d[0],
                d->frames[st->rest].root2d[1], &x0, &z0);
  smgi_xf_point(M0, d->frames[st->last].root2d[0],
                d->frames[st->last].root2d[1], &x1, &z1);
  if ((x1 - x0) * (x1 - x0) + (z1 - z0) * (z1 - z0) < 1e-6f) return;
  const float h = smgi_atan2f(x1 - x0, z1 - z0);
  if (fabsf(smgi_wrap_angle(h - S->dir)) > SMGI_START_TURN) return;
  memcpy(S->best.edges, route, sizeof(uint32_t) * count);
  S->best.count = count;
  S->best.rest_offset = 0;
  S->best.miss = 0.0f;
  S->best_wait = wait;
}

static void visit_start(start_search* S, uint32_t depth, uint32_t edge,
                        smgi_xform2 W, float waited) {
  if (S->budget == 0 || waited >= S->best_wait) return;
  S->budget--;
  const smgi_edge* e = &S->g->data.lower_edges[edge];
  const uint32_t k = segment_of(S->dv, e->first_frame, SMGI_STOP_KIND_START);
  if (k != SMGI_NONE) try_start(S, depth, edge, W, waited, k);
  if (depth >= SMGI_STOP_ROUTE_LEAD) return;
  S->lead[depth] = edge;
  const smgi_node* to = &S->g->data.lower_nodes[e->to];
  const smgi_xform2 W2 = smgi_xf_mul(W, smgi_edge_displacement(e));
  for (uint32_t i = 0; i < to->edge_count; ++i)
    visit_start(S, depth + 1u, to->first_edge + i, W2,
                waited + (float)e->frame_count);
}

static void start_search_init(start_search* S, const smg_graph* g,
                              const smgi_path* path, uint32_t seg) {
  S->g = g;
  S->dv = smgi_derived_of(g);
  S->dir = smgi_path_heading(path, seg < path->count - 1u ? seg
                                                          : path->count - 2u);
  S->budget = SMGI_STOP_ROUTE_BUDGET;
  S->best_wait = INFINITY;
  S->best.count = 0;
}

int smgi_start_jump(const smg_graph* g, const smgi_path* path, uint32_t seg,
                    smgi_xform2 W, smgi_stop_route* out) {
  const smgi_derived* dv = smgi_derived_of(g);
  if (dv->start_count == 0 || path->count < 2u) return 0;
  start_search S;
  start_search_init(&S, g, path, seg);
  for (uint32_t k = 0; k < dv->stop_count; ++k) {
    const uint32_t node = dv->start_entry[k];
    if (node == SMGI_NONE) continue;
    const uint32_t e = dv->node_next[node].natural;
    if (e != SMGI_NONE &&
        g->data.lower_edges[e].first_frame == g->data.lower_nodes[node].frame)
      try_start(&S, 0, e, W, 0.0f, k);
  }
  if (S.best.count == 0) return 0;
  *out = S.best;
  return 1;
}

int smgi_start_match(const smg_graph* g, const smgi_path* path,
                     uint32_t seg, uint32_t node, smgi_xform2 W,
                     smgi_stop_route* out) {
  const smgi_derived* dv = smgi_derived_of(g);
  if (dv->start_count == 0 || path->count < 2u ||
      node >= g->data.lower_node_count)
    return 0;
  start_search S;
  start_search_init(&S, g, path, seg);
  const smgi_node* n = &g->data.lower_nodes[node];
  for (uint32_t i = 0; i < n->edge_count; ++i)
    visit_start(&S, 0, n->first_edge + i, W, 0.0f);
  if (S.best.count == 0) return 0;
  *out = S.best;
  return 1;
}
