/*
 * eval_gait.h - gait measures of the behaviour section (issue 24) as plain
 * functions on arrays, unit-tested in tests/eval/test_gait.c apart from
 * the runtime that produces the poses.
 *
 * Inputs are joint world positions per frame (x, y, z; y up; metres),
 * `stride` doubles from one frame to the next, frames dt seconds apart.
 *
 *   swing       a stretch of frames in which a toe is more than
 *               EVAL_GAIT_SWING_M above its floor level, lasting at least
 *               EVAL_GAIT_SWING_MIN_S. A lifted toe that is still up at the
 *               last frame considered counts up to that frame (a foot
 *               frozen in the air is a long swing).
 *   floor level of a toe at a frame: the lowest height of its latest
 *               stance, a stretch of frames in which it moves horizontally
 *               slower than EVAL_GAIT_STILL_MS (before its first stance,
 *               the EVAL_FEET_FLOOR_PERCENTILE-th percentile of its height
 *               over the run, eval_feet_geom.h). Per stance and not one
 *               level for the run, because a graph of several performers
 *               plants the toe joint at heights up to a few centimetres
 *               apart (their feet and toe joints differ): with one level,
 *               the stance of the performer whose toe sits higher would
 *               count as part of a swing. A swinging toe moves, so its
 *               level stays that of the stance it left, in slow motion too.
 *   window speed the hips' horizontal path length over a window of frames
 *               divided by its duration: the sway of a stride adds to it
 *               only in quadrature, and unlike the chord it does not shrink
 *               on a tight curve.
 *   facing      the heading (radians about +y, atan2(x, z)) of a body-frame
 *               axis of the pelvis in the world. Which pelvis axis points
 *               forward depends on the rig, so it is calibrated from a
 *               straight walk (eval_gait_calibrate_forward).
 */
#ifndef EVAL_GAIT_H
#define EVAL_GAIT_H

#include <stddef.h>

#define EVAL_GAIT_SWING_M 0.025    /* toe this far above its floor: swing */
#define EVAL_GAIT_SWING_MIN_S 0.1  /* shorter lifts are not steps */
#define EVAL_GAIT_STILL_MS 0.3     /* a toe slower than this is planted */

/* The floor level of one toe at each of its n frames (level[0..n)).
 * Returns 0, or -1 on bad arguments. */
int eval_gait_floor_levels(const double* toe, size_t stride, size_t n,
                           double dt, double* level);

/* Swings of one toe between frames first and last (inclusive of first,
 * exclusive of last; swings that start in the range and are still lifted
 * at `last` end there). level: the toe's floor level per frame, indexed
 * like its frames. Writes the durations (seconds) of at most cap swings to
 * out, returns their count. */
size_t eval_gait_swings(const double* toe, size_t stride, size_t first,
                        size_t last, const double* level, double dt,
                        double* out, size_t cap);

/* Median of v[0..n) (v is sorted in place); NaN when n == 0. */
double eval_gait_median(double* v, size_t n);

/* Hips window speed (m/s) at frame i over frames [i - half, i + half]
 * clipped to [0, n): horizontal path length / window duration. NaN when
 * the clipped window is a single frame. */
double eval_gait_window_speed(const double* hips, size_t stride, size_t n,
                              size_t i, size_t half, double dt);

/* Heading of the horizontal direction from frame a to frame b of the hips
 * (radians, atan2(dx, dz)); NaN when they are less than 1 mm apart. */
double eval_gait_travel_heading(const double* hips, size_t stride, size_t a,
                                size_t b);

/* Pelvis forward axis in the pelvis frame: the normalised mean of
 * q_i^-1 * (travel direction at i) over the frames whose travel heading
 * (travel[i]) is finite. q: 4 doubles per frame (x, y, z, w), world
 * rotation of the pelvis. Returns 0, or -1 when no frame was usable. */
int eval_gait_calibrate_forward(const double* q, const double* travel,
                                size_t n, double out_axis[3]);

/* Heading (radians, atan2(x, z)) of the pelvis axis `axis` rotated by q;
 * NaN when it points straight up or down. */
double eval_gait_facing(const double q[4], const double axis[3]);

/* The pelvis facing over frames [a, b] as the direction of travel over
 * them is taken (the chord from a to b, eval_gait_travel_heading: each
 * frame counts by the way the hips go in it): the circular mean of the
 * frames' facings (eval_gait_facing; q: 4 doubles per frame) weighted by
 * the hips' horizontal travel around each frame (half of each of its two
 * steps inside [a, b]). A body that faces its travel at every frame then
 * faces the chord, however its speed changes; a plain mean over time
 * counts the slow frames of a braking turn more than the chord does (up
 * to 20 degrees on a runner pivoting round a hairpin). NaN when the hips
 * do not move or no facing is defined. */
double eval_gait_window_facing(const double* q, const double* hips,
                               size_t stride, size_t a, size_t b,
                               const double axis[3]);

/* a - b wrapped to [-pi, pi). */
double eval_gait_angle_diff(double a, double b);

/* Largest angle (degrees) between any two of the n unit quaternions q
 * (4 doubles each, `stride` doubles apart): the range a joint's rotation
 * covers over those frames. */
double eval_gait_rotation_range_deg(const double* q, size_t stride, size_t n);

#endif /* EVAL_GAIT_H */
