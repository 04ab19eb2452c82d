/*
 * bake_graph_build.c - motion-graph construction (Kovar et al. 2002) for
 * one body half.
 *
 *   lower graph: clips with role LOWER; point cloud = world positions of the
 *     lower-body joints (root + legs); style = clip label.
 *   upper graph: clips with role UPPER; point cloud = upper-body segment
 *     COGs in the root's ground frame, weighted by mass (bake_upper.c);
 *     transitions only between frames of the same action (actions connect
 *     through splicing, not through edges), and only where the two frames'
 *     gait phases agree (phase_agrees), unless that leaves an action
 *     without a cycle.
 *
 * Every local minimum of the window distance grid is a candidate (minus
 * near-diagonal pairs and pairs that cannot lie on a cycle). Same-label
 * candidates are ranked per (source clip, target clip) pair and capped at
 * their label pair's median; label changes (walk <-> run) are chosen
 * afterwards among candidates joining the labels' strongly connected cores;
 * then redundant ones are thinned out (select_candidates explains why).
 * A transition from (A, i) to (B, j) blends A_i..A_i+k-1 with the aligned
 * B_j..B_j+k-1 and arrives at B_j+k. Nodes are the frames where
 * transitions leave or arrive; original motion between consecutive nodes
 * of a clip becomes an edge.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_coverage.h"
#include "bake_graph_build.h"
#include "bake_pointcloud.h"
#include "bake_scc.h"
#include "bake_upper.h"
#include "bake_math.h"
#include "bake_pair_search.h"

/* ---- building ------------------------------------------------------------- */

typedef struct build_ctx {
  smgb_bake* b;
  uint32_t role;
  uint32_t* map;      /* cloud frame -> pool frame */
  uint32_t* clip_of;  /* cloud frame -> pool clip */
  const uint8_t* mark; /* set while searching label changes (mark_cores) */
} build_ctx;

static int pair_filter(uint32_t i, uint32_t j, void* user) {
  const build_ctx* c = user;
  const smgb_bake* b = c->b;
  uint32_t ci = c->clip_of[i], cj = c->clip_of[j];
  uint32_t k = b->opt.window;
  /* A transition can only lie on a cycle if something arrives at or before
   * its start (arrivals are >= k frames into a clip) and something departs
   * at or after its arrival (departures need k + 1 frames of clip left):
   * others would be pruned anyway, and keeping them would crowd out useful
   * ones in the thinning below. */
  if (c->map[i] - b->clips[ci].first < k) return 0;
  if (c->map[j] - b->clips[cj].first + 2u * k + 1u > b->clips[cj].count)
    return 0;
  if (ci == cj) {
    uint32_t d = i > j ? i - j : j - i;
    if (d < 2u * k) return 0; /* near the diagonal: same motion */
  }
  if (c->role == SMGI_CLIP_UPPER && b->clips[ci].label != b->clips[cj].label)
    return 0;
  if (c->mark) {
    /* a label change from one style's core into another's */
    uint32_t li = b->clips[ci].label, lj = b->clips[cj].label;
    return li != lj && c->mark[c->map[i]] == li + 1 &&
           c->mark[c->map[j] + k] == lj + 1;
  }
  return 1;
}

/* Upper graph: does a transition from pool frame pa into pool frame pb
 * keep the gait phase (FRMI, bake_contacts.c)? An action recorded while
 * walking is tied to the steps: a dribbler's arm repeats on either foot,
 * so the upper-body poses of a left and a right step look alike and the
 * distance grid offers transitions half a stride apart. Played, such a
 * transition jumps the upper body's gait phase by about half a cycle,
 * which synchronization then has to make up over a second or more, and a
 * jump past half a cycle is made up the wrong way round, as a whole
 * stride slipped against the legs.
 *
 * Tolerance: the blended frames' phase moves from one side's to the
 * other's with the blend (bake_transition.c), so a phase difference d
 * turns a window that spans w cycles of gait into w + d cycles, and the
 * rate that keeps the upper body in step over the window is w / (w + d).
 * |d| <= w / 2 keeps that rate within [2/3, 2], inside the rate range
 * synchronization allows: a jump it can absorb within the blend itself.
 * w is the window's length (k frames) at the slower side's phase speed,
 * so the tolerance follows each clip's own gait and the bake's window.
 * The phases are compared where the window starts and where it ends.
 * Frames without a phase (an action in place) agree with everything. */
static int phase_agrees(const smgb_bake* b, uint32_t pa, uint32_t pb) {
  uint32_t k = b->opt.window;
  float a0 = b->frames[pa].phase, a1 = b->frames[pa + k].phase;
  float b0 = b->frames[pb].phase, b1 = b->frames[pb + k].phase;
  float wa, wb, d0, d1, tol;
  if (a0 < 0.0f || a1 < 0.0f || b0 < 0.0f || b1 < 0.0f) return 1;
  wa = a1 - a0;
  wb = b1 - b0;
  wa -= floorf(wa); /* cycles the window spans, [0, 1) */
  wb -= floorf(wb);
  d0 = a0 - b0;
  d1 = a1 - b1;
  d0 -= floorf(d0 + 0.5f); /* (-0.5, 0.5] */
  d1 -= floorf(d1 + 0.5f);
  tol = 0.5f * (wa < wb ? wa : wb);
  return fabsf(d0) <= tol && fabsf(d1) <= tol;
}

typedef struct cand {
  smgb_minimum m;
  uint32_t admissible; /* 0: the upper graph's phase rule rejects it */
  uint32_t li, lj;    /* labels */
  uint32_t ci, cj;    /* clips */
  uint32_t region;    /* source region: (clip, local frame / span) */
  uint32_t target;    /* thinning group: target clip and its mirror */
  float best;         /* label changes: best cost of the source region
                         into the same target label (select_candidates) */
} cand;

/* Start cells per source window for the minimum search
 * (bake_pair_search.h): its nearest windows in pose-feature space. */
#define SMGB_TRANSITION_NEIGHBOURS 32u
/* ... and into each other style: style changes are few and only need to
 * be available (select_candidates keeps the best per source region). */
#define SMGB_STYLE_CHANGE_NEIGHBOURS 8u

/* Same-label transitions kept per source region (select_candidates). */
#define SMGB_REGION_TRANSITIONS 3u

/* Relative tolerance of the per-label-pair median ceiling (see
 * select_candidates): costs within 5 % of the median count as equal. */
#define MEDIAN_TOLERANCE 0.05f

static int region_cmp(const void* pa, const void* pb) {
  const cand* a = pa;
  const cand* b = pb;
  if (a->region != b->region) return a->region < b->region ? -1 : 1;
  if (a->target != b->target) return a->target < b->target ? -1 : 1;
  if (a->m.dist != b->m.dist) return a->m.dist < b->m.dist ? -1 : 1;
  if (a->m.i != b->m.i) return a->m.i < b->m.i ? -1 : 1;
  if (a->m.j != b->m.j) return a->m.j < b->m.j ? -1 : 1;
  return 0;
}

/* The ceilings of same-label transitions (sampled_ceilings). */
typedef struct pair_cut {
  uint32_t ca, cb;             /* source clip, target clip */
  float cut;
} pair_cut;

typedef struct ceilings {
  float* median;               /* [l * L + l]: the label's median minimum */
  float* cut;                  /* [l]: its transition_percentile-th minimum */
  pair_cut* pairs;             /* sampled clip pairs' own percentile cuts,
                                  sorted by (ca, cb) */
  uint32_t pair_count;
} ceilings;

/* The cost a same-label candidate from clip ca into clip cb may have. */
static float ceiling_of(const ceilings* c, uint32_t L, uint32_t l,
                        uint32_t ca, uint32_t cb) {
  uint32_t lo = 0, hi = c->pair_count;
  float pct = l < L ? c->cut[l] : INFINITY, med;
  while (lo < hi) {
    uint32_t mid = (lo + hi) / 2;
    const pair_cut* q = &c->pairs[mid];
    if (q->ca < ca || (q->ca == ca && q->cb < cb))
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo < c->pair_count && c->pairs[lo].ca == ca && c->pairs[lo].cb == cb)
    pct = c->pairs[lo].cut;
  med = l < L ? c->median[l * L + l] : INFINITY;
  return pct < med ? pct : med;
}

static int region_cost_cmp(const void* pa, const void* pb) {
  const cand* a = pa;
  const cand* b = pb;
  if (a->region != b->region) return a->region < b->region ? -1 : 1;
  if (a->m.dist != b->m.dist) return a->m.dist < b->m.dist ? -1 : 1;
  if (a->m.i != b->m.i) return a->m.i < b->m.i ? -1 : 1;
  if (a->m.j != b->m.j) return a->m.j < b->m.j ? -1 : 1;
  return 0;
}

static int cand_cmp(const void* pa, const void* pb) {
  const cand* a = pa;
  const cand* b = pb;
  if (a->li != b->li) return a->li < b->li ? -1 : 1;
  if (a->lj != b->lj) return a->lj < b->lj ? -1 : 1;
  if (a->m.dist != b->m.dist) return a->m.dist < b->m.dist ? -1 : 1;
  if (a->m.i != b->m.i) return a->m.i < b->m.i ? -1 : 1;
  if (a->m.j != b->m.j) return a->m.j < b->m.j ? -1 : 1;
  return 0;
}

static int clip_cmp(const void* pa, const void* pb) {
  const cand* a = pa;
  const cand* b = pb;
  if (a->ci != b->ci) return a->ci < b->ci ? -1 : 1;
  if (a->cj != b->cj) return a->cj < b->cj ? -1 : 1;
  return cand_cmp(pa, pb);
}

static int float_cmp(const void* pa, const void* pb) {
  float a = *(const float*)pa, b = *(const float*)pb;
  return a < b ? -1 : a > b ? 1 : 0;
}

static int u32_cmp(const void* pa, const void* pb) {
  uint32_t a = *(const uint32_t*)pa, b = *(const uint32_t*)pb;
  return a < b ? -1 : a > b ? 1 : 0;
}

static uint32_t find_node(const smgb_graph* g, uint32_t frame) {
  uint32_t lo = 0, hi = g->node_count;
  while (lo < hi) {
    uint32_t mid = (lo + hi) / 2;
    if (g->nodes[mid].frame < frame)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < g->node_count && g->nodes[lo].frame == frame ? lo : SMGI_NONE;
}

/* Choose transitions among local minima.
 *
 * Same-label candidates (by_clip = 1) are the local minima reached from
 * each window's nearest matches (bake_pair_search.h), which already ranks
 * them per source window the way a percentile per clip pair did over the
 * whole grid: near-identical clips (a clip and its own periodic repeats,
 * mirrored twins) cannot take every place, because each target clip keeps
 * at most one per source region below. They are kept when no worse than
 * `ceiling` for their (label, label) pair (sampled_ceilings) and the
 * absolute transition_threshold when set.
 * Label changes (by_clip = 0): the percentile is taken per label pair.
 *
 * Then thinning: periodic motion has a local minimum against every cycle
 * of every similar clip, so per source region (see cand.region) and target
 * clip (label, for label changes) only the best candidate is kept.
 * Returns the new count. */
static uint32_t select_candidates(const smgb_bake* b, cand* cands, uint32_t n,
                                  int by_clip, const ceilings* ceiling) {
  uint32_t i, kept = 0, t, nk = 0;
  uint32_t L = b->style_count > b->action_count ? b->style_count
                                                : b->action_count;
  float* median = NULL; /* exact mode: per label pair, from all minima */
  if (n == 0) return 0;
  if (by_clip && !ceiling) {
    median = malloc((size_t)L * L * sizeof *median);
    if (median) {
      for (i = 0; i < L * L; ++i) median[i] = INFINITY;
      qsort(cands, n, sizeof *cands, cand_cmp);
      for (i = 0; i < n;) {
        uint32_t e = i;
        while (e < n && cands[e].li == cands[i].li &&
               cands[e].lj == cands[i].lj)
          ++e;
        if (cands[i].li < L && cands[i].lj < L) {
          float med = cands[i + (e - i - 1) / 2].m.dist *
                      (1.0f + MEDIAN_TOLERANCE);
          median[cands[i].li * L + cands[i].lj] = med;
        }
        i = e;
      }
    }
  }
  qsort(cands, n, sizeof *cands, by_clip ? clip_cmp : cand_cmp);
  for (i = 0; i < n;) {
    uint32_t e = i, keep, taken;
    float cap = INFINITY;
    while (e < n && cands[e].li == cands[i].li &&
           cands[e].lj == cands[i].lj &&
           (!by_clip || (cands[e].ci == cands[i].ci &&
                         cands[e].cj == cands[i].cj)))
      ++e;
    /* Same-label pairs: the ceiling of their clip pair decides (the
     * search found the good minima; sampled_ceilings knows the rest).
     * Label changes: the percentile per label pair. */
    keep = by_clip && ceiling
               ? e - i
               : (uint32_t)ceil((e - i) *
                                (double)b->opt.transition_percentile / 100.0);
    if (keep < 1) keep = 1;
    if (keep > e - i) keep = e - i;
    if (by_clip && ceiling)
      cap = ceiling_of(ceiling, L, cands[i].li, cands[i].ci, cands[i].cj);
    if (by_clip && !ceiling) {
      /* exact mode: every minimum of the pair is here; ties at the cut
       * are kept (same tolerance as the median) */
      float cut = cands[i + keep - 1].m.dist * (1.0f + MEDIAN_TOLERANCE);
      while (i + keep < e && cands[i + keep].m.dist <= cut) ++keep;
      if (median && cands[i].li < L && cands[i].lj < L)
        cap = median[cands[i].li * L + cands[i].lj];
    }
    if (b->opt.transition_threshold > 0.0f && b->opt.transition_threshold < cap)
      cap = b->opt.transition_threshold;
    /* Candidates the phase rule rejects still count above (the median
     * and the share kept are those of the whole grid, so the rule does
     * not thin the graph out further), but are not taken: their places go
     * to the next admissible ones under the same ceiling. */
    for (t = i, taken = 0; taken < keep && t < e; ++t) {
      if (!cands[t].admissible) continue;
      /* label changes always keep their best candidate */
      if (cands[t].m.dist > cap && (by_clip || taken > 0)) break;
      cands[kept++] = cands[t];
      ++taken;
    }
    i = e;
  }
  free(median);
  qsort(cands, kept, sizeof *cands, region_cmp);
  for (t = 0; t < kept; ++t) {
    if (nk > 0 && cands[nk - 1].region == cands[t].region &&
        cands[nk - 1].target == cands[t].target)
      continue;
    cands[nk++] = cands[t];
  }
  if (by_clip && ceiling && nk > 0) {
    /* and (search mode) per source region only the best SMGB_REGION_TRANSITIONS target
     * clips: with hundreds of similar clips every region has a good
     * match in each of them, and one per clip made the graph (and the
     * blend frames of its transitions) grow with clips x frames */
    uint32_t out = 0, run = 0;
    qsort(cands, nk, sizeof *cands, region_cost_cmp);
    for (t = 0; t < nk; ++t) {
      run = t > 0 && cands[t].region == cands[t - 1].region ? run + 1 : 0;
      if (run < SMGB_REGION_TRANSITIONS) cands[out++] = cands[t];
    }
    nk = out;
  }
  if (!by_clip) {
    /* Label changes are few and costly: per source region keep only the
     * target clips whose best candidate ties (within MEDIAN_TOLERANCE)
     * with the region's best into the same label. A strict "best per
     * target label" let float noise pick one target among equals: the
     * synthetic straight walk then only ever entered the turning runs. */
    uint32_t r0 = 0, out = 0;
    while (r0 < nk) {
      uint32_t r1 = r0, u, v;
      while (r1 < nk && cands[r1].region == cands[r0].region) ++r1;
      /* compacting in place: a candidate's group starts at or after
       * `out`, so the group is read (best per label) before any write */
      for (u = r0; u < r1; ++u) {
        float best = cands[u].m.dist;
        for (v = r0; v < r1; ++v)
          if (cands[v].lj == cands[u].lj && cands[v].m.dist < best)
            best = cands[v].m.dist;
        cands[u].best = best;
      }
      for (u = r0; u < r1; ++u)
        if (cands[u].m.dist <= cands[u].best * (1.0f + MEDIAN_TOLERANCE))
          cands[out++] = cands[u];
      r0 = r1;
    }
    nk = out;
  }
  return nk;
}

/* Below this many grid cells (frames squared) a graph is built from the
 * full distance grid, exact and quicker than the search at that size
 * (the paper-size CMU set: 6M cells, 0.1 s); above it the search
 * (bake_pair_search.h) keeps the cost near-linear. */
#define SMGB_EXACT_GRID_CELLS 50000000ull

/* Clip pairs per label whose full grids give the median (below). */
#define SMGB_CEILING_SAMPLE_PAIRS 64u
/* The ceiling is never below 1 mm RMS, far below capture noise: a
 * perfectly periodic clip (synthetic motion) has a median of 0, and its
 * exact repeats differ from 0 only by rounding. */
#define SMGB_CEILING_FLOOR 0.001f

typedef struct sub_filter {
  const build_ctx* ctx;
  uint32_t row0, col0;         /* cloud index of the sub-clouds' frame 0 */
} sub_filter;

static int sub_pair_filter(uint32_t i, uint32_t j, void* user) {
  const sub_filter* f = user;
  return pair_filter(f->row0 + i, f->col0 + j, (void*)f->ctx);
}

/* The cost below which the best `pct` % of sorted minima d[0..n) lie,
 * widened by MEDIAN_TOLERANCE: periodic clips give dozens of minima of one
 * and the same cost, and a strict cut through such a plateau lets float
 * noise pick the few that survive. */
static float share_cut(const float* d, uint32_t n, double pct) {
  uint32_t keep = (uint32_t)ceil(n * pct / 100.0);
  if (keep < 1) keep = 1;
  if (keep > n) keep = n;
  return d[keep - 1] * (1.0f + MEDIAN_TOLERANCE);
}

static int pair_cut_cmp(const void* pa, const void* pb) {
  const pair_cut* a = pa;
  const pair_cut* b = pb;
  if (a->ca != b->ca) return a->ca < b->ca ? -1 : 1;
  return a->cb < b->cb ? -1 : a->cb > b->cb ? 1 : 0;
}

/* Kovar's threshold for same-label transitions, relative to the data: a
 * candidate from clip A into clip B is kept if it is among the best
 * transition_percentile % of the local minima of (A, B) and no worse than
 * the median minimum of the label (ranking per clip pair: near-identical
 * clips, periodic repeats and mirrored twins, have minima near 0 that
 * would otherwise set the bar for all and leave, say, straight and
 * turning walks unconnected). The search only finds good minima, so these
 * statistics cannot come from its output: they come from the exact full
 * grids (bake_pointcloud.c) of up to SMGB_CEILING_SAMPLE_PAIRS clip pairs
 * per label, evenly spread over all its pairs. A sampled pair gets its own
 * cut; the others the label's cut over all sampled minima. In small sets
 * (CMU's) every pair is sampled and the rule is exactly the full grid's. */
static smg_result sampled_ceilings(smgb_bake* b, const build_ctx* ctx,
                                   const smgb_cloud* cloud,
                                   const uint32_t* clip_start, ceilings* out,
                                   uint32_t L) {
  uint32_t l, c, i;
  uint32_t* members = malloc((b->clip_count ? b->clip_count : 1) *
                             sizeof *members);
  float* d = NULL;
  uint32_t nd = 0, dcap = 0, pcap = 0;
  double pct = b->opt.transition_percentile;
  smg_result r = SMG_OK;
  if (!members) return SMG_ERROR_OUT_OF_MEMORY;
  for (i = 0; i < L * L; ++i) out->median[i] = INFINITY;
  for (i = 0; i < L; ++i) out->cut[i] = INFINITY;
  out->pair_count = 0;
  for (l = 0; l < L && r == SMG_OK; ++l) {
    uint32_t n = 0;
    uint64_t pairs, step, p;
    for (c = 0; c < b->clip_count; ++c)
      if (clip_start[c] != SMGI_NONE && b->clips[c].label == l)
        members[n++] = c;
    if (n == 0) continue;
    pairs = (uint64_t)n * n;
    step = (pairs + SMGB_CEILING_SAMPLE_PAIRS - 1u) / SMGB_CEILING_SAMPLE_PAIRS;
    nd = 0;
    for (p = 0; p < pairs && r == SMG_OK; p += step) {
      uint32_t ca = members[p / n], cb = members[p % n];
      smgb_cloud A = *cloud, B = *cloud;
      smgb_grid_job job;
      sub_filter sf;
      smgb_minimum* mins = NULL;
      uint32_t nm = 0, u;
      size_t stride = (size_t)cloud->points * 3u;
      A.frames = b->clips[ca].count;
      A.xyz = cloud->xyz + clip_start[ca] * stride;
      A.valid = cloud->valid + clip_start[ca];
      B.frames = b->clips[cb].count;
      B.xyz = cloud->xyz + clip_start[cb] * stride;
      B.valid = cloud->valid + clip_start[cb];
      sf.ctx = ctx;
      sf.row0 = clip_start[ca];
      sf.col0 = clip_start[cb];
      memset(&job, 0, sizeof job);
      job.rows = &A;
      job.cols = &B;
      job.window = b->opt.window;
      job.align = 1;
      job.filter = sub_pair_filter;
      job.filter_user = &sf;
      job.threads = 1;
      r = smgb_grid_minima(&job, &mins, &nm);
      if (r == SMG_OK && nd + nm > dcap) {
        uint32_t cap = (nd + nm) * 2u;
        float* nd2 = realloc(d, cap * sizeof *d);
        if (!nd2)
          r = SMG_ERROR_OUT_OF_MEMORY;
        else {
          d = nd2;
          dcap = cap;
        }
      }
      if (r == SMG_OK && out->pair_count == pcap) {
        uint32_t cap = pcap ? pcap * 2u : 64u;
        pair_cut* np = realloc(out->pairs, cap * sizeof *np);
        if (!np)
          r = SMG_ERROR_OUT_OF_MEMORY;
        else {
          out->pairs = np;
          pcap = cap;
        }
      }
      if (r == SMG_OK && nm > 0) {
        for (u = 0; u < nm; ++u) d[nd + u] = mins[u].dist;
        qsort(d + nd, nm, sizeof *d, float_cmp);
        out->pairs[out->pair_count].ca = ca;
        out->pairs[out->pair_count].cb = cb;
        out->pairs[out->pair_count].cut = share_cut(d + nd, nm, pct);
        ++out->pair_count;
        nd += nm;
      }
      free(mins);
    }
    if (r == SMG_OK && nd > 0) {
      float med;
      qsort(d, nd, sizeof *d, float_cmp);
      med = d[(nd - 1) / 2] * (1.0f + MEDIAN_TOLERANCE);
      out->median[l * L + l] =
          med > SMGB_CEILING_FLOOR ? med : SMGB_CEILING_FLOOR;
      out->cut[l] = share_cut(d, nd, pct);
    }
  }
  if (out->pair_count > 1)
    qsort(out->pairs, out->pair_count, sizeof *out->pairs, pair_cut_cmp);
  free(members);
  free(d);
  return r;
}

/* Big sets: clips whose motion earlier kept clips of their label already
 * cover (bake_coverage.h) get no windows in the search, hence no node, and
 * leave the pool after the graphs are built (bake_pool_compact.h). The
 * radius is the label's transition cut (the sampled percentile cut, no
 * more than the median ceiling): a window of a covered clip has a kept
 * window as near as the transitions the graph keeps. */
static smg_result cover_clips(smgb_bake* b, const smgb_cloud* cloud,
                              const double* heading,
                              const uint32_t* clip_start,
                              const ceilings* ceil_, uint32_t L,
                              uint8_t* vfrom, uint8_t* vinto) {
  smgb_coverage_job job;
  size_t nc = b->clip_count ? b->clip_count : 1;
  uint32_t* frames = malloc(nc * sizeof *frames);
  uint32_t* label = malloc(nc * sizeof *label);
  uint8_t* covered = malloc(nc);
  float* radius = malloc((L ? L : 1) * sizeof *radius);
  uint32_t c, l, f;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  if (!frames || !label || !covered || !radius) goto done;
  for (c = 0; c < b->clip_count; ++c) {
    frames[c] = b->clips[c].count;
    label[c] = b->clips[c].label;
  }
  for (l = 0; l < L; ++l) {
    float m = ceil_->median[l * L + l];
    if (ceil_->cut[l] < m) m = ceil_->cut[l];
    radius[l] = m < INFINITY ? m : 0.0f;
  }
  memset(&job, 0, sizeof job);
  job.cloud = cloud;
  job.heading = heading;
  job.window = b->opt.window;
  job.clip_count = b->clip_count;
  job.clip_first = clip_start;
  job.clip_frames = frames;
  job.clip_label = label;
  job.label_count = L;
  job.radius = radius;
  job.threads = b->opt.threads;
  r = smgb_cover_clips(&job, covered);
  if (r != SMG_OK) goto done;
  for (c = 0; c < b->clip_count; ++c) {
    if (clip_start[c] == SMGI_NONE) continue;
    b->clips[c].covered = covered[c];
    if (!covered[c]) continue;
    for (f = 0; f < b->clips[c].count; ++f)
      vfrom[clip_start[c] + f] = vinto[clip_start[c] + f] = 0;
  }
done:
  free(frames);
  free(label);
  free(covered);
  free(radius);
  return r;
}

/* mark[f] = label + 1 for every pool frame lying on an original edge
 * inside the largest strongly connected component of its label. */
static smg_result mark_cores(const smgb_bake* b, const smgb_graph* g,
                             uint8_t* mark) {
  uint32_t N = g->node_count, n, e, l;
  uint32_t* comp = malloc((N ? N : 1) * sizeof *comp);
  uint32_t* size;
  uint32_t best[SMGB_MAX_LABELS];
  int32_t nc;
  if (!comp) return SMG_ERROR_OUT_OF_MEMORY;
  nc = smgb_scc(g, comp);
  if (nc < 0) {
    free(comp);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  size = calloc((size_t)nc + 1, sizeof *size);
  if (!size) {
    free(comp);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (n = 0; n < N; ++n) size[comp[n]]++;
  for (l = 0; l < SMGB_MAX_LABELS; ++l) best[l] = SMGI_NONE;
  for (n = 0; n < N; ++n) {
    uint32_t lab = g->nodes[n].label;
    if (lab >= SMGB_MAX_LABELS || size[comp[n]] < 2) continue;
    if (best[lab] == SMGI_NONE || size[comp[n]] > size[best[lab]])
      best[lab] = comp[n];
  }
  for (e = 0; e < g->edge_count; ++e) {
    const smgb_edge* ed = &g->edges[e];
    uint32_t lab = g->nodes[ed->from].label, f;
    if (ed->kind != SMGB_EDGE_ORIGINAL || lab >= SMGB_MAX_LABELS) continue;
    if (comp[ed->from] != best[lab] || comp[ed->to] != best[lab]) continue;
    for (f = g->nodes[ed->from].frame; f <= g->nodes[ed->to].frame; ++f)
      mark[f] = (uint8_t)(lab + 1);
  }
  (void)b;
  free(size);
  free(comp);
  return SMG_OK;
}

/* Nodes at every transition end, transition edges, and original-motion
 * edges between consecutive nodes of a clip. */
static smg_result assemble(smgb_bake* b, smgb_graph* g, uint32_t role,
                           const build_ctx* ctx, const cand* cands,
                           uint32_t kept) {
  uint32_t k = b->opt.window, i, n = 0;
  uint32_t* frames = malloc((2u * kept + 1u) * sizeof *frames);
  if (!frames) return SMG_ERROR_OUT_OF_MEMORY;
  for (i = 0; i < kept; ++i) {
    frames[n++] = ctx->map[cands[i].m.i];
    frames[n++] = ctx->map[cands[i].m.j] + k;
  }
  qsort(frames, n, sizeof *frames, u32_cmp);
  for (i = 0; i < n; ++i) {
    if (i > 0 && frames[i] == frames[i - 1]) continue;
    if (smgb_graph_add_node(g, frames[i],
                            b->clips[b->frames[frames[i]].clip].label,
                            NULL) != SMG_OK) {
      free(frames);
      return SMG_ERROR_OUT_OF_MEMORY;
    }
  }
  free(frames);
  for (i = 0; i < kept; ++i) {
    smgb_edge e;
    uint32_t pa = ctx->map[cands[i].m.i], pb = ctx->map[cands[i].m.j];
    memset(&e, 0, sizeof e);
    e.kind = SMGB_EDGE_TRANSITION;
    e.a = pa;
    e.b = pb;
    e.from = find_node(g, pa);
    e.to = find_node(g, pb + k);
    e.cost = cands[i].m.dist;
    if (role == SMGI_CLIP_LOWER) {
      memcpy(e.align, cands[i].m.align, sizeof e.align);
    } else {
      /* upper clouds live in each frame's ground frame; the root of the
       * action is irrelevant to splicing, so align ground frames */
      double ga[3], gb[3], inv[3], zero[3] = {0, 0, 0};
      const smgi_frame* fa = &b->frames[pa];
      const smgi_frame* fb = &b->frames[pb];
      ga[0] = fa->root2d[0]; ga[1] = fa->root2d[1]; ga[2] = fa->root2d[2];
      gb[0] = fb->root2d[0]; gb[1] = fb->root2d[1]; gb[2] = fb->root2d[2];
      smgb_g_relative(gb, zero, inv);
      smgb_g_compose(ga, inv, e.align);
    }
    if (smgb_graph_add_edge(g, &e) != SMG_OK) return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (i = 0; i + 1 < g->node_count; ++i) {
    uint32_t fa = g->nodes[i].frame, fb = g->nodes[i + 1].frame;
    if (b->frames[fa].clip == b->frames[fb].clip) {
      smgb_edge e;
      memset(&e, 0, sizeof e);
      e.kind = SMGB_EDGE_ORIGINAL;
      e.from = i;
      e.to = i + 1;
      e.a = fa;
      e.b = fb;
      if (smgb_graph_add_edge(g, &e) != SMG_OK)
        return SMG_ERROR_OUT_OF_MEMORY;
    }
  }
  smgb_graph_sort_edges(g);
  return SMG_OK;
}

/* Candidates with their labels, clips, phase rule and thinning groups. */
static void to_cands(const smgb_bake* b, const build_ctx* ctx,
                     const smgb_minimum* mins, uint32_t n, int exact,
                     cand* cands) {
  uint32_t k = b->opt.window, i;
  for (i = 0; i < n; ++i) {
    uint32_t c0 = ctx->clip_of[mins[i].i], span;
    cands[i].m = mins[i];
    cands[i].li = b->clips[c0].label;
    cands[i].lj = b->clips[ctx->clip_of[mins[i].j]].label;
    cands[i].ci = c0;
    cands[i].cj = ctx->clip_of[mins[i].j];
    cands[i].admissible =
        ctx->role != SMGI_CLIP_UPPER ||
        (b->upper_phase_free >> cands[i].li & 1u) ||
        phase_agrees(b, ctx->map[mins[i].i], ctx->map[mins[i].j]);
    /* same-label candidates: one per k source frames; label changes are
     * far costlier (walk vs run poses) and only need to be available, so
     * one per max_edge_frames */
    span = cands[i].li == cands[i].lj ? k : b->opt.max_edge_frames;
    if (span < 1) span = 1;
    /* pool frames are contiguous per clip: (clip, local frame / span) */
    cands[i].region =
        c0 * 65536u + (ctx->map[mins[i].i] - b->clips[c0].first) / span;
    /* search mode: a clip and its mirror are one target (select) */
    cands[i].target = exact ? cands[i].cj : b->clips[cands[i].cj].source_clip;
    cands[i].best = 0.0f;
  }
}

/* Small sets (exact mode): the full grid's minima are all at hand, so the
 * rule is applied to them directly: same-label candidates per clip pair
 * (the best transition_percentile % under their label pair's median);
 * label changes among the minima that join the styles' cores. */
static smg_result exact_selection(smgb_bake* b, smgb_graph* g, uint32_t role,
                                  const build_ctx* ctx, cand* cands,
                                  uint32_t n, uint32_t* out_kept) {
  uint32_t nsame = 0, ncross, t, k = b->opt.window;
  smg_result r;
  for (t = 0; t < n; ++t)
    if (cands[t].li == cands[t].lj) {
      cand tmp = cands[nsame];
      cands[nsame++] = cands[t];
      cands[t] = tmp;
    }
  ncross = n - nsame;
  nsame = select_candidates(b, cands, nsame, 1, NULL);
  if (ncross > 0) {
    uint8_t* mark;
    memmove(cands + nsame, cands + (n - ncross), ncross * sizeof *cands);
    if ((r = assemble(b, g, role, ctx, cands, nsame)) != SMG_OK) return r;
    mark = calloc(b->frame_count, 1);
    if (!mark || mark_cores(b, g, mark) != SMG_OK) {
      free(mark);
      return SMG_ERROR_OUT_OF_MEMORY;
    }
    for (t = nsame; t < nsame + ncross;) {
      uint32_t fi = ctx->map[cands[t].m.i], fj = ctx->map[cands[t].m.j] + k;
      if (mark[fi] == cands[t].li + 1 && mark[fj] == cands[t].lj + 1) {
        ++t;
      } else {
        cands[t] = cands[nsame + ncross - 1];
        --ncross;
      }
    }
    free(mark);
    ncross = select_candidates(b, cands + nsame, ncross, 0, NULL);
    smgb_graph_free(g);
  }
  *out_kept = nsame + ncross;
  return SMG_OK;
}

smg_result smgb_build_graph(smgb_bake* b, uint32_t role) {
  smgb_graph* g = role == SMGI_CLIP_LOWER ? &b->lower : &b->upper;
  uint32_t k = b->opt.window, F = 0, c, f, P;
  build_ctx ctx;
  double *xyz = NULL, *w = NULL;
  uint8_t* valid = NULL;
  smgb_minimum* mins = NULL;
  uint32_t min_count = 0, kept = 0;
  cand* cands = NULL;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  smgb_cloud cloud, from, into;
  uint8_t *vfrom = NULL, *vinto = NULL;
  smgb_pair_search job;
  int exact;
  double* heading = NULL;
  uint32_t* group = NULL;
  uint32_t* clip_start = NULL;
  ceilings ceil_;
  uint32_t L = b->style_count > b->action_count ? b->style_count
                                                : b->action_count;

  memset(&ctx, 0, sizeof ctx);
  ctx.b = b;
  ctx.role = role;
  smgb_graph_free(g);
  for (c = 0; c < b->clip_count; ++c)
    if ((b->clips[c].flags & role) && !(b->clips[c].flags & SMGI_CLIP_BLEND))
      F += b->clips[c].count;
  if (F == 0) return SMG_OK;
  P = role == SMGI_CLIP_LOWER ? b->body.lower_point_count
                              : b->body.upper_segment_count;
  ctx.map = malloc(F * sizeof *ctx.map);
  ctx.clip_of = malloc(F * sizeof *ctx.clip_of);
  xyz = malloc((size_t)F * P * 3u * sizeof *xyz);
  w = malloc(P * sizeof *w);
  valid = malloc(F);
  vfrom = malloc(F);
  vinto = malloc(F);
  heading = malloc(F * sizeof *heading);
  group = malloc(F * sizeof *group);
  clip_start = malloc((b->clip_count ? b->clip_count : 1) * sizeof *clip_start);
  memset(&ceil_, 0, sizeof ceil_);
  ceil_.median = malloc((size_t)(L ? L : 1) * (L ? L : 1) * sizeof(float));
  ceil_.cut = malloc((L ? L : 1) * sizeof(float));
  if (!ctx.map || !ctx.clip_of || !xyz || !w || !valid || !vfrom ||
      !vinto || !heading || !group || !clip_start || !ceil_.median ||
      !ceil_.cut)
    goto oom;
  for (c = 0; c < b->clip_count; ++c) clip_start[c] = SMGI_NONE;

  /* point clouds */
  F = 0;
  for (c = 0; c < b->clip_count; ++c) {
    const smgb_pool_clip* pc = &b->clips[c];
    if (!(pc->flags & role) || (pc->flags & SMGI_CLIP_BLEND)) continue;
    clip_start[c] = F;
    for (f = 0; f < pc->count; ++f) {
      uint32_t pf = pc->first + f;
      double* dst = xyz + (size_t)F * P * 3u;
      ctx.map[F] = pf;
      ctx.clip_of[F] = c;
      heading[F] = b->frames[pf].root2d[2];
      group[F] = pc->label;
      /* window + arrival frame inside the clip */
      valid[F] = f + k < pc->count;
      /* windows pair_filter can accept as a transition's start / end:
       * the search then never looks at the others (a row that the filter
       * would reject against every column costs a scan of the whole
       * tree) */
      vfrom[F] = valid[F] && f >= k;
      vinto[F] = valid[F] && f + 2u * k + 1u <= pc->count;
      if (role == SMGI_CLIP_LOWER) {
        uint32_t p;
        for (p = 0; p < P; ++p) {
          const float* s =
              b->positions + ((size_t)pf * b->J + b->body.lower_points[p]) * 3u;
          dst[3 * p] = s[0];
          dst[3 * p + 1] = s[1];
          dst[3 * p + 2] = s[2];
        }
      } else {
        smgb_upper_cogs(b, pf, dst);
      }
      ++F;
    }
  }
  if (role == SMGI_CLIP_LOWER) {
    uint32_t p;
    for (p = 0; p < P; ++p) w[p] = 1.0;
  } else {
    smgb_upper_weights(b, w);
  }
  cloud.frames = F;
  cloud.points = P;
  cloud.xyz = xyz;
  cloud.weights = w;
  cloud.valid = valid;
  memset(&job, 0, sizeof job);
  from = cloud;
  from.valid = vfrom;
  into = cloud;
  into.valid = vinto;
  job.rows = &from;
  job.cols = &into;
  job.window = k;
  job.neighbours = SMGB_TRANSITION_NEIGHBOURS;
  /* every second window starts walks: neighbouring windows share their
   * nearest matches, and the walks reach the minima in between (the
   * CMU set's graph is the same with all of them) */
  job.row_stride = 2u;
  job.align = 1;
  job.filter = pair_filter;
  job.filter_user = &ctx;
  job.threads = b->opt.threads;
  job.report = &b->report;
  job.col_group = job.row_group = group;
  if (role == SMGI_CLIP_LOWER) {
    job.row_heading = job.col_heading = heading;
    job.group_count = b->style_count;
  } else {
    job.group_count = b->action_count; /* within an action only */
  }
  exact = (uint64_t)F * F <= SMGB_EXACT_GRID_CELLS;
  if (exact) {
    /* small set: every minimum of the full grid (bake_pointcloud.c) */
    smgb_grid_job grid;
    memset(&grid, 0, sizeof grid);
    grid.rows = grid.cols = &cloud;
    grid.window = k;
    grid.align = 1;
    grid.filter = pair_filter;
    grid.filter_user = &ctx;
    grid.threads = b->opt.threads;
    grid.report = &b->report;
    r = smgb_grid_minima(&grid, &mins, &min_count);
  } else {
    r = sampled_ceilings(b, &ctx, &cloud, clip_start, &ceil_, L);
    if (r == SMG_OK)
      r = cover_clips(b, &cloud, heading, clip_start, &ceil_, L, vfrom, vinto);
    if (r == SMG_OK) r = smgb_pair_search_minima(&job, &mins, &min_count);
  }

  if (r != SMG_OK) {
    smgb_fail(&b->report, "%s graph: distance grid failed (%s)",
              role == SMGI_CLIP_LOWER ? "lower" : "upper",
              smg_result_string(r));
    goto done;
  }

  cands = malloc((min_count ? min_count : 1) * sizeof *cands);
  if (!cands) goto oom;
  to_cands(b, &ctx, mins, min_count, exact, cands);
  if (exact) {
    r = exact_selection(b, g, role, &ctx, cands, min_count, &kept);
    if (r != SMG_OK) goto oom;
  } else
  /* Same-label transitions first; label changes (walk <-> run) are
   * searched afterwards, only from one style's strongly connected core
   * into another's, so that the few costly ones that are kept actually
   * connect the styles (the best matches between styles are often where
   * a clip starts or ends, outside every cycle). */
  {
    uint32_t nsame = select_candidates(b, cands, min_count, 1, &ceil_);
    uint32_t ncross = 0;
    if (role == SMGI_CLIP_LOWER && b->style_count > 1) {
      uint8_t* mark = NULL;
      smgb_minimum* cm = NULL;
      cand* grown;
      if ((r = assemble(b, g, role, &ctx, cands, nsame)) != SMG_OK) goto done;
      mark = calloc(b->frame_count, 1);
      if (!mark || mark_cores(b, g, mark) != SMG_OK) {
        free(mark);
        goto oom;
      }
      smgb_graph_free(g);
      ctx.mark = mark;
      for (f = 0; f < F; ++f) {
        uint32_t lab = b->clips[ctx.clip_of[f]].label + 1u;
        vfrom[f] = vfrom[f] && mark[ctx.map[f]] == lab;
        vinto[f] = vinto[f] && mark[ctx.map[f] + k] == lab;
      }
      job.neighbours = 0;
      job.other_neighbours = SMGB_STYLE_CHANGE_NEIGHBOURS;
      job.row_stride = k / 2u;
      r = smgb_pair_search_minima(&job, &cm, &ncross);
      ctx.mark = NULL;
      free(mark);
      if (r != SMG_OK) {
        free(cm);
        goto oom;
      }
      grown = realloc(cands, ((size_t)nsame + ncross + 1u) * sizeof *cands);
      if (!grown) {
        free(cm);
        goto oom;
      }
      cands = grown;
      to_cands(b, &ctx, cm, ncross, 0, cands + nsame);
      free(cm);
      ncross = select_candidates(b, cands + nsame, ncross, 0, NULL);
    }
    kept = nsame + ncross;
  }
  if (role == SMGI_CLIP_LOWER)
    b->lower_candidates = kept;
  else
    b->upper_candidates = kept;
  r = assemble(b, g, role, &ctx, cands, kept);
  if (r != SMG_OK) goto oom;
  goto done;
oom:
  smgb_fail(&b->report, "out of memory building the %s graph",
            role == SMGI_CLIP_LOWER ? "lower" : "upper");
  r = SMG_ERROR_OUT_OF_MEMORY;
done:
  free(ctx.map);
  free(ctx.clip_of);
  free(xyz);
  free(w);
  free(valid);
  free(vfrom);
  free(vinto);
  free(heading);
  free(group);
  free(clip_start);
  free(ceil_.median);
  free(ceil_.cut);
  free(ceil_.pairs);
  free(mins);
  free(cands);
  return r;
}
