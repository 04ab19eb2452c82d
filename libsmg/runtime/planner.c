/*
 * planner.c - keeps the lower queue planned ahead: the paper's search
 * (III.C.2), made incremental and bounded.
 *
 * Each time what is planned beyond the playhead falls below the horizon
 * (plus the character's phase, which spreads a crowd's searches over the
 * frames), the node where the plan ends is ranked:
 *  - rank_pass scores every out-edge by the best edge sequence starting
 *    with it that covers SMGI_SEQ_SECONDS (plan_search.c: path distance,
 *    heading and travel terms along the sequence, style penalties from
 *    the derived time to each style, branch and bound under a budget);
 *  - rank_node ranks again with the style yielding to the graph's most
 *    agile one when even the best sequence in the wanted style stays off
 *    the path by more than SMGI_YIELD_ERROR on average beyond what the
 *    steering removes, or the character has drifted off by more than a
 *    runner still running cuts on purpose (yield_drift) and that
 *    sequence does not bring it back (failing_to_follow).
 * The best edge is pushed with its distance error (where its end leaves
 * the character from the path, the paper's threshold test), followed by
 * up to SMGI_SEQ_COMMIT_FRAMES of the best sequence's next edges (fewer
 * searches per second of motion). When the best edge misses the threshold
 * while the plan is itself on the path, backtrack (the paper's back-up
 * step, made safe) re-ranks the previous planned choice and keeps an
 * alternative only if it does better.
 * Work per step is bounded by a budget of edge evaluations; only when the
 * playhead would otherwise run out is it exceeded, by what this step
 * needs. Path or constraint edits (smgi_replan) drop the planned entries
 * and keep the one playing.
 */
#include <math.h>
#include <string.h>

#include "planner.h"

#include "plan_search.h"
#include "stop_match.h"

/* The planner's job: its own state, the timeline it extends and its
 * inputs (planner.h). */
typedef struct job {
  smgi_planner* pl;
  smgi_lower* lower;
  const smgi_step_in* in;
  const smgi_steer_envelope* steer;
} job;

typedef struct cand {
  uint32_t edge;
  float score, err, s_end, pen;
  uint32_t seg_end;
  smgi_xform2 end; /* ground transform after the edge */
  uint32_t work;    /* edge evaluations spent on it (look-ahead included) */
  float seq_beyond; /* its best sequence's mean distance from the path
                     * beyond what the steering removes */
} cand;

/* The paper's distance error of an edge whose end lies d from the path,
 * less what the root steering takes out by the edge's end (steer.c), `u`
 * metres of planned motion before it: the threshold judges the motion as
 * it will be shown. */
static float edge_error(const job* j, const smgi_edge* e,
                        float u, float d) {
  float speed = j->in->fps * e->arc_length / (float)e->frame_count;
  float reach =
      smgi_steer_plan_reach(j->steer, u + e->arc_length, speed);
  return d > reach ? d - reach : 0.0f;
}

/* A committed edge's bookkeeping without a search: where it ends, the
 * progress there and its distance error, `u` metres into the sequence
 * that was ranked (the search valued it with the steering's reach from
 * the sequence's start, so the threshold does too). */
static void make_cand(const job* j, smgi_xform2 W, float s,
                      uint32_t seg, float u, uint32_t ei, cand* x) {
  const smgi_edge* e = &j->in->graph->data.lower_edges[ei];
  memset(x, 0, sizeof *x);
  x->edge = ei;
  x->end = smgi_xf_mul(W, smgi_edge_displacement(e));
  x->s_end = s + e->arc_length;
  x->seg_end = seg;
  x->work = 1u;
  if (j->in->path->count >= 2u) {
    float d;
    uint32_t sg = seg;
    float sp = smgi_path_project_local(j->in->path, x->end.x, x->end.z, &sg, &d);
    x->s_end = smgi_clampf(sp, s, s + e->arc_length + 0.25f);
    x->seg_end = sg;
    if (s < j->in->path->length - SMGI_END_EPS) x->err = edge_error(j, e, u, d);
  }
}

/* Coming to rest at the end in a style that does not stop in one step
 * (a run, graph_derived.h): for the last metres the graph's stop style
 * (its fastest walk) is wanted instead, as a runner slows to a walk
 * before stopping - from where that walk, braking over the steering's
 * stop_seconds plus SMGI_STEER_SETTLE_SECONDS, reaches the end. Where the
 * graph needs more of the run to reach a walk than that, the run brakes
 * itself with shorter strides (steer.c, brake_stride). */
static void slow_to_stop(const job* j, smgi_seq_ctx* sc, float s) {
  const smgi_derived* dv = smgi_derived_of(j->in->graph);
  const smgi_steer_envelope* st = j->steer;
  if (!st->enabled || j->in->path->count < 2u ||
      dv->stop_style == SMGI_NONE || dv->style_can_stop[sc->style0])
    return;
  const float way = dv->stop_speed *
                        (st->stop_seconds + SMGI_STEER_SETTLE_SECONDS) +
                    SMGI_STEER_STOP_NEAR;
  if (j->in->path->length - s >= way) return;
  sc->style0 = dv->stop_style;
  sc->style_end = INFINITY;
}

static void tail_state(const job* j, uint32_t* node, smgi_xform2* W,
                       float* s, uint32_t* seg);
static void push(const job* j, smgi_xform2 W, float s, const cand* c,
                 uint32_t rank, uint32_t count);

/* Queue a whole route from the stop matching (stop_match.h) as planned
 * edges, each placed after the one before, from the plan's tail state. */
static void push_route(const job* j, const smgi_stop_route* r, uint32_t node,
                       smgi_xform2 W, float s, uint32_t seg) {
  const smg_graph* g = j->in->graph;
  float u = 0.0f;
  for (uint32_t k = 0; k < r->count; ++k) {
    cand x;
    if (k > 0) tail_state(j, &node, &W, &s, &seg);
    make_cand(j, W, s, seg, u, r->edges[k], &x);
    push(j, W, s, &x, 0, 1);
    u += g->data.lower_edges[r->edges[k]].arc_length;
  }
}

/* Stopping motion from the data (stop_match.h): once the plan ends within
 * the graph's longest stop plus the horizon of the end, a route into a
 * stop whose rest lands on the end is planned instead of the search's
 * choice, and its rest marked for the steering, which plays it to rest.
 * Graphs without stops never get here (their stop is the IK's). Returns
 * 1 if it planned one. */
static int plan_data_stop(const job* j, uint32_t node, smgi_xform2 W,
                          float s, uint32_t seg) {
  const smg_graph* g = j->in->graph;
  if (smgi_derived_of(g)->stop_count == 0 || !j->steer->enabled ||
      j->in->path->count < 2u || j->lower->stop_seq != SMGI_NONE)
    return 0;
  const float way = j->in->path->length - s;
  if (way < 0.0f || way > smgi_derived_of(g)->stop_longest +
                              j->steer->own_speed * j->pl->horizon)
    return 0;
  smgi_stop_route r;
  if (!smgi_stop_match(g, j->in->path, node, W, s, &r) ||
      j->lower->count + r.count > SMGI_QUEUE_CAP)
    return 0;
  push_route(j, &r, node, W, s, seg);
  j->lower->stop_seq = smgi_q_at(j->lower, j->lower->count - 1u)->seq;
  j->lower->stop_offset = r.rest_offset;
  return 1;
}

/* Starting motion from the data (stop_match.h): where the plan stands
 * still in a stop's or start's standing frames with more of the path
 * ahead than the graph's stops need to come to rest again, a route into
 * the start that moves off soonest along the path is planned instead of
 * the search's choice (the search, valuing two seconds, cannot tell one
 * standing edge from another). Graphs without starts never get here.
 * Returns 1 if it planned one. */
static int plan_data_start(const job* j, uint32_t node, smgi_xform2 W,
                           float s, uint32_t seg) {
  const smg_graph* g = j->in->graph;
  if (smgi_derived_of(g)->start_count == 0 || !j->steer->enabled ||
      j->in->path->count < 2u ||
      j->in->path->length - s <= smgi_derived_of(g)->stop_longest ||
      !smgi_stop_still(g, g->data.lower_nodes[node].frame))
    return 0;
  smgi_stop_route r;
  if (!smgi_start_match(g, j->in->path, seg, node, W, &r) ||
      j->lower->count + r.count > SMGI_QUEUE_CAP)
    return 0;
  push_route(j, &r, node, W, s, seg);
  return 1;
}

/* Score all out-edges of `node` from (W, s, seg), sorted best first
 * (ties by edge index, so the order is deterministic). */
static uint32_t rank_pass(const job* j, uint32_t node,
                          smgi_xform2 W, float s, uint32_t seg, cand* c,
                          uint32_t* seq, uint32_t* seq_len, int yield,
                          int* following) {
  const smg_graph* g = j->in->graph;
  const smgi_node* n = &g->data.lower_nodes[node];
  uint32_t count = n->edge_count < SMGI_MAX_CANDIDATES ? n->edge_count
                                                       : SMGI_MAX_CANDIDATES;
  smgi_seq_ctx sc;
  smgi_seq_init(&sc, j->in, j->steer, node, W, s, seg);
  sc.best_len = 0;
  sc.yield = yield;
  slow_to_stop(j, &sc, s);
  *following = sc.following && !sc.lost;
  smgi_seq_state root = {node, W, 0.0f, 0.0f, 0.0f, 0.0f, seg, 0.0f, 0u, 0u};
  smgi_seq_state first[SMGI_MAX_CANDIDATES];
  float best = INFINITY;
  float cw, sw;
  smgi_sincosf(W.h, &sw, &cw);
  for (uint32_t k = 0; k < count; ++k) {
    cand* x = &c[k];
    uint32_t ei = n->first_edge + k;
    const smgi_edge* e = &g->data.lower_edges[ei];
    if (sc.budget > 0) sc.budget--;
    smgi_seq_step(&sc, &root, cw, sw, ei, 1.0f, INFINITY, &first[k]);
    x->edge = ei;
    x->end = first[k].W;
    x->err = 0.0f; /* nothing to follow: never back up */
    x->pen = first[k].pen;
    /* progress: where the edge's end projects, kept within what it
     * travelled (a re-projection keeps the sequences' reference anchored
     * to where the character actually is) */
    uint32_t sg = seg;
    float s_end = s + e->arc_length, d;
    if (j->in->path->count >= 2u) {
      float sp = smgi_path_project_local(j->in->path, x->end.x, x->end.z, &sg,
                                         &d);
      s_end = smgi_clampf(sp, s, s + e->arc_length + 0.25f);
      /* the paper's distance error (what the threshold is compared
       * with): how far the edge leaves the character from the path */
      if (sc.following) x->err = edge_error(j, e, 0.0f, d);
    }
    x->s_end = s_end;
    x->seg_end = sg;
    x->score = smgi_seq_leaf(&sc, first[k], INFINITY);
    x->seq_beyond = sc.leaf_beyond;
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
    smgi_seq_dfs(&sc, first[order[i]], SMGI_SEQ_BRANCHES, 1u, &b);
    pool -= share - sc.budget;
    if (b < best) { /* found a better sequence below this candidate */
      x->score = b;
      x->seq_beyond = sc.best_beyond;
      best = b;
    } else if (isfinite(best)) {
      x->score = best + x->score;
    }
  }
  for (uint32_t k = 0; k < count; ++k) {
    c[k].work = 1u;
    if (!isfinite(c[k].score)) c[k].score = INFINITY;
  }
  c[0].work = smgi_seq_budget(j->steer) - pool;
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

/* How far the character may be off the path before the wanted `style`
 * counts as failing to follow (SMGI_YIELD_DRIFT). A style faster than the
 * walk-run transition (one that cannot stop in one step, graph_derived.h)
 * is still that style to see while it moves faster than midway between
 * the graph's walk (its stop style) and its own speed; a runner slowed
 * for a sharp turn but still running cuts what it cannot turn at that
 * speed: a right angle, at the tightest radius friction allows there
 * (v^2 / (SMGI_STEER_GRIP g)), leaves it (sqrt 2 - 1) r off the corner.
 * Off by no more than that, it is doing what a runner does, not failing
 * to follow, and the run asked for is kept (on a 90-degree corner the
 * sparse CMU graph's runner was 0.25-0.42 m off, and 0.25 m handed it to
 * the walk for 2 m after the corner). */
static float yield_drift(const job* j, float s) {
  const smgi_derived* dv = smgi_derived_of(j->in->graph);
  const uint32_t style = smgi_style_at(j->in->cons, s);
  const float own = j->steer->own_speed;
  if (!j->steer->enabled || style >= j->in->graph->data.style_count ||
      dv->style_can_stop[style] || dv->stop_style == SMGI_NONE ||
      !(own > dv->stop_speed))
    return SMGI_YIELD_DRIFT;
  const float v = 0.5f * (dv->stop_speed + own);
  const float cut = (sqrtf(2.0f) - 1.0f) * v * v /
                    (SMGI_STEER_GRIP * SMGI_GRAVITY);
  return cut > SMGI_YIELD_DRIFT ? cut : SMGI_YIELD_DRIFT;
}

/* The wanted style is failing to follow: the character is further off
 * the path than yield_drift, and even the best sequence in that style
 * (`best`) stays off by as much on average beyond what the root steering
 * removes. Being off alone is no failure while the steering is taking the
 * offset out: a runner swings wide out of a corner it cut, and yielding
 * there, on the character's distance alone, traded the run for a walk
 * that followed a little better for a moment (on a graph of another
 * performer's straight runs: 2 m of walking after a left corner, 0.46 m
 * off at most, and none after the mirrored right one, 0.17 m off). */
static int failing_to_follow(const job* j, float s, const cand* best) {
  const float drift = yield_drift(j, s);
  return j->in->path_error > drift && best->seq_beyond > drift;
}

/* Rank the out-edges of `node`; when even the best sequence in the wanted
 * style stays off the path by more than SMGI_YIELD_ERROR on average beyond
 * what the root steering removes (a run asked for where the path turns
 * tighter than a run can be bent), or when the style is failing to follow
 * (failing_to_follow), rank again letting the style yield to the most
 * agile one - before the character is lost. An error the steering
 * removes is no reason to drop the style: a run bent around a curve is
 * still the run asked for, and a runner slows for a sharp turn (steer.c)
 * but keeps running; that the steering turns short of the path at some
 * point ahead is no reason either (it cuts a turn too tight for any
 * speed, within the drift). */
static uint32_t rank_node(const job* j, uint32_t node,
                          smgi_xform2 W, float s, uint32_t seg, cand* c,
                          uint32_t* seq, uint32_t* seq_len) {
  int following;
  uint32_t n = rank_pass(j, node, W, s, seg, c, seq, seq_len, 0, &following);
  if (n > 0 && following &&
      (c[0].seq_beyond > SMGI_YIELD_ERROR ||
       failing_to_follow(j, s, &c[0])) &&
      smgi_derived_of(j->in->graph)->agile_style != smgi_style_at(j->in->cons, s)) {
    n = rank_pass(j, node, W, s, seg, c, seq, seq_len, 1, &following);
    for (uint32_t i = 0; i < n; ++i)
      c[i].work = i == 0 ? 2u * smgi_seq_budget(j->steer) : 0u;
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

static void push(const job* j, smgi_xform2 W, float s, const cand* c,
                 uint32_t rank, uint32_t count) {
  const smg_graph* g = j->in->graph;
  const smgi_edge* e = &g->data.lower_edges[c->edge];
  const uint32_t i = j->lower->count++;
  smgi_qentry* q = smgi_q_at(j->lower, i);
  j->lower->frames += e->frame_count;
  q->edge = c->edge;
  q->seq = j->lower->next_seq++;
  /* beyond the next two, stored (W and M) as before the steering's
   * pending correction (smgi_q_ground) */
  if (i >= 2u) W = smgi_lag_undo(&j->lower->lag, W);
  q->W = W;
  q->M = smgi_xf_mul(
      W, smgi_xf_inv(smgi_frame_ground(g, g->data.lower_nodes[e->from].frame)));
  q->s_start = s;
  q->s_end = c->s_end;
  q->seg_end = c->seg_end;
  q->rank = (uint16_t)rank;
  q->cand_count = (uint16_t)count;
  q->err = c->err;
}

/* The state planning continues from: after the last queued edge. */
static void tail_state(const job* j, uint32_t* node,
                       smgi_xform2* W, float* s, uint32_t* seg) {
  const smgi_qentry* q = smgi_q_at_c(j->lower, j->lower->count - 1u);
  const smgi_edge* e = &j->in->graph->data.lower_edges[q->edge];
  *node = e->to;
  *W = smgi_xf_mul(smgi_q_ground(j->lower, j->lower->count - 1u), smgi_edge_displacement(e));
  *s = q->s_end;
  *seg = q->seg_end;
}

/* The paper's back-up step, made safe: the last planned choice led to a
 * node whose best edge misses the path by more than the threshold. Back up
 * to that choice's node and try its next-best edges (up to SMGI_MAX_RANK,
 * never ones that move away from the wanted style): each alternative is
 * judged by the worse of its own error and its best follow-up's error. The
 * best alternative replaces the old choice only if it does better, so
 * backtracking can never make the plan worse than plain greedy. The entry
 * is then final (not backed up into again). Returns 1 if the plan changed. */
static int backtrack(const job* j, uint32_t* budget) {
  const smg_graph* g = j->in->graph;
  cand c[SMGI_MAX_CANDIDATES]; /* the caller's ranking must survive */
  if (j->lower->count < 2u || j->pl->backtracks >= SMGI_MAX_BACKTRACKS) return 0;
  smgi_qentry* lastp = smgi_q_at(j->lower, j->lower->count - 1u);
  if (lastp->rank >= SMGI_MAX_RANK) return 0;
  smgi_qentry last = *lastp;
  last.W = smgi_q_ground(j->lower, j->lower->count - 1u);
  j->pl->backtracks++;
  uint32_t from = g->data.lower_edges[last.edge].from;
  uint32_t seg = smgi_q_at(j->lower, j->lower->count - 2u)->seg_end;
  uint32_t n = rank_node(j, from, last.W, last.s_start, seg, c, NULL, NULL);
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
    uint32_t m = rank_node(j, to, c[r].end, c[r].s_end, c[r].seg_end, child,
                           NULL, NULL);
    spend(budget, work_of(child, m));
    float v = c[r].err;
    if (m > 0 && child[0].err > v) v = child[0].err;
    if (v < best_v - 1e-4f || (r == cur && v <= best_v + 1e-4f)) {
      best_v = v;
      best_r = r;
    }
  }
  j->lower->count--;
  j->lower->frames -= g->data.lower_edges[last.edge].frame_count;
  push(j, last.W, last.s_start, &c[best_r], best_r, n);
  smgi_q_at(j->lower, j->lower->count - 1u)->rank = (uint16_t)SMGI_MAX_RANK; /* final */
  return c[best_r].edge != last.edge;
}

/* Seconds the planner keeps planned ahead. Steering moves the queued plan
 * with the character and plans it again once the correction adds up
 * (SMGI_STEER_REPLAN_*): whatever lies beyond what the next re-plan keeps
 * is searched for nothing, so while following, the plan reaches
 * SMGI_STEER_HORIZON ahead (the search itself still judges 2 s sequences).
 * Near the end the full horizon comes back: choosing the stop frame needs
 * the braking distance and a gait cycle beyond it planned. */
static float plan_horizon(const job* j) {
  const smgi_steer_envelope* s = j->steer;
  const float full = j->pl->horizon;
  if (!s->enabled || j->in->path->count < 2u || full <= SMGI_STEER_HORIZON)
    return full;
  const float to_end = j->in->path->length - j->in->progress;
  const float near = s->own_speed * (s->stop_seconds + SMGI_STEER_STOP_SCAN +
                                     SMGI_STEER_SETTLE_SECONDS + full) +
                     SMGI_STEER_STOP_NEAR;
  return to_end > near ? SMGI_STEER_HORIZON : full;
}

static void plan(const job* j, uint32_t budget, float step_frames) {
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
  const float horizon = plan_horizon(j);
  const float horizon_frames = horizon * j->in->fps + j->pl->phase * span;
  /* the steering follows the path, away from its end (plan_horizon) */
  const int steered = horizon < j->pl->horizon;
  for (;;) {
    if (j->lower->count == 0 || j->lower->count >= SMGI_QUEUE_CAP) return;
    float ahead = smgi_frames_ahead(j->lower);
    int forced = ahead < min_frames;
    if (!forced && (ahead >= horizon_frames || budget == 0)) return;
    uint32_t node, seg;
    smgi_xform2 W;
    float s;
    tail_state(j, &node, &W, &s, &seg);
    if (plan_data_stop(j, node, W, s, seg) ||
        plan_data_start(j, node, W, s, seg))
      continue;
    uint32_t seq[SMGI_SEQ_PATH_CAP], seq_len = 0;
    uint32_t n = rank_node(j, node, W, s, seg, c, seq, &seq_len);
    if (n == 0) return; /* dead end: playback holds the last frame */
    spend(&budget, work_of(c, n));
    /* Backtracking can only help when the planned state is itself on the
     * path: when the character is already off it (new path far away, or
     * unavoidable drift), no local choice fixes that and the greedy pick
     * steers back. */
    const int missed = c[0].err > j->pl->error_threshold;
    const int on_path =
        !missed || smgi_plan_start_error(j->in->path, W, s, seg) <=
                       j->pl->error_threshold;
    if (missed && on_path && backtrack(j, &budget)) continue;
    push(j, W, s, &c[0], 0, n);
    if (!missed) j->pl->backtracks = 0;
    /* commit a little more of the best sequence at once (what its next
     * rankings would most likely choose anyway): fewer searches per
     * second of motion. Each edge still faces the threshold, which ends
     * the commit where the next ranking could back up. Where none would
     * - the first edge missed from a plan already off the path - while
     * the steering follows away from the end, the first edge's error is
     * the bar instead: an edge leaving the plan no further off than the
     * one just taken anyway is committed too, rather than ranking again
     * after each edge of a few frames (on the big graph a third of the
     * rankings started so, its plan drifting off ahead of the steering;
     * docs/runtime.md, Performance). */
    const float bound =
        steered && !on_path ? c[0].err : j->pl->error_threshold;
    if (seq_len > 1u && seq[0] == c[0].edge) {
      float frames = (float)j->in->graph->data.lower_edges[seq[0]].frame_count;
      float u = j->in->graph->data.lower_edges[seq[0]].arc_length;
      for (uint32_t k = 1; k < seq_len && frames < SMGI_SEQ_COMMIT_FRAMES &&
                           j->lower->count < SMGI_QUEUE_CAP; ++k) {
        cand x;
        tail_state(j, &node, &W, &s, &seg);
        if (j->in->graph->data.lower_edges[seq[k]].from != node) break;
        make_cand(j, W, s, seg, u, seq[k], &x);
        if (x.err > bound) break;
        push(j, W, s, &x, 0, 1);
        frames += (float)j->in->graph->data.lower_edges[seq[k]].frame_count;
        u += j->in->graph->data.lower_edges[seq[k]].arc_length;
      }
    }
  }
}

/* Setting off from rest in a stop's standing frames (stop_match.h): the
 * edge playing would stand on to its end, and the graph's way into a
 * start stand on through its standing (the synthetic test graph: 1.4 s
 * before moving off). Standing frames are one pose, so the plan starts
 * over in the start that moves off soonest along the path, at its last
 * standing node, placed where the character stands (smgi_start_jump);
 * the rest stage covers the change of stance as it covers any start
 * from rest. Returns 1 if it did. */
static int restart_from_rest(const job* j) {
  const smg_graph* g = j->in->graph;
  if (smgi_derived_of(g)->start_count == 0 || !j->steer->enabled ||
      j->in->path->count < 2u ||
      j->in->path->length - j->in->progress <= smgi_derived_of(g)->stop_longest)
    return 0;
  const smgi_qentry* h = smgi_q_at(j->lower, 0);
  const smgi_edge* e = &g->data.lower_edges[h->edge];
  const uint32_t f = e->first_frame + (uint32_t)j->lower->t;
  if (!smgi_stop_still(g, f)) return 0;
  const smgi_xform2 W =
      smgi_xf_mul(smgi_q_placement(j->lower, 0), smgi_frame_ground(g, f));
  smgi_stop_route r;
  if (!smgi_start_jump(g, j->in->path, j->in->seg, W, &r)) return 0;
  j->lower->count = 0;
  j->lower->frames = 0;
  j->lower->t = 0.0f;
  j->lower->node = g->data.lower_edges[r.edges[0]].from;
  j->lower->stop_seq = SMGI_NONE;
  j->pl->backtracks = 0;
  smgi_lag_reset(&j->lower->lag);
  cand x;
  make_cand(j, W, j->in->progress, j->in->seg, 0.0f, r.edges[0], &x);
  push(j, W, j->in->progress, &x, 0, 1);
  float u = g->data.lower_edges[r.edges[0]].arc_length;
  for (uint32_t k = 1; k < r.count; ++k) {
    uint32_t node, seg;
    smgi_xform2 Wk;
    float s;
    tail_state(j, &node, &Wk, &s, &seg);
    make_cand(j, Wk, s, seg, u, r.edges[k], &x);
    push(j, Wk, s, &x, 0, 1);
    u += g->data.lower_edges[r.edges[k]].arc_length;
  }
  return 1;
}

static void replan(const job* j) {
  if (j->lower->count == 0) return;
  if (restart_from_rest(j)) return;
  if (j->in->time == 0.0 && j->lower->t == 0.0f) {
    /* nothing played yet: the first edge itself may be re-chosen */
    smgi_qentry h = *smgi_q_at(j->lower, 0);
    cand c[SMGI_MAX_CANDIDATES];
    uint32_t from = j->in->graph->data.lower_edges[h.edge].from;
    uint32_t n = rank_node(j, from, h.W, j->in->progress, j->in->seg, c, NULL, NULL);
    j->lower->count = 0;
    j->lower->frames = 0;
    j->lower->stop_seq = SMGI_NONE;
    j->pl->backtracks = 0;
    smgi_lag_reset(&j->lower->lag);
    push(j, h.W, j->in->progress, &c[0], 0, n);
    return;
  }
  j->lower->stop_seq = SMGI_NONE; /* the stop, if any, is chosen again */
  j->lower->count = 1; /* keep only the edge that is playing */
  smgi_lag_reset(&j->lower->lag); /* nothing beyond the next two is left */
  j->lower->frames =
      j->in->graph->data.lower_edges[smgi_q_at(j->lower, 0)->edge].frame_count;
  j->pl->backtracks = 0;
  smgi_qentry* h = smgi_q_at(j->lower, 0);
  const smgi_edge* e = &j->in->graph->data.lower_edges[h->edge];
  smgi_xform2 end = smgi_xf_mul(h->W, smgi_edge_displacement(e));
  uint32_t seg = j->in->seg;
  float dist;
  h->s_start = j->in->progress;
  h->s_end = smgi_path_project_local(j->in->path, end.x, end.z, &seg, &dist);
  h->seg_end = seg;
}

static smg_result plan_start(const job* j, uint32_t* rng, float x, float z,
                             float h) {
  const smg_graph* g = j->in->graph;
  const smgi_derived* dv = smgi_derived_of(g);
  /* a node of the initial style with out-edges, chosen by the seed (the
   * derived list holds them in node order), else the first with any */
  const uint32_t st = j->in->cons->base_style;
  const uint32_t matches =
      st < g->data.style_count ? dv->start_first[st + 1u] - dv->start_first[st]
                               : 0u;
  uint32_t node = dv->first_start;
  if (matches > 0)
    node = dv->start_nodes[dv->start_first[st] + smgi_xorshift(rng) % matches];
  if (node == SMGI_NONE) return SMG_ERROR_BLOB_VALUE; /* no edges at all */
  cand c[SMGI_MAX_CANDIDATES];
  smgi_xform2 W = {x, z, smgi_wrap_angle(h)};
  uint32_t n = rank_node(j, node, W, j->in->progress, j->in->seg, c, NULL, NULL);
  j->lower->head = 0;
  j->lower->count = 0;
  j->lower->frames = 0;
  j->lower->t = 0.0f;
  j->lower->stop_seq = SMGI_NONE;
  smgi_lag_reset(&j->lower->lag);
  push(j, W, j->in->progress, &c[0], 0, n);
  j->lower->node = node;
  return SMG_OK;
}

void smgi_plan(smgi_planner* pl, smgi_lower* lower, const smgi_step_in* in,
               const smgi_steer_envelope* steer, uint32_t budget,
               float step_frames) {
  const job j = {pl, lower, in, steer};
  plan(&j, budget, step_frames);
}

void smgi_replan(smgi_planner* pl, smgi_lower* lower, const smgi_step_in* in,
                 const smgi_steer_envelope* steer) {
  const job j = {pl, lower, in, steer};
  replan(&j);
}

smg_result smgi_plan_start(smgi_planner* pl, smgi_lower* lower,
                           const smgi_step_in* in,
                           const smgi_steer_envelope* steer, uint32_t* rng,
                           float x, float z, float h) {
  const job j = {pl, lower, in, steer};
  return plan_start(&j, rng, x, z, h);
}
