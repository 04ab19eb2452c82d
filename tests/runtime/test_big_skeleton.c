/*
 * test_big_skeleton.c - a skeleton larger than the pose scratch that
 * smgi_pose_compose keeps on the stack (SMGI_POSE_STACK_JOINTS = 64): the
 * synthetic 31-joint clips get 40 more joints (two finger-like chains under
 * the hands, animated), are baked in-process, and a character walks a
 * turning path while its action switches on and off (crossfades through
 * the heap scratch ch->tmp). Every step's pose must be finite, every
 * model matrix must equal forward kinematics of the reported local pose
 * (so the extra chains follow their hands), the action must switch, and
 * create/destroy must balance through the allocator hooks.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "bake_synthetic.h"
#include "runtime/runtime_testutil.h"
#include "smg_bake.h"

#define EXTRA 40u   /* joints added to the 31-joint synthetic skeleton */
#define MAXJ 96u
#define NCLIPS 3u

typedef struct big_clip {
  smgb_clip src;
  char names[MAXJ][SMGB_NAME_MAX];
  const char* name_ptr[MAXJ];
  int32_t parents[MAXJ];
  float offsets[MAXJ][3];
  float* poses;
  smg_bake_memory_clip mem;
} big_clip;

static uint32_t find_name(const smgb_clip* c, const char* name) {
  for (uint32_t j = 0; j < c->skeleton.joint_count; ++j)
    if (strcmp(c->skeleton.names[j], name) == 0) return j;
  fail_msg("synthetic skeleton has no %s", name);
  return 0;
}

/* The synthetic clip plus two 20-joint chains hanging from the hands,
 * curling a little with time (so their rotations are sampled, blended and
 * crossfaded like any other upper-body joint). */
static void make_big(smgb_synth_kind kind, float turn, big_clip* b) {
  smgb_synth_params p;
  memset(&p, 0, sizeof p);
  p.kind = kind;
  p.duration = 4.0f;
  p.frame_rate = 30.0f;
  p.turn_rate = turn;
  assert_int_equal(smgb_synth_generate(&p, &b->src, NULL), SMG_OK);
  const smgb_clip* c = &b->src;
  const uint32_t J0 = c->skeleton.joint_count, J = J0 + EXTRA;
  assert_true(J <= MAXJ && J > 64u);
  const uint32_t hands[2] = {find_name(c, "LeftHand"),
                             find_name(c, "RightHand")};
  for (uint32_t j = 0; j < J; ++j) {
    if (j < J0) {
      snprintf(b->names[j], SMGB_NAME_MAX, "%s", c->skeleton.names[j]);
      b->parents[j] = c->skeleton.parents[j];
      memcpy(b->offsets[j], c->skeleton.offsets[j], sizeof b->offsets[j]);
    } else {
      const uint32_t k = j - J0, side = k / (EXTRA / 2u);
      snprintf(b->names[j], SMGB_NAME_MAX, "Extra%02u", (unsigned)k);
      b->parents[j] = k % (EXTRA / 2u) == 0 ? (int32_t)hands[side]
                                            : (int32_t)(j - 1u);
      b->offsets[j][0] = side ? -0.01f : 0.01f;
      b->offsets[j][1] = -0.005f;
      b->offsets[j][2] = 0.0f;
    }
    b->name_ptr[j] = b->names[j];
  }
  const uint32_t s0 = SMGB_STRIDE(J0), s1 = SMGB_STRIDE(J);
  b->poses = (float*)malloc(sizeof(float) * s1 * c->frame_count);
  assert_non_null(b->poses);
  for (uint32_t f = 0; f < c->frame_count; ++f) {
    float* o = b->poses + (size_t)s1 * f;
    memcpy(o, c->poses + (size_t)s0 * f, sizeof(float) * s0);
    const float a = 0.05f * sinf(0.2f * (float)f); /* half-angle */
    for (uint32_t k = 0; k < EXTRA; ++k) {
      float* q = o + s0 + 4u * k;
      q[0] = 0.0f;
      q[1] = 0.0f;
      q[2] = sinf(a);
      q[3] = cosf(a);
    }
  }
  memset(&b->mem, 0, sizeof b->mem);
  b->mem.joint_count = J;
  b->mem.joint_names = b->name_ptr;
  b->mem.parents = b->parents;
  b->mem.offsets = &b->offsets[0][0];
  b->mem.poses = b->poses;
  b->mem.frame_count = c->frame_count;
  b->mem.frame_rate = c->frame_rate;
}

static void free_big(big_clip* b) {
  free(b->poses);
  smgb_clip_free(&b->src);
}

static void test_big_skeleton(void** state) {
  (void)state;
  static big_clip clips[NCLIPS];
  make_big(SMGB_SYNTH_WALK, 0.0f, &clips[0]);
  make_big(SMGB_SYNTH_WALK, 0.4f, &clips[1]);
  make_big(SMGB_SYNTH_PUNCH, 0.0f, &clips[2]);
  smg_bake_clip_desc descs[NCLIPS];
  const char* labels[NCLIPS] = {"walk", "walk", "punch"};
  for (uint32_t i = 0; i < NCLIPS; ++i) {
    memset(&descs[i], 0, sizeof descs[i]);
    descs[i].struct_size = sizeof descs[i];
    descs[i].role = i < 2u ? SMG_BAKE_ROLE_LOWER : SMG_BAKE_ROLE_UPPER;
    descs[i].memory = &clips[i].mem;
    descs[i].label = labels[i];
  }
  smg_bake_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = NCLIPS;
  smg_bake_result res;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  smg_result r = smg_bake_run(&d, &res);
  if (r != SMG_OK) fail_msg("bake: %s", res.error);

  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(res.blob, res.blob_size, NULL, &g),
                   SMG_OK);
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  const uint32_t J = info.joint_count;
  assert_int_equal(J, clips[0].mem.joint_count);
  assert_true(info.action_count >= 2u);
  int32_t parent[MAXJ];
  float offset[MAXJ][3];
  rt_skeleton(g, J, parent, offset);

  rt_counter counter = {0, 0};
  smg_character_desc cd;
  memset(&cd, 0, sizeof cd);
  cd.struct_size = sizeof cd;
  cd.allocator.alloc = rt_count_alloc;
  cd.allocator.free = rt_count_free;
  cd.allocator.user = &counter;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, &cd, &ch), SMG_OK);
  float xz[2 * 64];
  uint32_t n = rt_turn_r(xz, 4.0f, 8.0f, 1, 4.0f);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);

  static float rot[4u * MAXJ], mats[16u * MAXJ];
  float root[3], wpos[3u * MAXJ], wrot[4u * MAXJ];
  float max_dp = 0.0f;
  int punched = 0;
  const int steps = getenv("SMG_TEST_QUICK") ? 240 : 600;
  for (int i = 0; i < steps; ++i) {
    /* on, off, on: two crossfades each way */
    if (i % 120 == 20)
      assert_int_equal(smg_character_set_action(ch, (i / 120) % 2 ? 0u : 1u),
                       SMG_OK);
    assert_int_equal(smg_character_step(ch, 1.0f / 60.0f), SMG_OK);
    smg_character_state st;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    assert_int_equal(smg_character_get_state(ch, &st), SMG_OK);
    if (st.action == 1u) punched = 1;
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    assert_true(rt_pose_finite(root, rot, J));
    /* the added chains only ever curl about z by at most 0.05 rad (half
     * angle) in every clip, so sampling, blending and crossfading them
     * must keep them so: a wrong scratch buffer would not */
    for (uint32_t j = J - EXTRA; j < J; ++j) {
      const float* q = rot + 4u * j;
      assert_true(fabsf(q[0]) < 1e-3f && fabsf(q[1]) < 1e-3f);
      assert_true(fabsf(q[2]) < sinf(0.05f) + 1e-3f);
    }
    assert_int_equal(
        smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats, J),
        SMG_OK);
    rt_fk(J, parent, offset, root, rot, wpos, wrot);
    for (uint32_t j = 0; j < J; ++j)
      for (int k = 0; k < 3; ++k) {
        float dp = fabsf(mats[16u * j + 12u + (uint32_t)k] - wpos[3u * j + k]);
        if (dp > max_dp) max_dp = dp;
      }
  }
  print_message("%u joints: %d steps, max model-matrix vs FK position "
                "difference %.2g m\n",
                (unsigned)J, steps, (double)max_dp);
  assert_true(punched);
  /* rounding only (IK's own cache refresh included) */
  assert_true(max_dp < 1e-4f);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
  assert_int_equal(counter.allocs, counter.frees);
  assert_true(counter.allocs >= 1);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
  smg_bake_result_free(&res);
  for (uint32_t i = 0; i < NCLIPS; ++i) free_big(&clips[i]);
}

int main(void) {
  const struct CMUnitTest tests[] = {cmocka_unit_test(test_big_skeleton)};
  return cmocka_run_group_tests(tests, NULL, NULL);
}
