/*
 * test_bake_cli.c - the smg-bake command line: a bake from --lower/--upper
 * clip arguments (synthetic BVH files written here), the one-line-per-stage
 * progress and timing table when stderr is not a terminal, --info on the
 * result, and clear failures (missing clip file, garbage blob, bad option)
 * with exit status 1 or 2; a bake that fails or is killed half-way through
 * writing leaves the old output file intact. Skips when build/smg-bake has not been built.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bake_graph_helpers.h"

#ifndef SMG_BUILD_DIR
#define SMG_BUILD_DIR "build"
#endif

static char g_dir[64];
static char g_tool[1024];

static int run(const char* args, const char* out_file) {
  char cmd[4096];
  int st;
  snprintf(cmd, sizeof cmd, "'%s' %s > '%s/%s' 2>&1", g_tool, args, g_dir,
           out_file);
  st = system(cmd);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static char* slurp(const char* name) {
  char path[256];
  FILE* fp;
  long n;
  char* buf;
  snprintf(path, sizeof path, "%s/%s", g_dir, name);
  fp = fopen(path, "rb");
  if (!fp) return NULL;
  fseek(fp, 0, SEEK_END);
  n = ftell(fp);
  fseek(fp, 0, SEEK_SET);
  buf = calloc((size_t)n + 1, 1);
  if (fread(buf, 1, (size_t)n, fp) != (size_t)n) buf[0] = '\0';
  fclose(fp);
  return buf;
}

static void expect_in(const char* file, const char* needle) {
  char* t = slurp(file);
  assert_non_null(t);
  if (!strstr(t, needle)) fail_msg("'%s' not in output:\n%s", needle, t);
  free(t);
}

static void test_cli(void** state) {
  bg_set s;
  smgb_error err;
  char path[256], args[2048];
  (void)state;
  snprintf(g_tool, sizeof g_tool, "%s/smg-bake", SMG_BUILD_DIR);
  if (access(g_tool, X_OK) != 0) {
    printf("SKIP: %s not built (run make first)\n", g_tool);
    skip();
    return;
  }
  snprintf(g_dir, sizeof g_dir, "/tmp/smg-bake-cli-XXXXXX");
  assert_non_null(mkdtemp(g_dir));
  memset(&s, 0, sizeof s);
  bg_add(&s, SMGB_SYNTH_WALK, 3.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(&s, SMGB_SYNTH_RUN, 3.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "run");
  bg_add(&s, SMGB_SYNTH_PUNCH, 3.0f, 0.0f, SMG_BAKE_ROLE_UPPER, "punch");
  snprintf(path, sizeof path, "%s/w.bvh", g_dir);
  assert_int_equal(smgb_bvh_save(path, &s.clips[0], &err), SMG_OK);
  snprintf(path, sizeof path, "%s/r.bvh", g_dir);
  assert_int_equal(smgb_bvh_save(path, &s.clips[1], &err), SMG_OK);
  snprintf(path, sizeof path, "%s/p.bvh", g_dir);
  assert_int_equal(smgb_bvh_save(path, &s.clips[2], &err), SMG_OK);
  bg_free(&s);

  snprintf(args, sizeof args,
           "--data-dir '%s' --lower walk w.bvh --lower run r.bvh "
           "--upper punch p.bvh --unit 1 --no-mirror -o '%s/out.smg'",
           g_dir, g_dir);
  assert_int_equal(run(args, "bake.txt"), 0);
  expect_in("bake.txt", "smg-bake: lower graph ...");
  expect_in("bake.txt", "splice search");
  expect_in("bake.txt", "total");
  expect_in("bake.txt", "before simplification");

  snprintf(args, sizeof args, "--info '%s/out.smg'", g_dir);
  assert_int_equal(run(args, "info.txt"), 0);
  expect_in("info.txt", "skeleton: 31 joints, pelvis Hips, spine base LowerBack");
  expect_in("info.txt", "styles: walk run");
  expect_in("info.txt", "actions: none punch");
  expect_in("info.txt", "lower graph:");
  expect_in("info.txt", "splice candidates:");
  expect_in("info.txt", "SPLC");

  snprintf(args, sizeof args,
           "--data-dir '%s' --lower walk missing.bvh -o '%s/x.smg'", g_dir,
           g_dir);
  assert_int_equal(run(args, "missing.txt"), 1);
  expect_in("missing.txt", "missing.bvh");

  snprintf(args, sizeof args, "--info '%s/bake.txt'", g_dir);
  assert_int_equal(run(args, "garbage.txt"), 1);
  expect_in("garbage.txt", "not a valid graph blob");

  /* atomic output: bakes that fail - before writing, or half-way through
   * the write (the file-size limit makes write() fail), or killed half-way
   * (the limit's signal) - leave the old out.smg byte for byte */
  {
    char* old_blob = slurp("out.smg");
    char *now, cmd[4096];
    long old_size;
    int st;
    FILE* fp;
    snprintf(path, sizeof path, "%s/out.smg", g_dir);
    fp = fopen(path, "rb");
    assert_non_null(fp);
    fseek(fp, 0, SEEK_END);
    old_size = ftell(fp);
    fclose(fp);
    assert_true(old_size > 64 * 512); /* more than the limit below */
    snprintf(args, sizeof args,
             "--data-dir '%s' --lower walk missing.bvh -o '%s/out.smg'",
             g_dir, g_dir);
    assert_int_equal(run(args, "fail-early.txt"), 1);
    snprintf(args, sizeof args,
             "--data-dir '%s' --lower walk w.bvh --lower run r.bvh "
             "--upper punch p.bvh --unit 1 -o '%s/out.smg'",
             g_dir, g_dir);
    snprintf(cmd, sizeof cmd,
             "trap '' XFSZ; ulimit -f 64; '%s' %s > '%s/fail-write.txt' 2>&1",
             g_tool, args, g_dir);
    st = system(cmd);
    assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 1);
    expect_in("fail-write.txt", "out.smg is unchanged");
    snprintf(cmd, sizeof cmd,
             "ulimit -f 64; exec '%s' %s > '%s/killed.txt' 2>&1", g_tool,
             args, g_dir);
    st = system(cmd);
    assert_false(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    now = slurp("out.smg");
    assert_non_null(now);
    assert_memory_equal(now, old_blob, (size_t)old_size);
    free(now);
    free(old_blob);
    /* the failed write cleaned up after itself; the killed one could not,
     * and left only a hidden temporary (never out.smg) */
    snprintf(cmd, sizeof cmd, "test $(ls -A '%s' | grep -c '^\\.out\\.smg\\.') = 1",
             g_dir);
    assert_int_equal(system(cmd), 0);
  }

  assert_int_equal(run("--frame-rate abc -m x -o y", "opt.txt"), 2);
  expect_in("opt.txt", "not a number");
  assert_int_equal(run("--bogus", "opt2.txt"), 2);
  expect_in("opt2.txt", "unknown option");
  {
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_dir);
    assert_int_equal(system(cmd), 0);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cli),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
