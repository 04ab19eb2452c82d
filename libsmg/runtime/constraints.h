/*
 * constraints.h - what the user asked for along the path (constraints.c):
 * transition points (lower-body style from an arc length on) and splice
 * points (upper-body action from an arc length on), plus the style and
 * action set directly (smg_character_set_style/_action), which hold from
 * where they were set. The planner, the upper body and synchronization
 * only read this.
 */
#ifndef SMG_CONSTRAINTS_H
#define SMG_CONSTRAINTS_H

#include <stdint.h>

#define SMGI_CONSTRAINT_TRANSITION 0u
#define SMGI_CONSTRAINT_SPLICE 1u

/* A constraint on the path. */
typedef struct smgi_constraint {
  uint32_t id;     /* > 0 */
  uint32_t kind;   /* SMGI_CONSTRAINT_* */
  uint32_t value;  /* style or action */
  float arc;       /* metres along the path */
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

#endif /* SMG_CONSTRAINTS_H */
