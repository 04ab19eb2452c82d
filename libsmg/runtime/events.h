/*
 * events.h - what happened in the last step, for the engine to read after
 * it (events.c; smg_character_get_events): constraints taking effect,
 * footsteps, arriving at the path's end. The queue is carved out of the
 * character's block at create with room for every event one step can
 * give, so it never overflows and the step never allocates.
 */
#ifndef SMG_EVENTS_H
#define SMG_EVENTS_H

#include <stdint.h>

#include "constraints.h"
#include "smg.h"

typedef struct smgi_events {
  smg_event* items;      /* capacity entries, count used (the last step's) */
  uint32_t count, capacity;
  uint32_t started;      /* a step has been seen: style and action below
                            are what the previous step showed */
  uint32_t style, action;
  uint32_t end_reached;
  /* per foot, from the toe's geometry */
  uint32_t down[2];      /* standing: landed, not lifted off since */
  float stand[2];        /* lowest the toe has been above its ground
                            (INFINITY: not yet seen) */
  float toe[2][3];       /* toe at the previous step */
  float descent[2];      /* toe's downward speed, low-passed, m/s */
} smgi_events;

/* What the step shows at its end, as the events stage reads it. */
typedef struct smgi_events_in {
  uint32_t style, action;   /* at the playhead */
  float progress;           /* path distance */
  float ground[3];          /* ground position (x, y, z) */
  const float* toe[2];      /* world toe (left, right), NULL: no leg */
  float floor[2];           /* ground height under each toe */
  uint32_t end_reached;
  float leg_length;         /* hip to ankle at rest, metres */
  float dt;
} smgi_events_in;

/* Room one step can need: every constraint once, a change no constraint
 * asked for per kind, two feet, the end. */
static inline uint32_t smgi_events_capacity(uint32_t constraint_capacity) {
  return constraint_capacity + 5u;
}

/* Nothing seen yet (at create). */
void smgi_events_reset(smgi_events* ev);

/* Forget the last step's events (at the start of a step). */
static inline void smgi_events_clear(smgi_events* ev) { ev->count = 0; }

/* Record this step's events; marks the constraints whose event was given
 * (smgi_constraint.reported). */
void smgi_events_collect(smgi_events* ev, smgi_constraints* cons,
                         const smgi_events_in* in);

#endif /* SMG_EVENTS_H */
