/*
 * test_result.c - version and result-name API.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "smg.h"

static void test_version_matches_header(void** state) {
  (void)state;
  assert_int_equal(smg_version(), SMG_VERSION);
  assert_int_equal(SMG_VERSION >> 16, SMG_VERSION_MAJOR);
  assert_int_equal((SMG_VERSION >> 8) & 0xff, SMG_VERSION_MINOR);
  assert_int_equal(SMG_VERSION & 0xff, SMG_VERSION_PATCH);
  assert_true(SMG_BLOB_VERSION_MIN <= SMG_BLOB_VERSION_MAX);
}

/* Every code has its own string that starts with the enumerator's name. */
static void test_result_strings_name_their_code(void** state) {
  static const struct {
    smg_result code;
    const char* name;
  } k[] = {
      {SMG_OK, "SMG_OK"},
      {SMG_ERROR_INVALID_ARGUMENT, "SMG_ERROR_INVALID_ARGUMENT"},
      {SMG_ERROR_OUT_OF_MEMORY, "SMG_ERROR_OUT_OF_MEMORY"},
      {SMG_ERROR_IO, "SMG_ERROR_IO"},
      {SMG_ERROR_BLOB_TRUNCATED, "SMG_ERROR_BLOB_TRUNCATED"},
      {SMG_ERROR_BLOB_MAGIC, "SMG_ERROR_BLOB_MAGIC"},
      {SMG_ERROR_BLOB_ENDIAN, "SMG_ERROR_BLOB_ENDIAN"},
      {SMG_ERROR_BLOB_VERSION, "SMG_ERROR_BLOB_VERSION"},
      {SMG_ERROR_BLOB_ALIGNMENT, "SMG_ERROR_BLOB_ALIGNMENT"},
      {SMG_ERROR_BLOB_CHECKSUM, "SMG_ERROR_BLOB_CHECKSUM"},
      {SMG_ERROR_BLOB_SECTION, "SMG_ERROR_BLOB_SECTION"},
      {SMG_ERROR_BLOB_INDEX, "SMG_ERROR_BLOB_INDEX"},
      {SMG_ERROR_BLOB_VALUE, "SMG_ERROR_BLOB_VALUE"},
      {SMG_ERROR_UNKNOWN_STYLE, "SMG_ERROR_UNKNOWN_STYLE"},
      {SMG_ERROR_UNKNOWN_ACTION, "SMG_ERROR_UNKNOWN_ACTION"},
      {SMG_ERROR_OUT_OF_RANGE, "SMG_ERROR_OUT_OF_RANGE"},
      {SMG_ERROR_CAPACITY, "SMG_ERROR_CAPACITY"},
      {SMG_ERROR_BUFFER_TOO_SMALL, "SMG_ERROR_BUFFER_TOO_SMALL"},
      {SMG_ERROR_IN_USE, "SMG_ERROR_IN_USE"},
      {SMG_ERROR_NOT_FOUND, "SMG_ERROR_NOT_FOUND"},
      {SMG_ERROR_PARSE, "SMG_ERROR_PARSE"},
      {SMG_ERROR_UNSUPPORTED, "SMG_ERROR_UNSUPPORTED"},
  };
  size_t n = sizeof k / sizeof k[0], i, j;
  (void)state;
  /* the table above must list every code: codes are 0..n-1 */
  assert_int_equal(SMG_ERROR_UNSUPPORTED, (int)n - 1);
  for (i = 0; i < n; ++i) {
    const char* s = smg_result_string(k[i].code);
    size_t len = strlen(k[i].name);
    assert_non_null(s);
    assert_int_equal((int)k[i].code, (int)i);
    assert_memory_equal(s, k[i].name, len);
    /* the name is followed by ": explanation", not by a longer name */
    assert_true(s[len] == ':');
    assert_true(strlen(s) > len + 4);
    for (j = 0; j < i; ++j)
      assert_true(strcmp(s, smg_result_string(k[j].code)) != 0);
  }
}

static void test_unknown_results_are_named_unknown(void** state) {
  static const int bad[] = {-1, 22, 100, 0x7ffffffe, (int)SMG_RESULT_FORCE_32};
  size_t i;
  (void)state;
  for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    const char* s = smg_result_string((smg_result)bad[i]);
    assert_non_null(s);
    assert_memory_equal(s, "SMG_ERROR_UNKNOWN", 17);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_version_matches_header),
      cmocka_unit_test(test_result_strings_name_their_code),
      cmocka_unit_test(test_unknown_results_are_named_unknown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
