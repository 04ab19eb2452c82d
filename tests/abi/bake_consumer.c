/*
 * bake_consumer.c - a tools-side program built against an *installed*
 * libsmg through `pkg-config smg-bake` (make test-install): bakes a graph
 * from one locomotion clip given on the command line with smg_bake_run,
 * loads the blob with the runtime and steps a character along a path -
 * the whole offline-to-runtime round trip from outside the tree.
 */
#include <smg.h>
#include <smg_bake.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: bake_consumer CLIP.bvh\n");
    return 2;
  }
  smg_bake_clip_desc clip;
  memset(&clip, 0, sizeof clip);
  clip.struct_size = sizeof clip;
  clip.role = SMG_BAKE_ROLE_LOWER;
  clip.path = argv[1];
  clip.label = "walk";
  smg_bake_desc desc;
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.clip_count = 1;
  desc.clips = &clip;
  smg_bake_result res;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  smg_result r = smg_bake_run(&desc, &res);
  if (r != SMG_OK) {
    fprintf(stderr, "bake_consumer: bake failed: %s (%s)\n",
            smg_result_string(r), res.error);
    return 1;
  }
  smg_graph* g = NULL;
  smg_character* ch = NULL;
  r = smg_graph_load_memory(res.blob, res.blob_size, NULL, &g);
  if (r == SMG_OK) r = smg_character_create(g, NULL, &ch);
  const float path[4] = {0.0f, 0.0f, 0.0f, 10.0f};
  if (r == SMG_OK) r = smg_character_set_path(ch, path, 2);
  for (int i = 0; i < 120 && r == SMG_OK; ++i)
    r = smg_character_step(ch, 1.0f / 60.0f);
  smg_character_state st;
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  if (r == SMG_OK) r = smg_character_get_state(ch, &st);
  if (ch) smg_character_destroy(ch);
  if (g) smg_graph_destroy(g);
  size_t bytes = res.blob_size;
  smg_bake_result_free(&res);
  if (r != SMG_OK) {
    fprintf(stderr, "bake_consumer: runtime failed: %s\n",
            smg_result_string(r));
    return 1;
  }
  /* 2 s of walking towards +z: it must have moved along the path */
  if (!(st.path_distance > 0.5f)) {
    fprintf(stderr, "bake_consumer: character did not move (%.3f m)\n",
            (double)st.path_distance);
    return 1;
  }
  printf("bake_consumer: baked %zu bytes, walked %.2f m in 2 s\n", bytes,
         (double)st.path_distance);
  return 0;
}
