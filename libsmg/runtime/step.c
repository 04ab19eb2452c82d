/*
 * step.c - one frame of a character: the stages run in order, each given
 * its own state and the inputs it reads (docs/architecture.md, "The
 * step"). This and character.c are the only files that see the whole
 * character; the stages see what this file hands them. Bounded work, no
 * allocation.
 */
#include <math.h>

#include "character_state.h"

/* Start fetching what this step will touch: in a big crowd these lines
 * were evicted since the character's last step, and the planner's work
 * hides the fetches. A hint only (no effect on results).
 *
 * Kept out of interprocedural analysis: GCC 12 at -O2 (IPA mod/ref)
 * counts a function that only prefetches as free of side effects and
 * deletes the call, so this never ran in the builds measured before
 * (objdump of step.o showed no prefetch instruction). */
#if defined(__has_attribute)
#if __has_attribute(noipa)
#define SMGI_KEEP_CALL __attribute__((noipa))
#endif
#endif
#ifndef SMGI_KEEP_CALL
#define SMGI_KEEP_CALL
#endif
SMGI_KEEP_CALL static void prefetch(const smg_character* ch) {
#if defined(__GNUC__) || defined(__clang__)
#define PREFETCH_RANGE(ptr, bytes, rw)                                   \
  do {                                                                   \
    const char* p_ = (const char*)(ptr);                                 \
    const size_t n_ = (size_t)(bytes);                                   \
    for (size_t o_ = 0; o_ < n_; o_ += 64u) __builtin_prefetch(p_ + o_, rw, 3); \
    __builtin_prefetch(p_ + n_ - 1u, rw, 3);                             \
  } while (0)
  const uint32_t J = ch->joint_count;
  /* The character itself (its fields are read one after the other, so
   * each line would otherwise miss only when first used), then the pose,
   * its world transforms, which are rewritten, and its decoded records.
   * character.c lays them out in that order in one block: one range
   * then, else four. */
  const size_t dec = sizeof(float) * 2u * smgi_decoded_floats(J);
  const char* c0 = (const char*)ch;
  const char* c1 = ch->pose.decoded.rot
                       ? (const char*)ch->pose.decoded.rot + dec
                       : (const char*)(ch->pose.wrot + 4u * J);
  if ((const char*)ch->pose.rot > c0 && (const char*)ch->pose.wpos > c0 &&
      (const char*)ch->pose.wrot > c0 && c1 > c0 &&
      (size_t)(c1 - c0) <= sizeof *ch + sizeof(float) * 12u * J + dec + 64u) {
    PREFETCH_RANGE(c0, c1 - c0, 1);
  } else {
    PREFETCH_RANGE(ch, sizeof *ch, 1);
    PREFETCH_RANGE(ch->pose.rot, sizeof(float) * 4u * J, 1);
    PREFETCH_RANGE(ch->pose.wpos, sizeof(float) * 3u * J, 1);
    PREFETCH_RANGE(ch->pose.wrot, sizeof(float) * 4u * J, 1);
    if (ch->pose.decoded.rot) PREFETCH_RANGE(ch->pose.decoded.rot, dec, 1);
  }
  /* the queue entries the pose is placed with */
  PREFETCH_RANGE(smgi_q_at_c(&ch->lower, 0), sizeof(smgi_qentry), 0);
  if (ch->lower.count > 1u) PREFETCH_RANGE(smgi_q_at_c(&ch->lower, 1), sizeof(smgi_qentry), 0);
  /* the path around the character's projection (progress tracking) */
  if (ch->seg + 2u < ch->path.count) {
    PREFETCH_RANGE(ch->path.xz + 2u * ch->seg, sizeof(float) * 6u, 0);
    PREFETCH_RANGE(ch->path.cum + ch->seg, sizeof(float) * 3u, 0);
  }
  /* the lower-body records the playhead is at and goes to next, after
   * this step's advance too (its pose is sampled there), with their
   * frames' ground placements; past the edge's end, the next edge's first
   * (on a big graph each was a miss of its own) */
  const smg_graph* g = ch->graph;
  const smgi_qentry* h = smgi_q_at_c(&ch->lower, 0);
  const smgi_edge* e = &g->data.lower_edges[h->edge];
  const uint32_t i0 = (uint32_t)ch->lower.t;
  if (i0 < e->frame_count) {
    const uint32_t n = e->frame_count - i0 < 3u ? e->frame_count - i0 : 3u;
    PREFETCH_RANGE(smgi_graph_pose(g, e->first_frame + i0),
                   n * (size_t)SMGI_POSE_RECORD_SIZE(J), 0);
    PREFETCH_RANGE(&g->data.frames[e->first_frame + i0],
                   n * sizeof(smgi_frame), 0);
  }
  /* the next entries' edges: the steering and the upper body look
   * frames ahead through the queue (smgi_q_locate) */
  if (ch->lower.count > 1u) {
    const smgi_edge* e1 =
        &g->data.lower_edges[smgi_q_at_c(&ch->lower, 1)->edge];
    PREFETCH_RANGE(e1, sizeof *e1, 0);
    if (ch->lower.count > 2u)
      PREFETCH_RANGE(&g->data.lower_edges[smgi_q_at_c(&ch->lower, 2)->edge],
                     sizeof *e1, 0);
    if (i0 + 3u >= e->frame_count)
      PREFETCH_RANGE(smgi_graph_pose(g, e1->first_frame),
                     (size_t)SMGI_POSE_RECORD_SIZE(J), 0);
  }
#undef PREFETCH_RANGE
#else
  (void)ch;
#endif
}

static void update_progress(smg_character* ch) {
  const smgi_path* p = &ch->path;
  float dist = 0.0f;
  if (p->count == 0) {
    ch->path_error = 0.0f;
    ch->end_reached = 0;
    return;
  }
  ch->progress = smgi_path_project_ahead(
      p, ch->pose.ground[0], ch->pose.ground[1], &ch->seg, &dist,
      SMGI_PATH_AHEAD_OFF, SMGI_PATH_AHEAD_ARC);
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

void smgi_character_replan(smg_character* ch) {
  const smgi_step_in in = smgi_step_in_of(ch);
  const smgi_steer_envelope env = smgi_steer_envelope_of(&ch->steer);
  smgi_replan(&ch->plan, &ch->lower, &in, &env);
  smgi_upper_plan_dropped(&ch->upper, &ch->lower);
}

/* What the step shows, for the events stage (events.c). */
static void collect_events(smg_character* ch, float dt) {
  const smgi_info* info = ch->graph->data.info;
  smgi_events_in in;
  in.style = ch->lower.style;
  in.action = ch->upper.action;
  in.progress = ch->progress;
  in.ground[0] = ch->pose.ground[0];
  in.ground[1] = ch->pose.ground_y;
  in.ground[2] = ch->pose.ground[1];
  for (uint32_t f = 0; f < 2u; ++f) {
    const uint32_t* leg = f ? info->right_leg : info->left_leg;
    const uint32_t toe = leg[3] < ch->joint_count ? leg[3] : leg[2];
    in.toe[f] = toe < ch->joint_count ? ch->pose.wpos + 3u * toe : NULL;
    in.floor[f] = ch->ik.ground.on ? ch->ik.ground.foot_y[f] : 0.0f;
  }
  in.end_reached = ch->end_reached;
  in.leg_length = info->leg_length;
  in.dt = dt;
  smgi_events_collect(&ch->events, &ch->cons, &in);
}

smg_result smgi_step(smg_character* ch, float dt) {
  const smg_graph* g = ch->graph;
  prefetch(ch);
  smgi_events_clear(&ch->events);
  smgi_root_motion_begin(&ch->root_motion, &ch->pose);
  /* progress and segment stay as the last step left them until
   * update_progress at the end */
  const smgi_step_in in = smgi_step_in_of(ch);
  /* steering: re-plan once its correction since the plan was chosen has
   * added up; then the playback rate (slower for a tight turn, braking at
   * the end) */
  if (smgi_steer_wants_replan(&ch->steer, &in)) {
    smgi_character_replan(ch);
    smgi_steer_replanned(&ch->steer);
  }
  const float frames = smgi_rest_frames(
      &ch->rest, smgi_steer_frames(&ch->steer, &ch->lower, &in, dt));
  /* planner: keep the horizon planned; this step's frames are guaranteed
   * whatever the budget */
  const smgi_steer_envelope env = smgi_steer_envelope_of(&ch->steer);
  smgi_plan(&ch->plan, &ch->lower, &in, &env, SMGI_PLAN_BUDGET, frames);
  /* playback */
  smgi_lower_advance(&ch->lower, g->data.lower_edges, frames);
  ch->time += (double)dt;

  /* upper body: time advance and crossfade, splice scheduling; entering
   * an action's edge anew starts synchronization afresh */
  /* at rest the lower body stands still but an action goes on */
  const float upper_frames =
      ch->rest.phase != SMGI_REST_OFF ? dt * in.fps : frames;
  int entered = smgi_upper_advance(&ch->upper, g, &ch->rng, ch->pose.rot,
                                   upper_frames, ch->sync.rate, dt);
  uint32_t key = smgi_q_at(&ch->lower, 0)->seq * 4096u + (uint32_t)ch->lower.t;
  int new_frame = key != ch->lower.last_frame;
  ch->lower.last_frame = key;
  entered |= smgi_upper_update_splice(&ch->upper, &ch->lower, &in, &ch->rng,
                                      ch->pose.rot, dt, new_frame);
  if (entered) smgi_sync_reset(&ch->sync);
  if (new_frame) smgi_sync_update(&ch->sync, &ch->upper, &ch->lower, &in);

  smgi_pose_compose(&ch->pose, &ch->lower, &ch->upper, g);
  if (smgi_rest_steers(&ch->rest))
    smgi_steer_apply(&ch->steer, &ch->pose, &ch->lower, &in, dt);
  /* standing still: settling, standing motion, turning on the spot */
  const smgi_rest_io rest = {&in,       &ch->steer, &ch->pose,
                             &ch->lower, &ch->ik,    &ch->upper};
  if (smgi_rest_pose(&ch->rest, &rest, dt)) smgi_character_replan(ch);
  /* world transforms are cached: IK needs them, and the getters then
   * only convert (model matrices) or copy (local pose) */
  smgi_fk(g, ch->pose.root, ch->pose.rot, ch->pose.wpos, ch->pose.wrot);
  smgi_rest_flatten(&ch->rest, &rest);
  smgi_rest_feet(&ch->rest, &rest);
  smgi_ik_apply(&ch->ik, &ch->pose, g, dt);
  update_progress(ch);
  /* for the engine: the root motion and the events of this step */
  smgi_root_motion_end(&ch->root_motion, &ch->pose, dt);
  collect_events(ch, dt);
  return SMG_OK;
}
