/*
 * test_upper.c - the upper body alone (upper.c), through its job
 * interface: its state, the fixture graph (one action, "punch": upper
 * edges e0 0->1 of 15 frames and e1 1->0 of 15; splice candidates at
 * lower frames 0 and 15), a lower timeline the test fills and the step's
 * inputs. No character, no pose composition.
 *  - start: the action's first edge, no crossfade;
 *  - advance: the playhead moves by lower frames times the sync rate and
 *    carries over into the connected next edge; the crossfade moves by dt
 *    at the window's rate and stops at 1;
 *  - a splice point schedules the best candidate among the lower frames
 *    coming up and switches when the playhead reaches it (reported, with
 *    the shown pose snapped for the crossfade); without the point the
 *    upper body goes back to action 0 at once;
 *  - a re-plan that dropped the scheduled entry forgets the switch;
 *  - sampling writes the upper joints only, with the Horn correction on
 *    the spine base.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "graph_derived.h"
#include "rmath.h"
#include "runtime/stage_testutil.h"
#include "upper.h"

#define PUNCH 1u

typedef rt_fixture_ctx ctx;

typedef struct upper_rig {
  stage_rig r;
  float snap[4u * FIXTURE_JOINTS];
  float shown[4u * FIXTURE_JOINTS];
  smgi_upper u;
  uint32_t rng;
} upper_rig;

static void rig(upper_rig* x, const smg_graph* g) {
  memset(x, 0, sizeof *x);
  stage_rig_init(&x->r, g);
  const smgi_xform2 I = {0.0f, 0.0f, 0.0f};
  for (int i = 0; i < 4; ++i) stage_rig_push(&x->r, 0u, I); /* walks */
  float xz[2 * 21];
  rt_line(xz, 21, 20.0f);
  stage_rig_path(&x->r, xz, 21, 0.0f, 0.0f);
  for (uint32_t j = 0; j < FIXTURE_JOINTS; ++j) {
    const float q[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    memcpy(x->shown + 4u * j, q, sizeof q);
    x->shown[4u * j] = 0.01f * (float)j; /* recognisable */
  }
  x->u.snap = x->snap;
  x->u.fade_rate = 4.0f;
  x->rng = 1u;
}

static void test_start_and_advance(void** state) {
  ctx* c = (ctx*)*state;
  static upper_rig x;
  rig(&x, c->g);
  const smgi_edge* ue = c->g->data.upper_edges;
  smgi_upper_start(&x.u, c->g, &x.rng, x.shown, PUNCH);
  assert_int_equal(x.u.action, PUNCH);
  assert_int_equal(x.u.edge, smgi_derived_of(c->g)->action_first_edge[PUNCH]);
  assert_true(x.u.fade == 1.0f && x.u.t == 0.0f);
  const uint32_t first = x.u.edge;
  /* 5 lower frames at rate 1, then 4 at rate 0.5 */
  assert_int_equal(smgi_upper_advance(&x.u, c->g, &x.rng, x.shown, 5.0f,
                                      1.0f, 1.0f / 60.0f),
                   0);
  assert_true(fabsf(x.u.t - 5.0f) < 1e-6f);
  smgi_upper_advance(&x.u, c->g, &x.rng, x.shown, 4.0f, 0.5f, 1.0f / 60.0f);
  assert_true(fabsf(x.u.t - 7.0f) < 1e-6f);
  /* past the edge's end: into the next, which starts where it ended */
  const uint32_t fc = ue[first].frame_count;
  smgi_upper_advance(&x.u, c->g, &x.rng, x.shown, (float)fc - 7.0f + 2.0f,
                     1.0f, 1.0f / 60.0f);
  assert_int_not_equal(x.u.edge, first);
  assert_int_equal(ue[x.u.edge].from, ue[first].to);
  assert_int_equal(x.u.node, ue[first].to);
  assert_true(fabsf(x.u.t - 2.0f) < 1e-5f);
  assert_int_equal(ue[x.u.edge].label, PUNCH);
  assert_int_equal(ue[x.u.next].from, ue[x.u.edge].to);
}

static void test_fade(void** state) {
  ctx* c = (ctx*)*state;
  static upper_rig x;
  rig(&x, c->g);
  smgi_upper_start(&x.u, c->g, &x.rng, x.shown, 0u);
  x.u.fade = 0.0f;
  smgi_upper_advance(&x.u, c->g, &x.rng, x.shown, 1.0f, 1.0f, 0.1f);
  assert_true(fabsf(x.u.fade - 0.4f) < 1e-6f); /* 0.1 s at 4 per second */
  smgi_upper_advance(&x.u, c->g, &x.rng, x.shown, 1.0f, 1.0f, 0.2f);
  assert_true(x.u.fade == 1.0f);
}

static void test_splice_point(void** state) {
  ctx* c = (ctx*)*state;
  static upper_rig x;
  rig(&x, c->g);
  smgi_upper_start(&x.u, c->g, &x.rng, x.shown, 0u);
  assert_int_equal(smgi_constraints_add(&x.r.cons, x.r.path.length, 0.0f,
                                        SMGI_CONSTRAINT_SPLICE, PUNCH, NULL),
                   SMG_OK);
  /* scheduled, not yet switched */
  assert_int_equal(smgi_upper_update_splice(&x.u, &x.r.lower, &x.r.in,
                                            &x.rng, x.shown, 1.0f / 60.0f, 1),
                   0);
  assert_int_equal(x.u.action, 0);
  assert_true(x.u.pending.valid);
  const smgi_splice* sp = &c->g->data.splices[x.u.pending.splice];
  assert_int_equal(sp->action, PUNCH);
  /* the candidate is one of the frames coming up */
  const smgi_qentry* q = smgi_q_at_c(&x.r.lower, 0);
  assert_int_equal(x.u.pending.seq, q->seq);
  assert_true(x.u.pending.offset >= 1u &&
              x.u.pending.offset <= SMGI_SPLICE_WINDOW);
  assert_int_equal(c->g->data.lower_edges[q->edge].first_frame +
                       x.u.pending.offset,
                   sp->lower_frame);
  /* the playhead one frame short: still waiting */
  x.r.lower.t = (float)x.u.pending.offset - 1.0f;
  assert_int_equal(smgi_upper_update_splice(&x.u, &x.r.lower, &x.r.in,
                                            &x.rng, x.shown, 1.0f / 60.0f, 1),
                   0);
  assert_true(x.u.pending.valid);
  /* reached: switched into the candidate's upper edge, fading from the
   * pose shown */
  x.r.lower.t = (float)x.u.pending.offset;
  assert_int_equal(smgi_upper_update_splice(&x.u, &x.r.lower, &x.r.in,
                                            &x.rng, x.shown, 1.0f / 60.0f, 1),
                   1);
  assert_int_equal(x.u.action, PUNCH);
  assert_int_equal(x.u.edge, sp->upper_edge);
  assert_true(x.u.t == (float)sp->upper_offset);
  assert_true(x.u.fade == 0.0f);
  assert_false(x.u.pending.valid);
  assert_memory_equal(x.snap, x.shown, sizeof x.shown);
  assert_memory_equal(x.u.correction, sp->correction, sizeof(float) * 4u);
  /* the point removed: back to the locomotion's own upper body at once,
   * crossfading (not reported: with no action there is nothing to
   * synchronize, smgi_sync_update settles that) */
  smgi_constraints_clear(&x.r.cons);
  x.u.fade = 1.0f;
  assert_int_equal(smgi_upper_update_splice(&x.u, &x.r.lower, &x.r.in,
                                            &x.rng, x.shown, 1.0f / 60.0f, 0),
                   0);
  assert_int_equal(x.u.action, 0);
  assert_true(x.u.fade == 0.0f);
}

static void test_plan_dropped(void** state) {
  ctx* c = (ctx*)*state;
  static upper_rig x;
  rig(&x, c->g);
  smgi_upper_start(&x.u, c->g, &x.rng, x.shown, 0u);
  x.u.pending.valid = 1;
  x.u.pending.seq = smgi_q_at_c(&x.r.lower, 0)->seq;
  smgi_upper_plan_dropped(&x.u, &x.r.lower);
  assert_true(x.u.pending.valid); /* on the entry playing: kept */
  x.u.pending.seq = smgi_q_at_c(&x.r.lower, 2)->seq;
  smgi_upper_plan_dropped(&x.u, &x.r.lower);
  assert_false(x.u.pending.valid);
}

static void test_sample(void** state) {
  ctx* c = (ctx*)*state;
  static upper_rig x;
  rig(&x, c->g);
  const uint32_t J = c->g->data.joint_count;
  const uint32_t sb = c->g->data.info->spine_base_joint;
  smgi_upper_start(&x.u, c->g, &x.rng, x.shown, PUNCH);
  x.u.t = 3.5f;
  float a[4u * FIXTURE_JOINTS], b[4u * FIXTURE_JOINTS];
  for (uint32_t i = 0; i < 4u * J; ++i) a[i] = b[i] = -7.0f;
  smgi_upper_sample(&x.u, c->g, a);
  /* a 10-degree correction about Y on the spine base */
  smgi_q_yaw(0.17453293f, x.u.correction);
  smgi_upper_sample(&x.u, c->g, b);
  for (uint32_t j = 0; j < J; ++j) {
    const int upper = c->g->data.joints[j].body_part == SMG_BODY_UPPER;
    if (!upper || j == 0) {
      assert_true(a[4u * j] == -7.0f && b[4u * j + 3u] == -7.0f);
      continue;
    }
    float n = a[4u * j] * a[4u * j] + a[4u * j + 1u] * a[4u * j + 1u] +
              a[4u * j + 2u] * a[4u * j + 2u] + a[4u * j + 3u] * a[4u * j + 3u];
    assert_true(fabsf(n - 1.0f) < 1e-4f);
    if (j != sb) assert_memory_equal(a + 4u * j, b + 4u * j, 16u);
  }
  float want[4];
  smgi_q_mul(x.u.correction, a + 4u * sb, want);
  smgi_q_normalize(want);
  for (int k = 0; k < 4; ++k) assert_true(fabsf(want[k] - b[4u * sb + k]) < 1e-6f);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_start_and_advance),
      cmocka_unit_test(test_fade),
      cmocka_unit_test(test_splice_point),
      cmocka_unit_test(test_plan_dropped),
      cmocka_unit_test(test_sample),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
