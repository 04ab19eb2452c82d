/*
 * test_ground.c - uneven ground (smg_character_get_ground_probes,
 * _set_ground): a character walking up a 10-degree ramp or 15 cm steps
 * onto a plateau, the ground measured at the probes before every step as an
 * engine's ray casts would, keeps its planted toes within 2 cm of the
 * surface - frame for frame as high above it as on flat ground (the ground
 * changes no choice of motion, so the same frames play; planted toes of
 * different clips stand at different heights) - never straightens a knee
 * further than on flat ground, and follows its path with the path error
 * and planted-toe speed of flat ground. With no ground given nothing
 * changes; the ground can be taken back (NULL). Argument checks. Uses
 * build/default.smg, and build/cmu.smg (real capture: planted toes at
 * clip-dependent heights) when `make` baked it from ../shared.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define FPS 30.0f
#define STEPS 600 /* 20 s */
#define WARM 60   /* the first 2 s: starting */
#define MAXJ 64

#define FLAT 0
#define RAMP 1
#define STAIRS 2
#define RISE 0.15f  /* stair height */
#define TREAD 0.5f  /* stair depth */

/* The ground: up along +Z from z = 2 m for 8 m, then level (a plateau). */
static float ground_at(int kind, float x, float z) {
  (void)x;
  float u = z - 2.0f;
  if (u < 0.0f) u = 0.0f;
  if (u > 8.0f) u = 8.0f;
  if (kind == RAMP) return u * tanf(10.0f * 3.14159265f / 180.0f);
  if (kind == STAIRS) return RISE * floorf(u / TREAD);
  return 0.0f;
}

typedef struct stats {
  float above[STEPS][2]; /* toe height above the ground, per step */
  uint8_t still[STEPS][2]; /* the toe planted (standing still) */
  float toe_err;       /* largest |planted toe above ground - on flat
                          ground at the same step| */
  float knee_ratio;    /* largest hip-ankle / (thigh + shin) */
  float knee_back;     /* most a knee lies behind its hip-ankle line, m */
  float path_error;    /* largest path error after the start */
  float toe_speed;     /* mean ground speed of toes in contact, m/s */
  float climbed;       /* ground height reached */
} stats;

static void walk(smg_graph* g, int kind, int give_ground, const stats* flat, stats* st) {
  const uint32_t J = rt_joint_count(g, MAXJ);
  const char* names[2][4] = {{"LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase"},
                             {"RightUpLeg", "RightLeg", "RightFoot", "RightToeBase"}};
  uint32_t leg[2][4];
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < 4; ++k) assert_int_equal(smg_graph_find_joint(g, names[f][k], &leg[f][k]), SMG_OK);
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  float xz[2 * 32];
  rt_line(xz, 32, 14.0f);
  assert_int_equal(smg_character_set_path(ch, xz, 32), SMG_OK);
  memset(st, 0, sizeof *st);
  float mats[16 * MAXJ], prev_toe[2][3] = {{0}};
  float sum_speed = 0.0f;
  int n_speed = 0;
  const float leg_len = 0.84f;
  for (int i = 0; i < STEPS; ++i) {
    if (give_ground) {
      float p[6];
      assert_int_equal(smg_character_get_ground_probes(ch, p, 3), SMG_OK);
      smg_ground gr;
      memset(&gr, 0, sizeof gr);
      gr.struct_size = sizeof gr;
      gr.foot_height[0] = ground_at(kind, p[0], p[1]);
      gr.foot_height[1] = ground_at(kind, p[2], p[3]);
      gr.root_height = ground_at(kind, p[4], p[5]);
      assert_int_equal(smg_character_set_ground(ch, &gr), SMG_OK);
    }
    assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
    smg_character_state s;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
    assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats, J), SMG_OK);
    const float fwd[2] = {sinf(s.heading), cosf(s.heading)};
    for (int f = 0; f < 2; ++f) {
      const float* hip = mats + 16u * leg[f][0] + 12u;
      const float* knee = mats + 16u * leg[f][1] + 12u;
      const float* ankle = mats + 16u * leg[f][2] + 12u;
      const float* toe = mats + 16u * leg[f][3] + 12u;
      float a[3], b[3], c[3];
      for (int k = 0; k < 3; ++k) {
        a[k] = knee[k] - hip[k];
        b[k] = ankle[k] - knee[k];
        c[k] = ankle[k] - hip[k];
      }
      const float la = sqrtf(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      const float lb = sqrtf(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
      const float lc = sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      const float speed = sqrtf((toe[0] - prev_toe[f][0]) * (toe[0] - prev_toe[f][0]) +
                                (toe[2] - prev_toe[f][2]) * (toe[2] - prev_toe[f][2])) * FPS;
      const float vy = fabsf(toe[1] - prev_toe[f][1]) * FPS;
      memcpy(prev_toe[f], toe, sizeof prev_toe[f]);
      if (i < WARM) continue;
      if (lc / (la + lb) > st->knee_ratio) st->knee_ratio = lc / (la + lb);
      /* the knee's offset from the hip-ankle midpoint, forwards */
      const float mid[2] = {0.5f * (hip[0] + ankle[0]), 0.5f * (hip[2] + ankle[2])};
      const float ahead = (knee[0] - mid[0]) * fwd[0] + (knee[2] - mid[1]) * fwd[1];
      if (-ahead > st->knee_back) st->knee_back = -ahead;
      /* planted: toes standing still (geometry, not the runtime's flags) */
      st->above[i][f] = toe[1] - ground_at(kind, toe[0], toe[2]);
      st->still[i][f] = speed + vy < 0.15f * leg_len;
      if (flat && st->still[i][f] && flat->still[i][f]) {
        const float e = fabsf(st->above[i][f] - flat->above[i][f]);
        if (e > st->toe_err) st->toe_err = e;
      }
      const uint32_t bit = f ? SMG_STATE_RIGHT_CONTACT : SMG_STATE_LEFT_CONTACT;
      if (s.flags & bit) {
        sum_speed += speed;
        ++n_speed;
      }
    }
    if (i >= WARM && s.path_error > st->path_error) st->path_error = s.path_error;
    if (s.position[1] > st->climbed) st->climbed = s.position[1];
  }
  st->toe_speed = n_speed ? sum_speed / (float)n_speed : 0.0f;
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

static void check(smg_graph* g, int kind, const char* name) {
  stats* both = (stats*)malloc(2 * sizeof(stats));
  assert_non_null(both);
  stats flat, st;
  walk(g, FLAT, 0, NULL, &both[0]);
  walk(g, kind, 1, &both[0], &both[1]);
  flat = both[0];
  st = both[1];
  free(both);
  printf("%s: climbed %.2f m; planted toes within %.1f mm of their flat-ground height above the "
         "surface; hip-ankle %.4f of the leg (flat %.4f); knee behind the hip-ankle line %.1f mm "
         "(flat %.1f); path error %.3f m (flat %.3f); toe speed in contact %.3f m/s (flat %.3f)\n",
         name, st.climbed, st.toe_err * 1000.0f, st.knee_ratio, flat.knee_ratio, st.knee_back * 1000.0f,
         flat.knee_back * 1000.0f, st.path_error, flat.path_error, st.toe_speed, flat.toe_speed);
  assert_true(st.climbed > 1.0f);
  assert_true(st.toe_err <= 0.02f);
  assert_true(st.knee_ratio <= 0.9995f);
  assert_true(st.knee_back <= flat.knee_back + 0.01f);
  assert_true(st.path_error <= flat.path_error + 0.02f);
  assert_true(st.toe_speed <= flat.toe_speed + 0.02f);
}

static void test_ramp(void** state) { check((smg_graph*)*state, RAMP, "10-degree ramp"); }

static void test_stairs(void** state) { check((smg_graph*)*state, STAIRS, "15 cm steps"); }

/* The same on the CMU graph when it was baked. */
static void test_cmu(void** state) {
  (void)state;
  char path[1024];
  smg_graph* g = NULL;
  snprintf(path, sizeof path, "%s/cmu.smg", SMG_BUILD_DIR);
  FILE* f = fopen(path, "rb");
  if (!f) {
    printf("SKIP: %s not baked (make bakes it when ../shared has the CMU clips)\n", path);
    return;
  }
  fclose(f);
  assert_int_equal(smg_graph_load_file(path, NULL, &g), SMG_OK);
  check(g, RAMP, "CMU, 10-degree ramp");
  check(g, STAIRS, "CMU, 15 cm steps");
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* level ground at 0 given: the character stays on it, as without ground */
static void test_level_ground(void** state) {
  smg_graph* g = (smg_graph*)*state;
  stats* both = (stats*)malloc(2 * sizeof(stats));
  assert_non_null(both);
  walk(g, FLAT, 0, NULL, &both[0]);
  walk(g, FLAT, 1, &both[0], &both[1]);
  const stats flat = both[0], st = both[1];
  free(both);
  printf("level ground given: planted toes within %.1f mm, path error %.3f m (without %.3f)\n",
         st.toe_err * 1000.0f, st.path_error, flat.path_error);
  assert_true(st.toe_err <= 0.01f);
  assert_true(st.path_error <= flat.path_error + 0.01f);
}

static void test_arguments(void** state) {
  smg_graph* g = (smg_graph*)*state;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  float p[6];
  assert_int_equal(smg_character_get_ground_probes(NULL, p, 3), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_ground_probes(ch, NULL, 3), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_ground_probes(ch, p, 2), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_ground_probes(ch, p, 3), SMG_OK);
  for (int k = 0; k < 6; ++k) assert_true(isfinite(p[k]));
  smg_ground gr;
  memset(&gr, 0, sizeof gr);
  assert_int_equal(smg_character_set_ground(NULL, &gr), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_ERROR_INVALID_ARGUMENT); /* size 0 */
  gr.struct_size = sizeof gr + 4;
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_ERROR_INVALID_ARGUMENT);
  gr.struct_size = sizeof gr;
  gr.flags = 1;
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_ERROR_INVALID_ARGUMENT);
  gr.flags = 0;
  gr.foot_height[1] = NAN;
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_ERROR_INVALID_ARGUMENT);
  gr.foot_height[1] = 2.0f * SMG_MAX_COORDINATE;
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_ERROR_INVALID_ARGUMENT);
  gr.foot_height[1] = 0.5f;
  gr.foot_height[0] = gr.root_height = 0.5f;
  assert_int_equal(smg_character_set_ground(ch, &gr), SMG_OK);
  for (int i = 0; i < 30; ++i) assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  assert_true(fabsf(s.position[1] - 0.5f) < 0.01f);
  /* taken back: on the data's floor again */
  assert_int_equal(smg_character_set_ground(ch, NULL), SMG_OK);
  assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  assert_true(s.position[1] == 0.0f);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

static int setup(void** state) {
  smg_graph* g = rt_default_graph();
  if (!g) return -1;
  *state = g;
  return 0;
}

static int teardown(void** state) {
  return smg_graph_destroy((smg_graph*)*state) == SMG_OK ? 0 : -1;
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ramp),
      cmocka_unit_test(test_stairs),
      cmocka_unit_test(test_cmu),
      cmocka_unit_test(test_level_ground),
      cmocka_unit_test(test_arguments),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
