/*
 * eval_joints.h - the joints the evaluation measures (pelvis, both feet and
 * toes, both hands) found in a loaded graph by their body roles (bake_roles.h), so the
 * metrics work on any rig the baker accepts (CMU's LeftToeBase, Bandai
 * Namco's Toes_L, Mixamo's mixamorig:LeftToeBase, ...).
 */
#ifndef EVAL_JOINTS_H
#define EVAL_JOINTS_H

#include <stdint.h>

#include "smg.h"

typedef struct eval_joints {
  uint32_t hips, lfoot, ltoe, rfoot, rtoe;
  uint32_t lhand, rhand; /* wrists; UINT32_MAX where not recognised */
} eval_joints;

/* Fills *j from the graph's skeleton; 0 when a role is not recognised (or
 * out of memory), 1 on success. */
int eval_find_joints(const smg_graph* g, eval_joints* j);

#endif /* EVAL_JOINTS_H */
