/*
 * test_path.c - the path internals: arc lengths, evaluation by arc length,
 * the pruned one-pass nearest-point search used by set_path against brute
 * force, local projection, and the finite check.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "path.h"
#include "rmath.h"
#include "runtime/runtime_testutil.h"

#define CAP 4096

typedef struct buf {
  float xz[2 * CAP], cum[CAP];
} buf;

static smgi_path make(buf* b) {
  smgi_path p;
  p.xz = b->xz;
  p.cum = b->cum;
  p.capacity = CAP;
  smgi_path_reset(&p);
  return p;
}

static uint32_t rng = 12345;
static float frand(void) { return (float)(smgi_xorshift(&rng) % 100000) / 100000.0f; }

static void test_lengths_and_eval(void** state) {
  (void)state;
  static buf b;
  smgi_path p = make(&b);
  float pts[8] = {0, 0, 3, 4, 3, 10, 3, 10}; /* last segment zero length */
  uint32_t seg = 0;
  float d;
  smgi_path_load(&p, pts, 0, 2, 0, 0, 0, &seg, &d);
  smgi_path_load(&p, pts + 4, 2, 2, 0, 0, 0, &seg, &d); /* append */
  assert_int_equal(p.count, 4);
  assert_float_equal(p.length, 11.0f, 1e-5f);
  float x, z, h;
  seg = 0;
  smgi_path_eval(&p, 2.5f, &seg, &x, &z, &h);
  assert_float_equal(x, 1.5f, 1e-5f);
  assert_float_equal(z, 2.0f, 1e-5f);
  assert_float_equal(h, atan2f(3, 4), 1e-5f);
  smgi_path_eval(&p, 8.0f, &seg, &x, &z, &h);
  assert_float_equal(x, 3.0f, 1e-5f);
  assert_float_equal(z, 7.0f, 1e-5f);
  assert_float_equal(h, 0.0f, 1e-5f);
  /* beyond the end clamps; a zero-length segment still has a heading */
  smgi_path_eval(&p, 50.0f, &seg, &x, &z, &h);
  assert_float_equal(z, 10.0f, 1e-5f);
  assert_true(isfinite(h));
  smgi_path_eval(&p, -5.0f, &seg, &x, &z, &h);
  assert_float_equal(x, 0.0f, 1e-6f);
}

static void test_projection_matches_brute_force(void** state) {
  (void)state;
  static buf b;
  static float pts[2 * CAP];
  for (int trial = 0; trial < 200; ++trial) {
    uint32_t n = 1 + smgi_xorshift(&rng) % (trial < 100 ? 12u : CAP);
    float x = 0, z = 0;
    for (uint32_t i = 0; i < n; ++i) {
      /* random walks with both tiny and long segments */
      float step = (i % 7 == 0) ? 20.0f * frand() : 0.3f * frand();
      float a = 6.2831853f * frand();
      x += step * sinf(a);
      z += step * cosf(a);
      pts[2 * i] = x;
      pts[2 * i + 1] = z;
    }
    smgi_path p = make(&b);
    float qx = 40.0f * frand() - 20.0f, qz = 40.0f * frand() - 20.0f;
    uint32_t seg1 = 0, seg2 = 0;
    float d1, d2;
    float s1 = smgi_path_load(&p, pts, 0, n, 1, qx, qz, &seg1, &d1);
    float s2 = smgi_path_project_global(&p, qx, qz, &seg2, &d2);
    /* set_path keeps the earliest pass within 2 cm of the nearest (a
     * closed loop starts where it ends): never nearer than brute force,
     * never more than the tie margin further */
    assert_true(d1 >= d2 - 1e-4f && d1 <= d2 + 0.02f + 1e-4f);
    if (fabsf(s1 - s2) > 1e-3f) {
      /* equally near points elsewhere are fine; the distance decides */
      float ex, ez;
      uint32_t sg = 0;
      smgi_path_eval(&p, s1, &sg, &ex, &ez, NULL);
      float dd = sqrtf((ex - qx) * (ex - qx) + (ez - qz) * (ez - qz));
      assert_float_equal(dd, d1, 1e-3f);
      assert_true(s1 <= s2 + 1e-3f); /* ties go to the earlier pass */
    }
  }
}

/* The set_path projection's rule spelled out with no pruning at all:
 * every segment in order, a later one replaces the best only when nearer
 * by more than 2 cm. The pruned, blocked search must give the same
 * segment and the same arc length bit for bit. */
static float rule_projection(const smgi_path* p, float px, float pz,
                             uint32_t* out_seg) {
  float best2 = INFINITY, best = INFINITY, s_best = 0.0f;
  for (uint32_t i = 0; i + 1u < p->count; ++i) {
    const float* a = &p->xz[2u * i];
    float dx = a[2] - a[0], dz = a[3] - a[1];
    float l2 = dx * dx + dz * dz, u = 0.0f;
    float qx = px - a[0], qz = pz - a[1];
    if (l2 > 1e-18f) u = smgi_clampf((qx * dx + qz * dz) / l2, 0.0f, 1.0f);
    float ex = a[0] + u * dx - px, ez = a[1] + u * dz - pz;
    float d2 = ex * ex + ez * ez, t = best - 0.02f;
    if (d2 < best2 && (best2 == INFINITY || (t > 0.0f && d2 < t * t))) {
      best2 = d2;
      best = sqrtf(d2);
      s_best = p->cum[i] + u * (p->cum[i + 1u] - p->cum[i]);
      *out_seg = i;
    }
  }
  return s_best;
}

static void test_projection_is_the_rule(void** state) {
  (void)state;
  static buf b;
  static float pts[2 * CAP];
  for (int trial = 0; trial < 300; ++trial) {
    uint32_t n = 2 + smgi_xorshift(&rng) % (trial < 100 ? 70u : CAP - 2u);
    int kind = trial % 3;
    float x = 0, z = 0;
    for (uint32_t i = 0; i < n; ++i) {
      if (kind == 0) { /* dense wiggly line, 1 cm spacing */
        z = 0.01f * (float)i;
        x = 0.7f * sinf(z * 1.3f);
      } else if (kind == 1) { /* closed loops passed several times */
        float a = 6.2831853f * 3.0f * (float)i / (float)n;
        x = 4.0f * sinf(a);
        z = 4.0f * cosf(a) + 100.0f; /* offset: rounding of larger cums */
      } else { /* random walk, tiny and long segments, repeats */
        float step = (i % 5 == 0) ? 0.0f : (i % 7 == 0) ? 15.0f * frand()
                                                         : 0.2f * frand();
        float a = 6.2831853f * frand();
        x += step * sinf(a);
        z += step * cosf(a);
      }
      pts[2 * i] = x;
      pts[2 * i + 1] = z;
    }
    smgi_path p = make(&b);
    /* query points on, near and far from the path */
    uint32_t k = smgi_xorshift(&rng) % n;
    float off = (trial % 4 == 0) ? 0.0f : (trial % 4 == 1) ? 0.01f : 5.0f * frand();
    float qx = pts[2 * k] + off, qz = pts[2 * k + 1] - 0.5f * off;
    uint32_t seg = 0, seg_rule = 0;
    float d;
    float s = smgi_path_load(&p, pts, 0, n, 1, qx, qz, &seg, &d);
    float s_rule = rule_projection(&p, qx, qz, &seg_rule);
    assert_int_equal(seg, seg_rule);
    assert_true(s == s_rule);
  }
}

/* Evaluation by arc length from any hint lands on the last segment whose
 * start is at or before s (galloping from far hints included). */
static void test_eval_from_any_hint(void** state) {
  (void)state;
  static buf b;
  static float pts[2 * CAP];
  smgi_path p = make(&b);
  uint32_t n = CAP;
  float x = 0, z = 0;
  for (uint32_t i = 0; i < n; ++i) {
    float step = (i % 9 == 0) ? 0.0f : 0.05f + frand(); /* some repeats */
    x += step * 0.6f;
    z += step * 0.8f;
    pts[2 * i] = x;
    pts[2 * i + 1] = z;
  }
  uint32_t seg = 0;
  float d;
  smgi_path_load(&p, pts, 0, n, 0, 0, 0, &seg, &d);
  for (int q = 0; q < 20000; ++q) {
    float s = p.length * frand();
    uint32_t hint = smgi_xorshift(&rng) % (n + 5u); /* some out of range */
    float ex, ez;
    seg = hint;
    smgi_path_eval(&p, s, &seg, &ex, &ez, NULL);
    assert_true(seg + 1u < n);
    /* the segment holds s */
    assert_true(p.cum[seg] <= s && s <= p.cum[seg + 1u]);
    /* and the point is where s says */
    float u = (s - p.cum[seg]) / (p.cum[seg + 1u] - p.cum[seg] + 1e-30f);
    float wx = pts[2 * seg] + u * (pts[2 * seg + 2] - pts[2 * seg]);
    assert_float_equal(ex, wx, 1e-3f);
  }
}

/* smgi_path_segment (inline for a hint that already holds s) and
 * smgi_path_find give the segment smgi_path_eval puts s on, from any hint:
 * on and between segment ends (also of zero-length segments), before the
 * start and past the end. */
static void test_segment_lookup_is_eval_s(void** state) {
  (void)state;
  static buf b;
  static float pts[2 * 600];
  smgi_path p = make(&b);
  const uint32_t n = 600;
  float x = 0, z = 0;
  for (uint32_t i = 0; i < n; ++i) {
    float step = (i % 7 == 0) ? 0.0f : 0.05f + 2.0f * frand();
    x += step * 0.6f;
    z += step * 0.8f;
    pts[2 * i] = x;
    pts[2 * i + 1] = z;
  }
  uint32_t seg = 0;
  float d;
  smgi_path_load(&p, pts, 0, n, 0, 0, 0, &seg, &d);
  for (int q = 0; q < 40000; ++q) {
    const uint32_t r = smgi_xorshift(&rng) % 4u;
    float s = (p.length + 2.0f) * frand() - 1.0f;
    if (r == 0) s = p.cum[smgi_xorshift(&rng) % n]; /* exactly on an end */
    const uint32_t hint = smgi_xorshift(&rng) % (n + 3u);
    float ex, ez;
    seg = hint;
    smgi_path_eval(&p, s, &seg, &ex, &ez, NULL);
    assert_int_equal(smgi_path_segment(&p, s, hint), seg);
    assert_int_equal(smgi_path_find(&p, s, hint), seg);
  }
}

static void test_local_projection(void** state) {
  (void)state;
  static buf b;
  static float pts[2 * 1001];
  smgi_path p = make(&b);
  rt_line(pts, 1001, 100.0f);
  uint32_t seg = 0;
  float d;
  smgi_path_load(&p, pts, 0, 1001, 0, 0, 0, &seg, &d);
  /* walking along: the local search follows a moving point */
  seg = 0;
  for (int i = 0; i <= 100; ++i) {
    float s = smgi_path_project_local(&p, 0.3f, (float)i * 0.9f, &seg, &d);
    assert_float_equal(s, (float)i * 0.9f, 1e-3f);
    assert_float_equal(d, 0.3f, 1e-4f);
  }
}

/* Path coordinates: finite and below SMG_MAX_COORDINATE in magnitude (the
 * runtime fuzzer found a path with 3e38 coordinates: its length overflowed
 * to inf and every arc length after it was meaningless). */
static void test_coords_ok(void** state) {
  (void)state;
  float v[7] = {0, 1, -2, 1048575.9f, -1e-40f, 5, -1048575.9f};
  assert_true(smgi_coords_ok(v, 7));
  for (int i = 0; i < 7; ++i) {
    float keep = v[i];
    v[i] = NAN;
    assert_false(smgi_coords_ok(v, 7));
    v[i] = -INFINITY;
    assert_false(smgi_coords_ok(v, 7));
    v[i] = SMG_MAX_COORDINATE;
    assert_false(smgi_coords_ok(v, 7));
    v[i] = -3e38f;
    assert_false(smgi_coords_ok(v, 7));
    v[i] = keep;
  }
  assert_true(smgi_coords_ok(v, 0));
  /* every length and position through the unrolled body and the tail */
  float w[41];
  for (uint32_t n = 0; n <= 41; ++n) {
    for (uint32_t i = 0; i < 41; ++i) w[i] = (float)i - 20.0f;
    assert_true(smgi_coords_ok(w, n));
    for (uint32_t i = 0; i < n; ++i) {
      w[i] = (i % 3u == 0) ? INFINITY : (i % 3u == 1) ? NAN : 2e6f;
      assert_false(smgi_coords_ok(w, n));
      w[i] = 1.0f;
    }
    if (n < 41) { /* a bad value just past the end is not looked at */
      w[n] = NAN;
      assert_true(smgi_coords_ok(w, n));
    }
  }
}

/* smgi_wrap_angle is O(1): huge finite angles (the blob fuzzer found a
 * loop that never ended on them) come back in (-pi, pi] and equal to the
 * input modulo 2 pi; small ones are unchanged. */
static void test_wrap_angle(void** state) {
  (void)state;
  assert_true(smgi_wrap_angle(0.5f) == 0.5f);
  assert_true(smgi_wrap_angle(SMGI_PI) == SMGI_PI);
  assert_true(fabsf(smgi_wrap_angle(-SMGI_PI) - SMGI_PI) < 1e-5f);
  assert_true(fabsf(smgi_wrap_angle(3.0f * SMGI_PI) - SMGI_PI) < 1e-5f);
  assert_true(fabsf(smgi_wrap_angle(7.0f) - (7.0f - 2.0f * SMGI_PI)) < 1e-5f);
  assert_true(fabsf(smgi_wrap_angle(-7.0f) + (7.0f - 2.0f * SMGI_PI)) < 1e-5f);
  const float huge[] = {1e30f, -1e30f, 3.4e38f, -3.4e38f, 123456.7f, 1e9f};
  for (size_t i = 0; i < sizeof huge / sizeof huge[0]; ++i) {
    float w = smgi_wrap_angle(huge[i]);
    assert_true(w > -SMGI_PI - 1e-6f && w <= SMGI_PI + 1e-6f);
    /* same direction as the input (sin/cos agree up to float rounding of
     * the input itself, which for 1e30 is already many turns) */
    if (fabsf(huge[i]) < 1e6f) {
      assert_true(fabsf(sinf(w) - sinf(huge[i])) < 1e-2f);
      assert_true(fabsf(cosf(w) - cosf(huge[i])) < 1e-2f);
    }
  }
  assert_true(isnan(smgi_wrap_angle(NAN)));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_lengths_and_eval),
      cmocka_unit_test(test_projection_matches_brute_force),
      cmocka_unit_test(test_projection_is_the_rule),
      cmocka_unit_test(test_eval_from_any_hint),
      cmocka_unit_test(test_segment_lookup_is_eval_s),
      cmocka_unit_test(test_local_projection),
      cmocka_unit_test(test_coords_ok),
      cmocka_unit_test(test_wrap_angle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
