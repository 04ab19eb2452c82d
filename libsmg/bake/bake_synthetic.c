/*
 * bake_synthetic.c - procedural SYNTHETIC clips on the CMU 31-joint
 * hierarchy with exact ground truth (see bake_synthetic.h).
 *
 * Per frame: plan the pelvis (path point + small sway/bob/rotation), plan
 * both feet (planted at a footprint or on a swing arc), lower the pelvis if a
 * foot would be out of reach, then solve each leg with closed-form two-bone
 * IK so the ankle lands exactly on its target. Arms, spine and head are
 * driven by simple periodic angle curves (they carry no ground truth).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_import_util.h"
#include "bake_math.h"
#include "bake_synthetic.h"

#define J_COUNT 31
enum {
  J_HIPS = 0, J_LHIPJ = 1, J_LUPLEG = 2, J_LLEG = 3, J_LFOOT = 4, J_LTOE = 5,
  J_RHIPJ = 6, J_RUPLEG = 7, J_RLEG = 8, J_RFOOT = 9, J_RTOE = 10,
  J_LOWERBACK = 11, J_SPINE = 12, J_SPINE1 = 13, J_NECK = 14, J_NECK1 = 15,
  J_HEAD = 16, J_LSHOULDER = 17, J_LARM = 18, J_LFOREARM = 19, J_LHAND = 20,
  J_LFINGER = 21, J_LINDEX = 22, J_LTHUMB = 23, J_RSHOULDER = 24, J_RARM = 25,
  J_RFOREARM = 26, J_RHAND = 27, J_RFINGER = 28, J_RINDEX = 29, J_RTHUMB = 30
};

static const char* const k_names[J_COUNT] = {
    "Hips", "LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase",
    "RHipJoint", "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase",
    "LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head", "LeftShoulder",
    "LeftArm", "LeftForeArm", "LeftHand", "LeftFingerBase", "LeftHandIndex1",
    "LThumb", "RightShoulder", "RightArm", "RightForeArm", "RightHand",
    "RightFingerBase", "RightHandIndex1", "RThumb"};

static const int32_t k_parents[J_COUNT] = {
    -1, 0, 1, 2, 3, 4, 0, 6, 7, 8, 9, 0, 11, 12, 13, 14, 15, 13, 17, 18, 19,
    20, 21, 20, 13, 24, 25, 26, 27, 28, 27};

/* Symmetric, CMU-like proportions (metres); rest pose: legs straight down,
 * arms along +-X, facing +Z. Zero-length helper joints as in CMU. */
#define HIP_X 0.09
#define HIP_Y (-0.06)
#define THIGH 0.42
#define SHIN 0.42
#define ANKLE_H 0.07 /* ankle height with the foot flat on the floor */
static const float k_offsets[J_COUNT][3] = {
    {0, 0, 0},           {0, 0, 0},          {0.09f, -0.06f, 0},
    {0, -0.42f, 0},      {0, -0.42f, 0},     {0, -0.05f, 0.13f},
    {0, 0, 0},           {-0.09f, -0.06f, 0}, {0, -0.42f, 0},
    {0, -0.42f, 0},      {0, -0.05f, 0.13f}, {0, 0, 0},
    {0, 0.11f, -0.01f},  {0, 0.11f, 0},      {0, 0, 0},
    {0, 0.10f, 0},       {0, 0.10f, 0.01f},  {0, 0, 0},
    {0.17f, 0.07f, -0.02f}, {0.29f, 0, 0},   {0.25f, 0, 0},
    {0, 0, 0},           {0.04f, 0, 0},      {0, 0, 0},
    {0, 0, 0},           {-0.17f, 0.07f, -0.02f}, {-0.29f, 0, 0},
    {-0.25f, 0, 0},      {0, 0, 0},          {-0.04f, 0, 0},
    {0, 0, 0}};

smg_result smgb_synth_skeleton(smgb_skeleton* out) {
  smgb_skeleton s;
  uint32_t j;
  if (!out) return SMG_ERROR_INVALID_ARGUMENT;
  memset(&s, 0, sizeof s);
  s.joint_count = J_COUNT;
  s.names = (char(*)[SMGB_NAME_MAX])calloc(J_COUNT, sizeof *s.names);
  s.parents = (int32_t*)malloc(sizeof *s.parents * J_COUNT);
  s.offsets = (float(*)[3])malloc(sizeof *s.offsets * J_COUNT);
  if (!s.names || !s.parents || !s.offsets) {
    smgb_skeleton_free(&s);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < J_COUNT; ++j) {
    snprintf(s.names[j], SMGB_NAME_MAX, "%s", k_names[j]);
    s.parents[j] = k_parents[j];
    memcpy(s.offsets[j], k_offsets[j], sizeof s.offsets[j]);
  }
  *out = s;
  return SMG_OK;
}

/* ---- gait description ---------------------------------------------------- */

typedef struct gait {
  int standing;
  double v, L, T, D;      /* speed, step length, stride period, duty */
  double kappa;           /* path curvature (turn_rate / v) */
  double width;           /* footprint lateral distance from the path */
  double lift;            /* swing apex above ANKLE_H */
  double h0, bob;         /* pelvis nominal height and bob amplitude */
  int bob_sign;           /* +1: high at mid-stance (walk), -1: low (run) */
  double sway;            /* lateral pelvis sway amplitude */
  double yaw_osc, roll;   /* pelvis oscillation amplitudes, rad */
  double lean;            /* forward pelvis/spine lean, rad */
  double arm_swing, elbow;/* rad */
  /* a walk that stops or starts (SMGB_SYNTH_WALK_STOP/START): the pelvis
   * speed ramps over ramp_seconds from ramp_at (0: constant speed) */
  int ramp;               /* 0 none, 1 to rest, 2 from rest */
  double ramp_at, ramp_seconds;
} gait;

static double frac(double x) { return x - floor(x); }

/* Minimum-jerk ease: zero velocity and acceleration at both ends, so a foot
 * leaving or reaching its footprint does so smoothly. */
static double ease(double u) {
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

/* Integral over [0, u] of ease (u in [0, 1]). */
static double ease_integral(double u) {
  return u * u * u * u * (2.5 + u * (-3.0 + u));
}

/* Distance the pelvis has travelled along the path at time t: v t, or
 * with the speed ramping to rest (ramp 1: v (1 - ease)) or from rest
 * (ramp 2: v ease) over ramp_seconds from ramp_at - as a person stops or
 * starts within a couple of steps at an unchanged cadence. */
static double dist_at(const gait* g, double t) {
  const double u0 = (t - g->ramp_at) / g->ramp_seconds;
  const double u = u0 < 0.0 ? 0.0 : u0 > 1.0 ? 1.0 : u0;
  if (g->ramp == 1) {
    if (t < g->ramp_at) return g->v * t;
    return g->v * (g->ramp_at + g->ramp_seconds * (u - ease_integral(u)));
  }
  if (t < g->ramp_at) return 0.0;
  return g->v * (g->ramp_seconds * ease_integral(u) +
                 (u0 > 1.0 ? t - g->ramp_at - g->ramp_seconds : 0.0));
}

/* The share of the walk's speed the pelvis moves at (1 without a ramp). */
static double speed_share(const gait* g, double t) {
  if (!g->ramp) return 1.0;
  double u = (t - g->ramp_at) / g->ramp_seconds;
  u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
  return g->ramp == 1 ? 1.0 - ease(u) : ease(u);
}

/* Path point and heading at arc length s (start at origin, heading 0). */
static void path_at(const gait* g, double s, double pos[2], double* heading) {
  double h = g->kappa * s;
  if (fabs(g->kappa) < 1e-9) {
    pos[0] = 0.0;
    pos[1] = s;
  } else {
    pos[0] = (1.0 - cos(h)) / g->kappa;
    pos[1] = sin(h) / g->kappa;
  }
  *heading = h;
}

/* Footprint m of foot f: ankle position (x, z) and heading. */
static void footprint(const gait* g, int f, double m, double pos[2],
                      double* heading) {
  double off = f ? 0.5 : 0.0, h, side = f ? -1.0 : 1.0;
  if (g->standing) {
    /* Feet slightly apart, toes out a little. */
    pos[0] = side * g->width;
    pos[1] = 0.0;
    *heading = side * 0.12;
    return;
  }
  /* where the pelvis is at the stance's middle (with a ramp the
   * footprints close up as it slows: side by side once it stands) */
  if (g->ramp)
    path_at(g, dist_at(g, g->T * (m + off + 0.5 * g->D)), pos, &h);
  else
    path_at(g, g->v * g->T * (m + off + 0.5 * g->D), pos, &h);
  /* Left of heading h is the direction of heading h + pi/2: (cos h, -sin h).
   */
  pos[0] += side * g->width * cos(h);
  pos[1] += side * g->width * -sin(h);
  *heading = h;
}

/* Ankle target, foot heading and pitch of foot f at time t. */
static void foot_at(const gait* g, int f, double t, double a[3],
                    double* heading, double* pitch) {
  double u, p, m, p0[2], p1[2], h0, h1, e, s;
  if (g->standing) {
    footprint(g, f, 0.0, p0, heading);
    a[0] = p0[0];
    a[1] = ANKLE_H;
    a[2] = p0[1];
    *pitch = 0.0;
    return;
  }
  u = t / g->T - (f ? 0.5 : 0.0);
  m = floor(u);
  p = u - m;
  if (p < g->D) {
    footprint(g, f, m, p0, heading);
    a[0] = p0[0];
    a[1] = ANKLE_H;
    a[2] = p0[1];
    *pitch = 0.0;
    return;
  }
  s = (p - g->D) / (1.0 - g->D);
  e = ease(s);
  footprint(g, f, m, p0, &h0);
  footprint(g, f, m + 1.0, p1, &h1);
  a[0] = p0[0] + (p1[0] - p0[0]) * e;
  a[2] = p0[1] + (p1[1] - p0[1]) * e;
  a[1] = ANKLE_H + g->lift * sin(SMGB_M_PI * s) * sin(SMGB_M_PI * s);
  *heading = h0 + (h1 - h0) * e;
  *pitch = 0.35 * sin(SMGB_M_PI * s) * (1.0 - s);
  if (g->ramp) {
    /* a short step (under a third of a step length) lifts the foot
     * less, none stays planted */
    const double dx = p1[0] - p0[0], dz = p1[1] - p0[1];
    double k = sqrt(3.0 * sqrt(dx * dx + dz * dz) / g->L);
    k = k > 1.0 ? 1.0 : k;
    a[1] = ANKLE_H + (a[1] - ANKLE_H) * k;
    *pitch *= k;
  }
}

/* World rotation of a leg bone along unit direction `b` (its local -Y),
 * with its local +Z in the leg plane toward `fwd`. */
static void bone_rotation(const double b[3], const double fwd[3],
                          double q[4]) {
  double X[3], Y[3], Z[3], dot, pn;
  int i;
  for (i = 0; i < 3; ++i) Y[i] = -b[i];
  dot = fwd[0] * Y[0] + fwd[1] * Y[1] + fwd[2] * Y[2];
  for (i = 0; i < 3; ++i) Z[i] = fwd[i] - dot * Y[i];
  pn = sqrt(Z[0] * Z[0] + Z[1] * Z[1] + Z[2] * Z[2]);
  for (i = 0; i < 3; ++i) Z[i] /= pn;
  X[0] = Y[1] * Z[2] - Y[2] * Z[1];
  X[1] = Y[2] * Z[0] - Y[0] * Z[2];
  X[2] = Y[0] * Z[1] - Y[1] * Z[0];
  smgb_q_from_axes(X, Y, Z, q);
}

/* Two-bone IK: hip at `hip`, ankle target `a`, knee bending toward `fwd`.
 * Writes the world rotations of thigh and shank (rest bones point -Y). */
static void leg_ik(const double hip[3], const double a[3], const double fwd[3],
                   double w_thigh[4], double w_shank[4]) {
  double d[3] = {a[0] - hip[0], a[1] - hip[1], a[2] - hip[2]};
  double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double ax[3], pole[3], pn, x, y, knee[3], b[3], dot;
  const double l1 = THIGH, l2 = SHIN, reach = (THIGH + SHIN) * 0.99999;
  int i;
  if (len < 1e-9) len = 1e-9;
  for (i = 0; i < 3; ++i) ax[i] = d[i] / len;
  if (len > reach) len = reach; /* never happens: pelvis height is capped */
  if (len < fabs(l1 - l2) + 1e-6) len = fabs(l1 - l2) + 1e-6;
  dot = fwd[0] * ax[0] + fwd[1] * ax[1] + fwd[2] * ax[2];
  for (i = 0; i < 3; ++i) pole[i] = fwd[i] - dot * ax[i];
  pn = sqrt(pole[0] * pole[0] + pole[1] * pole[1] + pole[2] * pole[2]);
  for (i = 0; i < 3; ++i) pole[i] /= pn; /* fwd is never parallel to the leg */
  x = (l1 * l1 - l2 * l2 + len * len) / (2.0 * len);
  y = sqrt(l1 * l1 - x * x > 0.0 ? l1 * l1 - x * x : 0.0);
  for (i = 0; i < 3; ++i) knee[i] = hip[i] + ax[i] * x + pole[i] * y;
  /* Thigh along hip->knee, shank along knee->ankle (the target, up to the
   * reach clamp). */
  for (i = 0; i < 3; ++i) b[i] = (knee[i] - hip[i]) / l1;
  bone_rotation(b, fwd, w_thigh);
  for (i = 0; i < 3; ++i) b[i] = (hip[i] + ax[i] * len - knee[i]) / l2;
  bone_rotation(b, fwd, w_shank);
}

static void put_q(float* pose, int j, const double q[4]) {
  pose[3 + 4 * j + 0] = (float)q[0];
  pose[3 + 4 * j + 1] = (float)q[1];
  pose[3 + 4 * j + 2] = (float)q[2];
  pose[3 + 4 * j + 3] = (float)q[3];
}

/* q = Ry(y) * Rx(x) * Rz(z) */
static void q_yxz(double y, double x, double z, double q[4]) {
  double a[4], b[4];
  smgb_q_axis(1, y, a);
  smgb_q_axis(0, x, b);
  smgb_q_mul(a, b, q);
  smgb_q_axis(2, z, b);
  smgb_q_mul(q, b, q);
}

/* Arm rotation: lower the arm by `down` (rad, toward -Y), then swing it
 * forward by `fwd` about the x axis; side = +1 left (bone +X), -1 right. */
static void arm_q(int side, double down, double fwd, double q[4]) {
  double a[4], b[4];
  smgb_q_axis(0, -fwd, a);
  smgb_q_axis(2, -side * down, b);
  smgb_q_mul(a, b, q);
}

/* Elbow flexion (forearm toward +Z in the arm's frame). */
static void elbow_q(int side, double flex, double q[4]) {
  smgb_q_axis(1, -side * flex, q);
}

/* Upper-body pose for standing actions and locomotion. */
static void upper_body(const gait* g, smgb_synth_kind kind, double t,
                       double gait_phase, double pelvis_yaw_osc, float* pose) {
  double q[4], guard[4], strike[4];
  int side;
  /* Spine counter-rotates the pelvis oscillation and leans a little. */
  q_yxz(-pelvis_yaw_osc * 0.9, g->lean * 0.3, 0.0, q);
  put_q(pose, J_LOWERBACK, q);
  q_yxz(0.0, 0.03, 0.0, q);
  put_q(pose, J_SPINE, q);
  put_q(pose, J_SPINE1, q);
  q_yxz(0.0, -0.06 - g->lean * 0.5, 0.0, q);
  put_q(pose, J_NECK1, q);

  if (kind == SMGB_SYNTH_WALK || kind == SMGB_SYNTH_RUN) {
    /* Arms swing opposite to the legs: left arm forward with right foot. */
    for (side = 1; side >= -1; side -= 2) {
      double ph = side > 0 ? gait_phase - 0.5 : gait_phase;
      double swing = g->arm_swing * cos(2.0 * SMGB_M_PI * ph);
      arm_q(side, 1.30, swing, q);
      put_q(pose, side > 0 ? J_LARM : J_RARM, q);
      elbow_q(side, g->elbow + 0.25 * g->elbow * (1.0 + sin(2.0 * SMGB_M_PI * ph)), q);
      put_q(pose, side > 0 ? J_LFOREARM : J_RFOREARM, q);
    }
    return;
  }
  if (kind == SMGB_SYNTH_WAVE) {
    /* Left arm relaxed; right arm raises, waves, lowers every 4 s. */
    double cyc = fmod(t, 4.0), up, wave;
    arm_q(1, 1.25 + 0.03 * sin(t), 0.05, q);
    put_q(pose, J_LARM, q);
    elbow_q(1, 0.2, q);
    put_q(pose, J_LFOREARM, q);
    up = cyc < 0.8 ? ease(cyc / 0.8) : cyc < 3.0 ? 1.0
         : cyc < 3.8 ? 1.0 - ease((cyc - 3.0) / 0.8) : 0.0;
    wave = 0.45 * sin(2.0 * SMGB_M_PI * 2.5 * t) * up;
    {
      double down[4], raised[4], el_down[4], el_up[4];
      arm_q(-1, 1.25, 0.05, down);
      arm_q(-1, -0.45, 0.25, raised);
      smgb_q_slerp(down, raised, up, q);
      put_q(pose, J_RARM, q);
      elbow_q(-1, 0.2, el_down);
      /* Forearm up (toward +Y in the arm frame), waving about the arm. */
      smgb_q_axis(2, -(1.45 + wave), el_up);
      smgb_q_slerp(el_down, el_up, up, q);
      put_q(pose, J_RFOREARM, q);
    }
    return;
  }
  /* Punch: guard, then alternating straight punches every 0.9 s. */
  for (side = 1; side >= -1; side -= 2) {
    double local = fmod(t + (side > 0 ? 0.0 : 0.45), 0.9);
    double ext = local < 0.15 ? ease(local / 0.15)
                 : local < 0.22 ? 1.0
                 : local < 0.55 ? 1.0 - ease((local - 0.22) / 0.33) : 0.0;
    double a[4], b[4];
    arm_q(side, 1.05, 0.75, guard);
    /* Straight forward: +-X bone rotated onto +Z, slightly inward. */
    smgb_q_axis(1, side > 0 ? -1.45 : 1.45, strike);
    smgb_q_slerp(guard, strike, ext, q);
    put_q(pose, side > 0 ? J_LARM : J_RARM, q);
    elbow_q(side, 2.2, a);
    elbow_q(side, 0.08, b);
    smgb_q_slerp(a, b, ext, q);
    put_q(pose, side > 0 ? J_LFOREARM : J_RFOREARM, q);
  }
  {
    /* Shoulders turn into each punch. */
    double l = fmod(t, 0.9), twist = 0.0;
    if (l < 0.45) twist = -0.25 * sin(SMGB_M_PI * l / 0.45);
    else twist = 0.25 * sin(SMGB_M_PI * (l - 0.45) / 0.45);
    q_yxz(twist, 0.08, 0.0, q);
    put_q(pose, J_LOWERBACK, q);
  }
}

static void gait_init(const smgb_synth_params* p, double duration, gait* g) {
  memset(g, 0, sizeof *g);
  g->width = HIP_X;
  g->D = 1.0;
  if (p->kind == SMGB_SYNTH_WALK_STOP) g->ramp = 1;
  if (p->kind == SMGB_SYNTH_WALK_START) g->ramp = 2;
  switch (p->kind) {
    case SMGB_SYNTH_WALK_STOP:
    case SMGB_SYNTH_WALK_START:
    case SMGB_SYNTH_WALK:
      g->v = 1.2; g->L = 0.6; g->D = 0.58; g->lift = 0.07;
      g->h0 = 0.895; g->bob = 0.015; g->bob_sign = 1; g->sway = 0.02;
      g->yaw_osc = 0.07; g->roll = 0.03; g->lean = 0.03;
      g->arm_swing = 0.30; g->elbow = 0.25;
      break;
    case SMGB_SYNTH_RUN:
      g->v = 3.0; g->L = 1.2; g->D = 0.32; g->lift = 0.18;
      g->h0 = 0.885; g->bob = 0.035; g->bob_sign = -1; g->sway = 0.01;
      g->yaw_osc = 0.10; g->roll = 0.02; g->lean = 0.12;
      g->arm_swing = 0.55; g->elbow = 1.35;
      break;
    default:
      g->standing = 1;
      g->width = 0.11;
      g->h0 = 0.93; g->sway = 0.03;
      break;
  }
  if (!g->standing) {
    g->T = 2.0 * g->L / g->v;
    g->kappa = p->turn_rate / g->v;
  }
  if (g->ramp) {
    /* over one stride (two steps), standing still for
     * SMGB_SYNTH_STILL_SECONDS after a stop or before a start */
    g->ramp_seconds = g->T;
    g->ramp_at = g->ramp == 1 ? duration - g->T - SMGB_SYNTH_STILL_SECONDS
                              : SMGB_SYNTH_STILL_SECONDS;
    if (g->ramp_at < 0.0) g->ramp_at = 0.0;
  }
}

int smgb_synth_foot_planted(const smgb_synth_truth* truth, int foot,
                            double t) {
  if (!truth || foot < 0 || foot > 1) return 0;
  if (!(truth->stride_period > 0.0f)) return 1;
  return frac(t / truth->stride_period - truth->phase_offset[foot]) <
         truth->duty_factor;
}

smg_result smgb_synth_generate(const smgb_synth_params* params,
                               smgb_clip* out, smgb_synth_truth* truth) {
  smgb_clip c;
  smg_result r;
  gait g;
  double duration, rate;
  uint32_t frames, f, stride;
  if (!params || !out || (int)params->kind < 0 ||
      params->kind > SMGB_SYNTH_WALK_START ||
      !(params->duration >= 0.0f) ||
      params->duration > 3600.0f || !(params->frame_rate >= 0.0f) ||
      params->frame_rate > 1000.0f || !isfinite(params->turn_rate) ||
      fabsf(params->turn_rate) > 2.0f)
    return SMG_ERROR_INVALID_ARGUMENT;
  duration = params->duration > 0.0f ? params->duration : 8.0;
  rate = params->frame_rate > 0.0f ? params->frame_rate : 60.0;
  gait_init(params, duration, &g);
  frames = (uint32_t)floor(duration * rate + 0.5);
  if (frames < 2) frames = 2;

  memset(&c, 0, sizeof c);
  r = smgb_synth_skeleton(&c.skeleton);
  if (r != SMG_OK) return r;
  stride = SMGB_STRIDE(J_COUNT);
  c.poses = (float*)malloc(sizeof(float) * (size_t)frames * stride);
  if (!c.poses) {
    smgb_skeleton_free(&c.skeleton);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  c.frame_count = frames;
  c.frame_rate = (float)rate;
  snprintf(c.name, sizeof c.name, "synthetic_%s",
           params->kind == SMGB_SYNTH_WALK ? "walk"
           : params->kind == SMGB_SYNTH_WALK_STOP ? "walk_stop"
           : params->kind == SMGB_SYNTH_WALK_START ? "walk_start"
           : params->kind == SMGB_SYNTH_RUN ? "run"
           : params->kind == SMGB_SYNTH_WAVE ? "wave" : "punch");

  for (f = 0; f < frames; ++f) {
    float* pose = c.poses + (size_t)f * stride;
    double t = f / rate, ph, base[2], heading, sway, H, yaw_osc, roll, w0[4];
    double hipbase[2][3], a[2][3], fh[2], fp[2], w0inv[4];
    int side, k;
    for (k = 0; k < (int)stride; ++k) pose[k] = 0.0f;
    for (k = 0; k < J_COUNT; ++k) pose[3 + 4 * k + 3] = 1.0f;

    /* Pelvis plan. */
    if (g.standing) {
      ph = t / 3.2;
      base[0] = 0.0;
      base[1] = 0.0;
      heading = 0.0;
      sway = g.sway * sin(2.0 * SMGB_M_PI * ph);
      H = g.h0 - 0.01 * (1.0 - cos(4.0 * SMGB_M_PI * ph));
      yaw_osc = 0.03 * sin(2.0 * SMGB_M_PI * ph);
      roll = -0.02 * sin(2.0 * SMGB_M_PI * ph);
    } else {
      ph = frac(t / g.T);
      if (g.ramp)
        path_at(&g, dist_at(&g, t), base, &heading);
      else
        path_at(&g, g.v * t, base, &heading);
      /* Weight toward the stance foot (left during the first half of the
       * cycle); zero at whole cycles so the root is exactly on the path
       * there, which tests use as ground truth. */
      sway = g.sway * sin(2.0 * SMGB_M_PI * ph);
      H = g.h0 + g.bob_sign * g.bob * cos(4.0 * SMGB_M_PI * (ph - 0.5 * g.D));
      yaw_osc = -g.yaw_osc * cos(2.0 * SMGB_M_PI * ph);
      roll = -g.roll * cos(2.0 * SMGB_M_PI * (ph - 0.5 * g.D));
      if (g.ramp) {
        /* the gait's sway, bob and turning fade with the speed: standing
         * still, the pelvis is still */
        const double k = speed_share(&g, t);
        sway *= k;
        H = g.h0 + k * (H - g.h0);
        yaw_osc *= k;
        roll *= k;
      }
    }
    base[0] += sway * cos(heading);
    base[1] += sway * -sin(heading);
    q_yxz(heading + yaw_osc, g.lean, roll, w0);

    /* Feet, and the highest pelvis that still reaches both. */
    for (side = 0; side < 2; ++side) {
      double o[3] = {side ? -HIP_X : HIP_X, HIP_Y, 0.0}, dx, dz, dh2, lim;
      const double reach = (THIGH + SHIN) * 0.995;
      smgb_q_rotate(w0, o, o);
      hipbase[side][0] = base[0] + o[0];
      hipbase[side][1] = o[1];
      hipbase[side][2] = base[1] + o[2];
      foot_at(&g, side, t, a[side], &fh[side], &fp[side]);
      dx = a[side][0] - hipbase[side][0];
      dz = a[side][2] - hipbase[side][2];
      dh2 = dx * dx + dz * dz;
      if (dh2 > reach * reach * 0.95) dh2 = reach * reach * 0.95;
      lim = a[side][1] - hipbase[side][1] + sqrt(reach * reach - dh2);
      if (H > lim) H = lim;
    }
    pose[0] = (float)base[0];
    pose[1] = (float)H;
    pose[2] = (float)base[1];
    put_q(pose, J_HIPS, w0);
    smgb_q_conj(w0, w0inv);

    for (side = 0; side < 2; ++side) {
      double hip[3], fwd[3], wt[4], ws[4], wf[4], tmp[4], inv[4], q[4];
      hip[0] = hipbase[side][0];
      hip[1] = hipbase[side][1] + H;
      hip[2] = hipbase[side][2];
      fwd[0] = sin(fh[side]);
      fwd[1] = 0.0;
      fwd[2] = cos(fh[side]);
      leg_ik(hip, a[side], fwd, wt, ws);
      q_yxz(fh[side], fp[side], 0.0, wf);
      /* Local = inverse(parent world) * world; the HipJoint is identity. */
      smgb_q_mul(w0inv, wt, q);
      put_q(pose, side ? J_RUPLEG : J_LUPLEG, q);
      smgb_q_conj(wt, inv);
      smgb_q_mul(inv, ws, q);
      put_q(pose, side ? J_RLEG : J_LLEG, q);
      smgb_q_conj(ws, inv);
      smgb_q_mul(inv, wf, tmp);
      put_q(pose, side ? J_RFOOT : J_LFOOT, tmp);
    }
    if (g.ramp) {
      gait arms = g; /* the arms swing less as the walk slows */
      arms.arm_swing *= speed_share(&g, t);
      upper_body(&arms, SMGB_SYNTH_WALK, t, ph, yaw_osc, pose);
    } else {
      upper_body(&g, params->kind, t, ph, yaw_osc, pose);
    }
  }
  /* Hemisphere continuity, as the BVH importer guarantees. */
  for (f = 1; f < frames; ++f) {
    float* q = c.poses + (size_t)f * stride + 3;
    const float* p = q - stride;
    int j;
    for (j = 0; j < J_COUNT; ++j, q += 4, p += 4)
      if (q[0] * p[0] + q[1] * p[1] + q[2] * p[2] + q[3] * p[3] < 0.0f) {
        q[0] = -q[0]; q[1] = -q[1]; q[2] = -q[2]; q[3] = -q[3];
      }
  }
  if (truth) {
    memset(truth, 0, sizeof *truth);
    truth->kind = params->kind;
    truth->speed = (float)g.v;
    truth->ramp_at = (float)g.ramp_at;
    truth->ramp_seconds = (float)g.ramp_seconds;
    truth->step_length = (float)g.L;
    truth->stride_period = (float)g.T;
    truth->duty_factor = (float)g.D;
    truth->phase_offset[0] = 0.0f;
    truth->phase_offset[1] = g.standing ? 0.0f : 0.5f;
    truth->turn_rate = g.standing ? 0.0f : params->turn_rate;
    truth->foot_width = (float)g.width;
    truth->ankle_height = (float)ANKLE_H;
    truth->start_heading = 0.0f;
    truth->left_foot = J_LFOOT;
    truth->right_foot = J_RFOOT;
  }
  *out = c;
  return SMG_OK;
}

/* ---- the standard set ------------------------------------------------------ */

typedef struct std_clip {
  const char* file;
  const char* label;
  smgb_synth_kind kind;
  float turn_rate;
  float duration;
} std_clip;

/* Turn rates: the walk turns on a 3.4 m radius (1.2 m/s, 0.35 rad/s), the
 * run on 3.75 m (3 m/s, 0.8 rad/s; lateral acceleration 2.4 m/s^2), so both
 * styles can follow the 4 m bends of the evaluation and tests. With 0.5 rad/s
 * (6 m) the run could not, and the runtime had to give such bends to the
 * walk. */
static const std_clip k_standard[SMGB_SYNTH_STANDARD_COUNT] = {
    {"synthetic_walk_straight.bvh", "walk", SMGB_SYNTH_WALK, 0.0f, 8.0f},
    {"synthetic_walk_left.bvh", "walk", SMGB_SYNTH_WALK, 0.35f, 8.0f},
    {"synthetic_walk_right.bvh", "walk", SMGB_SYNTH_WALK, -0.35f, 8.0f},
    {"synthetic_run_straight.bvh", "run", SMGB_SYNTH_RUN, 0.0f, 6.0f},
    {"synthetic_run_left.bvh", "run", SMGB_SYNTH_RUN, 0.8f, 6.0f},
    {"synthetic_run_right.bvh", "run", SMGB_SYNTH_RUN, -0.8f, 6.0f},
    {"synthetic_wave.bvh", "wave", SMGB_SYNTH_WAVE, 0.0f, 8.0f},
    {"synthetic_punch.bvh", "punch", SMGB_SYNTH_PUNCH, 0.0f, 8.0f}};

smg_result smgb_synth_standard(uint32_t index, smgb_synth_params* params,
                               const char** file, const char** label,
                               int* is_lower) {
  const std_clip* s;
  if (index >= SMGB_SYNTH_STANDARD_COUNT) return SMG_ERROR_OUT_OF_RANGE;
  s = &k_standard[index];
  if (params) {
    memset(params, 0, sizeof *params);
    params->kind = s->kind;
    params->turn_rate = s->turn_rate;
    params->duration = s->duration;
    params->frame_rate = 60.0f;
  }
  if (file) *file = s->file;
  if (label) *label = s->label;
  if (is_lower)
    *is_lower = s->kind == SMGB_SYNTH_WALK || s->kind == SMGB_SYNTH_RUN;
  return SMG_OK;
}

smg_result smgb_synth_write_all(const char* dir, smgb_error* err) {
  char path[4096];
  uint32_t i;
  FILE* fp;
  if (err) err->message[0] = '\0';
  if (!dir || !*dir) {
    smgb_imp_errorf(err, "smgb_synth_write_all: no output folder");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  for (i = 0; i < SMGB_SYNTH_STANDARD_COUNT; ++i) {
    smgb_synth_params p;
    const char* file;
    smgb_clip c;
    smg_result r;
    smgb_synth_standard(i, &p, &file, NULL, NULL);
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, file) >= sizeof path) {
      smgb_imp_errorf(err, "%s: output path too long", dir);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    r = smgb_synth_generate(&p, &c, NULL);
    if (r != SMG_OK) {
      smgb_imp_errorf(err, "%s: generation failed", file);
      return r;
    }
    r = smgb_bvh_save(path, &c, err);
    smgb_clip_free(&c);
    if (r != SMG_OK) return r;
  }
  snprintf(path, sizeof path, "%s/README.txt", dir);
  fp = fopen(path, "w");
  if (!fp) {
    smgb_imp_errorf(err, "%s: cannot create", path);
    return SMG_ERROR_IO;
  }
  fprintf(fp,
          "SYNTHETIC motion clips generated by smg-gen-clips (libsmg).\n"
          "They are procedural, NOT motion capture: a walk and a run on\n"
          "straight, left-turning and right-turning paths, and two standing\n"
          "upper-body actions (wave, punch), on the CMU 31-joint hierarchy.\n"
          "Units are metres (unit 1), 60 frames/s, no T-pose frame.\n"
          "Feet are planted exactly (analytic two-bone IK), so tests know the\n"
          "ground truth: walk 1.2 m/s with 0.6 m steps, run 3.0 m/s with\n"
          "1.2 m steps, turns of +-0.35 (walk) and +-0.8 (run) rad/s.\n"
          "Regenerate with: smg-gen-clips DIR. See libsmg/bake/bake_synthetic.h.\n");
  if (fclose(fp) != 0) {
    smgb_imp_errorf(err, "%s: write error", path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
