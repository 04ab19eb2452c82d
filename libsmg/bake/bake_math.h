/*
 * bake_math.h - the baker's double-precision helpers, for the importers
 * and the graph stages alike: quaternions (x,y,z,w; v' = q v q*;
 * mul(a,b) applies b then a) and 2-D ground transforms (x, z, heading;
 * heading h faces (sin h, 0, cos h), i.e. a rotation of h about +Y).
 * static inline: no symbols exported.
 */
#ifndef BAKE_MATH_H
#define BAKE_MATH_H

#include <math.h>

#define SMGB_M_PI 3.14159265358979323846

static inline void smgb_q_mul(const double a[4], const double b[4],
                              double o[4]) {
  double r0 = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  double r1 = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  double r2 = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  double r3 = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  o[0] = r0; o[1] = r1; o[2] = r2; o[3] = r3;
}

static inline void smgb_q_rotate(const double q[4], const double v[3],
                                 double o[3]) {
  double tx = 2.0 * (q[1] * v[2] - q[2] * v[1]);
  double ty = 2.0 * (q[2] * v[0] - q[0] * v[2]);
  double tz = 2.0 * (q[0] * v[1] - q[1] * v[0]);
  double r0 = v[0] + q[3] * tx + (q[1] * tz - q[2] * ty);
  double r1 = v[1] + q[3] * ty + (q[2] * tx - q[0] * tz);
  double r2 = v[2] + q[3] * tz + (q[0] * ty - q[1] * tx);
  o[0] = r0; o[1] = r1; o[2] = r2;
}

static inline void smgb_q_conj(const double q[4], double o[4]) {
  o[0] = -q[0]; o[1] = -q[1]; o[2] = -q[2]; o[3] = q[3];
}

static inline void smgb_q_normalize(double q[4]) {
  double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 1e-300) || !isfinite(n)) {
    q[0] = q[1] = q[2] = 0.0; q[3] = 1.0;
    return;
  }
  q[0] /= n; q[1] /= n; q[2] /= n; q[3] /= n;
}

static inline void smgb_q_yaw(double heading, double q[4]) {
  q[0] = 0.0; q[1] = sin(0.5 * heading); q[2] = 0.0; q[3] = cos(0.5 * heading);
}

/* Shortest-arc slerp (nlerp when nearly parallel). */
static inline void smgb_q_slerp(const double a[4], const double b[4],
                                double t, double o[4]) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  double s = 1.0, wa, wb;
  int i;
  if (d < 0.0) { d = -d; s = -1.0; }
  if (d > 0.9995) {
    wa = 1.0 - t; wb = t;
  } else {
    double th = acos(d), sn = sin(th);
    wa = sin((1.0 - t) * th) / sn;
    wb = sin(t * th) / sn;
  }
  for (i = 0; i < 4; ++i) o[i] = wa * a[i] + s * wb * b[i];
  smgb_q_normalize(o);
}

/* Rotation of `radians` about coordinate axis 0 (x), 1 (y) or 2 (z). */
static inline void smgb_q_axis(int axis, double radians, double q[4]) {
  double s = sin(0.5 * radians);
  q[0] = q[1] = q[2] = 0.0;
  q[axis] = s;
  q[3] = cos(0.5 * radians);
}

/* Rotation about an arbitrary unit axis. */
static inline void smgb_q_axis_angle(const double axis[3], double radians,
                                    double q[4]) {
  double s = sin(0.5 * radians);
  q[0] = axis[0] * s; q[1] = axis[1] * s; q[2] = axis[2] * s;
  q[3] = cos(0.5 * radians);
}

/* Euler angles (radians) such that R(q) = Rz(z) * Ry(y) * Rx(x), i.e. the BVH
 * channel order "Zrotation Yrotation Xrotation". */
static inline void smgb_q_to_euler_zyx(const double q[4], double* z, double* y,
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
static inline void smgb_q_from_axes(const double X[3], const double Y[3],
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
  smgb_q_normalize(q);
}

static inline double smgb_wrap_angle(double a) {
  while (a > SMGB_M_PI) a -= 2.0 * SMGB_M_PI;
  while (a < -SMGB_M_PI) a += 2.0 * SMGB_M_PI;
  return a;
}

/* Heading of a root rotation: yaw of its forward (+Z) axis on the ground. */
static inline double smgb_heading_of(const double q[4]) {
  double f[3], z[3] = {0.0, 0.0, 1.0};
  smgb_q_rotate(q, z, f);
  if (fabs(f[0]) + fabs(f[2]) < 1e-9) return 0.0;
  return atan2(f[0], f[2]);
}

/* Ground transform g = (x, z, h): local (lx, lz) -> world. */
static inline void smgb_g_apply(const double g[3], double lx, double lz,
                                double* wx, double* wz) {
  double c = cos(g[2]), s = sin(g[2]);
  *wx = g[0] + lx * c + lz * s;
  *wz = g[1] - lx * s + lz * c;
}

/* World (wx, wz) -> local of g. */
static inline void smgb_g_inverse_apply(const double g[3], double wx,
                                        double wz, double* lx, double* lz) {
  double c = cos(g[2]), s = sin(g[2]);
  double dx = wx - g[0], dz = wz - g[1];
  *lx = dx * c - dz * s;
  *lz = dx * s + dz * c;
}

/* b expressed in a's frame: rel = inverse(a) * b. */
static inline void smgb_g_relative(const double a[3], const double b[3],
                                   double rel[3]) {
  smgb_g_inverse_apply(a, b[0], b[1], &rel[0], &rel[1]);
  rel[2] = smgb_wrap_angle(b[2] - a[2]);
}

/* o = a * b (apply b, then a). */
static inline void smgb_g_compose(const double a[3], const double b[3],
                                  double o[3]) {
  double x, z;
  smgb_g_apply(a, b[0], b[1], &x, &z);
  o[0] = x; o[1] = z; o[2] = smgb_wrap_angle(a[2] + b[2]);
}

#endif /* BAKE_MATH_H */
