/*
 * eval_joints.c - see eval_joints.h. The graph's skeleton is rebuilt from
 * the public joint queries and handed to the baker's role recognition.
 */
#include "eval_joints.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_roles.h"

int eval_find_joints(const smg_graph* g, eval_joints* j) {
  smg_graph_info info;
  smgb_skeleton s;
  smgb_roles r;
  uint32_t k;
  int ok = 0;
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if (smg_graph_get_info(g, &info) != SMG_OK || info.joint_count == 0)
    return 0;
  memset(&s, 0, sizeof(s));
  s.joint_count = info.joint_count;
  s.names = calloc(info.joint_count, sizeof(*s.names));
  s.parents = calloc(info.joint_count, sizeof(*s.parents));
  s.offsets = calloc(info.joint_count, sizeof(*s.offsets));
  if (s.names && s.parents && s.offsets) {
    for (k = 0; k < info.joint_count; ++k) {
      smg_joint_info ji;
      memset(&ji, 0, sizeof(ji));
      ji.struct_size = sizeof(ji);
      if (smg_graph_get_joint(g, k, &ji) != SMG_OK) break;
      snprintf(s.names[k], SMGB_NAME_MAX, "%s", ji.name);
      s.parents[k] = ji.parent;
      memcpy(s.offsets[k], ji.rest_offset, sizeof(s.offsets[k]));
    }
    if (k == info.joint_count) {
      smgb_roles_guess(&s, &r);
      ok = r.joint[SMGB_ROLE_PELVIS] >= 0 && r.joint[SMGB_ROLE_LEFT_FOOT] >= 0 &&
           r.joint[SMGB_ROLE_LEFT_TOES] >= 0 &&
           r.joint[SMGB_ROLE_RIGHT_FOOT] >= 0 &&
           r.joint[SMGB_ROLE_RIGHT_TOES] >= 0;
      if (ok) {
        j->hips = (uint32_t)r.joint[SMGB_ROLE_PELVIS];
        j->lfoot = (uint32_t)r.joint[SMGB_ROLE_LEFT_FOOT];
        j->ltoe = (uint32_t)r.joint[SMGB_ROLE_LEFT_TOES];
        j->rfoot = (uint32_t)r.joint[SMGB_ROLE_RIGHT_FOOT];
        j->rtoe = (uint32_t)r.joint[SMGB_ROLE_RIGHT_TOES];
        j->lhand = r.joint[SMGB_ROLE_LEFT_HAND] >= 0
                       ? (uint32_t)r.joint[SMGB_ROLE_LEFT_HAND]
                       : UINT32_MAX;
        j->rhand = r.joint[SMGB_ROLE_RIGHT_HAND] >= 0
                       ? (uint32_t)r.joint[SMGB_ROLE_RIGHT_HAND]
                       : UINT32_MAX;
      }
    }
  }
  free(s.names);
  free(s.parents);
  free(s.offsets);
  return ok;
}
