/*
 * test_style_change.c - the style-change measure of the big-graph bench
 * (tools/eval/eval_style_change.c) on synthetic walks with a known change:
 * two gaits that differ in speed, hips height and bounce, each varying
 * along the line as a performer's does, walked along a 24 m line and then
 * stood at the end for the rest of the run.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_style_change.h"

#define PI 3.14159265358979323846
#define RATE 30.0
#define LENGTH 24.0
#define SECONDS 36.0 /* the bench's run: 24 m / 0.8 m/s + 6 s */
#define FRAMES 1081 /* SECONDS at RATE, both ends */

/* A gait: speed and hips height, each varying along the line by a share
 * of a cycle of `period` metres, and the hips' bounce (spread, m). */
typedef struct gait {
  double speed, speed_var, height, height_var, period, bounce;
} gait;

static const gait k_a = {0.9, 0.15, 0.86, 0.002, 6.0, 0.015};
static const gait k_b = {1.4, 0.05, 0.84, 0.002, 5.0, 0.028};

typedef struct track_buf {
  double hips[3 * FRAMES];
  double toes[6 * FRAMES];
  eval_track t;
} track_buf;

/* Walks gait `a` to arc `at` (beyond LENGTH: none), then gait `b`, to the
 * end of the line; then stands there with both toes at `rest_toe` until
 * SECONDS. While walking the toes take turns on the floor (y = 0), the
 * hips bounce twice a second and sway once. */
static void walk(track_buf* r, const gait* a, const gait* b, double at,
                 double rest_toe) {
  double z = 0.0, t = 0.0;
  for (size_t i = 0; i < FRAMES; ++i, t += 1.0 / RATE) {
    double* h = r->hips + 3 * i;
    double* toe = r->toes + 6 * i;
    if (z < LENGTH) {
      const gait* g = z < at ? a : b;
      const double var = sin(2.0 * PI * z / g->period);
      const double lift = 0.08 * sin(2.0 * PI * t);
      h[0] = 0.01 * sin(2.0 * PI * t);
      h[1] = g->height + g->height_var * var +
             g->bounce * sqrt(2.0) * sin(4.0 * PI * t);
      h[2] = z;
      toe[1] = lift > 0.0 ? lift : 0.0;
      toe[4] = lift < 0.0 ? -lift : 0.0;
      z += (g->speed + g->speed_var * var) / RATE;
    } else {
      h[0] = 0.0;
      h[1] = 0.87;
      h[2] = LENGTH;
      toe[1] = toe[4] = rest_toe;
    }
    toe[0] = h[0] - 0.1;
    toe[3] = h[0] + 0.1;
    toe[2] = toe[5] = h[2];
  }
  r->t.frames = FRAMES;
  r->t.hips = r->hips;
  r->t.toes = r->toes;
}

static const eval_style_line k_line = {RATE, LENGTH, 3.0};

/* A change at 12 m and at 8 m is found within a few decimetres (the
 * window is a second long), and the styles are told apart. */
static void test_change_found(void** state) {
  static track_buf a, b, sw;
  eval_style_change c;
  (void)state;
  walk(&a, &k_a, &k_a, INFINITY, 0.0);
  walk(&b, &k_b, &k_b, INFINITY, 0.0);
  walk(&sw, &k_a, &k_b, 12.0, 0.0);
  assert_int_equal(eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &c),
                   1);
  assert_true(c.told >= 0.95);
  assert_true(c.agree >= 0.95);
  assert_true(fabs(c.at - 12.0) <= 0.5);
  assert_true(fabs(c.mean[0][EVAL_SIG_SPEED] - 0.9) < 0.05);
  assert_true(fabs(c.mean[1][EVAL_SIG_SPEED] - 1.4) < 0.05);
  assert_true(fabs(c.mean[1][EVAL_SIG_BOUNCE] - 0.028) < 0.003);
  walk(&sw, &k_a, &k_b, 8.0, 0.0);
  assert_int_equal(eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &c),
                   1);
  assert_true(fabs(c.at - 8.0) <= 0.5);
}

/* The floor is the one walked on over the measured stretch: a run that
 * stands at the end with a toe 1.3 cm lower (a standing pose of its own,
 * held for 14 of its 36 seconds) keeps the floor of its walk. Over the
 * whole run that pose set the floor, the hips of its walk measured 1.3 cm
 * higher than the calibration runs', and the B part nearer A's hips
 * height: the change measured 0.55 m later than the same walk's without
 * that pose. Where a run stops says nothing about where it changed. */
static void test_floor_under_the_walk(void** state) {
  static track_buf a, b, sw;
  eval_style_change c, level;
  (void)state;
  walk(&a, &k_a, &k_a, INFINITY, 0.0);
  walk(&b, &k_b, &k_b, INFINITY, 0.0);
  walk(&sw, &k_a, &k_b, 12.0, 0.0);
  assert_int_equal(
      eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &level), 1);
  walk(&sw, &k_a, &k_b, 12.0, -0.013);
  assert_true(fabs(eval_style_floor(&k_line, &sw.t)) < 1e-9);
  assert_int_equal(eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &c),
                   1);
  assert_true(c.told >= 0.95);
  assert_true(c.agree >= 0.95);
  assert_true(fabs(c.at - level.at) < 1e-9);
  assert_true(fabs(c.at - 12.0) <= 0.5);
}

/* Two runs of the same gait are not told apart: the measure says so
 * rather than placing a change. */
static void test_same_gait_not_told_apart(void** state) {
  static track_buf a, b, sw;
  eval_style_change c;
  (void)state;
  walk(&a, &k_a, &k_a, INFINITY, 0.0);
  walk(&b, &k_a, &k_a, INFINITY, 0.0);
  walk(&sw, &k_a, &k_a, INFINITY, 0.0);
  assert_int_equal(eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &c),
                   1);
  assert_true(c.told < 0.8);
}

/* A run that never reaches the measured stretch has no windows. */
static void test_no_windows(void** state) {
  static track_buf a, b, sw;
  eval_style_change c;
  (void)state;
  walk(&a, &k_a, &k_a, INFINITY, 0.0);
  walk(&b, &k_b, &k_b, INFINITY, 0.0);
  walk(&sw, &k_a, &k_b, 12.0, 0.0);
  for (size_t i = 0; i < FRAMES; ++i) sw.hips[3 * i + 2] = 1.0;
  assert_true(isnan(eval_style_floor(&k_line, &sw.t)));
  assert_int_equal(eval_style_change_measure(&k_line, &a.t, &b.t, &sw.t, &c),
                   0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_change_found),
      cmocka_unit_test(test_floor_under_the_walk),
      cmocka_unit_test(test_same_gait_not_told_apart),
      cmocka_unit_test(test_no_windows),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
