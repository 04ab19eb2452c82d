/*
 * dmath.h - the runtime's sine, cosine and atan2, computed from IEEE-754
 * basic operations only (+, -, *, /, fmod; round to nearest, the default
 * mode), so they give the same bits on every C library.
 *
 * Why: libm's transcendental functions are not required to be correctly
 * rounded, and their last bit changes between implementations and
 * versions (glibc 2.41 replaced atan2f with a correctly rounded one: it
 * differs from glibc 2.36's in about one result in six). The planner
 * compares sequence values that can lie within a few ulps of each other,
 * so one differing heading is enough for two builds of the same code -
 * e.g. a program and an engine plugin loaded by a process with a newer
 * libm - to choose different motion on the same path. Same inputs give
 * bit-identical poses on any platform with IEEE binary32/binary64
 * arithmetic, given no contraction into fused multiply-adds (the library
 * is compiled with -ffp-contract=off).
 *
 * Both are evaluated in double and rounded once to float: well inside
 * 1 ulp of float (tests/runtime/test_dmath.c checks the error against
 * libm's double functions and pins the bits of a few thousand results).
 */
#ifndef SMG_DMATH_H
#define SMG_DMATH_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* sin and cos of x (radians): within 1 ulp for |x| up to 1e9 (2 pi is
 * not a double, so beyond that the reduction drifts; still a point on the
 * unit circle). Non-finite x gives NaN for both. */
static inline void smgi_sincosf(float x, float* s, float* c) {
  double xd = (double)x;
  if (!(fabs(xd) < 1e6)) {
    if (xd != xd || fabs(xd) > 3.4e38) {
      *s = *c = (float)(xd - xd); /* NaN (also for infinities) */
      return;
    }
    /* exact (fmod is), so the reduction below stays accurate */
    xd = fmod(xd, 6.283185307179586);
  }
  /* nearest multiple of pi/2 (adding and removing 1.5 * 2^52 rounds to
   * an integer, which then sits in the low bits of kb); pi/2 in two parts
   * (the first has 33 bits, so k times it is exact for |k| < 2^20) */
  const double kb = xd * 0.6366197723675814 + 6755399441055744.0;
  const double k = kb - 6755399441055744.0;
  const double r = (xd - k * 1.5707963267341256) - k * 6.077100506506192e-11;
  const double r2 = r * r;
  /* Taylor series on |r| <= pi/4, truncated below 2e-9 (sine, 1/30 of a
   * float ulp at sin(pi/4)) and 2e-10 (cosine); a product with r keeps
   * the sign of a zero */
  const double sr =
      r * (1.0 + r2 * (-1.0 / 6.0 +
                       r2 * (1.0 / 120.0 +
                             r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362880.0)))));
  const double cr =
      1.0 + r2 * (-0.5 +
                  r2 * (1.0 / 24.0 +
                        r2 * (-1.0 / 720.0 +
                              r2 * (1.0 / 40320.0 + r2 * (-1.0 / 3628800.0)))));
  /* quadrant 0..3: the low bits of k (two's complement in kb's
   * mantissa), without branches */
  uint64_t kbits;
  memcpy(&kbits, &kb, sizeof kbits);
  const unsigned q = (unsigned)kbits & 3u;
  const double a = (q & 1u) ? cr : sr, b = (q & 1u) ? sr : cr;
  *s = (float)((q & 2u) ? -a : a);
  *c = (float)(((q + 1u) & 2u) ? -b : b);
}

static inline float smgi_sinf(float x) {
  float s, c;
  smgi_sincosf(x, &s, &c);
  return s;
}

static inline float smgi_cosf(float x) {
  float s, c;
  smgi_sincosf(x, &s, &c);
  return c;
}

/* atan2(y, x) in [-pi, pi]; (+-0, +-0) gives +-0 or +-pi like C's, NaN
 * propagates. */
static inline float smgi_atan2f(float y, float x) {
  const double ax = fabs((double)x), ay = fabs((double)y);
  const double mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
  double a, r;
  if (x != x || y != y) return x + y;
  if (mx == 0.0) {
    a = 0.0;
  } else if (mn == mx) {
    a = 1.0; /* also both infinite */
  } else {
    a = mn / mx; /* [0, 1) */
  }
  /* atan(a) = atan(c) + atan(t), t = (a - c) / (1 + a c), with c the
   * nearest quarter: |t| <= 0.125, where the Taylor series to t^13 is
   * exact to 1e-14 */
  static const double atan_c[5] = {0.0, 0.24497866312686414,
                                   0.4636476090008061, 0.6435011087932844,
                                   0.7853981633974483};
  const int i = (int)(a * 4.0 + 0.5);
  const double cq = 0.25 * (double)i;
  const double t = (a - cq) / (1.0 + a * cq), t2 = t * t;
  r = atan_c[i] +
      (t + t * t2 * (-1.0 / 3.0 +
                     t2 * (1.0 / 5.0 +
                           t2 * (-1.0 / 7.0 +
                                 t2 * (1.0 / 9.0 +
                                       t2 * (-1.0 / 11.0 + t2 * (1.0 / 13.0)))))));
  if (ay > ax) r = 1.5707963267948966 - r;
  if (signbit(x)) r = 3.141592653589793 - r;
  return (float)(signbit(y) ? -r : r);
}

#endif /* SMG_DMATH_H */
