/*
 * bake_state.h - the state one bake hands from stage to stage: options,
 * the reference skeleton and body, the frame POOL, the labels, both
 * working graphs, the splice candidates, the report, and the figures the
 * result's statistics are read from. The stages' own headers
 * (bake_import.h, bake_graph_build.h, ...) say which part each reads and
 * writes; bake_pipeline.c runs them in order.
 *
 * The frame POOL holds every clip frame (clips contiguous, each original
 * followed by its mirror; in big bakes the covered clips leave it once the
 * graphs are built, bake_pool_compact.h) and, at output time, the blended
 * transition frames of the surviving transition edges (two pseudo-clips,
 * lower then upper).
 * Nodes and edges refer to pool frame indices.
 */
#ifndef BAKE_STATE_H
#define BAKE_STATE_H

#include <stdint.h>

#include "bake_body.h"
#include "bake_options.h"
#include "bake_report.h"
#include "bake_skeleton.h"
#include "bake_workgraph.h"
#include "smg_format.h"

#define SMGB_MAX_LABELS 64
#define SMGB_LABEL_MAX 64

typedef struct smgb_pool_clip {
  char name[SMGB_NAME_MAX];
  uint32_t first, count;       /* pool frames */
  uint32_t label;              /* style or action index */
  uint32_t flags;              /* SMGI_CLIP_* */
  uint32_t source_clip;        /* mirror: the clip it mirrors, else self */
  uint32_t covered;            /* 1: kept clips of its label already cover
                                  its motion (bake_coverage.h); it gets no
                                  node and leaves the pool before the blob */
} smgb_pool_clip;

typedef struct smgb_splice {
  uint32_t lower_frame, action, upper_frame;
  uint32_t upper_edge, upper_offset;
  float distance;
  double correction[4];
} smgb_splice;

typedef struct smgb_bake {
  smgb_options opt;
  smgb_report report;          /* progress and every problem */
  smgb_skeleton skel;          /* reference skeleton (owned) */
  char target_name[SMGB_NAME_MAX]; /* rig file when baking onto a target,
                                      "" = the first clip's skeleton */
  smgb_body body;
  uint32_t J, stride;

  /* pool */
  float* poses;                /* stride floats per frame */
  smgi_frame* frames;
  float* positions;            /* 3 * J world positions per frame */
  uint32_t frame_count, frame_cap;
  uint32_t source_frame_count; /* clip frames (blend frames follow) */

  smgb_pool_clip* clips;
  uint32_t clip_count, clip_cap;

  char styles[SMGB_MAX_LABELS][SMGB_LABEL_MAX];
  uint32_t style_count;
  char actions[SMGB_MAX_LABELS][SMGB_LABEL_MAX]; /* [0] = "none" */
  uint32_t action_count;

  smgb_graph lower, upper;
  /* Bit l set: action l's upper graph is built without the phase rule
   * (bake_graph_build.c, phase_agrees), because with it the action had no
   * cycle; set by smgb_prune, which the pipeline then reruns. */
  uint64_t upper_phase_free;
  uint32_t lower_candidates, upper_candidates;
  uint32_t lower_nodes_before, lower_edges_before;
  uint32_t upper_nodes_before, upper_edges_before;

  smgb_splice* splices;
  uint32_t splice_count, splice_cap;
  float splice_coverage, splice_max_gap;

  uint32_t bake_flags;
  uint32_t skipped_clips;      /* unusable clips left out (bake_import.c) */
  uint32_t covered_clips;      /* clips the coverage pass left out */
  uint32_t covered_frames;     /* and their frames */
} smgb_bake;

/* An empty bake: default options (smgb_options_resolve fills them), no
 * clips yet, and action 0 ("none", the locomotion's own upper body). */
void smgb_bake_init(smgb_bake* b, smg_bake_progress_fn progress,
                    void* progress_user);
/* Free everything the stages allocated (the report too). */
void smgb_bake_free(smgb_bake* b);

#endif /* BAKE_STATE_H */
