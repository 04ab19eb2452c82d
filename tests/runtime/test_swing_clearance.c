/*
 * test_swing_clearance.c - a foot swinging fast keeps its toe above the
 * floor by the clearance (ik.c, "Swing clearance"), without changing
 * anything else: the character's motion, its planted feet and its
 * standing feet are those of the same character with the clearance off
 * (SMG_CHARACTER_NO_SWING_CLEARANCE), and the lift comes and goes without
 * a jump. Uses build/default.smg, whose synthetic walk swings its toes
 * 1-2 cm above the floor (so the first test fails without the feature).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define DT (1.0f / 60.0f)
#define MAXJ 64
#define STEPS 900

/* Per step and toe: the world toe position of two characters on the same
 * path, one with the clearance on (given), one with it off. */
typedef struct run {
  float toe[2][STEPS][2][3]; /* [character][step][foot][xyz] */
  uint32_t contact[STEPS][2];
} run;

static void walk(smg_graph* g, float clearance, run* r) {
  const uint32_t J = rt_joint_count(g, MAXJ);
  uint32_t toe[2];
  rt_toes(g, toe);
  smg_character* ch[2] = {NULL, NULL};
  float xz[2 * 64];
  const uint32_t n = rt_turn_r(xz, 6.0f, 8.0f, 1, 2.0f);
  for (int c = 0; c < 2; ++c) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.flags = c ? SMG_CHARACTER_NO_SWING_CLEARANCE : 0u;
    d.swing_clearance = clearance;
    assert_int_equal(smg_character_create(g, &d, &ch[c]), SMG_OK);
    assert_int_equal(smg_character_set_path(ch[c], xz, n), SMG_OK);
  }
  float mats[2][16 * MAXJ];
  for (int i = 0; i < STEPS; ++i) {
    for (int c = 0; c < 2; ++c) {
      assert_int_equal(smg_character_step(ch[c], DT), SMG_OK);
      assert_int_equal(
          smg_character_get_model_matrices(ch[c], SMG_SPACE_WORLD, mats[c], J),
          SMG_OK);
      for (int f = 0; f < 2; ++f)
        memcpy(r->toe[c][i][f], mats[c] + 16u * toe[f] + 12u, 3 * sizeof(float));
    }
    /* the clearance moves feet only: the hips are the same bits */
    assert_memory_equal(mats[0] + 12, mats[1] + 12, 3 * sizeof(float));
    smg_character_state s;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    assert_int_equal(smg_character_get_state(ch[0], &s), SMG_OK);
    r->contact[i][0] = (s.flags & SMG_STATE_LEFT_CONTACT) != 0;
    r->contact[i][1] = (s.flags & SMG_STATE_RIGHT_CONTACT) != 0;
  }
  for (int c = 0; c < 2; ++c) smg_character_destroy(ch[c]);
}

/* The lowest a toe stands (contact frames) in the run without clearance. */
static float stand_height(const run* r, int f) {
  float lo = INFINITY;
  for (int i = 0; i < STEPS; ++i)
    if (r->contact[i][f] && r->toe[1][i][f][1] < lo) lo = r->toe[1][i][f][1];
  return lo;
}

/* Mid-swing at step i: no contact within 0.1 s either side (a toe leaving
 * or reaching the floor passes low heights by nature; the lift comes and
 * goes there at a bounded rate). */
static int mid_swing(const run* r, int i, int f) {
  const int w = (int)(0.1f / DT + 0.5f);
  if (i < w || i + w >= STEPS) return 0;
  for (int k = i - w; k <= i + w; ++k)
    if (r->contact[k][f]) return 0;
  return 1;
}

/* The toe's speed over the ground at step i, without clearance (the
 * animation's swing: IK holds no swinging foot). */
static float ground_speed(const run* r, int i, int f) {
  const float* a = r->toe[1][i - 1][f];
  const float* b = r->toe[1][i][f];
  return hypotf(b[0] - a[0], b[2] - a[2]) / DT;
}

static float leg_length(smg_graph* g) {
  uint32_t hip, ankle;
  smg_joint_info a;
  assert_int_equal(smg_graph_find_joint(g, "LeftUpLeg", &hip), SMG_OK);
  assert_int_equal(smg_graph_find_joint(g, "LeftFoot", &ankle), SMG_OK);
  float len = 0.0f;
  /* hip-to-ankle at rest: the bones from the knee down to the ankle */
  for (uint32_t j = ankle; j != hip;) {
    memset(&a, 0, sizeof a);
    a.struct_size = sizeof a;
    assert_int_equal(smg_graph_get_joint(g, j, &a), SMG_OK);
    len += sqrtf(a.rest_offset[0] * a.rest_offset[0] +
                 a.rest_offset[1] * a.rest_offset[1] +
                 a.rest_offset[2] * a.rest_offset[2]);
    j = (uint32_t)a.parent;
  }
  return len;
}

/* Fast mid-swing (over 2 leg lengths per second): at least the clearance
 * above the floor with it on; without it the synthetic walk's toes pass
 * lower (else this test could not fail). */
static void test_fast_swing_clears_the_floor(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  assert_non_null(g);
  const float leg = leg_length(g), c = 0.04f * leg;
  run* r = (run*)calloc(1, sizeof *r);
  assert_non_null(r);
  walk(g, 0.0f, r);
  float lowest_on = INFINITY, lowest_off = INFINITY;
  int fast = 0;
  for (int f = 0; f < 2; ++f) {
    const float floor = stand_height(r, f);
    assert_true(floor < INFINITY);
    for (int i = 60; i < STEPS; ++i) {
      if (!mid_swing(r, i, f) || ground_speed(r, i, f) < 2.0f * leg) continue;
      ++fast;
      const float on = r->toe[0][i][f][1] - floor;
      const float off = r->toe[1][i][f][1] - floor;
      if (on < lowest_on) lowest_on = on;
      if (off < lowest_off) lowest_off = off;
    }
  }
  print_message("fast mid-swing frames %d: lowest toe above its floor %.1f cm "
                "with clearance (%.1f cm asked), %.1f cm without\n",
                fast, 100.0 * lowest_on, 100.0 * c, 100.0 * lowest_off);
  assert_true(fast > 50);
  assert_true(lowest_off < c - 0.5e-2f); /* the data skims the floor ... */
  assert_true(lowest_on >= c - 1e-3f); /* ... and is lifted clear of it */
  free(r);
  smg_graph_destroy(g);
}

/* Planted feet are the same bits; the lift (toe height with clearance
 * minus without) never jumps up: per 1/60 s step it grows by less than a
 * quarter of the clearance (a lift switched on at once would move it by
 * the whole clearance), and it falls by less than half of it (it falls as
 * a landing foot slows down). A clearance asked for (8 cm) is used: the
 * largest lift comes near it (the default is 3.4 cm on this skeleton). */
static void test_lift_is_smooth_and_planted_feet_untouched(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  assert_non_null(g);
  const float c = 0.08f;
  run* r = (run*)calloc(1, sizeof *r);
  assert_non_null(r);
  walk(g, c, r);
  float worst_rise = 0.0f, worst_fall = 0.0f, most = 0.0f;
  int planted = 0;
  for (int f = 0; f < 2; ++f) {
    for (int i = 1; i < STEPS; ++i) {
      const float lift = r->toe[0][i][f][1] - r->toe[1][i][f][1];
      const float prev = r->toe[0][i - 1][f][1] - r->toe[1][i - 1][f][1];
      if (lift - prev > worst_rise) worst_rise = lift - prev;
      if (prev - lift > worst_fall) worst_fall = prev - lift;
      if (lift > most) most = lift;
      if (r->contact[i][f]) {
        ++planted;
        assert_memory_equal(r->toe[0][i][f], r->toe[1][i][f], 3 * sizeof(float));
      }
    }
  }
  print_message("clearance %.0f cm: largest lift %.1f cm, in one step "
                "rising by %.2f cm at most, falling by %.2f cm; %d planted "
                "foot-steps identical\n",
                100.0 * c, 100.0 * most, 100.0 * worst_rise,
                100.0 * worst_fall, planted);
  assert_true(planted > STEPS / 2);
  assert_true(most > 0.5f * c);
  assert_true(worst_rise < 0.25f * c);
  assert_true(worst_fall < 0.5f * c);
  free(r);
  smg_graph_destroy(g);
}

/* Negative, non-finite or too large clearances are refused, nothing
 * created. */
static void test_bad_clearance(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  assert_non_null(g);
  const float bad[4] = {-0.01f, NAN, INFINITY, SMG_MAX_SWING_CLEARANCE * 1.01f};
  for (int i = 0; i < 4; ++i) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.swing_clearance = bad[i];
    smg_character* ch = (smg_character*)&d; /* must stay untouched */
    assert_int_equal(smg_character_create(g, &d, &ch), SMG_ERROR_INVALID_ARGUMENT);
    assert_ptr_equal(ch, (smg_character*)&d);
    size_t bytes = 0;
    assert_int_equal(smg_character_memory_size(g, &d, &bytes),
                     SMG_ERROR_INVALID_ARGUMENT);
  }
  smg_graph_destroy(g);
}

/* The setter: bad values are refused and change nothing; turning the
 * clearance off mid-walk lets the lift go at its bounded rate, after
 * which the feet are those of a character created without it; turning
 * it on lifts a character created without it. */
static void test_setter(void** state) {
  (void)state;
  smg_graph* g = rt_default_graph();
  assert_non_null(g);
  uint32_t toe[2];
  rt_toes(g, toe);
  /* 0: on, switched off at step 300; 1: created without; 2: on, given
   * bad values; 3: created on, the default */
  smg_character* ch[4];
  float xz[2 * 64];
  const uint32_t n = rt_turn_r(xz, 6.0f, 8.0f, 1, 2.0f);
  for (int c = 0; c < 4; ++c) {
    smg_character_desc d;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.flags = c == 1 ? SMG_CHARACTER_NO_SWING_CLEARANCE : 0u;
    assert_int_equal(smg_character_create(g, &d, &ch[c]), SMG_OK);
    assert_int_equal(smg_character_set_path(ch[c], xz, n), SMG_OK);
  }
  assert_int_equal(smg_character_set_swing_clearance(NULL, 1, 0.0f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_swing_clearance(ch[2], 1, -0.1f),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_swing_clearance(ch[2], 0, NAN),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_swing_clearance(ch[2], 0, INFINITY),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_swing_clearance(ch[2], 1, 1e30f),
                   SMG_ERROR_INVALID_ARGUMENT);
  float m[4][16 * MAXJ];
  float worst_fall = 0.0f, prev_lift = 0.0f, lift_at_off = 0.0f;
  int off_at = -1, same_after = 0, after = 0, same_as_on = 0;
  for (int i = 0; i < STEPS; ++i) {
    if (i == 600) /* on again, for the one created without it */
      assert_int_equal(smg_character_set_swing_clearance(ch[1], 1, 0.0f), SMG_OK);
    for (int c = 0; c < 4; ++c) {
      assert_int_equal(smg_character_step(ch[c], DT), SMG_OK);
      assert_int_equal(
          smg_character_get_model_matrices(ch[c], SMG_SPACE_WORLD, m[c], 31),
          SMG_OK);
    }
    /* bad values changed nothing: 2 moves as 3 */
    assert_memory_equal(m[2], m[3], sizeof(float) * 16 * 31);
    const float lift = m[0][16 * toe[0] + 13] - m[1][16 * toe[0] + 13];
    if (off_at < 0 && i >= 300 && lift > 0.01f) {
      /* off while the left foot is lifted by more than 1 cm */
      assert_int_equal(smg_character_set_swing_clearance(ch[0], 0, 0.0f), SMG_OK);
      off_at = i;
      lift_at_off = lift;
    } else if (off_at >= 0 && i < 600) {
      if (prev_lift - lift > worst_fall) worst_fall = prev_lift - lift;
      if (i >= off_at + 6) { /* 0.05 s of fall is over by then */
        ++after;
        same_after += memcmp(m[0], m[1], sizeof(float) * 16 * 31) == 0;
      }
    }
    prev_lift = lift;
    if (i >= 660) same_as_on += memcmp(m[1], m[3], sizeof(float) * 16 * 31) == 0;
  }
  print_message("switched off with the foot %.1f cm up: the lift fell by at "
                "most %.2f cm a step; afterwards %d of %d steps the same "
                "bits as without; switched on: the same bits as with it on "
                "%d of %d steps\n",
                100.0 * lift_at_off, 100.0 * worst_fall, same_after, after,
                same_as_on, STEPS - 660);
  assert_true(off_at >= 0);
  assert_true(after > 100);
  assert_int_equal(same_after, after);
  /* at the default's rate: 3.4 cm over 0.05 s is 1.15 cm per 1/60 s */
  assert_true(worst_fall < 0.015f);
  assert_true(worst_fall > 0.0f);
  assert_int_equal(same_as_on, STEPS - 660);
  for (int c = 0; c < 4; ++c) smg_character_destroy(ch[c]);
  smg_graph_destroy(g);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_fast_swing_clears_the_floor),
      cmocka_unit_test(test_lift_is_smooth_and_planted_feet_untouched),
      cmocka_unit_test(test_bad_clearance),
      cmocka_unit_test(test_setter),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
