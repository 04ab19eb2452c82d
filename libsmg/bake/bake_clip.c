/*
 * bake_clip.c - clip utilities: free/copy, resampling, mirroring,
 * retargeting to a reference skeleton, grounding.
 *
 * Pose layout (bake_skeleton.h): root translation (the root joint's
 * position in clip space; the root's OFFSET is informational only)
 * followed by one local rotation per joint.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_clip.h"
#include "bake_horn.h"
#include "bake_import_util.h"
#include "bake_math.h"

/* ---- clip ---------------------------------------------------------------- */

void smgb_clip_free(smgb_clip* clip) {
  if (!clip) return;
  smgb_skeleton_free(&clip->skeleton);
  free(clip->poses);
  memset(clip, 0, sizeof *clip);
}

static int clip_valid(const smgb_clip* c) {
  return c && c->skeleton.joint_count > 0 && c->skeleton.names &&
         c->skeleton.parents && c->skeleton.offsets && c->frame_count > 0 &&
         c->poses && c->frame_rate > 0.0f && isfinite(c->frame_rate);
}

/* Allocate `out` with src's name/skeleton and `frames` uninitialised poses. */
static smg_result clip_alloc_like(const smgb_clip* src, uint32_t frames,
                                  smgb_clip* out) {
  smgb_clip c;
  smg_result r;
  size_t n = (size_t)frames * SMGB_STRIDE(src->skeleton.joint_count);
  memset(&c, 0, sizeof c);
  memcpy(c.name, src->name, sizeof c.name);
  c.name[SMGB_NAME_MAX - 1] = '\0';
  r = smgb_skeleton_copy(&src->skeleton, &c.skeleton);
  if (r != SMG_OK) return r;
  c.poses = (float*)malloc(sizeof(float) * (n ? n : 1));
  if (!c.poses) {
    smgb_skeleton_free(&c.skeleton);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  c.frame_count = frames;
  c.frame_rate = src->frame_rate;
  *out = c;
  return SMG_OK;
}

smg_result smgb_clip_copy(const smgb_clip* src, smgb_clip* out) {
  smg_result r;
  smgb_clip c;
  if (!clip_valid(src) || !out) return SMG_ERROR_INVALID_ARGUMENT;
  r = clip_alloc_like(src, src->frame_count, &c);
  if (r != SMG_OK) return r;
  memcpy(c.poses, src->poses,
         sizeof(float) * (size_t)src->frame_count *
             SMGB_STRIDE(src->skeleton.joint_count));
  *out = c;
  return SMG_OK;
}

smg_result smgb_clip_resample(const smgb_clip* src, float frame_rate,
                              smgb_clip* out) {
  smgb_clip c;
  smg_result r;
  uint32_t frames, f, j, J, stride;
  double duration, ratio;
  if (!clip_valid(src) || !out || !(frame_rate > 0.0f) ||
      !isfinite(frame_rate) || frame_rate > 1e5f)
    return SMG_ERROR_INVALID_ARGUMENT;
  J = src->skeleton.joint_count;
  stride = SMGB_STRIDE(J);
  /* Keep the clip's time span [0, duration]; the last output frame is the
   * last one at or before the end (a small epsilon absorbs rounding so that
   * e.g. 121 frames at 120 Hz give exactly 31 frames at 30 Hz). */
  duration = (double)(src->frame_count - 1) / src->frame_rate;
  if (duration * frame_rate + 1.0 > 1e8) return SMG_ERROR_CAPACITY;
  frames = (uint32_t)floor(duration * frame_rate + 1e-6) + 1u;
  r = clip_alloc_like(src, frames, &c);
  if (r != SMG_OK) return r;
  c.frame_rate = frame_rate;
  ratio = (double)src->frame_rate / frame_rate;
  for (f = 0; f < frames; ++f) {
    double s = f * ratio;
    uint32_t i0 = (uint32_t)floor(s + 1e-9);
    double t;
    const float *a, *b;
    float* o = c.poses + (size_t)f * stride;
    if (i0 >= src->frame_count - 1) {
      i0 = src->frame_count - 1;
      t = 0.0;
    } else {
      t = s - i0;
      if (t < 1e-9) t = 0.0;
    }
    a = src->poses + (size_t)i0 * stride;
    b = t > 0.0 ? a + stride : a;
    if (t == 0.0) {
      memcpy(o, a, sizeof(float) * stride); /* exact frames stay exact */
      continue;
    }
    for (j = 0; j < 3; ++j) o[j] = (float)((1.0 - t) * a[j] + t * b[j]);
    for (j = 0; j < J; ++j) {
      double qa[4], qb[4], qo[4];
      int k;
      for (k = 0; k < 4; ++k) {
        qa[k] = a[3 + 4 * j + k];
        qb[k] = b[3 + 4 * j + k];
      }
      smgb_q_slerp(qa, qb, t, qo);
      /* Stay in qa's hemisphere so the output stays continuous. */
      if (qo[0] * qa[0] + qo[1] * qa[1] + qo[2] * qa[2] + qo[3] * qa[3] < 0)
        for (k = 0; k < 4; ++k) qo[k] = -qo[k];
      for (k = 0; k < 4; ++k) o[3 + 4 * j + k] = (float)qo[k];
    }
  }
  *out = c;
  return SMG_OK;
}

/* ---- mirroring ----------------------------------------------------------- */

/* Child directions that disagree with their reflected partners by less
 * than this are a symmetric rig's measurement noise (CMU: a few degrees),
 * reflected as they are; beyond it the rig's joint frames are not mirror
 * images of each other (Bandai Namco, Maya/MotionBuilder joint orients:
 * 90-180 deg) and the joint gets a constant correction. */
#define SMGB_MIRROR_SYMMETRIC_DEG 20.0

static double angle_between(const double a[3], const double b[3]) {
  double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  return acos(c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c) * (180.0 / SMGB_M_PI);
}

/* Shortest rotation taking direction a to direction b. */
static void shortest_arc(const double a[3], const double b[3], double q[4]) {
  double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  double d = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  if (d < -0.999999) {
    /* Opposite: half a turn about any axis perpendicular to a. */
    double ax[3] = {0.0, -a[2], a[1]};
    if (ax[1] * ax[1] + ax[2] * ax[2] < 1e-12 * la * la) {
      ax[0] = -a[1];
      ax[1] = a[0];
      ax[2] = 0.0;
    }
    q[0] = ax[0]; q[1] = ax[1]; q[2] = ax[2]; q[3] = 0.0;
  } else {
    q[0] = (a[1] * b[2] - a[2] * b[1]) / (la * lb);
    q[1] = (a[2] * b[0] - a[0] * b[2]) / (la * lb);
    q[2] = (a[0] * b[1] - a[1] * b[0]) / (la * lb);
    q[3] = 1.0 + d;
  }
  smgb_q_normalize(q);
}

static int is_identity(const double q[4]) {
  return q[0] == 0.0 && q[1] == 0.0 && q[2] == 0.0;
}

/* Mean local rotation of every joint over the clip (sign-aligned to the
 * first frame, normalised sum). */
static void mean_rotations(const smgb_clip* c, double (*mean)[4]) {
  uint32_t J = c->skeleton.joint_count, S = SMGB_STRIDE(J), f, j;
  for (j = 0; j < J; ++j) {
    const float* q0 = c->poses + 3 + 4 * j;
    double* m = mean[j];
    m[0] = m[1] = m[2] = m[3] = 0.0;
    for (f = 0; f < c->frame_count; ++f) {
      const float* q = c->poses + (size_t)f * S + 3 + 4 * j;
      double sg = q[0] * q0[0] + q[1] * q0[1] + q[2] * q0[2] + q[3] * q0[3];
      sg = sg < 0.0 ? -1.0 : 1.0;
      m[0] += sg * q[0]; m[1] += sg * q[1]; m[2] += sg * q[2]; m[3] += sg * q[3];
    }
    smgb_q_normalize(m);
  }
}

/* Q_j for every joint: the constant rotation with Q_j o_k = S o_partner(k)
 * for j's children k (S = reflection x -> -x), so that the reflected pose
 * W'_j = S W_partner(j) S Q_j puts every child where the mirror image of
 * the partner's child is, on the unchanged skeleton; the local rotations
 * become q'_j = Q_parent^-1 (S q_partner S) Q_j.
 *
 * Several children fix Q_j (Horn's least-squares fit). One child leaves a
 * twist about it free, no child leaves Q_j free: these are chosen so that
 * the clip's mean local rotation of the partner, mirrored, equals the
 * joint's own mean (a gait's left and right sides are mirror images on
 * average). Any other twist would be a valid mirror too, but the split of
 * a twist between a chain's joints (Spine -> Chest, a whole arm) would
 * then differ between a clip and its mirror, and a transition blending
 * the two local rotations would spin that limb through the twist.
 * Children already agreeing within SMGB_MIRROR_SYMMETRIC_DEG under an
 * uncorrected parent give the identity (symmetric rigs such as CMU are
 * reflected exactly as before). Parents precede children, so one forward
 * pass sees Q_parent first. fix[j]: Q_j is not the identity. */
static void mirror_corrections(const smgb_clip* c, const int32_t* partner,
                               double (*Q)[4], uint8_t* fix) {
  const smgb_skeleton* s = &c->skeleton;
  uint32_t J = s->joint_count, j, k;
  double* a = (double*)malloc(sizeof(double) * 6 * J);
  double(*mean)[4] = (double(*)[4])malloc(sizeof *mean * J);
  /* unpaired[j]: j has no counterpart but hangs below a joint that has
   * one (a prop or extra chain on one hand). Its "partner" is itself, so
   * its offset says nothing about the rig's frames: it keeps its parent's
   * correction and does not take part in its parent's fit. */
  uint8_t* unpaired = (uint8_t*)calloc(J, 1);
  uint8_t* sided = (uint8_t*)calloc(J, 1);
  if (mean) mean_rotations(c, mean);
  for (j = 0; j < J && sided && unpaired; ++j) {
    int32_t p = s->parents[j];
    sided[j] = partner[j] != (int32_t)j || (p >= 0 && sided[p]);
    unpaired[j] = sided[j] && partner[j] == (int32_t)j;
  }
  for (j = 0; j < J; ++j) {
    static const double ident[4] = {0.0, 0.0, 0.0, 1.0};
    const double* qp = j > 0 ? Q[s->parents[j]] : ident;
    uint32_t n = 0;
    int asym = 0;
    Q[j][0] = Q[j][1] = Q[j][2] = 0.0;
    Q[j][3] = 1.0;
    if (unpaired && unpaired[j]) {
      memcpy(Q[j], qp, sizeof Q[j]);
      continue;
    }
    for (k = j + 1; k < J && a; ++k) {
      const float* o = s->offsets[k];
      const float* m = s->offsets[partner[k]];
      double* ak = a + 6 * n;
      if (s->parents[k] != (int32_t)j || (unpaired && unpaired[k])) continue;
      ak[0] = o[0]; ak[1] = o[1]; ak[2] = o[2];
      ak[3] = -m[0]; ak[4] = m[1]; ak[5] = m[2];
      if (ak[0] * ak[0] + ak[1] * ak[1] + ak[2] * ak[2] < 1e-12 ||
          ak[3] * ak[3] + ak[4] * ak[4] + ak[5] * ak[5] < 1e-12)
        continue; /* zero-length helper joint: no direction */
      if (angle_between(ak, ak + 3) > SMGB_MIRROR_SYMMETRIC_DEG) asym = 1;
      ++n;
    }
    if (!asym && (n >= 2 || is_identity(qp))) continue;
    if (n >= 2) {
      double* from = (double*)malloc(sizeof(double) * 6 * n);
      uint32_t i;
      if (!from) continue;
      for (i = 0; i < n; ++i) {
        memcpy(from + 3 * i, a + 6 * i, sizeof(double) * 3);
        memcpy(from + 3 * (n + i), a + 6 * i + 3, sizeof(double) * 3);
      }
      smgb_horn(from, from + 3 * n, NULL, n, Q[j]);
      smgb_q_normalize(Q[j]);
      free(from);
    } else if (mean && a) {
      /* M = Q_parent^-1 (S mean_partner S): the mirrored mean before Q_j.
       * No child: Q_j = M^-1 mean_j. One child: Q_j = base R(axis, t) with
       * base taking the child's direction onto its target and t the twist
       * of (M base)^-1 mean_j about the child's direction. */
      const double* mp = mean[partner[j]];
      double mir[4] = {mp[0], -mp[1], -mp[2], mp[3]}, inv[4], M[4], D[4];
      smgb_q_conj(qp, inv);
      smgb_q_mul(inv, mir, M);
      if (n == 0) {
        smgb_q_conj(M, inv);
        smgb_q_mul(inv, mean[j], Q[j]);
      } else {
        double base[4], axis[3], len, t, tw[4];
        shortest_arc(a, a + 3, base);
        smgb_q_mul(M, base, D);
        smgb_q_conj(D, inv);
        smgb_q_mul(inv, mean[j], D);
        len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        axis[0] = a[0] / len; axis[1] = a[1] / len; axis[2] = a[2] / len;
        t = 2.0 * atan2(D[0] * axis[0] + D[1] * axis[1] + D[2] * axis[2],
                        D[3]);
        smgb_q_axis_angle(axis, t, tw);
        smgb_q_mul(base, tw, Q[j]);
      }
      smgb_q_normalize(Q[j]);
    }
  }
  for (j = 0; j < J; ++j) fix[j] = !is_identity(Q[j]);
  free(a);
  free(mean);
  free(unpaired);
  free(sided);
}

smg_result smgb_clip_mirror(const smgb_clip* src, smgb_clip* out) {
  int32_t* partner;
  smg_result r;
  if (!clip_valid(src) || !out) return SMG_ERROR_INVALID_ARGUMENT;
  partner = (int32_t*)malloc(sizeof *partner * src->skeleton.joint_count);
  if (!partner) return SMG_ERROR_OUT_OF_MEMORY;
  smgb_roles_partners(&src->skeleton, NULL, partner);
  /* Non-negative indices; signed and unsigned variants may alias. */
  r = smgb_clip_mirror_partners(src, (const uint32_t*)partner, out);
  free(partner);
  return r;
}

smg_result smgb_clip_mirror_partners(const smgb_clip* src,
                                     const uint32_t* partner_in,
                                     smgb_clip* out) {
  smgb_clip c;
  smg_result r;
  uint32_t J, j, f, stride;
  int32_t* partner;
  double(*Q)[4];
  uint8_t* fix;
  if (!clip_valid(src) || !out || !partner_in)
    return SMG_ERROR_INVALID_ARGUMENT;
  J = src->skeleton.joint_count;
  stride = SMGB_STRIDE(J);
  partner = (int32_t*)malloc(sizeof *partner * J);
  Q = (double(*)[4])malloc(sizeof *Q * J);
  fix = (uint8_t*)malloc(J);
  if (!partner || !Q || !fix) {
    free(partner);
    free(Q);
    free(fix);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < J; ++j)
    partner[j] = partner_in[j] < J ? (int32_t)partner_in[j] : (int32_t)j;
  /* Only swap true pairs (A->B and B->A); anything else stays in place. */
  for (j = 0; j < J; ++j)
    if (partner[partner[j]] != (int32_t)j) partner[j] = (int32_t)j;
  mirror_corrections(src, partner, Q, fix);

  r = clip_alloc_like(src, src->frame_count, &c);
  if (r != SMG_OK) {
    free(partner);
    free(Q);
    free(fix);
    return r;
  }
  /* Skeleton: names and parents stay. Below a symmetric joint each joint
   * takes its partner's offset reflected in x (parents of partners are
   * partners in sane rigs); below a corrected one it keeps its own, which
   * the correction turns onto the reflected partner's direction. */
  for (j = 0; j < J; ++j) {
    const float* o = src->skeleton.offsets[partner[j]];
    int32_t p = src->skeleton.parents[j];
    if (p >= 0 && fix[p]) continue;
    c.skeleton.offsets[j][0] = -o[0];
    c.skeleton.offsets[j][1] = o[1];
    c.skeleton.offsets[j][2] = o[2];
  }
  /* Reflection S = diag(-1, 1, 1): a rotation R becomes S R S, which for a
   * quaternion is (x, -y, -z, w); positions get x -> -x. With corrections:
   * local q'_j = Q_parent^-1 (S q_partner S) Q_j. */
  for (f = 0; f < src->frame_count; ++f) {
    const float* a = src->poses + (size_t)f * stride;
    float* o = c.poses + (size_t)f * stride;
    o[0] = -a[0];
    o[1] = a[1];
    o[2] = a[2];
    for (j = 0; j < J; ++j) {
      const float* q = a + 3 + 4 * partner[j];
      float* d = o + 3 + 4 * j;
      int32_t p = src->skeleton.parents[j];
      if (fix[j] || (p >= 0 && fix[p])) {
        double m[4] = {q[0], -q[1], -q[2], q[3]};
        if (p >= 0 && fix[p]) {
          double inv[4];
          smgb_q_conj(Q[p], inv);
          smgb_q_mul(inv, m, m);
        }
        if (fix[j]) smgb_q_mul(m, Q[j], m);
        smgb_q_normalize(m);
        d[0] = (float)m[0];
        d[1] = (float)m[1];
        d[2] = (float)m[2];
        d[3] = (float)m[3];
      } else {
        d[0] = q[0];
        d[1] = -q[1];
        d[2] = -q[2];
        d[3] = q[3];
      }
    }
  }
  free(partner);
  free(Q);
  free(fix);
  *out = c;
  return SMG_OK;
}

/* ---- retargeting and grounding ------------------------------------------ */

smg_result smgb_clip_retarget(smgb_clip* clip, const smgb_skeleton* reference,
                              smgb_error* err) {
  smgb_roles rc, rr;
  if (!clip_valid(clip) || !reference || !reference->names ||
      !reference->parents || !reference->offsets) {
    if (err) smgb_imp_errorf(err, "smgb_clip_retarget: invalid clip or reference");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  smgb_roles_guess(&clip->skeleton, &rc);
  smgb_roles_guess(reference, &rr);
  return smgb_clip_retarget_roles(clip, &rc, reference, &rr, err);
}

smg_result smgb_clip_retarget_roles(smgb_clip* clip,
                                    const smgb_roles* clip_roles,
                                    const smgb_skeleton* reference,
                                    const smgb_roles* reference_roles,
                                    smgb_error* err) {
  uint32_t J, j, f, stride;
  float leg_clip, leg_ref, k;
  if (err) err->message[0] = '\0';
  if (!clip_valid(clip) || !reference || !reference->names ||
      !reference->parents || !reference->offsets || !clip_roles ||
      !reference_roles) {
    smgb_imp_errorf(err, "smgb_clip_retarget: invalid clip or reference");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  J = clip->skeleton.joint_count;
  if (reference->joint_count != J) {
    smgb_imp_errorf(err,
                    "%s: hierarchy mismatch: %u joints, the reference "
                    "skeleton has %u",
                    clip->name, J, reference->joint_count);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  for (j = 0; j < J; ++j) {
    if (strcmp(clip->skeleton.names[j], reference->names[j]) != 0 ||
        clip->skeleton.parents[j] != reference->parents[j]) {
      smgb_imp_errorf(err,
                      "%s: hierarchy mismatch at joint %u: '%s' (parent %d) "
                      "vs reference '%s' (parent %d)",
                      clip->name, j, clip->skeleton.names[j],
                      (int)clip->skeleton.parents[j], reference->names[j],
                      (int)reference->parents[j]);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  }
  leg_clip = smgb_roles_leg_length(&clip->skeleton, clip_roles);
  leg_ref = smgb_roles_leg_length(reference, reference_roles);
  if (!(leg_clip > 1e-6f) || !(leg_ref > 1e-6f)) {
    smgb_imp_errorf(err,
                    "%s: cannot retarget: no left leg (roles left_upper_leg "
                    "down to left_foot) to measure in %s",
                    clip->name, leg_clip > 1e-6f ? "the reference" : "the clip");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  k = leg_ref / leg_clip;
  stride = SMGB_STRIDE(J);
  for (f = 0; f < clip->frame_count; ++f) {
    float* p = clip->poses + (size_t)f * stride;
    p[0] *= k;
    p[1] *= k;
    p[2] *= k;
  }
  memcpy(clip->skeleton.offsets, reference->offsets, sizeof(float) * 3 * J);
  return SMG_OK;
}

void smgb_clip_ground(smgb_clip* clip) {
  uint32_t J, f, j, stride;
  float* pos;
  double lowest = 1e300;
  if (!clip_valid(clip)) return;
  J = clip->skeleton.joint_count;
  stride = SMGB_STRIDE(J);
  pos = (float*)malloc(sizeof(float) * 3 * J);
  if (!pos) return;
  for (f = 0; f < clip->frame_count; ++f) {
    smgb_fk(&clip->skeleton, clip->poses + (size_t)f * stride, pos, NULL);
    for (j = 0; j < J; ++j)
      if (pos[3 * j + 1] < lowest) lowest = pos[3 * j + 1];
  }
  free(pos);
  for (f = 0; f < clip->frame_count; ++f)
    clip->poses[(size_t)f * stride + 1] -= (float)lowest;
}
