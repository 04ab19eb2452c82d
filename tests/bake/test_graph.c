/*
 * test_graph.c - the graph-construction building blocks: the windowed
 * point-cloud distance and its optimal 2-D alignment (Kovar et al. 2002),
 * the streamed distance grid against a direct evaluation, strongly
 * connected components (iterative Tarjan) and chain simplification.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_math.h"

/* Deterministic pseudo-random numbers in [-1, 1]. */
static double rnd(uint32_t* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}

/* A smooth random cloud: F frames of P points drifting along +Z. */
static double* make_cloud(uint32_t F, uint32_t P, uint32_t seed) {
  double* x = malloc((size_t)F * P * 3 * sizeof *x);
  double base[64][3];
  uint32_t f, p, s = seed;
  for (p = 0; p < P; ++p) {
    base[p][0] = 0.3 * rnd(&s);
    base[p][1] = 0.5 + 0.4 * rnd(&s);
    base[p][2] = 0.3 * rnd(&s);
  }
  for (f = 0; f < F; ++f)
    for (p = 0; p < P; ++p) {
      double ph = 0.35 * f + p;
      x[(f * P + p) * 3 + 0] = base[p][0] + 0.1 * sin(ph) + 0.01 * rnd(&s);
      x[(f * P + p) * 3 + 1] = base[p][1] + 0.05 * cos(1.3 * ph);
      x[(f * P + p) * 3 + 2] = base[p][2] + 0.04 * f + 0.1 * cos(ph);
    }
  return x;
}

static void test_window_distance_to_itself_is_zero(void** state) {
  uint32_t F = 40, P = 7, i;
  double* x = make_cloud(F, P, 1);
  double w[7] = {1, 1, 2, 1, 0.5, 1, 1};
  uint8_t valid[40];
  smgb_cloud c = {F, P, NULL, w, valid};
  (void)state;
  c.xyz = x;
  for (i = 0; i + 10 <= F; ++i) {
    double al[3];
    double d = smgb_window_distance(&c, i, &c, i, 10, 1, al);
    assert_true(d < 1e-9);
    assert_true(fabs(al[0]) < 1e-9 && fabs(al[1]) < 1e-9);
    assert_true(fabs(al[2]) < 1e-9);
  }
  free(x);
}

static void test_alignment_recovers_rigid_motion(void** state) {
  uint32_t F = 30, P = 6, f, p;
  double* a = make_cloud(F, P, 7);
  double* b = malloc((size_t)F * P * 3 * sizeof *b);
  double w[6] = {1, 1, 1, 1, 1, 1};
  const double th = 0.7, tx = 1.5, tz = -2.0;
  smgb_cloud A = {F, P, NULL, w, NULL}, B = {F, P, NULL, w, NULL};
  double al[3], d;
  (void)state;
  /* B = inverse rigid motion of A; the alignment must map B back onto A */
  for (f = 0; f < F; ++f)
    for (p = 0; p < P; ++p) {
      const double* s = a + (f * P + p) * 3;
      double* o = b + (f * P + p) * 3;
      double x = s[0] - tx, z = s[2] - tz, c = cos(-th), sn = sin(-th);
      o[0] = x * c + z * sn;
      o[1] = s[1];
      o[2] = -x * sn + z * c;
    }
  A.xyz = a;
  B.xyz = b;
  d = smgb_window_distance(&A, 5, &B, 5, 10, 1, al);
  assert_true(d < 1e-9);
  assert_true(fabs(al[0] - tx) < 1e-9);
  assert_true(fabs(al[1] - tz) < 1e-9);
  assert_true(fabs(al[2] - th) < 1e-9);
  /* without alignment the distance is large */
  assert_true(smgb_window_distance(&A, 5, &B, 5, 10, 0, NULL) > 0.5);
  free(a);
  free(b);
}

typedef struct grid_run {
  smgb_minimum* m;
  uint32_t n;
} grid_run;

static int no_diag(uint32_t i, uint32_t j, void* u) {
  (void)u;
  return i != j;
}

static void run_grid(const smgb_cloud* A, const smgb_cloud* B, int align,
                     uint32_t threads, grid_run* out) {
  smgb_grid_job job;
  memset(&job, 0, sizeof job);
  job.rows = A;
  job.cols = B;
  job.window = 6;
  job.align = align;
  job.threads = threads;
  job.filter = A == B ? no_diag : NULL;
  assert_int_equal(smgb_grid_minima(&job, &out->m, &out->n), SMG_OK);
}

/* The streamed diagonal-sum grid gives the same values as evaluating every
 * window directly, finds only true local minima, and does not depend on
 * the thread count. */
static void test_grid_matches_direct_evaluation(void** state) {
  uint32_t FA = 150, FB = 97, P = 5, i, k = 6;
  double* xa = make_cloud(FA, P, 3);
  double* xb = make_cloud(FB, P, 4);
  double w[5] = {1, 2, 1, 0.5, 1};
  uint8_t va[150], vb[97];
  smgb_cloud A = {FA, P, NULL, w, va}, B = {FB, P, NULL, w, vb};
  grid_run g1, g2;
  int align;
  (void)state;
  A.xyz = xa;
  B.xyz = xb;
  for (i = 0; i < FA; ++i) va[i] = i + k <= FA;
  for (i = 0; i < FB; ++i) vb[i] = i + k <= FB;
  for (align = 0; align <= 1; ++align) {
    run_grid(&A, &B, align, 1, &g1);
    run_grid(&A, &B, align, 2, &g2);
    assert_true(g1.n > 0);
    assert_int_equal(g1.n, g2.n);
    assert_memory_equal(g1.m, g2.m, g1.n * sizeof *g1.m);
    for (i = 0; i < g1.n; ++i) {
      const smgb_minimum* m = &g1.m[i];
      double al[3];
      double d = smgb_window_distance(&A, m->i, &B, m->j, k, align, al);
      int di, dj;
      assert_true(fabs(d - m->dist) < 1e-4 * (1.0 + d));
      if (align) {
        assert_true(fabs(smgb_wrap_angle(al[2] - m->align[2])) < 1e-3 ||
                    d < 1e-3);
      }
      for (di = -1; di <= 1; ++di)
        for (dj = -1; dj <= 1; ++dj) {
          int64_t ii = (int64_t)m->i + di, jj = (int64_t)m->j + dj;
          if (ii < 0 || jj < 0 || ii + k > FA || jj + k > FB) continue;
          assert_true(smgb_window_distance(&A, (uint32_t)ii, &B, (uint32_t)jj,
                                           k, align, NULL) >= d - 1e-4);
        }
    }
    free(g1.m);
    free(g2.m);
  }
  /* self-grid with the diagonal filtered out */
  run_grid(&A, &A, 1, 2, &g1);
  for (i = 0; i < g1.n; ++i) assert_true(g1.m[i].i != g1.m[i].j);
  free(g1.m);
  free(xa);
  free(xb);
}

static void add_edge(smgb_graph* g, uint32_t a, uint32_t b, uint32_t kind) {
  smgb_edge e;
  memset(&e, 0, sizeof e);
  e.from = a;
  e.to = b;
  e.kind = kind;
  e.a = g->nodes[a].frame;
  e.b = g->nodes[b].frame;
  assert_int_equal(smgb_graph_add_edge(g, &e), SMG_OK);
}

static void test_scc_small_and_deep(void** state) {
  smgb_graph g;
  uint32_t comp[5], n, *big;
  int32_t nc;
  (void)state;
  memset(&g, 0, sizeof g);
  for (n = 0; n < 5; ++n) smgb_graph_add_node(&g, n, 0, NULL);
  add_edge(&g, 0, 1, 0);
  add_edge(&g, 1, 2, 0);
  add_edge(&g, 2, 0, 0);
  add_edge(&g, 2, 3, 0);
  add_edge(&g, 3, 4, 0);
  add_edge(&g, 4, 3, 0);
  smgb_graph_sort_edges(&g);
  nc = smgb_scc(&g, comp);
  assert_int_equal(nc, 2);
  assert_true(comp[0] == comp[1] && comp[1] == comp[2]);
  assert_true(comp[3] == comp[4] && comp[3] != comp[0]);
  smgb_graph_free(&g);

  /* a 200000-node ring: recursion would overflow the stack */
  memset(&g, 0, sizeof g);
  for (n = 0; n < 200000; ++n) smgb_graph_add_node(&g, n, 0, NULL);
  for (n = 0; n < 200000; ++n) add_edge(&g, n, (n + 1) % 200000, 0);
  smgb_graph_sort_edges(&g);
  big = malloc(200000 * sizeof *big);
  assert_int_equal(smgb_scc(&g, big), 1);
  free(big);
  smgb_graph_free(&g);
}

/* A 100-frame branch-free run is re-cut into pieces of at most
 * max_edge_frames; the transition closing the loop is kept. */
static void test_simplify_caps_merged_edges(void** state) {
  smgb_bake* b = calloc(1, sizeof *b);
  smgb_graph* g = &b->lower;
  uint32_t n, e, originals = 0;
  (void)state;
  b->opt.max_edge_frames = 30;
  for (n = 0; n <= 20; ++n) smgb_graph_add_node(g, 5 * n, 0, NULL);
  for (n = 0; n < 20; ++n) add_edge(g, n, n + 1, SMGB_EDGE_ORIGINAL);
  add_edge(g, 20, 0, SMGB_EDGE_TRANSITION);
  smgb_graph_sort_edges(g);
  assert_int_equal(smgb_simplify(b, g), SMG_OK);
  assert_int_equal(g->node_count, 5); /* 100 frames / 30 -> 4 pieces */
  for (e = 0; e < g->edge_count; ++e) {
    const smgb_edge* ed = &g->edges[e];
    if (ed->kind == SMGB_EDGE_ORIGINAL) {
      uint32_t len = g->nodes[ed->to].frame - g->nodes[ed->from].frame;
      assert_true(len >= 1 && len <= 30);
      assert_int_equal(ed->to, ed->from + 1);
      ++originals;
    } else {
      assert_int_equal(g->nodes[ed->from].frame, 100);
      assert_int_equal(g->nodes[ed->to].frame, 0);
    }
  }
  assert_int_equal(originals, 4);
  assert_int_equal(smgb_scc(g, (uint32_t[8]){0}), 1);
  smgb_graph_free(g);
  free(b);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_window_distance_to_itself_is_zero),
      cmocka_unit_test(test_alignment_recovers_rigid_motion),
      cmocka_unit_test(test_grid_matches_direct_evaluation),
      cmocka_unit_test(test_scc_small_and_deep),
      cmocka_unit_test(test_simplify_caps_merged_edges),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
