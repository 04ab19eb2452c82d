/*
 * bake_contacts.c - per-frame foot-contact labels and gait phase.
 *
 * A foot is planted when its ankle or toe joint is low (within
 * contact_height of the lowest that joint gets in the clip) and slow
 * (horizontal speed below contact_speed). Hysteresis: a planted foot stays
 * planted until both joints exceed 1.5x those limits, so noise around the
 * thresholds does not flicker. One-frame gaps inside a contact are filled.
 *
 * Gait phase: 0 at each left foot-strike (a frame where the left contact
 * begins), rising linearly to 1 at the next one. Before the first and after
 * the last strike the neighbouring cycle's period is extrapolated for at most
 * one period; frames no cycle reaches (and clips with fewer than two left
 * strikes, e.g. actions in place) get -1.
 */
#include <math.h>
#include <stdlib.h>

#include "bake_graph.h"

static double joint_y(const smgb_bake* b, uint32_t f, uint32_t j) {
  return b->positions[((size_t)f * b->J + j) * 3u + 1u];
}

static double joint_speed(const smgb_bake* b, const smgb_pool_clip* c,
                          uint32_t f, uint32_t j) {
  uint32_t f0 = f > c->first ? f - 1 : f;
  uint32_t f1 = f + 1 < c->first + c->count ? f + 1 : f;
  const float* a = b->positions + ((size_t)f0 * b->J + j) * 3u;
  const float* d = b->positions + ((size_t)f1 * b->J + j) * 3u;
  double dx = d[0] - a[0], dz = d[2] - a[2];
  if (f1 == f0) return 0.0;
  return sqrt(dx * dx + dz * dz) * b->opt.frame_rate / (double)(f1 - f0);
}

static void foot_contacts(smgb_bake* b, const smgb_pool_clip* c,
                          const uint32_t leg[4], uint32_t bit) {
  double min_a = 1e30, min_t = 1e30;
  double H = b->opt.contact_height, V = b->opt.contact_speed;
  uint32_t f;
  int on = 0;
  for (f = c->first; f < c->first + c->count; ++f) {
    double ya = joint_y(b, f, leg[2]), yt = joint_y(b, f, leg[3]);
    if (ya < min_a) min_a = ya;
    if (yt < min_t) min_t = yt;
  }
  for (f = c->first; f < c->first + c->count; ++f) {
    double ha = joint_y(b, f, leg[2]) - min_a;
    double ht = joint_y(b, f, leg[3]) - min_t;
    double va = joint_speed(b, c, f, leg[2]);
    double vt = joint_speed(b, c, f, leg[3]);
    double s = on ? 1.5 : 1.0;
    on = (ha < H * s && va < V * s) || (ht < H * s && vt < V * s);
    if (on)
      b->frames[f].flags |= bit;
    else
      b->frames[f].flags &= ~bit;
  }
  /* Fill one-frame gaps. */
  for (f = c->first + 1; f + 1 < c->first + c->count; ++f) {
    if (!(b->frames[f].flags & bit) && (b->frames[f - 1].flags & bit) &&
        (b->frames[f + 1].flags & bit))
      b->frames[f].flags |= bit;
  }
}

void smgb_contacts_clip(smgb_bake* b, uint32_t clip) {
  const smgb_pool_clip* c = &b->clips[clip];
  uint32_t f, n = 0, i;
  uint32_t* strikes;
  foot_contacts(b, c, b->body.left_leg, SMGI_FRAME_LEFT_CONTACT);
  foot_contacts(b, c, b->body.right_leg, SMGI_FRAME_RIGHT_CONTACT);
  for (f = c->first; f < c->first + c->count; ++f) b->frames[f].phase = -1.0f;
  strikes = malloc((c->count + 1) * sizeof *strikes);
  if (!strikes) return; /* phase stays undefined; never fatal */
  for (f = c->first + 1; f < c->first + c->count; ++f) {
    if ((b->frames[f].flags & SMGI_FRAME_LEFT_CONTACT) &&
        !(b->frames[f - 1].flags & SMGI_FRAME_LEFT_CONTACT))
      strikes[n++] = f;
  }
  if (n >= 2) {
    for (i = 0; i + 1 < n; ++i) {
      uint32_t len = strikes[i + 1] - strikes[i];
      for (f = strikes[i]; f < strikes[i + 1]; ++f)
        b->frames[f].phase = (float)(f - strikes[i]) / (float)len;
    }
    {
      uint32_t p0 = strikes[1] - strikes[0];
      uint32_t p1 = strikes[n - 1] - strikes[n - 2];
      for (f = c->first; f < strikes[0]; ++f) {
        uint32_t back = strikes[0] - f;
        if (back <= p0) b->frames[f].phase = 1.0f - (float)back / (float)p0;
        if (b->frames[f].phase >= 1.0f) b->frames[f].phase = 0.0f;
      }
      for (f = strikes[n - 1]; f < c->first + c->count; ++f) {
        uint32_t fw = f - strikes[n - 1];
        if (fw < p1) b->frames[f].phase = (float)fw / (float)p1;
      }
    }
  }
  free(strikes);
}
