/*
 * eval_feet_geom.h - planted-foot speed measured from geometry alone.
 *
 * Quality of the feet is judged from where the toes actually are in the
 * exported poses, never from the runtime's contact flags (which can miss a
 * foot that is on the floor, or keep one that is already lifting). For one
 * run, given each toe's world position per frame:
 *
 *   floor level  of a toe = the EVAL_FEET_FLOOR_PERCENTILE-th percentile of
 *                that toe's height (y) over the run. A low percentile and
 *                not the minimum, so that one frame pushed through the
 *                floor (a blend, an IK overshoot) does not move it; low
 *                enough to lie inside the stance phases of any gait that
 *                has the foot down at least a tenth of the time. Per toe
 *                and per run, so a rig whose toe joint sits higher above
 *                the sole, or data grounded a little off y = 0, needs no
 *                constant.
 *   planted      a toe is planted over the frame pair (i-1, i) when it is
 *                within EVAL_FEET_PLANT_BAND_M of its floor level in both
 *                frames.
 *   speed        of a planted pair: horizontal (x, z) displacement / dt,
 *                cm/s. A perfectly planted toe scores 0; the figure grows
 *                with slides and with pops (a toe jumping while down).
 *
 * Reported over all planted pairs of all toes: mean, 95th and 99th
 * percentile, max; and the lowest toe height of the run (absolute world y,
 * cm) so that feet lifted off or pushed into the floor show as well.
 *
 * Units in: metres, seconds, y up. Units out: cm/s and cm.
 * Unit tests: tests/eval/test_feet_geom.c.
 */
#ifndef EVAL_FEET_GEOM_H
#define EVAL_FEET_GEOM_H

#include <stddef.h>

#define EVAL_FEET_PLANT_BAND_M 0.025  /* planted: within 2.5 cm of floor */
#define EVAL_FEET_FLOOR_PERCENTILE 5.0 /* floor level: this percentile */

typedef struct eval_feet_geom {
  size_t frames;        /* frames measured */
  size_t planted_pairs; /* planted frame pairs, summed over the toes */
  double mean_cms, p95_cms, p99_cms, max_cms; /* planted-toe speed */
  double lowest_cm;     /* lowest toe height over the run (world y, cm) */
} eval_feet_geom;

/* Floor level (metres) of one toe: the EVAL_FEET_FLOOR_PERCENTILE-th
 * percentile of pos[i * stride + 1] over frames 0..n-1 (pos points at the
 * toe's x of frame 0; stride = doubles from one frame to the next, 3 for a
 * packed array, 3 * joint_count for an eval_trace). NaN when n == 0 or no
 * height is finite. */
double eval_feet_floor_level(const double* pos, size_t stride, size_t n);

/* Measures toe_count toes over n frames of time step dt (seconds):
 * toes[k] points at toe k's x at frame 0, frames stride doubles apart.
 * Optionally per_frame (n * toe_count doubles) receives, at
 * [i * toe_count + k], the speed (cm/s) of toe k over the pair (i-1, i)
 * when planted, NaN otherwise (frame 0 is always NaN): the series to plot.
 * Returns 0, or -1 (out filled with NaNs / 0 counts) on bad arguments or
 * out of memory. With no planted pair the speeds are NaN. */
int eval_feet_geom_measure(const double* const* toes, size_t toe_count,
                           size_t stride, size_t n, double dt,
                           double* per_frame, eval_feet_geom* out);

#endif /* EVAL_FEET_GEOM_H */
