/*
 * events.c - the event queue of a step (events.h). Constraints are matched
 * to what the step shows, not to where they lie on the path: the planner
 * reaches a transition a little before or after its arc (where the graph
 * has one), and a splice waits for a splice candidate, so the event comes
 * at the step whose frame first shows the new style or action. Every
 * constraint gives exactly one event (taken, reached unchanged, or
 * superseded); smgi_constraint.reported remembers which have.
 *
 * Footsteps are read from the toes as shown (after foot IK), not from the
 * contact labels: a label starts when the heel or the toe is down, frames
 * before or after the toe itself lands, and a sound or a dust puff belongs
 * to the toe. A foot lands when its toe comes within LAND_HEIGHT of the
 * lowest it has stood above its ground, moving slower than LAND_SPEED; it
 * lifts off once it leaves twice those bounds (hysteresis: a toe rolling
 * on the floor does not land again).
 */
#include <math.h>
#include <string.h>

#include "events.h"

/* How fast the toe's downward speed is averaged: over about 0.1 s, the
 * last part of a foot's descent (how hard it lands). */
#define DESCENT_SECONDS 0.1f
/* Landing bounds in leg lengths (about 4 cm) and leg lengths per second
 * (about 13 cm/s): a planted toe still settles and rolls by a fraction of
 * a millimetre a frame. */
#define LAND_HEIGHT 0.05f
#define LAND_SPEED 0.15f

void smgi_events_reset(smgi_events* ev) {
  smg_event* items = ev->items;
  uint32_t capacity = ev->capacity;
  memset(ev, 0, sizeof *ev);
  ev->items = items;
  ev->capacity = capacity;
  ev->stand[0] = ev->stand[1] = INFINITY;
}

static smg_event* push(smgi_events* ev, uint32_t type,
                       const smgi_events_in* in) {
  /* cannot fail: capacity covers every constraint, two feet and the end */
  if (ev->count >= ev->capacity) return NULL;
  smg_event* e = &ev->items[ev->count++];
  memset(e, 0, sizeof *e);
  e->struct_size = (uint32_t)sizeof *e;
  e->type = type;
  memcpy(e->position, in->ground, sizeof e->position);
  e->arc_length = in->progress;
  return e;
}

static void report(smgi_events* ev, smgi_constraint* c, uint32_t flags,
                   const smgi_events_in* in) {
  smg_event* e = push(ev, SMG_EVENT_CONSTRAINT, in);
  c->reported = 1;
  if (!e) return;
  e->id = c->id;
  e->value = c->value;
  e->flags = flags | (c->kind == SMGI_CONSTRAINT_SPLICE ? SMG_EVENT_SPLICE : 0u);
}

/* The earliest unreported constraint of `kind` after `after` (by arc;
 * insertion order among equal arcs), with value `value` unless any. */
static smgi_constraint* first_pending(smgi_constraints* cons, uint32_t kind,
                                      float after, int any, uint32_t value) {
  smgi_constraint* best = NULL;
  for (uint32_t i = 0; i < cons->count; ++i) {
    smgi_constraint* c = &cons->items[i];
    if (c->reported || c->kind != kind || !(c->arc > after)) continue;
    if (!any && c->value != value) continue;
    if (!best || c->arc < best->arc) best = c;
  }
  return best;
}

/* One kind of constraint (transitions: style; splices: action). */
static void constraints_of(smgi_events* ev, smgi_constraints* cons,
                           uint32_t kind, uint32_t before, uint32_t now,
                           float base_arc, const smgi_events_in* in) {
  /* set_style/set_action override every constraint before where they were
   * set: those will never take effect */
  for (uint32_t i = 0; i < cons->count; ++i) {
    smgi_constraint* c = &cons->items[i];
    if (!c->reported && c->kind == kind && c->arc <= base_arc)
      report(ev, c, SMG_EVENT_SUPERSEDED, in);
  }
  if (ev->started && now != before) {
    smgi_constraint* m = first_pending(cons, kind, base_arc, 0, now);
    if (m) {
      /* pending ones before it were overtaken: the graph went on to it */
      for (smgi_constraint* p; (p = first_pending(cons, kind, base_arc, 1, 0)) != m;)
        report(ev, p, SMG_EVENT_SUPERSEDED, in);
      report(ev, m, 0u, in);
    } else {
      /* a change no constraint asked for: set_style/set_action, or the
       * steering walking the last metres to stop */
      smg_event* e = push(ev, SMG_EVENT_CONSTRAINT, in);
      if (e) {
        e->value = now;
        e->flags = kind == SMGI_CONSTRAINT_SPLICE ? SMG_EVENT_SPLICE : 0u;
      }
    }
  }
  /* passed ones: the latest passed is what is wanted now; earlier ones
   * that never took effect are superseded by it; it is reached unchanged
   * when its value is already shown (else it waits for the change) */
  smgi_constraint* latest = NULL;
  for (uint32_t i = 0; i < cons->count; ++i) {
    smgi_constraint* c = &cons->items[i];
    if (c->reported || c->kind != kind || !(c->arc > base_arc) ||
        c->arc > in->progress)
      continue;
    if (!latest || c->arc >= latest->arc) latest = c;
  }
  if (!latest) return;
  for (uint32_t i = 0; i < cons->count; ++i) {
    smgi_constraint* c = &cons->items[i];
    if (c != latest && !c->reported && c->kind == kind &&
        c->arc > base_arc && c->arc <= latest->arc)
      report(ev, c, SMG_EVENT_SUPERSEDED, in);
  }
  if (latest->value == now) report(ev, latest, SMG_EVENT_UNCHANGED, in);
}

static void footsteps(smgi_events* ev, const smgi_events_in* in) {
  const float band = LAND_HEIGHT * in->leg_length;
  const float slow = LAND_SPEED * in->leg_length;
  for (uint32_t f = 0; f < 2u; ++f) {
    const float* toe = in->toe[f];
    if (!toe) continue;
    const float h = toe[1] - in->floor[f];
    if (h < ev->stand[f]) ev->stand[f] = h;
    /* a step of dt 0 moves nothing: judged at the next real step */
    if (ev->started && in->dt > 0.0f) {
      const float dx = toe[0] - ev->toe[f][0], dy = toe[1] - ev->toe[f][1],
                  dz = toe[2] - ev->toe[f][2];
      const float speed = sqrtf(dx * dx + dy * dy + dz * dz) / in->dt;
      const float k = in->dt < DESCENT_SECONDS ? in->dt / DESCENT_SECONDS : 1.0f;
      ev->descent[f] += ((dy < 0.0f ? -dy / in->dt : 0.0f) - ev->descent[f]) * k;
      const float above = h - ev->stand[f];
      if (!ev->down[f] && above < band && speed < slow) {
        ev->down[f] = 1u;
        smg_event* e = push(ev, SMG_EVENT_FOOTSTEP, in);
        if (e) {
          e->id = f;
          memcpy(e->position, toe, sizeof e->position);
          e->strength = ev->descent[f];
        }
      } else if (ev->down[f] && (above > 2.0f * band || speed > 2.0f * slow)) {
        ev->down[f] = 0u;
      }
    }
    memcpy(ev->toe[f], toe, sizeof ev->toe[f]);
  }
}

void smgi_events_collect(smgi_events* ev, smgi_constraints* cons,
                         const smgi_events_in* in) {
  constraints_of(ev, cons, SMGI_CONSTRAINT_TRANSITION, ev->style, in->style,
                 cons->base_style_arc, in);
  constraints_of(ev, cons, SMGI_CONSTRAINT_SPLICE, ev->action, in->action,
                 cons->base_action_arc, in);
  footsteps(ev, in);
  if (ev->started && in->end_reached && !ev->end_reached)
    push(ev, SMG_EVENT_PATH_END, in);
  ev->end_reached = in->end_reached;
  ev->style = in->style;
  ev->action = in->action;
  ev->started = 1u;
}
