/*
 * character_state.h - what an smg_character is: the stages' own state
 * structs, each defined in its stage's header, composed here. character.c
 * creates and edits it; step.c steps it (smgi_step) by running the stages
 * in order, handing each its own state and its inputs. Of the library,
 * only those two files include this header (a test that inspects a
 * character's state may too). Every buffer is carved out of one block
 * allocated at create, so stepping never allocates.
 */
#ifndef SMG_CHARACTER_STATE_H
#define SMG_CHARACTER_STATE_H

#include <stdint.h>

#include "constraints.h"
#include "events.h"
#include "graph_derived.h"
#include "graph_data.h"
#include "ik.h"
#include "lower.h"
#include "path.h"
#include "planner.h"
#include "pose.h"
#include "rest.h"
#include "rmath.h"
#include "root_motion.h"
#include "smg.h"
#include "steer.h"
#include "step_in.h"
#include "sync.h"
#include "tuning.h"
#include "upper.h"

struct smg_character {
  smg_graph* graph;
  smg_allocator allocator;
  uint32_t joint_count;
  uint32_t flags;          /* SMG_CHARACTER_* from the desc */
  uint32_t rng;            /* seeded xorshift: every random choice */
  float fps;               /* the graph's frame rate */
  double time;             /* seconds stepped */

  /* what to follow */
  smgi_path path;
  smgi_constraints cons;
  float anchor[2];         /* where to stay when there is no path to follow */

  /* where the character is along its path (step.c, update_progress) */
  float progress;          /* arc length of the ground position's projection */
  uint32_t seg;            /* segment of that projection */
  float path_error;        /* distance from the path there */
  uint32_t end_reached;

  /* the stages, in step order */
  smgi_planner plan;
  smgi_lower lower;
  smgi_upper upper;
  smgi_sync sync;
  smgi_pose pose;
  smgi_steer steer;
  smgi_rest rest;
  smgi_ik ik;

  /* for the engine: what the last step did */
  smgi_events events;
  smgi_root_motion root_motion;
};

/* What every stage may read besides its own state (step_in.h). */
static inline smgi_step_in smgi_step_in_of(const smg_character* ch) {
  smgi_step_in in;
  in.graph = ch->graph;
  in.path = &ch->path;
  in.cons = &ch->cons;
  in.fps = ch->fps;
  in.progress = ch->progress;
  in.seg = ch->seg;
  in.path_error = ch->path_error;
  in.anchor[0] = ch->anchor[0];
  in.anchor[1] = ch->anchor[1];
  in.time = ch->time;
  return in;
}

/* One frame: steering's re-plan and rate, plan, advance, upper body,
 * pose, steering, IK, progress (step.c). */
smg_result smgi_step(smg_character* ch, float dt);
/* Path, constraints or threshold changed (or the steering asked): drop
 * the planned entries and what referred to them (step.c). */
void smgi_character_replan(smg_character* ch);

#endif /* SMG_CHARACTER_STATE_H */
