/*
 * bench_bake.c - baker figures (make bench-bake). Prints, never fails on
 * time.
 *
 *  1. The paper-size CMU set (data/cmu.manifest: the forward part of 09_12
 *     plus 06_01/02_01 walks, the subject-09 runs, 02_05 punch; mirrored) baked end to
 *     end, median of several runs, per stage beside the paper's single-core
 *     preprocessing times (lower graph 70 min, upper graph 10 min, splice
 *     search 30 min, internodal data 3 h), with wall and CPU time, peak
 *     memory and graph sizes.
 *  2. Baseline measured in the same run: the lower-body distance grid of
 *     that size evaluated window by window (Kovar's formula per frame pair,
 *     O(F^2 k P), extrapolated from a slice of rows) against the streamed
 *     diagonal-sum grid (O(F^2 P)); and 1 vs 2 worker threads.
 *  3. Every clip in ../shared (data/cmu-all.manifest) and growth of the bake
 *     time with the frame count (subsets of that set).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "bake_pointcloud.h"
#include "bake_manifest.h"
#include "bake_synthetic.h"
#include "smg_bake.h"

#ifndef SMG_SHARED_DIR
#define SMG_SHARED_DIR "../shared"
#endif

#define RUNS 5

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double cpu_seconds(void) {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec +
         (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

static long peak_kb(void) {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

/* The wall-clock figures depend on what else runs on the machine. */
static const char* load_average(void) {
  static char buf[64];
  FILE* fp = fopen("/proc/loadavg", "r");
  buf[0] = '\0';
  if (fp) {
    if (!fgets(buf, sizeof buf, fp)) buf[0] = '\0';
    fclose(fp);
  }
  {
    char* sp = strchr(buf, ' ');
    if (sp) *sp = '\0';
  }
  return buf[0] ? buf : "unknown";
}

static int cmp(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static double median(double* v, int n) {
  qsort(v, (size_t)n, sizeof *v, cmp);
  return v[n / 2];
}

typedef struct bake_set {
  smgb_manifest m;
  smg_bake_clip_desc* descs;
  uint32_t count;
} bake_set;

static int load_set(const char* manifest, const char* dir, bake_set* s) {
  smgb_error err;
  memset(s, 0, sizeof *s);
  if (smgb_manifest_load(manifest, dir, &s->m, &err) != SMG_OK) {
    printf("  cannot load %s: %s\n", manifest, err.message);
    return 0;
  }
  s->descs = calloc(s->m.clip_count, sizeof *s->descs);
  if (!s->descs ||
      smgb_manifest_descs(&s->m, s->descs, s->m.clip_count) != SMG_OK) {
    printf("  out of memory\n");
    smgb_manifest_free(&s->m);
    free(s->descs);
    return 0;
  }
  s->count = s->m.clip_count;
  return 1;
}

static void free_set(bake_set* s) {
  free(s->descs);
  smgb_manifest_free(&s->m);
}

static smg_result bake_onto(const smg_bake_clip_desc* descs, uint32_t n,
                            uint32_t threads, const char* rig,
                            float rig_unit, smg_bake_result* res,
                            double* cpu) {
  smg_bake_desc d;
  double c0 = cpu_seconds();
  smg_result r;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = n;
  d.options.struct_size = sizeof d.options;
  d.options.threads = threads;
  d.target_path = rig;
  d.target_unit_scale = rig_unit;
  memset(res, 0, sizeof *res);
  res->struct_size = sizeof *res;
  r = smg_bake_run(&d, res);
  if (cpu) *cpu = cpu_seconds() - c0;
  return r;
}

static smg_result bake(const smg_bake_clip_desc* descs, uint32_t n,
                       uint32_t threads, smg_bake_result* res, double* cpu) {
  return bake_onto(descs, n, threads, NULL, 0.0f, res, cpu);
}

static double stage_seconds(const smg_bake_result* r, const char* name) {
  uint32_t i;
  for (i = 0; i < r->stage_count; ++i)
    if (strcmp(r->stages[i].name, name) == 0) return r->stages[i].seconds;
  return 0.0;
}

/* The paper-size set onto the generated Mixamo-style rig
 * (bake_synth_rig.c) against the same set on its own skeleton, runs
 * interleaved so both see the same machine load. */
static void retarget_cost(const char* dir) {
  bake_set s;
  char rig[] = "/tmp/smg_bench_rig_XXXXXX";
  char path[64];
  smgb_error err;
  char cmu_rig[1100];
  double plain[RUNS], onto[RUNS], cp[RUNS], co[RUNS], ip[RUNS], io[RUNS];
  double same[RUNS], cs[RUNS];
  int run;
  printf("\n== retargeting cost: paper-size set onto the test rig vs its "
         "own skeleton, median of %d runs each\n", RUNS);
  if (!mkdtemp(rig)) {
    printf("  cannot create a temporary folder\n");
    return;
  }
  snprintf(path, sizeof path, "%s/rig.bvh", rig);
  snprintf(cmu_rig, sizeof cmu_rig, "%s/09_12.bvh", dir);
  if (smgb_synth_write_rig(path, &err) != SMG_OK ||
      !load_set("data/cmu.manifest", dir, &s)) {
    printf("  cannot prepare the rig or the set\n");
    rmdir(rig);
    return;
  }
  for (run = 0; run < RUNS; ++run) {
    smg_bake_result res;
    double t0 = now();
    if (bake(s.descs, s.count, 2, &res, &cp[run]) != SMG_OK) break;
    plain[run] = now() - t0;
    ip[run] = stage_seconds(&res, "import");
    smg_bake_result_free(&res);
    t0 = now();
    if (bake_onto(s.descs, s.count, 2, path, 1.0f, &res, &co[run]) != SMG_OK) {
      printf("  bake onto the rig failed: %s\n", res.error);
      break;
    }
    onto[run] = now() - t0;
    io[run] = stage_seconds(&res, "import");
    smg_bake_result_free(&res);
    /* the full retargeting onto the CMU skeleton itself (its own BVH as
     * the rig): same joint count, so only the retargeting differs */
    t0 = now();
    if (bake_onto(s.descs, s.count, 2, cmu_rig, 0.056444f, &res,
                  &cs[run]) != SMG_OK) {
      printf("  bake onto %s failed: %s\n", cmu_rig, res.error);
      break;
    }
    same[run] = now() - t0;
    smg_bake_result_free(&res);
  }
  if (run == RUNS) {
    double p = median(plain, RUNS), o = median(onto, RUNS);
    double pc = median(cp, RUNS), oc = median(co, RUNS);
    /* the rig has 22 joints to CMU's 31, so the later stages get cheaper;
     * the import stage holds the retargeting itself */
    printf("  own skeleton  %.3f s wall, %.3f s CPU, import stage %.3f s\n",
           p, pc, median(ip, RUNS));
    printf("  onto the rig  %.3f s wall, %.3f s CPU, import stage %.3f s\n",
           o, oc, median(io, RUNS));
    printf("  ratio         %.2f wall, %.2f CPU (budget: at most 1.20)\n",
           o / p, oc / pc);
    printf("  onto 09_12.bvh's own skeleton as a rig (31 joints, every clip "
           "retargeted): %.3f s wall, %.3f s CPU, ratio %.2f wall, %.2f "
           "CPU\n", median(same, RUNS), median(cs, RUNS),
           median(same, RUNS) / p, median(cs, RUNS) / pc);
  }
  free_set(&s);
  remove(path);
  rmdir(rig);
}

static void paper_set(const char* dir) {
  static const struct {
    const char* stage;
    double paper_seconds;
    const char* paper;
  } rows[] = {{"import", 0, "-"},
              {"lower graph", 70 * 60.0, "70 min"},
              {"upper graph", 10 * 60.0, "10 min"},
              {"simplify", 0, "-"},
              {"splice search", 30 * 60.0, "30 min"},
              {"internodal + blob", 3 * 3600.0, "3 h"}};
  bake_set s;
  smg_bake_result res;
  double st[6][RUNS], total[RUNS], cpu[RUNS], t1[RUNS], t2[RUNS];
  int run;
  size_t i;
  printf("== paper-size set (data/cmu.manifest, mirrored), median of %d "
         "runs\n", RUNS);
  if (!load_set("data/cmu.manifest", dir, &s)) return;
  for (run = 0; run < RUNS; ++run) {
    if (bake(s.descs, s.count, 2, &res, &cpu[run]) != SMG_OK) {
      printf("  bake failed: %s\n", res.error);
      free_set(&s);
      return;
    }
    for (i = 0; i < 6; ++i) st[i][run] = stage_seconds(&res, rows[i].stage);
    total[run] = res.total_seconds;
    if (run + 1 < RUNS) smg_bake_result_free(&res);
  }
  printf("  %-20s %12s %14s %12s\n", "stage", "this (s)", "paper (1 core)",
         "speed-up");
  for (i = 0; i < 6; ++i) {
    double m = median(st[i], RUNS);
    if (rows[i].paper_seconds > 0)
      printf("  %-20s %12.3f %14s %11.0fx\n", rows[i].stage, m, rows[i].paper,
             rows[i].paper_seconds / (m > 1e-6 ? m : 1e-6));
    else
      printf("  %-20s %12.3f %14s %12s\n", rows[i].stage, m, "-", "-");
  }
  {
    double w = median(total, RUNS), c = median(cpu, RUNS);
    printf("  %-20s %12.3f %14s %11.0fx\n", "total (wall)", w, "4 h 50 min",
           (4 * 3600.0 + 50 * 60.0) / w);
    printf("  %-20s %12.3f   (user+sys of both threads)\n", "total (CPU)", c);
    printf("  budget: <= 2 s wall on 2 cores: %s (load average while "
           "measuring: %s)\n",
           w <= 2.0 ? "met" : "NOT met (machine load? compare CPU time)",
           load_average());
  }
  printf("  peak memory (max RSS of this process so far): %.1f MB\n",
         peak_kb() / 1024.0);
  printf("  frames %u source + %u blended; lower graph %u nodes / %u edges "
         "before simplification -> %u / %u; upper %u / %u -> %u / %u "
         "(paper: 240 lower, 64 upper nodes after simplification); %u "
         "splice candidates, coverage %.1f %% (longest wait %.2f s); blob "
         "%.2f MB\n",
         res.stats.source_frames, res.stats.blend_frames,
         res.stats.lower_nodes_before, res.stats.lower_edges_before,
         res.stats.lower_nodes, res.stats.lower_edges,
         res.stats.upper_nodes_before, res.stats.upper_edges_before,
         res.stats.upper_nodes, res.stats.upper_edges,
         res.stats.splice_count, 100.0 * res.stats.splice_coverage,
         res.stats.splice_max_gap, res.blob_size / 1048576.0);
  smg_bake_result_free(&res);

  printf("  threads: ");
  for (run = 0; run < 3; ++run) {
    double a = now();
    bake(s.descs, s.count, 1, &res, NULL);
    t1[run] = now() - a;
    smg_bake_result_free(&res);
    a = now();
    bake(s.descs, s.count, 2, &res, NULL);
    t2[run] = now() - a;
    smg_bake_result_free(&res);
  }
  {
    double a = median(t1, 3), b = median(t2, 3);
    printf("1 thread %.3f s, 2 threads %.3f s (ratio %.2f)\n", a, b, a / b);
  }
  free_set(&s);
}

/* Smooth random cloud (values do not change the cost). */
static double* cloud(uint32_t F, uint32_t P) {
  double* x = malloc((size_t)F * P * 3 * sizeof *x);
  uint32_t f, p;
  for (f = 0; f < F; ++f)
    for (p = 0; p < P; ++p) {
      x[(f * P + p) * 3] = sin(0.3 * f + p) * 0.3;
      x[(f * P + p) * 3 + 1] = 0.5 + 0.1 * cos(0.2 * f + 2 * p);
      x[(f * P + p) * 3 + 2] = 0.03 * f + 0.2 * sin(0.4 * f + p);
    }
  return x;
}

static void grid_baseline(void) {
  /* the paper set's lower cloud: 1672 frames of 9 lower-body points
   * (root, hips, knees, ankles, toes), k = 10 */
  const uint32_t F = 1672, P = 9, k = 10, slice = 60;
  double* x = cloud(F, P);
  double w[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1}, a, streamed[3], direct;
  uint8_t* valid = malloc(F);
  smgb_cloud c;
  smgb_grid_job job;
  smgb_minimum* m;
  uint32_t n, i, j, run;
  volatile double sink = 0.0;
  for (i = 0; i < F; ++i) valid[i] = i + k < F;
  c.frames = F; c.points = P; c.xyz = x; c.weights = w; c.valid = valid;
  memset(&job, 0, sizeof job);
  job.rows = &c;
  job.cols = &c;
  job.window = k;
  job.align = 1;
  job.threads = 1;
  for (run = 0; run < 3; ++run) {
    a = now();
    smgb_grid_minima(&job, &m, &n);
    streamed[run] = now() - a;
    free(m);
  }
  a = now();
  for (i = 0; i < slice; ++i)
    for (j = 0; j + k < F; ++j) sink += smgb_window_distance(&c, i, &c, j, k, 1, NULL);
  direct = (now() - a) * (double)(F - k) / slice;
  printf("== baseline: lower distance grid %u x %u frames, %u points, "
         "window %u, 1 thread\n", F, F, P, k);
  printf("  direct per-window evaluation (extrapolated from %u rows): "
         "%.3f s\n", slice, direct);
  printf("  streamed diagonal sums (median of 3):                    %.3f s"
         "  (%.0fx faster)\n", median(streamed, 3), direct / median(streamed, 3));
  (void)sink;
  free(x);
  free(valid);
}

static void all_clips(const char* dir) {
  bake_set s;
  smg_bake_result res;
  double cpu, t;
  uint32_t lower = 0, upper = 0, i, q;
  double fr[4], ts[4];
  printf("== every clip (data/cmu-all.manifest, mirrored)\n");
  if (!load_set("data/cmu-all.manifest", dir, &s)) return;
  t = now();
  if (bake(s.descs, s.count, 2, &res, &cpu) != SMG_OK) {
    printf("  bake failed: %s\n", res.error);
    free_set(&s);
    return;
  }
  t = now() - t;
  printf("  %u clips with mirrors, %u source frames: %.3f s wall, %.3f s "
         "CPU; lower %u nodes, upper %u nodes, %u splices, blob %.2f MB\n",
         res.stats.clip_count, res.stats.source_frames, t, cpu,
         res.stats.lower_nodes, res.stats.upper_nodes,
         res.stats.splice_count, res.blob_size / 1048576.0);
  smg_bake_result_free(&res);
  /* growth: the first quarter, half, ... of the lower and upper clips */
  for (i = 0; i < s.count; ++i)
    if (s.descs[i].role == SMG_BAKE_ROLE_LOWER) ++lower; else ++upper;
  printf("  growth with the frame count (subsets of the set):\n");
  for (q = 1; q <= 4; ++q) {
    smg_bake_clip_desc sub[64];
    uint32_t nl = (lower * q + 3) / 4, nu = (upper * q + 3) / 4, n = 0;
    uint32_t sl = 0, su = 0;
    for (i = 0; i < s.count && n < 64; ++i) {
      if (s.descs[i].role == SMG_BAKE_ROLE_LOWER && sl < nl) {
        sub[n++] = s.descs[i];
        ++sl;
      } else if (s.descs[i].role == SMG_BAKE_ROLE_UPPER && su < nu) {
        sub[n++] = s.descs[i];
        ++su;
      }
    }
    t = now();
    if (bake(sub, n, 2, &res, &cpu) != SMG_OK) {
      printf("  subset %u/4 failed: %s\n", q, res.error);
      fr[q - 1] = ts[q - 1] = 0;
      continue;
    }
    t = now() - t;
    fr[q - 1] = res.stats.source_frames;
    ts[q - 1] = cpu;
    printf("    %2u manifest clips %6u frames: %.3f s wall, %.3f s CPU\n", n,
           res.stats.source_frames, t, cpu);
    smg_bake_result_free(&res);
  }
  if (fr[0] > 0 && fr[3] > fr[0] && ts[0] > 0)
    printf("  CPU time grows as frames^%.2f (the distance grids are "
           "quadratic; import and output linear)\n",
           log(ts[3] / ts[0]) / log(fr[3] / fr[0]));
  free_set(&s);
}

int main(void) {
  const char* shared = getenv("SMG_SHARED");
  char dir[1024], probe[1100];
  FILE* fp;
  if (!shared || !*shared) shared = SMG_SHARED_DIR;
  snprintf(dir, sizeof dir, "%s/mocap/cmu", shared);
  snprintf(probe, sizeof probe, "%s/09_12.bvh", dir);
  grid_baseline();
  fp = fopen(probe, "rb");
  if (!fp) {
    printf("SKIP: CMU clips not found in %s (set SMG_SHARED); the paper-set "
           "and all-clip figures need them\n", dir);
    return 0;
  }
  fclose(fp);
  paper_set(dir);
  retarget_cost(dir);
  all_clips(dir);
  return 0;
}
