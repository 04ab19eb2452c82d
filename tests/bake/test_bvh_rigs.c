/*
 * test_bvh_rigs.c - BVH files shaped like real exports other than CMU, all
 * generated here (no data is copied):
 *
 *  - Bandai Namco shape: a static joint_Root (here with a rotation and a
 *    translation) above a translating Hips, 6 channels on every joint,
 *    centimetres, position channels in several places of the channel list
 *    and several rotation orders. The same motion written the plain way
 *    (Hips as root, 3 ZYX rotation channels, metres) must import to the
 *    same skeleton and the same world joint positions.
 *  - Non-root position channels that wobble (solver noise) become the
 *    mean offset; ones that really move are rejected naming the joint.
 *  - Mirroring a rig whose joint frames are not mirror images of each
 *    other (Maya/MotionBuilder joint orients, as in Bandai Namco's files):
 *    the mirrored motion, on the unchanged skeleton, puts every joint at
 *    the reflected position of its counterpart; and on a left/right
 *    symmetric gait the mirror of frame t has the same local rotations as
 *    frame t + half a cycle, so a transition blending a clip with its
 *    mirror is smooth (a different but position-equivalent split of a
 *    twist along a chain spun whole limbs in such blends).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_math.h"
#include "bake_roles.h"
#include "import_helpers.h"

#define NJ 21  /* Hips .. Toes_R: Bandai Namco's joints below joint_Root */
#define NF 12

static const char* const k_names[NJ] = {
    "Hips",       "Spine",      "Chest",      "Neck",       "Head",
    "Shoulder_L", "UpperArm_L", "LowerArm_L", "Hand_L",     "Shoulder_R",
    "UpperArm_R", "LowerArm_R", "Hand_R",     "UpperLeg_L", "LowerLeg_L",
    "Foot_L",     "Toes_L",     "UpperLeg_R", "LowerLeg_R", "Foot_R",
    "Toes_R"};
static const int32_t k_parents[NJ] = {-1, 0, 1, 2, 3, 2, 5, 6, 7, 2, 9,
                                      10, 11, 0, 13, 14, 15, 0, 17, 18, 19};
/* Rest offsets, centimetres, a standing figure. */
static const double k_offsets_cm[NJ][3] = {
    {0, 93, 0},     {0, 12, -1},  {0, 14, 0},    {0, 20, 0},  {0, 9, 1},
    {4, 16, 0},     {13, 0, 0},   {26, 0, 0},    {24, 0, 0},  {-4, 16, 0},
    {-13, 0, 0},    {-26, 0, 0},  {-24, 0, 0},   {9, -6, 0},  {0, -40, 0},
    {0, -41, 0},    {0, -6, 12},  {-9, -6, 0},   {0, -40, 0}, {0, -41, 0},
    {0, -6, 12}};

/* Channel lists used in the Bandai-shaped file, cycled over the joints:
 * positions first (as Bandai writes them), last, and interleaved. */
static const char* const k_orders[4][6] = {
    {"Xposition", "Yposition", "Zposition", "Zrotation", "Xrotation", "Yrotation"},
    {"Yrotation", "Xrotation", "Zrotation", "Xposition", "Yposition", "Zposition"},
    {"Xrotation", "Zposition", "Zrotation", "Xposition", "Yrotation", "Yposition"},
    {"Zposition", "Yposition", "Xposition", "Yrotation", "Zrotation", "Xrotation"}};

/* Static root: 90 deg about Y, then 30 cm along x, -20 cm along z. */
static const double k_root_t[3] = {30.0, 0.0, -20.0};

/* Angle (degrees) of rotation channel `axis` (0 x, 1 y, 2 z) of joint j in
 * frame f: smooth, different per joint, axis and frame. */
static double angle(uint32_t j, int axis, uint32_t f) {
  return 25.0 * sin(0.3 * f + 1.7 * j + 2.1 * axis) + 5.0 * axis;
}

/* Hips translation (cm) in the static root's frame. */
static void hips_local(uint32_t f, double t[3]) {
  t[0] = 3.0 * sin(0.2 * f);
  t[1] = 93.0 + 2.0 * cos(0.5 * f);
  t[2] = 9.0 * f;
}

/* Quaternion of joint j in frame f: the product of its rotation channels in
 * the order joint j lists them. */
static void joint_q(uint32_t j, uint32_t f, double q[4]) {
  const char* const* order = k_orders[j % 4];
  int c;
  q[0] = q[1] = q[2] = 0.0;
  q[3] = 1.0;
  for (c = 0; c < 6; ++c) {
    if (strstr(order[c], "rotation")) {
      int axis = order[c][0] - 'X';
      double r[4];
      smgb_q_axis(axis, angle(j, axis, f) * (SMGB_M_PI / 180.0), r);
      smgb_q_mul(q, r, q);
    }
  }
}

static void root_q(double q[4]) {
  smgb_q_axis(1, SMGB_M_PI / 2.0, q);
}

/* Bandai-shaped file. wobble: add +-w cm of noise to LowerLeg_L's position
 * channels (index 14). */
static void write_bandai_shape(const char* path, double wobble) {
  FILE* fp = fopen(path, "wb");
  uint32_t j, f;
  int depth = 1, c;
  assert_non_null(fp);
  fprintf(fp, "HIERARCHY\nROOT joint_Root\n{\n\tOFFSET 0 0 0\n\tCHANNELS 6 "
              "Xposition Yposition Zposition Zrotation Xrotation Yrotation\n");
  for (j = 0; j < NJ; ++j) {
    /* Close the joints that are not ancestors of j. */
    int32_t p = k_parents[j];
    int want = 1;
    while (p >= 0) {
      ++want;
      p = k_parents[p];
    }
    while (depth > want) {
      --depth;
      fprintf(fp, "%*s}\n", depth, "");
    }
    fprintf(fp, "%*sJOINT %s\n%*s{\n%*sOFFSET %g %g %g\n%*sCHANNELS 6", depth,
            "", k_names[j], depth, "", depth + 1, "", k_offsets_cm[j][0],
            k_offsets_cm[j][1], k_offsets_cm[j][2], depth + 1, "");
    for (c = 0; c < 6; ++c) fprintf(fp, " %s", k_orders[j % 4][c]);
    fputc('\n', fp);
    ++depth;
  }
  while (depth > 0) {
    --depth;
    fprintf(fp, "%*s}\n", depth, "");
  }
  fprintf(fp, "MOTION\nFrames: %d\nFrame Time: 0.0333333\n", NF);
  for (f = 0; f < NF; ++f) {
    /* joint_Root: ZXY order like Bandai's; root_q() = Ry(90). */
    fprintf(fp, "%g %g %g %g %g %g", k_root_t[0], k_root_t[1], k_root_t[2],
            0.0, 0.0, 90.0);
    for (j = 0; j < NJ; ++j) {
      double t[3];
      if (j == 0) {
        hips_local(f, t);
      } else {
        t[0] = k_offsets_cm[j][0];
        t[1] = k_offsets_cm[j][1];
        t[2] = k_offsets_cm[j][2];
        if (j == 14) t[1] += wobble * ((f % 2) ? 1.0 : -1.0);
      }
      for (c = 0; c < 6; ++c) {
        const char* ch = k_orders[j % 4][c];
        int axis = ch[0] - 'X';
        fprintf(fp, " %.9g", strstr(ch, "position") ? t[axis]
                                                   : angle(j, axis, f));
      }
    }
    fputc('\n', fp);
  }
  assert_int_equal(fclose(fp), 0);
}

/* The same motion the plain way: Hips is the root, world translation and
 * rotation in metres, 3 ZYX rotation channels below. */
static void write_plain(const char* path) {
  FILE* fp = fopen(path, "wb");
  uint32_t j, f;
  int depth = 0;
  assert_non_null(fp);
  fprintf(fp, "HIERARCHY\n");
  for (j = 0; j < NJ; ++j) {
    int32_t p = k_parents[j];
    int want = 0;
    while (p >= 0) {
      ++want;
      p = k_parents[p];
    }
    while (depth > want) {
      --depth;
      fprintf(fp, "%*s}\n", depth, "");
    }
    fprintf(fp, "%*s%s %s\n%*s{\n%*sOFFSET %.9g %.9g %.9g\n", depth, "",
            j ? "JOINT" : "ROOT", k_names[j], depth, "", depth + 1, "",
            k_offsets_cm[j][0] * 0.01, k_offsets_cm[j][1] * 0.01,
            k_offsets_cm[j][2] * 0.01);
    fprintf(fp, "%*sCHANNELS %s\n", depth + 1, "",
            j ? "3 Zrotation Yrotation Xrotation"
              : "6 Xposition Yposition Zposition Zrotation Yrotation "
                "Xrotation");
    ++depth;
  }
  while (depth > 0) {
    --depth;
    fprintf(fp, "%*s}\n", depth, "");
  }
  fprintf(fp, "MOTION\nFrames: %d\nFrame Time: 0.0333333\n", NF);
  for (f = 0; f < NF; ++f) {
    double rq[4], t[3], q[4], z, y, x;
    root_q(rq);
    hips_local(f, t);
    smgb_q_rotate(rq, t, t);
    fprintf(fp, "%.9g %.9g %.9g", (t[0] + k_root_t[0]) * 0.01,
            (t[1] + k_root_t[1]) * 0.01, (t[2] + k_root_t[2]) * 0.01);
    for (j = 0; j < NJ; ++j) {
      joint_q(j, f, q);
      if (j == 0) smgb_q_mul(rq, q, q);
      smgb_q_to_euler_zyx(q, &z, &y, &x);
      fprintf(fp, " %.9g %.9g %.9g", z * (180.0 / SMGB_M_PI),
              y * (180.0 / SMGB_M_PI), x * (180.0 / SMGB_M_PI));
    }
    fputc('\n', fp);
  }
  assert_int_equal(fclose(fp), 0);
}

static double max_fk_diff(const smgb_clip* a, const smgb_clip* b) {
  uint32_t J = a->skeleton.joint_count, f, k;
  float* pa = malloc(sizeof(float) * 3 * J);
  float* pb = malloc(sizeof(float) * 3 * J);
  double m = 0.0;
  assert_true(pa && pb);
  for (f = 0; f < a->frame_count; ++f) {
    smgb_fk(&a->skeleton, a->poses + (size_t)f * SMGB_STRIDE(J), pa, NULL);
    smgb_fk(&b->skeleton, b->poses + (size_t)f * SMGB_STRIDE(J), pb, NULL);
    for (k = 0; k < 3 * J; ++k)
      if (fabs(pa[k] - pb[k]) > m) m = fabs(pa[k] - pb[k]);
  }
  free(pa);
  free(pb);
  return m;
}

static void test_bandai_shape_matches_plain(void** state) {
  char dir[64], a[128], b[128];
  smgb_clip ca, cb;
  smgb_error err;
  smgb_roles r;
  uint32_t j;
  (void)state;
  imp_tempdir(dir, sizeof dir);
  assert_true(dir[0] != '\0');
  snprintf(a, sizeof a, "%s/bandai_shape.bvh", dir);
  snprintf(b, sizeof b, "%s/plain.bvh", dir);
  write_bandai_shape(a, 0.0);
  write_plain(b);
  /* Units guessed: centimetres for one, metres for the other. */
  if (smgb_bvh_load(a, 0.0f, 0, &ca, &err) != SMG_OK) fail_msg("%s", err.message);
  if (smgb_bvh_load(b, 0.0f, 0, &cb, &err) != SMG_OK) fail_msg("%s", err.message);
  assert_int_equal(ca.skeleton.joint_count, NJ); /* joint_Root folded */
  assert_int_equal(cb.skeleton.joint_count, NJ);
  assert_int_equal(ca.frame_count, NF);
  for (j = 0; j < NJ; ++j) {
    assert_string_equal(ca.skeleton.names[j], cb.skeleton.names[j]);
    assert_int_equal(ca.skeleton.parents[j], cb.skeleton.parents[j]);
    if (j > 0) {
      int k;
      for (k = 0; k < 3; ++k)
        assert_float_equal(ca.skeleton.offsets[j][k], cb.skeleton.offsets[j][k],
                           1e-6f);
    }
  }
  printf("Bandai-shaped vs plain: largest joint position difference %.2e m\n",
         max_fk_diff(&ca, &cb));
  assert_true(max_fk_diff(&ca, &cb) < 1e-4);
  /* Roles on the folded skeleton: the pelvis is joint 0. */
  assert_int_equal(smgb_roles_find(&ca.skeleton, NULL, a, &r, &err), SMG_OK);
  assert_int_equal(r.joint[SMGB_ROLE_PELVIS], 0);
  assert_int_equal(r.joint[SMGB_ROLE_SPINE_BASE], 1);
  assert_int_equal(r.joint[SMGB_ROLE_LEFT_TOES], 16);
  smgb_clip_free(&ca);
  smgb_clip_free(&cb);
  imp_rmdir(dir);
}

/* A knee whose position channels wobble by 0.4 cm on a 40 cm bone imports
 * with the mean offset; 8 cm of movement is real translation: rejected. */
static void test_wobbling_positions(void** state) {
  char dir[64], a[128];
  smgb_clip c;
  smgb_error err;
  (void)state;
  imp_tempdir(dir, sizeof dir);
  snprintf(a, sizeof a, "%s/wobble.bvh", dir);
  write_bandai_shape(a, 0.4);
  if (smgb_bvh_load(a, 0.01f, 0, &c, &err) != SMG_OK) fail_msg("%s", err.message);
  /* NF is even: the +-0.4 cm alternation averages out exactly. */
  assert_float_equal(c.skeleton.offsets[14][1], -0.40f, 1e-6f);
  smgb_clip_free(&c);
  write_bandai_shape(a, 4.0);
  assert_int_equal(smgb_bvh_load(a, 0.01f, 0, &c, &err),
                   SMG_ERROR_UNSUPPORTED);
  assert_non_null(strstr(err.message, "wobble.bvh:"));
  assert_non_null(strstr(err.message, "'LowerLeg_L'"));
  imp_rmdir(dir);
}

/* Mirroring a rig with arbitrary joint orients: the local offsets are a
 * symmetric standing figure seen from per-joint rotated frames (O_j =
 * Rz(90) Rx(37 j deg): no joint frame is the mirror image of its
 * counterpart's). Poses are random local rotations. */
static void test_mirror_joint_orients(void** state) {
  smgb_clip c, m, mm;
  double O[NJ][4];
  uint32_t J = NJ, S = SMGB_STRIDE(NJ), j, f;
  int32_t partner[NJ];
  float pa[3 * NJ], pb[3 * NJ];
  (void)state;
  memset(&c, 0, sizeof c);
  snprintf(c.name, sizeof c.name, "orients");
  c.skeleton.joint_count = J;
  c.skeleton.names = calloc(J, sizeof *c.skeleton.names);
  c.skeleton.parents = calloc(J, sizeof *c.skeleton.parents);
  c.skeleton.offsets = calloc(J, sizeof *c.skeleton.offsets);
  c.frame_count = NF;
  c.frame_rate = 30.0f;
  c.poses = calloc((size_t)NF * S, sizeof(float));
  assert_true(c.skeleton.names && c.skeleton.parents && c.skeleton.offsets &&
              c.poses);
  for (j = 0; j < J; ++j) {
    double rz[4], rx[4], inv[4], u[3];
    smgb_q_axis(2, SMGB_M_PI / 2.0, rz);
    smgb_q_axis(0, 37.0 * j * SMGB_M_PI / 180.0, rx);
    smgb_q_mul(rz, rx, O[j]);
    snprintf(c.skeleton.names[j], SMGB_NAME_MAX, "%s", k_names[j]);
    c.skeleton.parents[j] = k_parents[j];
    u[0] = k_offsets_cm[j][0] * 0.01;
    u[1] = k_offsets_cm[j][1] * 0.01;
    u[2] = k_offsets_cm[j][2] * 0.01;
    if (j > 0) {
      smgb_q_conj(O[k_parents[j]], inv);
      smgb_q_rotate(inv, u, u);
    }
    c.skeleton.offsets[j][0] = (float)u[0];
    c.skeleton.offsets[j][1] = (float)u[1];
    c.skeleton.offsets[j][2] = (float)u[2];
  }
  for (f = 0; f < NF; ++f) {
    float* p = c.poses + (size_t)f * S;
    p[0] = 0.1f * f;
    p[1] = 0.9f;
    p[2] = 0.05f * f;
    for (j = 0; j < J; ++j) {
      double q[4];
      joint_q(j, f, q);
      p[3 + 4 * j] = (float)q[0];
      p[4 + 4 * j] = (float)q[1];
      p[5 + 4 * j] = (float)q[2];
      p[6 + 4 * j] = (float)q[3];
    }
  }
  for (j = 0; j < J; ++j) {
    char other[SMGB_NAME_MAX];
    partner[j] = smgb_roles_counterpart_name(k_names[j], other)
                     ? smgb_skeleton_find(&c.skeleton, other)
                     : (int32_t)j;
    assert_true(partner[j] >= 0);
  }
  assert_int_equal(smgb_clip_mirror(&c, &m), SMG_OK);
  assert_int_equal(smgb_clip_mirror(&m, &mm), SMG_OK);
  for (f = 0; f < NF; ++f) {
    /* The blob keeps one skeleton: FK of the mirror on the original. */
    smgb_fk(&c.skeleton, c.poses + (size_t)f * S, pa, NULL);
    smgb_fk(&c.skeleton, m.poses + (size_t)f * S, pb, NULL);
    for (j = 0; j < J; ++j) {
      int32_t k = partner[j];
      assert_float_equal(pb[3 * j + 0], -pa[3 * k + 0], 1e-5f);
      assert_float_equal(pb[3 * j + 1], pa[3 * k + 1], 1e-5f);
      assert_float_equal(pb[3 * j + 2], pa[3 * k + 2], 1e-5f);
    }
  }
  assert_true(max_fk_diff(&c, &mm) < 1e-5);
  smgb_clip_free(&c);
  smgb_clip_free(&m);
  smgb_clip_free(&mm);
}

/* Joint orients of the rig in test_mirror_joint_orients: no joint frame
 * is the mirror image of its counterpart's. */
static void orient(uint32_t j, double O[4]) {
  double rz[4], rx[4];
  smgb_q_axis(2, SMGB_M_PI / 2.0, rz);
  smgb_q_axis(0, 37.0 * j * SMGB_M_PI / 180.0, rx);
  smgb_q_mul(rz, rx, O);
}

/* A symmetric gait on the unoriented figure: r_partner(t) is the mirror
 * (x, -y, -z, w) of r_j(t + T/2); central joints sway about y with
 * sin(wt) and pitch about x with cos(2wt). */
static void gait_rotation(uint32_t j, int32_t partner, double t, double T,
                          double q[4]) {
  double w = 2.0 * SMGB_M_PI / T, a[4], b[4];
  if (partner == (int32_t)j) {
    smgb_q_axis(1, 0.3 * sin(w * t), a);
    smgb_q_axis(0, 0.2 * cos(2.0 * w * t) + 0.05 * j, b);
    smgb_q_mul(a, b, q);
    return;
  }
  if (partner < (int32_t)j) { /* right side: mirror of the left, later */
    gait_rotation((uint32_t)partner, (int32_t)j, t + 0.5 * T, T, q);
    q[1] = -q[1];
    q[2] = -q[2];
    return;
  }
  smgb_q_axis(0, 0.6 * sin(w * t + 0.4 * j), a);
  smgb_q_axis(2, 0.25 + 0.2 * cos(w * t + j), b);
  smgb_q_mul(a, b, q);
}

static void test_mirror_symmetric_gait(void** state) {
  enum { HALF = 15, FRAMES = 4 * HALF }; /* two cycles of 30 frames */
  smgb_clip c, m;
  double O[NJ][4];
  uint32_t J = NJ, S = SMGB_STRIDE(NJ), j, f;
  int32_t partner[NJ];
  double worst = 0.0;
  (void)state;
  memset(&c, 0, sizeof c);
  snprintf(c.name, sizeof c.name, "gait");
  c.skeleton.joint_count = J;
  c.skeleton.names = calloc(J, sizeof *c.skeleton.names);
  c.skeleton.parents = calloc(J, sizeof *c.skeleton.parents);
  c.skeleton.offsets = calloc(J, sizeof *c.skeleton.offsets);
  c.frame_count = FRAMES;
  c.frame_rate = 30.0f;
  c.poses = calloc((size_t)FRAMES * S, sizeof(float));
  assert_true(c.skeleton.names && c.skeleton.parents && c.skeleton.offsets &&
              c.poses);
  for (j = 0; j < J; ++j) {
    double inv[4], u[3];
    orient(j, O[j]);
    snprintf(c.skeleton.names[j], SMGB_NAME_MAX, "%s", k_names[j]);
    c.skeleton.parents[j] = k_parents[j];
    u[0] = k_offsets_cm[j][0] * 0.01;
    u[1] = k_offsets_cm[j][1] * 0.01;
    u[2] = k_offsets_cm[j][2] * 0.01;
    if (j > 0) {
      smgb_q_conj(O[k_parents[j]], inv);
      smgb_q_rotate(inv, u, u);
    }
    c.skeleton.offsets[j][0] = (float)u[0];
    c.skeleton.offsets[j][1] = (float)u[1];
    c.skeleton.offsets[j][2] = (float)u[2];
  }
  for (j = 0; j < J; ++j) {
    char other[SMGB_NAME_MAX];
    partner[j] = smgb_roles_counterpart_name(k_names[j], other)
                     ? smgb_skeleton_find(&c.skeleton, other)
                     : (int32_t)j;
  }
  for (f = 0; f < FRAMES; ++f) {
    float* p = c.poses + (size_t)f * S;
    p[0] = (float)(0.03 * sin(SMGB_M_PI * f / HALF));
    p[1] = 0.9f;
    p[2] = 0.04f * f;
    for (j = 0; j < J; ++j) {
      /* The oriented rig's local rotation: O_parent^-1 r_j O_j. */
      double r[4], inv[4], q[4];
      gait_rotation(j, partner[j], f, 2.0 * HALF, r);
      smgb_q_mul(r, O[j], q);
      if (j > 0) {
        smgb_q_conj(O[k_parents[j]], inv);
        smgb_q_mul(inv, q, q);
      }
      smgb_q_normalize(q);
      p[3 + 4 * j] = (float)q[0];
      p[4 + 4 * j] = (float)q[1];
      p[5 + 4 * j] = (float)q[2];
      p[6 + 4 * j] = (float)q[3];
    }
  }
  assert_int_equal(smgb_clip_mirror(&c, &m), SMG_OK);
  for (f = 0; f + HALF < FRAMES; ++f)
    for (j = 0; j < J; ++j) {
      const float* a = m.poses + (size_t)f * S + 3 + 4 * j;
      const float* b = c.poses + (size_t)(f + HALF) * S + 3 + 4 * j;
      double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
      double angle = 2.0 * acos(d > 1.0 ? 1.0 : d) * (180.0 / SMGB_M_PI);
      if (angle > worst) worst = angle;
    }
  printf("mirrored symmetric gait vs half a cycle later: local rotations "
         "within %.4f deg\n", worst);
  assert_true(worst < 0.2); /* float rounding: acos near 1 */
  smgb_clip_free(&c);
  smgb_clip_free(&m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bandai_shape_matches_plain),
      cmocka_unit_test(test_wobbling_positions),
      cmocka_unit_test(test_mirror_joint_orients),
      cmocka_unit_test(test_mirror_symmetric_gait),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
