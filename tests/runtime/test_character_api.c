/*
 * test_character_api.c - every smg_character_* function refuses bad input
 * with the documented error and leaves the character usable: NULL handles,
 * NaN/inf, bad struct_size, unknown style/action, constraints beyond the
 * path, capacities, destroying a graph still in use. Runs on the fixture.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

/* The fixture graph for every test of this file (runtime_testutil.h). */
typedef rt_fixture_ctx ctx;

static void test_create_args(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  smg_character_desc d;
  assert_int_equal(smg_character_create(NULL, NULL, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_create(c->g, NULL, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  memset(&d, 0, sizeof d);
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT); /* struct_size 0 */
  d.struct_size = sizeof d + 4;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.struct_size = 2; /* cannot even hold struct_size itself */
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.struct_size = sizeof d;
  d.initial_style = 2;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_UNKNOWN_STYLE);
  d.initial_style = 0;
  d.initial_action = 7;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_UNKNOWN_ACTION);
  d.initial_action = 0;
  d.position[0] = NAN;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.position[0] = 0;
  d.heading = INFINITY;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.heading = 0;
  d.horizon = -1;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.horizon = 0;
  d.error_threshold = NAN;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.error_threshold = 0;
  d.flags = 8u; /* no such flag */
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.flags = SMG_CHARACTER_NO_IK | SMG_CHARACTER_NO_STEERING |
            SMG_CHARACTER_NO_SWING_CLEARANCE;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
  ch = NULL;
  d.flags = 0;
  d.allocator.alloc = rt_count_alloc; /* free missing */
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_null(ch);
  /* a shorter (older) desc is accepted: fields past it are defaults */
  d.allocator.alloc = NULL;
  d.struct_size = offsetof(smg_character_desc, position);
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_non_null(ch);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
  assert_int_equal(smg_character_destroy(NULL), SMG_ERROR_INVALID_ARGUMENT);
}

static void test_memory_size(void** state) {
  ctx* c = (ctx*)*state;
  size_t bytes = 0, bytes_big = 0;
  smg_character_desc d;
  assert_int_equal(smg_character_memory_size(NULL, NULL, &bytes),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_memory_size(c->g, NULL, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_memory_size(c->g, NULL, &bytes), SMG_OK);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = 512 + 100000;
  assert_int_equal(smg_character_memory_size(c->g, &d, &bytes_big), SMG_OK);
  /* path points cost 12 bytes each (x, z, arc length) */
  assert_true(bytes_big >= bytes + 100000u * 12u);
  /* the memory-size figure is what create really allocates */
  rt_counter cnt = {0, 0};
  d.path_capacity = 0;
  d.allocator.alloc = rt_count_alloc;
  d.allocator.free = rt_count_free;
  d.allocator.user = &cnt;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_int_equal(cnt.allocs, 1);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
  assert_int_equal(cnt.frees, 1);
  /* a character with the default desc (its 512-point path buffer
   * included) fits the 16 KiB */
  size_t path_bytes = 512u * 12u;
  print_message("per-character memory: %zu bytes total, %zu without the "
                "512-point path buffer\n",
                bytes, bytes - path_bytes);
  assert_true(bytes <= 16384u);
  assert_true(bytes_big - bytes == 100000u * 12u);
}

static void test_path_args(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  smg_character_desc d;
  float xz[8] = {0, 0, 0, 1, 0, 2, 0, 3};
  float len = -1;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = 4;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(NULL, xz, 4),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_path(ch, NULL, 4),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_path(ch, xz, 5), SMG_ERROR_CAPACITY);
  xz[3] = NAN;
  assert_int_equal(smg_character_set_path(ch, xz, 4),
                   SMG_ERROR_INVALID_ARGUMENT);
  xz[3] = INFINITY;
  assert_int_equal(smg_character_append_path(ch, xz, 4),
                   SMG_ERROR_INVALID_ARGUMENT);
  xz[3] = 1;
  /* a rejected edit changes nothing */
  assert_int_equal(smg_character_get_path_length(ch, &len), SMG_OK);
  assert_true(len == 0.0f);
  assert_int_equal(smg_character_set_path(ch, xz, 4), SMG_OK);
  assert_int_equal(smg_character_get_path_length(ch, &len), SMG_OK);
  assert_float_equal(len, 3.0f, 1e-5f);
  assert_int_equal(smg_character_append_path(ch, xz, 1), SMG_ERROR_CAPACITY);
  assert_int_equal(smg_character_append_path(NULL, xz, 1),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_append_path(ch, NULL, 1),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_append_path(ch, NULL, 0), SMG_OK);
  assert_int_equal(smg_character_get_path_length(NULL, &len),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_path_length(ch, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_clear_path(NULL), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_clear_path(ch), SMG_OK);
  assert_int_equal(smg_character_get_path_length(ch, &len), SMG_OK);
  assert_true(len == 0.0f);
  /* single point and append after clear */
  assert_int_equal(smg_character_append_path(ch, xz, 1), SMG_OK);
  assert_int_equal(smg_character_append_path(ch, xz + 2, 3), SMG_OK);
  assert_int_equal(smg_character_get_path_length(ch, &len), SMG_OK);
  assert_float_equal(len, 3.0f, 1e-5f);
  assert_int_equal(smg_character_set_path(ch, xz, 0), SMG_OK); /* clears */
  assert_int_equal(smg_character_get_path_length(ch, &len), SMG_OK);
  assert_true(len == 0.0f);
  assert_int_equal(smg_character_step(ch, 0.1f), SMG_OK);
  smg_character_destroy(ch);
}

static void test_constraint_args(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  smg_character_desc d;
  float xz[4] = {0, 0, 0, 10};
  uint32_t id = 0, id2 = 0;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.constraint_capacity = 2;
  assert_int_equal(smg_character_create(c->g, &d, &ch), SMG_OK);
  /* no path yet: any positive arc is beyond the end */
  assert_int_equal(smg_character_add_transition(ch, 1.0f, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_character_set_path(ch, xz, 2), SMG_OK);
  assert_int_equal(smg_character_add_transition(NULL, 1.0f, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_add_transition(ch, NAN, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_add_transition(ch, 1.0f, 2, &id),
                   SMG_ERROR_UNKNOWN_STYLE);
  assert_int_equal(smg_character_add_transition(ch, 10.5f, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_character_add_transition(ch, -0.5f, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_character_add_splice(NULL, 1.0f, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_add_splice(ch, INFINITY, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_add_splice(ch, 1.0f, 2, &id),
                   SMG_ERROR_UNKNOWN_ACTION);
  assert_int_equal(smg_character_add_splice(ch, 11.0f, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_character_add_transition(ch, 5.0f, 1, &id), SMG_OK);
  assert_true(id > 0);
  assert_int_equal(smg_character_add_splice(ch, 2.0f, 1, &id2), SMG_OK);
  assert_true(id2 > 0 && id2 != id);
  assert_int_equal(smg_character_add_splice(ch, 3.0f, 0, NULL),
                   SMG_ERROR_CAPACITY);
  assert_int_equal(smg_character_move_constraint(NULL, id, 1.0f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_move_constraint(ch, id, NAN),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_move_constraint(ch, id, 20.0f),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_character_move_constraint(ch, 9999, 1.0f),
                   SMG_ERROR_NOT_FOUND);
  assert_int_equal(smg_character_move_constraint(ch, 0, 1.0f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_move_constraint(ch, id, 4.0f), SMG_OK);
  assert_int_equal(smg_character_remove_constraint(NULL, id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_remove_constraint(ch, 9999),
                   SMG_ERROR_NOT_FOUND);
  assert_int_equal(smg_character_remove_constraint(ch, id), SMG_OK);
  assert_int_equal(smg_character_remove_constraint(ch, id),
                   SMG_ERROR_NOT_FOUND);
  assert_int_equal(smg_character_clear_constraints(NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_clear_constraints(ch), SMG_OK);
  assert_int_equal(smg_character_remove_constraint(ch, id2),
                   SMG_ERROR_NOT_FOUND);
  /* constraints beyond a shortened path are kept and wait */
  assert_int_equal(smg_character_add_transition(ch, 9.0f, 1, &id), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, 2), SMG_OK);
  float shorter[4] = {0, 0, 0, 4};
  assert_int_equal(smg_character_set_path(ch, shorter, 2), SMG_OK);
  assert_int_equal(smg_character_step(ch, 0.5f), SMG_OK);
  assert_int_equal(smg_character_remove_constraint(ch, id), SMG_OK);
  smg_character_destroy(ch);
}

static void test_controls_and_step_args(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_style(NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_style(ch, 2), SMG_ERROR_UNKNOWN_STYLE);
  assert_int_equal(smg_character_set_style(ch, 1), SMG_OK);
  assert_int_equal(smg_character_set_action(NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_action(ch, 2), SMG_ERROR_UNKNOWN_ACTION);
  assert_int_equal(smg_character_set_action(ch, 1), SMG_OK);
  assert_int_equal(smg_character_set_error_threshold(NULL, 1.0f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_error_threshold(ch, NAN),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_error_threshold(ch, -1.0f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_error_threshold(ch, 0.5f), SMG_OK);
  assert_int_equal(smg_character_set_ik(NULL, 1), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ik(ch, 0), SMG_OK);
  assert_int_equal(smg_character_set_ik(ch, 1), SMG_OK);
  assert_int_equal(smg_character_step(NULL, 0.1f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_step(ch, NAN), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_step(ch, -0.01f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_step(ch, 1.5f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_step(ch, INFINITY),
                   SMG_ERROR_INVALID_ARGUMENT);
  smg_character_state s0, s1;
  memset(&s0, 0, sizeof s0);
  s0.struct_size = 2; /* same struct_size rule as every output struct */
  assert_int_equal(smg_character_get_state(ch, &s0),
                   SMG_ERROR_INVALID_ARGUMENT);
  s0.struct_size = sizeof s0;
  assert_int_equal(smg_character_get_state(ch, &s0), SMG_OK);
  assert_int_equal(smg_character_step(ch, 0.0f), SMG_OK); /* no-op */
  memset(&s1, 0, sizeof s1);
  s1.struct_size = sizeof s1;
  assert_int_equal(smg_character_get_state(ch, &s1), SMG_OK);
  assert_true(s0.time == s1.time);
  assert_int_equal(smg_character_step(ch, 1.0f), SMG_OK); /* max dt */
  assert_int_equal(smg_character_get_state(ch, &s1), SMG_OK);
  assert_true(s1.time > 0.99 && s1.time < 1.01);
  assert_true(s1.style == 1); /* set_style(1) applies with no path too */
  smg_character_destroy(ch);
}

static void test_getters_args(void** state) {
  ctx* c = (ctx*)*state;
  smg_character* ch = NULL;
  float root[3], rot[4 * 32], mats[16 * 32];
  smg_character_state s;
  assert_int_equal(smg_character_create(c->g, NULL, &ch), SMG_OK);
  memset(&s, 0, sizeof s);
  assert_int_equal(smg_character_get_state(ch, &s),
                   SMG_ERROR_INVALID_ARGUMENT); /* struct_size 0 */
  s.struct_size = sizeof s + 1;
  assert_int_equal(smg_character_get_state(ch, &s),
                   SMG_ERROR_INVALID_ARGUMENT);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(NULL, &s),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_state(ch, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  /* an older, shorter state struct gets only its own fields */
  memset(&s, 0xab, sizeof s);
  s.struct_size = offsetof(smg_character_state, time);
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  {
    smg_character_state probe;
    memset(&probe, 0xab, sizeof probe);
    assert_memory_equal(&s.time, &probe.time, sizeof s.time);
  }
  assert_int_equal(smg_character_get_local_pose(NULL, root, rot, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_local_pose(ch, NULL, rot, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_local_pose(ch, root, NULL, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_local_pose(ch, root, rot, 30),
                   SMG_ERROR_BUFFER_TOO_SMALL);
  assert_int_equal(smg_character_get_local_pose(ch, root, rot, 32),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_local_pose(ch, root, rot, 31), SMG_OK);
  assert_true(rt_pose_finite(root, rot, 31));
  assert_int_equal(smg_character_get_model_matrices(NULL, 0, mats, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_model_matrices(ch, 2, mats, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_model_matrices(ch, 0, NULL, 31),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_model_matrices(ch, 0, mats, 3),
                   SMG_ERROR_BUFFER_TOO_SMALL);
  assert_int_equal(
      smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats, 31), SMG_OK);
  /* world matrix of joint 0 carries the root translation */
  assert_float_equal(mats[12], root[0], 1e-5f);
  assert_float_equal(mats[13], root[1], 1e-5f);
  assert_float_equal(mats[14], root[2], 1e-5f);
  /* character space: the root sits above the origin */
  assert_int_equal(
      smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, mats, 31),
      SMG_OK);
  assert_float_equal(mats[13], root[1], 1e-5f);
  assert_true(fabsf(mats[12]) < 0.3f && fabsf(mats[14]) < 0.3f);
  smg_character_destroy(ch);
}

static void test_graph_in_use(void** state) {
  ctx* c = (ctx*)*state;
  smg_character *a = NULL, *b = NULL;
  smg_graph_info info;
  assert_int_equal(smg_character_create(c->g, NULL, &a), SMG_OK);
  assert_int_equal(smg_character_create(c->g, NULL, &b), SMG_OK);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(c->g, &info), SMG_OK);
  assert_int_equal(info.character_count, 2);
  assert_int_equal(smg_graph_destroy(c->g), SMG_ERROR_IN_USE);
  smg_character_destroy(a);
  assert_int_equal(smg_graph_destroy(c->g), SMG_ERROR_IN_USE);
  /* the graph still works for the remaining character */
  assert_int_equal(smg_character_step(b, 0.1f), SMG_OK);
  smg_character_destroy(b);
  assert_int_equal(smg_graph_get_info(c->g, &info), SMG_OK);
  assert_int_equal(info.character_count, 0);
}

static void* failing_alloc(size_t size, size_t align, void* user) {
  (void)size;
  (void)align;
  (void)user;
  return NULL;
}

static void failing_free(void* p, void* user) {
  (void)p;
  (void)user;
}

static void test_out_of_memory(void** state) {
  ctx* c = (ctx*)*state;
  smg_character_desc d;
  smg_character* ch = NULL;
  smg_graph_info info;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.allocator.alloc = failing_alloc;
  d.allocator.free = failing_free;
  assert_int_equal(smg_character_create(c->g, &d, &ch),
                   SMG_ERROR_OUT_OF_MEMORY);
  assert_null(ch);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(c->g, &info), SMG_OK);
  assert_int_equal(info.character_count, 0); /* nothing retained */
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_create_args),
      cmocka_unit_test(test_memory_size),
      cmocka_unit_test(test_path_args),
      cmocka_unit_test(test_constraint_args),
      cmocka_unit_test(test_controls_and_step_args),
      cmocka_unit_test(test_getters_args),
      cmocka_unit_test(test_graph_in_use),
      cmocka_unit_test(test_out_of_memory),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
