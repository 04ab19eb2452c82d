/*
 * test_bake_second_studio.c - bake the real Bandai Namco Research Motion Dataset
 * clips (data/bandai.manifest: a second studio, a static joint_Root above
 * a translating Hips, 6 channels on every joint, centimetres, _L/_R names,
 * two performers) and judge the result from geometry: forward kinematics
 * of the baked POSE records of every locomotion clip.
 *
 *  - the blob's skeleton is the first clip's (joint_Root folded away, Hips
 *    joint 0) with its bone lengths in metres;
 *  - every pool frame follows the previous one smoothly, blended
 *    transitions included: no joint moves more than 0.5 m (15 m/s) relative
 *    to the hips in one frame (a running foot: 0.32 m; the rig's joint
 *    frames are not mirror images, and a transition between a clip and
 *    its mirror once spun whole limbs, 1.1 m per frame);
 *  - styles walk / run / exhausted, actions wave / raise, and walk and
 *    exhausted joined by transitions both ways;
 *  - toes rest 0-5 cm above the floor: each toe's floor level (its 5th
 *    percentile height over a clip) lies in [0, 5] cm;
 *  - planted feet stay planted: over the pairs of consecutive frames in
 *    which a toe is within 2.5 cm of its floor level, the horizontal toe
 *    speed is at most 20 cm/s, per clip and foot. The median is asserted
 *    and the mean printed: in these recordings the toe joint (the ball of
 *    the foot; the rig has no toe tip) skims 1-2 cm above the floor in mid
 *    swing at 3-4 m/s, so 5-10 % of the pairs inside the band are swing,
 *    not contact, and they dominate a mean (0.17-0.37 m/s per clip on the
 *    raw clips, against medians of 0.016-0.020 m/s).
 *
 * Skips with a message when ../shared has no Bandai Namco clips. Under
 * SMG_TEST_QUICK (valgrind) a few clips are baked without mirrors.
 * Nothing baked is written to disk (the data's licence forbids derived
 * files in the project).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_manifest.h"
#include "quat_pack.h"

#define FLOOR_PERCENTILE 0.05
#define PLANT_BAND 0.025       /* metres above the floor level */
#define MAX_PLANTED_SPEED 0.20 /* metres per second */

static const char* bandai_dir(void) {
  static char dir[1024];
  char probe[1200];
  FILE* fp;
  snprintf(dir, sizeof dir, "%s/mocap/bandai-namco", smgt_shared_dir());
  snprintf(probe, sizeof probe, "%s/dataset-2_walk_normal_001.bvh", dir);
  fp = fopen(probe, "rb");
  if (!fp) {
    printf("SKIP: Bandai Namco clips not found in %s (set SMG_SHARED to the "
           "folder holding mocap/bandai-namco)\n", dir);
    return NULL;
  }
  fclose(fp);
  return dir;
}

static int cmp_float(const void* a, const void* b) {
  float x = *(const float*)a, y = *(const float*)b;
  return x < y ? -1 : x > y;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* Toe floor level and the median and mean planted speed of one toe over
 * one clip. */
static void toe_stats(const float* heights, const float* xz, uint32_t n,
                      float fps, double* level, double* median, double* mean,
                      uint32_t* planted_pairs) {
  float* sorted = malloc(sizeof *sorted * n);
  double* speed = malloc(sizeof *speed * n);
  double sum = 0.0;
  uint32_t f, pairs = 0;
  assert_non_null(sorted);
  assert_non_null(speed);
  memcpy(sorted, heights, sizeof *sorted * n);
  qsort(sorted, n, sizeof *sorted, cmp_float);
  *level = sorted[(uint32_t)(FLOOR_PERCENTILE * (n - 1))];
  free(sorted);
  for (f = 0; f + 1 < n; ++f) {
    if (heights[f] <= *level + PLANT_BAND &&
        heights[f + 1] <= *level + PLANT_BAND) {
      double dx = xz[2 * (f + 1)] - xz[2 * f];
      double dz = xz[2 * (f + 1) + 1] - xz[2 * f + 1];
      speed[pairs] = sqrt(dx * dx + dz * dz) * fps;
      sum += speed[pairs++];
    }
  }
  qsort(speed, pairs, sizeof *speed, cmp_double);
  *median = pairs ? speed[pairs / 2] : 0.0;
  *mean = pairs ? sum / pairs : 0.0;
  *planted_pairs = pairs;
  free(speed);
}

/* Geometry of every locomotion clip in the blob. */
static void check_feet(const smgi_graph_data* g) {
  uint32_t J = g->joint_count, c, j, checked = 0;
  char(*names)[SMGB_NAME_MAX] = calloc(J, sizeof *names);
  int32_t* parents = calloc(J, sizeof *parents);
  float(*offsets)[3] = calloc(J, sizeof *offsets);
  float* pose = malloc(sizeof(float) * SMGI_POSE_FLOATS(J));
  float* pos = malloc(sizeof(float) * 3 * J);
  smgb_skeleton s;
  uint32_t toe[2];
  double worst_median = 0.0, worst_mean = 0.0;
  double worst_level_lo = 1.0, worst_level_hi = -1.0;
  assert_true(names && parents && offsets && pose && pos);
  for (j = 0; j < J; ++j) {
    snprintf(names[j], SMGB_NAME_MAX, "%s", g->strings + g->joints[j].name);
    parents[j] = g->joints[j].parent;
    memcpy(offsets[j], g->joints[j].offset, sizeof offsets[j]);
  }
  s.joint_count = J;
  s.names = names;
  s.parents = parents;
  s.offsets = offsets;
  toe[0] = g->info->left_leg[3];
  toe[1] = g->info->right_leg[3];
  assert_string_equal(names[toe[0]], "Toes_L");
  assert_string_equal(names[toe[1]], "Toes_R");
  for (c = 0; c < g->clip_count; ++c) {
    const smgi_clip* cl = &g->clips[c];
    uint32_t n = cl->frame_count, f, side;
    float* h[2];
    float* xz[2];
    if (!(cl->flags & SMGI_CLIP_LOWER) || (cl->flags & SMGI_CLIP_BLEND))
      continue;
    for (side = 0; side < 2; ++side) {
      h[side] = malloc(sizeof(float) * n);
      xz[side] = malloc(sizeof(float) * 2 * n);
      assert_true(h[side] && xz[side]);
    }
    for (f = 0; f < n; ++f) {
      smgi_pose_unpack(smgi_pose_record(g, cl->first_frame + f), J, pose);
      smgb_fk(&s, pose, pos, NULL);
      for (side = 0; side < 2; ++side) {
        h[side][f] = pos[3 * toe[side] + 1] - g->info->ground_height;
        xz[side][2 * f] = pos[3 * toe[side]];
        xz[side][2 * f + 1] = pos[3 * toe[side] + 2];
      }
    }
    for (side = 0; side < 2; ++side) {
      double level, median, mean;
      uint32_t pairs;
      toe_stats(h[side], xz[side], n, g->info->frame_rate, &level, &median,
                &mean, &pairs);
      if (level < worst_level_lo) worst_level_lo = level;
      if (level > worst_level_hi) worst_level_hi = level;
      if (median > worst_median) worst_median = median;
      if (mean > worst_mean) worst_mean = mean;
      if (level < -0.002 || level > 0.05 || median > MAX_PLANTED_SPEED ||
          pairs < n / 5)
        fail_msg("%s, %s toe: floor level %.3f m (want 0-0.05), planted "
                 "speed median %.3f m/s over %u frame pairs of %u (want <= "
                 "%.2f)",
                 g->strings + cl->name, side ? "right" : "left", level,
                 median, pairs, n, MAX_PLANTED_SPEED);
      free(h[side]);
      free(xz[side]);
    }
    ++checked;
  }
  printf("Bandai Namco: %u locomotion clips; toe floor levels %.3f-%.3f m; "
         "planted-toe speed per clip and foot: worst median %.3f m/s, worst "
         "mean %.3f m/s\n",
         checked, worst_level_lo, worst_level_hi, worst_median, worst_mean);
  assert_true(checked >= 3);
  free(names);
  free(parents);
  free(offsets);
  free(pose);
  free(pos);
}

/* Largest movement of any joint relative to the hips between consecutive
 * frames of a clip or of one blended transition window. */
static void check_smooth(const smgi_graph_data* g) {
  uint32_t J = g->joint_count, c, j, f;
  uint32_t k = (uint32_t)(g->info->window_seconds * g->info->frame_rate + 0.5f);
  char(*names)[SMGB_NAME_MAX] = calloc(J, sizeof *names);
  int32_t* parents = calloc(J, sizeof *parents);
  float(*offsets)[3] = calloc(J, sizeof *offsets);
  float* pose = malloc(sizeof(float) * SMGI_POSE_FLOATS(J));
  float* pos = malloc(sizeof(float) * 3 * J);
  float* prev = malloc(sizeof(float) * 3 * J);
  smgb_skeleton s;
  double worst = 0.0;
  const char* where = "";
  assert_true(names && parents && offsets && pose && pos && prev && k > 0);
  for (j = 0; j < J; ++j) {
    parents[j] = g->joints[j].parent;
    memcpy(offsets[j], g->joints[j].offset, sizeof offsets[j]);
  }
  s.joint_count = J;
  s.names = names;
  s.parents = parents;
  s.offsets = offsets;
  for (c = 0; c < g->clip_count; ++c) {
    const smgi_clip* cl = &g->clips[c];
    for (f = 0; f < cl->frame_count; ++f) {
      smgi_pose_unpack(smgi_pose_record(g, cl->first_frame + f), J, pose);
      smgb_fk(&s, pose, pos, NULL);
      for (j = 0; j < J; ++j) {
        pos[3 * j] -= pos[0];
        pos[3 * j + 1] -= pos[1];
        pos[3 * j + 2] -= pos[2];
      }
      if (f > 0 && (!(cl->flags & SMGI_CLIP_BLEND) || f % k != 0)) {
        for (j = 1; j < J; ++j) {
          double dx = pos[3 * j] - prev[3 * j];
          double dy = pos[3 * j + 1] - prev[3 * j + 1];
          double dz = pos[3 * j + 2] - prev[3 * j + 2];
          double d = sqrt(dx * dx + dy * dy + dz * dz);
          if (d > worst) {
            worst = d;
            where = g->strings + cl->name;
          }
        }
      }
      memcpy(prev, pos, sizeof(float) * 3 * J);
    }
  }
  printf("largest joint movement relative to the hips in one frame: %.3f m "
         "(%s)\n", worst, where);
  assert_true(worst <= 0.5);
  free(names);
  free(parents);
  free(offsets);
  free(pose);
  free(pos);
  free(prev);
}

/* The blob's bones are the first clip's, in metres. */
static void check_bones(const smgi_graph_data* g, const char* first_clip) {
  smgb_clip c;
  smgb_error err;
  uint32_t j;
  if (smgb_bvh_load(first_clip, 0.01f, 0, &c, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_int_equal(g->joint_count, c.skeleton.joint_count);
  assert_string_equal(g->strings + g->joints[0].name, "Hips");
  for (j = 1; j < g->joint_count; ++j) {
    const float* a = g->joints[j].offset;
    const float* b = c.skeleton.offsets[j];
    float la = sqrtf(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    float lb = sqrtf(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    assert_string_equal(g->strings + g->joints[j].name, c.skeleton.names[j]);
    assert_float_equal(la, lb, 1e-5f);
  }
  /* Leg length (hip to ankle) of an adult in metres, not centimetres. */
  assert_true(g->info->leg_length > 0.6f && g->info->leg_length < 1.1f);
  smgb_clip_free(&c);
}

static void check_labels(const smgi_graph_data* g) {
  uint32_t e, w2x = 0, x2w = 0;
  assert_int_equal(g->style_count, 3);
  assert_string_equal(g->strings + g->styles[0].name, "walk");
  assert_string_equal(g->strings + g->styles[1].name, "run");
  assert_string_equal(g->strings + g->styles[2].name, "exhausted");
  assert_int_equal(g->action_count, 3);
  assert_string_equal(g->strings + g->actions[1].name, "wave");
  assert_string_equal(g->strings + g->actions[2].name, "raise");
  for (e = 0; e < g->lower_edge_count; ++e) {
    uint32_t a = g->lower_nodes[g->lower_edges[e].from].label;
    uint32_t b = g->lower_nodes[g->lower_edges[e].to].label;
    w2x += a == 0 && b == 2;
    x2w += a == 2 && b == 0;
  }
  printf("walk -> exhausted %u, exhausted -> walk %u transitions\n", w2x, x2w);
  assert_true(w2x >= 1 && x2w >= 1);
  assert_true(g->splice_count > 0);
}

static void test_bandai_set(void** state) {
  const char* dir = bandai_dir();
  char manifest[1200], first[1400];
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc* descs;
  smg_bake_desc d;
  smg_bake_result res;
  smgi_graph_data g;
  uint32_t i, n;
  (void)state;
  if (!dir) {
    skip();
    return;
  }
  snprintf(manifest, sizeof manifest, "%s/../data/bandai.manifest",
           SMG_BUILD_DIR);
  if (smgb_manifest_load(manifest, dir, &m, &err) != SMG_OK)
    fail_msg("%s", err.message);
  descs = calloc(m.clip_count, sizeof *descs);
  assert_non_null(descs);
  assert_int_equal(smgb_manifest_descs(&m, descs, m.clip_count), SMG_OK);
  n = m.clip_count;
  if (smgt_quick()) {
    /* One clip per label, no mirrors: the first walk, turn, run,
     * exhausted walk and each action. */
    static const char* const keep[] = {"walk_normal_001", "turn-left_normal_001",
                                       "run_normal_001", "walk_exhausted_001",
                                       "wave-right-hand", "raise-up-right-hand"};
    uint32_t k = 0;
    for (i = 0; i < m.clip_count; ++i) {
      size_t q;
      for (q = 0; q < sizeof keep / sizeof keep[0]; ++q)
        if (strstr(descs[i].path, keep[q])) {
          descs[k] = descs[i];
          descs[k].mirror = SMG_BAKE_MIRROR_NO;
          ++k;
          break;
        }
    }
    n = k;
  }
  snprintf(first, sizeof first, "%s", descs[0].path);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = n;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  if (smg_bake_run(&d, &res) != SMG_OK) fail_msg("bake: %s", res.error);
  bg_read(&res, &g);
  printf("Bandai Namco %s set: %u clips, lower %u nodes / %u edges, upper "
         "%u / %u, %u splices\n", smgt_quick() ? "quick" : "manifest", n,
         g.lower_node_count, g.lower_edge_count, g.upper_node_count,
         g.upper_edge_count, g.splice_count);
  check_bones(&g, first);
  check_labels(&g);
  check_smooth(&g);
  check_feet(&g);
  smg_bake_result_free(&res);
  free(descs);
  smgb_manifest_free(&m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bandai_set),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
