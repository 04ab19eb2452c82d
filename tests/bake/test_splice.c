/*
 * test_splice.c - splice candidates of a synthetic bake: sorted as
 * smg_format.h says, every action reachable within 1 s of every locomotion
 * frame, indices that point where they claim (lower frame on an original
 * lower edge; upper_edge/upper_offset on an original upper edge of the same
 * action), unit corrections, and a correction that keeps the action's
 * torso posture relative to the pelvis (it only turns it about the pelvis's
 * up axis).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_math.h"
#include "quat_pack.h"

static bg_set g_set;
static smg_bake_result g_res;
static smgi_graph_data g_g;

static int setup(void** state) {
  (void)state;
  bg_standard(&g_set, smgt_quick() ? 3.0f : 6.0f);
  if (bg_bake(&g_set, NULL, &g_res) != SMG_OK) {
    fprintf(stderr, "bake failed: %s\n", g_res.error);
    return -1;
  }
  if (smgi_blob_read(g_res.blob, g_res.blob_size, 0, &g_g, NULL, 0) != SMG_OK)
    return -1;
  return 0;
}

static int teardown(void** state) {
  (void)state;
  smg_bake_result_free(&g_res);
  bg_free(&g_set);
  return 0;
}

static void test_sorted_and_valid(void** state) {
  const smgi_graph_data* g = &g_g;
  uint32_t i, per_action[8] = {0};
  (void)state;
  assert_true(g->splice_count > 0);
  for (i = 0; i < g->splice_count; ++i) {
    const smgi_splice* s = &g->splices[i];
    const smgi_edge* ue = &g->upper_edges[s->upper_edge];
    uint32_t uf = ue->first_frame + s->upper_offset, e;
    int on_lower = 0;
    const float* q = s->correction;
    if (i > 0) {
      const smgi_splice* p = &g->splices[i - 1];
      assert_true(p->lower_frame < s->lower_frame ||
                  (p->lower_frame == s->lower_frame &&
                   (p->action < s->action ||
                    (p->action == s->action && p->distance <= s->distance))));
    }
    assert_true(s->action >= 1 && s->action < g->action_count);
    per_action[s->action < 8 ? s->action : 7]++;
    assert_false(ue->flags & SMGI_EDGE_TRANSITION);
    assert_int_equal(g->upper_nodes[ue->from].label, s->action);
    assert_int_equal(g->clips[g->frames[uf].clip].label, s->action);
    assert_true(g->clips[g->frames[uf].clip].flags & SMGI_CLIP_UPPER);
    for (e = 0; e < g->lower_edge_count && !on_lower; ++e) {
      const smgi_edge* le = &g->lower_edges[e];
      on_lower = !(le->flags & SMGI_EDGE_TRANSITION) &&
                 s->lower_frame >= le->first_frame &&
                 s->lower_frame < le->first_frame + le->frame_count;
    }
    assert_true(on_lower);
    assert_true(fabs(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] -
                     1.0) < 1e-5);
    assert_true(s->distance >= 0.0f && isfinite(s->distance));
  }
  assert_true(per_action[1] > 0 && per_action[2] > 0);
}

/* Every action within 1 s (same clip) of every lower frame on an edge. */
static void test_coverage(void** state) {
  const smgi_graph_data* g = &g_g;
  uint32_t e, a, f, worst = 0;
  (void)state;
  assert_true(g_res.stats.splice_coverage >= 0.999f);
  for (e = 0; e < g->lower_edge_count; ++e) {
    const smgi_edge* le = &g->lower_edges[e];
    if (le->flags & SMGI_EDGE_TRANSITION) continue;
    for (f = le->first_frame; f < le->first_frame + le->frame_count; ++f) {
      uint32_t clip = g->frames[f].clip;
      for (a = 1; a < g->action_count; ++a) {
        uint32_t best = UINT32_MAX, i;
        for (i = 0; i < g->splice_count; ++i) {
          const smgi_splice* s = &g->splices[i];
          uint32_t d;
          if (s->action != a || g->frames[s->lower_frame].clip != clip)
            continue;
          d = s->lower_frame > f ? s->lower_frame - f : f - s->lower_frame;
          if (d < best) best = d;
        }
        if (best > worst) worst = best;
      }
    }
  }
  assert_true(worst <= (uint32_t)lround(g->info->frame_rate));
}

/* Torso points (spine chain, neck, head, shoulders) relative to the spine
 * base in the pelvis frame, with the spine base's local rotation replaced by
 * `spine` (NULL: as stored). */
static void torso(const smgi_graph_data* g, const smgb_skeleton* sk,
                  uint32_t frame, const double* corr, double* out,
                  uint32_t* count) {
  uint32_t J = g->joint_count, j, sb = g->info->spine_base_joint, n = 0;
  float pose[3 + 4 * 64], pos[3 * 64];
  smgi_pose_unpack(smgi_pose_record(g, frame), J, pose);
  /* pelvis at the origin, identity: positions come out in pelvis space */
  pose[0] = pose[1] = pose[2] = 0.0f;
  pose[3] = pose[4] = pose[5] = 0.0f;
  pose[6] = 1.0f;
  if (corr) {
    double q[4], r[4];
    float* s = pose + 3 + 4 * sb;
    q[0] = s[0]; q[1] = s[1]; q[2] = s[2]; q[3] = s[3];
    smgb_q_mul(corr, q, r);
    s[0] = (float)r[0]; s[1] = (float)r[1]; s[2] = (float)r[2];
    s[3] = (float)r[3];
  }
  smgb_fk(sk, pose, pos, NULL);
  for (j = 0; j < J; ++j) {
    const char* nm = sk->names[j];
    if (g->joints[j].body_part != SMG_BODY_UPPER || j == sb) continue;
    if (strstr(nm, "Fore") || strstr(nm, "Hand") || strstr(nm, "Finger") ||
        strstr(nm, "Thumb"))
      continue;
    out[3 * n] = pos[3 * j] - pos[3 * sb];
    out[3 * n + 1] = pos[3 * j + 1] - pos[3 * sb + 1];
    out[3 * n + 2] = pos[3 * j + 2] - pos[3 * sb + 2];
    ++n;
  }
  *count = n;
}

/* The splice reproduces the action's upper body relative to the pelvis:
 * the correction only turns it about the pelvis's up axis (towards where
 * the action faced relative to its direction of travel), so the spliced
 * torso, in the pelvis frame, stays within a few centimetres of the
 * action's own at every candidate (the bend is never replaced by the
 * locomotion's). */
static void test_correction_keeps_action_posture(void** state) {
  const smgi_graph_data* g = &g_g;
  smgb_skeleton sk;
  uint32_t i, j, n, m, J = g->joint_count;
  double worst = 0.0, sum = 0.0;
  (void)state;
  memset(&sk, 0, sizeof sk);
  sk.joint_count = J;
  sk.names = calloc(J, sizeof *sk.names);
  sk.parents = calloc(J, sizeof *sk.parents);
  sk.offsets = calloc(J, sizeof *sk.offsets);
  for (j = 0; j < J; ++j) {
    snprintf(sk.names[j], SMGB_NAME_MAX, "%s", g->strings + g->joints[j].name);
    sk.parents[j] = g->joints[j].parent;
    memcpy(sk.offsets[j], g->joints[j].offset, sizeof sk.offsets[j]);
  }
  assert_true(g->splice_count > 0);
  for (i = 0; i < g->splice_count; ++i) {
    const smgi_splice* s = &g->splices[i];
    uint32_t uf = g->upper_edges[s->upper_edge].first_frame + s->upper_offset;
    double corr[4], a0[3 * 64], a1[3 * 64], e = 0.0;
    corr[0] = s->correction[0]; corr[1] = s->correction[1];
    corr[2] = s->correction[2]; corr[3] = s->correction[3];
    torso(g, &sk, uf, NULL, a0, &n);
    torso(g, &sk, uf, corr, a1, &m);
    assert_int_equal(n, m);
    for (j = 0; j < n; ++j)
      e += sqrt((a1[3 * j] - a0[3 * j]) * (a1[3 * j] - a0[3 * j]) +
                (a1[3 * j + 1] - a0[3 * j + 1]) *
                    (a1[3 * j + 1] - a0[3 * j + 1]) +
                (a1[3 * j + 2] - a0[3 * j + 2]) *
                    (a1[3 * j + 2] - a0[3 * j + 2]));
    e /= (double)n;
    sum += e;
    if (e > worst) worst = e;
  }
  printf("spliced torso vs the action's own, pelvis frame, over %u "
         "splices: mean %.2f cm, worst %.2f cm\n", g->splice_count,
         100.0 * sum / g->splice_count, 100.0 * worst);
  /* the correction fitted onto the locomotion's torso (before) was 0.9 cm
   * mean / 1.9 cm worst here */
  assert_true(sum / g->splice_count < 0.003);
  assert_true(worst < 0.01);
  smgb_skeleton_free(&sk);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_sorted_and_valid),
      cmocka_unit_test(test_coverage),
      cmocka_unit_test(test_correction_keeps_action_posture),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
