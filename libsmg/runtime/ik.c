/*
 * ik.c - foot cleanup. When a foot's contact label (FRMI) begins, the
 * toe's world position is recorded, and again each step while the animated
 * toe still descends (it lands after the heel) and is above the floor the
 * foot was last held on; while the contact lasts,
 * cyclic coordinate descent on hip and knee moves the ankle to where the
 * animation has it relative to the toe, placed at that anchor horizontally
 * and at the animation's height - so a flat foot stays put and a rolling
 * foot pivots about its planted toe instead of dragging, and the feet stay
 * on the floor the data has. The ankle keeps its animated world
 * orientation, which puts the toe on the anchor. The correction blends in
 * over SMGI_IK_BLEND seconds and, once released, out as the toe rises off
 * the floor (or, for a foot that shuffles on, over a short distance of the
 * toe's own travel), eased at both ends, so contact changes never pop. A
 * contact whose anchor drifted implausibly far (a re-plan moved the body)
 * is released rather than stretched, and planted anew only once that
 * correction is gone; one the leg cannot reach slides towards the hip
 * instead of lifting the foot (keep_in_reach). Each solve starts from the foot's previous correction
 * (see solve_leg), and IK refreshes the world transform cache of the joints
 * it moved itself.
 *
 * Swing clearance: a foot that swings fast with its toe within twice the
 * clearance of the floor it last stood on is raised (the same leg solve,
 * the foot rigid) so the toe passes at least the clearance above it.
 * Performers' toes pass 1-2 cm above the floor at 3-4 m/s in mid-swing; on
 * a character that reads as a foot sliding along the ground, and a shoe
 * mesh thicker than the performer's foot cuts into the floor. The lift is
 * a smooth function of the toe's height (none from twice the clearance up)
 * and fades in and out with the toe's speed over the ground, so it is
 * gone before the foot stands, lands or pushes off: those keep the data's
 * heights and the contact logic above.
 *
 * Uneven ground (smg_character_set_ground): the engine measures ground
 * heights at three probes before the step (each toe where it is expected,
 * the root). The body is carried at the root's ground height (smoothed);
 * each toe is placed on the ground under it, which follows the
 * measurement at a bounded rate while the toe swings (a stair edge passing
 * under it raises it over a few frames); where a leg would have to
 * stretch further than the animation does, or than SMGI_GROUND_REACH of
 * its length, to put its foot on a lower ground, the pelvis is lowered by
 * the difference. Every leg is then solved to its foot's height, planted
 * ones also to their anchors. Without ground nothing of this runs.
 */
#include <math.h>
#include <string.h>

#include "ik.h"

#include "pose.h"
#include "pose_simd.h"
#include "rmath.h"
#include "tuning.h"
#include "simd.h"

/* -DIK_SSE=0 builds the plain C path; the SSE one uses pose_simd.h's
 * quaternion kernels (bit for bit the plain math) */
#ifndef IK_SSE
#define IK_SSE SMGI_POSE_SSE
#endif
#if IK_SSE && !SMGI_POSE_SSE
#error "IK_SSE needs the SSE kernels of pose_simd.h (SMGI_POSE_SSE)"
#endif

static const float k_identity[4] = {0.0f, 0.0f, 0.0f, 1.0f};

static float dot3(const float* a, const float* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* ---- the solve's vectors and quaternions --------------------------------
 * Values, kept in SSE registers where IK_SSE (lanes 0..2 of a vec3; lane 3
 * is unused): the solve's bones, target and corrections live in registers
 * instead of being stored and reloaded around every product. Each
 * operation is the plain code's, lane by lane and in its order (dot
 * products sum x, y, z left to right), so both builds give the same bits. */
#if IK_SSE
typedef __m128 vec3;
typedef __m128 quat;

static inline vec3 v3_load(const float* p) { return smgi_load3_sse(p); }
static inline void v3_store(float* p, vec3 v) { smgi_store3_sse(p, v); }
static inline vec3 v3_add(vec3 a, vec3 b) { return _mm_add_ps(a, b); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return _mm_sub_ps(a, b); }
static inline vec3 v3_scale(vec3 a, float k) {
  return _mm_mul_ps(a, _mm_set1_ps(k));
}
static inline float v3_dot(vec3 a, vec3 b) {
  const __m128 m = _mm_mul_ps(a, b);
  const __m128 t = _mm_add_ss(m, SMGI_SHUF(m, 1, 1, 1, 1));
  return _mm_cvtss_f32(_mm_add_ss(t, SMGI_SHUF(m, 2, 2, 2, 2)));
}
/* (a1 b2 - a2 b1, a2 b0 - a0 b2, a0 b1 - a1 b0) */
static inline vec3 v3_cross(vec3 a, vec3 b) {
  return _mm_sub_ps(_mm_mul_ps(SMGI_SHUF(a, 1, 2, 0, 3), SMGI_SHUF(b, 2, 0, 1, 3)),
                    _mm_mul_ps(SMGI_SHUF(a, 2, 0, 1, 3), SMGI_SHUF(b, 1, 2, 0, 3)));
}
static inline quat q_load(const float* p) { return _mm_loadu_ps(p); }
static inline void q_store(float* p, quat q) { _mm_storeu_ps(p, q); }
static inline quat q_mul(quat a, quat b) { return smgi_q_mul_sse(a, b); }
static inline vec3 q_rotate(quat q, vec3 v) { return smgi_q_rotate_sse(q, v); }
/* (v * s, w * s) */
static inline quat q_scaled(vec3 v, float w, float s) {
  const __m128 vw = _mm_shuffle_ps(v, _mm_unpackhi_ps(v, _mm_set1_ps(w)),
                                   _MM_SHUFFLE(1, 0, 1, 0));
  return _mm_mul_ps(vw, _mm_set1_ps(s));
}
#else
typedef struct vec3 {
  float v[3];
} vec3;
typedef struct quat {
  float q[4];
} quat;

static inline vec3 v3_load(const float* p) {
  vec3 r = {{p[0], p[1], p[2]}};
  return r;
}
static inline void v3_store(float* p, vec3 v) { memcpy(p, v.v, sizeof v.v); }
static inline vec3 v3_add(vec3 a, vec3 b) {
  vec3 r = {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2]}};
  return r;
}
static inline vec3 v3_sub(vec3 a, vec3 b) {
  vec3 r = {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2]}};
  return r;
}
static inline vec3 v3_scale(vec3 a, float k) {
  vec3 r = {{a.v[0] * k, a.v[1] * k, a.v[2] * k}};
  return r;
}
static inline float v3_dot(vec3 a, vec3 b) { return dot3(a.v, b.v); }
static inline vec3 v3_cross(vec3 a, vec3 b) {
  vec3 r = {{a.v[1] * b.v[2] - a.v[2] * b.v[1],
             a.v[2] * b.v[0] - a.v[0] * b.v[2],
             a.v[0] * b.v[1] - a.v[1] * b.v[0]}};
  return r;
}
static inline quat q_load(const float* p) {
  quat r;
  memcpy(r.q, p, sizeof r.q);
  return r;
}
static inline void q_store(float* p, quat q) { memcpy(p, q.q, sizeof q.q); }
static inline quat q_mul(quat a, quat b) {
  quat r;
  smgi_q_mul(a.q, b.q, r.q);
  return r;
}
static inline vec3 q_rotate(quat q, vec3 v) {
  vec3 r;
  smgi_q_rotate(q.q, v.v, r.v);
  return r;
}
static inline quat q_scaled(vec3 v, float w, float s) {
  quat r = {{v.v[0] * s, v.v[1] * s, v.v[2] * s, w * s}};
  return r;
}
#endif

/* Shortest rotation taking direction a to direction b (smgi_q_from_to),
 * given their squared lengths, also giving |a||b|, which the caller needs
 * to place the turned bone. Returns 0 (and leaves dq alone) when the two
 * are opposite or degenerate: there is no shortest arc then, and the sweep
 * skips that joint. */
static inline int turn(vec3 a, float a2, vec3 b, float b2, quat* dq,
                       float* lab) {
  float l = sqrtf(a2 * b2);
  float w = l + v3_dot(a, b);
  if (!(w > 1e-6f * (l + 1e-12f))) return 0;
  /* |(a x b, w)|^2 = 2 l w, so one sqrt normalizes */
  float s = 1.0f / sqrtf(2.0f * l * w);
  *dq = q_scaled(v3_cross(a, b), w, s);
  *lab = l;
  return 1;
}

/* o = conj(a) * b */
static inline void qmul_conj(const float* a, const float* b, float* o) {
#if IK_SSE
  const __m128 conj = _mm_setr_ps(-0.0f, -0.0f, -0.0f, 0.0f);
  _mm_storeu_ps(o, smgi_q_mul_sse(_mm_xor_ps(_mm_loadu_ps(a), conj),
                                  _mm_loadu_ps(b)));
#else
  float inv[4];
  smgi_q_conj(a, inv);
  smgi_q_mul(inv, b, o);
#endif
}

/* smgi_q_normalize, the same bits */
static inline quat qnorm(quat q) {
#if IK_SSE
  return smgi_q_normalize_sse(q);
#else
  smgi_q_normalize(q.q);
  return q;
#endif
}

/* Local rotation `local` blended over the animation's in `rot` by w. At
 * full weight nlerp would only renormalize (the inputs are unit products);
 * keep its choice of sign, the animation's hemisphere. */
static inline void blend_local(float* rot, const float* local, float w) {
  if (w >= 1.0f) {
#if IK_SSE
    /* the sign flip as a sign-bit flip: -1 * x is -x */
    const __m128 l = _mm_loadu_ps(local);
    const float d = smgi_hsum4_sse(_mm_mul_ps(_mm_loadu_ps(rot), l));
    _mm_storeu_ps(rot, d < 0.0f ? _mm_xor_ps(l, _mm_set1_ps(-0.0f)) : l);
#else
    float s = dot3(rot, local) + rot[3] * local[3] < 0.0f ? -1.0f : 1.0f;
    rot[0] = s * local[0];
    rot[1] = s * local[1];
    rot[2] = s * local[2];
    rot[3] = s * local[3];
#endif
  } else {
#if IK_SSE
    _mm_storeu_ps(rot, smgi_q_nlerp_sse(_mm_loadu_ps(rot),
                                        _mm_loadu_ps(local), w));
#else
    float out[4];
    smgi_q_nlerp(rot, local, w, out);
    memcpy(rot, out, sizeof out);
#endif
  }
}

/* Turn the whole leg (bones a, b from the hip) about the hip so that
 * hip->ankle lies along t (|t|^2 = d2), adding the turn to the world
 * corrections Th and Tk. */
static inline void hip_turn(vec3* a, vec3* b, vec3 t, float d2, quat* Th,
                            quat* Tk) {
  const vec3 sum = v3_add(*a, *b);
  const float s2 = v3_dot(sum, sum);
  quat dq;
  float lab;
  if (turn(sum, s2, t, d2, &dq, &lab)) {
    float k = s2 / lab; /* |sum| / |t| */
    *a = q_rotate(dq, *a);
    *b = v3_sub(v3_scale(t, k), *a);
    *Th = q_mul(dq, *Th);
    *Tk = q_mul(dq, *Tk);
  }
}

/* CCD on knee then hip, moving the ankle to `target`. The chain is kept as
 * two bone vectors a (hip->knee) and b (knee->ankle) relative to the hip,
 * and the rotations CCD applies are accumulated as world-space corrections
 * Th (hip) and Tk (knee) of the animated pose. Each solve starts from the
 * foot's previous corrections: while a foot is planted the target hardly
 * moves between steps, so CCD starts next to the answer and its sweeps add
 * up across steps instead of restarting from the raw animation. */
static void solve_leg(smgi_ik* ik, smgi_pose* pose, const smg_graph* g,
                      uint32_t f, const float* target,
                      float w, float (*fix)[4]) {
  const smgi_joint* joints = g->data.joints;
  const uint32_t* list = ik->leg_joints + (size_t)f * g->data.joint_count;
  const uint32_t hip = list[0], knee = list[1], ankle = list[2];
  smgi_foot* foot = &ik->feet[f];
  const uint32_t hp = (uint32_t)joints[hip].parent;
  const vec3 p0 = v3_load(pose->wpos + 3u * hip);
  const vec3 p1 = v3_load(pose->wpos + 3u * knee);
  const vec3 p2 = v3_load(pose->wpos + 3u * ankle);
  const vec3 a0 = v3_sub(p1, p0), b0 = v3_sub(p2, p1);
  const vec3 t = v3_sub(v3_load(target), p0);
  quat Th = q_load(fix[0]), Tk = q_load(fix[1]);
  vec3 a = q_rotate(Th, a0), b = q_rotate(Tk, b0);
  /* Stop within SMGI_IK_TOLERANCE of the closest the ankle can get: 0 for a
   * reachable target, else how far it lies outside the leg's annulus.
   * A released foot blending out moves the pose's ankle by only about w
   * times what it moves the solved one, and its solve is on its way to
   * being dropped: both stop rules are on the pose's scale then. A foot
   * blending in keeps full precision: its correction is about to be
   * shown whole, and the next solves start from it. */
  const float l1 = sqrtf(v3_dot(a0, a0)), l2sq = v3_dot(b0, b0);
  const float d2 = v3_dot(t, t);
  const float l2 = sqrtf(l2sq), d = sqrtf(d2);
  float reach = d - (l1 + l2);
  float inner = fabsf(l1 - l2) - d;
  if (inner > reach) reach = inner;
  if (reach < 0.0f) reach = 0.0f;
  const float tol = foot->planted ? SMGI_IK_TOLERANCE : SMGI_IK_TOLERANCE / w;
  const float stop2 = (reach + tol) * (reach + tol);
  /* The knee first, in closed form: bend it (in the leg's own plane) so
   * that hip->ankle is as long as hip->target, or as near as the leg
   * allows. CCD alone cannot shorten a nearly straight leg: the shin
   * already points along knee->target, its sweep turns it by almost
   * nothing, and the hip sweep then lays the too-long leg along the
   * target's direction, past it - below it for a leg reaching down, the
   * toe pushed into the floor (by 1.3 cm on the synthetic walk when root
   * steering moved the body towards a planted foot). */
  {
    const float l1sq = v3_dot(a, a);
    /* never quite straight (0.1 % short, within the tolerance): a
     * straight leg has no plane left to bend the knee in next time */
    const float longest = 0.999f * (l1 + l2);
    float want = d < longest ? d : longest;
    if (want < fabsf(l1 - l2)) want = fabsf(l1 - l2);
    const vec3 s = v3_add(a, b);
    const float have = sqrtf(v3_dot(s, s));
    /* b's part across a: the leg's plane and which way the knee bends */
    const float k = v3_dot(a, b) / l1sq;
    const vec3 p = v3_sub(b, v3_scale(a, k));
    const float p2 = v3_dot(p, p);
    if (fabsf(have - want) > tol && p2 > 1e-12f * l2sq) {
      /* cos of the angle between the bones for |a + b| = want */
      float c = (want * want - l1sq - l2sq) / (2.0f * l1 * l2);
      c = smgi_clampf(c, -1.0f, 1.0f);
      const float sn = sqrtf(1.0f - c * c);
      const float ia = l2 / l1, ip = l2 / sqrtf(p2);
      const vec3 nb = v3_add(v3_scale(a, c * ia), v3_scale(p, sn * ip));
      quat dq;
      float lab;
      if (turn(b, l2sq, nb, l2sq, &dq, &lab)) {
        b = nb;
        Tk = q_mul(dq, Tk);
        hip_turn(&a, &b, t, d2, &Th, &Tk); /* and aim it: done, unless the
                                              target is out of reach */
      }
    }
  }
  float prev2 = INFINITY;
  for (uint32_t it = 0; it < SMGI_IK_ITERATIONS; ++it) {
    const vec3 e = v3_sub(v3_sub(t, a), b);
    float e2 = v3_dot(e, e);
    if (e2 <= stop2) break;
    /* a sweep gained < 0.5 tol (a singular or slowly converging pose) */
    if (prev2 - e2 < tol * sqrtf(e2) + 1e-6f) break;
    prev2 = e2;
    quat dq;
    float lab;
    /* knee: turn the shin toward the target; it then lies along v */
    const vec3 v = v3_sub(t, a);
    if (turn(b, l2sq, v, v3_dot(v, v), &dq, &lab)) {
      float k = l2sq / lab; /* |b| / |v| */
      b = v3_scale(v, k);
      Tk = q_mul(dq, Tk);
    }
    hip_turn(&a, &b, t, d2, &Th, &Tk);
  }
  Th = qnorm(Th);
  Tk = qnorm(Tk);
  q_store(fix[0], Th);
  q_store(fix[1], Tk);
  /* back to local rotations, blended with the animation by w; the ankle
   * keeps its animated world orientation */
  float r0[4], r1[4], local[4];
  float* wrot = pose->wrot;
  q_store(r0, q_mul(Th, q_load(wrot + 4u * hip)));
  q_store(r1, q_mul(Tk, q_load(wrot + 4u * knee)));
  qmul_conj(wrot + 4u * hp, r0, local);
  blend_local(pose->rot + 4u * hip, local, w);
  qmul_conj(r0, r1, local);
  blend_local(pose->rot + 4u * knee, local, w);
  qmul_conj(r1, wrot + 4u * ankle, local);
  blend_local(pose->rot + 4u * ankle, local, w);

  /* keep the world transform cache true for every joint IK moved */
  const uint32_t side = ik->leg_side[f], below = ik->leg_below[f];
  if (w < 1.0f) { /* blended: the solve's transforms are not the pose's */
    smgi_fk_joints(pose, g, list, 3u + side + below);
    return;
  }
  /* At full weight the solve already has the pose's hip and knee (what FK
   * of the new local rotations gives, to rounding) and the ankle keeps its
   * world rotation, so joints below it only move with it. */
  float* wpos = pose->wpos;
  memcpy(wrot + 4u * hip, r0, sizeof r0);
  memcpy(wrot + 4u * knee, r1, sizeof r1);
  const vec3 kp = v3_add(p0, a), ap = v3_add(kp, b);
  float moved[3];
  v3_store(moved, v3_sub(ap, p2));
  v3_store(wpos + 3u * knee, kp);
  v3_store(wpos + 3u * ankle, ap);
  smgi_fk_joints(pose, g, list + 3, side);
  for (uint32_t i = 3u + side; i < 3u + side + below; ++i) {
    float* p = wpos + 3u * list[i];
    p[0] += moved[0];
    p[1] += moved[1];
    p[2] += moved[2];
  }
}

void smgi_ik_init_legs(smgi_ik* ik, const smg_graph* g, uint8_t* mark) {
  const uint32_t J = g->data.joint_count;
  const smgi_joint* joints = g->data.joints;
  const smgi_info* info = g->data.info;
  const uint32_t* legs[2] = {info->left_leg, info->right_leg};
  enum { OUT = 0, SIDE = 1, BELOW = 2 };
  for (uint32_t f = 0; f < 2u; ++f) {
    const uint32_t hip = legs[f][0], knee = legs[f][1], ankle = legs[f][2];
    ik->leg_ok[f] = hip > 0 && hip < J && knee < J && ankle < J &&
                    (uint32_t)joints[knee].parent == hip &&
                    (uint32_t)joints[ankle].parent == knee;
    ik->leg_side[f] = ik->leg_below[f] = 0;
    if (!ik->leg_ok[f]) continue;
    uint32_t* list = ik->leg_joints + (size_t)f * J;
    list[0] = hip;
    list[1] = knee;
    list[2] = ankle;
    memset(mark, OUT, J);
    mark[hip] = mark[knee] = SIDE;
    mark[ankle] = BELOW;
    uint32_t n = 3;
    /* parents come first, so one ascending pass sees every parent's mark */
    for (uint32_t j = hip + 1u; j < J; ++j) {
      if (j == knee || j == ankle) continue;
      mark[j] = mark[(uint32_t)joints[j].parent];
      if (mark[j] == SIDE) list[n++] = j;
    }
    ik->leg_side[f] = n - 3u;
    for (uint32_t j = ankle + 1u; j < J; ++j)
      if (mark[j] == BELOW) list[n++] = j;
    ik->leg_below[f] = n - 3u - ik->leg_side[f];
  }
}

void smgi_ik_reset(smgi_ik* ik) {
  for (uint32_t f = 0; f < 2u; ++f) {
    ik->feet[f].planted = 0;
    ik->feet[f].weight = 0.0f;
    ik->feet[f].landing = 0;
    ik->feet[f].let_go = 0;
    ik->feet[f].guided = 0;
    ik->feet[f].toe[0] = ik->feet[f].toe[2] = 0.0f;
    ik->feet[f].toe[1] = INFINITY;
    ik->feet[f].floor_y = -INFINITY;
    ik->feet[f].stand_y = INFINITY;
    ik->feet[f].lift = 0.0f;
    ik->feet[f].shown[0] = ik->feet[f].shown[1] = INFINITY;
    memcpy(ik->feet[f].fix[0], k_identity, sizeof k_identity);
    memcpy(ik->feet[f].fix[1], k_identity, sizeof k_identity);
  }
}

/* How far to raise a foot that is not planted, whose animated toe is at
 * height toe_y and moves at `speed` m/s over the ground (see the top of
 * this file). h is the toe's height above the lowest it has stood. At
 * h <= 0 the toe is raised to the clearance c; from
 * there to 2c the lift eases to 0 (toe height h + c (2 - h/c)^2/4: rising
 * with h, equal to h with zero slope at 2c), so the swing's shape is kept
 * and nothing bends where the lift starts. Until a foot has stood
 * somewhere its floor is unknown: no lift. */
static float swing_lift(const smgi_foot* foot, float toe_y, float speed,
                        float c, float leg) {
  if (foot->planted || !(c > 0.0f) || !(foot->stand_y < INFINITY)) return 0.0f;
  const float h = toe_y - foot->stand_y;
  if (h >= 2.0f * c) return 0.0f;
  const float x = 2.0f - h / c;
  const float lift = h <= 0.0f ? c - h : 0.25f * c * x * x;
  float s = (speed / leg - SMGI_IK_SWING_SLOW) /
            (SMGI_IK_SWING_FAST - SMGI_IK_SWING_SLOW);
  s = smgi_clampf(s, 0.0f, 1.0f);
  return s * s * (3.0f - 2.0f * s) * lift;
}

void smgi_ik_guide(smgi_ik* ik, uint32_t f, float x, float z, float raise) {
  smgi_foot* foot = &ik->feet[f & 1u];
  foot->guided = 1;
  foot->guide[0] = x;
  foot->guide[1] = z;
  foot->guide[2] = raise;
}

void smgi_ground_reset(smgi_ground* g) {
  memset(g, 0, sizeof *g);
  g->root_y = NAN;
  for (uint32_t f = 0; f < 2u; ++f) {
    g->foot_y[f] = NAN;
    g->prev_toe[f][0] = g->prev_toe[f][1] = INFINITY;
  }
}

static float approach(float v, float want, float most) {
  if (want > v + most) return v + most;
  if (want < v - most) return v - most;
  return want;
}

/* The toe joint of leg f (the ankle when the skeleton has none). */
static uint32_t toe_of(const smg_graph* g, uint32_t f) {
  const smgi_info* info = g->data.info;
  const uint32_t* leg = f ? info->right_leg : info->left_leg;
  return leg[3] < g->data.joint_count ? leg[3] : leg[2];
}

/* Carry the body onto the ground (see the top of this file): the whole
 * pose is raised by the root's ground height less the pelvis drop, and
 * off[f] is how far foot f must go beyond that to stand on its ground. */
static void ground_lift(smgi_ik* ik, smgi_pose* pose, const smg_graph* graph,
                        float dt, float* off) {
  smgi_ground* g = &ik->ground;
  const smgi_info* info = graph->data.info;
  const float L = info->leg_length;
  const uint32_t* legs[2] = {info->left_leg, info->right_leg};
  float* wpos = pose->wpos;
  const float k = dt < SMGI_GROUND_ROOT_SECONDS ? dt / SMGI_GROUND_ROOT_SECONDS : 1.0f;
  g->root_y = isnan(g->root_y) ? g->root : g->root_y + (g->root - g->root_y) * k;
  float need = 0.0f, rel[2] = {0.0f, 0.0f};
  for (uint32_t f = 0; f < 2u; ++f) {
    if (!ik->leg_ok[f]) continue;
    const float* tp = wpos + 3u * toe_of(graph, f);
    if (isnan(g->foot_y[f]) || !(dt > 0.0f)) {
      if (isnan(g->foot_y[f])) g->foot_y[f] = g->foot[f];
    } else {
      float speed = 0.0f;
      if (g->prev_toe[f][0] < INFINITY) {
        const float sx = tp[0] - g->prev_toe[f][0], sz = tp[2] - g->prev_toe[f][1];
        speed = sqrtf(sx * sx + sz * sz) / dt;
      }
      const float rate = speed > SMGI_GROUND_FOOT_RATE * L ? speed : SMGI_GROUND_FOOT_RATE * L;
      g->foot_y[f] = approach(g->foot_y[f], g->foot[f], rate * dt);
    }
    rel[f] = g->foot_y[f] - g->root_y;
    /* how far the pelvis must come down for this leg to reach its ankle
     * moved by rel[f]: no further than the animation stretches it, or
     * SMGI_GROUND_REACH of its length */
    const float* hp = wpos + 3u * legs[f][0];
    const float* kn = wpos + 3u * legs[f][1];
    const float* an = wpos + 3u * legs[f][2];
    const float l1[3] = {kn[0] - hp[0], kn[1] - hp[1], kn[2] - hp[2]};
    const float l2[3] = {an[0] - kn[0], an[1] - kn[1], an[2] - kn[2]};
    const float v[3] = {hp[0] - an[0], hp[1] - an[1], hp[2] - an[2]};
    float reach = SMGI_GROUND_REACH * (sqrtf(dot3(l1, l1)) + sqrtf(dot3(l2, l2)));
    const float anim = sqrtf(dot3(v, v));
    if (anim > reach) reach = anim;
    const float hd2 = v[0] * v[0] + v[2] * v[2];
    const float vd = v[1] - rel[f];
    const float p = hd2 < reach * reach ? vd - sqrtf(reach * reach - hd2) : vd;
    if (p > need) need = p;
  }
  if (need > L) need = L;
  g->drop = dt > 0.0f ? smgi_clampf(need, g->drop - SMGI_GROUND_DROP_RISE * L * dt,
                                    g->drop + SMGI_GROUND_DROP_FALL * L * dt)
                      : g->drop;
  if (g->drop < 0.0f) g->drop = 0.0f;
  const float lift = g->root_y - g->drop;
  pose->root[1] += lift;
  for (uint32_t j = 0; j < graph->data.joint_count; ++j) wpos[3u * j + 1u] += lift;
  pose->ground_y = g->root_y;
  off[0] = rel[0] + g->drop;
  off[1] = rel[1] + g->drop;
}

void smgi_ground_probes(const smgi_ik* ik, const smgi_pose* pose,
                        const smg_graph* graph, float* xz) {
  const smgi_ground* g = &ik->ground;
  for (uint32_t f = 0; f < 2u; ++f) {
    const smgi_foot* foot = &ik->feet[f];
    const float* tp = pose->wpos + 3u * toe_of(graph, f);
    if (ik->enabled && foot->planted && !foot->landing) {
      xz[2u * f] = foot->anchor[0];
      xz[2u * f + 1u] = foot->anchor[2];
    } else if (g->prev_toe[f][0] < INFINITY) {
      /* carried on by its last step */
      xz[2u * f] = tp[0] + (tp[0] - g->prev_toe[f][0]);
      xz[2u * f + 1u] = tp[2] + (tp[2] - g->prev_toe[f][1]);
    } else {
      xz[2u * f] = tp[0];
      xz[2u * f + 1u] = tp[2];
    }
  }
}

/* Keep a held toe where its leg can reach it. The ankle target is the
 * anchor plus the animated ankle-from-toe offset, at height y; the leg
 * reaches as far as the animation stretches it, or SMGI_GROUND_REACH of
 * its length. Held further out, the leg stretched along hip->target, its
 * ankle stopped short and above the target, and the toe rose on the spot:
 * up to 11 cm on the sparse graph's scribble, where the body turns away
 * from a foot that landed while the animation's toe still slid on by
 * 26 cm, hovering until the contact ended (that swing measured 1.6 times
 * the median). Now the toe, with what the animation lifts it, rises at
 * most to SMGI_IK_CLEAR above where it was held (where a toe still counts
 * as on the floor: the end of a push-off, as before), and beyond that the
 * anchor slides over the floor towards the hip, at most
 * SMGI_IK_SWING_SLOW leg lengths per second (faster reads as a swing, not
 * a stance). */
static void keep_in_reach(const smgi_ik* ik, smgi_foot* foot,
                          const smgi_pose* pose, const smg_graph* g,
                          uint32_t f, const float* ap, float y, float dt) {
  const uint32_t* list = ik->leg_joints + (size_t)f * g->data.joint_count;
  const float* hp = pose->wpos + 3u * list[0];
  const float* kn = pose->wpos + 3u * list[1];
  const float* an = pose->wpos + 3u * list[2];
  const float l1[3] = {kn[0] - hp[0], kn[1] - hp[1], kn[2] - hp[2]};
  const float l2[3] = {an[0] - kn[0], an[1] - kn[1], an[2] - kn[2]};
  const float v[3] = {an[0] - hp[0], an[1] - hp[1], an[2] - hp[2]};
  float reach = SMGI_GROUND_REACH * (sqrtf(dot3(l1, l1)) + sqrtf(dot3(l2, l2)));
  const float anim = sqrtf(dot3(v, v));
  if (anim > reach) reach = anim;
  const float dy = y - hp[1];
  /* a target level with the hip or above it, or below its reach, is no
   * stance */
  if (!(dy < 0.0f) || dy * dy >= reach * reach) return;
  /* the target's horizontal offset from the hip */
  const float tx = foot->anchor[0] + an[0] - ap[0] - hp[0];
  const float tz = foot->anchor[2] + an[2] - ap[2] - hp[2];
  const float h = sqrtf(tx * tx + tz * tz);
  /* out of reach, the ankle falls short along hip->target by d - reach
   * and rises by that times |dy| / d; the rise allowed is what is left of
   * SMGI_IK_CLEAR above the held height once the animation's own lift of
   * the toe is counted */
  const float d = sqrtf(h * h + dy * dy);
  float up = ap[1] - foot->anchor[1];
  if (!(up > 0.0f)) up = 0.0f;
  float rise = SMGI_IK_CLEAR * g->data.info->leg_length - up;
  if (!(rise > 0.0f)) rise = 0.0f;
  const float allow = rise * d / -dy;
  const float far = reach + allow;
  if (!(d > far)) return;
  float slide = h - sqrtf(far * far - dy * dy);
  const float fastest = SMGI_IK_SWING_SLOW * g->data.info->leg_length * dt;
  if (slide > fastest) slide = fastest;
  const float k = slide / h;
  foot->anchor[0] -= k * tx;
  foot->anchor[2] -= k * tz;
}

void smgi_ik_apply(smgi_ik* ik, smgi_pose* pose, const smg_graph* g,
                   float dt) {
  float off[2] = {0.0f, 0.0f};
  smgi_ground* ground = &ik->ground;
  if (ground->on)
    ground_lift(ik, pose, g, dt, off);
  else
    pose->ground_y = 0.0f;
  /* the animated toes, for the ground probes' next positions */
  for (uint32_t f = 0; f < 2u; ++f) {
    const float* tp = pose->wpos + 3u * toe_of(g, f);
    ground->prev_toe[f][0] = tp[0];
    ground->prev_toe[f][1] = tp[2];
  }
  if (!ik->enabled) {
    smgi_ik_reset(ik);
    return;
  }
  const smgi_info* info = g->data.info;
  const uint32_t bits[2] = {SMG_STATE_LEFT_CONTACT, SMG_STATE_RIGHT_CONTACT};
  const uint32_t* legs[2] = {info->left_leg, info->right_leg};
  const float step_in = dt / SMGI_IK_BLEND;
  for (uint32_t f = 0; f < 2u; ++f) {
    smgi_foot* foot = &ik->feet[f];
    if (!ik->leg_ok[f]) continue;
    uint32_t ankle = legs[f][2];
    /* the planted point: the toe when the skeleton has one */
    uint32_t toe = legs[f][3] < g->data.joint_count ? legs[f][3] : ankle;
    const float* ap = pose->wpos + 3u * toe;
    int contact = (pose->contacts & bits[f]) || foot->guided;
    if (foot->guided) {
      /* placed by the caller: planted where it says, no landing to
       * follow and no drift to let go of */
      foot->planted = 1;
      foot->landing = 0;
      foot->let_go = 0;
      foot->anchor[0] = foot->guide[0];
      foot->anchor[1] = ap[1];
      foot->anchor[2] = foot->guide[1];
    }
    if (foot->weight <= 0.0f) foot->let_go = 0;
    if (contact && !foot->planted && !foot->let_go) {
      foot->planted = 1;
      /* A contact that starts while the last one's correction is still
       * shown (a label flickering off for a step) holds the same anchor
       * again: a new anchor at the animated toe would move the pose by
       * that whole correction in one step (17 cm on the sparse graph's
       * U-turn). If the old anchor is too far, the drift check below lets
       * it go, and the foot is planted anew once the weight is 0. */
      if (foot->weight <= 0.0f) {
        foot->landing = 1;
        /* the animation has the foot exactly there now: no correction
         * to start the solve from */
        memcpy(foot->fix[0], k_identity, sizeof k_identity);
        memcpy(foot->fix[1], k_identity, sizeof k_identity);
      }
    } else if (!contact) {
      foot->planted = 0;
      foot->let_go = 0;
    }
    /* A contact label starts when the heel OR the toe is down: at a heel
     * strike the toe is still coming down and forward. The anchor follows
     * the animated toe while it descends and holds from the first step on
     * which it does not (or once the correction has blended in fully: a
     * toe that keeps sinking a little through a stance is down), so the
     * toe is held where it lands, not in the air (on a graph of two
     * performers the old anchor at the heel strike held toes 6 cm up).
     * It also holds once the toe is within SMGI_IK_CLEAR of the height
     * the foot was last held at: the last centimetre of a landing rolls
     * the toe forward along the floor (20-50 cm/s on the CMU walks), and
     * following it there was a slide. */
    if (foot->planted && foot->landing) {
      memcpy(foot->anchor, ap, sizeof foot->anchor);
      if (!(ap[1] < foot->toe[1]) || foot->weight >= 1.0f ||
          ap[1] <= foot->floor_y + SMGI_IK_CLEAR * info->leg_length) {
        foot->landing = 0;
        foot->floor_y = ap[1];
      }
    }
    /* the floor for swing clearance: the lowest the toe has stood (the
     * ground is flat; a single stance is not enough: a heel-first contact
     * or a turn on the heel holds the toe in the air, 3-5 cm up on the
     * CMU walks, and where the toe was held is not the floor either) */
    /* on uneven ground, heights above the ground the toe is placed on:
     * the animated toe's own height (the whole pose was raised by
     * `lifted` above; the legs are solved onto their grounds below, so a
     * toe ends that high above its ground). Where the toe stands is
     * measured that way too, not after the lift: the pelvis drop and
     * the root's ground against the foot's would count as floor (8-12 cm
     * under a ramp's plateau, where rest.c then stood the feet). */
    const float rel = ground->on ? ground->foot_y[f] : 0.0f;
    const float lifted = ground->on ? ground->root_y - ground->drop : 0.0f;
    if (foot->planted && ap[1] - lifted < foot->stand_y) foot->stand_y = ap[1] - lifted;
    float travel = 0.0f; /* the animated toe's ground step since the last */
    if (foot->toe[1] < INFINITY) {
      const float sx = ap[0] - foot->toe[0], sz = ap[2] - foot->toe[2];
      travel = sqrtf(sx * sx + sz * sz);
    }
    memcpy(foot->toe, ap, sizeof foot->toe);
    if (foot->planted && !foot->guided) {
      float dx = foot->anchor[0] - ap[0], dz = foot->anchor[2] - ap[2];
      float lim = SMGI_IK_RELEASE * info->leg_length;
      if (dx * dx + dz * dz > lim * lim) {
        /* implausible: let go smoothly; planted anew only once the
         * old correction is gone (at once, the pose would jump to the new
         * anchor) */
        foot->planted = 0;
        foot->let_go = 1;
      }
    }
    if (foot->planted) {
      foot->weight += step_in;
    } else {
      /* A released foot lets its correction go as the animated toe rises
       * off the floor (over SMGI_IK_LIFT leg lengths once it is
       * SMGI_IK_CLEAR above where it was held), so the correction returns
       * in the air, not as a slide while the toe rolls and pushes off; and
       * over SMGI_IK_LET_GO leg lengths of the toe's own travel at most,
       * for a foot that shuffles on without lifting (a fixed 0.3 s there
       * dragged toes still on the floor: the release then went on at the
       * same rate whether the foot moved or not). */
      float by_travel =
          foot->weight - travel / (SMGI_IK_LET_GO * info->leg_length);
      float by_lift = 1.0f - (ap[1] - foot->anchor[1] -
                              SMGI_IK_CLEAR * info->leg_length) /
                                 (SMGI_IK_LIFT * info->leg_length);
      foot->weight = by_travel < by_lift ? by_travel : by_lift;
    }
    foot->weight = smgi_clampf(foot->weight, 0.0f, 1.0f);
    if (ground->on) {
      /* every leg to its foot's ground; planted ones, eased by their
       * weight, also to their anchors */
      const float w = foot->weight * foot->weight * (3.0f - 2.0f * foot->weight);
      const float* an = pose->wpos + 3u * ankle;
      /* a guided foot (rest.c) rises by its step's arc on uneven ground
       * too */
      float target[3] = {an[0] + w * (foot->anchor[0] - ap[0]),
                         an[1] + off[f] + (foot->guided ? foot->guide[2] : 0.0f),
                         an[2] + w * (foot->anchor[2] - ap[2])};
      solve_leg(ik, pose, g, f, target, 1.0f, foot->fix);
    } else if (foot->weight > 0.0f) {
      /* eased (smoothstep): the correction starts and stops moving
       * gently */
      const float w = foot->weight * foot->weight * (3.0f - 2.0f * foot->weight);
      /* ankle target: the animated ankle-from-toe offset at the anchor,
       * at the animation's height (the data's feet are on the data's
       * floor; IK only stops them sliding) */
      const float* an = pose->wpos + 3u * ankle;
      if (!foot->guided) keep_in_reach(ik, foot, pose, g, f, ap, an[1], dt);
      float target[3] = {foot->anchor[0] + an[0] - ap[0],
                         an[1] + (foot->guided ? foot->guide[2] : 0.0f),
                         foot->anchor[2] + an[2] - ap[2]};
      solve_leg(ik, pose, g, f, target, w, foot->fix);
    } else {
      /* a later contact starts from the animation again */
      memcpy(foot->fix[0], k_identity, sizeof k_identity);
      memcpy(foot->fix[1], k_identity, sizeof k_identity);
    }
    /* Swing clearance, judged on the toe as shown after the contact
     * solve: a released foot's correction may still hold it back while
     * the animated toe already swings ahead at 1 m/s and more. The lift
     * follows what swing_lift wants at a bounded rate: it grows over
     * SMGI_IK_SWING_RISE at the fastest and shrinks over
     * SMGI_IK_SWING_FALL (a toe goes from standing to swing speed, or
     * back, within about 0.05 s: the lift would jump with it). What is
     * left of it when a contact starts is let go over the first steps of
     * the landing, on top of the contact's solve. */
    float speed = 0.0f;
    if (foot->shown[0] < INFINITY) {
      const float sx = ap[0] - foot->shown[0], sz = ap[2] - foot->shown[1];
      speed = sqrtf(sx * sx + sz * sz) / dt;
    }
    const float c = ik->swing_clearance;
    const float want = swing_lift(foot, ap[1] - rel, speed, c, info->leg_length);
    /* rates on the scale of the clearance, at least the default's: a
     * lift left when the clearance is turned off (c = 0) still returns */
    float scale = ik->swing_default;
    if (c > scale) scale = c;
    const float most = foot->lift + scale * dt / SMGI_IK_SWING_RISE;
    const float least = foot->lift - scale * dt / SMGI_IK_SWING_FALL;
    foot->lift = smgi_clampf(want, least > 0.0f ? least : 0.0f, most);
    if (foot->lift > 0.0f) {
      /* on top of whatever the contact solve left: the whole foot up by
       * the lift, from the pose as it is now, not from the contact's
       * correction */
      const float* an = pose->wpos + 3u * ankle;
      const float target[3] = {an[0], an[1] + foot->lift, an[2]};
      float fix[2][4];
      memcpy(fix[0], k_identity, sizeof k_identity);
      memcpy(fix[1], k_identity, sizeof k_identity);
      solve_leg(ik, pose, g, f, target, 1.0f, fix);
    }
    foot->shown[0] = ap[0];
    foot->shown[1] = ap[2];
    foot->guided = 0;
  }
}
