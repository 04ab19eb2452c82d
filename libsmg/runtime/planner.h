/*
 * planner.h - the lower body's motion planning (planner.c, with the
 * sequence search in plan_search.c): keeps the lower queue (lower.h)
 * planned about `horizon` seconds ahead with graph edges whose motion
 * follows the path, the paper's search (III.C.2) made incremental.
 * Inputs: the step's (graph, path, constraints, progress; step_in.h) and
 * what the root steering will correct (steer_envelope.h); output: the
 * planned entries of the lower timeline.
 */
#ifndef SMG_PLANNER_H
#define SMG_PLANNER_H

#include <stdint.h>

#include "lower.h"
#include "smg.h"
#include "steer_envelope.h"
#include "step_in.h"

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
void smgi_plan(smgi_planner* pl, smgi_lower* lower, const smgi_step_in* in,
               const smgi_steer_envelope* steer, uint32_t budget,
               float step_frames);
/* Path or constraints changed: drop planned entries, keep the head (or,
 * before anything played, choose the head again). Entries dropped take
 * their seq with them: whoever refers to one (a scheduled splice) must
 * check that it is still in the queue. */
void smgi_replan(smgi_planner* pl, smgi_lower* lower, const smgi_step_in* in,
                 const smgi_steer_envelope* steer);
/* First edge at create, from ground position (x, z) facing h; the start
 * node of the initial style is chosen with the seeded `rng`. */
smg_result smgi_plan_start(smgi_planner* pl, smgi_lower* lower,
                           const smgi_step_in* in,
                           const smgi_steer_envelope* steer, uint32_t* rng,
                           float x, float z, float h);

#endif /* SMG_PLANNER_H */
