/*
 * test_retarget_twist.c - retargeting (bake_retarget.c) puts the twist
 * about every bone in the target rig's convention, whatever the source
 * rig's joints' local axes are:
 *   - the same motion on source skeletons that differ only in their
 *     joints' local axes (bones along local x as in Bandai Namco's BVH,
 *     arbitrary rest rotations as in glTF/FBX rigs) gives the same local
 *     rotations on the target;
 *   - retargeted onto its own skeleton from those skeletons, a clip gets
 *     back (nearly) its own local rotations;
 *   - with ../shared: blended transitions of the mixed CMU + Bandai Namco
 *     set move the toes no faster than the CMU set's own transitions.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <unistd.h>
#include <cmocka.h>

#include "bake_graph_helpers.h"
#include "bake_import_util.h"
#include "bake_manifest.h"
#include "bake_retarget.h"
#include "quat_pack.h"

#define DEG (180.0 / 3.14159265358979323846)

static void qget(const float* pose, uint32_t j, double q[4]) {
  int k;
  for (k = 0; k < 4; ++k) q[k] = pose[3 + 4 * j + k];
}

static void qput(float* pose, uint32_t j, const double q[4]) {
  int k;
  for (k = 0; k < 4; ++k) pose[3 + 4 * j + k] = (float)q[k];
}

/* Angle between two rotations, degrees. */
static double q_angle(const double a[4], const double b[4]) {
  double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return 2.0 * acos(d > 1.0 ? 1.0 : d) * DEG;
}

/* Shortest rotation taking unit u onto unit v (u, v not opposite). */
static void arc(const double u[3], const double v[3], double q[4]) {
  q[0] = u[1] * v[2] - u[2] * v[1];
  q[1] = u[2] * v[0] - u[0] * v[2];
  q[2] = u[0] * v[1] - u[1] * v[0];
  q[3] = 1.0 + u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  smgb_qnormalize(q);
}

/* `in` (a world-aligned rest: identity local rotations at rest) re-expressed
 * with a rest rotation R_j per joint, the same motion: offsets in the
 * parent's rotated axes, local rotations R_parent^-1 q R_j. along_x: every
 * bone lies along its joint's local +x (Bandai Namco's convention), with an
 * arbitrary roll about it; else arbitrary rotations (glTF/FBX rigs). */
static void with_rest_axes(const smgb_clip* in, int along_x, smgb_clip* out) {
  const smgb_skeleton* s = &in->skeleton;
  uint32_t J = s->joint_count, j, f;
  double(*R)[4] = malloc(sizeof *R * J);
  assert_non_null(R);
  assert_int_equal(smgb_clip_copy(in, out), SMG_OK);
  for (j = 0; j < J; ++j) {
    double roll[4], x[3] = {1.0, 0.0, 0.0}, a[4], axis[3], n;
    uint32_t c;
    axis[0] = sin(1.7 * j + 0.3);
    axis[1] = cos(0.9 * j);
    axis[2] = 0.4 - 0.1 * (double)(j % 7);
    n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    axis[0] /= n; axis[1] /= n; axis[2] /= n;
    smgb_qaxis_angle(axis, 0.5 + 0.37 * j, R[j]);
    if (!along_x) continue;
    for (c = j + 1; c < J; ++c) {
      const float* o = s->offsets[c];
      double d[3] = {o[0], o[1], o[2]};
      n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (s->parents[c] != (int32_t)j || n < 1e-4) continue;
      d[0] /= n; d[1] /= n; d[2] /= n;
      if (d[0] < -0.999) { /* along -x: a half turn about y */
        a[0] = a[2] = 0.0; a[1] = 1.0; a[3] = 0.0;
      } else {
        arc(x, d, a);
      }
      smgb_qaxis(0, 2.1 + 0.8 * j, roll);
      smgb_qmul(a, roll, R[j]);
      break;
    }
  }
  for (j = 1; j < J; ++j) {
    double pi[4], o[3] = {s->offsets[j][0], s->offsets[j][1], s->offsets[j][2]};
    smgb_qconj(R[s->parents[j]], pi);
    smgb_qrot(pi, o, o);
    out->skeleton.offsets[j][0] = (float)o[0];
    out->skeleton.offsets[j][1] = (float)o[1];
    out->skeleton.offsets[j][2] = (float)o[2];
  }
  for (f = 0; f < in->frame_count; ++f) {
    const float* p = in->poses + (size_t)f * SMGB_STRIDE(J);
    float* q = out->poses + (size_t)f * SMGB_STRIDE(J);
    for (j = 0; j < J; ++j) {
      double l[4], t[4], pi[4] = {0.0, 0.0, 0.0, 1.0};
      qget(p, j, l);
      if (j > 0) smgb_qconj(R[s->parents[j]], pi);
      smgb_qmul(pi, l, t);
      smgb_qmul(t, R[j], l);
      qput(q, j, l);
    }
  }
  free(R);
}

static void walk_clip(smgb_clip* c) {
  smgb_synth_params p;
  memset(&p, 0, sizeof p);
  p.kind = SMGB_SYNTH_WALK;
  p.duration = 3.0f;
  p.frame_rate = 30.0f;
  p.turn_rate = 0.3f;
  assert_int_equal(smgb_synth_generate(&p, c, NULL), SMG_OK);
}

static void retarget(const smgb_clip* src, const smgb_skeleton* target,
                     smgb_clip* out) {
  smgb_roles sr, tr;
  smgb_error err;
  assert_int_equal(smgb_clip_copy(src, out), SMG_OK);
  assert_int_equal(smgb_roles_find(&src->skeleton, NULL, "src", &sr, &err),
                   SMG_OK);
  assert_int_equal(smgb_roles_find(target, NULL, "target", &tr, &err), SMG_OK);
  if (smgb_retarget_clip(out, &sr, target, &tr, "target", &err) != SMG_OK)
    fail_msg("%s", err.message);
}

/* Worst and worst-joint-mean angle between the local rotations of two
 * clips on one skeleton; `joint` gets the joint of the worst mean. */
static void compare(const smgb_clip* a, const smgb_clip* b, double* worst,
                    double* worst_mean, uint32_t* joint) {
  uint32_t J = a->skeleton.joint_count, j, f;
  assert_int_equal(b->skeleton.joint_count, J);
  assert_int_equal(b->frame_count, a->frame_count);
  *worst = *worst_mean = 0.0;
  *joint = 0;
  for (j = 0; j < J; ++j) {
    double sum = 0.0;
    for (f = 0; f < a->frame_count; ++f) {
      double qa[4], qb[4], d;
      qget(a->poses + (size_t)f * SMGB_STRIDE(J), j, qa);
      qget(b->poses + (size_t)f * SMGB_STRIDE(J), j, qb);
      d = q_angle(qa, qb);
      sum += d;
      if (d > *worst) *worst = d;
    }
    if (sum / a->frame_count > *worst_mean) {
      *worst_mean = sum / a->frame_count;
      *joint = j;
    }
  }
}

/* The same motion from three source skeletons that differ only in their
 * joints' local axes, onto the Mixamo-style A-pose rig: the same local
 * rotations (positions were always the same; the twist about each bone was
 * the source's convention). */
static void test_local_axes_cancel(void** state) {
  smgb_clip src, along_x, rotated, ta, tb, tc;
  smgb_skeleton rig;
  smgb_error err;
  char path[64];
  double worst, mean;
  uint32_t joint;
  (void)state;
  snprintf(path, sizeof path, "/tmp/smg_twist_rig_%ld.bvh", (long)getpid());
  assert_int_equal(smgb_synth_write_rig(path, &err), SMG_OK);
  assert_int_equal(smgb_rig_load(path, 1.0f, 0, &rig, &err), SMG_OK);
  remove(path);
  walk_clip(&src);
  with_rest_axes(&src, 1, &along_x);
  with_rest_axes(&src, 0, &rotated);
  retarget(&src, &rig, &ta);
  retarget(&along_x, &rig, &tb);
  retarget(&rotated, &rig, &tc);
  compare(&ta, &tb, &worst, &mean, &joint);
  printf("onto the rig, bones along x vs world-aligned source: worst %.3g "
         "deg, worst joint mean %.3g deg (%s)\n",
         worst, mean, ta.skeleton.names[joint]);
  assert_true(worst < 1.0);
  compare(&ta, &tc, &worst, &mean, &joint);
  printf("onto the rig, rotated axes vs world-aligned source: worst %.3g "
         "deg, worst joint mean %.3g deg (%s)\n",
         worst, mean, ta.skeleton.names[joint]);
  assert_true(worst < 1.0);
  smgb_clip_free(&src);
  smgb_clip_free(&along_x);
  smgb_clip_free(&rotated);
  smgb_clip_free(&ta);
  smgb_clip_free(&tb);
  smgb_clip_free(&tc);
  smgb_skeleton_free(&rig);
}

/* A clip retargeted onto its own (world-aligned) skeleton from a source
 * whose bones lie along local x gets back its own local rotations: the
 * twist is the target's convention, not the source's. */
static void test_back_onto_own_skeleton(void** state) {
  smgb_clip src, along_x, back;
  double worst, mean;
  uint32_t joint;
  (void)state;
  walk_clip(&src);
  with_rest_axes(&src, 1, &along_x);
  retarget(&along_x, &src.skeleton, &back);
  compare(&src, &back, &worst, &mean, &joint);
  printf("bones along x, back onto the own skeleton: worst %.3g deg, worst "
         "joint mean %.3g deg (%s)\n",
         worst, mean, src.skeleton.names[joint]);
  assert_true(mean < 5.0);
  assert_true(worst < 15.0);
  smgb_clip_free(&src);
  smgb_clip_free(&along_x);
  smgb_clip_free(&back);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_local_axes_cancel),
      cmocka_unit_test(test_back_onto_own_skeleton),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
