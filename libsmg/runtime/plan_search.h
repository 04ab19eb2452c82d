/*
 * plan_search.h - the planner's sequence search (plan_search.c; Kovar et
 * al. 2002 path synthesis), used by the ranking in planner.c.
 *
 * A candidate is judged by the best sequence of edges starting with it
 * that covers SMGI_SEQ_SECONDS of motion. The error of a sequence is the mean,
 * over root samples along it, of the distance between the motion's root
 * after travelling arc length u and the path point at s0 + u, plus a
 * heading term (facing vs the direction towards the path point a little
 * further on, which is the tangent on the path and the way back off it)
 * and a forward-walking term (direction of travel vs facing). Roots come
 * from FRMI root2d placed with the edge's start transform (no FK). The
 * tree of out-edge sequences is searched depth first with branch and
 * bound under an edge-evaluation budget; every candidate first gets a
 * dive along its natural continuation, so all have a complete value even
 * when the budget ends the search early. */
#ifndef SMG_PLAN_SEARCH_H
#define SMG_PLAN_SEARCH_H

#include <stdint.h>

#include "constraints.h"
#include "graph_derived.h"
#include "graph_data.h"
#include "path.h"
#include "rmath.h"
#include "steer_envelope.h"
#include "step_in.h"
#include "tuning.h"

typedef struct smgi_seq_ctx {
  /* the inputs, copied from the step's (step_in.h) */
  const smg_graph* g;
  const smgi_path* track;    /* the path followed */
  const smgi_constraints* cons;
  float fps;
  smgi_steer_plan steer; /* what the steering will correct */
  float s0;          /* path arc length where the sequences start */
  float T;           /* frames a sequence covers */
  int following;     /* a path to follow from s0 on (else: stay near tx,tz) */
  int lost;          /* far off the path: the agile style is wanted */
  int yield;         /* the wanted style cannot follow: the agile one is */
  float leaf_beyond; /* mean distance from the path beyond the steering's
                      * reach of the last smgi_seq_leaf sequence ... */
  float best_beyond; /* ... and of the best sequence found */
  float tx, tz;      /* where to stay when not following */
  uint32_t style0;   /* wanted style at s0 ... */
  float style_end;   /* ... which holds until this arc (next constraint) */
  uint32_t style_next; /* wanted style from style_end on */
  uint32_t style_now;  /* style of the node the sequences start at */
  uint32_t budget;   /* edge evaluations left */
  uint32_t path[SMGI_SEQ_PATH_CAP];      /* edges of the sequence being built */
  uint32_t best_path[SMGI_SEQ_PATH_CAP]; /* and of the best one so far */
  uint32_t best_len;
} smgi_seq_ctx;

typedef struct smgi_seq_state {
  uint32_t node;
  smgi_xform2 W;     /* ground transform at the node */
  float u;           /* arc length travelled since s0 */
  float f;           /* frames covered */
  float cost;        /* accumulated error (mean over the window) */
  float pen;         /* worst style penalty on the way */
  uint32_t seg;      /* path segment hint near s0 + u */
  float beyond;      /* accumulated distance from the path beyond what the
                      * steering removes (mean over the window) */
  uint32_t first_edge, edge_count; /* the node's out-edges (set by
                                    * smgi_seq_step from the edge's record;
                                    * not read of a state it is given) */
} smgi_seq_state;

/* Edge evaluations one ranking may spend. With root steering on, a
 * ranking cost 1.5x the instructions (every root sample also values the
 * steering's reach, and the whole budget was spent), while the residual
 * error of a slightly worse sequence is corrected anyway: each ranking
 * searches half as wide (docs/runtime.md, Root steering, measured). */
static inline uint32_t smgi_seq_budget(const smgi_steer_envelope* steer) {
  return steer->enabled ? SMGI_SEQ_BUDGET_STEER : SMGI_SEQ_BUDGET;
}

/* Distance of a planned ground position W from the path point at s. */
float smgi_plan_start_error(const smgi_path* path, smgi_xform2 W, float s,
                            uint32_t seg);
/* A search starting at lower node `node`, ground transform W, path arc s
 * (segment hint seg): following or staying, lost or not, the wanted
 * style, a full budget. */
void smgi_seq_init(smgi_seq_ctx* c, const smgi_step_in* in,
                   const smgi_steer_envelope* steer, uint32_t node,
                   smgi_xform2 W, float s, uint32_t seg);
/* Append edge `ei` to the sequence in `in` (cw, sw: cosine and sine of
 * in->W.h); `pen_scale` weighs its style penalty. Once cost plus penalty
 * reaches `bound` it stops early with an infinite cost (and only u, f
 * and pen of *out set): the caller prunes it. */
void smgi_seq_step(smgi_seq_ctx* c, const smgi_seq_state* in, float cw,
                   float sw, uint32_t ei, float pen_scale, float bound,
                   smgi_seq_state* out);
/* Value of a sequence that stops choosing at `st` (its natural
 * continuation stands for the rest of the window); INFINITY once it
 * cannot beat `bound`. Sets c->leaf_beyond. */
float smgi_seq_leaf(smgi_seq_ctx* c, smgi_seq_state st, float bound);
/* Depth-first branch and bound below `st`, branching at the next
 * `branches` nodes with a choice; *best is the bound, lowered (with
 * c->best_path, best_len, best_beyond) when a better sequence is found.
 * c->path[0 .. depth) holds the edges leading to st. */
void smgi_seq_dfs(smgi_seq_ctx* c, smgi_seq_state st, uint32_t branches,
                  uint32_t depth, float* best);

#endif /* SMG_PLAN_SEARCH_H */
