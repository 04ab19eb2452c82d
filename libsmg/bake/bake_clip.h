/*
 * bake_clip.h - the baker's in-memory motion clip and skeleton.
 *
 * Every importer (BVH, assimp) produces an smgb_clip; every baking stage
 * (graphs, splicing, internodal data) consumes them. Poses are floats: per
 * frame, the root translation (3 floats, metres) followed by J local
 * rotations (x,y,z,w) - SMGI_POSE_FLOATS in smg_format.h; only the blob
 * writer (bake_output.c) packs the rotations into POSE records.
 *
 * Conventions after import: metres, Y up, the character faces +Z when the
 * root rotation is identity, floor at y = 0. Internal baker symbols use the
 * smgb_ prefix.
 */
#ifndef BAKE_CLIP_H
#define BAKE_CLIP_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

#define SMGB_NAME_MAX 64

typedef struct smgb_skeleton {
  uint32_t joint_count;
  char (*names)[SMGB_NAME_MAX]; /* joint_count names */
  int32_t* parents;             /* -1 for joint 0; parent < index */
  float (*offsets)[3];          /* rest offsets from parent, metres */
} smgb_skeleton;

typedef struct smgb_clip {
  char name[SMGB_NAME_MAX];     /* e.g. file name without directory */
  smgb_skeleton skeleton;       /* owned by the clip */
  uint32_t frame_count;
  float frame_rate;             /* frames per second */
  float* poses;                 /* frame_count * (3 + 4 * joint_count) */
} smgb_clip;

/* Floats per pose: root translation + one quaternion per joint. */
#define SMGB_STRIDE(joint_count) (3u + 4u * (uint32_t)(joint_count))

/* Error detail filled by failing importers: file, line and problem. */
typedef struct smgb_error {
  char message[512];
} smgb_error;

/* ---- import (bake_bvh.c, bake_assimp.c) ---------------------------------- */

/* Parse a BVH file. unit_scale converts file units to metres (CMU: 0.056444;
 * 0 = guess from the hips height). skip_first_frame drops a synthetic
 * T-pose frame 0 (CMU). Any hierarchy and any channel order. */
smg_result smgb_bvh_load(const char* path, float unit_scale,
                         uint32_t skip_first_frame, smgb_clip* out,
                         smgb_error* err);
/* Same, from memory (fuzz target and tests). name is used in errors. */
smg_result smgb_bvh_parse(const char* text, size_t size, const char* name,
                          float unit_scale, uint32_t skip_first_frame,
                          smgb_clip* out, smgb_error* err);
/* Write a clip as BVH (ZYX channels, metres as units). */
smg_result smgb_bvh_save(const char* path, const smgb_clip* clip,
                         smgb_error* err);

/* glTF/GLB/FBX skeletal animation through assimp's C API. */
smg_result smgb_assimp_load(const char* path, float unit_scale,
                            uint32_t animation_index, smgb_clip* out,
                            smgb_error* err);

void smgb_clip_free(smgb_clip* clip);
smg_result smgb_clip_copy(const smgb_clip* src, smgb_clip* out);

/* ---- processing (bake_clip.c) -------------------------------------------- */

/* Resample to `frame_rate` (slerp rotations, lerp translation). */
smg_result smgb_clip_resample(const smgb_clip* src, float frame_rate,
                              smgb_clip* out);
/* Reflect across the sagittal (x = 0) plane and swap left/right joints by
 * name (smgb_roles_counterpart_name: Left/Right, L/R, _L/_R, .L/.R, ...).
 * mirror(mirror(c)) == c. */
smg_result smgb_clip_mirror(const smgb_clip* src, smgb_clip* out);
/* The same with the counterpart of every joint given (partner[j] = j for
 * central joints; smgb_roles_partners). */
smg_result smgb_clip_mirror_partners(const smgb_clip* src,
                                     const uint32_t* partner, smgb_clip* out);
/* Put `clip` on `reference` (same joint names and order required, else
 * SMG_ERROR_INVALID_ARGUMENT with a message): keep joint rotations, scale
 * root translation by the ratio of leg lengths, replace offsets. */
smg_result smgb_clip_retarget(smgb_clip* clip, const smgb_skeleton* reference,
                              smgb_error* err);
/* The same with the body roles of both skeletons given (bake_roles.h;
 * the plain version recognises them by name). */
struct smgb_roles;
smg_result smgb_clip_retarget_roles(smgb_clip* clip,
                                    const struct smgb_roles* clip_roles,
                                    const smgb_skeleton* reference,
                                    const struct smgb_roles* reference_roles,
                                    smgb_error* err);
/* Lowest point of the skeleton over the clip is moved to y = 0. */
void smgb_clip_ground(smgb_clip* clip);

int32_t smgb_skeleton_find(const smgb_skeleton* s, const char* name);
smg_result smgb_skeleton_copy(const smgb_skeleton* src, smgb_skeleton* out);
void smgb_skeleton_free(smgb_skeleton* s);
/* Hip-to-ankle rest length of the left leg, metres, with the body roles
 * recognised by name (0 if not found; bake_roles.h). */
float smgb_skeleton_leg_length(const smgb_skeleton* s);

/* Forward kinematics of one pose: world positions (3 per joint) and,
 * optionally, world rotations (4 per joint, may be NULL). */
void smgb_fk(const smgb_skeleton* s, const float* pose, float* out_positions,
             float* out_rotations);

#endif /* BAKE_CLIP_H */
