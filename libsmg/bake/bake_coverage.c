/*
 * bake_coverage.c - clips whose motion kept clips already cover
 * (bake_coverage.h).
 *
 * Nearness: a window's features are its point cloud at 3 of its k steps,
 * each point scaled by sqrt(w_p) (bake_pair_search.h), so the squared
 * feature distance of two windows is about 3 / k of their windowed
 * distance D, and a radius r in RMS metres, sqrt(D / (k sum w)), is a
 * squared feature distance of 3 r^2 sum w. The principal axes drop part
 * of the distance, so the feature test is a little generous.
 *
 * Kept windows are found in a kd-tree rebuilt whenever PENDING_MAX
 * windows have been kept since the last build, and among those by a plain
 * scan: the greedy order needs the kept set as it grows, and the kept set
 * of a library with much repetition grows far slower than the data.
 */
#include "bake_coverage.h"

#include <stdlib.h>
#include <string.h>

#include "bake_kdtree.h"
#include "bake_options.h"
#include "bake_pair_search.h"
#include "bake_threads.h"
#include "smg_format.h"

#define PENDING_MAX 1024u

typedef struct label_state {
  const smgb_coverage_job* job;
  const float* feat;
  uint32_t dims;
  uint8_t* covered;
  uint32_t* labels;            /* labels this worker decides */
  uint32_t label_count;
  int failed;
} label_state;

/* Is window w within r2 of a kept window (tree or pending)? */
static int near_kept(const smgb_kd_tree* t, const uint32_t* kept,
                     uint32_t pending_from, uint32_t kept_count,
                     const float* feat, uint32_t d, uint32_t w, float r2) {
  const float* q = feat + (size_t)w * d;
  uint32_t i;
  if (smgb_kd_any_within(t, feat, d, q, r2)) return 1;
  for (i = pending_from; i < kept_count; ++i)
    if (smgb_kd_within(feat + (size_t)kept[i] * d, q, d, r2)) return 1;
  return 0;
}

static int decide_label(label_state* s, uint32_t l) {
  const smgb_coverage_job* job = s->job;
  const uint8_t* valid = job->cloud->valid;
  uint32_t c, f, d = s->dims, kept_count = 0, kept_cap = 0, built = 0;
  uint32_t* kept = NULL;
  double wsum = 0.0;
  float r2;
  smgb_kd_tree t;
  uint32_t p;
  for (p = 0; p < job->cloud->points; ++p) wsum += job->cloud->weights[p];
  r2 = (float)(3.0 * wsum * (double)job->radius[l] * job->radius[l]);
  memset(&t, 0, sizeof t);
  for (c = 0; c < job->clip_count; ++c) {
    uint32_t first = job->clip_first[c], n = job->clip_frames[c], windows = 0;
    int cover = 1;
    if (first == SMGI_NONE || job->clip_label[c] != l) continue;
    for (f = first; f < first + n; ++f) {
      if (!valid[f]) continue;
      ++windows;
      if (kept_count == 0 ||
          !near_kept(&t, kept, built, kept_count, s->feat, d, f, r2)) {
        cover = 0; /* the first window nothing covers decides */
        break;
      }
    }
    if (windows == 0) continue; /* no window: nothing to decide */
    if (cover) {
      s->covered[c] = 1;
      continue;
    }
    for (f = first; f < first + n; ++f) {
      if (!valid[f]) continue;
      if (kept_count == kept_cap) {
        uint32_t cap = kept_cap ? kept_cap * 2u : 4096u;
        uint32_t* k2 = realloc(kept, cap * sizeof *k2);
        if (!k2) goto oom;
        kept = k2;
        kept_cap = cap;
      }
      kept[kept_count++] = f;
    }
    if (kept_count - built > PENDING_MAX) {
      uint32_t* idx = realloc(t.idx, kept_count * sizeof *idx);
      if (!idx) goto oom;
      t.idx = idx;
      memcpy(t.idx, kept, kept_count * sizeof *idx);
      t.n = kept_count;
      if (!smgb_kd_build(&t, s->feat, d)) goto oom;
      built = kept_count;
    }
  }
  smgb_kd_free(&t);
  free(kept);
  return 1;
oom:
  smgb_kd_free(&t);
  free(kept);
  return 0;
}

static void* worker_run(void* arg) {
  label_state* s = arg;
  uint32_t i;
  for (i = 0; i < s->label_count && !s->failed; ++i)
    if (!decide_label(s, s->labels[i])) s->failed = 1;
  return NULL;
}

smg_result smgb_cover_clips(const smgb_coverage_job* job, uint8_t* covered) {
  smgb_pair_search fj;
  label_state ws[SMGB_MAX_THREADS];
  float* feat = NULL;
  uint32_t dims = 0, nt = job->threads ? job->threads : 1u, t, l, c;
  uint32_t* order = NULL;
  uint64_t* size = NULL;
  uint64_t load[SMGB_MAX_THREADS];
  smg_result r;
  memset(covered, 0, job->clip_count);
  if (job->cloud->frames == 0 || job->label_count == 0) return SMG_OK;
  memset(&fj, 0, sizeof fj);
  fj.rows = fj.cols = job->cloud;
  fj.row_heading = fj.col_heading = job->heading;
  fj.window = job->window;
  fj.align = 1;
  r = smgb_pair_features(&fj, &feat, &dims);
  if (r != SMG_OK) return r;
  if (nt > SMGB_MAX_THREADS) nt = SMGB_MAX_THREADS;
  order = malloc(job->label_count * sizeof *order);
  size = calloc(job->label_count, sizeof *size);
  memset(ws, 0, sizeof ws);
  for (t = 0; t < nt; ++t) {
    ws[t].labels = malloc(job->label_count * sizeof *ws[t].labels);
    if (!ws[t].labels) r = SMG_ERROR_OUT_OF_MEMORY;
  }
  if (!order || !size || r != SMG_OK) {
    r = SMG_ERROR_OUT_OF_MEMORY;
    goto done;
  }
  /* labels to workers, biggest first onto the least loaded (the split
   * only balances the work: every label is decided alone) */
  for (c = 0; c < job->clip_count; ++c)
    if (job->clip_first[c] != SMGI_NONE &&
        job->clip_label[c] < job->label_count)
      size[job->clip_label[c]] += job->clip_frames[c];
  for (l = 0; l < job->label_count; ++l) {
    uint32_t i = l;
    while (i > 0 && size[order[i - 1]] < size[l]) {
      order[i] = order[i - 1];
      --i;
    }
    order[i] = l;
  }
  memset(load, 0, sizeof load);
  for (l = 0; l < job->label_count; ++l) {
    uint32_t lab = order[l], best = 0;
    if (size[lab] == 0 || !(job->radius[lab] > 0.0f)) continue;
    for (t = 1; t < nt; ++t)
      if (load[t] < load[best]) best = t;
    load[best] += size[lab];
    ws[best].labels[ws[best].label_count++] = lab;
  }
  for (t = 0; t < nt; ++t) {
    ws[t].job = job;
    ws[t].feat = feat;
    ws[t].dims = dims;
    ws[t].covered = covered;
  }
  smgb_run_workers(ws, sizeof ws[0], nt, worker_run);
  for (t = 0; t < nt; ++t)
    if (ws[t].failed) r = SMG_ERROR_OUT_OF_MEMORY;
done:
  for (t = 0; t < nt; ++t) free(ws[t].labels);
  free(order);
  free(size);
  free(feat);
  return r;
}
