/*
 * bake_transition.c - the frames of transition edges (Kovar et al. 2002):
 * over the window, frame t is A_{a+t} blended with B_{b+t} placed in A's
 * space by the edge's 2-D alignment; A's weight eases out as
 * alpha(t) = 2s^3 - 3s^2 + 1 with s = (t+1)/k (so the last frame is pure
 * aligned B and the arrival frame B_{b+k} follows smoothly). Root position
 * is interpolated linearly, every rotation (root included) by slerp.
 *
 * The frames are appended to the pool only for transitions that survived
 * pruning, as two pseudo-clips ("lower transitions", "upper transitions",
 * flags SMGI_CLIP_BLEND) after all clip frames.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_pool.h"
#include "bake_transition.h"
#include "bake_math.h"

double smgb_blend_alpha(uint32_t t, uint32_t k) {
  double s = (double)(t + 1) / (double)k;
  return 2.0 * s * s * s - 3.0 * s * s + 1.0;
}

void smgb_pose_transform(const float* pose, const double g[3], float* out,
                         uint32_t stride) {
  double x, z, q[4], y[4], r[4];
  if (out != pose) memcpy(out, pose, stride * sizeof *out);
  smgb_g_apply(g, pose[0], pose[2], &x, &z);
  out[0] = (float)x;
  out[1] = pose[1];
  out[2] = (float)z;
  q[0] = pose[3]; q[1] = pose[4]; q[2] = pose[5]; q[3] = pose[6];
  smgb_q_yaw(g[2], y);
  smgb_q_mul(y, q, r);
  smgb_q_normalize(r);
  out[3] = (float)r[0]; out[4] = (float)r[1];
  out[5] = (float)r[2]; out[6] = (float)r[3];
}

void smgb_blend_pose(const smgb_bake* b, const smgb_edge* e, uint32_t t,
                     float* out) {
  uint32_t J = b->J, j, stride = b->stride, k = b->opt.window;
  const float* pa = b->poses + (size_t)(e->a + t) * stride;
  const float* pb0 = b->poses + (size_t)(e->b + t) * stride;
  float pb[3 + 4 * SMGB_MAX_JOINTS]; /* J <= SMGB_MAX_JOINTS (body init) */
  double alpha = smgb_blend_alpha(t, k), u = 1.0 - alpha;
  smgb_pose_transform(pb0, e->align, pb, stride);
  for (j = 0; j < 3; ++j) out[j] = (float)(alpha * pa[j] + u * pb[j]);
  for (j = 0; j < J; ++j) {
    double qa[4], qb[4], q[4];
    int c;
    for (c = 0; c < 4; ++c) {
      qa[c] = pa[3 + 4 * j + c];
      qb[c] = pb[3 + 4 * j + c];
    }
    smgb_q_slerp(qa, qb, u, q);
    for (c = 0; c < 4; ++c) out[3 + 4 * j + c] = (float)q[c];
  }
}

/* Gait phase of a blended frame: moves from A's to B's with the blend
 * weight u of B, the short way round the cycle, so a transition between
 * slightly different phases shows synchronization a short change of
 * phase speed instead of a jump halfway through the window. Without a
 * phase on both sides: `fallback`, the phase of the frame the contacts
 * come from. */
static float blend_phase(float pa, float pb, double u, float fallback) {
  double d, p;
  if (pa < 0.0f || pb < 0.0f) return fallback;
  d = (double)pb - (double)pa;
  d -= floor(d + 0.5); /* (-0.5, 0.5] */
  p = (double)pa + u * d;
  p -= floor(p);
  return p < 1.0 ? (float)p : 0.0f;
}

static smg_result materialize(smgb_bake* b, smgb_graph* g, uint32_t role,
                              const char* name) {
  uint32_t e, k = b->opt.window, count = 0, first, clip;
  smg_result r;
  smgb_pool_clip* pc;
  for (e = 0; e < g->edge_count; ++e)
    if (g->edges[e].kind == SMGB_EDGE_TRANSITION) ++count;
  if (count == 0) return SMG_OK;
  if ((r = smgb_pool_reserve(b, count * k)) != SMG_OK) return r;
  pc = smgb_pool_new_clip(b, name, count * k, 0, role | SMGI_CLIP_BLEND,
                          SMGI_NONE);
  if (!pc) return SMG_ERROR_OUT_OF_MEMORY;
  clip = (uint32_t)(pc - b->clips);
  first = b->frame_count;
  for (e = 0; e < g->edge_count; ++e) {
    smgb_edge* ed = &g->edges[e];
    uint32_t t;
    if (ed->kind != SMGB_EDGE_TRANSITION) continue;
    ed->first_frame = b->frame_count;
    ed->frame_count = k;
    for (t = 0; t < k; ++t) {
      uint32_t f = b->frame_count++;
      const smgi_frame* src = &b->frames[t < k / 2 ? ed->a + t : ed->b + t];
      smgi_frame* fr = &b->frames[f];
      smgb_blend_pose(b, ed, t, b->poses + (size_t)f * b->stride);
      memset(fr, 0, sizeof *fr);
      fr->flags = src->flags & (SMGI_FRAME_LEFT_CONTACT |
                                SMGI_FRAME_RIGHT_CONTACT);
      fr->clip = clip;
      fr->phase = blend_phase(b->frames[ed->a + t].phase,
                              b->frames[ed->b + t].phase,
                              1.0 - smgb_blend_alpha(t, k), src->phase);
    }
  }
  smgb_pool_derive(b, first, b->frame_count - first);
  return SMG_OK;
}

smg_result smgb_materialize_transitions(smgb_bake* b) {
  smg_result r;
  uint32_t e;
  /* original edges play their clip frames in place */
  for (e = 0; e < b->lower.edge_count; ++e) {
    smgb_edge* ed = &b->lower.edges[e];
    if (ed->kind == SMGB_EDGE_ORIGINAL) {
      ed->first_frame = ed->a;
      ed->frame_count = ed->b - ed->a;
    }
  }
  for (e = 0; e < b->upper.edge_count; ++e) {
    smgb_edge* ed = &b->upper.edges[e];
    if (ed->kind == SMGB_EDGE_ORIGINAL) {
      ed->first_frame = ed->a;
      ed->frame_count = ed->b - ed->a;
    }
  }
  if ((r = materialize(b, &b->lower, SMGI_CLIP_LOWER, "lower transitions")))
    return r;
  return materialize(b, &b->upper, SMGI_CLIP_UPPER, "upper transitions");
}
