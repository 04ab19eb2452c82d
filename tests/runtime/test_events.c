/*
 * test_events.c - the event queue (smg_character_get_events): every
 * constraint gives exactly one event, at the step whose frame first shows
 * its style or action (or flagged unchanged / superseded); every change
 * of style or action has its event; footsteps come at the landings
 * measured from the toes' geometry, within one frame; the path's end
 * gives one event. Argument checks. Uses build/default.smg (walk, run;
 * none, wave, punch), and build/cmu.smg (walk, run; none, punch) when
 * `make` baked it from ../shared.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "runtime/runtime_testutil.h"

#define FPS 30.0f
#define STEPS 900 /* 30 s */
#define MAXJ 64
#define MAXEV 64

typedef struct take {
  uint32_t style[STEPS], action[STEPS], end[STEPS];
  float toe[STEPS][2][3];
  smg_event ev[STEPS][8];
  uint32_t nev[STEPS];
  uint32_t ids[16], nids;
  float leg;
} take;

static void run(smg_graph* g, take* t, int superseded) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  const uint32_t J = info.joint_count;
  assert_true(J <= MAXJ);
  uint32_t toe[2];
  rt_toes(g, toe);
  smg_character* ch = NULL;
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  float xz[2 * 64];
  const uint32_t n = rt_turn_r(xz, 24.0f, 10.0f, 1, 3.0f);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  memset(t, 0, sizeof *t);
  uint32_t run_style, walk_style, first, second;
  assert_int_equal(smg_graph_find_style(g, "run", &run_style), SMG_OK);
  assert_int_equal(smg_graph_find_style(g, "walk", &walk_style), SMG_OK);
  /* two actions besides "none" (the same one twice when there is one) */
  first = 1;
  second = info.action_count > 2 ? 2 : 1;
  uint32_t* id = t->ids;
  assert_int_equal(smg_character_add_transition(ch, 6.0f, run_style, id++), SMG_OK);
  assert_int_equal(smg_character_add_transition(ch, 18.0f, walk_style, id++), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 3.0f, first, id++), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 12.0f, second, id++), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 22.0f, 0, id++), SMG_OK);
  /* already walking: reached unchanged */
  assert_int_equal(smg_character_add_transition(ch, 1.0f, walk_style, id++), SMG_OK);
  if (superseded) { /* a run overtaken at once by a walk 5 cm on: the
                     * character walks there, wherever around 18 m the
                     * walk began (within the metre a change may take) */
    assert_int_equal(smg_character_add_transition(ch, 19.0f, run_style, id++), SMG_OK);
    assert_int_equal(smg_character_add_transition(ch, 19.05f, walk_style, id++), SMG_OK);
  }
  assert_int_equal(smg_character_add_transition(ch, 18.05f, walk_style, id++), SMG_OK);
  t->nids = (uint32_t)(id - t->ids);
  /* leg length: thigh and shin at rest */
  {
    uint32_t knee, ankle;
    smg_joint_info a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.struct_size = b.struct_size = sizeof a;
    assert_int_equal(smg_graph_find_joint(g, "LeftLeg", &knee), SMG_OK);
    assert_int_equal(smg_graph_find_joint(g, "LeftFoot", &ankle), SMG_OK);
    assert_int_equal(smg_graph_get_joint(g, knee, &a), SMG_OK);
    assert_int_equal(smg_graph_get_joint(g, ankle, &b), SMG_OK);
    t->leg = sqrtf(a.rest_offset[0] * a.rest_offset[0] + a.rest_offset[1] * a.rest_offset[1] +
                   a.rest_offset[2] * a.rest_offset[2]) +
             sqrtf(b.rest_offset[0] * b.rest_offset[0] + b.rest_offset[1] * b.rest_offset[1] +
                   b.rest_offset[2] * b.rest_offset[2]);
  }
  float mats[16 * MAXJ];
  for (int i = 0; i < STEPS; ++i) {
    if (i > 0) assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
    smg_character_state s;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    assert_int_equal(smg_character_get_state(ch, &s), SMG_OK);
    t->style[i] = s.style;
    t->action[i] = s.action;
    t->end[i] = (s.flags & SMG_STATE_PATH_END_REACHED) != 0;
    assert_int_equal(smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats, J), SMG_OK);
    for (int f = 0; f < 2; ++f) memcpy(t->toe[i][f], mats + 16u * toe[f] + 12u, sizeof t->toe[i][f]);
    uint32_t count = 99;
    assert_int_equal(smg_character_get_events(ch, NULL, 0, &count), SMG_OK);
    assert_true(count <= 8);
    t->ev[i][0].struct_size = sizeof(smg_event);
    assert_int_equal(smg_character_get_events(ch, t->ev[i], 8, &t->nev[i]), SMG_OK);
    assert_int_equal(t->nev[i], count);
  }
  assert_int_equal(smg_character_destroy(ch), SMG_OK);
}

/* every constraint once; taken ones at the step their value first shows;
 * every change has an event */
static void check_constraints(const take* t) {
  for (uint32_t k = 0; k < t->nids; ++k) {
    int found = 0;
    for (int i = 0; i < STEPS; ++i)
      for (uint32_t e = 0; e < t->nev[i]; ++e) {
        const smg_event* ev = &t->ev[i][e];
        if (ev->type != SMG_EVENT_CONSTRAINT || ev->id != t->ids[k]) continue;
        ++found;
        const uint32_t* shown = (ev->flags & SMG_EVENT_SPLICE) ? t->action : t->style;
        if (!(ev->flags & (SMG_EVENT_SUPERSEDED | SMG_EVENT_UNCHANGED))) {
          assert_int_equal(shown[i], ev->value);
          assert_true(i > 0 && shown[i - 1] != ev->value);
        } else if (ev->flags & SMG_EVENT_UNCHANGED) {
          assert_int_equal(shown[i], ev->value);
        }
      }
    if (found != 1) fprintf(stderr, "constraint %u: %d events\n", t->ids[k], found);
    assert_int_equal(found, 1);
  }
  int changes = 0;
  for (int i = 1; i < STEPS; ++i)
    for (int kind = 0; kind < 2; ++kind) {
      const uint32_t* shown = kind ? t->action : t->style;
      if (shown[i] == shown[i - 1]) continue;
      ++changes;
      int has = 0;
      for (uint32_t e = 0; e < t->nev[i]; ++e) {
        const smg_event* ev = &t->ev[i][e];
        if (ev->type == SMG_EVENT_CONSTRAINT && ev->value == shown[i] &&
            !(ev->flags & (SMG_EVENT_SUPERSEDED | SMG_EVENT_UNCHANGED)) &&
            ((ev->flags & SMG_EVENT_SPLICE) != 0) == kind)
          has = 1;
      }
      assert_true(has);
    }
  /* run, walk; the actions and back to none */
  assert_true(changes >= 4);
}

static void constraints_once(smg_graph* g) {
  take* t = (take*)malloc(sizeof *t);
  assert_non_null(t);
  run(g, t, 0);
  check_constraints(t);
  /* the walk at 1 m is reached unchanged */
  int unchanged = 0;
  for (int i = 0; i < STEPS; ++i)
    for (uint32_t e = 0; e < t->nev[i]; ++e)
      if (t->ev[i][e].id == t->ids[5]) unchanged = (t->ev[i][e].flags & SMG_EVENT_UNCHANGED) != 0;
  assert_true(unchanged);
  run(g, t, 1);
  check_constraints(t);
  int superseded = 0;
  for (int i = 0; i < STEPS; ++i)
    for (uint32_t e = 0; e < t->nev[i]; ++e)
      if (t->ev[i][e].id == t->ids[6]) superseded = (t->ev[i][e].flags & SMG_EVENT_SUPERSEDED) != 0;
  assert_true(superseded);
  free(t);
}

/* Landings from geometry: the toe comes within 0.05 leg lengths of the
 * lowest it stood on, moving slower than 0.15 leg lengths per second,
 * after it had been lifted off (beyond twice either bound). */
static void footsteps_match_geometry(smg_graph* g) {
  take* t = (take*)malloc(sizeof *t);
  assert_non_null(t);
  run(g, t, 0);
  int matched = 0, landings = 0;
  for (int f = 0; f < 2; ++f) {
    float low = INFINITY;
    for (int i = 0; i < STEPS; ++i)
      if (t->toe[i][f][1] < low) low = t->toe[i][f][1];
    int still[STEPS] = {0}, geo[STEPS] = {0}, down = 0;
    for (int i = 1; i < STEPS; ++i) {
      float dx = t->toe[i][f][0] - t->toe[i - 1][f][0], dy = t->toe[i][f][1] - t->toe[i - 1][f][1],
            dz = t->toe[i][f][2] - t->toe[i - 1][f][2];
      float v = sqrtf(dx * dx + dy * dy + dz * dz) * FPS, h = t->toe[i][f][1] - low;
      still[i] = v < 0.15f * t->leg && h < 0.05f * t->leg;
      if (!down && still[i]) geo[i] = down = 1;
      else if (down && (v > 0.3f * t->leg || h > 0.1f * t->leg)) down = 0;
    }
    /* every footstep event of this foot lands at a geometric landing */
    int events = 0;
    for (int i = 0; i < STEPS; ++i)
      for (uint32_t e = 0; e < t->nev[i]; ++e) {
        const smg_event* ev = &t->ev[i][e];
        if (ev->type != SMG_EVENT_FOOTSTEP || ev->id != (uint32_t)f) continue;
        ++events;
        assert_true(ev->strength >= 0.0f);
        int ok = 0;
        for (int k = i - 1; k <= i + 1; ++k)
          if (k >= 0 && k < STEPS && geo[k]) ok = 1;
        if (!ok) fprintf(stderr, "foot %d: event at %d has no landing within 1 frame\n", f, i);
        matched += ok;
        /* the event's position is the toe at that step */
        assert_true(fabsf(ev->position[0] - t->toe[i][f][0]) < 1e-4f);
        assert_true(fabsf(ev->position[2] - t->toe[i][f][2]) < 1e-4f);
      }
    for (int i = 0; i < STEPS; ++i) landings += geo[i];
    assert_true(events > 10);
  }
  int events = 0;
  for (int i = 0; i < STEPS; ++i)
    for (uint32_t e = 0; e < t->nev[i]; ++e) events += t->ev[i][e].type == SMG_EVENT_FOOTSTEP;
  printf("footsteps: %d events, %d geometric landings, %d within one frame\n", events, landings,
         matched);
  /* every event at a landing; every landing has its event */
  assert_int_equal(matched, events);
  assert_int_equal(landings, events);
  free(t);
}

static void path_end_once(smg_graph* g) {
  take* t = (take*)malloc(sizeof *t);
  assert_non_null(t);
  run(g, t, 0);
  int ends = 0;
  for (int i = 0; i < STEPS; ++i)
    for (uint32_t e = 0; e < t->nev[i]; ++e)
      if (t->ev[i][e].type == SMG_EVENT_PATH_END) {
        ++ends;
        assert_true(t->end[i] && i > 0 && !t->end[i - 1]);
      }
  assert_int_equal(ends, 1);
  free(t);
}

static void test_constraints_once(void** state) { constraints_once((smg_graph*)*state); }

static void test_footsteps_match_geometry(void** state) {
  footsteps_match_geometry((smg_graph*)*state);
}

static void test_path_end_once(void** state) { path_end_once((smg_graph*)*state); }

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
  constraints_once(g);
  footsteps_match_geometry(g);
  path_end_once(g);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

static void test_arguments(void** state) {
  smg_graph* g = (smg_graph*)*state;
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  smg_event ev[4];
  uint32_t n = 7;
  memset(ev, 0, sizeof ev);
  assert_int_equal(smg_character_get_events(NULL, NULL, 0, &n), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_events(ch, NULL, 0, NULL), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_character_get_events(ch, NULL, 3, &n), SMG_ERROR_INVALID_ARGUMENT);
  /* element size: at least an event, whole floats */
  ev[0].struct_size = 8;
  assert_int_equal(smg_character_get_events(ch, ev, 4, &n), SMG_ERROR_INVALID_ARGUMENT);
  ev[0].struct_size = sizeof(smg_event) + 2;
  assert_int_equal(smg_character_get_events(ch, ev, 4, &n), SMG_ERROR_INVALID_ARGUMENT);
  ev[0].struct_size = sizeof(smg_event);
  assert_int_equal(smg_character_get_events(ch, ev, 4, &n), SMG_OK);
  assert_int_equal(n, 0);
  /* a step with a change of action: too small a buffer says how many */
  assert_int_equal(smg_character_set_action(ch, 1), SMG_OK);
  uint32_t total = 0;
  for (int i = 0; i < 300 && total == 0; ++i) {
    assert_int_equal(smg_character_step(ch, 1.0f / FPS), SMG_OK);
    assert_int_equal(smg_character_get_events(ch, NULL, 0, &total), SMG_OK);
  }
  assert_true(total > 0);
  assert_int_equal(smg_character_get_events(ch, ev, 0, &n), SMG_ERROR_BUFFER_TOO_SMALL);
  assert_int_equal(n, total);
  assert_int_equal(smg_character_get_events(ch, ev, total, &n), SMG_OK);
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
      cmocka_unit_test(test_constraints_once),
      cmocka_unit_test(test_footsteps_match_geometry),
      cmocka_unit_test(test_path_end_once),
      cmocka_unit_test(test_cmu),
      cmocka_unit_test(test_arguments),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
