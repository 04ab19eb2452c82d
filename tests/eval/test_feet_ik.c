/*
 * test_feet_ik.c - foot IK never makes the feet worse than no IK, judged
 * from geometry alone (tools/eval/eval_feet_geom.h), and keeps them on the
 * floor the data has: IK moves the lowest toe height by at most 1 cm.
 *  - The synthetic default graph (straight line, left and right turns):
 *    its feet are planted exactly by construction, so IK has nothing to
 *    remove; the mean planted-toe speed with IK may not exceed the one
 *    without by more than 1 %.
 *  - A graph of two performers (CMU 02_01 + 06_01 walks on 02_01's
 *    skeleton; skipped without ../shared): retargeted feet slide, and the
 *    mean with IK must not be above the one without (it was 13x above when
 *    IK held toes where the heel struck).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eval_feet_geom.h"
#include "eval_metrics.h"
#include "eval_run.h"
#include "smg_bake.h"
#include "test_env.h"

static smg_graph* g_graph;

static int setup(void** state) {
  char path[1024];
  (void)state;
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  if (smg_graph_load_file(path, NULL, &g_graph) != SMG_OK) {
    fprintf(stderr, "cannot load %s: run `make` first\n", path);
    return -1;
  }
  return 0;
}

static int teardown(void** state) {
  (void)state;
  smg_graph_destroy(g_graph);
  return 0;
}

static void feet(const float* path, uint32_t n, uint32_t flags,
                 eval_feet_geom* out) {
  eval_run_desc rd;
  eval_trace t;
  char err[256];
  uint32_t lt, rt, walk;
  const double* toes[2];
  assert_int_equal(smg_graph_find_joint(g_graph, "LeftToeBase", &lt), SMG_OK);
  assert_int_equal(smg_graph_find_joint(g_graph, "RightToeBase", &rt),
                   SMG_OK);
  assert_int_equal(smg_graph_find_style(g_graph, "walk", &walk), SMG_OK);
  memset(&rd, 0, sizeof rd);
  rd.path_xz = path;
  rd.path_count = n;
  rd.initial_style = walk;
  rd.rate = 30.0f;
  rd.max_seconds = 25.0f;
  rd.extra_seconds = 1.0f;
  rd.seed = 7;
  rd.character_flags = flags;
  assert_int_equal(eval_run(g_graph, &rd, &t, err, sizeof err), SMG_OK);
  toes[0] = t.joints + 3 * lt;
  toes[1] = t.joints + 3 * rt;
  assert_int_equal(eval_feet_geom_measure(toes, 2, 3 * (size_t)t.joint_count,
                                          t.frames, t.dt, NULL, out),
                   0);
  eval_trace_free(&t);
}

static void check(const char* what, const double* xz, size_t n,
                  double slack) {
  static float path[2 * 2048];
  eval_feet_geom on, off;
  size_t i;
  for (i = 0; i < 2 * n; ++i) path[i] = (float)xz[i];
  feet(path, (uint32_t)n, 0, &on);
  feet(path, (uint32_t)n, SMG_CHARACTER_NO_IK, &off);
  print_message("%s: planted-toe speed with IK %.2f / p99 %.1f cm/s, without "
                "%.2f / p99 %.1f; lowest toe %.2f / %.2f cm\n", what,
                on.mean_cms, on.p99_cms, off.mean_cms, off.p99_cms,
                on.lowest_cm, off.lowest_cm);
  assert_true(on.planted_pairs > 50 && off.planted_pairs > 50);
  assert_true(on.mean_cms <= off.mean_cms * (1.0 + slack));
  assert_true(fabs(on.lowest_cm - off.lowest_cm) <= 1.0);
}

static void test_straight(void** state) {
  static double xz[2 * 2048];
  (void)state;
  check("straight", xz, em_path_straight(12.0, 0.1, xz, 2048), 0.01);
}

static void test_turns(void** state) {
  static double xz[2 * 2048];
  (void)state;
  check("left turn", xz, em_path_turn(3.0, 3.0, 1.5707963, 5.0, 0.1, xz,
                                      2048), 0.01);
  check("right turn", xz, em_path_turn(3.0, 3.0, -1.5707963, 5.0, 0.1, xz,
                                       2048), 0.01);
}

static void test_two_performers(void** state) {
  static double xz[2 * 2048];
  const char* cmu = smgt_cmu_dir();
  smg_bake_clip_desc c[2];
  smg_bake_desc desc;
  smg_bake_result br;
  smg_graph* synthetic = g_graph;
  int k;
  (void)state;
  if (!cmu) return;
  memset(c, 0, sizeof c);
  for (k = 0; k < 2; ++k) {
    c[k].struct_size = sizeof c[k];
    c[k].role = SMG_BAKE_ROLE_LOWER;
    c[k].label = "walk";
    c[k].skip_first_frame = 1;
    c[k].unit_scale = 0.056444f;
  }
  c[0].path = "02_01.bvh"; /* first: its skeleton is the target */
  c[1].path = "06_01.bvh";
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.clip_count = 2;
  desc.clips = c;
  desc.data_dir = cmu;
  desc.options.struct_size = sizeof desc.options;
  memset(&br, 0, sizeof br);
  br.struct_size = sizeof br;
  assert_int_equal(smg_bake_run(&desc, &br), SMG_OK);
  assert_int_equal(smg_graph_load_memory(br.blob, br.blob_size, NULL,
                                         &g_graph),
                   SMG_OK);
  check("02_01 + 06_01, straight", xz,
        em_path_straight(20.0, 0.1, xz, 2048), 0.0);
  check("02_01 + 06_01, left turn", xz,
        em_path_turn(6.0, 4.0, 1.5707963, 8.0, 0.1, xz, 2048), 0.0);
  smg_graph_destroy(g_graph);
  g_graph = synthetic;
  smg_bake_result_free(&br);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_straight),
      cmocka_unit_test(test_turns),
      cmocka_unit_test(test_two_performers),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
