/*
 * test_random_use.c - random sequences of every character call with
 * awkward but legal input (duplicate points, zero-length paths, a single
 * point, huge and tiny coordinates, paths far away, constraint churn,
 * style/action switches, dt from 0 to 1, IK toggles) and some illegal
 * input, on the fixture and on build/default.smg. Nothing may crash, the
 * pose must stay finite and the root must never jump further per step
 * than the fastest motion allows. Deterministic (seeded).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

static uint32_t rng = 0x1234567u;
static uint32_t next(void) {
  rng ^= rng << 13;
  rng ^= rng >> 17;
  rng ^= rng << 5;
  return rng;
}
static float uni(float a, float b) {
  return a + (b - a) * (float)(next() % 1000001u) / 1000000.0f;
}

static void churn(smg_graph* g, int ops) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  const uint32_t J = info.joint_count;
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  float* mats = (float*)malloc(sizeof(float) * 16 * J);
  float root[3], prev[3];
  enum { CAP = 300 };
  float xz[2 * CAP];
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = CAP;
  d.constraint_capacity = 8;
  d.seed = next();
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  smg_character_get_local_pose(ch, prev, rot, J);
  uint32_t ids[16];
  uint32_t nid = 0;
  for (int i = 0; i < ops; ++i) {
    uint32_t op = next() % 20u;
    smg_character_state s;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    smg_character_get_state(ch, &s);
    float len = 0;
    smg_character_get_path_length(ch, &len);
    if (op == 0) { /* random path near the character */
      uint32_t n = 1 + next() % CAP;
      float step = (next() % 4 == 0) ? 0.0f : uni(0.001f, 2.0f);
      float x = s.position[0] + uni(-3, 3), z = s.position[2] + uni(-3, 3);
      for (uint32_t k = 0; k < n; ++k) {
        xz[2 * k] = x;
        xz[2 * k + 1] = z;
        x += step * uni(-1, 1);
        z += step * uni(-1, 1);
      }
      assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
    } else if (op == 1) { /* far away or huge coordinates */
      float far = (next() % 2) ? 1e5f : 300.0f;
      xz[0] = uni(-far, far);
      xz[1] = uni(-far, far);
      xz[2] = xz[0] + uni(-10, 10);
      xz[3] = xz[1] + uni(-10, 10);
      assert_int_equal(smg_character_set_path(ch, xz, 2), SMG_OK);
    } else if (op == 2) { /* append */
      uint32_t n = next() % 8;
      for (uint32_t k = 0; k < n; ++k) {
        xz[2 * k] = s.position[0] + uni(-5, 5);
        xz[2 * k + 1] = s.position[2] + uni(-5, 5);
      }
      smg_result r = smg_character_append_path(ch, xz, n);
      assert_true(r == SMG_OK || r == SMG_ERROR_CAPACITY);
    } else if (op == 3) {
      smg_character_clear_path(ch);
    } else if (op == 4 || op == 5) { /* constraints, some beyond the end */
      float arc = uni(-1.0f, len + 2.0f);
      uint32_t id = 0;
      smg_result r = op == 4 ? smg_character_add_transition(
                                   ch, arc, next() % (info.style_count + 1), &id)
                             : smg_character_add_splice(
                                   ch, arc, next() % (info.action_count + 1), &id);
      assert_true(r == SMG_OK || r == SMG_ERROR_OUT_OF_RANGE ||
                  r == SMG_ERROR_CAPACITY || r == SMG_ERROR_UNKNOWN_STYLE ||
                  r == SMG_ERROR_UNKNOWN_ACTION);
      if (r == SMG_OK && nid < 16) ids[nid++] = id;
    } else if (op == 6 && nid) {
      smg_character_move_constraint(ch, ids[next() % nid], uni(0, len));
    } else if (op == 7 && nid) {
      uint32_t k = next() % nid;
      smg_character_remove_constraint(ch, ids[k]);
      ids[k] = ids[--nid];
    } else if (op == 8) {
      smg_character_clear_constraints(ch);
      nid = 0;
    } else if (op == 9) {
      smg_character_set_style(ch, next() % info.style_count);
    } else if (op == 10) {
      smg_character_set_action(ch, next() % info.action_count);
    } else if (op == 11) {
      smg_character_set_ik(ch, next() % 2);
    } else if (op == 12) {
      smg_character_set_error_threshold(ch, uni(0, 2));
    } else if (op == 13) { /* illegal input changes nothing */
      float bad[4] = {0, NAN, 1, 2};
      assert_int_equal(smg_character_set_path(ch, bad, 2),
                       SMG_ERROR_INVALID_ARGUMENT);
      assert_int_equal(smg_character_step(ch, -1.0f),
                       SMG_ERROR_INVALID_ARGUMENT);
      assert_int_equal(smg_character_add_splice(ch, INFINITY, 0, NULL),
                       SMG_ERROR_INVALID_ARGUMENT);
    } else {
      float dt = (next() % 10 == 0) ? uni(0.0f, 1.0f) : 1.0f / 60.0f;
      assert_int_equal(smg_character_step(ch, dt), SMG_OK);
      smg_character_get_local_pose(ch, root, rot, J);
      smg_character_get_model_matrices(ch, next() % 2, mats, J);
      assert_true(rt_pose_finite(root, rot, J));
      for (uint32_t k = 0; k < 16 * J; ++k) assert_true(isfinite(mats[k]));
      /* no motion in the data is faster than 10 m/s */
      float dx = root[0] - prev[0], dz = root[2] - prev[2];
      assert_true(sqrtf(dx * dx + dz * dz) <= 10.0f * dt + 0.05f);
      memcpy(prev, root, sizeof prev);
      smg_character_get_state(ch, &s);
      assert_true(isfinite(s.path_distance) && isfinite(s.path_error) &&
                  isfinite(s.heading) && isfinite(s.sync_rate));
    }
  }
  smg_character_destroy(ch);
  free(rot);
  free(mats);
}

static void test_fixture(void** state) {
  (void)state;
  void* blob;
  smg_graph* g = rt_fixture(&blob);
  assert_non_null(g);
  for (int k = 0; k < 4; ++k) churn(g, smgt_quick() ? 800 : 6000);
  rt_fixture_free(g, blob);
}

static void test_default(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  assert_non_null(g); /* run `make` first */
  for (int k = 0; k < 3; ++k) churn(g, smgt_quick() ? 600 : 6000);
  smg_graph_destroy(g);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_fixture),
      cmocka_unit_test(test_default),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
