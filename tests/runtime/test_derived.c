/*
 * test_derived.c - the tables the runtime derives at load time
 * (libsmg/runtime/graph_derived.c) against plain reference versions kept
 * here: the straightforward code the load-time builders replaced (node_turn
 * one frame and one node at a time, node_trail composing smgi_xf_mul edge
 * by edge with a sincosf each, search_edges' mid samples inverting the
 * from-node's ground frame for every edge).
 *
 * Every table must match bit for bit, except the x and z of node_trail:
 * the builder walks with a carried (cos, sin) of the heading
 * rotated by each edge's own instead of cosf/sinf of the accumulated
 * heading. Each hop the carried pair gains at most a few float roundings
 * (two products and a sum, the edge's own cosf/sinf) against the reference's
 * cosf/sinf, so after j hops it is off by at most ~j * 2^-22 and the
 * position by at most that times the distance walked; the check allows
 * hops * distance * 2^-21 + 1e-6 m and prints the largest deviation seen
 * (a few micrometres on baked graphs). Heading, arc length, frames and
 * edges are the same float operations and must match exactly.
 *
 * Graphs: random ones (cycles of short edges or not, odd frame rates,
 * nodes without edges, edges longer than node_turn's horizon), checked
 * against both the SSE2 build in libsmg.a and the plain-C one compiled
 * into this test (and the two against each other, bit for bit); the
 * fixture; build/default.smg; a CMU graph
 * (build/cmu.smg when it loads, else baked here from ../shared unless
 * SMG_TEST_QUICK; skipped with a message without the clips).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* The builder once more with the plain-C node_turn, under other names (the
 * real ones come from libsmg.a). */
#define smgi_graph_derived_build plain_graph_derived_build
#define smgi_graph_derived_free plain_graph_derived_free
#define SMGI_DERIVED_SSE 0
#include "graph_derived.c"
#undef smgi_graph_derived_build
#undef smgi_graph_derived_free
smg_result smgi_graph_derived_build(smg_graph* g);
void smgi_graph_derived_free(smg_graph* g);

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bake_manifest.h"
#include "fixture_graph.h"
#include "smg_bake.h"
#include "test_env.h"

/* ---- the reference: the plain versions ---------------------------------- */

typedef struct ref_tables {
  uint8_t *lower_hops, *upper_hops;
  /* per style and lower node: steps of motion to the style (as in
   * edge_style_time), and per style what a step weighs in hops */
  uint8_t* style_time;
  float* style_time_hop;
  uint32_t *splice_first, *action_first;
  uint32_t *natural, *trail_edge;
  float *trail, *trail_frames, *turn, *edge_mid;
  /* per trail sample: hops walked and ground distance covered (bound) */
  uint32_t* trail_hops;
  float* trail_dist;
  uint32_t agile_style;
  uint8_t* can_stop;
  uint32_t stop_style;
  float stop_speed;
} ref_tables;

static float ref_fps(const smgi_graph_data* d) {
  return d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
}

/* hops[n*L + l]: edges to traverse before an out-edge labelled l; BFS from
 * the nodes that have one, over reversed edges. */
static void ref_hops(const smgi_node* nodes, uint32_t N, const smgi_edge* edges,
                     uint32_t E, uint32_t L, uint8_t* hops) {
  uint32_t* queue = (uint32_t*)malloc(sizeof(uint32_t) * (N + 1u));
  assert_non_null(queue);
  for (uint32_t l = 0; l < L; ++l) {
    uint32_t head = 0, tail = 0;
    for (uint32_t n = 0; n < N; ++n) {
      uint8_t h = SMGI_HOPS_UNREACHABLE;
      for (uint32_t k = 0; k < nodes[n].edge_count; ++k)
        if (edges[nodes[n].first_edge + k].label == l) h = 0;
      hops[(size_t)n * L + l] = h;
      if (h == 0) queue[tail++] = n;
    }
    while (head < tail) {
      uint32_t n = queue[head++];
      uint8_t hn = hops[(size_t)n * L + l];
      if (hn + 1u >= SMGI_HOPS_UNREACHABLE) continue;
      for (uint32_t e = 0; e < E; ++e) {
        if (edges[e].to != n) continue;
        uint8_t* hf = &hops[(size_t)edges[e].from * L + l];
        if (*hf == SMGI_HOPS_UNREACHABLE) {
          *hf = (uint8_t)(hn + 1u);
          queue[tail++] = edges[e].from;
        }
      }
    }
  }
  free(queue);
}

/* style_time[st * N + n]: the least frames of motion from node n to one
 * with an out-edge labelled st (relaxing every edge until nothing
 * changes), in steps of 1 / SMGI_STYLE_TIME_HZ s rounded to nearest and
 * capped; SMGI_HOPS_UNREACHABLE where lower_hops has no path. The hop
 * worth of a step per style: the hops over the steps of every node a
 * step or more and less than the cap away. */
static void ref_style_time(const smgi_graph_data* d, const uint8_t* hops,
                           ref_tables* r) {
  const uint32_t N = d->lower_node_count, S = d->style_count;
  const double fps = ref_fps(d);
  uint64_t* dist = (uint64_t*)malloc(sizeof(uint64_t) * (N + 1u));
  assert_non_null(dist);
  r->style_time = (uint8_t*)calloc((size_t)N * S + 1u, 1);
  r->style_time_hop = (float*)calloc((size_t)S + 1u, sizeof(float));
  assert_non_null(r->style_time);
  assert_non_null(r->style_time_hop);
  for (uint32_t st = 0; st < S; ++st) {
    uint64_t sum_hops = 0, sum_steps = 0;
    for (uint32_t n = 0; n < N; ++n)
      dist[n] = hops[(size_t)n * S + st] == 0u ? 0u : UINT64_MAX;
    for (int changed = 1; changed;) {
      changed = 0;
      for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
        const smgi_edge* E = &d->lower_edges[e];
        if (dist[E->to] == UINT64_MAX) continue;
        if (dist[E->to] + E->frame_count < dist[E->from]) {
          dist[E->from] = dist[E->to] + E->frame_count;
          changed = 1;
        }
      }
    }
    for (uint32_t n = 0; n < N; ++n) {
      uint8_t t = SMGI_HOPS_UNREACHABLE;
      if (dist[n] != UINT64_MAX) {
        double q = floor((double)dist[n] * (SMGI_STYLE_TIME_HZ / fps) + 0.5);
        t = q < (double)SMGI_STYLE_TIME_FAR ? (uint8_t)q
                                            : (uint8_t)SMGI_STYLE_TIME_FAR;
        if (t > 0u && t < SMGI_STYLE_TIME_FAR) {
          sum_hops += hops[(size_t)n * S + st];
          sum_steps += t;
        }
      }
      r->style_time[(size_t)st * N + n] = t;
    }
    r->style_time_hop[st] =
        sum_steps > 0u ? (float)((double)sum_hops / (double)sum_steps) : 1.0f;
  }
  free(dist);
}

static void ref_natural(const smgi_graph_data* d, uint32_t* natural) {
  for (uint32_t n = 0; n < d->lower_node_count; ++n) {
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
      uint32_t best = node->first_edge;
      for (uint32_t k = 1; k < node->edge_count; ++k)
        if (d->lower_edges[node->first_edge + k].cost <
            d->lower_edges[best].cost)
          best = node->first_edge + k;
      natural[n] = best;
    }
  }
}

static smgi_xform2 ref_step(const smgi_edge* E) {
  smgi_xform2 s = {E->displacement[0], E->displacement[1],
                   E->displacement[2]};
  return s;
}

static void ref_trail(const smgi_graph_data* d, const uint32_t* natural,
                      ref_tables* r) {
  const uint32_t K = SMGI_TRAIL_SAMPLES;
  const float step = SMGI_TRAIL_STEP_SECONDS * ref_fps(d);
  for (uint32_t n = 0; n < d->lower_node_count; ++n) {
    smgi_xform2 acc = {0.0f, 0.0f, 0.0f};
    float arc = 0.0f, frames = 0.0f, dist = 0.0f;
    uint32_t cur = n, last = natural[n], hops = 0;
    for (uint32_t k = 0; k < K; ++k) {
      float want = step * (float)(k + 1u);
      for (uint32_t hop = 0; hop < 1024u && frames < want; ++hop) {
        uint32_t e = natural[cur];
        if (e == SMGI_NONE) break;
        const smgi_edge* E = &d->lower_edges[e];
        acc = smgi_xf_mul(acc, ref_step(E));
        arc += E->arc_length;
        frames += (float)E->frame_count;
        dist += hypotf(E->displacement[0], E->displacement[1]);
        ++hops;
        cur = E->to;
        last = e;
      }
      size_t i = (size_t)n * K + k;
      r->trail[4u * i + 0u] = acc.x;
      r->trail[4u * i + 1u] = acc.z;
      r->trail[4u * i + 2u] = acc.h;
      r->trail[4u * i + 3u] = arc;
      r->trail_frames[i] = frames;
      r->trail_edge[i] = last;
      r->trail_hops[i] = hops;
      r->trail_dist[i] = dist;
    }
  }
}

/* best[t][n] frame by frame and node by node, one direction at a time. */
static void ref_turn(const smgi_graph_data* d, float* node_turn) {
  const uint32_t LN = d->lower_node_count;
  const uint32_t T = (uint32_t)(SMGI_TURN_SECONDS * ref_fps(d) + 0.5f);
  float* best = (float*)malloc(sizeof(float) * (T + 1u) * (LN ? LN : 1u));
  assert_non_null(best);
  for (uint32_t dir = 0; dir < 2u; ++dir) {
    const float sg = dir == 0 ? 1.0f : -1.0f;
    for (uint32_t n = 0; n < LN; ++n) best[n] = 0.0f;
    for (uint32_t t = 1; t <= T; ++t) {
      for (uint32_t n = 0; n < LN; ++n) {
        const smgi_node* node = &d->lower_nodes[n];
        float b = 0.0f;
        for (uint32_t k = 0; k < node->edge_count; ++k) {
          const smgi_edge* e = &d->lower_edges[node->first_edge + k];
          float dh = sg * e->displacement[2];
          float v = e->frame_count <= t
                        ? dh + best[(size_t)(t - e->frame_count) * LN + e->to]
                        : dh * (float)t / (float)e->frame_count;
          if (v > b) b = v;
        }
        best[(size_t)t * LN + n] = b;
      }
    }
    for (uint32_t n = 0; n < LN; ++n)
      node_turn[2u * n + dir] = best[(size_t)T * LN + n];
  }
  free(best);
}

static void ref_edge_mid(const smgi_graph_data* d, float* edge_mid) {
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_edge* E = &d->lower_edges[e];
    float* o = edge_mid + 4u * (size_t)e;
    o[0] = o[1] = o[2] = o[3] = 0.0f;
    if (E->frame_count < 4u) continue;
    const float* g0 = d->frames[d->lower_nodes[E->from].frame].root2d;
    const float* r = d->frames[E->first_frame + E->frame_count / 2u].root2d;
    smgi_xform2 inv = smgi_xf_inv((smgi_xform2){g0[0], g0[1], g0[2]});
    smgi_xf_point(inv, r[0], r[1], &o[0], &o[1]);
    o[2] = smgi_wrap_angle(inv.h + r[2]);
  }
}

static void ref_build(const smgi_graph_data* d, ref_tables* r) {
  const uint32_t F = d->frame_count, S = d->style_count, A = d->action_count;
  const uint32_t LN = d->lower_node_count, UN = d->upper_node_count;
  const size_t TK = (size_t)LN * SMGI_TRAIL_SAMPLES;
  memset(r, 0, sizeof *r);
  r->lower_hops = (uint8_t*)calloc((size_t)LN * S + 1u, 1);
  r->upper_hops = (uint8_t*)calloc((size_t)UN * A + 1u, 1);
  r->splice_first = (uint32_t*)calloc((size_t)F + 1u, sizeof(uint32_t));
  r->action_first = (uint32_t*)calloc((size_t)A + 1u, sizeof(uint32_t));
  r->natural = (uint32_t*)calloc((size_t)LN + 1u, sizeof(uint32_t));
  r->trail = (float*)calloc(4u * TK + 1u, sizeof(float));
  r->trail_frames = (float*)calloc(TK + 1u, sizeof(float));
  r->trail_edge = (uint32_t*)calloc(TK + 1u, sizeof(uint32_t));
  r->trail_hops = (uint32_t*)calloc(TK + 1u, sizeof(uint32_t));
  r->trail_dist = (float*)calloc(TK + 1u, sizeof(float));
  r->turn = (float*)calloc(2u * (size_t)LN + 1u, sizeof(float));
  r->edge_mid =
      (float*)calloc(4u * (size_t)d->lower_edge_count + 1u, sizeof(float));
  assert_true(r->lower_hops && r->upper_hops && r->splice_first &&
              r->action_first && r->natural && r->trail && r->trail_frames &&
              r->trail_edge && r->trail_hops && r->trail_dist && r->turn &&
              r->edge_mid);

  ref_hops(d->lower_nodes, LN, d->lower_edges, d->lower_edge_count, S,
           r->lower_hops);
  ref_hops(d->upper_nodes, UN, d->upper_edges, d->upper_edge_count, A,
           r->upper_hops);
  ref_style_time(d, r->lower_hops, r);
  for (uint32_t i = 0; i < d->splice_count; ++i)
    if (d->splices[i].lower_frame < F)
      r->splice_first[d->splices[i].lower_frame + 1u]++;
  for (uint32_t f = 0; f < F; ++f)
    r->splice_first[f + 1u] += r->splice_first[f];
  for (uint32_t a = 0; a < A; ++a) {
    r->action_first[a] = SMGI_NONE;
    for (uint32_t e = 0; e < d->upper_edge_count; ++e)
      if (d->upper_edges[e].label == a) {
        r->action_first[a] = e;
        break;
      }
  }
  ref_natural(d, r->natural);
  ref_trail(d, r->natural, r);
  ref_turn(d, r->turn);
  ref_edge_mid(d, r->edge_mid);
  /* a style can stop: some frame of its edges has both feet down, or
   * support passes from one foot straight to the other */
  r->can_stop = (uint8_t*)calloc((size_t)S + 1u, 1);
  assert_non_null(r->can_stop);
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_edge* E = &d->lower_edges[e];
    for (uint32_t k = 0; E->label < S && k < E->frame_count; ++k) {
      uint32_t fl = d->frames[E->first_frame + k].flags & 3u;
      uint32_t pv = k > 0 ? d->frames[E->first_frame + k - 1u].flags & 3u : 0u;
      if (fl == 3u || (fl && pv && fl != pv)) r->can_stop[E->label] = 1;
    }
  }
  /* ... unless it is faster than the walk-run transition (Froude number
   * 0.5 on the leg length); the stop style is the fastest one left */
  r->stop_style = SMGI_NONE;
  r->stop_speed = 0.0f;
  for (uint32_t st = 0; st < S; ++st) {
    double arc = 0.0, frames = 0.0;
    for (uint32_t e = 0; e < d->lower_edge_count; ++e)
      if (d->lower_edges[e].label == st) {
        arc += d->lower_edges[e].arc_length;
        frames += d->lower_edges[e].frame_count;
      }
    const float v =
        frames > 0.0 ? (float)(arc * (double)d->info->frame_rate / frames)
                     : 0.0f;
    if (v * v > 0.5f * 9.81f * d->info->leg_length) r->can_stop[st] = 0;
    if (r->can_stop[st] && (r->stop_style == SMGI_NONE || v > r->stop_speed)) {
      r->stop_style = st;
      r->stop_speed = v;
    }
  }
  float best = -1.0f;
  for (uint32_t st = 0; st < S; ++st) {
    double turn = 0.0, arc = 0.0;
    for (uint32_t n = 0; n < LN; ++n) {
      if (d->lower_nodes[n].label != st) continue;
      /* heading change summed over the trail's samples, per metre */
      const float* tr = r->trail + 4u * (size_t)n * SMGI_TRAIL_SAMPLES;
      float h = 0.0f;
      for (uint32_t k = 0; k < SMGI_TRAIL_SAMPLES; ++k) {
        turn += fabs((double)smgi_wrap_angle(tr[4u * k + 2u] - h));
        h = tr[4u * k + 2u];
      }
      arc += (double)tr[4u * (SMGI_TRAIL_SAMPLES - 1u) + 3u];
    }
    float mean = arc > 1e-6 ? (float)(turn / arc) : -1.0f;
    if (mean > best) {
      best = mean;
      r->agile_style = st;
    }
  }
}

static void ref_free(ref_tables* r) {
  free(r->lower_hops);
  free(r->style_time);
  free(r->style_time_hop);
  free(r->upper_hops);
  free(r->splice_first);
  free(r->action_first);
  free(r->natural);
  free(r->can_stop);
  free(r->trail);
  free(r->trail_frames);
  free(r->trail_edge);
  free(r->trail_hops);
  free(r->trail_dist);
  free(r->turn);
  free(r->edge_mid);
}

/* ---- comparison ---------------------------------------------------------- */

typedef struct dev_stats {
  double max_abs;   /* largest |x or z - reference| in metres */
  double max_ratio; /* largest deviation / allowed */
  size_t inexact;   /* x/z entries not bit-identical */
  size_t checked;
} dev_stats;

static int same_bits(const void* a, const void* b, size_t bytes) {
  return memcmp(a, b, bytes) == 0;
}

#define EXPECT_SAME(what, a, b, bytes)                                    \
  do {                                                                    \
    if (!same_bits((a), (b), (bytes))) {                                  \
      print_error("%s: %s differs from the reference\n", name, (what));   \
      fail();                                                             \
    }                                                                     \
  } while (0)

/* One ground sample (x, z, heading, arc): heading and arc exact, x and z
 * within the bound for `hops` edges over `dist` metres. */
static void check_sample(const char* name, const char* what, uint32_t n,
                         const float* got, const float* want, uint32_t hops,
                         float dist, dev_stats* st) {
  if (!same_bits(got + 2, want + 2, 2 * sizeof(float))) {
    print_error("%s: %s[%u] heading/arc %.9g %.9g, reference %.9g %.9g\n",
                name, what, n, (double)got[2], (double)got[3],
                (double)want[2], (double)want[3]);
    fail();
  }
  const double allowed =
      (double)hops * (double)dist * ldexp(1.0, -21) + 1e-6;
  for (int c = 0; c < 2; ++c) {
    double dev = fabs((double)got[c] - (double)want[c]);
    st->checked++;
    if (!same_bits(got + c, want + c, sizeof(float))) st->inexact++;
    if (dev > st->max_abs) st->max_abs = dev;
    if (dev / allowed > st->max_ratio) st->max_ratio = dev / allowed;
    if (!(dev <= allowed)) {
      print_error("%s: %s[%u].%c = %.9g, reference %.9g (%u hops, %.3f m; "
                  "allowed %.3g)\n",
                  name, what, n, c ? 'z' : 'x', (double)got[c],
                  (double)want[c], hops, (double)dist, allowed);
      fail();
    }
  }
}

/* Every table of `dv` against the reference for graph data `d`. */
static void compare(const char* name, const smgi_graph_data* d,
                    const smgi_derived* dv, const ref_tables* r,
                    dev_stats* st) {
  const uint32_t F = d->frame_count, S = d->style_count, A = d->action_count;
  const uint32_t LN = d->lower_node_count, UN = d->upper_node_count;
  const uint32_t K = SMGI_TRAIL_SAMPLES;
  EXPECT_SAME("lower_hops", dv->lower_hops, r->lower_hops, (size_t)LN * S);
  EXPECT_SAME("upper_hops", dv->upper_hops, r->upper_hops, (size_t)UN * A);
  for (uint32_t st = 0; st < S; ++st) {
    for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
      const smgi_edge* E = &d->lower_edges[e];
      const uint8_t* t =
          dv->edge_style_time + 2u * ((size_t)st * d->lower_edge_count + e);
      EXPECT_SAME("edge_style_time (from)", t,
                  r->style_time + (size_t)st * LN + E->from, 1u);
      EXPECT_SAME("edge_style_time (to)", t + 1,
                  r->style_time + (size_t)st * LN + E->to, 1u);
    }
  }
  EXPECT_SAME("style_time_hop", dv->style_time_hop, r->style_time_hop,
              sizeof(float) * (size_t)S);
  EXPECT_SAME("splice_first", dv->splice_first, r->splice_first,
              4u * ((size_t)F + 1u));
  EXPECT_SAME("action_first_edge", dv->action_first_edge, r->action_first,
              4u * (size_t)A);
  for (uint32_t n = 0; n < LN; ++n) {
    const smgi_node_next* x = &dv->node_next[n];
    const uint32_t unused[3] = {0, 0, 0};
    EXPECT_SAME("node_next.unused", x->unused, unused, sizeof unused);
    for (uint32_t k = 0; k < K; ++k) {
      /* the trail edge's label, or WIDE where there is none or it does
       * not fit 16 bits */
      const uint32_t te = r->trail_edge[(size_t)n * K + k];
      const uint32_t lab = te == SMGI_NONE ? SMGI_TRAIL_LABEL_WIDE
                                           : d->lower_edges[te].label;
      assert_int_equal(x->trail_label[k], lab < SMGI_TRAIL_LABEL_WIDE
                                              ? lab
                                              : SMGI_TRAIL_LABEL_WIDE);
    }
    EXPECT_SAME("node_next.natural", &x->natural, r->natural + n, 4u);
    EXPECT_SAME("node_next.trail_frames", x->trail_frames,
                r->trail_frames + (size_t)n * K, 4u * K);
    EXPECT_SAME("node_next.trail_edge", x->trail_edge,
                r->trail_edge + (size_t)n * K, 4u * K);
    EXPECT_SAME("node_next.turn", x->turn, r->turn + 2u * (size_t)n, 8u);
  }
  assert_true(((uintptr_t)dv->node_next & 63u) == 0);
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_search_edge* x = &dv->search_edges[e];
    const smgi_edge* E = &d->lower_edges[e];
    EXPECT_SAME("search_edges.displacement", x->displacement,
                E->displacement, sizeof x->displacement);
    EXPECT_SAME("search_edges.arc_length", &x->arc_length, &E->arc_length, 4u);
    EXPECT_SAME("search_edges.mid", x->mid, r->edge_mid + 4u * (size_t)e,
                sizeof x->mid);
    EXPECT_SAME("search_edges.to", &x->to, &E->to, 4u);
    EXPECT_SAME("search_edges.frame_count", &x->frame_count, &E->frame_count,
                4u);
    EXPECT_SAME("search_edges.label", &x->label, &E->label, 4u);
    EXPECT_SAME("search_edges.to_first_edge", &x->to_first_edge,
                &d->lower_nodes[E->to].first_edge, 4u);
    EXPECT_SAME("search_edges.to_edge_count", &x->to_edge_count,
                &d->lower_nodes[E->to].edge_count, 4u);
  }
  {
    /* start nodes: per style, the nodes with out-edges in node order */
    uint32_t first_any = SMGI_NONE;
    for (uint32_t st = 0; st < S; ++st) {
      uint32_t k = dv->start_first[st];
      for (uint32_t n = 0; n < LN; ++n) {
        if (d->lower_nodes[n].edge_count == 0) continue;
        if (first_any == SMGI_NONE) first_any = n;
        if (d->lower_nodes[n].label != st) continue;
        assert_true(k < dv->start_first[st + 1u]);
        assert_int_equal(dv->start_nodes[k], n);
        ++k;
      }
      assert_int_equal(k, dv->start_first[st + 1u]);
    }
    assert_int_equal(dv->start_first[0], 0);
    assert_int_equal(dv->first_start, first_any);
  }
  assert_int_equal(dv->agile_style, r->agile_style);
  EXPECT_SAME("style_can_stop", dv->style_can_stop, r->can_stop, (size_t)S);
  assert_int_equal(dv->stop_style, r->stop_style);
  assert_true(dv->stop_speed == r->stop_speed);
  for (uint32_t n = 0; n < LN; ++n) {
    for (uint32_t k = 0; k < K; ++k) {
      const size_t i = (size_t)n * K + k;
      check_sample(name, "node_next.trail", n, dv->node_next[n].trail + 4u * k,
                   r->trail + 4u * i, r->trail_hops[i], r->trail_dist[i], st);
    }
  }
}

static void report(const char* name, const dev_stats* st) {
  printf("%s: x/z of node_trail: %zu of %zu not bit-identical, "
         "max deviation %.3g m (%.2g of the allowed bound); every other "
         "table bit-identical\n",
         name, st->inexact, st->checked, st->max_abs, st->max_ratio);
}

/* The library's build (SSE2 on x86-64) and the plain-C one: the same
 * operations lane by lane, so every table bit for bit. */
static void compare_builds(const char* name, const smgi_graph_data* d,
                           const smgi_derived* a, const smgi_derived* b) {
  const size_t LN = d->lower_node_count;
  EXPECT_SAME("node_next (SSE2 vs plain)", a->node_next, b->node_next,
              sizeof(smgi_node_next) * LN);
  EXPECT_SAME("search_edges (SSE2 vs plain)", a->search_edges,
              b->search_edges,
              sizeof(smgi_search_edge) * (size_t)d->lower_edge_count);
}

/* A loaded graph: its own tables, and the plain-C build of the same data. */
static void check_graph(const char* name, smg_graph* g) {
  ref_tables r;
  dev_stats st;
  memset(&st, 0, sizeof st);
  ref_build(&g->data, &r);
  compare(name, &g->data, smgi_derived_of(g), &r, &st);
  void* keep = g->derived;
  g->derived = NULL;
  assert_int_equal(plain_graph_derived_build(g), SMG_OK);
  compare(name, &g->data, smgi_derived_of(g), &r, &st);
  compare_builds(name, &g->data, (const smgi_derived*)keep,
                 smgi_derived_of(g));
  plain_graph_derived_free(g);
  g->derived = keep;
  ref_free(&r);
  report(name, &st);
}

/* ---- random graphs ------------------------------------------------------- */

#define RG_FRAMES 240u
#define RG_MAX_NODES 48u
#define RG_MAX_EDGES (RG_MAX_NODES * 5u)

typedef struct rand_graph {
  smgi_info info;
  smgi_frame frames[RG_FRAMES];
  smgi_node lower_nodes[RG_MAX_NODES], upper_nodes[RG_MAX_NODES];
  smgi_edge lower_edges[RG_MAX_EDGES], upper_edges[RG_MAX_EDGES];
  smgi_splice splices[64];
  smg_graph g;
} rand_graph;

static uint32_t rng_next(uint64_t* s) {
  *s = *s * 6364136223846793005ull + 1442695040888963407ull;
  return (uint32_t)(*s >> 33);
}
static float rng_unit(uint64_t* s) { /* [0, 1) */
  return (float)(rng_next(s) & 0xffffffu) / 16777216.0f;
}
static float rng_range(uint64_t* s, float lo, float hi) {
  return lo + (hi - lo) * rng_unit(s);
}

/* Nodes and edges of one graph; `dag` keeps edges shorter than 8 frames
 * going to higher node indices (no cycle of them: the block path);
 * `short_only` makes edges 1-2 frames (hundreds of them per trail sample
 * at high frame rates). */
static uint32_t rand_edges(uint64_t* s, smgi_node* nodes, uint32_t N,
                           smgi_edge* edges, uint32_t labels, int dag,
                           int short_only, uint32_t T) {
  /* one edge in ten may be longer than node_turn's horizon T */
  const uint32_t long_fc = T + 40u < RG_FRAMES ? T + 40u : RG_FRAMES;
  uint32_t E = 0;
  for (uint32_t n = 0; n < N; ++n) {
    smgi_node* nd = &nodes[n];
    nd->frame = rng_next(s) % RG_FRAMES;
    nd->label = rng_next(s) % labels;
    nd->first_edge = E;
    nd->edge_count = rng_next(s) % 7u == 0 ? 0u : 1u + rng_next(s) % 4u;
    for (uint32_t k = 0; k < nd->edge_count; ++k) {
      smgi_edge* e = &edges[E++];
      memset(e, 0, sizeof *e);
      e->from = n;
      e->to = rng_next(s) % N;
      uint32_t r = rng_next(s) % 10u;
      e->frame_count = r < 5u   ? 1u + rng_next(s) % 7u
                       : r < 9u ? 8u + rng_next(s) % 24u
                                : 1u + rng_next(s) % long_fc;
      if (short_only) e->frame_count = 1u + rng_next(s) % 2u;
      if (dag && e->frame_count < 8u && e->to <= n) e->frame_count += 8u;
      /* some edges continue the node's own motion (natural), one in ten
       * turns far (heading wraps) */
      e->first_frame = rng_next(s) % 3u == 0 ? nd->frame : rng_next(s);
      if (e->first_frame + e->frame_count > RG_FRAMES)
        e->first_frame = rng_next(s) % (RG_FRAMES - e->frame_count + 1u);
      e->displacement[0] = rng_range(s, -1.5f, 1.5f);
      e->displacement[1] = rng_range(s, -0.5f, 2.5f);
      e->displacement[2] = rng_next(s) % 10u == 0 ? rng_range(s, -7.0f, 7.0f)
                                                : rng_range(s, -0.6f, 0.6f);
      e->arc_length = rng_range(s, 0.0f, 3.0f);
      e->cost = rng_next(s) % 4u == 0 ? 0.0f : rng_range(s, 0.0f, 2.0f);
      e->label = rng_next(s) % labels;
      e->flags = rng_next(s) % 2u ? SMGI_EDGE_TRANSITION : 0u;
    }
  }
  return E;
}

static void rand_graph_make(rand_graph* rg, uint64_t seed) {
  static const float rates[] = {30.0f, 24.0f, 60.0f, 29.97f, 7.5f,
                                120.0f, 25.0f, 1.0f, 0.1f, 500.0f};
  uint64_t s = seed;
  memset(rg, 0, sizeof *rg);
  rg->info.frame_rate = rates[rng_next(&s) % (sizeof rates / sizeof *rates)];
  /* every 8th graph: 500 Hz with 1-2 frame edges: long walks */
  if ((seed & 7u) == 0) rg->info.frame_rate = 500.0f;
  const uint32_t T = (uint32_t)(SMGI_TURN_SECONDS * rg->info.frame_rate + 0.5f);
  for (uint32_t f = 0; f < RG_FRAMES; ++f) {
    rg->frames[f].root2d[0] = rng_range(&s, -20.0f, 20.0f);
    rg->frames[f].root2d[1] = rng_range(&s, -20.0f, 20.0f);
    /* headings past +-pi too: edge_mid's inverse then wraps */
    rg->frames[f].root2d[2] = rng_range(&s, -4.0f, 4.0f);
    rg->frames[f].phase = -1.0f;
  }
  smgi_graph_data* d = &rg->g.data;
  d->info = &rg->info;
  d->frames = rg->frames;
  d->frame_count = RG_FRAMES;
  d->style_count = 1u + rng_next(&s) % 3u;
  d->action_count = 1u + rng_next(&s) % 3u;
  d->lower_node_count = 1u + rng_next(&s) % RG_MAX_NODES;
  d->upper_node_count = 1u + rng_next(&s) % 12u;
  d->lower_nodes = rg->lower_nodes;
  d->lower_edges = rg->lower_edges;
  d->upper_nodes = rg->upper_nodes;
  d->upper_edges = rg->upper_edges;
  d->lower_edge_count =
      rand_edges(&s, rg->lower_nodes, d->lower_node_count, rg->lower_edges,
                 d->style_count, (int)(seed & 1u), (seed & 6u) == 0, T);
  d->upper_edge_count =
      rand_edges(&s, rg->upper_nodes, d->upper_node_count, rg->upper_edges,
                 d->action_count, 0, 0, T);
  d->splice_count = rng_next(&s) % 64u;
  uint32_t f = 0; /* SPLC is sorted by lower_frame */
  for (uint32_t i = 0; i < d->splice_count; ++i) {
    f += rng_next(&s) % 8u;
    if (f >= RG_FRAMES) f = RG_FRAMES - 1u;
    rg->splices[i].lower_frame = f;
    rg->splices[i].action = rng_next(&s) % d->action_count;
  }
  d->splices = rg->splices;
  assert_int_equal(smgi_allocator_resolve(NULL, &rg->g.allocator), SMG_OK);
}

static void test_random_graphs(void** state) {
  (void)state;
  rand_graph* rg = (rand_graph*)malloc(sizeof *rg);
  assert_non_null(rg);
  dev_stats st;
  memset(&st, 0, sizeof st);
  const uint32_t trials = smgt_quick() ? 60u : 400u;
  unsigned cyclic = 0;
  for (uint32_t i = 0; i < trials; ++i) {
    char name[64];
    snprintf(name, sizeof name, "random graph %u", i);
    rand_graph_make(rg, 0x5eed0000u + i);
    {
      /* which node_turn path this graph takes (coverage report) */
      const size_t LN = rg->g.data.lower_node_count;
      uint32_t* scratch = (uint32_t*)malloc(
          sizeof(uint32_t) * (4u * LN + 1u + rg->g.data.lower_edge_count));
      assert_non_null(scratch);
      cyclic += short_edge_levels(&rg->g.data, scratch, scratch + LN,
                                  scratch + 3u * LN, scratch + 4u * LN + 1u) ==
                0;
      free(scratch);
    }
    ref_tables r;
    ref_build(&rg->g.data, &r);
    assert_int_equal(smgi_graph_derived_build(&rg->g), SMG_OK);
    compare(name, &rg->g.data, smgi_derived_of(&rg->g), &r, &st);
    void* lib = rg->g.derived;
    rg->g.derived = NULL;
    assert_int_equal(plain_graph_derived_build(&rg->g), SMG_OK);
    compare(name, &rg->g.data, smgi_derived_of(&rg->g), &r, &st);
    compare_builds(name, &rg->g.data, (const smgi_derived*)lib,
                   smgi_derived_of(&rg->g));
    plain_graph_derived_free(&rg->g);
    rg->g.derived = lib;
    smgi_graph_derived_free(&rg->g);
    assert_null(rg->g.derived);
    ref_free(&r);
  }
  report("random graphs", &st);
  printf("random graphs: %u of %u with a cycle of short edges (node_turn "
         "frame by frame)\n",
         cyclic, trials);
  assert_true(cyclic > 0 && cyclic < trials);
  free(rg);
}

/* ---- the fixture, with short edges that do or do not form a cycle ------- */

static smg_graph* load_fixture(fixture_graph* f, void** blob) {
  size_t size = 0;
  smg_graph* g = NULL;
  assert_int_equal(smgi_blob_write(&f->data, NULL, blob, &size, NULL, 0),
                   SMG_OK);
  assert_int_equal(smg_graph_load_memory(*blob, size, NULL, &g), SMG_OK);
  return g;
}

static void test_fixture(void** state) {
  (void)state;
  fixture_graph* f = fixture_graph_new();
  assert_non_null(f);
  void* blob = NULL;
  smg_graph* g = load_fixture(f, &blob);
  check_graph("fixture", g);
  smg_graph_destroy(g);
  smgi_blob_free(blob, NULL);

  /* walk_to_run and run_to_walk 3 frames long: short edges, no cycle of
   * them (node_turn in blocks, short edges first) */
  f->lower_edges[3].frame_count = 3u;
  f->lower_edges[5].frame_count = 9u;
  g = load_fixture(f, &blob);
  check_graph("fixture, short transition", g);
  smg_graph_destroy(g);
  smgi_blob_free(blob, NULL);

  /* the run loop 5 frames long: a cycle of short edges (frame by frame) */
  f->lower_edges[4].frame_count = 5u;
  g = load_fixture(f, &blob);
  check_graph("fixture, short cycle", g);
  smg_graph_destroy(g);
  smgi_blob_free(blob, NULL);
  fixture_graph_delete(f);
}

/* ---- baked graphs -------------------------------------------------------- */

static void test_default(void** state) {
  (void)state;
  char path[1024];
  smg_graph* g = NULL;
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  smg_result r = smg_graph_load_file(path, NULL, &g);
  if (r != SMG_OK) {
    print_message("skipped: cannot load %s (%s); `make` bakes it\n", path,
                  smg_result_string(r));
    skip();
  }
  check_graph("default.smg", g);
  smg_graph_destroy(g);
}

/* The CMU graph: build/cmu.smg (make demo-cmu) when it loads; otherwise
 * baked here from data/cmu.manifest (not under SMG_TEST_QUICK: too slow
 * under valgrind). */
static void test_cmu(void** state) {
  (void)state;
  char path[1024];
  smg_graph* g = NULL;
  snprintf(path, sizeof path, "%s/cmu.smg", SMG_BUILD_DIR);
  if (smg_graph_load_file(path, NULL, &g) == SMG_OK) {
    check_graph("cmu.smg", g);
    smg_graph_destroy(g);
    return;
  }
  const char* dir = smgt_cmu_dir();
  struct stat sb;
  if (!dir) skip();
  if (smgt_quick()) {
    print_message("skipped: no loadable %s and SMG_TEST_QUICK (baking the "
                  "CMU set is too slow under valgrind)\n", path);
    skip();
  }
  if (stat("data/cmu.manifest", &sb) != 0) {
    print_message("skipped: data/cmu.manifest not found (run from the "
                  "repository root)\n");
    skip();
  }
  smgb_manifest m;
  smgb_error err;
  assert_int_equal(smgb_manifest_load("data/cmu.manifest", dir, &m, &err),
                   SMG_OK);
  smg_bake_clip_desc descs[64];
  smg_bake_desc desc;
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.options.struct_size = sizeof desc.options;
  desc.options.frame_rate = m.frame_rate;
  desc.clip_count = m.clip_count;
  desc.clips = descs;
  assert_true(m.clip_count <= 64);
  assert_int_equal(smgb_manifest_descs(&m, descs, 64), SMG_OK);
  smg_bake_result res;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  smg_result rr = smg_bake_run(&desc, &res);
  smgb_manifest_free(&m);
  if (rr != SMG_OK) print_error("CMU bake: %s\n", res.error);
  assert_int_equal(rr, SMG_OK);
  assert_int_equal(smg_graph_load_memory(res.blob, res.blob_size, NULL, &g),
                   SMG_OK);
  check_graph("CMU (baked here)", g);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_random_graphs),
      cmocka_unit_test(test_fixture),
      cmocka_unit_test(test_default),
      cmocka_unit_test(test_cmu),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
