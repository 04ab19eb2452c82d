/*
 * path.c - the polyline a character follows: evaluation by arc length and
 * nearest-point projection. Arc lengths are precomputed when the path is
 * edited (character.c), so every query here is O(1) amortized: queries walk
 * from a segment hint and fall back to binary search for long jumps.
 */
#include <math.h>
#include <string.h>

#include "path.h"
#include "rmath.h"
#include "tuning.h"

void smgi_path_reset(smgi_path* p) {
  p->count = 0;
  p->length = 0.0f;
}

/* Last segment index in [lo, hi] whose start arc length is <= s; the
 * caller guarantees cum[lo] <= s. */
static uint32_t last_at_or_before(const smgi_path* p, float s, uint32_t lo,
                                  uint32_t hi) {
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo + 1u) / 2u;
    if (p->cum[mid] <= s) lo = mid;
    else hi = mid - 1u;
  }
  return lo;
}

/* Segment i spans points i..i+1 (0 <= i <= count - 2). Queries move a
 * little at a time, so a short walk from the hint usually ends it; past
 * that the search starts from where s would be on evenly spaced points,
 * gallops from there (steps 1, 2, 4, ...) and bisects the bracket:
 * O(log distance) instead of a whole-path bisection, which on a dense path
 * (10^5 points a centimetre apart, where a search sample 0.5 m on is 50
 * segments away) was a fifth of an edit frame. The answer
 * past the walk is the same as a whole-path bisection's: the last i with
 * cum[i] <= s. */
static uint32_t find_segment(const smgi_path* p, float s, uint32_t hint) {
  uint32_t last = p->count - 2u;
  uint32_t i = hint > last ? last : hint;
  for (uint32_t k = 0; k < SMGI_PATH_WALK_LIMIT; ++k) {
    if (s < p->cum[i] && i > 0) {
      --i;
    } else if (s > p->cum[i + 1u] && i < last) {
      ++i;
    } else {
      return i;
    }
  }
  /* jump to where s would be if the points were evenly spaced: on a
   * dense, evenly drawn path the gallop then ends after a probe or two */
  if (p->length > 0.0f) {
    float g = (s / p->length) * (float)(last + 1u);
    i = g <= 0.0f ? 0u : g >= (float)last ? last : (uint32_t)g;
  }
  if (s < p->cum[i]) {
    /* behind: cum[ub] > s; cum[0] = 0 <= s (s is clamped to >= 0) */
    uint32_t ub = i, step = 1u, lb = 0u;
    for (;;) {
      lb = ub > step ? ub - step : 0u;
      if (lb == 0u || p->cum[lb] <= s) break;
      ub = lb;
      step *= 2u;
    }
    return last_at_or_before(p, s, lb, ub - 1u);
  }
  /* ahead (or here): cum[lb] <= s */
  uint32_t lb = i, step = 1u;
  for (;;) {
    uint32_t probe = last - lb > step ? lb + step : last;
    if (probe == lb || p->cum[probe] > s)
      return last_at_or_before(p, s, lb, probe == lb ? lb : probe - 1u);
    lb = probe;
    step *= 2u;
  }
}

static float segment_heading(const smgi_path* p, uint32_t i) {
  /* zero-length segments have no direction: look at neighbours */
  uint32_t last = p->count - 2u;
  for (uint32_t k = 0; k < 8u; ++k) {
    uint32_t j = i + k <= last ? i + k : last;
    float dx = p->xz[2u * j + 2u] - p->xz[2u * j];
    float dz = p->xz[2u * j + 3u] - p->xz[2u * j + 1u];
    if (dx * dx + dz * dz > 1e-12f) return smgi_atan2f(dx, dz);
    if (i >= k + 1u) {
      j = i - k - 1u;
      dx = p->xz[2u * j + 2u] - p->xz[2u * j];
      dz = p->xz[2u * j + 3u] - p->xz[2u * j + 1u];
      if (dx * dx + dz * dz > 1e-12f) return smgi_atan2f(dx, dz);
    }
  }
  return 0.0f;
}

void smgi_path_eval(const smgi_path* p, float s, uint32_t* seg, float* x,
                    float* z, float* heading) {
  if (p->count == 0) {
    *x = *z = 0.0f;
    if (heading) *heading = 0.0f;
    return;
  }
  if (p->count == 1) {
    *x = p->xz[0];
    *z = p->xz[1];
    if (heading) *heading = 0.0f;
    *seg = 0;
    return;
  }
  if (s < 0.0f) s = 0.0f;
  if (s > p->length) s = p->length;
  uint32_t i = find_segment(p, s, *seg);
  *seg = i;
  float len = p->cum[i + 1u] - p->cum[i];
  float u = len > 1e-9f ? (s - p->cum[i]) / len : 0.0f;
  u = smgi_clampf(u, 0.0f, 1.0f);
  const float* a = &p->xz[2u * i];
  *x = a[0] + u * (a[2] - a[0]);
  *z = a[1] + u * (a[3] - a[1]);
  if (heading) *heading = segment_heading(p, i);
}

uint32_t smgi_path_find(const smgi_path* p, float s, uint32_t hint) {
  if (p->count < 2u) return 0u;
  if (s < 0.0f) s = 0.0f;
  if (s > p->length) s = p->length;
  return find_segment(p, s, hint);
}

float smgi_path_heading(const smgi_path* p, uint32_t seg) {
  if (p->count < 2u) return 0.0f;
  return segment_heading(p, seg <= p->count - 2u ? seg : p->count - 2u);
}

/* Squared distance from (x, z) to segment i and the arc length there. */
static float seg_dist2(const smgi_path* p, uint32_t i, float x, float z,
                       float* s) {
  const float* a = &p->xz[2u * i];
  float dx = a[2] - a[0], dz = a[3] - a[1];
  float l2 = dx * dx + dz * dz;
  float u = 0.0f;
  if (l2 > 1e-18f) u = smgi_clampf(((x - a[0]) * dx + (z - a[1]) * dz) / l2,
                                   0.0f, 1.0f);
  float px = a[0] + u * dx - x, pz = a[1] + u * dz - z;
  *s = p->cum[i] + u * (p->cum[i + 1u] - p->cum[i]);
  return px * px + pz * pz;
}

float smgi_path_project_local(const smgi_path* p, float x, float z,
                              uint32_t* seg, float* out_dist) {
  if (p->count == 0) {
    *out_dist = 0.0f;
    return 0.0f;
  }
  if (p->count == 1) {
    float dx = x - p->xz[0], dz = z - p->xz[1];
    *out_dist = sqrtf(dx * dx + dz * dz);
    *seg = 0;
    return 0.0f;
  }
  uint32_t last = p->count - 2u;
  uint32_t i = *seg > last ? last : *seg;
  float s_best;
  float d_best = seg_dist2(p, i, x, z, &s_best);
  /* descend towards the nearer neighbour until neither improves; ties
   * move forward so progress never stalls on zero-length segments */
  for (uint32_t k = 0; k < SMGI_PATH_PROJECT_LIMIT; ++k) {
    float s_n, s_p;
    float d_n = i < last ? seg_dist2(p, i + 1u, x, z, &s_n) : INFINITY;
    float d_p = i > 0 ? seg_dist2(p, i - 1u, x, z, &s_p) : INFINITY;
    if (d_n <= d_best && d_n <= d_p) {
      ++i;
      d_best = d_n;
      s_best = s_n;
    } else if (d_p < d_best) {
      --i;
      d_best = d_p;
      s_best = s_p;
    } else {
      break;
    }
  }
  *seg = i;
  *out_dist = sqrtf(d_best);
  return s_best;
}

float smgi_path_project_ahead(const smgi_path* p, float x, float z,
                              uint32_t* seg, float* out_dist, float off,
                              float ahead) {
  float s = smgi_path_project_local(p, x, z, seg, out_dist);
  if (!(*out_dist > off) || p->count < 2u) return s;
  const float tie = *out_dist - SMGI_PATH_PROJECT_TIE;
  float d2_best = tie > 0.0f ? tie * tie : 0.0f;
  uint32_t best = *seg;
  float s_best = s;
  for (uint32_t i = *seg + 1u; i + 1u < p->count && p->cum[i] <= s + ahead;
       ++i) {
    float si;
    const float d2 = seg_dist2(p, i, x, z, &si);
    if (d2 < d2_best) {
      d2_best = d2;
      best = i;
      s_best = si;
    }
  }
  if (best == *seg) return s;
  *seg = best;
  *out_dist = sqrtf(d2_best);
  return s_best;
}

/* Every one of n floats finite and below SMG_MAX_COORDINATE (2^20) in
 * magnitude, branch-free so it runs at memory speed: adding 109 to the
 * 8-bit exponent carries into the word's top bit exactly when the
 * exponent is 127 + 20 or more (|v| >= 2^20, inf, NaN). Blocks of 16
 * words with size_t indices are a shape GCC's -O2 vectorizer takes (four
 * or more words per instruction). */
#define SMGI_COORD_CARRY (109u << 23)
int smgi_coords_ok(const float* v, uint32_t count) {
  const size_t n = count;
  size_t i = 0;
  uint32_t bad = 0;
  for (; i + 16u <= n; i += 16u) {
    uint32_t w[16];
    memcpy(w, v + i, sizeof w);
    for (size_t k = 0; k < 16u; ++k)
      bad |= (w[k] & 0x7f800000u) + SMGI_COORD_CARRY;
  }
  for (; i < n; ++i) {
    uint32_t w;
    memcpy(&w, v + i, sizeof w);
    bad |= (w & 0x7f800000u) + SMGI_COORD_CARRY;
  }
  return (bad & 0x80000000u) == 0;
}

/* Segments per block of the projection's coarse pass. */
#define PROJECT_BLOCK 32u

/* Exact nearest point to (px, pz) over segments [first, last] (arc
 * lengths already summed). A segment can only replace the best so far if
 * it is nearer than t = best - SMGI_PATH_PROJECT_TIE (a later pass must be nearer by
 * more than that: where the path passes the character twice, as a closed
 * loop does, progress is the earliest pass, not float noise's pick), and
 * it can only be that near if its start is within t + its length; once
 * t <= 0 nothing can. Coarse pass: a block of PROJECT_BLOCK segments lies
 * within its path length of its first point, so one compare rejects the
 * whole block; only blocks that pass are refined segment by segment. The
 * rejections only skip segments that cannot win, so the answer is that of
 * testing every segment in order (lengths from arc-length differences get
 * a slack for float rounding). Returns the arc length there; *out_seg and
 * *out_dist get the segment and the distance. */
static float nearest_segment(const smgi_path* p, uint32_t first,
                             uint32_t last, float px, float pz,
                             uint32_t* out_seg, float* out_dist) {
  const float* X = p->xz;
  const float* cum = p->cum;
  const float slack = 1e-6f + 4e-7f * cum[last + 1u];
  float best2 = INFINITY, best = INFINITY, s_best = cum[first], t = INFINITY;
  uint32_t best_seg = first;
  for (uint32_t b = first; b <= last; b += PROJECT_BLOCK) {
    uint32_t e = last - b >= PROJECT_BLOCK ? b + PROJECT_BLOCK - 1u : last;
    float qx = px - X[2u * b], qz = pz - X[2u * b + 1u];
    float hb = t + (cum[e + 1u] - cum[b]) + slack;
    if (qx * qx + qz * qz >= hb * hb) continue;
    for (uint32_t i = b; i <= e; ++i) {
      qx = px - X[2u * i];
      qz = pz - X[2u * i + 1u];
      float h = t + (cum[i + 1u] - cum[i]) + slack;
      if (qx * qx + qz * qz >= h * h) continue;
      float si;
      float d2 = seg_dist2(p, i, px, pz, &si);
      if (d2 < best2 && (best2 == INFINITY || d2 < t * t)) {
        best2 = d2;
        best = sqrtf(d2);
        s_best = si;
        best_seg = i;
        t = best - SMGI_PATH_PROJECT_TIE;
        if (t <= 0.0f) { /* on the path: no later pass can win */
          b = last;      /* ends the outer loop after this block */
          break;
        }
      }
    }
  }
  *out_seg = best_seg;
  *out_dist = best;
  return s_best;
}

/* out[k] = length of the segment from point k to point k + 1 of P (x, z
 * interleaved). Blocks of eight with size_t indices are a shape GCC's -O2
 * vectorizer takes (four or eight square roots per instruction); the
 * arithmetic is the same per element, so are the bits. */
static void segment_lengths(const float* restrict P, float* restrict out,
                            size_t n) {
  size_t k = 0;
  for (; k + 8u <= n; k += 8u) {
    for (size_t i = 0; i < 8u; ++i) {
      float dx = P[2u * (k + i) + 2u] - P[2u * (k + i)];
      float dz = P[2u * (k + i) + 3u] - P[2u * (k + i) + 1u];
      out[k + i] = sqrtf(dx * dx + dz * dz);
    }
  }
  for (; k < n; ++k) {
    float dx = P[2u * k + 2u] - P[2u * k];
    float dz = P[2u * k + 3u] - P[2u * k + 1u];
    out[k] = sqrtf(dx * dx + dz * dz);
  }
}

float smgi_path_load(smgi_path* p, const float* xz, uint32_t from,
                     uint32_t count, int project, float px, float pz,
                     uint32_t* seg, float* out_dist) {
  /* Separate tight passes rather than one loop doing everything: copy;
   * segment lengths (independent per segment, vectorized); the arc
   * length prefix sum, the only loop-carried chain, accumulated in double
   * (so 10^5 points do not drift) in four interleaved chains over four
   * quarters so the adds overlap instead of waiting on each other; then,
   * when asked, the projection (coarse blocks, see nearest_segment). Sums
   * of float lengths in double are exact for any real path (its total and
   * its shortest segment are well within double's 53 bits of each other),
   * so the split gives the same bits as one running sum. */
  if (count == 0) return 0.0f;
  const uint32_t end = from + count;
  float* X = p->xz;
  float* cum = p->cum;
  memcpy(X + 2u * from, xz, sizeof(float) * 2u * count);
  const uint32_t j0 = from > 0u ? from : 1u; /* first new segment's end */
  segment_lengths(X + 2u * (j0 - 1u), cum + j0, end - j0);
  /* prefix sum of cum[j0 .. end) on top of cum[j0 - 1] */
  if (from == 0u) cum[0] = 0.0f;
  {
    const uint32_t n = end - j0, q = n / 4u;
    double base = (double)cum[j0 - 1u];
    if (q >= 64u) {
      /* quarter totals (independent chains), then four running sums each
       * from its quarter's base */
      double t0 = 0.0, t1 = 0.0, t2 = 0.0;
      const float *c0 = cum + j0, *c1 = c0 + q, *c2 = c1 + q;
      for (uint32_t k = 0; k < q; ++k) {
        t0 += (double)c0[k];
        t1 += (double)c1[k];
        t2 += (double)c2[k];
      }
      double a0 = base, a1 = base + t0, a2 = a1 + t1, a3 = a2 + t2;
      float *o0 = cum + j0, *o1 = o0 + q, *o2 = o1 + q, *o3 = o2 + q;
      for (uint32_t k = 0; k < q; ++k) {
        a0 += (double)o0[k];
        a1 += (double)o1[k];
        a2 += (double)o2[k];
        a3 += (double)o3[k];
        o0[k] = (float)a0;
        o1[k] = (float)a1;
        o2[k] = (float)a2;
        o3[k] = (float)a3;
      }
      for (uint32_t k = q; k < n - 3u * q; ++k) {
        a3 += (double)o3[k];
        o3[k] = (float)a3;
      }
    } else {
      for (uint32_t j = j0; j < end; ++j) {
        base += (double)cum[j];
        cum[j] = (float)base;
      }
    }
  }
  p->count = end;
  p->length = cum[end - 1u];
  if (!project) return 0.0f;
  if (end < 2u) return smgi_path_project_local(p, px, pz, seg, out_dist);
  return nearest_segment(p, j0 - 1u, end - 2u, px, pz, seg, out_dist);
}

float smgi_path_project_global(const smgi_path* p, float x, float z,
                               uint32_t* seg, float* out_dist) {
  if (p->count < 2u) return smgi_path_project_local(p, x, z, seg, out_dist);
  uint32_t best = 0;
  float s_best = 0.0f, d_best = INFINITY;
  for (uint32_t i = 0; i + 1u < p->count; ++i) {
    float s;
    float d = seg_dist2(p, i, x, z, &s);
    if (d < d_best) {
      d_best = d;
      s_best = s;
      best = i;
    }
  }
  *seg = best;
  *out_dist = sqrtf(d_best);
  return s_best;
}
