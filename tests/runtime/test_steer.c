/*
 * test_steer.c - root steering (steer.c), judged from the exported poses:
 *  - a sharp 90-degree corner and a 2 m U-turn, which the fixture's motion
 *    (45 degrees of turn per 1.2 m, about a 1.5 m radius) can only cut,
 *    are rounded with a radius of about 1 m: the root stays within the
 *    distance such a rounding gives (0.29 r) plus the gait's sway, and
 *    the same run with steering off leaves that bound (the test can fail);
 *  - at the end the character comes to rest with the root within 0.3 m of
 *    the last point, stands (speed <= 0.1 m/s over the last second) and
 *    reports SMG_STATE_PATH_END_REACHED; appending points starts it again;
 *    a run walks the last metres and stands on both feet;
 *  - the correction is continuous: no per-step root jump beyond what the
 *    same motion does without steering plus the correction's bound, and
 *    switching steering off mid-run fades the correction out;
 *  - settings: negative or non-finite limits are refused at create and by
 *    the setter, which then changes nothing (bit-identical poses);
 *  - with steering off the state reports no correction and playback rate
 *    1; the steering on the synthetic default graph follows a corner too;
 *  - a runner gets round a 0.2 m hairpin and back (no circling beside
 *    its tip) without slowing for it longer than its cut needs, keeps the run asked for through the scribble's hairpins
 *    (issue 24's style-held share, >= 75 %, from the root's 1 s window
 *    speed), and faces its travel round a U-turn (95th percentile within
 *    10 degrees).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define DT (1.0f / 60.0f)

typedef rt_fixture_ctx ctx;

static smg_character_state get_state(const smg_character* ch) {
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  return s;
}

/* Distance from (x, z) to the polyline. */
static float polyline_distance(const float* xz, uint32_t n, float x,
                               float z) {
  float best = INFINITY;
  for (uint32_t i = 1; i < n; ++i) {
    float ax = xz[2 * i - 2], az = xz[2 * i - 1];
    float dx = xz[2 * i] - ax, dz = xz[2 * i + 1] - az;
    float l2 = dx * dx + dz * dz;
    float t = l2 > 0.0f ? ((x - ax) * dx + (z - az) * dz) / l2 : 0.0f;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    float ex = x - ax - t * dx, ez = z - az - t * dz;
    float d = sqrtf(ex * ex + ez * ez);
    if (d < best) best = d;
  }
  return best;
}

typedef struct run_result {
  float mean, max;      /* root to path until within 0.5 m of the end */
  int reached;          /* root came within 0.5 m of the last point */
  float rest_speed;     /* last second: mean root ground speed */
  float rest_dist;      /* last second: largest distance to the end */
  float max_jump;       /* largest per-step root ground displacement */
  int flag_at_end;      /* SMG_STATE_PATH_END_REACHED in the last step */
} run_result;

/* Runs a character on the path for `seconds`, measuring the root (joint
 * 0 of the exported local pose) on the ground. */
static run_result run_path(smg_graph* g, uint32_t J, const float* xz,
                           uint32_t n, uint32_t flags, float seconds) {
  run_result r;
  smg_character_desc d;
  smg_character* ch = NULL;
  float root[3], prev[3];
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  const float ex = xz[2 * n - 2], ez = xz[2 * n - 1];
  const int steps = (int)(seconds / DT), last = (int)(1.0f / DT);
  double sum = 0.0;
  int measured = 0;
  memset(&r, 0, sizeof r);
  assert_non_null(rot);
  rt_desc_on_path(&d, xz);
  d.flags = flags;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  assert_int_equal(smg_character_get_local_pose(ch, prev, rot, J), SMG_OK);
  for (int i = 0; i < steps; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    float jx = root[0] - prev[0], jz = root[2] - prev[2];
    float jump = sqrtf(jx * jx + jz * jz);
    if (jump > r.max_jump) r.max_jump = jump;
    float de = sqrtf((root[0] - ex) * (root[0] - ex) +
                     (root[2] - ez) * (root[2] - ez));
    if (!r.reached) {
      float e = polyline_distance(xz, n, root[0], root[2]);
      sum += e;
      ++measured;
      if (e > r.max) r.max = e;
      if (de < 0.5f) r.reached = 1;
    }
    if (i >= steps - last) {
      r.rest_speed += jump / (last * DT);
      if (de > r.rest_dist) r.rest_dist = de;
    }
    memcpy(prev, root, sizeof prev);
  }
  r.mean = measured ? (float)(sum / measured) : 0.0f;
  r.flag_at_end = (get_state(ch).flags & SMG_STATE_PATH_END_REACHED) != 0;
  smg_character_destroy(ch);
  free(rot);
  return r;
}

static void print_result(const char* what, const run_result* r) {
  print_message("%s: mean %.3f m, max %.3f m, reached %d, last second "
                "%.3f m/s at <= %.3f m from the end, max step %.3f m, end "
                "flag %d\n",
                what, r->mean, r->max, r->reached, r->rest_speed,
                r->rest_dist, r->max_jump, r->flag_at_end);
}

/* A sharp corner: 6 m, 90 degrees, 6 m. */
static uint32_t corner(float* xz, int left) {
  const float s = left ? 1.0f : -1.0f;
  xz[0] = 0.0f, xz[1] = 0.0f;
  xz[2] = 0.0f, xz[3] = 6.0f;
  xz[4] = 6.0f * s, xz[5] = 6.0f;
  return 3;
}

/* Rounded with radius <= 1 m the root stays within 0.29 m of a 90-degree
 * polyline corner (r (1 - cos 45 deg)); the gait's sway stays inside. */
#define CORNER_MAX 0.30f
#define CORNER_MEAN 0.10f

static void test_corner_and_rest(void** state) {
  ctx* c = (ctx*)*state;
  float xz[6];
  for (int left = 0; left < 2; ++left) {
    uint32_t n = corner(xz, left);
    run_result on = run_path(c->g, FIXTURE_JOINTS, xz, n, 0u, 16.0f);
    run_result off =
        run_path(c->g, FIXTURE_JOINTS, xz, n, SMG_CHARACTER_NO_STEERING, 16.0f);
    print_result(left ? "left corner, steering on" : "right corner, steering on",
                 &on);
    print_result("  steering off", &off);
    assert_true(on.max < CORNER_MAX);
    assert_true(on.mean < CORNER_MEAN);
    assert_true(on.reached);
    assert_true(on.rest_dist < 0.3f);
    assert_true(on.rest_speed <= 0.1f);
    assert_true(on.flag_at_end);
    /* without steering the fixture cuts the corner and never stands */
    assert_true(off.max > CORNER_MAX || off.rest_speed > 0.1f);
    /* continuity: steps no longer than the motion's own plus the
     * translation bound (a quarter of the speed) */
    assert_true(on.max_jump <= 1.25f * off.max_jump + 1e-3f);
  }
}

static void test_u_turn(void** state) {
  ctx* c = (ctx*)*state;
  const float xz[8] = {0.0f, 0.0f, 0.0f, 8.0f, 2.0f, 8.0f, 2.0f, 0.0f};
  run_result on = run_path(c->g, FIXTURE_JOINTS, xz, 4, 0u, 20.0f);
  print_result("U-turn 2 m across, steering on", &on);
  assert_true(on.max < CORNER_MAX);
  assert_true(on.mean < CORNER_MEAN);
  assert_true(on.reached);
  assert_true(on.rest_dist < 0.3f && on.rest_speed <= 0.1f);
}

/* Resting lasts until the path changes; appending points walks on. */
static void test_rest_until_path_changes(void** state) {
  ctx* c = (ctx*)*state;
  float xz[6], more[2];
  float root[3], rest[3], rot[4 * FIXTURE_JOINTS];
  smg_character* ch = NULL;
  uint32_t n = corner(xz, 1);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  for (int i = 0; i < (int)(16.0f / DT); ++i)
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
  assert_true(get_state(ch).flags & SMG_STATE_PATH_END_REACHED);
  assert_int_equal(smg_character_get_local_pose(ch, rest, rot, FIXTURE_JOINTS),
                   SMG_OK);
  for (int i = 0; i < (int)(3.0f / DT); ++i)
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
  assert_int_equal(smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS),
                   SMG_OK);
  /* standing: not a millimetre moved in 3 s */
  assert_true(fabsf(root[0] - rest[0]) < 1e-3f &&
              fabsf(root[2] - rest[2]) < 1e-3f);
  smg_character_state s = get_state(ch);
  assert_true(s.playback_rate == 0.0f);
  /* 4 m more along the last direction */
  more[0] = 10.0f;
  more[1] = 6.0f;
  assert_int_equal(smg_character_append_path(ch, more, 1), SMG_OK);
  assert_false(get_state(ch).flags & SMG_STATE_PATH_END_REACHED);
  for (int i = 0; i < (int)(2.0f / DT); ++i)
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
  assert_int_equal(smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS),
                   SMG_OK);
  print_message("after appending 4 m: moved %.2f m along +x in 2 s\n",
                root[0] - rest[0]);
  assert_true(root[0] - rest[0] > 0.8f);
  for (int i = 0; i < (int)(8.0f / DT); ++i)
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
  s = get_state(ch);
  assert_true(s.flags & SMG_STATE_PATH_END_REACHED);
  assert_true(fabsf(s.position[0] - 10.0f) < 0.3f &&
              fabsf(s.position[2] - 6.0f) < 0.3f);
  smg_character_destroy(ch);
}

/* A run asked for until the end: the last metres are walked (the graph's
 * most agile style) so that the stop lands on a frame with both feet down,
 * within 0.3 m of the last point. */
static void test_run_comes_to_rest(void** state) {
  ctx* c = (ctx*)*state;
  float xz[2 * 21];
  smg_character* ch = NULL;
  float root[3], prev[3], rot[4 * FIXTURE_JOINTS];
  rt_line(xz, 21, 20.0f);
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 21), SMG_OK);
  assert_int_equal(smg_character_add_transition(ch, 2.0f, 1, NULL), SMG_OK);
  int ran = 0;
  float travelled = 0.0f;
  smg_character_get_local_pose(ch, prev, rot, FIXTURE_JOINTS);
  const int steps = (int)(14.0f / DT);
  for (int i = 0; i < steps; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    if (get_state(ch).style == 1) ran = 1;
    smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS);
    if (i >= steps - (int)(1.0f / DT))
      travelled += sqrtf((root[0] - prev[0]) * (root[0] - prev[0]) +
                         (root[2] - prev[2]) * (root[2] - prev[2]));
    memcpy(prev, root, sizeof prev);
  }
  smg_character_state s = get_state(ch);
  print_message("run to the end: ran %d, rests at z %.2f (end 20) in style "
                "%u, contacts %u, last second %.3f m\n",
                ran, root[2], s.style, s.flags & 12u, travelled);
  assert_true(ran);
  assert_true(fabsf(root[2] - 20.0f) < 0.3f && fabsf(root[0]) < 0.3f);
  assert_true(travelled <= 0.1f);
  assert_true(s.flags & SMG_STATE_PATH_END_REACHED);
  assert_int_equal(s.style, 0); /* walked out */
  assert_int_equal(s.flags & (SMG_STATE_LEFT_CONTACT | SMG_STATE_RIGHT_CONTACT),
                   SMG_STATE_LEFT_CONTACT | SMG_STATE_RIGHT_CONTACT);
  smg_character_destroy(ch);
}

/* Off: no correction reported, full playback, and switching it off in
 * mid-run fades the correction instead of dropping it. */
static void test_switch_off(void** state) {
  ctx* c = (ctx*)*state;
  float xz[6];
  smg_character* ch = NULL;
  smg_character_desc d;
  uint32_t n = corner(xz, 1);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.flags = SMG_CHARACTER_NO_STEERING;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  /* off for 3 s (3.6 m of the 6 m lead) */
  for (int i = 0; i < (int)(3.0f / DT); ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    smg_character_state s = get_state(ch);
    assert_true(s.steer_turn_rate == 0.0f && s.steer_slide_speed == 0.0f);
    assert_true(s.playback_rate == 1.0f);
  }
  /* on for the corner, then off while it corrects */
  assert_int_equal(smg_character_set_steering(ch, 1), SMG_OK);
  float peak = 0.0f, prev = 0.0f, max_change = 0.0f;
  for (int i = 0; i < (int)(5.0f / DT); ++i) {
    if (fabsf(prev) > peak) peak = fabsf(prev);
    if (i == (int)(2.2f / DT))
      assert_int_equal(smg_character_set_steering(ch, 0), SMG_OK);
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    float t = get_state(ch).steer_turn_rate;
    if (fabsf(t - prev) > max_change) max_change = fabsf(t - prev);
    prev = t;
  }
  print_message("switch on, then off: largest correction %.3f rad/s, "
                "largest change per step %.3f rad/s, %.4f at the end\n",
                peak, max_change, prev);
  assert_true(peak > 0.2f); /* it did correct the corner */
  /* the rate changes by at most its bounded acceleration per step
   * (SMGI_STEER_TURN_ACCEL, 8 rad/s^2), switching on and off included */
  assert_true(max_change <= 8.0f * DT + 1e-4f);
  assert_true(prev == 0.0f);
  smg_character_destroy(ch);
}

static void test_settings(void** state) {
  ctx* c = (ctx*)*state;
  smg_character_desc d;
  smg_character *a = NULL, *b = NULL;
  /* 1e30 s of braking made the frames to scan infinite (found by the
   * runtime fuzz target: tests/fuzz/regress/runtime/) */
  const float bad[] = {-1.0f, NAN, INFINITY, 1e30f};
  for (int k = 0; k < 4; ++k) {
    for (int f = 0; f < 3; ++f) {
      smg_character* ch = NULL;
      memset(&d, 0, sizeof d);
      d.struct_size = sizeof d;
      if (f == 0) d.steer_turn_rate = bad[k];
      if (f == 1) d.steer_slide_ratio = bad[k];
      if (f == 2) d.stop_seconds = bad[k];
      assert_int_equal(smg_character_create(c->g, &d, &ch),
                       SMG_ERROR_INVALID_ARGUMENT);
      assert_null(ch);
    }
  }
  assert_int_equal(smg_character_set_steering(NULL, 1),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_steering_limits(NULL, 0, 0, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  /* a refused setter changes nothing: same poses as an untouched twin */
  float xz[6];
  uint32_t n = corner(xz, 0);
  assert_int_equal(smg_character_create(c->g, NULL, &a), SMG_OK);
  assert_int_equal(smg_character_create(c->g, NULL, &b), SMG_OK);
  assert_int_equal(smg_character_set_path(a, xz, n), SMG_OK);
  assert_int_equal(smg_character_set_path(b, xz, n), SMG_OK);
  for (int k = 0; k < 4; ++k) {
    assert_int_equal(smg_character_set_steering_limits(a, bad[k], 1.0f, 1.0f),
                     SMG_ERROR_INVALID_ARGUMENT);
    assert_int_equal(smg_character_set_steering_limits(a, 1.0f, bad[k], 1.0f),
                     SMG_ERROR_INVALID_ARGUMENT);
    assert_int_equal(smg_character_set_steering_limits(a, 1.0f, 1.0f, bad[k]),
                     SMG_ERROR_INVALID_ARGUMENT);
  }
  float ra[3], qa[4 * FIXTURE_JOINTS], rb[3], qb[4 * FIXTURE_JOINTS];
  for (int i = 0; i < (int)(12.0f / DT); ++i) {
    assert_int_equal(smg_character_step(a, DT), SMG_OK);
    assert_int_equal(smg_character_step(b, DT), SMG_OK);
  }
  smg_character_get_local_pose(a, ra, qa, FIXTURE_JOINTS);
  smg_character_get_local_pose(b, rb, qb, FIXTURE_JOINTS);
  assert_memory_equal(ra, rb, sizeof ra);
  assert_memory_equal(qa, qb, sizeof qa);
  /* the maxima are accepted, a little more is not (on a third character:
   * a and b must stay twins) */
  {
    smg_character* m = NULL;
    assert_int_equal(smg_character_create(c->g, NULL, &m), SMG_OK);
    assert_int_equal(smg_character_set_steering_limits(
                         m, SMG_MAX_STEER_TURN_RATE, SMG_MAX_STEER_SLIDE_RATIO,
                         SMG_MAX_STOP_SECONDS),
                     SMG_OK);
    assert_int_equal(smg_character_set_steering_limits(
                         m, 1.01f * SMG_MAX_STEER_TURN_RATE, 0.0f, 0.0f),
                     SMG_ERROR_INVALID_ARGUMENT);
    assert_int_equal(smg_character_set_steering_limits(
                         m, 0.0f, 1.01f * SMG_MAX_STEER_SLIDE_RATIO, 0.0f),
                     SMG_ERROR_INVALID_ARGUMENT);
    assert_int_equal(smg_character_set_steering_limits(
                         m, 0.0f, 0.0f, 1.01f * SMG_MAX_STOP_SECONDS),
                     SMG_ERROR_INVALID_ARGUMENT);
    smg_character_destroy(m);
  }
  /* zero is the default: explicit defaults change nothing either */
  assert_int_equal(smg_character_set_steering_limits(a, 0.0f, 0.0f, 0.0f),
                   SMG_OK);
  /* a turn limit of 0.1 rad/s cannot round the corner: limits matter */
  smg_character_destroy(a);
  smg_character_destroy(b);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.steer_turn_rate = 0.1f;
  d.steer_slide_ratio = 0.01f;
  assert_int_equal(smg_character_create(c->g, &d, &a), SMG_OK);
  assert_int_equal(smg_character_set_path(a, xz, n), SMG_OK);
  float max_err = 0.0f;
  for (int i = 0; i < (int)(10.0f / DT); ++i) {
    assert_int_equal(smg_character_step(a, DT), SMG_OK);
    smg_character_state s = get_state(a);
    /* 0.1 rad/s (twice that while cutting a turn no slowing makes,
     * SMGI_STEER_CUT_TURN) plus half the motion's own turning (the
     * fixture turns at most about 1.5 rad/s) */
    assert_true(fabsf(s.steer_turn_rate) <= 2.0f * 0.1f + 0.5f * 1.5f);
    if (s.path_error > max_err) max_err = s.path_error;
  }
  /* slowed right down for the corner it cannot turn (a cut), the
   * fixture's own turning brings it round closer than without steering,
   * but still wider than the default limits' rounding */
  run_result def = run_path(c->g, FIXTURE_JOINTS, xz, n, 0u, 16.0f);
  print_message("weak limits: max error %.3f m (default limits %.3f m)\n",
                max_err, def.max);
  assert_true(max_err > def.max + 0.01f);
  smg_character_destroy(a);
}

/* The synthetic default graph (build/default.smg) rounds a corner too. */
static void test_default_graph_corner(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  smg_graph_info info;
  float xz[6];
  if (!g) {
    skip();
    return;
  }
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  for (int left = 0; left < 2; ++left) {
    uint32_t n = corner(xz, left);
    run_result on = run_path(g, info.joint_count, xz, n, 0u, 16.0f);
    print_result(left ? "default graph, left corner"
                      : "default graph, right corner", &on);
    assert_true(on.max < CORNER_MAX && on.mean < CORNER_MEAN);
    assert_true(on.reached && on.rest_dist < 0.3f && on.rest_speed <= 0.1f);
  }
  smg_graph_destroy(g);
}

/* A hairpin: 8 m straight, a half circle of radius 0.2 m, 8 m back. */
static uint32_t hairpin(float* xz) {
  uint32_t n = 0;
  xz[2 * n] = 0.0f, xz[2 * n + 1] = 0.0f, ++n;
  for (int k = 0; k <= 12; ++k) {
    float a = 3.14159265f * (float)k / 12.0f;
    xz[2 * n] = 0.2f - 0.2f * cosf(a);
    xz[2 * n + 1] = 8.0f + 0.2f * sinf(a);
    ++n;
  }
  xz[2 * n] = 0.4f, xz[2 * n + 1] = 0.0f, ++n;
  return n;
}

#define CUT_STEPS 720 /* 12 s at 60 Hz */

/* A run through the hairpin, from the exported root: the time it spends
 * beyond z = `z0` (the last metres before the turn, the turn and the
 * first metres back: 12 s when it never gets back) and how far off the
 * path it gets there. */
static void hairpin_pass(smg_graph* g, uint32_t J, const float* xz,
                         uint32_t n, uint32_t style, float z0,
                         float* seconds, float* wide) {
  smg_character_desc d;
  smg_character* ch = NULL;
  float root[3];
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  int inside = 0, back = 0;
  assert_non_null(rot);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.initial_style = style;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  *wide = 0.0f;
  for (int i = 0; i < CUT_STEPS && !back; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    if (root[2] < z0) {
      back = inside > 0;
      continue;
    }
    ++inside;
    const float e = polyline_distance(xz, n, root[0], root[2]);
    if (e > *wide) *wide = e;
  }
  *seconds = back ? inside * DT : CUT_STEPS * DT;
  smg_character_destroy(ch);
  free(rot);
}

/* A runner gets round a hairpin it cannot turn at any speed a tight turn
 * slows to (the steering cuts it: steer.c) and back: from 2 m before the
 * turn until 2 m back out within 1.65 s, never more than 1 m off the
 * path. The cut is taken at the speed its own pivot (twice the turn
 * limit, reached as fast as a plain turn reaches its limit) allows:
 * capped at what the plain turn limit allows, and pivoting no faster
 * than a plain turn, it took 1.72 s here and held a Bandai Namco
 * performer's run at running speed on only 66 % of the scribble
 * (issue 24). A cut that crossed to the leg beside the tip before passing it
 * left progress behind on the first leg (the local projection cannot
 * climb over the tip), and the character circled there for 9 s before
 * progress looked for a later pass nearer the character
 * (smgi_path_project_ahead). */
static void test_run_through_hairpin(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  smg_graph_info info;
  float xz[2 * 16], seconds, wide;
  if (!g) {
    skip();
    return;
  }
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  uint32_t n = hairpin(xz), run;
  assert_int_equal(smg_graph_find_style(g, "run", &run), SMG_OK);
  hairpin_pass(g, info.joint_count, xz, n, run, 6.0f, &seconds, &wide);
  print_message("run through a 0.2 m hairpin: %.2f s from 2 m before it to "
                "2 m back, %.2f m off the path at most\n", seconds, wide);
  assert_true(seconds < 1.65f);
  assert_true(wide < 1.0f);
  smg_graph_destroy(g);
}

#define HELD_MAX_POINTS 256
#define HELD_STEPS 1800 /* 30 s at 60 Hz */
#define HELD_HALF 30    /* half of a 1 s window */

/* data/paths/NAME.txt ("x z" per line, '#' comments): its point count, 0
 * when it cannot be read. */
static uint32_t read_path(const char* name, float* xz, uint32_t cap) {
  char file[256], line[256];
  uint32_t n = 0;
  snprintf(file, sizeof file, "data/paths/%s.txt", name);
  FILE* f = fopen(file, "r");
  if (!f) return 0;
  while (n < cap && fgets(line, sizeof line, f))
    if (line[0] != '#' && sscanf(line, "%f %f", &xz[2 * n], &xz[2 * n + 1]) == 2)
      ++n;
  fclose(f);
  return n;
}

/* The root's ground positions of a character started in `style` at the
 * path's first point facing its second, with a transition to `to` (when
 * not SMGI_NONE) 4 m along; the number of steps recorded. */
static int record_root(smg_graph* g, uint32_t J, const float* xz, uint32_t n,
                       uint32_t style, uint32_t to, float (*pos)[2]) {
  smg_character_desc d;
  smg_character* ch = NULL;
  float root[3];
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  uint32_t id;
  assert_non_null(rot);
  rt_desc_on_path(&d, xz);
  d.initial_style = style;
  d.path_capacity = HELD_MAX_POINTS;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  if (to != 0xffffffffu)
    assert_int_equal(smg_character_add_transition(ch, 4.0f, to, &id), SMG_OK);
  for (int i = 0; i < HELD_STEPS; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    pos[i][0] = root[0], pos[i][1] = root[2];
  }
  smg_character_destroy(ch);
  free(rot);
  return HELD_STEPS;
}

/* The root's path length over the 1 s window centred on step i, per
 * second. */
static float window_speed(const float (*pos)[2], int count, int i) {
  const int a = i > HELD_HALF ? i - HELD_HALF : 0;
  const int b = i + HELD_HALF < count ? i + HELD_HALF : count - 1;
  float way = 0.0f;
  for (int k = a + 1; k <= b; ++k)
    way += sqrtf((pos[k][0] - pos[k - 1][0]) * (pos[k][0] - pos[k - 1][0]) +
                 (pos[k][1] - pos[k - 1][1]) * (pos[k][1] - pos[k - 1][1]));
  return b > a ? way / ((float)(b - a) * DT) : 0.0f;
}

/* The arc length along the path of every recorded root position: the
 * nearest point within 0.5 m back and 1 m ahead of the last one. */
static void track_arc(const float* xz, uint32_t n, const float (*pos)[2],
                      int count, float* arc) {
  float s = 0.0f;
  for (int i = 0; i < count; ++i) {
    float best = INFINITY, at = s, cum = 0.0f;
    for (uint32_t k = 1; k < n; ++k) {
      const float ax = xz[2 * k - 2], az = xz[2 * k - 1];
      const float dx = xz[2 * k] - ax, dz = xz[2 * k + 1] - az;
      const float len = sqrtf(dx * dx + dz * dz);
      if (len > 1e-6f && cum + len >= s - 0.5f && cum <= s + 1.0f) {
        float t = ((pos[i][0] - ax) * dx + (pos[i][1] - az) * dz) / (len * len);
        t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
        const float ex = pos[i][0] - ax - t * dx, ez = pos[i][1] - az - t * dz;
        const float e = ex * ex + ez * ez;
        const float u = cum + t * len;
        if (e < best && u >= s - 0.5f && u <= s + 1.0f) best = e, at = u;
      }
      cum += len;
    }
    s = at;
    arc[i] = s;
  }
}

/* Median 1 s window speed between 3 m along and 4 m before the end of a
 * straight 20 m in `style`. */
static float straight_speed(smg_graph* g, uint32_t J, uint32_t style) {
  static float pos[HELD_STEPS][2], arc[HELD_STEPS], v[HELD_STEPS];
  const float xz[4] = {0.0f, 0.0f, 0.0f, 20.0f};
  int count = record_root(g, J, xz, 2, style, 0xffffffffu, pos), m = 0;
  track_arc(xz, 2, (const float(*)[2])pos, count, arc);
  for (int i = 0; i < count; ++i)
    if (arc[i] >= 3.0f && arc[i] <= 16.0f)
      v[m++] = window_speed((const float(*)[2])pos, count, i);
  for (int i = 1; i < m; ++i) { /* insertion sort */
    float x = v[i];
    int k = i;
    while (k > 0 && v[k - 1] > x) v[k] = v[k - 1], --k;
    v[k] = x;
  }
  return m ? v[m / 2] : NAN;
}

/* Issue 24's style-held share on a path: started walking with a
 * transition to run 4 m along, the share of the steps from 3 m after it
 * to 4 m before the end whose 1 s window speed exceeds midway between
 * the walk's and the run's on a straight line. */
static float style_held(smg_graph* g, const char* name) {
  static float xz[2 * HELD_MAX_POINTS], pos[HELD_STEPS][2], arc[HELD_STEPS];
  smg_graph_info info;
  uint32_t walk, run, n = read_path(name, xz, HELD_MAX_POINTS);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(smg_graph_find_style(g, "walk", &walk), SMG_OK);
  assert_int_equal(smg_graph_find_style(g, "run", &run), SMG_OK);
  assert_true(n >= 2);
  const uint32_t J = info.joint_count;
  const float midway =
      0.5f * (straight_speed(g, J, walk) + straight_speed(g, J, run));
  float length = 0.0f;
  for (uint32_t k = 1; k < n; ++k)
    length += sqrtf((xz[2 * k] - xz[2 * k - 2]) * (xz[2 * k] - xz[2 * k - 2]) +
                    (xz[2 * k + 1] - xz[2 * k - 1]) *
                        (xz[2 * k + 1] - xz[2 * k - 1]));
  int count = record_root(g, J, xz, n, walk, run, pos), judged = 0, fast = 0;
  track_arc(xz, n, (const float(*)[2])pos, count, arc);
  for (int i = 0; i < count; ++i) {
    if (arc[i] < 7.0f || arc[i] > length - 4.0f) continue;
    ++judged;
    fast += window_speed((const float(*)[2])pos, count, i) > midway;
  }
  print_message("%s: run held at %.0f %% of the judged steps (midway speed "
                "%.2f m/s)\n", name, judged ? 100.0f * fast / judged : 0.0f,
                midway);
  return judged ? (float)fast / (float)judged : 0.0f;
}

/* A run asked for on the scribble (loops of 2-3 m radius with hairpin
 * tips a few decimetres across) is kept through the hairpins: the runner
 * cuts each tip with a short, hard braking and a pivot instead of
 * jogging through a long slowing, so at least 75 % of the judged steps
 * move faster than midway between the walk and the run (issue 24; the
 * steering that slowed to 0.6 of the speed for the whole of each tip
 * held 63 % on the synthetic default graph and 67 % on the CMU one). On
 * the synthetic default graph, and on the CMU graph when `make` has baked
 * build/cmu.smg. */
static void test_run_held_on_scribble(void** state) {
  (void)state;
  static float probe[2 * HELD_MAX_POINTS];
  if (read_path("scribble", probe, HELD_MAX_POINTS) < 2) {
    print_message("skipped: data/paths/scribble.txt not found\n");
    skip();
    return;
  }
  smg_graph* g = rt_default_graph();
  if (!g) {
    skip();
    return;
  }
  print_message("default graph: ");
  assert_true(style_held(g, "scribble") >= 0.75f);
  smg_graph_destroy(g);
  char path[1024];
  snprintf(path, sizeof path, "%s/cmu.smg", SMG_BUILD_DIR);
  g = NULL;
  if (smg_graph_load_file(path, NULL, &g) != SMG_OK) {
    print_message("CMU graph: skipped, %s not baked\n", path);
    return;
  }
  print_message("CMU graph: ");
  assert_true(style_held(g, "scribble") >= 0.75f);
  smg_graph_destroy(g);
}

/* q rotating v (x, y, z). */
static void rotate(const float* q, const float* v, float* out) {
  const float p[4] = {v[0], v[1], v[2], 0.0f};
  const float qc[4] = {-q[0], -q[1], -q[2], q[3]};
  float r[4], c[4];
  rt_q_mul(q, p, r);
  rt_q_mul(r, qc, c);
  out[0] = c[0], out[1] = c[1], out[2] = c[2];
}

static float wrap_pi(float a) {
  while (a > 3.14159265f) a -= 6.2831853f;
  while (a < -3.14159265f) a += 6.2831853f;
  return a;
}

#define FACE_STEPS 600 /* 10 s at 60 Hz */
#define FACE_HALF 30   /* half of a 1 s window */

/* 95th percentile (degrees) of the root's facing against its direction of
 * travel, both over 1 s windows (a stride: the twist of each step does
 * not count), over the frames moving faster than 0.5 m/s, for a
 * character started in `style` on the path. The root's forward axis is
 * calibrated on the run's first straight metres. */
static float facing_p95(smg_graph* g, uint32_t J, const float* xz,
                        uint32_t n, uint32_t style) {
  smg_character_desc d;
  smg_character* ch = NULL;
  static float pos[FACE_STEPS][2], q[FACE_STEPS][4], err[FACE_STEPS];
  float root[3], fwd[3] = {0.0f, 0.0f, 0.0f};
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  assert_non_null(rot);
  rt_desc_on_path(&d, xz);
  d.initial_style = style;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  for (int i = 0; i < FACE_STEPS; ++i) {
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(smg_character_get_local_pose(ch, root, rot, J), SMG_OK);
    pos[i][0] = root[0], pos[i][1] = root[2];
    memcpy(q[i], rot, sizeof q[i]);
  }
  smg_character_destroy(ch);
  free(rot);
  /* forward axis: the travel direction (+z here) in the root's frame,
   * averaged over the first straight second */
  for (int i = FACE_HALF; i < 2 * FACE_HALF + FACE_HALF; ++i) {
    const float inv[4] = {-q[i][0], -q[i][1], -q[i][2], q[i][3]};
    const float dz[3] = {0.0f, 0.0f, 1.0f};
    float l[3];
    rotate(inv, dz, l);
    fwd[0] += l[0], fwd[1] += l[1], fwd[2] += l[2];
  }
  int m = 0;
  for (int i = FACE_HALF; i + FACE_HALF < FACE_STEPS; ++i) {
    float tx = pos[i + FACE_HALF][0] - pos[i - FACE_HALF][0];
    float tz = pos[i + FACE_HALF][1] - pos[i - FACE_HALF][1];
    float way = 0.0f, sx = 0.0f, sz = 0.0f;
    for (int k = i - FACE_HALF; k <= i + FACE_HALF; ++k) {
      float f[3];
      rotate(q[k], fwd, f);
      float fl = sqrtf(f[0] * f[0] + f[2] * f[2]);
      if (fl > 1e-6f) sx += f[0] / fl, sz += f[2] / fl;
      if (k > i - FACE_HALF)
        way += sqrtf((pos[k][0] - pos[k - 1][0]) * (pos[k][0] - pos[k - 1][0]) +
                     (pos[k][1] - pos[k - 1][1]) * (pos[k][1] - pos[k - 1][1]));
    }
    if (way < 0.5f * 2.0f * FACE_HALF * DT || tx * tx + tz * tz < 1e-4f)
      continue; /* slower than 0.5 m/s */
    err[m++] = fabsf(wrap_pi(atan2f(sx, sz) - atan2f(tx, tz))) * 57.29578f;
  }
  /* insertion sort, then the 95th percentile */
  for (int i = 1; i < m; ++i) {
    float v = err[i];
    int k = i;
    while (k > 0 && err[k - 1] > v) err[k] = err[k - 1], --k;
    err[k] = v;
  }
  return m ? err[(int)(0.95f * (float)(m - 1))] : NAN;
}

/* A run around a 2 m U-turn faces where it goes: the steering turns the
 * body with its travel and slides it sideways only by the ratio of the
 * speed it moves at (pelvis facing against travel, 95th percentile,
 * within 10 degrees, as issue 24 asks; the steering that slid a slowed
 * runner sideways at the ratio of the motion's own speed, with a 2 rad/s
 * turn, gave 13.7). */
static void test_run_faces_travel(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  smg_graph_info info;
  const float xz[8] = {0.0f, 0.0f, 0.0f, 8.0f, 2.0f, 8.0f, 2.0f, 0.0f};
  uint32_t run;
  if (!g) {
    skip();
    return;
  }
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(smg_graph_find_style(g, "run", &run), SMG_OK);
  float p95 = facing_p95(g, info.joint_count, xz, 4, run);
  print_message("run round a 2 m U-turn: facing against travel p95 %.1f "
                "deg\n", p95);
  assert_true(p95 <= 10.0f);
  smg_graph_destroy(g);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_corner_and_rest),
      cmocka_unit_test(test_u_turn),
      cmocka_unit_test(test_rest_until_path_changes),
      cmocka_unit_test(test_run_comes_to_rest),
      cmocka_unit_test(test_switch_off),
      cmocka_unit_test(test_settings),
      cmocka_unit_test(test_default_graph_corner),
      cmocka_unit_test(test_run_through_hairpin),
      cmocka_unit_test(test_run_held_on_scribble),
      cmocka_unit_test(test_run_faces_travel),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
