/*
 * test_upper_phase.c - the upper (action) graph keeps the gait phase
 * (bake_graph_build.c, phase_agrees; bake_transition.c, blended phase).
 *
 * The action is a synthetic walk whose upper body repeats every one and
 * a half strides (a dribbler's arm does the same on either foot), so the
 * upper-body distance grid offers transitions between poses one and a
 * half strides apart as readily as three strides apart. Played, the first
 * kind would jump the upper body's gait phase by half a cycle. The
 * baker must keep only transitions whose phases agree within half the
 * blend window's length in cycles, and the blended frames' phase must
 * move on smoothly. When no phase-keeping transition can form a cycle
 * (the upper body repeats only at one and a half strides and the clip is
 * too short to repeat twice) the action is rebuilt without the rule, and
 * the result says so.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "bake/bake_graph_helpers.h"

#define RATE 30.0

/* Stride period (s) of the synthetic walk. */
static double walk_period(void) {
  smgb_synth_params p;
  smgb_synth_truth t;
  smgb_clip c;
  memset(&p, 0, sizeof p);
  p.kind = SMGB_SYNTH_WALK;
  if (smgb_synth_generate(&p, &c, &t) != SMG_OK) fail_msg("synthetic walk");
  smgb_clip_free(&c);
  return t.stride_period;
}

/* Bake a walk (legs) plus `strides` strides of the walk with a retimed
 * upper body (action "dribble"). */
static void bake_dribble(double T, double per_stride, double strides,
                         smg_bake_result* res) {
  static bg_set s;
  memset(&s, 0, sizeof s);
  bg_add(&s, SMGB_SYNTH_WALK, 12.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(&s, SMGB_SYNTH_WALK, (float)(strides * T), 0.0f,
         SMG_BAKE_ROLE_UPPER, "dribble");
  bg_retime_upper_body(&s.clips[1], T, per_stride);
  if (bg_bake(&s, NULL, res) != SMG_OK) fail_msg("bake: %s", res->error);
  bg_free(&s);
}

static double wrap_half(double d) { return d - floor(d + 0.5); }

static void test_upper_transitions_keep_phase(void** state) {
  smg_bake_result res;
  smgi_graph_data g;
  double T, speed, w;
  uint32_t e, transitions = 0, k;
  (void)state;
  T = walk_period();
  bake_dribble(T, 1.0 / 1.5, 10.0, &res);
  bg_read(&res, &g);
  speed = 1.0 / (T * RATE); /* cycles per frame */
  assert_int_equal(res.upper_phase_fallbacks, 0);
  assert_true(g.upper_edge_count > 0);
  for (e = 0; e < g.upper_edge_count; ++e) {
    const smgi_edge* ed = &g.upper_edges[e];
    uint32_t from = g.upper_nodes[ed->from].frame;
    uint32_t to = g.upper_nodes[ed->to].frame;
    double p0 = g.frames[from].phase, p1 = g.frames[to].phase, prev, d;
    if (!(ed->flags & SMGI_EDGE_TRANSITION)) continue;
    ++transitions;
    assert_true(p0 >= 0.0 && p1 >= 0.0);
    /* over the edge the phase advances by its window's worth, give or
     * take half of it (the baker's tolerance) */
    w = (double)ed->frame_count * speed;
    d = wrap_half(p1 - p0 - w);
    if (fabs(d) > 0.5 * w + 0.01)
      fail_msg("upper transition %u (frames %u -> %u) jumps the gait phase "
               "by %.3f cycles (tolerance %.3f)", e, from, to, d, 0.5 * w);
    /* and it moves on smoothly through the blended frames */
    prev = p0;
    for (k = 0; k <= ed->frame_count; ++k) {
      double p = k < ed->frame_count ? g.frames[ed->first_frame + k].phase
                                     : p1;
      double step = p - prev;
      step -= floor(step);
      if (step > 2.0 * speed + 1e-4)
        fail_msg("upper transition %u: phase step %.4f at blend frame %u "
                 "(gait speed %.4f per frame)", e, step, k, speed);
      prev = p;
    }
  }
  print_message("%u upper transitions, all within half a window of phase\n",
                transitions);
  assert_true(transitions >= 2);
  smg_bake_result_free(&res);
}

static void test_rule_falls_back_without_a_cycle(void** state) {
  smg_bake_result res;
  smgi_graph_data g;
  uint32_t e, transitions = 0;
  (void)state;
  /* the upper body repeats every 1.5 strides, within a clip of 2.6: its
   * only loops jump half a cycle */
  bake_dribble(walk_period(), 1.0 / 1.5, 2.6, &res);
  bg_read(&res, &g);
  assert_int_equal(res.upper_phase_fallbacks, 1);
  for (e = 0; e < g.upper_edge_count; ++e)
    if (g.upper_edges[e].flags & SMGI_EDGE_TRANSITION) ++transitions;
  assert_true(transitions >= 1);
  smg_bake_result_free(&res);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_upper_transitions_keep_phase),
      cmocka_unit_test(test_rule_falls_back_without_a_cycle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
