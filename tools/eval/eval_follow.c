/*
 * eval_follow.c - section "Staying on drawn paths" (issue 12): characters
 * follow the paths of data/paths/ on three graphs - the paper-size CMU set
 * (data/cmu.manifest), a sparse set of two nearly straight walks and three
 * straight runs (data/cmu-sparse.manifest), and the Bandai Namco set
 * (data/bandai.manifest: another studio and skeleton, turning walks; run
 * in its `walk` style and again in its second style `exhausted`; read from
 * the shared folder at run time, nothing baked from it is written) - once
 * with the root steering on (the default) and once with it off (the
 * motion graph alone).
 *
 * Everything is measured from the poses the public API exports (world
 * model matrices), never from the runtime's own flags:
 *  - hips-to-path distance on the ground, mean and max, from the start
 *    until the hips first come within 0.5 m of the last point (the whole
 *    run when they never do). The distance is to the part of the path near
 *    where the hips are along it (a window that moves with them), so a
 *    path that crosses itself does not hide a character that cut a loop;
 *  - end reached: the hips came within 0.5 m of the last point;
 *  - at rest: over the last second of a run long enough to stop, the hips'
 *    mean ground speed and their largest distance from the last point;
 *  - the correction the steering applied (smg_character_state: heading
 *    correction in deg/s, translation in cm/s), mean over the run;
 *  - planted-toe speed (eval_feet_geom) until the end is reached, of this
 *    run and over FEET_SEEDS seeds (smg_character_desc.seed: which of
 *    equally good clips the character picks). One run's figure moves by
 *    0.2-0.9 cm/s with the seed alone, more than steering changes it, so
 *    "not above steering off" is judged on the seeds' means: on counts as
 *    above off when its mean exceeds off's by more than twice the
 *    standard error of the difference.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_manifest.h"
#include "eval_ctx.h"
#include "eval_feet_geom.h"
#include "eval_joints.h"
#include "eval_metrics.h"
#include "eval_run.h"
#include "smg_bake.h"
#include "svg_plot.h"

#define FOLLOW_RATE 30.0       /* steps per second */
#define FOLLOW_SPEED 0.8       /* m/s: a run lasts length / this ... */
#define FOLLOW_EXTRA 6.0       /* ... plus this many seconds to stop */
#define END_RADIUS 0.5         /* hips this near the last point: reached */
#define WINDOW_BACK 0.5        /* distance window along the path, metres */
#define WINDOW_AHEAD 1.5
#define MAX_POINTS 4096
#define FEET_SEEDS 8           /* seeds of the planted-toe comparison */
#define PI 3.14159265358979323846

typedef struct follow_path {
  const char* key;   /* data/paths/<key>.txt */
  const char* title;
  int tight;         /* the tight-path targets apply (else smooth) */
} follow_path;

static const follow_path k_paths[] = {
    {"straight", "straight 20 m", 0},
    {"s-curve", "S-curve, r = 4 m", 0},
    {"circle-r5", "circle r = 5 m", 0},
    {"corner-left", "corner left 90 deg", 1},
    {"corner-right", "corner right 90 deg", 1},
    {"u-turn", "U-turn, 2 m across", 1},
    {"circle-r2", "circle r = 2 m", 1},
    {"scribble", "scribble, 1.2 m loops", 1},
};
#define PATH_COUNT (sizeof(k_paths) / sizeof(k_paths[0]))

/* What one run gave. */
typedef struct follow_result {
  int ok;
  double mean_cm, max_cm;   /* hips to path until the end is reached */
  int reached;              /* hips within END_RADIUS of the last point */
  double reach_s;           /* when, seconds */
  double rest_speed;        /* last second: mean hips ground speed, m/s */
  double rest_dist;         /* last second: max hips distance to the end */
  double turn_deg_s;        /* mean |heading correction|, deg/s */
  double slide_cm_s;        /* mean |translation correction|, cm/s */
  double feet_cm_s;         /* planted-toe speed (eval_feet_geom), mean */
  double style_share;       /* frames the runtime reports in the initial
                             * style (a label, not a quality measure) */
  size_t frames;
  double* hips;             /* 2 per frame (ground x, z), for figures */
} follow_result;


/* One run from the path's first point; `style`: the initial style. */
static void follow_run(smg_graph* g, const eval_joints* joint,
                       const double* path, size_t n, int steering,
                       uint32_t style, uint32_t seed, follow_result* out) {
  smg_character_desc cd;
  smg_character* ch = NULL;
  smg_graph_info info;
  float* xz = NULL;
  float* mats = NULL;
  double* toes = NULL; /* per frame: left toe x, y, z, right toe x, y, z */
  const uint32_t hips = joint->hips, toe[2] = {joint->ltoe, joint->rtoe};
  double length = em_polyline_length(path, n), arc = 0.0;
  double sum_d = 0.0, max_d = 0.0, turn = 0.0, slide = 0.0;
  double ex = path[2 * n - 2], ez = path[2 * n - 1];
  size_t i, F, measured = 0, in_style = 0;
  const double dt = 1.0 / FOLLOW_RATE;

  memset(out, 0, sizeof(*out));
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if (smg_graph_get_info(g, &info) != SMG_OK) return;
  F = (size_t)ceil((length / FOLLOW_SPEED + FOLLOW_EXTRA) * FOLLOW_RATE);
  xz = (float*)malloc(2 * n * sizeof(float));
  mats = (float*)malloc(16 * (size_t)info.joint_count * sizeof(float));
  out->hips = (double*)malloc(2 * (F + 1) * sizeof(double));
  toes = (double*)malloc(6 * (F + 1) * sizeof(double));
  if (!xz || !mats || !out->hips || !toes) goto done;
  for (i = 0; i < 2 * n; ++i) xz[i] = (float)path[i];

  memset(&cd, 0, sizeof(cd));
  cd.struct_size = sizeof(cd);
  cd.flags = steering ? 0u : SMG_CHARACTER_NO_STEERING;
  cd.initial_style = style;
  cd.seed = seed;
  cd.path_capacity = (uint32_t)n + 16u;
  cd.position[0] = xz[0];
  cd.position[2] = xz[1];
  cd.heading = (float)atan2(path[2] - path[0], path[3] - path[1]);
  if (smg_character_create(g, &cd, &ch) != SMG_OK ||
      smg_character_set_path(ch, xz, (uint32_t)n) != SMG_OK)
    goto done;
  out->reached = 0;
  for (i = 0; i <= F; ++i) {
    smg_character_state st;
    double hx, hz, d;
    if (i > 0 && smg_character_step(ch, (float)dt) != SMG_OK) goto done;
    if (smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                         info.joint_count) != SMG_OK)
      goto done;
    memset(&st, 0, sizeof(st));
    st.struct_size = sizeof(st);
    if (smg_character_get_state(ch, &st) != SMG_OK) goto done;
    in_style += st.style == style;
    hx = mats[16 * hips + 12];
    hz = mats[16 * hips + 14];
    out->hips[2 * i] = hx;
    out->hips[2 * i + 1] = hz;
    for (int f = 0; f < 2; ++f)
      for (int c = 0; c < 3; ++c)
        toes[6 * i + 3 * f + c] = mats[16 * toe[f] + 12 + c];
    if (i > 0) {
      turn += fabs((double)st.steer_turn_rate);
      slide += fabs((double)st.steer_slide_speed);
    }
    if (!out->reached) {
      /* the part of the path near where the hips are along it */
      d = em_polyline_distance_window(path, n, hx, hz, arc - WINDOW_BACK,
                                      arc + WINDOW_AHEAD, &arc);
      sum_d += d;
      if (d > max_d) max_d = d;
      ++measured;
      if (hypot(hx - ex, hz - ez) < END_RADIUS) {
        out->reached = 1;
        out->reach_s = (double)i * dt;
      }
    }
  }
  out->frames = F + 1;
  out->style_share = (double)in_style / (double)(F + 1);
  out->mean_cm = measured ? 100.0 * sum_d / (double)measured : NAN;
  out->max_cm = 100.0 * max_d;
  out->turn_deg_s = F ? turn / (double)F * 180.0 / PI : 0.0;
  out->slide_cm_s = F ? 100.0 * slide / (double)F : 0.0;
  {
    /* the last second */
    size_t k = (size_t)FOLLOW_RATE, first = F - k;
    double travelled = 0.0, far = 0.0;
    for (i = first; i <= F; ++i) {
      double dx = out->hips[2 * i] - ex, dz = out->hips[2 * i + 1] - ez;
      if (i > first)
        travelled += hypot(out->hips[2 * i] - out->hips[2 * i - 2],
                           out->hips[2 * i + 1] - out->hips[2 * i - 1]);
      if (hypot(dx, dz) > far) far = hypot(dx, dz);
    }
    out->rest_speed = travelled / ((double)k * dt);
    out->rest_dist = far;
  }
  {
    const double* feet[2] = {toes, toes + 3};
    eval_feet_geom fg;
    /* while moving along the path: a character standing still at the
     * end for seconds would dilute the figure */
    size_t upto = out->reached ? (size_t)(out->reach_s / dt) + 1 : F + 1;
    eval_feet_geom_measure(feet, 2, 6, upto, dt, NULL, &fg);
    out->feet_cm_s = fg.mean_cms;
  }
  out->ok = 1;
done:
  free(toes);
  if (ch) smg_character_destroy(ch);
  free(xz);
  free(mats);
  if (!out->ok) {
    free(out->hips);
    out->hips = NULL;
  }
}

/* The graphs of the section: which blob (0 CMU, 1 sparse, 2 Bandai
 * Namco), which style the character starts in (NULL: the first), and
 * whether figures are drawn. The Bandai Namco clips are CC BY-NC-ND: a
 * plot of motion made from them is an adaptation the repository must not
 * carry, so those graphs get tables (measurements) only. */
typedef struct follow_graph_spec {
  const char* key;   /* figure names: eval-follow-<key>-<path>.svg */
  const char* name;  /* table heading */
  const char* title; /* figure titles (short: the figures are narrow) */
  int blob;
  const char* style;
  int figures;
} follow_graph_spec;

static const follow_graph_spec k_graphs[] = {
    {"cmu", "CMU graph (data/cmu.manifest)", "CMU graph", 0, NULL, 1},
    {"sparse", "Sparse graph (data/cmu-sparse.manifest)", "Sparse graph", 1,
     NULL, 1},
    {"bandai", "Bandai Namco graph (data/bandai.manifest)",
     "Bandai Namco graph", 2, NULL, 0},
    {"bandai-exhausted",
     "Bandai Namco graph (data/bandai.manifest), style `exhausted`",
     "Bandai Namco graph, exhausted", 2, "exhausted", 0},
};
#define GRAPH_COUNT (sizeof(k_graphs) / sizeof(k_graphs[0]))

/* Top-down figure of one path: the drawn path and the hips with steering
 * off and on. */
static void draw(eval_ctx* ctx, const follow_graph_spec* gs,
                 const follow_path* p, const double* path, size_t n,
                 const follow_result* off, const follow_result* on) {
  char name[128], full[1400], title[200];
  double *x = NULL, *z = NULL;
  size_t cap = n, i;
  svp_figure* fig;
  if (off->ok && off->frames > cap) cap = off->frames;
  if (on->ok && on->frames > cap) cap = on->frames;
  snprintf(title, sizeof(title), "%s: %s", gs->title, p->title);
  fig = svp_create(520, 520, title);
  x = (double*)malloc(cap * sizeof(double));
  z = (double*)malloc(cap * sizeof(double));
  if (!fig || !x || !z) goto done;
  svp_set_labels(fig, "x (m)  [true top view: +x points left]", "z (m)");
  svp_set_equal_aspect(fig, 1);
  svp_set_x_left(fig, 1);
  for (i = 0; i < n; ++i) x[i] = path[2 * i], z[i] = path[2 * i + 1];
  svp_line(fig, x, z, n, "#c8c8c8", 7.0, 0, "drawn path");
  if (off->ok) {
    for (i = 0; i < off->frames; ++i)
      x[i] = off->hips[2 * i], z[i] = off->hips[2 * i + 1];
    svp_line(fig, x, z, off->frames, "#d62728", 1.5, 1, "hips, steering off");
  }
  if (on->ok) {
    for (i = 0; i < on->frames; ++i)
      x[i] = on->hips[2 * i], z[i] = on->hips[2 * i + 1];
    svp_line(fig, x, z, on->frames, "#1f77b4", 2.0, 0, "hips, steering on");
  }
  svp_marker(fig, path[2 * n - 2], path[2 * n - 1], SVP_SQUARE, "#333333",
             5.0, "end");
  snprintf(name, sizeof(name), "eval-follow-%s-%s.svg", gs->key, p->key);
  eval_img_path(ctx, name, full, sizeof(full));
  if (svp_write(fig, full) != 0) eval_log("cannot write %s", full);
done:
  svp_destroy(fig);
  free(x);
  free(z);
}

static const char* yes_no(int v) { return v ? "yes" : "**no**"; }

/* Planted-toe speed over FEET_SEEDS seeds: seed 0 is the run already made
 * (`first`), the others are run here. Mean and sample standard deviation;
 * NaN when a run fails. */
static void feet_over_seeds(smg_graph* g, const eval_joints* joint,
                            const double* path, size_t n, int steering,
                            uint32_t style, double first, double* mean,
                            double* sd) {
  double v[FEET_SEEDS], sum = 0.0, sq = 0.0;
  uint32_t i;
  v[0] = first;
  for (i = 1; i < FEET_SEEDS; ++i) {
    follow_result r;
    follow_run(g, joint, path, n, steering, style, i, &r);
    v[i] = r.ok ? r.feet_cm_s : NAN;
    free(r.hips);
  }
  for (i = 0; i < FEET_SEEDS; ++i) sum += v[i];
  *mean = sum / FEET_SEEDS;
  for (i = 0; i < FEET_SEEDS; ++i) sq += (v[i] - *mean) * (v[i] - *mean);
  *sd = sqrt(sq / (FEET_SEEDS - 1));
}

/* One graph and initial style: every path, steering off and on, table
 * rows and figures. met[0]: runs meeting the path, end and rest targets;
 * met[1]: the planted-toe target; met[2]: runs (steering on). */
static void follow_graph(eval_ctx* ctx, smg_graph* g,
                         const follow_graph_spec* gs, uint32_t style,
                         int* met) {
  static double path[2 * MAX_POINTS];
  eval_joints joint;
  size_t k;
  char b[8][32];
  double style_min = 1.0;
  if (!eval_find_joints(g, &joint)) {
    eval_md(ctx, "**%s**: its pelvis, feet or toes are not recognised: "
                 "not measured.\n\n", gs->name);
    met[2] += (int)PATH_COUNT;
    return;
  }
  eval_md(ctx,
          "**%s**\n\n"
          "| path | steering | mean cm | max cm | end reached (s) | "
          "last 1 s: speed m/s | last 1 s: max distance to end m | "
          "correction deg/s | correction cm/s | planted toes cm/s | "
          "planted toes, %d seeds: mean +- sd |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n",
          gs->name, FEET_SEEDS);
  for (k = 0; k < PATH_COUNT; ++k) {
    const follow_path* p = &k_paths[k];
    char file[256];
    follow_result r[2];
    double feet_mean[2] = {NAN, NAN}, feet_sd[2] = {NAN, NAN};
    size_t n;
    int s;
    snprintf(file, sizeof(file), "data/paths/%s.txt", p->key);
    n = eval_read_path(file, path, MAX_POINTS);
    if (n < 2) {
      eval_md(ctx, "| %s | | cannot read `%s` | | | | | | | | |\n", p->title,
              file);
      met[2]++;
      continue;
    }
    for (s = 0; s < 2; ++s) {
      follow_result* x = &r[s];
      follow_run(g, &joint, path, n, s, style, 0u, x);
      if (!x->ok) {
        eval_md(ctx, "| %s | %s | run failed | | | | | | | | |\n", p->title,
                s ? "on" : "off");
        if (s) met[2]++;
        continue;
      }
      eval_log("follow %s %-12s steering %-3s: %5.1f / %5.1f cm, end %s, "
               "rest %.2f m/s %.2f m, corr %.1f deg/s %.1f cm/s, feet %.1f cm/s",
               gs->key, p->key, s ? "on" : "off", x->mean_cm, x->max_cm,
               x->reached ? "yes" : "no", x->rest_speed, x->rest_dist,
               x->turn_deg_s, x->slide_cm_s, x->feet_cm_s);
      feet_over_seeds(g, &joint, path, n, s, style, x->feet_cm_s,
                      &feet_mean[s], &feet_sd[s]);
      if (x->reached)
        snprintf(b[0], sizeof(b[0]), "yes (%.1f)", x->reach_s);
      else
        snprintf(b[0], sizeof(b[0]), "%s", yes_no(0));
      eval_md(ctx, "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | "
                   "%.1f +- %.1f |\n",
              p->title, s ? "on" : "off",
              eval_fmt(b[1], sizeof(b[1]), "%.1f", x->mean_cm),
              eval_fmt(b[2], sizeof(b[2]), "%.1f", x->max_cm), b[0],
              eval_fmt(b[3], sizeof(b[3]), "%.2f", x->rest_speed),
              eval_fmt(b[4], sizeof(b[4]), "%.2f", x->rest_dist),
              eval_fmt(b[5], sizeof(b[5]), "%.1f", x->turn_deg_s),
              eval_fmt(b[6], sizeof(b[6]), "%.1f", x->slide_cm_s),
              eval_fmt(b[7], sizeof(b[7]), "%.1f", x->feet_cm_s),
              feet_mean[s], feet_sd[s]);
      if (x->style_share < style_min) style_min = x->style_share;
      if (s) {
        double mean_max = p->tight ? 10.0 : 5.0, max_max = p->tight ? 45.0 : 25.0;
        met[0] += x->mean_cm <= mean_max && x->max_cm <= max_max &&
                  x->reached && x->rest_speed <= 0.1 && x->rest_dist <= 0.3;
        /* not above steering off: beyond twice the standard error of
         * the difference of the seeds' means */
        const double se = sqrt((feet_sd[0] * feet_sd[0] +
                                feet_sd[1] * feet_sd[1]) / FEET_SEEDS);
        met[1] += x->feet_cm_s <= 20.0 && feet_mean[1] <= 20.0 &&
                  (!r[0].ok || feet_mean[1] - feet_mean[0] <= 2.0 * se);
        met[2]++;
      }
    }
    if (ctx->img_dir && gs->figures) draw(ctx, gs, p, path, n, &r[0], &r[1]);
    free(r[0].hips);
    free(r[1].hips);
  }
  eval_md(ctx, "\n");
  if (gs->style && style_min >= 1.0)
    eval_md(ctx, "The runtime reported the style `%s` on every frame of "
                 "every run.\n\n", gs->style);
  else if (gs->style)
    eval_md(ctx, "The runtime reported the style `%s` on at least %.1f %% "
                 "of the frames of every run.\n\n", gs->style,
            100.0 * style_min);
  if (ctx->img_dir && !gs->figures)
    eval_md(ctx, "No figures: the clips' license (CC BY-NC-ND) does not "
                 "allow sharing motion made from them.\n\n");
  if (ctx->img_dir && gs->figures) {
    eval_md(ctx, "Hips seen from above, steering off (dashed) and on:\n\n");
    for (k = 0; k < PATH_COUNT; ++k)
      eval_md(ctx, "![%s, %s](%s/eval-follow-%s-%s.svg)\n", gs->name,
              k_paths[k].title, ctx->img_rel, gs->key, k_paths[k].key);
    eval_md(ctx, "\n");
  }
}

/* Check mode: the tight paths on one graph, steering on, against the
 * issue's targets (loose enough for any sane build, tight enough that a
 * character cutting corners or walking on past the end fails). */
static void check_graph(eval_ctx* ctx, smg_graph* g, const char* name) {
  static double path[2 * MAX_POINTS];
  eval_joints joint;
  if (!eval_find_joints(g, &joint)) {
    eval_check(ctx, 0, "%s: pelvis, feet or toes not recognised", name);
    return;
  }
  for (size_t k = 0; k < PATH_COUNT; ++k) {
    const follow_path* p = &k_paths[k];
    char file[256];
    follow_result r;
    snprintf(file, sizeof(file), "data/paths/%s.txt", p->key);
    size_t n = eval_read_path(file, path, MAX_POINTS);
    if (!p->tight) continue;
    if (n < 2) {
      eval_check(ctx, 0, "cannot read %s", file);
      continue;
    }
    follow_run(g, &joint, path, n, 1, 0, 0u, &r);
    eval_check(ctx, r.ok && r.mean_cm <= 10.0 && r.max_cm <= 45.0 &&
                        r.reached && r.rest_speed <= 0.1 && r.rest_dist <= 0.3,
               "%s, %s, steering on: hips %.1f / %.1f cm from the path "
               "(bounds 10 / 45), end %s, last second %.2f m/s at <= %.2f m "
               "(bounds 0.1, 0.3)",
               name, p->title, r.mean_cm, r.max_cm,
               r.reached ? "reached" : "NOT reached", r.rest_speed,
               r.rest_dist);
    free(r.hips);
  }
}

/* Check mode: the tight paths on the Bandai Namco graph (another studio,
 * skeleton and frame rate), baked in memory when its clips are there. */
static void check_bandai(eval_ctx* ctx) {
  void* blob;
  size_t size = 0;
  smg_graph* g = NULL;
  if (!ctx->have_bandai) {
    printf("SKIP follow, Bandai Namco graph: clips not at %s\n",
           ctx->bandai_dir);
    return;
  }
  blob = eval_bake_to_memory(ctx->bandai_manifest, ctx->bandai_dir, &size);
  if (!eval_check(ctx, blob && smg_graph_load_memory(blob, size, NULL, &g) ==
                                   SMG_OK,
                  "follow: Bandai Namco graph baked and loaded")) {
    free(blob);
    return;
  }
  check_graph(ctx, g, "Bandai Namco blob");
  smg_graph_destroy(g);
  free(blob);
}

/* Bakes the sparse and Bandai Namco sets, runs every graph, and writes
 * the summary line. */
static void follow_graphs(eval_ctx* ctx, const void* cmu_blob,
                          size_t cmu_size) {
  static const char* const k_sparse = "data/cmu-sparse.manifest";
  void* blob[3] = {NULL, NULL, NULL};
  size_t size[3] = {cmu_size, 0, 0};
  int met[3] = {0, 0, 0}, measured = 0;
  char per_graph[512] = "";
  size_t k, used = 0;
  if (ctx->have_cmu) {
    eval_log("baking %s...", k_sparse);
    blob[1] = eval_bake_to_memory(k_sparse, ctx->cmu_dir, &size[1]);
  }
  if (ctx->have_bandai) {
    eval_log("baking %s...", ctx->bandai_manifest);
    blob[2] =
        eval_bake_to_memory(ctx->bandai_manifest, ctx->bandai_dir, &size[2]);
  } else {
    eval_log("Bandai Namco clips not found at %s: skipping that graph",
             ctx->bandai_dir);
  }
  for (k = 0; k < GRAPH_COUNT; ++k) {
    const follow_graph_spec* gs = &k_graphs[k];
    const void* b = gs->blob == 0 ? cmu_blob : blob[gs->blob];
    uint32_t style = 0;
    smg_graph* g = NULL;
    if (gs->blob == 2 && !ctx->have_bandai) {
      eval_md(ctx, "**%s**: not measured, the Bandai Namco clips are "
                   "not at `%s`.\n\n", gs->name, ctx->bandai_dir);
      continue;
    }
    if (gs->blob < 2 && !ctx->have_cmu) {
      eval_md(ctx, "**%s**: not measured, the CMU clips are not at "
                   "`%s`.\n\n", gs->name, ctx->cmu_dir);
      continue;
    }
    if (!b || smg_graph_load_memory(b, size[gs->blob], NULL, &g) != SMG_OK) {
      eval_md(ctx, "**%s**: not available in this run (bake or load "
                   "failed).\n\n", gs->name);
      continue;
    }
    if (gs->style && smg_graph_find_style(g, gs->style, &style) != SMG_OK) {
      eval_md(ctx, "**%s**: the graph has no style `%s`.\n\n",
              gs->name, gs->style);
      smg_graph_destroy(g);
      continue;
    }
    {
      int before[3] = {met[0], met[1], met[2]};
      follow_graph(ctx, g, gs, style, met);
      used += (size_t)snprintf(
          per_graph + used, used < sizeof(per_graph) ? sizeof(per_graph) - used
                                                     : 0,
          "%s%s %d / %d of %d", used ? "; " : "", gs->title,
          met[0] - before[0], met[1] - before[1], met[2] - before[2]);
    }
    smg_graph_destroy(g);
    ++measured;
  }
  free(blob[1]);
  free(blob[2]);
  eval_summary(ctx,
               "**Staying on drawn paths** (section 2c, %d of %d graphs and "
               "styles, %d paths, steering on): the distance, end-reached "
               "and at-rest targets are met on %d of %d runs, the "
               "planted-toe target (<= 20 cm/s and, over %d seeds, not "
               "above steering off) on %d of %d (per graph, path targets / "
               "planted toes: %s).",
               measured, (int)GRAPH_COUNT, (int)PATH_COUNT, met[0], met[2],
               FEET_SEEDS, met[1], met[2], per_graph);
}

void eval_section_follow(eval_ctx* ctx, const void* cmu_blob,
                         size_t cmu_size) {
  if (ctx->check) {
    smg_graph* g = NULL;
    if (ctx->default_blob &&
        smg_graph_load_file(ctx->default_blob, NULL, &g) == SMG_OK) {
      check_graph(ctx, g, "default blob");
      smg_graph_destroy(g);
    }
    g = NULL;
    if (cmu_blob && smg_graph_load_memory(cmu_blob, cmu_size, NULL, &g) ==
                        SMG_OK) {
      check_graph(ctx, g, "CMU blob");
      smg_graph_destroy(g);
    }
    check_bandai(ctx);
    return;
  }
  eval_md(ctx,
          "## 2c. Staying on drawn paths (root steering)\n\n"
          "Characters follow the paths in `data/paths/` (one `x z` point "
          "per line) from their first point, facing the second, stepped at "
          "%.0f Hz through the public API for (path length / %.1f m/s + "
          "%.0f s), once with the root steering on (the default) and once "
          "with `SMG_CHARACTER_NO_STEERING` (the motion graph alone). "
          "Graphs: the paper-size CMU set of section 1; "
          "`data/cmu-sparse.manifest` (the 02_01 and 06_01 walks and the "
          "09_01-09_03 runs, mirrored: the few nearly straight clips a user "
          "has first); and the Bandai Namco set of section 6 "
          "(`data/bandai.manifest`, another studio and skeleton with walks "
          "turning 90 deg, clips read at run time), started once in its "
          "first style `walk` and once in its second performer's style "
          "`exhausted` (`smg_character_desc.initial_style`). "
          "Measured from the exported world matrices only: the hips' "
          "distance on the ground from the path (to the part of it near "
          "where the hips are along it) until they first come within "
          "%.1f m of the last point; whether they do (and when); over the "
          "last second of the run their mean speed and largest distance "
          "from the last point; and the mean correction the steering "
          "reported (`smg_character_state.steer_turn_rate`, "
          "`steer_slide_speed`). Targets with steering on, on every graph: "
          "smooth paths (straight, S-curve, r = 5 m circle) mean <= 5 cm "
          "and max <= 25 cm; tight paths (corners, U-turn, r = 2 m circle, "
          "scribble) mean <= 10 cm and max <= 45 cm; every end reached; at "
          "rest within 0.3 m at <= 0.1 m/s; planted-toe speed (toes within "
          "2.5 cm of their own floor level in two consecutive frames, "
          "`tools/eval/eval_feet_geom.c`, until the end is reached) <= 20 "
          "cm/s and not above the same run with steering off. That last "
          "comparison is made over %d seeds (`smg_character_desc.seed`: "
          "which of equally good clips the character picks): one run's "
          "figure moves by 0.2-0.9 cm/s with the seed alone, more than "
          "steering changes it, so steering on counts as above off when "
          "its seeds' mean exceeds off's by more than twice the standard "
          "error of the difference.\n\n",
          FOLLOW_RATE, FOLLOW_SPEED, FOLLOW_EXTRA, END_RADIUS, FEET_SEEDS);
  follow_graphs(ctx, cmu_blob, cmu_size);
}
