/*
 * pose.c - pose composition: sample the lower body at the fractional
 * playhead (lerp root, nlerp rotations, across edge boundaries), place it in
 * the world with the entry's ground transform, then lay the upper body on
 * top (spliced action with the Horn correction at the spine base, or the
 * locomotion's own) with a crossfade after every switch. Its inputs are
 * the lower timeline and the upper body's state, both const. Also forward
 * kinematics for IK and the model-matrix getter.
 */
#include <string.h>

#include "pose.h"

#include "pose_simd.h"
#include "rmath.h"

/* A queue entry's frame -> world transform with its trigonometry done:
 * both sampled frames usually share one entry, so its sines and cosines
 * are computed once per step instead of twice. */
typedef struct placement {
  smgi_xform2 M;
  float c, s;   /* cos, sin of M.h (smgi_rot2) */
  float yaw[4]; /* smgi_q_yaw(M.h) */
} placement;

static void placement_init(smgi_xform2 M, placement* pl) {
  pl->M = M;
  smgi_sincosf(M.h, &pl->s, &pl->c);
  smgi_q_yaw(M.h, pl->yaw);
}

/* smgi_xf_point(pl->M, px, pz, ox, oz), same operations */
static void placement_point(const placement* pl, float px, float pz,
                            float* ox, float* oz) {
  const float x = pl->c * px + pl->s * pz;
  const float z = -pl->s * px + pl->c * pz;
  *ox = pl->M.x + x;
  *oz = pl->M.z + z;
}

/* World root position/rotation and ground placement of one lower frame. */
static void place(const smg_graph* g, uint32_t frame, const placement* pl,
                  float* pos, float* rot, float* gx, float* gz, float* gh) {
  const unsigned char* rec = smgi_graph_pose(g, frame);
  float p[3], x, z, r0[4];
  smgi_pose_root(rec, p);
  placement_point(pl, p[0], p[2], &x, &z);
  pos[0] = x;
  pos[1] = p[1] - g->data.info->ground_height;
  pos[2] = z;
  /* raw decode: the caller's nlerp normalises */
  smgi_quat_unpack_raw(smgi_pose_rot(rec, 0), r0);
#if SMGI_POSE_SSE
  _mm_storeu_ps(rot, smgi_q_mul_sse(_mm_loadu_ps(pl->yaw), _mm_loadu_ps(r0)));
#else
  smgi_q_mul(pl->yaw, r0, rot);
#endif
  const float* r = g->data.frames[frame].root2d;
  placement_point(pl, r[0], r[1], gx, gz);
  *gh = pl->M.h + r[2];
}

void smgi_pose_compose(smgi_pose* pose, const smgi_lower* lower,
                       const smgi_upper* upper, const smg_graph* g) {
  const uint32_t J = g->data.joint_count;
  const smgi_edge* edges = g->data.lower_edges;
  const smgi_qentry* h = smgi_q_at_c(lower, 0);
  const smgi_edge* e = &edges[h->edge];
  uint32_t i0 = (uint32_t)lower->t;
  if (i0 >= e->frame_count) i0 = e->frame_count - 1u;
  float a = lower->t - (float)i0;
  a = smgi_clampf(a, 0.0f, 1.0f);
  uint32_t fa = e->first_frame + i0, fb = fa;
  placement pa_pl, pb_pl;
  placement_init(h->M, &pa_pl);
  const placement* plb = &pa_pl;
  if (i0 + 1u < e->frame_count) {
    fb = fa + 1u;
  } else if (lower->count > 1u) {
    const smgi_qentry* n = smgi_q_at_c(lower, 1);
    fb = edges[n->edge].first_frame;
    placement_init(n->M, &pb_pl);
    plb = &pb_pl;
  }
  float pa[3], pb[3], ra[4], rb[4], gax, gaz, gah, gbx, gbz, gbh;
  place(g, fa, &pa_pl, pa, ra, &gax, &gaz, &gah);
  place(g, fb, plb, pb, rb, &gbx, &gbz, &gbh);
  for (int k = 0; k < 3; ++k) pose->root[k] = pa[k] + a * (pb[k] - pa[k]);
#if SMGI_POSE_SSE
  _mm_storeu_ps(pose->rot,
                smgi_q_nlerp_sse(_mm_loadu_ps(ra), _mm_loadu_ps(rb), a));
#else
  smgi_q_nlerp(ra, rb, a, pose->rot);
#endif
  pose->ground[0] = gax + a * (gbx - gax);
  pose->ground[1] = gaz + a * (gbz - gaz);
  pose->heading = smgi_wrap_angle(gah + a * smgi_wrap_angle(gbh - gah));
  /* Decode both frames' joints straight into their nlerps, four joints at
   * a time. While an action plays, its sample replaces every upper-body
   * joint below, so the locomotion's own are not sampled at all. */
  smgi_sample_frames(g, fa, fb, a,
                     upper->action != 0 ? SMGI_JOINTS_NOT_UPPER
                                        : SMGI_JOINTS_ALL,
                     &pose->decoded, pose->rot);
  uint32_t flags = g->data.frames[a < 0.5f ? fa : fb].flags;
  pose->contacts = ((flags & SMGI_FRAME_LEFT_CONTACT) ? SMG_STATE_LEFT_CONTACT
                                                     : 0u) |
                 ((flags & SMGI_FRAME_RIGHT_CONTACT) ? SMG_STATE_RIGHT_CONTACT
                                                      : 0u);

  /* upper body */
  if (upper->action == 0 && upper->fade >= 1.0f) return;
  /* smoothstep keeps the crossfade's velocity continuous at both ends */
  float w = upper->fade >= 1.0f ? 1.0f : upper->fade * upper->fade * (3.0f - 2.0f * upper->fade);
  const smgi_joint* joints = g->data.joints;
  if (upper->action != 0 && w >= 1.0f) {
    /* no crossfade: the action's upper body goes straight into the pose
     * (the upper joints were not written above). Only when the spine-base
     * correction lands on an upper joint too, as in every baked skeleton;
     * otherwise the general path below keeps it off the pose. */
    const uint32_t sb = g->data.info->spine_base_joint;
    if (sb == 0 || sb >= J || joints[sb].body_part == SMG_BODY_UPPER) {
      smgi_upper_sample(upper, g, pose->rot);
      return;
    }
  }
  /* upper-body rotations go straight into the pose unless a crossfade
   * needs them apart; the scratch for that lives on the stack up to
   * SMGI_POSE_STACK_JOINTS joints (pose.tmp exists only for bigger
   * skeletons) */
  float stack_tmp[4u * SMGI_POSE_STACK_JOINTS];
  float* tmp = J <= SMGI_POSE_STACK_JOINTS ? stack_tmp : pose->tmp;
  if (upper->action != 0) smgi_upper_sample(upper, g, tmp);
  for (uint32_t j = 1; j < J; ++j) {
    if (joints[j].body_part != SMG_BODY_UPPER) continue;
    float* out = pose->rot + 4u * j;
    const float* target = upper->action != 0 ? tmp + 4u * j : out;
    if (w >= 1.0f) {
      memcpy(out, target, sizeof(float) * 4u);
    } else {
      float q[4];
      smgi_q_nlerp(upper->snap + 4u * j, target, w, q);
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
#if SMGI_POSE_SSE
  /* The previous joint's transform stays in registers: in a skeleton most
   * joints are their predecessor's child (chains), and the others reload
   * their parent with the access sizes it was stored with. */
  __m128 prev_rot = _mm_loadu_ps(rot), prev_pos = smgi_load3_sse(root);
  for (uint32_t j = 1; j < J; ++j) {
    const uint32_t p = (uint32_t)joints[j].parent;
    __m128 prot = prev_rot, ppos = prev_pos;
    if (p != j - 1u) {
      prot = _mm_loadu_ps(wrot + 4u * p);
      ppos = smgi_load3_sse(wpos + 3u * p);
    }
    /* offset[3] is followed by mass_ratio: a 16-byte load stays inside
     * the joint record, lane 3 is ignored */
    prev_rot = smgi_fk_joint_sse(prot, ppos, _mm_loadu_ps(joints[j].offset),
                                 rot + 4u * j, wpos + 3u * j, wrot + 4u * j,
                                 &prev_pos);
  }
#else
  for (uint32_t j = 1; j < J; ++j) {
    const uint32_t p = (uint32_t)joints[j].parent;
    smgi_fk_joint_c(wrot + 4u * p, wpos + 3u * p, joints[j].offset,
                    rot + 4u * j, wpos + 3u * j, wrot + 4u * j);
  }
#endif
}

void smgi_fk_joints(smgi_pose* pose, const smg_graph* g, const uint32_t* list,
                    uint32_t count) {
  const smgi_joint* joints = g->data.joints;
  float* wpos = pose->wpos;
  float* wrot = pose->wrot;
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t j = list[i];
    const uint32_t p = (uint32_t)joints[j].parent;
#if SMGI_POSE_SSE
    __m128 unused;
    (void)smgi_fk_joint_sse(_mm_loadu_ps(wrot + 4u * p),
                            smgi_load3_sse(wpos + 3u * p),
                            _mm_loadu_ps(joints[j].offset), pose->rot + 4u * j,
                            wpos + 3u * j, wrot + 4u * j, &unused);
#else
    smgi_fk_joint_c(wrot + 4u * p, wpos + 3u * p, joints[j].offset,
                    pose->rot + 4u * j, wpos + 3u * j, wrot + 4u * j);
#endif
  }
}

void smgi_pose_model_matrices(const smgi_pose* p, uint32_t joint_count,
                              uint32_t space, float* matrices) {
  const uint32_t J = joint_count;
  const float* wpos = p->wpos;
  const float* wrot = p->wrot;
#if SMGI_POSE_SSE
  /* four joints at a time; a last partial group is moved back to end at
   * J (rewriting a few matrices with the same values), and only a skeleton
   * of fewer than four joints pads with identities */
  const int world = space == SMG_SPACE_WORLD;
  __m128 yaw = _mm_setzero_ps(), ground = _mm_setzero_ps();
  if (!world) {
    float y[4];
    smgi_q_yaw(-p->heading, y);
    yaw = _mm_loadu_ps(y);
    ground = _mm_setr_ps(p->ground[0], p->ground_y, p->ground[1], 0.0f);
  }
  if (J >= 4u) {
    for (uint32_t j = 0; j < J; j += 4u) {
      const uint32_t b = j + 4u <= J ? j : J - 4u;
      if (world)
        smgi_mat4_world_sse(wrot + 4u * b, wpos + 3u * b, matrices + 16u * b);
      else
        smgi_mat4_character_sse(wrot + 4u * b, wpos + 3u * b, yaw, ground,
                                matrices + 16u * b);
    }
    return;
  }
  float q[16] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  float pp[12] = {0};
  float m[64];
  memcpy(q, wrot, sizeof(float) * 4u * J);
  memcpy(pp, wpos, sizeof(float) * 3u * J);
  if (world)
    smgi_mat4_world_sse(q, pp, m);
  else
    smgi_mat4_character_sse(q, pp, yaw, ground, m);
  memcpy(matrices, m, sizeof(float) * 16u * J);
#else
  if (space == SMG_SPACE_WORLD) {
    for (uint32_t j = 0; j < J; ++j)
      smgi_mat_from_c(wrot + 4u * j, wpos + 3u * j, matrices + 16u * j);
    return;
  }
  /* character space: the inverse of (ground position, heading) first */
  float yaw[4];
  smgi_q_yaw(-p->heading, yaw);
  for (uint32_t j = 0; j < J; ++j) {
    float q[4], v[3], r[3];
    smgi_q_mul(yaw, wrot + 4u * j, q);
    v[0] = wpos[3u * j] - p->ground[0];
    v[1] = wpos[3u * j + 1u] - p->ground_y;
    v[2] = wpos[3u * j + 2u] - p->ground[1];
    smgi_q_rotate(yaw, v, r);
    smgi_mat_from_c(q, r, matrices + 16u * j);
  }
#endif
}
