/*
 * stage_testutil.h - a bench for running one runtime stage alone: the
 * inputs a step would hand it (step_in.h) built from the fixture graph, a
 * path and constraints, plus a lower timeline the test fills itself. No
 * smg_character is involved.
 */
#ifndef SMG_STAGE_TESTUTIL_H
#define SMG_STAGE_TESTUTIL_H

#include "graph_data.h"
#include "lower.h"
#include "path.h"
#include "runtime/runtime_testutil.h"
#include "steer_envelope.h"
#include "step_in.h"

#define STAGE_PATH_CAP 128u
#define STAGE_CONS_CAP 8u

typedef struct stage_rig {
  const smg_graph* g;
  smgi_qentry queue[SMGI_QUEUE_CAP];
  smgi_lower lower;
  float xz[2u * STAGE_PATH_CAP], cum[STAGE_PATH_CAP];
  smgi_path path;
  smgi_constraint items[STAGE_CONS_CAP];
  smgi_constraints cons;
  smgi_steer_envelope steer; /* off unless a test turns it on */
  smgi_step_in in;
} stage_rig;

static inline void stage_rig_init(stage_rig* r, const smg_graph* g) {
  memset(r, 0, sizeof *r);
  r->g = g;
  r->lower.queue = r->queue;
  r->lower.last_frame = 0xffffffffu;
  smgi_lag_reset(&r->lower.lag);
  r->path.xz = r->xz;
  r->path.cum = r->cum;
  r->path.capacity = STAGE_PATH_CAP;
  smgi_path_reset(&r->path);
  r->cons.items = r->items;
  r->cons.capacity = STAGE_CONS_CAP;
  r->cons.next_id = 1;
  r->cons.base_style_arc = r->cons.base_action_arc = -1.0f;
  r->in.graph = g;
  r->in.path = &r->path;
  r->in.cons = &r->cons;
  r->in.fps = g->data.info->frame_rate;
}

/* The path, with progress projected from (x, z). */
static inline void stage_rig_path(stage_rig* r, const float* xz, uint32_t n,
                                  float x, float z) {
  float dist = 0.0f;
  r->in.seg = 0;
  r->in.progress =
      smgi_path_load(&r->path, xz, 0, n, 1, x, z, &r->in.seg, &dist);
}

/* Append lower edge `edge` to the timeline, placed at W (frame -> world
 * through the from-node's ground frame, as the planner places it). */
static inline void stage_rig_push(stage_rig* r, uint32_t edge,
                                  smgi_xform2 W) {
  const smgi_edge* e = &r->g->data.lower_edges[edge];
  smgi_qentry* q = smgi_q_at(&r->lower, r->lower.count++);
  const float* g0 = r->g->data.frames[r->g->data.lower_nodes[e->from].frame].root2d;
  const smgi_xform2 G = {g0[0], g0[1], g0[2]};
  memset(q, 0, sizeof *q);
  q->edge = edge;
  q->seq = r->lower.next_seq++;
  q->W = W;
  q->M = smgi_xf_mul(W, smgi_xf_inv(G));
  r->lower.frames += e->frame_count;
}

#endif /* SMG_STAGE_TESTUTIL_H */
