/*
 * idle.c - choose the standing motion played at rest (idle.h).
 */
#include "idle.h"

#include <math.h>
#include <string.h>

#include "rmath.h"
#include "standing.h"

void smgi_frame_joint(const smg_graph* g, uint32_t f, uint32_t j,
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

/* Median length of the stretches without a foot's contact label in the
 * locomotion clips, in seconds (SMGI_IDLE_SWING_DEFAULT without any). */
static float swing_seconds(const smg_graph* g) {
  const smgi_graph_data* d = &g->data;
  uint32_t hist[64], total = 0;
  memset(hist, 0, sizeof hist);
  for (uint32_t c = 0; c < d->clip_count; ++c) {
    const smgi_clip* cl = &d->clips[c];
    if (!(cl->flags & SMGI_CLIP_LOWER) || (cl->flags & SMGI_CLIP_BLEND))
      continue;
    for (uint32_t f = 0; f < 2u; ++f) {
      const uint32_t bit = f ? SMGI_FRAME_RIGHT_CONTACT : SMGI_FRAME_LEFT_CONTACT;
      uint32_t run = 0, seen = 0; /* a swing counts between two contacts */
      for (uint32_t i = 0; i < cl->frame_count; ++i) {
        if (!(d->frames[cl->first_frame + i].flags & bit)) {
          ++run;
          continue;
        }
        if (seen && run > 0) {
          hist[run < 63u ? run : 63u]++;
          ++total;
        }
        seen = 1;
        run = 0;
      }
    }
  }
  if (total == 0) return SMGI_IDLE_SWING_DEFAULT;
  uint32_t k = 0, acc = 0;
  while (k < 63u && acc + hist[k] <= total / 2u) acc += hist[k++];
  return (float)k / d->info->frame_rate;
}

/* The arms at rest for standing motion from an action (idle.h): the
 * stretch's frame in which the arms' end joints (the hands, or the
 * fingers where the rig has them) hang lowest below the hips, summed (the
 * first of equals). Bounded by the stretch's length times the skeleton's. */
static void choose_arms(const smg_graph* g, smgi_idle* out) {
  const smgi_graph_data* d = &g->data;
  const uint32_t J = d->joint_count;
  /* the arms' end joints (up to 64 of them) */
  uint32_t ends[64], m = 0;
  for (uint32_t j = 1; j < J && m < 64u; ++j) {
    if (d->joints[j].body_part != SMG_BODY_UPPER ||
        smgi_idle_trunk(d->joints, j))
      continue;
    int end = 1; /* no joint below it */
    for (uint32_t k = j + 1u; k < J && end; ++k)
      end = d->joints[k].parent != (int32_t)j;
    if (end) ends[m++] = j;
  }
  out->arms = out->first;
  float lowest = INFINITY;
  for (uint32_t i = 0; i < out->count && m > 0u; ++i) {
    const uint32_t f = out->first + i;
    float hips[3], p[3], hang = 0.0f;
    smgi_frame_joint(g, f, 0u, hips);
    for (uint32_t k = 0; k < m; ++k) {
      smgi_frame_joint(g, f, ends[k], p);
      hang += p[1] - hips[1];
    }
    if (hang < lowest) {
      lowest = hang;
      out->arms = f;
    }
  }
}

void smgi_idle_choose(const smg_graph* g, smgi_idle* out) {
  const smgi_graph_data* d = &g->data;
  const smgi_info* info = d->info;
  const uint32_t toes[2] = {info->left_leg[3], info->right_leg[3]};
  const float stance = SMGI_IDLE_STANCE * info->leg_length;
  memset(out, 0, sizeof *out);
  out->swing_seconds = swing_seconds(g);
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
        smgi_frame_joint(g, s[i].first, toes[f], p[f]);
        smgi_rot2(-fr->root2d[2], p[f][0] - fr->root2d[0],
                  p[f][2] - fr->root2d[1], &local[f][0], &local[f][1]);
      }
      const float dx = p[0][0] - p[1][0], dz = p[0][2] - p[1][2];
      if (dx * dx + dz * dz > stance * stance) continue;
      out->first = s[i].first;
      out->count = s[i].count;
      out->whole = whole;
      memcpy(out->toe, local, sizeof local);
      out->floor = fminf(p[0][1], p[1][1]) - info->ground_height;
    }
  }
  /* how far the chosen stretch's hips stray from where it begins */
  const float* a = d->frames[out->first].root2d;
  for (uint32_t i = 1; i < out->count; ++i) {
    const float* b = d->frames[out->first + i].root2d;
    const float dx = b[0] - a[0], dz = b[1] - a[1];
    out->sway = fmaxf(out->sway, sqrtf(dx * dx + dz * dz));
  }
  if (out->count > 0 && !out->whole) choose_arms(g, out);
}

uint32_t smgi_idle_trunk_count(const smg_graph* g) {
  uint32_t n = 0;
  for (uint32_t j = 1; j < g->data.joint_count; ++j)
    n += (uint32_t)smgi_idle_calmed(g, j);
  return n;
}

size_t smgi_idle_calm_floats(const smg_graph* g, const smgi_idle* idle) {
  if (idle->count == 0u || idle->whole) return 0u;
  return 4u * (size_t)smgi_idle_trunk_count(g) * (idle->count + 1u);
}

/* An action's trunk follows the action's beat (an energetic wave bobs the
 * chest 3-4 deg at 2 Hz); its slower sway is standing. Each entry is a box
 * over the frames about its own, summed with the signs of that frame's
 * rotation; rest.c blends two neighbours and normalises. */
void smgi_idle_calm_build(const smg_graph* g, const smgi_idle* idle,
                          float* calm) {
  const uint32_t J = g->data.joint_count;
  const int32_t K = (int32_t)(0.5f * SMGI_IDLE_TRUNK_SECONDS *
                                  g->data.info->frame_rate +
                              0.5f);
  const int32_t last = (int32_t)idle->count - 1;
  for (int32_t i = 0; i <= last + 1; ++i) {
    const int32_t own = i > last ? last : i;
    for (uint32_t j = 1; j < J; ++j) {
      if (!smgi_idle_calmed(g, j)) continue;
      float ref[4], sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      smgi_quat_unpack_raw(
          smgi_pose_rot(smgi_graph_pose(g, idle->first + (uint32_t)own), j),
          ref);
      for (int32_t k = -K; k <= K; ++k) {
        int32_t f = i + k;
        f = f < 0 ? 0 : f > last ? last : f;
        float q[4];
        smgi_quat_unpack_raw(
            smgi_pose_rot(smgi_graph_pose(g, idle->first + (uint32_t)f), j),
            q);
        const float s =
            q[0] * ref[0] + q[1] * ref[1] + q[2] * ref[2] + q[3] * ref[3] <
                    0.0f
                ? -1.0f
                : 1.0f;
        for (int c = 0; c < 4; ++c) sum[c] += s * q[c];
      }
      memcpy(calm, sum, sizeof sum);
      calm += 4;
    }
  }
}
