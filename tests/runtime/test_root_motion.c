/*
 * test_root_motion.c - root motion for an engine's mover
 * (smg_character_get_root_motion, _set_ground_position). A mover that
 * applies the root motion and collides with nothing reproduces the
 * character's own motion; one that stops it at a wall (sliding along it)
 * moves no joint further in a step than the free motion's own steps do,
 * and once the wall is gone the character is back on its path within 1 s.
 * A character standing at its path's end (the rest stage holding its
 * feet) keeps its feet under it when the mover moves and turns it.
 * Argument checks. Uses build/default.smg.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define FPS 60.0f
#define STEPS 900 /* 15 s */
#define MAXJ 64

/* The wall: the line z = WALL_Z + WALL_SLOPE * x, across the path (along
 * +Z at x = 0) at an angle, there for steps [WALL_FROM, WALL_TO). */
#define WALL_Z 5.0f
#define WALL_SLOPE 1.0f
#define WALL_FROM 0
#define WALL_TO 360 /* gone after 6 s */

typedef struct trace {
  float wpos[STEPS][MAXJ][3]; /* world */
  float cpos[STEPS][MAXJ][3]; /* character space: the pose itself */
  float path_error[STEPS];
  float ground[STEPS][3];
  uint32_t J;
} trace;

/* mover: 0 none (the library moves the character), 1 a mover without
 * walls, 2 a mover with the wall */
static void walk(smg_graph* g, int mover, trace* t) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  t->J = info.joint_count;
  assert_true(t->J <= MAXJ);
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  float xz[2 * 32];
  rt_line(xz, 32, 40.0f);
  assert_int_equal(smg_character_set_path(ch, xz, 32), SMG_OK);
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  float pos[3] = {s.position[0], s.position[1], s.position[2]}, heading = s.heading;
  float mats[16 * MAXJ];
  for (int i = 0; i < STEPS; ++i) {
    assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
    if (mover) {
      smg_root_motion m;
      memset(&m, 0, sizeof m);
      m.struct_size = sizeof m;
      assert_int_equal(smg_character_get_root_motion(ch, &m), SMG_OK);
      float p[3] = {pos[0] + m.translation[0], pos[1] + m.translation[1], pos[2] + m.translation[2]};
      /* the local translation is the same move in the heading's frame */
      const float sh = sinf(heading), chh = cosf(heading);
      assert_true(fabsf(chh * m.translation[0] - sh * m.translation[2] - m.local_translation[0]) < 1e-4f);
      assert_true(fabsf(sh * m.translation[0] + chh * m.translation[2] - m.local_translation[2]) < 1e-4f);
      heading += m.yaw;
      const float limit = WALL_Z + WALL_SLOPE * p[0];
      if (mover == 2 && i >= WALL_FROM && i < WALL_TO && p[2] > limit) {
        /* slide: project onto the wall line */
        const float nx = -WALL_SLOPE, nz = 1.0f, nn = nx * nx + nz * nz;
        const float d = (p[2] - limit) / nn;
        p[0] -= d * nx;
        p[2] -= d * nz;
      }
      memcpy(pos, p, sizeof pos);
      assert_int_equal(smg_character_set_ground_position(ch, pos, heading), SMG_OK);
    }
    assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
    t->path_error[i] = s.path_error;
    memcpy(t->ground[i], s.position, sizeof t->ground[i]);
    if (mover) { /* the character is where the mover put it */
      assert_true(fabsf(s.position[0] - pos[0]) < 1e-4f && fabsf(s.position[2] - pos[2]) < 1e-4f);
    }
    assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats, t->J), SMG_OK);
    for (uint32_t j = 0; j < t->J; ++j) memcpy(t->wpos[i][j], mats + 16u * j + 12u, sizeof t->wpos[i][j]);
    assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, mats, t->J), SMG_OK);
    for (uint32_t j = 0; j < t->J; ++j) memcpy(t->cpos[i][j], mats + 16u * j + 12u, sizeof t->cpos[i][j]);
  }
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

/* the largest distance any joint moves in one step in character space
 * (the pose; the mover moves the character as a whole), over [from, to) */
static float largest_step(const trace* t, int from, int to) {
  float worst = 0.0f;
  for (int i = from > 1 ? from : 1; i < to; ++i)
    for (uint32_t j = 0; j < t->J; ++j) {
      float dx = t->cpos[i][j][0] - t->cpos[i - 1][j][0], dy = t->cpos[i][j][1] - t->cpos[i - 1][j][1],
            dz = t->cpos[i][j][2] - t->cpos[i - 1][j][2];
      float d = sqrtf(dx * dx + dy * dy + dz * dz);
      if (d > worst) worst = d;
    }
  return worst;
}

static void test_mover_without_walls_is_the_motion(void** state) {
  smg_graph* g = (smg_graph*)*state;
  trace* a = (trace*)malloc(sizeof *a);
  trace* b = (trace*)malloc(sizeof *b);
  assert_non_null(a);
  assert_non_null(b);
  walk(g, 0, a);
  walk(g, 1, b);
  float worst = 0.0f;
  for (int i = 0; i < STEPS; ++i)
    for (uint32_t j = 0; j < a->J; ++j)
      for (int k = 0; k < 3; ++k) {
        float d = fabsf(a->wpos[i][j][k] - b->wpos[i][j][k]);
        if (d > worst) worst = d;
      }
  printf("mover without walls: largest joint difference %.2g m\n", worst);
  assert_true(worst < 1e-3f);
  free(a);
  free(b);
}

static void test_wall(void** state) {
  smg_graph* g = (smg_graph*)*state;
  trace* free_run = (trace*)malloc(sizeof *free_run);
  trace* t = (trace*)malloc(sizeof *t);
  assert_non_null(free_run);
  assert_non_null(t);
  walk(g, 0, free_run);
  walk(g, 2, t);
  /* it was stopped and pushed off the path by the wall */
  float pushed = 0.0f;
  for (int i = 0; i < WALL_TO; ++i)
    if (t->path_error[i] > pushed) pushed = t->path_error[i];
  assert_true(t->ground[WALL_TO - 1][2] < WALL_Z + WALL_SLOPE * t->ground[WALL_TO - 1][0] + 1e-3f);
  assert_true(pushed > 0.3f);
  /* no pose jump beyond the motion's own steps */
  const float own = largest_step(free_run, 60, STEPS);
  /* while blocked and as it is let go (0.25 s). Later the steering
   * brings the character back to the path within its limits, and a foot
   * planted during that return lets its correction go at lift-off like
   * after any large path error (printed, not held here) */
  const float blocked = largest_step(t, 60, WALL_TO + (int)(0.25f * FPS));
  const float after = largest_step(t, WALL_TO + (int)(0.25f * FPS), STEPS);
  /* on the path in the free run (after the start) */
  float normal = 0.0f;
  for (int i = 60; i < STEPS; ++i)
    if (free_run->path_error[i] > normal) normal = free_run->path_error[i];
  /* once free: back within the free run's own path error in 1 s */
  int back = -1;
  for (int i = WALL_TO; i < STEPS && back < 0; ++i)
    if (t->path_error[i] <= normal + 0.02f) back = i;
  printf("wall: pushed %.2f m off the path; largest joint step in character space %.3f m "
         "blocked (free motion %.3f m, %.3f m during the return); back on the path "
         "(error <= %.3f m) %.2f s after the wall went\n",
         pushed, blocked, own, after, normal + 0.02f,
         back < 0 ? -1.0 : (back - WALL_TO) / (double)FPS);
  assert_true(blocked <= own * 1.05f);
  assert_true(back >= 0 && back - WALL_TO <= (int)FPS);
  free(free_run);
  free(t);
}

/* Toe positions (x, y, z) of both feet in character space. */
static void toes_in_character_space(smg_character* ch, const uint32_t* toe, uint32_t J,
                                    float* out) {
  float mats[16 * MAXJ];
  assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, mats, J), SMG_OK);
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < 3; ++k) out[3 * f + k] = mats[16u * toe[f] + 12u + (uint32_t)k];
}

static void test_mover_moves_a_standing_character(void** state) {
  smg_graph* g = (smg_graph*)*state;
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_true(info.joint_count <= MAXJ);
  uint32_t toe[2];
  rt_toes(g, toe);
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  float xz[2 * 8];
  rt_line(xz, 8, 4.0f);
  assert_int_equal(smg_character_set_path(ch, xz, 8), SMG_OK);
  /* to the end, then standing for a while */
  for (int i = 0; i < 10 * (int)FPS; ++i)
    assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  assert_true(s.flags & SMG_STATE_PATH_END_REACHED);
  float before[6], after[6];
  toes_in_character_space(ch, toe, info.joint_count, before);
  /* the engine's mover puts it 1.1 m away, turned by 0.6 rad */
  const float to[3] = {s.position[0] + 1.0f, s.position[1], s.position[2] + 0.5f};
  assert_int_equal(smg_character_set_ground_position(ch, to, s.heading + 0.6f), SMG_OK);
  float worst = 0.0f;
  for (int i = 0; i < (int)FPS; ++i) {
    assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
    toes_in_character_space(ch, toe, info.joint_count, after);
    for (int k = 0; k < 6; ++k)
      if (fabsf(after[k] - before[k]) > worst) worst = fabsf(after[k] - before[k]);
  }
  printf("standing character moved 1.1 m and turned 0.6 rad by the mover: its toes "
         "stay within %.3f m of where they stood under it\n",
         worst);
  assert_true(worst < 0.02f);
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

static void test_arguments(void** state) {
  smg_graph* g = (smg_graph*)*state;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  smg_root_motion m;
  memset(&m, 0, sizeof m);
  assert_int_equal(smg_character_get_root_motion(ch, &m), SMG_ERROR_INVALID_ARGUMENT);
  m.struct_size = sizeof m + 4;
  assert_int_equal(smg_character_get_root_motion(ch, &m), SMG_ERROR_INVALID_ARGUMENT);
  m.struct_size = sizeof m;
  assert_int_equal(smg_character_get_root_motion(NULL, &m), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_root_motion(ch, NULL), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_root_motion(ch, &m), SMG_OK);
  const float ok[3] = {1.0f, 0.0f, 2.0f};
  const float nan3[3] = {NAN, 0.0f, 0.0f};
  const float far[3] = {0.0f, 0.0f, 2.0f * SMG_MAX_COORDINATE};
  assert_int_equal(smg_character_set_ground_position(NULL, ok, 0.0f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground_position(ch, NULL, 0.0f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground_position(ch, nan3, 0.0f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground_position(ch, far, 0.0f), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground_position(ch, ok, INFINITY), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_set_ground_position(ch, ok, 0.5f), SMG_OK);
  smg_character_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
  assert_true(fabsf(s.position[0] - 1.0f) < 1e-5f && fabsf(s.position[2] - 2.0f) < 1e-5f);
  assert_true(fabsf(s.heading - 0.5f) < 1e-5f);
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
      cmocka_unit_test(test_mover_without_walls_is_the_motion),
      cmocka_unit_test(test_wall),
      cmocka_unit_test(test_mover_moves_a_standing_character),
      cmocka_unit_test(test_arguments),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
