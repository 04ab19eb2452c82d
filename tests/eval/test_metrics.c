/*
 * test_metrics.c - the measurements of `make eval` (tools/eval/
 * eval_metrics.c) on inputs with known answers: path distance, path
 * builders, foot contacts and skate, footfalls, phases, statistics and the
 * rigid-frame helpers used for the spine error.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_metrics.h"

#define PI 3.14159265358979323846
#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_stats(void** state) {
  double v[6] = {3, NAN, 1, 2, 5, 4}, scratch[6];
  em_stats s;
  (void)state;
  em_stats_compute(v, 6, scratch, &s);
  assert_int_equal(s.count, 5);
  NEAR(s.mean, 3.0, 1e-12);
  NEAR(s.median, 3.0, 1e-12);
  NEAR(s.min, 1.0, 1e-12);
  NEAR(s.max, 5.0, 1e-12);
  NEAR(s.p99, 4.96, 1e-12); /* 1 + 0.99 * 4 positions -> 4.96 */
  em_stats_compute(v + 1, 1, scratch, &s);
  assert_int_equal(s.count, 0);
  assert_true(isnan(s.mean));
}

static void test_correlation_and_slope(void** state) {
  double x[5] = {0, 1, 2, 3, 4}, y[5], z[5], b0;
  int i;
  (void)state;
  for (i = 0; i < 5; ++i) {
    y[i] = 2.0 + 0.5 * x[i];
    z[i] = -y[i];
  }
  NEAR(em_pearson(x, y, 5), 1.0, 1e-12);
  NEAR(em_pearson(x, z, 5), -1.0, 1e-12);
  NEAR(em_linear_slope(x, y, 5, &b0), 0.5, 1e-12);
  NEAR(b0, 2.0, 1e-12);
  assert_true(isnan(em_pearson(x, x, 1)));
  z[0] = z[1] = z[2] = z[3] = z[4] = 1.0; /* constant: undefined */
  assert_true(isnan(em_pearson(x, z, 5)));
}

static void test_polyline_distance(void** state) {
  /* An L: (0,0) -> (0,10) -> (5,10). */
  double p[6] = {0, 0, 0, 10, 5, 10}, arc = -1, x, z;
  (void)state;
  NEAR(em_polyline_length(p, 3), 15.0, 1e-12);
  NEAR(em_polyline_distance(p, 3, 1.0, 4.0, &arc), 1.0, 1e-12);
  NEAR(arc, 4.0, 1e-12);
  NEAR(em_polyline_distance(p, 3, 3.0, 12.0, &arc), 2.0, 1e-12);
  NEAR(arc, 13.0, 1e-12);
  /* Beyond the start: distance to the end point. */
  NEAR(em_polyline_distance(p, 3, 0.0, -3.0, &arc), 3.0, 1e-12);
  NEAR(arc, 0.0, 1e-12);
  /* Windowed: only arc lengths 11..15 (the horizontal leg) count. */
  NEAR(em_polyline_distance_window(p, 3, 1.0, 4.0, 11.0, 15.0, &arc),
       hypot(0.0, 6.0), 1e-12);
  NEAR(arc, 11.0, 1e-12);
  em_polyline_point_at(p, 3, 12.5, &x, &z);
  NEAR(x, 2.5, 1e-12);
  NEAR(z, 10.0, 1e-12);
  em_polyline_point_at(p, 3, 99.0, &x, &z);
  NEAR(x, 5.0, 1e-12);
  {
    double traj[6] = {1, 1, -2, 5, 0, 10}, mean, max;
    em_path_deviation(p, 3, traj, 3, &mean, &max);
    NEAR(mean, 1.0, 1e-12);
    NEAR(max, 2.0, 1e-12);
  }
}

static void test_path_builders(void** state) {
  static double xz[2 * 4096];
  size_t n;
  double x, z, r = 3.0;
  (void)state;
  n = em_path_straight(10.0, 0.25, xz, 4096);
  assert_int_equal(n, 41);
  NEAR(xz[2 * n - 2], 0.0, 1e-12);
  NEAR(xz[2 * n - 1], 10.0, 1e-12);
  /* Left 90 degree turn: heading grows, forward (sin h, cos h) turns from
   * +z to +x; the arc ends at (r, lead + r) and the tail runs along +x. */
  n = em_path_turn(2.0, r, PI / 2, 4.0, 0.05, xz, 4096);
  NEAR(em_polyline_length(xz, n), 2.0 + r * PI / 2 + 4.0, 1e-3);
  NEAR(xz[2 * n - 2], r + 4.0, 1e-9);
  NEAR(xz[2 * n - 1], 2.0 + r, 1e-9);
  /* Right turn mirrors it. */
  n = em_path_turn(2.0, r, -PI / 2, 4.0, 0.05, xz, 4096);
  NEAR(xz[2 * n - 2], -(r + 4.0), 1e-9);
  /* S-curve ends heading +z again, displaced sideways by 2 r (1 - cos a). */
  n = em_path_s_curve(1.0, r, PI / 3, 1.0, 0.05, xz, 4096);
  NEAR(xz[2 * n - 2], 2.0 * r * (1.0 - cos(PI / 3)), 1e-9);
  NEAR(xz[2 * n - 1] - xz[2 * n - 3], 0.05, 1e-3);
  /* A full circle returns to where it started, then leaves along +z. */
  n = em_path_circle(2.0, r, 1.0, 0.05, xz, 4096);
  NEAR(em_polyline_length(xz, n), 3.0 + 2 * PI * r, 1e-2);
  NEAR(xz[2 * n - 2], 0.0, 1e-9);
  NEAR(xz[2 * n - 1], 3.0, 1e-9);
  em_polyline_point_at(xz, n, 2.0 + PI * r, &x, &z);
  NEAR(x, 2.0 * r, 1e-3); /* half way round: opposite side, to the left */
  NEAR(z, 2.0, 1e-3);
  /* Capacity respected. */
  assert_int_equal(em_path_straight(10.0, 0.25, xz, 5), 5);
  assert_int_equal(em_path_straight(10.0, 0.0, xz, 5), 0);
}

static void test_contacts_and_skate(void** state) {
  /* A foot at rest for frames 0-9 (sliding 1 cm per frame in 5-9), swinging
   * up and forward for 10-19, planted again for 20-29. */
  double pos[3 * 30];
  uint8_t contact[30], truth[30];
  size_t falls[8], i, k;
  em_skate sk;
  (void)state;
  for (i = 0; i < 30; ++i) {
    double x = 0, y = 0.05, z = 0;
    if (i >= 5 && i < 10) x = 0.01 * (double)(i - 4);
    if (i >= 10 && i < 20) {
      double t = (double)(i - 9) / 11.0;
      x = 0.05;
      y = 0.05 + 0.15 * sin(PI * t);
      z = 0.8 * t;
    }
    if (i >= 20) x = 0.05, z = 0.8;
    pos[3 * i] = x;
    pos[3 * i + 1] = y;
    pos[3 * i + 2] = z;
    truth[i] = (uint8_t)(i < 10 || i >= 20);
  }
  em_foot_skate(pos, truth, 30, &sk);
  /* Pairs inside contact: 9 in the first stance, 9 in the second. */
  assert_int_equal(sk.contact_frames, 18);
  NEAR(sk.total_cm, 5.0, 1e-9);
  NEAR(sk.max_cm, 1.0, 1e-9);
  NEAR(sk.mean_cm, 5.0 / 18.0, 1e-9);
  /* Height + speed detection at 30 Hz: 1 cm/frame = 0.3 m/s passes a
   * 0.5 m/s limit, the swing (about 2.4 m/s) does not. */
  em_detect_contacts(pos, 30, 1.0 / 30.0, 0.03, 0.5, contact);
  for (i = 0; i < 30; ++i)
    if (i != 9 && i != 20) assert_int_equal(contact[i], truth[i]);
  k = em_footfalls(truth, 30, falls, 8);
  assert_int_equal(k, 1);
  assert_int_equal(falls[0], 20);
  /* No contacts: NaN means, zero frames. */
  memset(truth, 0, sizeof(truth));
  em_foot_skate(pos, truth, 30, &sk);
  assert_int_equal(sk.contact_frames, 0);
  assert_true(isnan(sk.mean_cm));
}

static void test_skate_lowest(void** state) {
  /* Heel planted for frames 0-3 while the toe rolls down; then the heel
   * lifts and the planted toe slides 2 cm per frame for frames 4-6. */
  double ankle[3 * 7], toe[3 * 7];
  uint8_t c[7] = {1, 1, 1, 1, 1, 1, 1};
  em_skate sk;
  size_t i;
  (void)state;
  for (i = 0; i < 7; ++i) {
    ankle[3 * i] = 0.0;
    ankle[3 * i + 1] = i < 4 ? 0.02 : 0.02 + 0.03 * (double)(i - 3);
    ankle[3 * i + 2] = i < 4 ? 0.0 : 0.05 * (double)(i - 3);
    toe[3 * i] = 0.0;
    toe[3 * i + 1] = i < 4 ? 0.06 - 0.01 * (double)i : 0.01;
    toe[3 * i + 2] = i < 4 ? 0.15 : 0.15 + 0.02 * (double)(i - 3);
  }
  em_foot_skate_lowest(ankle, toe, c, 7, &sk);
  assert_int_equal(sk.contact_frames, 6);
  /* Pairs 1-3: ankle lower, still (0). Pair 4: toe lower (0.01 < 0.05),
   * slides 2 cm; pairs 5, 6: 2 cm each. */
  NEAR(sk.total_cm, 6.0, 1e-9);
  NEAR(sk.max_cm, 2.0, 1e-9);
}

static void test_fk_and_ground_frame(void** state) {
  /* Root at (1, 1, 0) turned 90 degrees about Y; child offset +Z 0.5,
   * grandchild offset +Y 0.25 under a local 90 degree X rotation. */
  int32_t parents[3] = {-1, 0, 1};
  float offsets[9] = {0, 0, 0, 0, 0, 0.5f, 0, 0.25f, 0};
  float s = (float)sqrt(0.5);
  float pose[3 + 12] = {1, 1, 0, 0, s, 0, s, s, 0, 0, s, 0, 0, 0, 1};
  double pos[9], rot[12], o[3], g[4], local[3];
  (void)state;
  em_fk(3, parents, offsets, pose, pos, rot);
  NEAR(pos[3], 1.5, 1e-6); /* +Z turned to +X */
  NEAR(pos[4], 1.0, 1e-6);
  NEAR(pos[5], 0.0, 1e-6);
  /* Child rotation: yaw 90 then local X 90: +Y maps to the yawed +Z = +X. */
  NEAR(pos[6], 1.75, 1e-6);
  NEAR(pos[7], 1.0, 1e-6);
  em_ground_frame(pos, rot, o, g);
  NEAR(o[1], 0.0, 1e-12);
  em_to_frame(o, g, pos + 6, local);
  NEAR(local[0], 0.0, 1e-6); /* straight ahead of the character */
  NEAR(local[1], 1.0, 1e-6);
  NEAR(local[2], 0.75, 1e-6);
}

static void test_labels(void** state) {
  uint32_t lab[6] = {0, 0, 1, 1, 0, 2};
  (void)state;
  assert_int_equal(em_first_label(lab, 6, 0, 1), 2);
  assert_int_equal(em_first_label(lab, 6, 3, 0), 4);
  assert_int_equal(em_first_label(lab, 6, 0, 7), 6);
}

static void test_phases(void** state) {
  size_t falls[3] = {10, 20, 40};
  double ph[50], d[200], u[200], mean, sd;
  size_t i;
  (void)state;
  em_phase_from_footfalls(falls, 3, 50, ph);
  assert_true(isnan(ph[9]));
  NEAR(ph[10], 0.0, 1e-12);
  NEAR(ph[15], 0.5, 1e-12);
  NEAR(ph[30], 0.5, 1e-12);
  assert_true(isnan(ph[40]));
  NEAR(em_wrap_half(0.75), -0.25, 1e-12);
  NEAR(em_wrap_half(-0.5), -0.5, 1e-12);
  NEAR(em_wrap_half(0.5), -0.5, 1e-12);
  NEAR(em_wrap_half(2.1), 0.1, 1e-12);
  /* A constant offset near the wrap point: mean -0.48, std ~0. */
  for (i = 0; i < 200; ++i) d[i] = (i % 2) ? 0.52 : -0.48;
  assert_int_equal(em_circular_stats(d, 200, &mean, &sd), 200);
  NEAR(mean, -0.48, 1e-9);
  assert_true(sd < 1e-6);
  /* A steady drift (velocity differential) of 0.01 cycle per frame spreads
   * over the whole circle and unwraps to a straight line. */
  for (i = 0; i < 200; ++i) d[i] = em_wrap_half(0.01 * (double)i);
  em_circular_stats(d, 200, &mean, &sd);
  assert_true(sd > 0.3);
  em_unwrap(d, 200, u);
  for (i = 0; i < 200; ++i) NEAR(u[i], 0.01 * (double)i, 1e-9);
}

static void test_rigid_frames(void** state) {
  double s = sqrt(0.5);
  double qy[4] = {0, s, 0, s}; /* 90 degrees about +Y */
  double v[3] = {0, 0, 1}, o[3] = {1, 2, 3}, r[3], back[3], p[3];
  float m[16];
  double q2[4];
  (void)state;
  em_quat_rotate(qy, v, r); /* +z -> +x (heading convention) */
  NEAR(r[0], 1.0, 1e-12);
  NEAR(r[1], 0.0, 1e-12);
  NEAR(r[2], 0.0, 1e-12);
  p[0] = o[0] + r[0];
  p[1] = o[1] + r[1];
  p[2] = o[2] + r[2];
  em_to_frame(o, qy, p, back);
  NEAR(back[0], 0.0, 1e-12);
  NEAR(back[2], 1.0, 1e-12);
  /* Column-major rotation matrix of qy: x -> -z, z -> x. */
  memset(m, 0, sizeof(m));
  m[0] = 0;  m[1] = 0; m[2] = -1;  /* column 0 = image of x */
  m[5] = 1;                        /* column 1 = y */
  m[8] = 1;  m[9] = 0; m[10] = 0;  /* column 2 = image of z */
  m[15] = 1;
  em_quat_from_matrix(m, q2);
  NEAR(em_quat_angle(q2, qy), 0.0, 1e-6);
  {
    double qn[4] = {0, -s, 0, -s}; /* same rotation, other sign */
    NEAR(em_quat_angle(qn, qy), 0.0, 1e-6);
    qn[1] = 0; qn[3] = 1;
    NEAR(em_quat_angle(qn, qy), PI / 2, 1e-9);
  }
}

static void test_joint_error(void** state) {
  double a[6] = {0, 0, 0, 0, 1, 0}, b[6] = {0.3, 0, 0.4, 0, 1, 0};
  (void)state;
  NEAR(em_mean_joint_error(a, b, 2, 0.5), 0.5, 1e-12); /* (0.5+0)/2/0.5 */
  assert_true(isnan(em_mean_joint_error(a, b, 2, 0.0)));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_stats),
      cmocka_unit_test(test_correlation_and_slope),
      cmocka_unit_test(test_polyline_distance),
      cmocka_unit_test(test_path_builders),
      cmocka_unit_test(test_contacts_and_skate),
      cmocka_unit_test(test_skate_lowest),
      cmocka_unit_test(test_fk_and_ground_frame),
      cmocka_unit_test(test_labels),
      cmocka_unit_test(test_phases),
      cmocka_unit_test(test_rigid_frames),
      cmocka_unit_test(test_joint_error),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
