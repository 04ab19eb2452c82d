/*
 * test_bvh_errors.c - every kind of malformed BVH gives the expected error
 * code and a message naming file:line (and never crashes or leaks: this
 * program also runs under valgrind).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_clip.h"
#include "import_helpers.h"

/* Lines 1-15: a valid two-joint hierarchy. */
#define HIER                                                                \
  "HIERARCHY\n"                                                   /* 1 */   \
  "ROOT Hips\n"                                                   /* 2 */   \
  "{\n"                                                           /* 3 */   \
  "\tOFFSET 0 0 0\n"                                              /* 4 */   \
  "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation " \
  "Xrotation\n"                                                   /* 5 */   \
  "\tJOINT Spine\n"                                               /* 6 */   \
  "\t{\n"                                                         /* 7 */   \
  "\t\tOFFSET 0 1 0\n"                                            /* 8 */   \
  "\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n"                /* 9 */   \
  "\t\tEnd Site\n"                                                /* 10 */  \
  "\t\t{\n"                                                       /* 11 */  \
  "\t\t\tOFFSET 0 1 0\n"                                          /* 12 */  \
  "\t\t}\n"                                                       /* 13 */  \
  "\t}\n"                                                         /* 14 */  \
  "}\n"                                                           /* 15 */
#define MOTION2                                                             \
  "MOTION\n"                                                      /* 16 */  \
  "Frames: 2\n"                                                   /* 17 */  \
  "Frame Time: 0.0333333\n"                                       /* 18 */
#define ROW "0 1 0 0 0 0 0 0 0\n"

typedef struct bad_case {
  const char* what;
  const char* text;
  smg_result code;
  int line;             /* expected line in "bad.bvh:LINE:" */
  const char* needle;   /* a word the message must contain */
} bad_case;

static const bad_case k_cases[] = {
    {"empty file", "", SMG_ERROR_PARSE, 1, "HIERARCHY"},
    {"not a BVH", "hello world\n", SMG_ERROR_PARSE, 1, "HIERARCHY"},
    {"truncated in hierarchy", "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n",
     SMG_ERROR_PARSE, 4, "end of file"},
    {"truncated in offset", "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0",
     SMG_ERROR_PARSE, 4, "end of file"},
    {"too few channel names",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 3 Zrotation "
     "Yrotation\n\tJOINT A\n",
     SMG_ERROR_PARSE, 6, "declares 3 channels"},
    {"channel count 7",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 7 Xposition\n",
     SMG_ERROR_PARSE, 5, "0..6"},
    {"unknown channel",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Wrotation\n",
     SMG_ERROR_PARSE, 5, "Wrotation"},
    {"repeated channel",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 2 Xrotation "
     "Xrotation\n",
     SMG_ERROR_PARSE, 5, "twice"},
    {"missing MOTION", HIER, SMG_ERROR_PARSE, 15, "MOTION"},
    {"garbage instead of MOTION", HIER "MOTON\n", SMG_ERROR_PARSE, 16,
     "MOTION"},
    {"missing Frames", HIER "MOTION\nFrame Time: 0.03\n", SMG_ERROR_PARSE, 17,
     "Frames:"},
    {"missing Frame Time", HIER "MOTION\nFrames: 2\n" ROW ROW,
     SMG_ERROR_PARSE, 18, "Frame Time"},
    {"non-numeric frame count", HIER "MOTION\nFrames: two\n",
     SMG_ERROR_PARSE, 17, "not a number"},
    {"fractional frame count", HIER "MOTION\nFrames: 2.5\n", SMG_ERROR_PARSE,
     17, "whole"},
    {"zero frames", HIER "MOTION\nFrames: 0\nFrame Time: 0.03\n",
     SMG_ERROR_PARSE, 17, "zero frames"},
    {"zero frame time", HIER "MOTION\nFrames: 2\nFrame Time: 0\n" ROW ROW,
     SMG_ERROR_PARSE, 18, "frame time"},
    {"NaN frame time", HIER "MOTION\nFrames: 2\nFrame Time: nan\n" ROW ROW,
     SMG_ERROR_PARSE, 18, "finite"},
    {"non-numeric value", HIER MOTION2 ROW "0 1 0 0 zero 0 0 0 0\n",
     SMG_ERROR_PARSE, 20, "not a number"},
    {"NaN value", HIER MOTION2 "0 1 0 nan 0 0 0 0 0\n" ROW, SMG_ERROR_PARSE,
     19, "finite"},
    {"inf value", HIER MOTION2 ROW "0 1 0 0 0 0 0 0 -inf\n", SMG_ERROR_PARSE,
     20, "finite"},
    {"huge value", HIER MOTION2 "0 1e7 0 0 0 0 0 0 0\n" ROW, SMG_ERROR_PARSE,
     19, "too large"},
    {"huge offset",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 2e6 0\n", SMG_ERROR_PARSE, 4,
     "too large"},
    {"NaN offset", "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 NaN 0\n",
     SMG_ERROR_PARSE, 4, "finite"},
    {"too few values on a line", HIER MOTION2 ROW "0 1 0 0 0 0 0 0\n",
     SMG_ERROR_PARSE, 20, "9 channels"},
    {"too many values on a line", HIER MOTION2 "0 1 0 0 0 0 0 0 0 0\n" ROW,
     SMG_ERROR_PARSE, 19, "9 channels"},
    {"truncated motion (fewer frames)", HIER MOTION2 ROW, SMG_ERROR_PARSE, 20,
     "truncated"},
    {"truncated mid-line", HIER MOTION2 ROW "0 1 0 0", SMG_ERROR_PARSE, 20,
     "9 channels"},
    {"more frames than declared", HIER MOTION2 ROW ROW ROW, SMG_ERROR_PARSE,
     21, "more frame lines"},
    {"too many frames",
     HIER "MOTION\nFrames: 20000000\nFrame Time: 0.03\n" ROW,
     SMG_ERROR_CAPACITY, 17, "too many frames"},
    {"extra closing brace", HIER "}\n" MOTION2 ROW ROW, SMG_ERROR_PARSE, 16,
     "MOTION"},
    {"missing closing brace",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "MOTION\nFrames: 1\nFrame Time: 0.03\n0\n",
     SMG_ERROR_PARSE, 6, "MOTION"},
    {"overlong token",
     "HIERARCHY\nROOT "
     "Hips_aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
     "aaaaaaaaaa\n",
     SMG_ERROR_PARSE, 2, "longer than"},
    {"overlong value", HIER MOTION2 ROW
     "0 1 0 0 0 0 0 0 "
     "0.00000000000000000000000000000000000000000000000000000000000000000000"
     "1\n",
     SMG_ERROR_PARSE, 20, "longer than"},
    {"duplicate joint name",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "\tJOINT Hips\n",
     SMG_ERROR_PARSE, 6, "duplicate"},
    {"missing OFFSET",
     "HIERARCHY\nROOT Hips\n{\n\tCHANNELS 1 Xrotation\n}\n", SMG_ERROR_PARSE,
     5, "OFFSET"},
    {"missing CHANNELS", "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n}\n",
     SMG_ERROR_PARSE, 5, "CHANNELS"},
    {"no channels at all",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 0\n}\n",
     SMG_ERROR_PARSE, 6, "no channels"},
    {"two roots",
     "HIERARCHY\nROOT A\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n}\n"
     "ROOT B\n",
     SMG_ERROR_PARSE, 7, "ROOT"},
    {"junk inside joint",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "\tWHATEVER\n",
     SMG_ERROR_PARSE, 6, "WHATEVER"},
    {"End Site without offset",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "\tEnd Site\n\t{\n\t}\n",
     SMG_ERROR_PARSE, 8, "End Site"},
    {"End Site with a joint inside",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "\tEnd Site\n\t{\n\tOFFSET 0 1 0\n\tJOINT X\n",
     SMG_ERROR_PARSE, 9, "End Site"},
    /* The root rotates, so it is not a static root that could be folded
     * into A; A's translation (0.5 on a 1.25 bone) is no noise either. */
    {"animated non-root translation",
     "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 1 Xrotation\n"
     "\tJOINT A\n\t{\n\t\tOFFSET 0 1 0\n"
     "\t\tCHANNELS 4 Xposition Yposition Zposition Xrotation\n"
     "\t}\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n0 0 1 0 0\n10 0 1.5 0 0\n",
     SMG_ERROR_UNSUPPORTED, 9, "animated position"},
    {"only the T-pose frame", HIER "MOTION\nFrames: 1\nFrame Time: 0.03\n" ROW,
     SMG_ERROR_PARSE, 17, "T-pose"},
};

static void check_case(const bad_case* c, uint32_t skip) {
  smgb_clip clip;
  smgb_error err;
  char want[64];
  smg_result r;
  memset(&clip, 0xab, sizeof clip);
  r = smgb_bvh_parse(c->text, strlen(c->text), "bad.bvh", 1.0f, skip, &clip,
                     &err);
  snprintf(want, sizeof want, "bad.bvh:%d:", c->line);
  if (r != c->code || !strstr(err.message, want) ||
      !strstr(err.message, c->needle)) {
    print_error("case '%s': got %s \"%s\", want %s with \"%s\" and \"%s\"\n",
                c->what, smg_result_string(r), err.message,
                smg_result_string(c->code), want, c->needle);
    fail();
  }
}

static void test_bad_inputs(void** state) {
  size_t i;
  (void)state;
  for (i = 0; i < sizeof k_cases / sizeof k_cases[0]; ++i)
    check_case(&k_cases[i], strstr(k_cases[i].what, "T-pose") ? 1u : 0u);
}

/* Every prefix of a valid file is either a valid file or a clean error. */
static void test_every_truncation(void** state) {
  static const char text[] = HIER MOTION2 ROW "0 1.5 0 10 20 30 40 50 60\n";
  size_t n = strlen(text), k;
  (void)state;
  for (k = 0; k < n; ++k) {
    smgb_clip clip;
    smgb_error err;
    smg_result r = smgb_bvh_parse(text, k, "cut.bvh", 1.0f, 0, &clip, &err);
    if (r == SMG_OK) {
      /* Only a cut inside the last value ("...50 6") can still parse. */
      assert_true(k >= n - 2);
      smgb_clip_free(&clip);
    } else {
      assert_int_equal(r, SMG_ERROR_PARSE);
      assert_non_null(strstr(err.message, "cut.bvh:"));
    }
  }
}

/* Too many joints: a chain deeper than the 512-joint limit. */
static void test_too_many_joints(void** state) {
  size_t cap = 700 * 64 + 256, len = 0;
  char* t = (char*)malloc(cap);
  int i;
  smgb_clip clip;
  smgb_error err;
  smg_result r;
  (void)state;
  assert_non_null(t);
  len += (size_t)sprintf(t + len, "HIERARCHY\nROOT J0\n{\nOFFSET 0 1 0\n"
                                  "CHANNELS 1 Xrotation\n");
  for (i = 1; i < 600; ++i)
    len += (size_t)sprintf(t + len, "JOINT J%d\n{\nOFFSET 0 1 0\n"
                                    "CHANNELS 1 Xrotation\n", i);
  r = smgb_bvh_parse(t, len, "deep.bvh", 1.0f, 0, &clip, &err);
  assert_int_equal(r, SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "too many joints"));
  /* Joint 512 (J512) is declared on line 5 + 511 * 4 + 1. */
  assert_non_null(strstr(err.message, "deep.bvh:2050:"));
  free(t);
}

/* NUL bytes and other binary garbage are reported, not trusted. */
static void test_binary_garbage(void** state) {
  static const char text[] = "HIERARCHY\nROOT H\0ps\n{\n";
  smgb_clip clip;
  smgb_error err;
  smg_result r;
  (void)state;
  r = smgb_bvh_parse(text, sizeof text - 1, "nul.bvh", 1.0f, 0, &clip, &err);
  assert_int_equal(r, SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "nul.bvh:"));
}

static void test_invalid_arguments(void** state) {
  smgb_clip clip;
  smgb_error err;
  static const char text[] = HIER MOTION2 ROW ROW;
  (void)state;
  assert_int_equal(smgb_bvh_parse(text, strlen(text), "x", 1.0f, 0, NULL, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_bvh_parse(NULL, 5, "x", 1.0f, 0, &clip, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(
      smgb_bvh_parse(text, strlen(text), "x", -1.0f, 0, &clip, &err),
      SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_bvh_load(NULL, 1.0f, 0, &clip, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  /* A NULL error pointer is allowed. */
  assert_int_equal(smgb_bvh_parse("", 0, "x", 1.0f, 0, &clip, NULL),
                   SMG_ERROR_PARSE);
}

static void test_missing_file(void** state) {
  smgb_clip clip;
  smgb_error err;
  smg_result r;
  (void)state;
  r = smgb_bvh_load("/nonexistent/dir/clip.bvh", 0.0f, 1, &clip, &err);
  assert_int_equal(r, SMG_ERROR_IO);
  assert_non_null(strstr(err.message, "/nonexistent/dir/clip.bvh"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bad_inputs),
      cmocka_unit_test(test_every_truncation),
      cmocka_unit_test(test_too_many_joints),
      cmocka_unit_test(test_binary_garbage),
      cmocka_unit_test(test_invalid_arguments),
      cmocka_unit_test(test_missing_file),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
