/*
 * rest_scene.h - one character for the rest-stage tests (test_rest.c,
 * test_data_stop.c): created at the origin facing +Z with the default
 * desc, stepped at a fixed rate, every frame from its first pose recorded
 * into a run (rest_geom.h). Include after cmocka.h.
 */
#ifndef SMG_REST_SCENE_H
#define SMG_REST_SCENE_H

#include "runtime/rest_geom.h"

typedef struct scene {
  smg_character* ch;
  rg_legs legs;
  rg_run* run; /* where the frames go */
  float fps;
} scene;

static inline void scene_start(smg_graph* g, scene* s, rg_run* run,
                               float fps) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_true(rg_find_legs(g, info.joint_count, &s->legs));
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  assert_int_equal(smg_character_create(g, &d, &s->ch), SMG_OK);
  s->run = run;
  s->fps = fps;
  memset(run, 0, sizeof *run);
  run->J = info.joint_count;
  run->dt = 1.0f / fps;
  assert_true(rg_record(run, s->ch, &s->legs));
  rg_orient(run, &s->legs, 0.0f);
  if (run->n == 0) assert_true(rg_record(run, s->ch, &s->legs));
}

static inline void scene_run(scene* s, float seconds) {
  const uint32_t n = (uint32_t)(seconds * s->fps + 0.5f);
  for (uint32_t i = 0; i < n; ++i) {
    assert_int_equal(smg_character_step(s->ch, 1.0f / s->fps), SMG_OK);
    assert_true(rg_record(s->run, s->ch, &s->legs));
  }
}

#endif /* SMG_REST_SCENE_H */
