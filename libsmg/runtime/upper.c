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

#include "character_internal.h"

static const float IDENTITY[4] = {0.0f, 0.0f, 0.0f, 1.0f};

/* Next upper edge from `node` for the current action. */
static uint32_t choose_next(smg_character* ch, uint32_t node) {
  const smg_graph* g = ch->graph;
  const smgi_node* n = &g->data.upper_nodes[node];
  const smgi_edge* edges = g->data.upper_edges;
  uint32_t A = g->data.action_count;
  uint32_t matches = 0;
  for (uint32_t k = 0; k < n->edge_count; ++k)
    if (edges[n->first_edge + k].label == ch->upper.action) ++matches;
  if (matches > 0) {
    uint32_t pick = smgi_xorshift(&ch->rng) % matches;
    for (uint32_t k = 0; k < n->edge_count; ++k) {
      if (edges[n->first_edge + k].label != ch->upper.action) continue;
      if (pick-- == 0) return n->first_edge + k;
    }
  }
  /* no edge of the action here: head towards the nearest one */
  const uint8_t* hops = smgi_derived_of(g)->upper_hops;
  uint32_t best = SMGI_NONE;
  uint32_t best_h = SMGI_HOPS_UNREACHABLE + 1u;
  for (uint32_t k = 0; k < n->edge_count; ++k) {
    uint32_t to = edges[n->first_edge + k].to;
    uint32_t hh = hops[(size_t)to * A + ch->upper.action];
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
static void switch_to(smg_character* ch, uint32_t action, uint32_t uedge,
                      uint32_t offset, const float* correction) {
  const uint32_t J = ch->joint_count;
  memcpy(ch->upper.snap, ch->pose.rot, sizeof(float) * 4u * J);
  ch->upper.fade = 0.0f;
  ch->upper.action = action;
  ch->upper.pending.valid = 0;
  if (action == 0) return;
  const smg_graph* g = ch->graph;
  ch->upper.edge = uedge;
  const smgi_edge* e = &g->data.upper_edges[uedge];
  ch->upper.t = (float)(offset < e->frame_count ? offset : e->frame_count - 1u);
  memcpy(ch->upper.correction, correction, sizeof(float) * 4u);
  ch->upper.node = e->from;
  ch->upper.next = choose_next(ch, e->to);
  if (ch->upper.next == SMGI_NONE) ch->upper.next = uedge;
  ch->sync.rate = 1.0f;
}

void smgi_upper_start(smg_character* ch) {
  ch->upper.fade = 1.0f;
  ch->sync.rate = 1.0f;
  memcpy(ch->upper.correction, IDENTITY, sizeof IDENTITY);
  uint32_t a = ch->cons.base_action;
  ch->upper.action = 0;
  if (a == 0) return;
  uint32_t first = smgi_derived_of(ch->graph)->action_first_edge[a];
  if (first == SMGI_NONE) return;
  switch_to(ch, a, first, 0, IDENTITY);
  ch->upper.fade = 1.0f;
}

void smgi_upper_advance(smg_character* ch, float lower_frames) {
  if (ch->upper.action == 0) return;
  const smgi_edge* edges = ch->graph->data.upper_edges;
  ch->upper.t += lower_frames * ch->sync.rate;
  for (uint32_t guard = 0; guard < 64u; ++guard) {
    const smgi_edge* e = &edges[ch->upper.edge];
    if (ch->upper.t < (float)e->frame_count) return;
    ch->upper.t -= (float)e->frame_count;
    ch->upper.node = e->to;
    uint32_t next = ch->upper.next;
    if (edges[next].from != e->to) {
      /* the planned successor does not connect (dead end): re-enter the
       * action's first edge with a crossfade */
      float t = ch->upper.t;
      switch_to(ch, ch->upper.action, next, 0, ch->upper.correction);
      ch->upper.t = t < (float)edges[next].frame_count ? t : 0.0f;
      return;
    }
    ch->upper.edge = next;
    ch->upper.next = choose_next(ch, edges[next].to);
    if (ch->upper.next == SMGI_NONE) {
      uint32_t first = smgi_derived_of(ch->graph)->action_first_edge[ch->upper.action];
      ch->upper.next = first != SMGI_NONE ? first : next;
    }
  }
  ch->upper.t = 0.0f; /* absurd dt with 1-frame edges: stop catching up */
}

void smgi_upper_sample(const smg_character* ch, float* out) {
  const smg_graph* g = ch->graph;
  const smgi_edge* edges = g->data.upper_edges;
  const smgi_edge* e = &edges[ch->upper.edge];
  uint32_t i0 = (uint32_t)ch->upper.t;
  if (i0 >= e->frame_count) i0 = e->frame_count - 1u;
  float a = smgi_clampf(ch->upper.t - (float)i0, 0.0f, 1.0f);
  uint32_t fa = e->first_frame + i0;
  uint32_t fb = i0 + 1u < e->frame_count ? fa + 1u
                                         : edges[ch->upper.next].first_frame;
  const uint32_t J = ch->joint_count;
  const uint32_t sb = g->data.info->spine_base_joint;
  smgi_sample_joints(g, smgi_graph_pose(g, fa), smgi_graph_pose(g, fb), a,
                     SMGI_JOINTS_UPPER, out);
  if (sb < J && sb > 0) {
    /* local'(spine_base) = correction * local_upper(spine_base) */
    float q[4];
    smgi_q_mul(ch->upper.correction, out + 4u * sb, q);
    smgi_q_normalize(q);
    memcpy(out + 4u * sb, q, sizeof q);
  }
}

/* Best candidate for `action` among the next SMGI_SPLICE_WINDOW lower
 * frames; fills ch->upper.pending. */
static int find_candidate(smg_character* ch, uint32_t action) {
  const smg_graph* g = ch->graph;
  const smgi_derived* dv = smgi_derived_of(g);
  const smgi_edge* edges = g->data.lower_edges;
  float best = 0.0f;
  int found = 0;
  for (uint32_t k = 1; k <= SMGI_SPLICE_WINDOW; ++k) {
    uint32_t entry, offset;
    if (!smgi_q_locate(&ch->lower, g->data.lower_edges, k, &entry, &offset)) break;
    const smgi_qentry* q = smgi_q_at(&ch->lower, entry);
    uint32_t f = edges[q->edge].first_frame + offset;
    for (uint32_t i = dv->splice_first[f]; i < dv->splice_first[f + 1u];
         ++i) {
      const smgi_splice* sp = &g->data.splices[i];
      if (sp->action != action) continue;
      if (!found || sp->distance < best) {
        best = sp->distance;
        found = 1;
        ch->upper.pending.valid = 1;
        ch->upper.pending.seq = q->seq;
        ch->upper.pending.offset = offset;
        ch->upper.pending.splice = i;
      }
    }
  }
  return found;
}

void smgi_upper_update_splice(smg_character* ch, float dt, int new_frame) {
  const smg_graph* g = ch->graph;
  /* a scheduled switch whose frame has come */
  if (ch->upper.pending.valid) {
    const smgi_qentry* h = smgi_q_at(&ch->lower, 0);
    const smgi_splice* sp = &g->data.splices[ch->upper.pending.splice];
    int due = (int32_t)(h->seq - ch->upper.pending.seq) > 0 ||
              (h->seq == ch->upper.pending.seq &&
               (uint32_t)ch->lower.t >= ch->upper.pending.offset);
    if (due) {
      switch_to(ch, sp->action, sp->upper_edge, sp->upper_offset,
                sp->correction);
      ch->upper.want_time = 0.0f;
      return;
    }
  }
  float arc;
  uint32_t wanted = smgi_action_at(&ch->cons, ch->progress + SMGI_SPLICE_LEAD, &arc);
  if (wanted == ch->upper.action) {
    ch->upper.pending.valid = 0;
    ch->upper.want_time = 0.0f;
    return;
  }
  if (wanted == 0) { /* back to the locomotion's own upper body */
    switch_to(ch, 0, 0, 0, IDENTITY);
    ch->upper.want_time = 0.0f;
    return;
  }
  ch->upper.want_time += dt;
  if (ch->upper.pending.valid &&
      g->data.splices[ch->upper.pending.splice].action == wanted)
    return;
  ch->upper.pending.valid = 0;
  if (new_frame && find_candidate(ch, wanted)) return;
  if (ch->progress > arc + SMGI_FORCE_DISTANCE || ch->upper.want_time > SMGI_FORCE_SECONDS) {
    uint32_t first = smgi_derived_of(g)->action_first_edge[wanted];
    if (first != SMGI_NONE) switch_to(ch, wanted, first, 0, IDENTITY);
    ch->upper.want_time = 0.0f;
  }
}
