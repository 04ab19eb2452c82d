/*
 * lower.h - the lower body's timeline: a ring of graph edges (the head
 * entry playing, the rest planned) and the fractional playhead into the
 * head. The planner (planner.c) appends and drops planned entries;
 * playback (playback.c) advances the playhead and pops finished edges;
 * pose, upper body and synchronization look frames up through it.
 */
#ifndef SMG_LOWER_H
#define SMG_LOWER_H

#include <stdint.h>

#include "graph_internal.h"
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
} smgi_lower;

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
/* Lower frame sample position: entry index and frame offset of the
 * playhead plus k frames (returns 0 when beyond the queue). */
int smgi_q_locate(const smgi_lower* l, const smgi_edge* edges, uint32_t k,
                  uint32_t* entry, uint32_t* offset);

#endif /* SMG_LOWER_H */
