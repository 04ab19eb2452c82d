/*
 * bake_pointcloud.c - the windowed point-cloud distance of Kovar et al.
 * 2002 over a whole grid of frame pairs, and its local minima.
 *
 * D(i, j) compares the window of rows i..i+k-1 with the window of columns
 * j..j+k-1 (the same points, weights w_p, every frame weighted equally):
 *
 *   D = min over (theta, x0, z0) of  sum_t sum_p w_p |a - T b|^2
 *
 * where T rotates about +Y by theta and translates on the floor. With
 * W = k sum_p w_p, window sums Ax = sum w x (rows), Az, Bx, Bz (columns),
 * Asq = sum w |a|^2, Bsq, and the cross sums over aligned frame pairs
 *   dot = sum w (xa xb + za zb),  crs = sum w (xa zb - za xb),
 *   yy  = sum w ya yb,
 * the centred cross terms are a = dot - (Ax Bx + Az Bz)/W and
 * b = crs - (Ax Bz - Az Bx)/W; the optimum is theta = atan2(b, a) and
 *
 *   D = Asq - (Ax^2+Az^2)/W + Bsq - (Bx^2+Bz^2)/W - 2 (yy + sqrt(a^2+b^2)).
 *
 * (Kovar's closed form, rearranged.) Only dot/crs/yy depend on the pair,
 * and they are sums along a grid diagonal of per-frame-pair cross terms
 * C(i, j); so row i follows from row i-1 by one subtraction and one
 * addition per cell (S_i(j) = S_{i-1}(j-1) - C(i-1,j-1) + C(i+k-1,j+k-1)).
 * Cost O(F^2 P) instead of O(F^2 k P); memory O(k F) per worker: the grid
 * is streamed row by row and never stored (three rows are kept to find
 * local minima). Rows are split over worker threads; each worker's results
 * are concatenated in row order, so the output does not depend on timing.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_pointcloud.h"
#include "bake_threads.h"

typedef struct win_sums {
  double* sq;
  double* x;
  double* z;
} win_sums;

typedef struct worker {
  const smgb_grid_job* job;
  const win_sums* A;
  const win_sums* B;
  const double* soa;         /* column cloud, point-major */
  double W;
  uint32_t r0, r1;           /* rows whose minima this worker reports */
  smgb_minimum* out;
  uint32_t count, cap;
  int failed;
  int report_progress;
} worker;

static int window_sums(const smgb_cloud* c, uint32_t k, win_sums* s) {
  uint32_t F = c->frames, P = c->points, f, p;
  double* fsq = s->sq;
  /* per-frame sums first (stored in place), then a sliding window */
  for (f = 0; f < F; ++f) {
    double sq = 0, x = 0, z = 0;
    const double* v = c->xyz + (size_t)f * P * 3u;
    for (p = 0; p < P; ++p) {
      double w = c->weights[p];
      sq += w * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      x += w * v[0];
      z += w * v[2];
      v += 3;
    }
    fsq[f] = sq;
    s->x[f] = x;
    s->z[f] = z;
  }
  {
    double rs = 0, rx = 0, rz = 0;
    double* tsq = malloc(F * sizeof *tsq * 3u);
    if (!tsq) return 0;
    memcpy(tsq, fsq, F * sizeof *tsq);
    memcpy(tsq + F, s->x, F * sizeof *tsq);
    memcpy(tsq + 2 * F, s->z, F * sizeof *tsq);
    /* window starting at f: sum of frames f..f+k-1 (clipped at F) */
    for (f = F; f-- > 0;) {
      rs += tsq[f];
      rx += tsq[F + f];
      rz += tsq[2 * F + f];
      if (f + k < F) {
        rs -= tsq[f + k];
        rx -= tsq[F + f + k];
        rz -= tsq[2 * F + f + k];
      }
      s->sq[f] = rs;
      s->x[f] = rx;
      s->z[f] = rz;
    }
    free(tsq);
  }
  return 1;
}

/* Cross terms of row frame a against every column frame. The columns are
 * kept point-major (soa[(3p + axis) * FB + j]) so that the inner loop runs
 * over contiguous frames and vectorises. */
static void cross_row(const smgb_cloud* A, const double* soa, uint32_t FB,
                      uint32_t a, double* dot, double* crs, double* yy) {
  uint32_t P = A->points, j, p;
  const double* va = A->xyz + (size_t)a * P * 3u;
  const double* w = A->weights;
  for (j = 0; j < FB; ++j) dot[j] = crs[j] = yy[j] = 0.0;
  for (p = 0; p < P; ++p) {
    const double xa = w[p] * va[3 * p], ya = w[p] * va[3 * p + 1],
                 za = w[p] * va[3 * p + 2];
    const double* xb = soa + (size_t)(3u * p) * FB;
    const double* yb = xb + FB;
    const double* zb = yb + FB;
    for (j = 0; j < FB; ++j) {
      dot[j] += xa * xb[j] + za * zb[j];
      crs[j] += xa * zb[j] - za * xb[j];
      yy[j] += ya * yb[j];
    }
  }
}

static double cell_distance(const worker* w, uint32_t i, uint32_t j,
                            double dot, double crs, double yy,
                            double align_out[3]) {
  const win_sums* A = w->A;
  const win_sums* B = w->B;
  double W = w->W, D;
  if (w->job->align) {
    double a = dot - (A->x[i] * B->x[j] + A->z[i] * B->z[j]) / W;
    double bb = crs - (A->x[i] * B->z[j] - A->z[i] * B->x[j]) / W;
    D = A->sq[i] - (A->x[i] * A->x[i] + A->z[i] * A->z[i]) / W + B->sq[j] -
        (B->x[j] * B->x[j] + B->z[j] * B->z[j]) / W -
        2.0 * (yy + sqrt(a * a + bb * bb));
    if (align_out) {
      double th = atan2(bb, a), c = cos(th), s = sin(th);
      double bx = B->x[j] / W, bz = B->z[j] / W;
      align_out[0] = A->x[i] / W - (bx * c + bz * s);
      align_out[1] = A->z[i] / W - (-bx * s + bz * c);
      align_out[2] = th;
    }
  } else {
    D = A->sq[i] + B->sq[j] - 2.0 * (dot + yy);
    if (align_out) align_out[0] = align_out[1] = align_out[2] = 0.0;
  }
  return D > 0.0 ? D : 0.0;
}

static int push_min(worker* w, const smgb_minimum* m) {
  if (w->count == w->cap) {
    uint32_t cap = w->cap ? w->cap * 2 : 1024;
    smgb_minimum* n = realloc(w->out, cap * sizeof *n);
    if (!n) return 0;
    w->out = n;
    w->cap = cap;
  }
  w->out[w->count++] = *m;
  return 1;
}

/* Report local minima of row r given rows r-1 (prev, may be NULL), r, r+1
 * (next, may be NULL). S arrays of row r are needed for the alignment. */
static void row_minima(worker* w, uint32_t r, const float* prev,
                       const float* cur, const float* next,
                       const double* sdot, const double* scrs,
                       const double* syy) {
  const smgb_grid_job* job = w->job;
  uint32_t FB = job->cols->frames, j;
  const uint8_t* vr = job->rows->valid;
  const uint8_t* vc = job->cols->valid;
  if (!vr[r]) return;
  for (j = 0; j < FB; ++j) {
    float d = cur[j];
    int ok = 1, dc;
    if (!vc[j]) continue;
    for (dc = -1; dc <= 1 && ok; ++dc) {
      int64_t jj = (int64_t)j + dc;
      if (jj < 0 || jj >= FB || !vc[jj]) continue;
      if (prev && vr[r - 1] && !(d <= prev[jj])) ok = 0;
      if (next && vr[r + 1] && !(d < next[jj])) ok = 0;
      if (dc < 0 && !(d <= cur[jj])) ok = 0;
      if (dc > 0 && !(d < cur[jj])) ok = 0;
    }
    if (!ok) continue;
    if (job->filter && !job->filter(r, j, job->filter_user)) continue;
    {
      smgb_minimum m;
      double D;
      memset(&m, 0, sizeof m); /* padding too: results are compared */
      D = cell_distance(w, r, j, sdot[j], scrs[j], syy[j], m.align);
      m.i = r;
      m.j = j;
      m.dist = (float)sqrt(D / w->W);
      if (!push_min(w, &m)) {
        w->failed = 1;
        return;
      }
    }
  }
}

/* Running sums restart from a direct diagonal sum at every multiple of
 * SMGB_GRID_BLOCK rows. Row i's values therefore depend only on i (not on
 * which worker computed it or where it started), so the output is the same
 * bit for bit for any thread count, and float drift is bounded. */
#define SMGB_GRID_BLOCK 32u

static void direct_sums(const double* cbuf, uint32_t ring, uint32_t FA,
                        uint32_t FB, uint32_t k, uint32_t i, double* S) {
  uint32_t j, t;
  for (j = 0; j < FB; ++j) {
    double d = 0, cr = 0, y = 0;
    for (t = 0; t < k && j + t < FB && i + t < FA; ++t) {
      const double* c = cbuf + (size_t)((i + t) % ring) * 3u * FB;
      d += c[j + t];
      cr += c[FB + j + t];
      y += c[2u * FB + j + t];
    }
    S[j] = d;
    S[FB + j] = cr;
    S[2u * FB + j] = y;
  }
}

static void* worker_run(void* arg) {
  worker* w = arg;
  const smgb_grid_job* job = w->job;
  const smgb_cloud* A = job->rows;
  const smgb_cloud* B = job->cols;
  uint32_t FA = A->frames, FB = B->frames, k = job->window;
  uint32_t ring = k + 1, lo, hi, i, t, j;
  double* cbuf = malloc((size_t)ring * 3u * FB * sizeof *cbuf);
  double* S = malloc((size_t)3u * FB * sizeof *S);
  double* Sprev = malloc((size_t)3u * FB * sizeof *Sprev);
  float* drow = malloc((size_t)3u * FB * sizeof *drow);
  float *dprev, *dcur, *dnext;
  if (!cbuf || !S || !Sprev || !drow) {
    w->failed = 1;
    goto done;
  }
#define CROW(a) (cbuf + (size_t)((a) % ring) * 3u * FB)
  /* start one block early so that the halo row r0-1 is computed exactly
   * as its own worker computes it */
  lo = w->r0 >= SMGB_GRID_BLOCK ? w->r0 - SMGB_GRID_BLOCK : 0;
  hi = w->r1 < FA ? w->r1 : FA - 1; /* inclusive */
  for (t = 0; t < k; ++t) {
    double* c = CROW(lo + t);
    if (lo + t < FA)
      cross_row(A, w->soa, FB, lo + t, c, c + FB, c + 2u * FB);
    else
      memset(c, 0, 3u * FB * sizeof *c);
  }
  dprev = NULL;
  dcur = drow;
  dnext = drow + FB;
  for (i = lo; i <= hi; ++i) {
    float* dst;
    if (i > lo) {
      double* cnew = CROW(i + k - 1);
      double* tmp;
      if (i + k - 1 < FA)
        cross_row(A, w->soa, FB, i + k - 1, cnew, cnew + FB, cnew + 2u * FB);
      else
        memset(cnew, 0, 3u * FB * sizeof *cnew);
      tmp = Sprev;
      Sprev = S;
      S = tmp;
    }
    if (i == lo || i % SMGB_GRID_BLOCK == 0) {
      direct_sums(cbuf, ring, FA, FB, k, i, S);
    } else {
      /* S_i(j) = S_{i-1}(j-1) - C(i-1, j-1) + C(i+k-1, j+k-1) */
      const double* cold = CROW(i - 1);
      const double* cnew = CROW(i + k - 1);
      for (t = 0; t < 3; ++t) {
        double* s = S + (size_t)t * FB;
        const double* sp = Sprev + (size_t)t * FB;
        const double* co = cold + (size_t)t * FB;
        const double* cn = cnew + (size_t)t * FB;
        double s0 = 0.0;
        uint32_t u;
        for (u = 0; u < k && u < FB && i + u < FA; ++u)
          s0 += CROW(i + u)[(size_t)t * FB + u];
        s[0] = s0;
        for (j = 1; j < FB; ++j) {
          double v = sp[j - 1] - co[j - 1];
          if (j + k - 1 < FB) v += cn[j + k - 1];
          s[j] = v;
        }
      }
    }
    dst = i == lo ? dcur : dnext;
    for (j = 0; j < FB; ++j)
      dst[j] = (float)cell_distance(w, i, j, S[j], S[FB + j], S[2u * FB + j],
                                    NULL);
    if (i > lo) {
      uint32_t r = i - 1;
      if (r >= w->r0 && r < w->r1)
        row_minima(w, r, r > lo ? dprev : NULL, dcur, dnext, Sprev,
                   Sprev + FB, Sprev + 2u * FB);
      if (w->failed) goto done;
      {
        float* old = dprev ? dprev : drow + 2u * FB;
        dprev = dcur;
        dcur = dnext;
        dnext = old;
      }
    }
    if (w->report_progress && job->report && (i & 15u) == 0)
      smgb_progress(job->report, (float)(i - lo + 1) / (float)(hi - lo + 1));
  }
  if (hi >= w->r0 && hi < w->r1 && hi == FA - 1)
    row_minima(w, hi, hi > lo ? dprev : NULL, dcur, NULL, S, S + FB,
               S + 2u * FB);
#undef CROW
done:
  free(cbuf);
  free(S);
  free(Sprev);
  free(drow);
  return NULL;
}

smg_result smgb_grid_minima(const smgb_grid_job* job, smgb_minimum** out,
                            uint32_t* out_count) {
  const smgb_cloud* A = job->rows;
  const smgb_cloud* B = job->cols;
  win_sums sa, sb;
  worker ws[8];
  uint32_t nt = job->threads ? job->threads : 1, t, total = 0, p;
  double* soa;
  double wsum = 0.0;
  smg_result res = SMG_OK;
  *out = NULL;
  *out_count = 0;
  if (A->frames == 0 || B->frames == 0 || job->window == 0) return SMG_OK;
  if (nt > 8) nt = 8;
  if (A->frames < 64u * nt) nt = 1;
  sa.sq = malloc(3u * A->frames * sizeof(double));
  sb.sq = malloc(3u * B->frames * sizeof(double));
  if (!sa.sq || !sb.sq) {
    free(sa.sq);
    free(sb.sq);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  sa.x = sa.sq + A->frames;
  sa.z = sa.x + A->frames;
  sb.x = sb.sq + B->frames;
  sb.z = sb.x + B->frames;
  if (!window_sums(A, job->window, &sa) || !window_sums(B, job->window, &sb)) {
    free(sa.sq);
    free(sb.sq);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (p = 0; p < A->points; ++p) wsum += A->weights[p];
  soa = malloc((size_t)B->frames * B->points * 3u * sizeof *soa);
  if (!soa) {
    free(sa.sq);
    free(sb.sq);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  {
    uint32_t f, q, ax;
    for (q = 0; q < B->points; ++q)
      for (ax = 0; ax < 3; ++ax)
        for (f = 0; f < B->frames; ++f)
          soa[(size_t)(3u * q + ax) * B->frames + f] =
              B->xyz[((size_t)f * B->points + q) * 3u + ax];
  }
  memset(ws, 0, sizeof ws);
  for (t = 0; t < nt; ++t) {
    ws[t].job = job;
    ws[t].A = &sa;
    ws[t].B = &sb;
    ws[t].soa = soa;
    ws[t].W = wsum * job->window;
    /* split at block boundaries (see SMGB_GRID_BLOCK) */
    uint32_t blocks = (A->frames + SMGB_GRID_BLOCK - 1) / SMGB_GRID_BLOCK;
    ws[t].r0 = (uint32_t)((uint64_t)blocks * t / nt) * SMGB_GRID_BLOCK;
    ws[t].r1 = (uint32_t)((uint64_t)blocks * (t + 1) / nt) * SMGB_GRID_BLOCK;
    if (ws[t].r1 > A->frames) ws[t].r1 = A->frames;
    ws[t].report_progress = t == 0;
  }
  if (!(ws[0].W > 0.0)) {
    free(soa);
    free(sa.sq);
    free(sb.sq);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  smgb_run_workers(ws, sizeof ws[0], nt, worker_run);
  for (t = 0; t < nt; ++t) {
    if (ws[t].failed) res = SMG_ERROR_OUT_OF_MEMORY;
    total += ws[t].count;
  }
  if (res == SMG_OK && total > 0) {
    *out = malloc((size_t)total * sizeof **out);
    if (!*out) res = SMG_ERROR_OUT_OF_MEMORY;
  }
  if (res == SMG_OK) {
    uint32_t at = 0;
    for (t = 0; t < nt; ++t) {
      if (ws[t].count) memcpy(*out + at, ws[t].out, ws[t].count * sizeof **out);
      at += ws[t].count;
    }
    *out_count = total;
  }
  for (t = 0; t < nt; ++t) free(ws[t].out);
  free(soa);
  free(sa.sq);
  free(sb.sq);
  return res;
}

double smgb_window_distance(const smgb_cloud* A, uint32_t i,
                            const smgb_cloud* B, uint32_t j, uint32_t k,
                            int align, double out_align[3]) {
  /* Direct evaluation: centre both windows on the floor, rotate B by the
   * optimal angle, sum squared distances. O(k P); used by tests as the
   * reference for the streamed grid. */
  uint32_t P = A->points, t, p;
  double W = 0, ax = 0, az = 0, bx = 0, bz = 0, a = 0, bb = 0, th = 0, D = 0;
  double c, s, tx, tz;
  for (t = 0; t < k; ++t)
    for (p = 0; p < P; ++p) {
      const double* va = A->xyz + ((size_t)(i + t) * P + p) * 3u;
      const double* vb = B->xyz + ((size_t)(j + t) * P + p) * 3u;
      double w = A->weights[p];
      W += w;
      ax += w * va[0]; az += w * va[2];
      bx += w * vb[0]; bz += w * vb[2];
    }
  if (!(W > 0)) return 0.0;
  ax /= W; az /= W; bx /= W; bz /= W;
  if (!align) { ax = az = bx = bz = 0.0; }
  for (t = 0; t < k; ++t)
    for (p = 0; p < P; ++p) {
      const double* va = A->xyz + ((size_t)(i + t) * P + p) * 3u;
      const double* vb = B->xyz + ((size_t)(j + t) * P + p) * 3u;
      double w = A->weights[p];
      double qx = va[0] - ax, qz = va[2] - az, rx = vb[0] - bx, rz = vb[2] - bz;
      a += w * (qx * rx + qz * rz);
      bb += w * (qx * rz - qz * rx);
    }
  if (align) th = atan2(bb, a);
  c = cos(th);
  s = sin(th);
  tx = ax - (bx * c + bz * s);
  tz = az - (-bx * s + bz * c);
  for (t = 0; t < k; ++t)
    for (p = 0; p < P; ++p) {
      const double* va = A->xyz + ((size_t)(i + t) * P + p) * 3u;
      const double* vb = B->xyz + ((size_t)(j + t) * P + p) * 3u;
      double w = A->weights[p];
      double x = vb[0] * c + vb[2] * s + tx, z = -vb[0] * s + vb[2] * c + tz;
      double dx = va[0] - x, dy = va[1] - vb[1], dz = va[2] - z;
      D += w * (dx * dx + dy * dy + dz * dz);
    }
  if (out_align) {
    out_align[0] = tx;
    out_align[1] = tz;
    out_align[2] = th;
  }
  return sqrt(D / W);
}
