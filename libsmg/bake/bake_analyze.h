/*
 * bake_analyze.h - per-clip locomotion analysis for choosing manifest frame
 * ranges (smg-bake --analyze) and for the contact tests: the clip goes
 * through the same import path as a bake (resample, ground, frame pool with
 * the baker's own foot contacts and gait phase), then every working-rate
 * frame gets the root's ground speed and the direction of travel relative to
 * the facing, and sustained stretches of one direction class are reported
 * in FILE frame numbers, ready for `frames=A-B` in a manifest.
 */
#ifndef BAKE_ANALYZE_H
#define BAKE_ANALYZE_H

#include <stdint.h>
#include <stdio.h>

#include "bake_clip.h"

/* Direction classes of a frame (root ground velocity vs facing). */
#define SMGB_DIR_STILL 0u    /* ground speed below the minimum */
#define SMGB_DIR_FORWARD 1u  /* |angle| < max_angle */
#define SMGB_DIR_BACKWARD 2u /* |angle| > 180 deg - max_angle */
#define SMGB_DIR_SIDEWAYS 3u /* anything between */

typedef struct smgb_analysis {
  uint32_t frame_count;  /* working-rate frames */
  float frame_rate;      /* working rate (Hz) */
  float source_rate;     /* the clip's own rate (Hz) */
  uint32_t file_offset;  /* file frame of working frame 0 (T-pose, crop) */
  uint8_t* contact;      /* per frame: bit 0 left, bit 1 right planted */
  float* phase;          /* gait phase as the baker stores it (-1: none) */
  float* speed;          /* root ground speed, m/s (smoothed) */
  float* angle;          /* travel direction minus facing, radians, 0 =
                            forward, +-pi = backward, + = to the left */
  uint8_t* dir;          /* SMGB_DIR_* per frame */
  float* heading;        /* root heading, radians, unwrapped over the clip */
  float* foot;           /* per frame, left then right: height of the lower
                            of ankle/toe above the clip's lowest, metres,
                            and that joint's horizontal speed, m/s */
} smgb_analysis;

/* Analyse a loaded clip (metres; as smgb_bvh_load returns it). file_offset
 * is the file frame of the clip's frame 0 (1 when the T-pose was skipped).
 * Direction classes use max_angle (radians) and min_speed (m/s); 0 picks
 * the defaults (35 deg, 0.3 m/s). */
smg_result smgb_analyze_clip(const smgb_clip* clip, float frame_rate,
                             uint32_t file_offset, float max_angle,
                             float min_speed, smgb_analysis* out,
                             smgb_error* err);
void smgb_analysis_free(smgb_analysis* a);

/* Working frame -> file frame (nearest source frame). */
uint32_t smgb_analysis_file_frame(const smgb_analysis* a, uint32_t frame);

/* Frames where a foot's contact begins (0 = left, 1 = right). Returns the
 * count written (at most cap). */
uint32_t smgb_analysis_strikes(const smgb_analysis* a, int foot,
                               uint32_t* out, uint32_t cap);

/* Maximal runs of direction class `dir` lasting at least min_seconds, as
 * working frames [first, last]; brief (< 0.3 s) interruptions by another
 * class are bridged. Returns the count written (at most cap). */
uint32_t smgb_analysis_ranges(const smgb_analysis* a, uint8_t dir,
                              float min_seconds, uint32_t (*out)[2],
                              uint32_t cap);

/* Mean horizontal speed (m/s) of the planted feet (lower of ankle/toe)
 * over frames labelled as contact on both sides of the step: foot skate as
 * the labels see it. */
double smgb_analysis_planted_speed(const smgb_analysis* a);

/* Load a clip file (BVH, else assimp), optionally retarget it to the
 * skeleton of `reference` (another clip file, same options; NULL = none)
 * as a bake would, analyse it at frame_rate (0 = 30) and print strikes,
 * stride periods, alternation, planted-foot speed and direction ranges in
 * file frames to fp; verbose adds a per-frame table. */
smg_result smgb_analyze_file(const char* path, const char* reference,
                             float unit_scale, uint32_t skip_first_frame,
                             float frame_rate, int verbose, FILE* fp,
                             smgb_error* err);

#endif /* BAKE_ANALYZE_H */
