/*
 * soak_timing.c - the soak's step-time flatness measurement: reference
 * characters replayed from saved memory, interleaved with the soak's
 * steps; per-frame ratios; window quantiles (see soak_timing.h).
 */
#include "soak_timing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The quantile of the per-frame ratio compared between the windows. */
#define SOAK_TIMING_QUANTILE 0.25
#define SOAK_REF_PATH_POINTS 80 /* 1 m apart: longer than a warm-up and a
                                   cycle at the fastest speeds */
#define SOAK_REF_DT (1.0f / 60.0f)
/* Where each reference starts in its cycle: k x 49 (mod 120). 49 is prime
 * to the cycle, so up to 120 references are at different points of it,
 * and the ones stepped together (consecutive k) are spread over it:
 * every group's reference work is about the same. (With references at
 * neighbouring points, reference work followed the cycle's re-plans and
 * the two windows compared saw different parts of it: 4-5 % apart by
 * that alone.) */
#define SOAK_REF_STRIDE 49u

double soak_cpu_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The reference characters' allocator remembers every block, so their
 * whole state can be saved and restored in place. */
static void* replay_alloc(size_t size, size_t align, void* user) {
  soak_replay* r = (soak_replay*)user;
  void* p = NULL;
  if (r->blocks == SOAK_REF_BLOCKS) return NULL;
  if (align < sizeof(void*)) align = sizeof(void*);
  if (posix_memalign(&p, align, size ? size : 1) != 0) return NULL;
  r->block[r->blocks] = p;
  r->size[r->blocks++] = size;
  return p;
}

static void replay_free(void* p, void* user) {
  (void)user;
  free(p);
}

/* Reference k: every style and action in turn, foot IK off for one in
 * four (as in the soak), a path turning 0.04 rad/m (steering works, as on
 * the soak's paths); warmed up 1 s and saved, then stepped k x
 * SOAK_REF_STRIDE steps (mod the cycle) into its cycle. */
static int replay_init(soak_replay* r, smg_graph* graph,
                       const smg_graph_info* info, uint32_t k) {
  float xz[2 * SOAK_REF_PATH_POINTS], x = 0.0f, z = 0.0f, h;
  smg_character_desc d;
  uint32_t i, b;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = 1000u + k;
  d.initial_style = k % info->style_count;
  d.initial_action = k / info->style_count % info->action_count;
  if (k % 4 == 3) d.flags = SMG_CHARACTER_NO_IK;
  d.heading = h = 0.6f * (float)k;
  d.allocator.alloc = replay_alloc;
  d.allocator.free = replay_free;
  d.allocator.user = r;
  for (i = 0; i < SOAK_REF_PATH_POINTS; ++i) {
    xz[2 * i] = x;
    xz[2 * i + 1] = z;
    x += sinf(h);
    z += cosf(h);
    h += 0.04f;
  }
  if (smg_character_create(graph, &d, &r->ch) != SMG_OK ||
      smg_character_set_path(r->ch, xz, SOAK_REF_PATH_POINTS) != SMG_OK)
    return 0;
  for (i = 0; i < 60; ++i)
    if (smg_character_step(r->ch, SOAK_REF_DT) != SMG_OK) return 0;
  for (b = 0; b < r->blocks; ++b) {
    r->saved[b] = (unsigned char*)malloc(r->size[b] ? r->size[b] : 1);
    r->cycle_end[b] = (unsigned char*)malloc(r->size[b] ? r->size[b] : 1);
    if (!r->saved[b] || !r->cycle_end[b]) return 0;
    memcpy(r->saved[b], r->block[b], r->size[b]);
  }
  for (r->at = 0; r->at < k * SOAK_REF_STRIDE % SOAK_REF_CYCLE; ++r->at)
    if (smg_character_step(r->ch, SOAK_REF_DT) != SMG_OK) return 0;
  return 1;
}

int soak_timing_init(soak_timing* t, smg_graph* graph,
                     const smg_graph_info* info, uint32_t refs,
                     uint32_t frames) {
  uint32_t k;
  memset(t, 0, sizeof *t);
  t->frames = frames;
  t->step_seconds = (double*)calloc(frames, sizeof(double));
  t->ref_seconds = (double*)calloc(frames, sizeof(double));
  t->ref = (soak_replay*)calloc(refs, sizeof *t->ref);
  if (!t->step_seconds || !t->ref_seconds || !t->ref) {
    fprintf(stderr, "soak: out of memory for the timing\n");
    return 0;
  }
  t->refs = refs;
  for (k = 0; k < refs; ++k)
    if (!replay_init(&t->ref[k], graph, info, k)) {
      fprintf(stderr, "soak: cannot set up reference character %u\n", k);
      return 0;
    }
  return 1;
}

/* At the end of its cycle, a reference is checked and restored. */
static void rewind_if_due(soak_timing* t, soak_replay* r) {
  uint32_t b;
  int same = 1;
  if (r->at < SOAK_REF_CYCLE) return;
  for (b = 0; b < r->blocks; ++b) {
    if (!r->has_cycled)
      memcpy(r->cycle_end[b], r->block[b], r->size[b]);
    else if (memcmp(r->cycle_end[b], r->block[b], r->size[b]) != 0)
      same = 0;
    memcpy(r->block[b], r->saved[b], r->size[b]);
  }
  if (!same) t->diverged++;
  r->has_cycled = 1;
  r->at = 0;
}

double soak_timing_reference_steps(soak_timing* t, uint32_t n) {
  const uint32_t first = t->next;
  double c0, c1;
  uint32_t i;
  if (n > t->refs) n = t->refs;
  for (i = 0; i < n; ++i) rewind_if_due(t, &t->ref[(first + i) % t->refs]);
  c0 = soak_cpu_seconds();
  for (i = 0; i < n; ++i) {
    soak_replay* r = &t->ref[(first + i) % t->refs];
    smg_character_step(r->ch, SOAK_REF_DT);
    r->at++;
  }
  c1 = soak_cpu_seconds();
  t->next = (first + n) % t->refs;
  return c1 - c0;
}

void soak_timing_record(soak_timing* t, uint32_t frame, double step,
                        double ref) {
  if (frame >= t->frames) return;
  t->step_seconds[frame] = step;
  t->ref_seconds[frame] = ref;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* SOAK_TIMING_QUANTILE of step / ref over frames [from, from + n). */
static double window_quantile(const soak_timing* t, uint32_t from,
                              uint32_t n) {
  double* v = (double*)malloc(sizeof(double) * (n ? n : 1));
  double q = 0.0;
  uint32_t i, m = 0;
  if (!v) return 0.0;
  for (i = from; i < from + n; ++i)
    if (t->ref_seconds[i] > 0.0)
      v[m++] = t->step_seconds[i] / t->ref_seconds[i];
  if (m) {
    qsort(v, m, sizeof *v, cmp_double);
    q = v[(uint32_t)(SOAK_TIMING_QUANTILE * (double)(m - 1) + 0.5)];
  }
  free(v);
  return q;
}

void soak_timing_windows(const soak_timing* t, double* first, double* last) {
  uint32_t tenth = t->frames / 10 ? t->frames / 10 : 1;
  *first = window_quantile(t, 0, tenth);
  *last = window_quantile(t, t->frames - tenth, tenth);
}

void soak_timing_free(soak_timing* t) {
  uint32_t k, b;
  for (k = 0; t->ref && k < t->refs; ++k) {
    soak_replay* r = &t->ref[k];
    if (r->ch) smg_character_destroy(r->ch);
    for (b = 0; b < r->blocks; ++b) {
      free(r->saved[b]);
      free(r->cycle_end[b]);
    }
  }
  free(t->ref);
  free(t->step_seconds);
  free(t->ref_seconds);
  memset(t, 0, sizeof *t);
}
