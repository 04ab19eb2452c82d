/*
 * test_manifest.c - the manifest format (docs/manifest.md): settings and
 * per-clip options, path resolution (root relative to the manifest, the
 * --data-dir override), frame ranges, every parse error naming file:line,
 * missing clip files, conversion to smg_bake_clip_desc, folder patterns
 * with label templates, and the project's own data/ manifest files.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <sys/stat.h>

#include "bake_manifest.h"
#include "bake_synthetic.h"
#include "import_helpers.h"

static char g_dir[256];

static int setup(void** state) {
  char sub[400], path[500];
  (void)state;
  imp_tempdir(g_dir, sizeof g_dir);
  if (!g_dir[0]) return -1;
  snprintf(sub, sizeof sub, "%s/clips", g_dir);
  if (mkdir(sub, 0777) != 0) return -1;
  snprintf(path, sizeof path, "%s/walk.bvh", sub);
  imp_write_file(path, "x");
  snprintf(path, sizeof path, "%s/run.bvh", sub);
  imp_write_file(path, "x");
  snprintf(path, sizeof path, "%s/my punch.bvh", sub);
  imp_write_file(path, "x");
  return 0;
}

static int teardown(void** state) {
  (void)state;
  imp_rmdir(g_dir);
  return 0;
}

static smg_result load_text(const char* text, const char* override,
                            smgb_manifest* m, smgb_error* err, char* path,
                            size_t n) {
  snprintf(path, n, "%s/test.manifest", g_dir);
  assert_true(imp_write_file(path, text));
  return smgb_manifest_load(path, override, m, err);
}

static void test_valid(void** state) {
  static const char text[] =
      "# a comment\n"
      "frame_rate 25\n"
      "\n"
      "root clips   # relative to the manifest's folder\n"
      "unit 0.056444\n"
      "skip_first_frame 1\n"
      "mirror 1\n"
      "lower walk walk.bvh frames=1-100\n"
      "lower run run.bvh mirror=0 name=fast unit=0.01 skip_first_frame=0 "
      "frames=0-end\n"
      "upper punch \"my punch.bvh\" frames=10-10 animation=2\n";
  char path[400], want[500];
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc d[3];
  (void)state;
  if (load_text(text, NULL, &m, &err, path, sizeof path) != SMG_OK)
    fail_msg("%s", err.message);
  assert_float_equal(m.frame_rate, 25.0f, 0.0f);
  assert_int_equal(m.clip_count, 3);
  snprintf(want, sizeof want, "%s/./clips/walk.bvh", g_dir);
  if (strcmp(m.clips[0].path, want) != 0) {
    snprintf(want, sizeof want, "%s/clips/walk.bvh", g_dir);
    assert_string_equal(m.clips[0].path, want);
  }
  assert_int_equal(m.clips[0].role, SMG_BAKE_ROLE_LOWER);
  assert_string_equal(m.clips[0].label, "walk");
  assert_int_equal(m.clips[0].first_frame, 0); /* file frame 1 = first kept */
  assert_int_equal(m.clips[0].frame_count, 100);
  assert_int_equal(m.clips[0].mirror, SMG_BAKE_MIRROR_YES);
  assert_int_equal(m.clips[0].skip_first_frame, 1);
  assert_float_equal(m.clips[0].unit_scale, 0.056444f, 0.0f);
  assert_int_equal(m.clips[0].line, 8);
  assert_int_equal(m.clips[1].mirror, SMG_BAKE_MIRROR_NO);
  assert_string_equal(m.clips[1].name, "fast");
  assert_float_equal(m.clips[1].unit_scale, 0.01f, 0.0f);
  assert_int_equal(m.clips[1].skip_first_frame, 0);
  assert_int_equal(m.clips[1].first_frame, 0);
  assert_int_equal(m.clips[1].frame_count, 0); /* to the end */
  assert_int_equal(m.clips[2].role, SMG_BAKE_ROLE_UPPER);
  assert_non_null(strstr(m.clips[2].path, "my punch.bvh"));
  assert_int_equal(m.clips[2].first_frame, 9);
  assert_int_equal(m.clips[2].frame_count, 1);
  assert_int_equal(m.clips[2].animation_index, 2);
  assert_int_equal(smgb_manifest_descs(&m, d, 2), SMG_ERROR_BUFFER_TOO_SMALL);
  assert_int_equal(smgb_manifest_descs(&m, d, 3), SMG_OK);
  assert_int_equal(d[0].struct_size, sizeof(smg_bake_clip_desc));
  assert_ptr_equal(d[0].path, m.clips[0].path);
  assert_string_equal(d[1].name, "fast");
  assert_null(d[0].name);
  assert_int_equal(d[2].source_line, 10);
  assert_int_equal(d[2].first_frame, 9);
  smgb_manifest_free(&m);
}

/* A clip line whose file name has '*' takes every matching file of the
 * folder in name order (every=N: every N-th), labelled from the captures;
 * its clips are marked skippable, explicit lines are not. */
static void test_pattern(void** state) {
  static const char* names[] = {
      "d_walk_active_001.bvh", "d_walk_active_002.bvh",
      "d_walk-turn-left_exhausted_001.bvh", "d_walk_exhausted_003.bvh",
      "d_run_active_001.bvh", "d_run_active_002.bvh", "d_walk_notes.txt"};
  char sub[400], path[600];
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc d[8];
  size_t i;
  (void)state;
  snprintf(sub, sizeof sub, "%s/lib", g_dir);
  assert_int_equal(mkdir(sub, 0777), 0);
  for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
    snprintf(path, sizeof path, "%s/%s", sub, names[i]);
    assert_true(imp_write_file(path, "x"));
  }
  if (load_text("root lib\n"
                "lower walk:{2} \"d_walk*_*_*.bvh\"\n"
                "lower run:{1} d_run_*_*.bvh every=2 mirror=0\n"
                "upper wave d_run_active_002.bvh\n",
                NULL, &m, &err, path, sizeof path) != SMG_OK)
    fail_msg("%s", err.message);
  /* name order: '-' sorts before '_' */
  assert_int_equal(m.clip_count, 6);
  assert_string_equal(m.clips[0].label, "walk:exhausted");
  assert_non_null(strstr(m.clips[0].path, "d_walk-turn-left_exhausted_001"));
  assert_string_equal(m.clips[1].label, "walk:active");
  assert_string_equal(m.clips[2].label, "walk:active");
  assert_string_equal(m.clips[3].label, "walk:exhausted");
  assert_string_equal(m.clips[4].label, "run:active"); /* every=2: 1 of 2 */
  assert_non_null(strstr(m.clips[4].path, "d_run_active_001"));
  assert_int_equal(m.clips[4].mirror, SMG_BAKE_MIRROR_NO);
  assert_int_equal(m.clips[4].line, 3);
  assert_string_equal(m.clips[5].label, "wave");
  assert_int_equal(smgb_manifest_descs(&m, d, 8), SMG_OK);
  assert_int_equal(d[0].flags, SMG_BAKE_CLIP_SKIP_UNUSABLE);
  assert_int_equal(d[4].flags, SMG_BAKE_CLIP_SKIP_UNUSABLE);
  assert_int_equal(d[5].flags, 0); /* an explicit line stays strict */
  smgb_manifest_free(&m);

  /* errors name the line and the problem */
  assert_int_not_equal(load_text("root lib\nlower walk nomatch_*.bvh\n", NULL,
                                 &m, &err, path, sizeof path), SMG_OK);
  assert_non_null(strstr(err.message, "test.manifest:2"));
  assert_non_null(strstr(err.message, "no file"));
  assert_int_not_equal(load_text("root lib\nlower walk:{3} d_run_*.bvh\n",
                                 NULL, &m, &err, path, sizeof path), SMG_OK);
  assert_non_null(strstr(err.message, "{N}"));
  assert_int_not_equal(load_text("lower walk l*b/d_run_*.bvh\n", NULL, &m,
                                 &err, path, sizeof path), SMG_OK);
  assert_non_null(strstr(err.message, "folder"));
  assert_int_not_equal(load_text("root lib\nlower walk d_run_*.bvh every=0\n",
                                 NULL, &m, &err, path, sizeof path), SMG_OK);
  assert_non_null(strstr(err.message, "every"));
  assert_int_not_equal(load_text("root lib\nlower walk d_run_active_001.bvh "
                                 "every=2\n",
                                 NULL, &m, &err, path, sizeof path), SMG_OK);
  assert_non_null(strstr(err.message, "unknown option 'every'"));
  assert_int_not_equal(load_text("root lib\nlower walk{ d_run_*.bvh\n", NULL,
                                 &m, &err, path, sizeof path), SMG_OK);
}

static void test_override(void** state) {
  static const char text[] = "root nowhere\nlower walk walk.bvh\n";
  char path[400], over[400];
  smgb_manifest m;
  smgb_error err;
  (void)state;
  /* Without the override the root does not exist: clear missing-file error. */
  assert_int_equal(load_text(text, NULL, &m, &err, path, sizeof path),
                   SMG_ERROR_IO);
  assert_non_null(strstr(err.message, "test.manifest:2:"));
  assert_non_null(strstr(err.message, "walk.bvh"));
  assert_non_null(strstr(err.message, "not found"));
  snprintf(over, sizeof over, "%s/clips", g_dir);
  if (smgb_manifest_load(path, over, &m, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_int_equal(m.clip_count, 1);
  assert_non_null(strstr(m.clips[0].path, "/clips/walk.bvh"));
  smgb_manifest_free(&m);
}

typedef struct bad {
  const char* text;
  smg_result code;
  int line;
  const char* needle;
} bad;

static void test_errors(void** state) {
  static const bad cases[] = {
      {"root clips\nwalk walk.bvh\n", SMG_ERROR_PARSE, 2, "walk"},
      {"root clips\nlower walk\n", SMG_ERROR_PARSE, 2, "LABEL FILE"},
      {"root clips\nlower walk walk.bvh frames=5\n", SMG_ERROR_PARSE, 2, "frames=5"},
      {"root clips\nlower walk walk.bvh frames=9-3\n", SMG_ERROR_PARSE, 2, "ends before"},
      {"root clips\nskip_first_frame 1\nlower walk walk.bvh frames=0-3\n",
       SMG_ERROR_PARSE, 3, "T-pose"},
      {"root clips\nlower walk walk.bvh mirror=maybe\n", SMG_ERROR_PARSE, 2, "maybe"},
      {"root clips\nlower walk walk.bvh speed=3\n", SMG_ERROR_PARSE, 2, "unknown option"},
      {"root clips\nlower walk walk.bvh mirror\n", SMG_ERROR_PARSE, 2, "key=value"},
      {"root clips\nlower w@lk walk.bvh\n", SMG_ERROR_PARSE, 2, "invalid label"},
      {"root clips\nlower walk walk.bvh\nupper none run.bvh\n",
       SMG_ERROR_INVALID_ARGUMENT, 3, "none"},
      {"root clips\nlower walk missing.bvh\n", SMG_ERROR_IO, 2, "missing.bvh"},
      {"root clips\nlower walk .\n", SMG_ERROR_IO, 2, "regular file"},
      /* found by the manifest fuzzer: named no file and no line */
      {"root clips\nlower walk \"\"\n", SMG_ERROR_INVALID_ARGUMENT, 2,
       "empty clip file name"},
      {"root clips\nlower walk walk.bvh\nroot other\n", SMG_ERROR_PARSE, 3, "root"},
      {"frame_rate fast\n", SMG_ERROR_PARSE, 1, "frame_rate"},
      {"frame_rate -30\n", SMG_ERROR_PARSE, 1, "frame_rate"},
      {"unit nan\n", SMG_ERROR_PARSE, 1, "unit"},
      {"skip_first_frame 2\n", SMG_ERROR_PARSE, 1, "skip_first_frame"},
      {"\n\nbake everything now\n", SMG_ERROR_PARSE, 3, "bake"},
      {"root clips\nupper punch \"my punch.bvh\n", SMG_ERROR_PARSE, 2, "quoted"},
      {"root clips\nupper punch \"my punch.bvh\"\n", SMG_ERROR_PARSE, 2, "no 'lower'"},
      {"# nothing\n", SMG_ERROR_PARSE, 1, "no 'lower'"},
  };
  size_t i;
  (void)state;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    char path[400], want[64];
    smgb_manifest m;
    smgb_error err;
    smg_result r = load_text(cases[i].text, NULL, &m, &err, path, sizeof path);
    snprintf(want, sizeof want, "test.manifest:%d:", cases[i].line);
    if (r != cases[i].code || !strstr(err.message, want) ||
        !strstr(err.message, cases[i].needle)) {
      print_error("case %u: got %s \"%s\", want %s with \"%s\" \"%s\"\n",
                  (unsigned)i, smg_result_string(r), err.message,
                  smg_result_string(cases[i].code), want, cases[i].needle);
      fail();
    }
    assert_int_equal(m.clip_count, 0); /* nothing left to free */
  }
}

static void test_overlong_line_and_missing_manifest(void** state) {
  char* text = (char*)malloc(10000);
  char path[400];
  smgb_manifest m;
  smgb_error err;
  (void)state;
  memset(text, 'a', 9000);
  memcpy(text, "root ", 5);
  strcpy(text + 9000, "\n");
  assert_int_equal(load_text(text, NULL, &m, &err, path, sizeof path),
                   SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "test.manifest:1:"));
  assert_non_null(strstr(err.message, "longer"));
  free(text);
  assert_int_equal(smgb_manifest_load("/nonexistent/x.manifest", NULL, &m, &err),
                   SMG_ERROR_IO);
  assert_non_null(strstr(err.message, "/nonexistent/x.manifest"));
  assert_int_equal(smgb_manifest_load(NULL, NULL, &m, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
}

/* Built in code, as the smg-bake CLI does from its arguments. */
static void test_built_in_code(void** state) {
  smgb_manifest m;
  smgb_manifest_clip c;
  smgb_error err;
  char root[400];
  (void)state;
  snprintf(root, sizeof root, "%s/clips", g_dir);
  assert_int_equal(smgb_manifest_init(&m, root), SMG_OK);
  memset(&c, 0, sizeof c);
  c.role = SMG_BAKE_ROLE_LOWER;
  snprintf(c.label, sizeof c.label, "walk");
  assert_int_equal(smgb_manifest_add(&m, &c, "walk.bvh", 1, &err), SMG_OK);
  assert_int_equal(smgb_manifest_add(&m, &c, "nope.bvh", 1, &err), SMG_ERROR_IO);
  assert_non_null(strstr(err.message, "nope.bvh"));
  assert_int_equal(smgb_manifest_add(&m, &c, "later.bvh", 0, &err), SMG_OK);
  c.role = 7;
  assert_int_equal(smgb_manifest_add(&m, &c, "walk.bvh", 1, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(m.clip_count, 2);
  smgb_manifest_free(&m);
}

/* The project's manifests parse (CMU: when ../shared is present). */
static void test_project_manifests(void** state) {
  const char* cmu = smgt_cmu_dir();
  smgb_manifest m;
  smgb_error err;
  char over[400];
  FILE* fp = fopen("data/cmu.manifest", "r");
  (void)state;
  if (!fp) {
    printf("SKIP: data/cmu.manifest not found (run from the repository root)\n");
    skip();
    return;
  }
  fclose(fp);
  if (cmu) {
    if (smgb_manifest_load("data/cmu.manifest", cmu, &m, &err) != SMG_OK)
      fail_msg("%s", err.message);
    /* 09_12 forward part (file frames 1-861), 06_01, 02_01, ten runs,
     * punch */
    assert_int_equal(m.clip_count, 14);
    assert_float_equal(m.frame_rate, 30.0f, 0.0f);
    assert_int_equal(m.clips[0].first_frame, 0);
    assert_int_equal(m.clips[0].frame_count, 861);
    assert_int_equal(m.clips[13].role, SMG_BAKE_ROLE_UPPER);
    smgb_manifest_free(&m);
    if (smgb_manifest_load("data/cmu-all.manifest", cmu, &m, &err) != SMG_OK)
      fail_msg("%s", err.message);
    assert_int_equal(m.clip_count, 19);
    smgb_manifest_free(&m);
  }
  /* The synthetic manifest against freshly generated clips. */
  snprintf(over, sizeof over, "%s/synthetic", g_dir);
  assert_int_equal(mkdir(over, 0777), 0);
  {
    /* Existence is all the manifest checks: empty stand-ins will do. */
    uint32_t i;
    for (i = 0; i < SMGB_SYNTH_STANDARD_COUNT; ++i) {
      const char* file;
      char p[600];
      assert_int_equal(smgb_synth_standard(i, NULL, &file, NULL, NULL), SMG_OK);
      snprintf(p, sizeof p, "%s/%s", over, file);
      assert_true(imp_write_file(p, ""));
    }
  }
  if (smgb_manifest_load("data/synthetic.manifest", over, &m, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_int_equal(m.clip_count, 8);
  assert_float_equal(m.clips[0].unit_scale, 1.0f, 0.0f);
  assert_int_equal(m.clips[0].skip_first_frame, 0);
  smgb_manifest_free(&m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_valid),
      cmocka_unit_test(test_pattern),
      cmocka_unit_test(test_override),
      cmocka_unit_test(test_errors),
      cmocka_unit_test(test_overlong_line_and_missing_manifest),
      cmocka_unit_test(test_built_in_code),
      cmocka_unit_test(test_project_manifests),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
