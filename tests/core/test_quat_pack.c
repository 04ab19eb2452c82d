/*
 * test_quat_pack.c - the blob's 48-bit "smallest three" rotations
 * (libsmg/common/quat_pack.h): accuracy over random and awkward unit
 * quaternions (the bound docs/blob-format.md quotes), exact identity and
 * axis-aligned rotations, sign and index handling, rejection of non-unit
 * input, whole POSE records, and the property the blob reader relies on:
 * every 6-byte pattern decodes to a finite unit quaternion.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "quat_pack.h"
#include "rmath.h"
#include "test_env.h"

/* Max rotation error of a pack + unpack, radians (docs/blob-format.md):
 * the analytic bound. Stored components err by at most half a step
 * (1.08e-5 for the 16-bit one, 2.16e-5 for the 15-bit ones: 3.24e-5
 * together), the rebuilt largest one by at most |(a,b,c)| / q[i] times
 * that <= sqrt(3) * 3.24e-5 (q[i] >= 1/2), so |dq| <= 6.5e-5 and the angle
 * 2 |dq| <= 1.3e-4. Measured: 1.15e-4 over 10^7 random rotations. */
#define MAX_ERROR_RAD 1.3e-4

static uint64_t g_rng = 0x9e3779b97f4a7c15ull;

static uint32_t rnd32(void) {
  g_rng ^= g_rng << 13;
  g_rng ^= g_rng >> 7;
  g_rng ^= g_rng << 17;
  return (uint32_t)(g_rng >> 32);
}

static double rnd01(void) { return (double)rnd32() / 4294967296.0; }

/* Uniform random rotation (Shoemake), as floats. */
static void random_quat(float* q) {
  const double tau = 6.283185307179586;
  double u1 = rnd01(), u2 = rnd01(), u3 = rnd01();
  double a = sqrt(1.0 - u1), b = sqrt(u1);
  q[0] = (float)(a * sin(tau * u2));
  q[1] = (float)(a * cos(tau * u2));
  q[2] = (float)(b * sin(tau * u3));
  q[3] = (float)(b * cos(tau * u3));
}

/* Rotation angle between q and p (any lengths), radians, in double and
 * well conditioned for tiny angles: 2 atan2(|v|, |w|) of conj(p) q (acos
 * of a dot product near 1 would turn float rounding of the lengths into
 * apparent errors of ~1e-3 rad). */
static double angle_between(const float* q, const float* p) {
  double a[4], b[4], na = 0.0, nb = 0.0, v[3], w;
  int k;
  for (k = 0; k < 4; ++k) {
    a[k] = q[k];
    b[k] = p[k];
    na += a[k] * a[k];
    nb += b[k] * b[k];
  }
  na = sqrt(na);
  nb = sqrt(nb);
  for (k = 0; k < 4; ++k) a[k] /= na, b[k] /= nb;
  /* conj(b) * a */
  w = b[3] * a[3] + b[0] * a[0] + b[1] * a[1] + b[2] * a[2];
  v[0] = b[3] * a[0] - b[0] * a[3] - b[1] * a[2] + b[2] * a[1];
  v[1] = b[3] * a[1] - b[1] * a[3] - b[2] * a[0] + b[0] * a[2];
  v[2] = b[3] * a[2] - b[2] * a[3] - b[0] * a[1] + b[1] * a[0];
  return 2.0 * atan2(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), fabs(w));
}

/* Pack, unpack (both decoders) and return the angle error; checks the
 * decoded quaternion is unit. */
static double round_trip(const float* q) {
  unsigned char b[SMGI_QPACK_BYTES];
  float u[4], r[4];
  double n2, e;
  assert_int_equal(smgi_quat_pack(q, b), 1);
  smgi_quat_unpack(b, u);
  smgi_quat_unpack_raw(b, r);
  n2 = (double)u[0] * u[0] + (double)u[1] * u[1] + (double)u[2] * u[2] +
       (double)u[3] * u[3];
  assert_true(fabs(n2 - 1.0) < 1e-6);
  /* for what the encoder writes the raw decode is already unit */
  n2 = (double)r[0] * r[0] + (double)r[1] * r[1] + (double)r[2] * r[2] +
       (double)r[3] * r[3];
  assert_true(fabs(n2 - 1.0) < 1e-6);
  e = angle_between(u, q);
  assert_true(e <= MAX_ERROR_RAD);
  return e;
}

static void test_random_rotations_within_bound(void** state) {
  uint32_t i, n = smgt_quick() ? 20000u : 1000000u;
  double worst = 0.0, sum = 0.0;
  (void)state;
  for (i = 0; i < n; ++i) {
    float q[4];
    double e;
    random_quat(q);
    e = round_trip(q);
    sum += e;
    if (e > worst) worst = e;
  }
  printf("random rotations: %u, max error %.3g rad (%.4f deg), mean %.3g "
         "rad\n",
         (unsigned)n, worst, worst * 57.29577951308232, sum / n);
}

/* Near-180-degree rotations (w ~ 0: the dropped component is x, y or z),
 * near-ties between the largest components (the index flips between
 * neighbouring codes), components at the +-1/sqrt2 range ends, tiny
 * angles. */
static void test_awkward_rotations_within_bound(void** state) {
  static const double eps[] = {0.0, 1e-7, 1e-5, 1e-3, 3e-2};
  uint32_t i, k, n = smgt_quick() ? 2000u : 50000u;
  double worst = 0.0;
  (void)state;
  for (i = 0; i < n; ++i) {
    for (k = 0; k < sizeof eps / sizeof eps[0]; ++k) {
      float q[4], axis[4];
      double nn, ang;
      uint32_t c;
      /* near 180 degrees about a random axis: w = +-eps */
      random_quat(axis);
      nn = sqrt((double)axis[0] * axis[0] + (double)axis[1] * axis[1] +
                (double)axis[2] * axis[2]);
      ang = eps[k] * (rnd32() & 1 ? 1.0 : -1.0);
      for (c = 0; c < 3; ++c)
        q[c] = (float)(axis[c] / nn * sqrt(1.0 - ang * ang));
      q[3] = (float)ang;
      worst = fmax(worst, round_trip(q));
      /* tiny rotation about a random axis */
      for (c = 0; c < 3; ++c) q[c] = (float)(axis[c] / nn * eps[k]);
      q[3] = (float)sqrt(1.0 - eps[k] * eps[k]);
      worst = fmax(worst, round_trip(q));
      /* two largest components nearly tied at ~1/sqrt2 (90 degrees) */
      {
        uint32_t a = rnd32() % 4u, b = (a + 1u + rnd32() % 3u) % 4u;
        double t = 0.70710678118654752;
        memset(q, 0, sizeof q);
        q[a] = (float)(t + eps[k]);
        q[b] = (float)(rnd32() & 1 ? -1.0 : 1.0) *
               (float)sqrt(1.0 - (t + eps[k]) * (t + eps[k]));
        worst = fmax(worst, round_trip(q));
      }
      /* all four components near 0.5 */
      for (c = 0; c < 4; ++c)
        q[c] = (float)((rnd32() & 1 ? -0.5 : 0.5) +
                       eps[k] * (rnd01() - 0.5));
      nn = sqrt((double)q[0] * q[0] + (double)q[1] * q[1] +
                (double)q[2] * q[2] + (double)q[3] * q[3]);
      for (c = 0; c < 4; ++c) q[c] = (float)(q[c] / nn);
      worst = fmax(worst, round_trip(q));
    }
  }
  printf("awkward rotations: max error %.3g rad\n", worst);
}

/* Identity, the half turns about the axes and the quarter turns whose two
 * components are exactly +-1/sqrt2 in float come back bit-exact or within
 * float rounding (0 and +-1/sqrt2 are codes); q and -q pack to the same
 * bytes, here and for a four-way tie. */
static void test_axis_aligned_and_sign(void** state) {
  const float h = 0.70710678f;
  const float cases[][4] = {
      {0, 0, 0, 1}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0},
      {h, 0, 0, h}, {0, h, 0, h}, {0, 0, h, h}, {h, h, 0, 0},
      {0, -h, 0, h}, {-h, 0, h, 0}};
  size_t i, k;
  (void)state;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    unsigned char a[SMGI_QPACK_BYTES], b[SMGI_QPACK_BYTES];
    float neg[4], u[4];
    for (k = 0; k < 4; ++k) neg[k] = -cases[i][k];
    assert_int_equal(smgi_quat_pack(cases[i], a), 1);
    assert_int_equal(smgi_quat_pack(neg, b), 1);
    assert_memory_equal(a, b, sizeof a);
    smgi_quat_unpack(a, u);
    /* up to the overall sign */
    {
      float s = u[0] * cases[i][0] + u[1] * cases[i][1] +
                u[2] * cases[i][2] + u[3] * cases[i][3];
      s = s < 0.0f ? -1.0f : 1.0f;
      for (k = 0; k < 4; ++k)
        assert_float_equal(s * u[k], cases[i][k], 2e-7f);
    }
  }
  {
    const float tie[4] = {-0.5f, 0.5f, -0.5f, 0.5f};
    const float ntie[4] = {0.5f, -0.5f, 0.5f, -0.5f};
    unsigned char a[SMGI_QPACK_BYTES], b[SMGI_QPACK_BYTES];
    uint16_t w[3];
    smgi_quat_pack(tie, a);
    smgi_quat_pack(ntie, b);
    assert_memory_equal(a, b, sizeof a);
    memcpy(w, a, sizeof w);
    /* ties go to the first index */
    assert_int_equal((w[1] & 1u) | ((w[2] & 1u) << 1), 0);
    round_trip(tie);
  }
  /* identity and half turns: zero components are exact zeros */
  {
    unsigned char a[SMGI_QPACK_BYTES];
    float u[4];
    for (i = 0; i < 4; ++i) {
      float q[4] = {0, 0, 0, 0};
      q[i] = 1.0f;
      smgi_quat_pack(q, a);
      smgi_quat_unpack(a, u);
      for (k = 0; k < 4; ++k)
        assert_true(u[k] == (k == i ? 1.0f : 0.0f));
    }
  }
}

/* The dropped component's index sits in the low bits of words 1 and 2,
 * and the stored three follow it cyclically (docs/blob-format.md). */
static void test_index_bits_and_layout(void** state) {
  uint32_t i;
  (void)state;
  for (i = 0; i < 4; ++i) {
    float q[4] = {0.1f, -0.2f, 0.3f, -0.4f};
    unsigned char b[SMGI_QPACK_BYTES];
    uint16_t w[3];
    double n = 0.0;
    uint32_t k;
    q[i] = -0.8f; /* largest magnitude, negative: the encoder flips */
    for (k = 0; k < 4; ++k) n += (double)q[k] * q[k];
    for (k = 0; k < 4; ++k) q[k] = (float)(q[k] / sqrt(n));
    assert_int_equal(smgi_quat_pack(q, b), 1);
    memcpy(w, b, sizeof w);
    assert_int_equal((w[1] & 1u) | ((w[2] & 1u) << 1), i);
    /* word 0 holds -q[(i+1)&3] (the flipped sign) in 16 bits */
    assert_float_equal(
        (float)((int32_t)w[0] - SMGI_QPACK_MID16) * SMGI_QPACK_STEP16,
        -q[(i + 1u) & 3u], SMGI_QPACK_STEP16);
    assert_float_equal(
        (float)((int32_t)(w[1] >> 1) - SMGI_QPACK_MID15) * SMGI_QPACK_STEP15,
        -q[(i + 2u) & 3u], SMGI_QPACK_STEP15);
    assert_float_equal(
        (float)((int32_t)(w[2] >> 1) - SMGI_QPACK_MID15) * SMGI_QPACK_STEP15,
        -q[(i + 3u) & 3u], SMGI_QPACK_STEP15);
  }
}

/* Non-finite or clearly non-unit input is reported (the baker fails on
 * it) and written as the identity. */
static void test_rejects_non_unit(void** state) {
  const float bad[][4] = {{0, 0, 0, 0},        {0, 0, 0, 1.01f},
                          {NAN, 0, 0, 1},      {INFINITY, 0, 0, 0},
                          {0.5f, 0.5f, 0.5f, 0.4f}};
  const float ok[4] = {0, 0, 0, 1.0009f}; /* within 1e-3: normalised */
  size_t i;
  (void)state;
  for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    unsigned char b[SMGI_QPACK_BYTES];
    float u[4];
    assert_int_equal(smgi_quat_pack(bad[i], b), 0);
    smgi_quat_unpack(b, u);
    assert_true(u[0] == 0.0f && u[1] == 0.0f && u[2] == 0.0f &&
                u[3] == 1.0f);
  }
  {
    unsigned char b[SMGI_QPACK_BYTES];
    assert_int_equal(smgi_quat_pack(ok, b), 1);
  }
}

static void check_pattern(const unsigned char* b) {
  float u[4], r[4];
  double n2;
  smgi_quat_unpack(b, u);
  n2 = (double)u[0] * u[0] + (double)u[1] * u[1] + (double)u[2] * u[2] +
       (double)u[3] * u[3];
  if (!(fabs(n2 - 1.0) < 1e-6))
    fail_msg("bytes %02x%02x%02x%02x%02x%02x decode to length^2 %g", b[0],
             b[1], b[2], b[3], b[4], b[5], n2);
  smgi_quat_unpack_raw(b, r);
  n2 = (double)r[0] * r[0] + (double)r[1] * r[1] + (double)r[2] * r[2] +
       (double)r[3] * r[3];
  /* raw: finite, never shorter than unit, at most ~sqrt(1.5) long */
  if (!(n2 > 1.0 - 1e-6 && n2 < 1.51))
    fail_msg("raw decode of %02x%02x%02x%02x%02x%02x: length^2 %g", b[0],
             b[1], b[2], b[3], b[4], b[5], n2);
}

/* Every word-0 value against a set of word-1/word-2 pairs (all four index
 * values, both range ends, the middle), then random patterns. */
static void test_every_pattern_decodes_to_unit(void** state) {
  static const uint16_t other[] = {0x0000, 0x0001, 0xfffe, 0xffff,
                                   0x7ffe, 0x7fff, 0x8000, 0x8001,
                                   0x5a5b, 0xa5a4};
  const size_t no = sizeof other / sizeof other[0];
  uint32_t w0, i, n = smgt_quick() ? 20000u : 2000000u;
  size_t a, c, step = smgt_quick() ? 61 : 1;
  (void)state;
  for (w0 = 0; w0 < 65536u; w0 += (uint32_t)step)
    for (a = 0; a < no; ++a)
      for (c = 0; c < no; ++c) {
        uint16_t w[3];
        unsigned char b[6];
        w[0] = (uint16_t)w0;
        w[1] = other[a];
        w[2] = other[c];
        memcpy(b, w, sizeof b);
        check_pattern(b);
      }
  for (i = 0; i < n; ++i) {
    unsigned char b[6];
    uint32_t x = rnd32(), y = rnd32();
    memcpy(b, &x, 4);
    memcpy(b + 4, &y, 2);
    check_pattern(b);
  }
}

/* Whole records: root copied exactly, rotations within the bound, padding
 * zero for odd and even joint counts, non-unit rotations counted. */
static void test_pose_records(void** state) {
  uint32_t J;
  (void)state;
  assert_int_equal(SMGI_POSE_RECORD_SIZE(31), 200);
  assert_int_equal(SMGI_POSE_RECORD_SIZE(30), 192);
  assert_int_equal(SMGI_POSE_RECORD_SIZE(1), 20);
  for (J = 1; J <= 32; ++J) {
    float pose[SMGI_POSE_FLOATS(32)], back[SMGI_POSE_FLOATS(32)];
    unsigned char rec[SMGI_POSE_RECORD_SIZE(32) + 4];
    uint32_t j, size = SMGI_POSE_RECORD_SIZE(J), used = 12u + 6u * J;
    pose[0] = 1.25f;
    pose[1] = -0.5f;
    pose[2] = 3e4f;
    for (j = 0; j < J; ++j) random_quat(pose + 3 + 4 * j);
    memset(rec, 0xcc, sizeof rec);
    assert_int_equal(smgi_pose_pack(pose, J, rec), 0);
    assert_int_equal(size % 4u, 0);
    for (j = used; j < size; ++j) assert_int_equal(rec[j], 0);
    assert_int_equal(rec[size], 0xcc); /* nothing written past the record */
    smgi_pose_unpack(rec, J, back);
    assert_memory_equal(back, pose, 3 * sizeof(float));
    for (j = 0; j < J; ++j)
      assert_true(angle_between(back + 3 + 4 * j, pose + 3 + 4 * j) <=
                  MAX_ERROR_RAD);
    pose[3 + 4 * (J - 1) + 3] = NAN;
    assert_int_equal(smgi_pose_pack(pose, J, rec), 1);
  }
}

/* Four joints at a time (the runtime's SSE2 sampling) equals decoding each
 * joint and running the runtime's nlerp on it (what builds without SSE2
 * do), bit for bit: on neighbouring rotations (what consecutive frames
 * look like), unrelated ones (edge boundaries) and random bytes. */
static void test_nlerp4_matches_joint_by_joint(void** state) {
  uint32_t n = smgt_quick() ? 3000u : 100000u, it, k;
  (void)state;
  for (it = 0; it < n; ++it) {
    unsigned char a[24], b[24];
    float ref[16], fast[16];
    const float t = it % 7 == 0 ? 0.0f : it % 7 == 1 ? 1.0f : (float)rnd01();
    for (k = 0; k < 4; ++k) {
      float qa[4], qb[4];
      random_quat(qa);
      if (it % 3 == 0) {
        random_quat(qb); /* unrelated, often the other hemisphere */
      } else {
        uint32_t c;
        for (c = 0; c < 4; ++c)
          qb[c] = qa[c] + (float)(0.1 * (rnd01() - 0.5));
      }
      if (it % 5 == 4) {
        uint32_t c;
        for (c = 0; c < 6; ++c) {
          a[6 * k + c] = (unsigned char)rnd32();
          b[6 * k + c] = (unsigned char)rnd32();
        }
      } else {
        float nb = 0.0f;
        uint32_t c;
        for (c = 0; c < 4; ++c) nb += qb[c] * qb[c];
        for (c = 0; c < 4; ++c) qb[c] /= sqrtf(nb);
        assert_int_equal(smgi_quat_pack(qa, a + 6 * k), 1);
        assert_int_equal(smgi_quat_pack(qb, b + 6 * k), 1);
      }
    }
    for (k = 0; k < 4; ++k) {
      float ja[4], jb[4];
      smgi_quat_unpack_raw(a + 6 * k, ja);
      smgi_quat_unpack_raw(b + 6 * k, jb);
      smgi_q_nlerp(ja, jb, t, ref + 4 * k);
    }
#if SMGI_QPACK_SSE
    smgi_pose_nlerp4_sse(a, b, t, fast);
    assert_memory_equal(fast, ref, sizeof ref);
#else
    (void)fast;
#endif
  }
  printf("nlerp4: %s\n", SMGI_QPACK_SSE
                              ? "SSE2 path checked against joint by joint"
                              : "no SSE2: the runtime samples joint by joint");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_random_rotations_within_bound),
      cmocka_unit_test(test_awkward_rotations_within_bound),
      cmocka_unit_test(test_axis_aligned_and_sign),
      cmocka_unit_test(test_index_bits_and_layout),
      cmocka_unit_test(test_rejects_non_unit),
      cmocka_unit_test(test_every_pattern_decodes_to_unit),
      cmocka_unit_test(test_pose_records),
      cmocka_unit_test(test_nlerp4_matches_joint_by_joint),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
