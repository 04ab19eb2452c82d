/*
 * test_style_detour.c - a style change goes straight to the requested
 * style, not through a third one (plan_search.c style penalties,
 * graph_derived.c edge_style_time).
 *
 * A hand-built graph of three styles, every edge moving straight ahead
 * at one speed, so that only the style terms tell its sequences apart:
 *  - style A: a loop of five nodes a0..a4 joined by short edges
 *    (4 frames); a4 has a transition to style B;
 *  - a0 also has a transition to a third style C: one long C edge
 *    (30 frames) to c0, which reaches B either at once or after one more
 *    long C edge (the two scenes below);
 *  - style B: one looping node.
 * The character plays A at a0 and B is wanted from here on. Going
 * straight (four short A edges, then A -> B) takes 16 frames; by hop
 * count that is four edges, while the detour through C is one or two.
 *  - scene 1 (C reaches B after two long edges): the detour is also
 *    longer in time; a hop count had it nearer;
 *  - scene 2 (C reaches B at once): the detour is nearer in time too; it
 *    is still a style nobody asked for and must lose.
 * In both the search must value the direct way better than the detour.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "alloc.h"
#include "graph_derived.h"
#include "plan_search.h"
#include "runtime/stage_testutil.h"

#define FRAMES 200u
#define FPS 30.0f
#define SPEED 1.2f /* m/s, every edge */
#define STYLE_A 0u
#define STYLE_B 1u
#define STYLE_C 2u

enum { A0, A1, A2, A3, A4, C0, C1, B0, NODES };

typedef struct detour_graph {
  smgi_info info;
  smgi_frame frames[FRAMES];
  smgi_node lower[NODES], upper[1];
  smgi_edge edges[16];
  smg_graph g;
} detour_graph;

/* Node frames: every edge starts at its from node's frame and all frames
 * lie on one straight line, so each edge moves straight ahead. */
static const uint32_t k_node_frame[NODES] = {0, 4, 8, 12, 16, 40, 80, 120};

static void add_edge(detour_graph* d, uint32_t* E, uint32_t from,
                     uint32_t to, uint32_t frames, uint32_t label) {
  smgi_edge* e = &d->edges[(*E)++];
  memset(e, 0, sizeof *e);
  e->from = from;
  e->to = to;
  e->first_frame = k_node_frame[from];
  e->frame_count = frames;
  e->displacement[1] = SPEED * (float)frames / FPS;
  e->arc_length = e->displacement[1];
  e->label = label;
  if (label != d->lower[from].label)
    e->flags = SMGI_EDGE_TRANSITION | SMGI_EDGE_STYLE_CHANGE;
  d->lower[from].edge_count++;
}

/* The graph; `c_to_b_at_once`: c0 has the transition to B (scene 2), else
 * only c1 has it (scene 1). */
static void build(detour_graph* d, int c_to_b_at_once) {
  memset(d, 0, sizeof *d);
  d->info.frame_rate = FPS;
  d->info.leg_length = 0.9f;
  for (uint32_t f = 0; f < FRAMES; ++f) {
    d->frames[f].root2d[1] = SPEED * (float)f / FPS;
    d->frames[f].phase = -1.0f;
  }
  static const uint32_t labels[NODES] = {STYLE_A, STYLE_A, STYLE_A, STYLE_A,
                                         STYLE_A, STYLE_C, STYLE_C, STYLE_B};
  uint32_t E = 0;
  for (uint32_t n = 0; n < NODES; ++n) {
    d->lower[n].frame = k_node_frame[n];
    d->lower[n].label = labels[n];
    d->lower[n].first_edge = E;
    switch (n) {
      case A0:
        add_edge(d, &E, A0, A1, 4, STYLE_A);
        add_edge(d, &E, A0, C0, 30, STYLE_C);
        break;
      case A4:
        add_edge(d, &E, A4, A0, 4, STYLE_A);
        add_edge(d, &E, A4, B0, 6, STYLE_B);
        break;
      case C0:
        add_edge(d, &E, C0, C1, 30, STYLE_C);
        if (c_to_b_at_once) add_edge(d, &E, C0, B0, 6, STYLE_B);
        break;
      case C1:
        add_edge(d, &E, C1, C1, 30, STYLE_C);
        add_edge(d, &E, C1, B0, 6, STYLE_B);
        break;
      case B0:
        add_edge(d, &E, B0, B0, 30, STYLE_B);
        break;
      default: /* a1..a3: along the loop */
        add_edge(d, &E, n, n + 1u, 4, STYLE_A);
        break;
    }
  }
  d->upper[0].label = 0;
  smgi_graph_data* g = &d->g.data;
  g->info = &d->info;
  g->frames = d->frames;
  g->frame_count = FRAMES;
  g->style_count = 3;
  g->action_count = 1;
  g->lower_nodes = d->lower;
  g->lower_node_count = NODES;
  g->lower_edges = d->edges;
  g->lower_edge_count = E;
  g->upper_nodes = d->upper;
  g->upper_node_count = 1;
  g->upper_edges = NULL;
  g->upper_edge_count = 0;
  assert_int_equal(smgi_allocator_resolve(NULL, &d->g.allocator), SMG_OK);
  assert_int_equal(smgi_graph_derived_build(&d->g), SMG_OK);
}

/* Best value the search finds below out-edge `k` of a0, with A playing
 * at a0 and B wanted from the start of a straight path on. */
static float best_below(detour_graph* d, stage_rig* r, uint32_t k) {
  smgi_seq_ctx c;
  const smgi_xform2 W = {0.0f, 0.0f, 0.0f};
  const smgi_node* n = &d->g.data.lower_nodes[A0];
  smgi_seq_init(&c, &r->in, &r->steer, A0, W, 0.0f, 0u);
  smgi_seq_state root = {A0, W, 0.0f, 0.0f, 0.0f, 0.0f, 0u, 0.0f,
                         n->first_edge, n->edge_count};
  smgi_seq_state st;
  smgi_seq_step(&c, &root, 1.0f, 0.0f, n->first_edge + k, 1.0f, INFINITY,
                &st);
  float best = INFINITY;
  c.path[0] = n->first_edge + k;
  smgi_seq_dfs(&c, st, SMGI_SEQ_BRANCHES, 1u, &best);
  return best;
}

static void check_scene(int c_to_b_at_once) {
  static detour_graph d;
  static stage_rig r;
  build(&d, c_to_b_at_once);
  const smgi_derived* dv = smgi_derived_of(&d.g);
  const size_t E = d.g.data.lower_edge_count;
  /* the premise: the direct way's first edge (a0 -> a1) is more hops
   * from B than the detour's (a0 -> c0) */
  const uint8_t* hops = dv->lower_hops;
  assert_true(hops[A1 * 3u + STYLE_B] > hops[C0 * 3u + STYLE_B]);
  const uint8_t* direct = dv->edge_style_time + 2u * (STYLE_B * E + 0u);
  const uint8_t* detour = dv->edge_style_time + 2u * (STYLE_B * E + 1u);
  /* in time: 12 frames from a1, 0 or 30 from c0 */
  assert_int_equal(direct[1], 12);
  assert_int_equal(detour[1], c_to_b_at_once ? 0 : 30);

  float xz[2 * 21];
  stage_rig_init(&r, &d.g);
  rt_line(xz, 21, 20.0f);
  stage_rig_path(&r, xz, 21, 0.0f, 0.0f);
  r.cons.base_style = STYLE_A;
  assert_int_equal(smgi_constraints_add(&r.cons, r.path.length, 0.0f,
                                        SMGI_CONSTRAINT_TRANSITION, STYLE_B,
                                        NULL),
                   SMG_OK);
  const float v_direct = best_below(&d, &r, 0u);
  const float v_detour = best_below(&d, &r, 1u);
  print_message("scene %d: direct %.3f, through the third style %.3f\n",
                c_to_b_at_once ? 2 : 1, v_direct, v_detour);
  assert_true(v_direct < v_detour);
  smgi_graph_derived_free(&d.g);
}

static void test_detour_longer_in_time(void** state) {
  (void)state;
  check_scene(0);
}

static void test_detour_shorter_in_time(void** state) {
  (void)state;
  check_scene(1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_detour_longer_in_time),
      cmocka_unit_test(test_detour_shorter_in_time),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
