/*
 * test_frozen_format.c - a format-version-2 blob baked once and committed
 * (tests/data/frozen_v2.smg, from tests/data/frozen_v2.manifest) must keep
 * loading, with the same facts, and keep driving a character: a change to
 * the reader or the format that would break the files users already have
 * fails here. The fixture is never re-baked; a new format version gets a
 * fixture of its own beside this one.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "smg.h"

/* `make test` runs the suites from the repository root. */
#define FROZEN_V2 "tests/data/frozen_v2.smg"

static smg_graph* g_graph;

static int setup(void** state) {
  smg_result r;
  (void)state;
  r = smg_graph_load_file(FROZEN_V2, NULL, &g_graph);
  if (r != SMG_OK) {
    fprintf(stderr, "test_frozen_format: %s: %s (run from the repository "
                    "root)\n", FROZEN_V2, smg_result_string(r));
    return -1;
  }
  return 0;
}

static int teardown(void** state) {
  (void)state;
  return smg_graph_destroy(g_graph) == SMG_OK ? 0 : -1;
}

/* What the file held when it was baked (printed by smg-bake then). */
static void test_facts(void** state) {
  smg_graph_info info;
  smg_joint_info joint;
  const char* name;
  uint32_t index;
  (void)state;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g_graph, &info), SMG_OK);
  assert_int_equal(info.format_version, 2);
  assert_int_equal(info.blob_size, 99472);
  assert_int_equal(info.joint_count, 31);
  assert_int_equal(info.frame_count, 420); /* 240 clip + 180 blended */
  assert_true(info.frame_rate == 30.0f);
  assert_int_equal(info.lower_node_count, 31);
  assert_int_equal(info.lower_edge_count, 46);
  assert_int_equal(info.upper_node_count, 2);
  assert_int_equal(info.upper_edge_count, 2);
  assert_int_equal(info.splice_count, 9);
  assert_int_equal(info.style_count, 2);
  assert_int_equal(info.action_count, 2);
  assert_int_equal(smg_graph_get_style_name(g_graph, 0, &name), SMG_OK);
  assert_string_equal(name, "walk");
  assert_int_equal(smg_graph_get_style_name(g_graph, 1, &name), SMG_OK);
  assert_string_equal(name, "run");
  assert_int_equal(smg_graph_get_action_name(g_graph, 0, &name), SMG_OK);
  assert_string_equal(name, "none");
  assert_int_equal(smg_graph_find_action(g_graph, "wave", &index), SMG_OK);
  assert_int_equal(index, 1);
  memset(&joint, 0, sizeof joint);
  joint.struct_size = sizeof joint;
  assert_int_equal(smg_graph_get_joint(g_graph, 0, &joint), SMG_OK);
  assert_string_equal(joint.name, "Hips");
  assert_int_equal(joint.parent, SMG_NO_PARENT);
  assert_int_equal(smg_graph_find_joint(g_graph, "LeftFoot", &index),
                   SMG_OK);
  assert_int_equal(smg_graph_get_joint(g_graph, index, &joint), SMG_OK);
  assert_int_equal(joint.body_part, SMG_BODY_LOWER);
}

/* A character walks a 12 m line on it, waves from 2 m, runs from 6 m:
 * every output finite, the root at a standing height, on the path until
 * its end (this small graph has no stopping motion: it runs on past it). */
static void test_character_walks(void** state) {
  static const float path[] = {0, 0, 0, 12};
  float matrices[16 * 31], root[3], rotations[4 * 31];
  smg_character* ch;
  smg_character_state st;
  uint32_t id, i, k, ran = 0, waved = 0;
  (void)state;
  assert_int_equal(smg_character_create(g_graph, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, path, 2), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 2.0f, 1, &id), SMG_OK);
  assert_int_equal(smg_character_add_transition(ch, 6.0f, 1, &id), SMG_OK);
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  for (i = 0; i < 30 * 12 && st.path_distance < 11.5f; ++i) {
    assert_int_equal(smg_character_step(ch, 1.0f / 30.0f), SMG_OK);
    assert_int_equal(smg_character_get_state(ch, &st), SMG_OK);
    assert_true(st.path_error < 1.0f);
    ran |= st.style == 1;
    waved |= st.action == 1;
    assert_int_equal(smg_character_get_local_pose(ch, root, rotations, 31),
                     SMG_OK);
    assert_true(root[1] > 0.5f && root[1] < 1.5f);
    assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_WORLD,
                                                      matrices, 31),
                     SMG_OK);
    for (k = 0; k < 16 * 31; ++k) assert_true(isfinite(matrices[k]));
  }
  assert_true(st.path_distance >= 11.5f);
  assert_true(ran);
  assert_true(waved);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_facts),
      cmocka_unit_test(test_character_walks),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
