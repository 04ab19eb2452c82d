/*
 * eval_gait.c - swings, window speeds and pelvis facing from joint world
 * positions and rotations (definitions in eval_gait.h).
 */
#include "eval_gait.h"

#include <math.h>
#include <stdlib.h>

#include "eval_feet_geom.h"
#include "eval_metrics.h"

#define PI 3.14159265358979323846

int eval_gait_floor_levels(const double* toe, size_t stride, size_t n,
                           double dt, double* level) {
  double floor_now;
  size_t i;
  int still = 0;
  if (!toe || !level || stride < 3 || !(dt > 0.0)) return -1;
  floor_now = eval_feet_floor_level(toe, stride, n);
  for (i = 0; i < n; ++i) {
    const size_t a = i > 0 ? i - 1 : i, b = i + 1 < n ? i + 1 : i;
    const double y = toe[i * stride + 1];
    int now = 0;
    if (b > a && isfinite(y))
      now = hypot(toe[b * stride] - toe[a * stride],
                  toe[b * stride + 2] - toe[a * stride + 2]) /
                ((double)(b - a) * dt) <
            EVAL_GAIT_STILL_MS;
    if (now && (!still || y < floor_now)) floor_now = y;
    still = now;
    level[i] = floor_now;
  }
  return 0;
}

size_t eval_gait_swings(const double* toe, size_t stride, size_t first,
                        size_t last, const double* level, double dt,
                        double* out, size_t cap) {
  const size_t min_frames = (size_t)ceil(EVAL_GAIT_SWING_MIN_S / dt - 1e-9);
  size_t i, start = 0, count = 0;
  int up = 0;
  if (!toe || !level || !out || stride < 3 || !(dt > 0.0)) return 0;
  for (i = first; i <= last && count < cap; ++i) {
    int lifted = i < last && isfinite(level[i]) &&
                 toe[i * stride + 1] > level[i] + EVAL_GAIT_SWING_M;
    if (lifted && !up) {
      up = 1;
      start = i;
    } else if (!lifted && up) {
      up = 0;
      if (i - start >= min_frames) out[count++] = (double)(i - start) * dt;
    }
  }
  return count;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

double eval_gait_median(double* v, size_t n) {
  if (!v || n == 0) return NAN;
  qsort(v, n, sizeof *v, cmp_double);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double eval_gait_window_speed(const double* hips, size_t stride, size_t n,
                              size_t i, size_t half, double dt) {
  size_t a = i > half ? i - half : 0, b = i + half, k;
  double len = 0.0;
  if (!hips || i >= n || !(dt > 0.0)) return NAN;
  if (b >= n) b = n - 1;
  if (b <= a) return NAN;
  for (k = a + 1; k <= b; ++k)
    len += hypot(hips[k * stride] - hips[(k - 1) * stride],
                 hips[k * stride + 2] - hips[(k - 1) * stride + 2]);
  return len / ((double)(b - a) * dt);
}

double eval_gait_travel_heading(const double* hips, size_t stride, size_t a,
                                size_t b) {
  double dx, dz;
  if (!hips) return NAN;
  dx = hips[b * stride] - hips[a * stride];
  dz = hips[b * stride + 2] - hips[a * stride + 2];
  if (hypot(dx, dz) < 1e-3) return NAN;
  return atan2(dx, dz);
}

int eval_gait_calibrate_forward(const double* q, const double* travel,
                                size_t n, double out_axis[3]) {
  double sum[3] = {0.0, 0.0, 0.0}, len;
  size_t i, used = 0;
  if (!q || !travel || !out_axis) return -1;
  for (i = 0; i < n; ++i) {
    const double* r = q + 4 * i;
    double inv[4], d[3], local[3];
    if (!isfinite(travel[i])) continue;
    inv[0] = -r[0], inv[1] = -r[1], inv[2] = -r[2], inv[3] = r[3];
    d[0] = sin(travel[i]), d[1] = 0.0, d[2] = cos(travel[i]);
    em_quat_rotate(inv, d, local);
    sum[0] += local[0], sum[1] += local[1], sum[2] += local[2];
    ++used;
  }
  len = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  if (!used || !(len > 1e-9)) return -1;
  for (i = 0; i < 3; ++i) out_axis[i] = sum[i] / len;
  return 0;
}

double eval_gait_facing(const double q[4], const double axis[3]) {
  double w[3];
  if (!q || !axis) return NAN;
  em_quat_rotate(q, axis, w);
  if (hypot(w[0], w[2]) < 1e-6) return NAN;
  return atan2(w[0], w[2]);
}

/* Horizontal distance of the hips from frame k to frame k + 1. */
static double step_length(const double* hips, size_t stride, size_t k) {
  const double* h = hips + k * stride;
  return hypot(h[stride] - h[0], h[stride + 2] - h[2]);
}

double eval_gait_window_facing(const double* q, const double* hips,
                               size_t stride, size_t a, size_t b,
                               const double axis[3]) {
  double sx = 0.0, sz = 0.0;
  size_t k;
  if (!q || !hips || !axis || b < a) return NAN;
  for (k = a; k <= b; ++k) {
    double w = 0.0, f = eval_gait_facing(q + 4 * k, axis);
    if (k > a) w += 0.5 * step_length(hips, stride, k - 1);
    if (k < b) w += 0.5 * step_length(hips, stride, k);
    if (!isfinite(f)) continue;
    sx += w * sin(f);
    sz += w * cos(f);
  }
  return hypot(sx, sz) > 1e-9 ? atan2(sx, sz) : NAN;
}

double eval_gait_angle_diff(double a, double b) {
  double d = fmod(a - b + PI, 2.0 * PI);
  if (d < 0.0) d += 2.0 * PI;
  return d - PI;
}

double eval_gait_rotation_range_deg(const double* q, size_t stride,
                                    size_t n) {
  double best = 0.0;
  size_t i, k;
  if (!q || stride < 4) return NAN;
  for (i = 0; i < n; ++i)
    for (k = i + 1; k < n; ++k) {
      double a = em_quat_angle(q + i * stride, q + k * stride);
      if (a > best) best = a;
    }
  return best * 180.0 / PI;
}
