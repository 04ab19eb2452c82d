/*
 * rest.h - standing still (rest.c): what a character does from the moment
 * the steering brings it to rest at its path's end until it walks on.
 */
#ifndef SMG_REST_H
#define SMG_REST_H

#include <stdint.h>

#include "rmath.h"
#include "smg.h"

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
  float hold[2][2];     /* where each toe stands (x, z) */
  uint32_t foot;        /* the foot stepping now (0 left, 1 right) */
  float from[2];        /* its toe where the step began (x, z) */
  float glide[2];       /* the hips' ground shift of the settling step */
  float glided;         /* of it shown now (0..1) */
  float glide_from;     /* glided when the fade out began */
  float settle_seconds; /* how long the hips take to come to stand */
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

/* Where the settling step would take the hips of a character stopping on
 * pool frame `frame`, relative to that frame's ground point, in its clip
 * space (the steering chooses the frame to stop on with it). */
void smgi_rest_settle_shift(const smg_graph* g, uint32_t frame, float* dx,
                            float* dz);
/* Frames the lower body advances this step, given what the steering
 * wants: none while turning on the spot. */
float smgi_rest_frames(const smg_character* ch, float frames);
/* Whether the steering should correct the pose this step (not while
 * turning on the spot: the turn is the correction). */
int smgi_rest_steers(const smg_character* ch);
/* After the pose is composed and steered, before forward kinematics:
 * follow the steering into and out of rest, lay the standing motion over
 * the pose and move the character as it settles or turns. */
void smgi_rest_pose(smg_character* ch, float dt);
/* After forward kinematics, before foot IK: where the feet go. */
void smgi_rest_feet(smg_character* ch);
/* After smgi_rest_feet, before foot IK: the feet this stage places are
 * laid flat (a stop pose can have a heel or a toe up; standing, both are
 * down); the IK keeps the ankles' world rotations, so the toes land where
 * they are placed. */
void smgi_rest_flatten(smg_character* ch);

#endif /* SMG_REST_H */
