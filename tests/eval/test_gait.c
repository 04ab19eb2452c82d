/*
 * test_gait.c - the gait measures of the behaviour section (tools/eval/
 * eval_gait.c) on tracks with known answers: swings (threshold, minimum
 * length, a foot still up at the end), the floor level of the latest
 * stance across two performers' planted heights, the median, window speed on a
 * straight line and a circle, travel heading, pelvis forward calibration
 * and facing, angle wrapping and a joint's rotation range.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_gait.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
#define PI 3.14159265358979323846
#define DT (1.0 / 30.0)

/* Toe heights: down, a 12-frame swing, down, a 2-frame flick (shorter than
 * 0.1 s), down, a swing still up at the end. */
static void toe_track(double* p, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i) {
    double y = 0.05;
    if (i >= 10 && i < 22) y = 0.15;
    if (i >= 40 && i < 42) y = 0.15;
    if (i >= 60) y = 0.30;
    p[3 * i] = 0.0;
    p[3 * i + 1] = y;
    p[3 * i + 2] = 0.0;
  }
}

static void fill(double* level, size_t n, double v) {
  size_t i;
  for (i = 0; i < n; ++i) level[i] = v;
}

static void test_swings(void** state) {
  double p[3 * 80], out[8], level[80];
  size_t c;
  (void)state;
  toe_track(p, 80);
  fill(level, 80, 0.05);
  c = eval_gait_swings(p, 3, 0, 80, level, DT, out, 8);
  assert_int_equal(c, 2); /* the flick is not a step */
  NEAR(out[0], 12 * DT, 1e-9);
  NEAR(out[1], 20 * DT, 1e-9); /* still up at the last frame */
  /* a toe 2 cm up is not swinging (band 2.5 cm) */
  fill(level, 80, 0.13);
  c = eval_gait_swings(p, 3, 0, 80, level, DT, out, 8);
  assert_int_equal(c, 1);
  NEAR(out[0], 20 * DT, 1e-9);
  /* a range that ends mid-swing cuts it there */
  fill(level, 80, 0.05);
  c = eval_gait_swings(p, 3, 0, 70, level, DT, out, 8);
  assert_int_equal(c, 2);
  NEAR(out[1], 10 * DT, 1e-9);
  assert_int_equal(eval_gait_swings(NULL, 3, 0, 80, level, DT, out, 8), 0);
  assert_int_equal(eval_gait_swings(p, 3, 0, 80, NULL, DT, out, 8), 0);
}

/* Two performers: the planted toe sits at 0 for four strides, then at
 * 4 cm (the motion changes performer during a swing); 0.4 s swings 15 cm
 * up, moving at 3 m/s, every 1.1 s. One level for
 * the run would make the second performer's stances part of its swings;
 * the level of the latest stance follows them. */
static void test_floor_levels(void** state) {
  enum { N = 240 };
  double p[3 * N], level[N], out[32], x = 0.0;
  size_t i, c;
  (void)state;
  for (i = 0; i < N; ++i) {
    int up = (i % 33) < 12;
    if (up) x += 0.1;
    p[3 * i] = x;
    p[3 * i + 1] = (i < 132 ? 0.0 : 0.04) + (up ? 0.15 : 0.0);
    p[3 * i + 2] = 0.0;
  }
  assert_int_equal(eval_gait_floor_levels(p, 3, N, DT, level), 0);
  NEAR(level[20], 0.0, 1e-9);  /* in a stance: its height */
  NEAR(level[5], 0.0, 1e-9);   /* in the first swing: the run's floor */
  NEAR(level[N - 10], 0.04, 1e-9);
  NEAR(level[N - 30], 0.04, 1e-9); /* mid-swing: the stance it left */
  c = eval_gait_swings(p, 3, 0, N, level, DT, out, 32);
  assert_int_equal(c, 8); /* the last one cut by the end of the run */
  for (i = 0; i + 1 < c; ++i) NEAR(out[i], 12 * DT, 1e-9);
  assert_int_equal(eval_gait_floor_levels(NULL, 3, N, DT, level), -1);
  assert_int_equal(eval_gait_floor_levels(p, 3, N, 0.0, level), -1);
}

static void test_median(void** state) {
  double a[5] = {5, 1, 4, 2, 3}, b[4] = {4, 1, 3, 2};
  (void)state;
  NEAR(eval_gait_median(a, 5), 3.0, 1e-12);
  NEAR(eval_gait_median(b, 4), 2.5, 1e-12);
  assert_true(isnan(eval_gait_median(a, 0)));
}

static void test_window_speed(void** state) {
  double line[3 * 61], circle[3 * 61];
  size_t i;
  (void)state;
  for (i = 0; i < 61; ++i) {
    double a = 3.0 * (double)i * DT / 2.0; /* 3 m/s on r = 2: 1.5 rad/s */
    line[3 * i] = 0.0;
    line[3 * i + 1] = 1.0;
    line[3 * i + 2] = 1.5 * (double)i * DT;
    circle[3 * i] = 2.0 * sin(a);
    circle[3 * i + 1] = 1.0;
    circle[3 * i + 2] = 2.0 - 2.0 * cos(a);
  }
  NEAR(eval_gait_window_speed(line, 3, 61, 30, 15, DT), 1.5, 1e-9);
  /* near the ends the window is clipped, not shortened to nothing */
  NEAR(eval_gait_window_speed(line, 3, 61, 0, 15, DT), 1.5, 1e-9);
  /* path length, not the chord: a tight circle keeps its speed */
  NEAR(eval_gait_window_speed(circle, 3, 61, 30, 15, DT), 3.0, 1e-3);
  assert_true(isnan(eval_gait_window_speed(line, 3, 1, 0, 15, DT)));
  NEAR(eval_gait_travel_heading(line, 3, 0, 30), 0.0, 1e-12);
  assert_true(isnan(eval_gait_travel_heading(line, 3, 5, 5)));
}

/* Rotation about +y by angle a. */
static void yaw(double a, double q[4]) {
  q[0] = 0.0;
  q[1] = sin(a / 2.0);
  q[2] = 0.0;
  q[3] = cos(a / 2.0);
}

static void test_facing(void** state) {
  double q[4 * 40], travel[40], axis[3], f;
  size_t i;
  (void)state;
  /* a rig whose pelvis forward is its local +x: the pelvis is turned by
   * -90 deg about y when the body walks along +z (heading 0) */
  for (i = 0; i < 40; ++i) {
    double twist = 0.1 * sin((double)i); /* each step twists the pelvis */
    yaw(-PI / 2.0 + twist, q + 4 * i);
    travel[i] = i % 7 == 0 ? NAN : 0.0;
  }
  assert_int_equal(eval_gait_calibrate_forward(q, travel, 40, axis), 0);
  NEAR(axis[0], 1.0, 0.02);
  NEAR(axis[1], 0.0, 1e-9);
  /* that rig turned to heading +60 deg faces +60 deg */
  yaw(-PI / 2.0 + PI / 3.0, q);
  f = eval_gait_facing(q, axis);
  NEAR(f, PI / 3.0, 0.02);
  for (i = 0; i < 40; ++i) travel[i] = NAN;
  assert_int_equal(eval_gait_calibrate_forward(q, travel, 40, axis), -1);
  NEAR(eval_gait_angle_diff(PI - 0.1, -PI + 0.1), -0.2, 1e-12);
  NEAR(eval_gait_angle_diff(0.3, 0.1), 0.2, 1e-12);
}

/* A runner facing exactly its direction of travel at every frame, round
 * a hairpin of about 150 degrees it brakes for (3 m/s down to 1 m/s at the apex and
 * back up), faces its travel over every 1 s window; the plain mean of
 * the facings over time, which counts the slow frames at the apex more
 * than the chord does, is more than 10 degrees off somewhere (within 5
 * degrees: the facing turns by up to 6 degrees from one frame to the
 * next at the apex). */
static void test_window_facing(void** state) {
  enum { N = 121, HALF = 15 };
  double hips[3 * N], q[4 * N], axis[3] = {0.0, 0.0, 1.0};
  double h = 0.0, x = 0.0, z = 0.0, worst = 0.0, worst_time = 0.0;
  size_t i, k;
  (void)state;
  for (i = 0; i < N; ++i) {
    const double t = (double)i * DT - 2.0; /* apex at t = 0 */
    const double v = fmin(3.0, 1.0 + 5.0 * fabs(t));
    /* the turn rate of a 0.3 m radius at the apex, fading with speed */
    const double w = fabs(t) < 0.25 ? -v / 0.3 : 0.0;
    hips[3 * i] = x;
    hips[3 * i + 1] = 1.0;
    hips[3 * i + 2] = z;
    yaw(h, q + 4 * i);
    x += v * DT * sin(h);
    z += v * DT * cos(h);
    h += w * DT;
  }
  assert_true(h < -2.5); /* turned by more than 140 degrees */
  for (i = HALF; i + HALF < N; ++i) {
    const double travel =
        eval_gait_travel_heading(hips, 3, i - HALF, i + HALF);
    const double f =
        eval_gait_window_facing(q, hips, 3, i - HALF, i + HALF, axis);
    double sx = 0.0, sz = 0.0;
    for (k = i - HALF; k <= i + HALF; ++k) {
      const double fk = eval_gait_facing(q + 4 * k, axis);
      sx += sin(fk);
      sz += cos(fk);
    }
    worst = fmax(worst, fabs(eval_gait_angle_diff(f, travel)));
    worst_time =
        fmax(worst_time, fabs(eval_gait_angle_diff(atan2(sx, sz), travel)));
  }
  print_message("facing against travel: weighted by travel %.1f deg, by time "
                "%.1f deg at most\n", worst * 180.0 / PI,
                worst_time * 180.0 / PI);
  assert_true(worst * 180.0 / PI < 5.0); /* a frame turns up to 6 deg */
  assert_true(worst_time * 180.0 / PI > 10.0);
  assert_true(isnan(eval_gait_window_facing(q, hips, 3, 5, 4, axis)));
}

static void test_rotation_range(void** state) {
  double q[4 * 5];
  size_t i;
  (void)state;
  for (i = 0; i < 5; ++i) yaw(0.01 * (double)i, q + 4 * i);
  NEAR(eval_gait_rotation_range_deg(q, 4, 5), 0.04 * 180.0 / PI, 1e-6);
  /* a frozen joint covers no range */
  for (i = 0; i < 5; ++i) yaw(0.3, q + 4 * i);
  NEAR(eval_gait_rotation_range_deg(q, 4, 5), 0.0, 1e-5);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_swings),
      cmocka_unit_test(test_floor_levels),
      cmocka_unit_test(test_median),
      cmocka_unit_test(test_window_speed),
      cmocka_unit_test(test_facing),
      cmocka_unit_test(test_window_facing),
      cmocka_unit_test(test_rotation_range),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
