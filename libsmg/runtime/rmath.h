/*
 * rmath.h - the small amount of vector/quaternion math the runtime needs,
 * inline and branch-light. Quaternions are (x, y, z, w); ground transforms
 * are (x, z, heading) with heading about +Y and forward (sin h, 0, cos h).
 */
#ifndef SMG_RMATH_H
#define SMG_RMATH_H

#include <math.h>
#include <stdint.h>

#include "dmath.h"

#define SMGI_PI 3.14159265358979323846f

/* A placement on the ground: translation (x, z) and heading about +Y. */
typedef struct smgi_xform2 {
  float x, z, h;
} smgi_xform2;

static inline float smgi_wrap_angle(float a) {
  /* into (-pi, pi] in O(1): a loop subtracting 2 pi would take forever on
   * a huge finite angle (a corrupt blob, a far-away path), and fmodf is
   * exact. Non-finite input gives NaN, which callers' finite checks see. */
  if (a > -SMGI_PI && a <= SMGI_PI) return a; /* the common case */
  a = fmodf(a + SMGI_PI, 2.0f * SMGI_PI); /* (-2 pi, 2 pi) */
  if (a <= 0.0f) a += 2.0f * SMGI_PI;     /* (0, 2 pi] */
  return a - SMGI_PI;
}

/* Rotate a ground vector (x, z) by heading h: local +Z maps to forward. */
static inline void smgi_rot2(float h, float x, float z, float* ox, float* oz) {
  float c, s;
  smgi_sincosf(h, &s, &c);
  *ox = c * x + s * z;
  *oz = -s * x + c * z;
}

/* a * b: first b, then a (b expressed in a's local frame). */
static inline smgi_xform2 smgi_xf_mul(smgi_xform2 a, smgi_xform2 b) {
  smgi_xform2 r;
  float x, z;
  smgi_rot2(a.h, b.x, b.z, &x, &z);
  r.x = a.x + x;
  r.z = a.z + z;
  r.h = smgi_wrap_angle(a.h + b.h);
  return r;
}

static inline smgi_xform2 smgi_xf_inv(smgi_xform2 a) {
  smgi_xform2 r;
  float x, z;
  smgi_rot2(-a.h, -a.x, -a.z, &x, &z);
  r.x = x;
  r.z = z;
  r.h = smgi_wrap_angle(-a.h);
  return r;
}

static inline void smgi_xf_point(smgi_xform2 a, float px, float pz, float* ox,
                                 float* oz) {
  float x, z;
  smgi_rot2(a.h, px, pz, &x, &z);
  *ox = a.x + x;
  *oz = a.z + z;
}

/* ---- quaternions -------------------------------------------------------- */

static inline void smgi_q_mul(const float* a, const float* b, float* o) {
  float x = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  float y = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  float z = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  float w = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  o[0] = x;
  o[1] = y;
  o[2] = z;
  o[3] = w;
}

static inline void smgi_q_conj(const float* a, float* o) {
  o[0] = -a[0];
  o[1] = -a[1];
  o[2] = -a[2];
  o[3] = a[3];
}

static inline void smgi_q_normalize(float* q) {
  float n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  if (n > 1e-20f && isfinite(n)) {
    float s = 1.0f / sqrtf(n);
    q[0] *= s;
    q[1] *= s;
    q[2] *= s;
    q[3] *= s;
  } else {
    q[0] = q[1] = q[2] = 0.0f;
    q[3] = 1.0f;
  }
}

/* Normalised lerp along the shorter arc: cheap and, for the small angles
 * between consecutive frames, indistinguishable from slerp. */
static inline void smgi_q_nlerp(const float* a, const float* b, float t,
                                float* o) {
  float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  float s = d < 0.0f ? -t : t;
  float u = 1.0f - t;
  o[0] = u * a[0] + s * b[0];
  o[1] = u * a[1] + s * b[1];
  o[2] = u * a[2] + s * b[2];
  o[3] = u * a[3] + s * b[3];
  smgi_q_normalize(o);
}

/* Rotation about +Y by angle h. */
static inline void smgi_q_yaw(float h, float* o) {
  o[0] = 0.0f;
  smgi_sincosf(0.5f * h, &o[1], &o[3]);
  o[2] = 0.0f;
}

static inline void smgi_q_rotate(const float* q, const float* v, float* o) {
  /* v' = v + 2w (q x v) + 2 q x (q x v) */
  float tx = 2.0f * (q[1] * v[2] - q[2] * v[1]);
  float ty = 2.0f * (q[2] * v[0] - q[0] * v[2]);
  float tz = 2.0f * (q[0] * v[1] - q[1] * v[0]);
  float x = v[0] + q[3] * tx + (q[1] * tz - q[2] * ty);
  float y = v[1] + q[3] * ty + (q[2] * tx - q[0] * tz);
  float z = v[2] + q[3] * tz + (q[0] * ty - q[1] * tx);
  o[0] = x;
  o[1] = y;
  o[2] = z;
}

/* Shortest rotation taking direction a to direction b. */
static inline void smgi_q_from_to(const float* a, const float* b, float* o) {
  float cx = a[1] * b[2] - a[2] * b[1];
  float cy = a[2] * b[0] - a[0] * b[2];
  float cz = a[0] * b[1] - a[1] * b[0];
  float l2 = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) *
             (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  float lab = sqrtf(l2);
  float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  float w = lab + d;
  if (!(w > 1e-6f * (lab + 1e-12f))) {
    /* opposite or degenerate: no well-defined shortest arc, do nothing */
    o[0] = o[1] = o[2] = 0.0f;
    o[3] = 1.0f;
    return;
  }
  /* |(c, w)|^2 = 2 lab w, so one sqrt normalizes */
  float s = 1.0f / sqrtf(2.0f * lab * w);
  o[0] = cx * s;
  o[1] = cy * s;
  o[2] = cz * s;
  o[3] = w * s;
}

/* Deterministic xorshift32 (never 0 state). */
static inline uint32_t smgi_xorshift(uint32_t* s) {
  uint32_t x = *s;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *s = x;
  return x;
}

static inline float smgi_clampf(float v, float lo, float hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

#endif /* SMG_RMATH_H */
