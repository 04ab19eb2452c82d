/*
 * test_feet_geom.c - the geometric planted-foot measure (tools/eval/
 * eval_feet_geom.c) on toe tracks with known answers: floor level from a
 * low percentile, planting by height alone, speeds of a slide and of a pop,
 * strided (eval_trace-like) input, bad arguments.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_feet_geom.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
#define N 100

/* A toe that walks: planted (y = base) for frames [0, 40) and [60, 100),
 * swinging 10 cm up in between; while planted it stays put except for
 * `slide` metres per frame along x. */
static void walk(double* p, double base, double slide) {
  int i;
  double x = 0.0;
  for (i = 0; i < N; ++i) {
    int down = i < 40 || i >= 60;
    if (down) x += slide;
    else x += 0.05;
    p[3 * i] = x;
    p[3 * i + 1] = down ? base : base + 0.10;
    p[3 * i + 2] = 0.0;
  }
}

static void test_floor_level(void** state) {
  double p[3 * N];
  (void)state;
  walk(p, 0.04, 0.0);
  p[3 * 10 + 1] = -0.5; /* one glitch through the floor */
  NEAR(eval_feet_floor_level(p, 3, N), 0.04, 1e-12);
  assert_true(isnan(eval_feet_floor_level(p, 3, 0)));
  assert_true(isnan(eval_feet_floor_level(NULL, 3, N)));
}

static void test_still_and_sliding(void** state) {
  double p[3 * N], per[N];
  const double* toes[1] = {p};
  eval_feet_geom g;
  (void)state;
  walk(p, 0.02, 0.0);
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, N, 1.0 / 30, per, &g),
                   0);
  assert_int_equal(g.planted_pairs, 39 + 39);
  NEAR(g.mean_cms, 0.0, 1e-9);
  NEAR(g.p99_cms, 0.0, 1e-9);
  NEAR(g.lowest_cm, 2.0, 1e-9);
  assert_true(isnan(per[0]) && isnan(per[50]));
  NEAR(per[20], 0.0, 1e-9);
  /* 1 cm per frame at 30 Hz while planted = 30 cm/s, wherever the toe is
   * planted above the world floor (here 7 cm: a rig's toe joint). */
  walk(p, 0.07, 0.01);
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, N, 1.0 / 30, NULL, &g),
                   0);
  NEAR(g.mean_cms, 30.0, 1e-6);
  NEAR(g.p95_cms, 30.0, 1e-6);
  NEAR(g.max_cms, 30.0, 1e-6);
  NEAR(g.lowest_cm, 7.0, 1e-9);
}

static void test_pop_and_band(void** state) {
  double p[3 * N];
  const double* toes[1] = {p};
  eval_feet_geom g;
  (void)state;
  walk(p, 0.0, 0.0);
  p[3 * 20] += 0.10;      /* a pop: 10 cm in one frame and back */
  p[3 * 70 + 1] = 0.024;  /* still planted (inside 2.5 cm) */
  p[3 * 80 + 1] = 0.026;  /* lifted: pairs (79,80), (80,81) not planted */
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, N, 0.1, NULL, &g), 0);
  assert_int_equal(g.planted_pairs, 78 - 2);
  NEAR(g.max_cms, 100.0, 1e-6); /* 10 cm in 0.1 s */
  NEAR(g.mean_cms, 200.0 / 76.0, 1e-6);
}

static void test_strided_two_toes(void** state) {
  /* Frames of 4 "joints" (x, y, z each), toes are joints 1 and 3. */
  double a[3 * N], b[3 * N], frames[12 * N], per[2 * N];
  const double* toes[2] = {frames + 3, frames + 9};
  eval_feet_geom g;
  int i;
  (void)state;
  walk(a, 0.03, 0.0);
  walk(b, 0.01, 0.02);
  memset(frames, 0, sizeof frames);
  for (i = 0; i < N; ++i) {
    memcpy(frames + 12 * i + 3, a + 3 * i, 3 * sizeof(double));
    memcpy(frames + 12 * i + 9, b + 3 * i, 3 * sizeof(double));
  }
  assert_int_equal(eval_feet_geom_measure(toes, 2, 12, N, 0.5, per, &g), 0);
  assert_int_equal(g.planted_pairs, 4 * 39);
  NEAR(g.mean_cms, 2.0, 1e-6); /* half the pairs at 0, half at 4 cm/s */
  NEAR(g.max_cms, 4.0, 1e-6);
  NEAR(g.lowest_cm, 1.0, 1e-9);
  NEAR(per[2 * 10], 0.0, 1e-9);
  NEAR(per[2 * 10 + 1], 4.0, 1e-6);
}

static void test_bad_arguments(void** state) {
  double p[3 * N];
  const double* toes[1] = {p};
  const double* none[1] = {NULL};
  eval_feet_geom g;
  (void)state;
  walk(p, 0.0, 0.0);
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, N, 0.0, NULL, &g), -1);
  assert_true(isnan(g.mean_cms));
  assert_int_equal(eval_feet_geom_measure(none, 1, 3, N, 0.1, NULL, &g), -1);
  assert_int_equal(eval_feet_geom_measure(toes, 1, 2, N, 0.1, NULL, &g), -1);
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, N, 0.1, NULL, NULL),
                   -1);
  /* No planted pair: counts 0, speeds NaN, still a success. */
  assert_int_equal(eval_feet_geom_measure(toes, 1, 3, 1, 0.1, NULL, &g), 0);
  assert_int_equal(g.planted_pairs, 0);
  assert_true(isnan(g.p99_cms));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_floor_level),
      cmocka_unit_test(test_still_and_sliding),
      cmocka_unit_test(test_pop_and_band),
      cmocka_unit_test(test_strided_two_toes),
      cmocka_unit_test(test_bad_arguments),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
