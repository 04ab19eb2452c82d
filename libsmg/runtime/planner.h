/*
 * planner.h - the lower body's motion planning (planner.c, with the
 * sequence search in plan_search.c): keeps the lower queue (lower.h)
 * planned about `horizon` seconds ahead with graph edges whose motion
 * follows the path, the paper's search (III.C.2) made incremental.
 */
#ifndef SMG_PLANNER_H
#define SMG_PLANNER_H

#include <stdint.h>

#include "smg.h"

typedef struct smgi_planner {
  float horizon;         /* seconds planned ahead */
  float error_threshold; /* metres: the paper's distance error bound */
  float phase;           /* 0..1 of a step added to the horizon, so a
                            crowd's searches spread over the frames */
  uint32_t backtracks;   /* since the last within-threshold choice */
} smgi_planner;

/* Plan until the horizon is covered or `budget` candidate evaluations were
 * spent; this step's `step_frames` (plus one to interpolate) of lookahead
 * beyond the playhead are guaranteed regardless of budget. */
void smgi_plan(smg_character* ch, uint32_t budget, float step_frames);
/* Path or constraints changed: drop planned entries, keep the head. */
void smgi_replan(smg_character* ch);
/* First edge at create, from ground position (x, z) facing h. */
smg_result smgi_plan_start(smg_character* ch, float x, float z, float h);

#endif /* SMG_PLANNER_H */
