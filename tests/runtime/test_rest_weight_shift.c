/*
 * test_rest_weight_shift.c - a stop onto standing motion in which the
 * performer shifts the weight: both toes are down by the time the hips
 * stand, judged from the exported poses the way docs/evaluation.md does
 * (at rest: from the first frame after which the hips stay within 5 cm of
 * where they are 4 s after arriving at the path's end; each toe within
 * 2.5 cm of its floor level, the 5th percentile of its height).
 *
 * The graph is baked here from the synthetic clips (bake_synthetic.h)
 * with one change: the hips of the actions performed standing (the
 * standing motion's source) hold still and then move back 4.5 cm over
 * 1.5 s, as a performer settling back while waving does. The character
 * stops towards where the standing motion ends up, so its hips come
 * within 5 cm of where they stand sooner than the settling step aims for.
 * On the runtime that landed that step at a fixed share of the settling
 * (0.55, the hips' last 20 %), a toe was still 3.6-5.1 cm up once the
 * hips stood (a 90-degree corner walked, a U-turn walked, an S-curve
 * run); a performer of the Bandai Namco scale set who shifts the weight
 * while waving stood with a foot 2-3 cm up the same way.
 *
 * A second test ends straight runs in every phase of the stride. A stop
 * in mid-stance over the front foot, the rear foot still in its swing,
 * leaves the hips so near where they stand that no landing within their
 * ease-out keeps the way the step should land before: on the runtime
 * without the hips waiting for the step, the hips stood with the
 * swinging toe 6.4 cm up (a 6.75 m run; the youthful performer of the
 * Bandai Namco scale set, a 90-degree corner run, 6.1 cm).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "bake/bake_graph_helpers.h"
#include "graph_derived.h"
#include "runtime/rest_geom.h"

#define FPS 30.0f
#define SHIFT_M 0.045f   /* how far the standing hips move back */
#define SHIFT_S 1.5f     /* over how long */
#define AFTER_S 4.0f     /* recorded after arriving */
#define MAX_POINTS 256

static rg_run g_run; /* one run at a time */

/* The synthetic set; the actions' hips hold still, then shift back. */
static smg_graph* bake_shifting(smg_bake_result* res) {
  static bg_set s;
  bg_standard(&s, 8.0f);
  for (uint32_t i = 0; i < s.count; ++i) {
    if (s.descs[i].role != SMG_BAKE_ROLE_UPPER) continue;
    smgb_clip* c = &s.clips[i];
    const uint32_t S = SMGB_STRIDE(c->skeleton.joint_count);
    const float x0 = c->poses[0], z0 = c->poses[2];
    for (uint32_t f = 0; f < c->frame_count; ++f) {
      float u = (float)f / c->frame_rate / SHIFT_S;
      if (u > 1.0f) u = 1.0f;
      c->poses[(size_t)f * S] = x0;
      c->poses[(size_t)f * S + 2u] = z0 - SHIFT_M * u * u * (3.0f - 2.0f * u);
    }
  }
  assert_int_equal(bg_bake(&s, NULL, res), SMG_OK);
  bg_free(&s);
  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(res->blob, res->blob_size, NULL, &g),
                   SMG_OK);
  return g;
}

/* One "x z" point per line of data/paths/NAME.txt ('#': comments). */
static uint32_t read_path(const char* name, float* xz) {
  char file[256], line[256];
  snprintf(file, sizeof file, "data/paths/%s.txt", name);
  FILE* f = fopen(file, "r");
  assert_non_null(f);
  uint32_t n = 0;
  while (n < MAX_POINTS && fgets(line, sizeof line, f))
    if (line[0] != '#' && sscanf(line, "%f %f", &xz[2 * n], &xz[2 * n + 1]) == 2)
      ++n;
  fclose(f);
  assert_true(n >= 2u);
  return n;
}

/* Walks or runs the n points xz from the first and stands at the last;
 * returns how far a toe is above its floor level at rest (m). */
static float toe_at_rest_on(smg_graph* g, const float* xz, uint32_t n,
                            const char* style) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  rg_legs legs;
  assert_true(rg_find_legs(g, info.joint_count, &legs));
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = MAX_POINTS;
  d.position[0] = xz[0];
  d.position[2] = xz[1];
  d.heading = atan2f(xz[2] - xz[0], xz[3] - xz[1]);
  assert_int_equal(smg_graph_find_style(g, style, &d.initial_style), SMG_OK);
  smg_character* ch = NULL;
  assert_int_equal(smg_character_create(g, &d, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, xz, n), SMG_OK);
  rg_run* r = &g_run;
  memset(r, 0, sizeof *r);
  r->J = info.joint_count;
  r->dt = 1.0f / FPS;
  assert_true(rg_record_stop(r, ch, &legs, xz[2 * n - 2], xz[2 * n - 1],
                             AFTER_S));
  smg_character_destroy(ch);
  const uint32_t rest = rg_rest_start(r);
  float up = 0.0f;
  for (int f = 0; f < 2; ++f) {
    const float level = rg_floor(r, f);
    for (uint32_t i = rest; i < r->n; ++i)
      up = fmaxf(up, r->toe[i][f][1] - level);
  }
  return up;
}

/* The same along data/paths/NAME.txt. */
static float toe_at_rest(smg_graph* g, const char* path, const char* style) {
  float xz[2 * MAX_POINTS];
  const uint32_t n = read_path(path, xz);
  const float up = toe_at_rest_on(g, xz, n, style);
  print_message("%s %s: a toe %.1f cm above its floor level at rest\n", path,
                style, 100.0f * up);
  return up;
}

static void test_toes_down_when_the_hips_stand(void** state) {
  (void)state;
  smg_bake_result res;
  smg_graph* g = bake_shifting(&res);
  const float sway = smgi_derived_of(g)->idle.sway;
  print_message("standing motion: %u frames, hips stray %.1f cm\n",
                smgi_derived_of(g)->idle.count, 100.0f * sway);
  /* the shift is what the standing motion found shows */
  assert_true(sway >= 0.9f * SHIFT_M);
  assert_true(toe_at_rest(g, "u-turn", "walk") <= RG_BAND);
  if (!smgt_quick()) {
    assert_true(toe_at_rest(g, "corner-left", "walk") <= RG_BAND);
    assert_true(toe_at_rest(g, "s-curve", "run") <= RG_BAND);
  }
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
}

/* Straight runs ending at every length over more than a stride, in steps
 * of 5 cm: the stop arrives in every phase of the stride, among them in
 * mid-stance over the front foot with the rear one in its swing. */
static void test_run_stops_in_every_phase(void** state) {
  (void)state;
  smg_bake_result res;
  smg_graph* g = bake_shifting(&res);
  float worst = 0.0f, at = 0.0f;
  /* quick (valgrind): a quarter of a stride about the phase that failed */
  const uint32_t k0 = smgt_quick() ? 12u : 0u, k1 = smgt_quick() ? 20u : 32u;
  for (uint32_t k = k0; k < k1; ++k) {
    const float len = 6.0f + 0.05f * (float)k;
    const float xz[4] = {0.0f, 0.0f, 0.0f, len};
    const float up = toe_at_rest_on(g, xz, 2u, "run");
    if (up > worst) {
      worst = up;
      at = len;
    }
  }
  print_message("straight runs: a toe at most %.1f cm above its floor level "
                "at rest (%.2f m)\n",
                100.0f * worst, at);
  assert_true(worst <= RG_BAND);
  smg_graph_destroy(g);
  smg_bake_result_free(&res);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_toes_down_when_the_hips_stand),
      cmocka_unit_test(test_run_stops_in_every_phase),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
