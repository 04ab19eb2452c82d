/*
 * eval_bake.c - section 1: the paper-size CMU bake through the public
 * baking API (smg_bake.h), in-process, with its per-stage times and graph
 * sizes beside the paper's (Section IV: 70 min lower graph, 10 min upper
 * graph, 30 min splice search, 3 h internodal data; 240 lower and 64 upper
 * nodes after simplification; Core 2 Duo 2.4 GHz, one core).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_manifest.h"
#include "eval_ctx.h"
#include "smg_bake.h"

/* Frames of a BVH file (the "Frames:" line), minus the CMU T-pose frame;
 * 0 when unreadable. */
static uint32_t bvh_motion_frames(const char* path) {
  FILE* f = fopen(path, "r");
  char line[512];
  unsigned long n = 0;
  if (!f) return 0;
  while (fgets(line, sizeof(line), f))
    if (sscanf(line, " Frames: %lu", &n) == 1) break;
  fclose(f);
  return n > 1 ? (uint32_t)(n - 1) : 0;
}

static void progress_quiet(const char* stage, float fraction, void* user) {
  (void)stage;
  (void)fraction;
  (void)user;
}

smg_result eval_bake_manifest(const smgb_manifest* m, uint32_t threads,
                              smg_bake_result* res) {
  smg_bake_clip_desc* clips;
  smg_bake_desc desc;
  smg_result r;
  memset(res, 0, sizeof(*res));
  res->struct_size = sizeof(*res);
  clips = (smg_bake_clip_desc*)calloc(m->clip_count ? m->clip_count : 1,
                                      sizeof(*clips));
  if (!clips) return SMG_ERROR_OUT_OF_MEMORY;
  r = smgb_manifest_descs(m, clips, m->clip_count);
  if (r == SMG_OK) {
    memset(&desc, 0, sizeof(desc));
    desc.struct_size = sizeof(desc);
    desc.clip_count = m->clip_count;
    desc.clips = clips;
    desc.options.struct_size = sizeof(desc.options);
    desc.options.frame_rate = m->frame_rate;
    desc.options.threads = threads;
    desc.progress = progress_quiet;
    r = smg_bake_run(&desc, res);
  }
  free(clips);
  return r;
}

/* Seconds of the stages whose name contains `key` (NAN when none). */
void* eval_bake_to_memory(const char* manifest, const char* data_dir,
                          size_t* out_size) {
  smgb_manifest man;
  smgb_error merr;
  smg_bake_result res;
  void* copy = NULL;
  memset(&man, 0, sizeof(man));
  memset(&merr, 0, sizeof(merr));
  if (smgb_manifest_load(manifest, data_dir, &man, &merr) != SMG_OK) {
    eval_log("%s: %s", manifest, merr.message);
    return NULL;
  }
  if (eval_bake_manifest(&man, 0, &res) == SMG_OK &&
      posix_memalign(&copy, 16, res.blob_size) == 0) {
    memcpy(copy, res.blob, res.blob_size);
    *out_size = res.blob_size;
  } else {
    eval_log("%s: bake failed: %s", manifest, res.error);
  }
  smg_bake_result_free(&res);
  smgb_manifest_free(&man);
  return copy;
}

static double stage_seconds(const smg_bake_result* r, const char* key) {
  double s = 0.0;
  int found = 0;
  uint32_t i;
  for (i = 0; i < r->stage_count && i < SMG_BAKE_MAX_STAGES; ++i)
    if (r->stages[i].name && strstr(r->stages[i].name, key)) {
      s += r->stages[i].seconds;
      found = 1;
    }
  return found ? s : NAN;
}

static const char* fmt_seconds(char* buf, size_t size, double s) {
  if (!isfinite(s)) return snprintf(buf, size, "(no such stage)"), buf;
  if (s < 0.01)
    snprintf(buf, size, "%.2f ms", s * 1e3);
  else
    snprintf(buf, size, "%.3f s", s);
  return buf;
}

static void write_report(eval_ctx* ctx, const smgb_manifest* man,
                         const smg_bake_result* r1,
                         const smg_bake_result* r2, uint32_t threads2) {
  static const struct {
    const char* row;
    const char* key;
    const char* paper;
    double paper_s;
  } rows[] = {
      {"Lower-body graph", "lower", "70 min", 4200.0},
      {"Upper-body graph", "upper", "10 min", 600.0},
      {"Splice candidate search", "splice", "30 min", 1800.0},
      {"Internodal data", "internodal", "3 h", 10800.0},
  };
  const smg_bake_stats* st = &r1->stats;
  char a[64], b[64];
  uint32_t walk = 0, run = 0, punch = 0, i;
  size_t k;

  eval_md(ctx,
          "## 1. Preprocessing (paper Section IV, first table)\n\n"
          "Input: the clips of `%s` (the same set `smg-bake` benchmarks), "
          "baked in-process with `smg_bake_run()` at the manifest's "
          "options (working rate %.0f Hz; mirroring as listed):\n\n"
          "| Clip | graph | label | frames used (120 Hz) | mirrored |\n"
          "|---|---|---|---:|---|\n",
          ctx->manifest, man->frame_rate > 0 ? man->frame_rate : 30.0);
  for (i = 0; i < man->clip_count; ++i) {
    const smgb_manifest_clip* c = &man->clips[i];
    const char* base = strrchr(c->path, '/');
    uint32_t n = c->frame_count;
    if (!n) {
      n = bvh_motion_frames(c->path);
      n = n > c->first_frame ? n - c->first_frame : 0;
    }
    if (c->role == SMG_BAKE_ROLE_UPPER) punch += n;
    else if (!strcmp(c->label, "walk")) walk += n;
    else run += n;
    eval_md(ctx, "| %s | %s | `%s` | %u | %s |\n", base ? base + 1 : c->path,
            c->role == SMG_BAKE_ROLE_UPPER ? "upper" : "lower", c->label, n,
            c->mirror == SMG_BAKE_MIRROR_NO ? "no" : "yes");
  }
  eval_md(ctx,
          "\n"
          "| Data (frames at 120 Hz, T-pose excluded) | paper | libsmg |\n"
          "|---|---:|---:|\n"
          "| Walk | 1506 | %u |\n| Run | 761 | %u |\n"
          "| Boxing / punch | 1500 | %u |\n"
          "| Pool frames at 30 Hz incl. mirrors (+ blended transition "
          "frames) | - | %u (+ %u) |\n\n",
          walk, run, punch, st->source_frames, st->blend_frames);

  eval_md(ctx,
          "Stage times, one worker thread (`options.threads = 1`, like the "
          "paper's single core). The paper names four stages; the baker's "
          "own stage list (import and chain simplification are separate "
          "there) follows below:\n\n"
          "| Stage | paper (Core 2 Duo 2.4 GHz, 1 core) | libsmg, 1 thread "
          "| speed-up |\n|---|---:|---:|---:|\n");
  for (k = 0; k < sizeof(rows) / sizeof(rows[0]); ++k) {
    double s = stage_seconds(r1, rows[k].key);
    eval_md(ctx, "| %s | %s | %s | %s |\n", rows[k].row, rows[k].paper,
            fmt_seconds(a, sizeof(a), s),
            eval_fmt(b, sizeof(b), "%.0fx", rows[k].paper_s / s));
  }
  eval_summary(ctx,
               "**Preprocessing** (paper-size CMU set, mirrored, 1 thread): "
               "%s for the whole bake vs the paper's 4 h 50 min; graphs "
               "after simplification: %u lower / %u upper nodes (paper: 240 "
               "/ 64).",
               fmt_seconds(a, sizeof(a), r1->total_seconds),
               st->lower_nodes, st->upper_nodes);
  eval_md(ctx, "| **Total bake** (all stages incl. import) | 4 h 50 min | "
               "%s | %s |\n\n",
          fmt_seconds(a, sizeof(a), r1->total_seconds),
          eval_fmt(b, sizeof(b), "%.0fx", 17400.0 / r1->total_seconds));

  eval_md(ctx, "Every stage the baker reported (1 thread%s):\n\n"
               "| Stage | 1 thread |%s\n|---|---:|%s\n",
          r2 ? " and the default thread count" : "",
          r2 ? " default threads |" : "", r2 ? "---:|" : "");
  for (i = 0; i < r1->stage_count && i < SMG_BAKE_MAX_STAGES; ++i) {
    eval_md(ctx, "| %s | %s |", r1->stages[i].name ? r1->stages[i].name : "?",
            fmt_seconds(a, sizeof(a), r1->stages[i].seconds));
    if (r2) {
      double s2 = (i < r2->stage_count) ? r2->stages[i].seconds : NAN;
      eval_md(ctx, " %s |", fmt_seconds(b, sizeof(b), s2));
    }
    eval_md(ctx, "\n");
  }
  eval_md(ctx, "| total | %s |", fmt_seconds(a, sizeof(a), r1->total_seconds));
  if (r2)
    eval_md(ctx, " %s (%u threads) |",
            fmt_seconds(b, sizeof(b), r2->total_seconds), threads2);
  eval_md(ctx, "\n\n");

  eval_md(ctx,
          "Graph sizes (\"before\" = after pruning to the strongly connected "
          "component, before chain simplification; \"after\" = in the "
          "blob):\n\n"
          "| Graph | paper, after simplification | libsmg before | libsmg "
          "after |\n|---|---:|---:|---:|\n"
          "| Lower-body nodes | 240 | %u | %u |\n"
          "| Lower-body edges | - | %u | %u |\n"
          "| Upper-body nodes | 64 | %u | %u |\n"
          "| Upper-body edges | - | %u | %u |\n\n"
          "Transition candidates before pruning: lower %u, upper %u. Splice "
          "candidates: %u (coverage %.0f %% of lower frames have a "
          "candidate for every action within 1 s; longest wait %.2f s). "
          "Blob: %.1f KiB.\n\n",
          st->lower_nodes_before, st->lower_nodes, st->lower_edges_before,
          st->lower_edges, st->upper_nodes_before, st->upper_nodes,
          st->upper_edges_before, st->upper_edges, st->lower_candidates,
          st->upper_candidates, st->splice_count,
          100.0 * st->splice_coverage, st->splice_max_gap,
          (double)r1->blob_size / 1024.0);
}

void eval_section_bake(eval_ctx* ctx, void** out_blob, size_t* out_size) {
  smg_bake_result r1, r2;
  smg_result rc;
  smgb_manifest man;
  smgb_error merr;
  int have_r2 = 0;

  *out_blob = NULL;
  *out_size = 0;
  if (!ctx->have_cmu) {
    eval_md(ctx, "## 1. Preprocessing\n\nNot produced: the CMU clips are "
                 "not at `%s`.\n\n", ctx->cmu_dir);
    if (ctx->check) printf("SKIP CMU bake: clips not at %s\n", ctx->cmu_dir);
    return;
  }
  memset(&man, 0, sizeof(man));
  memset(&merr, 0, sizeof(merr));
  rc = smgb_manifest_load(ctx->manifest, ctx->cmu_dir, &man, &merr);
  if (rc != SMG_OK) {
    eval_md(ctx, "## 1. Preprocessing\n\nNot produced: the manifest `%s` "
                 "could not be read: %s\n\n", ctx->manifest, merr.message);
    eval_check(ctx, 0, "manifest %s: %s", ctx->manifest, merr.message);
    return;
  }
  eval_log("baking the paper-size CMU set (1 thread)...");
  rc = eval_bake_manifest(&man, 1, &r1);
  if (rc != SMG_OK) {
    eval_log("bake failed: %s: %s", smg_result_string(rc), r1.error);
    eval_summary(ctx, "**Preprocessing**: the bake FAILED in this run (see "
                      "section 1).");
    eval_md(ctx, "## 1. Preprocessing\n\nThe bake FAILED in this run: "
                 "`%s`: %s\n\n", smg_result_string(rc), r1.error);
    eval_check(ctx, 0, "CMU paper-set bake: %s: %s", smg_result_string(rc),
               r1.error);
    smg_bake_result_free(&r1);
    smgb_manifest_free(&man);
    return;
  }
  eval_log("bake done in %.2f s (%u lower / %u upper nodes)",
           r1.total_seconds, r1.stats.lower_nodes, r1.stats.upper_nodes);
  if (ctx->check) {
    eval_check(ctx, r1.total_seconds < 60.0,
               "CMU paper-set bake in %.2f s (bound 60 s)", r1.total_seconds);
    eval_check(ctx, r1.stats.lower_nodes > 0 && r1.stats.upper_nodes > 0 &&
                        r1.stats.splice_count > 0 && r1.stats.style_count == 2,
               "graphs: %u lower nodes, %u upper nodes, %u splices, %u "
               "styles", r1.stats.lower_nodes, r1.stats.upper_nodes,
               r1.stats.splice_count, r1.stats.style_count);
  } else {
    eval_log("baking again with the default thread count...");
    rc = eval_bake_manifest(&man, 0, &r2);
    have_r2 = rc == SMG_OK;
    if (!have_r2) smg_bake_result_free(&r2);
    write_report(ctx, &man, &r1, have_r2 ? &r2 : NULL, 2);
  }
  if (ctx->keep_dir) {
    char path[1200], why[256];
    snprintf(path, sizeof(path), "%s/cmu-paper.smg", ctx->keep_dir);
    if (smg_bake_write_file(&r1, path, why, sizeof(why)) != SMG_OK)
      eval_log("cannot keep %s: %s", path, why);
  }
  smgb_manifest_free(&man);
  {
    void* copy = NULL;
    if (posix_memalign(&copy, 16, r1.blob_size) == 0) {
      memcpy(copy, r1.blob, r1.blob_size);
      *out_blob = copy;
      *out_size = r1.blob_size;
    }
  }
  smg_bake_result_free(&r1);
  if (have_r2) smg_bake_result_free(&r2);
}
