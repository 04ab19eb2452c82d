/*
 * bake_clip.h - the baker's in-memory motion clip: a skeleton
 * (bake_skeleton.h) and its poses.
 *
 * Every importer (BVH, assimp) produces an smgb_clip; the import stage
 * (bake_import.c) puts them into the frame pool the graph stages share.
 *
 * Conventions after import: metres, Y up, the character faces +Z when the
 * root rotation is identity, floor at y = 0. Internal baker symbols use the
 * smgb_ prefix.
 */
#ifndef BAKE_CLIP_H
#define BAKE_CLIP_H

#include <stddef.h>
#include <stdint.h>

#include "bake_report.h"
#include "bake_roles.h"
#include "bake_skeleton.h"
#include "smg.h"

typedef struct smgb_clip {
  char name[SMGB_NAME_MAX];     /* e.g. file name without directory */
  smgb_skeleton skeleton;       /* owned by the clip */
  uint32_t frame_count;
  float frame_rate;             /* frames per second */
  float* poses;                 /* frame_count * (3 + 4 * joint_count) */
} smgb_clip;

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
/* The same with the body roles of both skeletons given (the plain version
 * recognises them by name). */
smg_result smgb_clip_retarget_roles(smgb_clip* clip,
                                    const smgb_roles* clip_roles,
                                    const smgb_skeleton* reference,
                                    const smgb_roles* reference_roles,
                                    smgb_error* err);
/* Lowest point of the skeleton over the clip is moved to y = 0. */
void smgb_clip_ground(smgb_clip* clip);

#endif /* BAKE_CLIP_H */
