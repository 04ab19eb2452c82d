/*
 * root_motion.c - root motion for the engine's mover. The step records how
 * far the ground transform moved (smg_character_get_root_motion); when the
 * engine's mover put the character elsewhere (a wall stopped it), the
 * character is moved there rigidly, like the root steering moves it
 * (steer.c): the pose, the queued placements (the two the pose samples
 * directly, further ones through the pending correction, smgi_lag_apply),
 * the steering's own-motion reference, planted feet, the carried
 * ground and where the rest stage holds a standing character. The pose in character space does not change, so nothing pops;
 * the move counts towards the steering's drift, which re-plans from the
 * new place once it adds up.
 */
#include <math.h>
#include <string.h>

#include "root_motion.h"

void smgi_root_motion_begin(smgi_root_motion* rm, const smgi_pose* pose) {
  rm->before[0] = pose->ground[0];
  rm->before[1] = pose->ground_y;
  rm->before[2] = pose->ground[1];
  rm->before[3] = pose->heading;
}

void smgi_root_motion_end(smgi_root_motion* rm, const smgi_pose* pose,
                          float dt) {
  rm->dt = dt;
  rm->delta[0] = pose->ground[0] - rm->before[0];
  rm->delta[1] = pose->ground_y - rm->before[1];
  rm->delta[2] = pose->ground[1] - rm->before[2];
  rm->delta[3] = smgi_wrap_angle(pose->heading - rm->before[3]);
}

/* Rotation by da (cos c, sin s) about (px, pz), then the shift (tx, tz);
 * the same convention as the steering's (heading + da). */
typedef struct move {
  float c, s, da, px, pz, tx, tz, dy;
  float yaw[4], yaw_inv[4];
} move;

static void move_xz(const move* m, float* x, float* z) {
  const float vx = *x - m->px, vz = *z - m->pz;
  *x = m->px + m->c * vx + m->s * vz + m->tx;
  *z = m->pz - m->s * vx + m->c * vz + m->tz;
}

static void move_xf(const move* m, smgi_xform2* x) {
  move_xz(m, &x->x, &x->z);
  x->h = smgi_wrap_angle(x->h + m->da);
}

static void move_rot(const move* m, float* q) {
  float r[4];
  smgi_q_mul(m->yaw, q, r);
  smgi_q_normalize(r);
  memcpy(q, r, sizeof r);
}

/* a world-space correction (IK's hip and knee fixes) seen from the moved
 * character: yaw * fix * yaw^-1 */
static void move_fix(const move* m, float* q) {
  float a[4], b[4];
  smgi_q_mul(m->yaw, q, a);
  smgi_q_mul(a, m->yaw_inv, b);
  smgi_q_normalize(b);
  memcpy(q, b, sizeof b);
}

static void move_point(const move* m, float* p) {
  move_xz(m, &p[0], &p[2]);
  p[1] += m->dy;
}

void smgi_root_motion_place(const smgi_root_motion* rm, smgi_pose* pose,
                            smgi_lower* lower, smgi_steer* st, smgi_ik* ik,
                            smgi_rest* rest, uint32_t joint_count,
                            float* anchor, const float* position,
                            float heading) {
  move m;
  m.px = pose->ground[0];
  m.pz = pose->ground[1];
  m.da = smgi_wrap_angle(heading - pose->heading);
  smgi_sincosf(m.da, &m.s, &m.c);
  m.tx = position[0] - pose->ground[0];
  m.tz = position[2] - pose->ground[1];
  m.dy = position[1] - pose->ground_y;
  smgi_q_yaw(m.da, m.yaw);
  smgi_q_conj(m.yaw, m.yaw_inv);

  /* the pose and its cached world transforms */
  move_point(&m, pose->root);
  move_rot(&m, pose->rot);
  for (uint32_t j = 0; j < joint_count; ++j) {
    move_point(&m, pose->wpos + 3u * j);
    move_rot(&m, pose->wrot + 4u * j);
  }
  pose->ground[0] = position[0];
  pose->ground[1] = position[2];
  pose->heading = smgi_wrap_angle(heading);
  pose->ground_y = position[1];

  /* the queued placements: the next two as stored, further ones through
   * the correction pending for them (kept about a point near the
   * character: far from the origin, moving every entry at every call
   * would add up their rounding) */
  for (uint32_t i = 0; i < lower->count && i < 2u; ++i) {
    smgi_qentry* e = smgi_q_at(lower, i);
    move_xf(&m, &e->W);
    move_xf(&m, &e->M);
  }
  if (lower->count > 2u)
    smgi_lag_follow(&lower->lag, m.c, m.s, m.da, m.px, m.pz, m.tx, m.tz);
  else
    smgi_lag_reset(&lower->lag);

  /* steering: the motion's own speed and turning are measured from its
   * last ground transform, which moves too; the move counts as drift */
  smgi_xform2 prev = {st->prev_x, st->prev_z, st->prev_h};
  move_xf(&m, &prev);
  st->prev_x = prev.x;
  st->prev_z = prev.z;
  st->prev_h = prev.h;
  st->drift_turn += fabsf(m.da);
  st->drift_move += sqrtf(m.tx * m.tx + m.tz * m.tz);

  /* Planted feet move with the character, except by the part of the move
   * that takes back the steering's slide of the last step: the steering
   * slid the body over feet it left in place, and a mover that stops the
   * body there (the steering pressing it against a wall on its way back
   * to the path) must leave them in place too, or they would slide with
   * it step after step and spring back at lift-off. */
  float keep[2] = {0.0f, 0.0f};
  {
    const float sx = st->slide[0] * rm->dt, sz = st->slide[1] * rm->dt;
    const float s2 = sx * sx + sz * sz, back = -(m.tx * sx + m.tz * sz);
    if (s2 > 0.0f && back > 0.0f) {
      const float k = back < s2 ? back / s2 : 1.0f;
      keep[0] = k * sx;
      keep[1] = k * sz;
    }
  }
  for (uint32_t f = 0; f < 2u; ++f) {
    smgi_foot* foot = &ik->feet[f];
    move_point(&m, foot->anchor);
    foot->anchor[0] += keep[0];
    foot->anchor[2] += keep[1];
    if (foot->toe[1] < INFINITY) move_point(&m, foot->toe);
    if (foot->floor_y > -INFINITY) foot->floor_y += m.dy;
    /* stand_y is a height above the ground (flat: the data's floor; a
     * move up or down turns the ground on, below), which moves itself */
    if (foot->shown[0] < INFINITY) move_xz(&m, &foot->shown[0], &foot->shown[1]);
    move_fix(&m, foot->fix[0]);
    move_fix(&m, foot->fix[1]);
    smgi_ground* g = &ik->ground;
    if (g->prev_toe[f][0] < INFINITY)
      move_xz(&m, &g->prev_toe[f][0], &g->prev_toe[f][1]);
  }

  /* the ground carried: the engine's floor is at position[1] here. With
   * no ground given, a level floor at that height. */
  smgi_ground* g = &ik->ground;
  if (!g->on && m.dy != 0.0f) {
    g->on = 1u;
    g->foot[0] = g->foot[1] = g->root = position[1];
    g->root_y = g->foot_y[0] = g->foot_y[1] = position[1];
  } else if (g->on) {
    /* rigidly, measurements included (a set_ground before the next step
     * replaces those) */
    g->root += m.dy;
    if (!isnan(g->root_y)) g->root_y += m.dy;
    for (uint32_t f = 0; f < 2u; ++f) {
      g->foot[f] += m.dy;
      if (!isnan(g->foot_y[f])) g->foot_y[f] += m.dy;
    }
  }

  /* standing still (rest.c): where it holds the feet, where a step began,
   * the point it turns about, the standing motion's placement and the
   * hips' glide (a shift: turned only) */
  for (uint32_t f = 0; f < 2u; ++f) move_xz(&m, &rest->hold[f][0], &rest->hold[f][1]);
  move_xz(&m, &rest->from[0], &rest->from[1]);
  move_xz(&m, &rest->pivot[0], &rest->pivot[1]);
  move_xf(&m, &rest->M);
  {
    const float gx = rest->glide[0], gz = rest->glide[1];
    rest->glide[0] = m.c * gx + m.s * gz;
    rest->glide[1] = -m.s * gx + m.c * gz;
  }

  /* where to stay without a path moves along */
  move_xz(&m, &anchor[0], &anchor[1]);
}
