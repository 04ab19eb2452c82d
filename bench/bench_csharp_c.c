/*
 * bench_csharp_c - the C side of `make bench-csharp` (bench/BenchCsharp.cs
 * runs it and the same loop through the C# binding, alternately).
 *
 *   bench_csharp_c BLOB CHARACTERS WARMUP FRAMES
 *
 * Creates CHARACTERS characters on one path, steps WARMUP frames, then
 * times FRAMES frames of step + get_state + get_local_pose per character
 * (what the Unity component does per frame) in thread CPU time and prints
 * nanoseconds per character-frame. BenchCsharp.cs does exactly the same
 * calls, so both sides do identical work.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "smg.h"

static const float path[] = {0, 0, 0, 30, 30, 30, 30, 0, 0, 0, 0, 30};

static double thread_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int fail(const char* what, smg_result r) {
  fprintf(stderr, "bench_csharp_c: %s: %s\n", what, smg_result_string(r));
  return 1;
}

int main(int argc, char** argv) {
  if (argc != 5) {
    fprintf(stderr, "usage: bench_csharp_c BLOB CHARACTERS WARMUP FRAMES\n");
    return 2;
  }
  int n = atoi(argv[2]), warmup = atoi(argv[3]), frames = atoi(argv[4]);
  smg_graph* graph = NULL;
  smg_result r = smg_graph_load_file(argv[1], NULL, &graph);
  if (r != SMG_OK) return fail(argv[1], r);
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_graph_get_info(graph, &info);
  uint32_t joints = info.joint_count;
  smg_character** ch = (smg_character**)calloc((size_t)n, sizeof *ch);
  float* rot = (float*)malloc(sizeof(float) * 4 * joints);
  if (!ch || !rot || n <= 0) return fail("setup", SMG_ERROR_OUT_OF_MEMORY);
  for (int k = 0; k < n; ++k) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.seed = 1u + (uint32_t)k;
    d.position[0] = 0.5f * (float)k;
    if ((r = smg_character_create(graph, &d, &ch[k])) != SMG_OK) return fail("create", r);
    if ((r = smg_character_set_path(ch[k], path, 6)) != SMG_OK) return fail("path", r);
  }
  double start = 0.0;
  for (int f = 0; f < warmup + frames; ++f) {
    if (f == warmup) start = thread_seconds();
    for (int k = 0; k < n; ++k) {
      smg_character_state st;
      float root[3];
      memset(&st, 0, sizeof st);
      st.struct_size = sizeof st;
      if ((r = smg_character_step(ch[k], 1.0f / 60.0f)) != SMG_OK) return fail("step", r);
      if ((r = smg_character_get_state(ch[k], &st)) != SMG_OK) return fail("state", r);
      if ((r = smg_character_get_local_pose(ch[k], root, rot, joints)) != SMG_OK) return fail("pose", r);
    }
  }
  double seconds = thread_seconds() - start;
  printf("%.1f\n", 1e9 * seconds / ((double)n * (double)frames));
  for (int k = 0; k < n; ++k) smg_character_destroy(ch[k]);
  smg_graph_destroy(graph);
  free(ch);
  free(rot);
  return 0;
}
