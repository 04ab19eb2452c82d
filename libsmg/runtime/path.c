/*
 * path.c - the polyline a character follows: evaluation by arc length and
 * nearest-point projection. Arc lengths are precomputed when the path is
 * edited (character.c), so every query here is O(1) amortized: queries walk
 * from a segment hint and fall back to binary search for long jumps.
 */
#include <math.h>
#include <string.h>

#include "character_internal.h"

#define WALK_LIMIT 16u
#define PROJECT_LIMIT 256u

void smgi_path_reset(smgi_path* p) {
  p->count = 0;
  p->length = 0.0f;
}

/* Segment i spans points i..i+1 (0 <= i <= count - 2). */
static uint32_t find_segment(const smgi_path* p, float s, uint32_t hint) {
  uint32_t last = p->count - 2u;
  uint32_t i = hint > last ? last : hint;
  for (uint32_t k = 0; k < WALK_LIMIT; ++k) {
    if (s < p->cum[i] && i > 0) {
      --i;
    } else if (s > p->cum[i + 1u] && i < last) {
      ++i;
    } else {
      return i;
    }
  }
  /* far away: binary search for the last i with cum[i] <= s */
  uint32_t lo = 0, hi = last;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo + 1u) / 2u;
    if (p->cum[mid] <= s) lo = mid;
    else hi = mid - 1u;
  }
  return lo;
}

static float segment_heading(const smgi_path* p, uint32_t i) {
  /* zero-length segments have no direction: look at neighbours */
  uint32_t last = p->count - 2u;
  for (uint32_t k = 0; k < 8u; ++k) {
    uint32_t j = i + k <= last ? i + k : last;
    float dx = p->xz[2u * j + 2u] - p->xz[2u * j];
    float dz = p->xz[2u * j + 3u] - p->xz[2u * j + 1u];
    if (dx * dx + dz * dz > 1e-12f) return atan2f(dx, dz);
    if (i >= k + 1u) {
      j = i - k - 1u;
      dx = p->xz[2u * j + 2u] - p->xz[2u * j];
      dz = p->xz[2u * j + 3u] - p->xz[2u * j + 1u];
      if (dx * dx + dz * dz > 1e-12f) return atan2f(dx, dz);
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

#define PROJECT_TIE 0.02f /* metres: nearer passes within this are ties */

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
  for (uint32_t k = 0; k < PROJECT_LIMIT; ++k) {
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

/* Any inf or NaN among n floats. Branch-free so it runs at memory speed:
 * adding one to an all-ones exponent carries into the lane's top bit, and
 * two floats are checked per 64-bit word. */
int smgi_all_finite(const float* v, uint32_t n) {
  uint64_t bad = 0;
  uint32_t i = 0;
  for (; i + 2u <= n; i += 2u) {
    uint64_t bits;
    memcpy(&bits, &v[i], sizeof bits);
    bad |= (bits & 0x7f8000007f800000ull) + 0x0080000000800000ull;
  }
  if (i < n) {
    uint32_t bits;
    memcpy(&bits, &v[i], sizeof bits);
    bad |= (uint64_t)((bits & 0x7f800000u) + 0x00800000u);
  }
  return (bad & 0x8000000080000000ull) == 0;
}

float smgi_path_load(smgi_path* p, const float* xz, uint32_t from,
                     uint32_t count, int project, float px, float pz,
                     uint32_t* seg, float* out_dist) {
  /* One pass copies the points, accumulates arc lengths (double, so 10^5
   * points do not drift) and, when asked, finds the exact nearest point
   * to (px, pz): a segment can only be nearer than the best so far if its
   * start is within best + its length, so almost every segment is
   * rejected by one squared-distance compare. */
  if (count == 0) return 0.0f;
  float* dst = p->xz + 2u * from;
  float* cum = p->cum + from;
  double acc;
  float ax, az;
  uint32_t k = 0;
  if (from == 0) {
    dst[0] = xz[0];
    dst[1] = xz[1];
    cum[0] = 0.0f;
    acc = 0.0;
    k = 1;
  } else {
    acc = (double)p->cum[from - 1u];
  }
  /* the point before the first new segment (from + k >= 1 here) */
  ax = p->xz[2u * (from + k) - 2u];
  az = p->xz[2u * (from + k) - 1u];
  float best2 = INFINITY, best = INFINITY, s_best = 0.0f;
  uint32_t best_seg = 0;
  if (!project) {
    /* appending: copy and accumulate only (kept apart so this loop has no
     * branch at all) */
    for (; k < count; ++k) {
      float bx = xz[2u * k], bz = xz[2u * k + 1u];
      dst[2u * k] = bx;
      dst[2u * k + 1u] = bz;
      float dx = bx - ax, dz = bz - az;
      acc += (double)sqrtf(dx * dx + dz * dz);
      cum[k] = (float)acc;
      ax = bx;
      az = bz;
    }
  }
  for (; k < count; ++k) {
    float bx = xz[2u * k], bz = xz[2u * k + 1u];
    dst[2u * k] = bx;
    dst[2u * k + 1u] = bz;
    float dx = bx - ax, dz = bz - az;
    float len = sqrtf(dx * dx + dz * dz);
    acc += (double)len;
    cum[k] = (float)acc;
    float qx = px - ax, qz = pz - az;
    float h = best + len;
    if (qx * qx + qz * qz < h * h) {
      float sd;
      uint32_t sgi = from + k - 1u;
      float d2 = seg_dist2(p, sgi, px, pz, &sd);
      /* a later segment must be nearer by more than PROJECT_TIE: where
       * the path passes the character twice (a closed loop starts where
       * it ends) progress is the earliest pass, not float noise's pick */
      float t = best - PROJECT_TIE;
      if (d2 < best2 && (best2 == INFINITY || (t > 0.0f && d2 < t * t))) {
        best2 = d2;
        best = sqrtf(d2);
        s_best = sd;
        best_seg = sgi;
      }
    }
    ax = bx;
    az = bz;
  }
  uint32_t end = from + count;
  p->count = end;
  p->length = p->cum[end - 1u];
  if (!project) return 0.0f;
  if (end < 2u) return smgi_path_project_local(p, px, pz, seg, out_dist);
  *seg = best_seg;
  *out_dist = best;
  return s_best;
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
