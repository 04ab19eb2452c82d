/*
 * constraints.c - transition points (lower-body style from an arc length
 * on) and splice points (upper-body action from an arc length on). A small
 * fixed array (capacity chosen at create) scanned linearly: with tens of
 * constraints a scan is cheaper than keeping anything sorted. Data only:
 * the API (character.c) validates, edits through these and has the plan
 * chosen again.
 */
#include <math.h>

#include "constraints.h"

#define ARC_SLACK 1e-4f /* tolerance when comparing with the path length */

uint32_t smgi_style_at(const smgi_constraints* c, float s) {
  uint32_t v = c->base_style;
  float best = c->base_style_arc;
  for (uint32_t i = 0; i < c->count; ++i) {
    const smgi_constraint* k = &c->items[i];
    if (k->kind == SMGI_CONSTRAINT_TRANSITION && k->arc <= s &&
        k->arc > best) {
      best = k->arc;
      v = k->value;
    }
  }
  return v;
}

uint32_t smgi_action_at(const smgi_constraints* c, float s, float* out_arc) {
  uint32_t v = c->base_action;
  float best = c->base_action_arc;
  for (uint32_t i = 0; i < c->count; ++i) {
    const smgi_constraint* k = &c->items[i];
    if (k->kind == SMGI_CONSTRAINT_SPLICE && k->arc <= s && k->arc > best) {
      best = k->arc;
      v = k->value;
    }
  }
  if (out_arc) *out_arc = best;
  return v;
}

float smgi_next_constraint_arc(const smgi_constraints* c, float s) {
  float next = INFINITY;
  for (uint32_t i = 0; i < c->count; ++i) {
    float a = c->items[i].arc;
    if (a > s && a < next) next = a;
  }
  return next;
}

static smg_result check_arc(float path_length, float arc) {
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (arc < 0.0f || arc > path_length + ARC_SLACK)
    return SMG_ERROR_OUT_OF_RANGE;
  return SMG_OK;
}

smg_result smgi_constraints_add(smgi_constraints* c, float path_length,
                                float arc, uint32_t kind, uint32_t value,
                                uint32_t* out_id) {
  smg_result r = check_arc(path_length, arc);
  if (r != SMG_OK) return r;
  if (c->count >= c->capacity) return SMG_ERROR_CAPACITY;
  smgi_constraint* k = &c->items[c->count++];
  k->id = c->next_id++;
  if (c->next_id == 0) c->next_id = 1; /* ids stay > 0 after wrap */
  k->kind = kind;
  k->value = value;
  k->arc = arc;
  k->reported = 0;
  if (out_id) *out_id = k->id;
  return SMG_OK;
}

static smgi_constraint* find(smgi_constraints* c, uint32_t id) {
  for (uint32_t i = 0; i < c->count; ++i)
    if (c->items[i].id == id) return &c->items[i];
  return NULL;
}

smg_result smgi_constraints_move(smgi_constraints* c, float path_length,
                                 uint32_t id, float arc) {
  smg_result r = check_arc(path_length, arc);
  if (r != SMG_OK) return r;
  smgi_constraint* k = find(c, id);
  if (!k) return SMG_ERROR_NOT_FOUND;
  k->arc = arc;
  return SMG_OK;
}

smg_result smgi_constraints_remove(smgi_constraints* c, uint32_t id) {
  smgi_constraint* k = find(c, id);
  if (!k) return SMG_ERROR_NOT_FOUND;
  /* keep insertion order: ties between equal arcs stay deterministic */
  smgi_constraint* end = c->items + c->count;
  for (smgi_constraint* p = k; p + 1 < end; ++p) p[0] = p[1];
  c->count--;
  return SMG_OK;
}
