/*
 * bake_pair_search.c - local minima of the windowed point-cloud distance
 * without the full grid (see bake_pair_search.h for the idea).
 *
 * Features. Window i of a cloud is described by its points at window
 * steps 0, k/2 and k-1, each scaled by sqrt(w_p); with alignment they are
 * taken relative to the window's weighted floor centroid and turned by
 * minus the body heading at the middle step, so that two windows that the
 * optimal alignment would match land near each other. The feature vectors
 * (9 P numbers) are reduced to their leading principal components (at most
 * SMGB_PAIR_DIMS), computed with Jacobi's method on the covariance of a
 * regular sample of the windows: a kd-tree works well in a dozen
 * dimensions, not in a hundred, and locomotion spans few of them.
 *
 * Search. One kd-tree per column group (median splits on the dimension of
 * largest spread). For each usable row window the `neighbours` nearest
 * column windows that pass the filter are the start cells. From each
 * start cell the search steps to the smallest of the 3 x 3 neighbourhood
 * (exact distance; cells ordered by distance, then row, then column, which
 * is the full grid's local-minimum rule with its ties) until the cell
 * itself is the smallest: a local minimum of the exact grid over the pairs
 * the filter accepts. Rejected pairs count as outside the grid: along the
 * flat valley of a periodic clip against itself the walk would otherwise
 * slide into the rejected band (too near a clip's start) and find
 * nothing, where the full grid keeps whichever minimum float noise makes
 * inside the valley.
 *
 * Cost: O(F log F) for the trees and O(F * neighbours * steps * k * P) for
 * the walks; memory O(F * dims). Threads take contiguous row ranges; row
 * i's start cells depend only on row i, and a walk's end only on its
 * start, so the sorted, de-duplicated output is the same for any
 * thread count. Two caches per worker (exact distances; cells already
 * walked through) only save work: a cell once walked through leads to a
 * minimum that is already recorded.
 */
#include "bake_pair_search.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_kdtree.h"
#include "bake_threads.h"
#include "smg_format.h"

#define SMGB_PAIR_DIMS 12u
#define SMGB_PAIR_MAX_K 64u
#define CACHE_BITS 16u
/* Approximate nearest neighbours: a far cell is searched only if it could
 * hold a window twice as near as the current k-th (squared: 4). The start
 * cells only need to be near; the walks find the exact minima. On 1/8 of
 * the scale set this halves the tree's share of the bake, and the CMU
 * graph keeps its counts (102 instead of 100 upper transitions). */
#define KD_SLACK 4.0f




typedef struct sums {
  double *sq, *x, *z;
} sums;

typedef struct search {
  const smgb_pair_search* job;
  sums A, B;
  double W;
  uint32_t dims;
  float* frow;                 /* rows x dims (features, rows) */
  float* fcol;                 /* cols x dims (frow itself when shared) */
  int shared;                  /* rows and cols are one cloud's windows */
  smgb_kd_tree* trees;         /* group_count */
  uint32_t groups;
} search;

typedef struct hit {
  float d;
  uint32_t j;
} hit;

typedef struct cell_cache {
  uint64_t key[1u << CACHE_BITS];
  float d[1u << CACHE_BITS];
  uint64_t seen[1u << CACHE_BITS];
} cell_cache;

typedef struct worker {
  const search* s;
  uint32_t r0, r1;
  smgb_minimum* out;
  uint32_t count, cap;
  cell_cache* cache;
  int failed;
} worker;

/* ---- window sums (as bake_pointcloud.c) ---------------------------------- */

static int window_sums(const smgb_cloud* c, uint32_t k, sums* s) {
  uint32_t F = c->frames, P = c->points, f, p;
  double *fs, *fx, *fz;
  s->sq = malloc((size_t)F * 3u * sizeof *s->sq);
  fs = malloc((size_t)F * 3u * sizeof *fs);
  if (!s->sq || !fs) {
    free(fs);
    return 0;
  }
  s->x = s->sq + F;
  s->z = s->x + F;
  fx = fs + F;
  fz = fx + F;
  for (f = 0; f < F; ++f) {
    const double* v = c->xyz + (size_t)f * P * 3u;
    double sq = 0, x = 0, z = 0;
    for (p = 0; p < P; ++p, v += 3) {
      double w = c->weights[p];
      sq += w * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      x += w * v[0];
      z += w * v[2];
    }
    fs[f] = sq;
    fx[f] = x;
    fz[f] = z;
  }
  {
    double rs = 0, rx = 0, rz = 0;
    for (f = F; f-- > 0;) {
      rs += fs[f];
      rx += fx[f];
      rz += fz[f];
      if (f + k < F) {
        rs -= fs[f + k];
        rx -= fx[f + k];
        rz -= fz[f + k];
      }
      s->sq[f] = rs;
      s->x[f] = rx;
      s->z[f] = rz;
    }
  }
  free(fs);
  return 1;
}

/* ---- exact distance of one window pair ------------------------------------ */

static double exact(const search* s, uint32_t i, uint32_t j,
                    double align_out[3]) {
  const smgb_pair_search* job = s->job;
  const smgb_cloud* A = job->rows;
  const smgb_cloud* B = job->cols;
  uint32_t P = A->points, k = job->window, t, p;
  double dot = 0, crs = 0, yy = 0, D, W = s->W;
  for (t = 0; t < k; ++t) {
    const double* va = A->xyz + (size_t)(i + t) * P * 3u;
    const double* vb = B->xyz + (size_t)(j + t) * P * 3u;
    for (p = 0; p < P; ++p, va += 3, vb += 3) {
      double w = A->weights[p];
      dot += w * (va[0] * vb[0] + va[2] * vb[2]);
      crs += w * (va[0] * vb[2] - va[2] * vb[0]);
      yy += w * va[1] * vb[1];
    }
  }
  if (job->align) {
    const sums* a = &s->A;
    const sums* b = &s->B;
    double ca = dot - (a->x[i] * b->x[j] + a->z[i] * b->z[j]) / W;
    double cb = crs - (a->x[i] * b->z[j] - a->z[i] * b->x[j]) / W;
    D = a->sq[i] - (a->x[i] * a->x[i] + a->z[i] * a->z[i]) / W + b->sq[j] -
        (b->x[j] * b->x[j] + b->z[j] * b->z[j]) / W -
        2.0 * (yy + sqrt(ca * ca + cb * cb));
    if (align_out) {
      double th = atan2(cb, ca), c = cos(th), sn = sin(th);
      double bx = b->x[j] / W, bz = b->z[j] / W;
      align_out[0] = a->x[i] / W - (bx * c + bz * sn);
      align_out[1] = a->z[i] / W - (-bx * sn + bz * c);
      align_out[2] = th;
    }
  } else {
    D = s->A.sq[i] + s->B.sq[j] - 2.0 * (dot + yy);
    if (align_out) align_out[0] = align_out[1] = align_out[2] = 0.0;
  }
  return D > 0.0 ? D : 0.0;
}

/* ---- features ------------------------------------------------------------- */

static void raw_feature(const search* s, const smgb_cloud* c, const sums* ws,
                        const double* heading, uint32_t f, double* out) {
  const smgb_pair_search* job = s->job;
  uint32_t k = job->window, P = c->points, q, p;
  uint32_t steps[3];
  double cx = 0, cz = 0, ch = 1, sh = 0;
  steps[0] = 0;
  steps[1] = k / 2;
  steps[2] = k - 1;
  if (job->align) {
    cx = ws->x[f] / s->W;
    cz = ws->z[f] / s->W;
    if (heading) {
      ch = cos(heading[f + k / 2]);
      sh = sin(heading[f + k / 2]);
    }
  }
  for (q = 0; q < 3; ++q) {
    const double* v = c->xyz + (size_t)(f + steps[q]) * P * 3u;
    for (p = 0; p < P; ++p, v += 3) {
      double sw = sqrt(c->weights[p]);
      double x = v[0] - cx, z = v[2] - cz;
      /* turn by -heading: the body faces +Z in the feature frame */
      *out++ = sw * (x * ch - z * sh);
      *out++ = sw * v[1];
      *out++ = sw * (x * sh + z * ch);
    }
  }
}

/* Eigenvectors of the symmetric n x n matrix a (destroyed) by cyclic
 * Jacobi rotations; v gets them as columns, e the eigenvalues. */
static void jacobi(double* a, uint32_t n, double* v, double* e) {
  uint32_t i, j, p, q, sweep;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j) v[i * n + j] = i == j ? 1.0 : 0.0;
  for (sweep = 0; sweep < 50; ++sweep) {
    double off = 0.0;
    for (p = 0; p < n; ++p)
      for (q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
    if (off < 1e-22) break;
    for (p = 0; p < n; ++p)
      for (q = p + 1; q < n; ++q) {
        double apq = a[p * n + q], th, t, c, sn;
        if (fabs(apq) < 1e-300) continue;
        th = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
        c = 1.0 / sqrt(t * t + 1.0);
        sn = t * c;
        for (i = 0; i < n; ++i) { /* columns p, q */
          double aip = a[i * n + p], aiq = a[i * n + q];
          a[i * n + p] = c * aip - sn * aiq;
          a[i * n + q] = sn * aip + c * aiq;
        }
        for (i = 0; i < n; ++i) { /* rows p, q */
          double api = a[p * n + i], aqi = a[q * n + i];
          a[p * n + i] = c * api - sn * aqi;
          a[q * n + i] = sn * api + c * aqi;
        }
        for (i = 0; i < n; ++i) {
          double vip = v[i * n + p], viq = v[i * n + q];
          v[i * n + p] = c * vip - sn * viq;
          v[i * n + q] = sn * vip + c * viq;
        }
      }
  }
  for (i = 0; i < n; ++i) e[i] = a[i * n + i];
}

/* Project every usable window of both clouds onto the leading principal
 * components of the column windows' features. */
static int build_features(search* s) {
  const smgb_pair_search* job = s->job;
  const smgb_cloud* A = job->rows;
  const smgb_cloud* B = job->cols;
  uint32_t n = 9u * A->points, d, i, j, f, used = 0, stride;
  double *raw = malloc(n * sizeof *raw), *mean = calloc(n, sizeof *mean);
  double* cov = calloc((size_t)n * n, sizeof *cov);
  double* vec = malloc((size_t)n * n * sizeof *vec);
  double* ev = malloc(n * sizeof *ev);
  uint32_t* order = malloc(n * sizeof *order);
  double* basis = NULL;
  int ok = 0;
  if (!raw || !mean || !cov || !vec || !ev || !order) goto done;
  d = n < SMGB_PAIR_DIMS ? n : SMGB_PAIR_DIMS;
  s->dims = d;
  /* a regular sample of at most ~4096 windows is plenty for the axes */
  stride = B->frames / 4096u + 1u;
  for (f = 0; f < B->frames; f += stride) {
    if (!B->valid[f]) continue;
    raw_feature(s, B, &s->B, job->col_heading, f, raw);
    for (i = 0; i < n; ++i) mean[i] += raw[i];
    ++used;
  }
  if (used == 0) used = 1;
  for (i = 0; i < n; ++i) mean[i] /= used;
  for (f = 0; f < B->frames; f += stride) {
    if (!B->valid[f]) continue;
    raw_feature(s, B, &s->B, job->col_heading, f, raw);
    for (i = 0; i < n; ++i) raw[i] -= mean[i];
    for (i = 0; i < n; ++i)
      for (j = i; j < n; ++j) cov[i * n + j] += raw[i] * raw[j];
  }
  for (i = 0; i < n; ++i)
    for (j = 0; j < i; ++j) cov[i * n + j] = cov[j * n + i];
  jacobi(cov, n, vec, ev);
  for (i = 0; i < n; ++i) order[i] = i;
  for (i = 1; i < n; ++i) { /* by eigenvalue, descending (stable) */
    uint32_t o = order[i];
    j = i;
    while (j > 0 && ev[order[j - 1]] < ev[o]) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = o;
  }
  basis = malloc((size_t)d * n * sizeof *basis);
  /* Rows and columns from one cloud (graph searches: the same frames,
   * only the usable windows differ): one feature array for both, each
   * window computed once. */
  s->shared = A->xyz == B->xyz && A->frames == B->frames &&
              A->weights == B->weights &&
              job->row_heading == job->col_heading;
  s->frow = malloc((size_t)A->frames * d * sizeof *s->frow);
  s->fcol = s->shared ? s->frow
                      : malloc((size_t)B->frames * d * sizeof *s->fcol);
  if (!basis || !s->frow || !s->fcol) goto done;
  for (i = 0; i < d; ++i)
    for (j = 0; j < n; ++j) basis[i * n + j] = vec[j * n + order[i]];
  for (f = 0; f < A->frames + (s->shared ? 0 : B->frames); ++f) {
    int row = f < A->frames;
    uint32_t g = row ? f : f - A->frames;
    const smgb_cloud* c = row ? A : B;
    float* dst = (row ? s->frow : s->fcol) + (size_t)g * d;
    if (!c->valid[g] && !(s->shared && B->valid[g])) {
      memset(dst, 0, d * sizeof *dst);
      continue;
    }
    raw_feature(s, c, row ? &s->A : &s->B,
                row ? job->row_heading : job->col_heading, g, raw);
    for (i = 0; i < d; ++i) {
      double acc = 0.0;
      for (j = 0; j < n; ++j) acc += basis[i * n + j] * (raw[j] - mean[j]);
      dst[i] = (float)acc;
    }
  }
  ok = 1;
done:
  free(raw);
  free(mean);
  free(cov);
  free(vec);
  free(ev);
  free(order);
  free(basis);
  return ok;
}

/* ---- nearest windows ---------------------------------------------------- */

typedef struct query {
  const search* s;
  const float* q;
  uint32_t row;
  hit* best;
  uint32_t n, k;
} query;

static int hit_worse(const hit* a, const hit* b) {
  return a->d > b->d || (a->d == b->d && a->j > b->j);
}

static void offer(query* qr, float d, uint32_t j) {
  hit h;
  uint32_t i;
  h.d = d;
  h.j = j;
  if (qr->n == qr->k && !hit_worse(&qr->best[qr->n - 1], &h)) return;
  i = qr->n < qr->k ? qr->n++ : qr->n - 1;
  while (i > 0 && hit_worse(&qr->best[i - 1], &h)) {
    qr->best[i] = qr->best[i - 1];
    --i;
  }
  qr->best[i] = h;
}

/* Nearest-first descent; `rd` is the squared distance from the query to
 * the node's cell, built up from the per-dimension offsets `off` of the
 * splits crossed so far (Arya and Mount's incremental distance), a far
 * tighter bound in a dozen dimensions than the last split alone. */
static void kd_query(const smgb_kd_tree* t, uint32_t node, query* qr,
                     float rd, float* off) {
  const smgb_kd_node* n = &t->nodes[node];
  const smgb_pair_search* job = qr->s->job;
  uint32_t d = qr->s->dims;
  if (!n->left) {
    uint32_t i, a;
    for (i = n->lo; i < n->hi; ++i) {
      uint32_t j = t->idx[i];
      const float* f = qr->s->fcol + (size_t)j * d;
      float acc = 0.0f;
      for (a = 0; a < d; ++a) {
        float df = f[a] - qr->q[a];
        acc += df * df;
      }
      if (qr->n == qr->k && acc > qr->best[qr->n - 1].d) continue;
      if (job->filter && !job->filter(qr->row, j, job->filter_user)) continue;
      offer(qr, acc, j);
    }
    return;
  }
  {
    float diff = qr->q[n->dim] - n->split;
    uint32_t near = diff < 0.0f ? n->left : n->right;
    uint32_t far = diff < 0.0f ? n->right : n->left;
    float old = off[n->dim], frd;
    kd_query(t, near, qr, rd, off);
    frd = rd - old * old + diff * diff;
    if (qr->n < qr->k || frd * KD_SLACK <= qr->best[qr->n - 1].d) {
      off[n->dim] = diff;
      kd_query(t, far, qr, frd, off);
      off[n->dim] = old;
    }
  }
}

/* Start cells of row i: the nearest columns in each searched group. */
static uint32_t starts(const search* s, uint32_t i, hit* buf,
                       uint32_t* out) {
  const smgb_pair_search* job = s->job;
  uint32_t g, n = 0, own = SMGI_NONE, t;
  float off[SMGB_PAIR_DIMS];
  query qr;
  if (!job->rows->valid[i]) return 0;
  if (job->row_group) own = job->row_group[i];
  qr.s = s;
  qr.q = s->frow + (size_t)i * s->dims;
  qr.row = i;
  qr.best = buf;
  for (g = 0; g < s->groups; ++g) {
    qr.k = own == SMGI_NONE || g == own ? job->neighbours
                                         : job->other_neighbours;
    if (s->trees[g].n == 0 || qr.k == 0) continue;
    qr.n = 0;
    memset(off, 0, sizeof off);
    kd_query(&s->trees[g], 0, &qr, 0.0f, off);
    for (t = 0; t < qr.n; ++t) out[n++] = buf[t].j;
  }
  return n;
}

/* ---- walks ---------------------------------------------------------------- */

static float cached(worker* w, uint32_t i, uint32_t j) {
  uint64_t key = ((uint64_t)i << 32 | j) + 1u; /* 0 = empty */
  uint32_t h = (uint32_t)((key * 0x9E3779B97F4A7C15ull) >> (64 - CACHE_BITS));
  if (w->cache->key[h] != key) {
    w->cache->key[h] = key;
    w->cache->d[h] = (float)exact(w->s, i, j, NULL);
  }
  return w->cache->d[h];
}

/* 1 when the cell was walked through before (and marks it). */
static int seen(worker* w, uint32_t i, uint32_t j) {
  uint64_t key = ((uint64_t)i << 32 | j) + 1u;
  uint32_t h = (uint32_t)((key * 0xC2B2AE3D27D4EB4Full) >> (64 - CACHE_BITS));
  if (w->cache->seen[h] == key) return 1;
  w->cache->seen[h] = key;
  return 0;
}

static int cell_before(float da, uint32_t ia, uint32_t ja, float db,
                       uint32_t ib, uint32_t jb) {
  if (da != db) return da < db;
  if (ia != ib) return ia < ib;
  return ja < jb;
}

static int push_min(worker* w, uint32_t i, uint32_t j) {
  smgb_minimum m;
  double D;
  if (w->count == w->cap) {
    uint32_t cap = w->cap ? w->cap * 2u : 1024u;
    smgb_minimum* n = realloc(w->out, cap * sizeof *n);
    if (!n) return 0;
    w->out = n;
    w->cap = cap;
  }
  memset(&m, 0, sizeof m); /* padding too: results are compared */
  D = exact(w->s, i, j, m.align);
  m.i = i;
  m.j = j;
  m.dist = (float)sqrt(D / w->s->W);
  w->out[w->count++] = m;
  return 1;
}

static int walk(worker* w, uint32_t i, uint32_t j) {
  const smgb_pair_search* job = w->s->job;
  const uint8_t* vr = job->rows->valid;
  const uint8_t* vc = job->cols->valid;
  uint32_t FA = job->rows->frames, FB = job->cols->frames;
  for (;;) {
    float bd;
    uint32_t bi = i, bj = j;
    int di, dj;
    if (seen(w, i, j)) return 1;
    bd = cached(w, i, j);
    for (di = -1; di <= 1; ++di)
      for (dj = -1; dj <= 1; ++dj) {
        int64_t ii = (int64_t)i + di, jj = (int64_t)j + dj;
        float d;
        if ((di == 0 && dj == 0) || ii < 0 || jj < 0 || ii >= FA ||
            jj >= FB || !vr[ii] || !vc[jj] ||
            (job->filter &&
             !job->filter((uint32_t)ii, (uint32_t)jj, job->filter_user)))
          continue;
        d = cached(w, (uint32_t)ii, (uint32_t)jj);
        if (cell_before(d, (uint32_t)ii, (uint32_t)jj, bd, bi, bj)) {
          bd = d;
          bi = (uint32_t)ii;
          bj = (uint32_t)jj;
        }
      }
    if (bi == i && bj == j) return push_min(w, i, j);
    i = bi;
    j = bj;
  }
}

static int u32_cmp(const void* pa, const void* pb) {
  uint32_t a = *(const uint32_t*)pa, b = *(const uint32_t*)pb;
  return a < b ? -1 : a > b ? 1 : 0;
}

static void* worker_run(void* arg) {
  worker* w = arg;
  const search* s = w->s;
  const smgb_pair_search* job = s->job;
  uint32_t most = job->neighbours > job->other_neighbours
                      ? job->neighbours
                      : job->other_neighbours;
  uint32_t per = most * s->groups;
  hit* buf = malloc(most * sizeof *buf);
  uint32_t* cur = malloc((per ? per : 1) * sizeof *cur);
  uint32_t nc, i, t;
  if (!buf || !cur) {
    w->failed = 1;
    goto done;
  }
  for (i = w->r0; i < w->r1; ++i) {
    if (job->row_stride > 1 && i % job->row_stride != 0) continue;
    nc = starts(s, i, buf, cur);
    qsort(cur, nc, sizeof *cur, u32_cmp);
    for (t = 0; t < nc; ++t) {
      if (t > 0 && cur[t] == cur[t - 1]) continue;
      if (!walk(w, i, cur[t])) {
        w->failed = 1;
        goto done;
      }
    }
    if (w->r0 == 0 && job->report && (i & 255u) == 0)
      smgb_progress(job->report, (float)(i + 1) / (float)(w->r1 + 1));
  }
done:
  free(buf);
  free(cur);
  return NULL;
}

static int min_cmp(const void* pa, const void* pb) {
  const smgb_minimum* a = pa;
  const smgb_minimum* b = pb;
  if (a->i != b->i) return a->i < b->i ? -1 : 1;
  if (a->j != b->j) return a->j < b->j ? -1 : 1;
  return 0;
}

static void search_free(search* s) {
  uint32_t g;
  free(s->A.sq);
  free(s->B.sq);
  free(s->frow);
  if (!s->shared) free(s->fcol);
  if (s->trees)
    for (g = 0; g < s->groups; ++g) smgb_kd_free(&s->trees[g]);
  free(s->trees);
}

static int build_trees(search* s) {
  const smgb_pair_search* job = s->job;
  const smgb_cloud* B = job->cols;
  uint32_t g, f;
  s->groups = job->col_group ? job->group_count : 1u;
  s->trees = calloc(s->groups ? s->groups : 1, sizeof *s->trees);
  if (!s->trees) return 0;
  for (f = 0; f < B->frames; ++f) {
    uint32_t gr = job->col_group ? job->col_group[f] : 0u;
    if (B->valid[f] && gr < s->groups) s->trees[gr].n++;
  }
  for (g = 0; g < s->groups; ++g) {
    s->trees[g].idx = malloc((s->trees[g].n ? s->trees[g].n : 1) *
                             sizeof *s->trees[g].idx);
    if (!s->trees[g].idx) return 0;
    s->trees[g].n = 0;
  }
  for (f = 0; f < B->frames; ++f) {
    uint32_t gr = job->col_group ? job->col_group[f] : 0u;
    if (B->valid[f] && gr < s->groups)
      s->trees[gr].idx[s->trees[gr].n++] = f;
  }
  for (g = 0; g < s->groups; ++g) {
    if (!smgb_kd_build(&s->trees[g], s->fcol, s->dims)) return 0;
  }
  return 1;
}

smg_result smgb_pair_search_minima(const smgb_pair_search* job,
                                   smgb_minimum** out, uint32_t* out_count) {
  const smgb_cloud* A = job->rows;
  const smgb_cloud* B = job->cols;
  search s;
  worker ws[8];
  uint32_t nt = job->threads ? job->threads : 1u, t, p, total = 0;
  smg_result res = SMG_OK;
  double wsum = 0.0;
  *out = NULL;
  *out_count = 0;
  if (A->frames == 0 || B->frames == 0 || job->window == 0 ||
      (job->neighbours == 0 && job->other_neighbours == 0) ||
      A->points != B->points || A->points == 0)
    return SMG_OK;
  if (job->neighbours > SMGB_PAIR_MAX_K ||
      job->other_neighbours > SMGB_PAIR_MAX_K)
    return SMG_ERROR_INVALID_ARGUMENT;
  memset(&s, 0, sizeof s);
  s.job = job;
  for (p = 0; p < A->points; ++p) wsum += A->weights[p];
  s.W = wsum * job->window;
  if (!(s.W > 0.0)) return SMG_ERROR_INVALID_ARGUMENT;
  if (!window_sums(A, job->window, &s.A) ||
      !window_sums(B, job->window, &s.B) || !build_features(&s) ||
      !build_trees(&s)) {
    search_free(&s);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  if (nt > 8) nt = 8;
  if (A->frames < 256u * nt) nt = 1;
  memset(ws, 0, sizeof ws);
  for (t = 0; t < nt; ++t) {
    ws[t].s = &s;
    ws[t].r0 = (uint32_t)((uint64_t)A->frames * t / nt);
    ws[t].r1 = (uint32_t)((uint64_t)A->frames * (t + 1) / nt);
    ws[t].cache = calloc(1, sizeof *ws[t].cache);
    if (!ws[t].cache) res = SMG_ERROR_OUT_OF_MEMORY;
  }
  if (res == SMG_OK) {
    smgb_run_workers(ws, sizeof ws[0], nt, worker_run);
    for (t = 0; t < nt; ++t) {
      if (ws[t].failed) res = SMG_ERROR_OUT_OF_MEMORY;
      total += ws[t].count;
    }
  }
  if (res == SMG_OK && total > 0) {
    *out = malloc((size_t)total * sizeof **out);
    if (!*out) res = SMG_ERROR_OUT_OF_MEMORY;
  }
  if (res == SMG_OK && total > 0) {
    uint32_t at = 0, u, n = 0;
    for (t = 0; t < nt; ++t) {
      if (ws[t].count)
        memcpy(*out + at, ws[t].out, ws[t].count * sizeof **out);
      at += ws[t].count;
    }
    qsort(*out, total, sizeof **out, min_cmp);
    for (u = 0; u < total; ++u)
      if (n == 0 || min_cmp(&(*out)[n - 1], &(*out)[u]) != 0)
        (*out)[n++] = (*out)[u];
    *out_count = n;
  }
  for (t = 0; t < nt; ++t) {
    free(ws[t].out);
    free(ws[t].cache);
  }
  search_free(&s);
  return res;
}

smg_result smgb_pair_features(const smgb_pair_search* job, float** out,
                              uint32_t* out_dims) {
  search s;
  uint32_t p;
  double wsum = 0.0;
  *out = NULL;
  *out_dims = 0;
  if (job->rows->frames == 0 || job->cols->frames == 0 || job->window == 0 ||
      job->rows->points != job->cols->points || job->rows->points == 0)
    return SMG_ERROR_INVALID_ARGUMENT;
  memset(&s, 0, sizeof s);
  s.job = job;
  for (p = 0; p < job->rows->points; ++p) wsum += job->rows->weights[p];
  s.W = wsum * job->window;
  if (!(s.W > 0.0)) return SMG_ERROR_INVALID_ARGUMENT;
  if (!window_sums(job->rows, job->window, &s.A) ||
      !window_sums(job->cols, job->window, &s.B) || !build_features(&s)) {
    search_free(&s);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  *out = s.frow;
  *out_dims = s.dims;
  s.frow = NULL;
  if (s.shared) s.fcol = NULL;
  search_free(&s);
  return SMG_OK;
}
