/*
 * test_pose.c - pose composition alone (pose.c), through its job
 * interface: the pose buffers, a lower timeline and an upper-body state
 * the test sets up by hand on the fixture graph. No character, no
 * planner, no steering.
 *  - the lower body: root and ground placement interpolated between the
 *    two frames around the playhead, each placed with its queue entry's
 *    transform (across an edge boundary the next entry's), joint
 *    rotations sampled at the playhead, contacts of the nearer frame;
 *  - a dead end (no next entry) holds the edge's last frame;
 *  - an action replaces the upper-body joints with the upper body's
 *    sample and leaves the others;
 *  - a crossfade blends from the snapshot with a smoothstep weight.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "pose.h"
#include "rmath.h"
#include "runtime/stage_testutil.h"
#include "upper.h"

#define J FIXTURE_JOINTS
#define TOL 1e-5f

typedef rt_fixture_ctx ctx;

typedef struct pose_rig {
  stage_rig r;
  float rot[4u * J], wpos[3u * J], wrot[4u * J], snap[4u * J];
  smgi_pose pose;
  smgi_upper u;
} pose_rig;

static void rig(pose_rig* x, const smg_graph* g) {
  memset(x, 0, sizeof *x);
  stage_rig_init(&x->r, g);
  x->pose.rot = x->rot;
  x->pose.wpos = x->wpos;
  x->pose.wrot = x->wrot;
  x->u.snap = x->snap;
  x->u.fade = 1.0f;
  x->u.fade_rate = 4.0f;
}

/* Root position and ground (x, z, heading) of frame f placed with M. */
static void placed(const smg_graph* g, uint32_t f, smgi_xform2 M, float* root,
                   float* ground) {
  float p[3];
  smgi_pose_root(smgi_graph_pose(g, f), p);
  smgi_xf_point(M, p[0], p[2], &root[0], &root[2]);
  root[1] = p[1] - g->data.info->ground_height;
  const float* r = g->data.frames[f].root2d;
  smgi_xf_point(M, r[0], r[1], &ground[0], &ground[1]);
  ground[2] = M.h + r[2];
}

static void test_lower_between_frames(void** state) {
  ctx* c = (ctx*)*state;
  static pose_rig x;
  rig(&x, c->g);
  const smgi_xform2 W = {1.0f, 2.0f, 0.5f};
  stage_rig_push(&x.r, 1u, W); /* walk left, frames [30, 60) */
  x.r.lower.t = 4.25f;
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  const smgi_qentry* q = smgi_q_at_c(&x.r.lower, 0);
  const uint32_t fa = 30u + 4u, fb = fa + 1u;
  float ra[3], rb[3], ga[3], gb[3];
  placed(c->g, fa, q->M, ra, ga);
  placed(c->g, fb, q->M, rb, gb);
  for (int k = 0; k < 3; ++k)
    assert_true(fabsf(x.pose.root[k] - (ra[k] + 0.25f * (rb[k] - ra[k]))) < TOL);
  assert_true(fabsf(x.pose.ground[0] - (ga[0] + 0.25f * (gb[0] - ga[0]))) < TOL);
  assert_true(fabsf(x.pose.ground[1] - (ga[1] + 0.25f * (gb[1] - ga[1]))) < TOL);
  assert_true(fabsf(smgi_wrap_angle(
                  x.pose.heading -
                  (ga[2] + 0.25f * smgi_wrap_angle(gb[2] - ga[2])))) < TOL);
  /* the joints: the two records' nlerp at 0.25 */
  float want[4u * J];
  smgi_sample_joints(c->g, smgi_graph_pose(c->g, fa), smgi_graph_pose(c->g, fb),
                     0.25f, SMGI_JOINTS_ALL, want);
  assert_memory_equal(x.rot + 4, want + 4, sizeof(float) * 4u * (J - 1u));
  /* contacts of the nearer frame */
  const uint32_t fl = c->g->data.frames[fa].flags;
  assert_int_equal((x.pose.contacts & SMG_STATE_LEFT_CONTACT) != 0,
                   (fl & SMGI_FRAME_LEFT_CONTACT) != 0);
  assert_int_equal((x.pose.contacts & SMG_STATE_RIGHT_CONTACT) != 0,
                   (fl & SMGI_FRAME_RIGHT_CONTACT) != 0);
}

static void test_across_edges(void** state) {
  ctx* c = (ctx*)*state;
  static pose_rig x;
  rig(&x, c->g);
  const smgi_xform2 W0 = {0.0f, 0.0f, 0.0f};
  const smgi_xform2 W1 = {-3.0f, 5.0f, 1.0f}; /* far from W0's end */
  stage_rig_push(&x.r, 0u, W0);
  x.r.lower.t = 29.5f; /* half way from the last frame to the next edge */
  /* alone: the last frame is held */
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  float ra[3], ga[3], rb[3], gb[3];
  placed(c->g, 29u, smgi_q_at_c(&x.r.lower, 0)->M, ra, ga);
  for (int k = 0; k < 3; ++k) assert_true(fabsf(x.pose.root[k] - ra[k]) < TOL);
  /* with a next entry: towards its first frame, placed with its own M */
  stage_rig_push(&x.r, 0u, W1);
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  placed(c->g, 0u, smgi_q_at_c(&x.r.lower, 1)->M, rb, gb);
  for (int k = 0; k < 3; ++k)
    assert_true(fabsf(x.pose.root[k] - (ra[k] + 0.5f * (rb[k] - ra[k]))) < TOL);
  assert_true(fabsf(x.pose.ground[0] - (ga[0] + 0.5f * (gb[0] - ga[0]))) < TOL);
}

/* joints of the upper body (SMG_BODY_UPPER) */
static int is_upper(const smg_graph* g, uint32_t j) {
  return j > 0 && g->data.joints[j].body_part == SMG_BODY_UPPER;
}

static void test_action_and_crossfade(void** state) {
  ctx* c = (ctx*)*state;
  static pose_rig x;
  rig(&x, c->g);
  const smgi_xform2 W = {0.0f, 0.0f, 0.0f};
  stage_rig_push(&x.r, 0u, W);
  x.r.lower.t = 10.0f;
  /* the lower body's own pose first */
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  float own[4u * J];
  memcpy(own, x.rot, sizeof own);
  /* an action playing, fully faded in */
  x.u.action = 1u;
  x.u.edge = 0u;
  x.u.next = 1u;
  x.u.t = 6.0f;
  smgi_q_yaw(0.0f, x.u.correction);
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  float action[4u * J];
  memset(action, 0, sizeof action);
  smgi_upper_sample(&x.u, c->g, action);
  int upper_seen = 0, differs = 0;
  for (uint32_t j = 1; j < J; ++j) {
    if (is_upper(c->g, j)) {
      upper_seen = 1;
      assert_memory_equal(x.rot + 4u * j, action + 4u * j, 16u);
      if (memcmp(own + 4u * j, action + 4u * j, 16u) != 0) differs = 1;
    } else {
      assert_memory_equal(x.rot + 4u * j, own + 4u * j, 16u);
    }
  }
  assert_true(upper_seen && differs); /* the action changed something */
  /* a quarter through a crossfade from the identity: weight
   * smoothstep(0.25) = 0.15625 */
  for (uint32_t j = 0; j < J; ++j) smgi_q_yaw(0.0f, x.snap + 4u * j);
  x.u.fade = 0.25f;
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  for (uint32_t j = 1; j < J; ++j) {
    if (!is_upper(c->g, j)) continue;
    float q[4];
    smgi_q_nlerp(x.snap + 4u * j, action + 4u * j, 0.15625f, q);
    for (int k = 0; k < 4; ++k) assert_true(fabsf(x.rot[4u * j + k] - q[k]) < TOL);
  }
  /* at the start of the crossfade: the snapshot */
  x.u.fade = 0.0f;
  smgi_pose_compose(&x.pose, &x.r.lower, &x.u, c->g);
  for (uint32_t j = 1; j < J; ++j)
    if (is_upper(c->g, j))
      for (int k = 0; k < 4; ++k)
        assert_true(fabsf(x.rot[4u * j + k] - x.snap[4u * j + k]) < TOL);
}

/* Sampling through the decoded-record slots (smgi_sample_frames, what the
 * pose samples with) gives smgi_sample_joints' bits for any sequence of
 * frame pairs: advancing as playback does (each pair on two steps), the
 * two ends swapped or equal, jumps (a re-plan, a new edge), every joint
 * set; joints outside the set are left alone. */
static void test_decoded_records_sample_the_same(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  if (!g) {
    fail_msg("build/default.smg missing: run `make` first");
    return;
  }
  const uint32_t nj = g->data.joint_count, frames = g->data.frame_count;
  const uint32_t n = smgi_decoded_floats(nj);
  float* buf = (float*)malloc(sizeof(float) * (2u * n + 1u));
  float* ref = (float*)malloc(sizeof(float) * 4u * nj);
  float* got = (float*)malloc(sizeof(float) * 4u * nj);
  assert_non_null(buf);
  assert_non_null(ref);
  assert_non_null(got);
  smgi_decoded dec;
  dec.rot = n ? buf : NULL;
  dec.frame[0] = dec.frame[1] = SMGI_NONE;
  uint32_t rng = 99u, f = 0u;
  for (uint32_t it = 0; it < 20000u; ++it) {
    const uint32_t r = smgi_xorshift(&rng);
    if (it % 2u == 0u) f = (f + 1u) % (frames - 1u); /* playback */
    if (r % 17u == 0u) f = (r >> 8) % (frames - 1u);  /* a jump */
    uint32_t fa = f, fb = f + 1u;
    if (r % 13u == 0u) fb = fa;                      /* a dead end */
    if (r % 11u == 0u) {                             /* swapped */
      fa = f + 1u;
      fb = f;
    }
    const float t = (r % 7u == 0u) ? 0.0f
                    : (r % 7u == 1u) ? 1.0f
                                     : (float)((r >> 12) % 1000u) / 1000.0f;
    const smgi_joint_set set = (smgi_joint_set)((r >> 4) % 3u);
    for (uint32_t k = 0; k < 4u * nj; ++k) ref[k] = got[k] = (float)k;
    smgi_sample_joints(g, smgi_graph_pose(g, fa), smgi_graph_pose(g, fb), t,
                       set, ref);
    smgi_sample_frames(g, fa, fb, t, set, &dec, got);
    if (memcmp(ref, got, sizeof(float) * 4u * nj) != 0)
      fail_msg("step %u: frames %u, %u at %g (set %d) differ", (unsigned)it,
               (unsigned)fa, (unsigned)fb, (double)t, (int)set);
  }
  free(buf);
  free(ref);
  free(got);
  smg_graph_destroy(g);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_lower_between_frames),
      cmocka_unit_test(test_across_edges),
      cmocka_unit_test(test_action_and_crossfade),
      cmocka_unit_test(test_decoded_records_sample_the_same),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
