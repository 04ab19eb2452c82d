/*
 * smg_bake.h - libsmg's OFFLINE baking API (not part of the runtime).
 *
 * Turns motion-capture clips into the graph blob that the runtime
 * (include/smg.h) loads: the preprocessing of "Splicing Motion Graphs"
 * (Tamada, Kitaoka, Kitamura), section III.B:
 *   1. import + retarget to one reference skeleton + resample + mirror,
 *   2. lower-body (locomotion) and upper-body (action) motion graphs by the
 *      construction of Kovar et al. 2002 (windowed point-cloud distance with
 *      optimal 2-D alignment, local minima, blended transitions, pruning to
 *      strongly connected components), then chain simplification,
 *   3. splice candidates (upper-body segment-COG distance) with the Horn
 *      1987 spine correction,
 *   4. internodal data (frame counts, displacements, arc lengths, costs)
 *      and per-frame foot contacts / gait phase.
 * Link with libsmg_bake.a (and assimp, pthread, m). The command-line front
 * end is `smg-bake` (tools/smg_bake.c); docs/baker.md explains every stage.
 *
 * Conventions are smg.h's: descriptor structs are zero-initialised, the
 * caller sets struct_size and only the fields it cares about (zero = the
 * documented default); struct_size may be that of an older, smaller
 * version of the struct (all clip descs of one array share one size; an
 * all-zero options struct means defaults); every call returns an
 * smg_result; on failure a
 * one-line message naming the file, line (when there is one) and problem
 * is written to the result's `error` buffer, and the list of every problem
 * the bake met to its `problems`.
 *
 * Not thread-safe per result; independent bakes may run on different
 * threads. The baker itself may use worker threads (options.threads).
 */
#ifndef SMG_BAKE_H
#define SMG_BAKE_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which graph a clip feeds. */
#define SMG_BAKE_ROLE_LOWER 1u /* locomotion: lower-body graph, label=style */
#define SMG_BAKE_ROLE_UPPER 2u /* action: upper-body graph, label=action */

/* Per-clip mirroring. */
#define SMG_BAKE_MIRROR_DEFAULT 0u /* follow smg_bake_options.no_mirror */
#define SMG_BAKE_MIRROR_YES 1u     /* add a mirrored copy */
#define SMG_BAKE_MIRROR_NO 2u      /* never mirror this clip */

/* smg_bake_clip_desc.flags */
/* A clip that cannot be used (unreadable, too short for a transition
 * window, a skeleton without the body roles, ...) is left out with a
 * warning instead of failing the bake: the clips of a manifest's folder
 * pattern (docs/manifest.md). Without it every problem is an error. */
#define SMG_BAKE_CLIP_SKIP_UNUSABLE 1u

/* A clip held in memory instead of a file (tools, tests, engines that have
 * their own importers). Poses use the blob's layout: per frame the root
 * translation (3 floats, metres, Y up, facing +Z at identity) then one
 * local rotation (x,y,z,w) per joint. Everything is copied. */
typedef struct smg_bake_memory_clip {
  uint32_t joint_count;
  const char* const* joint_names; /* joint_count names */
  const int32_t* parents;         /* -1 for joint 0; parent < index */
  const float* offsets;           /* 3 * joint_count, metres */
  const float* poses;             /* frame_count * (3 + 4 * joint_count) */
  uint32_t frame_count;
  float frame_rate;               /* frames per second of `poses` */
} smg_bake_memory_clip;

typedef struct smg_bake_clip_desc {
  uint32_t struct_size;    /* = sizeof(smg_bake_clip_desc) */
  uint32_t role;           /* SMG_BAKE_ROLE_LOWER or _UPPER (required) */
  const char* path;        /* .bvh, or .gltf/.glb/.fbx through assimp;
                              relative paths are joined to data_dir.
                              NULL when `memory` is set. */
  const smg_bake_memory_clip* memory; /* in-memory clip instead of path */
  const char* label;       /* style ("walk", "run") or action ("punch");
                              required; an upper label may not be "none" */
  const char* name;        /* shown in --info; NULL = file name */
  uint32_t first_frame;    /* first source frame used (after skipping the
                              T-pose), 0 = start */
  uint32_t frame_count;    /* source frames used, 0 = to the end */
  uint32_t mirror;         /* SMG_BAKE_MIRROR_* */
  uint32_t skip_first_frame; /* 1: drop a synthetic T-pose frame 0 (CMU) */
  float unit_scale;        /* file units -> metres (CMU 0.056444);
                              0 = guess from the hips height */
  uint32_t animation_index; /* assimp files: which animation */
  int32_t source_line;     /* manifest line, for error messages (0 = none) */
  uint32_t flags;          /* SMG_BAKE_CLIP_* (0 = none) */
  const char* bones;       /* bone map: which joint plays which body role,
                              one "role=joint" per line, e.g.
                              "left_foot=Foot_L\nright_foot=Foot_R"
                              (docs/manifest.md `bones`); NULL = recognise
                              the roles from the joint names */
} smg_bake_clip_desc;

typedef struct smg_bake_options {
  uint32_t struct_size;      /* = sizeof(smg_bake_options) */
  uint32_t no_mirror;        /* 1: do not add mirrored copies (default:
                                every clip is mirrored so that left and
                                right turns both exist) */
  float frame_rate;          /* working frame rate; 0 = 30 */
  float window_seconds;      /* transition/splice window; 0 = 1/3 s */
  float transition_percentile; /* transition candidates kept: this percent
                                of the local minima of the frame distance,
                                ranked per (source clip, target clip) pair
                                for same-label transitions and per (label,
                                label) pair for label changes; 0 = 30 */
  float transition_threshold;  /* absolute RMS distance cap (metres) on
                                top of the percentile; 0 = none */
  float max_edge_seconds;    /* simplification cap on merged edges; 0 = 1 */
  float splice_percentile;   /* splice minima kept per action; 0 = 30 */
  float splice_region_seconds; /* one group of candidates per lower region
                                of this length; 0 = 0.5 s */
  uint32_t splices_per_region; /* best candidates kept per (region,
                                action); 0 = 2 */
  float contact_height;      /* foot contact: ankle/toe height above the
                                clip's lowest, metres; 0 = 0.06 */
  float contact_speed;       /* foot contact: horizontal speed, m/s;
                                0 = 0.6 */
  uint32_t threads;          /* worker threads for the distance grids;
                                0 = 2, 1 = single-threaded */
  uint32_t reserved[7];
} smg_bake_options;

/* Called between and inside long stages. stage is a static name ("import",
 * "lower graph", ...), fraction in [0,1] within it. */
typedef void (*smg_bake_progress_fn)(const char* stage, float fraction,
                                     void* user);

typedef struct smg_bake_desc {
  uint32_t struct_size;      /* = sizeof(smg_bake_desc) */
  uint32_t clip_count;
  const smg_bake_clip_desc* clips; /* at least one lower clip */
  const char* data_dir;      /* base of relative paths; NULL = cwd */
  smg_bake_options options;  /* zero = defaults (set options.struct_size
                                or leave the whole struct zero) */
  smg_bake_progress_fn progress; /* optional */
  void* progress_user;
  /* Added with retargeting (a desc whose struct_size ends before these
   * fields bakes onto the first clip's skeleton): */
  const char* target_path;   /* rig whose skeleton, rest pose and
                                proportions the blob uses (.bvh, or
                                .gltf/.glb/.fbx through assimp: the first
                                frame of target_animation is its rest);
                                every clip is retargeted onto it. Relative
                                paths are joined to data_dir. NULL = the
                                first clip's skeleton */
  float target_unit_scale;   /* rig file units -> metres; 0 = guess */
  uint32_t target_animation; /* assimp rigs: which animation */
} smg_bake_desc;

#define SMG_BAKE_MAX_STAGES 16

typedef struct smg_bake_stage {
  const char* name;          /* static string */
  double seconds;            /* wall-clock time of the stage */
} smg_bake_stage;

typedef struct smg_bake_stats {
  uint32_t clip_count;       /* incl. mirrored copies, excl. blend clips */
  uint32_t source_frames;    /* clip frames in the pool */
  uint32_t blend_frames;     /* transition frames appended */
  uint32_t lower_candidates, upper_candidates; /* transitions before SCC */
  uint32_t lower_nodes_before, lower_edges_before; /* after SCC pruning,
                                                      before simplify */
  uint32_t lower_nodes, lower_edges;               /* in the blob */
  uint32_t upper_nodes_before, upper_edges_before;
  uint32_t upper_nodes, upper_edges;
  uint32_t splice_count;
  float splice_coverage;     /* fraction of lower frames that have a
                                candidate for every action within 1 s */
  float splice_max_gap;      /* longest wait (s) for any action's candidate
                                from any lower frame */
  uint32_t style_count, action_count;
} smg_bake_stats;

typedef struct smg_bake_result {
  uint32_t struct_size;      /* caller sets = sizeof(smg_bake_result) */
  uint32_t stage_count;
  void* blob;                /* the graph blob (16-byte aligned), owned */
  size_t blob_size;
  smg_bake_stage stages[SMG_BAKE_MAX_STAGES];
  double total_seconds;
  smg_bake_stats stats;
  char error[512];           /* one line on failure, "" on success */
  uint32_t upper_phase_fallbacks; /* actions whose upper graph had to keep
                                     transitions that jump the gait phase
                                     (with only phase-keeping ones the
                                     action had no cycle; docs/baker.md) */
  /* Added with the problem list (a result whose struct_size ends before
   * these fields gets `error` only): */
  uint32_t error_count;      /* errors met; the bake failed when > 0 */
  uint32_t warning_count;    /* warnings met; the bake went on */
  char problems[4096];       /* every error and warning of the bake, one
                                per line ("error: ..." / "warning: ..."),
                                in the order met, so a run with several
                                broken clips or options names all of them
                                ("" when none; a last line counts those
                                that did not fit) */
  /* Added with folder patterns: */
  uint32_t skipped_clip_count; /* clips marked SMG_BAKE_CLIP_SKIP_UNUSABLE
                                  that were left out (each named by a
                                  warning in `problems`) */
  /* Per stage (as `stages`) and in all: CPU seconds of the whole process
   * (every thread), and the process's peak resident memory in bytes at
   * the end of the stage (getrusage; 0 where not known). */
  double stage_cpu_seconds[SMG_BAKE_MAX_STAGES];
  uint64_t stage_peak_bytes[SMG_BAKE_MAX_STAGES];
  double total_cpu_seconds;
  uint64_t peak_bytes;
  /* Added with the coverage pass (big sets, docs/baker.md): clips left out
   * because kept clips of their label already cover their motion, and
   * their frames (stats.clip_count and stats.source_frames count the
   * clips and frames kept). */
  uint32_t covered_clip_count;
  uint32_t covered_frame_count;
} smg_bake_result;

/* Bake. `out` must have struct_size set; it is reset first. On failure out
 * holds no blob, out->error is the first problem and out->problems lists
 * them all. Same inputs and options give a
 * byte-identical blob. */
smg_result smg_bake_run(const smg_bake_desc* desc, smg_bake_result* out);

/* Write result->blob to `path` atomically: into a fresh hidden temporary
 * file in the same directory (.NAME.XXXXXX), flushed to disk, then renamed
 * over `path`. A failed or interrupted write never leaves a partial file
 * at `path`: the old file, if any, stays as it was. */
smg_result smg_bake_write_file(const smg_bake_result* result,
                               const char* path, char* error,
                               size_t error_size);

/* Free what smg_bake_run allocated (safe on a zeroed or failed result). */
void smg_bake_result_free(smg_bake_result* result);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SMG_BAKE_H */
