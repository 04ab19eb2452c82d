/*
 * playback.c - per-frame stepping: keep the plan ahead of the playhead,
 * advance the fractional playhead through the queue of committed edges,
 * drive the upper body (splices, synchronization), compose the pose, steer
 * it (steer.c) and track progress along the path. Bounded work, no allocation.
 */
#include <math.h>

#include "character_internal.h"

int smgi_q_locate(const smgi_lower* l, const smgi_edge* edges, uint32_t k,
                  uint32_t* entry, uint32_t* offset) {
  uint32_t off = (uint32_t)l->t + k;
  for (uint32_t i = 0; i < l->count; ++i) {
    uint32_t fc = edges[smgi_q_at_c(l, i)->edge].frame_count;
    if (off < fc) {
      *entry = i;
      *offset = off;
      return 1;
    }
    off -= fc;
  }
  return 0;
}

static void update_progress(smg_character* ch) {
  const smgi_path* p = &ch->path;
  float dist = 0.0f;
  if (p->count == 0) {
    ch->path_error = 0.0f;
    ch->end_reached = 0;
    return;
  }
  ch->progress =
      smgi_path_project_local(p, ch->pose.ground[0], ch->pose.ground[1], &ch->seg, &dist);
  ch->path_error = dist;
  if (p->count == 1) {
    ch->end_reached = dist < 0.5f;
  } else {
    float ex = p->xz[2u * (p->count - 1u)] - ch->pose.ground[0];
    float ez = p->xz[2u * (p->count - 1u) + 1u] - ch->pose.ground[1];
    /* both: at the end of the path by progress (a closed path starts
     * where it ends) and actually near its last point (a character that
     * cut across to the last segment has not arrived). Latched until the
     * path changes: there are no idle clips, so an arrived character
     * keeps moving around the end point and would flicker. */
    if (ch->steer.enabled) {
      /* steered: arrived means standing at the end */
      ch->end_reached = ch->steer.mode == SMGI_STEER_REST;
      return;
    }
    ch->end_reached = ch->end_reached ||
                      (ch->progress >= p->length - SMGI_END_EPS &&
                       ex * ex + ez * ez < SMGI_END_NEAR * SMGI_END_NEAR);
  }
}

smg_result smgi_step(smg_character* ch, float dt) {
  const smgi_edge* edges = ch->graph->data.lower_edges;
  smgi_pose_prefetch(ch);
  /* the playback rate: slower for a tight turn, braking at the end */
  const float frames = smgi_rest_frames(ch, smgi_steer_frames(ch, dt));
  /* keep the horizon planned; this step's frames are guaranteed whatever
   * the budget */
  smgi_plan(ch, SMGI_PLAN_BUDGET, frames);

  ch->lower.t += frames;
  uint32_t pops = 0;
  for (;;) {
    const smgi_qentry* h = smgi_q_at(&ch->lower, 0);
    float fc = (float)edges[h->edge].frame_count;
    if (ch->lower.t < fc) break;
    if (ch->lower.count <= 1u) {
      /* dead end in the graph: hold the last frame */
      ch->lower.t = fc - 1.0f;
      break;
    }
    ch->lower.t -= fc;
    ch->lower.node = edges[h->edge].to;
    ch->lower.head = (ch->lower.head + 1u) & (SMGI_QUEUE_CAP - 1u);
    ch->lower.count--;
    ch->lower.frames -= edges[h->edge].frame_count;
    ++pops;
  }
  smgi_steer_refresh(ch, pops);
  ch->lower.style = edges[smgi_q_at(&ch->lower, 0)->edge].label;
  ch->time += (double)dt;

  /* upper body: time advance, splice scheduling and synchronization */
  /* at rest the lower body stands still but an action goes on */
  smgi_upper_advance(ch, ch->rest.phase != SMGI_REST_OFF ? dt * ch->fps
                                                         : frames);
  if (ch->upper.fade < 1.0f) {
    ch->upper.fade += dt * ch->upper.fade_rate;
    if (ch->upper.fade > 1.0f) ch->upper.fade = 1.0f;
  }
  uint32_t key = smgi_q_at(&ch->lower, 0)->seq * 4096u + (uint32_t)ch->lower.t;
  int new_frame = key != ch->lower.last_frame;
  ch->lower.last_frame = key;
  smgi_upper_update_splice(ch, dt, new_frame);
  if (new_frame) smgi_sync_update(ch);

  smgi_pose_compose(ch);
  if (smgi_rest_steers(ch)) smgi_steer_apply(ch, dt);
  smgi_rest_pose(ch, dt);
  /* world transforms are cached: IK needs them, and the getters then
   * only convert (model matrices) or copy (local pose) */
  smgi_fk(ch->graph, ch->pose.root, ch->pose.rot, ch->pose.wpos, ch->pose.wrot);
  smgi_rest_feet(ch);
  smgi_rest_flatten(ch);
  smgi_ik_apply(ch, dt);
  update_progress(ch);
  return SMG_OK;
}
