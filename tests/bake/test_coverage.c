/*
 * test_coverage.c - the coverage pass of big bakes (bake_coverage.c) and
 * the pool without the covered clips (bake_pool_compact.c): copies of a
 * kept clip's motion are covered, new motion is kept, labels are decided
 * alone and the first clip of each is kept, a radius of 0 covers nothing,
 * the answer does not depend on the thread count; the compacted pool keeps
 * the other clips' frames and every index that refers to them right; and
 * a whole bake of repeated clips leaves the repeats out of a valid blob.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "bake_coverage.h"
#include "bake_graph_helpers.h"
#include "bake_pool.h"
#include "bake_pool_compact.h"
#include "bake_state.h"
#include "smg.h"

#define K 6u
#define P 5u
#define LEN 80u
#define MAX_CLIPS 32u

/* A clip: a gait-like cloud of P points cycling at `rate` radians per
 * frame with amplitude `amp`, walking straight along `heading` from
 * (x0, z0), starting at phase `ph0`. From frame `switch_at` on it moves
 * with amplitude `amp2` instead (new motion inside a clip). */
typedef struct clip_spec {
  double rate, amp, amp2, ph0, heading, x0, z0;
  uint32_t switch_at;
  uint32_t label;
} clip_spec;

typedef struct setup {
  uint32_t clips;
  double* xyz;
  double w[P];
  uint8_t valid[MAX_CLIPS * LEN];
  double heading[MAX_CLIPS * LEN];
  uint32_t first[MAX_CLIPS], frames[MAX_CLIPS], label[MAX_CLIPS];
  smgb_cloud cloud;
} setup;

static void setup_make(setup* s, const clip_spec* spec, uint32_t clips) {
  uint32_t c, f, p, seed = 777u;
  memset(s, 0, sizeof *s);
  s->clips = clips;
  s->xyz = malloc((size_t)clips * LEN * P * 3u * sizeof *s->xyz);
  for (p = 0; p < P; ++p) s->w[p] = 0.5 + 0.25 * p;
  for (c = 0; c < clips; ++c) {
    const clip_spec* cs = &spec[c];
    double h = cs->heading;
    s->first[c] = c * LEN;
    s->frames[c] = LEN;
    s->label[c] = cs->label;
    for (f = 0; f < LEN; ++f) {
      uint32_t g = c * LEN + f;
      double ph = cs->ph0 + cs->rate * f;
      double amp = f >= cs->switch_at ? cs->amp2 : cs->amp;
      double px = cs->x0 + 0.03 * f * sin(h), pz = cs->z0 + 0.03 * f * cos(h);
      s->valid[g] = f + K < LEN;
      s->heading[g] = h;
      for (p = 0; p < P; ++p) {
        double bx = amp * sin(ph + p) + 0.05 * p;
        double by = 0.3 + 0.1 * p + 0.05 * cos(2.0 * ph + p);
        double bz = amp * cos(ph + 0.5 * p);
        double* o = s->xyz + ((size_t)g * P + p) * 3u;
        seed = seed * 1664525u + 1013904223u;
        bz += 1e-4 * ((double)(seed >> 8) / (double)(1u << 24) - 0.5);
        o[0] = px + bx * cos(h) + bz * sin(h);
        o[1] = by;
        o[2] = pz - bx * sin(h) + bz * cos(h);
      }
    }
  }
  s->cloud.frames = clips * LEN;
  s->cloud.points = P;
  s->cloud.xyz = s->xyz;
  s->cloud.weights = s->w;
  s->cloud.valid = s->valid;
}

static void run(const setup* s, float radius, uint32_t threads,
                uint8_t* covered) {
  smgb_coverage_job job;
  float radii[2];
  radii[0] = radii[1] = radius;
  memset(&job, 0, sizeof job);
  job.cloud = &s->cloud;
  job.heading = s->heading;
  job.window = K;
  job.clip_count = s->clips;
  job.clip_first = s->first;
  job.clip_frames = s->frames;
  job.clip_label = s->label;
  job.label_count = 2;
  job.radius = radii;
  job.threads = threads;
  assert_int_equal(smgb_cover_clips(&job, covered), SMG_OK);
}

/* a whole cycle in 24 frames: a copy started n frames later holds the
 * same windows (but those of its last n frames, which the cycle's
 * earlier turns hold) */
#define RATE (2.0 * 3.14159265358979 / 24.0)
/* a clip of motif A: the same cycle, started a whole number of frames
 * later, walking elsewhere in another direction */
#define A(n, lab) \
  {RATE, 0.20, 0.20, RATE * (n), 0.7 * (n), 3.0 * (n), -2.0 * (n), LEN, lab}
/* motif B: a larger swing */
#define B(n, lab) \
  {RATE, 0.35, 0.35, RATE * (n), -0.4 * (n), 1.0 * (n), 2.0 * (n), LEN, lab}

/* Copies of kept motion are covered (wherever and in whichever direction
 * they walk); a clip of new motion is kept, and so is a copy that turns
 * into new motion half way. */
static void test_copies_covered(void** state) {
  clip_spec spec[6] = {A(0, 0), A(3, 0), B(1, 0), A(7, 0), B(5, 0), A(2, 0)};
  setup s;
  uint8_t cov[6];
  (void)state;
  spec[5].switch_at = LEN / 2;
  spec[5].amp2 = 0.28;
  setup_make(&s, spec, 6);
  run(&s, 0.01f, 1, cov);
  assert_int_equal(cov[0], 0); /* first: always kept */
  assert_int_equal(cov[1], 1);
  assert_int_equal(cov[2], 0); /* new motion */
  assert_int_equal(cov[3], 1);
  assert_int_equal(cov[4], 1);
  assert_int_equal(cov[5], 0); /* half new */
  free(s.xyz);
}

/* Labels are decided alone: the first clip of a label is kept even when
 * another label holds the same motion; a radius of 0 covers nothing. */
static void test_labels_and_radius(void** state) {
  clip_spec spec[4] = {A(0, 0), A(1, 1), A(2, 1), A(3, 0)};
  setup s;
  uint8_t cov[4];
  (void)state;
  setup_make(&s, spec, 4);
  run(&s, 0.01f, 1, cov);
  assert_int_equal(cov[0], 0);
  assert_int_equal(cov[1], 0);
  assert_int_equal(cov[2], 1);
  assert_int_equal(cov[3], 1);
  run(&s, 0.0f, 1, cov);
  assert_int_equal(cov[0] + cov[1] + cov[2] + cov[3], 0);
  free(s.xyz);
}

/* A radius below the distance between motifs keeps both; one above it
 * lets the first motif cover the second; 1 and 2 threads agree. */
static void test_radius_and_threads(void** state) {
  clip_spec spec[8] = {A(0, 0), B(1, 0), A(2, 1), B(3, 1),
                       A(4, 0), B(5, 1), A(6, 1), B(7, 0)};
  setup s;
  uint8_t one[8], two[8];
  uint32_t c;
  (void)state;
  setup_make(&s, spec, 8);
  run(&s, 0.01f, 1, one);
  run(&s, 0.01f, 2, two);
  assert_memory_equal(one, two, 8);
  assert_int_equal(one[0] + one[1] + one[2] + one[3], 0);
  for (c = 4; c < 8; ++c) assert_int_equal(one[c], 1);
  run(&s, 1.0f, 2, two);
  assert_int_equal(two[0], 0);
  assert_int_equal(two[1], 1);
  free(s.xyz);
}

/* More kept windows than the pass scans plainly: they go into its
 * kd-tree, and copies are still found there. 16 motifs of different
 * swings, then a copy of each. */
static void test_many_kept(void** state) {
  clip_spec spec[MAX_CLIPS];
  setup s;
  uint8_t cov[MAX_CLIPS];
  uint32_t c, kept = 0;
  (void)state;
  for (c = 0; c < MAX_CLIPS; ++c) {
    clip_spec a = A(c, 0);
    a.amp = a.amp2 = 0.10 + 0.04 * (c % 16u);
    spec[c] = a;
  }
  setup_make(&s, spec, MAX_CLIPS);
  run(&s, 0.01f, 1, cov);
  for (c = 0; c < 16; ++c) kept += !cov[c];
  assert_true(kept * (LEN - K) > 1024u); /* more than the plain scan */
  for (c = 16; c < MAX_CLIPS; ++c) assert_int_equal(cov[c], 1);
  free(s.xyz);
}

/* The pool without covered clips: frames, poses and positions of the
 * kept clips move down in order, nodes and edges follow their frames, a
 * mirror whose original left becomes its own source. */
static void test_pool_drop_covered(void** state) {
  smgb_bake b;
  smgb_pool_clip* pc;
  uint32_t c, f, counts[4] = {5, 7, 4, 7};
  smgb_edge e;
  (void)state;
  smgb_bake_init(&b, NULL, NULL);
  b.J = 2;
  b.stride = 7;
  /* clip 1 covered; clip 3 is its mirror (kept) */
  for (c = 0; c < 4; ++c) {
    assert_int_equal(smgb_pool_reserve(&b, counts[c]), SMG_OK);
    pc = smgb_pool_new_clip(&b, "clip", counts[c], 0, SMGI_CLIP_LOWER,
                            c == 3 ? 1u : SMGI_NONE);
    assert_non_null(pc);
    for (f = 0; f < counts[c]; ++f) {
      uint32_t g = b.frame_count++;
      b.poses[(size_t)g * b.stride] = (float)g;
      b.positions[(size_t)g * 3u * b.J] = (float)g;
      b.frames[g].clip = c;
      b.frames[g].phase = (float)g;
    }
  }
  b.source_frame_count = b.frame_count;
  b.clips[1].covered = 1;
  /* pool: clip 0 [0, 5), 1 [5, 12), 2 [12, 16), 3 [16, 23); nodes at
   * frames 2 (clip 0), 13 (clip 2), 17 and 21 (clip 3) */
  assert_int_equal(smgb_graph_add_node(&b.lower, 2, 0, NULL), SMG_OK);
  assert_int_equal(smgb_graph_add_node(&b.lower, 13, 0, NULL), SMG_OK);
  assert_int_equal(smgb_graph_add_node(&b.lower, 17, 0, NULL), SMG_OK);
  assert_int_equal(smgb_graph_add_node(&b.lower, 21, 0, NULL), SMG_OK);
  memset(&e, 0, sizeof e);
  e.kind = SMGB_EDGE_TRANSITION;
  e.from = 0;
  e.to = 3;
  e.a = 2;
  e.b = 18;
  assert_int_equal(smgb_graph_add_edge(&b.lower, &e), SMG_OK);
  smgb_pool_drop_covered(&b);
  assert_int_equal(b.clip_count, 3);
  assert_int_equal(b.frame_count, 16);
  assert_int_equal(b.source_frame_count, 16);
  assert_int_equal(b.covered_clips, 1);
  assert_int_equal(b.covered_frames, 7);
  assert_int_equal(b.clips[1].first, 5);
  assert_int_equal(b.clips[1].count, 4);
  assert_int_equal(b.clips[2].first, 9);
  assert_int_equal(b.clips[2].source_clip, 2);
  assert_int_equal(b.clips[0].source_clip, 0);
  for (f = 0; f < 16; ++f) {
    float old = (float)(f < 5 ? f : f + 7);
    assert_true(b.poses[(size_t)f * b.stride] == old);
    assert_true(b.positions[(size_t)f * 3u * b.J] == old);
    assert_true(b.frames[f].phase == old);
    assert_int_equal(b.frames[f].clip, f < 5 ? 0 : f < 9 ? 1 : 2);
  }
  assert_int_equal(b.lower.nodes[0].frame, 2);
  assert_int_equal(b.lower.nodes[1].frame, 6);
  assert_int_equal(b.lower.nodes[2].frame, 10);
  assert_int_equal(b.lower.nodes[3].frame, 14);
  assert_int_equal(b.lower.edges[0].a, 2);
  assert_int_equal(b.lower.edges[0].b, 11);
  smgb_bake_free(&b);
}

/* A whole bake big enough for the search (and so the pass): copies of a
 * straight and a turning synthetic walk and of a run, each listed
 * several times, plus a wave. The copies are covered and leave the blob,
 * which loads with full validation, keeps both styles and the action, and
 * is the same for 1 and 2 threads. */
static void test_bake_leaves_copies_out(void** state) {
  bg_set s;
  smg_bake_clip_desc descs[24];
  smg_bake_desc d;
  smg_bake_result one, two;
  smgi_graph_data g;
  smg_graph* graph = NULL;
  /* valgrind: just above the size where the search takes over */
  float seconds = smgt_quick() ? 12.0f : 20.0f;
  uint32_t i, n = 0, copies = smgt_quick() ? 4u : 6u;
  (void)state;
  memset(&s, 0, sizeof s);
  bg_add(&s, SMGB_SYNTH_WALK, seconds, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(&s, SMGB_SYNTH_WALK, seconds, 0.4f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(&s, SMGB_SYNTH_RUN, seconds, 0.0f, SMG_BAKE_ROLE_LOWER, "run");
  bg_add(&s, SMGB_SYNTH_WAVE, 10.0f, 0.0f, SMG_BAKE_ROLE_UPPER, "wave");
  for (i = 0; i < copies; ++i) {
    descs[n++] = s.descs[0];
    descs[n++] = s.descs[1];
    descs[n++] = s.descs[2];
  }
  descs[n++] = s.descs[3];
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = n;
  d.options.struct_size = sizeof d.options;
  d.options.threads = 1;
  memset(&one, 0, sizeof one);
  one.struct_size = sizeof one;
  if (smg_bake_run(&d, &one) != SMG_OK) fail_msg("%s", one.error);
  /* mirrored: above the exact grid's size (about 7,000 frames) */
  assert_true(one.stats.source_frames + one.covered_frame_count >
              2u * (uint32_t)(30.0f * seconds) * 3u * copies);
  /* every repeat of a clip (and more) is covered; nothing else is lost */
  assert_true(one.covered_clip_count >= 2u * 3u * (copies - 1u));
  assert_int_equal(one.stats.clip_count + one.covered_clip_count, 2u * n);
  assert_int_equal(one.stats.style_count, 2);
  assert_int_equal(one.stats.action_count, 2);
  bg_read(&one, &g);
  assert_int_equal(g.clip_count, one.stats.clip_count + 2u); /* + blends */
  for (i = 0; i < g.lower_node_count; ++i)
    assert_true(g.lower_nodes[i].frame < g.frame_count);
  assert_int_equal(smg_graph_load_memory(one.blob, one.blob_size, NULL,
                                         &graph),
                   SMG_OK);
  assert_int_equal(smg_graph_destroy(graph), SMG_OK);
  if (!smgt_quick()) {
    d.options.threads = 2;
    memset(&two, 0, sizeof two);
    two.struct_size = sizeof two;
    if (smg_bake_run(&d, &two) != SMG_OK) fail_msg("%s", two.error);
    assert_int_equal(two.blob_size, one.blob_size);
    assert_memory_equal(two.blob, one.blob, one.blob_size);
    smg_bake_result_free(&two);
  }
  smg_bake_result_free(&one);
  bg_free(&s);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_copies_covered),
      cmocka_unit_test(test_labels_and_radius),
      cmocka_unit_test(test_radius_and_threads),
      cmocka_unit_test(test_many_kept),
      cmocka_unit_test(test_pool_drop_covered),
      cmocka_unit_test(test_bake_leaves_copies_out),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
