/*
 * bake_retarget.h - put clips from any humanoid skeleton onto one target
 * rig (its joints, rest pose and proportions) at bake time.
 *
 * The target rig is kept as an smgb_skeleton whose rest pose has identity
 * local rotations ("world-aligned rest": every offset is the rest bone
 * vector in world axes), which is what the blob stores. A rig whose own
 * bones have other local axes gets its rotations back by conjugating with
 * its rest rotations (the Godot binding does that, see its README).
 *
 * Method (docs/baker.md, "Retargeting onto a target rig"): joints are
 * paired by body role; every paired target joint takes the source joint's
 * world rotation times a constant alignment measured from the clip's
 * joint positions, never from the source joints' local axes (rest frames
 * of pelvis and chest, bone directions, and the twist about each bone the
 * source has when its bone is swung onto the rig's rest direction), so
 * A-pose vs T-pose and other bone axes cancel; limbs are swung per frame
 * onto the source's actual bone direction (source joints the target lacks
 * fold into it), unpaired target joints stay at rest, the root moves by
 * the leg-length ratio and a two-bone leg solve puts each ankle at the
 * source ankle scaled by the same ratio, so planted feet stay planted.
 */
#ifndef BAKE_RETARGET_H
#define BAKE_RETARGET_H

#include "bake_clip.h"
#include "bake_roles.h"

/* Load a rig file (BVH, or glTF/GLB/FBX through assimp) as a target
 * skeleton with world-aligned rest offsets, metres. BVH: the rest pose is
 * the OFFSET pose; assimp formats: the first frame of `animation_index`.
 * unit_scale as for clips (0 = guess). */
smg_result smgb_rig_load(const char* path, float unit_scale,
                         uint32_t animation_index, smgb_skeleton* out,
                         smgb_error* err);

/* The skeleton of `pose` (one pose of `s`) as a world-aligned rest
 * skeleton: same names and parents, offsets = world bone vectors. */
smg_result smgb_rig_from_pose(const smgb_skeleton* s, const float* pose,
                              smgb_skeleton* out);

/* Whether `a` and `b` have the same joint names and parents (then the
 * plain same-skeleton path, smgb_clip_retarget, applies). */
int smgb_same_hierarchy(const smgb_skeleton* a, const smgb_skeleton* b);

/* Replace `clip` by its motion on `target` (world-aligned rest). Joints
 * are paired by body role (bake_roles.h), the others by name without
 * namespace. Errors name the clip and the joint or body part that could not
 * be paired; `target_name` names the rig in them. On failure `clip` is
 * unchanged. */
smg_result smgb_retarget_clip(smgb_clip* clip, const smgb_roles* clip_roles,
                              const smgb_skeleton* target,
                              const smgb_roles* target_roles,
                              const char* target_name, smgb_error* err);

#endif /* BAKE_RETARGET_H */
