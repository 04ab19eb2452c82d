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
static inline float smgi_steer_curve_of(float turn_limit, float speed) {
  float k = 1.0f / SMGI_STEER_TURN_RADIUS;
  if (speed > 1e-3f && turn_limit / speed < k) k = turn_limit / speed;
  return k;
}

static inline float smgi_steer_plan_curve(const smgi_steer_envelope* s,
                                          float speed) {
  return smgi_steer_curve_of(s->turn_limit, speed);
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

/* e counted at SMGI_STEER_PLAN_WEIGHT within reach, in full beyond */
static inline float smgi_steer_discount(float e, float reach) {
  if (e <= reach) return SMGI_STEER_PLAN_WEIGHT * e;
  return SMGI_STEER_PLAN_WEIGHT * reach + (e - reach);
}

/* What the planner's search reads of the envelope for each root sample
 * it values (smgi_steer_plan_view), derived once per search by
 * smgi_steer_plan_of: the limits of the steering slowing down for a turn
 * (smgi_steer_slowest) and of it cutting one (steer.c: down to
 * smgi_steer_cut_floor, turning at SMGI_STEER_CUT_TURN times the limit
 * and sliding at SMGI_STEER_CUT_SLIDE of the ratio) beside its own. Every
 * sample re-derived them (a tenth of a sample's instructions). */
typedef struct smgi_steer_plan {
  uint32_t enabled;      /* steering on */
  float turn_limit;      /* the envelope's */
  float slide_ratio;     /* the envelope's */
  float slow_share;      /* smgi_steer_slowest */
  float cut_share;       /* smgi_steer_cut_floor of the slide ratio */
  float cut_turn_limit;  /* turn_limit * SMGI_STEER_CUT_TURN */
  float cut_slide_ratio; /* slide_ratio * SMGI_STEER_CUT_SLIDE */
  /* 1 when the slowed and cutting envelopes turn no less per metre than
   * the plain one wherever it turns its most (shares of the speed <= 1,
   * the cut's limit >= the plain one) and slide no more (slide ratio >=
   * 0): smgi_steer_plan_view's shortcut */
  uint32_t nested;
} smgi_steer_plan;

static inline smgi_steer_plan smgi_steer_plan_of(const smgi_steer_envelope* s) {
  smgi_steer_plan p;
  p.enabled = s->enabled;
  p.turn_limit = s->turn_limit;
  p.slide_ratio = s->slide_ratio;
  p.slow_share = smgi_steer_slowest(s);
  p.cut_share = smgi_steer_cut_floor(s->slide_ratio);
  p.cut_turn_limit = s->turn_limit * SMGI_STEER_CUT_TURN;
  p.cut_slide_ratio = s->slide_ratio * SMGI_STEER_CUT_SLIDE;
  p.nested = p.slow_share <= 1.0f && p.cut_share <= 1.0f &&
             p.cut_turn_limit >= p.turn_limit && p.slide_ratio >= 0.0f &&
             p.cut_slide_ratio <= p.slide_ratio;
  return p;
}

/* One root sample `*d` metres off the path and `*a` radians off its
 * direction after the motion travelled `u` metres at `speed` m/s:
 * returns the part of *d that no correction removes, and turns *d and *a
 * into what the planner should count of them.
 *  - What no correction removes lies beyond the reach of the steering
 *    slowing down for the turn or cutting it, whichever reaches further
 *    (smgi_steer_plan_reach at the slowed speed and limits). Counting
 *    only the slowing had the planner hand a run to the walk at a hairpin
 *    the steering was cutting (a Bandai Namco runner on the scribble,
 *    2.5 m).
 *  - Corrections within the steering's reach at the motion's own speed
 *    count SMGI_STEER_PLAN_WEIGHT of themselves (smgi_steer_discount), so
 *    the planner still prefers motion that needs little correction;
 *    beyond reach in full. Unchanged with steering off.
 * The arithmetic is smgi_steer_plan_reach's for each of them: the plain envelope's turning k moves the motion sideways
 * by half of slide u + k u^2 / 2 and turns it by half of k u. */
static inline float smgi_steer_plan_view(const smgi_steer_plan* p, float u,
                                           float speed, float* d, float* a) {
  const float e = *d;
  if (!p->enabled || u <= 0.0f) return e > 0.0f ? e : 0.0f;
  const float k = smgi_steer_curve_of(p->turn_limit, speed);
  if (p->nested && k == 1.0f / SMGI_STEER_TURN_RADIUS) {
    /* the plain envelope turns its most (most samples: the limit allows
     * more than the radius at the motion's speed); a slower speed and a
     * larger limit only allow more, so the slowed and the cutting turn
     * their most too, and the cut, sliding less, reaches less far than
     * the slowing: the same values without two divisions. With k = 2,
     * 0.5 k u is u exactly, and both reaches are half of slide u + u^2. */
    const float reach = 0.5f * (p->slide_ratio * u + u * u);
    *d = smgi_steer_discount(e, reach);
    *a = smgi_steer_discount(*a, u);
    return e > reach ? e - reach : 0.0f;
  }
  const float k_slow =
      smgi_steer_curve_of(p->turn_limit, speed * p->slow_share);
  const float k_cut =
      smgi_steer_curve_of(p->cut_turn_limit, speed * p->cut_share);
  const float slide = p->slide_ratio * u;
  const float slowed = 0.5f * (slide + 0.5f * k_slow * u * u);
  const float cutting = 0.5f * (p->cut_slide_ratio * u + 0.5f * k_cut * u * u);
  const float reach = slowed > cutting ? slowed : cutting;
  const float turn = 0.5f * k * u;
  *d = smgi_steer_discount(e, 0.5f * (slide + turn * u));
  *a = smgi_steer_discount(*a, turn);
  return e > reach ? e - reach : 0.0f;
}

#endif /* SMG_STEER_ENVELOPE_H */
