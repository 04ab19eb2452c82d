/*
 * eval_paths.c - section 2: path following like the paper's Fig. 4, on
 * five paths (straight, left turn, right turn, S-curve, full circle), each
 * with transition points (walk -> run -> walk) and splice points (punch on
 * and off), through the public runtime API at a fixed 30 Hz step.
 *
 * Measured per path: time from "path given" to the first pose, per-frame
 * cost (step + model matrices), distance of the root (hips joint projected
 * on the ground) from the path, foot skate during contacts, and where the
 * style/action actually switched compared with where it was requested.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_ctx.h"
#include "eval_joints.h"
#include "eval_metrics.h"
#include "eval_run.h"
#include "svg_plot.h"

#define RATE 30.0f
#define MAX_PATH_POINTS 8192
#define PI 3.14159265358979323846
#define NO_ACTION 0xffffffffu /* the blob has no upper-body action */

typedef struct path_spec {
  const char* key;   /* figure name part */
  const char* title;
  int kind;          /* 0 straight, 1 turn, 2 s-curve, 3 circle */
  double angle;      /* turn: signed angle */
} path_spec;

static const path_spec k_paths[] = {
    {"straight", "Straight line", 0, 0.0},
    {"left", "Left turn (90 deg)", 1, PI / 2},
    {"right", "Right turn (90 deg)", 1, -PI / 2},
    {"s-curve", "S-curve (2 x 90 deg)", 2, PI / 2},
    {"circle", "Full circle (r = 5 m)", 3, 0.0},
};
#define PATH_COUNT (sizeof(k_paths) / sizeof(k_paths[0]))

static size_t build_path(const path_spec* p, double* xz, size_t cap) {
  switch (p->kind) {
    case 1: return em_path_turn(8.0, 4.0, p->angle, 10.0, 0.1, xz, cap);
    case 2: return em_path_s_curve(6.0, 4.0, p->angle, 8.0, 0.1, xz, cap);
    case 3: return em_path_circle(6.0, 5.0, 6.0, 0.1, xz, cap);
    default: return em_path_straight(26.0, 0.1, xz, cap);
  }
}

/* What one path run produced, for the report tables. */
typedef struct path_result {
  int ok;
  char error[256];
  double length;
  size_t frames;
  int reached_end;
  double first_pose_ms;
  em_stats step_us;
  double dev_mean, dev_max;
  em_skate skate_rt;   /* runtime contact flags */
  em_skate skate_own;  /* own height/speed detection */
  double contact_fraction_rt;
  uint32_t constraint_count;
  eval_constraint constraints[8];
  double switch_arc[8]; /* where it switched (NAN: never) */
  double style_agree, action_agree; /* share of frames as requested */
  double furthest;      /* largest hips arc length reached, metres */
  double seconds;       /* simulated time of the run */
  size_t switch_frame[8];
} path_result;

/* Per-frame series extracted from a trace. */
typedef struct series {
  double* hips_xz;
  double* arc;
  double* arc_dist; /* distance to the path at that arc length */
  double *lank, *ltoe, *rank, *rtoe; /* 3 per frame */
  uint8_t *lc_rt, *rc_rt, *lc_own, *rc_own;
  double* scratch;
} series;

static void series_free(series* s) {
  free(s->hips_xz);
  free(s->arc);
  free(s->arc_dist);
  free(s->lank);
  free(s->ltoe);
  free(s->rank);
  free(s->rtoe);
  free(s->lc_rt);
  free(s->rc_rt);
  free(s->lc_own);
  free(s->rc_own);
  free(s->scratch);
  memset(s, 0, sizeof(*s));
}

/* Series of the lower of two joints (the planted part of a foot). */
static void lowest_of(const double* a, const double* b, size_t n,
                      double* out) {
  size_t i;
  for (i = 0; i < n; ++i) {
    const double* p = (b[3 * i + 1] < a[3 * i + 1]) ? b + 3 * i : a + 3 * i;
    memcpy(out + 3 * i, p, 3 * sizeof(double));
  }
}

static int series_make(const eval_trace* t, const eval_joints* j,
                       const double* path, size_t n, series* s) {
  size_t i, F = t->frames;
  double prev_arc = 0.0;
  double* low = NULL;
  memset(s, 0, sizeof(*s));
  s->hips_xz = (double*)malloc(2 * F * sizeof(double));
  s->arc = (double*)malloc(F * sizeof(double));
  s->arc_dist = (double*)malloc(F * sizeof(double));
  s->lank = (double*)malloc(3 * F * sizeof(double));
  s->ltoe = (double*)malloc(3 * F * sizeof(double));
  s->rank = (double*)malloc(3 * F * sizeof(double));
  s->rtoe = (double*)malloc(3 * F * sizeof(double));
  s->lc_rt = (uint8_t*)malloc(F);
  s->rc_rt = (uint8_t*)malloc(F);
  s->lc_own = (uint8_t*)malloc(F);
  s->rc_own = (uint8_t*)malloc(F);
  s->scratch = (double*)malloc(F * sizeof(double));
  low = (double*)malloc(3 * F * sizeof(double));
  if (!s->hips_xz || !s->arc || !s->arc_dist || !s->lank || !s->ltoe || !s->rank ||
      !s->rtoe || !s->lc_rt || !s->rc_rt || !s->lc_own || !s->rc_own ||
      !s->scratch || !low) {
    free(low);
    series_free(s);
    return 0;
  }
  for (i = 0; i < F; ++i) {
    const double* h = eval_joint(t, i, j->hips);
    s->hips_xz[2 * i] = h[0];
    s->hips_xz[2 * i + 1] = h[2];
    /* Arc length of the hips along the path, tracked so that a path
     * passing the same place twice (the circle) is not confused. */
    s->arc_dist[i] = em_polyline_distance_window(
        path, n, h[0], h[2], prev_arc - 0.5, prev_arc + 2.0, &s->arc[i]);
    prev_arc = s->arc[i];
    memcpy(s->lank + 3 * i, eval_joint(t, i, j->lfoot), 3 * sizeof(double));
    memcpy(s->ltoe + 3 * i, eval_joint(t, i, j->ltoe), 3 * sizeof(double));
    memcpy(s->rank + 3 * i, eval_joint(t, i, j->rfoot), 3 * sizeof(double));
    memcpy(s->rtoe + 3 * i, eval_joint(t, i, j->rtoe), 3 * sizeof(double));
    s->lc_rt[i] = (t->flags[i] & SMG_STATE_LEFT_CONTACT) != 0;
    s->rc_rt[i] = (t->flags[i] & SMG_STATE_RIGHT_CONTACT) != 0;
  }
  /* Own detection on the lower of ankle and toe: within 3 cm of its
   * lowest height and slower than 1 m/s. */
  lowest_of(s->lank, s->ltoe, F, low);
  em_detect_contacts(low, F, t->dt, 0.03, 1.0, s->lc_own);
  lowest_of(s->rank, s->rtoe, F, low);
  em_detect_contacts(low, F, t->dt, 0.03, 1.0, s->rc_own);
  free(low);
  return 1;
}

/* Share of frames whose style (action) is the one requested at the hips'
 * arc length: the initial one, replaced by each constraint from its arc
 * on. Frames within 1.5 m of any constraint point are not counted, so a
 * switch a little early or late does not weigh on it. */
static void agreement(const eval_trace* t, const series* s,
                      const path_result* pr, uint32_t walk, double* style,
                      double* action) {
  size_t i, n = 0, ok_s = 0, ok_a = 0;
  uint32_t c;
  for (i = 0; i < t->frames; ++i) {
    uint32_t want_s = walk, want_a = 0;
    int near = 0;
    for (c = 0; c < pr->constraint_count; ++c) {
      const eval_constraint* k = &pr->constraints[c];
      if (fabs(s->arc[i] - k->arc) < 1.5) near = 1;
      if (s->arc[i] >= k->arc) {
        if (k->kind == EVAL_KIND_SPLICE) want_a = k->value;
        else want_s = k->value;
      }
    }
    if (near) continue;
    n++;
    ok_s += t->style[i] == want_s;
    ok_a += t->action[i] == want_a;
  }
  *style = n ? (double)ok_s / (double)n : NAN;
  *action = n ? (double)ok_a / (double)n : NAN;
}

/* Both feet together. */
static void skate_both(const series* s, size_t F, const uint8_t* lc,
                       const uint8_t* rc, em_skate* out) {
  em_skate l, r;
  em_foot_skate_lowest(s->lank, s->ltoe, lc, F, &l);
  em_foot_skate_lowest(s->rank, s->rtoe, rc, F, &r);
  memset(out, 0, sizeof(*out));
  out->contact_frames = l.contact_frames + r.contact_frames;
  out->total_cm = l.total_cm + r.total_cm;
  out->mean_cm = out->contact_frames
                     ? out->total_cm / (double)out->contact_frames
                     : NAN;
  out->max_cm = NAN;
  if (l.contact_frames) out->max_cm = l.max_cm;
  if (r.contact_frames && !(r.max_cm <= out->max_cm)) out->max_cm = r.max_cm;
}

/* Where each constraint took effect: the first frame after the previous
 * switch of the same kind at which the style/action changes INTO the
 * target (a change event, not merely "equals", so a constraint whose
 * predecessor never happened is not credited with the initial state). */
static void find_switches(const eval_trace* t, const series* s,
                          path_result* pr) {
  size_t from[2] = {0, 0};
  uint32_t c;
  for (c = 0; c < pr->constraint_count; ++c) {
    const eval_constraint* k = &pr->constraints[c];
    const uint32_t* lab = k->kind == EVAL_KIND_SPLICE ? t->action : t->style;
    size_t f;
    for (f = from[k->kind] + 1; f < t->frames; ++f)
      if (lab[f] == k->value && lab[f - 1] != k->value) break;
    pr->switch_frame[c] = f;
    pr->switch_arc[c] = f < t->frames ? s->arc[f] : NAN;
    if (f < t->frames) from[k->kind] = f;
  }
}

static const char* k_style_colors[4] = {"#1f5fd6", "#d62728", "#8c564b",
                                        "#9467bd"};

static void draw_figure(eval_ctx* ctx, smg_graph* g, const path_spec* p,
                        const double* path, size_t n, const eval_trace* t,
                        const series* s, const path_result* pr) {
  svp_figure* fig;
  char file[64], full[1400], title[160], txt[96];
  size_t F = t->frames, i, k;
  double *px = NULL, *pz = NULL, *ax = NULL, *az = NULL;
  double *fx = NULL, *fz = NULL;
  unsigned* idx = NULL;
  uint32_t c, style_count = 0;
  smg_graph_info info;

  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if (smg_graph_get_info(g, &info) == SMG_OK) style_count = info.style_count;
  snprintf(title, sizeof(title), "%s: root trajectory seen from above",
           p->title);
  fig = svp_create(640, 640, title);
  px = (double*)malloc((n + F) * sizeof(double));
  pz = (double*)malloc((n + F) * sizeof(double));
  ax = (double*)malloc(F * sizeof(double));
  az = (double*)malloc(F * sizeof(double));
  fx = (double*)malloc(F * sizeof(double));
  fz = (double*)malloc(F * sizeof(double));
  idx = (unsigned*)malloc((F + 1) * sizeof(unsigned));
  if (!fig || !px || !pz || !ax || !az || !fx || !fz || !idx) goto done;
  svp_set_labels(fig, "x (m)  [true top view: +x points left]", "z (m)");
  svp_set_equal_aspect(fig, 1);
  svp_set_x_left(fig, 1);

  for (i = 0; i < n; ++i) px[i] = path[2 * i], pz[i] = path[2 * i + 1];
  svp_line(fig, px, pz, n, "#c8c8c8", 7.0, 0, "drawn path");
  /* Upper-body action on: a green band under the trajectory. */
  for (i = 0; i < F; ++i) {
    int on = t->action[i] != 0;
    ax[i] = on ? s->hips_xz[2 * i] : NAN;
    az[i] = on ? s->hips_xz[2 * i + 1] : NAN;
  }
  svp_line(fig, ax, az, F, "#2ca02c", 6.0, 0, "upper body: punch spliced");
  /* Trajectory coloured by locomotion style. */
  for (i = 0; i < F; ++i) {
    px[i] = s->hips_xz[2 * i];
    pz[i] = s->hips_xz[2 * i + 1];
    idx[i] = t->style[i] < 4 ? t->style[i] : 3;
  }
  svp_colored_line(fig, px, pz, F, idx, k_style_colors, 4, 2.0);
  for (c = 0; c < style_count && c < 4; ++c) {
    const char* name = "?";
    smg_graph_get_style_name(g, c, &name);
    snprintf(txt, sizeof(txt), "root: %s", name);
    svp_legend_entry(fig, txt, k_style_colors[c], 0, SVP_CIRCLE);
  }
  /* Footprints: where each foot was planted (runtime contact flags). */
  for (k = 0; k < 2; ++k) {
    const uint8_t* con = k ? s->rc_rt : s->lc_rt;
    const double* an = k ? s->rank : s->lank;
    const double* to = k ? s->rtoe : s->ltoe;
    size_t m = 0;
    for (i = 0; i < F; ++i)
      if (con[i] && (i == 0 || !con[i - 1])) {
        const double* q = to[3 * i + 1] < an[3 * i + 1] ? to : an;
        fx[m] = q[3 * i];
        fz[m] = q[3 * i + 2];
        m++;
      }
    svp_scatter(fig, fx, fz, m, k ? SVP_TRIANGLE : SVP_SQUARE,
                k ? "#ff9f1c" : "#6a3d9a", 2.6,
                k ? "right footfall" : "left footfall");
  }
  /* Requested constraint points (on the path) and where they happened. */
  for (c = 0; c < pr->constraint_count; ++c) {
    const eval_constraint* q = &pr->constraints[c];
    double x, z;
    const char* name = "?";
    if (q->kind == EVAL_KIND_SPLICE)
      smg_graph_get_action_name(g, q->value, &name);
    else
      smg_graph_get_style_name(g, q->value, &name);
    em_polyline_point_at(path, n, q->arc, &x, &z);
    snprintf(txt, sizeof(txt), "%s %s", q->kind == EVAL_KIND_SPLICE
                                            ? "splice:"
                                            : "transition:", name);
    svp_marker(fig, x, z, q->kind == EVAL_KIND_SPLICE ? SVP_CIRCLE
                                                      : SVP_DIAMOND,
               q->kind == EVAL_KIND_SPLICE ? "#17becf" : "#ffd700", 6.0, txt);
    if (pr->switch_frame[c] < F)
      svp_marker(fig, s->hips_xz[2 * pr->switch_frame[c]],
                 s->hips_xz[2 * pr->switch_frame[c] + 1], SVP_CROSS, "#000",
                 5.0, NULL);
  }
  svp_legend_entry(fig, "requested splice point", "#17becf", 1, SVP_CIRCLE);
  svp_legend_entry(fig, "requested transition point", "#ffd700", 1,
                   SVP_DIAMOND);
  svp_legend_entry(fig, "where it switched", "#000", 1, SVP_CROSS);
  svp_marker(fig, path[0], path[1], SVP_CIRCLE, "#000", 3.0, "start");

  snprintf(file, sizeof(file), "eval-path-%s.svg", p->key);
  eval_img_path(ctx, file, full, sizeof(full));
  if (svp_write(fig, full) == 0)
    eval_md(ctx, "![%s](%s/%s)\n\n", p->title, ctx->img_rel, file);
  else
    eval_md(ctx, "(figure %s could not be written)\n\n", file);
done:
  svp_destroy(fig);
  free(px);
  free(pz);
  free(ax);
  free(az);
  free(fx);
  free(fz);
  free(idx);
}

/* --keep: the trace as CSV for inspection outside this program. */
static void keep_trace(const eval_ctx* ctx, const path_spec* p,
                       const eval_trace* t, const series* s) {
  char path[1200];
  FILE* f;
  size_t i;
  snprintf(path, sizeof(path), "%s/path-%s.csv", ctx->keep_dir, p->key);
  f = fopen(path, "w");
  if (!f) return;
  fprintf(f, "frame,time,hips_x,hips_z,arc,state_x,state_z,heading,style,"
             "action,flags,path_distance,path_error,sync_rate,lower_node,"
             "upper_node,step_us\n");
  for (i = 0; i < t->frames; ++i)
    fprintf(f, "%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%u,%u,%u,%.4f,%.4f,"
               "%.4f,0,%u,%.2f\n",
            i, (double)i * t->dt, s->hips_xz[2 * i], s->hips_xz[2 * i + 1],
            s->arc[i], t->ground[3 * i], t->ground[3 * i + 1],
            t->ground[3 * i + 2], t->style[i], t->action[i], t->flags[i],
            t->path_distance[i], t->path_error[i], t->sync_rate[i],
            t->upper_node[i], 1e6 * t->step_seconds[i]);
  fclose(f);
}

/* Runs one path and fills pr; draws the figure in report mode. */
static void run_path(eval_ctx* ctx, smg_graph* g, const path_spec* p,
                     uint32_t walk, uint32_t run, uint32_t action, int draw,
                     path_result* pr) {
  static double path[2 * MAX_PATH_POINTS];
  static float pathf[2 * MAX_PATH_POINTS];
  eval_run_desc rd;
  eval_trace t;
  series s;
  eval_joints j;
  size_t n, i, F;
  double* tmp;
  smg_result r;

  memset(pr, 0, sizeof(*pr));
  if (!eval_find_joints(g, &j)) {
    snprintf(pr->error, sizeof(pr->error),
             "skeleton lacks recognisable pelvis, feet or toes");
    return;
  }
  n = build_path(p, path, MAX_PATH_POINTS);
  for (i = 0; i < 2 * n; ++i) pathf[i] = (float)path[i];
  pr->length = em_polyline_length(path, n);

  /* walk -> (punch on) -> run -> (punch off) -> walk. */
  i = 0;
  if (action != NO_ACTION) {
    pr->constraints[i++] = (eval_constraint){EVAL_KIND_SPLICE,
                                             (float)(0.15 * pr->length),
                                             action};
  }
  pr->constraints[i++] = (eval_constraint){EVAL_KIND_TRANSITION,
                                           (float)(0.35 * pr->length), run};
  if (action != NO_ACTION) {
    pr->constraints[i++] = (eval_constraint){EVAL_KIND_SPLICE,
                                             (float)(0.55 * pr->length), 0};
  }
  pr->constraints[i++] = (eval_constraint){EVAL_KIND_TRANSITION,
                                           (float)(0.75 * pr->length), walk};
  pr->constraint_count = (uint32_t)i;

  memset(&rd, 0, sizeof(rd));
  rd.path_xz = pathf;
  rd.path_count = (uint32_t)n;
  rd.constraints = pr->constraints;
  rd.constraint_count = pr->constraint_count;
  rd.initial_style = walk;
  rd.rate = RATE;
  rd.max_seconds = (float)(pr->length / 0.6 + 10.0);
  rd.extra_seconds = 1.0f;
  r = eval_run(g, &rd, &t, pr->error, sizeof(pr->error));
  if (r != SMG_OK) return;
  F = t.frames;
  if (!series_make(&t, &j, path, n, &s)) {
    snprintf(pr->error, sizeof(pr->error), "out of memory");
    eval_trace_free(&t);
    return;
  }
  pr->ok = 1;
  pr->frames = F;
  pr->reached_end = t.reached_end;
  pr->first_pose_ms = 1e3 * t.first_pose_seconds;
  tmp = (double*)malloc(F * sizeof(double));
  if (tmp) {
    for (i = 1; i < F; ++i) tmp[i - 1] = 1e6 * t.step_seconds[i];
    em_stats_compute(tmp, F - 1, s.scratch, &pr->step_us);
    free(tmp);
  }
  em_path_deviation(path, n, s.hips_xz, F, &pr->dev_mean, &pr->dev_max);
  skate_both(&s, F, s.lc_rt, s.rc_rt, &pr->skate_rt);
  skate_both(&s, F, s.lc_own, s.rc_own, &pr->skate_own);
  {
    size_t con = 0;
    for (i = 0; i < F; ++i) con += s.lc_rt[i] + s.rc_rt[i];
    pr->contact_fraction_rt = (double)con / (2.0 * (double)F);
  }
  pr->furthest = 0.0;
  /* Only points actually reached count: within 1 m of the path there. */
  for (i = 0; i < F; ++i)
    if (s.arc_dist[i] < 1.0 && s.arc[i] > pr->furthest)
      pr->furthest = s.arc[i];
  pr->seconds = (double)(F - 1) * t.dt;
  find_switches(&t, &s, pr);
  agreement(&t, &s, pr, walk, &pr->style_agree, &pr->action_agree);
  if (draw) draw_figure(ctx, g, p, path, n, &t, &s, pr);
  if (ctx->keep_dir && (draw || ctx->check)) keep_trace(ctx, p, &t, &s);
  series_free(&s);
  eval_trace_free(&t);
}

static void summarize_paths(eval_ctx* ctx, const path_result* res,
                            const char* graph, uint32_t joints) {
  size_t k, ran = 0, ended = 0, sw_total = 0, sw_near = 0;
  double first_max = 0, med_max = 0, p99_max = 0, dev_lo = INFINITY,
         dev_hi = 0, sk_lo = INFINITY, sk_hi = 0;
  uint32_t c;
  for (k = 0; k < PATH_COUNT; ++k) {
    const path_result* r = &res[k];
    if (!r->ok) continue;
    ran++;
    ended += r->furthest >= r->length - 1.0;
    if (r->first_pose_ms > first_max) first_max = r->first_pose_ms;
    if (r->step_us.median > med_max) med_max = r->step_us.median;
    if (r->step_us.p99 > p99_max) p99_max = r->step_us.p99;
    if (r->dev_mean < dev_lo) dev_lo = r->dev_mean;
    if (r->dev_mean > dev_hi) dev_hi = r->dev_mean;
    if (r->skate_rt.mean_cm < sk_lo) sk_lo = r->skate_rt.mean_cm;
    if (r->skate_rt.mean_cm > sk_hi) sk_hi = r->skate_rt.mean_cm;
    for (c = 0; c < r->constraint_count; ++c) {
      sw_total++;
      sw_near += isfinite(r->switch_arc[c]) &&
                 fabs(r->switch_arc[c] - r->constraints[c].arc) <= 1.0;
    }
  }
  if (!ran) {
    eval_summary(ctx, "**Path following%s%s**: no path could be run.",
                 graph ? ", " : "", graph ? graph : "");
    return;
  }
  eval_summary(ctx,
               "**Path following%s%s** (%zu paths, 30 Hz): path given -> first "
               "pose at most %.3f ms (paper: 3-23 s to plan a drawn path); "
               "per frame (step + %u matrices) median <= %.1f us, p99 <= "
               "%.1f us; followed the path to its end (within 1 m) on %zu of %zu "
               "paths; mean "
               "root distance from the path %.2f-%.2f m per path; foot skate "
               "%.2f-%.2f cm per contact frame; %zu of %zu style/action "
               "switches within 1 m of the requested point.",
               graph ? ", " : "", graph ? graph : "", ran, first_max, joints,
               med_max,
               p99_max, ended, ran, dev_lo, dev_hi,
               sk_lo, sk_hi, sw_near, sw_total);
}

static void report_paths(eval_ctx* ctx, smg_graph* g,
                         const path_result* res, const char* graph) {
  size_t k;
  uint32_t c;
  char a[32], b[32], d[32], e[32], f[32], h[32], x[32];
  smg_graph_info info;
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  smg_graph_get_info(g, &info);
  summarize_paths(ctx, res, graph, info.joint_count);
  eval_md(ctx,
          "| Path | length (m) | frames | path given -> first pose (ms) | "
          "per frame median / p99 (us) | root distance from path mean / max "
          "(cm) | furthest point of the path reached, within 1 m (m), in "
          "time (s) | "
          "runtime flagged the end reached |\n|---|---:|---:|---:|---:|---:|---:|---|\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    const path_result* r = &res[k];
    if (!r->ok) {
      eval_md(ctx, "| %s | FAILED: %s | | | | | | |\n", k_paths[k].title,
              r->error);
      continue;
    }
    eval_md(ctx,
            "| %s | %.1f | %zu | %s | %s / %s | %s / %s | %.1f in %.1f | %s "
            "|\n",
            k_paths[k].title, r->length, r->frames,
            eval_fmt(a, sizeof(a), "%.3f", r->first_pose_ms),
            eval_fmt(b, sizeof(b), "%.1f", r->step_us.median),
            eval_fmt(d, sizeof(d), "%.1f", r->step_us.p99),
            eval_fmt(e, sizeof(e), "%.1f", 100.0 * r->dev_mean),
            eval_fmt(f, sizeof(f), "%.1f", 100.0 * r->dev_max), r->furthest,
            r->seconds, r->reached_end ? "yes" : "**no**");
  }
  eval_md(ctx,
          "\nFoot skate: horizontal slide of the planted part of the foot "
          "(the lower of ankle and toe) between consecutive contact frames, "
          "both feet, in cm per 30 Hz frame. Contacts from the runtime's "
          "`SMG_STATE_LEFT/RIGHT_CONTACT` flags, and, as a cross-check, from "
          "this evaluation's own detection (lower of ankle/toe within 3 cm of "
          "its lowest height and slower than 1 m/s; that speed limit hides "
          "slides faster than 3.3 cm/frame, so the runtime-flag column is "
          "the primary one).\n\n"
          "| Path | runtime contacts: mean / max (cm/frame) | contact frames "
          "(share of foot-frames) | own detection: mean / max | contact "
          "frames |\n|---|---:|---:|---:|---:|\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    const path_result* r = &res[k];
    if (!r->ok) continue;
    eval_md(ctx, "| %s | %s / %s | %zu (%.0f %%) | %s / %s | %zu |\n",
            k_paths[k].title,
            eval_fmt(a, sizeof(a), "%.2f", r->skate_rt.mean_cm),
            eval_fmt(b, sizeof(b), "%.2f", r->skate_rt.max_cm),
            r->skate_rt.contact_frames, 100.0 * r->contact_fraction_rt,
            eval_fmt(d, sizeof(d), "%.2f", r->skate_own.mean_cm),
            eval_fmt(e, sizeof(e), "%.2f", r->skate_own.max_cm),
            r->skate_own.contact_frames);
  }
  eval_md(ctx,
          "\nSwitches: each constraint's requested arc length and the arc "
          "length of the hips (projected on the path) at the first frame, "
          "after the previous switch of the same kind, at which the style/"
          "action changes into the target. Positive difference = switched "
          "after the requested point.\n\n"
          "| Path | constraint | requested at (m) | switched at (m) | "
          "difference (m) |\n|---|---|---:|---:|---:|\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    const path_result* r = &res[k];
    if (!r->ok) continue;
    for (c = 0; c < r->constraint_count; ++c) {
      const eval_constraint* q = &r->constraints[c];
      const char* name = "?";
      if (q->kind == EVAL_KIND_SPLICE)
        smg_graph_get_action_name(g, q->value, &name);
      else
        smg_graph_get_style_name(g, q->value, &name);
      eval_md(ctx, "| %s | %s -> %s | %.2f | %s | %s |\n", k_paths[k].title,
              q->kind == EVAL_KIND_SPLICE ? "splice" : "transition", name,
              (double)q->arc,
              eval_fmt(h, sizeof(h), "%.2f", r->switch_arc[c]),
              isfinite(r->switch_arc[c])
                  ? eval_fmt(x, sizeof(x), "%+.2f",
                             r->switch_arc[c] - (double)q->arc)
                  : "**never**");
    }
  }
  eval_md(ctx,
          "\nStyle and action held as requested: share of frames whose "
          "style (action) is the one requested at the hips' arc length "
          "(frames within 1.5 m of a constraint point not counted).\n\n"
          "| Path | style as requested | action as requested |\n"
          "|---|---:|---:|\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    const path_result* r = &res[k];
    if (!r->ok) continue;
    eval_md(ctx, "| %s | %s %% | %s %% |\n", k_paths[k].title,
            eval_fmt(a, sizeof(a), "%.0f", 100.0 * r->style_agree),
            eval_fmt(b, sizeof(b), "%.0f", 100.0 * r->action_agree));
  }
  eval_md(ctx, "\n");
}

/* Loose regression bounds used by `make test-eval`. */
static void check_path(eval_ctx* ctx, const char* what, const path_result* r) {
  uint32_t c;
  if (!eval_check(ctx, r->ok, "%s: ran (%s)", what, r->ok ? "ok" : r->error))
    return;
  eval_check(ctx, r->reached_end && r->furthest >= r->length - 1.5,
             "%s: followed a %.1f m path to %.1f m (within 1 m of it; "
             "bound: end - 1.5 m) and flagged the end %s", what, r->length,
             r->furthest, r->reached_end ? "reached" : "NOT reached");
  eval_check(ctx, r->dev_mean < 0.5 && r->dev_max < 1.5,
             "%s: root from path mean %.2f m, max %.2f m (bounds 0.5, 1.5)",
             what, r->dev_mean, r->dev_max);
  eval_check(ctx, r->first_pose_ms < 50.0,
             "%s: path given -> first pose %.3f ms (bound 50 ms)", what,
             r->first_pose_ms);
  eval_check(ctx, r->skate_rt.contact_frames > 0 && r->skate_rt.mean_cm < 3.0,
             "%s: foot skate %.2f cm/frame over %zu contact frames (bound 3)",
             what, r->skate_rt.mean_cm, r->skate_rt.contact_frames);
  for (c = 0; c < r->constraint_count; ++c)
    eval_check(ctx,
               isfinite(r->switch_arc[c]) &&
                   fabs(r->switch_arc[c] - r->constraints[c].arc) < 4.0,
               "%s: %s %u requested at %.1f m switched at %.2f m (bound 4 m)",
               what,
               r->constraints[c].kind == EVAL_KIND_SPLICE ? "splice"
                                                          : "transition",
               r->constraints[c].value, (double)r->constraints[c].arc,
               r->switch_arc[c]);
}

/* Style/action indices: by name on the CMU blob, by position otherwise. */
static void pick_labels(smg_graph* g, uint32_t* walk, uint32_t* run,
                        uint32_t* action) {
  smg_graph_info info;
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  smg_graph_get_info(g, &info);
  if (smg_graph_find_style(g, "walk", walk) != SMG_OK) *walk = 0;
  if (smg_graph_find_style(g, "run", run) != SMG_OK)
    *run = info.style_count > 1 ? (*walk == 0 ? 1 : 0) : *walk;
  if (smg_graph_find_action(g, "punch", action) != SMG_OK)
    *action = info.action_count > 1 ? 1 : NO_ACTION;
}

static int load_file(const char* path, void** out, size_t* size) {
  FILE* f = fopen(path, "rb");
  long n;
  void* buf = NULL;
  *out = NULL;
  if (!f) return 0;
  if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) <= 0 ||
      fseek(f, 0, SEEK_SET) != 0 ||
      posix_memalign(&buf, 16, (size_t)n) != 0) {
    fclose(f);
    return 0;
  }
  if (fread(buf, 1, (size_t)n, f) != (size_t)n) {
    free(buf);
    fclose(f);
    return 0;
  }
  fclose(f);
  *out = buf;
  *size = (size_t)n;
  return 1;
}

static void check_default_blob(eval_ctx* ctx) {
  void* data = NULL;
  size_t size = 0;
  smg_graph* g = NULL;
  smg_result r;
  uint32_t walk, run, action;
  path_result pr;
  if (!ctx->default_blob || !load_file(ctx->default_blob, &data, &size)) {
    printf("SKIP synthetic default blob: %s not readable\n",
           ctx->default_blob ? ctx->default_blob : "(none given)");
    return;
  }
  r = smg_graph_load_memory(data, size, NULL, &g);
  if (eval_check(ctx, r == SMG_OK, "synthetic default blob loads: %s",
                 smg_result_string(r))) {
    pick_labels(g, &walk, &run, &action);
    run_path(ctx, g, &k_paths[0], walk, run, action, 0, &pr);
    check_path(ctx, "synthetic straight", &pr);
    run_path(ctx, g, &k_paths[1], walk, run, action, 0, &pr);
    check_path(ctx, "synthetic left turn", &pr);
    smg_graph_destroy(g);
  }
  free(data);
}

void eval_section_paths(eval_ctx* ctx, const void* blob, size_t size) {
  smg_graph* g = NULL;
  smg_result r;
  uint32_t walk, run, action;
  static path_result res[PATH_COUNT];
  size_t k;

  if (ctx->check) check_default_blob(ctx);
  if (!blob) {
    eval_md(ctx, "## 2. Path following\n\nNot produced: no CMU blob was "
                 "baked in this run (see section 1).\n\n");
    if (ctx->check) printf("SKIP CMU path following: no CMU blob\n");
    return;
  }
  r = smg_graph_load_memory(blob, size, NULL, &g);
  if (r != SMG_OK) {
    eval_md(ctx, "## 2. Path following\n\nThe baked CMU blob did not load "
                 "in this run: `%s`.\n\n", smg_result_string(r));
    eval_check(ctx, 0, "CMU blob loads: %s", smg_result_string(r));
    return;
  }
  pick_labels(g, &walk, &run, &action);
  if (ctx->check) {
    path_result pr;
    run_path(ctx, g, &k_paths[0], walk, run, action, 0, &pr);
    check_path(ctx, "CMU straight", &pr);
    smg_graph_destroy(g);
    return;
  }
  eval_md(ctx,
          "## 2. Path following (paper Fig. 4)\n\n"
          "The CMU blob of section 1, one character, the public runtime API "
          "(`smg_character_set_path`, `_add_transition`, `_add_splice`, "
          "`smg_character_step` at a fixed 1/30 s, "
          "`smg_character_get_model_matrices`). Every path starts walking "
          "with no action; constraints at fractions of the path length L: "
          "splice `punch` on at 0.15 L, transition to `run` at 0.35 L, "
          "splice back to `none` at 0.55 L, transition to `walk` at 0.75 L. "
          "The root trajectory is the hips joint projected on the ground. "
          "Timing: *path given -> first pose* covers `set_path` + the "
          "constraints + the first `step` + reading the first pose (the "
          "character already exists); *per frame* is one `step` plus "
          "`get_model_matrices` (31 joints), wall clock, one thread; the "
          "paths run in the order listed on a freshly loaded graph, so the "
          "first one also pays first-touch costs of the graph's memory. The "
          "paper reports 3-23 s from drawing to animation for the whole "
          "path; libsmg plans incrementally within each step.\n\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    eval_log("path %s...", k_paths[k].key);
    run_path(ctx, g, &k_paths[k], walk, run, action, 0, &res[k]);
  }
  report_paths(ctx, g, res, NULL);
  eval_md(ctx,
          "Figures: grey = drawn path; root coloured by style; green band = "
          "upper body doing the spliced action; squares/triangles = left/"
          "right footfalls; circles/diamonds = requested splice/transition "
          "points; black crosses = where the switch actually happened.\n\n");
  for (k = 0; k < PATH_COUNT; ++k) {
    path_result again;
    /* Figures come from a second, identical run (the runtime is
     * deterministic), so drawing never disturbs the timed run. */
    run_path(ctx, g, &k_paths[k], walk, run, action, 1, &again);
    if (!again.ok)
      eval_md(ctx, "Figure for %s not produced: %s\n\n", k_paths[k].title,
              again.error);
  }
  smg_graph_destroy(g);
}

void eval_paths_on_graph(eval_ctx* ctx, const void* blob, size_t size,
                         const char* graph) {
  smg_graph* g = NULL;
  smg_result r = smg_graph_load_memory(blob, size, NULL, &g);
  uint32_t walk, run, action;
  static path_result res[PATH_COUNT];
  size_t k;
  if (!eval_check(ctx, r == SMG_OK, "%s blob loads: %s", graph,
                  smg_result_string(r))) {
    eval_md(ctx, "The %s blob did not load in this run: `%s`.\n\n", graph,
            smg_result_string(r));
    return;
  }
  pick_labels(g, &walk, &run, &action);
  if (ctx->check) {
    path_result pr;
    char what[96];
    snprintf(what, sizeof(what), "%s straight", graph);
    run_path(ctx, g, &k_paths[0], walk, run, action, 0, &pr);
    check_path(ctx, what, &pr);
    smg_graph_destroy(g);
    return;
  }
  for (k = 0; k < PATH_COUNT; ++k) {
    eval_log("%s path %s...", graph, k_paths[k].key);
    run_path(ctx, g, &k_paths[k], walk, run, action, 0, &res[k]);
  }
  report_paths(ctx, g, res, graph);
  smg_graph_destroy(g);
}
