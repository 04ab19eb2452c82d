/*
 * test_plan_search.c - the sequence search's shortcuts change nothing
 * (plan_search.c, steer_envelope.h), on the fixture graph:
 *  - smgi_steer_plan_view (the per-search constants of the steering
 *    envelope, one call per root sample) gives bit for bit what the
 *    envelope's reach at the slowed and the cutting limits and its
 *    discounts give, over a grid of limits, speeds, arcs and errors, with
 *    steering on and off;
 *  - a bound only prunes: smgi_seq_step and smgi_seq_leaf under a bound
 *    return exactly what they return unbounded when that is below the
 *    bound, and something the caller prunes (cost + penalty at or above
 *    it) otherwise - for every edge and leaf from states on, off and far
 *    off a path, with and without a transition to another style (whose
 *    penalty alone prunes), following and at the path's end.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "plan_search.h"
#include "runtime/stage_testutil.h"

typedef rt_fixture_ctx ctx;

static int same_bits(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The planner's view of one sample written out from the envelope's own
 * functions: what no correction removes lies beyond the reach of the
 * steering slowing down or cutting the turn; within its plain reach an
 * error counts SMGI_STEER_PLAN_WEIGHT of itself. */
static float view_ref(const smgi_steer_envelope* s, float u, float speed,
                      float* d, float* a) {
  smgi_steer_envelope cut = *s;
  cut.turn_limit *= SMGI_STEER_CUT_TURN;
  cut.slide_ratio *= SMGI_STEER_CUT_SLIDE;
  const float slowed = smgi_steer_plan_reach(s, u, speed * smgi_steer_slowest(s));
  const float cutting = smgi_steer_plan_reach(
      &cut, u, speed * smgi_steer_cut_floor(s->slide_ratio));
  const float reach = slowed > cutting ? slowed : cutting;
  const float beyond = *d > reach ? *d - reach : 0.0f;
  if (s->enabled && u > 0.0f) {
    const float k = smgi_steer_plan_curve(s, speed);
    *d = smgi_steer_discount(*d, 0.5f * (s->slide_ratio * u + 0.5f * k * u * u));
    *a = smgi_steer_discount(*a, 0.5f * k * u);
  }
  return beyond;
}

static void test_plan_view_matches_envelope(void** state) {
  (void)state;
  static const float limits[] = {0.0f, 0.3f, 1.0f, 2.5f, 6.0f};
  static const float slides[] = {-0.5f, 0.0f, 0.1f, 0.35f, 0.7f, 1.0f, 1.6f};
  static const float us[] = {-1.0f, 0.0f, 0.01f, 0.5f, 1.7f, 4.0f};
  static const float speeds[] = {0.0f, 5e-4f, 0.3f, 1.4f, 3.9f, 8.0f};
  static const float ds[] = {0.0f, 0.02f, 0.3f, 2.0f};
  static const float as[] = {0.0f, 0.1f, 1.5f};
  uint32_t checked = 0, discounted = 0;
  for (uint32_t on = 0; on < 2u; ++on)
    for (size_t il = 0; il < sizeof limits / sizeof *limits; ++il)
      for (size_t is = 0; is < sizeof slides / sizeof *slides; ++is) {
        smgi_steer_envelope env;
        memset(&env, 0, sizeof env);
        env.enabled = on;
        env.turn_limit = limits[il];
        env.slide_ratio = slides[is];
        const smgi_steer_plan plan = smgi_steer_plan_of(&env);
        for (size_t iu = 0; iu < sizeof us / sizeof *us; ++iu)
          for (size_t iv = 0; iv < sizeof speeds / sizeof *speeds; ++iv)
            for (size_t id = 0; id < sizeof ds / sizeof *ds; ++id)
              for (size_t ia = 0; ia < sizeof as / sizeof *as; ++ia) {
                float d0 = ds[id], a0 = as[ia], d1 = d0, a1 = a0;
                const float b0 = view_ref(&env, us[iu], speeds[iv], &d0, &a0);
                const float b1 =
                    smgi_steer_plan_view(&plan, us[iu], speeds[iv], &d1, &a1);
                assert_true(same_bits(b0, b1));
                assert_true(same_bits(d0, d1));
                assert_true(same_bits(a0, a1));
                if (d1 != ds[id]) ++discounted;
                ++checked;
              }
      }
  assert_true(checked > 10000u);
  assert_true(discounted > 1000u); /* the discount was exercised */
}

static int same_state(const smgi_seq_state* a, const smgi_seq_state* b) {
  return a->node == b->node && same_bits(a->W.x, b->W.x) &&
         same_bits(a->W.z, b->W.z) && same_bits(a->W.h, b->W.h) &&
         same_bits(a->u, b->u) && same_bits(a->f, b->f) &&
         same_bits(a->cost, b->cost) && same_bits(a->pen, b->pen) &&
         a->seg == b->seg && same_bits(a->beyond, b->beyond) &&
         a->first_edge == b->first_edge && a->edge_count == b->edge_count;
}

/* Bounds around value v: well below, just below, at, just above, above. */
static void bounds_around(float v, float* b) {
  b[0] = 0.5f * v;
  b[1] = nextafterf(v, -INFINITY);
  b[2] = v;
  b[3] = nextafterf(v, INFINITY);
  b[4] = 2.0f * v + 0.1f;
}

/* Every edge from `st` and every leaf after it, bounded against unbounded;
 * counts the comparisons made, those pruned and those kept. */
static void check_bounds_from(smgi_seq_ctx* c, const smgi_seq_state* st,
                              uint32_t* pruned, uint32_t* kept) {
  const smg_graph* g = c->g;
  float cw, sw;
  smgi_sincosf(st->W.h, &sw, &cw);
  for (uint32_t ei = 0; ei < g->data.lower_edge_count; ++ei) {
    if (g->data.lower_edges[ei].from != st->node) continue;
    smgi_seq_state full, cut;
    smgi_seq_step(c, st, cw, sw, ei, 0.5f, INFINITY, &full);
    float bs[5];
    bounds_around(full.cost + full.pen, bs);
    for (int k = 0; k < 5; ++k) {
      smgi_seq_step(c, st, cw, sw, ei, 0.5f, bs[k], &cut);
      if (full.cost + full.pen >= bs[k]) {
        assert_true(cut.cost + cut.pen >= bs[k]);
        ++*pruned;
      } else {
        assert_true(same_state(&full, &cut));
        ++*kept;
      }
    }
    if (!isfinite(full.cost)) continue;
    const float v = smgi_seq_leaf(c, full, INFINITY);
    const float beyond = c->leaf_beyond;
    bounds_around(v, bs);
    for (int k = 0; k < 5; ++k) {
      c->leaf_beyond = -1.0f;
      const float w = smgi_seq_leaf(c, full, bs[k]);
      if (v < bs[k]) {
        assert_true(same_bits(v, w));
        assert_true(same_bits(beyond, c->leaf_beyond));
        ++*kept;
      } else {
        assert_true(w >= bs[k]);
        ++*pruned;
      }
    }
  }
}

/* A search from node `node` placed at W on the rig's path at arc s. */
static void check_search(stage_rig* r, uint32_t node, smgi_xform2 W, float s,
                         uint32_t* pruned, uint32_t* kept) {
  smgi_seq_ctx c;
  smgi_seq_init(&c, &r->in, &r->steer, node, W, s, 0u);
  const smgi_node* n = &r->g->data.lower_nodes[node];
  smgi_seq_state root = {node, W, 0.0f, 0.0f, 0.0f, 0.0f, 0u, 0.0f,
                         n->first_edge, n->edge_count};
  check_bounds_from(&c, &root, pruned, kept);
  /* and one level down, where cost and penalty are not zero */
  float cw, sw;
  smgi_sincosf(W.h, &sw, &cw);
  for (uint32_t k = 0; k < n->edge_count; ++k) {
    smgi_seq_state st;
    smgi_seq_step(&c, &root, cw, sw, n->first_edge + k, 1.0f, INFINITY, &st);
    if (isfinite(st.cost)) check_bounds_from(&c, &st, pruned, kept);
  }
}

static void test_bounds_only_prune(void** state) {
  ctx* x = (ctx*)*state;
  static stage_rig r;
  uint32_t pruned = 0, kept = 0;
  for (int scene = 0; scene < 4; ++scene) {
    stage_rig_init(&r, x->g);
    float xz[2 * 21];
    rt_line(xz, 21, 12.0f);
    stage_rig_path(&r, xz, 21, 0.0f, 0.0f);
    if (scene >= 1) { /* steering on */
      r.steer.enabled = 1u;
      r.steer.turn_limit = 1.2f;
      r.steer.slide_ratio = 0.3f;
      r.steer.stop_seconds = 0.6f;
      r.steer.own_speed = 1.4f;
    }
    if (scene >= 2) /* run from 1 m on: walking edges pay a penalty */
      assert_int_equal(smgi_constraints_add(&r.cons, r.path.length, 1.0f,
                                            SMGI_CONSTRAINT_TRANSITION, 1,
                                            NULL),
                       SMG_OK);
    static const smgi_xform2 starts[] = {{0.0f, 0.0f, 0.0f},
                                         {0.4f, 0.5f, 0.6f},
                                         {-1.0f, 2.0f, -2.5f},
                                         {3.0f, 1.0f, 1.5f}}; /* lost */
    static const float arcs[] = {0.0f, 3.0f, 11.9f}; /* 11.9: the end */
    for (uint32_t node = 0; node < r.g->data.lower_node_count; ++node) {
      if (r.g->data.lower_nodes[node].edge_count == 0) continue;
      for (size_t i = 0; i < sizeof starts / sizeof *starts; ++i) {
        smgi_xform2 W = starts[i];
        for (size_t j = 0; j < sizeof arcs / sizeof *arcs; ++j) {
          if (scene == 3) W.h = smgi_wrap_angle(starts[i].h + 2.0f);
          check_search(&r, node, W, arcs[j], &pruned, &kept);
        }
      }
    }
  }
  assert_true(pruned > 100u);
  assert_true(kept > 100u);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_plan_view_matches_envelope),
      cmocka_unit_test(test_bounds_only_prune),
  };
  return cmocka_run_group_tests(tests, rt_fixture_setup, rt_fixture_teardown);
}
