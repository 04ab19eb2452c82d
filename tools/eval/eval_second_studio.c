/*
 * eval_second_studio.c - section 6: a second studio. The Bandai Namco Research
 * Motion Dataset clips (data/bandai.manifest: another skeleton and naming,
 * centimetres, a static root above the pelvis, walks that turn, runs, an
 * `exhausted` second style, waving and raising hands as actions) baked
 * with the same options as the CMU set, then run on section 2's paths.
 * The clips are read from <shared>/mocap/bandai-namco at run time; nothing
 * derived from them is written except this report (their licence:
 * CC BY-NC-ND, credit "Bandai Namco Research Motion Dataset").
 */
#include <stdlib.h>
#include <string.h>

#include "bake_manifest.h"
#include "eval_ctx.h"
#include "smg_bake.h"

/* Clip count per label, as "walk 9, run 4, ..." */
static void label_counts(const smgb_manifest* m, char* buf, size_t size) {
  uint32_t i, k;
  size_t used = 0;
  buf[0] = '\0';
  for (i = 0; i < m->clip_count; ++i) {
    uint32_t n = 0;
    int seen = 0;
    for (k = 0; k < i; ++k)
      seen |= m->clips[k].role == m->clips[i].role &&
              strcmp(m->clips[k].label, m->clips[i].label) == 0;
    if (seen) continue;
    for (k = i; k < m->clip_count; ++k)
      n += m->clips[k].role == m->clips[i].role &&
           strcmp(m->clips[k].label, m->clips[i].label) == 0;
    used += (size_t)snprintf(buf + used, used < size ? size - used : 0,
                             "%s%s `%s` %u", used ? ", " : "",
                             m->clips[i].role == SMG_BAKE_ROLE_UPPER
                                 ? "action"
                                 : "style",
                             m->clips[i].label, n);
  }
}

void eval_section_second_studio(eval_ctx* ctx) {
  smgb_manifest man;
  smgb_error merr;
  smg_bake_result res;
  smg_result rc;
  char labels[512];
  const smg_bake_stats* st;

  if (!ctx->have_bandai) {
    eval_md(ctx, "## 6. A second studio: Bandai Namco Research Motion "
                 "Dataset\n\nNot produced: the clips are not at `%s`.\n\n",
            ctx->bandai_dir);
    if (ctx->check)
      printf("SKIP Bandai Namco graph: clips not at %s\n", ctx->bandai_dir);
    return;
  }
  memset(&man, 0, sizeof(man));
  memset(&merr, 0, sizeof(merr));
  rc = smgb_manifest_load(ctx->bandai_manifest, ctx->bandai_dir, &man, &merr);
  if (!eval_check(ctx, rc == SMG_OK, "manifest %s: %s", ctx->bandai_manifest,
                  rc == SMG_OK ? "read" : merr.message)) {
    eval_md(ctx, "## 6. A second studio: Bandai Namco Research Motion "
                 "Dataset\n\nNot produced: `%s` could not be read: %s\n\n",
            ctx->bandai_manifest, merr.message);
    return;
  }
  eval_log("baking the Bandai Namco set...");
  rc = eval_bake_manifest(&man, 0, &res);
  if (!eval_check(ctx, rc == SMG_OK, "Bandai Namco bake: %s%s%s",
                  smg_result_string(rc), rc == SMG_OK ? "" : ": ",
                  rc == SMG_OK ? "" : res.error)) {
    eval_md(ctx, "## 6. A second studio: Bandai Namco Research Motion "
                 "Dataset\n\nThe bake FAILED in this run: `%s`: %s\n\n",
            smg_result_string(rc), res.error);
    eval_summary(ctx, "**Bandai Namco graph**: the bake FAILED in this run.");
    smg_bake_result_free(&res);
    smgb_manifest_free(&man);
    return;
  }
  st = &res.stats;
  label_counts(&man, labels, sizeof(labels));
  eval_log("Bandai Namco bake done in %.2f s (%u lower / %u upper nodes)",
           res.total_seconds, st->lower_nodes, st->upper_nodes);
  eval_check(ctx, st->style_count == 3 && st->lower_nodes > 0 &&
                      st->upper_nodes > 0 && st->splice_count > 0,
             "Bandai Namco graphs: %u styles, %u lower / %u upper nodes, %u "
             "splices", st->style_count, st->lower_nodes, st->upper_nodes,
             st->splice_count);
  eval_md(ctx,
          "## 6. A second studio: Bandai Namco Research Motion Dataset\n\n"
          "Clips of the Bandai Namco Research Motion Dataset (dataset 2, "
          "CC BY-NC-ND; read from `%s` at run time) through `%s`: another "
          "skeleton (a static `joint_Root` above the translating `Hips`, "
          "`UpperLeg_L`/`Toes_R` names, 6 channels on every joint, "
          "centimetres), walks that turn 90 deg, runs, a second performer "
          "walking `exhausted` as a second style, and waving and raising "
          "hands performed standing as actions. Nothing is configured for "
          "it: the importer folds the static root, the body roles come "
          "from the joint names. Clips: %s; all mirrored.\n\n"
          "| | |\n|---|---:|\n"
          "| Pool frames at 30 Hz incl. mirrors (+ blended transition "
          "frames) | %u (+ %u) |\n"
          "| Bake, default threads (all stages) | %.2f s |\n"
          "| Lower-body nodes / edges (before simplification) | %u / %u "
          "(%u / %u) |\n"
          "| Upper-body nodes / edges (before simplification) | %u / %u "
          "(%u / %u) |\n"
          "| Splice candidates (coverage within 1 s, longest wait) | %u "
          "(%.0f %%, %.2f s) |\n"
          "| Blob | %.1f MiB |\n\n"
          "Path following on section 2's five paths (constraints as there: "
          "transitions to `run` and back, the first action - `wave` - "
          "spliced on and off):\n\n",
          ctx->bandai_dir, ctx->bandai_manifest, labels, st->source_frames,
          st->blend_frames, res.total_seconds, st->lower_nodes,
          st->lower_edges, st->lower_nodes_before, st->lower_edges_before,
          st->upper_nodes, st->upper_edges, st->upper_nodes_before,
          st->upper_edges_before, st->splice_count,
          100.0 * st->splice_coverage, st->splice_max_gap,
          (double)res.blob_size / (1024.0 * 1024.0));
  eval_summary(ctx,
               "**Bandai Namco graph** (a second studio and skeleton, no "
               "configuration): baked in %.2f s, %u lower / %u upper nodes, "
               "%u splice candidates.",
               res.total_seconds, st->lower_nodes, st->upper_nodes,
               st->splice_count);
  {
    /* The runtime reads the blob in place: 16-byte aligned. */
    void* blob = NULL;
    if (posix_memalign(&blob, 16, res.blob_size) == 0) {
      memcpy(blob, res.blob, res.blob_size);
      eval_paths_on_graph(ctx, blob, res.blob_size, "Bandai Namco");
      free(blob);
    }
  }
  smg_bake_result_free(&res);
  smgb_manifest_free(&man);
}
