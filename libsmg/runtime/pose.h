/*
 * pose.h - the character's output pose (pose.c): local rotations, root
 * and ground placement, and the world transforms cached for IK and the
 * getters. Buffers are carved out of the character's block at create.
 */
#ifndef SMG_POSE_H
#define SMG_POSE_H

#include <stdint.h>

#include "graph_data.h"
#include "lower.h"
#include "smg.h"
#include "upper.h"

typedef struct smgi_pose {
  float root[3];     /* world position of joint 0 */
  float heading;     /* ground heading of the character */
  float ground[2];   /* ground position (x, z) */
  float ground_y;    /* ground height there: 0 on the data's flat floor,
                        the engine's ground otherwise (ik.c) */
  uint32_t contacts; /* SMG_STATE_*_CONTACT bits of the frame */
  float* rot;        /* 4J: local rotations */
  float* tmp;        /* 4J: crossfade sampling scratch, only for skeletons
                        of more than SMGI_POSE_STACK_JOINTS joints (NULL
                        otherwise: the stack is used) */
  float* wpos;       /* 3J: world joint positions */
  float* wrot;       /* 4J: world joint rotations */
  smgi_decoded decoded; /* the lower body's last two records, decoded */
} smgi_pose;

/* Sample the lower body at the playhead, place it, lay the upper body on
 * (crossfading from upper->snap after a switch). */
void smgi_pose_compose(smgi_pose* pose, const smgi_lower* lower,
                       const smgi_upper* upper, const smg_graph* g);
/* Forward kinematics of a whole local pose. */
void smgi_fk(const smg_graph* g, const float* root, const float* rot,
             float* wpos, float* wrot);
/* Re-run FK of the cached world transforms for `count` joints listed
 * parents first (after IK changed some of their local rotations). */
void smgi_fk_joints(smgi_pose* pose, const smg_graph* g, const uint32_t* list,
                    uint32_t count);
/* Column-major 4x4 matrices of the cached world transforms, in world
 * space or relative to the character's ground transform (SMG_SPACE_*). */
void smgi_pose_model_matrices(const smgi_pose* p, uint32_t joint_count,
                              uint32_t space, float* matrices);

#endif /* SMG_POSE_H */
