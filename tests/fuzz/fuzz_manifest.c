/*
 * fuzz_manifest.c - fuzz target for the manifest parser (smgb_manifest_load)
 * and its conversion to bake descriptors (smgb_manifest_descs).
 *
 * The parser reads a file, so each input is written to a manifest in a
 * private temporary folder that also holds the clip files the seed names
 * (manifests must name clips that exist). An accepted manifest must give
 * consistent clips; a refused one must say why, naming the file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake_manifest.h"
#include "fuzz.h"

static char g_dir[64];
static char g_manifest[128];

static void cleanup(void) {
  static const char* files[] = {"walk.bvh", "run.bvh", "punch.bvh",
                                "my clip.glb", "in.manifest"};
  char path[192];
  size_t i;
  for (i = 0; i < sizeof files / sizeof files[0]; ++i) {
    snprintf(path, sizeof path, "%s/%s", g_dir, files[i]);
    remove(path);
  }
  rmdir(g_dir);
}

/* The folder and the (empty) clip files the parser checks for. */
static void make_dir(void) {
  static const char* clips[] = {"walk.bvh", "run.bvh", "punch.bvh",
                                "my clip.glb"};
  char path[192];
  size_t i;
  if (g_dir[0]) return;
  /* memory-backed when the system has it: a file per input is the cost */
  snprintf(g_dir, sizeof g_dir, "/dev/shm/smg-fuzz-manifest-XXXXXX");
  if (!mkdtemp(g_dir)) {
    snprintf(g_dir, sizeof g_dir, "/tmp/smg-fuzz-manifest-XXXXXX");
    if (!mkdtemp(g_dir)) abort();
  }
  for (i = 0; i < sizeof clips / sizeof clips[0]; ++i) {
    FILE* f;
    snprintf(path, sizeof path, "%s/%s", g_dir, clips[i]);
    f = fopen(path, "wb");
    if (!f) abort();
    fclose(f);
  }
  snprintf(g_manifest, sizeof g_manifest, "%s/in.manifest", g_dir);
  atexit(cleanup);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc* descs;
  FILE* f;
  uint32_t i;
  int pass;
  make_dir();
  f = fopen(g_manifest, "wb");
  if (!f) abort();
  if (size && fwrite(data, 1, size, f) != size) abort();
  fclose(f);
  /* with the manifest's own root, then with an override */
  for (pass = 0; pass < 2; ++pass) {
    err.message[0] = '\0';
    if (smgb_manifest_load(g_manifest, pass ? g_dir : NULL, &m, &err) !=
        SMG_OK) {
      if (!strstr(err.message, "in.manifest")) abort(); /* names the file */
      continue;
    }
    if (m.clip_count == 0 || m.clip_count > SMGB_MANIFEST_MAX_CLIPS) abort();
    descs = (smg_bake_clip_desc*)calloc(m.clip_count, sizeof *descs);
    if (!descs) abort();
    if (smgb_manifest_descs(&m, descs, m.clip_count) != SMG_OK) abort();
    for (i = 0; i < m.clip_count; ++i)
      if ((descs[i].role != SMG_BAKE_ROLE_LOWER &&
           descs[i].role != SMG_BAKE_ROLE_UPPER) ||
          !descs[i].label || !descs[i].label[0] || !descs[i].path ||
          !(descs[i].unit_scale >= 0.0f))
        abort();
    free(descs);
    smgb_manifest_free(&m);
  }
  return 0;
}

/* Every statement and option of docs/manifest.md at least once. */
int fuzz_seed(uint32_t index, uint8_t** data, size_t* size) {
  static const char seed[] =
      "# a manifest\n"
      "frame_rate 30\n"
      "root .\n"
      "unit 0.056444\n"
      "skip_first_frame 1\n"
      "mirror 1\n"
      "animation 0\n"
      "lower walk walk.bvh frames=1-200 name=w1\n"
      "lower run  run.bvh mirror=0 unit=1 skip_first_frame=0\n"
      "mirror default\n"
      "upper punch punch.bvh frames=100-end\n"
      "upper dribble \"my clip.glb\" animation=1 unit=1   # comment\n";
  if (index) return FUZZ_SEED_NONE;
  *size = sizeof seed - 1;
  *data = (uint8_t*)malloc(*size);
  if (!*data) return -1;
  memcpy(*data, seed, *size);
  return 0;
}
