/*
 * eval_feet_geom.c - planted-toe speed and lowest toe height from world toe
 * positions (definitions in eval_feet_geom.h).
 */
#include "eval_feet_geom.h"

#include <math.h>
#include <stdlib.h>

#include "eval_metrics.h"

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

double eval_feet_floor_level(const double* pos, size_t stride, size_t n) {
  double* h;
  double level;
  size_t i, k = 0;
  if (!pos || n == 0 || stride < 3) return NAN;
  h = (double*)malloc(n * sizeof *h);
  if (!h) return NAN;
  for (i = 0; i < n; ++i) {
    double y = pos[i * stride + 1];
    if (isfinite(y)) h[k++] = y;
  }
  if (k == 0) {
    free(h);
    return NAN;
  }
  qsort(h, k, sizeof *h, cmp_double);
  level = em_percentile_sorted(h, k, EVAL_FEET_FLOOR_PERCENTILE);
  free(h);
  return level;
}

static void clear(eval_feet_geom* out, size_t n) {
  out->frames = n;
  out->planted_pairs = 0;
  out->mean_cms = out->p95_cms = out->p99_cms = out->max_cms = NAN;
  out->lowest_cm = NAN;
}

/* Planted over (i-1, i): both frames within the band of the floor. */
static int planted(const double* a, const double* b, double level) {
  return fabs(a[1] - level) <= EVAL_FEET_PLANT_BAND_M &&
         fabs(b[1] - level) <= EVAL_FEET_PLANT_BAND_M;
}

int eval_feet_geom_measure(const double* const* toes, size_t toe_count,
                           size_t stride, size_t n, double dt,
                           double* per_frame, eval_feet_geom* out) {
  double* speeds;
  double lowest = INFINITY, sum = 0.0;
  size_t i, k, m = 0;
  if (!out) return -1;
  clear(out, n);
  if (!toes || toe_count == 0 || stride < 3 || !(dt > 0.0)) return -1;
  for (k = 0; k < toe_count; ++k)
    if (!toes[k]) return -1;
  if (per_frame)
    for (i = 0; i < n * toe_count; ++i) per_frame[i] = NAN;
  if (n == 0) return 0;
  speeds = (double*)malloc(n * toe_count * sizeof *speeds);
  if (!speeds) return -1;
  for (k = 0; k < toe_count; ++k) {
    const double* p = toes[k];
    double level = eval_feet_floor_level(p, stride, n);
    for (i = 0; i < n; ++i)
      if (isfinite(p[i * stride + 1]) && p[i * stride + 1] < lowest)
        lowest = p[i * stride + 1];
    if (!isfinite(level)) continue;
    for (i = 1; i < n; ++i) {
      const double* a = p + (i - 1) * stride;
      const double* b = p + i * stride;
      double dx = b[0] - a[0], dz = b[2] - a[2], v;
      if (!planted(a, b, level)) continue;
      v = 100.0 * sqrt(dx * dx + dz * dz) / dt;
      if (!isfinite(v)) continue;
      speeds[m++] = v;
      sum += v;
      if (per_frame) per_frame[i * toe_count + k] = v;
    }
  }
  if (isfinite(lowest)) out->lowest_cm = 100.0 * lowest;
  out->planted_pairs = m;
  if (m > 0) {
    qsort(speeds, m, sizeof *speeds, cmp_double);
    out->mean_cms = sum / (double)m;
    out->p95_cms = em_percentile_sorted(speeds, m, 95.0);
    out->p99_cms = em_percentile_sorted(speeds, m, 99.0);
    out->max_cms = speeds[m - 1];
  }
  free(speeds);
  return 0;
}
