/*
 * test_horn.c - Horn's closed-form absolute orientation (1987) recovers a
 * known rotation: exactly without noise, closely with noise and weights,
 * also for a half-turn (where the quaternion's w is 0) and for planar
 * point sets.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_math.h"

static double rnd(uint32_t* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}

/* angle between two rotations (radians), sign-insensitive */
static double qangle(const double a[4], const double b[4]) {
  double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  if (d > 1.0) d = 1.0;
  return 2.0 * acos(d);
}

static void check(const double q[4], double noise, int planar, double tol,
                  uint32_t seed) {
  double a[3 * 40], b[3 * 40], w[40], r[4];
  uint32_t i, s = seed;
  for (i = 0; i < 40; ++i) {
    a[3 * i] = rnd(&s);
    a[3 * i + 1] = planar ? 0.0 : rnd(&s);
    a[3 * i + 2] = rnd(&s);
    smgb_q_rotate(q, a + 3 * i, b + 3 * i);
    b[3 * i] += noise * rnd(&s);
    b[3 * i + 1] += noise * rnd(&s);
    b[3 * i + 2] += noise * rnd(&s);
    w[i] = 0.5 + 0.5 * (rnd(&s) + 1.0);
  }
  smgb_horn(a, b, w, 40, r);
  assert_true(fabs(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3] -
                   1.0) < 1e-9);
  assert_true(r[3] >= 0.0);
  if (qangle(q, r) > tol)
    fail_msg("recovered rotation off by %g rad (tolerance %g)", qangle(q, r),
             tol);
}

static void test_exact_rotation(void** state) {
  double axis[3] = {0.3, 0.8, -0.52}, n, q[4], h;
  (void)state;
  n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (h = -3.0; h <= 3.0; h += 0.5) {
    q[0] = axis[0] / n * sin(h / 2);
    q[1] = axis[1] / n * sin(h / 2);
    q[2] = axis[2] / n * sin(h / 2);
    q[3] = cos(h / 2);
    check(q, 0.0, 0, 1e-6, 11u + (uint32_t)(h * 10 + 40));
  }
}

static void test_half_turn_and_planar(void** state) {
  double half[4] = {0.0, 1.0, 0.0, 0.0}; /* 180 degrees about Y */
  double yaw[4];
  (void)state;
  check(half, 0.0, 0, 1e-6, 5);
  smgb_q_yaw(0.9, yaw);
  check(yaw, 0.0, 1, 1e-6, 6); /* all points in one plane */
}

static void test_noisy_rotation(void** state) {
  double q[4] = {0.1, 0.2, 0.3, 0.9};
  (void)state;
  smgb_q_normalize(q);
  check(q, 0.01, 0, 0.02, 9);
}

static void test_identity_for_identical_points(void** state) {
  double a[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, r[4];
  (void)state;
  smgb_horn(a, a, NULL, 3, r);
  assert_true(fabs(r[3] - 1.0) < 1e-12);
  /* degenerate input (all zero) gives identity, not NaN */
  memset(a, 0, sizeof a);
  smgb_horn(a, a, NULL, 3, r);
  assert_true(isfinite(r[0]) && isfinite(r[3]));
  assert_true(fabs(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3] -
                   1.0) < 1e-9);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_exact_rotation),
      cmocka_unit_test(test_half_turn_and_planar),
      cmocka_unit_test(test_noisy_rotation),
      cmocka_unit_test(test_identity_for_identical_points),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
