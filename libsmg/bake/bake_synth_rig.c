/*
 * bake_synth_rig.c - a generated test rig for retargeting (not from any
 * third-party asset): Mixamo-style joint names ("mixamorig:Hips", ...),
 * 22 joints, three spine joints where the CMU/synthetic skeletons have two,
 * no fingers, an A-pose rest (arms 45 degrees down), legs straight down
 * and 8 % longer than the CMU and synthetic skeletons' (0.46 m thigh and
 * shin against 0.42-0.43 m), facing +Z, metres.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_import_util.h"
#include "bake_synthetic.h"

#define RIG_J 22
#define A45 0.70710678f

static const char* const k_rig_names[RIG_J] = {
    "mixamorig:Hips",         "mixamorig:Spine",
    "mixamorig:Spine1",       "mixamorig:Spine2",
    "mixamorig:Neck",         "mixamorig:Head",
    "mixamorig:LeftShoulder", "mixamorig:LeftArm",
    "mixamorig:LeftForeArm",  "mixamorig:LeftHand",
    "mixamorig:RightShoulder", "mixamorig:RightArm",
    "mixamorig:RightForeArm", "mixamorig:RightHand",
    "mixamorig:LeftUpLeg",    "mixamorig:LeftLeg",
    "mixamorig:LeftFoot",     "mixamorig:LeftToeBase",
    "mixamorig:RightUpLeg",   "mixamorig:RightLeg",
    "mixamorig:RightFoot",    "mixamorig:RightToeBase"};

static const int32_t k_rig_parents[RIG_J] = {
    -1, 0, 1, 2, 3, 4, 3, 6, 7, 8, 3, 10, 11, 12, 0, 14, 15, 16, 0, 18, 19, 20};

static const float k_rig_offsets[RIG_J][3] = {
    {0, 0, 0},
    {0, 0.10f, 0.01f},
    {0, 0.12f, 0},
    {0, 0.12f, -0.01f},
    {0, 0.16f, 0},
    {0, 0.10f, 0.02f},
    {0.04f, 0.11f, -0.01f},
    {0.13f, 0, 0},
    {0.28f * A45, -0.28f * A45, 0},
    {0.25f * A45, -0.25f * A45, 0},
    {-0.04f, 0.11f, -0.01f},
    {-0.13f, 0, 0},
    {-0.28f * A45, -0.28f * A45, 0},
    {-0.25f * A45, -0.25f * A45, 0},
    {0.10f, -0.07f, 0},
    {0, -0.46f, 0},
    {0, -0.46f, 0},
    {0, -0.06f, 0.14f},
    {-0.10f, -0.07f, 0},
    {0, -0.46f, 0},
    {0, -0.46f, 0},
    {0, -0.06f, 0.14f}};

smg_result smgb_synth_write_rig(const char* path, smgb_error* err) {
  smgb_clip c;
  smg_result r;
  uint32_t j;
  if (!path) return SMG_ERROR_INVALID_ARGUMENT;
  memset(&c, 0, sizeof c);
  snprintf(c.name, sizeof c.name, "test rig");
  c.skeleton.joint_count = RIG_J;
  c.skeleton.names = (char(*)[SMGB_NAME_MAX])calloc(RIG_J, SMGB_NAME_MAX);
  c.skeleton.parents = (int32_t*)malloc(sizeof(int32_t) * RIG_J);
  c.skeleton.offsets = (float(*)[3])malloc(sizeof(float) * 3 * RIG_J);
  c.poses = (float*)calloc(SMGB_STRIDE(RIG_J), sizeof(float));
  if (!c.skeleton.names || !c.skeleton.parents || !c.skeleton.offsets ||
      !c.poses) {
    smgb_clip_free(&c);
    smgb_imp_errorf(err, "%s: out of memory", path);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < RIG_J; ++j) {
    snprintf(c.skeleton.names[j], SMGB_NAME_MAX, "%s", k_rig_names[j]);
    c.skeleton.parents[j] = k_rig_parents[j];
    memcpy(c.skeleton.offsets[j], k_rig_offsets[j], sizeof k_rig_offsets[j]);
    c.poses[3 + 4 * j + 3] = 1.0f;
  }
  /* one frame: the rest pose standing on the floor */
  c.poses[1] = 0.07f + 0.46f + 0.46f + 0.06f;
  c.frame_count = 1;
  c.frame_rate = 30.0f;
  r = smgb_bvh_save(path, &c, err);
  smgb_clip_free(&c);
  return r;
}
