/*
 * upper.c - the upper body: traversal of the action graph and splicing.
 *
 * Action 0 ("none") is the locomotion frame's own upper body. Any other
 * action plays the upper graph restricted to edges labelled with it, the
 * choice among several being deterministic (the character's seeded
 * xorshift). A splice point on the path schedules a switch: among the lower
 * frames about to be played, the best splice candidate (smallest upper-body
 * distance, from SPLC) for the wanted action is chosen, and when the
 * playhead reaches it the upper body enters the action graph at the
 * candidate's (upper_edge, upper_offset) with its Horn correction, blended
 * over the blob's window. If no candidate shows up, the switch is forced
 * after a bounded distance/time at the action's first edge, so a splice
 * point always takes effect.
 */
#include <string.h>

#include "upper.h"

#include "graph_derived.h"
#include "rmath.h"
#include "tuning.h"

static const float IDENTITY[4] = {0.0f, 0.0f, 0.0f, 1.0f};

/* One call's state, its inputs and whether it entered an action's edge
 * anew (which starts synchronization afresh, sync.h). */
typedef struct job {
  smgi_upper* u;
  const smg_graph* g;
  uint32_t* rng;
  const float* shown; /* 4J: the pose shown, faded from on a switch */
  int switched;
} job;

/* Next upper edge from `node` for the current action. */
static uint32_t choose_next(job* j, uint32_t node) {
  const smg_graph* g = j->g;
  const smgi_node* n = &g->data.upper_nodes[node];
  const smgi_edge* edges = g->data.upper_edges;
  uint32_t A = g->data.action_count;
  uint32_t matches = 0;
  for (uint32_t k = 0; k < n->edge_count; ++k)
    if (edges[n->first_edge + k].label == j->u->action) ++matches;
  if (matches > 0) {
    uint32_t pick = smgi_xorshift(j->rng) % matches;
    for (uint32_t k = 0; k < n->edge_count; ++k) {
      if (edges[n->first_edge + k].label != j->u->action) continue;
      if (pick-- == 0) return n->first_edge + k;
    }
  }
  /* no edge of the action here: head towards the nearest one */
  const uint8_t* hops = smgi_derived_of(g)->upper_hops;
  uint32_t best = SMGI_NONE;
  uint32_t best_h = SMGI_HOPS_UNREACHABLE + 1u;
  for (uint32_t k = 0; k < n->edge_count; ++k) {
    uint32_t to = edges[n->first_edge + k].to;
    uint32_t hh = hops[(size_t)to * A + j->u->action];
    if (hh < best_h) {
      best_h = hh;
      best = n->first_edge + k;
    }
  }
  if (best != SMGI_NONE) return best;
  /* dead end: jump to the action's first edge (switch_to fades) */
  return SMGI_NONE;
}

/* Begin playing `uedge` at `offset` frames with `correction`, crossfading
 * from the pose currently shown. */
static void switch_to(job* j, uint32_t action, uint32_t uedge,
                      uint32_t offset, const float* correction) {
  smgi_upper* u = j->u;
  const uint32_t J = j->g->data.joint_count;
  memcpy(u->snap, j->shown, sizeof(float) * 4u * J);
  u->fade = 0.0f;
  u->action = action;
  u->pending.valid = 0;
  if (action == 0) return;
  const smg_graph* g = j->g;
  u->edge = uedge;
  const smgi_edge* e = &g->data.upper_edges[uedge];
  u->t = (float)(offset < e->frame_count ? offset : e->frame_count - 1u);
  memcpy(u->correction, correction, sizeof(float) * 4u);
  u->node = e->from;
  u->next = choose_next(j, e->to);
  if (u->next == SMGI_NONE) u->next = uedge;
  j->switched = 1;
}

void smgi_upper_start(smgi_upper* u, const smg_graph* g, uint32_t* rng,
                      const float* shown, uint32_t action) {
  job j = {u, g, rng, shown, 0};
  u->fade = 1.0f;
  memcpy(u->correction, IDENTITY, sizeof IDENTITY);
  u->action = 0;
  if (action == 0) return;
  uint32_t first = smgi_derived_of(g)->action_first_edge[action];
  if (first == SMGI_NONE) return;
  switch_to(&j, action, first, 0, IDENTITY);
  u->fade = 1.0f;
}

/* The playhead part of smgi_upper_advance. */
static void advance_playhead(job* j, float frames) {
  smgi_upper* u = j->u;
  if (u->action == 0) return;
  const smgi_edge* edges = j->g->data.upper_edges;
  u->t += frames;
  for (uint32_t guard = 0; guard < 64u; ++guard) {
    const smgi_edge* e = &edges[u->edge];
    if (u->t < (float)e->frame_count) return;
    u->t -= (float)e->frame_count;
    u->node = e->to;
    uint32_t next = u->next;
    if (edges[next].from != e->to) {
      /* the planned successor does not connect (dead end): re-enter the
       * action's first edge with a crossfade */
      float t = u->t;
      switch_to(j, u->action, next, 0, u->correction);
      u->t = t < (float)edges[next].frame_count ? t : 0.0f;
      return;
    }
    u->edge = next;
    u->next = choose_next(j, edges[next].to);
    if (u->next == SMGI_NONE) {
      uint32_t first = smgi_derived_of(j->g)->action_first_edge[u->action];
      u->next = first != SMGI_NONE ? first : next;
    }
  }
  u->t = 0.0f; /* absurd dt with 1-frame edges: stop catching up */
}

int smgi_upper_advance(smgi_upper* u, const smg_graph* g, uint32_t* rng,
                       const float* shown, float lower_frames,
                       float sync_rate, float dt) {
  job j = {u, g, rng, shown, 0};
  advance_playhead(&j, lower_frames * sync_rate);
  if (u->fade < 1.0f) {
    u->fade += dt * u->fade_rate;
    if (u->fade > 1.0f) u->fade = 1.0f;
  }
  return j.switched;
}

void smgi_upper_sample(const smgi_upper* u, const smg_graph* g, float* out) {
  const smgi_edge* edges = g->data.upper_edges;
  const smgi_edge* e = &edges[u->edge];
  uint32_t i0 = (uint32_t)u->t;
  if (i0 >= e->frame_count) i0 = e->frame_count - 1u;
  float a = smgi_clampf(u->t - (float)i0, 0.0f, 1.0f);
  uint32_t fa = e->first_frame + i0;
  uint32_t fb = i0 + 1u < e->frame_count ? fa + 1u
                                         : edges[u->next].first_frame;
  const uint32_t J = g->data.joint_count;
  const uint32_t sb = g->data.info->spine_base_joint;
  smgi_sample_joints(g, smgi_graph_pose(g, fa), smgi_graph_pose(g, fb), a,
                     SMGI_JOINTS_UPPER, out);
  if (sb < J && sb > 0) {
    /* local'(spine_base) = correction * local_upper(spine_base) */
    float q[4];
    smgi_q_mul(u->correction, out + 4u * sb, q);
    smgi_q_normalize(q);
    memcpy(out + 4u * sb, q, sizeof q);
  }
}

/* Best candidate for `action` among the next SMGI_SPLICE_WINDOW lower
 * frames; fills u->pending. */
static int find_candidate(smgi_upper* u, const smgi_lower* lower,
                          const smg_graph* g, uint32_t action) {
  const smgi_derived* dv = smgi_derived_of(g);
  const smgi_edge* edges = g->data.lower_edges;
  float best = 0.0f;
  int found = 0;
  for (uint32_t k = 1; k <= SMGI_SPLICE_WINDOW; ++k) {
    uint32_t entry, offset;
    if (!smgi_q_locate(lower, g->data.lower_edges, k, &entry, &offset)) break;
    const smgi_qentry* q = smgi_q_at_c(lower, entry);
    uint32_t f = edges[q->edge].first_frame + offset;
    for (uint32_t i = dv->splice_first[f]; i < dv->splice_first[f + 1u];
         ++i) {
      const smgi_splice* sp = &g->data.splices[i];
      if (sp->action != action) continue;
      if (!found || sp->distance < best) {
        best = sp->distance;
        found = 1;
        u->pending.valid = 1;
        u->pending.seq = q->seq;
        u->pending.offset = offset;
        u->pending.splice = i;
      }
    }
  }
  return found;
}

int smgi_upper_update_splice(smgi_upper* u, const smgi_lower* lower,
                             const smgi_step_in* in, uint32_t* rng,
                             const float* shown, float dt, int new_frame) {
  const smg_graph* g = in->graph;
  job j = {u, g, rng, shown, 0};
  /* a scheduled switch whose frame has come */
  if (u->pending.valid) {
    const smgi_qentry* h = smgi_q_at_c(lower, 0);
    const smgi_splice* sp = &g->data.splices[u->pending.splice];
    int due = (int32_t)(h->seq - u->pending.seq) > 0 ||
              (h->seq == u->pending.seq &&
               (uint32_t)lower->t >= u->pending.offset);
    if (due) {
      switch_to(&j, sp->action, sp->upper_edge, sp->upper_offset,
                sp->correction);
      u->want_time = 0.0f;
      return j.switched;
    }
  }
  float arc;
  uint32_t wanted =
      smgi_action_at(in->cons, in->progress + SMGI_SPLICE_LEAD, &arc);
  if (wanted == u->action) {
    u->pending.valid = 0;
    u->want_time = 0.0f;
    return j.switched;
  }
  if (wanted == 0) { /* back to the locomotion's own upper body */
    switch_to(&j, 0, 0, 0, IDENTITY);
    u->want_time = 0.0f;
    return j.switched;
  }
  u->want_time += dt;
  if (u->pending.valid && g->data.splices[u->pending.splice].action == wanted)
    return j.switched;
  u->pending.valid = 0;
  if (new_frame && find_candidate(u, lower, g, wanted)) return j.switched;
  if (in->progress > arc + SMGI_FORCE_DISTANCE ||
      u->want_time > SMGI_FORCE_SECONDS) {
    uint32_t first = smgi_derived_of(g)->action_first_edge[wanted];
    if (first != SMGI_NONE) switch_to(&j, wanted, first, 0, IDENTITY);
    u->want_time = 0.0f;
  }
  return j.switched;
}

void smgi_upper_plan_dropped(smgi_upper* u, const smgi_lower* lower) {
  if (lower->count > 0 && u->pending.valid && u->pending.seq != smgi_q_at_c(lower, 0)->seq)
    u->pending.valid = 0;
}
