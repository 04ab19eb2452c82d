/*
 * test_planner.c - the planner alone (planner.c, plan_search.c), through
 * its job interface: a lower timeline, the step's inputs and the steering
 * envelope, on the fixture graph (walk straight / left / right, a run, the
 * transitions between them). No character, no playback.
 *  - start + plan on a straight path: the timeline covers the horizon with
 *    edges that chain node to node, progress along the path only grows,
 *    the planned placements stay on the path, and no run is chosen;
 *  - a transition point to "run" makes the plan run after it;
 *  - a path bending left is followed with left-turning edges only (and
 *    one bending right with right-turning ones);
 *  - re-planning keeps only the edge playing (or, before anything played,
 *    chooses the first edge again);
 *  - the steering correction pending for entries beyond the next two (the
 *    lower timeline's lag) is invisible to whoever reads the plan.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "planner.h"
#include "runtime/stage_testutil.h"

#define FIX_LEFT 1u  /* fixture lower edges */
#define FIX_RIGHT 2u

typedef rt_fixture_ctx ctx;

static const smgi_xform2 ORIGIN = {0.0f, 0.0f, 0.0f};

/* start at the origin facing +Z and plan with a generous budget */
static void start_and_plan(stage_rig* r, smgi_planner* pl, uint32_t* rng) {
  memset(pl, 0, sizeof *pl);
  pl->horizon = 2.0f;
  pl->error_threshold = 0.25f;
  assert_int_equal(smgi_plan_start(pl, &r->lower, &r->in, &r->steer, rng,
                                   ORIGIN.x, ORIGIN.z, ORIGIN.h),
                   SMG_OK);
  assert_int_equal(r->lower.count, 1);
  smgi_plan(pl, &r->lower, &r->in, &r->steer, 100000u, 1.0f);
}

static void check_chain(const stage_rig* r) {
  const smgi_edge* edges = r->g->data.lower_edges;
  for (uint32_t i = 1; i < r->lower.count; ++i) {
    const smgi_qentry* a = smgi_q_at_c(&r->lower, i - 1u);
    const smgi_qentry* b = smgi_q_at_c(&r->lower, i);
    assert_int_equal(edges[a->edge].to, edges[b->edge].from);
    assert_int_equal(b->seq, a->seq + 1u);
    assert_true(b->s_end >= a->s_end);
  }
}

static void test_straight(void** state) {
  ctx* c = (ctx*)*state;
  static stage_rig r;
  stage_rig_init(&r, c->g);
  float xz[2 * 21];
  rt_line(xz, 21, 20.0f);
  stage_rig_path(&r, xz, 21, 0.0f, 0.0f);
  smgi_planner pl;
  uint32_t rng = 1u;
  start_and_plan(&r, &pl, &rng);
  assert_true(smgi_frames_ahead(&r.lower) >= pl.horizon * r.in.fps);
  assert_true(r.lower.count >= 2u);
  check_chain(&r);
  for (uint32_t i = 0; i < r.lower.count; ++i) {
    const smgi_qentry* q = smgi_q_at_c(&r.lower, i);
    const smgi_xform2 W = smgi_q_ground(&r.lower, i);
    assert_true(fabsf(W.x) < 0.5f); /* on the line x = 0 */
    assert_int_equal(r.g->data.lower_edges[q->edge].label, 0); /* walk */
  }
}

static void test_transition_to_run(void** state) {
  ctx* c = (ctx*)*state;
  static stage_rig r;
  stage_rig_init(&r, c->g);
  float xz[2 * 21];
  rt_line(xz, 21, 20.0f);
  stage_rig_path(&r, xz, 21, 0.0f, 0.0f);
  assert_int_equal(smgi_constraints_add(&r.cons, r.path.length, 1.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 1, NULL),
                   SMG_OK);
  smgi_planner pl;
  uint32_t rng = 1u;
  start_and_plan(&r, &pl, &rng);
  check_chain(&r);
  uint32_t runs = 0;
  for (uint32_t i = 0; i < r.lower.count; ++i) {
    const smgi_qentry* q = smgi_q_at_c(&r.lower, i);
    const uint32_t label = r.g->data.lower_edges[q->edge].label;
    if (label == 1u) ++runs;
    /* well after the point, every edge runs */
    if (q->s_start > 3.0f) assert_int_equal(label, 1);
  }
  assert_true(runs >= 2u);
}

/* An arc of `radius` turning left (sign 1) or right (-1) from the origin,
 * starting along +Z. */
static uint32_t arc_path(float* xz, float radius, float sign) {
  uint32_t n = 0;
  for (; n < 40u; ++n) {
    float t = 0.06f * (float)n; /* up to about 134 degrees */
    xz[2 * n] = sign * radius * (1.0f - cosf(t));
    xz[2 * n + 1] = radius * sinf(t);
  }
  return n;
}

static void turn_with(void** state, float sign, uint32_t want,
                      uint32_t never) {
  ctx* c = (ctx*)*state;
  static stage_rig r;
  stage_rig_init(&r, c->g);
  float xz[2 * 40];
  uint32_t n = arc_path(xz, 1.6f, sign);
  stage_rig_path(&r, xz, n, 0.0f, 0.0f);
  smgi_planner pl;
  uint32_t rng = 1u;
  start_and_plan(&r, &pl, &rng);
  check_chain(&r);
  uint32_t wanted = 0;
  for (uint32_t i = 0; i < r.lower.count; ++i) {
    const uint32_t e = smgi_q_at_c(&r.lower, i)->edge;
    if (e == want) ++wanted;
    assert_int_not_equal(e, never);
  }
  assert_true(wanted >= 2u);
}

static void test_turn_left(void** state) {
  turn_with(state, 1.0f, FIX_LEFT, FIX_RIGHT);
}

static void test_turn_right(void** state) {
  turn_with(state, -1.0f, FIX_RIGHT, FIX_LEFT);
}

static void test_replan(void** state) {
  ctx* c = (ctx*)*state;
  static stage_rig r;
  stage_rig_init(&r, c->g);
  float xz[2 * 21];
  rt_line(xz, 21, 20.0f);
  stage_rig_path(&r, xz, 21, 0.0f, 0.0f);
  smgi_planner pl;
  uint32_t rng = 1u;
  start_and_plan(&r, &pl, &rng);
  assert_true(r.lower.count > 1u);
  /* before anything played (time 0, playhead 0): the head is chosen
   * again, as a new entry */
  const uint32_t next_seq = r.lower.next_seq;
  smgi_replan(&pl, &r.lower, &r.in, &r.steer);
  assert_int_equal(r.lower.count, 1);
  assert_int_equal(smgi_q_at_c(&r.lower, 0)->seq, next_seq);
  smgi_plan(&pl, &r.lower, &r.in, &r.steer, 100000u, 1.0f);
  assert_true(r.lower.count > 1u);
  /* once playing: only the head stays, with its frames */
  r.in.time = 0.5;
  r.lower.t = 3.0f;
  const smgi_qentry head = *smgi_q_at_c(&r.lower, 0);
  smgi_replan(&pl, &r.lower, &r.in, &r.steer);
  assert_int_equal(r.lower.count, 1);
  assert_int_equal(smgi_q_at_c(&r.lower, 0)->seq, head.seq);
  assert_int_equal(smgi_q_at_c(&r.lower, 0)->edge, head.edge);
  assert_int_equal(r.lower.frames,
                   r.g->data.lower_edges[head.edge].frame_count);
  assert_true(r.lower.lag.c == 1.0f && r.lower.lag.a == 0.0f);
}

static void test_lag_is_invisible(void** state) {
  ctx* c = (ctx*)*state;
  static stage_rig a, b;
  float xz[2 * 40];
  uint32_t n = arc_path(xz, 3.0f, 1.0f);
  stage_rig_init(&a, c->g);
  stage_rig_init(&b, c->g);
  stage_rig_path(&a, xz, n, 0.0f, 0.0f);
  stage_rig_path(&b, xz, n, 0.0f, 0.0f);
  smgi_planner pa, pb;
  uint32_t ra = 1u, rb = 1u;
  memset(&pa, 0, sizeof pa);
  pa.horizon = 5.0f; /* entries beyond the next two */
  pa.error_threshold = 0.25f;
  pb = pa;
  assert_int_equal(smgi_plan_start(&pa, &a.lower, &a.in, &a.steer, &ra, 0, 0, 0), SMG_OK);
  assert_int_equal(smgi_plan_start(&pb, &b.lower, &b.in, &b.steer, &rb, 0, 0, 0), SMG_OK);
  /* a pending correction: a turn of 0.3 rad about (1, 2), a shift of
   * (0.2, -0.1); entries pushed beyond the next two are stored through
   * its inverse and read through it */
  b.lower.lag.a = 0.3f;
  b.lower.lag.c = cosf(0.3f);
  b.lower.lag.s = sinf(0.3f);
  b.lower.lag.p[0] = 1.0f;
  b.lower.lag.p[1] = 2.0f;
  b.lower.lag.t[0] = 0.2f;
  b.lower.lag.t[1] = -0.1f;
  smgi_plan(&pa, &a.lower, &a.in, &a.steer, 100000u, 1.0f);
  smgi_plan(&pb, &b.lower, &b.in, &b.steer, 100000u, 1.0f);
  assert_true(a.lower.count > 3u);
  assert_int_equal(a.lower.count, b.lower.count);
  int stored_differs = 0;
  for (uint32_t i = 0; i < a.lower.count; ++i) {
    assert_int_equal(smgi_q_at_c(&a.lower, i)->edge,
                     smgi_q_at_c(&b.lower, i)->edge);
    smgi_xform2 wa = smgi_q_ground(&a.lower, i);
    smgi_xform2 wb = smgi_q_ground(&b.lower, i);
    assert_true(fabsf(wa.x - wb.x) < 1e-4f && fabsf(wa.z - wb.z) < 1e-4f &&
                fabsf(smgi_wrap_angle(wa.h - wb.h)) < 1e-4f);
    if (fabsf(smgi_q_at_c(&a.lower, i)->W.x - smgi_q_at_c(&b.lower, i)->W.x) > 1e-2f)
      stored_differs = 1;
  }
  assert_true(stored_differs); /* the lag was in effect */
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_straight),
      cmocka_unit_test(test_transition_to_run),
      cmocka_unit_test(test_turn_left),
      cmocka_unit_test(test_turn_right),
      cmocka_unit_test(test_replan),
      cmocka_unit_test(test_lag_is_invisible),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
