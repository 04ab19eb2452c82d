/*
 * test_style_turns.c - a requested style is held along curves, and sharp
 * corners slow the character by shorter strides, not by slow motion
 * (planner.c style yield, steer.c playback floor and stride share), on
 * the fixture graph and the synthetic default graph:
 *  - after a transition to `run` on an r = 5 m circle, the root moves
 *    faster than midway between the graph's walking and running speeds
 *    (both measured here on a straight line, 1 s windows of the exported
 *    root) on at least 90 % of the frames from 3 m after the transition to
 *    the circle's end (a straight tail follows, where the run is walked
 *    out to stop): the steering bends a run around such a circle, so the
 *    planner must not trade the run for a walk;
 *  - running into a 90-degree polyline corner: playback never slower than
 *    0.8 of real time before the stop begins, the root within 0.45 m of
 *    the path, slower at the corner than on the straight before it (the
 *    runner slows down) and faster than the graph walks (it keeps
 *    running);
 *  - a run started 0.3-0.9 m beside a straight path, facing along it or
 *    turned 17 degrees away: the steering brings it back, so the run is
 *    held (faster than midway on at least 90 % of the frames of its first
 *    4 s) and the root is back within 10 cm of the path after 3 s. Being
 *    off the path is no failure to follow while the steering takes the
 *    offset out (a runner swinging wide out of a corner it cut); the
 *    planner used to hand such a run to the walk.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define DT (1.0f / 30.0f)
#define WINDOW 30 /* frames: 1 s */
#define MAX_FRAMES 2400
#define PI_F 3.14159265f

typedef struct graphs {
  void* blob;
  smg_graph* fixture;
  smg_graph* synthetic; /* NULL when build/default.smg is absent */
} graphs;

static int setup(void** state) {
  graphs* g = (graphs*)calloc(1, sizeof *g);
  if (!g) return -1;
  g->fixture = rt_fixture(&g->blob);
  if (!g->fixture) {
    free(g);
    return -1;
  }
  g->synthetic = rt_default_graph();
  *state = g;
  return 0;
}

static int teardown(void** state) {
  graphs* g = (graphs*)*state;
  rt_fixture_free(g->fixture, g->blob);
  if (g->synthetic) smg_graph_destroy(g->synthetic);
  free(g);
  return 0;
}

/* One recorded run: the exported root on the ground per frame, the state's
 * progress and playback rate. */
typedef struct trace {
  size_t n;
  float x[MAX_FRAMES], z[MAX_FRAMES], s[MAX_FRAMES], rate[MAX_FRAMES];
} trace;

/* Started on the path's first point facing its second, moved `beside`
 * metres to the side (+x) and turned `away` radians. */
static void run_from(smg_graph* g, const float* xz, uint32_t n,
                     uint32_t style, float beside, float away,
                     float transition_at, uint32_t transition_to,
                     float seconds, trace* t) {
  smg_graph_info info;
  smg_character_desc d;
  smg_character* ch = NULL;
  float root[3], *rot;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  rot = (float*)malloc(sizeof(float) * 4 * info.joint_count);
  assert_non_null(rot);
  rt_desc_on_path(&d, xz);
  d.position[0] += beside;
  d.heading += away;
  d.initial_style = style;
  d.path_capacity = n;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  if (transition_at >= 0.0f)
    assert_int_equal(
        smg_character_add_transition(ch, transition_at, transition_to, NULL),
        SMG_OK);
  t->n = 0;
  for (size_t i = 0; i < MAX_FRAMES && (float)i * DT < seconds; ++i) {
    smg_character_state st;
    assert_int_equal(smg_character_step(ch, DT), SMG_OK);
    assert_int_equal(
        smg_character_get_local_pose(ch, root, rot, info.joint_count),
        SMG_OK);
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    assert_int_equal(smg_character_get_state(ch, &st), SMG_OK);
    t->x[i] = root[0];
    t->z[i] = root[2];
    t->s[i] = st.path_distance;
    t->rate[i] = st.playback_rate;
    t->n = i + 1;
  }
  smg_character_destroy(ch);
  free(rot);
}

static void run(smg_graph* g, const float* xz, uint32_t n, uint32_t style,
                float transition_at, uint32_t transition_to, float seconds,
                trace* t) {
  run_from(g, xz, n, style, 0.0f, 0.0f, transition_at, transition_to, seconds,
           t);
}

/* Root ground path length over the 1 s window centred on i, per second. */
static float window_speed(const trace* t, size_t i) {
  size_t a = i >= WINDOW / 2 ? i - WINDOW / 2 : 0;
  size_t b = i + WINDOW / 2 < t->n ? i + WINDOW / 2 : t->n - 1;
  float len = 0.0f;
  for (size_t k = a + 1; k <= b; ++k)
    len += hypotf(t->x[k] - t->x[k - 1], t->z[k] - t->z[k - 1]);
  return b > a ? len / ((float)(b - a) * DT) : 0.0f;
}

/* Median window speed over the frames whose progress is in [lo, hi]. */
static float median_speed(const trace* t, float lo, float hi) {
  static float v[MAX_FRAMES];
  size_t m = 0;
  for (size_t i = 0; i < t->n; ++i)
    if (t->s[i] >= lo && t->s[i] <= hi) v[m++] = window_speed(t, i);
  assert_true(m > 0);
  for (size_t i = 1; i < m; ++i) /* insertion sort: small */
    for (size_t k = i; k > 0 && v[k - 1] > v[k]; --k) {
      float x = v[k];
      v[k] = v[k - 1];
      v[k - 1] = x;
    }
  return v[m / 2];
}

/* Lead of `lead` metres along +z, a full left circle of radius r, then
 * `tail` metres straight on (where a run is walked out to stop). */
static uint32_t circle(float* xz, float lead, float r, float tail) {
  uint32_t n = 0;
  xz[2 * n] = 0.0f, xz[2 * n + 1] = 0.0f, ++n;
  for (int k = 0; k <= 96; ++k) {
    float a = 2.0f * PI_F * (float)k / 96.0f;
    xz[2 * n] = r - r * cosf(a);
    xz[2 * n + 1] = lead + r * sinf(a);
    ++n;
  }
  xz[2 * n] = 0.0f, xz[2 * n + 1] = lead + tail, ++n;
  return n;
}

/* The graph's walking and running speeds on a 30 m straight line. */
static void speeds(smg_graph* g, float* walk, float* run_speed) {
  static trace t;
  float xz[2 * 31];
  rt_line(xz, 31, 30.0f);
  run(g, xz, 31, 0, -1.0f, 0, 30.0f, &t);
  *walk = median_speed(&t, 3.0f, 26.0f);
  run(g, xz, 31, 1, -1.0f, 0, 30.0f, &t);
  *run_speed = median_speed(&t, 3.0f, 26.0f);
}

static void run_held_on_circle(smg_graph* g, const char* name) {
  static trace t;
  float xz[2 * 99], walk, fast;
  uint32_t n = circle(xz, 4.0f, 5.0f, 12.0f);
  float circle_end = 4.0f + 2.0f * PI_F * 5.0f;
  size_t judged = 0, running = 0;
  speeds(g, &walk, &fast);
  run(g, xz, n, 0, 4.0f, 1, 40.0f, &t);
  for (size_t i = 0; i < t.n; ++i) {
    if (t.s[i] < 7.0f || t.s[i] > circle_end) continue;
    ++judged;
    running += window_speed(&t, i) > 0.5f * (walk + fast);
  }
  print_message("%s: walk %.2f m/s, run %.2f m/s; r = 5 m circle after a "
                "transition to run: %zu of %zu frames faster than %.2f\n",
                name, walk, fast, running, judged, 0.5f * (walk + fast));
  assert_true(fast > 1.3f * walk); /* the graph runs */
  assert_true(judged > 30);
  assert_true((float)running >= 0.9f * (float)judged);
}

static void test_run_held_on_circle(void** state) {
  graphs* g = (graphs*)*state;
  run_held_on_circle(g->fixture, "fixture");
  if (g->synthetic) run_held_on_circle(g->synthetic, "synthetic default");
}

/* Distance from (x, z) to the segment (ax, az)-(bx, bz). */
static float segment_distance(float x, float z, float ax, float az, float bx,
                              float bz) {
  float vx = bx - ax, vz = bz - az;
  float u = ((x - ax) * vx + (z - az) * vz) / (vx * vx + vz * vz);
  u = u < 0.0f ? 0.0f : (u > 1.0f ? 1.0f : u);
  return hypotf(x - ax - u * vx, z - az - u * vz);
}

static void corner_at_a_run(smg_graph* g, const char* name) {
  static trace t;
  float xz[6] = {0.0f, 0.0f, 0.0f, 10.0f, 10.0f, 10.0f};
  float slowest = 1.0f, worst = 0.0f, walk, fast, at_corner, straight, after;
  speeds(g, &walk, &fast);
  run(g, xz, 3, 1, -1.0f, 0, 20.0f, &t);
  for (size_t i = 0; i < t.n; ++i) {
    /* before the stop's braking distance (which slows on purpose) */
    if (t.s[i] < 16.0f && t.rate[i] < slowest) slowest = t.rate[i];
    float d = segment_distance(t.x[i], t.z[i], 0.0f, 0.0f, 0.0f, 10.0f);
    float d2 = segment_distance(t.x[i], t.z[i], 0.0f, 10.0f, 10.0f, 10.0f);
    if (d2 < d) d = d2;
    if (d > worst) worst = d;
  }
  at_corner = median_speed(&t, 9.0f, 11.0f);
  straight = median_speed(&t, 3.0f, 7.0f);
  after = median_speed(&t, 11.5f, 14.0f);
  print_message("%s: corner at a run: slowest playback %.2f, speed %.2f m/s "
                "at the corner vs %.2f before it and %.2f after it "
                "(midway to the walk %.2f), root within %.2f m\n",
                name, slowest, at_corner, straight, after,
                0.5f * (walk + fast), worst);
  assert_true(slowest >= 0.8f - 1e-4f);
  assert_true(at_corner < straight);
  assert_true(at_corner > walk); /* still running */
  assert_true(after > 0.5f * (walk + fast)); /* and running on after it */
  assert_true(worst < 0.45f);
}

static void test_corner_at_a_run(void** state) {
  graphs* g = (graphs*)*state;
  corner_at_a_run(g->fixture, "fixture");
  if (g->synthetic) corner_at_a_run(g->synthetic, "synthetic default");
}

static void run_held_beside(smg_graph* g, const char* name) {
  static trace t;
  float xz[2 * 31], walk, fast;
  rt_line(xz, 31, 30.0f);
  speeds(g, &walk, &fast);
  for (int k = 0; k < 6; ++k) {
    const float beside = 0.3f + 0.3f * (float)(k / 2);
    const float away = k % 2 ? 0.3f : 0.0f;
    size_t judged = 0, running = 0;
    run_from(g, xz, 31, 1, beside, away, -1.0f, 0, 4.5f, &t);
    /* the 1 s windows within the first 4 s */
    for (size_t i = WINDOW / 2; i + WINDOW / 2 < t.n && i < 4 * 30 - WINDOW / 2;
         ++i) {
      ++judged;
      running += window_speed(&t, i) > 0.5f * (walk + fast);
    }
    const float off = fabsf(t.x[3 * 30]);
    print_message("%s: run started %.1f m beside the path, turned %.1f rad "
                  "away: %zu of %zu frames faster than %.2f m/s, %.2f m off "
                  "after 3 s\n",
                  name, beside, away, running, judged, 0.5f * (walk + fast),
                  off);
    assert_true(judged > 60);
    assert_true((float)running >= 0.9f * (float)judged);
    assert_true(off < 0.1f);
  }
}

static void test_run_held_beside_the_path(void** state) {
  graphs* g = (graphs*)*state;
  run_held_beside(g->fixture, "fixture");
  if (g->synthetic) run_held_beside(g->synthetic, "synthetic default");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_run_held_on_circle),
      cmocka_unit_test(test_corner_at_a_run),
      cmocka_unit_test(test_run_held_beside_the_path),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
