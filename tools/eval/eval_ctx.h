/*
 * eval_ctx.h - what every part of the evaluation driver shares: where the
 * data is, where results go, and the report/check helpers.
 *
 * Two modes:
 *   report mode (make eval): every section writes Markdown to ctx->md and
 *     figures to ctx->img_dir; nothing is checked against bounds.
 *   check mode (make test-eval, --check): no files are written; each
 *     section measures a cheap subset and eval_check() compares it with
 *     loose bounds, counting failures (the exit status).
 */
#ifndef EVAL_CTX_H
#define EVAL_CTX_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "smg.h"

typedef struct eval_ctx {
  char cmu_dir[1024];    /* <shared>/mocap/cmu */
  int have_cmu;          /* the CMU clips are readable */
  const char* img_dir;   /* report mode: docs/img */
  const char* img_rel;   /* the same, relative to results.md ("img") */
  FILE* md;              /* report mode: the report body (sections) */
  FILE* summary;         /* report mode: summary bullets, printed first */
  int check;             /* check mode */
  int quick;             /* shrink work (check mode) */
  int failures;          /* failed checks */
  const char* default_blob; /* synthetic blob for checks without CMU */
  const char* keep_dir;  /* --keep: also write blobs and CSV traces here */
  const char* manifest;  /* the paper-size set (data/cmu.manifest) */
  char bandai_dir[1024]; /* <shared>/mocap/bandai-namco */
  int have_bandai;       /* the Bandai Namco clips are readable */
  const char* bandai_manifest; /* data/bandai.manifest */
  const char* only;      /* --only SECTION: run just that one ("follow",
                          * "behaviour") */
} eval_ctx;

/* Markdown output (no-op in check mode). */
void eval_md(eval_ctx* ctx, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* One summary bullet (Markdown, no leading "- ", no newline); shown at the
 * top of results.md. No-op in check mode. */
void eval_summary(eval_ctx* ctx, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* A check with loose bounds: prints PASS/FAIL with the measured text and
 * counts failures. Returns ok. */
int eval_check(eval_ctx* ctx, int ok, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Progress / diagnostics on stderr. */
void eval_log(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Full path of figure `name` (e.g. "eval-path-straight.svg") in img_dir. */
void eval_img_path(const eval_ctx* ctx, const char* name, char* buf,
                   size_t size);

/* Monotonic clock, seconds. */
double eval_now(void);

/* Path of a CMU clip ("09_12" -> <cmu_dir>/09_12.bvh). */
void eval_cmu_clip(const eval_ctx* ctx, const char* id, char* buf,
                   size_t size);

/* Number formatting for tables: "n/a" for non-finite values. */
const char* eval_fmt(char* buf, size_t size, const char* fmt, double v);

/* ---- sections (each writes its own part of results.md) ---------------- */

/* The paper-size CMU bake (Section IV preprocessing table). On success
 * *out_blob/out_size hold the baked blob (malloc'd, 16-byte aligned, the
 * caller frees it with free()); NULL when the bake could not run. */
void eval_section_bake(eval_ctx* ctx, void** out_blob, size_t* out_size);
/* Bakes a loaded manifest's clips at its frame rate with `threads` worker
 * threads (0: the baker's default), quietly; *res as smg_bake_run leaves
 * it (free with smg_bake_result_free). Every section that bakes uses it. */
struct smgb_manifest;
struct smg_bake_result;
smg_result eval_bake_manifest(const struct smgb_manifest* m, uint32_t threads,
                              struct smg_bake_result* res);
/* Loads a manifest (clips in data_dir) and bakes it in-process into a
 * 16-byte aligned block (free()) that lives in memory only; *out_size its
 * size. NULL (with a log line) when the manifest or the bake fails. */
void* eval_bake_to_memory(const char* manifest, const char* data_dir,
                          size_t* out_size);
/* Path following on five paths with transition and splice points. */
void eval_section_paths(eval_ctx* ctx, const void* blob, size_t size);
/* Feet from geometry: planted-toe speed with IK on and off on every path
 * of the CMU graph and of a two-performer graph, and the source clips'. */
void eval_section_feet(eval_ctx* ctx, const void* blob, size_t size);
/* Section 2b's swing-clearance figure (eval_swing.c): on the CMU blob. */
void eval_figure_swing(eval_ctx* ctx, const void* blob, size_t size);
/* Staying on drawn paths (issue 12): data/paths on the CMU blob (may be
 * NULL), the sparse set and the Bandai Namco set (in its `walk` and
 * `exhausted` styles; skipped when its clips are absent), root steering on
 * and off; in check mode the tight paths on the default, CMU and Bandai
 * Namco blobs with steering on. */
void eval_section_follow(eval_ctx* ctx, const void* cmu_blob,
                         size_t cmu_size);
/* Doing what was asked, like a person (issue 24, eval_behaviour.c):
 * style held, cadence, rest, start, a path behind, and what must keep
 * holding, from the exported poses on the CMU blob, the sparse set and
 * the Bandai Namco set (tables only); filmstrips of a stop and a start on
 * the CMU graph. Report mode only. */
void eval_section_behaviour(eval_ctx* ctx, const void* cmu_blob,
                            size_t cmu_size);
/* Splicing accuracy (Fig. 5) and the synchronization check. */
void eval_section_splice(eval_ctx* ctx);
/* Section 2's paths and tables on another baked graph (no figures);
 * `graph` names it in the tables and the summary. Check mode: the straight
 * path with section 2's bounds. */
void eval_paths_on_graph(eval_ctx* ctx, const void* blob, size_t size,
                         const char* graph);
/* A second studio: the Bandai Namco Research Motion Dataset graph
 * (data/bandai.manifest), baked and run on the evaluation paths. */
void eval_section_second_studio(eval_ctx* ctx);

#endif /* EVAL_CTX_H */
