/*
 * pose_simd.h - the per-joint math of forward kinematics and of the
 * model-matrix getter, in plain C and in SSE2.
 *
 * Why SSE: FK and the matrix conversion run for every joint of every
 * character every step (31 joints in the CMU skeleton). Scalar, a joint
 * cost ~125 instructions of FK and ~70 of matrix; four lanes at a time
 * they cost about a third.
 *
 * Bit for bit: each SSE lane performs the plain version's operations in
 * the same order (a - b is written as a + (-b), which IEEE makes exact,
 * and multiplying by 2 stays a separate step), so both paths give the same
 * floats and the SSE build's poses equal the reference the tests compute
 * with rmath.h (tests/runtime/test_pose_simd.c). No contraction into FMA
 * happens: the library is compiled as ISO C99, where GCC and Clang keep
 * a * b + c as two roundings.
 *
 * SSE2 where it is part of the ABI (x86-64) unless built with
 * -DSMGI_POSE_SSE=0; other builds use the plain versions.
 */
#ifndef SMG_POSE_SIMD_H
#define SMG_POSE_SIMD_H

#include <string.h>

#include "rmath.h"

#include "simd.h"

#ifndef SMGI_POSE_SSE
#define SMGI_POSE_SSE SMGI_SSE2
#endif
#if SMGI_POSE_SSE
#include <emmintrin.h>
#endif

/* ---- plain C (the reference) ------------------------------------------ */

/* World transform of a joint from its parent's world rotation prot and
 * position ppos, its rest offset and its local rotation lrot. */
static inline void smgi_fk_joint_c(const float* prot, const float* ppos,
                                   const float* offset, const float* lrot,
                                   float* wpos, float* wrot) {
  float o[3];
  smgi_q_rotate(prot, offset, o);
  wpos[0] = ppos[0] + o[0];
  wpos[1] = ppos[1] + o[1];
  wpos[2] = ppos[2] + o[2];
  smgi_q_mul(prot, lrot, wrot);
}

/* Column-major 4x4 from rotation q and translation t. */
static inline void smgi_mat_from_c(const float* q, const float* t, float* m) {
  float x = q[0], y = q[1], z = q[2], w = q[3];
  m[0] = 1.0f - 2.0f * (y * y + z * z);
  m[1] = 2.0f * (x * y + z * w);
  m[2] = 2.0f * (x * z - y * w);
  m[3] = 0.0f;
  m[4] = 2.0f * (x * y - z * w);
  m[5] = 1.0f - 2.0f * (x * x + z * z);
  m[6] = 2.0f * (y * z + x * w);
  m[7] = 0.0f;
  m[8] = 2.0f * (x * z + y * w);
  m[9] = 2.0f * (y * z - x * w);
  m[10] = 1.0f - 2.0f * (x * x + y * y);
  m[11] = 0.0f;
  m[12] = t[0];
  m[13] = t[1];
  m[14] = t[2];
  m[15] = 1.0f;
}

/* ---- SSE2 ---------------------------------------------------------------- */
#if SMGI_POSE_SSE

/* lanes (a, b, c, d) of v. pshufd rather than shufps: it writes a new
 * register, where shufps would overwrite its source and need a copy first
 * (no three-operand forms before AVX) - most of these shuffles read a value
 * that is used again. */
#define SMGI_SHUF(v, a, b, c, d)                     \
  _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), \
                                     _MM_SHUFFLE((d), (c), (b), (a))))

/* smgi_q_mul: the four products of each output component are summed in
 * the scalar order; the minus signs are folded into b's shuffled copies. */
static inline __m128 smgi_q_mul_sse(__m128 a, __m128 b) {
  const __m128 s0 = _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f);
  const __m128 s1 = _mm_setr_ps(0.0f, 0.0f, -0.0f, -0.0f);
  const __m128 s2 = _mm_setr_ps(-0.0f, 0.0f, 0.0f, -0.0f);
  __m128 r = _mm_mul_ps(SMGI_SHUF(a, 3, 3, 3, 3), b);
  r = _mm_add_ps(r, _mm_mul_ps(SMGI_SHUF(a, 0, 0, 0, 0),
                               _mm_xor_ps(SMGI_SHUF(b, 3, 2, 1, 0), s0)));
  r = _mm_add_ps(r, _mm_mul_ps(SMGI_SHUF(a, 1, 1, 1, 1),
                               _mm_xor_ps(SMGI_SHUF(b, 2, 3, 0, 1), s1)));
  r = _mm_add_ps(r, _mm_mul_ps(SMGI_SHUF(a, 2, 2, 2, 2),
                               _mm_xor_ps(SMGI_SHUF(b, 1, 0, 3, 2), s2)));
  return r;
}

/* smgi_q_rotate of v's lanes 0..2 (lane 3 of the result is meaningless). */
static inline __m128 smgi_q_rotate_sse(__m128 q, __m128 v) {
  const __m128 q_yzx = SMGI_SHUF(q, 1, 2, 0, 3);
  const __m128 q_zxy = SMGI_SHUF(q, 2, 0, 1, 3);
  const __m128 t = _mm_mul_ps(
      _mm_set1_ps(2.0f),
      _mm_sub_ps(_mm_mul_ps(q_yzx, SMGI_SHUF(v, 2, 0, 1, 3)),
                 _mm_mul_ps(q_zxy, SMGI_SHUF(v, 1, 2, 0, 3))));
  return _mm_add_ps(
      _mm_add_ps(v, _mm_mul_ps(SMGI_SHUF(q, 3, 3, 3, 3), t)),
      _mm_sub_ps(_mm_mul_ps(q_yzx, SMGI_SHUF(t, 2, 0, 1, 3)),
                 _mm_mul_ps(q_zxy, SMGI_SHUF(t, 1, 2, 0, 3))));
}

/* ((m0 + m1) + m2) + m3: four lanes summed in the plain code's order */
static inline float smgi_hsum4_sse(__m128 m) {
  __m128 t = _mm_add_ss(m, SMGI_SHUF(m, 1, 1, 1, 1));
  t = _mm_add_ss(t, SMGI_SHUF(m, 2, 2, 2, 2));
  return _mm_cvtss_f32(_mm_add_ss(t, SMGI_SHUF(m, 3, 3, 3, 3)));
}

/* smgi_q_normalize */
static inline __m128 smgi_q_normalize_sse(__m128 q) {
  const float n = smgi_hsum4_sse(_mm_mul_ps(q, q));
  if (n > 1e-20f && isfinite(n))
    return _mm_mul_ps(q, _mm_set1_ps(1.0f / sqrtf(n)));
  return _mm_setr_ps(0.0f, 0.0f, 0.0f, 1.0f);
}

/* smgi_q_nlerp */
static inline __m128 smgi_q_nlerp_sse(__m128 a, __m128 b, float t) {
  const float d = smgi_hsum4_sse(_mm_mul_ps(a, b));
  const __m128 s = _mm_set1_ps(d < 0.0f ? -t : t);
  return smgi_q_normalize_sse(
      _mm_add_ps(_mm_mul_ps(_mm_set1_ps(1.0f - t), a), _mm_mul_ps(s, b)));
}

/* Three floats out of lanes 0..2, nothing written beyond them. */
static inline void smgi_store3_sse(float* p, __m128 v) {
  _mm_storel_epi64((__m128i*)(void*)p, _mm_castps_si128(v));
  _mm_store_ss(p + 2, _mm_movehl_ps(v, v));
}

/* Three floats into lanes 0..2 (lane 3 = 0), nothing read beyond them.
 * Same access sizes as smgi_store3_sse, so a load right after the store
 * (a child reading its parent) is forwarded instead of stalling. */
static inline __m128 smgi_load3_sse(const float* p) {
  const __m128 xy =
      _mm_castsi128_ps(_mm_loadl_epi64((const __m128i*)(const void*)p));
  return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
}

/* smgi_fk_joint_c with the parent already in registers. ppos and offset
 * lanes 0..2 are used; wpos gets exactly three floats. Returns the world
 * rotation and sets *pos_out (lane 3 meaningless), so a caller walking a
 * chain keeps them in registers. */
static inline __m128 smgi_fk_joint_sse(__m128 prot, __m128 ppos,
                                       __m128 offset, const float* lrot,
                                       float* wpos, float* wrot,
                                       __m128* pos_out) {
  const __m128 p = _mm_add_ps(ppos, smgi_q_rotate_sse(prot, offset));
  const __m128 r = smgi_q_mul_sse(prot, _mm_loadu_ps(lrot));
  smgi_store3_sse(wpos, p);
  _mm_storeu_ps(wrot, r);
  *pos_out = p;
  return r;
}

/* The rotation columns (0..2, each with its w = 0) of four column-major
 * matrices from four rotations (x, y, z, w each), written to the matrices
 * at m, m + 16, m + 32, m + 48 (their translation columns untouched):
 * smgi_mat_from_c lane by lane, with the products computed on transposed
 * (x, y, z, w) vectors. */
static inline void smgi_mat4_rot_sse(__m128 q0, __m128 q1, __m128 q2,
                                     __m128 q3, float* m) {
  const __m128 one = _mm_set1_ps(1.0f), two = _mm_set1_ps(2.0f);
  const __m128 zero = _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(q0, q1, q2, q3); /* q0 = x of the four, q1 = y, ... */
  const __m128 x = q0, y = q1, z = q2, w = q3;
  const __m128 xx = _mm_mul_ps(x, x), yy = _mm_mul_ps(y, y),
               zz = _mm_mul_ps(z, z), xy = _mm_mul_ps(x, y),
               xz = _mm_mul_ps(x, z), yz = _mm_mul_ps(y, z),
               xw = _mm_mul_ps(x, w), yw = _mm_mul_ps(y, w),
               zw = _mm_mul_ps(z, w);
  __m128 c0x = _mm_sub_ps(one, _mm_mul_ps(two, _mm_add_ps(yy, zz)));
  __m128 c0y = _mm_mul_ps(two, _mm_add_ps(xy, zw));
  __m128 c0z = _mm_mul_ps(two, _mm_sub_ps(xz, yw));
  __m128 c0w = zero;
  __m128 c1x = _mm_mul_ps(two, _mm_sub_ps(xy, zw));
  __m128 c1y = _mm_sub_ps(one, _mm_mul_ps(two, _mm_add_ps(xx, zz)));
  __m128 c1z = _mm_mul_ps(two, _mm_add_ps(yz, xw));
  __m128 c1w = zero;
  __m128 c2x = _mm_mul_ps(two, _mm_add_ps(xz, yw));
  __m128 c2y = _mm_mul_ps(two, _mm_sub_ps(yz, xw));
  __m128 c2z = _mm_sub_ps(one, _mm_mul_ps(two, _mm_add_ps(xx, yy)));
  __m128 c2w = zero;
  /* one column at a time, stored as soon as it is transposed: the
   * registers hold one column's four joints, not all twelve */
  _MM_TRANSPOSE4_PS(c0x, c0y, c0z, c0w); /* now joint k's first column */
  _mm_storeu_ps(m, c0x);
  _mm_storeu_ps(m + 16, c0y);
  _mm_storeu_ps(m + 32, c0z);
  _mm_storeu_ps(m + 48, c0w);
  _MM_TRANSPOSE4_PS(c1x, c1y, c1z, c1w);
  _mm_storeu_ps(m + 4, c1x);
  _mm_storeu_ps(m + 20, c1y);
  _mm_storeu_ps(m + 36, c1z);
  _mm_storeu_ps(m + 52, c1w);
  _MM_TRANSPOSE4_PS(c2x, c2y, c2z, c2w);
  _mm_storeu_ps(m + 8, c2x);
  _mm_storeu_ps(m + 24, c2y);
  _mm_storeu_ps(m + 40, c2z);
  _mm_storeu_ps(m + 56, c2w);
}

/* World-space model matrices of four joints from their world rotations
 * q[0 .. 16) and positions p[0 .. 12). The translation columns are plain
 * copies: moved as floats, they need no vector register (the vector
 * version kept four positions live across the rotation math and spilled
 * them). */
static inline void smgi_mat4_world_sse(const float* q, const float* p,
                                       float* m) {
  smgi_mat4_rot_sse(_mm_loadu_ps(q), _mm_loadu_ps(q + 4),
                    _mm_loadu_ps(q + 8), _mm_loadu_ps(q + 12), m);
  /* written out: GCC -O2 kept the four as a loop */
  memcpy(m + 12, p, 3u * sizeof(float));
  memcpy(m + 28, p + 3, 3u * sizeof(float));
  memcpy(m + 44, p + 6, 3u * sizeof(float));
  memcpy(m + 60, p + 9, 3u * sizeof(float));
  m[15] = m[31] = m[47] = m[63] = 1.0f;
}

/* The same in character space: the inverse of the ground placement first
 * (rotation yaw, translation -ground = (x, 0, z)). */
static inline void smgi_mat4_character_sse(const float* q, const float* p,
                                           __m128 yaw, __m128 ground,
                                           float* m) {
  smgi_mat4_rot_sse(smgi_q_mul_sse(yaw, _mm_loadu_ps(q)),
                    smgi_q_mul_sse(yaw, _mm_loadu_ps(q + 4)),
                    smgi_q_mul_sse(yaw, _mm_loadu_ps(q + 8)),
                    smgi_q_mul_sse(yaw, _mm_loadu_ps(q + 12)), m);
  for (int k = 0; k < 4; ++k) {
    const __m128 t = smgi_q_rotate_sse(
        yaw, _mm_sub_ps(smgi_load3_sse(p + 3 * k), ground));
    smgi_store3_sse(m + 16 * k + 12, t);
    m[16 * k + 15] = 1.0f;
  }
}

#endif /* SMGI_POSE_SSE */

#endif /* SMG_POSE_SIMD_H */
