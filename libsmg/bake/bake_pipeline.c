/*
 * bake_pipeline.c - the stage driver behind smg_bake_run (bake_api.c): it
 * runs the stages in order on one smgb_bake (bake_state.h), times each
 * (wall clock), retries the graph stages where the docs say so, and turns
 * the state into the caller's result: blob, statistics, every problem.
 *
 *   import         load, crop, retarget to the first clip's skeleton,
 *                  resample to the working rate, ground, mirror; fill the
 *                  frame pool (FK, ground frames, foot contacts, phase)
 *   lower graph    Kovar graph of the locomotion clips, pruned to its
 *                  largest SCC
 *   upper graph    Kovar graph of the action clips, pruned per action
 *                  (big bakes: then the clips the coverage pass left out
 *                  of both graphs leave the pool)
 *   simplify       chain merging (both graphs)
 *   splice search  splice candidates + Horn corrections
 *   internodal     transition frames, displacements, arc lengths, blob
 */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _WIN32
#define PSAPI_VERSION 2 /* GetProcessMemoryInfo from kernel32 itself */
#include <windows.h>
#include <psapi.h>
#else
#include <sys/resource.h>
#endif

#include "bake_graph_build.h"
#include "bake_import.h"
#include "bake_pipeline.h"
#include "bake_pool_compact.h"
#include "bake_options.h"
#include "bake_output.h"
#include "bake_scc.h"
#include "bake_simplify.h"
#include "bake_splice.h"
#include "bake_state.h"
#include "bake_transition.h"
#include "blob.h"

static double clock_seconds(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double now_seconds(void) { return clock_seconds(CLOCK_MONOTONIC); }

/* CPU time of the whole process (every thread): the bake's workers
 * included, and whatever else the caller runs meanwhile. */
static double cpu_seconds(void) {
  return clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

/* The process's peak resident memory so far, bytes (Linux reports KiB;
 * Windows has no getrusage: its peak working set is the same measure). */
static uint64_t peak_memory(void) {
#ifdef _WIN32
  PROCESS_MEMORY_COUNTERS c;
  if (!GetProcessMemoryInfo(GetCurrentProcess(), &c, sizeof c)) return 0;
  return (uint64_t)c.PeakWorkingSetSize;
#else
  struct rusage u;
  if (getrusage(RUSAGE_SELF, &u) != 0 || u.ru_maxrss < 0) return 0;
  return (uint64_t)u.ru_maxrss * 1024u;
#endif
}

/* A stage: its name for progress and the result's timing table. */
typedef struct stage_clock {
  const char* name;
  double t0, cpu0;
} stage_clock;

static void stage_begin(smgb_bake* b, stage_clock* c, const char* name) {
  c->name = name;
  c->t0 = now_seconds();
  c->cpu0 = cpu_seconds();
  smgb_report_stage(&b->report, name);
}

static void stage_end(smgb_bake* b, const stage_clock* c,
                      smg_bake_result* out) {
  if (out->stage_count < SMG_BAKE_MAX_STAGES) {
    out->stages[out->stage_count].name = c->name;
    out->stages[out->stage_count].seconds = now_seconds() - c->t0;
    out->stage_cpu_seconds[out->stage_count] = cpu_seconds() - c->cpu0;
    out->stage_peak_bytes[out->stage_count] = peak_memory();
    ++out->stage_count;
  }
  smgb_progress(&b->report, 1.0f);
}

/* Lower graph, pruned to its largest SCC. A style lost in pruning: relax
 * the candidate percentile (per style pair) and retry before giving up. */
static smg_result lower_graph(smgb_bake* b) {
  smg_result r;
  int attempt;
  for (attempt = 0;; ++attempt) {
    uint32_t mark = smgb_report_mark(&b->report);
    r = smgb_build_graph(b, SMGI_CLIP_LOWER);
    if (r == SMG_OK) r = smgb_prune(b, SMGI_CLIP_LOWER);
    if (r != SMG_ERROR_NOT_FOUND || attempt >= 3 ||
        b->opt.transition_percentile >= 100.0f)
      break;
    smgb_report_rewind(&b->report, mark);
    b->opt.transition_percentile *= 2.0f;
    if (b->opt.transition_percentile > 100.0f)
      b->opt.transition_percentile = 100.0f;
  }
  b->lower_nodes_before = b->lower.node_count;
  b->lower_edges_before = b->lower.edge_count;
  return r;
}

/* Upper graph, pruned per action. An action the phase rule left without
 * a cycle is rebuilt without the rule (reported in upper_phase_fallbacks);
 * at most once per action. */
static smg_result upper_graph(smgb_bake* b) {
  smg_result r;
  uint32_t l;
  for (;;) {
    uint64_t phase_free = b->upper_phase_free;
    uint32_t mark = smgb_report_mark(&b->report);
    r = smgb_build_graph(b, SMGI_CLIP_UPPER);
    if (r == SMG_OK) r = smgb_prune(b, SMGI_CLIP_UPPER);
    if (r != SMG_ERROR_NOT_FOUND || b->upper_phase_free == phase_free) break;
    smgb_report_rewind(&b->report, mark);
  }
  for (l = 0; r == SMG_OK && l < b->action_count; ++l)
    if (b->upper_phase_free >> l & 1u)
      smgb_warn(&b->report, "upper graph: action '%s' keeps transitions "
                            "that jump the gait phase (without them it had "
                            "no cycle; docs/baker.md)", b->actions[l]);
  b->upper_nodes_before = b->upper.node_count;
  b->upper_edges_before = b->upper.edge_count;
  return r;
}

static smg_result simplify(smgb_bake* b) {
  smg_result r = smgb_simplify(b, &b->lower);
  if (r == SMG_OK) r = smgb_simplify(b, &b->upper);
  if (r == SMG_OK) r = smgb_materialize_transitions(b);
  return r;
}

static void fill_stats(const smgb_bake* b, smg_bake_result* out) {
  smg_bake_stats* s = &out->stats;
  uint32_t c;
  for (c = 0; c < b->clip_count; ++c)
    if (!(b->clips[c].flags & SMGI_CLIP_BLEND)) ++s->clip_count;
  s->source_frames = b->source_frame_count;
  s->blend_frames = b->frame_count - b->source_frame_count;
  s->lower_candidates = b->lower_candidates;
  s->upper_candidates = b->upper_candidates;
  s->lower_nodes_before = b->lower_nodes_before;
  s->lower_edges_before = b->lower_edges_before;
  s->lower_nodes = b->lower.node_count;
  s->lower_edges = b->lower.edge_count;
  s->upper_nodes_before = b->upper_nodes_before;
  s->upper_edges_before = b->upper_edges_before;
  s->upper_nodes = b->upper.node_count;
  s->upper_edges = b->upper.edge_count;
  s->splice_count = b->splice_count;
  s->splice_coverage = b->splice_coverage;
  s->splice_max_gap = b->splice_max_gap;
  s->style_count = b->style_count;
  s->action_count = b->action_count;
  for (c = 0; c < SMGB_MAX_LABELS; ++c)
    out->upper_phase_fallbacks += (uint32_t)(b->upper_phase_free >> c & 1u);
  out->skipped_clip_count = b->skipped_clips;
  out->covered_clip_count = b->covered_clips;
  out->covered_frame_count = b->covered_frames;
}

/* Every problem of the bake into the result: the first error as its one
 * line, and the whole list. */
static void fill_problems(const smgb_report* rep, smg_result r,
                          smg_bake_result* out) {
  const char* first = smgb_report_first_error(rep);
  snprintf(out->error, sizeof out->error, "%s",
           r == SMG_OK ? "" : first[0] ? first : smg_result_string(r));
  out->error_count = rep->error_count + rep->dropped;
  out->warning_count = rep->warning_count;
  if (r != SMG_OK && out->error_count == 0) out->error_count = 1;
  smgb_report_text(rep, out->problems, sizeof out->problems);
}

smg_result smgb_pipeline_run(const smg_bake_desc* desc,
                             smg_bake_result* out) {
  smgb_bake* b;
  smg_result r;
  stage_clock c;
  double tstart = now_seconds(), cstart = cpu_seconds();
  b = calloc(1, sizeof *b);
  if (!b) {
    snprintf(out->error, sizeof out->error, "out of memory");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  smgb_bake_init(b, desc->progress, desc->progress_user);
  r = smgb_options_resolve(&desc->options, &b->opt, &b->report);
  if (r != SMG_OK) goto done;

  stage_begin(b, &c, "import");
  if ((r = smgb_import_clips(b, desc)) != SMG_OK) goto done;
  stage_end(b, &c, out);

  stage_begin(b, &c, "lower graph");
  if ((r = lower_graph(b)) != SMG_OK) goto done;
  stage_end(b, &c, out);

  stage_begin(b, &c, "upper graph");
  if ((r = upper_graph(b)) != SMG_OK) goto done;
  stage_end(b, &c, out);

  /* covered clips (big sets) have no node: their frames go before the
   * transitions' blend frames are appended */
  smgb_pool_drop_covered(b);

  stage_begin(b, &c, "simplify");
  if ((r = simplify(b)) != SMG_OK) goto done;
  stage_end(b, &c, out);

  stage_begin(b, &c, "splice search");
  if ((r = smgb_find_splices(b)) != SMG_OK) goto done;
  stage_end(b, &c, out);
  /* The joint positions were for the distance searches; the blob is made
   * of poses and frame records. Freed before the blob is built, which is
   * when a big bake's memory peaks. */
  free(b->positions);
  b->positions = NULL;

  stage_begin(b, &c, "internodal + blob");
  if ((r = smgb_write_blob(b, &out->blob, &out->blob_size)) != SMG_OK)
    goto done;
  stage_end(b, &c, out);
  fill_stats(b, out);
done:
  if (r != SMG_OK) {
    if (out->blob) smgi_blob_free(out->blob, NULL);
    out->blob = NULL;
    out->blob_size = 0;
  }
  fill_problems(&b->report, r, out);
  out->total_seconds = now_seconds() - tstart;
  out->total_cpu_seconds = cpu_seconds() - cstart;
  out->peak_bytes = peak_memory();
  smgb_bake_free(b);
  free(b);
  return r;
}
