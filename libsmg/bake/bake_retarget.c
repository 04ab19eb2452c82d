/*
 * bake_retarget.c - motion from any humanoid skeleton onto a target rig
 * (see bake_retarget.h for the method, docs/baker.md for why).
 *
 * Both skeletons are looked at in their "identity pose" (every local
 * rotation identity): for the target that is its rest pose (world-aligned
 * rest, smgb_rig_load), for a source possibly no pose at all (Bandai
 * Namco's bones all lie along their local x). The target's rest decides
 * the rule of every target joint A (plan_rules); the alignments are then
 * measured on the clip's motion (plan_align), so that the source joints'
 * local axes cancel:
 *   FRAME   A branches into a central joint and a left/right pair (pelvis,
 *           chest): the constant rotation that maps the target's rest frame
 *           (central direction, left-right axis) onto the source's;
 *   SWING   A has one paired descendant B (limbs, neck): the rotation of
 *           the rest bone A->B onto the source's, with the source's twist
 *           about it, and per frame the shortest swing onto the source's
 *           actual A->B direction, which also folds in the rotations of
 *           source joints between them that the target lacks;
 *   END     ends (hands, head, toes): the source's mean relation to the
 *           nearest paired ancestor becomes the target's rest relation.
 * world(A) = world_source(pair(A)) * alignment(A) [* swing]. Unpaired target
 * joints (fingers, twist bones) keep their rest rotation relative to their
 * parent. Finally the root follows the source pelvis scaled by k = target
 * leg / source leg (shifted so the hips' midpoint matches the scaled
 * source's) and a two-bone solve per leg puts the ankle at k * the source
 * ankle, keeping the knee's bend plane.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_import_util.h"
#include "bake_math.h"
#include "bake_retarget.h"

#define RULE_REST 0    /* unpaired: rest relative to the parent */
#define RULE_FRAME 1
#define RULE_SWING 2
#define RULE_END 3

/* ---- rigs ------------------------------------------------------------- */

smg_result smgb_rig_from_pose(const smgb_skeleton* s, const float* pose,
                              smgb_skeleton* out) {
  smgb_skeleton r;
  float* pos;
  uint32_t j;
  smg_result res;
  if (!s || !pose || !out || s->joint_count == 0)
    return SMG_ERROR_INVALID_ARGUMENT;
  pos = (float*)malloc(sizeof(float) * 3 * s->joint_count);
  if (!pos) return SMG_ERROR_OUT_OF_MEMORY;
  res = smgb_skeleton_copy(s, &r);
  if (res != SMG_OK) {
    free(pos);
    return res;
  }
  smgb_fk(s, pose, pos, NULL);
  for (j = 1; j < s->joint_count; ++j) {
    int32_t p = s->parents[j];
    int k;
    for (k = 0; k < 3; ++k)
      r.offsets[j][k] = pos[3 * j + k] - pos[3 * (uint32_t)p + k];
  }
  free(pos);
  *out = r;
  return SMG_OK;
}

smg_result smgb_rig_load(const char* path, float unit_scale,
                         uint32_t animation_index, smgb_skeleton* out,
                         smgb_error* err) {
  smgb_clip c;
  smg_result r;
  if (err) err->message[0] = '\0';
  if (!path || !out) {
    smgb_imp_errorf(err, "smgb_rig_load: no path");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  memset(&c, 0, sizeof c);
  if (smgb_has_ext(path, ".bvh")) {
    /* BVH rest = the OFFSET pose: offsets are world-aligned already. */
    r = smgb_bvh_load(path, unit_scale, 0, &c, err);
    if (r == SMG_OK) r = smgb_skeleton_copy(&c.skeleton, out);
  } else {
    r = smgb_assimp_load(path, unit_scale, animation_index, &c, err);
    if (r == SMG_OK) r = smgb_rig_from_pose(&c.skeleton, c.poses, out);
  }
  smgb_clip_free(&c);
  return r;
}

int smgb_same_hierarchy(const smgb_skeleton* a, const smgb_skeleton* b) {
  uint32_t j;
  if (!a || !b || a->joint_count != b->joint_count) return 0;
  for (j = 0; j < a->joint_count; ++j)
    if (a->parents[j] != b->parents[j] || strcmp(a->names[j], b->names[j]))
      return 0;
  return 1;
}

/* ---- small vector / quaternion helpers -------------------------------- */

static double v_len(const double v[3]) {
  return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static int v_unit(double v[3]) {
  double n = v_len(v);
  if (!(n > 1e-9)) return 0;
  v[0] /= n; v[1] /= n; v[2] /= n;
  return 1;
}

static double v_dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void v_cross(const double a[3], const double b[3], double o[3]) {
  double r0 = a[1] * b[2] - a[2] * b[1];
  double r1 = a[2] * b[0] - a[0] * b[2];
  double r2 = a[0] * b[1] - a[1] * b[0];
  o[0] = r0; o[1] = r1; o[2] = r2;
}

static void v_sub(const double a[3], const double b[3], double o[3]) {
  o[0] = a[0] - b[0]; o[1] = a[1] - b[1]; o[2] = a[2] - b[2];
}

static void q_identity(double q[4]) {
  q[0] = q[1] = q[2] = 0.0;
  q[3] = 1.0;
}

/* Shortest rotation taking unit u onto unit v. */
static void q_arc(const double u[3], const double v[3], double q[4]) {
  double d = v_dot(u, v), c[3];
  if (d < -0.999999) {
    /* half turn about any axis perpendicular to u */
    double a[3] = {1.0, 0.0, 0.0};
    if (fabs(u[0]) > 0.9) { a[0] = 0.0; a[1] = 1.0; }
    v_cross(u, a, c);
    v_unit(c);
    q[0] = c[0]; q[1] = c[1]; q[2] = c[2]; q[3] = 0.0;
    return;
  }
  v_cross(u, v, c);
  q[0] = c[0]; q[1] = c[1]; q[2] = c[2]; q[3] = 1.0 + d;
  smgb_q_normalize(q);
}

/* Rotation whose columns are the orthonormal frame (lateral, primary,
 * lateral x primary); 0 when the two directions are (nearly) parallel. */
static int q_frame(const double primary[3], const double lateral[3],
                   double q[4]) {
  double y[3] = {primary[0], primary[1], primary[2]};
  double x[3], z[3], d;
  if (!v_unit(y)) return 0;
  d = v_dot(lateral, y);
  x[0] = lateral[0] - d * y[0];
  x[1] = lateral[1] - d * y[1];
  x[2] = lateral[2] - d * y[2];
  if (v_len(x) < 0.2 * v_len(lateral) || !v_unit(x)) return 0;
  v_cross(x, y, z);
  smgb_q_from_axes(x, y, z, q);
  return 1;
}

/* ---- joint pairing ------------------------------------------------------ */

/* The part of a name after any "namespace:" prefix. */
static const char* bare_name(const char* n) {
  const char* c = strrchr(n, ':');
  return c ? c + 1 : n;
}

static int same_name(const char* a, const char* b) {
  return smgb_name_ieq(bare_name(a), bare_name(b));
}

/* map[t] = source joint paired with target joint t, or -1: by body role,
 * then (for joints without a role: extra spine joints, fingers) by name. */
static void pair_joints(const smgb_skeleton* src, const smgb_roles* sr,
                        const smgb_skeleton* tgt, const smgb_roles* tr,
                        int32_t* map) {
  uint32_t t, s;
  int r;
  for (t = 0; t < tgt->joint_count; ++t) map[t] = -1;
  for (r = 0; r < SMGB_ROLE_COUNT; ++r)
    if (tr->joint[r] >= 0 && sr->joint[r] >= 0)
      map[tr->joint[r]] = sr->joint[r];
  for (t = 0; t < tgt->joint_count; ++t) {
    if (map[t] >= 0) continue;
    for (s = 0; s < src->joint_count; ++s) {
      uint32_t u;
      int used = 0;
      if (!same_name(tgt->names[t], src->names[s])) continue;
      for (u = 0; u < tgt->joint_count && !used; ++u)
        used = map[u] == (int32_t)s;
      for (r = 0; r < SMGB_ROLE_COUNT && !used; ++r)
        used = sr->joint[r] == (int32_t)s;
      if (!used) map[t] = (int32_t)s;
      break;
    }
  }
}

static const smgb_role k_leg_roles[2][3] = {
    {SMGB_ROLE_LEFT_UPPER_LEG, SMGB_ROLE_LEFT_LOWER_LEG, SMGB_ROLE_LEFT_FOOT},
    {SMGB_ROLE_RIGHT_UPPER_LEG, SMGB_ROLE_RIGHT_LOWER_LEG,
     SMGB_ROLE_RIGHT_FOOT}};

/* Leg chain of one side from the roles: hip, knee, ankle joints; returns
 * the first missing part (3 = complete). */
static int find_leg(const smgb_roles* r, int side, int32_t leg[3]) {
  int i;
  for (i = 0; i < 3; ++i) {
    leg[i] = r->joint[k_leg_roles[side][i]];
    if (leg[i] < 0) return i;
  }
  return 3;
}

/* Sum of bone lengths from `lo` up to its ancestor `hi` (0 if not one). */
static double chain_length(const smgb_skeleton* s, int32_t hi, int32_t lo) {
  double len = 0.0;
  while (lo != hi) {
    const float* o;
    if (lo <= 0) return 0.0;
    o = s->offsets[lo];
    len += sqrt((double)o[0] * o[0] + (double)o[1] * o[1] +
                (double)o[2] * o[2]);
    lo = s->parents[lo];
  }
  return len;
}

/* ---- per-clip plan ----------------------------------------------------- */

typedef struct rt_plan {
  uint32_t T, S;
  int32_t* map;        /* T: paired source joint or -1 */
  uint8_t* rule;       /* T: RULE_* */
  int32_t* primary;    /* T: target joint B of a SWING joint */
  int32_t* send;       /* T: source joint the swing aims at (B's pair, or
                          past it when that bone has no length) */
  int32_t* body;       /* T: SWING, END: nearest paired ancestor, whose
                          alignment the joint's is measured from */
  int32_t (*fsrc)[3];  /* T: FRAME: source central end, left, right */
  uint8_t* rest_frame; /* T: FRAME: the source's identity pose has one */
  double (*align)[4];  /* T: constant alignment quaternion */
  double (*tframe)[4]; /* T: FRAME: the target's rest frame */
  double (*dir)[3];    /* T: target rest direction A->B (SWING) */
  double (*sdir)[3];   /* T: the bone A->B in the source joint's axes */
  double* pt;          /* 3T target rest positions */
  double* ps;          /* 3S source identity-pose positions */
  int32_t leg[2][3];   /* target hip, knee, ankle */
  int32_t sleg[2][3];  /* source hip, knee, ankle */
  double k;            /* target leg / source leg */
  double side[3];      /* the rig's left-right axis at rest (right hip to
                          left hip), whatever way the rig faces */
} rt_plan;

static void plan_free(rt_plan* p) {
  free(p->map);
  free(p->rule);
  free(p->primary);
  free(p->send);
  free(p->body);
  free(p->fsrc);
  free(p->rest_frame);
  free(p->align);
  free(p->tframe);
  free(p->dir);
  free(p->sdir);
  free(p->pt);
  free(p->ps);
  memset(p, 0, sizeof *p);
}

/* Positions of the identity pose (root at the origin). */
static void rest_positions(const smgb_skeleton* s, double* out) {
  uint32_t j;
  out[0] = out[1] = out[2] = 0.0;
  for (j = 1; j < s->joint_count; ++j) {
    uint32_t p = (uint32_t)s->parents[j];
    int k;
    for (k = 0; k < 3; ++k) out[3 * j + k] = out[3 * p + k] + s->offsets[j][k];
  }
}

static int is_ancestor(const smgb_skeleton* s, int32_t a, int32_t j) {
  while (j >= 0 && j != a) j = s->parents[j];
  return j == a;
}

/* The paired descendants of a reached through unpaired joints only. */
static uint32_t frontier(const smgb_skeleton* s, const int32_t* map,
                         uint32_t a, int32_t* out, uint32_t cap) {
  uint32_t j, n = 0;
  for (j = a + 1; j < s->joint_count; ++j) {
    int32_t p;
    if (map[j] < 0 || !is_ancestor(s, (int32_t)a, (int32_t)j)) continue;
    for (p = s->parents[j]; p != (int32_t)a; p = s->parents[p])
      if (map[p] >= 0) break;
    if (p == (int32_t)a && n < cap) out[n++] = (int32_t)j;
  }
  return n;
}

static void dir_between(const double* pos, int32_t a, int32_t b,
                        double o[3]) {
  v_sub(pos + 3 * b, pos + 3 * a, o);
}

/* The joint a bone from joint a towards b ends at: b, or when b sits on a
 * in the pose `ps` (zero-length helper joints such as CMU's LowerBack and
 * LHipJoint), the first descendant down b's first-child chain that does
 * not. */
static int32_t bone_end(const smgb_skeleton* src, const double* ps,
                        int32_t a, int32_t b) {
  while (b >= 0) {
    double d[3];
    uint32_t c;
    dir_between(ps, a, b, d);
    if (v_len(d) > 1e-4) return b;
    for (c = (uint32_t)b + 1; c < src->joint_count; ++c)
      if (src->parents[c] == b) break;
    b = c < src->joint_count ? (int32_t)c : -1;
  }
  return -1;
}

/* Chooses the rule of every target joint, its target-side geometry and a
 * first alignment from the source's identity pose (kept where the motion
 * cannot measure a better one, plan_align). */
static void plan_rules(rt_plan* p, const smgb_skeleton* src,
                       const smgb_skeleton* tgt) {
  uint32_t t;
  int32_t cand[64];
  for (t = 0; t < p->T; ++t) {
    uint32_t n, i;
    int32_t central = -1, left = -1, right = -1;
    q_identity(p->align[t]);
    p->primary[t] = -1;
    p->body[t] = -1;
    if (p->map[t] < 0) {
      p->rule[t] = RULE_REST;
      continue;
    }
    p->rule[t] = RULE_END;
    n = frontier(tgt, p->map, t, cand, 64);
    if (n >= 3) {
      /* a left/right pair and a central joint: the most lateral joint on
       * each side of the rig's left-right axis, and of the others the one
       * nearest the middle, nearer than both (a chest's clavicles may
       * start close to its middle) */
      double x[64];
      for (i = 0; i < n; ++i) {
        double d[3];
        int32_t e = bone_end(tgt, p->pt, (int32_t)t, cand[i]);
        if (e < 0) e = cand[i];
        dir_between(p->pt, (int32_t)t, e, d);
        x[i] = v_dot(d, p->side);
        if (left < 0 || x[i] > x[left]) left = (int32_t)i;
        if (right < 0 || x[i] < x[right]) right = (int32_t)i;
      }
      for (i = 0; i < n; ++i)
        if ((int32_t)i != left && (int32_t)i != right &&
            (central < 0 || fabs(x[i]) < fabs(x[central])))
          central = (int32_t)i;
      if (central >= 0 && x[left] > 0.0 && x[right] < 0.0 &&
          fabs(x[central]) < x[left] && fabs(x[central]) < -x[right]) {
        central = cand[central];
        left = cand[left];
        right = cand[right];
      } else {
        central = left = right = -1;
      }
    }
    if (n == 1) {
      /* a limb (a zero-length bone in either skeleton: END) */
      int32_t b = cand[0];
      int32_t e = bone_end(src, p->ps, p->map[t], p->map[b]);
      double dt[3], ds[3] = {0.0, 0.0, 0.0};
      dir_between(p->pt, (int32_t)t, b, dt);
      if (e >= 0) dir_between(p->ps, p->map[t], e, ds);
      if (v_unit(dt) && v_unit(ds)) {
        int32_t a = tgt->parents[t];
        p->rule[t] = RULE_SWING;
        p->primary[t] = b;
        p->send[t] = e;
        memcpy(p->dir[t], dt, sizeof dt);
        memcpy(p->sdir[t], ds, sizeof ds);
        q_arc(dt, ds, p->align[t]);
        while (a >= 0 && p->map[a] < 0) a = tgt->parents[a];
        p->body[t] = a;
      }
    } else if (central >= 0) {
      double ct[3], cs[3] = {0.0, 0.0, 0.0}, lt[3], ls[3], qs[4], qi[4];
      /* directions to the ends of zero-length helper bones (CMU's hips
       * and clavicles may sit on the joint they branch from) */
      int32_t e = bone_end(src, p->ps, p->map[t], p->map[central]);
      int32_t sl = bone_end(src, p->ps, p->map[t], p->map[left]);
      int32_t sr = bone_end(src, p->ps, p->map[t], p->map[right]);
      int32_t tc = bone_end(tgt, p->pt, (int32_t)t, central);
      int32_t tl = bone_end(tgt, p->pt, (int32_t)t, left);
      int32_t tr = bone_end(tgt, p->pt, (int32_t)t, right);
      if (e >= 0 && sl >= 0 && sr >= 0 && tc >= 0 && tl >= 0 && tr >= 0) {
        dir_between(p->pt, (int32_t)t, tc, ct);
        dir_between(p->ps, p->map[t], e, cs);
        v_sub(p->pt + 3 * tl, p->pt + 3 * tr, lt);
        v_sub(p->ps + 3 * sl, p->ps + 3 * sr, ls);
      } else {
        e = -1;
      }
      if (e >= 0 && q_frame(ct, lt, p->tframe[t])) {
        p->rule[t] = RULE_FRAME;
        p->fsrc[t][0] = e;
        p->fsrc[t][1] = sl;
        p->fsrc[t][2] = sr;
        /* the source's identity pose may be no pose at all (then the
         * motion decides alone, plan_align) */
        p->rest_frame[t] = (uint8_t)q_frame(cs, ls, qs);
        if (p->rest_frame[t]) {
          smgb_q_conj(p->tframe[t], qi);
          smgb_q_mul(qs, qi, p->align[t]);
        }
      }
    }
    if (p->rule[t] == RULE_END) {
      int32_t a = tgt->parents[t];
      while (a >= 0 && p->map[a] < 0) a = tgt->parents[a];
      p->body[t] = a;
      if (a >= 0) memcpy(p->align[t], p->align[a], sizeof p->align[t]);
    }
  }
}

/* ---- alignments measured on the motion --------------------------------- */

/* Source joint s's world rotation and position at frame f of the FK
 * buffers (4S and 3S floats a frame). */
static void src_rot(const float* fkw, uint32_t S, uint32_t f, int32_t s,
                    double q[4]) {
  const float* w = fkw + ((size_t)f * S + (uint32_t)s) * 4;
  q[0] = w[0]; q[1] = w[1]; q[2] = w[2]; q[3] = w[3];
}

static void src_dir(const float* fkp, uint32_t S, uint32_t f, int32_t a,
                    int32_t b, double d[3]) {
  const float* pa = fkp + ((size_t)f * S + (uint32_t)a) * 3;
  const float* pb = fkp + ((size_t)f * S + (uint32_t)b) * 3;
  d[0] = (double)pb[0] - pa[0];
  d[1] = (double)pb[1] - pa[1];
  d[2] = (double)pb[2] - pa[2];
}

/* |cos(half the angle)| between two rotations. */
static double q_dot_abs(const double a[4], const double b[4]) {
  return fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
}

/* cos(15 deg): rotations within 30 degrees of each other */
static const double k_rest_agrees = 0.96592582628906831;

/* Adds unit quaternion q to a running sum in the hemisphere of the sum
 * (the mean of nearby rotations, normalised at the end). */
static void q_accumulate(double sum[4], const double q[4], double w) {
  double d = sum[0] * q[0] + sum[1] * q[1] + sum[2] * q[2] + sum[3] * q[3];
  int k;
  if (d < 0.0) w = -w;
  for (k = 0; k < 4; ++k) sum[k] += w * q[k];
}

static int q_mean(double sum[4]) {
  double n = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2] +
                  sum[3] * sum[3]);
  if (!(n > 1e-9)) return 0;
  sum[0] /= n; sum[1] /= n; sum[2] /= n; sum[3] /= n;
  return 1;
}

/* Replaces the identity-pose alignments by ones measured on the clip's
 * motion (world positions and rotations of every frame in fkp / fkw), so
 * that only geometry decides them, never the source joints' local axes
 * (a source whose identity pose is no pose at all, Bandai Namco's bones
 * all along local x, gets the same result as a T-pose rig). Joints go in
 * order, so a joint's paired ancestor has its final alignment when the
 * joint is measured:
 *   FRAME  the source joint's rotation to the source's frame (central
 *          direction, left-right axis) times the target's rest frame
 *          inverted: the identity pose's when the mean over the frames
 *          agrees with it within 30 degrees, else that mean;
 *   SWING  the rotation taking the target's rest bone onto the source's
 *          bone, with the twist about it that the source bone has when,
 *          seen from its aligned paired ancestor, it is swung the shortest
 *          way onto the target's rest direction (a hinge such as the knee
 *          or elbow straightens about its own axis, so its twist is
 *          measured exactly): a weighted circular mean over frames, those
 *          whose bone is near the rest direction counting most (the twist
 *          of a far pose depends on the way it went there);
 *   END    no direction to measure (hands, head, toes): the end's mean
 *          rotation relative to its paired ancestor becomes the target's
 *          rest relation.
 * Joints without usable frames keep their identity-pose alignment. */
static void plan_align(rt_plan* p, const float* fkp, const float* fkw,
                       uint32_t frames) {
  uint32_t S = p->S, t, f;
  /* a limb's bone in its source joint's axes: the mean over frames (it
   * moves when source joints the target lacks sit between its ends, and
   * the identity pose would put those at the source rig's whim) */
  for (t = 0; t < p->T; ++t) {
    double sum[3] = {0.0, 0.0, 0.0};
    if (p->rule[t] != RULE_SWING) continue;
    for (f = 0; f < frames; ++f) {
      double ws[4], wi[4], d[3];
      src_dir(fkp, S, f, p->map[t], p->send[t], d);
      if (!v_unit(d)) continue;
      src_rot(fkw, S, f, p->map[t], ws);
      smgb_q_conj(ws, wi);
      smgb_q_rotate(wi, d, d);
      sum[0] += d[0];
      sum[1] += d[1];
      sum[2] += d[2];
    }
    if (v_unit(sum)) {
      memcpy(p->sdir[t], sum, sizeof sum);
      q_arc(p->dir[t], p->sdir[t], p->align[t]);
    }
  }
  for (t = 0; t < p->T; ++t) {
    double sum[4] = {0.0, 0.0, 0.0, 0.0}, tmp[4], ws[4], wi[4], q[4];
    int32_t b = p->body[t];
    if (p->rule[t] == RULE_FRAME) {
      for (f = 0; f < frames; ++f) {
        double c[3], l[3];
        src_dir(fkp, S, f, p->map[t], p->fsrc[t][0], c);
        src_dir(fkp, S, f, p->fsrc[t][2], p->fsrc[t][1], l);
        if (!q_frame(c, l, tmp)) continue;
        src_rot(fkw, S, f, p->map[t], ws);
        smgb_q_conj(ws, wi);
        smgb_q_mul(wi, tmp, q);
        q_accumulate(sum, q, 1.0);
      }
      if (q_mean(sum)) {
        smgb_q_conj(p->tframe[t], tmp);
        smgb_q_mul(sum, tmp, q);
        /* the identity pose's frame is kept when the motion agrees with
         * it: a frame through helper joints (CMU's pelvis to spine runs
         * through the animated LowerBack) moves with the motion, and its
         * mean would tilt every clip's pelvis by that clip's mean lumbar
         * bend; an identity pose that is no pose differs by far more */
        if (!p->rest_frame[t] || q_dot_abs(q, p->align[t]) < k_rest_agrees)
          memcpy(p->align[t], q, sizeof q);
      }
    } else if (p->rule[t] == RULE_END && b >= 0) {
      for (f = 0; f < frames; ++f) {
        src_rot(fkw, S, f, p->map[t], ws);
        src_rot(fkw, S, f, p->map[b], q);
        smgb_q_conj(ws, wi);
        smgb_q_mul(wi, q, tmp);
        q_accumulate(sum, tmp, 1.0);
      }
      if (q_mean(sum))
        smgb_q_mul(sum, p->align[b], p->align[t]);
      else
        memcpy(p->align[t], p->align[b], sizeof tmp);
    } else if (p->rule[t] == RULE_SWING && b >= 0) {
      double r0i[4], ai[4], d;
      q_arc(p->dir[t], p->sdir[t], tmp);
      smgb_q_conj(tmp, r0i);
      smgb_q_conj(p->align[b], ai);
      for (f = 0; f < frames; ++f) {
        double wa[4], ls[4], li[4], db[3], sw[4], w;
        /* the source joint seen from its aligned paired ancestor, whose
         * target counterpart is at rest (world-aligned: identity) */
        src_rot(fkw, S, f, p->map[b], wa);
        src_rot(fkw, S, f, p->map[t], ws);
        smgb_q_conj(wa, wi);
        smgb_q_mul(wi, ws, tmp);
        smgb_q_mul(ai, tmp, ls);
        smgb_q_rotate(ls, p->sdir[t], db);
        w = 0.5 * (1.0 + v_dot(db, p->dir[t]));
        w *= w;
        w *= w;
        w *= w; /* ((1 + cos) / 2)^8: 0.28 at 45 deg, 0.004 at 90 */
        if (!(w > 1e-12)) continue;
        /* the alignment that puts the target's rest bone, swung the
         * shortest way onto this frame's bone, on this frame's source
         * joint: Ls^-1 * arc(rest, bone); its twist about the rest bone
         * relative to the shortest arc between the two bone directions */
        q_arc(p->dir[t], db, sw);
        smgb_q_conj(ls, li);
        smgb_q_mul(li, sw, tmp);
        smgb_q_mul(r0i, tmp, q);
        d = 2.0 * atan2(v_dot(q, p->dir[t]), q[3]);
        sum[0] += w * cos(d);
        sum[1] += w * sin(d);
      }
      if (sum[0] * sum[0] + sum[1] * sum[1] > 1e-24) {
        smgb_q_axis_angle(p->dir[t], atan2(sum[1], sum[0]), q);
        q_arc(p->dir[t], p->sdir[t], tmp);
        smgb_q_mul(tmp, q, p->align[t]);
      }
    }
  }
}

static smg_result plan_init(rt_plan* p, const smgb_clip* clip,
                            const smgb_roles* sr, const smgb_skeleton* tgt,
                            const smgb_roles* tr, const char* tname,
                            smgb_error* err) {
  const smgb_skeleton* src = &clip->skeleton;
  static const char* const side_name[2] = {"left", "right"};
  static const char* const part_name[3] = {"hip", "knee", "ankle"};
  uint32_t T = tgt->joint_count, S = src->joint_count;
  double lt = 0.0, ls = 0.0;
  int side;
  memset(p, 0, sizeof *p);
  p->T = T;
  p->S = S;
  p->map = (int32_t*)malloc(sizeof *p->map * T);
  p->rule = (uint8_t*)malloc(sizeof *p->rule * T);
  p->primary = (int32_t*)malloc(sizeof *p->primary * T);
  p->send = (int32_t*)malloc(sizeof *p->send * T);
  p->body = (int32_t*)malloc(sizeof *p->body * T);
  p->fsrc = (int32_t(*)[3])malloc(sizeof *p->fsrc * T);
  p->rest_frame = (uint8_t*)calloc(T, 1);
  p->align = (double(*)[4])malloc(sizeof *p->align * T);
  p->tframe = (double(*)[4])malloc(sizeof *p->tframe * T);
  p->dir = (double(*)[3])calloc(T, sizeof *p->dir);
  p->sdir = (double(*)[3])calloc(T, sizeof *p->sdir);
  p->pt = (double*)malloc(sizeof *p->pt * 3 * T);
  p->ps = (double*)malloc(sizeof *p->ps * 3 * S);
  if (!p->map || !p->rule || !p->primary || !p->send || !p->body ||
      !p->fsrc || !p->rest_frame || !p->align || !p->tframe || !p->dir || !p->sdir || !p->pt ||
      !p->ps) {
    plan_free(p);
    smgb_imp_errorf(err, "%s: out of memory (retarget)", clip->name);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  pair_joints(src, sr, tgt, tr, p->map);
  for (side = 0; side < 2; ++side) {
    int i, ft = find_leg(tr, side, p->leg[side]);
    int fs = find_leg(sr, side, p->sleg[side]);
    if (ft < 3 || fs < 3) {
      int missing = ft < 3 ? ft : fs;
      smgb_imp_errorf(err,
                      "%s: cannot retarget onto %s: no %s %s joint (role "
                      "'%s') in the %s",
                      clip->name, tname, side_name[side], part_name[missing],
                      smgb_role_name(k_leg_roles[side][missing]),
                      ft < 3 ? "rig" : "clip");
      plan_free(p);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    for (i = 0; i < 3; ++i)
      if (p->map[p->leg[side][i]] != p->sleg[side][i]) {
        smgb_imp_errorf(err,
                        "%s: cannot retarget onto %s: the rig's %s %s '%s' "
                        "is not paired with the clip's '%s'",
                        clip->name, tname, side_name[side], part_name[i],
                        tgt->names[p->leg[side][i]],
                        src->names[p->sleg[side][i]]);
        plan_free(p);
        return SMG_ERROR_INVALID_ARGUMENT;
      }
    lt += chain_length(tgt, p->leg[side][0], p->leg[side][2]);
    ls += chain_length(src, p->sleg[side][0], p->sleg[side][2]);
  }
  if (p->map[0] < 0) {
    smgb_imp_errorf(err,
                    "%s: cannot retarget onto %s: the rig's root joint '%s' "
                    "(its pelvis) has no counterpart in the clip",
                    clip->name, tname, tgt->names[0]);
    plan_free(p);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!(lt > 1e-4) || !(ls > 1e-4)) {
    smgb_imp_errorf(err,
                    "%s: cannot retarget onto %s: the %s's hip-to-ankle "
                    "chain has no length",
                    clip->name, tname, lt > 1e-4 ? "clip" : "rig");
    plan_free(p);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  p->k = lt / ls;
  rest_positions(tgt, p->pt);
  rest_positions(src, p->ps);
  v_sub(p->pt + 3 * p->leg[0][0], p->pt + 3 * p->leg[1][0], p->side);
  if (!v_unit(p->side)) {
    smgb_imp_errorf(err,
                    "%s: cannot retarget onto %s: the rig's hip joints '%s' "
                    "and '%s' coincide",
                    clip->name, tname, tgt->names[p->leg[0][0]],
                    tgt->names[p->leg[1][0]]);
    plan_free(p);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  plan_rules(p, src, tgt);
  return SMG_OK;
}

/* ---- per frame ---------------------------------------------------------- */

typedef struct rt_scratch {
  const float* ps; /* 3S source world positions of this frame */
  const float* ws; /* 4S source world rotations of this frame */
  double* w;     /* 4T target world rotations */
  double* pt;    /* 3T target world positions */
} rt_scratch;

/* Unpaired joints follow their parent (rest relative to it). */
static void propagate_rest(const smgb_skeleton* tgt, const rt_plan* p,
                           double* w) {
  uint32_t t;
  for (t = 1; t < p->T; ++t)
    if (p->map[t] < 0)
      memcpy(w + 4 * t, w + 4 * (uint32_t)tgt->parents[t], 4 * sizeof *w);
}

static void target_positions(const smgb_skeleton* tgt, const double root[3],
                             const double* w, double* pt) {
  uint32_t t;
  memcpy(pt, root, 3 * sizeof *pt);
  for (t = 1; t < tgt->joint_count; ++t) {
    uint32_t a = (uint32_t)tgt->parents[t];
    double o[3] = {tgt->offsets[t][0], tgt->offsets[t][1], tgt->offsets[t][2]};
    smgb_q_rotate(w + 4 * a, o, o);
    pt[3 * t + 0] = pt[3 * a + 0] + o[0];
    pt[3 * t + 1] = pt[3 * a + 1] + o[1];
    pt[3 * t + 2] = pt[3 * a + 2] + o[2];
  }
}

/* Two-bone solve: put the ankle at `goal`, keeping the knee's bend plane
 * (a straight leg bends towards the pelvis' forward). */
static void solve_leg(const int32_t leg[3], const double goal[3], double* w,
                      const double* pt) {
  const double *H = pt + 3 * leg[0], *K = pt + 3 * leg[1], *A = pt + 3 * leg[2];
  double hk[3], ka[3], ha[3], hg[3], n[3], th[3], nk[3], s1[3], s2[3];
  double a, b, d, c, alpha, qn[4], r1[4], r2[4], tmp[4];
  v_sub(K, H, hk);
  v_sub(A, K, ka);
  v_sub(A, H, ha);
  v_sub(goal, H, hg);
  a = v_len(hk);
  b = v_len(ka);
  d = v_len(hg);
  if (!(a > 1e-6) || !(b > 1e-6) || !(d > 1e-6)) return;
  v_cross(ha, hk, n);
  if (v_len(n) < 1e-6 * a * a) {
    double f[3] = {0.0, 0.0, 1.0};
    smgb_q_rotate(w, f, f); /* joint 0 is the pelvis */
    v_cross(ha, f, n);
  }
  if (!v_unit(n)) return;
  if (d > (a + b) * (1.0 - 1e-6)) d = (a + b) * (1.0 - 1e-6);
  if (d < fabs(a - b) + 1e-6) d = fabs(a - b) + 1e-6;
  c = (a * a + d * d - b * b) / (2.0 * a * d);
  alpha = acos(c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c);
  v_unit(hg);
  smgb_q_axis_angle(n, alpha, qn);
  smgb_q_rotate(qn, hg, th); /* new thigh direction */
  v_unit(hk);
  q_arc(hk, th, r1);
  nk[0] = H[0] + a * th[0];
  nk[1] = H[1] + a * th[1];
  nk[2] = H[2] + a * th[2];
  v_unit(ka);
  smgb_q_rotate(r1, ka, s1);
  v_sub(goal, nk, s2);
  if (!v_unit(s2)) return;
  q_arc(s1, s2, r2);
  smgb_q_mul(r1, w + 4 * leg[0], tmp);
  memcpy(w + 4 * leg[0], tmp, sizeof tmp);
  smgb_q_mul(r1, w + 4 * leg[1], tmp);
  smgb_q_mul(r2, tmp, w + 4 * leg[1]);
}

static void retarget_frame(const rt_plan* p, const smgb_skeleton* tgt,
                           float* out, rt_scratch* sc) {
  uint32_t t;
  double root[3];
  int side;
  for (t = 0; t < p->T; ++t) {
    int32_t s = p->map[t];
    double ws[4], *w = sc->w + 4 * t;
    int k;
    if (s < 0) continue;
    for (k = 0; k < 4; ++k) ws[k] = sc->ws[4 * s + k];
    smgb_q_mul(ws, p->align[t], w);
    if (p->rule[t] == RULE_SWING) {
      int32_t sb = p->send[t];
      double u[3], v[3], q[4], tmp[4];
      smgb_q_rotate(w, p->dir[t], u);
      for (k = 0; k < 3; ++k)
        v[k] = (double)sc->ps[3 * sb + k] - sc->ps[3 * s + k];
      if (v_unit(u) && v_unit(v)) {
        q_arc(u, v, q);
        smgb_q_mul(q, w, tmp);
        memcpy(w, tmp, sizeof tmp);
      }
    }
  }
  propagate_rest(tgt, p, sc->w);
  /* Root: where the source's pelvis is, scaled by k, then shifted so the
   * hip joints' midpoint lands on the scaled source's: hip-to-ankle
   * distances are then k times the source's and the leg solve always
   * reaches (a rig whose hips sit higher in its pelvis would otherwise
   * over-stretch its stance legs and drag the feet). */
  for (t = 0; t < 3; ++t) root[t] = p->k * sc->ps[3 * p->map[0] + t];
  target_positions(tgt, root, sc->w, sc->pt);
  for (t = 0; t < 3; ++t)
    root[t] += 0.5 * (p->k * ((double)sc->ps[3 * p->sleg[0][0] + t] +
                              sc->ps[3 * p->sleg[1][0] + t]) -
                      sc->pt[3 * p->leg[0][0] + t] -
                      sc->pt[3 * p->leg[1][0] + t]);
  target_positions(tgt, root, sc->w, sc->pt);
  for (side = 0; side < 2; ++side) {
    double goal[3];
    int32_t sa = p->sleg[side][2];
    for (t = 0; t < 3; ++t) goal[t] = p->k * sc->ps[3 * sa + t];
    solve_leg(p->leg[side], goal, sc->w, sc->pt);
  }
  propagate_rest(tgt, p, sc->w);
  for (t = 0; t < 3; ++t) out[t] = (float)root[t];
  for (t = 0; t < p->T; ++t) {
    double q[4], ci[4];
    int k;
    if (t == 0) {
      memcpy(q, sc->w, sizeof q);
    } else {
      smgb_q_conj(sc->w + 4 * (uint32_t)tgt->parents[t], ci);
      smgb_q_mul(ci, sc->w + 4 * t, q);
    }
    smgb_q_normalize(q);
    for (k = 0; k < 4; ++k) out[3 + 4 * t + k] = (float)q[k];
  }
}

smg_result smgb_retarget_clip(smgb_clip* clip, const smgb_roles* clip_roles,
                              const smgb_skeleton* target,
                              const smgb_roles* target_roles,
                              const char* target_name, smgb_error* err) {
  rt_plan plan;
  rt_scratch sc;
  smgb_skeleton skel;
  float *poses, *fkp, *fkw;
  uint32_t f, T, S;
  smg_result r;
  if (err) err->message[0] = '\0';
  if (!clip || !clip->poses || clip->frame_count == 0 || !target ||
      !clip_roles || !target_roles ||
      target->joint_count == 0 || !target->names || !target->parents ||
      !target->offsets) {
    smgb_imp_errorf(err, "smgb_retarget_clip: invalid clip or target");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (!target_name) target_name = "the target rig";
  r = plan_init(&plan, clip, clip_roles, target, target_roles, target_name,
                err);
  if (r != SMG_OK) return r;
  T = target->joint_count;
  S = clip->skeleton.joint_count;
  memset(&sc, 0, sizeof sc);
  /* the source's forward kinematics once: the alignments are measured on
   * all frames before any frame is retargeted */
  fkp = (float*)malloc(sizeof(float) * 3 * S * (size_t)clip->frame_count);
  fkw = (float*)malloc(sizeof(float) * 4 * S * (size_t)clip->frame_count);
  sc.w = (double*)malloc(sizeof(double) * 4 * T);
  sc.pt = (double*)malloc(sizeof(double) * 3 * T);
  poses = (float*)malloc(sizeof(float) * (size_t)clip->frame_count *
                         SMGB_STRIDE(T));
  memset(&skel, 0, sizeof skel);
  r = SMG_ERROR_OUT_OF_MEMORY;
  if (fkp && fkw && sc.w && sc.pt && poses &&
      smgb_skeleton_copy(target, &skel) == SMG_OK) {
    for (f = 0; f < clip->frame_count; ++f)
      smgb_fk(&clip->skeleton,
              clip->poses + (size_t)f * SMGB_STRIDE(S),
              fkp + (size_t)f * 3 * S, fkw + (size_t)f * 4 * S);
    plan_align(&plan, fkp, fkw, clip->frame_count);
    r = SMG_OK;
  }
  if (r == SMG_OK) {
    for (f = 0; f < clip->frame_count; ++f) {
      float* o = poses + (size_t)f * SMGB_STRIDE(T);
      uint32_t t;
      sc.ps = fkp + (size_t)f * 3 * S;
      sc.ws = fkw + (size_t)f * 4 * S;
      retarget_frame(&plan, target, o, &sc);
      /* keep each joint's quaternion in the previous frame's hemisphere:
       * later stages interpolate neighbouring frames component-wise */
      for (t = 0; f > 0 && t < T; ++t) {
        float* q = o + 3 + 4 * t;
        const float* r = q - SMGB_STRIDE(T);
        if (q[0] * r[0] + q[1] * r[1] + q[2] * r[2] + q[3] * r[3] < 0.0f) {
          q[0] = -q[0]; q[1] = -q[1]; q[2] = -q[2]; q[3] = -q[3];
        }
      }
    }
    smgb_skeleton_free(&clip->skeleton);
    free(clip->poses);
    clip->skeleton = skel;
    clip->poses = poses;
    poses = NULL;
  } else {
    smgb_imp_errorf(err, "%s: out of memory (retarget)", clip->name);
    smgb_skeleton_free(&skel);
  }
  free(poses);
  free(fkp);
  free(fkw);
  free(sc.w);
  free(sc.pt);
  plan_free(&plan);
  return r;
}
