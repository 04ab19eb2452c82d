/*
 * test_synthetic.c - the procedural SYNTHETIC clips honour their ground
 * truth: planted feet do not move (foot speed ~0 in contact frames), the
 * root travels at the stated speed and turn rate, footprints are one step
 * length apart along the path, generation is deterministic, and the files
 * smg-gen-clips writes load back as the same clips.
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

static void gen(uint32_t index, smgb_clip* c, smgb_synth_truth* t) {
  smgb_synth_params p;
  assert_int_equal(smgb_synth_standard(index, &p, NULL, NULL, NULL), SMG_OK);
  if (smgt_quick()) p.duration = 2.0f;
  assert_int_equal(smgb_synth_generate(&p, c, t), SMG_OK);
}

/* Planted feet stay put; ankles rest at the stated height; swing feet
 * actually move (so the test could fail). */
static void test_feet_planted(void** state) {
  uint32_t i;
  (void)state;
  for (i = 0; i < SMGB_SYNTH_STANDARD_COUNT; ++i) {
    smgb_clip c;
    smgb_synth_truth t;
    uint32_t S, f, J;
    float pos[93], prev[93];
    double max_contact_speed = 0.0, max_swing_speed = 0.0;
    int contact_frames = 0;
    gen(i, &c, &t);
    J = c.skeleton.joint_count;
    assert_int_equal(J, 31);
    S = SMGB_STRIDE(J);
    for (f = 0; f < c.frame_count; ++f) {
      int foot;
      smgb_fk(&c.skeleton, c.poses + (size_t)f * S, pos, NULL);
      for (foot = 0; foot < 2 && f > 0; ++foot) {
        uint32_t j = foot ? t.right_foot : t.left_foot;
        double t0 = (f - 1) / c.frame_rate, t1 = f / c.frame_rate;
        double dx = pos[3 * j] - prev[3 * j], dy = pos[3 * j + 1] - prev[3 * j + 1];
        double dz = pos[3 * j + 2] - prev[3 * j + 2];
        double speed = sqrt(dx * dx + dy * dy + dz * dz) * c.frame_rate;
        if (smgb_synth_foot_planted(&t, foot, t0) &&
            smgb_synth_foot_planted(&t, foot, t1)) {
          contact_frames++;
          if (speed > max_contact_speed) max_contact_speed = speed;
          assert_float_equal(pos[3 * j + 1], t.ankle_height, 1e-5);
        } else if (speed > max_swing_speed) {
          max_swing_speed = speed;
        }
      }
      memcpy(prev, pos, sizeof pos);
    }
    assert_true(contact_frames > 0);
    assert_true(max_contact_speed < 1e-3); /* < 1 mm/s: truly planted */
    if (t.speed > 0.0f) assert_true(max_swing_speed > 0.5 * t.speed);
    smgb_clip_free(&c);
  }
}

/* Speed, turn rate and step length against the truth. */
static void test_speed_turn_step(void** state) {
  uint32_t i;
  (void)state;
  for (i = 0; i < SMGB_SYNTH_STANDARD_COUNT; ++i) {
    smgb_clip c;
    smgb_synth_truth t;
    uint32_t S, f, n, cycle;
    double disp, expect, yaw0, yaw1, secs;
    float pos[93];
    int foot;
    gen(i, &c, &t);
    S = SMGB_STRIDE(31);
    if (t.speed == 0.0f) {
      /* Standing: the root stays within a few centimetres. */
      for (f = 0; f < c.frame_count; ++f)
        assert_true(hypot(c.poses[f * S], c.poses[f * S + 2]) < 0.05);
      smgb_clip_free(&c);
      continue;
    }
    /* Over whole gait cycles the sway cancels: chord of the path arc. */
    cycle = (uint32_t)floor(t.stride_period * c.frame_rate + 0.5);
    assert_float_equal(cycle / c.frame_rate, t.stride_period, 1e-6);
    n = (c.frame_count - 1) / cycle * cycle;
    secs = n / c.frame_rate;
    disp = hypot(c.poses[n * S] - c.poses[0], c.poses[n * S + 2] - c.poses[2]);
    if (fabsf(t.turn_rate) < 1e-6f)
      expect = t.speed * secs;
    else
      expect = 2.0 * t.speed / fabs(t.turn_rate) * sin(0.5 * fabs(t.turn_rate) * secs);
    assert_float_equal(disp, expect, 1e-4);
    /* Heading change over whole cycles: root yaw (oscillation cancels). */
    {
      const float* q0 = c.poses + 3;
      const float* q1 = c.poses + (size_t)n * S + 3;
      yaw0 = atan2(2.0 * (q0[3] * q0[1] + q0[0] * q0[2]),
                   1.0 - 2.0 * (q0[0] * q0[0] + q0[1] * q0[1]));
      yaw1 = atan2(2.0 * (q1[3] * q1[1] + q1[0] * q1[2]),
                   1.0 - 2.0 * (q1[0] * q1[0] + q1[1] * q1[1]));
      expect = remainder(t.turn_rate * secs, 2.0 * 3.14159265358979);
      assert_float_equal(remainder(yaw1 - yaw0, 2.0 * 3.14159265358979), expect, 1e-4);
    }
    /* Step length: consecutive left/right footprints (mid-stance ankle
     * positions) projected on the straight path are step_length apart. */
    if (fabsf(t.turn_rate) < 1e-6f) {
      double z[2];
      for (foot = 0; foot < 2; ++foot) {
        double tm = (foot ? 0.5 : 0.0) * t.stride_period +
                    0.5 * t.duty_factor * t.stride_period;
        uint32_t fm = (uint32_t)floor(tm * c.frame_rate + 0.5);
        uint32_t j = foot ? t.right_foot : t.left_foot;
        assert_true(smgb_synth_foot_planted(&t, foot, fm / c.frame_rate));
        smgb_fk(&c.skeleton, c.poses + (size_t)fm * S, pos, NULL);
        z[foot] = pos[3 * j + 2];
        assert_float_equal(fabs(pos[3 * j]), t.foot_width, 1e-4);
      }
      assert_float_equal(z[1] - z[0], t.step_length, 1e-4);
    }
    smgb_clip_free(&c);
  }
}

static void test_deterministic_and_files(void** state) {
  char dir[256], path[400];
  smgb_error err;
  uint32_t i;
  (void)state;
  imp_tempdir(dir, sizeof dir);
  assert_true(dir[0] != '\0');
  if (smgt_quick()) {
    /* Valgrind: formatting ~1 MB of BVH text is slow there; round-trip one
     * short clip instead of the whole set. */
    smgb_synth_params p;
    smgb_clip a, b;
    assert_int_equal(smgb_synth_standard(4, &p, NULL, NULL, NULL), SMG_OK);
    p.duration = 1.0f;
    assert_int_equal(smgb_synth_generate(&p, &a, NULL), SMG_OK);
    snprintf(path, sizeof path, "%s/short.bvh", dir);
    assert_int_equal(smgb_bvh_save(path, &a, &err), SMG_OK);
    assert_int_equal(smgb_bvh_load(path, 1.0f, 0, &b, &err), SMG_OK);
    assert_true(imp_rot_diff(&a, &b) < 1e-5);
    smgb_clip_free(&a);
    smgb_clip_free(&b);
    imp_rmdir(dir);
    return;
  }
  assert_int_equal(smgb_synth_write_all(dir, &err), SMG_OK);
  snprintf(path, sizeof path, "%s/README.txt", dir);
  {
    FILE* fp = fopen(path, "r");
    char buf[64] = {0};
    assert_non_null(fp);
    assert_true(fread(buf, 1, sizeof buf - 1, fp) > 0);
    fclose(fp);
    assert_non_null(strstr(buf, "SYNTHETIC"));
  }
  for (i = 0; i < SMGB_SYNTH_STANDARD_COUNT; ++i) {
    smgb_synth_params p;
    const char* file;
    const char* label;
    int lower;
    smgb_clip a, b, fromfile;
    assert_int_equal(smgb_synth_standard(i, &p, &file, &label, &lower), SMG_OK);
    assert_non_null(strstr(file, "synthetic_"));
    assert_int_equal(lower, i < 6);
    assert_int_equal(smgb_synth_generate(&p, &a, NULL), SMG_OK);
    assert_int_equal(smgb_synth_generate(&p, &b, NULL), SMG_OK);
    assert_true(imp_pose_diff(&a, &b) == 0.0);
    snprintf(path, sizeof path, "%s/%s", dir, file);
    if (smgb_bvh_load(path, 1.0f, 0, &fromfile, &err) != SMG_OK)
      fail_msg("%s", err.message);
    assert_int_equal(fromfile.frame_count, a.frame_count);
    assert_float_equal(fromfile.frame_rate, 60.0f, 0.0f);
    assert_true(imp_rot_diff(&a, &fromfile) < 1e-5);
    smgb_clip_free(&a);
    smgb_clip_free(&b);
    smgb_clip_free(&fromfile);
  }
  assert_int_equal(smgb_synth_standard(SMGB_SYNTH_STANDARD_COUNT, NULL, NULL,
                                       NULL, NULL),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smgb_synth_write_all("/nonexistent/folder", &err), SMG_ERROR_IO);
  imp_rmdir(dir);
}

static void test_bad_params(void** state) {
  smgb_synth_params p;
  smgb_clip c;
  (void)state;
  memset(&p, 0, sizeof p);
  p.kind = (smgb_synth_kind)7;
  assert_int_equal(smgb_synth_generate(&p, &c, NULL), SMG_ERROR_INVALID_ARGUMENT);
  p.kind = SMGB_SYNTH_WALK;
  p.duration = -1.0f;
  assert_int_equal(smgb_synth_generate(&p, &c, NULL), SMG_ERROR_INVALID_ARGUMENT);
  p.duration = 1.0f;
  p.turn_rate = NAN;
  assert_int_equal(smgb_synth_generate(&p, &c, NULL), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_synth_generate(NULL, &c, NULL), SMG_ERROR_INVALID_ARGUMENT);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_feet_planted),
      cmocka_unit_test(test_speed_turn_step),
      cmocka_unit_test(test_deterministic_and_files),
      cmocka_unit_test(test_bad_params),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
