/*
 * steer.h - root steering: the state of the stage that keeps a character's
 * ground transform on its path on top of the motion the planner chose, and
 * brings it to rest at the path's end (steer.c; docs/runtime.md, "Root
 * steering").
 */
#ifndef SMG_STEER_H
#define SMG_STEER_H

#include <stdint.h>

#include "rmath.h"
#include "smg.h"
#include "tuning.h"

#define SMGI_STEER_FOLLOW 0u /* on the path: correct towards it */
#define SMGI_STEER_BRAKE 1u  /* slowing down onto the chosen stop frame */
#define SMGI_STEER_REST 2u   /* standing at the end until the path changes */

typedef struct smgi_steer {
  uint32_t enabled;
  uint32_t mode;          /* SMGI_STEER_* */
  /* limits (smg_character_desc, resolved) */
  float turn_limit;       /* rad/s of heading correction beyond the clip's */
  float slide_ratio;      /* translation per metre the motion travels */
  float stop_seconds;     /* braking time at the end */
  /* what the motion itself did, low-passed over a gait cycle's fraction */
  uint32_t have_prev;
  float prev_x, prev_z, prev_h; /* ground transform after the last step */
  float own_turn;         /* the motion's own turning, rad/s */
  float own_speed;        /* the motion's own ground speed, m/s */
  /* the correction, continuous (its rate of change is bounded) */
  float turn;             /* heading correction, rad/s */
  float slide[2];         /* translation correction, m/s (x, z) */
  float rate;             /* playback rate: 1 following, < 1 slowing */
  /* correction applied since the planned edges were chosen: the plan
   * moves with the character, so beyond a bound it is chosen again */
  /* The correction since the entries beyond the next two were written,
   * as one transform (smgi_lag_apply): those entries are corrected when
   * read instead of written every step. A turn by lag_a (cos, sin in
   * lag_c, lag_s) about lag_p, then a shift by lag_t: kept about a point
   * near the character, so its numbers stay small far from the origin. */
  float lag_a, lag_c, lag_s, lag_p[2], lag_t[2];
  uint32_t lag_steps;     /* steps composed into it */
  /* the heading of the path segment last looked at (an atan2; the
   * curvature ahead mostly looks at the same segment step after step),
   * forgotten when the path changes */
  uint32_t heading_seg;   /* SMGI_NONE: none */
  float heading;
  /* the path point at the character's progress, found by the curvature
   * ahead and wanted again by the correction in the same step */
  uint32_t at_valid;      /* set this step */
  float at_x, at_z;
  float drift_turn;       /* radians */
  float drift_move;       /* metres */
  /* braking: the frame the character comes to rest on */
  uint32_t stop_seq;      /* queue entry (seq) holding it */
  uint32_t stop_offset;   /* frame offset inside that entry's edge */
} smgi_steer;


void smgi_steer_init(smgi_steer* s, uint32_t enabled, float turn_limit,
                     float slide_ratio, float stop_seconds);
/* Limits as in smg_character_desc (0 = default). */
void smgi_steer_set_limits(smgi_steer* s, float turn_limit,
                           float slide_ratio, float stop_seconds);
/* The path changed: follow it again (from rest too). */
void smgi_steer_path_changed(smgi_steer* s);
/* Frames the playhead advances this step: dt * fps scaled by the playback
 * rate (slowing for a tight turn, braking at the end, 0 at rest). */
float smgi_steer_frames(smg_character* ch, float dt);
/* After the playhead passed `pops` edges: the entries now next in line
 * get the correction pending for them written in (smgi_lag_apply). */
void smgi_steer_refresh(smg_character* ch, uint32_t pops);
/* Turn the pose just composed and every queued placement by da radians
 * about (px, pz), then shift them by (tx, tz): the character moves as a
 * whole, its plan with it (rest.c: the hips settling over the feet,
 * turning on the spot). */
void smgi_steer_move(smg_character* ch, float da, float px, float pz,
                     float tx, float tz);
/* Correct the pose just composed and the queued placements (before FK and
 * foot IK, so planted feet keep their world anchors). */
void smgi_steer_apply(smg_character* ch, float dt);

/* No correction pending for the entries beyond the next two. */
static inline void smgi_lag_reset(smgi_steer* s) {
  s->lag_a = s->lag_s = 0.0f;
  s->lag_c = 1.0f;
  s->lag_p[0] = s->lag_p[1] = s->lag_t[0] = s->lag_t[1] = 0.0f;
  s->lag_steps = 0;
}

/* A stored ground transform of a queue entry beyond the next two, as it
 * is now: with the correction made since it was written. */
static inline smgi_xform2 smgi_lag_apply(const smgi_steer* s, smgi_xform2 x) {
  float vx = x.x - s->lag_p[0], vz = x.z - s->lag_p[1];
  smgi_xform2 r;
  r.x = s->lag_p[0] + s->lag_c * vx + s->lag_s * vz + s->lag_t[0];
  r.z = s->lag_p[1] - s->lag_s * vx + s->lag_c * vz + s->lag_t[1];
  r.h = smgi_wrap_angle(x.h + s->lag_a);
  return r;
}

/* The inverse: what to store for an entry beyond the next two that is
 * at x now. */
static inline smgi_xform2 smgi_lag_undo(const smgi_steer* s, smgi_xform2 x) {
  float vx = x.x - s->lag_p[0] - s->lag_t[0];
  float vz = x.z - s->lag_p[1] - s->lag_t[1];
  smgi_xform2 r;
  r.x = s->lag_p[0] + s->lag_c * vx - s->lag_s * vz;
  r.z = s->lag_p[1] + s->lag_s * vx + s->lag_c * vz;
  r.h = smgi_wrap_angle(x.h - s->lag_a);
  return r;
}

/* What the planner should count of an error the steering will remove:
 * the planner asks for every root sample of every sequence it ranks, so
 * these are inline (a call per sample was a tenth of the planning).
 * Turning per metre the steering can add at `speed` m/s: its additive
 * term is at most speed / SMGI_STEER_TURN_RADIUS and turn_limit. */
static inline float smgi_steer_plan_curve(const smgi_steer* s, float speed) {
  float k = 1.0f / SMGI_STEER_TURN_RADIUS;
  if (speed > 1e-3f && s->turn_limit / speed < k) k = s->turn_limit / speed;
  return k;
}

/* How far off the path (metres) the steering brings motion back within
 * its first `u` metres at `speed` m/s (0 with steering off): the part of
 * an edge's distance error the planner's threshold need not see. The
 * additive turning k per metre turns the heading by k u and, with the
 * slide, moves the motion sideways by about ratio u + k u^2 / 2 after u
 * metres; half of that counts as reachable, since the heading must first
 * be turned. */
static inline float smgi_steer_plan_reach(const smgi_steer* s, float u,
                                          float speed) {
  if (!s->enabled || u <= 0.0f) return 0.0f;
  float k = smgi_steer_plan_curve(s, speed);
  return 0.5f * (s->slide_ratio * u + 0.5f * k * u * u);
}

/* e counted at SMGI_STEER_PLAN_WEIGHT within reach, in full beyond */
static inline float smgi_steer_discount(float e, float reach) {
  if (e <= reach) return SMGI_STEER_PLAN_WEIGHT * e;
  return SMGI_STEER_PLAN_WEIGHT * reach + (e - reach);
}

/* `d` metres off the path and `a` radians off its direction after the
 * motion travelled `u` metres at `speed` m/s, as the planner should count
 * them. Corrections within reach count SMGI_STEER_PLAN_WEIGHT of
 * themselves, so the planner still prefers motion that needs little
 * correction; beyond reach in full. Unchanged with steering off. */
static inline void smgi_steer_plan_view(const smgi_steer* s, float u,
                                        float speed, float* d, float* a) {
  if (!s->enabled || u <= 0.0f) return;
  float k = smgi_steer_plan_curve(s, speed);
  *d = smgi_steer_discount(*d, 0.5f * (s->slide_ratio * u + 0.5f * k * u * u));
  *a = smgi_steer_discount(*a, 0.5f * k * u);
}

/* Whether planning from arc s belongs to coming to rest at the path's end:
 * the end lies within what the current speed covers in the braking time
 * plus SMGI_STEER_SETTLE_SECONDS. Where the wanted style has no pose to
 * rest on (derived style_can_stop: a run), the planner then wants the
 * graph's most agile style (walking, in any graph that has it), whose
 * frames with both feet down make a stop. */
int smgi_steer_settling(const smg_character* ch, float s);

#endif /* SMG_STEER_H */
