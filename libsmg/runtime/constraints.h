/*
 * constraints.h - what the user asked for along the path (constraints.c):
 * transition points (lower-body style from an arc length on) and splice
 * points (upper-body action from an arc length on), plus the style and
 * action set directly (smg_character_set_style/_action), which hold from
 * where they were set. The planner, the upper body and synchronization
 * only read this; the API edits it (character.c).
 */
#ifndef SMG_CONSTRAINTS_H
#define SMG_CONSTRAINTS_H

#include <stdint.h>

#include "smg.h"

#define SMGI_CONSTRAINT_TRANSITION 0u
#define SMGI_CONSTRAINT_SPLICE 1u

/* A constraint on the path. */
typedef struct smgi_constraint {
  uint32_t id;     /* > 0 */
  uint32_t kind;   /* SMGI_CONSTRAINT_* */
  uint32_t value;  /* style or action */
  float arc;       /* metres along the path */
  uint32_t reported; /* its event was given (events.c) */
} smgi_constraint;

typedef struct smgi_constraints {
  smgi_constraint* items; /* capacity entries, count used */
  uint32_t count, capacity, next_id;
  uint32_t base_style, base_action;      /* set_style/set_action or the
                                            initial ones */
  float base_style_arc, base_action_arc; /* where they apply from (-1:
                                            from the start) */
} smgi_constraints;

uint32_t smgi_style_at(const smgi_constraints* c, float s);
/* *out_arc (optional): where the action found starts applying. */
uint32_t smgi_action_at(const smgi_constraints* c, float s, float* out_arc);
/* Arc of the first constraint strictly after s, or +infinity. */
float smgi_next_constraint_arc(const smgi_constraints* c, float s);

/* Edits. An arc must be finite (else SMG_ERROR_INVALID_ARGUMENT) and lie
 * on a path `path_length` long (else SMG_ERROR_OUT_OF_RANGE). */
smg_result smgi_constraints_add(smgi_constraints* c, float path_length,
                                float arc, uint32_t kind, uint32_t value,
                                uint32_t* out_id);
smg_result smgi_constraints_move(smgi_constraints* c, float path_length,
                                 uint32_t id, float arc);
smg_result smgi_constraints_remove(smgi_constraints* c, uint32_t id);
static inline void smgi_constraints_clear(smgi_constraints* c) {
  c->count = 0;
}

#endif /* SMG_CONSTRAINTS_H */
