/*
 * ik.c - foot cleanup. When a foot's contact label (FRMI) begins, the
 * toe's world position is recorded; while the contact lasts, cyclic
 * coordinate descent on hip and knee moves the ankle to where the
 * animation has it relative to the toe, placed at that anchor - so a flat
 * foot stays put and a rolling foot pivots about its planted toe instead of
 * dragging. The ankle keeps its animated world orientation, which puts the
 * toe exactly on the anchor. The correction blends in and out over IK_BLEND seconds so
 * contact changes never pop. A contact whose anchor drifted implausibly far
 * (a re-plan moved the body) is released rather than stretched.
 */
#include <math.h>
#include <string.h>

#include "character_internal.h"

#define IK_BLEND 0.1f      /* seconds to blend in/out */
#define IK_ITERATIONS 8u
#define IK_RELEASE 0.35f   /* fraction of leg length */

/* Rotate world-space chain joints [from, 3) about joint `k` by dq. */
static void rotate_chain(float pos[3][3], float rotw[3][4], uint32_t k,
                         const float* dq) {
  for (uint32_t c = k; c < 3u; ++c) {
    float q[4];
    smgi_q_mul(dq, rotw[c], q); /* unit * unit: renormalized at the end */
    memcpy(rotw[c], q, sizeof q);
    if (c > k) {
      float v[3] = {pos[c][0] - pos[k][0], pos[c][1] - pos[k][1],
                    pos[c][2] - pos[k][2]};
      float o[3];
      smgi_q_rotate(dq, v, o);
      pos[c][0] = pos[k][0] + o[0];
      pos[c][1] = pos[k][1] + o[1];
      pos[c][2] = pos[k][2] + o[2];
    }
  }
}

static void solve_leg(smg_character* ch, const uint32_t* leg,
                      const float* target, float w) {
  const smg_graph* g = ch->graph;
  const uint32_t hip = leg[0], knee = leg[1], ankle = leg[2];
  const uint32_t J = ch->joint_count;
  if (hip >= J || knee >= J || ankle >= J || hip == 0) return;
  int32_t hp = g->data.joints[hip].parent;
  if (hp < 0) return;
  float pos[3][3], rotw[3][4];
  const uint32_t chain[3] = {hip, knee, ankle};
  for (uint32_t c = 0; c < 3u; ++c) {
    memcpy(pos[c], ch->wpos + 3u * chain[c], sizeof(float) * 3u);
    memcpy(rotw[c], ch->wrot + 4u * chain[c], sizeof(float) * 4u);
  }
  float ankle_world[4];
  memcpy(ankle_world, rotw[2], sizeof ankle_world);
  float prev2 = INFINITY;
  for (uint32_t it = 0; it < IK_ITERATIONS; ++it) {
    float ex = target[0] - pos[2][0], ey = target[1] - pos[2][1],
          ez = target[2] - pos[2][2];
    float e2 = ex * ex + ey * ey + ez * ez;
    if (e2 < 4e-6f) break; /* within 2 mm */
    /* converged short of an unreachable target: more sweeps gain < 1 mm */
    if (prev2 - e2 < 2e-3f * sqrtf(e2) + 1e-6f && it > 0) break;
    prev2 = e2;
    for (int k = 1; k >= 0; --k) { /* knee, then hip */
      float v1[3] = {pos[2][0] - pos[k][0], pos[2][1] - pos[k][1],
                     pos[2][2] - pos[k][2]};
      float v2[3] = {target[0] - pos[k][0], target[1] - pos[k][1],
                     target[2] - pos[k][2]};
      float dq[4];
      smgi_q_from_to(v1, v2, dq);
      rotate_chain(pos, rotw, (uint32_t)k, dq);
    }
  }
  smgi_q_normalize(rotw[0]);
  smgi_q_normalize(rotw[1]);
  /* back to local rotations, blended with the animation by w */
  float inv[4], local[4], out[4];
  smgi_q_conj(ch->wrot + 4u * (uint32_t)hp, inv);
  smgi_q_mul(inv, rotw[0], local);
  smgi_q_nlerp(ch->rot + 4u * hip, local, w, out);
  memcpy(ch->rot + 4u * hip, out, sizeof out);
  smgi_q_conj(rotw[0], inv);
  smgi_q_mul(inv, rotw[1], local);
  smgi_q_nlerp(ch->rot + 4u * knee, local, w, out);
  memcpy(ch->rot + 4u * knee, out, sizeof out);
  smgi_q_conj(rotw[1], inv);
  smgi_q_mul(inv, ankle_world, local);
  smgi_q_nlerp(ch->rot + 4u * ankle, local, w, out);
  memcpy(ch->rot + 4u * ankle, out, sizeof out);
}

void smgi_ik_apply(smg_character* ch, float dt) {
  if (!ch->ik_enabled) {
    ch->feet[0].planted = ch->feet[1].planted = 0;
    ch->feet[0].weight = ch->feet[1].weight = 0.0f;
    return;
  }
  const smgi_info* info = ch->graph->data.info;
  const uint32_t bits[2] = {SMG_STATE_LEFT_CONTACT, SMG_STATE_RIGHT_CONTACT};
  const uint32_t* legs[2] = {info->left_leg, info->right_leg};
  float step = dt / IK_BLEND;
  for (uint32_t f = 0; f < 2u; ++f) {
    smgi_foot* foot = &ch->feet[f];
    uint32_t ankle = legs[f][2];
    if (ankle >= ch->joint_count) continue;
    /* the planted point: the toe when the skeleton has one */
    uint32_t toe = legs[f][3] < ch->joint_count ? legs[f][3] : ankle;
    const float* ap = ch->wpos + 3u * toe;
    int contact = (ch->contacts & bits[f]) != 0;
    if (contact && !foot->planted) {
      foot->planted = 1;
      memcpy(foot->anchor, ap, sizeof foot->anchor);
    } else if (!contact) {
      foot->planted = 0;
    }
    if (foot->planted) {
      float dx = foot->anchor[0] - ap[0], dy = foot->anchor[1] - ap[1],
            dz = foot->anchor[2] - ap[2];
      float lim = IK_RELEASE * info->leg_length;
      if (dx * dx + dy * dy + dz * dz > lim * lim) {
        foot->planted = 0; /* implausible: let go smoothly */
      }
    }
    foot->weight += foot->planted ? step : -step;
    foot->weight = smgi_clampf(foot->weight, 0.0f, 1.0f);
    if (foot->weight > 0.0f) {
      /* ankle target: the animated ankle-from-toe offset at the anchor */
      const float* an = ch->wpos + 3u * ankle;
      float target[3] = {foot->anchor[0] + an[0] - ap[0],
                         foot->anchor[1] + an[1] - ap[1],
                         foot->anchor[2] + an[2] - ap[2]};
      solve_leg(ch, legs[f], target, foot->weight);
      smgi_fk_masked(ch, (uint8_t)(1u << f)); /* keep the cache true */
    }
  }
}
