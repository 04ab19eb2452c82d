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
#define HEADING_WEIGHT 0.4f    /* metres of error per radian */
#define STYLE_WEIGHT 3.0f      /* metres of penalty per hop to the style:
                                  style constraints dominate path error */
#define END_SPEED_WEIGHT 0.5f  /* at the end prefer edges that travel less */
#define PROGRESS_WEIGHT 1.0f   /* metres of error per metre of lost progress */
#define LOST_DISTANCE 1.5f     /* off the path by more: style yields */
#define HEADING_WEIGHT_LOST 2.0f /* metres per radian when lost */
#define LOST_DISTANCE_WEIGHT 0.25f /* and distance counts less */

typedef struct cand {
  uint32_t edge;
  float score, err, s_end, pen;
  uint32_t seg_end;
  smgi_xform2 end; /* ground transform after the edge */
  uint32_t work;    /* edge evaluations spent on it (look-ahead included) */
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

/* How far a planned ground position is from following the path, given
 * that it should have progressed to arc length s_exp: its distance from
 * the path (nearest point near s_exp) plus a penalty when its progress
 * falls short of s_exp by more than a slack (looping, walking backwards).
 * Projection rather than "distance to the point at s_exp" lets a wide
 * turn cut a corner instead of being punished for it. Writes the
 * projected arc length and segment, and the tangent heading there. */
static float track_error(const smg_character* ch, float x, float z,
                         float s_exp, float slack, uint32_t* seg,
                         float* s_proj, float* tangent) {
  const smgi_path* p = &ch->path;
  float px, pz, d;
  smgi_path_eval(p, s_exp, seg, &px, &pz, NULL);
  float sp = smgi_path_project_local(p, x, z, seg, &d);
  float shortfall = s_exp - sp - slack;
  if (shortfall > 0.0f) d += PROGRESS_WEIGHT * shortfall;
  /* beyond the end: the overshoot counts as distance too */
  if (s_exp > p->length) {
    float ex = p->xz[2u * (p->count - 1u)] - x;
    float ez = p->xz[2u * (p->count - 1u) + 1u] - z;
    float de = sqrtf(ex * ex + ez * ez);
    if (de > d) d = de;
  }
  *s_proj = sp;
  if (tangent) {
    float tx, tz;
    uint32_t sg = *seg;
    smgi_path_eval(p, sp, &sg, &tx, &tz, tangent);
  }
  return d;
}

/* Value of standing at `node` with ground transform W and progress s:
 * where the node's natural continuation leads (derived node_look) against
 * the path further on, plus a heading error towards a pursuit point on
 * the path ahead (as far ahead as the character is off the path, at least
 * the look-ahead's length): on the path this is the tangent, off it the
 * direction that rejoins it. */
static float leaf_value(const smg_character* ch, uint32_t node,
                        smgi_xform2 W, float s, uint32_t seg, float hw) {
  const float* look = smgi_derived_of(ch->graph)->node_look + 4u * node;
  smgi_xform2 lk = {look[0], look[1], look[2]};
  smgi_xform2 end = smgi_xf_mul(W, lk);
  float sp;
  /* lost: progress along the path means nothing until it is rejoined */
  float slack = hw > HEADING_WEIGHT ? INFINITY : 0.5f * look[3];
  float d = track_error(ch, end.x, end.z, s + look[3], slack, &seg, &sp,
                        NULL);
  float ahead = look[3] > d ? look[3] : d;
  if (ahead < 0.5f) ahead = 0.5f;
  float px, pz, th;
  smgi_path_eval(&ch->path, sp + ahead, &seg, &px, &pz, &th);
  float dx = px - end.x, dz = pz - end.z;
  float want = dx * dx + dz * dz > 1e-4f ? atan2f(dx, dz) : th;
  /* the further off the path, the more the way back matters */
  float dh = fabsf(smgi_wrap_angle(end.h - want));
  /* lost: options differ little in distance (all move away at running
   * speed for the next second or two) but much in where they face */
  if (hw > HEADING_WEIGHT) return LOST_DISTANCE_WEIGHT * d + hw * dh;
  return d + hw * dh;
}

/* Bounded look-ahead below a candidate edge. Baked graphs can have edges
 * of two frames and nodes with one or two exits, so a one-edge greedy
 * choice cannot see that a turn becomes possible three edges later. This
 * walks the natural continuation (the original motion) for the next
 * `frames_left` frames and, at every branching node on the way, also
 * tries leaving it once (each exit judged by where its own natural
 * continuation leads, from the derived node_look table). The value is the
 * best, over these sequences, of the leaf's distance and heading error
 * plus how much further off the path the sequence gets on the way, plus
 * style penalties. Cost: about one edge
 * evaluation per natural edge plus two per alternative exit, capped by
 * *budget; deviations near the start are tried first, where they matter
 * most. */
static float look_value(const smg_character* ch, uint32_t node,
                        smgi_xform2 W, float s, uint32_t seg,
                        float frames_left, uint32_t* budget, float base) {
  const smg_graph* g = ch->graph;
  const smgi_derived* dv = smgi_derived_of(g);
  /* `worst` starts at the error the sequence starts from: only getting
   * further off the path counts, so a character that is already off it
   * (new path far away, a style that cannot turn) still compares its
   * options by where they lead instead of all scoring the same */
  float best = INFINITY, worst = base, pen_acc = 0.0f;
  /* lost: which way the character faces decides how soon it is back */
  const float hw = base > 0.0f ? HEADING_WEIGHT_LOST : HEADING_WEIGHT;
  for (uint32_t hop = 0; hop < 64u; ++hop) {
    const smgi_node* n = &g->data.lower_nodes[node];
    uint32_t nat = dv->natural_next[node];
    if (frames_left <= 0.0f || *budget == 0 || n->edge_count == 0) break;
    /* leave the natural motion here */
    for (uint32_t k = 0; k < n->edge_count && *budget > 0; ++k) {
      uint32_t ei = n->first_edge + k;
      if (ei == nat) continue;
      *budget = *budget > 2u ? *budget - 2u : 0u;
      const smgi_edge* e = &g->data.lower_edges[ei];
      smgi_xform2 end = smgi_xf_mul(W, disp_of(e));
      float s_t = s + e->arc_length;
      uint32_t sg = seg;
      float sp;
      float d = track_error(ch, end.x, end.z, s_t,
                            base > 0.0f ? INFINITY : 0.5f * e->arc_length, &sg,
                            &sp, NULL);
      float pen = 0.5f * (base > 0.0f ? lost_style_penalty(ch, e)
                                      : edge_style_penalty(ch, e, s, s_t));
      if (pen_acc > pen) pen = pen_acc;
      float excess = (worst > d ? worst : d) - base;
      if (excess + pen >= best) continue; /* cannot beat what we have */
      float lv = leaf_value(ch, e->to, end, sp, sg, hw);
      float v = (lv > excess ? lv : excess) + pen;
      if (v < best) best = v;
    }
    if (nat == SMGI_NONE) break;
    /* follow the natural motion one edge */
    (*budget)--;
    const smgi_edge* e = &g->data.lower_edges[nat];
    smgi_xform2 end = smgi_xf_mul(W, disp_of(e));
    float s_t = s + e->arc_length;
    float sp;
    float d = track_error(ch, end.x, end.z, s_t,
                          base > 0.0f ? INFINITY : 0.5f * e->arc_length, &seg,
                          &sp, NULL);
    if (d > worst) worst = d;
    /* the worst style mismatch along the way, not a sum: a long stretch
     * in the wrong style is no worse than a short one once the style
     * cannot follow the path at all */
    float pe = 0.5f * (base > 0.0f ? lost_style_penalty(ch, e)
                                   : edge_style_penalty(ch, e, s, s_t));
    if (pe > pen_acc) pen_acc = pe;
    W = end;
    s = sp;
    frames_left -= (float)e->frame_count;
    node = e->to;
    if (worst - base + pen_acc >= best) return best; /* only worse */
  }
  float lv = leaf_value(ch, node, W, s, seg, hw);
  float v = (lv > worst - base ? lv : worst - base) + pen_acc;
  return v < best ? v : best;
}

static void evaluate(const smg_character* ch, smgi_xform2 W, float s,
                     uint32_t seg, uint32_t edge_index, cand* out) {
  const smg_graph* g = ch->graph;
  const smgi_edge* e = &g->data.lower_edges[edge_index];
  const smgi_path* p = &ch->path;
  smgi_xform2 end = smgi_xf_mul(W, disp_of(e));
  out->end = end;
  out->edge = edge_index;
  out->work = 1u;
  out->seg_end = seg;
  out->s_end = s;

  /* where the edge's natural continuation leads: judges an edge by the
   * next SMGI_LOOK_SECONDS of motion, not only its own frames */
  const float* look = smgi_derived_of(g)->node_look + 4u * e->to;
  smgi_xform2 lk = {look[0], look[1], look[2]};
  smgi_xform2 end2 = smgi_xf_mul(end, lk);
  int following = p->count >= 2u && s < p->length - END_EPS;
  float score, err;
  if (following) {
    float arc = e->arc_length;
    float s_t = s + arc;
    uint32_t sg = seg;
    float sp;
    float e_end = track_error(ch, end.x, end.z, s_t, 0.5f * arc, &sg, &sp,
                              NULL);
    /* mid-edge root sample, placed from FRMI without FK */
    const smgi_node* from = &g->data.lower_nodes[e->from];
    smgi_xform2 M = smgi_xf_mul(W, smgi_xf_inv(ground_of(g, from->frame)));
    const float* r = g->data.frames[e->first_frame + e->frame_count / 2u]
                         .root2d;
    float mx, mz, spm;
    smgi_xf_point(M, r[0], r[1], &mx, &mz);
    uint32_t sm = seg;
    float e_mid = track_error(ch, mx, mz, s + 0.5f * arc, 0.5f * arc, &sm,
                              &spm, NULL);
    /* where this edge can lead within the look-ahead window. On the path
     * a sequence is worth the worse of its leaf and its largest error on
     * the way; when the character is lost (far off the path) errors are
     * counted from where the candidate leaves it, so the options still
     * compare by where they lead back. */
    float lost = start_error(ch, W, s, seg);
    uint32_t budget = SMGI_LOOK_BUDGET;
    float la = look_value(ch, e->to, end, sp, sg,
                          SMGI_SEARCH_SECONDS * ch->fps -
                              (float)e->frame_count,
                          &budget, lost > LOST_DISTANCE ? e_end : 0.0f);
    out->work = 1u + (SMGI_LOOK_BUDGET - budget);
    err = e_end > e_mid ? e_end : e_mid;
    /* lost: candidates last different times, so their own end errors are
     * not comparable; the look-ahead ends all sequences at the same time */
    score = lost > LOST_DISTANCE ? la : e_end + 0.5f * e_mid + la;
    out->s_end = sp;
    out->seg_end = sg;
    out->pen = lost > LOST_DISTANCE ? lost_style_penalty(ch, e)
                                    : edge_style_penalty(ch, e, s, s_t);
    score += out->pen;
  } else {
    float tx, tz;
    end_target(ch, &tx, &tz);
    float dx = end.x - tx, dz = end.z - tz;
    float lx = end2.x - tx, lz = end2.z - tz;
    err = 0.0f; /* nothing to follow: never backtrack */
    score = sqrtf(dx * dx + dz * dz) + sqrtf(lx * lx + lz * lz) +
            END_SPEED_WEIGHT * (e->arc_length + look[3]);
    /* nothing to follow: the asked-for style matters most */
    out->pen = 10.0f * style_penalty(ch, e, smgi_style_at(ch, s));
    score += out->pen;
  }
  out->score = isfinite(score) ? score : INFINITY;
  out->err = err;
}

/* Score all out-edges of `node` from (W, s, seg), sorted best first
 * (ties by edge index, so the order is deterministic). */
static uint32_t rank_node(const smg_character* ch, uint32_t node,
                          smgi_xform2 W, float s, uint32_t seg, cand* c) {
  const smgi_node* n = &ch->graph->data.lower_nodes[node];
  uint32_t count = n->edge_count < SMGI_MAX_CANDIDATES ? n->edge_count
                                                       : SMGI_MAX_CANDIDATES;
  for (uint32_t k = 0; k < count; ++k) {
    cand x;
    evaluate(ch, W, s, seg, n->first_edge + k, &x);
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
  uint32_t n = rank_node(ch, from, last.W, last.s_start, seg, c);
  spend(budget, work_of(c, n));
  uint32_t cur = last.rank < n ? last.rank : n - 1u;
  uint32_t limit = n < SMGI_MAX_RANK ? n : SMGI_MAX_RANK;
  cand child[SMGI_MAX_CANDIDATES];
  uint32_t best_r = cur;
  float best_v = INFINITY;
  for (uint32_t r = 0; r < limit; ++r) {
    if (r != cur && c[r].pen > c[cur].pen) continue;
    uint32_t to = g->data.lower_edges[c[r].edge].to;
    uint32_t m = rank_node(ch, to, c[r].end, c[r].s_end, c[r].seg_end, child);
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
  return best_r != cur;
}

void smgi_plan(smg_character* ch, uint32_t budget, float min_frames) {
  cand c[SMGI_MAX_CANDIDATES];
  const float horizon_frames = ch->horizon * ch->fps;
  for (;;) {
    if (ch->q_count == 0 || ch->q_count >= SMGI_QUEUE_CAP) return;
    float ahead = smgi_frames_ahead(ch);
    int forced = ahead < min_frames;
    if (!forced && (ahead >= horizon_frames || budget == 0)) return;
    uint32_t node, seg;
    smgi_xform2 W;
    float s;
    tail_state(ch, &node, &W, &s, &seg);
    uint32_t n = rank_node(ch, node, W, s, seg, c);
    if (n == 0) return; /* dead end: playback holds the last frame */
    spend(&budget, work_of(c, n));
    /* Backtracking can only help when the planned state is itself on the
     * path: when the character is already off it (new path far away, or
     * unavoidable drift), no local choice fixes that and the greedy pick
     * steers back. */
    if (c[0].err > ch->error_threshold &&
        start_error(ch, W, s, seg) <= ch->error_threshold &&
        backtrack(ch, &budget))
      continue;
    push(ch, W, s, &c[0], 0, n);
    if (c[0].err <= ch->error_threshold) ch->backtracks = 0;
  }
}

void smgi_replan(smg_character* ch) {
  if (ch->q_count == 0) return;
  if (ch->time == 0.0 && ch->t == 0.0f) {
    /* nothing played yet: the first edge itself may be re-chosen */
    smgi_qentry h = *smgi_q_at(ch, 0);
    cand c[SMGI_MAX_CANDIDATES];
    uint32_t from = ch->graph->data.lower_edges[h.edge].from;
    uint32_t n = rank_node(ch, from, h.W, ch->progress, ch->seg, c);
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
  uint32_t n = rank_node(ch, node, W, ch->progress, ch->seg, c);
  ch->q_head = 0;
  ch->q_count = 0;
  ch->q_frames = 0;
  ch->t = 0.0f;
  push(ch, W, ch->progress, &c[0], 0, n);
  ch->lower_node = node;
  return SMG_OK;
}
