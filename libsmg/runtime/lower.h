/*
 * lower.h - the lower body's timeline: a ring of graph edges (the head
 * entry playing, the rest planned), the fractional playhead into the
 * head, and the steering correction still pending for the entries beyond
 * the next two (lower.c). The planner (planner.c) appends and drops
 * planned entries; the step (step.c) advances the playhead and pops
 * finished edges (smgi_lower_advance); steering (steer.c) moves the
 * placements; pose, upper body and synchronization look frames up
 * through it.
 */
#ifndef SMG_LOWER_H
#define SMG_LOWER_H

#include <stdint.h>

#include "graph_data.h"
#include "rmath.h"
#include "tuning.h"

/* One lower-graph edge in the queue. The head entry is playing; the others
 * are planned and may be dropped and re-planned at any time. */
typedef struct smgi_qentry {
  uint32_t edge;
  uint32_t seq;         /* increases by one per pushed entry */
  smgi_xform2 W;        /* ground transform at the edge start */
  smgi_xform2 M;        /* W * inverse(ground(from.frame)): frame -> world */
  float s_start, s_end; /* planned progress along the path */
  uint32_t seg_end;     /* path segment hint at s_end */
  uint16_t rank;        /* which candidate (0 = best) this was */
  uint16_t cand_count;  /* candidates that were available */
  float err;            /* distance error of the choice */
} smgi_qentry;

/* The steering correction made since the entries beyond the next two
 * were written, as one transform (smgi_lag_apply): those entries are
 * corrected when read instead of written every step. A turn by a (cos,
 * sin in c, s) about p, then a shift by t: kept about a point near the
 * character, so its numbers stay small far from the origin. Steering
 * composes it (steer.c); the planner stores new entries through its
 * inverse and drops it with the entries it re-plans. */
typedef struct smgi_lag {
  float a, c, s, p[2], t[2];
  uint32_t steps;       /* steps composed into it */
} smgi_lag;

typedef struct smgi_lower {
  smgi_qentry* queue;   /* ring of SMGI_QUEUE_CAP */
  uint32_t head, count, next_seq;
  uint32_t frames;      /* sum of frame counts of the queued edges, kept
                           incrementally: scanning the queue every step
                           would touch every planned entry */
  float t;              /* frames into the head edge (fractional) */
  uint32_t node;        /* lower node last passed */
  uint32_t style;       /* label of the edge playing */
  uint32_t last_frame;  /* key of the integer lower frame last processed */
  smgi_lag lag;         /* pending for the entries beyond the next two */
  /* a stop from the data planned (stop_match.h): the queue entry (seq)
   * and frame offset its hips rest on; stop_seq SMGI_NONE: none. Written
   * by the planner, which drops it with the plan; read by the steering */
  uint32_t stop_seq, stop_offset;
} smgi_lower;

/* No correction pending for the entries beyond the next two. */
static inline void smgi_lag_reset(smgi_lag* l) {
  l->a = l->s = 0.0f;
  l->c = 1.0f;
  l->p[0] = l->p[1] = l->t[0] = l->t[1] = 0.0f;
  l->steps = 0;
}

/* A stored ground transform of a queue entry beyond the next two, as it
 * is now: with the correction made since it was written. */
static inline smgi_xform2 smgi_lag_apply(const smgi_lag* l, smgi_xform2 x) {
  float vx = x.x - l->p[0], vz = x.z - l->p[1];
  smgi_xform2 r;
  r.x = l->p[0] + l->c * vx + l->s * vz + l->t[0];
  r.z = l->p[1] - l->s * vx + l->c * vz + l->t[1];
  r.h = smgi_wrap_angle(x.h + l->a);
  return r;
}

/* The inverse: what to store for an entry beyond the next two that is
 * at x now. */
static inline smgi_xform2 smgi_lag_undo(const smgi_lag* l, smgi_xform2 x) {
  float vx = x.x - l->p[0] - l->t[0];
  float vz = x.z - l->p[1] - l->t[1];
  smgi_xform2 r;
  r.x = l->p[0] + l->c * vx - l->s * vz;
  r.z = l->p[1] + l->s * vx + l->c * vz;
  r.h = smgi_wrap_angle(x.h - l->a);
  return r;
}

static inline smgi_qentry* smgi_q_at(smgi_lower* l, uint32_t i) {
  return &l->queue[(l->head + i) & (SMGI_QUEUE_CAP - 1u)];
}
static inline const smgi_qentry* smgi_q_at_c(const smgi_lower* l,
                                             uint32_t i) {
  return &l->queue[(l->head + i) & (SMGI_QUEUE_CAP - 1u)];
}
/* Frames planned beyond the playhead. */
static inline float smgi_frames_ahead(const smgi_lower* l) {
  return (float)l->frames - l->t;
}
/* Queue entry i's ground transform as it is now: the steering keeps the
 * next two entries corrected, further ones get the correction made since
 * they were written when read (smgi_lag_apply). */
static inline smgi_xform2 smgi_q_ground(const smgi_lower* l, uint32_t i) {
  const smgi_qentry* q = smgi_q_at_c(l, i);
  return i < 2u ? q->W : smgi_lag_apply(&l->lag, q->W);
}
/* Queue entry i's placement (frame -> world), the same way: the lag is a
 * rigid transform applied on the world side, so it moves M as it moves
 * W. */
static inline smgi_xform2 smgi_q_placement(const smgi_lower* l, uint32_t i) {
  const smgi_qentry* q = smgi_q_at_c(l, i);
  return i < 2u ? q->M : smgi_lag_apply(&l->lag, q->M);
}
/* Entry i (beyond the next two when the lag was composed) as it is now:
 * the pending correction written into its W and M. */
void smgi_lower_lag_write_entry(smgi_lower* l, uint32_t i);

/* Lower frame sample position: entry index and frame offset of the
 * playhead plus k frames (returns 0 when beyond the queue). */
int smgi_q_locate(const smgi_lower* l, const smgi_edge* edges, uint32_t k,
                  uint32_t* entry, uint32_t* offset);
/* Advance the playhead by `frames`, popping finished edges (a dead end
 * holds the last frame); the entries that moved to index 0 or 1 from
 * further back get their pending correction written in, and `style`
 * becomes the label of the edge now playing. Returns the number of edges
 * popped. */
uint32_t smgi_lower_advance(smgi_lower* l, const smgi_edge* edges,
                            float frames);

#endif /* SMG_LOWER_H */
