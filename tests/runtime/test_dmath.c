/*
 * test_dmath.c - the runtime's own sine, cosine and atan2
 * (libsmg/runtime/dmath.h): within 1 ulp of the exact values (libm's
 * double functions stand in for them), C's conventions at zeros,
 * infinities and NaN, and the bits of a few thousand results pinned, so
 * a platform or compiler that computes them differently (a fused
 * multiply-add, x87 excess precision) fails here instead of silently
 * planning different motion from the same inputs.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
/* cmocka after the standard headers it needs */
#include <cmocka.h>

#include "dmath.h"
#include "rmath.h"

static uint32_t rng = 2463534242u;
static float frand(float lo, float hi) {
  return lo + (hi - lo) * (float)(smgi_xorshift(&rng) >> 8) * (1.0f / 16777216.0f);
}

/* |got - exact| in units of the float spacing at the exact value */
static double ulps(float got, double exact) {
  float e = (float)exact;
  double ulp = (double)nextafterf(fabsf(e), INFINITY) - (double)fabsf(e);
  return fabs((double)got - exact) / ulp;
}

static void test_sincos_accuracy(void** state) {
  (void)state;
  double worst_s = 0.0, worst_c = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    /* mostly headings, some far outside (-pi, pi], some tiny */
    float x = i % 10 == 0   ? frand(-1e4f, 1e4f)
              : i % 10 == 1 ? frand(-1e-3f, 1e-3f)
                            : frand(-8.0f, 8.0f);
    float s, c;
    smgi_sincosf(x, &s, &c);
    double es = ulps(s, sin((double)x)), ec = ulps(c, cos((double)x));
    if (es > worst_s) worst_s = es;
    if (ec > worst_c) worst_c = ec;
    if (!(es <= 1.0 && ec <= 1.0))
      fail_msg("sincos(%.9g) = %.9g, %.9g (%.2f, %.2f ulp)", (double)x,
               (double)s, (double)c, es, ec);
    assert_true(smgi_sinf(x) == s && smgi_cosf(x) == c);
  }
  print_message("sincos: worst %.3f / %.3f ulp\n", worst_s, worst_c);
}

static void test_atan2_accuracy(void** state) {
  (void)state;
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    float y = frand(-4.0f, 4.0f), x = frand(-4.0f, 4.0f);
    if (i % 7 == 0) y *= 1e-4f; /* nearly along an axis */
    if (i % 11 == 0) x *= 1e-4f;
    float a = smgi_atan2f(y, x);
    double e = ulps(a, atan2((double)y, (double)x));
    if (e > worst) worst = e;
    if (!(e <= 1.0))
      fail_msg("atan2(%.9g, %.9g) = %.9g (%.2f ulp)", (double)y, (double)x,
               (double)a, e);
  }
  print_message("atan2: worst %.3f ulp\n", worst);
}

static void test_special_values(void** state) {
  (void)state;
  const float pi = (float)3.141592653589793;
  assert_true(smgi_atan2f(0.0f, 0.0f) == 0.0f && !signbit(smgi_atan2f(0.0f, 0.0f)));
  assert_true(smgi_atan2f(-0.0f, 0.0f) == 0.0f && signbit(smgi_atan2f(-0.0f, 0.0f)));
  assert_true(smgi_atan2f(0.0f, -0.0f) == pi);
  assert_true(smgi_atan2f(-0.0f, -1.0f) == -pi);
  assert_true(smgi_atan2f(1.0f, 0.0f) == (float)1.5707963267948966);
  assert_true(smgi_atan2f(-1.0f, 0.0f) == -(float)1.5707963267948966);
  assert_true(smgi_atan2f(1.0f, 1.0f) == (float)0.7853981633974483);
  assert_true(smgi_atan2f(INFINITY, INFINITY) == (float)0.7853981633974483);
  assert_true(smgi_atan2f(1.0f, INFINITY) == 0.0f);
  assert_true(smgi_atan2f(1.0f, -INFINITY) == pi);
  assert_true(isnan(smgi_atan2f(NAN, 1.0f)) && isnan(smgi_atan2f(1.0f, NAN)));
  float s, c;
  smgi_sincosf(0.0f, &s, &c);
  assert_true(s == 0.0f && c == 1.0f);
  smgi_sincosf(-0.0f, &s, &c);
  assert_true(s == 0.0f && signbit(s) && c == 1.0f);
  smgi_sincosf(NAN, &s, &c);
  assert_true(isnan(s) && isnan(c));
  smgi_sincosf(INFINITY, &s, &c);
  assert_true(isnan(s) && isnan(c));
  smgi_sincosf(-INFINITY, &s, &c);
  assert_true(isnan(s) && isnan(c));
  /* large angles stay accurate; any finite one gives a point on the
   * unit circle */
  const float big[3] = {1e7f, -3.3e9f, 3.4e38f};
  for (int i = 0; i < 3; ++i) {
    smgi_sincosf(big[i], &s, &c);
    assert_true(fabs((double)s * s + (double)c * c - 1.0) < 1e-6);
    if (i < 2) {
      assert_true(fabs((double)s - sin((double)big[i])) < 1e-5);
      assert_true(fabs((double)c - cos((double)big[i])) < 1e-5);
    }
  }
}

/* FNV-1a over the bits of results for fixed inputs: the value is what
 * IEEE arithmetic gives, the same on every platform and C library. */
static uint32_t fnv(uint32_t h, float v) {
  uint32_t b;
  memcpy(&b, &v, sizeof b);
  for (int k = 0; k < 4; ++k) {
    h ^= (b >> (8 * k)) & 0xffu;
    h *= 16777619u;
  }
  return h;
}

static void test_pinned_bits(void** state) {
  (void)state;
  uint32_t r = 88172645u, h = 2166136261u;
  for (int i = 0; i < 4096; ++i) {
    float a = ((float)(smgi_xorshift(&r) >> 8) * (1.0f / 16777216.0f) - 0.5f) * 20.0f;
    float b = ((float)(smgi_xorshift(&r) >> 8) * (1.0f / 16777216.0f) - 0.5f) * 20.0f;
    float s, c;
    smgi_sincosf(a, &s, &c);
    h = fnv(fnv(fnv(h, s), c), smgi_atan2f(a, b));
  }
  print_message("pinned hash %08x\n", h);
  assert_int_equal(h, 0x5ddda3fdu);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_sincos_accuracy),
      cmocka_unit_test(test_atan2_accuracy),
      cmocka_unit_test(test_special_values),
      cmocka_unit_test(test_pinned_bits),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
