/*
 * bench_runtime.c - `make bench-runtime`: what a libsmg character costs.
 *
 * Baseline (same run, same skeleton, same machine): plain playback of one
 * clip - sample two pool frames (decoding their packed rotations like the
 * runtime does), lerp the root, nlerp every rotation and
 * run forward kinematics to model matrices - the least any animation
 * system does per character per frame. Measured against it:
 *   - steady-state smg_character_step + smg_character_get_model_matrices
 *     per character (median, one core), target <= 5 us;
 *   - the frame in which the path is replaced (10^3 and 10^5 points), p99,
 *     target <= 1 ms;
 *   - blob load (smg_graph_load_memory, full checksum), median, target
 *     <= 1 ms;
 *   - per-character memory with the default desc, its 512-point path
 *     buffer included (target <= 16 KiB);
 *   - characters per 60 Hz frame for 1, 100, 1000 and 5000 characters;
 *   - what root steering costs: 1000 characters with it on against 1000
 *     with it off, in alternating frames (target: on/off <= 1.25x, which
 *     is <= 2.5 us per character on the CMU graph on a quiet machine).
 * Graphs: build/default.smg (synthetic, baked by `make`) when present,
 * blobs named on the command line, and the small test fixture graph.
 * With `--ref BLOB` (make bench-runtime: the CMU graph) every other blob
 * named is also compared with that one: crowds of 1 to 5000 on both
 * graphs stepped in alternating frames, medians and their ratio (the big
 * graph of the scale set, issue 25: target <= 1.3x).
 * Per-frame costs are thread CPU time (clock_gettime THREAD_CPUTIME), so
 * other processes on a shared machine do not inflate them; the edit frame
 * and blob load also print wall time. Figures only; nothing here passes or
 * fails.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "blob.h"
#include "fixture_graph.h"
#include "graph_data.h"
#include "smg.h"

#define DT (1.0f / 60.0f)
/* Steps before timing starts: 5 s of motion. New characters spend their
 * first seconds converging onto their paths (starting node chosen by seed,
 * plans re-made while off the path), which costs the planner about 50 %
 * more than following does; the figures are for characters that follow. */
#define WARM_FRAMES 300

static double now_us(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e6 + (double)ts.tv_nsec * 1e-3;
}

/* CPU time of this thread: unlike wall time it excludes the slices the
 * scheduler gives to other processes, which on a loaded machine otherwise
 * dominate every p99 (4 ms scheduler ticks). */
static double cpu_us(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec * 1e6 + (double)ts.tv_nsec * 1e-3;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static double percentile(double* v, size_t n, double p) {
  qsort(v, n, sizeof *v, cmp_double);
  size_t i = (size_t)(p * (double)(n - 1) + 0.5);
  return v[i < n ? i : n - 1];
}

/* ---- baseline: plain clip playback ---------------------------------- */

static void nlerp(const float* a, const float* b, float t, float* o) {
  float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  float s = d < 0 ? -t : t, u = 1 - t;
  for (int k = 0; k < 4; ++k) o[k] = u * a[k] + s * b[k];
  float n = 1.0f / sqrtf(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
  for (int k = 0; k < 4; ++k) o[k] *= n;
}

static void mat_from(const float* q, const float* t, float* m) {
  float x = q[0], y = q[1], z = q[2], w = q[3];
  m[0] = 1 - 2 * (y * y + z * z); m[1] = 2 * (x * y + z * w);
  m[2] = 2 * (x * z - y * w);     m[3] = 0;
  m[4] = 2 * (x * y - z * w);     m[5] = 1 - 2 * (x * x + z * z);
  m[6] = 2 * (y * z + x * w);     m[7] = 0;
  m[8] = 2 * (x * z + y * w);     m[9] = 2 * (y * z - x * w);
  m[10] = 1 - 2 * (x * x + y * y); m[11] = 0;
  m[12] = t[0]; m[13] = t[1]; m[14] = t[2]; m[15] = 1;
}

static void mat_mul(const float* a, const float* b, float* o) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      o[4 * c + r] = a[r] * b[4 * c] + a[4 + r] * b[4 * c + 1] +
                     a[8 + r] * b[4 * c + 2] + a[12 + r] * b[4 * c + 3];
}

typedef struct player {
  double t; /* frames */
  uint32_t clip;
  float root[3], rot[4 * 64], mats[16 * 64];
} player;

/* One frame of plain playback of clip 0 (looping). */
static void baseline_step(const smg_graph* g, player* p, float dt) {
  const smgi_clip* clip = &g->data.clips[p->clip];
  const uint32_t J = g->data.joint_count;
  p->t += (double)dt * g->data.info->frame_rate;
  double len = clip->frame_count > 1 ? clip->frame_count - 1 : 1;
  while (p->t >= len) p->t -= len;
  uint32_t i0 = (uint32_t)p->t;
  float a = (float)(p->t - i0);
  uint32_t i1 = i0 + 1 < clip->frame_count ? i0 + 1 : i0;
  const unsigned char* fa = smgi_graph_pose(g, clip->first_frame + i0);
  const unsigned char* fb = smgi_graph_pose(g, clip->first_frame + i1);
  float ra[3], rb[3];
  smgi_pose_root(fa, ra);
  smgi_pose_root(fb, rb);
  for (int k = 0; k < 3; ++k) p->root[k] = ra[k] + a * (rb[k] - ra[k]);
  /* the same data as the characters read, decoded by the runtime's own
   * sampler (packed rotations straight into the nlerp, four joints at a
   * time); it leaves the root joint to the caller */
  {
    float qa[4], qb[4];
    smgi_quat_unpack_raw(smgi_pose_rot(fa, 0), qa);
    smgi_quat_unpack_raw(smgi_pose_rot(fb, 0), qb);
    nlerp(qa, qb, a, p->rot);
  }
  smgi_sample_joints(g, fa, fb, a, SMGI_JOINTS_ALL, p->rot);
  mat_from(p->rot, p->root, p->mats);
  for (uint32_t j = 1; j < J; ++j) {
    float local[16];
    mat_from(p->rot + 4 * j, g->data.joints[j].offset, local);
    mat_mul(p->mats + 16 * g->data.joints[j].parent, local, p->mats + 16 * j);
  }
}

static volatile float sink;

/* Median per-call time of the baseline, microseconds. */
static double bench_baseline(const smg_graph* g, int frames) {
  player* p = (player*)calloc(1, sizeof *p);
  double* v = (double*)malloc(sizeof(double) * (size_t)frames);
  const int batch = 64;
  for (int i = 0; i < frames; ++i) {
    double t0 = cpu_us();
    for (int b = 0; b < batch; ++b) baseline_step(g, p, DT);
    v[i] = (cpu_us() - t0) / batch;
    sink += p->mats[16 * 5 + 12];
  }
  double m = percentile(v, (size_t)frames, 0.5);
  free(v);
  free(p);
  return m;
}

/* Median per-player time of a frame of N plain players (different clips
 * and times, each with its own buffers), the baseline at the same crowd
 * size so cache effects are compared like with like. */
static double bench_baseline_crowd(const smg_graph* g, int n, int frames) {
  player* p = (player*)calloc((size_t)n, sizeof *p);
  double* v = (double*)malloc(sizeof(double) * (size_t)frames);
  /* each player its own clip (among those with frames) and time, so the
   * pose pool is touched as widely as by characters on a graph */
  uint32_t nclips = 0;
  for (uint32_t k = 0; k < g->data.clip_count; ++k)
    if (g->data.clips[k].frame_count > 1) ++nclips;
  for (int i = 0; i < n; ++i) {
    p[i].t = (double)(i % 97) * 0.37;
    uint32_t want = nclips ? (uint32_t)i % nclips : 0, k = 0;
    for (; k < g->data.clip_count; ++k)
      if (g->data.clips[k].frame_count > 1 && want-- == 0) break;
    p[i].clip = k < g->data.clip_count ? k : 0;
  }
  for (int f = 0; f < frames; ++f) {
    double t0 = cpu_us();
    for (int i = 0; i < n; ++i) baseline_step(g, &p[i], DT);
    v[f] = (cpu_us() - t0) / n;
    sink += p[0].mats[12];
  }
  double m = percentile(v, (size_t)frames, 0.5);
  free(v);
  free(p);
  return m;
}

/* ---- characters ----------------------------------------------------- */

/* A long gently curving path starting at (x0, 0), npoints over length. */
static void make_path(float* xz, uint32_t n, float length, float x0,
                      float wiggle) {
  for (uint32_t i = 0; i < n; ++i) {
    float z = length * (float)i / (float)(n - 1);
    xz[2 * i] = x0 + wiggle * sinf(z * 0.15f);
    xz[2 * i + 1] = z;
  }
}

typedef struct crowd {
  smg_character** ch;
  int n;
  float* mats;
  uint32_t J;
} crowd;

static int crowd_make(smg_graph* g, int n, uint32_t flags, crowd* c) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_graph_get_info(g, &info);
  c->J = info.joint_count;
  c->n = n;
  c->ch = (smg_character**)calloc((size_t)n, sizeof *c->ch);
  c->mats = (float*)malloc(sizeof(float) * 16 * c->J);
  float xz[2 * 256];
  for (int i = 0; i < n; ++i) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.seed = (uint32_t)i + 1;
    d.flags = flags;
    d.position[0] = 2.0f * (float)(i % 100);
    if (smg_character_create(g, &d, &c->ch[i]) != SMG_OK) return 0;
    make_path(xz, 256, 2000.0f, d.position[0], 1.0f + (float)(i % 5));
    smg_character_set_path(c->ch[i], xz, 256);
  }
  return 1;
}

static void crowd_free(crowd* c) {
  for (int i = 0; i < c->n; ++i)
    if (c->ch[i]) smg_character_destroy(c->ch[i]);
  free(c->ch);
  free(c->mats);
}

/* One frame for every character: step + model matrices. */
static void crowd_frame(crowd* c) {
  for (int i = 0; i < c->n; ++i) {
    smg_character_step(c->ch[i], DT);
    smg_character_get_model_matrices(c->ch[i], SMG_SPACE_WORLD, c->mats, c->J);
  }
  sink += c->mats[12];
}

/* Median of per-character step+pose, timed one call at a time in batches
 * of the whole crowd (so cache effects of many characters show). */
static double bench_crowd(smg_graph* g, int n, uint32_t flags, int frames,
                          double* p99, double* mean, double* start_mean,
                          double* start_worst) {
  crowd c;
  if (!crowd_make(g, n, flags, &c)) {
    crowd_free(&c);
    return -1;
  }
  /* the warm-up's first 2 s (characters converging onto their paths) are
   * reported on their own */
  double start_sum = 0;
  *start_worst = 0;
  for (int f = 0; f < 120; ++f) {
    double t0 = cpu_us();
    crowd_frame(&c);
    double t = (cpu_us() - t0) / n;
    start_sum += t;
    if (t > *start_worst) *start_worst = t;
  }
  *start_mean = start_sum / 120.0;
  for (int f = 120; f < WARM_FRAMES; ++f) crowd_frame(&c);
  double* v = (double*)malloc(sizeof(double) * (size_t)frames);
  for (int f = 0; f < frames; ++f) {
    double t0 = cpu_us();
    crowd_frame(&c);
    v[f] = (cpu_us() - t0) / n;
  }
  double sum = 0;
  for (int f = 0; f < frames; ++f) sum += v[f];
  *mean = sum / frames;
  double m = percentile(v, (size_t)frames, 0.5);
  if (p99) *p99 = percentile(v, (size_t)frames, 0.99);
  free(v);
  crowd_free(&c);
  return m;
}

/* Two crowds of n - graph ga with character flags fa, graph gb with fb -
 * stepped in alternating frames after the same warm-up, so load from
 * other processes falls on both alike (timed one after the other, the two
 * medians moved by 30 % between runs on a shared machine). Medians of the
 * per-character frame time of each, and of the ratio a/b of the frames of
 * each pair. */
static int bench_pair(smg_graph* ga, uint32_t fa, smg_graph* gb, uint32_t fb,
                      int n, int frames, double* on, double* off,
                      double* ratio) {
  crowd a, b;
  int ok_a = crowd_make(ga, n, fa, &a);
  int ok_b = ok_a && crowd_make(gb, n, fb, &b);
  if (!ok_a || !ok_b) {
    crowd_free(&a);
    if (ok_a) crowd_free(&b);
    return 0;
  }
  for (int f = 0; f < WARM_FRAMES; ++f) {
    crowd_frame(&a);
    crowd_frame(&b);
  }
  double* va = (double*)malloc(sizeof(double) * (size_t)frames * 3);
  double* vb = va + frames;
  double* vr = vb + frames;
  for (int f = 0; f < frames; ++f) {
    /* which crowd goes first alternates too */
    crowd* first = (f & 1) ? &b : &a;
    crowd* second = (f & 1) ? &a : &b;
    double t0 = cpu_us();
    crowd_frame(first);
    double t1 = cpu_us();
    crowd_frame(second);
    double t2 = cpu_us();
    va[f] = ((f & 1) ? t2 - t1 : t1 - t0) / n;
    vb[f] = ((f & 1) ? t1 - t0 : t2 - t1) / n;
    vr[f] = va[f] / vb[f];
  }
  *ratio = percentile(vr, (size_t)frames, 0.5);
  *on = percentile(va, (size_t)frames, 0.5);
  *off = percentile(vb, (size_t)frames, 0.5);
  free(va);
  crowd_free(&a);
  crowd_free(&b);
  return 1;
}

/* What root steering costs: n characters with it on against n with it
 * off on the same graph. */
static int bench_steer_pair(smg_graph* g, int n, int frames, double* on,
                            double* off, double* ratio) {
  return bench_pair(g, 0u, g, SMG_CHARACTER_NO_STEERING, n, frames, on, off,
                    ratio);
}

/* Single character, each frame timed on its own. */
static double bench_single(smg_graph* g, int frames, double* p99) {
  *p99 = -1;
  crowd c;
  if (!crowd_make(g, 1, 0u, &c)) {
    crowd_free(&c);
    return -1;
  }
  for (int f = 0; f < WARM_FRAMES; ++f) crowd_frame(&c);
  double* v = (double*)malloc(sizeof(double) * (size_t)frames);
  for (int f = 0; f < frames; ++f) {
    double t0 = cpu_us();
    crowd_frame(&c);
    v[f] = cpu_us() - t0;
  }
  double m = percentile(v, (size_t)frames, 0.5);
  *p99 = percentile(v, (size_t)frames, 0.99);
  free(v);
  crowd_free(&c);
  return m;
}

/* Frame in which the whole path is replaced (set_path + step + pose). */
static void bench_edit(smg_graph* g, uint32_t points, int frames,
                       double* median, double* p99, double* cpu_p99) {
  smg_character_desc d;
  smg_character* ch = NULL;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = points;
  float* a = (float*)malloc(sizeof(float) * 2 * points);
  float* b = (float*)malloc(sizeof(float) * 2 * points);
  make_path(a, points, 1000.0f, 0.0f, 1.0f);
  make_path(b, points, 1000.0f, 0.3f, 2.0f);
  float* mats = (float*)malloc(sizeof(float) * 16 * 64);
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_graph_get_info(g, &info);
  double* v = (double*)malloc(sizeof(double) * (size_t)frames);
  double* vc = (double*)malloc(sizeof(double) * (size_t)frames);
  *median = *p99 = *cpu_p99 = -1;
  if (smg_character_create(g, &d, &ch) == SMG_OK) {
    smg_character_set_path(ch, a, points);
    for (int f = 0; f < 60; ++f) smg_character_step(ch, DT);
    for (int f = 0; f < frames; ++f) {
      double t0 = now_us(), c0 = cpu_us();
      smg_character_set_path(ch, (f & 1) ? a : b, points);
      smg_character_step(ch, DT);
      smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                       info.joint_count);
      vc[f] = cpu_us() - c0;
      v[f] = now_us() - t0;
      /* a few ordinary frames between edits */
      for (int k = 0; k < 3; ++k) smg_character_step(ch, DT);
    }
    *median = percentile(v, (size_t)frames, 0.5);
    *p99 = percentile(v, (size_t)frames, 0.99);
    *cpu_p99 = percentile(vc, (size_t)frames, 0.99);
    smg_character_destroy(ch);
  }
  free(v);
  free(vc);
  free(mats);
  free(a);
  free(b);
}

static double bench_load(const void* blob, size_t size, int reps,
                         uint32_t flags) {
  double* v = (double*)malloc(sizeof(double) * (size_t)reps);
  smg_graph_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.flags = flags;
  for (int i = 0; i < reps; ++i) {
    smg_graph* g = NULL;
    double t0 = now_us();
    smg_result r = smg_graph_load_memory(blob, size, &d, &g);
    v[i] = now_us() - t0;
    if (r == SMG_OK) smg_graph_destroy(g);
  }
  double m = percentile(v, (size_t)reps, 0.5);
  free(v);
  return m;
}

static void* read_file(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  void* p = NULL;
  if (n > 0 && posix_memalign(&p, 64, (size_t)n) == 0 &&
      fread(p, 1, (size_t)n, f) != (size_t)n) {
    free(p);
    p = NULL;
  }
  fclose(f);
  *size = (size_t)n;
  return p;
}

static void run_graph(const char* name, const void* blob, size_t size) {
  smg_graph* g = NULL;
  smg_result r = smg_graph_load_memory(blob, size, NULL, &g);
  if (r != SMG_OK) {
    printf("%s: cannot load (%s)\n", name, smg_result_string(r));
    return;
  }
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_graph_get_info(g, &info);
  printf("\n== %s: %u joints, %u frames, lower %u nodes/%u edges, upper "
         "%u/%u, %u splices, %.0f KiB ==\n",
         name, info.joint_count, info.frame_count, info.lower_node_count,
         info.lower_edge_count, info.upper_node_count, info.upper_edge_count,
         info.splice_count, (double)info.blob_size / 1024.0);

  double base = bench_baseline(g, 2000);
  printf("baseline plain clip playback (2 frames + lerp/nlerp + FK): "
         "median %.3f us\n",
         base);
  double p99_single = 0;
  double single = bench_single(g, 6000, &p99_single);
  printf("step+pose, 1 character:   median %.3f us  p99 %.3f us  (%.1fx "
         "baseline; target <= 5 us)\n",
         single, p99_single, single / base);
  const int counts[4] = {1, 100, 1000, 5000};
  for (int i = 0; i < 4; ++i) {
    int frames = counts[i] >= 1000 ? 60 : 600;
    double p99, mean, start, start_worst;
    double per = bench_crowd(g, counts[i], 0u, frames, &p99, &mean, &start,
                             &start_worst);
    if (per < 0) {
      printf("crowd of %d: create failed\n", counts[i]);
      continue;
    }
    double bc = bench_baseline_crowd(g, counts[i], frames);
    /* per frame: the crowd's CPU time / n; the worst frame (p99) is
     * what a game's frame budget has to hold */
    printf("step+pose, %4d characters: median %.3f us/character (mean %.3f, "
           "p99 frame %.3f; first 2 s after spawning: mean %.3f, worst frame "
           "%.3f), plain playback %.3f us (%.1fx) -> %.0f characters per 60 "
           "Hz frame on one core\n",
           counts[i], per, mean, p99, start, start_worst, bc, per / bc,
           (1e6 / 60.0) / per);
  }
  {
    /* the same 1000 characters with the root steering off (the motion
     * graph alone): what steering costs, measured in this run */
    double on, off, ratio;
    if (bench_steer_pair(g, 1000, 120, &on, &off, &ratio))
      printf("step+pose, 1000 characters, steering on vs off in alternating "
             "frames: on %.3f us/character, off %.3f us, on/off %.2fx "
             "(target <= 1.25x; on <= 2.5 us on the CMU graph)\n",
             on, off, ratio);
  }
  double med = 0, p99 = 0, cpu99 = 0;
  bench_edit(g, 1000, 400, &med, &p99, &cpu99);
  printf("edit frame (set_path 10^3 points + step + pose): median %.1f us, "
         "p99 %.1f us wall, %.1f us CPU (target p99 <= 1000 us)\n",
         med, p99, cpu99);
  bench_edit(g, 100000, 200, &med, &p99, &cpu99);
  printf("edit frame (set_path 10^5 points + step + pose): median %.1f us, "
         "p99 %.1f us wall, %.1f us CPU (target p99 <= 1000 us)\n",
         med, p99, cpu99);
  {
    /* a big graph (hundreds of MB) loads in a tenth of a second or more:
     * fewer repetitions */
    const int reps = size > ((size_t)64 << 20) ? 11 : 100;
    printf("blob load from memory (full checksum): median %.1f us; "
           "without checksum %.1f us (target <= 1000 us; big graphs <= "
           "100000 us)\n",
           bench_load(blob, size, reps, 0),
           bench_load(blob, size, reps, SMG_GRAPH_SKIP_CHECKSUM));
  }
  /* the default desc, its default path buffer included; the share
   * without the path from a 16-point buffer (12 bytes a point, 16-byte
   * aligned: exact) */
  size_t bytes = 0, small = 0;
  smg_character_desc md;
  memset(&md, 0, sizeof md);
  md.struct_size = sizeof md;
  md.path_capacity = 16;
  smg_character_memory_size(g, NULL, &bytes);
  smg_character_memory_size(g, &md, &small);
  size_t no_path = small - 16u * 12u;
  printf("per-character memory (default desc): %zu bytes, of which the "
         "%zu-point path buffer %zu; %zu bytes without it (target <= "
         "16384)\n",
         bytes, (bytes - no_path) / 12u, bytes - no_path, no_path);
  smg_graph_destroy(g);
}

/* Step+pose per character on graph `name` against the reference graph,
 * crowds of both stepped in alternating frames (bench_pair): medians and
 * the median ratio per crowd size. */
static void compare_graphs(const char* name, const void* blob, size_t size,
                           const char* ref_name, const void* ref_blob,
                           size_t ref_size) {
  smg_graph *g = NULL, *ref = NULL;
  if (smg_graph_load_memory(blob, size, NULL, &g) != SMG_OK ||
      smg_graph_load_memory(ref_blob, ref_size, NULL, &ref) != SMG_OK) {
    printf("%s vs %s: cannot load\n", name, ref_name);
    if (g) smg_graph_destroy(g);
    return;
  }
  printf("\n== %s vs %s (reference): step+pose per character, crowds on "
         "both graphs in alternating frames (target <= 1.3x) ==\n",
         name, ref_name);
  const int counts[4] = {1, 100, 1000, 5000};
  const int frames[4] = {3000, 600, 120, 60};
  for (int i = 0; i < 4; ++i) {
    double a, b, ratio;
    if (!bench_pair(g, 0u, ref, 0u, counts[i], frames[i], &a, &b, &ratio)) {
      printf("crowd of %d: create failed\n", counts[i]);
      continue;
    }
    printf("%4d characters: %.3f us on this graph, %.3f us on the "
           "reference, ratio %.2fx\n",
           counts[i], a, b, ratio);
  }
  smg_graph_destroy(g);
  smg_graph_destroy(ref);
}

int main(int argc, char** argv) {
  printf("libsmg runtime benchmark (one core, dt = 1/60 s, medians of "
         "thread CPU time unless marked wall; crowds timed after %d steps "
         "of warm-up)\n",
         WARM_FRAMES);
  char path[1024];
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  size_t size = 0;
  void* blob = read_file(path, &size);
  if (blob) {
    run_graph("build/default.smg (synthetic)", blob, size);
    free(blob);
  } else {
    printf("(%s not found: run `make` to bake it)\n", path);
  }
  /* further blobs named on the command line, e.g. a CMU bake; the one
   * after --ref is also the reference the others are compared with */
  const char* ref_name = NULL;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--ref") && i + 1 < argc) {
      ref_name = argv[++i];
    }
    blob = read_file(argv[i], &size);
    if (!blob) {
      printf("(%s not readable, skipped)\n", argv[i]);
      continue;
    }
    run_graph(argv[i], blob, size);
    free(blob);
  }
  void* fb = NULL;
  size_t fsize = 0;
  if (fixture_graph_blob(&fb, &fsize) == SMG_OK) {
    run_graph("test fixture graph", fb, fsize);
    smgi_blob_free(fb, NULL);
  }
  size_t ref_size = 0;
  void* ref_blob = ref_name ? read_file(ref_name, &ref_size) : NULL;
  for (int i = 1; ref_blob && i < argc; ++i) {
    if (!strcmp(argv[i], "--ref")) {
      ++i;
      continue;
    }
    blob = read_file(argv[i], &size);
    if (!blob) continue;
    compare_graphs(argv[i], blob, size, ref_name, ref_blob, ref_size);
    free(blob);
  }
  free(ref_blob);
  return 0;
}
