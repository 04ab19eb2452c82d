/*
 * constraints.c - transition points (lower-body style from an arc length
 * on) and splice points (upper-body action from an arc length on). A small
 * fixed array (capacity chosen at create) scanned linearly: with tens of
 * constraints a scan is cheaper than keeping anything sorted.
 */
#include <math.h>

#include "character_internal.h"

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

static smg_result check_arc(const smg_character* ch, float arc) {
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (arc < 0.0f || arc > ch->path.length + ARC_SLACK)
    return SMG_ERROR_OUT_OF_RANGE;
  return SMG_OK;
}

static smg_result add(smg_character* ch, float arc, uint32_t kind,
                      uint32_t value, uint32_t* out_id) {
  smg_result r = check_arc(ch, arc);
  if (r != SMG_OK) return r;
  if (ch->cons.count >= ch->cons.capacity)
    return SMG_ERROR_CAPACITY;
  smgi_constraint* c = &ch->cons.items[ch->cons.count++];
  c->id = ch->cons.next_id++;
  if (ch->cons.next_id == 0) ch->cons.next_id = 1; /* ids stay > 0 after wrap */
  c->kind = kind;
  c->value = value;
  c->arc = arc;
  if (out_id) *out_id = c->id;
  smgi_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_add_transition(smg_character* ch, float arc,
                                                uint32_t style,
                                                uint32_t* out_id) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (style >= ch->graph->data.style_count) return SMG_ERROR_UNKNOWN_STYLE;
  return add(ch, arc, SMGI_CONSTRAINT_TRANSITION, style, out_id);
}

SMG_API smg_result smg_character_add_splice(smg_character* ch, float arc,
                                            uint32_t action,
                                            uint32_t* out_id) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  if (!isfinite(arc)) return SMG_ERROR_INVALID_ARGUMENT;
  if (action >= ch->graph->data.action_count)
    return SMG_ERROR_UNKNOWN_ACTION;
  return add(ch, arc, SMGI_CONSTRAINT_SPLICE, action, out_id);
}

static smgi_constraint* find(smg_character* ch, uint32_t id) {
  for (uint32_t i = 0; i < ch->cons.count; ++i)
    if (ch->cons.items[i].id == id) return &ch->cons.items[i];
  return NULL;
}

SMG_API smg_result smg_character_move_constraint(smg_character* ch,
                                                 uint32_t id, float arc) {
  if (!ch || id == 0) return SMG_ERROR_INVALID_ARGUMENT;
  smg_result r = check_arc(ch, arc);
  if (r != SMG_OK) return r;
  smgi_constraint* c = find(ch, id);
  if (!c) return SMG_ERROR_NOT_FOUND;
  c->arc = arc;
  smgi_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_remove_constraint(smg_character* ch,
                                                   uint32_t id) {
  if (!ch || id == 0) return SMG_ERROR_INVALID_ARGUMENT;
  smgi_constraint* c = find(ch, id);
  if (!c) return SMG_ERROR_NOT_FOUND;
  /* keep insertion order: ties between equal arcs stay deterministic */
  smgi_constraint* end = ch->cons.items + ch->cons.count;
  for (smgi_constraint* p = c; p + 1 < end; ++p) p[0] = p[1];
  ch->cons.count--;
  smgi_replan(ch);
  return SMG_OK;
}

SMG_API smg_result smg_character_clear_constraints(smg_character* ch) {
  if (!ch) return SMG_ERROR_INVALID_ARGUMENT;
  ch->cons.count = 0;
  smgi_replan(ch);
  return SMG_OK;
}
