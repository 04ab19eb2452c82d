/*
 * fuzz_blob.c - fuzz target for the graph-blob reader and graph loading.
 *
 * Random bytes almost never pass the checksum, so each input is tried
 * three ways: as given; with SMG_GRAPH_SKIP_CHECKSUM (so the structural
 * checks face the mutation directly); and, when that is accepted, through
 * smg_graph_load_memory (derived runtime tables), the inspection API and a
 * character walking a short path with a splice and a transition: a graph
 * the loader accepts must never crash the runtime, however odd it is.
 */
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "fixture_graph.h"
#include "fuzz.h"
#include "quat_pack.h"
#include "smg.h"

static volatile float g_sink; /* keeps the reads below from being elided */

static void touch_view(const smgi_graph_data* g) {
  float acc = 0.0f;
  uint64_t i;
  uint32_t f, j;
  /* every root and every packed rotation of the view, decoded */
  for (f = 0; f < g->frame_count; ++f) {
    const unsigned char* rec = smgi_pose_record(g, f);
    float root[3], q[4];
    smgi_pose_root(rec, root);
    acc += root[0] + root[1] + root[2];
    for (j = 0; j < g->joint_count; ++j) {
      float n2;
      smgi_quat_unpack(smgi_pose_rot(rec, j), q);
      /* the reader no longer checks rotations because every pattern
       * decodes to a unit quaternion: hold it to that */
      n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      if (!(n2 > 0.999f && n2 < 1.001f)) abort();
      acc += q[0] + q[3];
    }
  }
  for (i = 0; i < g->joint_count; ++i)
    acc += (float)strlen(g->strings + g->joints[i].name);
  for (i = 0; i < g->lower_edge_count; ++i)
    acc += g->frames[g->lower_edges[i].first_frame].phase +
           (float)g->lower_nodes[g->lower_edges[i].to].frame;
  for (i = 0; i < g->upper_edge_count; ++i)
    acc += (float)g->upper_nodes[g->upper_edges[i].to].frame;
  for (i = 0; i < g->splice_count; ++i)
    acc += (float)g->upper_edges[g->splices[i].upper_edge].frame_count;
  g_sink = acc;
}

/* A short walk: path, one transition to the last style, one splice to the
 * last action, a second of steps, then both pose getters. */
static void exercise_character(smg_graph* graph, uint32_t joints,
                               uint32_t styles, uint32_t actions) {
  static const float path[] = {0, 0, 0, 2, 1, 4, 3, 5};
  static float rotations[4 * 64], matrices[16 * 64];
  smg_character* ch = NULL;
  float root[3];
  uint32_t id, i;
  if (smg_character_create(graph, NULL, &ch) != SMG_OK) return;
  smg_character_set_path(ch, path, 4);
  smg_character_add_transition(ch, 1.0f, styles - 1, &id);
  smg_character_add_splice(ch, 0.5f, actions - 1, &id);
  for (i = 0; i < 30; ++i) smg_character_step(ch, 1.0f / 30.0f);
  if (joints <= 64) {
    smg_character_get_local_pose(ch, root, rotations, joints);
    smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, matrices, joints);
    g_sink = root[0] + rotations[0] + matrices[12];
  }
  smg_character_destroy(ch);
}

static void exercise_graph(const void* data, size_t size) {
  smg_graph_desc desc;
  smg_graph* graph = NULL;
  smg_graph_info info;
  smg_joint_info joint;
  const char* name;
  uint32_t i, idx;
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.flags = SMG_GRAPH_SKIP_CHECKSUM;
  if (smg_graph_load_memory(data, size, &desc, &graph) != SMG_OK) return;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (smg_graph_get_info(graph, &info) == SMG_OK) {
    for (i = 0; i < info.joint_count; ++i) {
      memset(&joint, 0, sizeof joint);
      joint.struct_size = sizeof joint;
      if (smg_graph_get_joint(graph, i, &joint) == SMG_OK)
        smg_graph_find_joint(graph, joint.name, &idx);
    }
    for (i = 0; i < info.style_count; ++i)
      if (smg_graph_get_style_name(graph, i, &name) == SMG_OK)
        smg_graph_find_style(graph, name, &idx);
    for (i = 0; i < info.action_count; ++i)
      if (smg_graph_get_action_name(graph, i, &name) == SMG_OK)
        smg_graph_find_action(graph, name, &idx);
    exercise_character(graph, info.joint_count, info.style_count,
                       info.action_count);
  }
  smg_graph_destroy(graph);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  void* aligned = NULL;
  smgi_graph_data view;
  /* The reader requires 16-byte aligned memory; libFuzzer's buffers are
   * not, so copy into an exact-size aligned block. */
  if (posix_memalign(&aligned, 16, size ? size : 1) != 0) return 0;
  if (size) memcpy(aligned, data, size);
  if (smgi_blob_read(aligned, size, 0, &view, NULL, 0) == SMG_OK)
    touch_view(&view);
  if (smgi_blob_read(aligned, size, SMG_GRAPH_SKIP_CHECKSUM, &view, NULL,
                     0) == SMG_OK) {
    touch_view(&view);
    exercise_graph(aligned, size);
  }
  free(aligned);
  return 0;
}

int fuzz_seed(uint32_t index, uint8_t** data, size_t* size) {
  void* blob = NULL;
  size_t n = 0;
  if (index) return FUZZ_SEED_NONE;
  if (fixture_graph_blob(&blob, &n) != SMG_OK) return -1;
  *data = (uint8_t*)malloc(n);
  if (!*data) {
    smgi_blob_free(blob, NULL);
    return -1;
  }
  memcpy(*data, blob, n);
  *size = n;
  smgi_blob_free(blob, NULL);
  return 0;
}
