/*
 * test_bvh_parse.c - BVH semantics: channel order (R = product of the
 * listed per-channel rotations), position channels, units, T-pose skip,
 * frame rate, quaternion hemisphere continuity, and the writer's round trip.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_clip.h"
#include "import_helpers.h"

static smgb_clip parse_ok(const char* text, float unit, uint32_t skip) {
  smgb_clip c;
  smgb_error err;
  smg_result r = smgb_bvh_parse(text, strlen(text), "t.bvh", unit, skip, &c,
                                &err);
  if (r != SMG_OK) print_error("parse failed: %s\n", err.message);
  assert_int_equal(r, SMG_OK);
  return c;
}

/* 3x3 rotation about axis (0 x, 1 y, 2 z), row-major, degrees. */
static void mat_axis(int axis, double deg, double m[9]) {
  double a = deg * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a);
  int i;
  for (i = 0; i < 9; ++i) m[i] = 0.0;
  if (axis == 0) { m[0] = 1; m[4] = c; m[5] = -s; m[7] = s; m[8] = c; }
  if (axis == 1) { m[0] = c; m[2] = s; m[4] = 1; m[6] = -s; m[8] = c; }
  if (axis == 2) { m[0] = c; m[1] = -s; m[3] = s; m[4] = c; m[8] = 1; }
}

static void mat_mul(const double a[9], const double b[9], double o[9]) {
  double r[9];
  int i, j, k;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) {
      r[3 * i + j] = 0.0;
      for (k = 0; k < 3; ++k) r[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    }
  memcpy(o, r, sizeof r);
}

/* Root at (1,2,3) rotated 90 degrees about Z; child offset (0,1,0). */
static void test_simple_fk(void** state) {
  static const char text[] =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n"
      " CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
      "Yrotation\n JOINT Child\n {\n  OFFSET 0 1 0\n"
      "  CHANNELS 3 Xrotation Yrotation Zrotation\n  End Site\n  {\n"
      "   OFFSET 0 1 0\n  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.5\n"
      "1 2 3 90 0 0 0 0 0\n";
  smgb_clip c = parse_ok(text, 1.0f, 0);
  float pos[6], rot[8];
  const float h = (float)sqrt(0.5);
  (void)state;
  assert_int_equal(c.skeleton.joint_count, 2);
  assert_string_equal(c.skeleton.names[1], "Child");
  assert_int_equal(c.skeleton.parents[1], 0);
  assert_int_equal(c.frame_count, 1);
  assert_float_equal(c.frame_rate, 2.0f, 1e-6f);
  assert_float_equal(c.poses[3 + 2], h, 1e-6f); /* q = (0,0,sin45,cos45) */
  assert_float_equal(c.poses[3 + 3], h, 1e-6f);
  smgb_fk(&c.skeleton, c.poses, pos, rot);
  assert_float_equal(pos[0], 1.0f, 1e-6f);
  assert_float_equal(pos[1], 2.0f, 1e-6f);
  assert_float_equal(pos[2], 3.0f, 1e-6f);
  /* Rz(90) maps +Y to -X: the child sits at (1-1, 2, 3). */
  assert_float_equal(pos[3], 0.0f, 1e-6f);
  assert_float_equal(pos[4], 2.0f, 1e-6f);
  assert_float_equal(pos[5], 3.0f, 1e-6f);
  assert_float_equal(rot[4 + 2], h, 1e-6f); /* child world = root world */
  smgb_clip_free(&c);
}

/* Channel order matters: "Zrotation Xrotation Yrotation" means Rz*Rx*Ry.
 * Checked against independent 3x3 matrices through a two-level chain. */
static void test_channel_order(void** state) {
  static const char* const orders[3] = {"Zrotation Xrotation Yrotation",
                                        "Xrotation Yrotation Zrotation",
                                        "Yrotation Zrotation Xrotation"};
  static const int axes[3][3] = {{2, 0, 1}, {0, 1, 2}, {1, 2, 0}};
  const double angles[3] = {30.0, -40.0, 75.0};
  int o;
  (void)state;
  for (o = 0; o < 3; ++o) {
    char text[1024];
    smgb_clip c;
    float pos[9];
    double m[9], t[9], p[3];
    int i;
    snprintf(text, sizeof text,
             "HIERARCHY\nROOT R\n{\n OFFSET 0 0 0\n CHANNELS 3 %s\n"
             " JOINT A\n {\n  OFFSET 1 2 3\n  CHANNELS 3 %s\n"
             "  JOINT B\n  {\n   OFFSET 0.5 -1 2\n   CHANNELS 1 Xrotation\n"
             "  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n"
             "%g %g %g %g %g %g 0\n",
             orders[o], orders[o], angles[0], angles[1], angles[2],
             angles[2], angles[0], angles[1]);
    c = parse_ok(text, 1.0f, 0);
    smgb_fk(&c.skeleton, c.poses, pos, NULL);
    /* Root matrix: product over the listed channels in order. */
    mat_axis(axes[o][0], angles[0], m);
    mat_axis(axes[o][1], angles[1], t);
    mat_mul(m, t, m);
    mat_axis(axes[o][2], angles[2], t);
    mat_mul(m, t, m);
    for (i = 0; i < 3; ++i)
      p[i] = m[3 * i] * 1 + m[3 * i + 1] * 2 + m[3 * i + 2] * 3;
    assert_float_equal(pos[3], p[0], 1e-5);
    assert_float_equal(pos[4], p[1], 1e-5);
    assert_float_equal(pos[5], p[2], 1e-5);
    {
      /* Joint A's own rotation with the shifted angle list. */
      double a[9];
      const double angA[3] = {angles[2], angles[0], angles[1]};
      mat_axis(axes[o][0], angA[0], a);
      mat_axis(axes[o][1], angA[1], t);
      mat_mul(a, t, a);
      mat_axis(axes[o][2], angA[2], t);
      mat_mul(a, t, a);
      mat_mul(m, a, a);
      for (i = 0; i < 3; ++i)
        p[i] = pos[3 + i] + a[3 * i] * 0.5 - a[3 * i + 1] * 1 + a[3 * i + 2] * 2;
      assert_float_equal(pos[6], p[0], 1e-5);
      assert_float_equal(pos[7], p[1], 1e-5);
      assert_float_equal(pos[8], p[2], 1e-5);
    }
    smgb_clip_free(&c);
  }
}

/* Units, T-pose skip, frame-rate snapping and channel subsets. */
static void test_units_skip_rate(void** state) {
  static const char text[] =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 5 6 7\n CHANNELS 2 Yposition "
      "Yrotation\n JOINT LeftUpLeg\n {\n  OFFSET 9 -6 0\n  CHANNELS 1 "
      "Xrotation\n  JOINT LeftLeg\n  {\n   OFFSET 0 -42 0\n   CHANNELS 1 "
      "Xrotation\n   JOINT LeftFoot\n   {\n    OFFSET 0 -42 0\n    CHANNELS 0\n"
      "   }\n  }\n }\n}\nMOTION\nFrames: 3\nFrame Time: .0083333\n"
      "100 0 0 0\n90 10 0 0\n91 20 0 0\n";
  smgb_clip c;
  (void)state;
  /* Explicit unit. */
  c = parse_ok(text, 0.01f, 1);
  assert_int_equal(c.frame_count, 2);
  assert_float_equal(c.frame_rate, 120.0f, 0.0f); /* snapped exactly */
  /* X and Z come from the OFFSET, Y from the channel, all scaled. */
  assert_float_equal(c.poses[0], 0.05f, 1e-6f);
  assert_float_equal(c.poses[1], 0.90f, 1e-6f);
  assert_float_equal(c.poses[2], 0.07f, 1e-6f);
  assert_float_equal(c.skeleton.offsets[2][1], -0.42f, 1e-6f);
  assert_float_equal(smgb_skeleton_leg_length(&c.skeleton), 0.84f, 1e-5f);
  smgb_clip_free(&c);
  /* Guessed unit: a 84-unit leg is centimetres. */
  c = parse_ok(text, 0.0f, 0);
  assert_int_equal(c.frame_count, 3);
  assert_float_equal(c.poses[1], 1.0f, 1e-6f);
  assert_float_equal(c.skeleton.offsets[2][1], -0.42f, 1e-6f);
  smgb_clip_free(&c);
}

/* q and -q: consecutive frames stay in one hemisphere, all unit length. */
static void test_hemisphere(void** state) {
  static const char text[] =
      "HIERARCHY\nROOT R\n{\n OFFSET 0 0 0\n CHANNELS 1 Zrotation\n}\n"
      "MOTION\nFrames: 4\nFrame Time: 0.1\n170\n-170\n-150\n179\n";
  smgb_clip c = parse_ok(text, 1.0f, 0);
  uint32_t f;
  (void)state;
  for (f = 0; f < 4; ++f) {
    const float* q = c.poses + 7 * f + 3;
    assert_float_equal(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3],
                       1.0f, 1e-6f);
    if (f > 0) {
      const float* p = q - 7;
      assert_true(p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3] >= 0);
    }
  }
  smgb_clip_free(&c);
}

/* Constant non-root position channels become that joint's offset. */
static void test_constant_joint_translation(void** state) {
  static const char text[] =
      "HIERARCHY\r\nROOT R\r\n{\r\n OFFSET 0 0 0\r\n CHANNELS 6 Xposition "
      "Yposition Zposition Xrotation Yrotation Zrotation\r\n JOINT A\r\n {\r\n"
      "  OFFSET 0 1 0\r\n  CHANNELS 6 Xposition Yposition Zposition "
      "Zrotation Xrotation Yrotation\r\n }\r\n}\r\nMOTION\r\nFrames: 2\r\n"
      "Frame Time: 0.1\r\n0 0 0 0 0 0 0.5 2 0 0 0 0\r\n"
      "0 0 0 0 0 0 0.5 2 0 10 0 0\r\n";
  smgb_clip c = parse_ok(text, 1.0f, 0);
  (void)state;
  assert_float_equal(c.skeleton.offsets[1][0], 0.5f, 0.0f);
  assert_float_equal(c.skeleton.offsets[1][1], 2.0f, 0.0f);
  assert_float_equal(c.skeleton.offsets[1][2], 0.0f, 0.0f);
  smgb_clip_free(&c);
}

/* Keywords and channel names are matched case-insensitively (exporters
 * write "End site", "XROTATION", ...). */
static void test_keyword_case(void** state) {
  static const char text[] =
      "hierarchy\nroot R\n{\n offset 0 0 0\n channels 2 YPOSITION "
      "xRotation\n End site\n {\n  OFFSET 0 1 0\n }\n}\nmotion\n"
      "frames: 1\nframe time: 0.5\n1.5 90\n";
  smgb_clip c = parse_ok(text, 1.0f, 0);
  (void)state;
  assert_int_equal(c.skeleton.joint_count, 1);
  assert_float_equal(c.poses[1], 1.5f, 0.0f);
  assert_float_equal(c.poses[3], (float)sqrt(0.5), 1e-6f);
  smgb_clip_free(&c);
}

/* Writer: ZYX channels in metres; load(save(c)) == c. */
static void test_round_trip(void** state) {
  static const char text[] =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 0.1 0.2 0.3\n CHANNELS 6 Xposition "
      "Yposition Zposition Xrotation Zrotation Yrotation\n JOINT LeftUpLeg\n"
      " {\n  OFFSET 0.1 -0.1 0\n  CHANNELS 3 Yrotation Xrotation Zrotation\n"
      "  JOINT LeftLeg\n  {\n   OFFSET 0 -0.4 0.01\n   CHANNELS 3 Xrotation "
      "Zrotation Yrotation\n  }\n }\n JOINT RightUpLeg\n {\n"
      "  OFFSET -0.1 -0.1 0\n  CHANNELS 1 Yrotation\n }\n}\nMOTION\n"
      "Frames: 3\nFrame Time: 0.0333333333\n"
      "0.5 0.9 -2 10 20 30 -40 50 -60 70 80 89.9 12\n"
      "0.6 0.95 -1.9 11 -179 31 -41 51 -61 71 -81 90 13\n"
      "0.7 0.91 -1.8 12 22 33 -44 55 -66 77 88 99 -170\n";
  char dir[256], path[300];
  smgb_clip a = parse_ok(text, 1.0f, 0), b;
  smgb_error err;
  uint32_t j;
  (void)state;
  imp_tempdir(dir, sizeof dir);
  assert_true(dir[0] != '\0');
  snprintf(path, sizeof path, "%s/rt.bvh", dir);
  assert_int_equal(smgb_bvh_save(path, &a, &err), SMG_OK);
  assert_int_equal(smgb_bvh_load(path, 1.0f, 0, &b, &err), SMG_OK);
  assert_string_equal(b.name, "rt.bvh");
  assert_int_equal(b.skeleton.joint_count, a.skeleton.joint_count);
  assert_float_equal(b.frame_rate, 30.0f, 0.0f);
  for (j = 0; j < a.skeleton.joint_count; ++j) {
    assert_string_equal(a.skeleton.names[j], b.skeleton.names[j]);
    assert_int_equal(a.skeleton.parents[j], b.skeleton.parents[j]);
    assert_float_equal(a.skeleton.offsets[j][0], b.skeleton.offsets[j][0], 1e-7f);
    assert_float_equal(a.skeleton.offsets[j][1], b.skeleton.offsets[j][1], 1e-7f);
    assert_float_equal(a.skeleton.offsets[j][2], b.skeleton.offsets[j][2], 1e-7f);
  }
  /* Float quaternions -> double Euler text -> quaternions: ~1e-7. */
  assert_true(imp_rot_diff(&a, &b) < 1e-6);
  assert_true(imp_pose_diff(&a, &b) < 1e-5);
  /* Saving with bad arguments fails cleanly. */
  assert_int_equal(smgb_bvh_save(NULL, &a, &err), SMG_ERROR_INVALID_ARGUMENT);
  snprintf(path, sizeof path, "%s/no/such/dir.bvh", dir);
  assert_int_equal(smgb_bvh_save(path, &a, &err), SMG_ERROR_IO);
  /* Names that are not one BVH token are refused, not written broken. */
  snprintf(a.skeleton.names[1], SMGB_NAME_MAX, "Left Up Leg");
  snprintf(path, sizeof path, "%s/space.bvh", dir);
  assert_int_equal(smgb_bvh_save(path, &a, &err), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "Left Up Leg"));
  smgb_clip_free(&a);
  smgb_clip_free(&b);
  imp_rmdir(dir);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_simple_fk),
      cmocka_unit_test(test_channel_order),
      cmocka_unit_test(test_units_skip_rate),
      cmocka_unit_test(test_hemisphere),
      cmocka_unit_test(test_constant_joint_translation),
      cmocka_unit_test(test_keyword_case),
      cmocka_unit_test(test_round_trip),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
