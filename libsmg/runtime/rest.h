/*
 * rest.h - standing still (rest.c): what a character does from the moment
 * the steering brings it to rest at its path's end until it walks on.
 */
#ifndef SMG_REST_H
#define SMG_REST_H

#include <stdint.h>

#include "graph_data.h"
#include "ik.h"
#include "lower.h"
#include "pose.h"
#include "rmath.h"
#include "smg.h"
#include "steer.h"
#include "step_in.h"
#include "upper.h"

#define SMGI_REST_OFF 0u    /* following the locomotion */
#define SMGI_REST_SETTLE 1u /* the last step: feet beside each other, hips
                               gliding on over them */
#define SMGI_REST_STAND 2u  /* standing: the graph's standing motion */
#define SMGI_REST_TURN 3u   /* turning on the spot towards a path behind */
#define SMGI_REST_LEAVE 4u  /* fading back into the locomotion */

typedef struct smgi_rest {
  uint32_t phase;       /* SMGI_REST_* */
  float t;              /* seconds into the phase */
  float dt;             /* of this step */
  float w;              /* weight of the standing pose over the locomotion */
  float w_from;         /* w when the fade out began */
  float at, dir;        /* standing motion: frames into it, +1 or -1 */
  smgi_xform2 M;        /* its frames -> world */
  float rise;           /* and raised by this much: its floor on the
                           stop's */
  float hold[2][2];     /* where each toe stands (x, z) */
  uint32_t foot;        /* the foot stepping now (0 left, 1 right) */
  float from[2];        /* its toe where the step began (x, z) */
  float glide[2];       /* the hips' ground shift of the settling step */
  float glided;         /* of it shown now (0..1) */
  float glide_from;     /* glided when the fade out began */
  float settle_seconds; /* how long the hips take to come to stand */
  float step_seconds;   /* how long the settling step takes */
  float hips_cap;       /* share of their way the hips go before the step
                           lands (1: as far as their ease-out takes them) */
  float pivot[2];       /* turning: about this ground point */
  float turn;           /* radians to turn in all (+ = left) */
  float turned;         /* radians turned so far */
  float turn_seconds;   /* how long the turn takes */
  uint32_t steps;       /* steps the turn takes */
  uint32_t step;        /* the turn's step under way (SMGI_NONE: none) */
  float placed[2];      /* turn made when each foot was last placed */
  uint32_t keep;        /* fading out: bit f while foot f stays where it
                           stood, until the locomotion lifts it */
  float rejoin[2];      /* then seconds since it followed the locomotion's
                           foot from there */
} smgi_rest;

/* What the stage reads and moves besides its own state: the step's
 * inputs (graph, path, progress), the steering (its mode and the motion's
 * speed; the turn on the spot moves the pose and plan through it), the
 * pose, the lower timeline (turned with the pose), the foot IK (where the
 * feet are shown; this stage places them) and the upper body (its
 * action, and its crossfade back to none: the standing upper body fades
 * in with it). */
typedef struct smgi_rest_io {
  const smgi_step_in* in;
  smgi_steer* steer;
  smgi_pose* pose;
  smgi_lower* lower;
  smgi_ik* ik;
  const smgi_upper* upper;
} smgi_rest_io;

/* Frames the lower body advances this step, given what the steering
 * wants: none while turning on the spot. */
float smgi_rest_frames(const smgi_rest* r, float frames);
/* Whether the steering should correct the pose this step (not while
 * turning on the spot: the turn is the correction). */
int smgi_rest_steers(const smgi_rest* r);
/* After the pose is composed and steered, before forward kinematics:
 * follow the steering into and out of rest, lay the standing motion over
 * the pose and turn the character on the spot. Returns 1 when the plan
 * should be chosen again (a turn on the spot ended). */
int smgi_rest_pose(smgi_rest* r, const smgi_rest_io* io, float dt);
/* After forward kinematics, before foot IK: the feet this stage places are
 * laid flat (a stop pose can have a heel or a toe up; standing, both are
 * down); the IK keeps the ankles' world rotations, so the toes land where
 * they are placed. */
void smgi_rest_flatten(const smgi_rest* r, const smgi_rest_io* io);
/* Then, before foot IK: where the feet go (on the floor they last stood
 * on, whatever height the pose has them at). */
void smgi_rest_feet(smgi_rest* r, const smgi_rest_io* io);

#endif /* SMG_REST_H */
