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

#define SMGI_QPACK_BYTES 6u
#define SMGI_QPACK_MID16 32767
#define SMGI_QPACK_MID15 16383
#define SMGI_QPACK_STEP16 (0.70710678118654752f / 32767.0f)
#define SMGI_QPACK_STEP15 (0.70710678118654752f / 16383.0f)

/* Decode 6 bytes into q with the dropped component reconstructed but not
 * normalised: unit within float rounding for every pattern the encoder
 * writes, length in [1, 1.23] for arbitrary bytes. Meant for callers that
 * normalise anyway (nlerp), which then cost no extra square root.
 *
 * Speed (this runs 60-100 times per character step): the words are
 * assembled from bytes (one 16-bit load each, no temporary), and the
 * dropped component is put in place by *loading* from a table filled with
 * constant-index stores, q[k] = t[(k - i) & 3]. Storing to q at a
 * variable index instead made the caller's wider loads of q wait on
 * store forwarding: 2x slower per joint. */
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
