/*
 * pose.c - pose composition: sample the lower body at the fractional
 * playhead (lerp root, nlerp rotations, across edge boundaries), place it in
 * the world with the entry's ground transform, then lay the upper body on
 * top (spliced action with the Horn correction at the spine base, or the
 * locomotion's own) with a crossfade after every switch. Also forward
 * kinematics for IK and the model-matrix getter.
 */
#include <string.h>

#include "character_internal.h"

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
  while (j < J) {
#if SMGI_QPACK_SSE
    if (j + 4u <= J && WANTED(j) && WANTED(j + 1u) && WANTED(j + 2u) &&
        WANTED(j + 3u)) {
      smgi_pose_nlerp4_sse(qa + SMGI_QPACK_BYTES * j,
                           qb + SMGI_QPACK_BYTES * j, t, out + 4u * j);
      j += 4u;
    } else
#endif
    {
      if (WANTED(j)) {
        /* the same operations as one lane of smgi_pose_nlerp4_sse */
        float ja[4], jb[4];
        smgi_quat_unpack_raw(qa + SMGI_QPACK_BYTES * j, ja);
        smgi_quat_unpack_raw(qb + SMGI_QPACK_BYTES * j, jb);
        smgi_q_nlerp(ja, jb, t, out + 4u * j);
      }
      ++j;
    }
  }
#undef WANTED
}

/* World root position/rotation and ground placement of one lower frame. */
static void place(const smg_graph* g, uint32_t frame, smgi_xform2 M,
                  float* pos, float* rot, float* gx, float* gz, float* gh) {
  const unsigned char* rec = smgi_graph_pose(g, frame);
  float p[3], x, z, q[4], r0[4];
  smgi_pose_root(rec, p);
  smgi_xf_point(M, p[0], p[2], &x, &z);
  pos[0] = x;
  pos[1] = p[1] - g->data.info->ground_height;
  pos[2] = z;
  smgi_q_yaw(M.h, q);
  /* raw decode: the caller's nlerp normalises */
  smgi_quat_unpack_raw(smgi_pose_rot(rec, 0), r0);
  smgi_q_mul(q, r0, rot);
  const float* r = g->data.frames[frame].root2d;
  smgi_xf_point(M, r[0], r[1], gx, gz);
  *gh = M.h + r[2];
}

void smgi_pose_compose(smg_character* ch) {
  const smg_graph* g = ch->graph;
  const uint32_t J = ch->joint_count;
  const smgi_edge* edges = g->data.lower_edges;
  const smgi_qentry* h = smgi_q_at(ch, 0);
  const smgi_edge* e = &edges[h->edge];
  uint32_t i0 = (uint32_t)ch->t;
  if (i0 >= e->frame_count) i0 = e->frame_count - 1u;
  float a = ch->t - (float)i0;
  a = smgi_clampf(a, 0.0f, 1.0f);
  uint32_t fa = e->first_frame + i0, fb = fa;
  smgi_xform2 Mb = h->M;
  if (i0 + 1u < e->frame_count) {
    fb = fa + 1u;
  } else if (ch->q_count > 1u) {
    const smgi_qentry* n = smgi_q_at(ch, 1);
    fb = edges[n->edge].first_frame;
    Mb = n->M;
  }
  float pa[3], pb[3], ra[4], rb[4], gax, gaz, gah, gbx, gbz, gbh;
  place(g, fa, h->M, pa, ra, &gax, &gaz, &gah);
  place(g, fb, Mb, pb, rb, &gbx, &gbz, &gbh);
  for (int k = 0; k < 3; ++k) ch->root[k] = pa[k] + a * (pb[k] - pa[k]);
  smgi_q_nlerp(ra, rb, a, ch->rot);
  ch->ground[0] = gax + a * (gbx - gax);
  ch->ground[1] = gaz + a * (gbz - gaz);
  ch->heading = smgi_wrap_angle(gah + a * smgi_wrap_angle(gbh - gah));
  /* Decode both frames' joints straight into their nlerps, four joints at
   * a time. While an action plays, its sample replaces every upper-body
   * joint below, so the locomotion's own are not sampled at all. */
  smgi_sample_joints(g, smgi_graph_pose(g, fa), smgi_graph_pose(g, fb), a,
                     ch->action != 0 ? SMGI_JOINTS_NOT_UPPER
                                     : SMGI_JOINTS_ALL,
                     ch->rot);
  uint32_t flags = g->data.frames[a < 0.5f ? fa : fb].flags;
  ch->contacts = ((flags & SMGI_FRAME_LEFT_CONTACT) ? SMG_STATE_LEFT_CONTACT
                                                     : 0u) |
                 ((flags & SMGI_FRAME_RIGHT_CONTACT) ? SMG_STATE_RIGHT_CONTACT
                                                      : 0u);

  /* upper body */
  if (ch->action == 0 && ch->fade >= 1.0f) return;
  if (ch->action != 0) smgi_upper_sample(ch, ch->tmp);
  /* smoothstep keeps the crossfade's velocity continuous at both ends */
  float w = ch->fade >= 1.0f ? 1.0f : ch->fade * ch->fade * (3.0f - 2.0f * ch->fade);
  for (uint32_t j = 1; j < J; ++j) {
    if (g->data.joints[j].body_part != SMG_BODY_UPPER) continue;
    float* out = ch->rot + 4u * j;
    const float* target = ch->action != 0 ? ch->tmp + 4u * j : out;
    if (w >= 1.0f) {
      memcpy(out, target, sizeof(float) * 4u);
    } else {
      float q[4];
      smgi_q_nlerp(ch->snap + 4u * j, target, w, q);
      memcpy(out, q, sizeof q);
    }
  }
}

void smgi_fk(const smg_graph* g, const float* root, const float* rot,
             float* wpos, float* wrot) {
  const uint32_t J = g->data.joint_count;
  const smgi_joint* joints = g->data.joints;
  wpos[0] = root[0];
  wpos[1] = root[1];
  wpos[2] = root[2];
  memcpy(wrot, rot, sizeof(float) * 4u);
  for (uint32_t j = 1; j < J; ++j) {
    uint32_t p = (uint32_t)joints[j].parent;
    float o[3];
    smgi_q_rotate(wrot + 4u * p, joints[j].offset, o);
    wpos[3u * j] = wpos[3u * p] + o[0];
    wpos[3u * j + 1u] = wpos[3u * p + 1u] + o[1];
    wpos[3u * j + 2u] = wpos[3u * p + 2u] + o[2];
    smgi_q_mul(wrot + 4u * p, rot + 4u * j, wrot + 4u * j);
  }
}

void smgi_fk_joints(smg_character* ch, const uint32_t* list,
                    uint32_t count) {
  const smgi_joint* joints = ch->graph->data.joints;
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t j = list[i];
    uint32_t p = (uint32_t)joints[j].parent;
    float o[3];
    smgi_q_rotate(ch->wrot + 4u * p, joints[j].offset, o);
    ch->wpos[3u * j] = ch->wpos[3u * p] + o[0];
    ch->wpos[3u * j + 1u] = ch->wpos[3u * p + 1u] + o[1];
    ch->wpos[3u * j + 2u] = ch->wpos[3u * p + 2u] + o[2];
    smgi_q_mul(ch->wrot + 4u * p, ch->rot + 4u * j, ch->wrot + 4u * j);
  }
}
