/*
 * graph_sample.c - joint rotations of two of the graph's POSE records
 * blended at t (graph_data.h): what the pose (lower body) and the
 * upper body sample their frames with. Packed rotations are decoded
 * straight into the nlerp, four joints at a time with SSE2 (pose_simd.h);
 * the pose's own records go through the two decoded slots a character
 * keeps (smgi_sample_frames), since each is blended on about four steps.
 */
#include <string.h>

#include "graph_data.h"
#include "pose_simd.h"
#include "rmath.h"

/* Whether joint j belongs to the set sampled. */
static inline int joint_wanted(const smgi_joint* joints, smgi_joint_set set,
                               uint32_t j) {
  return set == SMGI_JOINTS_ALL ||
         (set == SMGI_JOINTS_UPPER) == (joints[j].body_part == SMG_BODY_UPPER);
}

#if SMGI_QPACK_SSE
/* The joints of the group of four from `base` that the set wants, bit k
 * for joint base + k (15: all, the common case, computes nothing). */
static inline unsigned group_want(const smgi_joint* joints,
                                  smgi_joint_set set, uint32_t base) {
  if (set == SMGI_JOINTS_ALL) return 15u;
  unsigned want = 0u;
  for (uint32_t k = 0; k < 4u; ++k)
    if (joint_wanted(joints, set, base + k)) want |= 1u << k;
  return want;
}

/* A group that mixes wanted and unwanted joints is blended into scratch
 * q; its wanted joints are copied out. */
static inline void store_wanted(float* out, uint32_t base, const float* q,
                                unsigned want) {
  for (uint32_t k = 0; k < 4u; ++k)
    if (want & (1u << k)) memcpy(out + 4u * (base + k), q + 4u * k, 16u);
}
#endif

void smgi_sample_joints(const smg_graph* g, const unsigned char* ra,
                        const unsigned char* rb, float t,
                        smgi_joint_set set, float* out) {
  const uint32_t J = g->data.joint_count;
  const smgi_joint* joints = g->data.joints;
  const unsigned char* qa = smgi_pose_rot(ra, 0);
  const unsigned char* qb = smgi_pose_rot(rb, 0);
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
    for (; j < J; j += 4u) {
      const uint32_t base = j + 4u <= J ? j : J - 4u;
      const unsigned want = group_want(joints, set, base);
      if (want == 0u) continue;
      float q[16];
      smgi_pose_nlerp4_sse(qa + SMGI_QPACK_BYTES * base,
                           qb + SMGI_QPACK_BYTES * base, t,
                           want == 15u ? out + 4u * base : q);
      if (want != 15u) store_wanted(out, base, q, want);
    }
    return;
  }
#endif
  for (; j < J; ++j) {
    if (!joint_wanted(joints, set, j)) continue;
    /* the same operations as one lane of smgi_pose_nlerp4_sse */
    float ja[4], jb[4];
    smgi_quat_unpack_raw(qa + SMGI_QPACK_BYTES * j, ja);
    smgi_quat_unpack_raw(qb + SMGI_QPACK_BYTES * j, jb);
    smgi_q_nlerp(ja, jb, t, out + 4u * j);
  }
}

uint32_t smgi_decoded_floats(uint32_t joint_count) {
#if SMGI_QPACK_SSE
  /* one group per four joints from joint 1, the last moved back to end
   * at J (smgi_sample_joints' grouping) */
  if (joint_count >= 5u) return 16u * ((joint_count - 1u + 3u) / 4u);
#endif
  (void)joint_count;
  return 0u;
}

#if SMGI_QPACK_SSE
/* The slot holding record `frame`, or SMGI_NONE. */
static uint32_t find_record(const smgi_decoded* dec, uint32_t frame) {
  return dec->frame[0] == frame ? 0u : dec->frame[1] == frame ? 1u : SMGI_NONE;
}

/* Decode record `frame` into slot k. */
static void decode_record(const smg_graph* g, smgi_decoded* dec,
                          uint32_t frame, uint32_t k) {
  const uint32_t J = g->data.joint_count;
  float* v = dec->rot + (size_t)k * smgi_decoded_floats(J);
  const unsigned char* q = smgi_pose_rot(smgi_graph_pose(g, frame), 0);
  for (uint32_t j = 1; j < J; j += 4u, v += 16) {
    const uint32_t base = j + 4u <= J ? j : J - 4u;
    __m128 x, y, z, w;
    smgi_quat_unpack4_sse(q + SMGI_QPACK_BYTES * base, &x, &y, &z, &w);
    _mm_storeu_ps(v, x);
    _mm_storeu_ps(v + 4, y);
    _mm_storeu_ps(v + 8, z);
    _mm_storeu_ps(v + 12, w);
  }
  dec->frame[k] = frame;
}
#endif

void smgi_sample_frames(const smg_graph* g, uint32_t fa, uint32_t fb,
                        float t, smgi_joint_set set, smgi_decoded* dec,
                        float* out) {
#if SMGI_QPACK_SSE
  const uint32_t J = g->data.joint_count;
  if (dec->rot != NULL && smgi_decoded_floats(J) != 0u) {
    const smgi_joint* joints = g->data.joints;
    const uint32_t n = smgi_decoded_floats(J);
    /* a record not held goes into the slot the other end is not in: on
     * to the next frame, the newer of the two stays */
    uint32_t sa = find_record(dec, fa);
    if (sa == SMGI_NONE) {
      sa = find_record(dec, fb) == 0u ? 1u : 0u;
      decode_record(g, dec, fa, sa);
    }
    uint32_t sb = find_record(dec, fb);
    if (sb == SMGI_NONE) {
      sb = sa ^ 1u;
      decode_record(g, dec, fb, sb);
    }
    const float* va = dec->rot + (size_t)sa * n;
    const float* vb = dec->rot + (size_t)sb * n;
    const __m128 tv = _mm_set1_ps(t), u = _mm_set1_ps(1.0f - t);
    for (uint32_t j = 1, i = 0; j < J; j += 4u, ++i) {
      const uint32_t base = j + 4u <= J ? j : J - 4u;
      const unsigned want = group_want(joints, set, base);
      if (want == 0u) continue;
      float q[16];
      const float* a = va + 16u * i;
      const float* b = vb + 16u * i;
      smgi_nlerp4_sse(_mm_loadu_ps(a), _mm_loadu_ps(a + 4),
                      _mm_loadu_ps(a + 8), _mm_loadu_ps(a + 12),
                      _mm_loadu_ps(b), _mm_loadu_ps(b + 4),
                      _mm_loadu_ps(b + 8), _mm_loadu_ps(b + 12), tv, u,
                      want == 15u ? out + 4u * base : q);
      if (want != 15u) store_wanted(out, base, q, want);
    }
    return;
  }
#else
  (void)dec;
#endif
  smgi_sample_joints(g, smgi_graph_pose(g, fa), smgi_graph_pose(g, fb), t,
                     set, out);
}
