/*
 * eval_style_change.h - where a style change happened on a straight line,
 * from the hips alone (bench/bench_big_graph.c, `make bench-big-graph`).
 *
 * Three runs along a line that starts at the origin and runs along +Z:
 * the whole line in style A, the whole line in style B (the calibration
 * runs) and one that asks for B from some point on (the switching run).
 * Only the windows whose hips lie `margin` from both ends of the line are
 * measured (the arc length is the hips' z).
 *
 *   signature  per frame, over a EVAL_SIG_WINDOW window centred on it:
 *              hips ground speed (m/s), mean hips height above the floor
 *              walked on, and the spread of the hips' height (bounce) and
 *              of their sideways position (sway, x) within the window (m).
 *              Each feature is weighed in units of its spread in the
 *              calibration runs (the mean of the two spreads).
 *   floor      the lower toe's EVAL_FEET_FLOOR_PERCENTILE-th percentile
 *              height over the frames from the first to the last whose
 *              hips lie in the measured stretch, not over the whole run: a
 *              character stands at the end for whatever is left of the run
 *              (a faster style for longer), and that one standing pose
 *              would set the run's floor.
 *   labels     each window is labelled A or B by its nearest calibration
 *              window; a calibration run's own overlapping windows are left
 *              out when it labels itself. A performer's gait varies along a
 *              line, so a style is not one mean.
 *   the change the split of the switching run's labels (at least a metre
 *              of windows on either side) with the fewest labels against
 *              it, A before and B after.
 *
 * The caller judges: `told` (share of the calibration windows labelled
 * right) and `agree` (share of the switching run's windows the split
 * agrees with) say whether the styles were told apart at all.
 *
 * Units: metres, seconds, y up. Unit tests: tests/eval/test_style_change.c.
 */
#ifndef EVAL_STYLE_CHANGE_H
#define EVAL_STYLE_CHANGE_H

#include <stddef.h>

#define EVAL_SIG_WINDOW 1.0 /* gait signature window, seconds */

enum {
  EVAL_SIG_SPEED,
  EVAL_SIG_HEIGHT,
  EVAL_SIG_BOUNCE,
  EVAL_SIG_SWAY,
  EVAL_SIG_DIM
};

/* One run's exported geometry: per frame the hips (x, y, z) and both toes
 * (left x, y, z, then right x, y, z). */
typedef struct eval_track {
  size_t frames;
  const double* hips;
  const double* toes;
} eval_track;

/* The line: frames per second of the tracks, its length and the margin
 * left out at either end (m). */
typedef struct eval_style_line {
  double rate;
  double length;
  double margin;
} eval_style_line;

typedef struct eval_style_change {
  double mean[2][EVAL_SIG_DIM]; /* calibration runs A, B: signature mean */
  double sd[2][EVAL_SIG_DIM];   /* and spread */
  double told;  /* share of the calibration windows labelled right */
  double agree; /* share of the switching run's windows the split agrees
                   with (0: too short to split) */
  double at;    /* arc length of the split, m */
} eval_style_change;

/* The floor walked on over the measured stretch of one track (NAN when no
 * hips lie in it). */
double eval_style_floor(const eval_style_line* line, const eval_track* t);

/* Measures the change; returns 0 when a run has fewer than two windows in
 * the measured stretch or memory runs out, 1 otherwise. */
int eval_style_change_measure(const eval_style_line* line,
                              const eval_track* a, const eval_track* b,
                              const eval_track* sw, eval_style_change* out);

#endif
