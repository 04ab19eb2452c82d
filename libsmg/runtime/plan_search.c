/*
 * plan_search.c - the planner's sequence search (Kovar et al. 2002 path
 * synthesis, bounded for a per-frame budget; plan_search.h says what it
 * computes). It reads the step's inputs and the steering envelope
 * copied into the search context; it writes only the context.
 */
#include "plan_search.h"

#include <math.h>
#include <string.h>

/* The small helpers below run for every root sample or edge the search
 * weighs: inlined even where the compiler's size heuristics would make
 * calls of them (which they did as sample_cost grew). */
#if defined(__GNUC__) || defined(__clang__)
#define SAMPLE_INLINE static inline __attribute__((always_inline))
#else
#define SAMPLE_INLINE static inline
#endif

/* atan2 for the search's heading terms: a degree-11 minimax polynomial
 * on [0, 1] (max error about 1e-5 rad, i.e. micrometres at these
 * weights) instead of libm's atan2f, which was a fifth of all planning
 * instructions. (y, x) must not be (0, 0): every caller asks only for
 * the direction of a vector it found longer than a centimetre. NaN
 * propagates (the cost turns infinite). */
SAMPLE_INLINE float fast_atan2(float y, float x) {
  float ax = fabsf(x), ay = fabsf(y);
  float mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
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

/* Point at arc s on segment i, which holds it (cum[i] <= s <= cum[i +
 * 1]): smgi_path_eval's arithmetic, so the same result. Its clamp of the
 * segment parameter to [0, 1] is left out: rounding is monotonic, so
 * s - cum[i] lies in [0, len] and the quotient in [0, 1] already. */
SAMPLE_INLINE void seg_point(const smgi_path* p, uint32_t i, float s,
                            float* x, float* z) {
  float len = p->cum[i + 1u] - p->cum[i];
  float u = len > 1e-9f ? (s - p->cum[i]) / len : 0.0f;
  const float* a = &p->xz[2u * i];
  *x = a[0] + u * (a[2] - a[0]);
  *z = a[1] + u * (a[3] - a[1]);
}

/* smgi_path_eval without the call when the hint segment already holds s
 * (almost every query of a search: samples advance a little at a time);
 * same arithmetic, so the same result. */
SAMPLE_INLINE void path_at(const smgi_path* p, float s, uint32_t* seg,
                          float* x, float* z) {
  uint32_t i = *seg;
  if (p->count >= 2u && i + 1u < p->count && s >= p->cum[i] &&
      s <= p->cum[i + 1u] && s <= p->length) {
    seg_point(p, i, s, x, z);
    return;
  }
  smgi_path_eval(p, s, seg, x, z, NULL);
}

/* path_at for the pursuit point, a metre or more beyond the hint
 * segment's sample: when that segment does not hold s, the next one
 * often does (a quarter of all pursuit points on a path of 8 m segments
 * went through smgi_path_eval). An s strictly inside a segment lies on no
 * other, so smgi_path_eval would find that segment too: same result. */
SAMPLE_INLINE void path_ahead(const smgi_path* p, float s, uint32_t* seg,
                             float* x, float* z) {
  const uint32_t i = *seg, n = i + 1u;
  if (p->count >= 2u && n < p->count && s >= p->cum[i] && s <= p->cum[n] &&
      s <= p->length) {
    seg_point(p, i, s, x, z);
  } else if (n + 1u < p->count && s > p->cum[n] && s < p->cum[n + 1u] &&
             s <= p->length) {
    *seg = n;
    seg_point(p, n, s, x, z);
  } else {
    smgi_path_eval(p, s, seg, x, z, NULL);
  }
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
static void end_target(const smgi_step_in* in, float* x, float* z) {
  const smgi_path* p = in->path;
  if (p->count > 0) {
    *x = p->xz[2u * (p->count - 1u)];
    *z = p->xz[2u * (p->count - 1u) + 1u];
  } else {
    *x = in->anchor[0];
    *z = in->anchor[1];
  }
}

/* Penalty of an edge from which the wanted style cannot be reached. */
#define SMGI_STYLE_OUT_OF_REACH (4.0f * SMGI_STYLE_WEIGHT)

/* Style penalty of lower edge ei, labelled `label`, when `desired` is
 * wanted: one style weight for being out of style, and one more per hop's
 * worth of motion from the edge's end until the wanted style can be taken
 * (edge_style_time, style_time_hop: graph_derived.h). */
static float style_penalty(const smg_graph* g, uint32_t label, uint32_t ei,
                           uint32_t desired) {
  uint32_t S = g->data.style_count;
  if (desired >= S || label == desired) return 0.0f;
  /* the edge's from and to nodes' times, side by side */
  const uint8_t* t =
      smgi_derived_of(g)->edge_style_time +
      2u * ((size_t)desired * g->data.lower_edge_count + ei);
  if (t[0] == SMGI_HOPS_UNREACHABLE)
    return 0.0f; /* cannot get there from here: ignore */
  uint8_t h = t[1];
  if (h == SMGI_HOPS_UNREACHABLE) return SMGI_STYLE_OUT_OF_REACH;
  return SMGI_STYLE_WEIGHT *
         (1.0f + (float)h * smgi_derived_of(g)->style_time_hop[desired]);
}

/* Distance of a planned ground position from the path point at s. */
float smgi_plan_start_error(const smgi_path* path, smgi_xform2 W, float s,
                            uint32_t seg) {
  if (path->count < 2u) return 0.0f;
  float x, z;
  smgi_path_eval(path, s, &seg, &x, &z, NULL);
  return sqrtf((W.x - x) * (W.x - x) + (W.z - z) * (W.z - z));
}

/* An edge that spans arc lengths [s0, s1] is in style if its label is
 * wanted at either end: transition edges cross the point where the style
 * changes, and an edge ending exactly on a transition point is fine. */
static float edge_style_penalty(const smgi_seq_ctx* c, uint32_t label,
                                uint32_t ei, float s0, float s1) {
  uint32_t a = smgi_style_at(c->cons, s0), b = smgi_style_at(c->cons, s1);
  if (label == a || label == b) return 0.0f;
  return style_penalty(c->g, label, ei, b);
}

/* Lost (far off the path): the wanted style yields to the graph's most
 * agile one until the path is rejoined - a style that cannot turn (CMU
 * runs) would otherwise carry the character away for good. */
static float lost_style_penalty(const smg_graph* g, uint32_t label,
                                uint32_t ei) {
  return style_penalty(g, label, ei, smgi_derived_of(g)->agile_style);
}

/* Error of one root sample at (x, z) facing h, after arc u, having moved
 * (mx, mz) since the previous sample over w frames. *beyond gets the part
 * of its distance from the path (or the end point) that the root steering
 * cannot remove. */
static float sample_cost(const smgi_seq_ctx* c, float x, float z, float h,
                         float u, float mx, float mz, float w,
                         uint32_t* seg, float* beyond) {
  const smgi_path* p = c->track;
  float m2 = mx * mx + mz * mz;
  if (!c->following) {
    float dx = x - c->tx, dz = z - c->tz;
    float d = sqrtf(dx * dx + dz * dz);
    *beyond = d;
    /* at the end prefer motion that travels least and, there being no
     * idle clips, turns back towards the end point (circles around it
     * instead of walking off) */
    float sc = d + SMGI_END_SPEED_WEIGHT * sqrtf(m2) * c->fps /
                       (w > 1.0f ? w : 1.0f);
    if (d > SMGI_END_EPS)
      sc += SMGI_HEADING_WEIGHT * fabsf(smgi_wrap_angle(h - fast_atan2(-dx, -dz)));
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
  float ha = 0.0f; /* heading error towards the pursuit point */
  if (sr < p->length) {
    float qx, qz;
    uint32_t sg = *seg;
    path_ahead(p, sr + SMGI_PURSUIT_M + (c->lost ? 0.0f : d), &sg, &qx, &qz);
    float ax = qx - x, az = qz - z;
    if (ax * ax + az * az > 1e-4f)
      ha = fabsf(smgi_wrap_angle(h - fast_atan2(ax, az)));
  }
  /* as it will look after the root steering's correction (steer.c);
   * what lies beyond its reach, slowing for the turn included, is where
   * the character will really be off the path (the style yield judges
   * that, planner.c) */
  *beyond = d;
  if (!c->lost) {
    const float speed = c->fps * sqrtf(m2) / (w > 1.0f ? w : 1.0f);
    *beyond = smgi_steer_plan_view(&c->steer, u, speed, &d, &ha);
  }
  /* lost (far off the path): options differ little in distance (all move
   * away for the next second or two) but much in where they face; the
   * way back is towards the path near where the character left it */
  float sc = c->lost ? SMGI_LOST_DISTANCE_WEIGHT * d : d;
  sc += (c->lost ? SMGI_HEADING_WEIGHT_LOST : SMGI_HEADING_WEIGHT) * ha;
  if (m2 > 1e-4f) sc += SMGI_TRAVEL_WEIGHT * fabsf(smgi_wrap_angle(fast_atan2(mx, mz) - h));
  return sc;
}

/* Style penalty of lower edge ei (labelled `label`) at arc lengths
 * [a, b] of the path, while following it. */
static inline float follow_pen(const smgi_seq_ctx* c, uint32_t label,
                               uint32_t ei, float a, float b) {
  /* s0 <= a <= b: before the next constraint the wanted style is the one
   * at s0 (what edge_style_penalty would find with two scans) */
  if (b < c->style_end)
    return label == c->style0 ? 0.0f
                              : style_penalty(c->g, label, ei, c->style0);
  return edge_style_penalty(c, label, ei, a, b);
}

SAMPLE_INLINE float seq_pen(const smgi_seq_ctx* c, uint32_t label,
                            uint32_t ei, float a, float b) {
  if (!c->following)
    return c->yield ? 10.0f * lost_style_penalty(c->g, label, ei)
                    : 10.0f * style_penalty(c->g, label, ei, c->style0);
  if (c->lost || c->yield) return lost_style_penalty(c->g, label, ei);
  float p = follow_pen(c, label, ei, a, b);
  /* While the style changes (the motion playing is not what is wanted
   * everywhere ahead), a third style - neither the one playing nor one
   * wanted - is a detour nobody asked for: it costs what a wanted style
   * out of reach costs on top of its distance, so the search takes one
   * only where staying in the old style until a transition to the new is
   * more than that (four hops' worth of motion) longer. By distance alone
   * a run, near every walk, was the cheaper way from one walk to another
   * and the character ran through the point where it was to change. */
  if (p > 0.0f && label != c->style_now && label != c->style_next &&
      (c->style_now != c->style_next || c->style_now != c->style0))
    p += SMGI_STYLE_OUT_OF_REACH;
  return p;
}

/* One root sample of smgi_seq_step, `du` metres along the edge, standing
 * for w frames of the window: adds its cost and its distance beyond the
 * steering's reach to *out. Returns 0, with *out pruned, once cost plus
 * the penalty so far reaches the bound: costs and penalties only grow
 * (every term is >= 0), so the caller prunes it either way. */
static inline int step_sample(const smgi_seq_ctx* c, const smgi_seq_state* in,
                              smgi_seq_state* out, float x, float z, float h,
                              float du, float mx, float mz, float frames,
                              float w, float bound) {
  float b;
  const float sc =
      sample_cost(c, x, z, h, in->u + du, mx, mz, frames, &out->seg, &b);
  out->cost += sc * w / c->T;
  out->beyond += b * w / c->T;
  if (out->cost + in->pen >= bound) {
    out->cost = INFINITY;
    out->pen = in->pen;
    return 0;
  }
  return 1;
}

/* Append edge `ei` to the sequence in `in`: root samples at the edge's
 * middle (edges of 4+ frames) and end, each weighted by the frames it
 * stands for inside the window. */
void smgi_seq_step(smgi_seq_ctx* c, const smgi_seq_state* in, float cw,
                   float sw, uint32_t ei, float pen_scale, float bound,
                   smgi_seq_state* out) {
  /* the edge's search record (graph_derived.h): everything read below */
  const smgi_search_edge* e = &smgi_derived_of(c->g)->search_edges[ei];
  out->u = in->u + e->arc_length;
  out->f = in->f + (float)e->frame_count;
  /* the style penalty first: a sequence's value is at least its cost so
   * far plus its worst penalty, and costs only grow (every term is >=
   * 0), so an edge whose penalty alone reaches the bound (an edge of
   * another style, mostly) is pruned by the caller whatever its samples
   * cost: they are not computed */
  {
    const float pe = pen_scale * seq_pen(c, e->label, ei, c->s0 + in->u,
                                         c->s0 + out->u);
    out->pen = in->pen > pe ? in->pen : pe;
    if (in->cost + out->pen >= bound) {
      out->cost = INFINITY;
      return;
    }
  }
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
  out->first_edge = e->to_first_edge;
  out->edge_count = e->to_edge_count;
  out->seg = in->seg;
  out->cost = in->cost;
  out->beyond = in->beyond;
  /* the mid sample (edges of 4+ frames), then the end, while inside the
   * window */
  const uint32_t fc = e->frame_count;
  const float ffc = (float)fc;
  const float room = c->T - in->f; /* frames left in the window */
  float px = in->W.x, pz = in->W.z, kprev = 0.0f;
  int inside = 1;
  if (fc >= 4u) {
    const float k = (float)(fc / 2u);
    const float w = (k < room ? k : room) - (kprev < room ? kprev : room);
    if (w <= 0.0f) {
      inside = 0;
    } else {
      /* relative to the edge's start */
      const float* r = e->mid;
      const float x = in->W.x + (cw * r[0] + sw * r[1]);
      const float z = in->W.z + (-sw * r[0] + cw * r[1]);
      const float h = in->W.h + r[2];
      if (!step_sample(c, in, out, x, z, h, e->arc_length * k / ffc, x - px,
                       z - pz, k - kprev, w, bound))
        return;
      px = x;
      pz = z;
      kprev = k;
    }
  }
  if (inside) {
    const float k = ffc;
    const float w = (k < room ? k : room) - (kprev < room ? kprev : room);
    if (w > 0.0f &&
        !step_sample(c, in, out, out->W.x, out->W.z, out->W.h,
                     e->arc_length * k / ffc, out->W.x - px, out->W.z - pz,
                     k - kprev, w, bound))
      return;
  }
  if (!isfinite(out->cost)) out->cost = INFINITY;
}

/* Value of a finished (or budget-cut) sequence: an unfinished one is
 * extrapolated at its mean so far. */
static float seq_value(const smgi_seq_ctx* c, const smgi_seq_state* st) {
  float v = st->cost;
  if (st->f < c->T && st->f > 0.0f) v *= c->T / st->f;
  return v + st->pen;
}

/* Value of a sequence that stops choosing at `st`: the node's natural
 * continuation (derived node_next.trail, a few samples looked up, no edge
 * walk) stands for the rest of the window, style included. */
float smgi_seq_leaf(smgi_seq_ctx* c, smgi_seq_state st, float bound) {
  const smg_graph* g = c->g;
  const smgi_node_next* nx = &smgi_derived_of(g)->node_next[st.node];
  const float* tr = nx->trail;
  const float* tf = nx->trail_frames;
  const uint32_t* te = nx->trail_edge;
  const uint16_t* tl = nx->trail_label;
  const float f0 = st.f, u0 = st.u;
  float pf = 0.0f, pu = 0.0f, px = st.W.x, pz = st.W.z;
  /* beyond the window: can the motion turn towards the path soon? The
   * heading still missing once the node's best reachable turn (derived
   * node_next.turn) is spent costs like a heading error */
  if (c->following) {
    const smgi_path* p = c->track;
    float sr = c->s0 + st.u, rx, rz, qx, qz;
    uint32_t sg = st.seg;
    path_at(p, sr, &sg, &rx, &rz);
    float d = sqrtf((rx - st.W.x) * (rx - st.W.x) + (rz - st.W.z) * (rz - st.W.z));
    path_ahead(p, sr + SMGI_PURSUIT_M + (c->lost ? 0.0f : d), &sg, &qx, &qz);
    float ax = qx - st.W.x, az = qz - st.W.z;
    if (ax * ax + az * az > 1e-4f) {
      float need = smgi_wrap_angle(fast_atan2(ax, az) - st.W.h);
      const float* cap = nx->turn;
      float rest = fabsf(need) - (need > 0.0f ? cap[0] : cap[1]);
      if (rest > 0.0f) st.pen += SMGI_TURN_WEIGHT * rest;
    }
  }
  /* the value is at least cost + pen (an unfinished window only scales
   * the cost up): once that reaches the bound the leaf cannot win */
  if (st.cost + st.pen >= bound) return INFINITY;
  /* every sample is placed with the leaf's one heading (smgi_xf_mul's
   * arithmetic, its sine and cosine once) */
  float sw = 0.0f, cw = 1.0f;
  int placed = 0;
  for (uint32_t k = 0; k < SMGI_TRAIL_SAMPLES && st.f < c->T; ++k) {
    float fk = tf[k];
    if (fk <= pf) break; /* the continuation ended */
    /* the sample's style penalty first (as in smgi_seq_step): once it
     * alone reaches the bound, the sample's cost cannot save the leaf */
    if (te[k] != SMGI_NONE) {
      const uint32_t label = tl[k] != SMGI_TRAIL_LABEL_WIDE
                                 ? tl[k]
                                 : g->data.lower_edges[te[k]].label;
      float pe = 0.5f * seq_pen(c, label, te[k], c->s0 + u0 + pu,
                                c->s0 + u0 + tr[4u * k + 3u]);
      if (pe > st.pen) {
        st.pen = pe;
        if (st.cost + st.pen >= bound) return INFINITY;
      }
    }
    float room = c->T - f0;
    float w = (fk < room ? fk : room) - pf;
    if (!placed) {
      smgi_sincosf(st.W.h, &sw, &cw);
      placed = 1;
    }
    const float lx = tr[4u * k], lz = tr[4u * k + 1u];
    const float ex = st.W.x + (cw * lx + sw * lz);
    const float ez = st.W.z + (-sw * lx + cw * lz);
    const float eh = smgi_wrap_angle(st.W.h + tr[4u * k + 2u]);
    float b;
    float sc = sample_cost(c, ex, ez, eh, u0 + tr[4u * k + 3u], ex - px,
                           ez - pz, fk - pf, &st.seg, &b);
    st.cost += sc * w / c->T;
    st.beyond += b * w / c->T;
    st.f = f0 + (fk < room ? fk : room);
    if (st.cost + st.pen >= bound) return INFINITY;
    pf = fk;
    pu = tr[4u * k + 3u];
    px = ex;
    pz = ez;
  }
  float v = seq_value(c, &st);
  /* an unfinished window extrapolated at its mean, as seq_value does */
  c->leaf_beyond = st.f < c->T && st.f > 0.0f ? st.beyond * c->T / st.f
                                              : st.beyond;
  return v;
}

/* Depth-first branch and bound below `st`; *best is the bound. Branches
 * at the next `branches` nodes with several exits (the early choices
 * matter most; a node of one exit is no choice), then follows the natural
 * continuation to the end of the window (smgi_seq_leaf values what is left
 * when the graph or the budget ends first). */
void smgi_seq_dfs(smgi_seq_ctx* c, smgi_seq_state st, uint32_t branches,
                    uint32_t depth, float* best) {
  for (uint32_t d = 0; d < SMGI_SEQ_MAX_DEPTH && depth < SMGI_SEQ_PATH_CAP; ++d) {
    /* the node's out-edges, carried in the state from the edge that led
     * here (no read of the node's own records) */
    if (st.f >= c->T || st.edge_count == 0 || c->budget == 0) break;
    if (st.edge_count > 1u) {
      if (branches == 0) break;
      /* children cheapest first: good bounds early prune the most */
      smgi_seq_state kids[SMGI_SEQ_MAX_KIDS];
      uint32_t kid_edge[SMGI_SEQ_MAX_KIDS], nk = 0;
      uint32_t cnt = st.edge_count < SMGI_SEQ_MAX_KIDS ? st.edge_count : SMGI_SEQ_MAX_KIDS;
      float cw, sw;
      smgi_sincosf(st.W.h, &sw, &cw);
      for (uint32_t k = 0; k < cnt && c->budget > 0; ++k) {
        uint32_t ei = st.first_edge + k;
        smgi_seq_state nx;
        c->budget--;
        smgi_seq_step(c, &st, cw, sw, ei, 0.5f, *best, &nx);
        if (nx.cost + nx.pen >= *best) continue; /* costs only grow */
#if defined(__GNUC__) || defined(__clang__)
        /* a kid the search may descend into: its out-edge records and
         * its leaf record, cold on a big graph, start coming while the
         * other kids are weighed (a hint only). All of them: the records
         * of the edges it would branch over span several lines (48 bytes
         * each), and a leaf record two or three (128 bytes, unaligned) */
        {
          const smgi_derived* dv = smgi_derived_of(c->g);
          const uint32_t kn = nx.edge_count < SMGI_SEQ_MAX_KIDS
                                  ? nx.edge_count
                                  : SMGI_SEQ_MAX_KIDS;
          const char* ep = (const char*)&dv->search_edges[nx.first_edge];
          const size_t eb = (size_t)(kn ? kn : 1u) * sizeof(smgi_search_edge);
          for (size_t o = 0; o < eb; o += 64u) __builtin_prefetch(ep + o);
          __builtin_prefetch(ep + eb - 1u);
          const char* np = (const char*)&dv->node_next[nx.node];
          __builtin_prefetch(np);
          __builtin_prefetch(np + 64);
          __builtin_prefetch(np + sizeof(smgi_node_next) - 1u);
        }
#endif
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
        smgi_seq_dfs(c, kids[i], branches - 1u, depth + 1u, best);
      }
      return;
    }
    /* a single exit: no choice */
    smgi_seq_state nx;
    c->budget--;
    float cw, sw;
    smgi_sincosf(st.W.h, &sw, &cw);
    const uint32_t ei = st.first_edge;
    smgi_seq_step(c, &st, cw, sw, ei, 0.5f, *best, &nx);
    st = nx;
    c->path[depth++] = ei;
    if (st.cost + st.pen >= *best) return;
  }
  float v = smgi_seq_leaf(c, st, *best);
  if (v < *best) {
    *best = v;
    c->best_beyond = c->leaf_beyond;
    memcpy(c->best_path, c->path, sizeof(uint32_t) * depth);
    c->best_len = depth;
  }
}

void smgi_seq_init(smgi_seq_ctx* c, const smgi_step_in* in,
                   const smgi_steer_envelope* steer, uint32_t node,
                   smgi_xform2 W, float s, uint32_t seg) {
  c->g = in->graph;
  c->track = in->path;
  c->cons = in->cons;
  c->fps = in->fps;
  c->steer = smgi_steer_plan_of(steer);
  c->s0 = s;
  c->T = SMGI_SEQ_SECONDS * in->fps;
  c->following = in->path->count >= 2u && s < in->path->length - SMGI_END_EPS;
  c->lost = c->following &&
            smgi_plan_start_error(in->path, W, s, seg) > SMGI_LOST_DISTANCE;
  c->yield = 0;
  c->leaf_beyond = c->best_beyond = 0.0f;
  end_target(in, &c->tx, &c->tz);
  c->style0 = smgi_style_at(in->cons, s);
  c->style_end = smgi_next_constraint_arc(in->cons, s);
  c->style_next = smgi_style_at(in->cons, c->style_end);
  c->style_now = in->graph->data.lower_nodes[node].label;
  c->budget = smgi_seq_budget(steer);
}

