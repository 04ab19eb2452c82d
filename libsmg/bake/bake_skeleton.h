/*
 * bake_skeleton.h - the baker's skeleton: joint names, parents and rest
 * offsets, and the pose layout every clip and the frame pool use.
 *
 * Poses are floats: per frame, the root translation (3 floats, metres)
 * followed by J local rotations (x,y,z,w) - SMGI_POSE_FLOATS in
 * smg_format.h; only the blob writer (bake_output.c) packs the rotations
 * into POSE records.
 */
#ifndef BAKE_SKELETON_H
#define BAKE_SKELETON_H

#include <stdint.h>

#include "smg.h"

#define SMGB_NAME_MAX 64

typedef struct smgb_skeleton {
  uint32_t joint_count;
  char (*names)[SMGB_NAME_MAX]; /* joint_count names */
  int32_t* parents;             /* -1 for joint 0; parent < index */
  float (*offsets)[3];          /* rest offsets from parent, metres */
} smgb_skeleton;

/* Floats per pose: root translation + one quaternion per joint. */
#define SMGB_STRIDE(joint_count) (3u + 4u * (uint32_t)(joint_count))

int32_t smgb_skeleton_find(const smgb_skeleton* s, const char* name);
smg_result smgb_skeleton_copy(const smgb_skeleton* src, smgb_skeleton* out);
void smgb_skeleton_free(smgb_skeleton* s);

/* Forward kinematics of one pose: world positions (3 per joint) and,
 * optionally, world rotations (4 per joint, may be NULL). */
void smgb_fk(const smgb_skeleton* s, const float* pose, float* out_positions,
             float* out_rotations);

#endif /* BAKE_SKELETON_H */
