/*
 * test_data_stop.c - stopping and starting motion from the data, judged
 * from the exported poses. A graph of synthetic walks plus a walk that
 * comes to rest and one that sets off from rest (bake_synthetic.h:
 * WALK_STOP / WALK_START), baked in memory:
 *  - found at load (stopping.h): one stop and one start per such clip and
 *    its mirror, none in the walks alone, each stop's remaining travel
 *    falling to 0 at its rest;
 *  - an 8 m straight stop: the hips within 0.3 m of the end, the ankles
 *    at most 0.40 m apart at rest; over the last second before the hips
 *    stand (below 0.1 m/s), their speed follows the stop clip's own (its
 *    root, lined up at the frame it stands) within 0.15 m/s; standing
 *    toes slide at most 20 cm/s from 2 s before;
 *  - a start from that rest onto a 12 m path: the longest swing in the
 *    first 2 s at most 1.3 times the steady median, 80 % of the walk's
 *    speed within 1.5 s, the hips' speed over the first second of moving
 *    within 0.15 m/s of the start clip's, standing toes sliding at most
 *    20 cm/s over the first 3 s.
 * On the graph without the stop and start clips (the steering's stop and
 * the rest stage's start) the profiles are 1.08 and 0.42 m/s off, and the
 * test checks they fail: the measures tell the data's motion from the
 * IK's. With the planner's stop or restart switched off, the test fails.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "bake/bake_graph_helpers.h"
#include "graph_derived.h"
#include "runtime/rest_scene.h"
#include "runtime/runtime_testutil.h"

#define FPS 30.0f
#define DT (1.0f / FPS)

static rg_run g_run;

/* Walks (straight, turning both ways), a walk to rest and one from rest,
 * and an action for the upper body; with_ramps 0 leaves the last two
 * out. */
static smg_graph* bake_graph(int with_ramps, bg_set* set,
                             smg_bake_result* res) {
  memset(set, 0, sizeof *set);
  bg_add(set, SMGB_SYNTH_WALK, 8.0f, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(set, SMGB_SYNTH_WALK, 8.0f, 0.35f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(set, SMGB_SYNTH_WALK, 8.0f, -0.35f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(set, SMGB_SYNTH_WAVE, 8.0f, 0.0f, SMG_BAKE_ROLE_UPPER, "wave");
  if (with_ramps) {
    bg_add(set, SMGB_SYNTH_WALK_STOP, 7.0f, 0.0f, SMG_BAKE_ROLE_LOWER,
           "walk");
    bg_add(set, SMGB_SYNTH_WALK_START, 7.0f, 0.0f, SMG_BAKE_ROLE_LOWER,
           "walk");
  }
  assert_int_equal(bg_bake(set, NULL, res), SMG_OK);
  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(res->blob, res->blob_size, NULL, &g),
                   SMG_OK);
  return g;
}

static void test_found(void** state) {
  (void)state;
  bg_set set;
  smg_bake_result res;
  /* the walks alone: none (as on every shared graph) */
  smg_graph* g = bake_graph(0, &set, &res);
  assert_int_equal(smgi_derived_of(g)->stop_count, 0);
  assert_null(smgi_derived_of(g)->stop_left);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
  g = bake_graph(1, &set, &res);
  const smgi_derived* dv = smgi_derived_of(g);
  const float fps = set.clips[4].frame_rate;
  uint32_t stops = 0, starts = 0;
  for (uint32_t k = 0; k < dv->stop_count; ++k) {
    const smgi_stop_seg* s = &dv->stops[k];
    print_message("%s: clip %u, frames %u..%u..%u, %.2f m/s, %.2f m\n",
                  s->kind == SMGI_STOP_KIND_STOP ? "stop" : "start", s->clip,
                  s->first, s->rest, s->last, s->speed, s->travel);
    assert_true(s->first <= s->rest && s->rest <= s->last);
    /* the walk's speed, and a stop / start of about the ramp's way
     * (half a stride at speed over a stride: 0.6 m) plus a lead-in */
    assert_true(fabsf(s->speed - set.truth[4].speed) < 0.05f);
    if (s->kind == SMGI_STOP_KIND_STOP) {
      ++stops;
      /* still for at least a second after the rest */
      assert_true((float)(s->last - s->rest) >= fps - 1.0f);
      assert_true(s->travel > 0.5f * set.truth[4].speed *
                                  set.truth[4].ramp_seconds);
      const float* left = dv->stop_left + dv->stop_left_first[k];
      assert_float_equal(left[0], s->travel, 1e-4f);
      assert_float_equal(left[s->rest - s->first], 0.0f, 0.0f);
      for (uint32_t i = s->first; i < s->rest; ++i)
        assert_true(left[i - s->first] >= left[i + 1u - s->first]);
    } else {
      ++starts;
      assert_true(s->travel > 0.2f);
    }
  }
  /* each clip and its mirror */
  assert_int_equal(stops, 2);
  assert_int_equal(starts, 2);
  assert_int_equal(dv->start_count, 2);
  float longest = 0.0f;
  for (uint32_t k = 0; k < dv->stop_count; ++k)
    if (dv->stops[k].kind == SMGI_STOP_KIND_STOP && dv->stops[k].travel > longest)
      longest = dv->stops[k].travel;
  assert_float_equal(dv->stop_longest, longest, 0.0f);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
}

/* An allocator that fails from its `fail_at`-th call on (-1: never). */
typedef struct failing_alloc {
  int calls, frees, fail_at;
} failing_alloc;

static void* failing_alloc_fn(size_t size, size_t align, void* user) {
  failing_alloc* c = (failing_alloc*)user;
  if (c->fail_at >= 0 && c->calls >= c->fail_at) return NULL;
  void* p = NULL;
  if (posix_memalign(&p, align < sizeof(void*) ? sizeof(void*) : align,
                     size ? size : 1) != 0)
    return NULL;
  c->calls++;
  return p;
}

static void failing_free_fn(void* p, void* user) {
  failing_alloc* c = (failing_alloc*)user;
  if (p) c->frees++;
  free(p);
}

/* A graph with stops loads under every allocation failure cleanly: the
 * stop tables' own allocations included, it fails with OUT_OF_MEMORY and
 * gives back all it took. */
static void test_load_out_of_memory(void** state) {
  (void)state;
  bg_set set;
  smg_bake_result res;
  smg_graph* g = bake_graph(1, &set, &res);
  smg_graph_destroy(g);
  failing_alloc c = {0, 0, -1};
  smg_graph_desc desc;
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.allocator.alloc = failing_alloc_fn;
  desc.allocator.free = failing_free_fn;
  desc.allocator.user = &c;
  assert_int_equal(smg_graph_load_memory(res.blob, res.blob_size, &desc, &g),
                   SMG_OK);
  assert_true(smgi_derived_of(g)->stop_count > 0);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
  const int total = c.calls;
  assert_int_equal(c.frees, total);
  for (int n = 0; n < total; ++n) {
    c.calls = c.frees = 0;
    c.fail_at = n;
    g = NULL;
    assert_int_equal(smg_graph_load_memory(res.blob, res.blob_size, &desc, &g),
                     SMG_ERROR_OUT_OF_MEMORY);
    assert_null(g);
    assert_int_equal(c.frees, c.calls);
  }
  smg_bake_result_free(&res);
  bg_free(&set);
}

/* ---- the scene (rest_scene.h) ---- */

/* A straight path from the hips' ground point along +Z. */
static void scene_path(scene* s, float length) {
  float xz[2 * 25];
  const float* p = g_run.hips[g_run.n - 1u];
  for (int i = 0; i < 25; ++i) {
    xz[2 * i] = p[0];
    xz[2 * i + 1] = p[2] + length * (float)i / 24.0f;
  }
  assert_int_equal(smg_character_set_path(s->ch, xz, 25), SMG_OK);
}

static float hdist(const float* a, const float* b) {
  return sqrtf((a[0] - b[0]) * (a[0] - b[0]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Hips speed of a generated clip at frame i (root of its poses) over
 * +-w frames, as rg_speed measures the character's. */
static float clip_speed(const smgb_clip* c, uint32_t i, uint32_t w) {
  const uint32_t st = SMGB_STRIDE(c->skeleton.joint_count);
  const uint32_t a = i > w ? i - w : 0;
  const uint32_t b = i + w < c->frame_count ? i + w : c->frame_count - 1u;
  const float* pa = c->poses + (size_t)a * st;
  const float* pb = c->poses + (size_t)b * st;
  return sqrtf((pb[0] - pa[0]) * (pb[0] - pa[0]) +
               (pb[2] - pa[2]) * (pb[2] - pa[2])) /
         ((float)(b - a) / c->frame_rate);
}

/* Foot sliding (cm/s): the fastest a toe moves while it stands - on the
 * floor (within RG_BAND of its level) for at least STANCE_MIN frames -
 * over frames [a, b), leaving out the STANCE_EDGE frames at each end of
 * a stance, where a landing toe is still slowing and a lifting one
 * speeding up within the band. */
#define STANCE_MIN 6u
#define STANCE_EDGE 2u
static float stance_slide(const rg_run* r, uint32_t a, uint32_t b) {
  float most = 0.0f;
  for (int f = 0; f < 2; ++f) {
    const float fl = rg_floor(r, f);
    uint32_t start = a;
    for (uint32_t i = a; i <= b; ++i) {
      if (i < b && i < r->n && r->toe[i][f][1] <= fl + RG_BAND) continue;
      if (i - start >= STANCE_MIN)
        for (uint32_t k = start + STANCE_EDGE + 1u; k + STANCE_EDGE < i; ++k) {
          const float v = 100.0f * hdist(r->toe[k][f], r->toe[k - 1u][f]) / DT;
          if (v > most) most = v;
        }
      start = i + 1u;
    }
  }
  return most;
}

/* ---- the stop ---- */

typedef struct stop_measure {
  float end_error;  /* m: hips from the path's end, at rest */
  float ankle_gap;  /* m: most the ankles are apart at rest */
  float profile;    /* m/s: most the hips' speed over the last second
                       before they stand differs from the stop clip's */
  float planted;    /* cm/s: fastest planted toe from 2 s before the
                       hips stand */
} stop_measure;

#define STAND_SPEED 0.1f /* m/s: the hips stand below it */

static void measure_stop(smg_graph* g, const smgb_clip* stop_clip,
                         stop_measure* m) {
  scene s;
  scene_start(g, &s, &g_run, FPS);
  const float end[3] = {g_run.hips[0][0], 0.0f, g_run.hips[0][2] + 8.0f};
  scene_path(&s, 8.0f);
  scene_run(&s, 14.0f);
  smg_character_destroy(s.ch);
  const rg_run* r = &g_run;
  const uint32_t hw = (uint32_t)(0.25f * FPS);
  /* the frame the hips stand from: after the last one faster than
   * STAND_SPEED (the character's, and the clip's) */
  uint32_t rest = 0, crest = 0;
  for (uint32_t i = 0; i < r->n; ++i)
    if (rg_speed(r, i, hw) > STAND_SPEED) rest = i + 1u;
  for (uint32_t i = 0; i < stop_clip->frame_count; ++i)
    if (clip_speed(stop_clip, i, hw) > STAND_SPEED) crest = i + 1u;
  assert_true(rest + (uint32_t)(2.0f * FPS) < r->n);
  const uint32_t second = (uint32_t)FPS;
  assert_true(rest > 2u * second && crest > second);
  m->end_error = hdist(r->hips[r->n - 1u], end);
  m->ankle_gap = 0.0f;
  for (uint32_t i = rest + second; i < r->n; ++i) {
    const float gap = hdist(r->ankle[i][0], r->ankle[i][1]);
    if (gap > m->ankle_gap) m->ankle_gap = gap;
  }
  m->profile = 0.0f;
  for (uint32_t k = 1; k <= second; ++k) {
    const float d = fabsf(rg_speed(r, rest - k, hw) -
                          clip_speed(stop_clip, crest - k, hw));
    if (d > m->profile) m->profile = d;
  }
  m->planted = stance_slide(r, rest - 2u * second, r->n);
}

static void test_stop(void** state) {
  (void)state;
  bg_set set;
  smg_bake_result res;
  stop_measure with, without;
  smg_graph* g = bake_graph(0, &set, &res);
  measure_stop(g, &set.clips[0], &without); /* no stop clip: any walk */
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
  g = bake_graph(1, &set, &res);
  measure_stop(g, &set.clips[4], &with);
  for (int k = 0; k < 2; ++k) {
    const stop_measure* m = k ? &without : &with;
    print_message("%s: hips %.3f m from the end, ankles %.3f m apart, "
                  "speed in the last second %.3f m/s off the stop clip's, "
                  "planted toes <= %.1f cm/s\n",
                  k ? "IK stop (no stop clip)" : "stop clip", m->end_error,
                  m->ankle_gap, m->profile, m->planted);
  }
  assert_true(with.end_error <= 0.3f);
  assert_true(with.ankle_gap <= 0.40f);
  assert_true(with.profile <= 0.15f);
  assert_true(with.planted <= 20.0f);
  /* the measure tells the two apart */
  assert_true(without.profile > 0.15f);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
}

/* ---- the start ---- */

typedef struct start_measure {
  float swing_ratio; /* longest swing in the first 2 s / steady median */
  float reach_80;    /* s until 80 % of the steady speed */
  float steady;      /* m/s */
  float profile;     /* m/s: most the hips' speed over the first second
                        of moving differs from the start clip's */
  float planted;     /* cm/s: foot sliding in the 3 s from the path's
                        change */
} start_measure;

static void measure_start(smg_graph* g, const smgb_clip* start_clip,
                          start_measure* m) {
  scene s;
  scene_start(g, &s, &g_run, FPS);
  scene_path(&s, 8.0f);
  scene_run(&s, 12.0f);
  const uint32_t p0 = g_run.n;
  scene_path(&s, 12.0f);
  scene_run(&s, 9.0f);
  smg_character_destroy(s.ch);
  const rg_run* r = &g_run;
  const uint32_t hw = (uint32_t)(0.25f * FPS);
  const uint32_t s0 = p0 + (uint32_t)(3.0f * FPS);
  assert_true(rg_start_gait(r, p0, &m->swing_ratio, &m->steady, &m->reach_80));
  m->planted = stance_slide(r, p0, s0);
  /* the first frame faster than STAND_SPEED, the character's and the
   * clip's: the profiles are compared from there */
  uint32_t go = p0, cgo = 0;
  while (go < r->n && rg_speed(r, go, hw) <= STAND_SPEED) ++go;
  while (cgo < start_clip->frame_count &&
         clip_speed(start_clip, cgo, hw) <= STAND_SPEED)
    ++cgo;
  const uint32_t second = (uint32_t)FPS;
  assert_true(go + second < r->n && cgo + second < start_clip->frame_count);
  m->profile = 0.0f;
  for (uint32_t i = 0; i < second; ++i) {
    const float d = fabsf(rg_speed(r, go + i, hw) -
                          clip_speed(start_clip, cgo + i, hw));
    if (d > m->profile) m->profile = d;
  }
}

static void test_start(void** state) {
  (void)state;
  bg_set set;
  smg_bake_result res;
  start_measure with, without;
  smg_graph* g = bake_graph(0, &set, &res);
  bg_set ramps; /* the start clip, for its profile */
  memset(&ramps, 0, sizeof ramps);
  bg_add(&ramps, SMGB_SYNTH_WALK_START, 7.0f, 0.0f, SMG_BAKE_ROLE_LOWER,
         "walk");
  measure_start(g, &ramps.clips[0], &without);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
  g = bake_graph(1, &set, &res);
  measure_start(g, &set.clips[5], &with);
  for (int k = 0; k < 2; ++k) {
    const start_measure* m = k ? &without : &with;
    print_message("%s: longest swing in 2 s %.2f x the steady median, 80 %% "
                  "of %.2f m/s after %.2f s, speed in the first second of "
                  "moving %.3f m/s off the start clip's, planted toes <= "
                  "%.1f cm/s\n",
                  k ? "start without a start clip" : "start clip",
                  m->swing_ratio, m->steady, m->reach_80, m->profile,
                  m->planted);
  }
  assert_true(with.swing_ratio <= 1.3f);
  assert_true(with.reach_80 <= 1.5f);
  assert_true(with.profile <= 0.15f);
  assert_true(with.planted <= 20.0f);
  assert_true(without.profile > 0.15f);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
  bg_free(&set);
  bg_free(&ramps);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_found),
      cmocka_unit_test(test_load_out_of_memory),
      cmocka_unit_test(test_stop),
      cmocka_unit_test(test_start),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
