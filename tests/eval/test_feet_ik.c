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
 *    IK held toes where the heel struck), and the p99 with IK is at most
 *    100 cm/s (130 when the released correction returned over the toe's
 *    push-off).
 * On both, every planted pair faster than 100 cm/s with IK is one where
 * the toe moves as fast at the same frame without IK (the animation's
 * own swing passing low): IK adds no fast slide or pop of its own.
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

#define FAST_CMS 100.0
#define MAX_FRAMES 4096

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

/* One run's feet; per_frame (planted-pair speeds, NaN elsewhere) and
 * any_speed (every pair's speed) are 2 * MAX_FRAMES, toe-interleaved. */
static size_t feet(const float* path, uint32_t n, uint32_t flags,
                   eval_feet_geom* out, double* per_frame,
                   double* any_speed) {
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
  assert_true(t.frames <= MAX_FRAMES);
  toes[0] = t.joints + 3 * lt;
  toes[1] = t.joints + 3 * rt;
  assert_int_equal(eval_feet_geom_measure(toes, 2, 3 * (size_t)t.joint_count,
                                          t.frames, t.dt, per_frame, out),
                   0);
  for (size_t f = 1; f < t.frames; ++f)
    for (int k = 0; k < 2; ++k) {
      const double* a = toes[k] + (f - 1) * 3 * (size_t)t.joint_count;
      const double* b = toes[k] + f * 3 * (size_t)t.joint_count;
      any_speed[2 * f + k] = 100.0 * hypot(b[0] - a[0], b[2] - a[2]) / t.dt;
    }
  any_speed[0] = any_speed[1] = NAN;
  size_t frames = t.frames;
  eval_trace_free(&t);
  return frames;
}

static void check(const char* what, const double* xz, size_t n,
                  double slack, double p99_bound) {
  static float path[2 * 2048];
  static double on_v[2 * MAX_FRAMES], on_any[2 * MAX_FRAMES],
      off_v[2 * MAX_FRAMES], off_any[2 * MAX_FRAMES];
  eval_feet_geom on, off;
  size_t i, fast = 0, own = 0;
  for (i = 0; i < 2 * n; ++i) path[i] = (float)xz[i];
  size_t fon = feet(path, (uint32_t)n, 0, &on, on_v, on_any);
  size_t foff = feet(path, (uint32_t)n, SMG_CHARACTER_NO_IK, &off, off_v,
                     off_any);
  for (i = 0; i < 2 * fon && i < 2 * foff; ++i)
    if (on_v[i] > FAST_CMS) {
      ++fast;
      if (off_any[i] > FAST_CMS) ++own;
    }
  print_message("%s: planted-toe speed with IK %.2f / p99 %.1f cm/s, without "
                "%.2f / p99 %.1f; lowest toe %.2f / %.2f cm; planted pairs "
                "over %.0f cm/s with IK %zu, as fast without IK %zu\n", what,
                on.mean_cms, on.p99_cms, off.mean_cms, off.p99_cms,
                on.lowest_cm, off.lowest_cm, FAST_CMS, fast, own);
  assert_true(on.planted_pairs > 50 && off.planted_pairs > 50);
  assert_true(on.mean_cms <= off.mean_cms * (1.0 + slack));
  assert_true(fabs(on.lowest_cm - off.lowest_cm) <= 1.0);
  assert_true(fon == foff); /* IK does not change the plan */
  assert_int_equal(fast, own);
  assert_true(on.p99_cms <= p99_bound);
}

static void test_straight(void** state) {
  static double xz[2 * 2048];
  (void)state;
  check("straight", xz, em_path_straight(12.0, 0.1, xz, 2048), 0.01,
        INFINITY);
}

static void test_turns(void** state) {
  static double xz[2 * 2048];
  (void)state;
  check("left turn", xz, em_path_turn(3.0, 3.0, 1.5707963, 5.0, 0.1, xz,
                                      2048), 0.01, INFINITY);
  check("right turn", xz, em_path_turn(3.0, 3.0, -1.5707963, 5.0, 0.1, xz,
                                       2048), 0.01, INFINITY);
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
        em_path_straight(20.0, 0.1, xz, 2048), 0.0, FAST_CMS);
  check("02_01 + 06_01, left turn", xz,
        em_path_turn(6.0, 4.0, 1.5707963, 8.0, 0.1, xz, 2048), 0.0,
        FAST_CMS);
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
