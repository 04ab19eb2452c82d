/*
 * smg-gen-clips - write the SYNTHETIC procedural clip set (BVH, metres)
 * that `make` bakes into the default blob when no motion capture is given.
 *
 *   smg-gen-clips OUTPUT_DIR
 *
 * Writes synthetic_{walk,run}_{straight,left,right}.bvh, synthetic_wave.bvh,
 * synthetic_punch.bvh and README.txt into OUTPUT_DIR (created if missing),
 * plus rig_mixamo_apose.bvh, the generated retargeting test rig
 * (bake_synth_rig.c).
 * data/synthetic.manifest describes them for smg-bake.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <time.h>

#include "bake_clip.h"
#include "bake_synthetic.h"

static void usage(FILE* fp) {
  fprintf(fp,
          "usage: smg-gen-clips OUTPUT_DIR\n"
          "Writes the synthetic (procedural, not motion-capture) clip set as\n"
          "BVH files in metres plus a README.txt into OUTPUT_DIR.\n");
}

int main(int argc, char** argv) {
  smgb_error err;
  smg_result r;
  struct timespec a, b;
  if (argc == 2 && (strcmp(argv[1], "-h") == 0 ||
                    strcmp(argv[1], "--help") == 0)) {
    usage(stdout);
    return 0;
  }
  if (argc != 2 || argv[1][0] == '\0' || argv[1][0] == '-') {
    usage(stderr);
    return 2;
  }
  if (mkdir(argv[1], 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "smg-gen-clips: %s: cannot create folder: %s\n", argv[1],
            strerror(errno));
    return 1;
  }
  clock_gettime(CLOCK_MONOTONIC, &a);
  {
    /* the generated retargeting test rig (not a clip), first: the clip
     * set's README.txt, written last, is the build's stamp */
    char rig[4096];
    snprintf(rig, sizeof rig, "%s/rig_mixamo_apose.bvh", argv[1]);
    r = smgb_synth_write_rig(rig, &err);
  }
  if (r == SMG_OK) r = smgb_synth_write_all(argv[1], &err);
  clock_gettime(CLOCK_MONOTONIC, &b);
  if (r != SMG_OK) {
    fprintf(stderr, "smg-gen-clips: %s (%s)\n", err.message,
            smg_result_string(r));
    return 1;
  }
  printf("smg-gen-clips: wrote %u synthetic clips to %s in %.1f ms\n",
         (unsigned)SMGB_SYNTH_STANDARD_COUNT, argv[1],
         (double)(b.tv_sec - a.tv_sec) * 1e3 +
             (double)(b.tv_nsec - a.tv_nsec) / 1e6);
  return 0;
}
