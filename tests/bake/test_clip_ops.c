/*
 * test_clip_ops.c - clip processing: FK against hand-computed values,
 * mirror(mirror(c)) == c and mirror's geometry, resampling keeps timing,
 * retargeting (errors on mismatched hierarchies, leg-length scaling),
 * grounding, skeleton utilities.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_clip.h"
#include "bake_synthetic.h"
#include "import_helpers.h"

static smgb_clip synth(smgb_synth_kind kind, float turn, float seconds) {
  smgb_synth_params p;
  smgb_clip c;
  memset(&p, 0, sizeof p);
  p.kind = kind;
  p.turn_rate = turn;
  p.duration = seconds;
  p.frame_rate = 60.0f;
  assert_int_equal(smgb_synth_generate(&p, &c, NULL), SMG_OK);
  return c;
}

/* Three-joint chain, hand-computed: root at (0,1,0) rotated 90 deg about
 * Y; joint 1 offset (1,0,0) rotated 90 deg about Z; joint 2 offset (1,0,0).
 * World: R0 = Ry90 maps +X to -Z, so P1 = (0,1,-1); R1 = Ry90*Rz90 maps
 * +X to Ry90(+Y) = +Y, so P2 = (0,2,-1). */
static void test_fk_hand_computed(void** state) {
  char names[3][SMGB_NAME_MAX] = {"a", "b", "c"};
  int32_t parents[3] = {-1, 0, 1};
  float offsets[3][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  const float h = (float)sqrt(0.5);
  float pose[3 + 12] = {0, 1, 0, 0, h, 0, h, 0, 0, h, h, 0, 0, 0, 1};
  float pos[9], rot[12];
  smgb_skeleton s;
  (void)state;
  s.joint_count = 3;
  s.names = names;
  s.parents = parents;
  s.offsets = offsets;
  smgb_fk(&s, pose, pos, rot);
  assert_float_equal(pos[0], 0.0f, 1e-6f);
  assert_float_equal(pos[1], 1.0f, 1e-6f);
  assert_float_equal(pos[2], 0.0f, 1e-6f);
  assert_float_equal(pos[3], 0.0f, 1e-6f);
  assert_float_equal(pos[4], 1.0f, 1e-6f);
  assert_float_equal(pos[5], -1.0f, 1e-6f);
  assert_float_equal(pos[6], 0.0f, 1e-6f);
  assert_float_equal(pos[7], 2.0f, 1e-6f);
  assert_float_equal(pos[8], -1.0f, 1e-6f);
  /* World rotation of joint 2 = Ry90 * Rz90 = (0.5, 0.5, 0.5, 0.5). */
  assert_float_equal(rot[8], 0.5f, 1e-6f);
  assert_float_equal(rot[9], 0.5f, 1e-6f);
  assert_float_equal(rot[10], 0.5f, 1e-6f);
  assert_float_equal(rot[11], 0.5f, 1e-6f);
  /* Positions only (rotations NULL) give the same positions. */
  memset(pos, 0, sizeof pos);
  smgb_fk(&s, pose, pos, NULL);
  assert_float_equal(pos[7], 2.0f, 1e-6f);
}

static void test_mirror_involution_and_geometry(void** state) {
  smgb_clip c = synth(SMGB_SYNTH_WALK, 0.35f, smgt_quick() ? 1.0f : 4.0f);
  smgb_clip m, mm;
  uint32_t J = c.skeleton.joint_count, S = SMGB_STRIDE(J), f, j;
  float* pa = (float*)malloc(sizeof(float) * 3 * J);
  float* pb = (float*)malloc(sizeof(float) * 3 * J);
  int32_t lu = smgb_skeleton_find(&c.skeleton, "LeftUpLeg");
  int32_t ru = smgb_skeleton_find(&c.skeleton, "RightUpLeg");
  int32_t lh = smgb_skeleton_find(&c.skeleton, "LHipJoint");
  int32_t rh = smgb_skeleton_find(&c.skeleton, "RHipJoint");
  int32_t lt = smgb_skeleton_find(&c.skeleton, "LThumb");
  int32_t rt = smgb_skeleton_find(&c.skeleton, "RThumb");
  int32_t lb = smgb_skeleton_find(&c.skeleton, "LowerBack");
  (void)state;
  assert_true(lu >= 0 && ru >= 0 && lh >= 0 && rh >= 0 && lt >= 0 && rt >= 0);
  assert_int_equal(smgb_clip_mirror(&c, &m), SMG_OK);
  assert_int_equal(smgb_clip_mirror(&m, &mm), SMG_OK);
  assert_true(imp_pose_diff(&c, &mm) == 0.0); /* exact */
  for (j = 0; j < J; ++j) {
    assert_string_equal(mm.skeleton.names[j], c.skeleton.names[j]);
    assert_true(memcmp(mm.skeleton.offsets[j], c.skeleton.offsets[j],
                       sizeof(float) * 3) == 0);
  }
  /* Geometry: mirrored world position of a joint = reflected (x -> -x)
   * position of its counterpart; central joints reflect onto themselves. */
  for (f = 0; f < c.frame_count; f += 7) {
    smgb_fk(&c.skeleton, c.poses + (size_t)f * S, pa, NULL);
    smgb_fk(&m.skeleton, m.poses + (size_t)f * S, pb, NULL);
    for (j = 0; j < J; ++j) {
      int32_t k = (int32_t)j;
      const char* n = c.skeleton.names[j];
      char other[SMGB_NAME_MAX];
      if (strncmp(n, "Left", 4) == 0) snprintf(other, sizeof other, "Right%s", n + 4);
      else if (strncmp(n, "Right", 5) == 0) snprintf(other, sizeof other, "Left%s", n + 5);
      else if (n[0] == 'L' && n[1] >= 'A' && n[1] <= 'Z') snprintf(other, sizeof other, "R%s", n + 1);
      else if (n[0] == 'R' && n[1] >= 'A' && n[1] <= 'Z') snprintf(other, sizeof other, "L%s", n + 1);
      else snprintf(other, sizeof other, "%s", n);
      k = smgb_skeleton_find(&c.skeleton, other);
      assert_true(k >= 0);
      assert_float_equal(pb[3 * j + 0], -pa[3 * k + 0], 1e-5f);
      assert_float_equal(pb[3 * j + 1], pa[3 * k + 1], 1e-5f);
      assert_float_equal(pb[3 * j + 2], pa[3 * k + 2], 1e-5f);
    }
  }
  /* LowerBack starts with 'L' but is central. */
  assert_true(lb >= 0);
  assert_float_equal(m.skeleton.offsets[lb][0], -c.skeleton.offsets[lb][0], 0.0f);
  free(pa);
  free(pb);
  smgb_clip_free(&c);
  smgb_clip_free(&m);
  smgb_clip_free(&mm);
}

static void test_resample_timing(void** state) {
  /* 121 frames at 120 Hz = exactly 1 s -> 31 frames at 30 Hz. */
  char names[2][SMGB_NAME_MAX] = {"root", "child"};
  int32_t parents[2] = {-1, 0};
  float offsets[2][3] = {{0, 0, 0}, {0, 1, 0}};
  smgb_clip c, r;
  uint32_t f, S = SMGB_STRIDE(2);
  (void)state;
  memset(&c, 0, sizeof c);
  snprintf(c.name, sizeof c.name, "ramp");
  c.skeleton.joint_count = 2;
  c.skeleton.names = names;
  c.skeleton.parents = parents;
  c.skeleton.offsets = offsets;
  c.frame_count = 121;
  c.frame_rate = 120.0f;
  c.poses = (float*)malloc(sizeof(float) * S * 121);
  for (f = 0; f < 121; ++f) {
    float* p = c.poses + f * S;
    double a = 0.5 * (f / 120.0); /* root yaw: 0.5 rad/s */
    p[0] = (float)(f / 120.0);    /* 1 m/s along x */
    p[1] = 1.0f;
    p[2] = 0.0f;
    p[3] = 0; p[4] = (float)sin(a / 2); p[5] = 0; p[6] = (float)cos(a / 2);
    p[7] = 0; p[8] = 0; p[9] = 0; p[10] = 1;
  }
  assert_int_equal(smgb_clip_resample(&c, 30.0f, &r), SMG_OK);
  assert_int_equal(r.frame_count, 31);
  assert_float_equal(r.frame_rate, 30.0f, 0.0f);
  assert_string_equal(r.name, "ramp");
  for (f = 0; f < 31; ++f) {
    const float* p = r.poses + f * S;
    double t = f / 30.0, a = 0.5 * t;
    assert_float_equal(p[0], t, 1e-6);
    assert_float_equal(p[4], sin(a / 2), 1e-6);
    assert_float_equal(p[6], cos(a / 2), 1e-6);
  }
  smgb_clip_free(&r);
  /* Upsampling to 50 Hz: interpolated values in between. */
  assert_int_equal(smgb_clip_resample(&c, 50.0f, &r), SMG_OK);
  assert_int_equal(r.frame_count, 51);
  for (f = 0; f < 51; ++f) {
    double t = f / 50.0, a = 0.5 * t;
    assert_float_equal(r.poses[f * S], t, 1e-6);
    assert_float_equal(r.poses[f * S + 4], sin(a / 2), 1e-6);
  }
  smgb_clip_free(&r);
  assert_int_equal(smgb_clip_resample(&c, 0.0f, &r), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_clip_resample(NULL, 30.0f, &r), SMG_ERROR_INVALID_ARGUMENT);
  free(c.poses);
}

static void test_retarget(void** state) {
  smgb_clip c = synth(SMGB_SYNTH_WALK, 0.0f, 1.0f), bad;
  smgb_skeleton ref;
  smgb_error err;
  uint32_t J = c.skeleton.joint_count, S = SMGB_STRIDE(J), j;
  float before[3], leg;
  (void)state;
  assert_int_equal(smgb_skeleton_copy(&c.skeleton, &ref), SMG_OK);
  for (j = 0; j < J; ++j) {
    ref.offsets[j][0] *= 1.1f;
    ref.offsets[j][1] *= 1.1f;
    ref.offsets[j][2] *= 1.1f;
  }
  leg = smgb_skeleton_leg_length(&c.skeleton);
  assert_float_equal(leg, 0.84f, 1e-5f);
  memcpy(before, c.poses + 10 * S, sizeof before);
  assert_int_equal(smgb_clip_copy(&c, &bad), SMG_OK);
  assert_int_equal(smgb_clip_retarget(&c, &ref, &err), SMG_OK);
  assert_float_equal(c.poses[10 * S + 0], before[0] * 1.1f, 1e-5f);
  assert_float_equal(c.poses[10 * S + 1], before[1] * 1.1f, 1e-5f);
  assert_float_equal(c.poses[10 * S + 2], before[2] * 1.1f, 1e-5f);
  assert_float_equal(c.skeleton.offsets[3][1], ref.offsets[3][1], 0.0f);
  /* Rotations are kept. */
  assert_float_equal(c.poses[10 * S + 3 + 4 * 3], bad.poses[10 * S + 3 + 4 * 3], 0.0f);
  /* Mismatched names. */
  snprintf(bad.skeleton.names[5], SMGB_NAME_MAX, "LeftToe");
  assert_int_equal(smgb_clip_retarget(&bad, &ref, &err), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "hierarchy mismatch"));
  assert_non_null(strstr(err.message, "LeftToe"));
  /* Mismatched parents. */
  snprintf(bad.skeleton.names[5], SMGB_NAME_MAX, "LeftToeBase");
  bad.skeleton.parents[5] = 2;
  assert_int_equal(smgb_clip_retarget(&bad, &ref, &err), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "parent"));
  bad.skeleton.parents[5] = 4;
  /* Different joint counts. */
  ref.joint_count = 30;
  assert_int_equal(smgb_clip_retarget(&bad, &ref, &err), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "30"));
  ref.joint_count = J;
  smgb_skeleton_free(&ref);
  smgb_clip_free(&bad);
  smgb_clip_free(&c);
}

static void test_ground_and_skeleton_utils(void** state) {
  smgb_clip c = synth(SMGB_SYNTH_WAVE, 0.0f, 1.0f), d;
  uint32_t J = c.skeleton.joint_count, S = SMGB_STRIDE(J), f, j;
  float* pos = (float*)malloc(sizeof(float) * 3 * J);
  double lowest = 1e9;
  char ns[SMGB_NAME_MAX];
  (void)state;
  for (f = 0; f < c.frame_count; ++f) c.poses[f * S + 1] += 0.25f;
  smgb_clip_ground(&c);
  for (f = 0; f < c.frame_count; ++f) {
    smgb_fk(&c.skeleton, c.poses + f * S, pos, NULL);
    for (j = 0; j < J; ++j)
      if (pos[3 * j + 1] < lowest) lowest = pos[3 * j + 1];
  }
  assert_float_equal(lowest, 0.0, 1e-6);
  /* find: exact, then namespace-free; copy is deep. */
  assert_int_equal(smgb_skeleton_find(&c.skeleton, "Hips"), 0);
  assert_int_equal(smgb_skeleton_find(&c.skeleton, "NoSuchJoint"), -1);
  assert_int_equal(smgb_clip_copy(&c, &d), SMG_OK);
  snprintf(ns, sizeof ns, "mixamorig:LeftFoot");
  memcpy(d.skeleton.names[4], ns, sizeof ns);
  assert_int_equal(smgb_skeleton_find(&d.skeleton, "LeftFoot"), 4);
  assert_string_equal(c.skeleton.names[4], "LeftFoot");
  assert_float_equal(smgb_skeleton_leg_length(&d.skeleton), 0.84f, 1e-5f);
  assert_int_equal(smgb_clip_copy(NULL, &d), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_clip_mirror(NULL, &d), SMG_ERROR_INVALID_ARGUMENT);
  smgb_clip_free(&d);
  smgb_clip_free(&d); /* freeing twice is harmless (zeroed) */
  free(pos);
  smgb_clip_free(&c);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_fk_hand_computed),
      cmocka_unit_test(test_mirror_involution_and_geometry),
      cmocka_unit_test(test_resample_timing),
      cmocka_unit_test(test_retarget),
      cmocka_unit_test(test_ground_and_skeleton_utils),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
