/*
 * bake_graph.h - internal state shared by the baker's graph stages
 * (point clouds, graph construction, pruning, simplification, splicing,
 * internodal data, output). The import side (bake_clip.h) hands over
 * smgb_clip objects; from then on everything lives in one smgb_bake.
 *
 * The frame POOL holds every clip frame (clips contiguous, each original
 * followed by its mirror) and, at output time, the blended transition frames
 * of the surviving transition edges (two pseudo-clips, lower then upper).
 * Nodes and edges refer to pool frame indices.
 */
#ifndef BAKE_GRAPH_H
#define BAKE_GRAPH_H

#include <stddef.h>
#include <stdint.h>

#include "bake_clip.h"
#include "bake_roles.h"
#include "printf_check.h"
#include "smg.h"
#include "smg_bake.h"
#include "smg_format.h"

#define SMGB_MAX_LABELS 64
#define SMGB_MAX_JOINTS 256 /* skeletons larger than this are rejected */
#define SMGB_LABEL_MAX 64

/* Resolved options (defaults applied). */
typedef struct smgb_options {
  float frame_rate;
  float window_seconds;
  uint32_t window;             /* k frames */
  float transition_percentile; /* 0..100 */
  float transition_threshold;  /* metres RMS, 0 = none */
  float max_edge_seconds;
  uint32_t max_edge_frames;
  float splice_percentile;
  float splice_region_seconds;
  uint32_t splices_per_region;
  float contact_height, contact_speed;
  uint32_t threads;
  uint32_t no_mirror;
} smgb_options;

typedef struct smgb_pool_clip {
  char name[SMGB_NAME_MAX];
  uint32_t first, count;       /* pool frames */
  uint32_t label;              /* style or action index */
  uint32_t flags;              /* SMGI_CLIP_* */
  uint32_t source_clip;        /* mirror: the clip it mirrors, else self */
} smgb_pool_clip;

/* Skeleton-derived facts: body split, leg chains, segment table. */
#define SMGB_MAX_SEGMENTS 32
typedef struct smgb_segment {
  uint32_t proximal, distal;   /* joint indices */
  float mass;                  /* fraction of body mass */
  float ratio;                 /* COG = proximal + ratio*(distal-proximal) */
  uint32_t upper;              /* 1: upper-body segment */
  const char* name;
} smgb_segment;

typedef struct smgb_body {
  uint32_t joint_count;
  smgb_roles roles;            /* body roles of the reference skeleton */
  uint32_t spine_base;
  uint32_t left_leg[4], right_leg[4];
  uint32_t* body_part;         /* SMG_BODY_* per joint */
  uint32_t* mirror;            /* counterpart joint per joint */
  float* mass_ratio;           /* per joint (segment mass at its proximal) */
  uint32_t* lower_points;      /* joints measured by the lower graph */
  uint32_t lower_point_count;
  uint32_t* torso_points;      /* joints used by Horn's method */
  uint32_t torso_point_count;
  smgb_segment segments[SMGB_MAX_SEGMENTS];
  uint32_t segment_count;
  uint32_t upper_segment_count;
  float leg_length;
} smgb_body;

/* A working-graph edge. ORIGINAL edges play pool frames
 * [from.frame, to.frame) of one clip; TRANSITION edges blend window frames
 * a..a+k-1 with b..b+k-1 (b aligned by `align`, a 2-D transform taking b's
 * clip space into a's) and arrive at pool frame b+k. */
#define SMGB_EDGE_ORIGINAL 0u
#define SMGB_EDGE_TRANSITION 1u
typedef struct smgb_edge {
  uint32_t from, to;           /* node indices */
  uint32_t kind;
  uint32_t a, b;               /* transition: window starts (pool frames) */
  double align[3];             /* transition: x, z, heading */
  float cost;                  /* transition RMS distance, metres */
  /* filled at output */
  uint32_t first_frame, frame_count;
} smgb_edge;

typedef struct smgb_node {
  uint32_t frame;              /* pool frame */
  uint32_t label;
} smgb_node;

typedef struct smgb_graph {
  smgb_node* nodes;
  uint32_t node_count, node_cap;
  smgb_edge* edges;
  uint32_t edge_count, edge_cap;
} smgb_graph;

typedef struct smgb_splice {
  uint32_t lower_frame, action, upper_frame;
  uint32_t upper_edge, upper_offset;
  float distance;
  double correction[4];
} smgb_splice;

typedef struct smgb_bake {
  smgb_options opt;
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

  smg_bake_progress_fn progress;
  void* progress_user;
  const char* stage;
  char error[512];
} smgb_bake;

/* ---- bake_pipeline.c ------------------------------------------------------ */
void smgb_fail(smgb_bake* b, const char* fmt, ...)
    SMG_PRINTF_CHECK(2, 3)
    ;
void smgb_progress(smgb_bake* b, float fraction);
void smgb_bake_free(smgb_bake* b);

/* ---- bake_body.c: body split, mirror map, leg chains, torso points ------- */
/* Recognise the body roles of b->skel (bone_map may be NULL; `source`
 * names the skeleton's file in errors) and derive the tables. */
smg_result smgb_body_init(smgb_bake* b, const char* bone_map,
                          const char* source);
void smgb_body_free(smgb_body* body);

/* ---- bake_upper.c: segment table (Ae et al. 1996) and COGs ---------------- */
smg_result smgb_segments_init(smgb_bake* b);
/* Upper-body segment COGs of pool frame f relative to its root ground frame
 * (x, y, z per upper segment) and the matching weights (mass ratios). */
void smgb_upper_cogs(const smgb_bake* b, uint32_t f, double* out_xyz);
void smgb_upper_weights(const smgb_bake* b, double* out_w);

/* ---- bake_pool.c: the frame pool ------------------------------------------ */
smg_result smgb_pool_add_clip(smgb_bake* b, const smgb_clip* clip,
                              const char* name, uint32_t label,
                              uint32_t flags, uint32_t source_clip);
smg_result smgb_pool_reserve(smgb_bake* b, uint32_t frames);
/* Recompute FK positions and root2d of pool frames [first, first+count). */
void smgb_pool_derive(smgb_bake* b, uint32_t first, uint32_t count);
uint32_t smgb_pool_clip_of(const smgb_bake* b, uint32_t frame);
/* Ground frame of a pose (x, z, heading). */
void smgb_pose_ground(const float* pose, double g[3]);

/* ---- bake_contacts.c ------------------------------------------------------ */
void smgb_contacts_clip(smgb_bake* b, uint32_t clip);

/* ---- bake_pointcloud.c: windowed distance grid + local minima ------------- */
typedef struct smgb_cloud {
  uint32_t frames, points;
  const double* xyz;           /* frames * points * 3 */
  const double* weights;       /* points */
  const uint8_t* valid;        /* frames: window starting here is usable */
} smgb_cloud;

typedef struct smgb_minimum {
  uint32_t i, j;               /* cloud frame indices (row, column) */
  float dist;                  /* RMS distance, metres */
  double align[3];             /* column window -> row window (x, z, h) */
} smgb_minimum;

/* Accept a local minimum (i, j)? 1 = keep. */
typedef int (*smgb_pair_filter)(uint32_t i, uint32_t j, void* user);

typedef struct smgb_grid_job {
  const smgb_cloud* rows;
  const smgb_cloud* cols;
  uint32_t window;
  int align;                   /* 1: optimal 2-D alignment (Kovar) */
  smgb_pair_filter filter;
  void* filter_user;
  uint32_t threads;
  smgb_bake* bake;             /* progress + errors */
} smgb_grid_job;

smg_result smgb_grid_minima(const smgb_grid_job* job, smgb_minimum** out,
                            uint32_t* out_count);
/* Distance of one window pair (reference implementation, tests). */
double smgb_window_distance(const smgb_cloud* A, uint32_t i,
                            const smgb_cloud* B, uint32_t j, uint32_t k,
                            int align, double out_align[3]);

/* ---- bake_graph_build.c --------------------------------------------------- */
/* role: SMGI_CLIP_LOWER or SMGI_CLIP_UPPER. */
smg_result smgb_build_graph(smgb_bake* b, uint32_t role);
smg_result smgb_graph_add_node(smgb_graph* g, uint32_t frame, uint32_t label,
                               uint32_t* out_index);
smg_result smgb_graph_add_edge(smgb_graph* g, const smgb_edge* e);
void smgb_graph_free(smgb_graph* g);
/* Sort edges by (from, to, kind, a, b), stable and deterministic. */
void smgb_graph_sort_edges(smgb_graph* g);

/* ---- bake_scc.c ----------------------------------------------------------- */
/* Strongly connected components (iterative Tarjan). comp[n] gets a
 * component id; returns the number of components or -1 on OOM. */
int32_t smgb_scc(const smgb_graph* g, uint32_t* comp);
/* Keep only nodes with keep[n] != 0 and edges between kept nodes;
 * renumbers. */
smg_result smgb_graph_keep(smgb_graph* g, const uint8_t* keep);
/* Keep the lower graph's largest strongly connected component, and each
 * action's largest in the upper graph. SMG_ERROR_NOT_FOUND when a style or
 * action has none; for an action still built with the phase rule, its bit
 * in b->upper_phase_free is set first, so a rebuild can fall back. */
smg_result smgb_prune(smgb_bake* b, uint32_t role);

/* ---- bake_simplify.c ------------------------------------------------------ */
smg_result smgb_simplify(smgb_bake* b, smgb_graph* g);

/* ---- bake_transition.c ---------------------------------------------------- */
/* Blend weight of A at window step t (Kovar: 2s^3 - 3s^2 + 1, s=(t+1)/k). */
double smgb_blend_alpha(uint32_t t, uint32_t k);
/* Write blended pose t of a transition into out (stride floats). */
void smgb_blend_pose(const smgb_bake* b, const smgb_edge* e, uint32_t t,
                     float* out);
/* A pose of b's clip space placed by ground transform g. */
void smgb_pose_transform(const float* pose, const double g[3], float* out,
                         uint32_t stride);
/* Append blend frames of every transition edge of both graphs. */
smg_result smgb_materialize_transitions(smgb_bake* b);

/* ---- bake_horn.c ---------------------------------------------------------- */
/* Rotation q (x,y,z,w) minimising sum w_i |q a_i q* - b_i|^2 (points
 * already relative to their centres of rotation). */
void smgb_horn(const double* a, const double* b, const double* w,
               uint32_t n, double q[4]);

/* ---- bake_splice.c -------------------------------------------------------- */
smg_result smgb_find_splices(smgb_bake* b);

/* ---- bake_internodal.c ---------------------------------------------------- */
/* Fill first_frame/frame_count (transitions must be materialised) and
 * compute displacement, arc length. */
void smgb_edge_internodal(const smgb_bake* b, const smgb_graph* g,
                          const smgb_edge* e, float disp[3], float* arc);

/* ---- bake_output.c -------------------------------------------------------- */
smg_result smgb_write_blob(smgb_bake* b, void** out_blob, size_t* out_size);

#endif /* BAKE_GRAPH_H */
