/*
 * c_replay - the reference run for the C# binding test (make test-csharp).
 *
 *   c_replay BLOB FRAMES > stream
 *
 * Performs a fixed call sequence through the C API (three characters, a
 * path that grows, transition and splice points added, moved and removed,
 * immediate controls, a replaced and a cleared path, uneven dt, ground
 * heights from the probes for one character, a mover shifting another)
 * and writes every result code and every output (state struct, local
 * pose, world matrices, character-space matrices every 10th frame, the
 * step's events and root motion, the ground probes) as raw bytes to
 * stdout. tests/csharp/ReplayTest.cs performs the same sequence through
 * the C# classes and compares the stream byte for byte, so any difference in what the binding passes or reads shows up as
 * the first differing frame. Keep the two sequences identical: every
 * number here is exactly representable, so both sides compute the same
 * floats.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "smg.h"

#define CHARACTERS 3

static void put(const void* p, size_t n) {
  if (fwrite(p, 1, n, stdout) != n) {
    fprintf(stderr, "c_replay: write failed\n");
    exit(1);
  }
}

static void put_result(smg_result r) {
  int32_t v = (int32_t)r;
  put(&v, sizeof v);
}

static int fail(const char* what, smg_result r) {
  fprintf(stderr, "c_replay: %s: %s\n", what, smg_result_string(r));
  return 1;
}

static const float start_path[] = {0, 0, 0, 8, 6, 14, 14, 14, 20, 8, 20, 0, 12, -6, 4, -4};
static const float ring[] = {0, 4, 6, 10, 12, 4, 6, -2};
static const float square[] = {0, 0, 10, 0, 10, 10, 0, 10};

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: c_replay BLOB FRAMES > stream\n");
    return 2;
  }
  long frames = strtol(argv[2], NULL, 10);
  smg_graph* graph = NULL;
  smg_result r = smg_graph_load_file(argv[1], NULL, &graph);
  if (r != SMG_OK) return fail(argv[1], r);
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if ((r = smg_graph_get_info(graph, &info)) != SMG_OK) return fail("info", r);
  uint32_t joints = info.joint_count;
  float* rot = (float*)malloc(sizeof(float) * 4 * joints);
  float* mat = (float*)malloc(sizeof(float) * 16 * joints);
  if (!rot || !mat) return fail("malloc", SMG_ERROR_OUT_OF_MEMORY);

  /* header: joints, state size, characters, frames */
  uint32_t header[4] = {joints, (uint32_t)sizeof(smg_character_state), CHARACTERS, (uint32_t)frames};
  put(header, sizeof header);

  smg_character* ch[CHARACTERS];
  uint32_t first_splice[CHARACTERS], first_transition[CHARACTERS];
  for (int k = 0; k < CHARACTERS; ++k) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.seed = 1u + (uint32_t)k;
    d.position[0] = 1.5f * (float)k;
    d.position[2] = -1.0f;
    d.heading = 0.25f * (float)k;
    if ((r = smg_character_create(graph, &d, &ch[k])) != SMG_OK) return fail("create", r);
    put_result(smg_character_set_path(ch[k], start_path, 8));
    put_result(smg_character_add_splice(ch[k], 2.5f, info.action_count > 1 ? 1u : 0u, &first_splice[k]));
    put_result(smg_character_add_transition(ch[k], 4.0f, info.style_count - 1, &first_transition[k]));
    put_result(smg_character_add_splice(ch[k], 9.0f, 0, NULL));
    put_result(smg_character_add_transition(ch[k], 16.0f, 0, NULL));
  }

  for (long f = 0; f < frames; ++f) {
    if (f > 0 && f % 1500 == 0) {
      uint32_t n = (uint32_t)(f / 1500);
      float moved[8];
      for (int i = 0; i < 8; i += 2) {
        moved[i] = ring[i] + 2.0f * (float)n;
        moved[i + 1] = ring[i + 1];
      }
      for (int k = 0; k < CHARACTERS; ++k) {
        float length = 0.0f;
        put_result(smg_character_append_path(ch[k], moved, 4));
        put_result(smg_character_get_path_length(ch[k], &length));
        put(&length, sizeof length);
        put_result(smg_character_add_splice(ch[k], length - 3.0f, n % info.action_count, NULL));
        put_result(smg_character_add_transition(ch[k], length - 5.0f, n % info.style_count, NULL));
        if (n == 2) put_result(smg_character_move_constraint(ch[k], first_splice[k], 11.0f));
        if (n == 3) put_result(smg_character_remove_constraint(ch[k], first_transition[k]));
      }
    }
    if (f == 3000) put_result(smg_character_set_ik(ch[2], 0));
    if (f == 4000) put_result(smg_character_set_error_threshold(ch[0], 0.5f));
    if (f == 5000) {
      put_result(smg_character_set_style(ch[1], 0));
      put_result(smg_character_set_action(ch[1], info.action_count - 1));
    }
    if (f == 7000) put_result(smg_character_set_path(ch[0], square, 4));
    if (f == 8000) put_result(smg_character_clear_constraints(ch[1]));
    if (f == 8500) put_result(smg_character_clear_path(ch[2]));
    if (f == 9000) put_result(smg_character_set_path(ch[2], square, 4));

    /* character 2 walks on ground 0.1 z high, measured at its probes */
    if (f >= 2000 && f < 6000) {
      float p[6];
      smg_ground g;
      put_result(smg_character_get_ground_probes(ch[2], p, 3));
      put(p, sizeof p);
      memset(&g, 0, sizeof g);
      g.struct_size = sizeof g;
      g.foot_height[0] = 0.1f * p[1];
      g.foot_height[1] = 0.1f * p[3];
      g.root_height = 0.1f * p[5];
      put_result(smg_character_set_ground(ch[2], &g));
    }
    if (f == 6000) put_result(smg_character_set_ground(ch[2], NULL));

    float dt = f % 97 == 0 ? 0.0f : f % 7 == 3 ? 0.05f : 1.0f / 60.0f;
    for (int k = 0; k < CHARACTERS; ++k) {
      smg_character_state st;
      smg_event ev[32 + 5];
      smg_root_motion rm;
      uint32_t n = 0;
      float root[3];
      memset(&st, 0, sizeof st);
      st.struct_size = sizeof st;
      put_result(smg_character_step(ch[k], dt));
      memset(ev, 0, sizeof ev);
      ev[0].struct_size = sizeof ev[0];
      put_result(smg_character_get_events(ch[k], ev, 32 + 5, &n));
      put(&n, sizeof n);
      put(ev, sizeof ev[0] * n);
      memset(&rm, 0, sizeof rm);
      rm.struct_size = sizeof rm;
      put_result(smg_character_get_root_motion(ch[k], &rm));
      put(&rm, sizeof rm);
      put_result(smg_character_get_state(ch[k], &st));
      put(&st, sizeof st);
      /* character 0: a mover that shifts it 2 mm sideways every step */
      if (k == 0 && f >= 1000 && f < 2500) {
        const float moved_to[3] = {st.position[0] + 0.002f, st.position[1], st.position[2]};
        put_result(smg_character_set_ground_position(ch[0], moved_to, st.heading));
      }
      put_result(smg_character_get_local_pose(ch[k], root, rot, joints));
      put(root, sizeof root);
      put(rot, sizeof(float) * 4 * joints);
      put_result(smg_character_get_model_matrices(ch[k], SMG_SPACE_WORLD, mat, joints));
      put(mat, sizeof(float) * 16 * joints);
      if (f % 10 == 0) {
        put_result(smg_character_get_model_matrices(ch[k], SMG_SPACE_CHARACTER, mat, joints));
        put(mat, sizeof(float) * 16 * joints);
      }
    }
  }

  for (int k = 0; k < CHARACTERS; ++k) put_result(smg_character_destroy(ch[k]));
  put_result(smg_graph_destroy(graph));
  free(rot);
  free(mat);
  return fflush(stdout) == 0 ? 0 : 1;
}
