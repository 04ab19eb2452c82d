/*
 * eval_metrics.c - see eval_metrics.h.
 */
#include "eval_metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define EM_PI 3.14159265358979323846

/* ---- statistics --------------------------------------------------------- */

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

double em_percentile_sorted(const double* sorted, size_t n, double q) {
  double pos, frac;
  size_t i;
  if (!sorted || !n || !(q >= 0.0 && q <= 100.0)) return NAN;
  pos = q / 100.0 * (double)(n - 1);
  i = (size_t)floor(pos);
  if (i + 1 >= n) return sorted[n - 1];
  frac = pos - (double)i;
  return sorted[i] + frac * (sorted[i + 1] - sorted[i]);
}

void em_stats_compute(const double* v, size_t n, double* scratch,
                      em_stats* out) {
  size_t i, k = 0;
  double sum = 0.0;
  if (!out) return;
  out->count = 0;
  out->mean = out->max = out->min = out->median = out->p99 = NAN;
  if (!v || !scratch) return;
  for (i = 0; i < n; ++i)
    if (isfinite(v[i])) scratch[k++] = v[i];
  if (!k) return;
  qsort(scratch, k, sizeof(double), cmp_double);
  for (i = 0; i < k; ++i) sum += scratch[i];
  out->count = k;
  out->mean = sum / (double)k;
  out->min = scratch[0];
  out->max = scratch[k - 1];
  out->median = em_percentile_sorted(scratch, k, 50.0);
  out->p99 = em_percentile_sorted(scratch, k, 99.0);
}

/* Centred second moments of the pairs (a[i], b[i]) where both are finite:
 * sums of (a-ma)^2, (a-ma)(b-mb), (b-mb)^2 and the means. Returns the
 * number of pairs used. */
static size_t paired_moments(const double* a, const double* b, size_t n,
                             double* saa, double* sab, double* sbb,
                             double* ma, double* mb) {
  size_t i, k = 0;
  *saa = *sab = *sbb = *ma = *mb = 0.0;
  for (i = 0; i < n; ++i)
    if (isfinite(a[i]) && isfinite(b[i])) {
      *ma += a[i];
      *mb += b[i];
      k++;
    }
  if (k < 2) return k;
  *ma /= (double)k;
  *mb /= (double)k;
  for (i = 0; i < n; ++i)
    if (isfinite(a[i]) && isfinite(b[i])) {
      *sab += (a[i] - *ma) * (b[i] - *mb);
      *saa += (a[i] - *ma) * (a[i] - *ma);
      *sbb += (b[i] - *mb) * (b[i] - *mb);
    }
  return k;
}

double em_pearson(const double* a, const double* b, size_t n) {
  double ma, mb, sab, saa, sbb;
  if (!a || !b) return NAN;
  if (paired_moments(a, b, n, &saa, &sab, &sbb, &ma, &mb) < 2) return NAN;
  if (!(saa > 0.0) || !(sbb > 0.0)) return NAN;
  return sab / sqrt(saa * sbb);
}

double em_linear_slope(const double* x, const double* y, size_t n,
                       double* out_intercept) {
  double mx, my, sxy, sxx, syy, b;
  if (out_intercept) *out_intercept = NAN;
  if (!x || !y) return NAN;
  if (paired_moments(x, y, n, &sxx, &sxy, &syy, &mx, &my) < 2) return NAN;
  if (!(sxx > 0.0)) return NAN;
  b = sxy / sxx;
  if (out_intercept) *out_intercept = my - b * mx;
  return b;
}

/* ---- paths -------------------------------------------------------------- */

double em_polyline_length(const double* xz, size_t n) {
  double len = 0.0;
  size_t i;
  if (!xz) return 0.0;
  for (i = 1; i < n; ++i)
    len += hypot(xz[2 * i] - xz[2 * i - 2], xz[2 * i + 1] - xz[2 * i - 1]);
  return len;
}

void em_polyline_point_at(const double* xz, size_t n, double s,
                          double* out_x, double* out_z) {
  size_t i;
  double acc = 0.0;
  if (!xz || !n || !out_x || !out_z) return;
  *out_x = xz[0];
  *out_z = xz[1];
  if (!(s > 0.0)) return;
  for (i = 1; i < n; ++i) {
    double dx = xz[2 * i] - xz[2 * i - 2], dz = xz[2 * i + 1] - xz[2 * i - 1];
    double seg = hypot(dx, dz);
    if (acc + seg >= s && seg > 0.0) {
      double t = (s - acc) / seg;
      *out_x = xz[2 * i - 2] + t * dx;
      *out_z = xz[2 * i - 1] + t * dz;
      return;
    }
    acc += seg;
  }
  *out_x = xz[2 * n - 2];
  *out_z = xz[2 * n - 1];
}

double em_polyline_distance(const double* xz, size_t n, double px,
                            double pz, double* out_arc) {
  return em_polyline_distance_window(xz, n, px, pz, -INFINITY, INFINITY,
                                     out_arc);
}

double em_polyline_distance_window(const double* xz, size_t n, double px,
                                   double pz, double lo, double hi,
                                   double* out_arc) {
  double best = INFINITY, best_arc = 0.0, acc = 0.0;
  size_t i;
  if (!xz || !n) return NAN;
  if (n == 1) {
    if (out_arc) *out_arc = 0.0;
    return hypot(px - xz[0], pz - xz[1]);
  }
  for (i = 1; i < n; ++i) {
    double ax = xz[2 * i - 2], az = xz[2 * i - 1];
    double dx = xz[2 * i] - ax, dz = xz[2 * i + 1] - az;
    double len2 = dx * dx + dz * dz, t = 0.0, d, len = sqrt(len2);
    double tlo = 0.0, thi = 1.0;
    if (acc > hi || acc + len < lo) {
      acc += len;
      continue;
    }
    if (len > 0.0) {
      if (lo > acc) tlo = (lo - acc) / len;
      if (hi < acc + len) thi = (hi - acc) / len;
    }
    if (len2 > 0.0) {
      t = ((px - ax) * dx + (pz - az) * dz) / len2;
    }
    if (t < tlo) t = tlo;
    if (t > thi) t = thi;
    d = hypot(px - (ax + t * dx), pz - (az + t * dz));
    if (d < best) {
      best = d;
      best_arc = acc + t * len;
    }
    acc += len;
  }
  if (out_arc) *out_arc = best_arc;
  return best;
}

void em_path_deviation(const double* path_xz, size_t n, const double* traj_xz,
                       size_t m, double* out_mean, double* out_max) {
  double sum = 0.0, mx = 0.0;
  size_t i, k = 0;
  for (i = 0; i < m; ++i) {
    double d =
        em_polyline_distance(path_xz, n, traj_xz[2 * i], traj_xz[2 * i + 1],
                             NULL);
    if (!isfinite(d)) continue;
    sum += d;
    if (d > mx) mx = d;
    k++;
  }
  if (out_mean) *out_mean = k ? sum / (double)k : NAN;
  if (out_max) *out_max = k ? mx : NAN;
}

/* A path under construction: position, heading, and the output buffer. */
typedef struct path_builder {
  double x, z, h;
  double* xz;
  size_t n, cap;
  double step;
} path_builder;

static void pb_emit(path_builder* b) {
  if (b->n < b->cap) {
    b->xz[2 * b->n] = b->x;
    b->xz[2 * b->n + 1] = b->z;
    b->n++;
  }
}

static void pb_straight(path_builder* b, double length) {
  size_t k, steps;
  double x0 = b->x, z0 = b->z;
  if (!(length > 0.0)) return;
  steps = (size_t)ceil(length / b->step);
  for (k = 1; k <= steps; ++k) {
    double s = length * (double)k / (double)steps;
    b->x = x0 + s * sin(b->h);
    b->z = z0 + s * cos(b->h);
    pb_emit(b);
  }
}

/* Arc of signed angle (positive = heading grows = turning left). */
static void pb_arc(path_builder* b, double radius, double angle) {
  size_t k, steps;
  double x0 = b->x, z0 = b->z, h0 = b->h, kappa, len;
  if (!(radius > 0.0) || angle == 0.0) return;
  len = radius * fabs(angle);
  kappa = (angle > 0 ? 1.0 : -1.0) / radius;
  steps = (size_t)ceil(len / b->step);
  for (k = 1; k <= steps; ++k) {
    double s = len * (double)k / (double)steps, h = h0 + kappa * s;
    b->x = x0 + (cos(h0) - cos(h)) / kappa;
    b->z = z0 + (sin(h) - sin(h0)) / kappa;
    b->h = h;
    pb_emit(b);
  }
  b->h = h0 + angle;
}

static int pb_init(path_builder* b, double step, double* xz, size_t cap) {
  if (!xz || !cap || !(step > 0.0)) return 0;
  memset(b, 0, sizeof(*b));
  b->xz = xz;
  b->cap = cap;
  b->step = step;
  pb_emit(b);
  return 1;
}

size_t em_path_straight(double length, double step, double* xz, size_t cap) {
  path_builder b;
  if (!pb_init(&b, step, xz, cap)) return 0;
  pb_straight(&b, length);
  return b.n;
}

size_t em_path_turn(double lead, double radius, double angle, double tail,
                    double step, double* xz, size_t cap) {
  path_builder b;
  if (!pb_init(&b, step, xz, cap)) return 0;
  pb_straight(&b, lead);
  pb_arc(&b, radius, angle);
  pb_straight(&b, tail);
  return b.n;
}

size_t em_path_s_curve(double lead, double radius, double angle, double tail,
                       double step, double* xz, size_t cap) {
  path_builder b;
  if (!pb_init(&b, step, xz, cap)) return 0;
  pb_straight(&b, lead);
  pb_arc(&b, radius, angle);
  pb_arc(&b, radius, -angle);
  pb_straight(&b, tail);
  return b.n;
}

size_t em_path_circle(double lead, double radius, double tail, double step,
                      double* xz, size_t cap) {
  path_builder b;
  if (!pb_init(&b, step, xz, cap)) return 0;
  pb_straight(&b, lead);
  pb_arc(&b, radius, 2.0 * EM_PI);
  pb_straight(&b, tail);
  return b.n;
}

/* ---- feet --------------------------------------------------------------- */

void em_detect_contacts(const double* pos, size_t n, double dt,
                        double height_margin, double max_speed,
                        uint8_t* out_contact) {
  double lowest = INFINITY;
  size_t i;
  if (!pos || !out_contact || !n) return;
  for (i = 0; i < n; ++i)
    if (isfinite(pos[3 * i + 1]) && pos[3 * i + 1] < lowest)
      lowest = pos[3 * i + 1];
  for (i = 0; i < n; ++i) {
    size_t a = i ? i - 1 : i, b = i + 1 < n ? i + 1 : i;
    double speed = 0.0;
    if (b > a && dt > 0.0) {
      double dx = pos[3 * b] - pos[3 * a], dy = pos[3 * b + 1] - pos[3 * a + 1];
      double dz = pos[3 * b + 2] - pos[3 * a + 2];
      speed = sqrt(dx * dx + dy * dy + dz * dz) / ((double)(b - a) * dt);
    }
    out_contact[i] = (uint8_t)(isfinite(pos[3 * i + 1]) &&
                               pos[3 * i + 1] <= lowest + height_margin &&
                               speed <= max_speed);
  }
}

void em_foot_skate(const double* pos, const uint8_t* contact, size_t n,
                   em_skate* out) {
  size_t i;
  if (!out) return;
  memset(out, 0, sizeof(*out));
  out->mean_cm = out->max_cm = NAN;
  if (!pos || !contact) return;
  for (i = 1; i < n; ++i) {
    double d;
    if (!contact[i] || !contact[i - 1]) continue;
    d = 100.0 * hypot(pos[3 * i] - pos[3 * i - 3],
                      pos[3 * i + 2] - pos[3 * i - 1]);
    if (!isfinite(d)) continue;
    if (!out->contact_frames || d > out->max_cm) out->max_cm = d;
    out->total_cm += d;
    out->contact_frames++;
  }
  if (out->contact_frames)
    out->mean_cm = out->total_cm / (double)out->contact_frames;
}

void em_foot_skate_lowest(const double* ankle, const double* toe,
                          const uint8_t* contact, size_t n, em_skate* out) {
  size_t i;
  if (!out) return;
  memset(out, 0, sizeof(*out));
  out->mean_cm = out->max_cm = NAN;
  if (!ankle || !toe || !contact) return;
  for (i = 1; i < n; ++i) {
    const double* p;
    double d;
    if (!contact[i] || !contact[i - 1]) continue;
    p = (toe[3 * i + 1] < ankle[3 * i + 1]) ? toe : ankle;
    d = 100.0 * hypot(p[3 * i] - p[3 * i - 3], p[3 * i + 2] - p[3 * i - 1]);
    if (!isfinite(d)) continue;
    if (!out->contact_frames || d > out->max_cm) out->max_cm = d;
    out->total_cm += d;
    out->contact_frames++;
  }
  if (out->contact_frames)
    out->mean_cm = out->total_cm / (double)out->contact_frames;
}

size_t em_footfalls(const uint8_t* contact, size_t n, size_t* out,
                    size_t cap) {
  size_t i, k = 0;
  if (!contact || !out) return 0;
  for (i = 1; i < n && k < cap; ++i)
    if (contact[i] && !contact[i - 1]) out[k++] = i;
  return k;
}

size_t em_first_label(const uint32_t* label, size_t n, size_t start,
                      uint32_t value) {
  size_t i;
  if (!label) return n;
  for (i = start; i < n; ++i)
    if (label[i] == value) return i;
  return n;
}

/* ---- phases ------------------------------------------------------------- */

double em_wrap_half(double c) {
  double w;
  if (!isfinite(c)) return NAN;
  w = c - floor(c + 0.5);
  if (w >= 0.5) w -= 1.0;
  return w;
}

void em_phase_from_footfalls(const size_t* falls, size_t count, size_t n,
                             double* out_phase) {
  size_t i, k;
  if (!out_phase) return;
  for (i = 0; i < n; ++i) out_phase[i] = NAN;
  if (!falls) return;
  for (k = 0; k + 1 < count; ++k) {
    size_t a = falls[k], b = falls[k + 1];
    if (b <= a || b > n) continue;
    for (i = a; i < b; ++i)
      out_phase[i] = (double)(i - a) / (double)(b - a);
  }
}

size_t em_circular_stats(const double* d, size_t n, double* out_mean,
                         double* out_std) {
  double c = 0.0, s = 0.0, r;
  size_t i, k = 0;
  for (i = 0; i < n; ++i)
    if (isfinite(d[i])) {
      c += cos(2.0 * EM_PI * d[i]);
      s += sin(2.0 * EM_PI * d[i]);
      k++;
    }
  if (!k) {
    if (out_mean) *out_mean = NAN;
    if (out_std) *out_std = NAN;
    return 0;
  }
  c /= (double)k;
  s /= (double)k;
  r = sqrt(c * c + s * s);
  if (out_mean) *out_mean = em_wrap_half(atan2(s, c) / (2.0 * EM_PI));
  /* Circular standard deviation sqrt(-2 ln R), converted to cycles. */
  if (out_std)
    *out_std = (r > 0.0 ? sqrt(-2.0 * log(r > 1.0 ? 1.0 : r)) : INFINITY) /
               (2.0 * EM_PI);
  return k;
}

void em_unwrap(const double* d, size_t n, double* out) {
  size_t i;
  double prev = NAN, offset = 0.0;
  for (i = 0; i < n; ++i) {
    if (!isfinite(d[i])) {
      out[i] = NAN;
      continue;
    }
    if (isfinite(prev)) {
      double jump = d[i] - prev;
      if (jump > 0.5) offset -= 1.0;
      if (jump < -0.5) offset += 1.0;
    }
    prev = d[i];
    out[i] = d[i] + offset;
  }
}

/* ---- rigid frames ------------------------------------------------------- */

void em_quat_rotate(const double q[4], const double v[3], double out[3]) {
  /* v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z). */
  double ux = q[0], uy = q[1], uz = q[2], w = q[3];
  double tx = 2.0 * (uy * v[2] - uz * v[1]);
  double ty = 2.0 * (uz * v[0] - ux * v[2]);
  double tz = 2.0 * (ux * v[1] - uy * v[0]);
  out[0] = v[0] + w * tx + (uy * tz - uz * ty);
  out[1] = v[1] + w * ty + (uz * tx - ux * tz);
  out[2] = v[2] + w * tz + (ux * ty - uy * tx);
}

void em_to_frame(const double o[3], const double q[4], const double p[3],
                 double out[3]) {
  double inv[4] = {-q[0], -q[1], -q[2], q[3]};
  double d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
  em_quat_rotate(inv, d, out);
}

void em_quat_from_matrix(const float m[16], double q[4]) {
  /* Column-major: element (row r, col c) is m[4 c + r]. */
  double m00 = m[0], m11 = m[5], m22 = m[10];
  double m01 = m[4], m02 = m[8], m10 = m[1], m12 = m[9], m20 = m[2],
         m21 = m[6];
  double tr = m00 + m11 + m22, s, n;
  if (tr > 0.0) {
    s = sqrt(tr + 1.0) * 2.0;
    q[3] = 0.25 * s;
    q[0] = (m21 - m12) / s;
    q[1] = (m02 - m20) / s;
    q[2] = (m10 - m01) / s;
  } else if (m00 > m11 && m00 > m22) {
    s = sqrt(1.0 + m00 - m11 - m22) * 2.0;
    q[3] = (m21 - m12) / s;
    q[0] = 0.25 * s;
    q[1] = (m01 + m10) / s;
    q[2] = (m02 + m20) / s;
  } else if (m11 > m22) {
    s = sqrt(1.0 + m11 - m00 - m22) * 2.0;
    q[3] = (m02 - m20) / s;
    q[0] = (m01 + m10) / s;
    q[1] = 0.25 * s;
    q[2] = (m12 + m21) / s;
  } else {
    s = sqrt(1.0 + m22 - m00 - m11) * 2.0;
    q[3] = (m10 - m01) / s;
    q[0] = (m02 + m20) / s;
    q[1] = (m12 + m21) / s;
    q[2] = 0.25 * s;
  }
  n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0.0) {
    q[0] /= n;
    q[1] /= n;
    q[2] /= n;
    q[3] /= n;
  }
}

double em_quat_angle(const double a[4], const double b[4]) {
  double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  if (d > 1.0) d = 1.0;
  return 2.0 * acos(d);
}

void em_quat_mul(const double a[4], const double b[4], double out[4]) {
  double r[4];
  r[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  r[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  r[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  r[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  memcpy(out, r, sizeof(r));
}

void em_fk(uint32_t joint_count, const int32_t* parents, const float* offsets,
           const float* pose, double* out_positions, double* out_rotations) {
  double rot_local[4 * 256];
  double* rot = out_rotations ? out_rotations : rot_local;
  uint32_t j;
  if (!parents || !offsets || !pose || !out_positions) return;
  if (!out_rotations && joint_count > 256) return;
  for (j = 0; j < joint_count; ++j) {
    double q[4], n;
    const float* lq = pose + 3 + 4 * j;
    q[0] = lq[0];
    q[1] = lq[1];
    q[2] = lq[2];
    q[3] = lq[3];
    n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n > 0.0) q[0] /= n, q[1] /= n, q[2] /= n, q[3] /= n;
    if (j == 0 || parents[j] < 0 || (uint32_t)parents[j] >= j) {
      memcpy(rot + 4 * j, q, sizeof(q));
      out_positions[3 * j] = pose[0];
      out_positions[3 * j + 1] = pose[1];
      out_positions[3 * j + 2] = pose[2];
    } else {
      uint32_t p = (uint32_t)parents[j];
      double off[3] = {offsets[3 * j], offsets[3 * j + 1], offsets[3 * j + 2]};
      double r[3];
      em_quat_rotate(rot + 4 * p, off, r);
      out_positions[3 * j] = out_positions[3 * p] + r[0];
      out_positions[3 * j + 1] = out_positions[3 * p + 1] + r[1];
      out_positions[3 * j + 2] = out_positions[3 * p + 2] + r[2];
      em_quat_mul(rot + 4 * p, q, rot + 4 * j);
    }
  }
}

void em_ground_frame(const double root_pos[3], const double root_rot[4],
                     double out_origin[3], double out_rot[4]) {
  double fwd[3], z[3] = {0, 0, 1}, h;
  em_quat_rotate(root_rot, z, fwd);
  h = atan2(fwd[0], fwd[2]);
  out_origin[0] = root_pos[0];
  out_origin[1] = 0.0;
  out_origin[2] = root_pos[2];
  out_rot[0] = 0.0;
  out_rot[1] = sin(0.5 * h);
  out_rot[2] = 0.0;
  out_rot[3] = cos(0.5 * h);
}

double em_mean_joint_error(const double* a, const double* b, size_t k,
                           double norm) {
  double sum = 0.0;
  size_t j;
  if (!a || !b || !k || !(norm > 0.0)) return NAN;
  for (j = 0; j < k; ++j) {
    double dx = a[3 * j] - b[3 * j], dy = a[3 * j + 1] - b[3 * j + 1];
    double dz = a[3 * j + 2] - b[3 * j + 2];
    sum += sqrt(dx * dx + dy * dy + dz * dz);
  }
  return sum / (double)k / norm;
}
