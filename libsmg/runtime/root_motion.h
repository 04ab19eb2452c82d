/*
 * root_motion.h - the character's root motion for the engine's mover
 * (root_motion.c): how far its ground transform moved in the last step,
 * and moving the character rigidly to where the engine's mover put it.
 */
#ifndef SMG_ROOT_MOTION_H
#define SMG_ROOT_MOTION_H

#include <stdint.h>

#include "ik.h"
#include "lower.h"
#include "pose.h"
#include "smg.h"
#include "steer.h"

typedef struct smgi_root_motion {
  float before[4]; /* ground x, y, z and heading at the start of the step */
  float delta[4];  /* their change over the step (heading wrapped) */
  float dt;        /* the step's length, seconds */
} smgi_root_motion;

/* At the start of a step / at its end (step.c). */
void smgi_root_motion_begin(smgi_root_motion* rm, const smgi_pose* pose);
void smgi_root_motion_end(smgi_root_motion* rm, const smgi_pose* pose,
                          float dt);

/* Move everything the character placed in the world - pose, queued
 * placements, steering state, planted feet, ground carried, and `anchor`
 * (x, z: where it stays without a path) - by the rigid transform taking
 * its ground transform to (position x, y, z; heading). */
void smgi_root_motion_place(const smgi_root_motion* rm, smgi_pose* pose,
                            smgi_lower* lower, smgi_steer* steer, smgi_ik* ik,
                            uint32_t joint_count, float* anchor,
                            const float* position, float heading);

#endif /* SMG_ROOT_MOTION_H */
