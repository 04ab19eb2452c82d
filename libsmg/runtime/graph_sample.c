/*
 * graph_sample.c - joint rotations of two of the graph's POSE records
 * blended at t (graph_data.h): what the pose (lower body) and the
 * upper body sample their frames with. Packed rotations are decoded
 * straight into the nlerp, four joints at a time with SSE2 (pose_simd.h).
 */
#include <string.h>

#include "graph_data.h"
#include "pose_simd.h"
#include "rmath.h"

void smgi_sample_joints(const smg_graph* g, const unsigned char* ra,
                        const unsigned char* rb, float t,
                        smgi_joint_set set, float* out) {
  const uint32_t J = g->data.joint_count;
  const smgi_joint* joints = g->data.joints;
  const unsigned char* qa = smgi_pose_rot(ra, 0);
  const unsigned char* qb = smgi_pose_rot(rb, 0);
#define WANTED(j)                                                     \
  (set == SMGI_JOINTS_ALL ||                                          \
   (set == SMGI_JOINTS_UPPER) == (joints[j].body_part == SMG_BODY_UPPER))
  uint32_t j = 1;
#if SMGI_QPACK_SSE
  /* Every joint four at a time: the last group is moved back to end at
   * J (rewriting a few joints with the same values), and a group that
   * mixes wanted and unwanted joints goes through a scratch copy. Decoding
   * an unwanted joint is harmless: its bytes are inside the record. One
   * call site, so the compiler inlines the kernel and keeps its constants
   * in registers across the groups; the common case (every joint: no
   * action playing) computes no masks. */
  if (J >= 5u) {
    const int all = set == SMGI_JOINTS_ALL;
    for (; j < J; j += 4u) {
      const uint32_t base = j + 4u <= J ? j : J - 4u;
      unsigned want = 15u;
      if (!all) {
        want = (WANTED(base) ? 1u : 0u) | (WANTED(base + 1u) ? 2u : 0u) |
               (WANTED(base + 2u) ? 4u : 0u) | (WANTED(base + 3u) ? 8u : 0u);
        if (want == 0u) continue;
      }
      float q[16];
      smgi_pose_nlerp4_sse(qa + SMGI_QPACK_BYTES * base,
                           qb + SMGI_QPACK_BYTES * base, t,
                           want == 15u ? out + 4u * base : q);
      if (want != 15u)
        for (uint32_t k = 0; k < 4u; ++k)
          if (want & (1u << k)) memcpy(out + 4u * (base + k), q + 4u * k, 16u);
    }
    return;
  }
#endif
  for (; j < J; ++j) {
    if (!WANTED(j)) continue;
    /* the same operations as one lane of smgi_pose_nlerp4_sse */
    float ja[4], jb[4];
    smgi_quat_unpack_raw(qa + SMGI_QPACK_BYTES * j, ja);
    smgi_quat_unpack_raw(qb + SMGI_QPACK_BYTES * j, jb);
    smgi_q_nlerp(ja, jb, t, out + 4u * j);
  }
#undef WANTED
}
