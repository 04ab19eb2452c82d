/*
 * test_rest.c - stopping, standing, starting and turning on the spot,
 * judged from the exported poses alone (rest_geom.h):
 *  - a stop at the end of a straight path: the feet beside each other
 *    (ankles <= 0.40 m apart), both toes on the floor (within 2.5 cm of
 *    their floor level), the hips within 0.3 m of the path's end, and on
 *    graphs with standing motion the body never frozen (some joint turns
 *    by at least 1 degree in every 2 s at rest);
 *  - a stop from a run on an S-curve: slowed to a walk half a second
 *    before the hips stand, both toes down once they stand, within 0.3 m
 *    of the end, the longest swing at most 1.6 times the median;
 *  - a start from rest onto a 12 m straight path: the longest swing in
 *    the first 2 s at most 1.5 times the median swing of the walk that
 *    follows, 80 % of that walk's speed within 1.5 s;
 *  - a path that starts behind a standing character: the pelvis faces
 *    within 30 degrees of the path within 1.5 s, after the hips moved at
 *    most 0.5 m, with planted toes at most 20 cm/s meanwhile.
 * Runs on build/default.smg (synthetic walk; `make` bakes it), the CMU
 * graph (build/cmu.smg, else baked here from ../shared) and a Bandai Namco
 * graph baked here from ../shared (read at run time, nothing kept); each
 * measure is printed, so the figures in docs/runtime.md can be reproduced
 * with this program. On the runtime before the rest stage every graph
 * failed: feet 0.55-0.63 m apart, no motion at rest, a 0.8-1.2 m loop
 * before facing a path behind.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <sys/stat.h>

#include "bake/bake_graph_helpers.h"
#include "graph_derived.h"
#include "runtime/rest_scene.h"
#include "runtime/runtime_testutil.h"

#define FPS 30.0f
#define DT (1.0f / FPS)
#define PI_F 3.14159265f

static rg_run g_run; /* one run at a time: 1200 frames of a skeleton */

/* A straight path from the hips' ground point along heading h. */
static void scene_path(scene* s, float h, float length) {
  float xz[2 * 25];
  const float* p = g_run.hips[g_run.n - 1u];
  for (int i = 0; i < 25; ++i) {
    xz[2 * i] = p[0] + length * (float)i / 24.0f * sinf(h);
    xz[2 * i + 1] = p[2] + length * (float)i / 24.0f * cosf(h);
  }
  assert_int_equal(smg_character_set_path(s->ch, xz, 25), SMG_OK);
}

/* Standing: a 3 m walk along +Z, then 3 s at its end. */
static void scene_rest(scene* s) {
  scene_path(s, 0.0f, 3.0f);
  scene_run(s, 7.0f);
}

static float hdist(const float* a, const float* b) {
  return sqrtf((a[0] - b[0]) * (a[0] - b[0]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* ---- the stop ---- */

typedef struct stop_measure {
  float end_error;   /* m: hips from the path's end, at rest */
  float ankle_gap;   /* m: most the ankles are apart at rest */
  float toe_up;      /* m: most a toe is above its floor level at rest */
  float motion;      /* deg: least joint motion over 2 s at rest */
  float swing_ratio; /* longest swing / median swing until rest */
  float planted;     /* cm/s: fastest planted toe over the run */
  float planted95;   /* cm/s: their 95th percentile */
} stop_measure;

static void measure_stop(smg_graph* g, stop_measure* m) {
  scene s;
  scene_start(g, &s, &g_run, FPS);
  const float end[3] = {g_run.hips[0][0], 0.0f, g_run.hips[0][2] + 8.0f};
  scene_path(&s, 0.0f, 8.0f);
  scene_run(&s, 16.0f);
  smg_character_destroy(s.ch);
  const rg_run* r = &g_run;
  /* at rest: from the last frame the hips were more than 5 cm from
   * where they end, plus half a second */
  uint32_t rest = 0;
  const uint32_t hw = (uint32_t)(0.25f * FPS);
  for (uint32_t i = 0; i < r->n; ++i)
    if (rg_speed(r, i, hw) > 0.1f) rest = i + 1u;
  assert_true(rest + (uint32_t)(4.0f * FPS) < r->n);
  const uint32_t from = rest + (uint32_t)(0.5f * FPS);
  const float fl[2] = {rg_floor(r, 0), rg_floor(r, 1)};
  m->end_error = hdist(r->hips[r->n - 1u], end);
  m->planted = rg_planted(r, 1u, r->n, &m->planted95);
  m->ankle_gap = m->toe_up = 0.0f;
  for (uint32_t i = from; i < r->n; ++i) {
    float gap = hdist(r->ankle[i][0], r->ankle[i][1]);
    if (gap > m->ankle_gap) m->ankle_gap = gap;
    for (int f = 0; f < 2; ++f)
      if (r->toe[i][f][1] - fl[f] > m->toe_up)
        m->toe_up = r->toe[i][f][1] - fl[f];
  }
  const uint32_t w = (uint32_t)(2.0f * FPS);
  m->motion = INFINITY;
  for (uint32_t a = from; a + w <= r->n; a += w / 4u) {
    float deg = rg_motion_range(r, a, w);
    if (deg < m->motion) m->motion = deg;
  }
  uint32_t sw[256][2];
  uint32_t k = rg_swings(r, sw, 256), c = 0;
  float len[256], longest = 0.0f;
  for (uint32_t i = 0; i < k; ++i) {
    if (sw[i][0] >= rest) continue;
    len[c] = (float)(sw[i][1] - sw[i][0]);
    if (len[c] > longest) longest = len[c];
    ++c;
  }
  qsort(len, c, sizeof(float), rg_cmpf);
  m->swing_ratio = c ? longest / len[c / 2u] : 0.0f;
}

/* ---- a stop from a run on a curve ---- */

typedef struct run_stop_measure {
  int ran;           /* the graph has a style `run` */
  float toe_up;      /* m: most a toe is above its floor level at rest */
  float end_error;   /* m: hips from the path's end, at rest */
  float late_speed;  /* m/s: hips 0.5 s before they stand */
  float walk_speed;  /* m/s: the walk-run transition on this leg length */
  float swing_ratio; /* longest swing / median swing until rest */
} run_stop_measure;

/* A run stopped at the end of a path from the hips ahead: 4 m, a left
 * then a right quarter circle of r = 4 m, 4 m. A runner slows over its
 * last steps before it stops: half a second before the hips stand they
 * move no faster than a walk (a Froude number v^2 / (g * leg length)
 * below 0.5, where people change gait); the foot in the air at the stop
 * lands before the hips stand (a run's stop frame has a foot 15-50 cm
 * up: on the runtime before the settling step the CMU graph stood with a
 * toe 14 cm up); the stop comes at the end, at a natural cadence. On the
 * runtime before this measure the Bandai Namco run still moved at 3.0 m/s
 * half a second before it stood, and the CMU run stood 0.56 m from the
 * end. */
static void measure_run_stop(smg_graph* g, run_stop_measure* m) {
  uint32_t run;
  memset(m, 0, sizeof *m);
  if (smg_graph_find_style(g, "run", &run) != SMG_OK) return;
  m->ran = 1;
  scene s;
  scene_start(g, &s, &g_run, FPS);
  assert_int_equal(smg_character_set_style(s.ch, run), SMG_OK);
  float xz[2 * 48];
  const float* h0 = g_run.hips[g_run.n - 1u];
  int n = 0;
  const float r = 4.0f;
  for (int i = 0; i <= 4; ++i, ++n) {
    xz[2 * n] = 0.0f;
    xz[2 * n + 1] = (float)i;
  }
  for (int i = 1; i <= 16; ++i, ++n) { /* left: centre (r, 4) */
    const float a = 0.5f * PI_F * (float)i / 16.0f;
    xz[2 * n] = r - r * cosf(a);
    xz[2 * n + 1] = 4.0f + r * sinf(a);
  }
  for (int i = 1; i <= 16; ++i, ++n) { /* right: centre (r, 4 + 2r) */
    const float a = 0.5f * PI_F * (float)i / 16.0f;
    xz[2 * n] = r + r * sinf(a);
    xz[2 * n + 1] = 4.0f + 2.0f * r - r * cosf(a);
  }
  for (int i = 1; i <= 4; ++i, ++n) {
    xz[2 * n] = 2.0f * r;
    xz[2 * n + 1] = 4.0f + 2.0f * r + (float)i;
  }
  for (int i = 0; i < n; ++i) {
    xz[2 * i] += h0[0];
    xz[2 * i + 1] += h0[2];
  }
  const float end[3] = {xz[2 * n - 2], 0.0f, xz[2 * n - 1]};
  assert_int_equal(smg_character_set_path(s.ch, xz, (uint32_t)n), SMG_OK);
  scene_run(&s, 16.0f);
  smg_character_destroy(s.ch);
  const rg_run* rr = &g_run;
  /* at rest: after the last frame the hips moved faster than 0.1 m/s
   * (standing motion sways them by a few cm) */
  uint32_t stop = 0;
  const uint32_t hw = (uint32_t)(0.25f * FPS);
  for (uint32_t i = 0; i < rr->n; ++i)
    if (rg_speed(rr, i, hw) > 0.1f) stop = i + 1u;
  assert_true(stop + (uint32_t)(2.0f * FPS) < rr->n);
  const float fl[2] = {rg_floor(rr, 0), rg_floor(rr, 1)};
  for (uint32_t i = stop; i < rr->n; ++i)
    for (int f = 0; f < 2; ++f)
      if (rr->toe[i][f][1] - fl[f] > m->toe_up)
        m->toe_up = rr->toe[i][f][1] - fl[f];
  m->end_error = hdist(rr->hips[rr->n - 1u], end);
  const uint32_t late = (uint32_t)(0.5f * FPS);
  m->late_speed = rg_speed(rr, stop > late ? stop - late : 0u, 3u);
  float leg = 0.0f;
  for (int f = 0; f < 2; ++f) {
    const float* t = rr->thigh[0][f];
    const float* a = rr->ankle[0][f];
    const float d = sqrtf((t[0] - a[0]) * (t[0] - a[0]) +
                          (t[1] - a[1]) * (t[1] - a[1]) +
                          (t[2] - a[2]) * (t[2] - a[2]));
    if (d > leg) leg = d;
  }
  m->walk_speed = sqrtf(0.5f * 9.81f * leg);
  uint32_t sw[256][2];
  uint32_t k = rg_swings(rr, sw, 256), c = 0;
  float len[256], longest = 0.0f;
  for (uint32_t i = 0; i < k; ++i) {
    if (sw[i][0] >= stop) continue;
    len[c] = (float)(sw[i][1] - sw[i][0]);
    if (len[c] > longest) longest = len[c];
    ++c;
  }
  qsort(len, c, sizeof(float), rg_cmpf);
  m->swing_ratio = c ? longest / len[c / 2u] : 0.0f;
}

/* ---- the start ---- */

typedef struct start_measure {
  float swing_ratio; /* longest swing in the first 2 s / steady median */
  float reach_80;    /* s until 80 % of the steady speed */
  float steady;      /* m/s */
  float planted;     /* cm/s: fastest planted toe over the run */
  float planted95;   /* cm/s: their 95th percentile */
} start_measure;

static void measure_start(smg_graph* g, start_measure* m) {
  scene s;
  scene_start(g, &s, &g_run, FPS);
  scene_rest(&s);
  const uint32_t p0 = g_run.n;
  scene_path(&s, 0.0f, 12.0f);
  scene_run(&s, 10.0f);
  smg_character_destroy(s.ch);
  const rg_run* r = &g_run;
  assert_true(rg_start_gait(r, p0, &m->swing_ratio, &m->steady, &m->reach_80));
  m->planted = rg_planted(r, 1u, r->n, &m->planted95);
}

/* ---- a path behind ---- */

typedef struct behind_measure {
  float seconds;  /* until the pelvis faces within 30 deg of the path */
  float moved;    /* m the hips moved from where they stood by then */
  float planted;  /* cm/s: fastest planted toe meanwhile */
  float planted_all; /* cm/s: ... over the whole run */
  float wide;     /* m: furthest the hips went from the path's line */
} behind_measure;

static void measure_behind(smg_graph* g, behind_measure* m) {
  scene s;
  scene_start(g, &s, &g_run, FPS);
  scene_rest(&s);
  const uint32_t p0 = g_run.n;
  scene_path(&s, PI_F, 8.0f);
  scene_run(&s, 5.0f);
  smg_character_destroy(s.ch);
  const rg_run* r = &g_run;
  uint32_t at = r->n;
  for (uint32_t i = p0; i < r->n; ++i)
    if (fabsf(remainderf(rg_facing(r, i) - PI_F, 2.0f * PI_F)) <=
        30.0f * PI_F / 180.0f) {
      at = i;
      break;
    }
  m->seconds = (float)(at - p0) * DT;
  m->moved = at < r->n ? hdist(r->hips[at], r->hips[p0 - 1u]) : INFINITY;
  m->planted = rg_planted_max(r, p0, at + 1u);
  m->planted_all = rg_planted_max(r, 1u, r->n);
  m->wide = 0.0f;
  for (uint32_t i = p0; i < r->n && i < at + (uint32_t)FPS; ++i) {
    float dx = fabsf(r->hips[i][0] - r->hips[p0 - 1u][0]);
    if (dx > m->wide) m->wide = dx;
  }
}

/* ---- the tests ---- */

/* The graph under test: a blob in build/, else baked here from a manifest
 * and clips in ../shared (skipped when absent, and under valgrind: too
 * slow). */
typedef struct graph_src {
  const char* blob;     /* in the build folder, or NULL */
  const char* manifest; /* data/..., or NULL */
  const char* sub;      /* mocap folder in ../shared */
} graph_src;

static smg_graph* open_graph(const graph_src* src, smg_bake_result* res) {
  char path[1024];
  smg_graph* g = NULL;
  memset(res, 0, sizeof *res);
  if (src->blob) {
    snprintf(path, sizeof path, "%s/%s", SMG_BUILD_DIR, src->blob);
    if (smg_graph_load_file(path, NULL, &g) == SMG_OK) return g;
  }
  if (!src->manifest) {
    print_message("skipped: cannot load %s; `make` bakes it\n", path);
    return NULL;
  }
  char dir[1024];
  snprintf(dir, sizeof dir, "%s/mocap/%s", smgt_shared_dir(), src->sub);
  struct stat sb;
  if (stat(dir, &sb) != 0 || stat(src->manifest, &sb) != 0) {
    print_message("skipped: %s or %s not found\n", dir, src->manifest);
    return NULL;
  }
  if (smgt_quick()) {
    print_message("skipped: SMG_TEST_QUICK (baking is too slow under "
                  "valgrind)\n");
    return NULL;
  }
  bg_bake_manifest(src->manifest, dir, NULL, res);
  assert_int_equal(smg_graph_load_memory(res->blob, res->blob_size, NULL, &g),
                   SMG_OK);
  return g;
}

static void check(const graph_src* src, const char* name) {
  smg_bake_result res;
  smg_graph* g = open_graph(src, &res);
  if (!g) skip();
  const int standing = smgi_derived_of(g)->idle.count > 0;
  stop_measure st;
  start_measure sa;
  behind_measure be;
  measure_stop(g, &st);
  measure_start(g, &sa);
  measure_behind(g, &be);
  run_stop_measure rs;
  measure_run_stop(g, &rs);
  if (rs.ran)
    print_message("%s stop from a run on an S-curve: hips %.3f m from the "
                  "end, %.2f m/s half a second before they stand (a walk: "
                  "<= %.2f), a toe %.3f m up once they stand, longest swing "
                  "%.2f x the median\n",
                  name, rs.end_error, rs.late_speed, rs.walk_speed,
                  rs.toe_up, rs.swing_ratio);
  print_message("%s stop: hips %.3f m from the end, ankles %.3f m apart, a "
                "toe %.3f m up, least motion %.2f deg in 2 s (standing "
                "motion: %s), longest swing %.2f x the median, planted toes "
                "p95 %.1f max %.1f cm/s\n",
                name, st.end_error, st.ankle_gap, st.toe_up, st.motion,
                standing ? "yes" : "none", st.swing_ratio, st.planted95,
                st.planted);
  print_message("%s start: longest swing in 2 s %.2f x the steady median, "
                "80 %% of %.2f m/s after %.2f s, planted toes p95 %.1f max "
                "%.1f cm/s\n",
                name, sa.swing_ratio, sa.steady, sa.reach_80, sa.planted95,
                sa.planted);
  print_message("%s behind: faces the path after %.2f s, hips moved %.2f "
                "m, %.2f m aside, planted toes <= %.1f cm/s meanwhile (%.1f "
                "over the run)\n",
                name, be.seconds, be.moved, be.wide, be.planted,
                be.planted_all);
  /* the stop: feet beside each other on the floor, at the end */
  assert_true(st.end_error <= 0.3f);
  assert_true(st.ankle_gap <= 0.40f);
  assert_true(st.toe_up <= RG_BAND);
  assert_true(st.swing_ratio <= 1.6f);
  /* ... and from a run: slowed to a walk over the last steps, both feet
   * down before the hips stand, at the end, at a natural cadence */
  if (rs.ran) {
    assert_true(rs.late_speed <= rs.walk_speed);
    assert_true(rs.toe_up <= RG_BAND);
    assert_true(rs.end_error <= 0.3f);
    assert_true(rs.swing_ratio <= 1.6f);
  }
  /* standing: never a frozen frame where the graph has standing motion */
  if (standing) assert_true(st.motion >= 1.0f);
  /* the start: natural cadence, walking speed soon */
  assert_true(sa.swing_ratio <= 1.5f);
  assert_true(sa.reach_80 <= 1.5f);
  /* a path behind: turned on the spot */
  assert_true(be.seconds <= 1.5f);
  assert_true(be.moved <= 0.5f);
  assert_true(be.planted <= 20.0f);
  smg_graph_destroy(g);
  if (res.blob) smg_bake_result_free(&res);
}

static void test_default(void** state) {
  (void)state;
  const graph_src src = {"default.smg", NULL, NULL};
  check(&src, "default.smg");
}

/* the CMU walks: no standing motion, the IK places the feet */
static void test_cmu(void** state) {
  (void)state;
  const graph_src src = {"cmu.smg", "data/cmu.manifest", "cmu"};
  check(&src, "CMU");
}

/* standing motion from the lower bodies of actions performed standing */
static void test_bandai(void** state) {
  (void)state;
  const graph_src src = {NULL, "data/bandai.manifest", "bandai-namco"};
  check(&src, "Bandai Namco");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_default),
      cmocka_unit_test(test_cmu),
      cmocka_unit_test(test_bandai),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
