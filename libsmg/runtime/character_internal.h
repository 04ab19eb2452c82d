/*
 * character_internal.h - what an smg_character is: the stages' own state
 * structs, each defined in its stage's header, composed here. character.c
 * creates and edits it; playback.c steps it (smgi_step) by running the
 * stages in order. Every buffer is carved out of one block allocated at
 * create, so stepping never allocates.
 */
#ifndef SMG_CHARACTER_INTERNAL_H
#define SMG_CHARACTER_INTERNAL_H

#include <stdint.h>

#include "constraints.h"
#include "graph_derived.h"
#include "graph_internal.h"
#include "ik.h"
#include "lower.h"
#include "path.h"
#include "planner.h"
#include "pose.h"
#include "rest.h"
#include "rmath.h"
#include "smg.h"
#include "steer.h"
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

  /* where the character is along its path (playback.c, update_progress) */
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
};

/* Queue entry i's ground transform as it is now: the steering keeps the
 * next two entries corrected, further ones get the correction made since
 * they were written when read (steer.h, smgi_lag_apply). */
static inline smgi_xform2 smgi_q_ground(const smg_character* ch, uint32_t i) {
  const smgi_qentry* q = smgi_q_at_c(&ch->lower, i);
  return i < 2u ? q->W : smgi_lag_apply(&ch->steer, q->W);
}

/* One frame: plan, advance, upper body, pose, steering, IK, progress
 * (playback.c). */
smg_result smgi_step(smg_character* ch, float dt);

#endif /* SMG_CHARACTER_INTERNAL_H */
