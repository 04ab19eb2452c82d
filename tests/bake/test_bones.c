/*
 * test_bones.c - naming body roles for skeletons no convention covers:
 * the manifest `bones` statement (parsed into each following clip's bone
 * map, cleared with `bones none`, errors at the manifest line), and whole
 * bakes through smg-bake: a skeleton without recognisable legs and a bone
 * map naming a missing joint fail with the file and the role or joint in
 * the message and write no blob; the same skeleton with a correct map
 * bakes. The clips are synthetic walks with every joint renamed, written
 * here. Skips the smg-bake part when build/smg-bake has not been built.
 * Through the C API: a malformed smg_bake_clip_desc.bones fails first,
 * naming the clip.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bake_graph_helpers.h"
#include "bake_manifest.h"
#include "import_helpers.h"

#ifndef SMG_BUILD_DIR
#define SMG_BUILD_DIR "build"
#endif

/* The roles a bake needs, as the synthetic (CMU-named) skeleton has them,
 * mapped to the renamed joints "bone<index>". */
static const char* const k_roles[][2] = {
    {"neck", "Neck"},           {"head", "Head"},
    {"left_upper_leg", "LeftUpLeg"},  {"left_lower_leg", "LeftLeg"},
    {"left_foot", "LeftFoot"},        {"left_toes", "LeftToeBase"},
    {"right_upper_leg", "RightUpLeg"}, {"right_lower_leg", "RightLeg"},
    {"right_foot", "RightFoot"},       {"right_toes", "RightToeBase"},
    {"left_upper_arm", "LeftArm"},     {"left_lower_arm", "LeftForeArm"},
    {"left_hand", "LeftHand"},         {"right_upper_arm", "RightArm"},
    {"right_lower_arm", "RightForeArm"}, {"right_hand", "RightHand"}};
#define N_ROLES (sizeof k_roles / sizeof k_roles[0])

/* A synthetic clip with every joint renamed to bone<index>; returns the
 * index of each role's joint in `idx`. */
static void write_renamed(const char* path, smgb_synth_kind kind,
                          int idx[N_ROLES]) {
  smgb_synth_params p;
  smgb_clip c;
  smgb_error err;
  uint32_t j;
  size_t r;
  memset(&p, 0, sizeof p);
  p.kind = kind;
  p.duration = 3.0f;
  p.frame_rate = 30.0f;
  assert_int_equal(smgb_synth_generate(&p, &c, NULL), SMG_OK);
  for (r = 0; r < N_ROLES; ++r) {
    idx[r] = smgb_skeleton_find(&c.skeleton, k_roles[r][1]);
    assert_true(idx[r] >= 0);
  }
  for (j = 0; j < c.skeleton.joint_count; ++j)
    snprintf(c.skeleton.names[j], SMGB_NAME_MAX, "bone%u", j);
  if (smgb_bvh_save(path, &c, &err) != SMG_OK) fail_msg("%s", err.message);
  smgb_clip_free(&c);
}

/* The manifest statement: accumulates, applies to the clips that follow,
 * `bones none` clears; errors name the line. */
static void test_bones_statement(void** state) {
  char dir[64], clip[128], man[128], text[1024];
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc d[3];
  (void)state;
  imp_tempdir(dir, sizeof dir);
  snprintf(clip, sizeof clip, "%s/a.bvh", dir);
  assert_true(imp_write_file(clip, "x"));
  snprintf(man, sizeof man, "%s/m.manifest", dir);
  assert_true(imp_write_file(man,
                             "lower walk a.bvh\n"
                             "bones left_foot=Foot_L \"right_foot=Foot R\"\n"
                             "bones left_foot=Ankle_L\n"
                             "lower walk a.bvh\n"
                             "bones none\n"
                             "upper wave a.bvh\n"));
  if (smgb_manifest_load(man, NULL, &m, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_int_equal(m.clip_count, 3);
  assert_int_equal(smgb_manifest_descs(&m, d, 3), SMG_OK);
  assert_null(d[0].bones);
  assert_non_null(d[1].bones);
  assert_string_equal(d[1].bones, "left_foot=Ankle_L\nright_foot=Foot R\n");
  assert_null(d[2].bones);
  smgb_manifest_free(&m);

  snprintf(text, sizeof text, "lower walk a.bvh\nbones left_paw=X\n");
  assert_true(imp_write_file(man, text));
  assert_int_equal(smgb_manifest_load(man, NULL, &m, &err), SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "m.manifest:2:"));
  assert_non_null(strstr(err.message, "left_paw"));
  assert_true(imp_write_file(man, "lower walk a.bvh\nbones left_foot\n"));
  assert_int_equal(smgb_manifest_load(man, NULL, &m, &err), SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "m.manifest:2:"));
  assert_true(imp_write_file(man, "lower walk a.bvh\nbones\n"));
  assert_int_equal(smgb_manifest_load(man, NULL, &m, &err), SMG_ERROR_PARSE);
  imp_rmdir(dir);
}

static int run_bake(const char* tool, const char* dir, const char* manifest,
                    const char* out, char* log, size_t log_size) {
  char cmd[2048], path[256];
  FILE* fp;
  size_t n;
  int st;
  snprintf(cmd, sizeof cmd, "'%s' -q -m '%s/%s' -o '%s/%s' > '%s/log.txt' 2>&1",
           tool, dir, manifest, dir, out, dir);
  st = system(cmd);
  snprintf(path, sizeof path, "%s/log.txt", dir);
  fp = fopen(path, "rb");
  assert_non_null(fp);
  n = fread(log, 1, log_size - 1, fp);
  log[n] = '\0';
  fclose(fp);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int exists(const char* dir, const char* name) {
  char path[256];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return access(path, F_OK) == 0;
}

static void test_bake_with_bone_map(void** state) {
  char dir[64], tool[1024], path[256], log[4096], map[2048];
  int walk_idx[N_ROLES], punch_idx[N_ROLES];
  size_t r, used = 0;
  (void)state;
  snprintf(tool, sizeof tool, "%s/smg-bake", SMG_BUILD_DIR);
  if (access(tool, X_OK) != 0) {
    printf("SKIP: %s not built\n", tool);
    skip();
    return;
  }
  imp_tempdir(dir, sizeof dir);
  snprintf(path, sizeof path, "%s/walk.bvh", dir);
  write_renamed(path, SMGB_SYNTH_WALK, walk_idx);
  snprintf(path, sizeof path, "%s/punch.bvh", dir);
  write_renamed(path, SMGB_SYNTH_PUNCH, punch_idx);
  for (r = 0; r < N_ROLES; ++r) assert_int_equal(walk_idx[r], punch_idx[r]);
  used = (size_t)snprintf(map, sizeof map, "bones");
  for (r = 0; r < N_ROLES; ++r)
    used += (size_t)snprintf(map + used, sizeof map - used, " %s=bone%d",
                             k_roles[r][0], walk_idx[r]);
  assert_true(used < sizeof map);

  /* No map: nothing is recognisable; the file and a role are named. */
  snprintf(path, sizeof path, "%s/plain.manifest", dir);
  assert_true(imp_write_file(path, "unit 1\nlower walk walk.bvh\n"
                                   "upper punch punch.bvh\n"));
  assert_int_not_equal(run_bake(tool, dir, "plain.manifest", "a.smg", log,
                                sizeof log), 0);
  if (!strstr(log, "walk.bvh") || !strstr(log, "no joint for the body role"))
    fail_msg("unexpected message: %s", log);
  assert_false(exists(dir, "a.smg"));

  /* A map naming a joint the skeleton lacks. */
  snprintf(path, sizeof path, "%s/missing.manifest", dir);
  assert_true(imp_write_file(path, "unit 1\nbones left_foot=Ankle_L\n"
                                   "lower walk walk.bvh\n"
                                   "upper punch punch.bvh\n"));
  assert_int_not_equal(run_bake(tool, dir, "missing.manifest", "b.smg", log,
                                sizeof log), 0);
  if (!strstr(log, "walk.bvh") || !strstr(log, "'Ankle_L'") ||
      !strstr(log, "left_foot"))
    fail_msg("unexpected message: %s", log);
  assert_false(exists(dir, "b.smg"));

  /* The full map (over two lines: a manifest line has at most 16 words)
   * bakes. */
  {
    char text[4096];
    size_t half = 0, k;
    /* Cut the statement after the ninth pair. */
    for (k = 0; map[half] && k < 10; ++half)
      if (map[half] == ' ') ++k;
    snprintf(text, sizeof text, "unit 1\n%.*s\nbones %s\nlower walk walk.bvh\n"
             "upper punch punch.bvh\n", (int)half - 1, map, map + half);
    snprintf(path, sizeof path, "%s/mapped.manifest", dir);
    assert_true(imp_write_file(path, text));
  }
  if (run_bake(tool, dir, "mapped.manifest", "c.smg", log, sizeof log) != 0)
    fail_msg("bake with a bone map failed: %s", log);
  assert_true(exists(dir, "c.smg"));
  imp_rmdir(dir);
}

/* smg_bake_clip_desc.bones is checked before anything is loaded: the
 * clip and the bad entry are named; a good map on recognisable names
 * bakes (the map wins over the names it repeats). */
static void test_desc_bone_map(void** state) {
  bg_set set;
  smg_bake_result res;
  (void)state;
  memset(&set, 0, sizeof set);
  bg_add(&set, SMGB_SYNTH_WALK, 2.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(&set, SMGB_SYNTH_PUNCH, 2.0f, 0.0f, SMG_BAKE_ROLE_UPPER, "punch");
  set.descs[1].bones = "left_foot=LeftFoot\nleft_paw=LeftHand";
  assert_int_equal(bg_bake(&set, NULL, &res), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(res.error, "clip 2"));
  assert_non_null(strstr(res.error, "left_paw"));
  assert_null(res.blob);
  smg_bake_result_free(&res);
  set.descs[1].bones = "left_foot";
  assert_int_equal(bg_bake(&set, NULL, &res), SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(res.error, "ROLE=JOINT"));
  smg_bake_result_free(&res);
  set.descs[0].bones = "left_foot=LeftFoot\nright_foot=RightFoot";
  set.descs[1].bones = NULL;
  if (bg_bake(&set, NULL, &res) != SMG_OK) fail_msg("%s", res.error);
  assert_non_null(res.blob);
  smg_bake_result_free(&res);
  bg_free(&set);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bones_statement),
      cmocka_unit_test(test_bake_with_bone_map),
      cmocka_unit_test(test_desc_bone_map),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
