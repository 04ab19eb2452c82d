/*
 * test_bvh_cmu.c - the real CMU clips in ../shared/mocap/cmu all parse:
 * 31 joints in the documented order, frame counts from the README minus
 * the skipped T-pose, 120 Hz, metres (hips 0.85-1.05 m, floor near 0).
 * Skips with a message when ../shared is absent. Under SMG_TEST_QUICK only
 * the small clips are read.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_clip.h"
#include "import_helpers.h"

typedef struct cmu_file {
  const char* name;
  uint32_t frames; /* including the T-pose frame (README table) */
} cmu_file;

static const cmu_file k_files[] = {
    {"09_12.bvh", 1919}, {"09_01.bvh", 149}, {"09_02.bvh", 131},
    {"09_03.bvh", 129},  {"09_04.bvh", 138}, {"09_05.bvh", 144},
    {"09_06.bvh", 142},  {"09_07.bvh", 139}, {"09_08.bvh", 129},
    {"09_09.bvh", 153},  {"09_11.bvh", 166}, {"02_01.bvh", 344},
    {"02_02.bvh", 299},  {"02_03.bvh", 174}, {"06_01.bvh", 495},
    {"02_05.bvh", 1855}, {"02_06.bvh", 2236}, {"02_10.bvh", 2646},
    {"06_14.bvh", 480},  {"06_06.bvh", 403}, {"06_10.bvh", 1114}};

static const char* const k_order[31] = {
    "Hips", "LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase",
    "RHipJoint", "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase",
    "LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head", "LeftShoulder",
    "LeftArm", "LeftForeArm", "LeftHand", "LeftFingerBase", "LeftHandIndex1",
    "LThumb", "RightShoulder", "RightArm", "RightForeArm", "RightHand",
    "RightFingerBase", "RightHandIndex1", "RThumb"};

static void test_all_clips(void** state) {
  const char* dir = smgt_cmu_dir();
  size_t i;
  (void)state;
  if (!dir) {
    skip();
    return;
  }
  for (i = 0; i < sizeof k_files / sizeof k_files[0]; ++i) {
    char path[1200];
    smgb_clip c, raw;
    smgb_error err;
    uint32_t j, f, S;
    float pos[93];
    double lowest = 1e9, q;
    if (smgt_quick() && k_files[i].frames > 200) continue;
    snprintf(path, sizeof path, "%s/%s", dir, k_files[i].name);
    if (smgb_bvh_load(path, 0.056444f, 1, &c, &err) != SMG_OK)
      fail_msg("%s", err.message);
    assert_string_equal(c.name, k_files[i].name);
    assert_int_equal(c.skeleton.joint_count, 31);
    for (j = 0; j < 31; ++j) assert_string_equal(c.skeleton.names[j], k_order[j]);
    assert_int_equal(c.frame_count, k_files[i].frames - 1);
    assert_float_equal(c.frame_rate, 120.0f, 0.0f);
    /* Hips 0.85-1.05 m in the first motion frame; floor within ~5 cm. */
    assert_true(c.poses[1] > 0.85f && c.poses[1] < 1.05f);
    S = SMGB_STRIDE(31);
    for (f = 0; f < c.frame_count; f += 4) {
      smgb_fk(&c.skeleton, c.poses + (size_t)f * S, pos, NULL);
      for (j = 0; j < 31; ++j)
        if (pos[3 * j + 1] < lowest) lowest = pos[3 * j + 1];
      for (j = 0; j < 31; ++j) {
        const float* r = c.poses + (size_t)f * S + 3 + 4 * j;
        q = r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
        assert_float_equal(q, 1.0, 1e-5);
      }
    }
    assert_true(lowest > -0.05 && lowest < 0.06);
    /* The guessed unit is CMU's, and without skipping frame 0 is the
     * T-pose: LeftUpLeg Z = -21 degrees, everything else near zero. */
    if (smgb_bvh_load(path, 0.0f, 0, &raw, &err) != SMG_OK)
      fail_msg("%s", err.message);
    assert_int_equal(raw.frame_count, k_files[i].frames);
    assert_float_equal(raw.poses[S + 1], c.poses[1], 1e-6f);
    assert_float_equal(raw.poses[3 + 4 * 2 + 2], -sin(21.0 * 3.14159265358979 / 360.0), 1e-5);
    assert_float_equal(raw.poses[3 + 4 * 2 + 3], cos(21.0 * 3.14159265358979 / 360.0), 1e-5);
    smgb_clip_free(&raw);
    smgb_clip_free(&c);
  }
}

/* Subjects differ in bone lengths: leg lengths of subjects 02 and 09. */
static void test_subject_legs(void** state) {
  const char* dir = smgt_cmu_dir();
  char path[1200];
  smgb_clip a, b;
  smgb_error err;
  float la, lb;
  (void)state;
  if (!dir) {
    skip();
    return;
  }
  snprintf(path, sizeof path, "%s/02_03.bvh", dir);
  assert_int_equal(smgb_bvh_load(path, 0.056444f, 1, &a, &err), SMG_OK);
  snprintf(path, sizeof path, "%s/09_01.bvh", dir);
  assert_int_equal(smgb_bvh_load(path, 0.056444f, 1, &b, &err), SMG_OK);
  la = smgb_skeleton_leg_length(&a.skeleton);
  lb = smgb_skeleton_leg_length(&b.skeleton);
  /* README: thigh + shank 14.0-15.3 units = 0.79-0.86 m. */
  assert_true(la > 0.78f && la < 0.87f);
  assert_true(lb > 0.78f && lb < 0.87f);
  assert_true(fabsf(la - lb) > 1e-3f);
  assert_int_equal(smgb_clip_retarget(&a, &b.skeleton, &err), SMG_OK);
  assert_float_equal(smgb_skeleton_leg_length(&a.skeleton), lb, 1e-6f);
  smgb_clip_free(&a);
  smgb_clip_free(&b);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_all_clips),
      cmocka_unit_test(test_subject_legs),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
