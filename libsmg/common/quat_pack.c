/*
 * quat_pack.c - encoding side of the 48-bit rotations (quat_pack.h) and the
 * whole-record pack/unpack. Runs at bake time (and in tests), so it works
 * in double and may take a few more operations than the decoder.
 */
#include <math.h>
#include <string.h>

#include "quat_pack.h"

/* round(v / step) + mid, clamped to the code range [0, 2 * mid]. */
static uint32_t quantise(double v, double mid) {
  double c = floor(v * mid / 0.70710678118654752 + 0.5) + mid;
  if (c < 0.0) c = 0.0;
  if (c > 2.0 * mid) c = 2.0 * mid;
  return (uint32_t)c;
}

int smgi_quat_pack(const float* qf, unsigned char* out) {
  double q[4], n2 = 0.0, n, best = -1.0;
  unsigned i = 3u, k;
  int ok;
  uint16_t w[3];
  for (k = 0; k < 4u; ++k) {
    q[k] = (double)qf[k];
    n2 += q[k] * q[k];
  }
  n = sqrt(n2);
  /* NaN fails the comparison, inf gives an infinite norm */
  ok = fabs(n - 1.0) <= (double)SMGI_QUAT_UNIT_TOLERANCE;
  if (!ok) {
    q[0] = q[1] = q[2] = 0.0;
    q[3] = 1.0;
  } else {
    for (k = 0; k < 4u; ++k) q[k] /= n;
  }
  for (k = 0; k < 4u; ++k)
    if (fabs(q[k]) > best) {
      best = fabs(q[k]);
      i = k;
    }
  if (q[i] < 0.0)
    for (k = 0; k < 4u; ++k) q[k] = -q[k];
  w[0] = (uint16_t)quantise(q[(i + 1u) & 3u], SMGI_QPACK_MID16);
  w[1] = (uint16_t)(quantise(q[(i + 2u) & 3u], SMGI_QPACK_MID15) << 1 |
                    (i & 1u));
  w[2] = (uint16_t)(quantise(q[(i + 3u) & 3u], SMGI_QPACK_MID15) << 1 |
                    (i >> 1));
  /* little-endian words, like every blob field */
  for (k = 0; k < 3u; ++k) {
    out[2u * k] = (unsigned char)(w[k] & 0xffu);
    out[2u * k + 1u] = (unsigned char)(w[k] >> 8);
  }
  return ok;
}

uint32_t smgi_pose_pack(const float* pose, uint32_t joint_count,
                        unsigned char* record) {
  uint32_t j, bad = 0;
  size_t size = SMGI_POSE_RECORD_SIZE(joint_count);
  memcpy(record, pose, 3u * sizeof(float));
  for (j = 0; j < joint_count; ++j)
    bad += !smgi_quat_pack(pose + 3u + 4u * j,
                           record + SMGI_POSE_ROT_OFFSET +
                               SMGI_QPACK_BYTES * (size_t)j);
  /* padding to the 4-byte record multiple */
  {
    size_t used = SMGI_POSE_ROT_OFFSET + SMGI_QPACK_BYTES * (size_t)joint_count;
    memset(record + used, 0, size - used);
  }
  return bad;
}

void smgi_pose_unpack(const unsigned char* record, uint32_t joint_count,
                      float* pose) {
  uint32_t j;
  smgi_pose_root(record, pose);
  for (j = 0; j < joint_count; ++j)
    smgi_quat_unpack(smgi_pose_rot(record, j), pose + 3u + 4u * j);
}
