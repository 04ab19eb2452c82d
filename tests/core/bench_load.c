/*
 * bench_load.c - graph load cost (make bench-load): how long validating a
 * blob takes compared with just copying its bytes, with and without the
 * checksum. Prints medians of repeated runs and ratios against the memcpy
 * baseline measured in the same run; no pass/fail on time.
 *
 *   bench_load [BLOB]   default: the fixture graph (tests/fixture_graph.h)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "blob.h"
#include "fixture_graph.h"
#include "smg.h"

#define REPS 31

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static double median(double* v) {
  qsort(v, REPS, sizeof *v, cmp_double);
  return v[REPS / 2];
}

static void* read_file_aligned(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  void* buf = NULL;
  long n;
  if (!f) return NULL;
  if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 ||
      fseek(f, 0, SEEK_SET) != 0 ||
      posix_memalign(&buf, 16, (size_t)n ? (size_t)n : 1) != 0 ||
      fread(buf, 1, (size_t)n, f) != (size_t)n) {
    fclose(f);
    free(buf);
    return NULL;
  }
  fclose(f);
  *size = (size_t)n;
  return buf;
}

int main(int argc, char** argv) {
  void *blob = NULL, *copy;
  size_t size = 0;
  double t_copy[REPS], t_full[REPS], t_skip[REPS], base, full, skip;
  smg_graph_desc skip_desc;
  const char* name = argc > 1 ? argv[1] : "fixture graph";
  int i;

  if (argc > 1) {
    blob = read_file_aligned(argv[1], &size);
    if (!blob) {
      fprintf(stderr, "bench-load: cannot read %s\n", argv[1]);
      return 1;
    }
  } else {
    void* b = NULL;
    if (fixture_graph_blob(&b, &size) != SMG_OK) return 1;
    blob = b;
  }
  if (posix_memalign(&copy, 16, size) != 0) return 1;
  memset(&skip_desc, 0, sizeof skip_desc);
  skip_desc.struct_size = sizeof skip_desc;
  skip_desc.flags = SMG_GRAPH_SKIP_CHECKSUM;

  for (i = 0; i < REPS; ++i) {
    smg_graph* g = NULL;
    double t0 = now();
    memcpy(copy, blob, size);
    t_copy[i] = now() - t0;
    t0 = now();
    if (smg_graph_load_memory(blob, size, NULL, &g) != SMG_OK) {
      fprintf(stderr, "bench-load: %s does not load\n", name);
      return 1;
    }
    t_full[i] = now() - t0;
    smg_graph_destroy(g);
    t0 = now();
    if (smg_graph_load_memory(blob, size, &skip_desc, &g) != SMG_OK) return 1;
    t_skip[i] = now() - t0;
    smg_graph_destroy(g);
  }
  base = median(t_copy);
  full = median(t_full);
  skip = median(t_skip);
  printf("bench-load: %s, %.2f MB, median of %d runs\n", name,
         (double)size / 1e6, REPS);
  printf("  memcpy of the blob (baseline)    %8.3f ms  %7.0f MB/s\n",
         base * 1e3, (double)size / 1e6 / base);
  printf("  load, full validation            %8.3f ms  %7.0f MB/s  %5.1fx "
         "memcpy\n",
         full * 1e3, (double)size / 1e6 / full, full / base);
  printf("  load, SMG_GRAPH_SKIP_CHECKSUM    %8.3f ms  %7.0f MB/s  %5.1fx "
         "memcpy\n",
         skip * 1e3, (double)size / 1e6 / skip, skip / base);
  free(copy);
  free(blob);
  return 0;
}
