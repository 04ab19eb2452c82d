/*
 * bake_import_util.h - small helpers shared by the importers and clip
 * processing (bake_bvh.c, bake_assimp.c, bake_clip.c, bake_synthetic.c):
 * double-precision quaternion math and error formatting.
 *
 * Everything is static inline so each translation unit stays independent and
 * no extra symbols appear in libsmg_bake.a. Quaternions are (x, y, z, w) and
 * rotate column vectors: v' = q v q*. Products compose like matrices:
 * quat_mul(a, b) rotates by b first, then by a.
 */
#ifndef BAKE_IMPORT_UTIL_H
#define BAKE_IMPORT_UTIL_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "bake_report.h"
#include "printf_check.h"

#define SMGB_PI 3.14159265358979323846

/* Printf into err->message (err may be NULL). */
static inline void smgb_imp_errorf(smgb_error* err, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;
static inline void smgb_imp_errorf(smgb_error* err, const char* fmt, ...) {
  va_list ap;
  if (!err) return;
  va_start(ap, fmt);
  vsnprintf(err->message, sizeof err->message, fmt, ap);
  va_end(ap);
}

static inline void smgb_qmul(const double a[4], const double b[4], double o[4]) {
  double r[4];
  r[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  r[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  r[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  r[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  o[0] = r[0]; o[1] = r[1]; o[2] = r[2]; o[3] = r[3];
}

/* Rotate v by unit quaternion q (o may alias v). */
static inline void smgb_qrot(const double q[4], const double v[3], double o[3]) {
  /* t = 2 * cross(q.xyz, v); o = v + w t + cross(q.xyz, t) */
  double tx = 2.0 * (q[1] * v[2] - q[2] * v[1]);
  double ty = 2.0 * (q[2] * v[0] - q[0] * v[2]);
  double tz = 2.0 * (q[0] * v[1] - q[1] * v[0]);
  double r0 = v[0] + q[3] * tx + (q[1] * tz - q[2] * ty);
  double r1 = v[1] + q[3] * ty + (q[2] * tx - q[0] * tz);
  double r2 = v[2] + q[3] * tz + (q[0] * ty - q[1] * tx);
  o[0] = r0; o[1] = r1; o[2] = r2;
}

/* Normalise; a zero or non-finite quaternion becomes identity. */
static inline void smgb_qnormalize(double q[4]) {
  double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 1e-300) || !isfinite(n)) {
    q[0] = q[1] = q[2] = 0.0;
    q[3] = 1.0;
    return;
  }
  q[0] /= n; q[1] /= n; q[2] /= n; q[3] /= n;
}

/* Rotation of `radians` about coordinate axis 0 (x), 1 (y) or 2 (z). */
static inline void smgb_qaxis(int axis, double radians, double q[4]) {
  double s = sin(0.5 * radians);
  q[0] = q[1] = q[2] = 0.0;
  q[axis] = s;
  q[3] = cos(0.5 * radians);
}

/* Rotation about an arbitrary unit axis. */
static inline void smgb_qaxis_angle(const double axis[3], double radians,
                                    double q[4]) {
  double s = sin(0.5 * radians);
  q[0] = axis[0] * s; q[1] = axis[1] * s; q[2] = axis[2] * s;
  q[3] = cos(0.5 * radians);
}

/* Shortest-path slerp between unit quaternions (falls back to nlerp when the
 * two are nearly equal, where slerp's division is ill-conditioned). */
static inline void smgb_qslerp(const double a[4], const double b[4], double t,
                               double o[4]) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  double bb[4] = {b[0], b[1], b[2], b[3]};
  double wa, wb;
  int i;
  if (d < 0.0) {
    d = -d;
    bb[0] = -b[0]; bb[1] = -b[1]; bb[2] = -b[2]; bb[3] = -b[3];
  }
  if (d > 0.9995) {
    wa = 1.0 - t;
    wb = t;
  } else {
    double th = acos(d), s = sin(th);
    wa = sin((1.0 - t) * th) / s;
    wb = sin(t * th) / s;
  }
  for (i = 0; i < 4; ++i) o[i] = wa * a[i] + wb * bb[i];
  smgb_qnormalize(o);
}

/* Euler angles (radians) such that R(q) = Rz(z) * Ry(y) * Rx(x), i.e. the BVH
 * channel order "Zrotation Yrotation Xrotation". */
static inline void smgb_qto_euler_zyx(const double q[4], double* z, double* y,
                                      double* x) {
  double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  /* Rotation matrix entries needed for R = Rz Ry Rx:
   * r20 = -sin(y), r21 = cos(y) sin(x), r22 = cos(y) cos(x),
   * r10 = cos(y) sin(z), r00 = cos(y) cos(z). */
  double r00 = 1.0 - 2.0 * (qy * qy + qz * qz);
  double r10 = 2.0 * (qx * qy + qw * qz);
  double r20 = 2.0 * (qx * qz - qw * qy);
  double r21 = 2.0 * (qy * qz + qw * qx);
  double r22 = 1.0 - 2.0 * (qx * qx + qy * qy);
  double sy = -r20;
  if (sy > 1.0) sy = 1.0;
  if (sy < -1.0) sy = -1.0;
  *y = asin(sy);
  if (fabs(sy) < 0.9999999) {
    *x = atan2(r21, r22);
    *z = atan2(r10, r00);
  } else {
    /* Gimbal lock: only z - x (or z + x) is defined; put it all in z. */
    double r01 = 2.0 * (qx * qy - qw * qz);
    double r11 = 1.0 - 2.0 * (qx * qx + qz * qz);
    *x = 0.0;
    *z = atan2(-r01, r11);
  }
}

/* Quaternion of the rotation matrix whose columns are the images of the x,
 * y and z axes (Shepperd's method: stable for every rotation). */
static inline void smgb_qfrom_axes(const double X[3], const double Y[3],
                                   const double Z[3], double q[4]) {
  double m00 = X[0], m11 = Y[1], m22 = Z[2], tr = m00 + m11 + m22;
  if (tr > 0.0) {
    double s = sqrt(tr + 1.0) * 2.0;
    q[3] = 0.25 * s;
    q[0] = (Y[2] - Z[1]) / s;
    q[1] = (Z[0] - X[2]) / s;
    q[2] = (X[1] - Y[0]) / s;
  } else if (m00 > m11 && m00 > m22) {
    double s = sqrt(1.0 + m00 - m11 - m22) * 2.0;
    q[3] = (Y[2] - Z[1]) / s;
    q[0] = 0.25 * s;
    q[1] = (Y[0] + X[1]) / s;
    q[2] = (Z[0] + X[2]) / s;
  } else if (m11 > m22) {
    double s = sqrt(1.0 + m11 - m00 - m22) * 2.0;
    q[3] = (Z[0] - X[2]) / s;
    q[0] = (Y[0] + X[1]) / s;
    q[1] = 0.25 * s;
    q[2] = (Z[1] + Y[2]) / s;
  } else {
    double s = sqrt(1.0 + m22 - m00 - m11) * 2.0;
    q[3] = (X[1] - Y[0]) / s;
    q[0] = (Z[0] + X[2]) / s;
    q[1] = (Z[1] + Y[2]) / s;
    q[2] = 0.25 * s;
  }
  smgb_qnormalize(q);
}

static inline void smgb_qconj(const double q[4], double o[4]) {
  o[0] = -q[0]; o[1] = -q[1]; o[2] = -q[2]; o[3] = q[3];
}

#endif /* BAKE_IMPORT_UTIL_H */
