/*
 * playback.c - per-frame stepping: keep the plan ahead of the playhead,
 * advance the fractional playhead through the queue of committed edges,
 * drive the upper body (splices, synchronization), compose the pose and
 * track progress along the path. Bounded work, no allocation.
 */
#include <math.h>

#include "character_internal.h"

#define END_EPS 0.3f
#define END_NEAR 1.0f /* metres from the last point that count as there */

int smgi_q_locate(const smg_character* ch, uint32_t k, uint32_t* entry,
                  uint32_t* offset) {
  const smgi_edge* edges = ch->graph->data.lower_edges;
  uint32_t off = (uint32_t)ch->t + k;
  for (uint32_t i = 0; i < ch->q_count; ++i) {
    uint32_t fc = edges[smgi_q_at_c(ch, i)->edge].frame_count;
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
      smgi_path_project_local(p, ch->ground[0], ch->ground[1], &ch->seg, &dist);
  ch->path_error = dist;
  if (p->count == 1) {
    ch->end_reached = dist < 0.5f;
  } else {
    float ex = p->xz[2u * (p->count - 1u)] - ch->ground[0];
    float ez = p->xz[2u * (p->count - 1u) + 1u] - ch->ground[1];
    /* both: at the end of the path by progress (a closed path starts
     * where it ends) and actually near its last point (a character that
     * cut across to the last segment has not arrived). Latched until the
     * path changes: there are no idle clips, so an arrived character
     * keeps moving around the end point and would flicker. */
    ch->end_reached = ch->end_reached ||
                      (ch->progress >= p->length - END_EPS &&
                       ex * ex + ez * ez < END_NEAR * END_NEAR);
  }
}

smg_result smgi_step(smg_character* ch, float dt) {
  const smgi_edge* edges = ch->graph->data.lower_edges;
  float frames = dt * ch->fps;
  smgi_pose_prefetch(ch);
  /* keep the horizon planned; this step's frames are guaranteed whatever
   * the budget */
  smgi_plan(ch, SMGI_PLAN_BUDGET, frames);

  ch->t += frames;
  for (;;) {
    const smgi_qentry* h = smgi_q_at(ch, 0);
    float fc = (float)edges[h->edge].frame_count;
    if (ch->t < fc) break;
    if (ch->q_count <= 1u) {
      /* dead end in the graph: hold the last frame */
      ch->t = fc - 1.0f;
      break;
    }
    ch->t -= fc;
    ch->lower_node = edges[h->edge].to;
    ch->q_head = (ch->q_head + 1u) & (SMGI_QUEUE_CAP - 1u);
    ch->q_count--;
    ch->q_frames -= edges[h->edge].frame_count;
  }
  ch->style = edges[smgi_q_at(ch, 0)->edge].label;
  ch->time += (double)dt;

  /* upper body: time advance, splice scheduling and synchronization */
  smgi_upper_advance(ch, frames);
  if (ch->fade < 1.0f) {
    ch->fade += dt * ch->fade_rate;
    if (ch->fade > 1.0f) ch->fade = 1.0f;
  }
  uint32_t key = smgi_q_at(ch, 0)->seq * 4096u + (uint32_t)ch->t;
  int new_frame = key != ch->last_lower_frame;
  ch->last_lower_frame = key;
  smgi_upper_update_splice(ch, dt, new_frame);
  if (new_frame) smgi_sync_update(ch);

  smgi_pose_compose(ch);
  /* world transforms are cached: IK needs them, and the getters then
   * only convert (model matrices) or copy (local pose) */
  smgi_fk(ch->graph, ch->root, ch->rot, ch->wpos, ch->wrot);
  smgi_ik_apply(ch, dt);
  update_progress(ch);
  return SMG_OK;
}
