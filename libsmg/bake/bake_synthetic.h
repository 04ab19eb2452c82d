/*
 * bake_synthetic.h - procedural SYNTHETIC motion clips with exact ground
 * truth.
 *
 * The CMU clips cannot ship with the project, so a fresh machine bakes its
 * default blob from these procedural clips, and tests use them as data whose
 * speed, step length, foot-contact timing and turn rate are known exactly.
 * They are clearly synthetic (file names "synthetic_*.bvh", clip names, and a
 * README written beside them) and are never presented as motion capture.
 *
 * Skeleton: CMU's 31-joint hierarchy (same names, order and channels as the
 * clips in ../shared/mocap/cmu), with symmetric CMU-like bone lengths in
 * metres: legs straight down in the rest pose, arms along +-X (T-pose),
 * facing +Z.
 *
 * Locomotion: the pelvis follows a path of constant speed and constant turn
 * rate (a straight line or a circular arc). Footprints are laid along the
 * path, alternating left/right every step_length metres; a planted foot is
 * fixed exactly (flat, heading of the path at its footprint), a swinging foot
 * follows a minimum-jerk arc to the next footprint, and each leg is solved
 * analytically (two-bone IK, knee forward), so FK of the clip reproduces the
 * planned feet to float precision. At whole stride periods the root lies
 * exactly on the path (the lateral sway is zero there). Standing actions keep both feet planted
 * while the pelvis shifts its weight and the arms act.
 *
 * Generation is deterministic and takes milliseconds.
 */
#ifndef BAKE_SYNTHETIC_H
#define BAKE_SYNTHETIC_H

#include <stdint.h>

#include "bake_clip.h"

typedef enum smgb_synth_kind {
  SMGB_SYNTH_WALK = 0,  /* locomotion, style "walk" */
  SMGB_SYNTH_RUN = 1,   /* locomotion, style "run" (flight phase) */
  SMGB_SYNTH_WAVE = 2,  /* standing, right arm waves */
  SMGB_SYNTH_PUNCH = 3, /* standing, alternating straight punches */
  /* a walk that comes to rest / sets off from rest: the pelvis speed
   * ramps over one stride (minimum jerk) at the walk's cadence, the steps
   * shortening until the feet stand side by side; still for
   * SMGB_SYNTH_STILL_SECONDS at the clip's end / start. Not in the
   * standard set (tests of stopping and starting motion bake them). */
  SMGB_SYNTH_WALK_STOP = 4,
  SMGB_SYNTH_WALK_START = 5
} smgb_synth_kind;

#define SMGB_SYNTH_STILL_SECONDS 2.0

typedef struct smgb_synth_params {
  smgb_synth_kind kind;
  float duration;    /* seconds; 0 = 8 */
  float frame_rate;  /* 0 = 60 */
  float turn_rate;   /* rad/s about +Y; > 0 turns left (heading grows),
                        locomotion only */
} smgb_synth_params;

/* Exact ground truth of a generated clip. Foot index 0 = left, 1 = right.
 * Foot f is planted at time t (seconds from frame 0) iff
 *   frac(t / stride_period - phase_offset[f]) < duty_factor
 * (standing clips: always planted, stride_period = 0). */
typedef struct smgb_synth_truth {
  smgb_synth_kind kind;
  float speed;            /* m/s along the path (0 when standing) */
  float step_length;      /* m along the path between consecutive
                             left/right footprints */
  float stride_period;    /* s per gait cycle (two steps) */
  float duty_factor;      /* fraction of the cycle a foot is planted */
  float phase_offset[2];  /* 0 (left), 0.5 (right) */
  float turn_rate;        /* rad/s, > 0 = left */
  float foot_width;       /* lateral distance of each footprint from the
                             path, m */
  float ankle_height;     /* ankle (Foot joint) height when planted, m */
  float start_heading;    /* heading at t = 0 (0: facing +Z) */
  uint32_t left_foot, right_foot; /* joint indices (LeftFoot, RightFoot) */
  /* WALK_STOP / WALK_START: the pelvis speed is speed (1 - e(u)) / speed
   * e(u), e the minimum-jerk ease of u = (t - ramp_at) / ramp_seconds
   * clamped to [0, 1] (both 0 for the other kinds) */
  float ramp_at, ramp_seconds;
} smgb_synth_truth;

/* The synthetic 31-joint skeleton (metres). */
smg_result smgb_synth_skeleton(smgb_skeleton* out);

/* Generate one clip. truth may be NULL. */
smg_result smgb_synth_generate(const smgb_synth_params* params,
                               smgb_clip* out, smgb_synth_truth* truth);

/* 1 if foot (0 left, 1 right) is planted at time t, per the truth. */
int smgb_synth_foot_planted(const smgb_synth_truth* truth, int foot,
                            double t);

/* The standard set written by smg-gen-clips: straight/left/right walks and
 * runs, wave, punch. Returns SMG_ERROR_OUT_OF_RANGE past the end. `file` is
 * the BVH file name ("synthetic_walk_straight.bvh"), `label` the style or
 * action, `is_lower` 1 for locomotion clips. */
#define SMGB_SYNTH_STANDARD_COUNT 8u
smg_result smgb_synth_standard(uint32_t index, smgb_synth_params* params,
                               const char** file, const char** label,
                               int* is_lower);

/* Write the standard set as BVH (metres, unit 1, no T-pose frame) plus a
 * README.txt into `dir` (which must exist). */
smg_result smgb_synth_write_all(const char* dir, smgb_error* err);

/* Write the generated retargeting test rig (bake_synth_rig.c: Mixamo-style
 * names, 22 joints, A-pose rest, legs 8 % longer than the synthetic and
 * CMU skeletons') as a one-frame BVH in metres. */
smg_result smgb_synth_write_rig(const char* path, smgb_error* err);

#endif /* BAKE_SYNTHETIC_H */
