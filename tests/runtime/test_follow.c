/*
 * test_follow.c - behaviour of characters on the fixture graph: straight
 * and 90-degree paths are followed with bounded error, transition points
 * switch the style and splice points the action within a bounded distance,
 * a path edited every frame keeps poses finite and root motion continuous,
 * results are bit-identical for identical inputs (also across threads),
 * step/pose never allocate, and 10^5-point paths work.
 */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define DT (1.0f / 60.0f)

/* The fixture graph for every test of this file (runtime_testutil.h). */
typedef rt_fixture_ctx ctx;

static smg_character_state get_state(const smg_character* ch) {
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  return s;
}

typedef struct run_stats {
  float max_err, mean_err, final_distance, max_jump;
  int finite;
} run_stats;

/* Step `seconds`, tracking the distance from the path and root jumps. */
static run_stats run(smg_character* ch, float seconds) {
  run_stats r = {0, 0, 0, 0, 1};
  float root[3], prev[3], rot[4 * FIXTURE_JOINTS];
  int n = (int)(seconds / DT);
  assert_int_equal(smg_character_get_local_pose(ch, prev, rot, FIXTURE_JOINTS),
                   SMG_OK);
  for (int i = 0; i < n; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    smg_character_state s = get_state(ch);
    assert_int_equal(
        smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS), SMG_OK);
    if (!rt_pose_finite(root, rot, FIXTURE_JOINTS)) r.finite = 0;
    float dx = root[0] - prev[0], dz = root[2] - prev[2];
    float jump = sqrtf(dx * dx + dz * dz);
    if (jump > r.max_jump) r.max_jump = jump;
    memcpy(prev, root, sizeof prev);
    /* following error; after the end it circles the end point instead */
    if (!(s.flags & SMG_STATE_PATH_END_REACHED)) {
      if (s.path_error > r.max_err) r.max_err = s.path_error;
      r.mean_err += s.path_error / (float)n;
    }
    r.final_distance = s.path_distance;
  }
  return r;
}

static void test_straight(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  float xz[2 * 41];
  rt_line(xz, 41, 20.0f);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 41), SMG_OK);
  run_stats r = run(ch, 8.0f);
  print_message("straight: max err %.3f m, mean %.3f m, distance %.2f m\n",
                r.max_err, r.mean_err, r.final_distance);
  assert_true(r.finite);
  assert_true(r.max_err < 0.15f);
  /* walking at 1.2 m/s for 8 s */
  assert_true(r.final_distance > 8.0f && r.final_distance < 11.0f);
  assert_true(r.max_jump < 0.1f);
  smg_character_destroy(ch);
}

/* A drawn 90-degree turn (rounded, radius r) and, with r = 0, a sharp
 * corner the data can only cut. */
static void turn_case(ctx* c, int left, float r, float max_bound,
                      float mean_bound) {
  smg_character* ch = NULL;
  float xz[2 * 64];
  uint32_t n = rt_turn_r(xz, 5.0f, 8.0f, left, r);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  run_stats st = run(ch, 12.0f);
  smg_character_state s = get_state(ch);
  print_message("%s turn, radius %.1f m: max err %.3f m, mean %.3f m, "
                "distance %.2f m, end at (%.2f, %.2f)\n",
                left ? "left" : "right", r, st.max_err, st.mean_err,
                st.final_distance, s.position[0], s.position[2]);
  assert_true(st.finite);
  assert_true(st.max_err < max_bound);
  assert_true(st.mean_err < mean_bound);
  assert_true(st.final_distance > 10.0f);
  /* it went the right way round the corner */
  assert_true(left ? s.position[0] > 3.0f : s.position[0] < -3.0f);
  smg_character_destroy(ch);
}

/* The fixture turns 45 degrees per 1.2 m (about a 1.5 m radius): a 2 m
 * turn can be followed closely, a sharp corner only cut. */
static void test_turn_left(void** state) {
  turn_case((ctx*)*state, 1, 2.0f, 0.4f, 0.2f);
  turn_case((ctx*)*state, 1, 0.0f, 1.0f, 0.3f);
}
static void test_turn_right(void** state) {
  turn_case((ctx*)*state, 0, 2.0f, 0.4f, 0.2f);
  turn_case((ctx*)*state, 0, 0.0f, 1.0f, 0.3f);
}

static void test_transition(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  float xz[2 * 61];
  uint32_t id;
  rt_line(xz, 61, 60.0f);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 61), SMG_OK);
  assert_int_equal(smg_character_add_transition(ch, 6.0f, 1, &id), SMG_OK);
  float switched_at = -1.0f, back_at = -1.0f, max_err = 0.0f;
  uint32_t id2;
  assert_int_equal(smg_character_add_transition(ch, 20.0f, 0, &id2), SMG_OK);
  for (int i = 0; i < 60 * 14; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    smg_character_state s = get_state(ch);
    if (s.style == 1 && switched_at < 0) switched_at = s.path_distance;
    if (switched_at >= 0 && s.style == 0 && back_at < 0)
      back_at = s.path_distance;
    if (switched_at < 0) assert_int_equal(s.style, 0);
    if (s.path_error > max_err) max_err = s.path_error;
  }
  print_message("transition path: max err %.3f m\n", max_err);
  assert_true(max_err < 0.3f);
  print_message("walk->run at %.2f m (point 6), run->walk at %.2f m (point "
                "20)\n",
                switched_at, back_at);
  /* within one edge of the point (walk cycle 1.2 m, run cycle 2 m) */
  assert_true(switched_at > 4.0f && switched_at < 8.0f);
  assert_true(back_at > 18.0f && back_at < 23.0f);
  smg_character_destroy(ch);
}

static void test_splice(void** state) {
  ctx* c = (ctx*)*state;
  smg_character *ch = NULL, *plain = NULL;
  float xz[2 * 41];
  uint32_t id;
  rt_line(xz, 41, 30.0f);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_create(c->g, NULL, &plain), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 41), SMG_OK);
  assert_int_equal(smg_character_set_path(plain, xz, 41), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 3.0f, 1, &id), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 9.0f, 0, NULL), SMG_OK);
  float on_at = -1, off_at = -1, max_diff = 0, diff_after_off = 0;
  float r1[3], q1[4 * FIXTURE_JOINTS], r2[3], q2[4 * FIXTURE_JOINTS];
  for (int i = 0; i < 60 * 10; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(smg_character_step(plain, DT), SMG_OK);
    smg_character_state s = get_state(ch);
    if (s.action == 1 && on_at < 0) on_at = s.path_distance;
    if (on_at >= 0 && s.action == 0 && off_at < 0) off_at = s.path_distance;
    smg_character_get_local_pose(ch, r1, q1, FIXTURE_JOINTS);
    smg_character_get_local_pose(plain, r2, q2, FIXTURE_JOINTS);
    /* the lower body is the same motion; the right arm (joint 25) punches */
    float d = 0;
    for (int k = 0; k < 4; ++k) d += fabsf(q1[4 * 25 + k] - q2[4 * 25 + k]);
    if (s.action == 1 && d > max_diff) max_diff = d;
    if (off_at >= 0 && s.path_distance > off_at + 2.0f) diff_after_off += d;
    assert_true(s.sync_rate >= 0.5f && s.sync_rate <= 2.0f);
  }
  print_message("punch on at %.2f m (point 3), off at %.2f m (point 9), arm "
                "difference %.3f\n",
                on_at, off_at, max_diff);
  assert_true(on_at > 2.0f && on_at < 5.0f);
  assert_true(off_at > 8.0f && off_at < 10.5f);
  assert_true(max_diff > 0.05f);       /* the action really shows */
  assert_true(diff_after_off < 1e-3f); /* and is gone after the crossfade */
  smg_character_destroy(ch);
  smg_character_destroy(plain);
}

/* Synchronization: the fixture's punch clip walks with a 30-frame gait
 * cycle. Under walking (30-frame cycle) it plays at rate 1; under running
 * (20-frame cycle) the time warp must play it 1.5 times faster so its
 * support phases stay with the legs. */
static void test_sync_rate(void** state) {
  ctx* c = (ctx*)*state;
  for (uint32_t style = 0; style < 2; ++style) {
    smg_character_desc d;
    smg_character* ch = NULL;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.initial_style = style;
    d.initial_action = 1;
    assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
    float xz[2 * 61];
    rt_line(xz, 61, 100.0f);
    assert_int_equal(smg_character_set_path(ch, xz, 61), SMG_OK);
    double sum = 0;
    int n = 0;
    for (int i = 0; i < 600; ++i) {
      assert_int_equal(smg_character_step(ch, DT), SMG_OK);
      smg_character_state s = get_state(ch);
      assert_int_equal(s.action, 1);
      if (i >= 120) {
        sum += s.sync_rate;
        ++n;
      }
    }
    double mean = sum / n;
    print_message("%s with the walking punch: mean sync rate %.3f\n",
                  style ? "running" : "walking", mean);
    if (style == 0) {
      assert_true(fabs(mean - 1.0) < 0.05);
    } else {
      assert_true(fabs(mean - 1.5) < 0.1);
    }
    smg_character_destroy(ch);
  }
}

/* A path that changes every frame: a wobbling line ahead of the character,
 * alternately replaced and appended to, with a constraint moved around. */
static void edit_frame(smg_character* ch, int i, float* xz) {
  smg_character_state s = get_state(ch);
  float wob = 0.8f * sinf((float)i * 0.05f);
  uint32_t n = 16;
  for (uint32_t k = 0; k < n; ++k) {
    xz[2 * k] = s.position[0] + wob * (float)k / (float)n;
    xz[2 * k + 1] = s.position[2] + 0.5f * (float)k;
  }
  if (i % 3 == 2) {
    smg_character_append_path(ch, xz + 2 * (n - 1), 1);
  } else {
    assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  }
  if (i % 50 == 0) smg_character_clear_constraints(ch);
  if (i % 50 == 1) smg_character_add_transition(ch, 3.0f, 1, NULL);
  if (i % 50 == 2) smg_character_add_splice(ch, 1.0f, (uint32_t)(i / 50) % 2, NULL);
}

static void test_edit_every_frame(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  float xz[64], root[3], prev[3], rot[4 * FIXTURE_JOINTS];
  int frames = smgt_quick() ? 1500 : 10000;
  float max_jump = 0;
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  smg_character_get_local_pose(ch, prev, rot, FIXTURE_JOINTS);
  for (int i = 0; i < frames; ++i) {
    edit_frame(ch, i, xz);
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(
        smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS), SMG_OK);
    assert_true(rt_pose_finite(root, rot, FIXTURE_JOINTS));
    float dx = root[0] - prev[0], dy = root[1] - prev[1],
          dz = root[2] - prev[2];
    float jump = sqrtf(dx * dx + dy * dy + dz * dz);
    if (jump > max_jump) max_jump = jump;
    memcpy(prev, root, sizeof prev);
  }
  print_message("edited every frame for %d frames: largest root move per "
                "frame %.4f m\n",
                frames, max_jump);
  /* running at 3 m/s moves 0.05 m per 1/60 s: anything far above that is
   * a pop */
  assert_true(max_jump < 0.09f);
  smg_character_destroy(ch);
}

/* Same inputs, two characters: bit-identical poses every frame. */
static void drive(smg_graph* g, int frames, float* out_root, float* out_rot) {
  smg_character* ch = NULL;
  smg_character_desc d;
  float xz[64];
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = 1234;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  for (int i = 0; i < frames; ++i) {
    if (i % 7 == 0) edit_frame(ch, i, xz);
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
  }
  smg_character_get_local_pose(ch, out_root, out_rot, FIXTURE_JOINTS);
  smg_character_destroy(ch);
}

static void test_determinism(void** state) {
  ctx* c = (ctx*)*state;
  smg_character *a = NULL, *b = NULL;
  float xz[64];
  float ra[3], qa[4 * FIXTURE_JOINTS], rb[3], qb[4 * FIXTURE_JOINTS];
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = 99;
  assert_int_equal(smg_character_create(c->g, &d, &a), SMG_OK);
  assert_int_equal(smg_character_create(c->g, &d, &b), SMG_OK);
  int frames = smgt_quick() ? 600 : 3000;
  for (int i = 0; i < frames; ++i) {
    edit_frame(a, i, xz);
    edit_frame(b, i, xz);
    assert_int_equal(smg_character_step(a, DT), SMG_OK);
    assert_int_equal(smg_character_step(b, DT), SMG_OK);
    smg_character_get_local_pose(a, ra, qa, FIXTURE_JOINTS);
    smg_character_get_local_pose(b, rb, qb, FIXTURE_JOINTS);
    assert_memory_equal(ra, rb, sizeof ra);
    assert_memory_equal(qa, qb, sizeof qa);
  }
  smg_character_destroy(a);
  smg_character_destroy(b);
}

static void test_no_allocation_in_step(void** state) {
  ctx* c = (ctx*)*state;
  rt_counter cnt = {0, 0};
  smg_character_desc d;
  smg_character* ch = NULL;
  float xz[64], root[3], rot[4 * FIXTURE_JOINTS], mats[16 * FIXTURE_JOINTS];
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.allocator.alloc = rt_count_alloc;
  d.allocator.free = rt_count_free;
  d.allocator.user = &cnt;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  long after_create = cnt.allocs;
  int frames = smgt_quick() ? 1000 : 10000;
  for (int i = 0; i < frames; ++i) {
    edit_frame(ch, i, xz);
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS);
    smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                     FIXTURE_JOINTS);
  }
  assert_int_equal(cnt.allocs, after_create);
  assert_int_equal(cnt.frees, 0);
  smg_character_destroy(ch);
  assert_int_equal(cnt.frees, cnt.allocs);
}

typedef struct job {
  smg_graph* g;
  int frames;
  float root[3], rot[4 * FIXTURE_JOINTS];
} job;

static void* thread_main(void* arg) {
  job* j = (job*)arg;
  drive(j->g, j->frames, j->root, j->rot);
  return NULL;
}

static void test_threads(void** state) {
  ctx* c = (ctx*)*state;
  enum { N = 4 };
  job jobs[N], ref;
  pthread_t th[N];
  int frames = smgt_quick() ? 300 : 2000;
  ref.g = c->g;
  ref.frames = frames;
  drive(c->g, frames, ref.root, ref.rot);
  for (int i = 0; i < N; ++i) {
    jobs[i].g = c->g;
    jobs[i].frames = frames;
    assert_int_equal(pthread_create(&th[i], NULL, thread_main, &jobs[i]), 0);
  }
  for (int i = 0; i < N; ++i) assert_int_equal(pthread_join(th[i], NULL), 0);
  for (int i = 0; i < N; ++i) {
    assert_memory_equal(jobs[i].root, ref.root, sizeof ref.root);
    assert_memory_equal(jobs[i].rot, ref.rot, sizeof ref.rot);
  }
}

static void test_long_path(void** state) {
  ctx* c = (ctx*)*state;
  const uint32_t N = 100000;
  smg_character_desc d;
  smg_character* ch = NULL;
  float* xz = (float*)malloc(sizeof(float) * 2 * N);
  /* 10^5 points, 1 cm apart, a gentle S curve along +Z */
  for (uint32_t i = 0; i < N; ++i) {
    float z = 0.01f * (float)i;
    xz[2 * i] = 0.5f * sinf(z * 0.2f);
    xz[2 * i + 1] = z;
  }
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = N;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, N / 2), SMG_OK);
  assert_int_equal(smg_character_append_path(ch, xz + N, N / 2), SMG_OK);
  float len;
  smg_character_get_path_length(ch, &len);
  assert_true(len > 999.0f && len < 1003.0f);
  run_stats r = run(ch, smgt_quick() ? 3.0f : 10.0f);
  print_message("10^5-point path: max err %.3f, distance %.2f\n", r.max_err,
                r.final_distance);
  assert_true(r.finite);
  /* the fixture turns in 45-degree steps, so a gentle curve is followed
   * to within about half a metre */
  assert_true(r.max_err < 0.6f);
  assert_true(r.final_distance > (smgt_quick() ? 2.5f : 10.0f));
  /* replace it while walking: progress restarts at the nearest point */
  assert_int_equal(smg_character_set_path(ch, xz, N), SMG_OK);
  smg_character_state s = get_state(ch);
  assert_true(fabsf(s.path_distance - r.final_distance) < 0.5f);
  smg_character_destroy(ch);
  free(xz);
}

static void test_path_end_and_single_point(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  float xz[4] = {0, 0, 0, 3};
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 2), SMG_OK);
  int reached = 0;
  float far = 0;
  for (int i = 0; i < 60 * 10; ++i) {
    smg_character_step(ch, DT);
    smg_character_state s = get_state(ch);
    if (s.flags & SMG_STATE_PATH_END_REACHED) reached = 1;
    if (reached) {
      float dz = s.position[2] - 3.0f, dx = s.position[0];
      float dist = sqrtf(dx * dx + dz * dz);
      if (dist > far) far = dist;
    }
  }
  print_message("path end: reached %d, furthest afterwards %.2f m\n", reached,
                far);
  assert_true(reached);
  /* no idle clip in the fixture: it keeps walking but circles near the end
   * (its tightest circle, 45 degrees per 1.2 m, is about 3 m across) */
  assert_true(far < 3.6f);
  /* a single point is a place to go to */
  float pt[2] = {4.0f, 8.0f};
  assert_int_equal(smg_character_set_path(ch, pt, 1), SMG_OK);
  float best = 1e9f;
  for (int i = 0; i < 60 * 12; ++i) {
    smg_character_step(ch, DT);
    smg_character_state s = get_state(ch);
    float dx = s.position[0] - 4.0f, dz = s.position[2] - 8.0f;
    float d = sqrtf(dx * dx + dz * dz);
    if (d < best) best = d;
  }
  print_message("single point: closest approach %.2f m\n", best);
  assert_true(best < 1.0f);
  smg_character_destroy(ch);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_straight),
      cmocka_unit_test(test_turn_left),
      cmocka_unit_test(test_turn_right),
      cmocka_unit_test(test_transition),
      cmocka_unit_test(test_splice),
      cmocka_unit_test(test_sync_rate),
      cmocka_unit_test(test_edit_every_frame),
      cmocka_unit_test(test_determinism),
      cmocka_unit_test(test_no_allocation_in_step),
      cmocka_unit_test(test_threads),
      cmocka_unit_test(test_long_path),
      cmocka_unit_test(test_path_end_and_single_point),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
