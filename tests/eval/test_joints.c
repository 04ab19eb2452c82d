/*
 * test_joints.c - the evaluation finds the joints it measures (pelvis,
 * feet, toes) by body role on any rig (tools/eval/eval_joints.h), not by
 * CMU names:
 *  - the synthetic default graph (CMU names): the same joints as looking
 *    up Hips, LeftFoot, LeftToeBase, RightFoot, RightToeBase by name;
 *  - a graph baked onto a rig with Bandai Namco style names (Toes_L,
 *    Foot_R, UpperLeg_L, ...) and another joint count: the renamed joints,
 *    found although none of the CMU names exists;
 *  - no graph: not found.
 * The rig is the synthetic Mixamo-named rig smg-gen-clips writes, renamed
 * here, so no third-party data is needed.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_joints.h"
#include "smg_bake.h"

/* Mixamo name (without "mixamorig:") -> Bandai Namco style name. */
static const char* const k_rename[][2] = {
    {"LeftUpLeg", "UpperLeg_L"},   {"LeftLeg", "LowerLeg_L"},
    {"LeftFoot", "Foot_L"},        {"LeftToeBase", "Toes_L"},
    {"RightUpLeg", "UpperLeg_R"},  {"RightLeg", "LowerLeg_R"},
    {"RightFoot", "Foot_R"},       {"RightToeBase", "Toes_R"},
    {"LeftShoulder", "Shoulder_L"}, {"LeftArm", "UpperArm_L"},
    {"LeftForeArm", "LowerArm_L"}, {"LeftHand", "Hand_L"},
    {"RightShoulder", "Shoulder_R"}, {"RightArm", "UpperArm_R"},
    {"RightForeArm", "LowerArm_R"}, {"RightHand", "Hand_R"},
};

static const char* joint_name(const smg_graph* g, uint32_t j) {
  static smg_joint_info ji;
  memset(&ji, 0, sizeof(ji));
  ji.struct_size = sizeof(ji);
  if (smg_graph_get_joint(g, j, &ji) != SMG_OK) return "";
  return ji.name;
}

static void test_cmu_names(void** state) {
  char path[1024];
  smg_graph* g = NULL;
  eval_joints j;
  uint32_t want;
  (void)state;
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  assert_int_equal(smg_graph_load_file(path, NULL, &g), SMG_OK);
  assert_int_equal(eval_find_joints(g, &j), 1);
  assert_int_equal(smg_graph_find_joint(g, "Hips", &want), SMG_OK);
  assert_int_equal(j.hips, want);
  assert_int_equal(smg_graph_find_joint(g, "LeftFoot", &want), SMG_OK);
  assert_int_equal(j.lfoot, want);
  assert_int_equal(smg_graph_find_joint(g, "LeftToeBase", &want), SMG_OK);
  assert_int_equal(j.ltoe, want);
  assert_int_equal(smg_graph_find_joint(g, "RightFoot", &want), SMG_OK);
  assert_int_equal(j.rfoot, want);
  assert_int_equal(smg_graph_find_joint(g, "RightToeBase", &want), SMG_OK);
  assert_int_equal(j.rtoe, want);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* Writes the synthetic Mixamo rig with Bandai Namco style names to `out`;
 * 0 on failure. Names are replaced whole ("mixamorig:LeftFoot" followed by
 * a line end), so LeftFoot never matches inside LeftFootXYZ. */
static int write_renamed_rig(const char* in, const char* out) {
  FILE* f = fopen(in, "r");
  FILE* o;
  char line[1024];
  if (!f) return 0;
  o = fopen(out, "w");
  if (!o) {
    fclose(f);
    return 0;
  }
  while (fgets(line, sizeof(line), f)) {
    char* at = strstr(line, "mixamorig:");
    size_t k;
    if (at) {
      char name[256];
      size_t len = strcspn(at + 10, " \t\r\n");
      const char* repl = NULL;
      snprintf(name, sizeof(name), "%.*s", (int)len, at + 10);
      for (k = 0; k < sizeof(k_rename) / sizeof(k_rename[0]); ++k)
        if (!strcmp(name, k_rename[k][0])) repl = k_rename[k][1];
      fprintf(o, "%.*s%s%s", (int)(at - line), line, repl ? repl : name,
              at + 10 + len);
    } else {
      fputs(line, o);
    }
  }
  fclose(f);
  return fclose(o) == 0;
}

static void test_bandai_style_names(void** state) {
  char rig_in[1024], rig[1024], clip[1024];
  smg_bake_clip_desc c;
  smg_bake_desc d;
  smg_bake_result res;
  smg_graph* g = NULL;
  void* blob = NULL;
  eval_joints j;
  uint32_t unused;
  (void)state;
  snprintf(rig_in, sizeof rig_in, "%s/synthetic/rig_mixamo_apose.bvh",
           SMG_BUILD_DIR);
  snprintf(rig, sizeof rig, "%s/tests/eval/rig_bandai_names.bvh",
           SMG_BUILD_DIR);
  snprintf(clip, sizeof clip, "%s/synthetic/synthetic_walk_straight.bvh",
           SMG_BUILD_DIR);
  assert_true(write_renamed_rig(rig_in, rig));

  memset(&c, 0, sizeof(c));
  c.struct_size = sizeof(c);
  c.path = clip;
  c.name = "walk";
  c.label = "walk";
  c.role = SMG_BAKE_ROLE_LOWER;
  memset(&d, 0, sizeof(d));
  d.struct_size = sizeof(d);
  d.clip_count = 1;
  d.clips = &c;
  d.target_path = rig;
  memset(&res, 0, sizeof(res));
  res.struct_size = sizeof(res);
  assert_int_equal(smg_bake_run(&d, &res), SMG_OK);
  assert_int_equal(posix_memalign(&blob, 16, res.blob_size), 0);
  memcpy(blob, res.blob, res.blob_size);
  assert_int_equal(smg_graph_load_memory(blob, res.blob_size, NULL, &g),
                   SMG_OK);
  assert_int_not_equal(smg_graph_find_joint(g, "LeftToeBase", &unused),
                       SMG_OK);
  assert_int_equal(eval_find_joints(g, &j), 1);
  assert_string_equal(joint_name(g, j.hips), "Hips");
  assert_string_equal(joint_name(g, j.lfoot), "Foot_L");
  assert_string_equal(joint_name(g, j.ltoe), "Toes_L");
  assert_string_equal(joint_name(g, j.rfoot), "Foot_R");
  assert_string_equal(joint_name(g, j.rtoe), "Toes_R");
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
  free(blob);
  smg_bake_result_free(&res);
  remove(rig);
}

static void test_no_graph(void** state) {
  eval_joints j;
  (void)state;
  assert_int_equal(eval_find_joints(NULL, &j), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cmu_names),
      cmocka_unit_test(test_bandai_style_names),
      cmocka_unit_test(test_no_graph),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
