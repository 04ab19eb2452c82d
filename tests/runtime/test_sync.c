/*
 * test_sync.c - the upper body stays in step with the legs (sync.c).
 *
 * A graph whose locomotion is the synthetic walk and whose one action is
 * the upper body of the synthetic run (an action that has its own gait:
 * stride periods differ, so playing it at its own speed drifts against the
 * legs by their difference in cadence). A character walks a straight line
 * with the action spliced on; from a second after the switch on, the gait
 * phase of the lower frame played (FRMI) and that of the upper frame
 * played must stay locked: circular std of their difference <= 0.08
 * cycles, drift <= 0.01 cycles/s, and the upper body's mean playback rate
 * within 2 % of the ratio of the two stride periods. The same holds for
 * an action whose upper body repeats off the stride (every one and a half
 * strides), whose graph could join poses half a cycle apart.
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

#include "bake/bake_graph_helpers.h"
#include "bake_synthetic.h"
#include "character_state.h"
#include "runtime/runtime_testutil.h"
#include "smg_bake.h"

#define DT (1.0f / 30.0f)
#define STEPS 600

/* Phase of the frame at fractional time t into edge e (interpolated the
 * short way round), -1 when unknown. */
static double phase_at(const smgi_graph_data* d, const smgi_edge* e,
                       float t) {
  uint32_t i = (uint32_t)t;
  if (i + 1u >= e->frame_count) return d->frames[e->first_frame + e->frame_count - 1u].phase;
  double a = d->frames[e->first_frame + i].phase;
  double b = d->frames[e->first_frame + i + 1u].phase;
  if (a < 0.0 || b < 0.0) return -1.0;
  double s = b - a;
  s -= floor(s + 0.5);
  double p = a + (t - (float)i) * s;
  return p - floor(p);
}

/* Phase lock of a character walking a 40 m line with `action` spliced on
 * at 1 m: from a second after the switch on, the circular std and drift
 * of (upper - lower) gait phase (FRMI of the frames played) and the mean
 * playback rate. */
typedef struct lock_stats {
  double circ_std, drift, rate;
  int n;
} lock_stats;

static void measure_lock(smg_graph* g, uint32_t walk, uint32_t action,
                         lock_stats* out) {
  static float path[2 * 400];
  rt_line(path, 400, 40.0f);
  smg_character_desc cd;
  memset(&cd, 0, sizeof cd);
  cd.struct_size = sizeof cd;
  cd.initial_style = walk;
  cd.path_capacity = 400;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, &cd, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, path, 400), SMG_OK);
  uint32_t id;
  assert_int_equal(smg_character_add_splice(ch, 1.0f, action, &id), SMG_OK);

  const smgi_graph_data* d = &g->data;
  static double tt[STEPS], diff[STEPS];
  double prev = NAN, acc = 0.0, rate_sum = 0.0, var_c = 0.0, var_s = 0.0;
  int n = 0, since = -1;
  for (int i = 0; i < STEPS; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    if (ch->upper.action != action) continue;
    if (since < 0) since = i;
    if (i - since < 30) continue; /* the switch's blend and first lock */
    const smgi_qentry* q = smgi_q_at_c(&ch->lower, 0);
    double pl = phase_at(d, &d->lower_edges[q->edge], ch->lower.t);
    double pu = phase_at(d, &d->upper_edges[ch->upper.edge], ch->upper.t);
    if (pl < 0.0 || pu < 0.0) continue;
    double e = pu - pl;
    e -= floor(e + 0.5);
    if (!isnan(prev)) { /* unwrap */
      double s = e - prev;
      acc += s - floor(s + 0.5) - s;
    }
    prev = e;
    tt[n] = i * DT;
    diff[n] = e + acc;
    var_c += cos(2.0 * 3.14159265358979323846 * e);
    var_s += sin(2.0 * 3.14159265358979323846 * e);
    rate_sum += ch->sync.rate;
    ++n;
  }
  assert_true(n > 200);
  double R = sqrt(var_c * var_c + var_s * var_s) / n;
  out->circ_std = sqrt(-2.0 * log(R)) / (2.0 * 3.14159265358979323846);
  double mt = 0.0, md = 0.0, sxy = 0.0, sxx = 0.0;
  for (int k = 0; k < n; ++k) mt += tt[k], md += diff[k];
  mt /= n;
  md /= n;
  for (int k = 0; k < n; ++k) {
    sxy += (tt[k] - mt) * (diff[k] - md);
    sxx += (tt[k] - mt) * (tt[k] - mt);
  }
  out->drift = sxy / sxx;
  out->rate = rate_sum / n;
  out->n = n;
  smg_character_destroy(ch);
}

static void test_upper_phase_locked(void** state) {
  (void)state;
  char clips[1024];
  snprintf(clips, sizeof clips, "%s/synthetic", SMG_BUILD_DIR);
  smg_bake_clip_desc c[2];
  memset(c, 0, sizeof c);
  c[0].struct_size = c[1].struct_size = sizeof c[0];
  c[0].role = SMG_BAKE_ROLE_LOWER;
  c[0].path = "synthetic_walk_straight.bvh";
  c[0].label = "walk";
  c[1].role = SMG_BAKE_ROLE_UPPER;
  c[1].path = "synthetic_run_straight.bvh";
  c[1].label = "runarms";
  c[0].unit_scale = c[1].unit_scale = 1.0f;
  smg_bake_desc desc;
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.clip_count = 2;
  desc.clips = c;
  desc.data_dir = clips;
  desc.options.struct_size = sizeof desc.options;
  smg_bake_result br;
  memset(&br, 0, sizeof br);
  br.struct_size = sizeof br;
  if (smg_bake_run(&desc, &br) != SMG_OK) {
    fprintf(stderr, "bake failed (run `make` first): %s\n", br.error);
    fail();
  }
  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(br.blob, br.blob_size, NULL, &g),
                   SMG_OK);
  uint32_t walk, arms;
  assert_int_equal(smg_graph_find_style(g, "walk", &walk), SMG_OK);
  assert_int_equal(smg_graph_find_action(g, "runarms", &arms), SMG_OK);

  /* the two stride periods, from the generator's ground truth */
  smgb_synth_params p;
  smgb_synth_truth tw, tr;
  smgb_clip tmp;
  memset(&p, 0, sizeof p);
  p.kind = SMGB_SYNTH_WALK;
  assert_int_equal(smgb_synth_generate(&p, &tmp, &tw), SMG_OK);
  smgb_clip_free(&tmp);
  p.kind = SMGB_SYNTH_RUN;
  assert_int_equal(smgb_synth_generate(&p, &tmp, &tr), SMG_OK);
  smgb_clip_free(&tmp);
  double want_rate = tr.stride_period / tw.stride_period;

  lock_stats ls;
  measure_lock(g, walk, arms, &ls);
  print_message("upper - lower gait phase over %d frames: circular std %.4f "
                "cycles, drift %+.4f cycles/s; rate %.4f (stride periods "
                "%.3f / %.3f s call for %.4f)\n", ls.n, ls.circ_std,
                ls.drift, ls.rate, tr.stride_period, tw.stride_period,
                want_rate);
  assert_true(ls.circ_std <= 0.08);
  assert_true(fabs(ls.drift) <= 0.01);
  assert_true(fabs(ls.rate / want_rate - 1.0) <= 0.02);
  smg_graph_destroy(g);
  smg_bake_result_free(&br);
}

/* An action whose upper body repeats every one and a half strides (a
 * dribbler's arm does the same on either foot): its distance grid offers
 * transitions that would jump the gait phase by half a cycle. The baker
 * keeps only phase-keeping ones (bake_graph_build.c), so the lock holds as
 * on any other action: no jump for synchronization to make up. */
static void test_action_repeating_off_the_stride(void** state) {
  (void)state;
  static bg_set s;
  memset(&s, 0, sizeof s);
  bg_add(&s, SMGB_SYNTH_WALK, 12.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  double T = s.truth[0].stride_period;
  bg_add(&s, SMGB_SYNTH_WALK, (float)(10.0 * T), 0.0f, SMG_BAKE_ROLE_UPPER,
         "dribble");
  bg_retime_upper_body(&s.clips[1], T, 1.0 / 1.5);
  smg_bake_result br;
  assert_int_equal(bg_bake(&s, NULL, &br), SMG_OK);
  bg_free(&s);
  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(br.blob, br.blob_size, NULL, &g),
                   SMG_OK);
  uint32_t walk, dribble;
  assert_int_equal(smg_graph_find_style(g, "walk", &walk), SMG_OK);
  assert_int_equal(smg_graph_find_action(g, "dribble", &dribble), SMG_OK);
  lock_stats ls;
  measure_lock(g, walk, dribble, &ls);
  print_message("action repeating every 1.5 strides: circular std %.4f "
                "cycles, drift %+.4f cycles/s over %d frames; rate %.4f\n",
                ls.circ_std, ls.drift, ls.n, ls.rate);
  assert_true(ls.circ_std <= 0.08);
  assert_true(fabs(ls.drift) <= 0.01);
  assert_true(fabs(ls.rate - 1.0) <= 0.02); /* same stride on both sides */
  smg_graph_destroy(g);
  smg_bake_result_free(&br);
}

/* An action whose upper body repeats every 1.3 or 1.7 strides, in a clip
 * too short to repeat twice: its only loops join different gait phases,
 * so the baker keeps them (upper_phase_fallbacks) and the upper body's
 * phase jumps by 0.3 cycles at every loop. The lock makes each jump up
 * and, with its phase error kept continuous (sync.c), never turns a
 * difference that jumps pile up past half a cycle into a stride slipped
 * against the legs: drift -0.08 and -0.10 cycles/s with the error wrapped
 * to half a cycle, -0.015 and +0.005 kept continuous. */
static void test_phase_jumps_made_up_without_slipping(void** state) {
  (void)state;
  const double repeat[2] = {1.3, 1.7};
  for (int v = 0; v < 2; ++v) {
    static bg_set s;
    memset(&s, 0, sizeof s);
    bg_add(&s, SMGB_SYNTH_WALK, 12.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
    double T = s.truth[0].stride_period;
    bg_add(&s, SMGB_SYNTH_WALK, (float)(2.6 * repeat[v] * T), 0.0f,
           SMG_BAKE_ROLE_UPPER, "dribble");
    bg_retime_upper_body(&s.clips[1], T, 1.0 / repeat[v]);
    smg_bake_result br;
    assert_int_equal(bg_bake(&s, NULL, &br), SMG_OK);
    bg_free(&s);
    assert_int_equal(br.upper_phase_fallbacks, 1);
    smg_graph* g = NULL;
    assert_int_equal(smg_graph_load_memory(br.blob, br.blob_size, NULL, &g),
                     SMG_OK);
    uint32_t walk, dribble;
    assert_int_equal(smg_graph_find_style(g, "walk", &walk), SMG_OK);
    assert_int_equal(smg_graph_find_action(g, "dribble", &dribble), SMG_OK);
    lock_stats ls;
    measure_lock(g, walk, dribble, &ls);
    print_message("action repeating every %.1f strides, loops that jump the "
                  "phase: circular std %.4f cycles, drift %+.4f cycles/s "
                  "over %d frames\n", repeat[v], ls.circ_std, ls.drift,
                  ls.n);
    assert_true(fabs(ls.drift) <= 0.03);
    smg_graph_destroy(g);
    smg_bake_result_free(&br);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_upper_phase_locked),
      cmocka_unit_test(test_action_repeating_off_the_stride),
      cmocka_unit_test(test_phase_jumps_made_up_without_slipping),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
