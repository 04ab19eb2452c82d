/*
 * bake_pool.h - the frame pool (bake_pool.c): clips appended frame by
 * frame, with forward kinematics and ground frames derived.
 */
#ifndef BAKE_POOL_H
#define BAKE_POOL_H

#include <stdint.h>

#include "bake_clip.h"
#include "bake_state.h"

/* Append a clip's frames (and its clip table entry) and derive them: FK
 * positions, ground frames, foot contacts and phase. */
smg_result smgb_pool_add_clip(smgb_bake* b, const smgb_clip* clip,
                              const char* name, uint32_t label,
                              uint32_t flags, uint32_t source_clip);
/* The same without deriving: the caller runs smgb_pool_derive_clips
 * once all are in. */
smg_result smgb_pool_append_clip(smgb_bake* b, const smgb_clip* clip,
                                 const char* name, uint32_t label,
                                 uint32_t flags, uint32_t source_clip);
/* Derive clips [first_clip, clip_count) as smgb_pool_add_clip does, the
 * clips spread over `threads` workers (each clip's frames are its own, so
 * the result does not depend on the split). */
void smgb_pool_derive_clips(smgb_bake* b, uint32_t first_clip,
                            uint32_t threads);
smg_result smgb_pool_reserve(smgb_bake* b, uint32_t frames);
/* A new entry of the clip table for `count` frames from the pool's end
 * (the caller appends them); source_clip SMGI_NONE = itself. NULL (and
 * the failure reported) when the table cannot grow. */
smgb_pool_clip* smgb_pool_new_clip(smgb_bake* b, const char* name,
                                   uint32_t count, uint32_t label,
                                   uint32_t flags, uint32_t source_clip);
/* Recompute FK positions and root2d of pool frames [first, first+count). */
void smgb_pool_derive(smgb_bake* b, uint32_t first, uint32_t count);
uint32_t smgb_pool_clip_of(const smgb_bake* b, uint32_t frame);
/* Ground frame of a pose (x, z, heading). */
void smgb_pose_ground(const float* pose, double g[3]);

#endif /* BAKE_POOL_H */
