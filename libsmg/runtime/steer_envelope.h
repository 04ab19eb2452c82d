/*
 * steer_envelope.h - what the planner should make of the root steering
 * (steer.c): the steering's limits and the motion's own speed, copied from
 * the steering state by the step before planning (smgi_steer_envelope_of,
 * steer.h), and the inline math that turns them into the part of a path
 * error the steering will remove. The planner asks this for every root
 * sample of every sequence it ranks, so it is inline (a call per sample
 * was a tenth of the planning).
 */
#ifndef SMG_STEER_ENVELOPE_H
#define SMG_STEER_ENVELOPE_H

#include <stdint.h>

#include "tuning.h"

typedef struct smgi_steer_envelope {
  uint32_t enabled;    /* steering on */
  float turn_limit;    /* rad/s of heading correction beyond the clip's */
  float slide_ratio;   /* translation per metre the motion travels */
  float stop_seconds;  /* braking time at the end */
  float own_speed;     /* the motion's own ground speed, m/s */
} smgi_steer_envelope;

/* Turning per metre the steering can add at `speed` m/s: its additive
 * term is at most speed / SMGI_STEER_TURN_RADIUS and turn_limit. */
static inline float smgi_steer_plan_curve(const smgi_steer_envelope* s,
                                          float speed) {
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
static inline float smgi_steer_plan_reach(const smgi_steer_envelope* s,
                                          float u, float speed) {
  if (!s->enabled || u <= 0.0f) return 0.0f;
  float k = smgi_steer_plan_curve(s, speed);
  return 0.5f * (s->slide_ratio * u + 0.5f * k * u * u);
}

/* The slowest share of the motion's speed the steering takes a tight turn
 * at (steer.c): playback down to SMGI_STEER_RATE_MIN, strides shortened
 * by up to the slide ratio. */
static inline float smgi_steer_slowest(const smgi_steer_envelope* s) {
  return SMGI_STEER_RATE_MIN * (1.0f - s->slide_ratio);
}

/* The slowest share of the motion's speed a cut takes a turn at that
 * no tight-turn slowing makes (a hairpin, steer.c): playback at
 * SMGI_STEER_RATE_MIN, strides shortened as far as a run's braking to a
 * stop shortens them (SMGI_STEER_STRIDE_STOP), or by the slide ratio when
 * that is more. */
static inline float smgi_steer_cut_floor(float slide_ratio) {
  const float stride = 1.0f - slide_ratio < SMGI_STEER_STRIDE_STOP
                           ? 1.0f - slide_ratio
                           : SMGI_STEER_STRIDE_STOP;
  return SMGI_STEER_RATE_MIN * stride;
}

/* How far off the path the steering can bring motion back within its
 * first `u` metres at `speed` m/s when it also slows down for the turn
 * (smgi_steer_slowest), or cuts it (steer.c: down to
 * smgi_steer_cut_floor, turning at SMGI_STEER_CUT_TURN times the limit
 * and sliding at SMGI_STEER_CUT_SLIDE of the ratio), whichever reaches
 * further: what no correction removes lies beyond this. Counting only
 * the slowing had the planner hand a run to the walk at a hairpin the
 * steering was cutting (a Bandai Namco runner on the scribble, 2.5 m). */
static inline float smgi_steer_plan_reach_slowed(const smgi_steer_envelope* s,
                                                 float u, float speed) {
  smgi_steer_envelope cut = *s;
  cut.turn_limit *= SMGI_STEER_CUT_TURN;
  cut.slide_ratio *= SMGI_STEER_CUT_SLIDE;
  const float slowed = smgi_steer_plan_reach(s, u, speed * smgi_steer_slowest(s));
  const float cutting =
      smgi_steer_plan_reach(&cut, u, speed * smgi_steer_cut_floor(s->slide_ratio));
  return slowed > cutting ? slowed : cutting;
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
static inline void smgi_steer_plan_view(const smgi_steer_envelope* s,
                                        float u, float speed, float* d,
                                        float* a) {
  if (!s->enabled || u <= 0.0f) return;
  float k = smgi_steer_plan_curve(s, speed);
  *d = smgi_steer_discount(*d, 0.5f * (s->slide_ratio * u + 0.5f * k * u * u));
  *a = smgi_steer_discount(*a, 0.5f * k * u);
}

#endif /* SMG_STEER_ENVELOPE_H */
