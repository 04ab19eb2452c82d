/*
 * test_report.c - the bake's report (libsmg/bake/bake_report.c) and the
 * one home of its options (bake_options.c), each on its own: every
 * problem kept in order with its place, the first error, counts, the
 * retry mark, the text cut at whole lines; every bad option named, the
 * defaults and derived frame counts.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "bake_options.h"
#include "bake_report.h"

static void test_problems_in_order(void** state) {
  smgb_report r;
  char text[512];
  (void)state;
  smgb_report_init(&r, NULL, NULL);
  assert_string_equal(smgb_report_first_error(&r), "");
  smgb_warn(&r, "clip %d is short", 1);
  smgb_report_place(&r, "clip 2 (manifest line 7)");
  smgb_fail(&r, "no joint '%s'", "Hips");
  smgb_report_place(&r, NULL);
  smgb_fail(&r, "second");
  assert_int_equal(r.error_count, 2);
  assert_int_equal(r.warning_count, 1);
  assert_string_equal(smgb_report_first_error(&r),
                      "clip 2 (manifest line 7): no joint 'Hips'");
  assert_int_equal(smgb_report_text(&r, text, sizeof text), 3);
  assert_string_equal(text,
                      "warning: clip 1 is short\n"
                      "error: clip 2 (manifest line 7): no joint 'Hips'\n"
                      "error: second\n");
  smgb_report_free(&r);
}

/* A retried step forgets its failed attempt, the first error included. */
static void test_rewind(void** state) {
  smgb_report r;
  uint32_t mark;
  char text[256];
  (void)state;
  smgb_report_init(&r, NULL, NULL);
  smgb_warn(&r, "kept");
  mark = smgb_report_mark(&r);
  smgb_fail(&r, "attempt 1 failed");
  smgb_warn(&r, "attempt 1 warned");
  smgb_report_rewind(&r, mark);
  assert_int_equal(r.error_count, 0);
  assert_int_equal(r.warning_count, 1);
  assert_string_equal(smgb_report_first_error(&r), "");
  smgb_fail(&r, "attempt 2 failed");
  assert_string_equal(smgb_report_first_error(&r), "attempt 2 failed");
  smgb_report_text(&r, text, sizeof text);
  assert_string_equal(text, "warning: kept\nerror: attempt 2 failed\n");
  smgb_report_free(&r);
}

/* Many problems in a small buffer: whole lines, then how many are not
 * shown. */
static void test_text_cut(void** state) {
  smgb_report r;
  char text[200];
  uint32_t i, shown;
  (void)state;
  smgb_report_init(&r, NULL, NULL);
  for (i = 0; i < 40; ++i) smgb_fail(&r, "problem number %02u", i);
  assert_int_equal(r.error_count, 40);
  shown = smgb_report_text(&r, text, sizeof text);
  assert_true(shown > 0 && shown < 40);
  assert_true(strlen(text) < sizeof text);
  assert_non_null(strstr(text, "error: problem number 00\n"));
  {
    char tail[64];
    snprintf(tail, sizeof tail, "%u more problem(s) not shown\n", 40 - shown);
    assert_non_null(strstr(text, tail));
  }
  smgb_report_free(&r);
}

typedef struct seen {
  const char* stage;
  float last;
  int calls;
} seen;

static void on_progress(const char* stage, float fraction, void* user) {
  seen* s = user;
  s->stage = stage;
  s->last = fraction;
  ++s->calls;
}

static void test_progress(void** state) {
  smgb_report r;
  seen s = {NULL, -1.0f, 0};
  (void)state;
  smgb_report_init(&r, on_progress, &s);
  smgb_progress(&r, 0.5f); /* no stage yet: nothing */
  assert_int_equal(s.calls, 0);
  smgb_report_stage(&r, "import");
  smgb_progress(&r, 0.5f);
  assert_int_equal(s.calls, 2);
  assert_string_equal(s.stage, "import");
  assert_true(s.last == 0.5f);
  smgb_report_free(&r);
}

static void test_options_defaults(void** state) {
  smgb_report r;
  smgb_options o;
  (void)state;
  smgb_report_init(&r, NULL, NULL);
  assert_int_equal(smgb_options_resolve(NULL, &o, &r), SMG_OK);
  assert_true(o.frame_rate == SMGB_DEFAULT_FRAME_RATE);
  assert_int_equal(o.window, 10); /* 1/3 s at 30 Hz */
  assert_int_equal(o.max_edge_frames, 30);
  assert_true(o.transition_percentile == SMGB_DEFAULT_TRANSITION_PERCENTILE);
  assert_int_equal(o.splices_per_region, SMGB_DEFAULT_SPLICES_PER_REGION);
  assert_int_equal(o.threads, SMGB_DEFAULT_THREADS);
  assert_int_equal(r.problem_count, 0);
  smgb_report_free(&r);
}

/* Every value out of range is named, not only the first; threads are
 * capped, not refused; derived frame counts follow the given values. */
static void test_options_checked(void** state) {
  smgb_report r;
  smgb_options o;
  smg_bake_options in;
  char text[1024];
  (void)state;
  memset(&in, 0, sizeof in);
  in.struct_size = sizeof in;
  in.frame_rate = 60.0f;
  in.window_seconds = 0.5f;
  in.threads = 64;
  smgb_report_init(&r, NULL, NULL);
  assert_int_equal(smgb_options_resolve(&in, &o, &r), SMG_OK);
  assert_int_equal(o.window, 30);
  assert_int_equal(o.max_edge_frames, 60);
  assert_int_equal(o.threads, SMGB_MAX_THREADS);
  in.frame_rate = NAN;
  in.contact_speed = -1.0f;
  in.transition_percentile = 101.0f;
  in.splices_per_region = SMGB_MAX_SPLICES_PER_REGION + 1;
  assert_int_equal(smgb_options_resolve(&in, &o, &r),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(r.error_count, 4);
  smgb_report_text(&r, text, sizeof text);
  assert_non_null(strstr(text, "options.frame_rate"));
  assert_non_null(strstr(text, "options.contact_speed"));
  assert_non_null(strstr(text, "options.transition_percentile"));
  assert_non_null(strstr(text, "options.splices_per_region"));
  smgb_report_free(&r);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_problems_in_order),
      cmocka_unit_test(test_rewind),
      cmocka_unit_test(test_text_cut),
      cmocka_unit_test(test_progress),
      cmocka_unit_test(test_options_defaults),
      cmocka_unit_test(test_options_checked),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
