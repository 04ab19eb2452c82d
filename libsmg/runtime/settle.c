/*
 * settle.c - the settling step of a stop (settle.h).
 */
#include "settle.h"

#include <math.h>

#include "graph_derived.h"
#include "idle.h"
#include "tuning.h"

void smgi_settle_plan(const smg_graph* g, const float (*toe)[2], float gx,
                      float gz, float h, float width, smgi_settle* sp) {
  const smgi_idle* idle = &smgi_derived_of(g)->idle;
  float fx, fz, lx, lz;
  smgi_rot2(h, 0.0f, 1.0f, &fx, &fz);
  smgi_rot2(h, 1.0f, 0.0f, &lx, &lz);
  /* the front foot stands, the rear one steps up beside it */
  const float a0 = (toe[0][0] - gx) * fx + (toe[0][1] - gz) * fz;
  const float a1 = (toe[1][0] - gx) * fx + (toe[1][1] - gz) * fz;
  const uint32_t stance = a0 >= a1 ? 0u : 1u, step = 1u - stance;
  sp->step = step;
  sp->glide[0] = sp->glide[1] = 0.0f;
  if (idle->count > 0) {
    /* the standing motion placed with its stance foot on ours */
    float ox, oz;
    smgi_rot2(h, idle->toe[stance][0], idle->toe[stance][1], &ox, &oz);
    sp->G.x = toe[stance][0] - ox;
    sp->G.z = toe[stance][1] - oz;
    sp->G.h = h;
    smgi_rot2(h, idle->toe[step][0], idle->toe[step][1], &ox, &oz);
    sp->to[0] = sp->G.x + ox;
    sp->to[1] = sp->G.z + oz;
    sp->end[0] = sp->G.x;
    sp->end[1] = sp->G.z;
    return;
  }
  /* hip width beside the stance foot, on the stepping foot's side, and
   * the hips over the middle of the feet: they move on by half the
   * step */
  const float side = (toe[step][0] - toe[stance][0]) * lx +
                             (toe[step][1] - toe[stance][1]) * lz >=
                         0.0f
                     ? 1.0f
                     : -1.0f;
  sp->to[0] = toe[stance][0] + side * width * lx;
  sp->to[1] = toe[stance][1] + side * width * lz;
  /* along the facing: the hips carry on forwards (sideways they already
   * stand between the feet) */
  const float along = 0.5f * ((sp->to[0] - toe[step][0]) * fx +
                              (sp->to[1] - toe[step][1]) * fz);
  sp->glide[0] = along * fx;
  sp->glide[1] = along * fz;
  const float most = SMGI_REST_GLIDE_MAX * g->data.info->leg_length;
  const float gl = sqrtf(sp->glide[0] * sp->glide[0] +
                         sp->glide[1] * sp->glide[1]);
  if (gl > most) {
    sp->glide[0] *= most / gl;
    sp->glide[1] *= most / gl;
  }
  sp->end[0] = gx + sp->glide[0];
  sp->end[1] = gz + sp->glide[1];
}

void smgi_settle_shift(const smg_graph* g, uint32_t frame, float* dx,
                       float* dz) {
  const smgi_info* info = g->data.info;
  const float* r2 = g->data.frames[frame].root2d;
  float toe[2][2], p[3], hl[3], hr[3];
  for (uint32_t f = 0; f < 2u; ++f) {
    smgi_frame_joint(g, frame, f ? info->right_leg[3] : info->left_leg[3], p);
    toe[f][0] = p[0];
    toe[f][1] = p[2];
  }
  smgi_frame_joint(g, frame, info->left_leg[0], hl);
  smgi_frame_joint(g, frame, info->right_leg[0], hr);
  const float width = sqrtf((hl[0] - hr[0]) * (hl[0] - hr[0]) +
                            (hl[2] - hr[2]) * (hl[2] - hr[2]));
  smgi_settle sp;
  smgi_settle_plan(g, (const float(*)[2])toe, r2[0], r2[1], r2[2], width, &sp);
  *dx = sp.end[0] - r2[0];
  *dz = sp.end[1] - r2[1];
}


float smgi_settle_lift(const smg_graph* g, uint32_t frame) {
  const smgi_info* info = g->data.info;
  float l[3], r[3];
  smgi_frame_joint(g, frame, info->left_leg[3], l);
  smgi_frame_joint(g, frame, info->right_leg[3], r);
  return fabsf(l[1] - r[1]);
}
