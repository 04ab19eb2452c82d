/*
 * test_bake_cmu.c - bake the real CMU clips (the paper-size set: 09_12
 * walk forward/backward, the subject-09 runs, 02_05 punch) and check what
 * the runtime relies on: walk -> run and run -> walk transitions exist,
 * the lower graph is one strongly connected component holding both styles,
 * the punch graph is strongly connected, splice candidates cover the
 * locomotion, and the blob round-trips. Skips with a message when
 * ../shared is absent. Under SMG_TEST_QUICK (valgrind) only part of the
 * set is used and nothing is mirrored.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"

typedef struct cmu_clip {
  const char* file;
  uint32_t role;
  const char* label;
  uint32_t first, count; /* source frames (120 Hz) after the T-pose */
} cmu_clip;

static const cmu_clip k_full[] = {
    {"09_12.bvh", SMG_BAKE_ROLE_LOWER, "walk", 0, 0},
    {"09_01.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_02.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_03.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_04.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_05.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_06.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_07.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_08.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_09.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_11.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"02_05.bvh", SMG_BAKE_ROLE_UPPER, "punch", 100, 1700},
};

static const cmu_clip k_quick[] = {
    {"09_12.bvh", SMG_BAKE_ROLE_LOWER, "walk", 0, 720},
    {"09_01.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_02.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_03.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"09_04.bvh", SMG_BAKE_ROLE_LOWER, "run", 0, 0},
    {"02_05.bvh", SMG_BAKE_ROLE_UPPER, "punch", 100, 600},
};

static void test_cmu_paper_set(void** state) {
  const char* dir = smgt_cmu_dir();
  const cmu_clip* set = smgt_quick() ? k_quick : k_full;
  uint32_t n = smgt_quick() ? sizeof k_quick / sizeof k_quick[0]
                          : sizeof k_full / sizeof k_full[0];
  smg_bake_clip_desc descs[16];
  smg_bake_desc d;
  smg_bake_result res;
  smgi_graph_data g;
  uint32_t i, e, w2r = 0, r2w = 0, walk_nodes = 0, run_nodes = 0;
  (void)state;
  if (!dir) {
    skip();
    return;
  }
  memset(descs, 0, sizeof descs);
  for (i = 0; i < n; ++i) {
    descs[i].struct_size = sizeof descs[i];
    descs[i].role = set[i].role;
    descs[i].path = set[i].file;
    descs[i].label = set[i].label;
    descs[i].first_frame = set[i].first;
    descs[i].frame_count = set[i].count;
    descs[i].skip_first_frame = 1;
    descs[i].unit_scale = 0.056444f;
    descs[i].mirror = smgt_quick() ? SMG_BAKE_MIRROR_NO : SMG_BAKE_MIRROR_YES;
  }
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = n;
  d.data_dir = dir;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  if (smg_bake_run(&d, &res) != SMG_OK) fail_msg("bake: %s", res.error);
  bg_read(&res, &g);
  printf("CMU %s set: lower %u/%u nodes/edges (before simplification "
         "%u/%u), upper %u/%u (%u/%u), %u splices, coverage %.1f %%\n",
         smgt_quick() ? "quick" : "paper", g.lower_node_count,
         g.lower_edge_count, g.info->lower_nodes_before_simplify,
         g.info->lower_edges_before_simplify, g.upper_node_count,
         g.upper_edge_count, g.info->upper_nodes_before_simplify,
         g.info->upper_edges_before_simplify, g.splice_count,
         100.0 * res.stats.splice_coverage);
  assert_int_equal(g.style_count, 2);
  assert_string_equal(g.strings + g.styles[0].name, "walk");
  assert_string_equal(g.strings + g.styles[1].name, "run");
  for (e = 0; e < g.lower_edge_count; ++e) {
    uint32_t lf = g.lower_nodes[g.lower_edges[e].from].label;
    uint32_t lt = g.lower_nodes[g.lower_edges[e].to].label;
    if (lf == 0 && lt == 1) ++w2r;
    if (lf == 1 && lt == 0) ++r2w;
  }
  for (i = 0; i < g.lower_node_count; ++i) {
    walk_nodes += g.lower_nodes[i].label == 0;
    run_nodes += g.lower_nodes[i].label == 1;
  }
  printf("walk->run %u, run->walk %u transitions; %u walk, %u run nodes\n",
         w2r, r2w, walk_nodes, run_nodes);
  assert_true(w2r >= 1);
  assert_true(r2w >= 1);
  assert_true(walk_nodes >= 10 && run_nodes >= 4);
  assert_int_equal(bg_components(g.lower_nodes, g.lower_node_count,
                                 g.lower_edges, g.lower_edge_count,
                                 SMGI_NONE), 1);
  assert_int_equal(bg_components(g.upper_nodes, g.upper_node_count,
                                 g.upper_edges, g.upper_edge_count, 1), 1);
  assert_true(g.splice_count > 0);
  assert_true(res.stats.splice_coverage > 0.95f);
  /* real units: the walk moves at 0.5-2 m/s along its edges */
  {
    double arc = 0.0, frames = 0.0;
    for (e = 0; e < g.lower_edge_count; ++e)
      if (g.lower_nodes[g.lower_edges[e].from].label == 0 &&
          !(g.lower_edges[e].flags & SMGI_EDGE_TRANSITION)) {
        arc += g.lower_edges[e].arc_length;
        frames += g.lower_edges[e].frame_count;
      }
    assert_true(frames > 0);
    printf("walk speed along original edges: %.2f m/s\n",
           arc / (frames / g.info->frame_rate));
    assert_true(arc / (frames / g.info->frame_rate) > 0.5);
    assert_true(arc / (frames / g.info->frame_rate) < 2.0);
  }
  smg_bake_result_free(&res);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cmu_paper_set),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
