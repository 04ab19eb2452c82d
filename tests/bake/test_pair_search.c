/*
 * test_pair_search.c - the near-linear search for local minima of the
 * windowed point-cloud distance (bake_pair_search.c) against the full grid
 * (bake_pointcloud.c) and a direct evaluation: what it reports are exact
 * local minima with the right distances and alignments, it finds the good
 * ones the grid finds, it keeps to the groups it is given, and its output
 * does not depend on the thread count.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_pair_search.h"

#define K 6u

/* Deterministic pseudo-random numbers in [-1, 1]. */
static double rnd(uint32_t* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}

/* Clips of a gait-like cloud: P points swinging with a phase, walking
 * along a heading that turns slowly, each clip with its own speed, start
 * phase and noise, so that matches between clips exist but are not exact.
 * group[f] = clip % groups. */
static double* make_clips(uint32_t clips, uint32_t len, uint32_t P,
                          uint32_t groups, uint8_t* valid, uint32_t* group,
                          double* heading) {
  double* x = malloc((size_t)clips * len * P * 3 * sizeof *x);
  uint32_t c, f, p, s = 12345u;
  for (c = 0; c < clips; ++c) {
    double speed = 0.8 + 0.3 * rnd(&s), ph0 = 3.0 * rnd(&s);
    double turn = 0.01 * rnd(&s), h = 3.0 * rnd(&s), px = 0, pz = 0;
    for (f = 0; f < len; ++f) {
      uint32_t g = c * len + f;
      double ph = ph0 + 0.3 * speed * f;
      h += turn;
      px += 0.03 * speed * sin(h);
      pz += 0.03 * speed * cos(h);
      valid[g] = f + K < len;
      group[g] = c % groups;
      heading[g] = h;
      for (p = 0; p < P; ++p) {
        /* body-frame point, then turned by the heading */
        double bx = 0.2 * sin(ph + p) + 0.05 * p, by = 0.3 + 0.1 * p +
                                                         0.05 * cos(ph * 2 + p);
        double bz = 0.25 * cos(ph + 0.5 * p) + 0.005 * rnd(&s);
        double* o = x + ((size_t)g * P + p) * 3u;
        o[0] = px + bx * cos(h) + bz * sin(h);
        o[1] = by;
        o[2] = pz - bx * sin(h) + bz * cos(h);
      }
    }
  }
  return x;
}

/* Transition-like filter: not within 2K frames of itself in one clip. */
typedef struct filt {
  uint32_t len;
} filt;

static int not_near(uint32_t i, uint32_t j, void* u) {
  const filt* f = u;
  if (i / f->len != j / f->len) return 1;
  return (i > j ? i - j : j - i) >= 2u * K;
}

typedef struct setup {
  uint32_t clips, len, P, groups, F;
  double* xyz;
  double w[8];
  uint8_t* valid;
  uint32_t* group;
  double* heading;
  smgb_cloud cloud;
  filt f;
} setup;

static void setup_make(setup* s, uint32_t clips, uint32_t len,
                       uint32_t groups) {
  uint32_t p;
  memset(s, 0, sizeof *s);
  s->clips = clips;
  s->len = len;
  s->P = 6;
  s->groups = groups;
  s->F = clips * len;
  s->valid = malloc(s->F);
  s->group = malloc(s->F * sizeof *s->group);
  s->heading = malloc(s->F * sizeof *s->heading);
  s->xyz = make_clips(clips, len, s->P, groups, s->valid, s->group,
                      s->heading);
  for (p = 0; p < s->P; ++p) s->w[p] = 0.5 + 0.25 * p;
  s->cloud.frames = s->F;
  s->cloud.points = s->P;
  s->cloud.xyz = s->xyz;
  s->cloud.weights = s->w;
  s->cloud.valid = s->valid;
  s->f.len = len;
}

static void setup_free(setup* s) {
  free(s->xyz);
  free(s->valid);
  free(s->group);
  free(s->heading);
}

static void job_init(const setup* s, smgb_pair_search* job, uint32_t nb,
                     uint32_t threads) {
  memset(job, 0, sizeof *job);
  job->rows = job->cols = &s->cloud;
  job->row_heading = job->col_heading = s->heading;
  job->window = K;
  job->neighbours = nb;
  job->align = 1;
  job->filter = not_near;
  job->filter_user = (void*)&s->f;
  job->threads = threads;
}

/* Every reported pair is a local minimum of the exact distance over the
 * admissible cells, with the distance and alignment of a direct
 * evaluation; each is reported once, in (row, column) order. */
static void test_minima_are_exact(void** state) {
  setup s;
  smgb_pair_search job;
  smgb_minimum* m = NULL;
  uint32_t n = 0, u;
  (void)state;
  setup_make(&s, 8, 90, 1);
  job_init(&s, &job, 8, 1);
  assert_int_equal(smgb_pair_search_minima(&job, &m, &n), SMG_OK);
  assert_true(n > 20);
  for (u = 0; u < n; ++u) {
    double al[3], d = smgb_window_distance(&s.cloud, m[u].i, &s.cloud,
                                           m[u].j, K, 1, al);
    int di, dj;
    if (u > 0)
      assert_true(m[u - 1].i < m[u].i ||
                  (m[u - 1].i == m[u].i && m[u - 1].j < m[u].j));
    assert_true(fabs(d - m[u].dist) < 1e-4 * (1.0 + d));
    assert_true(fabs(al[2] - m[u].align[2]) < 1e-6 ||
                d < 1e-6); /* an exact match has no preferred angle */
    assert_true(not_near(m[u].i, m[u].j, &s.f));
    for (di = -1; di <= 1; ++di)
      for (dj = -1; dj <= 1; ++dj) {
        int64_t ii = (int64_t)m[u].i + di, jj = (int64_t)m[u].j + dj;
        if ((!di && !dj) || ii < 0 || jj < 0 || ii >= s.F || jj >= s.F ||
            !s.valid[ii] || !s.valid[jj] ||
            !not_near((uint32_t)ii, (uint32_t)jj, &s.f))
          continue;
        /* float rounding of two routes to the same sum: a hair of slack */
        assert_true(smgb_window_distance(&s.cloud, (uint32_t)ii, &s.cloud,
                                         (uint32_t)jj, K, 1, NULL) >=
                    m[u].dist - 1e-5);
      }
  }
  free(m);
  setup_free(&s);
}

/* The good minima of the full grid (the best quarter) are found. */
static void test_finds_the_good_minima(void** state) {
  setup s;
  smgb_pair_search job;
  smgb_grid_job grid;
  smgb_minimum *m = NULL, *g = NULL;
  uint32_t n = 0, ng = 0, u, v = 0, good = 0, found = 0;
  float* d;
  float cut;
  (void)state;
  setup_make(&s, 8, 90, 1);
  job_init(&s, &job, 32, 1);
  assert_int_equal(smgb_pair_search_minima(&job, &m, &n), SMG_OK);
  memset(&grid, 0, sizeof grid);
  grid.rows = grid.cols = &s.cloud;
  grid.window = K;
  grid.align = 1;
  grid.filter = not_near;
  grid.filter_user = &s.f;
  grid.threads = 1;
  assert_int_equal(smgb_grid_minima(&grid, &g, &ng), SMG_OK);
  assert_true(ng > 20);
  d = malloc(ng * sizeof *d);
  for (u = 0; u < ng; ++u) d[u] = g[u].dist;
  for (u = 1; u < ng; ++u) { /* insertion sort: small */
    float x = d[u];
    v = u;
    while (v > 0 && d[v - 1] > x) {
      d[v] = d[v - 1];
      --v;
    }
    d[v] = x;
  }
  cut = d[ng / 4];
  v = 0;
  for (u = 0; u < ng; ++u) {
    if (g[u].dist > cut) continue;
    ++good;
    while (v < n && (m[v].i < g[u].i || (m[v].i == g[u].i && m[v].j < g[u].j)))
      ++v;
    if (v < n && m[v].i == g[u].i && m[v].j == g[u].j) ++found;
  }
  print_message("pair search: %u of the grid's %u best minima found (%u "
                "minima, grid %u)\n", found, good, n, ng);
  assert_true(found * 10u >= good * 9u);
  free(d);
  free(m);
  free(g);
  setup_free(&s);
}

/* Output is the same for 1 and 2 threads (and the search stays within the
 * groups: own group only when other_neighbours is 0). */
static void test_threads_and_groups(void** state) {
  setup s;
  smgb_pair_search job;
  smgb_minimum *a = NULL, *b = NULL;
  uint32_t na = 0, nb = 0, u;
  (void)state;
  setup_make(&s, 10, 80, 2);
  job_init(&s, &job, 8, 1);
  job.col_group = job.row_group = s.group;
  job.group_count = 2;
  assert_int_equal(smgb_pair_search_minima(&job, &a, &na), SMG_OK);
  job.threads = 2;
  assert_int_equal(smgb_pair_search_minima(&job, &b, &nb), SMG_OK);
  assert_int_equal(na, nb);
  assert_true(na > 0);
  assert_memory_equal(a, b, na * sizeof *a);
  for (u = 0; u < na; ++u) assert_int_equal(s.group[a[u].i], s.group[a[u].j]);
  free(a);
  free(b);
  /* only other groups: every minimum crosses */
  job.neighbours = 0;
  job.other_neighbours = 4;
  job.threads = 1;
  assert_int_equal(smgb_pair_search_minima(&job, &a, &na), SMG_OK);
  assert_true(na > 0);
  for (u = 0; u < na; ++u)
    assert_int_not_equal(s.group[a[u].i], s.group[a[u].j]);
  free(a);
  setup_free(&s);
}

/* Bad or empty jobs: no output, no crash. */
static void test_edges(void** state) {
  setup s;
  smgb_pair_search job;
  smgb_minimum* m = NULL;
  uint32_t n = 7;
  (void)state;
  setup_make(&s, 2, 40, 1);
  job_init(&s, &job, 0, 1);
  assert_int_equal(smgb_pair_search_minima(&job, &m, &n), SMG_OK);
  assert_null(m);
  assert_int_equal(n, 0);
  job_init(&s, &job, 1000, 1);
  assert_int_equal(smgb_pair_search_minima(&job, &m, &n),
                   SMG_ERROR_INVALID_ARGUMENT);
  setup_free(&s);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_minima_are_exact),
      cmocka_unit_test(test_finds_the_good_minima),
      cmocka_unit_test(test_threads_and_groups),
      cmocka_unit_test(test_edges),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
