/*
 * test_standing.c - standing stretches (libsmg/common/standing.c): on
 * hand-made frames (still, swaying, shuffling, turning, one foot up, too
 * short, blend clips, frame rates and leg lengths) and on graphs baked
 * here from ../shared when the clips are there: the CMU set and the
 * Bandai Namco set (its waves and hand-raises are performed standing; read
 * at run time, nothing derived is kept). Prints what it finds.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake/bake_graph_helpers.h"
#include "standing.h"
#include "test_env.h"

#define BOTH (SMGI_FRAME_LEFT_CONTACT | SMGI_FRAME_RIGHT_CONTACT)
#define N 300

static smgi_frame F[N];

/* One clip of n frames at `fps`: standing at the origin, feet down. */
static void still(uint32_t n) {
  memset(F, 0, sizeof F);
  for (uint32_t i = 0; i < n; ++i) F[i].flags = BOTH;
}

static smgi_clip clip(uint32_t first, uint32_t count, uint32_t flags) {
  smgi_clip c;
  memset(&c, 0, sizeof c);
  c.first_frame = first;
  c.frame_count = count;
  c.flags = flags;
  return c;
}

static void test_still_clip_is_one_stretch(void** state) {
  (void)state;
  still(90);
  smgi_clip c = clip(0, 90, SMGI_CLIP_UPPER);
  smgi_stand s[4];
  assert_int_equal(smgi_standing_find(F, 90, &c, 1, 30.0f, 0.8f, s, 4), 1);
  assert_int_equal(s[0].first, 0);
  assert_int_equal(s[0].count, 90);
  assert_int_equal(s[0].clip, 0);
}

/* A walk (1.2 m/s) with 1.5 s standing before and after: two stretches,
 * the walk excluded with the frames whose +-0.25 s reaches into it. */
static void test_walk_between_stands(void** state) {
  (void)state;
  still(N);
  for (uint32_t i = 0; i < N; ++i) {
    float t = (float)i / 30.0f;
    float z = t < 1.5f ? 0.0f : t < 8.5f ? 1.2f * (t - 1.5f) : 8.4f;
    F[i].root2d[1] = z;
    if (t >= 1.5f && t < 8.5f && (i / 8u) % 2u) F[i].flags = 1u;
  }
  smgi_clip c = clip(0, N, SMGI_CLIP_LOWER);
  smgi_stand s[4];
  const uint32_t n = smgi_standing_find(F, N, &c, 1, 30.0f, 0.8f, s, 4);
  assert_int_equal(n, 2);
  assert_true(s[0].first == 0 && s[0].count >= 36 && s[0].count <= 45);
  assert_true(s[1].first + s[1].count == N);
  assert_true(s[1].count >= 36 && s[1].count <= 45);
}

/* Sway within a few centimetres stays standing; a slow shuffle does
 * not, nor turning on the spot, nor standing on one foot. */
static void test_what_is_not_standing(void** state) {
  (void)state;
  smgi_clip c = clip(0, 120, SMGI_CLIP_LOWER);
  still(120);
  for (uint32_t i = 0; i < 120; ++i)
    F[i].root2d[0] = 0.02f * sinf((float)i * 0.2f);
  assert_int_equal(smgi_standing_find(F, 120, &c, 1, 30.0f, 0.8f, NULL, 0),
                   1);
  still(120);
  for (uint32_t i = 0; i < 120; ++i) F[i].root2d[1] = 0.2f * (float)i / 30.0f;
  assert_int_equal(smgi_standing_find(F, 120, &c, 1, 30.0f, 0.8f, NULL, 0),
                   0);
  still(120);
  for (uint32_t i = 0; i < 120; ++i) F[i].root2d[2] = 0.8f * (float)i / 30.0f;
  assert_int_equal(smgi_standing_find(F, 120, &c, 1, 30.0f, 0.8f, NULL, 0),
                   0);
  still(120);
  for (uint32_t i = 0; i < 120; ++i) F[i].flags = SMGI_FRAME_LEFT_CONTACT;
  assert_int_equal(smgi_standing_find(F, 120, &c, 1, 30.0f, 0.8f, NULL, 0),
                   0);
}

/* A creep at 5 cm/s is slow enough to pass the speed test but strays
 * from where it began: cut into pieces no longer than the drift allows. */
static void test_drift_cuts(void** state) {
  (void)state;
  still(N);
  for (uint32_t i = 0; i < N; ++i) F[i].root2d[0] = 0.05f * (float)i / 30.0f;
  smgi_clip c = clip(0, N, SMGI_CLIP_LOWER);
  smgi_stand s[8];
  const uint32_t n = smgi_standing_find(F, N, &c, 1, 30.0f, 0.8f, s, 8);
  assert_true(n >= 3);
  for (uint32_t k = 0; k < n && k < 8; ++k) {
    float d = F[s[k].first + s[k].count - 1u].root2d[0] - F[s[k].first].root2d[0];
    assert_true(d <= SMGI_STAND_DRIFT * 0.8f + 1e-4f);
  }
}

/* Too short, blend clips and clips outside the pool are skipped; the
 * minimum length follows the frame rate and the speed the leg length. */
static void test_limits_scale(void** state) {
  (void)state;
  smgi_clip c[3] = {clip(0, 29, SMGI_CLIP_LOWER),
                    clip(29, 100, SMGI_CLIP_LOWER | SMGI_CLIP_BLEND),
                    clip(200, 200, SMGI_CLIP_LOWER)};
  still(N);
  assert_int_equal(smgi_standing_find(F, N, c, 3, 30.0f, 0.8f, NULL, 0), 0);
  c[0].frame_count = 30;
  assert_int_equal(smgi_standing_find(F, N, c, 1, 30.0f, 0.8f, NULL, 0), 1);
  assert_int_equal(smgi_standing_find(F, N, c, 1, 60.0f, 0.8f, NULL, 0), 0);
  /* 6 cm/s: standing for a 0.8 m leg, not for a 0.4 m one */
  for (uint32_t i = 0; i < 60; ++i) F[i].root2d[0] = 0.06f * (float)i / 30.0f;
  c[0].frame_count = 60;
  assert_int_equal(smgi_standing_find(F, N, c, 1, 30.0f, 0.8f, NULL, 0), 1);
  assert_int_equal(smgi_standing_find(F, N, c, 1, 30.0f, 0.4f, NULL, 0), 0);
  assert_int_equal(smgi_standing_find(NULL, N, c, 1, 30.0f, 0.8f, NULL, 0), 0);
  assert_int_equal(smgi_standing_find(F, N, c, 1, 0.0f, 0.8f, NULL, 0), 0);
}

/* ---- real data ---- */

/* Standing seconds found in the clips of one kind (flags bit). */
static float seconds_in(const smgi_graph_data* g, const smgi_stand* s,
                        uint32_t n, uint32_t kind) {
  float t = 0.0f;
  for (uint32_t k = 0; k < n; ++k)
    if (g->clips[s[k].clip].flags & kind)
      t += (float)s[k].count / g->info->frame_rate;
  return t;
}

/* Bakes `manifest` from `sub` under the shared folder (skips when the
 * clips or the manifest are absent, or under valgrind) and checks what
 * is found. */
static void report(const char* manifest, const char* sub, const char* probe,
                   int need_upper) {
  char dir[1024], file[1200];
  snprintf(dir, sizeof dir, "%s/mocap/%s", smgt_shared_dir(), sub);
  snprintf(file, sizeof file, "%s/%s", dir, probe);
  FILE* fp = fopen(file, "rb");
  if (!fp) {
    print_message("skipped: %s not found\n", file);
    skip();
  }
  fclose(fp);
  if (smgt_quick()) {
    print_message("skipped: SMG_TEST_QUICK (baking is too slow under "
                  "valgrind)\n");
    skip();
  }
  smg_bake_result res;
  smgi_graph_data g;
  bg_bake_manifest(manifest, dir, NULL, &res);
  bg_read(&res, &g);
  static smgi_stand s[4096];
  uint32_t n = smgi_standing_find(g.frames, g.frame_count, g.clips,
                                  g.clip_count, g.info->frame_rate,
                                  g.info->leg_length, s, 4096);
  assert_true(n <= 4096);
  float lower = seconds_in(&g, s, n, SMGI_CLIP_LOWER);
  float upper = seconds_in(&g, s, n, SMGI_CLIP_UPPER);
  print_message("%s: %u standing stretches, %.1f s in locomotion clips, "
                "%.1f s in action clips\n",
                manifest, n, lower, upper);
  /* every stretch really stands: the ground point within the drift of
   * its first frame, both feet down throughout */
  for (uint32_t k = 0; k < n; ++k) {
    const smgi_frame* a = &g.frames[s[k].first];
    for (uint32_t i = 0; i < s[k].count; ++i) {
      float dx = a[i].root2d[0] - a[0].root2d[0];
      float dz = a[i].root2d[1] - a[0].root2d[1];
      assert_true(sqrtf(dx * dx + dz * dz) <=
                  SMGI_STAND_DRIFT * g.info->leg_length + 1e-4f);
      assert_int_equal(a[i].flags & BOTH, BOTH);
    }
  }
  /* actions performed standing give standing motion */
  if (need_upper) assert_true(upper >= 10.0f);
  smg_bake_result_free(&res);
}

static void test_cmu(void** state) {
  (void)state;
  report("data/cmu.manifest", "cmu", "09_12.bvh", 0);
}

static void test_bandai(void** state) {
  (void)state;
  report("data/bandai.manifest", "bandai-namco",
         "dataset-2_wave-right-hand_normal_001.bvh", 1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_still_clip_is_one_stretch),
      cmocka_unit_test(test_walk_between_stands),
      cmocka_unit_test(test_what_is_not_standing),
      cmocka_unit_test(test_drift_cuts),
      cmocka_unit_test(test_limits_scale),
      cmocka_unit_test(test_cmu),
      cmocka_unit_test(test_bandai),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
