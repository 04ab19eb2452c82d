/*
 * settings.h - a character's settings with every default settled
 * (settings.c): the one place the runtime decides what a 0 in
 * smg_character_desc, or in a setter's argument, stands for. The values
 * come from tuning.h.
 */
#ifndef SMG_SETTINGS_H
#define SMG_SETTINGS_H

#include <stdint.h>

#include "graph_data.h"
#include "smg.h"

typedef struct smgi_settings {
  uint32_t path_capacity, constraint_capacity;
  float horizon;          /* seconds planned ahead */
  float error_threshold;  /* metres: the paper's distance error bound */
  float turn_limit;       /* steering: rad/s of additive heading correction */
  float slide_ratio;      /* steering: translation per metre of motion */
  float stop_seconds;     /* steering: braking time at the end */
  float swing_clearance;  /* metres (0: off, SMG_CHARACTER_NO_SWING_CLEARANCE) */
  float swing_default;    /* the clearance a 0 stands for on this skeleton */
  float fade_rate;        /* upper-body crossfades per second: 1 / the
                             graph's window */
} smgi_settings;

/* Settle every default of `d` (already validated: every field in range,
 * 0 = default) for graph `g`. */
void smgi_settle(const smg_graph* g, const smg_character_desc* d,
                 smgi_settings* out);

#endif /* SMG_SETTINGS_H */
