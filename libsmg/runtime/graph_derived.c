/*
 * graph_derived.c - load-time lookup tables for the runtime (see
 * graph_derived.h). Everything lives in one allocation so destroy is one
 * free and the tables stay close together in memory.
 */
#include "graph_derived.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "rmath.h"

static size_t align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

/* Multi-source BFS on reversed edges: hops[n*L + l] = 0 where node n has an
 * out-edge labelled l, else 1 + min over out-edges of hops[to]. `in_first`
 * / `in_edges` is the reverse adjacency (CSR), `queue` node_count scratch. */
static void compute_hops(const smgi_node* nodes, uint32_t node_count,
                         const smgi_edge* edges, uint32_t label_count,
                         const uint32_t* in_first, const uint32_t* in_edges,
                         uint32_t* queue, uint8_t* hops) {
  for (uint32_t l = 0; l < label_count; ++l) {
    uint32_t head = 0, tail = 0;
    for (uint32_t n = 0; n < node_count; ++n) {
      uint8_t h = SMGI_HOPS_UNREACHABLE;
      for (uint32_t k = 0; k < nodes[n].edge_count; ++k) {
        if (edges[nodes[n].first_edge + k].label == l) {
          h = 0;
          break;
        }
      }
      hops[(size_t)n * label_count + l] = h;
      if (h == 0) queue[tail++] = n;
    }
    while (head < tail) {
      uint32_t n = queue[head++];
      uint8_t hn = hops[(size_t)n * label_count + l];
      if (hn + 1u >= SMGI_HOPS_UNREACHABLE) continue;
      for (uint32_t k = in_first[n]; k < in_first[n + 1]; ++k) {
        uint32_t from = edges[in_edges[k]].from;
        uint8_t* hf = &hops[(size_t)from * label_count + l];
        if (*hf == SMGI_HOPS_UNREACHABLE) {
          *hf = (uint8_t)(hn + 1u);
          queue[tail++] = from;
        }
      }
    }
  }
}

/* Reverse adjacency of one graph into caller scratch: in_first has
 * node_count + 1 entries, in_edges edge_count. */
static void build_reverse(const smgi_edge* edges, uint32_t edge_count,
                          uint32_t node_count, uint32_t* in_first,
                          uint32_t* in_edges) {
  memset(in_first, 0, sizeof(uint32_t) * ((size_t)node_count + 1u));
  for (uint32_t e = 0; e < edge_count; ++e) in_first[edges[e].to + 1u]++;
  for (uint32_t n = 0; n < node_count; ++n) in_first[n + 1u] += in_first[n];
  for (uint32_t e = 0; e < edge_count; ++e) {
    /* in_first[to] is used as a cursor and restored below */
    in_edges[in_first[edges[e].to]++] = e;
  }
  for (uint32_t n = node_count; n > 0; --n) in_first[n] = in_first[n - 1u];
  in_first[0] = 0;
}

/* Natural continuation of every lower node and where following it for
 * SMGI_LOOK_SECONDS leads (ground transform composed edge by edge). */
static void build_look(const smgi_graph_data* d, uint32_t* natural,
                       float* look) {
  const uint32_t LN = d->lower_node_count;
  const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
  const float look_frames = SMGI_LOOK_SECONDS * fps;
  for (uint32_t n = 0; n < LN; ++n) {
    const smgi_node* node = &d->lower_nodes[n];
    natural[n] = SMGI_NONE;
    for (uint32_t k = 0; k < node->edge_count; ++k) {
      const smgi_edge* e = &d->lower_edges[node->first_edge + k];
      if (e->first_frame == node->frame &&
          !(e->flags & SMGI_EDGE_TRANSITION)) {
        natural[n] = node->first_edge + k;
        break;
      }
    }
    if (natural[n] == SMGI_NONE && node->edge_count > 0) {
      /* no original motion continues here: the cheapest edge stands in */
      uint32_t best = node->first_edge;
      for (uint32_t k = 1; k < node->edge_count; ++k)
        if (d->lower_edges[node->first_edge + k].cost <
            d->lower_edges[best].cost)
          best = node->first_edge + k;
      natural[n] = best;
    }
  }
  for (uint32_t n = 0; n < LN; ++n) {
    smgi_xform2 acc = {0.0f, 0.0f, 0.0f};
    float arc = 0.0f, frames = 0.0f;
    uint32_t cur = n;
    for (uint32_t hop = 0; hop < 256u && frames < look_frames; ++hop) {
      uint32_t e = natural[cur];
      if (e == SMGI_NONE) break;
      const smgi_edge* E = &d->lower_edges[e];
      smgi_xform2 step = {E->displacement[0], E->displacement[1],
                          E->displacement[2]};
      acc = smgi_xf_mul(acc, step);
      arc += E->arc_length;
      frames += (float)E->frame_count;
      cur = E->to;
    }
    look[4u * n + 0u] = acc.x;
    look[4u * n + 1u] = acc.z;
    look[4u * n + 2u] = acc.h;
    look[4u * n + 3u] = arc;
  }
}

/* The natural continuation of every node sampled every
 * SMGI_TRAIL_STEP_SECONDS for SMGI_TRAIL_SAMPLES steps. */
static void build_trail(const smgi_graph_data* d, const uint32_t* natural,
                        float* trail, float* trail_frames,
                        uint32_t* trail_edge) {
  const uint32_t LN = d->lower_node_count, K = SMGI_TRAIL_SAMPLES;
  const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
  const float step = SMGI_TRAIL_STEP_SECONDS * fps;
  for (uint32_t n = 0; n < LN; ++n) {
    smgi_xform2 acc = {0.0f, 0.0f, 0.0f};
    float arc = 0.0f, frames = 0.0f;
    uint32_t cur = n, last = natural[n];
    uint32_t e = natural[cur];
    for (uint32_t k = 0; k < K; ++k) {
      float want = step * (float)(k + 1u);
      for (uint32_t hop = 0; hop < 1024u && frames < want; ++hop) {
        e = natural[cur];
        if (e == SMGI_NONE) break;
        const smgi_edge* E = &d->lower_edges[e];
        smgi_xform2 st = {E->displacement[0], E->displacement[1],
                          E->displacement[2]};
        acc = smgi_xf_mul(acc, st);
        arc += E->arc_length;
        frames += (float)E->frame_count;
        cur = E->to;
        last = e;
      }
      float* o = trail + 4u * ((size_t)n * K + k);
      o[0] = acc.x;
      o[1] = acc.z;
      o[2] = acc.h;
      o[3] = arc;
      trail_frames[(size_t)n * K + k] = frames;
      trail_edge[(size_t)n * K + k] = last;
    }
  }
}

/* node_turn by dynamic programming over frames: best[t][n] = the largest
 * cumulative heading change (in direction `dir`) reached within t frames
 * from n, 0 included (not turning yet). An edge longer than the time left
 * counts in proportion. `scratch` holds (T + 1) * LN floats. */
static void build_turn(const smgi_graph_data* d, float* scratch,
                       float* node_turn) {
  const uint32_t LN = d->lower_node_count;
  const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
  const uint32_t T = (uint32_t)(SMGI_TURN_SECONDS * fps + 0.5f);
  for (uint32_t dir = 0; dir < 2u; ++dir) {
    const float sg = dir == 0 ? 1.0f : -1.0f;
    for (uint32_t n = 0; n < LN; ++n) scratch[n] = 0.0f;
    for (uint32_t t = 1; t <= T; ++t) {
      float* cur = scratch + (size_t)t * LN;
      for (uint32_t n = 0; n < LN; ++n) {
        const smgi_node* node = &d->lower_nodes[n];
        float b = 0.0f;
        for (uint32_t k = 0; k < node->edge_count; ++k) {
          const smgi_edge* e = &d->lower_edges[node->first_edge + k];
          float dh = sg * e->displacement[2];
          float v = e->frame_count <= t
                        ? dh + scratch[(size_t)(t - e->frame_count) * LN + e->to]
                        : dh * (float)t / (float)e->frame_count;
          if (v > b) b = v;
        }
        cur[n] = b;
      }
    }
    for (uint32_t n = 0; n < LN; ++n)
      node_turn[2u * n + dir] = scratch[(size_t)T * LN + n];
  }
}

smg_result smgi_graph_derived_build(smg_graph* g) {
  if (!g) return SMG_ERROR_INVALID_ARGUMENT;
  const smgi_graph_data* d = &g->data;
  const uint32_t F = d->frame_count;
  const uint32_t S = d->style_count, A = d->action_count;
  const uint32_t LN = d->lower_node_count, UN = d->upper_node_count;

  size_t off_lh = 0;
  size_t off_uh = off_lh + align16((size_t)LN * S);
  size_t off_sf = off_uh + align16((size_t)UN * A);
  size_t off_fu = off_sf + align16(sizeof(uint32_t) * ((size_t)F + 1u));
  size_t off_af = off_fu + align16(sizeof(uint32_t) * (size_t)F);
  size_t off_sn = off_af + align16(sizeof(uint32_t) * (size_t)A);
  size_t off_nl = off_sn + align16(sizeof(uint32_t) * (size_t)S);
  size_t off_nn = off_nl + align16(sizeof(float) * 4u * (size_t)LN);
  const size_t TK = (size_t)LN * SMGI_TRAIL_SAMPLES;
  size_t off_tr = off_nn + align16(sizeof(uint32_t) * (size_t)LN);
  size_t off_tf = off_tr + align16(sizeof(float) * 4u * TK);
  size_t off_te = off_tf + align16(sizeof(float) * TK);
  size_t off_nt = off_te + align16(sizeof(uint32_t) * TK);
  size_t off_em = off_nt + align16(sizeof(float) * 2u * (size_t)LN);
  size_t total =
      off_em + align16(sizeof(float) * 4u * (size_t)d->lower_edge_count);
  size_t block = align16(sizeof(smgi_derived));

  uint8_t* mem = (uint8_t*)smgi_alloc(&g->allocator, block + total, 16);
  if (!mem) return SMG_ERROR_OUT_OF_MEMORY;
  memset(mem, 0, block + total);
  smgi_derived* dv = (smgi_derived*)mem;
  uint8_t* base = mem + block;
  uint8_t* lower_hops = base + off_lh;
  uint8_t* upper_hops = base + off_uh;
  uint32_t* splice_first = (uint32_t*)(base + off_sf);
  uint32_t* frame_upper = (uint32_t*)(base + off_fu);
  uint32_t* action_first = (uint32_t*)(base + off_af);
  uint32_t* style_first = (uint32_t*)(base + off_sn);
  float* node_look = (float*)(base + off_nl);
  uint32_t* natural = (uint32_t*)(base + off_nn);
  float* trail = (float*)(base + off_tr);
  float* trail_frames = (float*)(base + off_tf);
  uint32_t* trail_edge = (uint32_t*)(base + off_te);
  float* node_turn = (float*)(base + off_nt);
  float* edge_mid = (float*)(base + off_em);
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_edge* E = &d->lower_edges[e];
    if (E->frame_count < 4u) continue;
    const float* g0 = d->frames[d->lower_nodes[E->from].frame].root2d;
    const float* r = d->frames[E->first_frame + E->frame_count / 2u].root2d;
    smgi_xform2 inv = smgi_xf_inv((smgi_xform2){g0[0], g0[1], g0[2]});
    float x, z;
    smgi_xf_point(inv, r[0], r[1], &x, &z);
    edge_mid[4u * e] = x;
    edge_mid[4u * e + 1u] = z;
    edge_mid[4u * e + 2u] = smgi_wrap_angle(inv.h + r[2]);
  }

  /* Scratch for the BFS: reverse adjacency of the larger graph. */
  uint32_t maxn = LN > UN ? LN : UN;
  uint32_t maxe = d->lower_edge_count > d->upper_edge_count
                      ? d->lower_edge_count
                      : d->upper_edge_count;
  size_t scratch_size = sizeof(uint32_t) * ((size_t)maxn + 1u + maxe + maxn);
  uint32_t* scratch = (uint32_t*)smgi_alloc(&g->allocator, scratch_size, 16);
  if (!scratch) {
    smgi_free(&g->allocator, mem);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  uint32_t* in_first = scratch;
  uint32_t* in_edges = scratch + maxn + 1u;
  uint32_t* queue = in_edges + maxe;

  build_reverse(d->lower_edges, d->lower_edge_count, LN, in_first, in_edges);
  compute_hops(d->lower_nodes, LN, d->lower_edges, S, in_first, in_edges,
               queue, lower_hops);
  build_reverse(d->upper_edges, d->upper_edge_count, UN, in_first, in_edges);
  compute_hops(d->upper_nodes, UN, d->upper_edges, A, in_first, in_edges,
               queue, upper_hops);
  smgi_free(&g->allocator, scratch);

  /* Splice index: SPLC is sorted by lower_frame (validated), so a counting
   * pass gives the CSR offsets. */
  for (uint32_t i = 0; i < d->splice_count; ++i) {
    uint32_t f = d->splices[i].lower_frame;
    if (f < F) splice_first[f + 1u]++;
  }
  for (uint32_t f = 0; f < F; ++f) splice_first[f + 1u] += splice_first[f];

  for (uint32_t f = 0; f < F; ++f) frame_upper[f] = SMGI_NONE;
  for (uint32_t e = 0; e < d->upper_edge_count; ++e) {
    const smgi_edge* ue = &d->upper_edges[e];
    for (uint32_t k = 0; k < ue->frame_count; ++k) {
      uint64_t f = (uint64_t)ue->first_frame + k;
      if (f < F && frame_upper[f] == SMGI_NONE) frame_upper[f] = e;
    }
  }
  for (uint32_t a = 0; a < A; ++a) action_first[a] = SMGI_NONE;
  for (uint32_t e = d->upper_edge_count; e > 0; --e) {
    uint32_t l = d->upper_edges[e - 1u].label;
    if (l < A) action_first[l] = e - 1u;
  }
  for (uint32_t s = 0; s < S; ++s) style_first[s] = SMGI_NONE;
  for (uint32_t n = LN; n > 0; --n) {
    uint32_t l = d->lower_nodes[n - 1u].label;
    if (l < S) style_first[l] = n - 1u;
  }
  uint32_t maxdeg = 0;
  for (uint32_t n = 0; n < LN; ++n)
    if (d->lower_nodes[n].edge_count > maxdeg)
      maxdeg = d->lower_nodes[n].edge_count;

  build_look(d, natural, node_look);
  build_trail(d, natural, trail, trail_frames, trail_edge);
  {
    const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
    size_t frames = (size_t)(SMGI_TURN_SECONDS * fps + 0.5f) + 1u;
    float* tscr = (float*)smgi_alloc(&g->allocator,
                                     sizeof(float) * frames * (LN ? LN : 1u), 16);
    if (!tscr) {
      smgi_free(&g->allocator, mem);
      return SMG_ERROR_OUT_OF_MEMORY;
    }
    build_turn(d, tscr, node_turn);
    smgi_free(&g->allocator, tscr);
  }
  dv->node_turn = node_turn;
  dv->edge_mid = edge_mid;
  dv->node_trail = trail;
  dv->node_trail_frames = trail_frames;
  dv->node_trail_edge = trail_edge;

  dv->lower_hops = lower_hops;
  dv->upper_hops = upper_hops;
  dv->splice_first = splice_first;
  dv->frame_upper_edge = frame_upper;
  dv->action_first_edge = action_first;
  dv->style_first_node = style_first;
  dv->max_lower_degree = maxdeg;
  dv->node_look = node_look;
  /* most agile style: heading change per metre travelled (curvature) of
   * the natural continuations - what decides how tightly it can turn back
   * to a path */
  {
    float best = -1.0f;
    dv->agile_style = 0;
    for (uint32_t st = 0; st < S; ++st) {
      double turn = 0.0, arc = 0.0;
      for (uint32_t n = 0; n < LN; ++n) {
        if (d->lower_nodes[n].label != st) continue;
        turn += fabs((double)node_look[4u * n + 2u]);
        arc += (double)node_look[4u * n + 3u];
      }
      float mean = arc > 1e-6 ? (float)(turn / arc) : -1.0f;
      if (mean > best) {
        best = mean;
        dv->agile_style = st;
      }
    }
  }
  dv->natural_next = natural;
  g->derived = dv;
  return SMG_OK;
}

void smgi_graph_derived_free(smg_graph* g) {
  if (!g || !g->derived) return;
  smgi_free(&g->allocator, g->derived);
  g->derived = NULL;
}
