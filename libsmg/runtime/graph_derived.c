/*
 * graph_derived.c - load-time lookup tables for the runtime (see
 * graph_derived.h). Everything lives in one allocation so destroy is one
 * free and the tables stay close together in memory.
 *
 * This runs inside every smg_graph_load_*, and a whole graph must load in
 * about a millisecond, so the three tables that cost most are built with
 * care (tests/runtime/test_derived.c keeps the plain versions as oracles
 * and checks every table against them):
 *  - node_next.turn, a dynamic programme over 3 s of frames x every edge, runs
 *    eight frames at a time in both directions at once, over rings of the
 *    last few frames (build_turn);
 *  - node_next.trail comes from one walk per node that carries the cosine and
 *    sine of its heading instead of calling sincosf per edge (build_walks;
 *    x and z agree with composing transforms edge by edge to float
 *    rounding, everything else is bit for bit the same);
 *  - search_edges' mid samples invert each node's ground frame once, not once
 *    per edge.
 */
#include "graph_derived.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "rmath.h"

/* node_next.turn's blocks and the walks use SSE2 where it is part of the ABI
 * (x86-64); plain loops compute the same lanes elsewhere (or with
 * -DSMGI_DERIVED_SSE=0, which is how the test covers them). */
#ifndef SMGI_DERIVED_SSE
#if defined(__SSE2__) || defined(_M_X64) || \
    (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#define SMGI_DERIVED_SSE 1
#else
#define SMGI_DERIVED_SSE 0
#endif
#endif
#if SMGI_DERIVED_SSE
#include <emmintrin.h>
#endif

static size_t align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

/* Multi-source BFS on reversed edges: hops[n*L + l] = 0 where node n has an
 * out-edge labelled l, else 1 + min over out-edges of hops[to] (capped at
 * SMGI_HOPS_UNREACHABLE). The sources of every label come from one pass
 * over the edges. `in_first` / `in_from` is the reverse adjacency (CSR),
 * `queue` node_count + 1 scratch (appends write one past the end), `col`
 * node_count bytes of scratch.
 *
 * Each label's search runs on its own column (`col`, one byte a node) and
 * is copied into the node-major table afterwards: a BFS touches nodes in
 * no predictable order, and in the node-major table each touch was a
 * cache line of its own (a 120k-node graph of 12 styles has a 1.4 MB table,
 * its column 120 KB). */
static void compute_hops(const smgi_node* nodes, uint32_t node_count,
                         const smgi_edge* edges, uint32_t label_count,
                         const uint32_t* in_first, const uint32_t* in_from,
                         uint32_t* queue, uint8_t* col, uint8_t* hops) {
  const size_t L = label_count;
  memset(hops, SMGI_HOPS_UNREACHABLE, (size_t)node_count * L);
  for (uint32_t n = 0; n < node_count; ++n) {
    const smgi_edge* e = edges + nodes[n].first_edge;
    for (uint32_t k = 0; k < nodes[n].edge_count; ++k)
      if (e[k].label < label_count) hops[n * L + e[k].label] = 0;
  }
  /* Branch-free appends: whether a node is new is data, not control flow
   * (a BFS visits each node's in-edges in a pattern nothing predicts). A
   * node already reached has hops <= hn + 1, so min() leaves it alone. */
  for (uint32_t l = 0; l < label_count; ++l) {
    uint32_t head = 0, tail = 0;
    for (uint32_t n = 0; n < node_count; ++n) {
      col[n] = hops[n * L + l];
      queue[tail] = n;
      tail += col[n] == 0;
    }
    while (head < tail) {
      const uint32_t n = queue[head++];
      const uint8_t hn = col[n];
      if (hn + 1u >= SMGI_HOPS_UNREACHABLE) continue;
      const uint8_t next = (uint8_t)(hn + 1u);
      for (uint32_t k = in_first[n]; k < in_first[n + 1u]; ++k) {
        const uint32_t from = in_from[k];
        uint8_t* hf = &col[from];
        const uint8_t old = *hf;
        queue[tail] = from;
        tail += old == SMGI_HOPS_UNREACHABLE;
        *hf = old < next ? old : next;
      }
    }
    for (uint32_t n = 0; n < node_count; ++n) hops[n * L + l] = col[n];
  }
}

/* edge_style_time's value for `frames` of motion at `fps`: in steps of
 * 1 / SMGI_STYLE_TIME_HZ s, rounded to nearest, capped at
 * SMGI_STYLE_TIME_FAR. */
static uint8_t style_time_steps(uint32_t frames, double fps) {
  const double q = floor((double)frames * (SMGI_STYLE_TIME_HZ / fps) + 0.5);
  return q < (double)SMGI_STYLE_TIME_FAR ? (uint8_t)q
                                         : (uint8_t)SMGI_STYLE_TIME_FAR;
}

/* The fewest frames of motion that edge_style_time holds as
 * SMGI_STYLE_TIME_FAR: the searches below stop there. */
static uint32_t style_time_limit(double fps) {
  uint32_t f = 0;
  while (style_time_steps(f, fps) < SMGI_STYLE_TIME_FAR) ++f;
  return f;
}

/* edge_style_time (graph_derived.h): per style a Dijkstra over reversed
 * lower edges, weighted by their frame counts, from every node with an
 * out-edge of the style, up to `limit` frames (style_time_limit). The
 * distances are whole frames below `limit`, so the queue is a bucket per
 * frame (Dial's algorithm): node n waits in a doubly linked list
 * (next[n], prev[n]) from head[dist[n]], and a shorter distance moves it
 * (a binary heap took twice as long here on a big graph). `in_first` /
 * `in_from` / `in_frames` is the reverse adjacency (build_reverse_frames),
 * `dist`, `next` and `prev` node_count scratch each, `head` `limit` and
 * `steps_of` `limit` bytes (each distance's value, computed once); `hops`
 * (lower_hops) tells "far" from "unreachable". Writes the hop
 * equivalent of one step per style to `time_hop` (style_time_hop,
 * graph_derived.h). */
static void build_edge_style_time(const smgi_graph_data* d,
                                   const uint8_t* hops, uint32_t limit,
                                   const uint32_t* in_first,
                                   const uint32_t* in_from,
                                   const uint32_t* in_frames, uint32_t* dist,
                                   uint32_t* next, uint32_t* prev,
                                   uint32_t* head, uint8_t* steps_of,
                                   uint8_t* out, float* time_hop) {
  const uint32_t N = d->lower_node_count, S = d->style_count;
  const uint32_t E = d->lower_edge_count;
  const smgi_edge* edges = d->lower_edges;
  const double fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0;
  for (uint32_t f = 0; f < limit; ++f) steps_of[f] = style_time_steps(f, fps);
  for (uint32_t st = 0; st < S; ++st) {
    uint64_t sum_hops = 0, sum_steps = 0;
    for (uint32_t f = 0; f < limit; ++f) head[f] = SMGI_NONE;
    for (uint32_t n = 0; n < N; ++n) {
      dist[n] = UINT32_MAX;
      if (hops[(size_t)n * S + st] != 0u) continue;
      dist[n] = 0;
      prev[n] = SMGI_NONE;
      next[n] = head[0];
      if (head[0] != SMGI_NONE) prev[head[0]] = n;
      head[0] = n;
    }
    for (uint32_t f = 0; f < limit; ++f) {
      while (head[f] != SMGI_NONE) {
        const uint32_t n = head[f];
        head[f] = next[n];
        if (next[n] != SMGI_NONE) prev[next[n]] = SMGI_NONE;
        for (uint32_t k = in_first[n]; k < in_first[n + 1u]; ++k) {
          const uint32_t from = in_from[k], w = in_frames[k];
          if (w >= limit - f || f + w >= dist[from]) continue;
          if (dist[from] != UINT32_MAX) { /* waiting: out of its bucket */
            const uint32_t p = prev[from], x = next[from];
            if (p != SMGI_NONE)
              next[p] = x;
            else
              head[dist[from]] = x;
            if (x != SMGI_NONE) prev[x] = p;
          }
          dist[from] = f + w;
          prev[from] = SMGI_NONE;
          next[from] = head[f + w];
          if (head[f + w] != SMGI_NONE) prev[head[f + w]] = from;
          head[f + w] = from;
        }
      }
    }
    /* each node's value once (in the links' place, free now), then the
     * edges' pairs from it; nodes a step or more away and within the cap
     * tell what one step towards the style is worth in hops, on average */
    uint8_t* col = (uint8_t*)next;
    for (uint32_t n = 0; n < N; ++n) {
      const uint8_t h = hops[(size_t)n * S + st];
      uint8_t t = SMGI_HOPS_UNREACHABLE;
      if (h != SMGI_HOPS_UNREACHABLE)
        t = dist[n] < limit ? steps_of[dist[n]] : SMGI_STYLE_TIME_FAR;
      col[n] = t;
      if (t > 0u && t < SMGI_STYLE_TIME_FAR) {
        sum_hops += h;
        sum_steps += t;
      }
    }
    time_hop[st] = sum_steps > 0u ? (float)((double)sum_hops /
                                            (double)sum_steps)
                                  : 1.0f;
    uint8_t* o = out + 2u * (size_t)E * st;
    for (uint32_t e = 0; e < E; ++e) {
      o[2u * (size_t)e] = col[edges[e].from];
      o[2u * (size_t)e + 1u] = col[edges[e].to];
    }
  }
}

/* The lower graph's reverse adjacency with each edge's frame count: the
 * edges into n come from in_from[k] and last in_frames[k] frames, k in
 * [in_first[n], in_first[n + 1]) (in_first node_count + 1 entries, the
 * others edge_count). Side by side, so that the searches below read them
 * in order: an edge record per relaxation was a cache miss of its own on
 * a big graph (76k edges of 48 bytes, read once per style). */
static void build_reverse_frames(const smgi_edge* edges, uint32_t edge_count,
                                 uint32_t node_count, uint32_t* in_first,
                                 uint32_t* in_from, uint32_t* in_frames) {
  memset(in_first, 0, sizeof(uint32_t) * ((size_t)node_count + 1u));
  for (uint32_t e = 0; e < edge_count; ++e) in_first[edges[e].to + 1u]++;
  for (uint32_t n = 0; n < node_count; ++n) in_first[n + 1u] += in_first[n];
  for (uint32_t e = 0; e < edge_count; ++e) {
    const uint32_t k = in_first[edges[e].to]++; /* cursor, restored below */
    in_from[k] = edges[e].from;
    in_frames[k] = edges[e].frame_count;
  }
  for (uint32_t n = node_count; n > 0; --n) in_first[n] = in_first[n - 1u];
  in_first[0] = 0;
}

/* Reverse adjacency of one graph into caller scratch: the nodes with an
 * edge into n are in_from[in_first[n] .. in_first[n + 1]) (in_first has
 * node_count + 1 entries, in_from edge_count). */
static void build_reverse(const smgi_edge* edges, uint32_t edge_count,
                          uint32_t node_count, uint32_t* in_first,
                          uint32_t* in_from) {
  memset(in_first, 0, sizeof(uint32_t) * ((size_t)node_count + 1u));
  for (uint32_t e = 0; e < edge_count; ++e) in_first[edges[e].to + 1u]++;
  for (uint32_t n = 0; n < node_count; ++n) in_first[n + 1u] += in_first[n];
  for (uint32_t e = 0; e < edge_count; ++e) {
    /* in_first[to] is used as a cursor and restored below */
    in_from[in_first[edges[e].to]++] = edges[e].from;
  }
  for (uint32_t n = node_count; n > 0; --n) in_first[n] = in_first[n - 1u];
  in_first[0] = 0;
}

/* nx[n].natural: the out-edge continuing node n's original motion, else
 * its cheapest edge, else SMGI_NONE. */
static void find_natural(const smgi_graph_data* d, smgi_node_next* nx) {
  for (uint32_t n = 0; n < d->lower_node_count; ++n) {
    const smgi_node* node = &d->lower_nodes[n];
    uint32_t* natural = &nx[n].natural;
    nx[n].unused[0] = nx[n].unused[1] = nx[n].unused[2] = 0;
    *natural = SMGI_NONE;
    for (uint32_t k = 0; k < node->edge_count; ++k) {
      const smgi_edge* e = &d->lower_edges[node->first_edge + k];
      if (e->first_frame == node->frame &&
          !(e->flags & SMGI_EDGE_TRANSITION)) {
        *natural = node->first_edge + k;
        break;
      }
    }
    if (*natural == SMGI_NONE && node->edge_count > 0) {
      /* no original motion continues here: the cheapest edge stands in */
      uint32_t best = node->first_edge;
      for (uint32_t k = 1; k < node->edge_count; ++k)
        if (d->lower_edges[node->first_edge + k].cost <
            d->lower_edges[best].cost)
          best = node->first_edge + k;
      *natural = best;
    }
  }
}

/* One step of a node's natural continuation, gathered once so a walk reads
 * one record per edge instead of node, edge and a sincosf. a and b are laid
 * out so that one 4-lane c * a + s * b gives both the edge's displacement
 * rotated by the heading so far (c, s) and the heading after it. */
typedef struct walk_step {
  float a[4];  /* dx, dz, cosf(dh), sinf(dh) */
  float b[4];  /* dz, -dx, -sinf(dh), cosf(dh) */
  const struct walk_step* next; /* to's step; NULL: no natural edge, every
                                   walk ends here */
  float frames, h, arc;
} walk_step;

/* smgi_wrap_angle with a cheaper test for the common case; the same
 * result (+-pi take the slow path, which maps both to pi). */
static inline float wrap_fast(float a) {
  return fabsf(a) < SMGI_PI ? a : smgi_wrap_angle(a);
}

static void put_sample(float* o, float x, float z, float h, float arc) {
  o[0] = x;
  o[1] = z;
  o[2] = h;
  o[3] = arc;
}

/* node_next.trail: every lower node's natural continuation, followed for
 * SMGI_TRAIL_SAMPLES * SMGI_TRAIL_STEP_SECONDS and sampled every
 * SMGI_TRAIL_STEP_SECONDS at the first edge end past the step (at most
 * 1024 edges per sample).
 *
 * The ground transform is composed edge by edge as acc = acc * step with
 * the heading wrapped each time, as smgi_xf_mul does; but instead of
 * cosf/sinf of the accumulated heading at every edge (20k calls on a CMU
 * graph, most of this function's time) the walk rotates the cosine and
 * sine it carries by each edge's own, computed once per node. Heading, arc
 * length, frames and edges are the same operations as composing with
 * smgi_xf_mul, bit for bit; x and z differ from it by float rounding only
 * (the first two edges of every walk are exact, later ones drift by a few
 * ulps of the rotation: <= 3.4e-6 m over the 2 s walks of a CMU graph).
 * The SSE2 and plain versions do the same operations lane by lane. */
static void build_walks(const smgi_graph_data* d, smgi_node_next* nx,
                        walk_step* ws) {
  const uint32_t LN = d->lower_node_count, K = SMGI_TRAIL_SAMPLES;
  const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
  const float step = SMGI_TRAIL_STEP_SECONDS * fps;
  for (uint32_t m = 0; m < LN; ++m) {
    walk_step* w = &ws[m];
    if (nx[m].natural == SMGI_NONE) {
      w->next = NULL;
      continue;
    }
    const smgi_edge* E = &d->lower_edges[nx[m].natural];
    float c, s;
    smgi_sincosf(E->displacement[2], &s, &c);
    w->a[0] = E->displacement[0];
    w->a[1] = E->displacement[1];
    w->a[2] = c;
    w->a[3] = s;
    w->b[0] = E->displacement[1];
    w->b[1] = -E->displacement[0];
    w->b[2] = -s;
    w->b[3] = c;
    /* the walk follows pointers: one load per edge on its critical path */
    w->next = &ws[E->to];
    w->frames = (float)E->frame_count;
    w->h = E->displacement[2];
    w->arc = E->arc_length;
  }
  for (uint32_t n = 0; n < LN; ++n) {
#if SMGI_DERIVED_SSE
    /* acc lanes 0, 1: x, z; rot lanes 2, 3: cos, sin of the heading (0, 1:
     * the last edge's rotated displacement, 2, 3 of acc: unused) */
    __m128 acc = _mm_setzero_ps(), rot = _mm_setr_ps(0.0f, 0.0f, 1.0f, 0.0f);
    float xz[4];
#else
    float x = 0.0f, z = 0.0f, c = 1.0f, s = 0.0f;
#endif
    float h = 0.0f, arc = 0.0f, frames = 0.0f;
    /* cur: the step about to be taken; from: the last one taken (its edge
     * is natural[from - ws]) */
    const walk_step *cur = &ws[n], *from = cur;
    for (uint32_t k = 0; k < K; ++k) {
      const float want = step * (float)(k + 1u);
      for (uint32_t hops = 0; hops < 1024u && frames < want && cur->next;
           ++hops) {
        const walk_step* w = cur;
#if SMGI_DERIVED_SSE
        const __m128 c = _mm_shuffle_ps(rot, rot, _MM_SHUFFLE(2, 2, 2, 2));
        const __m128 s = _mm_shuffle_ps(rot, rot, _MM_SHUFFLE(3, 3, 3, 3));
        rot = _mm_add_ps(_mm_mul_ps(c, _mm_loadu_ps(w->a)),
                         _mm_mul_ps(s, _mm_loadu_ps(w->b)));
        acc = _mm_add_ps(acc, rot);
#else
        x = x + (c * w->a[0] + s * w->b[0]);
        z = z + (c * w->a[1] + s * w->b[1]);
        const float c2 = c * w->a[2] + s * w->b[2];
        s = c * w->a[3] + s * w->b[3];
        c = c2;
#endif
        h = wrap_fast(h + w->h);
        arc += w->arc;
        frames += w->frames;
        from = w;
        cur = w->next;
      }
#if SMGI_DERIVED_SSE
      _mm_storeu_ps(xz, acc);
      put_sample(nx[n].trail + 4u * k, xz[0], xz[1], h, arc);
#else
      put_sample(nx[n].trail + 4u * k, x, z, h, arc);
#endif
      nx[n].trail_frames[k] = frames;
      const uint32_t te = nx[from - ws].natural;
      const uint32_t lab = te == SMGI_NONE ? SMGI_TRAIL_LABEL_WIDE
                                            : d->lower_edges[te].label;
      nx[n].trail_edge[k] = te;
      nx[n].trail_label[k] =
          (uint16_t)(lab < SMGI_TRAIL_LABEL_WIDE ? lab : SMGI_TRAIL_LABEL_WIDE);
    }
  }
}

/* ---- node_next.turn -------------------------------------------------------
 * best[t][n] = the largest cumulative heading change (in one direction)
 * reached within t frames from n, 0 included (not turning yet):
 *   best[0][n] = 0,
 *   best[t][n] = max(0, max over out-edges e of
 *                 fc(e) <= t ? dh(e) + best[t - fc(e)][to(e)]
 *                            : dh(e) * t / fc(e))
 * (an edge longer than the time left counts in proportion), for the left
 * (dh = +dheading) and right (dh = -dheading) directions; node_next.turn is
 * best[T][n]. T is 90 frames at 30 Hz and a CMU graph has ~1500 edges, so
 * the programme is ~270k edge steps: the code below computes the very same
 * float operations (max is exact and, starting from +0 and keeping the
 * larger, independent of order) in an order that keeps the CPU busy.
 *
 * Blocks: frames t0 .. t0 + 7 are computed together, node by node, the
 * node's maxima kept in registers. An edge with fc >= 8 reads only earlier
 * blocks; one with fc < 8 also reads the current block of its `to` node,
 * so nodes are visited by level (0: no short out-edge; else 1 + the
 * highest level its short edges lead to), which puts every such `to` first
 * - and far enough back that its block has left the store buffer (a read
 * overlapping a recent store of other offsets waits for it). Within a
 * level, nodes go by out-degree so the loop over a node's edges runs the
 * same count many times in a row. If short edges form a cycle there is no
 * such order and the programme runs one frame at a time (baked CMU and
 * synthetic graphs have no cycle of edges shorter than 11 frames).
 *
 * Memory: per node, one ring of the last W frames of best[], left and
 * right interleaved (frame t at 2 (t mod W), its right value next to it:
 * an edge's read of 8 frames in both directions is 64 contiguous bytes).
 * W is a power of two >= the longest edge that fits in T, plus a block
 * (32 on CMU), so the rings take ~260 KiB on a CMU graph where all T
 * frames took ~560 KiB (fewer pages to fault in on a one-shot load).
 * Positions W .. W + 7 repeat 0 .. 7 (a block written across the end is
 * written again at the start, and the other way round), so any 8
 * consecutive frames read contiguously. Each ring has TURN_SLACK frames
 * of zeros before it, which the lanes of the first blocks with t < fc
 * read before the proportional term replaces them. */
#define TURN_BLOCK 8u
#define TURN_SLACK 8u
#define TURN_DEGREE_KEYS 9u /* degrees 1..8+ sorted apart */

typedef struct turn_node {
  ptrdiff_t ring; /* float index of frame 0 in the node's ring */
  uint32_t first; /* its edges: turn_edge[first .. first + count) */
  uint32_t count;
} turn_node;

typedef struct turn_edge {
  ptrdiff_t src; /* float index of frame 0 in the `to` node's ring */
  float dh;      /* left heading change; the right values use -dh */
  uint32_t fc;
} turn_edge;

/* The geometry of the rings: W = mask + 1 and the floats per ring. */
typedef struct turn_rings {
  uint32_t mask;
  size_t len; /* 2 (TURN_SLACK + W + TURN_BLOCK + 1) (a block starting at
                 1 is repeated at W + 1), rounded up to 4 */
} turn_rings;

/* Where (in frames) a block starting at ring position p is written a
 * second time: at p + W when it covers positions 0..7 (read as W..W+7),
 * at p - W when it runs past W (those frames belong at the start); 0 when
 * neither. */
static ptrdiff_t turn_repeat(uint32_t p, uint32_t mask) {
  if (p < TURN_BLOCK) return (ptrdiff_t)mask + 1;
  if (p + TURN_BLOCK > mask + 1u) return -(ptrdiff_t)mask - 1;
  return 0;
}

#if SMGI_DERIVED_SSE
/* (dh, -dh, dh, -dh): one edge's step for a left/right pair of frames */
static inline __m128 turn_pair(float dh) {
  return _mm_xor_ps(_mm_set1_ps(dh), _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f));
}

/* full ? a : b lane by lane (full: all ones or all zeros) */
static inline __m128 turn_pick(__m128 full, __m128 a, __m128 b) {
  return _mm_or_ps(_mm_and_ps(full, a), _mm_andnot_ps(full, b));
}
#endif

/* Store a block's 2 * TURN_BLOCK results at o and, when the ring wraps
 * inside the block's reach, again `repeat` floats on (both kernels). */
#if SMGI_DERIVED_SSE
static void turn_store_sse(float* o, ptrdiff_t repeat, __m128 m0, __m128 m1,
                           __m128 m2, __m128 m3) {
  for (int k = 0; k < (repeat ? 2 : 1); ++k, o += repeat) {
    _mm_storeu_ps(o, m0);
    _mm_storeu_ps(o + 4, m1);
    _mm_storeu_ps(o + 8, m2);
    _mm_storeu_ps(o + 12, m3);
  }
}
#else
static void turn_store(float* o, ptrdiff_t repeat, const float* m) {
  for (uint32_t j = 0; j < 2u * TURN_BLOCK; ++j) {
    o[j] = m[j];
    if (repeat) o[repeat + (ptrdiff_t)j] = m[j];
  }
}
#endif

/* A block where every edge has fc <= t0: no proportional terms. */
static void turn_block(const turn_node* tn, uint32_t nodes,
                       const turn_edge* te, float* hist, turn_rings rg,
                       uint32_t t0) {
  const uint32_t p = t0 & rg.mask;
  const ptrdiff_t repeat = 2 * turn_repeat(p, rg.mask);
  for (uint32_t i = 0; i < nodes; ++i) {
    const turn_edge* e = te + tn[i].first;
    const turn_edge* end = e + tn[i].count;
    float* o = hist + tn[i].ring + 2u * p;
#if SMGI_DERIVED_SSE
    /* _mm_max_ps(v, b) is v > b ? v : b lane by lane */
    __m128 m0 = _mm_setzero_ps(), m1 = m0, m2 = m0, m3 = m0;
    for (; e != end; ++e) {
      const float* s = hist + e->src + 2u * ((t0 - e->fc) & rg.mask);
      const __m128 dh = turn_pair(e->dh);
      m0 = _mm_max_ps(_mm_add_ps(dh, _mm_loadu_ps(s)), m0);
      m1 = _mm_max_ps(_mm_add_ps(dh, _mm_loadu_ps(s + 4)), m1);
      m2 = _mm_max_ps(_mm_add_ps(dh, _mm_loadu_ps(s + 8)), m2);
      m3 = _mm_max_ps(_mm_add_ps(dh, _mm_loadu_ps(s + 12)), m3);
    }
    turn_store_sse(o, repeat, m0, m1, m2, m3);
#else
    float m[2u * TURN_BLOCK] = {0.0f};
    for (; e != end; ++e) {
      const float* s = hist + e->src + 2u * ((t0 - e->fc) & rg.mask);
      for (uint32_t j = 0; j < 2u * TURN_BLOCK; ++j) {
        const float v = ((j & 1u) ? -e->dh : e->dh) + s[j];
        m[j] = v > m[j] ? v : m[j];
      }
    }
    turn_store(o, repeat, m);
#endif
  }
}

/* A block where some edges are longer than some of its frames: lanes with
 * t < fc take the proportional term, and read the slack or older frames
 * meanwhile. Such blocks end before W (t0 < min(longest edge, T + 1) and
 * W >= both + 8), so frames here are not wrapped. */
static void turn_block_early(const turn_node* tn, uint32_t nodes,
                             const turn_edge* te, float* hist, turn_rings rg,
                             uint32_t t0) {
  const ptrdiff_t repeat = 2 * turn_repeat(t0, rg.mask);
#if SMGI_DERIVED_SSE
  const __m128 t_lo = _mm_setr_ps((float)t0, (float)(t0 + 1u),
                                  (float)(t0 + 2u), (float)(t0 + 3u));
  const __m128 t_hi = _mm_add_ps(t_lo, _mm_set1_ps(4.0f));
  const __m128 right = _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f);
#else
  float tf[TURN_BLOCK];
  for (uint32_t j = 0; j < TURN_BLOCK; ++j) tf[j] = (float)(t0 + j);
#endif
  for (uint32_t i = 0; i < nodes; ++i) {
    const turn_edge* e = te + tn[i].first;
    const turn_edge* end = e + tn[i].count;
    float* o = hist + tn[i].ring + 2u * t0;
#if SMGI_DERIVED_SSE
    __m128 m0 = _mm_setzero_ps(), m1 = m0, m2 = m0, m3 = m0;
#else
    float m[2u * TURN_BLOCK] = {0.0f};
#endif
    for (; e != end; ++e) {
      ptrdiff_t back = (ptrdiff_t)t0 - (ptrdiff_t)e->fc;
      if (back < -(ptrdiff_t)TURN_SLACK) back = -(ptrdiff_t)TURN_SLACK;
      const float* s = hist + e->src + 2 * back;
#if SMGI_DERIVED_SSE
      const __m128 dh1 = _mm_set1_ps(e->dh), dh = _mm_xor_ps(dh1, right);
      const __m128 fc = _mm_set1_ps((float)e->fc);
      /* full frames: t >= fc (exact: both below 2^24), lanes per frame */
      const __m128 f_lo = _mm_cmpge_ps(t_lo, fc);
      const __m128 f_hi = _mm_cmpge_ps(t_hi, fc);
      /* (-dh * t) / fc == -((dh * t) / fc): rounding to nearest is
       * symmetric, so the right values negate the left's */
      const __m128 p_lo = _mm_div_ps(_mm_mul_ps(dh1, t_lo), fc);
      const __m128 p_hi = _mm_div_ps(_mm_mul_ps(dh1, t_hi), fc);
      /* frame lanes -> left/right pair lanes */
      const __m128 f0 = _mm_unpacklo_ps(f_lo, f_lo);
      const __m128 f1 = _mm_unpackhi_ps(f_lo, f_lo);
      const __m128 f2 = _mm_unpacklo_ps(f_hi, f_hi);
      const __m128 f3 = _mm_unpackhi_ps(f_hi, f_hi);
      const __m128 p0 = _mm_xor_ps(_mm_unpacklo_ps(p_lo, p_lo), right);
      const __m128 p1 = _mm_xor_ps(_mm_unpackhi_ps(p_lo, p_lo), right);
      const __m128 p2 = _mm_xor_ps(_mm_unpacklo_ps(p_hi, p_hi), right);
      const __m128 p3 = _mm_xor_ps(_mm_unpackhi_ps(p_hi, p_hi), right);
      m0 = _mm_max_ps(turn_pick(f0, _mm_add_ps(dh, _mm_loadu_ps(s)), p0), m0);
      m1 = _mm_max_ps(turn_pick(f1, _mm_add_ps(dh, _mm_loadu_ps(s + 4)), p1),
                      m1);
      m2 = _mm_max_ps(turn_pick(f2, _mm_add_ps(dh, _mm_loadu_ps(s + 8)), p2),
                      m2);
      m3 = _mm_max_ps(turn_pick(f3, _mm_add_ps(dh, _mm_loadu_ps(s + 12)), p3),
                      m3);
#else
      const float fcf = (float)e->fc;
      for (uint32_t j = 0; j < TURN_BLOCK; ++j) {
        const int full = t0 + j >= e->fc;
        /* (-dh * t) / fc == -((dh * t) / fc): rounding to nearest is
         * symmetric */
        const float p = e->dh * tf[j] / fcf;
        const float v = full ? e->dh + s[2u * j] : p;
        const float w = full ? -e->dh + s[2u * j + 1u] : -p;
        m[2u * j] = v > m[2u * j] ? v : m[2u * j];
        m[2u * j + 1u] = w > m[2u * j + 1u] ? w : m[2u * j + 1u];
      }
#endif
    }
#if SMGI_DERIVED_SSE
    turn_store_sse(o, repeat, m0, m1, m2, m3);
#else
    turn_store(o, repeat, m);
#endif
  }
}

/* The frame-at-a-time programme, for graphs with a cycle of short edges. */
static void turn_frames(const turn_node* tn, uint32_t nodes,
                        const turn_edge* te, float* hist, turn_rings rg,
                        uint32_t T) {
  for (uint32_t t = 1; t <= T; ++t) {
    for (uint32_t i = 0; i < nodes; ++i) {
      float l = 0.0f, r = 0.0f;
      for (uint32_t k = 0; k < tn[i].count; ++k) {
        const turn_edge* e = &te[tn[i].first + k];
        float v, w;
        if (e->fc <= t) {
          const float* s = hist + e->src + 2u * ((t - e->fc) & rg.mask);
          v = e->dh + s[0];
          w = -e->dh + s[1];
        } else {
          v = e->dh * (float)t / (float)e->fc;
          w = -v;
        }
        l = v > l ? v : l;
        r = w > r ? w : r;
      }
      float* o = hist + tn[i].ring + 2u * (t & rg.mask);
      o[0] = l;
      o[1] = r;
    }
  }
}

/* Frames of the horizon. */
static uint32_t turn_horizon(const smgi_graph_data* d) {
  const float fps = d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0f;
  return (uint32_t)(SMGI_TURN_SECONDS * fps + 0.5f);
}

static turn_rings turn_rings_of(const smgi_graph_data* d) {
  const uint32_t T = turn_horizon(d);
  uint32_t reach = 0, W = 2u * TURN_BLOCK;
  for (uint32_t e = 0; e < d->lower_edge_count; ++e)
    if (d->lower_edges[e].frame_count > reach)
      reach = d->lower_edges[e].frame_count;
  /* edges longer than T never read best[] (lanes past T are not used) */
  if (reach > T) reach = T;
  while (W < reach + TURN_BLOCK) W <<= 1;
  turn_rings rg;
  rg.mask = W - 1u;
  rg.len = (2u * ((size_t)TURN_SLACK + W + TURN_BLOCK + 1u) + 3u) & ~(size_t)3u;
  return rg;
}

/* Scratch bytes build_turn needs (0 on overflow). */
static size_t turn_scratch_size(const smgi_graph_data* d) {
  const size_t LN = d->lower_node_count, LE = d->lower_edge_count;
  const size_t row = turn_rings_of(d).len;
  if (LN > SIZE_MAX / 128u / row) return 0;
  return sizeof(turn_edge) * LE + sizeof(turn_node) * LN +
         sizeof(uint32_t) * ((5u + TURN_DEGREE_KEYS) * (LN + 1u) + LE) +
         sizeof(float) * LN * row + 64u;
}

/* level[n] (0: no out-edge shorter than TURN_BLOCK frames, else 1 + the
 * highest level such an edge leads to) by depth-first search over a
 * compact copy of the short edges (sto[sfirst[n] .. sfirst[n + 1]), built
 * here: LN + 1 and LE entries); 0 if short edges form a cycle. `stack`
 * holds 2 LN. Returns the highest level + 1. */
static uint32_t short_edge_levels(const smgi_graph_data* d, uint32_t* level,
                                  uint32_t* stack, uint32_t* sfirst,
                                  uint32_t* sto) {
  const uint32_t LN = d->lower_node_count;
  uint32_t levels = 1, count = 0;
  for (uint32_t n = 0; n < LN; ++n) {
    const smgi_node* node = &d->lower_nodes[n];
    const smgi_edge* e = d->lower_edges + node->first_edge;
    sfirst[n] = count;
    for (uint32_t k = 0; k < node->edge_count; ++k) {
      sto[count] = e[k].to;
      count += e[k].frame_count < TURN_BLOCK;
    }
  }
  sfirst[LN] = count;
  /* level[]: 0 unseen, 1 on the DFS stack, 2 + level when done */
  for (uint32_t n = 0; n < LN; ++n)
    level[n] = sfirst[n] == sfirst[n + 1u] ? 2u : 0u; /* no short edge */
  for (uint32_t root = 0; root < LN; ++root) {
    if (level[root]) continue;
    uint32_t top = 0;
    stack[0] = root;
    stack[1] = sfirst[root];
    level[root] = 1;
    for (;;) {
      const uint32_t n = stack[2u * top];
      if (stack[2u * top + 1u] < sfirst[n + 1u]) {
        const uint32_t to = sto[stack[2u * top + 1u]++];
        if (level[to] == 1u) return 0; /* back to an open node */
        if (level[to] == 0u) {
          ++top;
          stack[2u * top] = to;
          stack[2u * top + 1u] = sfirst[to];
          level[to] = 1u;
        }
        continue;
      }
      uint32_t lv = 0;
      for (uint32_t k = sfirst[n]; k < sfirst[n + 1u]; ++k)
        if (level[sto[k]] - 1u > lv) lv = level[sto[k]] - 1u;
      level[n] = 2u + lv;
      if (lv + 1u > levels) levels = lv + 1u;
      if (top == 0) break;
      --top;
    }
  }
  for (uint32_t n = 0; n < LN; ++n) level[n] -= 2u;
  return levels;
}

static void build_turn(const smgi_graph_data* d, void* scratch,
                       smgi_node_next* nx) {
  const uint32_t LN = d->lower_node_count;
  const uint32_t T = turn_horizon(d);
  const turn_rings rg = turn_rings_of(d);
  const size_t row = rg.len;
  turn_edge* te = (turn_edge*)scratch;
  turn_node* tn = (turn_node*)(te + d->lower_edge_count);
  uint32_t* level = (uint32_t*)(tn + LN);
  uint32_t* stack = level + LN; /* 2 LN */
  uint32_t* order = stack + 2u * (size_t)LN;
  uint32_t* first = order + LN; /* TURN_DEGREE_KEYS * levels + 1 */
  uint32_t* sfirst = first + (size_t)TURN_DEGREE_KEYS * (LN + 1u) + 1u;
  uint32_t* sto = sfirst + LN + 1u; /* LE */
  float* hist = (float*)(sto + d->lower_edge_count);
  if (LN == 0) return;

  /* visiting order: by (level, degree) with a counting sort; a cycle of
   * short edges leaves everything on level 0 and sorted by degree only */
  const uint32_t levels = short_edge_levels(d, level, stack, sfirst, sto);
  const int blocks = levels != 0;
  if (!blocks) memset(level, 0, sizeof(uint32_t) * LN);
  const size_t keys = (size_t)(blocks ? levels : 1u) * TURN_DEGREE_KEYS;
  memset(first, 0, sizeof(uint32_t) * (keys + 1u));
  uint32_t max_fc = 0, nodes = 0, edges = 0;
  for (uint32_t n = 0; n < LN; ++n) {
    const uint32_t deg = d->lower_nodes[n].edge_count;
    if (deg == 0) continue;
    const uint32_t dk = deg < TURN_DEGREE_KEYS ? deg : TURN_DEGREE_KEYS;
    first[(size_t)level[n] * TURN_DEGREE_KEYS + dk]++;
  }
  for (size_t k = 0; k < keys; ++k) first[k + 1u] += first[k];
  for (uint32_t n = 0; n < LN; ++n) {
    const uint32_t deg = d->lower_nodes[n].edge_count;
    float* r = hist + (size_t)n * row;
    if (deg == 0) {
      /* never written: best[t] = 0 throughout */
      memset(r, 0, sizeof(float) * row);
      continue;
    }
    /* the slack and best[0] = 0 */
    for (uint32_t j = 0; j < 2u * (TURN_SLACK + 1u); ++j) r[j] = 0.0f;
    const uint32_t dk = deg < TURN_DEGREE_KEYS ? deg : TURN_DEGREE_KEYS;
    order[first[(size_t)level[n] * TURN_DEGREE_KEYS + dk - 1u]++] = n;
    ++nodes;
  }
  for (uint32_t i = 0; i < nodes; ++i) {
    const uint32_t n = order[i];
    const smgi_node* node = &d->lower_nodes[n];
    tn[i].ring = (ptrdiff_t)((size_t)n * row + 2u * TURN_SLACK);
    tn[i].first = edges;
    tn[i].count = node->edge_count;
    for (uint32_t k = 0; k < node->edge_count; ++k) {
      const smgi_edge* e = &d->lower_edges[node->first_edge + k];
      turn_edge* o = &te[edges++];
      o->src = (ptrdiff_t)((size_t)e->to * row + 2u * TURN_SLACK);
      o->dh = e->displacement[2];
      o->fc = e->frame_count;
      if (e->frame_count > max_fc) max_fc = e->frame_count;
    }
  }
  if (blocks) {
    for (uint32_t t0 = 1; t0 <= T; t0 += TURN_BLOCK) {
      if (t0 >= max_fc)
        turn_block(tn, nodes, te, hist, rg, t0);
      else
        turn_block_early(tn, nodes, te, hist, rg, t0);
    }
  } else {
    turn_frames(tn, nodes, te, hist, rg, T);
  }
  for (uint32_t n = 0; n < LN; ++n) {
    const float* r =
        hist + (size_t)n * row + 2u * (TURN_SLACK + (T & rg.mask));
    nx[n].turn[0] = r[0];
    nx[n].turn[1] = r[1];
  }
}

/* search_edges (graph_derived.h): LEDG's fields the search reads, the
 * `to` node's out-edge range, and for edges of 4+ frames the mid sample
 * inverse(ground(from.frame)) * ground(mid frame), composed as smgi_xf_inv
 * and smgi_xf_point would, with the node's inverse (one sincosf) computed
 * once for all its edges. */
static void build_search_edges(const smgi_graph_data* d,
                               smgi_search_edge* se) {
  for (uint32_t n = 0; n < d->lower_node_count; ++n) {
    const smgi_node* node = &d->lower_nodes[n];
    int have = 0;
    float ix = 0.0f, iz = 0.0f, ih = 0.0f, c = 1.0f, s = 0.0f;
    for (uint32_t k = 0; k < node->edge_count; ++k) {
      const uint32_t ei = node->first_edge + k;
      const smgi_edge* E = &d->lower_edges[ei];
      smgi_search_edge* o = &se[ei];
      memcpy(o->displacement, E->displacement, sizeof o->displacement);
      o->arc_length = E->arc_length;
      o->to = E->to;
      o->frame_count = E->frame_count;
      o->label = E->label;
      o->to_first_edge = d->lower_nodes[E->to].first_edge;
      o->to_edge_count = d->lower_nodes[E->to].edge_count;
      o->mid[0] = o->mid[1] = o->mid[2] = 0.0f;
      if (E->frame_count < 4u) continue;
      if (!have) {
        /* smgi_xf_inv: rotate (-x, -z) by -h, heading wrap(-h) */
        const float* g0 = d->frames[node->frame].root2d;
        const float nh = -g0[2];
        smgi_sincosf(nh, &s, &c);
        ix = c * -g0[0] + s * -g0[1];
        iz = -s * -g0[0] + c * -g0[1];
        ih = smgi_wrap_angle(nh);
        /* smgi_xf_point rotates by the wrapped heading: the same angle
         * unless -h was outside (-pi, pi] */
        if (ih != nh) smgi_sincosf(ih, &s, &c);
        have = 1;
      }
      const float* r = d->frames[E->first_frame + E->frame_count / 2u].root2d;
      o->mid[0] = ix + (c * r[0] + s * r[1]);
      o->mid[1] = iz + (-s * r[0] + c * r[1]);
      o->mid[2] = smgi_wrap_angle(ih + r[2]);
    }
  }
}

/* start_first, start_nodes (graph_derived.h) by a counting sort on the
 * label; returns the first node with out-edges (SMGI_NONE: none). */
static uint32_t build_start_nodes(const smgi_graph_data* d,
                                  uint32_t* first, uint32_t* nodes) {
  const uint32_t S = d->style_count;
  uint32_t any = SMGI_NONE;
  memset(first, 0, sizeof(uint32_t) * ((size_t)S + 1u));
  for (uint32_t n = 0; n < d->lower_node_count; ++n)
    if (d->lower_nodes[n].edge_count > 0) first[d->lower_nodes[n].label + 1u]++;
  for (uint32_t s = 0; s < S; ++s) first[s + 1u] += first[s];
  for (uint32_t n = 0; n < d->lower_node_count; ++n) {
    const smgi_node* v = &d->lower_nodes[n];
    if (v->edge_count == 0) continue;
    if (any == SMGI_NONE) any = n;
    nodes[first[v->label]++] = n; /* cursor, moved back below */
  }
  for (uint32_t s = S; s > 0; --s) first[s] = first[s - 1u];
  first[0] = 0;
  return any;
}

/* Which styles have a pose to come to rest on (graph_derived.h). */
/* Mean speed of style st's lower edges (arc length over their time),
 * m/s; 0 when it has none. */
static float style_speed(const smgi_graph_data* d, uint32_t st) {
  double arc = 0.0, frames = 0.0;
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_edge* E = &d->lower_edges[e];
    if (E->label != st) continue;
    arc += (double)E->arc_length;
    frames += (double)E->frame_count;
  }
  return frames > 0.0 ? (float)(arc * (double)d->info->frame_rate / frames)
                      : 0.0f;
}

/* A style faster than the walk-run transition (SMGI_STOP_FROUDE of the
 * skeleton's leg length) does not stop in one step, whatever its contact
 * labels say (a few frames of a run may carry both): a runner slows to a
 * walk over its last metres first (planner.c). The style it slows to is
 * the fastest one left that can stop (the least change of speed: a
 * normal walk before an exhausted one); SMGI_NONE when none can. */
static void build_stop_style(const smgi_graph_data* d, uint8_t* can_stop,
                             uint32_t* stop_style, float* stop_speed) {
  const float fast2 =
      SMGI_STOP_FROUDE * SMGI_GRAVITY * d->info->leg_length;
  *stop_style = SMGI_NONE;
  *stop_speed = 0.0f;
  for (uint32_t st = 0; st < d->style_count; ++st) {
    const float v = style_speed(d, st);
    if (v * v > fast2) can_stop[st] = 0;
    if (can_stop[st] && (*stop_style == SMGI_NONE || v > *stop_speed)) {
      *stop_style = st;
      *stop_speed = v;
    }
  }
}

static void build_can_stop(const smgi_graph_data* d, uint8_t* can_stop) {
  const uint32_t both = SMGI_FRAME_LEFT_CONTACT | SMGI_FRAME_RIGHT_CONTACT;
  memset(can_stop, 0, d->style_count);
  for (uint32_t e = 0; e < d->lower_edge_count; ++e) {
    const smgi_edge* E = &d->lower_edges[e];
    if (E->label >= d->style_count || can_stop[E->label]) continue;
    uint32_t prev = 0;
    for (uint32_t k = 0; k < E->frame_count; ++k) {
      const uint32_t fl = d->frames[E->first_frame + k].flags & both;
      if (fl == both || (k > 0 && fl != 0 && prev != 0 && fl != prev)) {
        can_stop[E->label] = 1;
        break;
      }
      prev = fl;
    }
  }
}

/* The stopping and starting motion of the data (stopping.h) and each
 * stop's remaining travel, frame by frame, in one block of their own
 * (none when the data has none). */
static smg_result build_stops(smg_graph* g, smgi_derived* dv) {
  const smgi_graph_data* d = &g->data;
  const float fps = d->info->frame_rate, leg = d->info->leg_length;
  const uint32_t n = smgi_stopping_find(d->frames, d->frame_count, d->clips,
                                        d->clip_count, fps, leg, NULL, 0);
  if (n == 0) return SMG_OK;
  /* the segments first, then their travel tables (bounded by the pool:
   * a stop lies within its clip) */
  smgi_stop_seg* segs = (smgi_stop_seg*)smgi_alloc(
      &g->allocator, sizeof(smgi_stop_seg) * (size_t)n, 16);
  if (!segs) return SMG_ERROR_OUT_OF_MEMORY;
  smgi_stopping_find(d->frames, d->frame_count, d->clips, d->clip_count, fps,
                     leg, segs, n);
  size_t left = 0;
  for (uint32_t k = 0; k < n; ++k)
    if (segs[k].kind == SMGI_STOP_KIND_STOP)
      left += (size_t)(segs[k].rest - segs[k].first) + 1u;
  const size_t off_first = align16(sizeof(smgi_stop_seg) * (size_t)n);
  const size_t off_entry = off_first + align16(sizeof(uint32_t) * (size_t)n);
  const size_t off_left = off_entry + align16(sizeof(uint32_t) * (size_t)n);
  uint8_t* mem = (uint8_t*)smgi_alloc(
      &g->allocator, off_left + sizeof(float) * (left + 1u), 16);
  if (!mem) {
    smgi_free(&g->allocator, segs);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  memcpy(mem, segs, sizeof(smgi_stop_seg) * (size_t)n);
  smgi_free(&g->allocator, segs);
  const smgi_stop_seg* s = (const smgi_stop_seg*)mem;
  uint32_t* first = (uint32_t*)(mem + off_first);
  float* table = (float*)(mem + off_left);
  uint32_t at = 0;
  dv->start_count = 0;
  dv->stop_longest = 0.0f;
  for (uint32_t k = 0; k < n; ++k) {
    first[k] = at;
    if (s[k].kind != SMGI_STOP_KIND_STOP) {
      dv->start_count++;
      continue;
    }
    /* from the rest backwards: each frame's travel is the next one's
     * plus the step between them */
    float t = 0.0f;
    const uint32_t len = s[k].rest - s[k].first;
    table[at + len] = 0.0f;
    for (uint32_t i = len; i > 0; --i) {
      t += smgi_stopping_travel(d->frames, s[k].first + i - 1u,
                                s[k].first + i);
      table[at + i - 1u] = t;
    }
    at += len + 1u;
    if (s[k].travel > dv->stop_longest) dv->stop_longest = s[k].travel;
  }
  /* each start's last standing node: nodes by frame against the
   * segments (in order of their first frames) */
  uint32_t* entry = (uint32_t*)(mem + off_entry);
  for (uint32_t k = 0; k < n; ++k) entry[k] = SMGI_NONE;
  for (uint32_t v = 0; v < d->lower_node_count; ++v) {
    const uint32_t f = d->lower_nodes[v].frame;
    if (d->lower_nodes[v].edge_count == 0) continue;
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
      const uint32_t mid = lo + (hi - lo) / 2u;
      if (s[mid].first <= f) lo = mid + 1u;
      else hi = mid;
    }
    for (uint32_t k = lo; k > 0 && lo - k < 4u; --k) {
      const smgi_stop_seg* q = &s[k - 1u];
      if (q->kind != SMGI_STOP_KIND_START || f > q->rest) continue;
      if (entry[k - 1u] == SMGI_NONE ||
          d->lower_nodes[entry[k - 1u]].frame < f)
        entry[k - 1u] = v;
    }
  }
  dv->start_entry = entry;
  dv->stops = s;
  dv->stop_count = n;
  dv->stop_left = table;
  dv->stop_left_first = first;
  dv->stop_block = mem;
  return SMG_OK;
}

smg_result smgi_graph_derived_build(smg_graph* g) {
  if (!g) return SMG_ERROR_INVALID_ARGUMENT;
  const smgi_graph_data* d = &g->data;
  const uint32_t F = d->frame_count;
  const uint32_t S = d->style_count, A = d->action_count;
  const uint32_t LN = d->lower_node_count, UN = d->upper_node_count;

  /* node_next first: 64-byte aligned records at the tables' start */
  size_t off_nx = 0;
  size_t off_lh = off_nx + sizeof(smgi_node_next) * (size_t)LN;
  size_t off_et = off_lh + align16((size_t)LN * S);
  size_t off_uh = off_et + align16((size_t)d->lower_edge_count * 2u * S);
  size_t off_sf = off_uh + align16((size_t)UN * A);
  size_t off_af = off_sf + align16(sizeof(uint32_t) * ((size_t)F + 1u));
  size_t off_se = off_af + align16(sizeof(uint32_t) * (size_t)A);
  size_t off_sn = off_se + align16(sizeof(smgi_search_edge) *
                                   (size_t)d->lower_edge_count);
  size_t off_sfs = off_sn + align16(sizeof(uint32_t) * (size_t)LN);
  size_t off_cs = off_sfs + align16(sizeof(uint32_t) * ((size_t)S + 1u));
  size_t off_th = off_cs + align16((size_t)S);
  size_t total = off_th + align16(sizeof(float) * (size_t)S);
  size_t block = align16(sizeof(smgi_derived));

  /* One scratch block for the phases below, sized for the largest. */
  uint32_t maxn = LN > UN ? LN : UN;
  uint32_t maxe = d->lower_edge_count > d->upper_edge_count
                      ? d->lower_edge_count
                      : d->upper_edge_count;
  size_t scratch_size =
      sizeof(uint32_t) * (2u * (size_t)maxn + 2u + maxe) + maxn;
  size_t walk_size = sizeof(walk_step) * (size_t)LN;
  size_t turn_size = turn_scratch_size(d);
  if (turn_size == 0) return SMG_ERROR_OUT_OF_MEMORY;
  /* edge_style_time: reverse adjacency with frame counts, dist, the
   * buckets' links and heads, each distance's value */
  const uint32_t time_limit = style_time_limit(
      d->info->frame_rate > 0.0f ? d->info->frame_rate : 30.0);
  size_t time_size =
      sizeof(uint32_t) * (4u * (size_t)LN + 1u +
                          2u * (size_t)d->lower_edge_count + time_limit) +
      time_limit;
  if (time_size > scratch_size) scratch_size = time_size;
  if (walk_size > scratch_size) scratch_size = walk_size;
  if (turn_size > scratch_size) scratch_size = turn_size;

  /* 16-byte aligned like every other block the runtime asks for (the
   * hooks' common case); the tables start at the next multiple of 64 */
  uint8_t* mem = (uint8_t*)smgi_alloc(&g->allocator, block + total + 48u, 16);
  if (!mem) return SMG_ERROR_OUT_OF_MEMORY;
  void* scratch = smgi_alloc(&g->allocator, scratch_size, 16);
  if (!scratch) {
    smgi_free(&g->allocator, mem);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  /* Every table below is written in full; only the struct and the splice
   * counts start from zero (a memset of the whole block cost ~10 us). */
  memset(mem, 0, block);
  smgi_derived* dv = (smgi_derived*)mem;
  uint8_t* base =
      mem + block + ((64u - ((uintptr_t)(mem + block) & 63u)) & 63u);
  uint8_t* lower_hops = base + off_lh;
  uint8_t* edge_style_time = base + off_et;
  uint8_t* upper_hops = base + off_uh;
  uint32_t* splice_first = (uint32_t*)(base + off_sf);
  uint32_t* action_first = (uint32_t*)(base + off_af);
  smgi_node_next* nx = (smgi_node_next*)(base + off_nx);
  smgi_search_edge* search_edges = (smgi_search_edge*)(base + off_se);
  uint8_t* can_stop = base + off_cs;
  float* time_hop = (float*)(base + off_th);
  uint32_t* start_nodes = (uint32_t*)(base + off_sn);
  uint32_t* start_first = (uint32_t*)(base + off_sfs);

  build_search_edges(d, search_edges);
  dv->first_start = build_start_nodes(d, start_first, start_nodes);
  build_can_stop(d, can_stop);
  build_stop_style(d, can_stop, &dv->stop_style, &dv->stop_speed);

  /* BFS scratch: reverse adjacency of either graph and the queue. */
  uint32_t* in_first = (uint32_t*)scratch;
  uint32_t* in_from = in_first + maxn + 1u;
  uint32_t* queue = in_from + maxe;
  uint8_t* col = (uint8_t*)(queue + maxn + 1u);
  build_reverse(d->lower_edges, d->lower_edge_count, LN, in_first, in_from);
  compute_hops(d->lower_nodes, LN, d->lower_edges, S, in_first, in_from,
               queue, col, lower_hops);
  {
    uint32_t* rev_from = in_first + LN + 1u;
    uint32_t* rev_frames = rev_from + d->lower_edge_count;
    uint32_t* dist = rev_frames + d->lower_edge_count;
    build_reverse_frames(d->lower_edges, d->lower_edge_count, LN, in_first,
                         rev_from, rev_frames);
    build_edge_style_time(
        d, lower_hops, time_limit, in_first, rev_from, rev_frames, dist,
        dist + LN, dist + 2u * (size_t)LN, dist + 3u * (size_t)LN,
        (uint8_t*)(dist + 3u * (size_t)LN + time_limit), edge_style_time,
        time_hop);
    dv->style_time_hop = time_hop;
  }
  build_reverse(d->upper_edges, d->upper_edge_count, UN, in_first, in_from);
  compute_hops(d->upper_nodes, UN, d->upper_edges, A, in_first, in_from,
               queue, col, upper_hops);

  /* Splice index: SPLC is sorted by lower_frame (validated), so a counting
   * pass gives the CSR offsets. */
  memset(splice_first, 0, sizeof(uint32_t) * ((size_t)F + 1u));
  for (uint32_t i = 0; i < d->splice_count; ++i) {
    uint32_t f = d->splices[i].lower_frame;
    if (f < F) splice_first[f + 1u]++;
  }
  for (uint32_t f = 0; f < F; ++f) splice_first[f + 1u] += splice_first[f];

  for (uint32_t a = 0; a < A; ++a) action_first[a] = SMGI_NONE;
  for (uint32_t e = d->upper_edge_count; e > 0; --e) {
    uint32_t l = d->upper_edges[e - 1u].label;
    if (l < A) action_first[l] = e - 1u;
  }

  find_natural(d, nx);
  build_walks(d, nx, (walk_step*)scratch);
  build_turn(d, scratch, nx);
  smgi_free(&g->allocator, scratch);

  dv->search_edges = search_edges;
  dv->start_first = start_first;
  dv->start_nodes = start_nodes;
  dv->node_next = nx;

  dv->lower_hops = lower_hops;
  dv->edge_style_time = edge_style_time;
  dv->upper_hops = upper_hops;
  dv->splice_first = splice_first;
  dv->action_first_edge = action_first;
  /* most agile style: heading change per metre travelled (curvature) of
   * the natural continuations - what decides how tightly it can turn back
   * to a path. The turn is summed over the trail's samples so that a
   * continuation turning more than half a circle counts in full. */
  {
    float best = -1.0f;
    dv->agile_style = 0;
    for (uint32_t st = 0; st < S; ++st) {
      double turn = 0.0, arc = 0.0;
      for (uint32_t n = 0; n < LN; ++n) {
        if (d->lower_nodes[n].label != st) continue;
        const float* tr = nx[n].trail;
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
        dv->agile_style = st;
      }
    }
  }
  dv->style_can_stop = can_stop;
  smgi_idle_choose(g, &dv->idle);
  const size_t calm = smgi_idle_calm_floats(g, &dv->idle);
  if (calm != 0u) {
    dv->idle.calm =
        (float*)smgi_alloc(&g->allocator, sizeof(float) * calm, 16);
    if (!dv->idle.calm) {
      smgi_free(&g->allocator, mem);
      return SMG_ERROR_OUT_OF_MEMORY;
    }
    smgi_idle_calm_build(g, &dv->idle, dv->idle.calm);
    dv->idle.calm_joints = smgi_idle_trunk_count(g);
  }
  smg_result r = build_stops(g, dv);
  if (r != SMG_OK) {
    if (dv->idle.calm) smgi_free(&g->allocator, dv->idle.calm);
    smgi_free(&g->allocator, mem);
    return r;
  }
  g->derived = dv;
  return SMG_OK;
}

void smgi_graph_derived_free(smg_graph* g) {
  if (!g || !g->derived) return;
  smgi_derived* dv = (smgi_derived*)g->derived;
  if (dv->stop_block) smgi_free(&g->allocator, dv->stop_block);
  if (dv->idle.calm) smgi_free(&g->allocator, dv->idle.calm);
  smgi_free(&g->allocator, g->derived);
  g->derived = NULL;
}
