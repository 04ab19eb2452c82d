/*
 * bench_import.c - import-side figures (make bench-import): BVH parse of the
 * largest CMU locomotion clip (09_12.bvh, when ../shared is present) and of
 * a synthetic clip, against a baseline measured in the same run (reading
 * the same bytes and scanning them once: the I/O + memory floor), plus
 * resampling, mirroring and synthetic generation. Prints medians; never
 * fails on time.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bake_clip.h"
#include "bake_synthetic.h"

#define RUNS 15

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Thread CPU time: on a loaded machine wall time mostly measures the
 * scheduler, so both are printed. */
static double cpu_now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int cmp(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static double median(double* v, int n) {
  qsort(v, (size_t)n, sizeof *v, cmp);
  return v[n / 2];
}

static char* slurp(const char* path, size_t* size) {
  FILE* fp = fopen(path, "rb");
  char* buf;
  long n;
  if (!fp) return NULL;
  fseek(fp, 0, SEEK_END);
  n = ftell(fp);
  fseek(fp, 0, SEEK_SET);
  buf = (char*)malloc((size_t)n + 1);
  if (buf && fread(buf, 1, (size_t)n, fp) != (size_t)n) {
    free(buf);
    buf = NULL;
  }
  fclose(fp);
  *size = (size_t)n;
  return buf;
}

static volatile unsigned long g_sink;

static void bench_file(const char* path, float unit, uint32_t skip) {
  double t_read[RUNS], t_load[RUNS], t_res[RUNS], t_mir[RUNS];
  double c_read[RUNS], c_load[RUNS];
  size_t size = 0;
  int i;
  smgb_clip c;
  smgb_error err;
  for (i = 0; i < RUNS; ++i) {
    double t0 = now(), c0 = cpu_now();
    char* text = slurp(path, &size);
    unsigned long lines = 0;
    size_t k;
    if (!text) {
      printf("  %s: cannot read\n", path);
      return;
    }
    for (k = 0; k < size; ++k) lines += text[k] == '\n';
    g_sink = lines;
    free(text);
    t_read[i] = now() - t0;
    c_read[i] = cpu_now() - c0;
    t0 = now();
    c0 = cpu_now();
    if (smgb_bvh_load(path, unit, skip, &c, &err) != SMG_OK) {
      printf("  %s\n", err.message);
      return;
    }
    t_load[i] = now() - t0;
    c_load[i] = cpu_now() - c0;
    {
      smgb_clip r, m;
      t0 = now();
      smgb_clip_resample(&c, 30.0f, &r);
      t_res[i] = now() - t0;
      t0 = now();
      smgb_clip_mirror(&r, &m);
      t_mir[i] = now() - t0;
      smgb_clip_free(&r);
      smgb_clip_free(&m);
    }
    if (i + 1 < RUNS) smgb_clip_free(&c);
  }
  {
    double r = median(t_read, RUNS), l = median(t_load, RUNS);
    double cr = median(c_read, RUNS), cl = median(c_load, RUNS);
    printf("  %-28s %8.2f MB %6u frames x %2u joints\n", strrchr(path, '/') + 1,
           size / 1e6, c.frame_count, c.skeleton.joint_count);
    printf("    read+scan (baseline)  %8.2f ms wall %8.2f ms cpu\n", r * 1e3,
           cr * 1e3);
    printf("    smgb_bvh_load         %8.2f ms wall %8.2f ms cpu  (cpu %.1f x "
           "baseline, %.0f MB/s, %.0f ns/value)\n",
           l * 1e3, cl * 1e3, cl / cr, size / cl / 1e6,
           cl * 1e9 / ((double)(c.frame_count + skip) *
                       (3.0 * c.skeleton.joint_count + 3.0)));
    printf("    resample to 30 Hz     %8.2f ms\n", median(t_res, RUNS) * 1e3);
    printf("    mirror (30 Hz)        %8.2f ms\n", median(t_mir, RUNS) * 1e3);
  }
  smgb_clip_free(&c);
}

int main(void) {
  const char* shared = getenv("SMG_SHARED");
  char path[1200], dir[] = "/tmp/smg-bench-import-XXXXXX";
  double t_gen[RUNS];
  smgb_synth_params p;
  smgb_clip c;
  smgb_error err;
  int i;
  printf("bench-import (medians of %d runs)\n", RUNS);
  if (!shared || !*shared) shared = SMG_SHARED_DIR;
  snprintf(path, sizeof path, "%s/mocap/cmu/09_12.bvh", shared);
  {
    FILE* probe = fopen(path, "rb");
    if (!probe) {
      printf("  CMU clips absent (%s): skipping 09_12.bvh\n", path);
    } else {
      fclose(probe);
      bench_file(path, 0.056444f, 1);
    }
  }

  smgb_synth_standard(0, &p, NULL, NULL, NULL);
  for (i = 0; i < RUNS; ++i) {
    double t0 = now();
    smgb_synth_generate(&p, &c, NULL);
    t_gen[i] = now() - t0;
    if (i + 1 < RUNS) smgb_clip_free(&c);
  }
  printf("  synthetic walk generation %6.2f ms for %u frames (%.2f us/frame)\n",
         median(t_gen, RUNS) * 1e3, c.frame_count,
         median(t_gen, RUNS) * 1e6 / c.frame_count);
  if (mkdtemp(dir)) {
    snprintf(path, sizeof path, "%s/synthetic_walk.bvh", dir);
    if (smgb_bvh_save(path, &c, &err) == SMG_OK) bench_file(path, 1.0f, 0);
    remove(path);
    remove(dir);
  }
  smgb_clip_free(&c);
  return 0;
}
