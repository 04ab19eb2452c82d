/*
 * test_pose_simd.c - the SSE2 forward kinematics and model-matrix math
 * (libsmg/runtime/pose_simd.h) against the plain C reference, and the
 * library's getters against a pose rebuilt from the public local pose.
 *
 * The SSE lanes do the reference's operations in the same order, so the
 * comparisons are exact (bit for bit), not within a tolerance: that is what
 * keeps the SSE and non-SSE builds' poses, and the evaluation's figures,
 * identical.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
/* cmocka after the standard headers it needs */
#include <cmocka.h>

#include "pose_simd.h"
#include "runtime/runtime_testutil.h"

#define MAXJ 64u

#if SMGI_POSE_SSE
static uint32_t rng = 12345u;
static float frand(float lo, float hi) {
  return lo + (hi - lo) * (float)(smgi_xorshift(&rng) >> 8) * (1.0f / 16777216.0f);
}

/* A random rotation, sometimes unnormalised or with exact zeros (the
 * identity, axis rotations) - the cases where a reordered sum or a lost
 * sign of zero would show. */
static void rand_quat(float* q) {
  for (int k = 0; k < 4; ++k) q[k] = frand(-1.0f, 1.0f);
  uint32_t r = smgi_xorshift(&rng) % 8u;
  if (r == 0) q[0] = q[1] = q[2] = 0.0f;
  if (r == 1) q[1] = q[2] = -0.0f;
  if (r < 6) smgi_q_normalize(q);
}
#endif

static void assert_same_bits(const float* a, const float* b, uint32_t n,
                             const char* what, uint32_t at) {
  if (memcmp(a, b, sizeof(float) * n) != 0) {
    for (uint32_t i = 0; i < n; ++i)
      if (memcmp(&a[i], &b[i], sizeof(float)) != 0)
        fail_msg("%s %u: float %u is %.9g, reference %.9g", what,
                 (unsigned)at, (unsigned)i, (double)a[i], (double)b[i]);
  }
}

static void test_joint_math(void** state) {
  (void)state;
#if SMGI_POSE_SSE
  for (uint32_t it = 0; it < 20000u; ++it) {
    float prot[4], lrot[4], ppos[4] = {0}, off[4] = {0};
    rand_quat(prot);
    rand_quat(lrot);
    for (int k = 0; k < 3; ++k) {
      ppos[k] = frand(-50.0f, 50.0f);
      off[k] = frand(-0.5f, 0.5f);
    }
    float pos_c[3], rot_c[4], pos_s[4] = {0, 0, 0, 0}, rot_s[4];
    smgi_fk_joint_c(prot, ppos, off, lrot, pos_c, rot_c);
    __m128 pos_out;
    __m128 r = smgi_fk_joint_sse(_mm_loadu_ps(prot), _mm_loadu_ps(ppos),
                                 _mm_loadu_ps(off), lrot, pos_s, rot_s,
                                 &pos_out);
    assert_same_bits(pos_s, pos_c, 3, "fk position", it);
    assert_same_bits(rot_s, rot_c, 4, "fk rotation", it);
    assert_true(pos_s[3] == 0.0f); /* exactly three floats written */
    float back[4];
    _mm_storeu_ps(back, r);
    assert_same_bits(back, rot_c, 4, "fk returned rotation", it);
    _mm_storeu_ps(back, pos_out);
    assert_same_bits(back, pos_c, 3, "fk returned position", it);
  }
  /* nlerp and normalisation (the pose's root, foot IK), also of
   * degenerate and non-finite quaternions */
  for (uint32_t it = 0; it < 20000u; ++it) {
    float a[4], b[4], ref[4], got[4];
    rand_quat(a);
    rand_quat(b);
    if (it % 50u == 0u) a[0] = a[1] = a[2] = a[3] = 0.0f;
    if (it % 50u == 1u) b[1] = INFINITY;
    if (it % 50u == 2u) b[0] = b[1] = b[2] = b[3] = 1e-12f;
    const float t = it % 7u == 0u ? 1.0f : frand(0.0f, 1.0f);
    smgi_q_nlerp(a, b, t, ref);
    _mm_storeu_ps(got, smgi_q_nlerp_sse(_mm_loadu_ps(a), _mm_loadu_ps(b), t));
    assert_same_bits(got, ref, 4, "nlerp", it);
    memcpy(ref, b, sizeof ref);
    smgi_q_normalize(ref);
    _mm_storeu_ps(got, smgi_q_normalize_sse(_mm_loadu_ps(b)));
    assert_same_bits(got, ref, 4, "normalize", it);
  }
  for (uint32_t it = 0; it < 5000u; ++it) {
    float q[16], p[12], m[64], ref[64], yaw[4];
    for (int k = 0; k < 4; ++k) rand_quat(q + 4 * k);
    for (int k = 0; k < 12; ++k) p[k] = frand(-100.0f, 100.0f);
    const float heading = frand(-3.2f, 3.2f), gx = frand(-90.0f, 90.0f),
                gz = frand(-90.0f, 90.0f);
    smgi_q_yaw(-heading, yaw);
    for (int world = 0; world < 2; ++world) {
      if (world)
        smgi_mat4_world_sse(q, p, m);
      else
        smgi_mat4_character_sse(q, p, _mm_loadu_ps(yaw),
                                _mm_setr_ps(gx, 0.0f, gz, 0.0f), m);
      for (int k = 0; k < 4; ++k) {
        if (world) {
          smgi_mat_from_c(q + 4 * k, p + 3 * k, ref + 16 * k);
        } else {
          float cq[4], v[3], cp[3];
          smgi_q_mul(yaw, q + 4 * k, cq);
          v[0] = p[3 * k] - gx;
          v[1] = p[3 * k + 1];
          v[2] = p[3 * k + 2] - gz;
          smgi_q_rotate(yaw, v, cp);
          smgi_mat_from_c(cq, cp, ref + 16 * k);
        }
      }
      assert_same_bits(m, ref, 64, world ? "world matrices" : "character matrices", it);
    }
  }
#else
  print_message("SSE2 path not built (SMGI_POSE_SSE=0): nothing to compare\n");
#endif
}

/* The getters after each step against FK + matrices recomputed here from
 * the public local pose and joint table with the plain math: the world
 * cache written by the step's FK must be exactly what the local pose
 * implies, in both spaces. Foot IK is off: at full weight it refreshes the
 * legs' cache from its own solve, equal to FK only to rounding (that is
 * held to a tolerance by test_ik.c). */
static void test_getters_match_local_pose(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  if (!g) {
    fail_msg("build/default.smg missing: run `make` first");
    return;
  }
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  const uint32_t J = info.joint_count;
  assert_true(J >= 2u && J <= MAXJ);
  int32_t parent[MAXJ];
  float offset[MAXJ][3];
  rt_skeleton(g, J, parent, offset);
  smg_character* ch = NULL;
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = 7;
  d.heading = 0.4f;
  d.flags = SMG_CHARACTER_NO_IK;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  float xz[2 * 64];
  for (uint32_t i = 0; i < 64u; ++i) {
    xz[2 * i] = 3.0f * sinf(0.2f * (float)i);
    xz[2 * i + 1] = 0.5f * (float)i;
  }
  assert_int_equal(smg_character_set_path(ch, xz, 64), SMG_OK);
  const uint32_t steps = smgt_quick() ? 60u : 400u;
  static float m[16u * MAXJ], ref[16u * MAXJ], rot[4u * MAXJ];
  float root[3], wpos[3u * MAXJ], wrot[4u * MAXJ];
  for (uint32_t s = 0; s < steps; ++s) {
    /* actions on and off: crossfades, spliced upper bodies */
    if (s % 100u == 20u && info.action_count > 1u)
      assert_int_equal(smg_character_set_action(ch, 1u + (s / 100u) % (info.action_count - 1u)), SMG_OK);
    if (s % 100u == 70u) assert_int_equal(smg_character_set_action(ch, 0), SMG_OK);
    assert_int_equal(smg_character_step(ch, 1.0f / 60.0f), SMG_OK);
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    memcpy(wpos, root, sizeof root);
    memcpy(wrot, rot, sizeof(float) * 4u);
    for (uint32_t j = 1; j < J; ++j) {
      const uint32_t p = (uint32_t)parent[j];
      smgi_fk_joint_c(wrot + 4u * p, wpos + 3u * p, offset[j], rot + 4u * j,
                      wpos + 3u * j, wrot + 4u * j);
    }
    assert_int_equal(
        smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, m, J), SMG_OK);
    for (uint32_t j = 0; j < J; ++j)
      smgi_mat_from_c(wrot + 4u * j, wpos + 3u * j, ref + 16u * j);
    assert_same_bits(m, ref, 16u * J, "world matrices at step", s);

    smg_character_state st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    assert_int_equal(smg_character_get_state(ch, &st), SMG_OK);
    float yaw[4];
    smgi_q_yaw(-st.heading, yaw);
    for (uint32_t j = 0; j < J; ++j) {
      float q[4], v[3], p[3];
      smgi_q_mul(yaw, wrot + 4u * j, q);
      v[0] = wpos[3u * j] - st.position[0];
      v[1] = wpos[3u * j + 1u];
      v[2] = wpos[3u * j + 2u] - st.position[2];
      smgi_q_rotate(yaw, v, p);
      smgi_mat_from_c(q, p, ref + 16u * j);
    }
    assert_int_equal(
        smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, m, J),
        SMG_OK);
    assert_same_bits(m, ref, 16u * J, "character matrices at step", s);
  }
  smg_character_destroy(ch);
  smg_graph_destroy(g);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_joint_math),
      cmocka_unit_test(test_getters_match_local_pose),
  };
  return cmocka_run_group_tests_name("pose_simd", tests, NULL, NULL);
}
