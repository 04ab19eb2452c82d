/*
 * steer.h - root steering: the state of the stage that keeps a character's
 * ground transform on its path on top of the motion the planner chose, and
 * brings it to rest at the path's end (steer.c; docs/runtime.md, "Root
 * steering"). Its inputs: the step's (step_in.h) and the lower timeline;
 * its outputs: the corrected pose and queue placements, the playback rate,
 * and whether the plan should be chosen again (smgi_steer_wants_replan).
 */
#ifndef SMG_STEER_H
#define SMG_STEER_H

#include <stdint.h>

#include "lower.h"
#include "pose.h"
#include "rmath.h"
#include "steer_envelope.h"
#include "step_in.h"
#include "tuning.h"

#define SMGI_STEER_FOLLOW 0u /* on the path: correct towards it */
#define SMGI_STEER_BRAKE 1u  /* slowing down onto the chosen stop frame */
#define SMGI_STEER_REST 2u   /* standing at the end until the path changes */

typedef struct smgi_steer {
  uint32_t enabled;
  uint32_t mode;          /* SMGI_STEER_* */
  /* limits (settled by smgi_settle_defaults, settings.c) */
  float turn_limit;       /* rad/s of heading correction beyond the clip's */
  float slide_ratio;      /* translation per metre the motion travels */
  float stop_seconds;     /* braking time at the end */
  /* what the motion itself did, low-passed over a gait cycle's fraction */
  uint32_t have_prev;
  float prev_x, prev_z, prev_h; /* ground transform after the last step */
  float own_turn;         /* the motion's own turning, rad/s */
  float own_speed;        /* the motion's own ground speed, m/s */
  /* the motion's own facing (unit vector of its heading) and travel
   * (velocity, m/s), low-passed over half a stride: how far the body
   * faces off the way it goes, without the sway and twist of each step */
  float own_face[2];
  float own_travel[2];
  /* the way the character really goes (the direction of its ground
   * steps after the correction, unit vectors low-passed the same way),
   * and the body's turn onto it about the ground point (radians, applied
   * to the pose alone: the plan and the ground transform keep the
   * motion's facing) */
  float out_travel[2];
  float body_face[2];     /* the motion's facing, low-passed as out_travel */
  float body_turn;
  float body_max;         /* the largest body_turn: the angle the slide
                           * ratio crabs the body by (its sine) */
  /* the correction, continuous (its rate of change is bounded) */
  float turn;             /* heading correction, rad/s */
  float slide[2];         /* translation correction, m/s (x, z) */
  float rate;             /* playback rate: 1 following, < 1 slowing */
  float stride;           /* share of the motion's travel kept: < 1 takes
                           * shorter strides for a tight turn (the rest is
                           * slid back along the travel; planted feet keep
                           * their anchors, so the steps shorten) */
  uint32_t cutting;       /* 1: a turn no tight-turn slowing makes (a
                           * hairpin) lies within the look-ahead or is
                           * being taken: cut like a runner (steer.c
                           * share_ahead) */
  /* the headings of the two path segments last looked at (an atan2
   * each; the curvature ahead mostly looks at the same one or two
   * segments step after step), the latest first, forgotten when the path
   * changes */
  uint32_t heading_seg[2]; /* SMGI_NONE: none */
  float heading[2];
  /* correction applied since the planned edges were chosen: the plan
   * moves with the character, so beyond a bound it is chosen again */
  float drift_turn;       /* radians */
  float drift_move;       /* metres */
  /* braking: the frame the character comes to rest on */
  uint32_t stop_seq;      /* queue entry (seq) holding it */
  uint32_t stop_offset;   /* frame offset inside that entry's edge */
  uint32_t data_stop;     /* 1: it is the rest of a stop from the data
                           * (stop_match.h), played at normal rate */
} smgi_steer;

/* Limits already settled (smgi_settle_defaults). */
void smgi_steer_init(smgi_steer* s, uint32_t enabled, float turn_limit,
                     float slide_ratio, float stop_seconds);
void smgi_steer_set_limits(smgi_steer* s, float turn_limit,
                           float slide_ratio, float stop_seconds);
/* The path changed: follow it again (from rest too). */
void smgi_steer_path_changed(smgi_steer* s);
/* Whether the correction since the plan was chosen has added up beyond
 * its bound (SMGI_STEER_REPLAN_*): the planned edges were chosen for where
 * the character would have been without it, and should be chosen again
 * from where it is (the edge playing stays). Asked at the start of a step,
 * before smgi_steer_frames; after re-planning, smgi_steer_replanned. */
int smgi_steer_wants_replan(const smgi_steer* s, const smgi_step_in* in);
void smgi_steer_replanned(smgi_steer* s);
/* Frames the playhead advances this step: dt * fps scaled by the playback
 * rate (slowing for a tight turn, braking at the end, 0 at rest). Reads
 * the queue to choose the frame to come to rest on. */
float smgi_steer_frames(smgi_steer* s, const smgi_lower* lower,
                        const smgi_step_in* in, float dt);
/* Turn the pose just composed and every queued placement by da radians
 * about (px, pz): the character turns as a whole, its plan with it
 * (rest.c: turning on the spot). */
void smgi_steer_move(smgi_steer* s, smgi_pose* pose, smgi_lower* lower,
                     float da, float px, float pz);
/* Correct the pose just composed and the queued placements (before FK and
 * foot IK, so planted feet keep their world anchors). */
/* Add a rigid move - a turn by da (cos c, sin sn) about (px, pz), then the
 * shift (tx, tz) - to the correction pending for the entries beyond the
 * next two (root_motion.c: where an engine's mover put the character). */
void smgi_lag_follow(smgi_lag* l, float c, float sn, float da, float px,
                     float pz, float tx, float tz);
void smgi_steer_apply(smgi_steer* s, smgi_pose* pose, smgi_lower* lower,
                      const smgi_step_in* in, float dt);

/* What the planner reads of the steering (steer_envelope.h). */
static inline smgi_steer_envelope smgi_steer_envelope_of(const smgi_steer* s) {
  smgi_steer_envelope e;
  e.enabled = s->enabled;
  e.turn_limit = s->turn_limit;
  e.slide_ratio = s->slide_ratio;
  e.stop_seconds = s->stop_seconds;
  e.own_speed = s->own_speed;
  return e;
}

#endif /* SMG_STEER_H */
