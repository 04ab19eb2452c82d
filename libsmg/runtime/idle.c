/*
 * idle.c - choose the standing motion played at rest (idle.h).
 */
#include "idle.h"

#include <string.h>

#include "rmath.h"
#include "standing.h"

/* Clip-space position of joint j in pool frame f: the chain from the root
 * composed joint by joint (a leg is a handful of joints). */
static void joint_position(const smg_graph* g, uint32_t f, uint32_t j,
                           float* out) {
  const smgi_joint* joints = g->data.joints;
  const unsigned char* rec = smgi_graph_pose(g, f);
  uint32_t chain[64], n = 0;
  for (uint32_t k = j; n < 64u; k = (uint32_t)joints[k].parent) {
    chain[n++] = k;
    if (joints[k].parent < 0) break;
  }
  float rot[4], pos[3];
  smgi_pose_root(rec, pos);
  smgi_quat_unpack_raw(smgi_pose_rot(rec, 0), rot);
  smgi_q_normalize(rot);
  for (uint32_t i = n - 1u; i-- > 0;) {
    const uint32_t k = chain[i];
    float off[3], q[4], r[4];
    smgi_q_rotate(rot, joints[k].offset, off);
    for (int c = 0; c < 3; ++c) pos[c] += off[c];
    smgi_quat_unpack_raw(smgi_pose_rot(rec, k), q);
    smgi_q_mul(rot, q, r);
    smgi_q_normalize(r);
    memcpy(rot, r, sizeof rot);
  }
  memcpy(out, pos, sizeof pos);
}

void smgi_idle_choose(const smg_graph* g, smgi_idle* out) {
  const smgi_graph_data* d = &g->data;
  const smgi_info* info = d->info;
  const uint32_t toes[2] = {info->left_leg[3], info->right_leg[3]};
  const float stance = SMGI_IDLE_STANCE * info->leg_length;
  memset(out, 0, sizeof *out);
  /* clip by clip, so a small buffer holds every stretch of one clip (a
   * clip with more than it holds keeps its first ones) */
  for (uint32_t c = 0; c < d->clip_count; ++c) {
    smgi_stand s[16];
    uint32_t k = smgi_standing_find(d->frames, d->frame_count, d->clips + c,
                                    1u, info->frame_rate, info->leg_length,
                                    s, 16u);
    const uint32_t whole = (d->clips[c].flags & SMGI_CLIP_LOWER) != 0;
    for (uint32_t i = 0; i < k && i < 16u; ++i) {
      if (out->count > 0 &&
          (whole < out->whole ||
           (whole == out->whole && s[i].count <= out->count)))
        continue;
      const smgi_frame* fr = &d->frames[s[i].first];
      float p[2][3], local[2][2];
      for (int f = 0; f < 2; ++f) {
        joint_position(g, s[i].first, toes[f], p[f]);
        smgi_rot2(-fr->root2d[2], p[f][0] - fr->root2d[0],
                  p[f][2] - fr->root2d[1], &local[f][0], &local[f][1]);
      }
      const float dx = p[0][0] - p[1][0], dz = p[0][2] - p[1][2];
      if (dx * dx + dz * dz > stance * stance) continue;
      out->first = s[i].first;
      out->count = s[i].count;
      out->whole = whole;
      memcpy(out->toe, local, sizeof local);
    }
  }
}
