/*
 * test_synth.c - smg-synth end to end: run the CLI on build/default.smg
 * with a path file and constraints, read its BVH back with the baker's
 * BVH parser (same skeleton, frame count, metres) and check the BVH root
 * track against the CSV the CLI wrote and the joint rotations against a
 * character driven through the API with the same inputs. Also checks the
 * CLI's error exits for bad input.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>

#include <cmocka.h>

#include "bake_clip.h"
#include "cli_testutil.h"
#include "runtime/runtime_testutil.h"

static char dir[512];

static int setup(void** state) {
  (void)state;
  return smgt_scratch_dir("test_synth", "runtime/synth", dir, sizeof dir);
}

static int teardown(void** state) {
  (void)state;
  smgt_run("rm -rf '%s'", dir);
  return 0;
}

static void test_bvh_round_trip(void** state) {
  (void)state;
  char path[600], bvh[600], csv[600];
  snprintf(path, sizeof path, "%s/path.txt", dir);
  snprintf(bvh, sizeof bvh, "%s/out.bvh", dir);
  snprintf(csv, sizeof csv, "%s/out.csv", dir);
  FILE* f = fopen(path, "w");
  assert_non_null(f);
  fprintf(f, "# a drawn path\n0 0\n0 4\n\n1.5 7  # comment\n5 8\n9 8\n");
  fclose(f);
  float seconds = smgt_quick() ? 2.0f : 6.0f;
  assert_int_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                           "--splice 2:punch --transition 6:run --seconds "
                           "%.1f --fps 30 --seed 3 --csv '%s' -o '%s' "
                           ">/dev/null",
                           SMG_BUILD_DIR, SMG_BUILD_DIR, path, seconds, csv,
                           bvh),
                   0);
  smgb_clip clip;
  smgb_error err;
  memset(&clip, 0, sizeof clip);
  assert_int_equal(smgb_bvh_load(bvh, 1.0f, 0, &clip, &err), SMG_OK);
  uint32_t frames = (uint32_t)(seconds * 30.0f + 0.5f);
  assert_int_equal(clip.frame_count, frames);
  assert_int_equal(clip.skeleton.joint_count, 31);
  assert_float_equal(clip.frame_rate, 30.0f, 0.01f);

  /* the same run through the API */
  smg_graph* g = rt_default_graph();
  assert_non_null(g);
  uint32_t punch, run;
  assert_int_equal(smg_graph_find_action(g, "punch", &punch), SMG_OK);
  assert_int_equal(smg_graph_find_style(g, "run", &run), SMG_OK);
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = 3;
  d.path_capacity = 5;
  d.constraint_capacity = 2;
  d.heading = atan2f(0.0f, 4.0f);
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  float xz[10] = {0, 0, 0, 4, 1.5f, 7, 5, 8, 9, 8};
  assert_int_equal(smg_character_set_path(ch, xz, 5), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 2.0f, punch, NULL), SMG_OK);
  assert_int_equal(smg_character_add_transition(ch, 6.0f, run, NULL), SMG_OK);
  FILE* c = fopen(csv, "r");
  assert_non_null(c);
  char line[1024];
  assert_non_null(fgets(line, sizeof line, c)); /* header */
  const uint32_t stride = 3 + 4 * 31;
  float max_root = 0, max_rot = 0;
  for (uint32_t i = 0; i < frames; ++i) {
    if (i > 0) assert_int_equal(smg_character_step(ch, 1.0f / 30.0f), SMG_OK);
    float root[3], rot[4 * 31];
    smg_character_get_local_pose(ch, root, rot, 31);
    const float* p = clip.poses + (size_t)i * stride;
    for (int k = 0; k < 3; ++k) {
      float dd = fabsf(p[k] - root[k]);
      if (dd > max_root) max_root = dd;
    }
    for (uint32_t j = 0; j < 31; ++j) {
      /* same rotation up to sign (BVH goes through Euler angles) */
      const float* a = p + 3 + 4 * j;
      const float* b = rot + 4 * j;
      float dot = fabsf(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
      if (1.0f - dot > max_rot) max_rot = 1.0f - dot;
    }
    long fi;
    double t, rx, ry, rz;
    assert_non_null(fgets(line, sizeof line, c));
    assert_int_equal(sscanf(line, "%ld,%lf,%lf,%lf,%lf", &fi, &t, &rx, &ry,
                            &rz),
                     5);
    assert_int_equal(fi, (long)i);
    assert_float_equal(rx, p[0], 1e-3);
    assert_float_equal(ry, p[1], 1e-3);
    assert_float_equal(rz, p[2], 1e-3);
  }
  fclose(c);
  print_message("BVH vs API: root %.2g m, rotation 1-|dot| %.2g over %u "
                "frames\n",
                max_root, max_rot, frames);
  assert_true(max_root < 1e-3f);
  assert_true(max_rot < 1e-5f);
  smg_character_destroy(ch);
  smg_graph_destroy(g);
  smgb_clip_free(&clip);
}

static void test_cli_errors(void** state) {
  (void)state;
  char path[600], bvh[600];
  snprintf(path, sizeof path, "%s/bad.txt", dir);
  snprintf(bvh, sizeof bvh, "%s/bad.bvh", dir);
  FILE* f = fopen(path, "w");
  assert_non_null(f);
  fprintf(f, "0 0\n0 nan\n");
  fclose(f);
  const char* q = ">/dev/null 2>&1";
  /* no arguments, unknown option, bad path file, bad constraint, unknown
   * style, missing blob */
  assert_int_not_equal(smgt_run("'%s/smg-synth' %s", SMG_BUILD_DIR, q), 0);
  assert_int_not_equal(smgt_run("'%s/smg-synth' --bogus %s", SMG_BUILD_DIR, q),
                       0);
  assert_int_not_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                               "-o '%s' %s",
                               SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, q),
                       0);
  f = fopen(path, "w");
  fprintf(f, "0 0\n0 5\n");
  fclose(f);
  assert_int_not_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                               "--splice x:punch -o '%s' %s",
                               SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, q),
                       0);
  assert_int_not_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                               "--transition 1:fly -o '%s' %s",
                               SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, q),
                       0);
  assert_int_not_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                               "--transition 9:run -o '%s' %s",
                               SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, q),
                       0); /* beyond the 5 m path */
  assert_int_not_equal(smgt_run("'%s/smg-synth' -g '%s/nope.smg' -p '%s' "
                               "-o '%s' %s",
                               SMG_BUILD_DIR, dir, path, bvh, q),
                       0);
  assert_int_equal(smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' "
                           "--seconds 0.5 -o '%s' %s",
                           SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, q),
                   0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bvh_round_trip),
      cmocka_unit_test(test_cli_errors),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
