/*
 * eval_splice.c - sections 3 and 4: splicing accuracy like the paper's
 * Fig. 5, and the upper/lower synchronization check.
 *
 * Ground truth: CMU 06_10 (subject 06 walking forward while dribbling).
 * Splice: a blob whose lower (locomotion) graph is the same actor's plain
 * walk 06_01 and whose upper (action) graph is 06_10, baked through
 * smg_bake_run(); the runtime then walks a straight path with a splice to
 * "dribble" at 2 m. The whole pipeline runs (bake, graphs, splice search,
 * Horn correction, runtime search, synchronization, IK).
 *
 * Frame-by-frame comparison: the runtime decides which 06_10 frame its
 * upper body plays (and warps its time), so every output frame is matched
 * to the 06_10 frame whose upper-body joint rotations (all upper joints
 * except the spine base, where the splice correction is applied) are
 * nearest; that frame - interpolated between its neighbours - is the
 * original the spliced spine is compared with.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "eval_ctx.h"
#include "eval_metrics.h"
#include "eval_run.h"
#include "quat_pack.h"
#include "smg_bake.h"
#include "smg_format.h"
#include "svg_plot.h"

#define CMU_UNIT 0.056444f
#define RATE 30.0f
#define PATH_LENGTH 24.0
#define SPLICE_AT 2.0f
#define MAX_MATCH_JOINTS 16
#define SPINE_JOINTS 4
#define MATCH_LIMIT_DEG 6.0 /* mean per-joint angle for a valid match */

static const char* const k_spine_names[SPINE_JOINTS] = {"Spine", "Spine1",
                                                        "Neck1", "Head"};
/* Upper-body joints whose local rotations identify the source frame. */
static const char* const k_match_names[] = {
    "Spine",        "Spine1",       "Neck",     "Neck1",
    "Head",         "LeftShoulder", "LeftArm",  "LeftForeArm",
    "LeftHand",     "RightShoulder", "RightArm", "RightForeArm",
    "RightHand"};
#define MATCH_COUNT (sizeof(k_match_names) / sizeof(k_match_names[0]))

typedef struct splice_blob {
  smg_bake_result bake;
  smgi_graph_data gd;
  smg_graph* graph;
  uint32_t walk, dribble;
  uint32_t upper_first, upper_count; /* the original 06_10 clip's frames */
  float* upper_poses; /* those frames unpacked: SMGI_POSE_FLOATS(J) each */
} splice_blob;

static smg_result bake_splice_blob(eval_ctx* ctx, splice_blob* sb,
                                   char* err, size_t err_size) {
  smg_bake_clip_desc clips[2];
  char p0[1200], p1[1200], why[256];
  smg_bake_desc desc;
  smg_result r;
  uint32_t c;

  memset(sb, 0, sizeof(*sb));
  eval_cmu_clip(ctx, "06_01", p0, sizeof(p0));
  eval_cmu_clip(ctx, "06_10", p1, sizeof(p1));
  memset(clips, 0, sizeof(clips));
  clips[0].struct_size = clips[1].struct_size = sizeof(clips[0]);
  clips[0].role = SMG_BAKE_ROLE_LOWER;
  clips[0].path = p0;
  clips[0].label = "walk";
  clips[0].name = "06_01";
  clips[1].role = SMG_BAKE_ROLE_UPPER;
  clips[1].path = p1;
  clips[1].label = "dribble";
  clips[1].name = "06_10";
  for (c = 0; c < 2; ++c) {
    clips[c].skip_first_frame = 1;
    clips[c].unit_scale = CMU_UNIT;
    clips[c].mirror = SMG_BAKE_MIRROR_NO; /* ground truth stays unmirrored */
  }
  memset(&desc, 0, sizeof(desc));
  desc.struct_size = sizeof(desc);
  desc.clip_count = 2;
  desc.clips = clips;
  desc.options.struct_size = sizeof(desc.options);
  sb->bake.struct_size = sizeof(sb->bake);
  r = smg_bake_run(&desc, &sb->bake);
  if (r != SMG_OK) {
    snprintf(err, err_size, "bake: %s: %s", smg_result_string(r),
             sb->bake.error);
    return r;
  }
  r = smgi_blob_read(sb->bake.blob, sb->bake.blob_size, 0, &sb->gd, why,
                     sizeof(why));
  if (r == SMG_OK)
    r = smg_graph_load_memory(sb->bake.blob, sb->bake.blob_size, NULL,
                              &sb->graph);
  if (r != SMG_OK) {
    snprintf(err, err_size, "blob: %s %s", smg_result_string(r), why);
    return r;
  }
  if (smg_graph_find_style(sb->graph, "walk", &sb->walk) != SMG_OK ||
      smg_graph_find_action(sb->graph, "dribble", &sb->dribble) != SMG_OK) {
    snprintf(err, err_size, "blob lacks style walk / action dribble");
    return SMG_ERROR_NOT_FOUND;
  }
  for (c = 0; c < sb->gd.clip_count; ++c) {
    const smgi_clip* k = &sb->gd.clips[c];
    if ((k->flags & SMGI_CLIP_UPPER) && !(k->flags & SMGI_CLIP_BLEND) &&
        !(k->flags & SMGI_CLIP_MIRROR)) {
      sb->upper_first = k->first_frame;
      sb->upper_count = k->frame_count;
      break;
    }
  }
  if (!sb->upper_count) {
    snprintf(err, err_size, "blob has no original upper clip");
    return SMG_ERROR_NOT_FOUND;
  }
  /* the blob's rotations are packed; the comparisons below want floats */
  sb->upper_poses = (float*)malloc((size_t)sb->upper_count *
                                   SMGI_POSE_FLOATS(sb->gd.joint_count) *
                                   sizeof(float));
  if (!sb->upper_poses) {
    snprintf(err, err_size, "out of memory");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (c = 0; c < sb->upper_count; ++c)
    smgi_pose_unpack(smgi_pose_record(&sb->gd, sb->upper_first + c),
                     sb->gd.joint_count,
                     sb->upper_poses +
                         (size_t)c * SMGI_POSE_FLOATS(sb->gd.joint_count));
  return SMG_OK;
}

static void splice_blob_free(splice_blob* sb) {
  if (sb->graph) smg_graph_destroy(sb->graph);
  free(sb->upper_poses);
  smg_bake_result_free(&sb->bake);
  memset(sb, 0, sizeof(*sb));
}

/* Mean angle (radians) between the match joints' local rotations of an
 * output pose and a blob pose. */
static double pose_distance(const float* out_local, const float* blob_pose,
                            const uint32_t* jm, size_t m) {
  double sum = 0.0;
  size_t k;
  for (k = 0; k < m; ++k) {
    const float* a = out_local + 3 + 4 * jm[k];
    const float* b = blob_pose + 3 + 4 * jm[k];
    double qa[4] = {a[0], a[1], a[2], a[3]}, qb[4] = {b[0], b[1], b[2], b[3]};
    double na = sqrt(qa[0] * qa[0] + qa[1] * qa[1] + qa[2] * qa[2] +
                     qa[3] * qa[3]);
    double nb = sqrt(qb[0] * qb[0] + qb[1] * qb[1] + qb[2] * qb[2] +
                     qb[3] * qb[3]);
    double d = fabs(qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] +
                    qa[3] * qb[3]) / (na * nb);
    sum += 2.0 * acos(d > 1.0 ? 1.0 : d);
  }
  return sum / (double)m;
}

/* Everything measured on the dribble run. */
typedef struct splice_eval {
  size_t frames;          /* output frames */
  size_t switch_frame;    /* first frame with action == dribble */
  size_t first_compared;  /* after the blend-in window */
  double* time;           /* seconds since the switch */
  double* src;            /* matched source frame (fractional, clip-local) */
  double* residual_deg;   /* match residual */
  double* base_deg;       /* spine-base local rotation: output vs original */
  double* err_pelvis;     /* fraction of spine length */
  double* err_ground;
  double* err_pelvis_cm;
  double* err_ground_cm;
  double* joint_cm;       /* per frame, SPINE_JOINTS pelvis-frame then
                             SPINE_JOINTS ground-frame distances, cm */
  double* phase_low;      /* lower-body gait phase from runtime contacts */
  double* phase_up;       /* upper-body source phase (synchronized) */
  double* phase_up_native;/* same source played at its own rate */
  size_t compared, rejected;
  size_t worst;           /* frame of the worst pelvis-frame error */
  double spine_length;
  double clip_phase_period; /* seconds per gait cycle in 06_10 */
  double played_period;     /* mean over compared frames of the 06_10
                               stride (s) holding the matched frame */
  double stride_min, stride_max; /* shortest / longest 06_10 stride (s) */
  double played_rate;       /* mean over compared frames of that stride
                               over the output's stride at the frame: the
                               rate a phase-locked upper body plays at */
  double low_period;        /* seconds per gait cycle of the output */
  double measured_rate;     /* upper source frames per frame-time played */
  double clip_period_baker; /* 06_10 gait period from the blob's contacts */
  double low_period_own;    /* output gait period from own detection */
} splice_eval;

static void splice_eval_free(splice_eval* e) {
  free(e->time);
  free(e->src);
  free(e->residual_deg);
  free(e->base_deg);
  free(e->err_pelvis);
  free(e->err_ground);
  free(e->err_pelvis_cm);
  free(e->err_ground_cm);
  free(e->joint_cm);
  free(e->phase_low);
  free(e->phase_up);
  free(e->phase_up_native);
  memset(e, 0, sizeof(*e));
}

/* FK of a blob pose with the blob skeleton. */
static void blob_fk(const splice_blob* sb, const float* pose, double* pos,
                    double* rot) {
  static int32_t parents[256];
  static float offsets[3 * 256];
  uint32_t j, J = sb->gd.joint_count;
  for (j = 0; j < J && j < 256; ++j) {
    parents[j] = sb->gd.joints[j].parent;
    offsets[3 * j] = sb->gd.joints[j].offset[0];
    offsets[3 * j + 1] = sb->gd.joints[j].offset[1];
    offsets[3 * j + 2] = sb->gd.joints[j].offset[2];
  }
  em_fk(J, parents, offsets, pose, pos, rot);
}

/* Positions of the spine joints in the pelvis frame and in the ground
 * frame, from world positions and the root's world rotation. */
static void spine_frames(const double* pos, const double* root_rot,
                         const uint32_t* spine, double* in_pelvis,
                         double* in_ground) {
  double go[3], gq[4];
  size_t k;
  em_ground_frame(pos, root_rot, go, gq);
  for (k = 0; k < SPINE_JOINTS; ++k) {
    em_to_frame(pos, root_rot, pos + 3 * spine[k], in_pelvis + 3 * k);
    em_to_frame(go, gq, pos + 3 * spine[k], in_ground + 3 * k);
  }
}

/* Gait phase (0 at left foot-strike) of every frame of the original
 * upper clip, from its own left-foot contacts (height + speed detection on
 * the lower of ankle and toe), and the length (s) of the stride holding
 * each frame. NaN outside the detected cycles. */
static int clip_phases(const splice_blob* sb, uint32_t lfoot, uint32_t ltoe,
                       double* out_phase, double* out_stride,
                       double* out_period, double* out_min,
                       double* out_max) {
  uint32_t n = sb->upper_count, J = sb->gd.joint_count, i;
  double* pos = (double*)malloc(3 * (size_t)J * sizeof(double));
  double* low = (double*)malloc(3 * (size_t)n * sizeof(double));
  uint8_t* con = (uint8_t*)malloc(n);
  size_t* falls = (size_t*)malloc(n * sizeof(size_t));
  size_t k;
  if (!pos || !low || !con || !falls) {
    free(pos);
    free(low);
    free(con);
    free(falls);
    return 0;
  }
  for (i = 0; i < n; ++i) {
    const float* pose = sb->upper_poses + (size_t)i * SMGI_POSE_FLOATS(J);
    const double* p;
    blob_fk(sb, pose, pos, NULL);
    p = pos[3 * ltoe + 1] < pos[3 * lfoot + 1] ? pos + 3 * ltoe
                                                : pos + 3 * lfoot;
    memcpy(low + 3 * i, p, 3 * sizeof(double));
  }
  em_detect_contacts(low, n, 1.0 / sb->gd.info->frame_rate, 0.03, 1.0, con);
  k = em_footfalls(con, n, falls, n);
  em_phase_from_footfalls(falls, k, n, out_phase);
  for (i = 0; i < n; ++i) out_stride[i] = NAN;
  *out_min = *out_max = NAN;
  for (i = 0; k > 1 && i + 1 < k; ++i) {
    double len = (double)(falls[i + 1] - falls[i]) / sb->gd.info->frame_rate;
    size_t f;
    for (f = falls[i]; f < falls[i + 1]; ++f) out_stride[f] = len;
    if (!(len >= *out_min)) *out_min = len;
    if (!(len <= *out_max)) *out_max = len;
  }
  *out_period = k > 1 ? (double)(falls[k - 1] - falls[0]) / (double)(k - 1) /
                            sb->gd.info->frame_rate
                      : NAN;
  free(pos);
  free(low);
  free(con);
  free(falls);
  return 1;
}

/* Mean time between rising edges of a contact signal (NAN if < 2). */
static double contact_period(const uint8_t* c, size_t n, double dt) {
  size_t first = n, last = 0, count = 0, i;
  for (i = 1; i < n; ++i)
    if (c[i] && !c[i - 1]) {
      if (first == n) first = i;
      last = i;
      count++;
    }
  return count > 1 ? (double)(last - first) / (double)(count - 1) * dt : NAN;
}

/* Phase at a fractional clip frame (circular interpolation). */
static double phase_at(const double* phase, uint32_t n, double f) {
  long i = (long)floor(f);
  double t = f - (double)i, a, b;
  if (i < 0 || (uint32_t)i >= n) return NAN;
  a = phase[i];
  if ((uint32_t)i + 1 >= n) return a;
  b = phase[i + 1];
  if (!isfinite(a) || !isfinite(b)) return t < 0.5 ? a : b;
  a += t * em_wrap_half(b - a);
  return a - floor(a);
}

static int measure(const splice_blob* sb, const eval_trace* t,
                   splice_eval* e) {
  uint32_t J = sb->gd.joint_count, i, k;
  uint32_t jm[MAX_MATCH_JOINTS], spine[SPINE_JOINTS];
  uint32_t lfoot, ltoe, hips, base;
  size_t F = t->frames, m = 0, f, falls_n, window;
  double *gt_a, *gt_b, *gt_rot_a, *gt_rot_b, *clip_phase, *clip_stride;
  double stride_sum = 0.0, rate_sum = 0.0, *low_stride = NULL;
  size_t stride_n = 0, rate_n = 0;
  uint8_t* lc;
  size_t* falls;
  smg_joint_info ji;
  double worst = -1.0;
  int ok = 0;

  memset(e, 0, sizeof(*e));
  for (i = 0; i < MATCH_COUNT; ++i)
    if (smg_graph_find_joint(sb->graph, k_match_names[i], &jm[m]) == SMG_OK)
      m++;
  for (i = 0; i < SPINE_JOINTS; ++i)
    if (smg_graph_find_joint(sb->graph, k_spine_names[i], &spine[i]) != SMG_OK)
      return 0;
  if (smg_graph_find_joint(sb->graph, "LeftFoot", &lfoot) != SMG_OK ||
      smg_graph_find_joint(sb->graph, "LeftToeBase", &ltoe) != SMG_OK ||
      smg_graph_find_joint(sb->graph, "Hips", &hips) != SMG_OK || hips != 0 ||
      smg_graph_find_joint(sb->graph, "LowerBack", &base) != SMG_OK ||
      m < 8)
    return 0;
  /* Spine length: rest offsets along Hips -> Head. */
  e->spine_length = 0.0;
  {
    uint32_t head = spine[SPINE_JOINTS - 1], j = head;
    while (j != 0) {
      memset(&ji, 0, sizeof(ji));
      ji.struct_size = sizeof(ji);
      if (smg_graph_get_joint(sb->graph, j, &ji) != SMG_OK || ji.parent < 0)
        break;
      e->spine_length += sqrt(ji.rest_offset[0] * ji.rest_offset[0] +
                              ji.rest_offset[1] * ji.rest_offset[1] +
                              ji.rest_offset[2] * ji.rest_offset[2]);
      j = (uint32_t)ji.parent;
    }
  }

  e->frames = F;
  e->time = (double*)malloc(F * sizeof(double));
  e->src = (double*)malloc(F * sizeof(double));
  e->residual_deg = (double*)malloc(F * sizeof(double));
  e->base_deg = (double*)malloc(F * sizeof(double));
  e->err_pelvis = (double*)malloc(F * sizeof(double));
  e->err_ground = (double*)malloc(F * sizeof(double));
  e->err_pelvis_cm = (double*)malloc(F * sizeof(double));
  e->err_ground_cm = (double*)malloc(F * sizeof(double));
  e->joint_cm = (double*)malloc(F * 2 * SPINE_JOINTS * sizeof(double));
  e->phase_low = (double*)malloc(F * sizeof(double));
  e->phase_up = (double*)malloc(F * sizeof(double));
  e->phase_up_native = (double*)malloc(F * sizeof(double));
  gt_a = (double*)malloc(3 * (size_t)J * sizeof(double));
  gt_b = (double*)malloc(3 * (size_t)J * sizeof(double));
  gt_rot_a = (double*)malloc(4 * (size_t)J * sizeof(double));
  gt_rot_b = (double*)malloc(4 * (size_t)J * sizeof(double));
  clip_phase = (double*)malloc(sb->upper_count * sizeof(double));
  clip_stride = (double*)malloc(sb->upper_count * sizeof(double));
  lc = (uint8_t*)malloc(F);
  falls = (size_t*)malloc(F * sizeof(size_t));
  if (!e->time || !e->src || !e->residual_deg || !e->base_deg || !e->err_pelvis ||
      !e->err_ground || !e->err_pelvis_cm || !e->err_ground_cm ||
      !e->joint_cm ||
      !e->phase_low || !e->phase_up || !e->phase_up_native || !gt_a ||
      !gt_b || !gt_rot_a || !gt_rot_b || !clip_phase || !clip_stride || !lc ||
      !falls)
    goto out;
  if (!clip_phases(sb, lfoot, ltoe, clip_phase, clip_stride,
                   &e->clip_phase_period, &e->stride_min, &e->stride_max))
    goto out;

  /* Cross-checks of both periods from a second contact source: the
   * baker's per-frame labels for the clip, own detection for the output. */
  {
    uint8_t* c = (uint8_t*)malloc(sb->upper_count > F ? sb->upper_count : F);
    double* low = (double*)malloc(3 * F * sizeof(double));
    if (c && low) {
      for (i = 0; i < sb->upper_count; ++i)
        c[i] = (sb->gd.frames[sb->upper_first + i].flags &
                SMGI_FRAME_LEFT_CONTACT) != 0;
      e->clip_period_baker = contact_period(c, sb->upper_count,
                                            1.0 / sb->gd.info->frame_rate);
      for (f = 0; f < F; ++f) {
        const double* a = eval_joint(t, f, lfoot);
        const double* b = eval_joint(t, f, ltoe);
        memcpy(low + 3 * f, b[1] < a[1] ? b : a, 3 * sizeof(double));
      }
      em_detect_contacts(low, F, t->dt, 0.03, 1.0, c);
      e->low_period_own = contact_period(c, F, t->dt);
    } else {
      e->clip_period_baker = e->low_period_own = NAN;
    }
    free(c);
    free(low);
  }
  e->switch_frame = em_first_label(t->action, F, 0, sb->dribble);
  window = (size_t)ceil(sb->gd.info->window_seconds * RATE);
  e->first_compared = e->switch_frame + window;
  for (f = 0; f < F; ++f) {
    e->time[f] = ((double)f - (double)e->switch_frame) * t->dt;
    e->src[f] = e->residual_deg[f] = e->base_deg[f] = NAN;
    e->err_pelvis[f] = e->err_ground[f] = NAN;
    e->err_pelvis_cm[f] = e->err_ground_cm[f] = NAN;
    e->phase_up[f] = e->phase_up_native[f] = NAN;
    lc[f] = (t->flags[f] & SMG_STATE_LEFT_CONTACT) != 0;
  }
  falls_n = em_footfalls(lc, F, falls, F);
  em_phase_from_footfalls(falls, falls_n, F, e->phase_low);
  e->low_period = falls_n > 1 ? (double)(falls[falls_n - 1] - falls[0]) /
                                    (double)(falls_n - 1) * t->dt
                              : NAN;
  /* the output's stride (s) holding each frame */
  low_stride = (double*)malloc(F * sizeof(double));
  if (!low_stride) goto out;
  for (f = 0; f < F; ++f) low_stride[f] = NAN;
  for (k = 0; falls_n > 1 && k + 1 < falls_n; ++k) {
    size_t q;
    for (q = falls[k]; q < falls[k + 1]; ++q)
      low_stride[q] = (double)(falls[k + 1] - falls[k]) * t->dt;
  }

  for (f = e->first_compared; f < F; ++f) {
    const float* out = t->local + f * (3 + 4 * (size_t)J);
    double best = INFINITY, dm = NAN, dp = NAN, frac = 0.0, src;
    uint32_t bi = 0;
    double op[3 * SPINE_JOINTS], og[3 * SPINE_JOINTS];
    double ap[3 * SPINE_JOINTS], ag[3 * SPINE_JOINTS];
    double bp[3 * SPINE_JOINTS], bg[3 * SPINE_JOINTS];
    double gp[3 * SPINE_JOINTS], gg[3 * SPINE_JOINTS];
    const float* pose_a;
    uint32_t next;
    if (t->action[f] != sb->dribble) continue;
    for (i = 0; i < sb->upper_count; ++i) {
      const float* p = sb->upper_poses + (size_t)i * SMGI_POSE_FLOATS(J);
      double d = pose_distance(out, p, jm, m);
      if (d < best) best = d, bi = i;
    }
    /* Sub-frame position of the match: a parabola through the residuals
     * of the best frame and its neighbours. */
    if (bi > 0)
      dm = pose_distance(
          out, sb->upper_poses + (size_t)(bi - 1) * SMGI_POSE_FLOATS(J), jm,
          m);
    if (bi + 1 < sb->upper_count)
      dp = pose_distance(
          out, sb->upper_poses + (size_t)(bi + 1) * SMGI_POSE_FLOATS(J), jm,
          m);
    if (isfinite(dm) && isfinite(dp) && dm + dp - 2.0 * best > 1e-12) {
      frac = 0.5 * (dm - dp) / (dm + dp - 2.0 * best);
      if (frac > 0.5) frac = 0.5;
      if (frac < -0.5) frac = -0.5;
    }
    src = (double)bi + frac;
    e->residual_deg[f] = best * 180.0 / 3.14159265358979323846;
    if (e->residual_deg[f] > MATCH_LIMIT_DEG) {
      e->rejected++;
      continue;
    }
    e->src[f] = src;
    /* How far the splice turned the spine base (LowerBack) away from the
     * original's, at the best whole frame: the Horn correction at work. */
    {
      const float* ob = out + 3 + 4 * base;
      const float* gb = sb->upper_poses + (size_t)bi * SMGI_POSE_FLOATS(J) +
                        3 + 4 * base;
      double qa[4] = {ob[0], ob[1], ob[2], ob[3]};
      double qb[4] = {gb[0], gb[1], gb[2], gb[3]};
      double na = sqrt(qa[0] * qa[0] + qa[1] * qa[1] + qa[2] * qa[2] +
                       qa[3] * qa[3]);
      double nb = sqrt(qb[0] * qb[0] + qb[1] * qb[1] + qb[2] * qb[2] +
                       qb[3] * qb[3]);
      for (k = 0; k < 4; ++k) qa[k] /= na, qb[k] /= nb;
      e->base_deg[f] = em_quat_angle(qa, qb) * 180.0 / 3.14159265358979323846;
    }
    /* Ground truth between frames floor(src) and floor(src) + 1. */
    if (src < 0.0) src = 0.0;
    i = (uint32_t)floor(src);
    frac = src - (double)i;
    next = i + 1 < sb->upper_count ? i + 1 : i;
    pose_a = sb->upper_poses + (size_t)i * SMGI_POSE_FLOATS(J);
    blob_fk(sb, pose_a, gt_a, gt_rot_a);
    blob_fk(sb, sb->upper_poses + (size_t)next * SMGI_POSE_FLOATS(J), gt_b,
            gt_rot_b);
    spine_frames(gt_a, gt_rot_a, spine, ap, ag);
    spine_frames(gt_b, gt_rot_b, spine, bp, bg);
    for (k = 0; k < 3 * SPINE_JOINTS; ++k) {
      gp[k] = ap[k] + frac * (bp[k] - ap[k]);
      gg[k] = ag[k] + frac * (bg[k] - ag[k]);
    }
    spine_frames(t->joints + f * 3 * (size_t)J, t->root_rot + 4 * f, spine,
                 op, og);
    e->err_pelvis[f] = em_mean_joint_error(op, gp, SPINE_JOINTS,
                                           e->spine_length);
    e->err_ground[f] = em_mean_joint_error(og, gg, SPINE_JOINTS,
                                           e->spine_length);
    e->err_pelvis_cm[f] = 100.0 * e->err_pelvis[f] * e->spine_length;
    e->err_ground_cm[f] = 100.0 * e->err_ground[f] * e->spine_length;
    for (k = 0; k < SPINE_JOINTS; ++k) {
      double* jc = e->joint_cm + f * 2 * SPINE_JOINTS;
      jc[k] = 100.0 * em_mean_joint_error(op + 3 * k, gp + 3 * k, 1, 1.0);
      jc[SPINE_JOINTS + k] =
          100.0 * em_mean_joint_error(og + 3 * k, gg + 3 * k, 1, 1.0);
    }
    e->phase_up[f] = phase_at(clip_phase, sb->upper_count, e->src[f]);
    if (isfinite(clip_stride[i])) {
      stride_sum += clip_stride[i];
      stride_n++;
      if (isfinite(low_stride[f])) {
        rate_sum += clip_stride[i] / low_stride[f];
        rate_n++;
      }
    }
    e->compared++;
    if (e->err_pelvis[f] > worst) worst = e->err_pelvis[f], e->worst = f;
  }
  e->played_period = stride_n ? stride_sum / (double)stride_n : NAN;
  e->played_rate = rate_n ? rate_sum / (double)rate_n : NAN;
  /* The unsynchronized counterfactual: from the first matched frame on,
   * the upper body's phase advances at the clip's own gait rate (one
   * cycle per clip_phase_period), whatever the lower body does. */
  for (f = e->first_compared; f < F; ++f)
    if (isfinite(e->phase_up[f])) break;
  if (f < F && isfinite(e->clip_phase_period) && e->clip_phase_period > 0) {
    size_t f0 = f;
    for (f = f0; f < F; ++f) {
      double ph = e->phase_up[f0] + (double)(f - f0) * t->dt /
                                        e->clip_phase_period;
      e->phase_up_native[f] = ph - floor(ph);
    }
  }
  /* The upper body's measured playback rate: source frames advanced per
   * output frame (median of steps inside one continuous stretch). */
  {
    double* inc = (double*)malloc(F * sizeof(double));
    double* scratch = (double*)malloc(F * sizeof(double));
    size_t q = 0;
    em_stats st;
    e->measured_rate = NAN;
    if (inc && scratch) {
      for (f = e->first_compared + 1; f < F; ++f)
        if (isfinite(e->src[f]) && isfinite(e->src[f - 1])) {
          double d = e->src[f] - e->src[f - 1];
          if (d > -0.5 && d < 3.0) inc[q++] = d; /* skip graph jumps */
        }
      em_stats_compute(inc, q, scratch, &st);
      e->measured_rate = st.mean / (t->dt * sb->gd.info->frame_rate);
    }
    free(inc);
    free(scratch);
  }
  ok = e->compared > 0;
out:
  free(gt_a);
  free(gt_b);
  free(gt_rot_a);
  free(gt_rot_b);
  free(clip_phase);
  free(clip_stride);
  free(low_stride);
  free(lc);
  free(falls);
  return ok;
}

/* ---- figures ------------------------------------------------------------ */

static void figure_error(eval_ctx* ctx, const splice_eval* e) {
  svp_figure* fig = svp_create(760, 380,
                               "Spine error, spliced vs original 06_10 "
                               "(dribbling walk)");
  double* yp = (double*)malloc(e->frames * sizeof(double));
  double* yg = (double*)malloc(e->frames * sizeof(double));
  char full[1400];
  size_t f;
  if (!fig || !yp || !yg) goto done;
  for (f = 0; f < e->frames; ++f) {
    yp[f] = 100.0 * e->err_pelvis[f];
    yg[f] = 100.0 * e->err_ground[f];
  }
  svp_set_labels(fig, "time since the splice (s)",
                 "mean spine-joint error (% of spine length)");
  svp_line(fig, e->time, yp, e->frames, "#d62728", 1.8, 0,
           "in the pelvis frame");
  svp_line(fig, e->time, yg, e->frames, "#1f5fd6", 1.8, 1,
           "in the ground (heading) frame");
  svp_marker(fig, e->time[e->worst], yp[e->worst], SVP_CIRCLE, "#d62728",
             4.0, "worst");
  eval_img_path(ctx, "eval-splice-error.svg", full, sizeof(full));
  if (svp_write(fig, full) == 0)
    eval_md(ctx, "![spine error over time](%s/eval-splice-error.svg)\n\n",
            ctx->img_rel);
done:
  svp_destroy(fig);
  free(yp);
  free(yg);
}

/* Side and front views of the two skeletons at the worst frame, both in
 * their own ground frame (root on the floor origin, facing +z). */
static void figure_worst(eval_ctx* ctx, const splice_blob* sb,
                         const eval_trace* t, const splice_eval* e) {
  uint32_t J = sb->gd.joint_count, j, view;
  double *a = NULL, *ar = NULL, *b = NULL, *la = NULL, *lb = NULL;
  double go[3], gq[4];
  svp_figure* fig = NULL;
  char full[1400], title[160];
  const double shift = 1.0; /* front view drawn beside the side view */
  size_t f = e->worst;
  double src = e->src[f];
  a = (double*)malloc(3 * (size_t)J * sizeof(double));
  ar = (double*)malloc(4 * (size_t)J * sizeof(double));
  b = (double*)malloc(3 * (size_t)J * sizeof(double));
  la = (double*)malloc(3 * (size_t)J * sizeof(double));
  lb = (double*)malloc(3 * (size_t)J * sizeof(double));
  snprintf(title, sizeof(title),
           "Worst frame (t = %.2f s, source frame %.1f): side | front",
           e->time[f], src);
  fig = svp_create(760, 520, title);
  if (!a || !ar || !b || !la || !lb || !fig || !isfinite(src)) goto done;
  /* Original: the matched 06_10 frame (nearest whole frame). */
  blob_fk(sb,
          sb->upper_poses +
              (size_t)(uint32_t)(src + 0.5) * SMGI_POSE_FLOATS(J),
          a, ar);
  em_ground_frame(a, ar, go, gq);
  for (j = 0; j < J; ++j) em_to_frame(go, gq, a + 3 * j, la + 3 * j);
  em_ground_frame(t->joints + f * 3 * (size_t)J, t->root_rot + 4 * f, go, gq);
  for (j = 0; j < J; ++j)
    em_to_frame(go, gq, t->joints + (f * J + j) * 3, lb + 3 * j);
  svp_set_labels(fig, "side view: forward (m)  |  front view: sideways (m)",
                 "height (m)");
  svp_set_equal_aspect(fig, 1);
  svp_set_range(fig, -0.7, 2.0, -0.1, 2.2);
  for (view = 0; view < 2; ++view) {
    for (j = 1; j < J; ++j) {
      int32_t p = sb->gd.joints[j].parent;
      double x[2], y[2];
      uint32_t s;
      for (s = 0; s < 2; ++s) {
        const double* L = s ? lb : la;
        /* Front view seen from ahead: the character's left (+x) is on
         * the viewer's right. */
        x[0] = view ? shift + L[3 * p] : L[3 * p + 2];
        x[1] = view ? shift + L[3 * j] : L[3 * j + 2];
        y[0] = L[3 * p + 1];
        y[1] = L[3 * j + 1];
        svp_line(fig, x, y, 2, s ? "#d62728" : "#222222", s ? 2.0 : 3.5, 0,
                 (j == 1 && view == 0) ? (s ? "spliced (06_01 legs + 06_10 "
                                              "upper body)"
                                            : "original 06_10")
                                       : NULL);
      }
    }
  }
  svp_text(fig, -0.45, 1.65, "side (facing right)", "#444");
  svp_text(fig, shift - 0.35, 1.65, "front (facing the viewer)", "#444");
  eval_img_path(ctx, "eval-splice-worst.svg", full, sizeof(full));
  if (svp_write(fig, full) == 0)
    eval_md(ctx, "![skeletons at the worst frame](%s/eval-splice-worst.svg)"
                 "\n\n", ctx->img_rel);
done:
  svp_destroy(fig);
  free(a);
  free(ar);
  free(b);
  free(la);
  free(lb);
}

/* Phase differences (cycles) upper - lower, raw (wrapped). */
static void phase_diffs(const splice_eval* e, const double* up, double* out) {
  size_t f;
  for (f = 0; f < e->frames; ++f)
    out[f] = (isfinite(up[f]) && isfinite(e->phase_low[f]))
                 ? em_wrap_half(up[f] - e->phase_low[f])
                 : NAN;
}

typedef struct sync_numbers {
  double mean, sd, drift, corr;
  size_t count;
  double foot_mean, foot_sd; /* phase difference at lower footfalls */
  size_t foot_count;
} sync_numbers;

static void sync_stats(const splice_eval* e, const double* up,
                       const eval_trace* t, sync_numbers* s, double* diff,
                       double* unwrapped) {
  double* cu = (double*)malloc(e->frames * sizeof(double));
  double* cl = (double*)malloc(e->frames * sizeof(double));
  size_t f;
  (void)t;
  phase_diffs(e, up, diff);
  s->count = em_circular_stats(diff, e->frames, &s->mean, &s->sd);
  em_unwrap(diff, e->frames, unwrapped);
  s->drift = em_linear_slope(e->time, unwrapped, e->frames, NULL);
  s->corr = NAN;
  s->foot_count = 0;
  s->foot_mean = s->foot_sd = NAN;
  if (cu) {
    size_t q = 0;
    for (f = 1; f < e->frames; ++f)
      if (e->phase_low[f] == 0.0 && isfinite(diff[f])) cu[q++] = diff[f];
    s->foot_count = em_circular_stats(cu, q, &s->foot_mean, &s->foot_sd);
  }
  if (cu && cl) {
    for (f = 0; f < e->frames; ++f) {
      cu[f] = isfinite(up[f]) ? cos(2.0 * 3.14159265358979323846 * up[f])
                              : NAN;
      cl[f] = isfinite(e->phase_low[f])
                  ? cos(2.0 * 3.14159265358979323846 * e->phase_low[f])
                  : NAN;
      if (!isfinite(diff[f])) cu[f] = cl[f] = NAN;
    }
    s->corr = em_pearson(cu, cl, e->frames);
  }
  free(cu);
  free(cl);
}

static void section_sync(eval_ctx* ctx, const eval_trace* t,
                         const splice_eval* e, uint32_t dribble) {
  double *d_after = NULL, *d_before = NULL, *u_after = NULL,
         *u_before = NULL;
  sync_numbers after, before;
  svp_figure* fig = NULL;
  char full[1400], a[32], b[32], c[32], d[32], x[32], y[32], z[32], p[32],
      r[32], s1[32], s2[32];
  double rate_sum = 0.0;
  size_t f, rate_n = 0;

  d_after = (double*)malloc(e->frames * sizeof(double));
  d_before = (double*)malloc(e->frames * sizeof(double));
  u_after = (double*)malloc(e->frames * sizeof(double));
  u_before = (double*)malloc(e->frames * sizeof(double));
  if (!d_after || !d_before || !u_after || !u_before) goto done;
  sync_stats(e, e->phase_up, t, &after, d_after, u_after);
  sync_stats(e, e->phase_up_native, t, &before, d_before, u_before);
  for (f = e->first_compared; f < e->frames; ++f)
    if (t->action[f] == dribble && isfinite(t->sync_rate[f])) {
      rate_sum += t->sync_rate[f];
      rate_n++;
    }
  if (ctx->check) {
    eval_check(ctx, after.count > 30 && fabs(after.drift) < 0.1,
               "sync: phase drift after synchronization %.3f cycles/s over "
               "%zu frames (bound 0.1)", after.drift, after.count);
    goto done;
  }
  eval_md(ctx,
          "## 4. Synchronization of upper and lower body\n\n"
          "Same run as section 3. **Lower-body phase**: from the runtime's "
          "left-foot contact flags, 0 at each left footfall, linear in time "
          "to the next. **Upper-body phase**: the gait phase of the matched "
          "06_10 source frame in the original clip (its own left footfalls, "
          "detected from the lower of ankle/toe: within 3 cm of the lowest "
          "height and slower than 1 m/s), i.e. where in the dribbler's step "
          "cycle the spliced upper body is. **After** = what the runtime "
          "played (time-warped by the synchronization). **Before** = the "
          "same starting phase advancing at the dribble clip's own gait "
          "rate (one cycle per 06_10 gait period): what the upper body "
          "would do without synchronization. A velocity differential "
          "between the halves shows up as a phase difference that drifts "
          "over time; synchronized halves keep it constant.\n\n"
          "| | before (native rate) | after (runtime) |\n|---|---:|---:|\n"
          "| frames with both phases | %zu | %zu |\n"
          "| phase drift, upper - lower (cycles/s; least-squares slope of "
          "the unwrapped difference) | %s | %s |\n"
          "| mean phase difference (cycles, circular) | %s | %s |\n",
          before.count, after.count,
          eval_fmt(a, sizeof(a), "%+.3f", before.drift),
          eval_fmt(b, sizeof(b), "%+.3f", after.drift),
          eval_fmt(c, sizeof(c), "%+.3f", before.mean),
          eval_fmt(d, sizeof(d), "%+.3f", after.mean));
  eval_md(ctx,
          "| circular std of the phase difference (cycles) | %s | %s |\n"
          "| correlation of cos(2 pi phase), upper vs lower | %s | %s |\n",
          eval_fmt(a, sizeof(a), "%.3f", before.sd),
          eval_fmt(b, sizeof(b), "%.3f", after.sd),
          eval_fmt(c, sizeof(c), "%.2f", before.corr),
          eval_fmt(d, sizeof(d), "%.2f", after.corr));
  eval_md(ctx,
          "| upper-body phase at the lower body's left footfalls: count, "
          "circular mean / std (cycles) | %zu, %s / %s | %zu, %s / %s |\n\n",
          before.foot_count, eval_fmt(a, sizeof(a), "%+.3f", before.foot_mean),
          eval_fmt(b, sizeof(b), "%.3f", before.foot_sd), after.foot_count,
          eval_fmt(c, sizeof(c), "%+.3f", after.foot_mean),
          eval_fmt(d, sizeof(d), "%.3f", after.foot_sd));
  eval_md(ctx,
          "Gait period of the output's lower body (06_01 walk, runtime "
          "contact flags): %s s (own detection on the output: %s s); gait "
          "period of the dribble clip 06_10: %s s (from the baker's contact "
          "labels: %s s); so synchronization should play the upper body at "
          "about %s x its own speed. But the 06_10 strides vary (detected: "
          "%s to %s s) and the action graph plays only part of the clip: "
          "the strides holding the source frames actually played last %s "
          "s on average (mean over the compared frames of the detected "
          "stride holding the matched frame); over the output's stride at "
          "each frame (the legs' strides vary too: steering slows the "
          "playback where the path turns and at its end), a phase-locked "
          "upper body plays at %s x on average. "
          "Mean `sync_rate` the runtime reported while "
          "dribbling: %s; upper-body playback rate measured from the "
          "matched source frames (mean source-frame advance per output "
          "frame, graph jumps excluded): %s.\n\n",
          eval_fmt(a, sizeof(a), "%.3f", e->low_period),
          eval_fmt(y, sizeof(y), "%.3f", e->low_period_own),
          eval_fmt(b, sizeof(b), "%.3f", e->clip_phase_period),
          eval_fmt(z, sizeof(z), "%.3f", e->clip_period_baker),
          eval_fmt(c, sizeof(c), "%.3f",
                   e->clip_phase_period / e->low_period),
          eval_fmt(s1, sizeof(s1), "%.3f", e->stride_min),
          eval_fmt(s2, sizeof(s2), "%.3f", e->stride_max),
          eval_fmt(p, sizeof(p), "%.3f", e->played_period),
          eval_fmt(r, sizeof(r), "%.3f", e->played_rate),
          eval_fmt(d, sizeof(d), "%.3f",
                   rate_n ? rate_sum / (double)rate_n : NAN),
          eval_fmt(x, sizeof(x), "%.3f", e->measured_rate));
  eval_summary(ctx,
               "**Synchronization**: phase drift of the upper body against "
               "the lower body %+.3f cycles/s without synchronization, "
               "%+.3f cycles/s as played by the runtime (0 = no velocity "
               "differential); upper-body phase at the legs' left footfalls "
               "scattered by %.3f cycles (circular std); the strides of the "
               "source frames played call for an upper-body playback rate "
               "of %.3f (the whole 06_10 clip's mean stride: %.3f), the "
               "runtime played it at %.3f (measured).",
               before.drift, after.drift, after.foot_sd,
               e->played_rate, e->clip_phase_period / e->low_period,
               e->measured_rate);
  fig = svp_create(760, 380,
                   "Upper-body phase minus lower-body phase (unwrapped)");
  if (!fig) goto done;
  svp_set_labels(fig, "time since the splice (s)", "phase difference (cycles)");
  svp_line(fig, e->time, u_before, e->frames, "#999999", 1.8, 1,
           "before: upper body at its own gait rate");
  svp_line(fig, e->time, u_after, e->frames, "#d62728", 2.0, 0,
           "after: libsmg runtime (synchronized)");
  /* The lower body's left footfalls: where the phase difference is read
   * as "upper-body phase at each footfall". */
  {
    double* fx = (double*)malloc(e->frames * sizeof(double));
    double* fy = (double*)malloc(e->frames * sizeof(double));
    size_t q = 0;
    if (fx && fy) {
      for (f = 1; f < e->frames; ++f)
        if (e->phase_low[f] == 0.0 && isfinite(u_after[f])) {
          fx[q] = e->time[f];
          fy[q] = u_after[f];
          q++;
        }
      svp_scatter(fig, fx, fy, q, SVP_SQUARE, "#6a3d9a", 3.0,
                  "lower-body left footfall");
    }
    free(fx);
    free(fy);
  }
  eval_img_path(ctx, "eval-sync-phase.svg", full, sizeof(full));
  if (svp_write(fig, full) == 0)
    eval_md(ctx, "![phase difference over time](%s/eval-sync-phase.svg)\n\n",
            ctx->img_rel);
done:
  svp_destroy(fig);
  free(d_after);
  free(d_before);
  free(u_after);
  free(u_before);
}

/* Mean and worst distance of each compared joint from the original, in
 * both frames: where along the spine the error is. */
static void per_joint_table(eval_ctx* ctx, const splice_eval* e) {
  double* v = (double*)malloc(e->frames * sizeof(double));
  double* scratch = (double*)malloc(e->frames * sizeof(double));
  size_t f, k, w;
  if (!v || !scratch) {
    free(v);
    free(scratch);
    return;
  }
  eval_md(ctx, "Per joint (distance from the original, cm):\n\n"
               "| joint | pelvis frame mean / worst | ground frame mean / "
               "worst |\n|---|---:|---:|\n");
  for (k = 0; k < SPINE_JOINTS; ++k) {
    em_stats st[2];
    char a[24], b[24], c[24], d[24];
    for (w = 0; w < 2; ++w) {
      for (f = 0; f < e->frames; ++f)
        v[f] = isnan(e->err_pelvis[f])
                   ? NAN
                   : e->joint_cm[f * 2 * SPINE_JOINTS + w * SPINE_JOINTS + k];
      em_stats_compute(v, e->frames, scratch, &st[w]);
    }
    eval_md(ctx, "| %s | %s / %s | %s / %s |\n", k_spine_names[k],
            eval_fmt(a, sizeof a, "%.2f", st[0].mean),
            eval_fmt(b, sizeof b, "%.2f", st[0].max),
            eval_fmt(c, sizeof c, "%.2f", st[1].mean),
            eval_fmt(d, sizeof d, "%.2f", st[1].max));
  }
  eval_md(ctx, "\n");
  free(v);
  free(scratch);
}

void eval_section_splice(eval_ctx* ctx) {
  splice_blob sb;
  eval_trace t;
  splice_eval e;
  eval_run_desc rd;
  eval_constraint con;
  static double path[2 * 1024];
  static float pathf[2 * 1024];
  char err[600];
  size_t n, i;
  smg_result r;

  if (!ctx->have_cmu) {
    eval_md(ctx, "## 3. Splicing accuracy\n\nNot produced: the CMU clips "
                 "are not at `%s`.\n\n## 4. Synchronization\n\nNot "
                 "produced: needs the CMU clips.\n\n", ctx->cmu_dir);
    if (ctx->check) printf("SKIP CMU splicing accuracy: no clips\n");
    return;
  }
  eval_log("baking 06_01 (walk) + 06_10 (dribble)...");
  r = bake_splice_blob(ctx, &sb, err, sizeof(err));
  if (r != SMG_OK) {
    eval_md(ctx, "## 3. Splicing accuracy\n\nNot produced in this run: %s"
                 "\n\n## 4. Synchronization\n\nNot produced: the splice blob "
                 "failed (above).\n\n", err);
    eval_check(ctx, 0, "splice blob: %s", err);
    splice_blob_free(&sb);
    return;
  }
  if (ctx->keep_dir) {
    char kp[1200], why[256];
    snprintf(kp, sizeof(kp), "%s/splice-dribble.smg", ctx->keep_dir);
    if (smg_bake_write_file(&sb.bake, kp, why, sizeof(why)) != SMG_OK)
      eval_log("cannot keep %s: %s", kp, why);
  }
  n = em_path_straight(PATH_LENGTH, 0.1, path, 1024);
  for (i = 0; i < 2 * n; ++i) pathf[i] = (float)path[i];
  con.kind = EVAL_KIND_SPLICE;
  con.arc = SPLICE_AT;
  con.value = sb.dribble;
  memset(&rd, 0, sizeof(rd));
  rd.path_xz = pathf;
  rd.path_count = (uint32_t)n;
  rd.constraints = &con;
  rd.constraint_count = 1;
  rd.initial_style = sb.walk;
  rd.rate = RATE;
  rd.max_seconds = (float)(PATH_LENGTH / 0.6);
  rd.extra_seconds = 0.0f;
  eval_log("running the dribble splice on a %.0f m straight path...",
           PATH_LENGTH);
  r = eval_run(sb.graph, &rd, &t, err, sizeof(err));
  if (r != SMG_OK) {
    eval_md(ctx, "## 3. Splicing accuracy\n\nThe runtime failed in this "
                 "run: %s\n\n## 4. Synchronization\n\nNot produced.\n\n",
            err);
    eval_check(ctx, 0, "dribble run: %s", err);
    splice_blob_free(&sb);
    return;
  }
  if (!measure(&sb, &t, &e)) {
    eval_md(ctx, "## 3. Splicing accuracy\n\nNot produced in this run: the "
                 "character never played a matchable dribble frame (switch "
                 "frame %zu of %zu, %zu rejected matches).\n\n"
                 "## 4. Synchronization\n\nNot produced.\n\n",
            e.switch_frame, t.frames, e.rejected);
    eval_check(ctx, 0, "dribble splice produced comparable frames");
    splice_eval_free(&e);
    eval_trace_free(&t);
    splice_blob_free(&sb);
    return;
  }
  {
    double* scratch = (double*)malloc(e.frames * sizeof(double));
    em_stats sp, sg, spc, sgc, res, bas;
    if (scratch) {
      em_stats_compute(e.err_pelvis, e.frames, scratch, &sp);
      em_stats_compute(e.err_ground, e.frames, scratch, &sg);
      em_stats_compute(e.err_pelvis_cm, e.frames, scratch, &spc);
      em_stats_compute(e.err_ground_cm, e.frames, scratch, &sgc);
      em_stats_compute(e.residual_deg, e.frames, scratch, &res);
      em_stats_compute(e.base_deg, e.frames, scratch, &bas);
      free(scratch);
      if (ctx->check) {
        eval_check(ctx, sp.count > 30 && sp.mean < 0.15,
                   "splice accuracy: mean spine error %.1f %% of spine "
                   "length over %zu frames (bound 15 %%)",
                   100.0 * sp.mean, sp.count);
      } else {
        eval_md(ctx,
                "## 3. Splicing accuracy (paper Fig. 5)\n\n"
                "Ground truth: CMU **06_10** (subject 06 dribbling a "
                "basketball while walking; stands in for the paper's "
                "\"carry\"). Spliced: a blob baked with `smg_bake_run()` "
                "whose lower graph is the same actor's plain walk **06_01** "
                "(`walk`) and whose upper graph is 06_10 (`dribble`), "
                "neither mirrored; the runtime walks a %.0f m straight path "
                "and a splice point switches the upper body to `dribble` at "
                "%.0f m - the whole pipeline (graphs, splice candidates, "
                "Horn correction, search, synchronization, foot IK). Each "
                "output frame from the end of the blend-in window (%.2f s "
                "after the switch) on is matched to the 06_10 frame whose "
                "local rotations of the 13 upper-body joints above the "
                "spine base are nearest (mean angle; sub-frame position by "
                "a parabola through the neighbours); matches worse than "
                "%.0f deg per joint (inside an upper-graph transition blend, "
                "where no single original frame exists) are not compared. "
                "Joints compared: **Spine, Spine1, Neck1, Head** (LowerBack "
                "and Neck have zero offsets in the CMU skeleton and coincide "
                "with Hips and Spine1). Error of a frame = mean over those "
                "4 joints of the Euclidean distance between spliced and "
                "original position, **divided by the spine length** (rest "
                "Hips->Head = %.1f cm), positions taken (a) in the pelvis "
                "frame (Hips position and rotation) and (b) in the ground "
                "frame (Hips projected on the floor, heading of the Hips' "
                "forward axis), which also counts the pelvis tilt and twist "
                "the lower body brings.\n\n"
                "| | pelvis frame | ground frame |\n|---|---:|---:|\n"
                "| frames compared (rejected) | %zu (%zu) | %zu |\n"
                "| mean error, %% of spine length | %.2f | %.2f |\n"
                "| worst error, %% of spine length | %.2f | %.2f |\n"
                "| mean / worst error, cm | %.2f / %.2f | %.2f / %.2f |\n"
                "| match residual mean / max (deg per joint) | %.2f / %.2f | "
                "|\n"
                "| spine-base (LowerBack) rotation vs the original's, mean / "
                "max (deg) | %.2f / %.2f | |\n\n"
                "The pelvis-frame error comes from the spine base: every "
                "joint above it is copied from the source frame, so the "
                "last row (the rotation the splice applies there, i.e. the "
                "Horn correction plus any blending) is what moves the spine "
                "away from the original relative to the pelvis.\n\n",
                PATH_LENGTH, (double)SPLICE_AT,
                sb.gd.info->window_seconds, MATCH_LIMIT_DEG,
                100.0 * e.spine_length, sp.count, e.rejected, sg.count,
                100.0 * sp.mean, 100.0 * sg.mean, 100.0 * sp.max,
                100.0 * sg.max, spc.mean, spc.max, sgc.mean, sgc.max,
                res.mean, res.max, bas.mean, bas.max);
        eval_summary(ctx,
                     "**Splicing accuracy** (06_01 walk legs + 06_10 "
                     "dribbling upper body vs the original 06_10, %zu "
                     "frames): spine error mean %.1f %% / worst %.1f %% of "
                     "the spine length in the pelvis frame (%.1f / %.1f cm); "
                     "in the ground frame mean %.1f %% / worst %.1f %%.",
                     sp.count, 100.0 * sp.mean, 100.0 * sp.max, spc.mean,
                     spc.max, 100.0 * sg.mean, 100.0 * sg.max);
        per_joint_table(ctx, &e);
        figure_error(ctx, &e);
        figure_worst(ctx, &sb, &t, &e);
      }
    }
  }
  section_sync(ctx, &t, &e, sb.dribble);
  splice_eval_free(&e);
  eval_trace_free(&t);
  splice_blob_free(&sb);
}
