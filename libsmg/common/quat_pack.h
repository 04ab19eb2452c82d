/*
 * quat_pack.h - the blob's 48-bit joint rotations ("smallest three") and
 * the POSE record helpers built on them. One implementation, shared by the
 * baker (packs when it writes POSE), the runtime (unpacks straight into its
 * nlerps) and the tools/tests (unpack a whole record into floats).
 *
 * Encoding of a unit quaternion q = (x, y, z, w), indices 0..3
 * (docs/blob-format.md, "POSE record"):
 *   i     = index of the largest |q[k]| (the first one on ties);
 *   q    := -q when q[i] < 0 (same rotation), so the dropped component is
 *           positive and follows from the others: q[i] = sqrt(1 - a2-b2-c2);
 *   a, b, c = q[(i+1)&3], q[(i+2)&3], q[(i+3)&3]: each in [-1/sqrt2,
 *           1/sqrt2], since a second component can hold at most half of
 *           the unit length;
 *   word0 = qa (16 bits), word1 = qb << 1 | (i & 1),
 *   word2 = qc << 1 | (i >> 1): a 16-bit code for a, 15-bit codes for b, c,
 *           whose low bits carry the 2-bit index;
 *   code  = round(v / STEP) + MID, with MID = 32767 (16-bit) or 16383
 *           (15-bit) and STEP = (1/sqrt2) / MID, so 0 is exact and
 *           identity / axis-aligned rotations survive unchanged.
 * Decoding cannot fail: every 48-bit pattern gives |a|, |b|, |c| <= ~0.7072,
 * the dropped component is sqrt(max(0, 1 - a2-b2-c2)) and the result has a
 * squared length in [1, ~1.5] before normalisation, so it is always a finite
 * (normalised: unit) quaternion. That is why the blob reader no longer
 * checks rotations. Accuracy: rotation error <= 1.3e-4 rad (analytic bound;
 * 1.15e-4 rad = 0.0066 deg measured over 10^7 random rotations, mean
 * 3.9e-5), held by tests/core/test_quat_pack.c.
 */
#ifndef SMG_QUAT_PACK_H
#define SMG_QUAT_PACK_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "smg_format.h"
#include "simd.h"

#define SMGI_QPACK_BYTES 6u
/* How far from 1 a float quaternion's length may be to count as a unit
 * rotation: what the baker packs and the reader accepts (splice
 * corrections) alike. */
#define SMGI_QUAT_UNIT_TOLERANCE 1e-3f
#define SMGI_QPACK_MID16 32767
#define SMGI_QPACK_MID15 16383
#define SMGI_QPACK_STEP16 (0.70710678118654752f / 32767.0f)
#define SMGI_QPACK_STEP15 (0.70710678118654752f / 16383.0f)

/* Decode 6 bytes into q with the dropped component reconstructed but not
 * normalised: unit within float rounding for every pattern the encoder
 * writes, length in [1, 1.23] for arbitrary bytes. Meant for callers that
 * normalise anyway (nlerp), which then cost no extra square root.
 *
 * Speed (the runtime's root joint and the joints left over by
 * smgi_pose_nlerp4_sse below): the words are assembled from bytes (one 16-bit
 * load each, no temporary), and the dropped component is put in place by
 * *loading* from a table filled with constant-index stores,
 * q[k] = t[(k - i) & 3]. Storing to q at a variable index instead made the
 * caller's wider loads of q wait on store forwarding: 2x slower per
 * joint. */
static inline void smgi_quat_unpack_raw(const unsigned char* p, float* q) {
  const uint32_t w0 = (uint32_t)p[0] | (uint32_t)p[1] << 8;
  const uint32_t w1 = (uint32_t)p[2] | (uint32_t)p[3] << 8;
  const uint32_t w2 = (uint32_t)p[4] | (uint32_t)p[5] << 8;
  const uint32_t i = (w1 & 1u) | (w2 & 1u) << 1;
  float t[4], r;
  t[1] = (float)((int32_t)w0 - SMGI_QPACK_MID16) * SMGI_QPACK_STEP16;
  t[2] = (float)((int32_t)(w1 >> 1) - SMGI_QPACK_MID15) * SMGI_QPACK_STEP15;
  t[3] = (float)((int32_t)(w2 >> 1) - SMGI_QPACK_MID15) * SMGI_QPACK_STEP15;
  r = 1.0f - (t[1] * t[1] + t[2] * t[2] + t[3] * t[3]);
  t[0] = sqrtf(r > 0.0f ? r : 0.0f);
  q[0] = t[(0u - i) & 3u];
  q[1] = t[(1u - i) & 3u];
  q[2] = t[(2u - i) & 3u];
  q[3] = t[(3u - i) & 3u];
}

/* Decode 6 bytes into a finite unit quaternion (any bytes). */
static inline void smgi_quat_unpack(const unsigned char* p, float* q) {
  smgi_quat_unpack_raw(p, q);
  /* >= ~1 whatever the bytes: never divides by zero */
  const float s =
      1.0f / sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  q[0] *= s;
  q[1] *= s;
  q[2] *= s;
  q[3] *= s;
}

/* ---- four joints at once ------------------------------------------------- */

/* smgi_pose_nlerp4_sse: out[0 .. 16) = nlerp(unpack(a_j), unpack(b_j), t)
 * for the four packed rotations at a and b (joints j .. j+3 of two
 * records; 24 bytes each), bit for bit what smgi_quat_unpack_raw on both
 * and then the runtime's smgi_q_nlerp (rmath.h) give joint by joint: same
 * operations in the same order, lane by lane. Why: one joint at a time the
 * decode is ~100 dependent scalar instructions on top of the nlerp (a
 * character step samples ~30-50 joints from two frames); four lanes at a
 * time, with the dropped component put in place by masks instead of
 * indexed loads, cost about as much as the float nlerp did in format 1.
 *
 * SSE2 where it is part of the ABI (x86-64) unless built with
 * -DSMGI_QPACK_SSE=0; other builds sample joint by joint (pose.c), which
 * is the reference tests/core/test_quat_pack.c holds this to. */
#ifndef SMGI_QPACK_SSE
#define SMGI_QPACK_SSE SMGI_SSE2
#endif
#if SMGI_QPACK_SSE
#include <emmintrin.h>
#endif

#if SMGI_QPACK_SSE
/* Four 32-bit lanes from the unaligned 4-byte words at p, p + 6, p + 12,
 * p + 18 (one per joint): 4 loads and 3 unpacks, where assembling each
 * 16-bit word from bytes took ~12 scalar instructions per lane. */
static inline __m128i smgi_qpack_dwords(const unsigned char* p) {
  int32_t v[4];
  memcpy(&v[0], p, 4);
  memcpy(&v[1], p + 6, 4);
  memcpy(&v[2], p + 12, 4);
  memcpy(&v[3], p + 18, 4);
  return _mm_unpacklo_epi64(
      _mm_unpacklo_epi32(_mm_cvtsi32_si128(v[0]), _mm_cvtsi32_si128(v[1])),
      _mm_unpacklo_epi32(_mm_cvtsi32_si128(v[2]), _mm_cvtsi32_si128(v[3])));
}

/* Unpack four consecutive packed rotations (24 bytes at p, nothing read
 * beyond) into x, y, z, w vectors (lane k = joint k), bit for bit what
 * smgi_quat_unpack_raw gives for each. */
static inline void smgi_quat_unpack4_sse(const unsigned char* p, __m128* x,
                                         __m128* y, __m128* z, __m128* w) {
  const __m128i one = _mm_set1_epi32(1);
  /* little-endian: d01 = word0 | word1 << 16, d12 = word1 | word2 << 16 */
  const __m128i d01 = smgi_qpack_dwords(p);
  const __m128i d12 = smgi_qpack_dwords(p + 2);
  const __m128i w0 = _mm_and_si128(d01, _mm_set1_epi32(0xffff));
  const __m128i w1 = _mm_srli_epi32(d01, 16);
  const __m128i w2 = _mm_srli_epi32(d12, 16);
  const __m128 a = _mm_mul_ps(
      _mm_cvtepi32_ps(_mm_sub_epi32(w0, _mm_set1_epi32(SMGI_QPACK_MID16))),
      _mm_set1_ps(SMGI_QPACK_STEP16));
  const __m128 b = _mm_mul_ps(
      _mm_cvtepi32_ps(_mm_sub_epi32(_mm_srli_epi32(w1, 1),
                                    _mm_set1_epi32(SMGI_QPACK_MID15))),
      _mm_set1_ps(SMGI_QPACK_STEP15));
  const __m128 c = _mm_mul_ps(
      _mm_cvtepi32_ps(_mm_sub_epi32(_mm_srli_epi32(w2, 1),
                                    _mm_set1_epi32(SMGI_QPACK_MID15))),
      _mm_set1_ps(SMGI_QPACK_STEP15));
  const __m128 r = _mm_sub_ps(
      _mm_set1_ps(1.0f),
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(a, a), _mm_mul_ps(b, b)),
                 _mm_mul_ps(c, c)));
  /* max(r, 0) is r > 0 ? r : 0, as in the plain version */
  const __m128 big = _mm_sqrt_ps(_mm_max_ps(r, _mm_setzero_ps()));
  /* Put the dropped component in place: q[k] = t[(k - i) & 3] with
   * t = (big, a, b, c), i = the 2-bit index, per lane. By bit 0 of i the
   * candidates pair up so that four selects serve all components, then
   * bit 1 picks between them; each select is y ^ (mask & (x ^ y)). */
  const __m128 m1 = _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(w1, one), one));
  const __m128 m2 = _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(w2, one), one));
#define SMGI_QPACK_SEL(m, if1, if0) \
  _mm_xor_ps((if0), _mm_and_ps((m), _mm_xor_ps((if1), (if0))))
  /* i even / odd: x is big / c (i = 0 / 1) or b / a (i = 2 / 3), ... */
  const __m128 P = SMGI_QPACK_SEL(m1, c, big); /* x if i < 2, z if i >= 2 */
  const __m128 Q = SMGI_QPACK_SEL(m1, a, b);   /* z if i < 2, x if i >= 2 */
  const __m128 R = SMGI_QPACK_SEL(m1, big, a); /* y if i < 2, w if i >= 2 */
  const __m128 S = SMGI_QPACK_SEL(m1, b, c);   /* w if i < 2, y if i >= 2 */
#undef SMGI_QPACK_SEL
  const __m128 dpq = _mm_and_ps(m2, _mm_xor_ps(P, Q));
  const __m128 drs = _mm_and_ps(m2, _mm_xor_ps(R, S));
  *x = _mm_xor_ps(P, dpq);
  *z = _mm_xor_ps(Q, dpq);
  *y = _mm_xor_ps(R, drs);
  *w = _mm_xor_ps(S, drs);
}

/* The nlerp half of smgi_pose_nlerp4_sse: out[0 .. 16) = nlerp of the
 * rotations given as x, y, z, w vectors (lane k = joint k), as decoded by
 * smgi_quat_unpack4_sse (what a caller that keeps decoded records hands
 * in), at tv = t and u = 1 - t in every lane (a caller's loop makes them
 * once). */
static inline void smgi_nlerp4_sse(__m128 ax, __m128 ay, __m128 az,
                                   __m128 aw, __m128 bx, __m128 by,
                                   __m128 bz, __m128 bw, __m128 tv,
                                   __m128 u, float* out) {
  __m128 d, s, ox, oy, oz, ow, inv;
  d = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)),
                            _mm_mul_ps(az, bz)),
                 _mm_mul_ps(aw, bw));
  /* d < 0 ? -t : t: flip t's sign bit where d < 0 */
  s = _mm_xor_ps(tv, _mm_and_ps(_mm_cmplt_ps(d, _mm_setzero_ps()),
                                _mm_set1_ps(-0.0f)));
  ox = _mm_add_ps(_mm_mul_ps(u, ax), _mm_mul_ps(s, bx));
  oy = _mm_add_ps(_mm_mul_ps(u, ay), _mm_mul_ps(s, by));
  oz = _mm_add_ps(_mm_mul_ps(u, az), _mm_mul_ps(s, bz));
  ow = _mm_add_ps(_mm_mul_ps(u, aw), _mm_mul_ps(s, bw));
  inv = _mm_div_ps(
      _mm_set1_ps(1.0f),
      _mm_sqrt_ps(_mm_add_ps(
          _mm_add_ps(_mm_add_ps(_mm_mul_ps(ox, ox), _mm_mul_ps(oy, oy)),
                     _mm_mul_ps(oz, oz)),
          _mm_mul_ps(ow, ow))));
  ox = _mm_mul_ps(ox, inv);
  oy = _mm_mul_ps(oy, inv);
  oz = _mm_mul_ps(oz, inv);
  ow = _mm_mul_ps(ow, inv);
  _MM_TRANSPOSE4_PS(ox, oy, oz, ow); /* lanes -> one quaternion each */
  _mm_storeu_ps(out, ox);
  _mm_storeu_ps(out + 4, oy);
  _mm_storeu_ps(out + 8, oz);
  _mm_storeu_ps(out + 12, ow);
}

static inline void smgi_pose_nlerp4_sse(const unsigned char* a,
                                        const unsigned char* b, float t,
                                        float* out) {
  __m128 ax, ay, az, aw, bx, by, bz, bw;
  smgi_quat_unpack4_sse(a, &ax, &ay, &az, &aw);
  smgi_quat_unpack4_sse(b, &bx, &by, &bz, &bw);
  smgi_nlerp4_sse(ax, ay, az, aw, bx, by, bz, bw, _mm_set1_ps(t),
                  _mm_set1_ps(1.0f - t), out);
}
#endif

/* Encode q (normalised first, in double). Returns 1 when q was finite and
 * of unit length within 1e-3, the blob's old acceptance rule, else 0 (the
 * identity is written then, so the bytes are still defined): the baker
 * treats 0 as its own bug. */
int smgi_quat_pack(const float* q, unsigned char* out);

/* ---- POSE records (layout: smg_format.h) ------------------------------- */

/* Record f of the blob's POSE section. */
static inline const unsigned char* smgi_pose_record(const smgi_graph_data* g,
                                                    uint32_t f) {
  return g->poses + (uint64_t)f * SMGI_POSE_RECORD_SIZE(g->joint_count);
}

/* Joint j's packed rotation inside a record. */
static inline const unsigned char* smgi_pose_rot(const unsigned char* rec,
                                                 uint32_t j) {
  return rec + SMGI_POSE_ROT_OFFSET + SMGI_QPACK_BYTES * j;
}

/* The record's root translation (3 floats). */
static inline void smgi_pose_root(const unsigned char* rec, float* out) {
  memcpy(out, rec, 3u * sizeof(float));
}

/* Pack one float pose (SMGI_POSE_FLOATS(J): root then J quaternions) into
 * a record of SMGI_POSE_RECORD_SIZE(J) bytes, padding zeroed. Returns the
 * number of rotations that were not finite unit quaternions (0 = all good;
 * see smgi_quat_pack). */
uint32_t smgi_pose_pack(const float* pose, uint32_t joint_count,
                        unsigned char* record);

/* Unpack a record into SMGI_POSE_FLOATS(J) floats (unit quaternions). For
 * tools and tests; the runtime decodes joint by joint instead. */
void smgi_pose_unpack(const unsigned char* record, uint32_t joint_count,
                      float* pose);

#endif /* SMG_QUAT_PACK_H */
