/*
 * planner.c - the paper's search (III.C.2), made incremental.
 *
 * From the node where the plan ends, every out-edge is scored by how well
 * its precomputed motion follows the path from the planned progress s:
 *  - its end (the edge's ground displacement) and a mid-edge root sample
 *    (FRMI root2d, placed without forward kinematics) against the path
 *    near the arc length they should have reached (track_error: distance
 *    by projection, plus a penalty for falling short in progress);
 *  - a bounded look-ahead below it (look_value): the natural continuation
 *    for SMGI_SEARCH_SECONDS, trying at every branch to leave it once,
 *    leaves valued by the derived node_look table plus a heading error
 *    towards a pursuit point on the path;
 *  - a style term from the derived hop counts (edges in the wanted style
 *    are free, others pay per hop still needed).
 * The greedy best is taken; when its distance error exceeds the threshold
 * the planner backs up to the previous planned node and tries its
 * next-best edges, keeping an alternative only if it does better (bounded).
 * A character far off the path ("lost") lets the wanted style yield to the
 * most agile one and compares options by where they face and lead.
 * Work per call is bounded by a budget of edge evaluations (look-ahead
 * included); only when the playhead would otherwise run out is the budget
 * exceeded (by at most the edges needed for this step).
 */
#include <math.h>
#include <string.h>

#include "character_internal.h"

#define END_EPS 0.3f           /* metres from the end that count as there */
#ifndef HEADING_WEIGHT
#define HEADING_WEIGHT 0.4f    /* metres of error per radian */
#endif
#define STYLE_WEIGHT 3.0f      /* metres of penalty per hop to the style:
                                  style constraints dominate path error */
#define END_SPEED_WEIGHT 0.5f  /* at the end prefer edges that travel less */
#define LOST_DISTANCE 1.5f     /* off the path by more: style yields */
#define HEADING_WEIGHT_LOST 2.0f   /* metres per radian when lost */
#ifndef YIELD_ERROR
#define YIELD_ERROR 0.8f /* mean sequence error beyond which the style yields */
#endif
#define LOST_DISTANCE_WEIGHT 0.25f /* and distance counts less */
#ifndef TRAVEL_WEIGHT
#define TRAVEL_WEIGHT 0.3f     /* metres per radian of travel vs facing */
#endif
#ifndef PURSUIT_M
#define PURSUIT_M 1.0f         /* heading aims this far ahead on the path */
#endif
#ifndef SEQ_SECONDS
#define SEQ_SECONDS 2.0f       /* motion a candidate sequence covers */
#endif
#ifndef SEQ_BUDGET
#define SEQ_BUDGET 256u        /* edge evaluations per ranking */
#endif
#ifndef SEQ_BRANCHES
#define SEQ_BRANCHES 6u        /* choices searched below a candidate */
#endif
#ifndef TURN_WEIGHT
#define TURN_WEIGHT 1.0f /* metres per radian of turn out of reach */
#endif
#define SEQ_MAX_DEPTH 48u
#define SEQ_MAX_KIDS 8u
#define SEQ_PATH_CAP 64u
#ifndef SEQ_COMMIT_FRAMES
#define SEQ_COMMIT_FRAMES 12.0f /* frames of the best sequence committed at once */
#endif
#ifndef SEQ_NO_BT
#define SEQ_NO_BT 0
#endif

typedef struct cand {
  uint32_t edge;
  float score, err, s_end, pen;
  uint32_t seg_end;
  smgi_xform2 end; /* ground transform after the edge */
  uint32_t work;    /* edge evaluations spent on it (look-ahead included) */
  float seq_err;    /* path error part of its best sequence's value */
} cand;

static smgi_xform2 ground_of(const smg_graph* g, uint32_t frame) {
  const float* r = g->data.frames[frame].root2d;
  smgi_xform2 x = {r[0], r[1], r[2]};
  return x;
}

static smgi_xform2 disp_of(const smgi_edge* e) {
  smgi_xform2 x = {e->displacement[0], e->displacement[1],
                   e->displacement[2]};
  return x;
}

/* atan2 for the search's heading terms: a degree-11 minimax polynomial
 * on [0, 1] (max error about 1e-5 rad, i.e. micrometres at these
 * weights) instead of libm's atan2f, which was a fifth of all planning
 * instructions. (0, 0) gives 0; NaN propagates (the cost turns infinite). */
static inline float fast_atan2(float y, float x) {
  float ax = fabsf(x), ay = fabsf(y);
  float mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
  if (mx == 0.0f) return 0.0f;
  float a = mn / mx, t = a * a;
  float r = a * (0.99997726f +
                 t * (-0.33262347f +
                      t * (0.19354346f +
                           t * (-0.11643287f +
                                t * (0.05265332f + t * -0.01172120f)))));
  if (ay > ax) r = 0.5f * SMGI_PI - r;
  if (x < 0.0f) r = SMGI_PI - r;
  return y < 0.0f ? -r : r;
}

/* smgi_path_eval without the call when the hint segment already holds s
 * (almost every query of a search: samples advance a little at a time);
 * same arithmetic, so the same result. */
static inline void path_at(const smgi_path* p, float s, uint32_t* seg,
                           float* x, float* z) {
  uint32_t i = *seg;
  if (p->count >= 2u && i + 1u < p->count && s >= p->cum[i] &&
      s <= p->cum[i + 1u] && s <= p->length) {
    float len = p->cum[i + 1u] - p->cum[i];
    float u = len > 1e-9f ? (s - p->cum[i]) / len : 0.0f;
    u = smgi_clampf(u, 0.0f, 1.0f);
    const float* a = &p->xz[2u * i];
    *x = a[0] + u * (a[2] - a[0]);
    *z = a[1] + u * (a[3] - a[1]);
    return;
  }
  smgi_path_eval(p, s, seg, x, z, NULL);
}

/* (x, z) = the end point moved `beyond` metres further along the path's
 * last non-degenerate segment (unchanged for a one-point path). */
static void extend_past_end(const smgi_path* p, float beyond, float* x,
                            float* z) {
  const float* e = &p->xz[2u * (p->count - 1u)];
  uint32_t i = p->count - 1u;
  while (i > 0u) {
    const float* a = &p->xz[2u * (i - 1u)];
    float dx = e[0] - a[0], dz = e[1] - a[1], l2 = dx * dx + dz * dz;
    if (l2 > 1e-8f) {
      float k = beyond / sqrtf(l2);
      *x = e[0] + k * dx;
      *z = e[1] + k * dz;
      return;
    }
    --i;
  }
}

/* Where to stay when there is nothing (more) to follow. */
static void end_target(const smg_character* ch, float* x, float* z) {
  const smgi_path* p = &ch->path;
  if (p->count > 0) {
    *x = p->xz[2u * (p->count - 1u)];
    *z = p->xz[2u * (p->count - 1u) + 1u];
  } else {
    *x = ch->anchor[0];
    *z = ch->anchor[1];
  }
}

static float style_penalty(const smg_character* ch, const smgi_edge* e,
                           uint32_t desired) {
  const smg_graph* g = ch->graph;
  uint32_t S = g->data.style_count;
  if (desired >= S || e->label == desired) return 0.0f;
  const uint8_t* hops = smgi_derived_of(g)->lower_hops;
  if (hops[(size_t)e->from * S + desired] == SMGI_HOPS_UNREACHABLE)
    return 0.0f; /* cannot get there from here: ignore */
  uint8_t h = hops[(size_t)e->to * S + desired];
  if (h == SMGI_HOPS_UNREACHABLE) return 4.0f * STYLE_WEIGHT;
  return STYLE_WEIGHT * (1.0f + (float)h);
}

/* Distance of a planned ground position from the path point at s. */
static float start_error(const smg_character* ch, smgi_xform2 W, float s,
                         uint32_t seg) {
  if (ch->path.count < 2u) return 0.0f;
  float x, z;
  smgi_path_eval(&ch->path, s, &seg, &x, &z, NULL);
  return sqrtf((W.x - x) * (W.x - x) + (W.z - z) * (W.z - z));
}

/* An edge that spans arc lengths [s0, s1] is in style if its label is
 * wanted at either end: transition edges cross the point where the style
 * changes, and an edge ending exactly on a transition point is fine. */
static float edge_style_penalty(const smg_character* ch, const smgi_edge* e,
                                float s0, float s1) {
  uint32_t a = smgi_style_at(ch, s0), b = smgi_style_at(ch, s1);
  if (e->label == a || e->label == b) return 0.0f;
  return style_penalty(ch, e, b);
}

/* Lost (far off the path): the wanted style yields to the graph's most
 * agile one until the path is rejoined - a style that cannot turn (CMU
 * runs) would otherwise carry the character away for good. */
static float lost_style_penalty(const smg_character* ch,
                                const smgi_edge* e) {
  return style_penalty(ch, e, smgi_derived_of(ch->graph)->agile_style);
}

/* ---- sequence search (Kovar et al. 2002 path synthesis) ----------------
 *
 * A candidate is judged by the best sequence of edges starting with it
 * that covers SEQ_SECONDS of motion. The error of a sequence is the mean,
 * over root samples along it, of the distance between the motion's root
 * after travelling arc length u and the path point at s0 + u, plus a
 * heading term (facing vs the direction towards the path point a little
 * further on, which is the tangent on the path and the way back off it)
 * and a forward-walking term (direction of travel vs facing). Roots come
 * from FRMI root2d placed with the edge's start transform (no FK). The
 * tree of out-edge sequences is searched depth first with branch and
 * bound under an edge-evaluation budget; every candidate first gets a
 * dive along its natural continuation, so all have a complete value even
 * when the budget ends the search early. */

typedef struct seq_ctx {
  const smg_character* ch;
  float s0;          /* path arc length where the sequences start */
  float T;           /* frames a sequence covers */
  int following;     /* a path to follow from s0 on (else: stay near tx,tz) */
  int lost;          /* far off the path: the agile style is wanted */
  int yield;         /* the wanted style cannot follow: the agile one is */
  float leaf_err;    /* path error part of the last seq_leaf value */
  float best_err;    /* and of the best sequence found */
  float tx, tz;      /* where to stay when not following */
  uint32_t style0;   /* wanted style at s0 ... */
  float style_end;   /* ... which holds until this arc (next constraint) */
  uint32_t budget;   /* edge evaluations left */
  uint32_t path[SEQ_PATH_CAP];      /* edges of the sequence being built */
  uint32_t best_path[SEQ_PATH_CAP]; /* and of the best one so far */
  uint32_t best_len;
} seq_ctx;

typedef struct seq_state {
  uint32_t node;
  smgi_xform2 W;     /* ground transform at the node */
  float u;           /* arc length travelled since s0 */
  float f;           /* frames covered */
  float cost;        /* accumulated error (mean over the window) */
  float pen;         /* worst style penalty on the way */
  uint32_t seg;      /* path segment hint near s0 + u */
} seq_state;

/* Error of one root sample at (x, z) facing h, after arc u, having moved
 * (mx, mz) since the previous sample over w frames. */
static float sample_cost(const seq_ctx* c, float x, float z, float h,
                         float u, float mx, float mz, float w,
                         uint32_t* seg, float* dist) {
  const smgi_path* p = &c->ch->path;
  float m2 = mx * mx + mz * mz;
  if (!c->following) {
    float dx = x - c->tx, dz = z - c->tz;
    float d = sqrtf(dx * dx + dz * dz);
    *dist = d;
    /* at the end prefer motion that travels least and, there being no
     * idle clips, turns back towards the end point (circles around it
     * instead of walking off) */
    float sc = d + END_SPEED_WEIGHT * sqrtf(m2) * c->ch->fps /
                       (w > 1.0f ? w : 1.0f);
    if (d > END_EPS)
      sc += HEADING_WEIGHT * fabsf(smgi_wrap_angle(h - fast_atan2(-dx, -dz)));
    return sc;
  }
  float sr = c->s0 + u, rx, rz;
  path_at(p, sr, seg, &rx, &rz);
  /* Past the end the path goes on along its last direction. Clamping the
   * target to the end point made any sequence that carries on beyond it
   * look "off the path", so near the end a fast style (a run covering 6 m
   * in the look-ahead) yielded to walking while right on the path. Coming
   * to rest at the end is the end phase's job, not the follower's. */
  if (sr > p->length) extend_past_end(p, sr - p->length, &rx, &rz);
  float dx = x - rx, dz = z - rz;
  float d = sqrtf(dx * dx + dz * dz);
  *dist = d;
  /* lost (far off the path): options differ little in distance (all move
   * away for the next second or two) but much in where they face; the
   * way back is towards the path near where the character left it */
  float sc = c->lost ? LOST_DISTANCE_WEIGHT * d : d;
  if (sr < p->length) {
    float qx, qz;
    uint32_t sg = *seg;
    path_at(p, sr + PURSUIT_M + (c->lost ? 0.0f : d), &sg, &qx, &qz);
    float ax = qx - x, az = qz - z;
    if (ax * ax + az * az > 1e-4f)
      sc += (c->lost ? HEADING_WEIGHT_LOST : HEADING_WEIGHT) *
            fabsf(smgi_wrap_angle(h - fast_atan2(ax, az)));
  }
  if (m2 > 1e-4f) sc += TRAVEL_WEIGHT * fabsf(smgi_wrap_angle(fast_atan2(mx, mz) - h));
  return sc;
}

/* Style penalty of an edge at arc lengths [a, b] of the path. */
static float seq_pen(const seq_ctx* c, const smgi_edge* e, float a, float b) {
  if (!c->following) return 10.0f * style_penalty(c->ch, e, c->style0);
  if (c->lost || c->yield) return lost_style_penalty(c->ch, e);
  /* s0 <= a <= b: before the next constraint the wanted style is the one
   * at s0 (what edge_style_penalty would find with two scans) */
  if (b < c->style_end)
    return e->label == c->style0 ? 0.0f : style_penalty(c->ch, e, c->style0);
  return edge_style_penalty(c->ch, e, a, b);
}

/* Append edge `ei` to the sequence in `in`: root samples at the edge's
 * middle (edges of 4+ frames) and end, each weighted by the frames it
 * stands for inside the window. *maxd gets the largest sample distance. */
static void seq_step(seq_ctx* c, const seq_state* in, float cw, float sw,
                     uint32_t ei, float pen_scale, float bound,
                     seq_state* out, float* maxd) {
  const smg_graph* g = c->ch->graph;
  const smgi_edge* e = &g->data.lower_edges[ei];
  /* one rotation (cw, sw = cos, sin of in->W.h, computed once by the
   * caller for all of a state's children) places both the edge's end and
   * its mid sample */
  {
    const float* dp = e->displacement;
    out->W.x = in->W.x + (cw * dp[0] + sw * dp[1]);
    out->W.z = in->W.z + (-sw * dp[0] + cw * dp[1]);
    out->W.h = smgi_wrap_angle(in->W.h + dp[2]);
  }
  out->node = e->to;
  out->seg = in->seg;
  out->cost = in->cost;
  const uint32_t fc = e->frame_count;
  uint32_t ks[2];
  uint32_t nk = 0;
  if (fc >= 4u) ks[nk++] = fc / 2u;
  ks[nk++] = fc;
  float px = in->W.x, pz = in->W.z, kprev = 0.0f, md = 0.0f;
  float room = c->T - in->f; /* frames left in the window */
  for (uint32_t i = 0; i < nk; ++i) {
    float k = (float)ks[i];
    float w = (k < room ? k : room) - (kprev < room ? kprev : room);
    if (w <= 0.0f) break;
    float x, z, h;
    if (ks[i] == fc) {
      x = out->W.x;
      z = out->W.z;
      h = out->W.h;
    } else {
      /* the mid sample relative to the edge's start (derived edge_mid) */
      const float* r = smgi_derived_of(g)->edge_mid + 4u * (size_t)ei;
      x = in->W.x + (cw * r[0] + sw * r[1]);
      z = in->W.z + (-sw * r[0] + cw * r[1]);
      h = in->W.h + r[2];
    }
    float d;
    float sc = sample_cost(c, x, z, h, in->u + e->arc_length * k / (float)fc,
                           x - px, z - pz, k - kprev, &out->seg, &d);
    out->cost += sc * w / c->T;
    if (d > md) md = d;
    if (out->cost + in->pen >= bound) {
      /* already no better than the bound: costs and penalties only grow
       * (every term is >= 0), so the caller prunes it either way */
      *maxd = md;
      out->cost = INFINITY;
      out->pen = in->pen;
      out->u = in->u + e->arc_length;
      out->f = in->f + (float)fc;
      return;
    }
    px = x;
    pz = z;
    kprev = k;
  }
  *maxd = md;
  out->u = in->u + e->arc_length;
  out->f = in->f + (float)fc;
  float pe = pen_scale * seq_pen(c, e, c->s0 + in->u, c->s0 + out->u);
  out->pen = in->pen > pe ? in->pen : pe;
  if (!isfinite(out->cost)) out->cost = INFINITY;
}

/* Value of a finished (or budget-cut) sequence: an unfinished one is
 * extrapolated at its mean so far. */
static float seq_value(const seq_ctx* c, const seq_state* st) {
  float v = st->cost;
  if (st->f < c->T && st->f > 0.0f) v *= c->T / st->f;
  return v + st->pen;
}

/* Value of a sequence that stops choosing at `st`: the node's natural
 * continuation (derived node_trail, a few samples looked up, no edge
 * walk) stands for the rest of the window, style included. */
static float seq_leaf(seq_ctx* c, seq_state st, float bound) {
  const smg_graph* g = c->ch->graph;
  const smgi_derived* dv = smgi_derived_of(g);
  const float* tr = dv->node_trail + 4u * (size_t)st.node * SMGI_TRAIL_SAMPLES;
  const float* tf = dv->node_trail_frames + (size_t)st.node * SMGI_TRAIL_SAMPLES;
  const uint32_t* te = dv->node_trail_edge + (size_t)st.node * SMGI_TRAIL_SAMPLES;
  const float f0 = st.f, u0 = st.u;
  float pf = 0.0f, pu = 0.0f, px = st.W.x, pz = st.W.z;
  /* beyond the window: can the motion turn towards the path soon? The
   * heading still missing once the node's best reachable turn (derived
   * node_turn) is spent costs like a heading error */
  if (c->following) {
    const smgi_path* p = &c->ch->path;
    float sr = c->s0 + st.u, rx, rz, qx, qz;
    uint32_t sg = st.seg;
    path_at(p, sr, &sg, &rx, &rz);
    float d = sqrtf((rx - st.W.x) * (rx - st.W.x) + (rz - st.W.z) * (rz - st.W.z));
    path_at(p, sr + PURSUIT_M + (c->lost ? 0.0f : d), &sg, &qx, &qz);
    float ax = qx - st.W.x, az = qz - st.W.z;
    if (ax * ax + az * az > 1e-4f) {
      float need = smgi_wrap_angle(fast_atan2(ax, az) - st.W.h);
      const float* cap = dv->node_turn + 2u * st.node;
      float rest = fabsf(need) - (need > 0.0f ? cap[0] : cap[1]);
      if (rest > 0.0f) st.pen += TURN_WEIGHT * rest;
    }
  }
  /* the value is at least cost + pen (an unfinished window only scales
   * the cost up): once that reaches the bound the leaf cannot win */
  if (st.cost + st.pen >= bound) return INFINITY;
  for (uint32_t k = 0; k < SMGI_TRAIL_SAMPLES && st.f < c->T; ++k) {
    float fk = tf[k];
    if (fk <= pf) break; /* the continuation ended */
    float room = c->T - f0;
    float w = (fk < room ? fk : room) - pf;
    smgi_xform2 lk = {tr[4u * k], tr[4u * k + 1u], tr[4u * k + 2u]};
    smgi_xform2 end = smgi_xf_mul(st.W, lk);
    float d;
    float sc = sample_cost(c, end.x, end.z, end.h, u0 + tr[4u * k + 3u],
                           end.x - px, end.z - pz, fk - pf, &st.seg, &d);
    st.cost += sc * w / c->T;
    st.f = f0 + (fk < room ? fk : room);
    if (te[k] != SMGI_NONE) {
      const smgi_edge* e = &g->data.lower_edges[te[k]];
      float pe = 0.5f * seq_pen(c, e, c->s0 + u0 + pu,
                                c->s0 + u0 + tr[4u * k + 3u]);
      if (pe > st.pen) st.pen = pe;
    }
    if (st.cost + st.pen >= bound) return INFINITY;
    pf = fk;
    pu = tr[4u * k + 3u];
    px = end.x;
    pz = end.z;
  }
  float v = seq_value(c, &st);
  c->leaf_err = v - st.pen;
  return v;
}

/* Depth-first branch and bound below `st`; *best is the bound. Branches
 * at the next `branches` nodes with several exits (the early choices
 * matter most; a node of one exit is no choice), then follows the natural
 * continuation to the end of the window (seq_leaf values what is left
 * when the graph or the budget ends first). */
static void seq_dfs(seq_ctx* c, seq_state st, uint32_t branches,
                    uint32_t depth, float* best) {
  const smg_graph* g = c->ch->graph;
  const smgi_derived* dv = smgi_derived_of(g);
  for (uint32_t d = 0; d < SEQ_MAX_DEPTH && depth < SEQ_PATH_CAP; ++d) {
    const smgi_node* n = &g->data.lower_nodes[st.node];
    if (st.f >= c->T || n->edge_count == 0 || c->budget == 0) break;
    uint32_t nat = dv->natural_next[st.node];
    if (n->edge_count > 1u) {
      if (branches == 0) break;
      /* children cheapest first: good bounds early prune the most */
      seq_state kids[SEQ_MAX_KIDS];
      uint32_t kid_edge[SEQ_MAX_KIDS], nk = 0;
      uint32_t cnt = n->edge_count < SEQ_MAX_KIDS ? n->edge_count : SEQ_MAX_KIDS;
      const float cw = cosf(st.W.h), sw = sinf(st.W.h);
      for (uint32_t k = 0; k < cnt && c->budget > 0; ++k) {
        uint32_t ei = n->first_edge + k;
        seq_state nx;
        float md;
        c->budget--;
        seq_step(c, &st, cw, sw, ei, 0.5f, *best, &nx, &md);
        if (nx.cost + nx.pen >= *best) continue; /* costs only grow */
        uint32_t i = nk++;
        while (i > 0 && kids[i - 1u].cost + kids[i - 1u].pen >
                            nx.cost + nx.pen) {
          kids[i] = kids[i - 1u];
          kid_edge[i] = kid_edge[i - 1u];
          --i;
        }
        kids[i] = nx;
        kid_edge[i] = ei;
      }
      for (uint32_t i = 0; i < nk; ++i) {
        if (kids[i].cost + kids[i].pen >= *best) break;
        c->path[depth] = kid_edge[i];
        seq_dfs(c, kids[i], branches - 1u, depth + 1u, best);
      }
      (void)nat;
      return;
    }
    /* a single exit: no choice */
    seq_state nx;
    float md;
    c->budget--;
    seq_step(c, &st, cosf(st.W.h), sinf(st.W.h), n->first_edge, 0.5f,
             *best, &nx, &md);
    st = nx;
    c->path[depth++] = n->first_edge;
    if (st.cost + st.pen >= *best) return;
  }
  float v = seq_leaf(c, st, *best);
  if (v < *best) {
    *best = v;
    c->best_err = c->leaf_err;
    memcpy(c->best_path, c->path, sizeof(uint32_t) * depth);
    c->best_len = depth;
  }
}

static void seq_init(seq_ctx* c, const smg_character* ch, smgi_xform2 W,
                     float s, uint32_t seg) {
  c->ch = ch;
  c->s0 = s;
  c->T = SEQ_SECONDS * ch->fps;
  c->following = ch->path.count >= 2u && s < ch->path.length - END_EPS;
  c->lost = c->following && start_error(ch, W, s, seg) > LOST_DISTANCE;
  c->yield = 0;
  c->leaf_err = c->best_err = 0.0f;
  end_target(ch, &c->tx, &c->tz);
  c->style0 = smgi_style_at(ch, s);
  c->style_end = smgi_next_constraint_arc(ch, s);
  c->budget = SEQ_BUDGET;
}

/* A committed edge's bookkeeping without a search: where it ends, the
 * progress there and its distance error. */
static void make_cand(const smg_character* ch, smgi_xform2 W, float s,
                      uint32_t seg, uint32_t ei, cand* x) {
  const smgi_edge* e = &ch->graph->data.lower_edges[ei];
  memset(x, 0, sizeof *x);
  x->edge = ei;
  x->end = smgi_xf_mul(W, disp_of(e));
  x->s_end = s + e->arc_length;
  x->seg_end = seg;
  x->work = 1u;
  if (ch->path.count >= 2u) {
    float d;
    uint32_t sg = seg;
    float sp = smgi_path_project_local(&ch->path, x->end.x, x->end.z, &sg, &d);
    x->s_end = smgi_clampf(sp, s, s + e->arc_length + 0.25f);
    x->seg_end = sg;
    if (s < ch->path.length - END_EPS) x->err = d;
  }
}

/* Score all out-edges of `node` from (W, s, seg), sorted best first
 * (ties by edge index, so the order is deterministic). */
static uint32_t rank_pass(const smg_character* ch, uint32_t node,
                          smgi_xform2 W, float s, uint32_t seg, cand* c,
                          uint32_t* seq, uint32_t* seq_len, int yield,
                          int* following) {
  const smg_graph* g = ch->graph;
  const smgi_node* n = &g->data.lower_nodes[node];
  uint32_t count = n->edge_count < SMGI_MAX_CANDIDATES ? n->edge_count
                                                       : SMGI_MAX_CANDIDATES;
  seq_ctx sc;
  seq_init(&sc, ch, W, s, seg);
  sc.best_len = 0;
  sc.yield = yield;
  *following = sc.following && !sc.lost;
  seq_state root = {node, W, 0.0f, 0.0f, 0.0f, 0.0f, seg};
  seq_state first[SMGI_MAX_CANDIDATES];
  float best = INFINITY;
  const float cw = cosf(W.h), sw = sinf(W.h);
  for (uint32_t k = 0; k < count; ++k) {
    cand* x = &c[k];
    uint32_t ei = n->first_edge + k;
    const smgi_edge* e = &g->data.lower_edges[ei];
    float md;
    if (sc.budget > 0) sc.budget--;
    seq_step(&sc, &root, cw, sw, ei, 1.0f, INFINITY, &first[k], &md);
    x->edge = ei;
    x->end = first[k].W;
    (void)md;
    x->err = 0.0f; /* nothing to follow: never back up */
    x->pen = first[k].pen;
    /* progress: where the edge's end projects, kept within what it
     * travelled (a re-projection keeps the sequences' reference anchored
     * to where the character actually is) */
    uint32_t sg = seg;
    float s_end = s + e->arc_length, d;
    if (ch->path.count >= 2u) {
      float sp = smgi_path_project_local(&ch->path, x->end.x, x->end.z, &sg,
                                         &d);
      s_end = smgi_clampf(sp, s, s + e->arc_length + 0.25f);
      /* the paper's distance error (what the threshold is compared
       * with): how far the edge leaves the character from the path */
      if (sc.following) x->err = d;
    }
    x->s_end = s_end;
    x->seg_end = sg;
    x->score = seq_leaf(&sc, first[k], INFINITY);
    x->seq_err = sc.leaf_err;
    if (x->score < best) best = x->score;
  }
  /* then branch and bound, the most promising first; a candidate's score
   * is the best sequence found below it (the look-up value above is only
   * an estimate); one whose every sequence is pruned is worse than the
   * best so far and keeps the bound plus its estimate, for ordering */
  uint32_t order[SMGI_MAX_CANDIDATES];
  for (uint32_t k = 0; k < count; ++k) {
    uint32_t i = k;
    while (i > 0 && c[order[i - 1u]].score > c[k].score) {
      order[i] = order[i - 1u];
      --i;
    }
    order[i] = k;
  }
  best = INFINITY;
  uint32_t pool = sc.budget;
  for (uint32_t i = 0; i < count && pool > 0; ++i) {
    cand* x = &c[order[i]];
    float b = best;
    /* an equal share of what is left: a deep first subtree must not
     * starve the others (they would keep their estimates) */
    uint32_t share = pool / (count - i);
    if (share == 0) share = 1;
    sc.budget = share;
    sc.path[0] = x->edge;
    seq_dfs(&sc, first[order[i]], SEQ_BRANCHES, 1u, &b);
    pool -= share - sc.budget;
    if (b < best) { /* found a better sequence below this candidate */
      x->score = b;
      x->seq_err = sc.best_err;
      best = b;
    } else if (isfinite(best)) {
      x->score = best + x->score;
    }
  }
  for (uint32_t k = 0; k < count; ++k) {
    c[k].work = 1u;
    if (!isfinite(c[k].score)) c[k].score = INFINITY;
  }
  c[0].work = SEQ_BUDGET - pool;
  if (seq_len) {
    /* the best sequence: the one the search found, or (when no search
     * beat an estimate) just the best candidate, decided below */
    *seq_len = 0;
    if (sc.best_len > 0 && isfinite(best)) {
      memcpy(seq, sc.best_path, sizeof(uint32_t) * sc.best_len);
      *seq_len = sc.best_len;
    }
  }
  /* sort best first */
  for (uint32_t k = 1; k < count; ++k) {
    cand x = c[k];
    uint32_t i = k;
    while (i > 0 && (c[i - 1u].score > x.score ||
                     (c[i - 1u].score == x.score && c[i - 1u].edge > x.edge))) {
      c[i] = c[i - 1u];
      --i;
    }
    c[i] = x;
  }
  return count;
}

/* Rank the out-edges of `node`; when even the best sequence in the wanted
 * style leaves the path by more than YIELD_ERROR on average (a run asked
 * for where the path turns tighter than runs can), rank again letting the
 * style yield to the most agile one - before the character is lost. */
static uint32_t rank_node(const smg_character* ch, uint32_t node,
                          smgi_xform2 W, float s, uint32_t seg, cand* c,
                          uint32_t* seq, uint32_t* seq_len) {
  int following;
  uint32_t n = rank_pass(ch, node, W, s, seg, c, seq, seq_len, 0, &following);
  if (n > 0 && following && c[0].seq_err > YIELD_ERROR &&
      smgi_derived_of(ch->graph)->agile_style != smgi_style_at(ch, s)) {
    n = rank_pass(ch, node, W, s, seg, c, seq, seq_len, 1, &following);
    for (uint32_t i = 0; i < n; ++i) c[i].work = i == 0 ? 2u * SEQ_BUDGET : 0u;
  }
  return n;
}

/* Edge evaluations spent ranking n candidates: what the step budget
 * counts, so an edit frame's re-planning stays bounded. */
static uint32_t work_of(const cand* c, uint32_t n) {
  uint32_t w = 0;
  for (uint32_t i = 0; i < n; ++i) w += c[i].work;
  return w;
}

static void spend(uint32_t* budget, uint32_t w) {
  *budget = *budget > w ? *budget - w : 0u;
}

static void push(smg_character* ch, smgi_xform2 W, float s, const cand* c,
                 uint32_t rank, uint32_t count) {
  const smg_graph* g = ch->graph;
  const smgi_edge* e = &g->data.lower_edges[c->edge];
  smgi_qentry* q = smgi_q_at(ch, ch->q_count++);
  ch->q_frames += e->frame_count;
  q->edge = c->edge;
  q->seq = ch->next_seq++;
  q->W = W;
  q->M = smgi_xf_mul(
      W, smgi_xf_inv(ground_of(g, g->data.lower_nodes[e->from].frame)));
  q->s_start = s;
  q->s_end = c->s_end;
  q->seg_end = c->seg_end;
  q->rank = (uint16_t)rank;
  q->cand_count = (uint16_t)count;
  q->err = c->err;
}

/* The state planning continues from: after the last queued edge. */
static void tail_state(const smg_character* ch, uint32_t* node,
                       smgi_xform2* W, float* s, uint32_t* seg) {
  const smgi_qentry* q = smgi_q_at_c(ch, ch->q_count - 1u);
  const smgi_edge* e = &ch->graph->data.lower_edges[q->edge];
  *node = e->to;
  *W = smgi_xf_mul(q->W, disp_of(e));
  *s = q->s_end;
  *seg = q->seg_end;
}

float smgi_frames_ahead(const smg_character* ch) {
  /* kept incrementally: scanning the queue every step would touch every
   * planned entry and its edge record (cache misses with many characters) */
  return (float)ch->q_frames - ch->t;
}

/* The paper's back-up step, made safe: the last planned choice led to a
 * node whose best edge misses the path by more than the threshold. Back up
 * to that choice's node and try its next-best edges (up to SMGI_MAX_RANK,
 * never ones that move away from the wanted style): each alternative is
 * judged by the worse of its own error and its best follow-up's error. The
 * best alternative replaces the old choice only if it does better, so
 * backtracking can never make the plan worse than plain greedy. The entry
 * is then final (not backed up into again). Returns 1 if the plan changed. */
static int backtrack(smg_character* ch, uint32_t* budget) {
  const smg_graph* g = ch->graph;
  cand c[SMGI_MAX_CANDIDATES]; /* the caller's ranking must survive */
  if (ch->q_count < 2u || ch->backtracks >= SMGI_MAX_BACKTRACKS) return 0;
  smgi_qentry* lastp = smgi_q_at(ch, ch->q_count - 1u);
  if (lastp->rank >= SMGI_MAX_RANK) return 0;
  smgi_qentry last = *lastp;
  ch->backtracks++;
  uint32_t from = g->data.lower_edges[last.edge].from;
  uint32_t seg = smgi_q_at(ch, ch->q_count - 2u)->seg_end;
  uint32_t n = rank_node(ch, from, last.W, last.s_start, seg, c, NULL, NULL);
  spend(budget, work_of(c, n));
  /* the current choice in this ranking (an edge committed as part of a
   * searched sequence need not rank first on its own) */
  uint32_t cur = n;
  for (uint32_t i = 0; i < n; ++i)
    if (c[i].edge == last.edge) cur = i;
  if (cur == n) return 0;
  uint32_t limit = n < SMGI_MAX_RANK ? n : SMGI_MAX_RANK;
  cand child[SMGI_MAX_CANDIDATES];
  uint32_t best_r = cur;
  float best_v = INFINITY;
  for (uint32_t i = 0; i <= limit; ++i) {
    /* the best few, and the current choice wherever it ranks */
    if (i == limit && cur < limit) break;
    uint32_t r = i < limit ? i : cur;
    if (r != cur && c[r].pen > c[cur].pen) continue;
    uint32_t to = g->data.lower_edges[c[r].edge].to;
    uint32_t m = rank_node(ch, to, c[r].end, c[r].s_end, c[r].seg_end, child,
                           NULL, NULL);
    spend(budget, work_of(child, m));
    float v = c[r].err;
    if (m > 0 && child[0].err > v) v = child[0].err;
    if (v < best_v - 1e-4f || (r == cur && v <= best_v + 1e-4f)) {
      best_v = v;
      best_r = r;
    }
  }
  ch->q_count--;
  ch->q_frames -= g->data.lower_edges[last.edge].frame_count;
  push(ch, last.W, last.s_start, &c[best_r], best_r, n);
  smgi_q_at(ch, ch->q_count - 1u)->rank = (uint16_t)SMGI_MAX_RANK; /* final */
  return c[best_r].edge != last.edge;
}

void smgi_plan(smg_character* ch, uint32_t budget, float step_frames) {
  cand c[SMGI_MAX_CANDIDATES];
  /* this step's frames plus one to interpolate towards */
  const float min_frames = step_frames + 2.0f;
  /* The plan is topped up on the step where what is planned ahead falls
   * below the horizon. Characters created together and stepped with one
   * fixed dt would all cross it on the same steps - with 30 fps data and
   * 60 Hz steps only ever on every other step, whose frames then carried
   * all of a crowd's searches (2.5x the cost of the frames between). A
   * per-character phase spreads the crossings over the steps. The plan
   * ends on whole frames, so the phase spans a frame or a step, whichever
   * is longer: with half-frame steps, only a threshold that moves by a
   * whole frame meets both kinds of step. */
  const float span = step_frames > 1.0f ? step_frames : 1.0f;
  const float horizon_frames = ch->horizon * ch->fps + ch->plan_phase * span;
  for (;;) {
    if (ch->q_count == 0 || ch->q_count >= SMGI_QUEUE_CAP) return;
    float ahead = smgi_frames_ahead(ch);
    int forced = ahead < min_frames;
    if (!forced && (ahead >= horizon_frames || budget == 0)) return;
    uint32_t node, seg;
    smgi_xform2 W;
    float s;
    tail_state(ch, &node, &W, &s, &seg);
    uint32_t seq[SEQ_PATH_CAP], seq_len = 0;
    uint32_t n = rank_node(ch, node, W, s, seg, c, seq, &seq_len);
    if (n == 0) return; /* dead end: playback holds the last frame */
    spend(&budget, work_of(c, n));
    /* Backtracking can only help when the planned state is itself on the
     * path: when the character is already off it (new path far away, or
     * unavoidable drift), no local choice fixes that and the greedy pick
     * steers back. */
    if (!SEQ_NO_BT && c[0].err > ch->error_threshold &&
        start_error(ch, W, s, seg) <= ch->error_threshold &&
        backtrack(ch, &budget))
      continue;
    push(ch, W, s, &c[0], 0, n);
    if (c[0].err <= ch->error_threshold) ch->backtracks = 0;
    /* commit a little more of the best sequence at once (what its next
     * rankings would most likely choose anyway): fewer searches per
     * second of motion; each edge still faces the threshold */
    if (seq_len > 1u && seq[0] == c[0].edge) {
      float frames = (float)ch->graph->data.lower_edges[seq[0]].frame_count;
      for (uint32_t j = 1; j < seq_len && frames < SEQ_COMMIT_FRAMES &&
                           ch->q_count < SMGI_QUEUE_CAP; ++j) {
        cand x;
        tail_state(ch, &node, &W, &s, &seg);
        if (ch->graph->data.lower_edges[seq[j]].from != node) break;
        make_cand(ch, W, s, seg, seq[j], &x);
        if (x.err > ch->error_threshold) break;
        push(ch, W, s, &x, 0, 1);
        frames += (float)ch->graph->data.lower_edges[seq[j]].frame_count;
      }
    }
  }
}

void smgi_replan(smg_character* ch) {
  if (ch->q_count == 0) return;
  if (ch->time == 0.0 && ch->t == 0.0f) {
    /* nothing played yet: the first edge itself may be re-chosen */
    smgi_qentry h = *smgi_q_at(ch, 0);
    cand c[SMGI_MAX_CANDIDATES];
    uint32_t from = ch->graph->data.lower_edges[h.edge].from;
    uint32_t n = rank_node(ch, from, h.W, ch->progress, ch->seg, c, NULL, NULL);
    ch->q_count = 0;
    ch->q_frames = 0;
    ch->backtracks = 0;
    ch->pending.valid = 0;
    push(ch, h.W, ch->progress, &c[0], 0, n);
    return;
  }
  ch->q_count = 1; /* keep only the edge that is playing */
  ch->q_frames =
      ch->graph->data.lower_edges[smgi_q_at(ch, 0)->edge].frame_count;
  ch->backtracks = 0;
  smgi_qentry* h = smgi_q_at(ch, 0);
  const smgi_edge* e = &ch->graph->data.lower_edges[h->edge];
  smgi_xform2 end = smgi_xf_mul(h->W, disp_of(e));
  uint32_t seg = ch->seg;
  float dist;
  h->s_start = ch->progress;
  h->s_end = smgi_path_project_local(&ch->path, end.x, end.z, &seg, &dist);
  h->seg_end = seg;
  if (ch->pending.valid && ch->pending.seq != h->seq) ch->pending.valid = 0;
}

smg_result smgi_plan_start(smg_character* ch, float x, float z, float h) {
  const smg_graph* g = ch->graph;
  uint32_t LN = g->data.lower_node_count;
  /* a node of the initial style with out-edges, chosen by the seed */
  uint32_t matches = 0;
  for (uint32_t n = 0; n < LN; ++n)
    if (g->data.lower_nodes[n].label == ch->base_style &&
        g->data.lower_nodes[n].edge_count > 0)
      ++matches;
  uint32_t node = SMGI_NONE;
  if (matches > 0) {
    uint32_t pick = smgi_xorshift(&ch->rng) % matches;
    for (uint32_t n = 0; n < LN; ++n) {
      if (g->data.lower_nodes[n].label == ch->base_style &&
          g->data.lower_nodes[n].edge_count > 0) {
        if (pick == 0) {
          node = n;
          break;
        }
        --pick;
      }
    }
  } else {
    for (uint32_t n = 0; n < LN && node == SMGI_NONE; ++n)
      if (g->data.lower_nodes[n].edge_count > 0) node = n;
  }
  if (node == SMGI_NONE) return SMG_ERROR_BLOB_VALUE; /* no edges at all */
  cand c[SMGI_MAX_CANDIDATES];
  smgi_xform2 W = {x, z, smgi_wrap_angle(h)};
  uint32_t n = rank_node(ch, node, W, ch->progress, ch->seg, c, NULL, NULL);
  ch->q_head = 0;
  ch->q_count = 0;
  ch->q_frames = 0;
  ch->t = 0.0f;
  push(ch, W, ch->progress, &c[0], 0, n);
  ch->lower_node = node;
  return SMG_OK;
}
