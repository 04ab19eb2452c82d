/*
 * eval_feet.c - section "feet from geometry": how still the toes are while
 * they are on the floor, judged from the exported toe positions alone
 * (tools/eval/eval_feet_geom.h), never from the runtime's contact flags.
 *
 * For every graph (the paper-size CMU blob of section 1, a graph whose
 * clips come from two performers: 02_01 + 06_01 walks on 02_01's skeleton,
 * the dribble graph of section 3, and with the Bandai Namco clips, their
 * graph on its own skeleton and the CMU set followed by them on the CMU
 * skeleton) and every path of section 2, one character runs with foot IK
 * on and one with it off; both get the geometric planted-toe speed (mean, p95, p99),
 * the lowest toe height, and, beside them, the flag-based skate of section
 * 2. The reference is the same measure on the graph's own source clips
 * (unmirrored lower clips as stored in the blob, i.e. after retargeting):
 * what the data itself does. One figure shows the planted-toe speed over
 * time on the CMU straight path.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_manifest.h"
#include "blob.h"
#include "eval_ctx.h"
#include "eval_feet_geom.h"
#include "eval_metrics.h"
#include "eval_run.h"
#include "quat_pack.h"
#include "smg_bake.h"
#include "smg_format.h"
#include "svg_plot.h"

#define RATE 30.0f
#define MAX_PATH_POINTS 8192
#define PI 3.14159265358979323846
#define CMU_UNIT 0.056444f
/* The bound on the planted-toe p99 (cm/s): pairs faster than this
 * are counted, and for IK on, checked against the IK-off run's same pair
 * (IK does not change the plan, so frame i is the same lower frame in
 * both): a pair as fast without IK is the animation's own. */
#define FAST_CMS 100.0
#define FAST_LISTED 4u /* clips named in the "pairs over FAST_CMS" list */

/* Planted pairs faster than FAST_CMS in a per-frame speed series (NaN =
 * not planted). */
static size_t count_fast(const double* v, size_t n) {
  size_t i, c = 0;
  for (i = 0; i < n; ++i)
    if (v[i] > FAST_CMS) ++c;
  return c;
}

typedef struct feet_path {
  const char* title;
  int kind; /* 0 straight, 1 turn, 2 s-curve, 3 circle */
  double angle;
} feet_path;

/* The paths of section 2. */
static const feet_path k_paths[] = {
    {"Straight line", 0, 0.0},
    {"Left turn (90 deg)", 1, PI / 2},
    {"Right turn (90 deg)", 1, -PI / 2},
    {"S-curve (2 x 90 deg)", 2, PI / 2},
    {"Full circle (r = 5 m)", 3, 0.0},
};
#define PATH_COUNT (sizeof(k_paths) / sizeof(k_paths[0]))

static size_t build_path(const feet_path* p, double* xz, size_t cap) {
  switch (p->kind) {
    case 1: return em_path_turn(8.0, 4.0, p->angle, 10.0, 0.1, xz, cap);
    case 2: return em_path_s_curve(6.0, 4.0, p->angle, 8.0, 0.1, xz, cap);
    case 3: return em_path_circle(6.0, 5.0, 6.0, 0.1, xz, cap);
    default: return em_path_straight(26.0, 0.1, xz, cap);
  }
}

typedef struct feet_joints {
  uint32_t lfoot, ltoe, rfoot, rtoe;
} feet_joints;

/* Ankles and toes as the baker found them (body roles, any naming). */
static int find_feet(const void* blob, size_t size, feet_joints* j) {
  smgi_graph_data gd;
  char why[256];
  if (smgi_blob_read(blob, size, 0, &gd, why, sizeof(why)) != SMG_OK)
    return 0;
  j->lfoot = gd.info->left_leg[2];
  j->ltoe = gd.info->left_leg[3];
  j->rfoot = gd.info->right_leg[2];
  j->rtoe = gd.info->right_leg[3];
  return j->lfoot < gd.joint_count && j->ltoe < gd.joint_count &&
         j->rfoot < gd.joint_count && j->rtoe < gd.joint_count;
}

/* One run's feet. */
typedef struct feet_run {
  int ok;
  char error[160];
  eval_feet_geom geom;
  em_skate flag_skate; /* section 2's figure: runtime contact flags */
  double* speed;       /* per frame, both toes (NaN: not planted) */
  double* any_speed;   /* per frame, both toes, planted or not */
  size_t frames;
} feet_run;

/* Section 2's flag-based skate: both feet, lower of ankle and toe. */
static void flag_skate(const eval_trace* t, const feet_joints* j,
                       em_skate* out) {
  size_t F = t->frames, i;
  double *la = (double*)malloc(3 * F * sizeof(double)),
         *lt = (double*)malloc(3 * F * sizeof(double)),
         *ra = (double*)malloc(3 * F * sizeof(double)),
         *rt = (double*)malloc(3 * F * sizeof(double));
  uint8_t *lc = (uint8_t*)malloc(F), *rc = (uint8_t*)malloc(F);
  em_skate l, r;
  memset(out, 0, sizeof(*out));
  out->mean_cm = out->max_cm = NAN;
  if (la && lt && ra && rt && lc && rc && F > 1) {
    for (i = 0; i < F; ++i) {
      memcpy(la + 3 * i, eval_joint(t, i, j->lfoot), 3 * sizeof(double));
      memcpy(lt + 3 * i, eval_joint(t, i, j->ltoe), 3 * sizeof(double));
      memcpy(ra + 3 * i, eval_joint(t, i, j->rfoot), 3 * sizeof(double));
      memcpy(rt + 3 * i, eval_joint(t, i, j->rtoe), 3 * sizeof(double));
      lc[i] = (t->flags[i] & SMG_STATE_LEFT_CONTACT) != 0;
      rc[i] = (t->flags[i] & SMG_STATE_RIGHT_CONTACT) != 0;
    }
    em_foot_skate_lowest(la, lt, lc, F, &l);
    em_foot_skate_lowest(ra, rt, rc, F, &r);
    out->contact_frames = l.contact_frames + r.contact_frames;
    out->total_cm = l.total_cm + r.total_cm;
    out->mean_cm = out->contact_frames
                       ? out->total_cm / (double)out->contact_frames
                       : NAN;
    out->max_cm = l.max_cm > r.max_cm ? l.max_cm : r.max_cm;
  }
  free(la);
  free(lt);
  free(ra);
  free(rt);
  free(lc);
  free(rc);
}

static void run_one(smg_graph* g, const feet_joints* j, const float* path,
                    uint32_t n, const eval_constraint* cons, uint32_t ncons,
                    uint32_t style, uint32_t flags, feet_run* out) {
  eval_run_desc rd;
  eval_trace t;
  const double* toes[2];
  double len = 0.0;
  uint32_t i;
  smg_result r;
  memset(out, 0, sizeof(*out));
  for (i = 1; i < n; ++i)
    len += hypot(path[2 * i] - path[2 * i - 2],
                 path[2 * i + 1] - path[2 * i - 1]);
  memset(&rd, 0, sizeof(rd));
  rd.path_xz = path;
  rd.path_count = n;
  rd.constraints = cons;
  rd.constraint_count = ncons;
  rd.initial_style = style;
  rd.initial_action = 0;
  rd.rate = RATE;
  rd.max_seconds = (float)(len / 0.6 + 10.0);
  rd.extra_seconds = 1.0f;
  rd.seed = 1;
  rd.character_flags = flags;
  r = eval_run(g, &rd, &t, out->error, sizeof(out->error));
  if (r != SMG_OK) return;
  toes[0] = t.joints + 3 * j->ltoe;
  toes[1] = t.joints + 3 * j->rtoe;
  out->speed = (double*)malloc(2 * t.frames * sizeof(double));
  out->any_speed = (double*)malloc(2 * t.frames * sizeof(double));
  if (out->any_speed) {
    size_t f;
    int k;
    for (k = 0; k < 2; ++k) out->any_speed[k] = NAN;
    for (f = 1; f < t.frames; ++f)
      for (k = 0; k < 2; ++k) {
        const double* a = toes[k] + (f - 1) * 3 * (size_t)t.joint_count;
        const double* b = toes[k] + f * 3 * (size_t)t.joint_count;
        out->any_speed[2 * f + k] =
            100.0 * hypot(b[0] - a[0], b[2] - a[2]) / t.dt;
      }
  }
  if (!out->speed || !out->any_speed ||
      eval_feet_geom_measure(toes, 2, 3 * (size_t)t.joint_count, t.frames,
                             t.dt, out->speed, &out->geom) != 0) {
    snprintf(out->error, sizeof(out->error), "out of memory");
    eval_trace_free(&t);
    return;
  }
  flag_skate(&t, j, &out->flag_skate);
  out->frames = t.frames;
  out->ok = 1;
  eval_trace_free(&t);
}

/* The graph's own source clips: unmirrored lower clips of the blob, FK on
 * its skeleton, the geometric measure pooled over all of them. */
static int source_clips(const void* blob, size_t size, eval_feet_geom* out,
                        uint32_t* clip_count, char* fast, size_t fast_size) {
  smgi_graph_data gd;
  char why[256];
  int32_t* parents = NULL;
  float *offsets = NULL, *pose = NULL;
  double *pos = NULL, *toe = NULL, *speed = NULL, *all = NULL;
  double lowest = INFINITY, sum = 0.0;
  size_t m = 0, total = 0;
  uint32_t c, i, J, lt, rt, listed = 0, unlisted = 0;
  int ok = 0;
  memset(out, 0, sizeof(*out));
  out->mean_cms = out->p95_cms = out->p99_cms = out->max_cms = NAN;
  out->lowest_cm = NAN;
  *clip_count = 0;
  fast[0] = '\0';
  if (smgi_blob_read(blob, size, 0, &gd, why, sizeof(why)) != SMG_OK)
    return 0;
  J = gd.joint_count;
  lt = gd.info->left_leg[3];
  rt = gd.info->right_leg[3];
  if (lt >= J || rt >= J) return 0;
  for (c = 0; c < gd.clip_count; ++c) total += gd.clips[c].frame_count;
  parents = (int32_t*)malloc(J * sizeof(int32_t));
  offsets = (float*)malloc(3 * J * sizeof(float));
  pose = (float*)malloc(SMGI_POSE_FLOATS(J) * sizeof(float));
  pos = (double*)malloc(3 * J * sizeof(double));
  toe = (double*)malloc(6 * total * sizeof(double));
  speed = (double*)malloc(2 * total * sizeof(double));
  all = (double*)malloc(2 * total * sizeof(double));
  if (!parents || !offsets || !pose || !pos || !toe || !speed || !all)
    goto done;
  for (i = 0; i < J; ++i) {
    parents[i] = gd.joints[i].parent;
    memcpy(offsets + 3 * i, gd.joints[i].offset, 3 * sizeof(float));
  }
  for (c = 0; c < gd.clip_count; ++c) {
    const smgi_clip* k = &gd.clips[c];
    const double* toes[2];
    eval_feet_geom g;
    uint32_t f;
    if (!(k->flags & SMGI_CLIP_LOWER) ||
        (k->flags & (SMGI_CLIP_MIRROR | SMGI_CLIP_BLEND)))
      continue;
    for (f = 0; f < k->frame_count; ++f) {
      smgi_pose_unpack(smgi_pose_record(&gd, k->first_frame + f), J, pose);
      em_fk(J, parents, offsets, pose, pos, NULL);
      memcpy(toe + 6 * f, pos + 3 * lt, 3 * sizeof(double));
      memcpy(toe + 6 * f + 3, pos + 3 * rt, 3 * sizeof(double));
    }
    toes[0] = toe;
    toes[1] = toe + 3;
    if (eval_feet_geom_measure(toes, 2, 6, k->frame_count,
                               1.0 / gd.info->frame_rate, speed, &g) != 0)
      goto done;
    for (f = 0; f < 2 * k->frame_count; ++f)
      if (isfinite(speed[f])) {
        all[m++] = speed[f];
        sum += speed[f];
      }
    /* which clips have them: "N: clip n, clip n", the first
     * FAST_LISTED clips by name, the rest counted (a line stays short) */
    {
      size_t nf = count_fast(speed, 2 * (size_t)k->frame_count), len;
      len = strlen(fast);
      if (nf && listed < FAST_LISTED && len + 1 < fast_size) {
        snprintf(fast + len, fast_size - len, "%s%s %zu",
                 len ? ", " : "", gd.strings + k->name, nf);
        ++listed;
      } else if (nf) {
        ++unlisted;
      }
    }
    if (g.lowest_cm < lowest) lowest = g.lowest_cm;
    out->frames += k->frame_count;
    ++*clip_count;
  }
  out->planted_pairs = m;
  if (unlisted) {
    size_t len = strlen(fast);
    snprintf(fast + len, fast_size - len, ", %u more clip%s", unlisted,
             unlisted == 1 ? "" : "s");
  }
  {
    /* the total first, then the clips listed above */
    char total[32];
    size_t tl = (size_t)snprintf(total, sizeof(total), "%zu%s",
                                 count_fast(all, m), fast[0] ? ": " : "");
    size_t len = strlen(fast);
    if (len + tl >= fast_size) len = fast_size - tl - 1;
    memmove(fast + tl, fast, len);
    fast[tl + len] = '\0';
    memcpy(fast, total, tl);
  }
  if (isfinite(lowest)) out->lowest_cm = lowest;
  if (m) {
    double* scratch = speed; /* big enough: 2 * total */
    em_stats st;
    em_stats_compute(all, m, scratch, &st);
    out->mean_cms = sum / (double)m;
    out->p95_cms = em_percentile_sorted(scratch, m, 95.0);
    out->p99_cms = st.p99;
    out->max_cms = st.max;
  }
  ok = 1;
done:
  free(parents);
  free(offsets);
  free(pose);
  free(pos);
  free(toe);
  free(speed);
  free(all);
  return ok;
}

/* A graph of two CMU clips: `lower` (walk) and `other`, a second walk
 * (role LOWER) or an action `label` (role UPPER). The first clip's
 * skeleton is the target. */
static smg_result bake_pair(const eval_ctx* ctx, const char* lower,
                            const char* other, uint32_t role,
                            const char* label, uint32_t mirror,
                            smg_bake_result* out, char* err,
                            size_t err_size) {
  smg_bake_clip_desc clips[2];
  smg_bake_desc desc;
  char p0[1200], p1[1200];
  smg_result r;
  int c;
  eval_cmu_clip(ctx, lower, p0, sizeof(p0));
  eval_cmu_clip(ctx, other, p1, sizeof(p1));
  memset(clips, 0, sizeof(clips));
  for (c = 0; c < 2; ++c) {
    clips[c].struct_size = sizeof(clips[c]);
    clips[c].skip_first_frame = 1;
    clips[c].unit_scale = CMU_UNIT;
    clips[c].mirror = mirror;
  }
  clips[0].role = SMG_BAKE_ROLE_LOWER;
  clips[0].label = "walk";
  clips[0].path = p0;
  clips[0].name = lower;
  clips[1].role = role;
  clips[1].label = label;
  clips[1].path = p1;
  clips[1].name = other;
  memset(&desc, 0, sizeof(desc));
  desc.struct_size = sizeof(desc);
  desc.clip_count = 2;
  desc.clips = clips;
  desc.options.struct_size = sizeof(desc.options);
  memset(out, 0, sizeof(*out));
  out->struct_size = sizeof(*out);
  r = smg_bake_run(&desc, out);
  if (r != SMG_OK)
    snprintf(err, err_size, "bake: %s: %.400s", smg_result_string(r),
             out->error);
  return r;
}

/* Appends every clip of the manifest at `path` (clips in `dir`) to `mix`
 * (whose root is the current folder, where those clip paths resolve). */
static smg_result add_manifest(smgb_manifest* mix, const char* path,
                               const char* dir, char* err, size_t err_size) {
  smgb_manifest m;
  smgb_error e;
  smg_result r;
  uint32_t i;
  memset(&e, 0, sizeof(e));
  r = smgb_manifest_load(path, dir, &m, &e);
  if (r == SMG_OK) {
    if (mix->clip_count == 0) mix->frame_rate = m.frame_rate;
    for (i = 0; i < m.clip_count && r == SMG_OK; ++i)
      r = smgb_manifest_add(mix, &m.clips[i], m.clips[i].path, 0, &e);
    smgb_manifest_free(&m);
  }
  if (r != SMG_OK) snprintf(err, err_size, "%s: %.400s", path, e.message);
  return r;
}

/* The Bandai Namco set (the Bandai manifest) on its own skeleton, or after
 * the CMU paper set, all on the CMU skeleton (its first clip's). */
static smg_result bake_bandai(const eval_ctx* ctx, int after_cmu,
                              smg_bake_result* out, char* err,
                              size_t err_size) {
  smgb_manifest mix;
  smg_result r;
  memset(out, 0, sizeof(*out));
  out->struct_size = sizeof(*out);
  r = smgb_manifest_init(&mix, NULL);
  if (r != SMG_OK) {
    snprintf(err, err_size, "manifest: %s", smg_result_string(r));
    return r;
  }
  if (after_cmu)
    r = add_manifest(&mix, ctx->manifest, ctx->cmu_dir, err, err_size);
  if (r == SMG_OK)
    r = add_manifest(&mix, ctx->bandai_manifest, ctx->bandai_dir, err,
                     err_size);
  if (r == SMG_OK) {
    r = eval_bake_manifest(&mix, 0, out);
    if (r != SMG_OK)
      snprintf(err, err_size, "bake: %s: %.400s", smg_result_string(r),
               out->error);
  }
  smgb_manifest_free(&mix);
  return r;
}

typedef struct feet_graph {
  const char* name;
  const void* blob;
  size_t size;
  int with_constraints; /* section 2's walk/run/punch constraints */
  const char* splice;   /* else: this action spliced on at 0.15 L */
} feet_graph;

static void row(eval_ctx* ctx, const char* graph, const char* what,
                const char* ik, const eval_feet_geom* g, const em_skate* s,
                const char* fast) {
  char a[32], b[32], c[32], d[32], e[32];
  eval_md(ctx, "| %s | %s | %s | %s | %s / %s / %s | %zu | %s | %s |\n",
          graph, what, ik,
          s ? eval_fmt(a, sizeof(a), "%.2f", s->mean_cm) : "-",
          eval_fmt(b, sizeof(b), "%.1f", g->mean_cms),
          eval_fmt(c, sizeof(c), "%.1f", g->p95_cms),
          eval_fmt(d, sizeof(d), "%.1f", g->p99_cms), g->planted_pairs,
          fast, eval_fmt(e, sizeof(e), "%.1f", g->lowest_cm));
}


static void figure(eval_ctx* ctx, const feet_run* on, const feet_run* off) {
  svp_figure* fig;
  double *x = NULL, *yon = NULL, *yoff = NULL;
  size_t n = on->frames > off->frames ? on->frames : off->frames, i;
  char file[1200];
  if (!ctx->img_dir || !n) return;
  x = (double*)malloc(n * sizeof(double));
  yon = (double*)malloc(n * sizeof(double));
  yoff = (double*)malloc(n * sizeof(double));
  fig = svp_create(760, 300,
                   "Planted-toe speed, CMU graph, straight path (both toes)");
  if (x && yon && yoff && fig) {
    const feet_run* runs[2] = {off, on};
    double* ys[2] = {yoff, yon};
    int r;
    for (r = 0; r < 2; ++r)
      for (i = 0; i < n; ++i) {
        double a = NAN, b = NAN;
        x[i] = (double)i / RATE;
        if (i < runs[r]->frames) {
          a = runs[r]->speed[2 * i];
          b = runs[r]->speed[2 * i + 1];
        }
        /* the faster planted toe of the frame (NaN: none planted) */
        ys[r][i] = isnan(a) ? b : (isnan(b) ? a : (a > b ? a : b));
      }
    svp_set_labels(fig, "time (s)", "planted-toe speed (cm/s)");
    svp_scatter(fig, x, yoff, n, SVP_CIRCLE, "#999999", 2.0, "IK off");
    svp_scatter(fig, x, yon, n, SVP_CIRCLE, "#1f5fd6", 2.0, "IK on");
    eval_img_path(ctx, "eval-feet-speed.svg", file, sizeof(file));
    svp_write(fig, file);
    eval_md(ctx, "\n![planted-toe speed over time](%s/eval-feet-speed.svg)\n",
            ctx->img_rel);
  }
  svp_destroy(fig);
  free(x);
  free(yon);
  free(yoff);
}

/* Section 2's constraints at fractions of the path length. */
static uint32_t constraints(smg_graph* g, double len, eval_constraint* c) {
  uint32_t walk = 0, run = 0, punch = 0;
  if (smg_graph_find_style(g, "walk", &walk) != SMG_OK ||
      smg_graph_find_style(g, "run", &run) != SMG_OK ||
      smg_graph_find_action(g, "punch", &punch) != SMG_OK)
    return 0;
  c[0].kind = EVAL_KIND_SPLICE, c[0].arc = (float)(0.15 * len),
  c[0].value = punch;
  c[1].kind = EVAL_KIND_TRANSITION, c[1].arc = (float)(0.35 * len),
  c[1].value = run;
  c[2].kind = EVAL_KIND_SPLICE, c[2].arc = (float)(0.55 * len),
  c[2].value = 0;
  c[3].kind = EVAL_KIND_TRANSITION, c[3].arc = (float)(0.75 * len),
  c[3].value = walk;
  return 4;
}

/* Runs every path of one graph with IK on and off; writes the rows and,
 * in check mode, compares IK on against IK off. */
static void range(double r[2], double v) {
  if (v < r[0]) r[0] = v;
  if (v > r[1]) r[1] = v;
}

static void feet_graph_run(eval_ctx* ctx, const feet_graph* fg) {
  smg_graph* g = NULL;
  feet_joints j;
  eval_feet_geom src;
  uint32_t nsrc, walk = 0;
  size_t p, fast_on = 0, fast_both = 0;
  char fast[192], src_fast[320] = "";
  /* ranges over the paths for the summary: [IK on, IK off] x [lo, hi] */
  double mean_r[2][2] = {{INFINITY, -INFINITY}, {INFINITY, -INFINITY}};
  double p99_r[2][2] = {{INFINITY, -INFINITY}, {INFINITY, -INFINITY}};
  if (smg_graph_load_memory(fg->blob, fg->size, NULL, &g) != SMG_OK ||
      !find_feet(fg->blob, fg->size, &j)) {
    eval_md(ctx, "| %s | Not produced: the blob does not load or lacks the "
                 "foot joints | | | | | |\n", fg->name);
    if (g) smg_graph_destroy(g);
    return;
  }
  smg_graph_find_style(g, "walk", &walk);
  src.mean_cms = src.p99_cms = NAN;
  if (source_clips(fg->blob, fg->size, &src, &nsrc, src_fast,
                   sizeof(src_fast))) {
    char what[64];
    snprintf(what, sizeof(what), "source clips (%u, as baked)", nsrc);
    row(ctx, fg->name, what, "-", &src, NULL, src_fast);
  }
  for (p = 0; p < PATH_COUNT && (!ctx->quick || p < 2); ++p) {
    static double xz[2 * MAX_PATH_POINTS];
    static float path[2 * MAX_PATH_POINTS];
    eval_constraint cons[4];
    feet_run on, off;
    size_t n = build_path(&k_paths[p], xz, MAX_PATH_POINTS), i;
    uint32_t nc = 0;
    for (i = 0; i < 2 * n; ++i) path[i] = (float)xz[i];
    if (fg->with_constraints)
      nc = constraints(g, em_polyline_length(xz, n), cons);
    else if (fg->splice &&
             smg_graph_find_action(g, fg->splice, &cons[0].value) == SMG_OK) {
      cons[0].kind = EVAL_KIND_SPLICE;
      cons[0].arc = (float)(0.15 * em_polyline_length(xz, n));
      nc = 1;
    }
    run_one(g, &j, path, (uint32_t)n, cons, nc, walk, 0, &on);
    run_one(g, &j, path, (uint32_t)n, cons, nc, walk, SMG_CHARACTER_NO_IK,
            &off);
    if (!on.ok || !off.ok) {
      eval_md(ctx, "| %s | %s | Not produced: %s | | | | | |\n", fg->name,
              k_paths[p].title, on.ok ? off.error : on.error);
    } else {
      size_t n_on = count_fast(on.speed, 2 * on.frames), both = 0;
      for (i = 0; i < 2 * on.frames && i < 2 * off.frames; ++i)
        if (on.speed[i] > FAST_CMS && off.any_speed[i] > FAST_CMS) ++both;
      fast_on += n_on;
      fast_both += both;
      snprintf(fast, sizeof(fast), "%zu (%zu)", n_on, both);
      row(ctx, fg->name, k_paths[p].title, "on", &on.geom, &on.flag_skate,
          fast);
      snprintf(fast, sizeof(fast), "%zu",
               count_fast(off.speed, 2 * off.frames));
      row(ctx, fg->name, k_paths[p].title, "off", &off.geom, &off.flag_skate,
          fast);
      range(mean_r[0], on.geom.mean_cms);
      range(mean_r[1], off.geom.mean_cms);
      range(p99_r[0], on.geom.p99_cms);
      range(p99_r[1], off.geom.p99_cms);
      eval_check(ctx, on.geom.mean_cms <= off.geom.mean_cms,
                 "%s, %s: planted-toe speed with IK mean %.1f cm/s (p99 "
                 "%.1f), without %.1f (p99 %.1f); bound: mean with IK not "
                 "above without", fg->name, k_paths[p].title,
                 on.geom.mean_cms, on.geom.p99_cms, off.geom.mean_cms,
                 off.geom.p99_cms);
      eval_check(ctx, both == n_on,
                 "%s, %s: %zu planted pairs over %.0f cm/s with IK, %zu of "
                 "them as fast without IK; bound: IK adds none", fg->name,
                 k_paths[p].title, n_on, FAST_CMS, both);
      eval_check(ctx, fabs(on.geom.lowest_cm - off.geom.lowest_cm) <= 1.0,
                 "%s, %s: lowest toe %.1f cm with IK, %.1f without "
                 "(bound 1 cm apart)", fg->name, k_paths[p].title,
                 on.geom.lowest_cm, off.geom.lowest_cm);
    }
    free(on.speed);
    free(off.speed);
    free(on.any_speed);
    free(off.any_speed);
  }
  if (mean_r[0][0] <= mean_r[0][1])
    eval_summary(ctx,
                 "**Feet from geometry**, %s: planted-toe speed with foot IK "
                 "mean %.1f-%.1f cm/s, p99 %.0f-%.0f per path; without IK "
                 "%.1f-%.1f, p99 %.0f-%.0f; the source clips %.1f, p99 %.0f. "
                 "Planted pairs faster than %.0f cm/s with IK, all paths: "
                 "%zu, of which the toe moves as fast at the same frame "
                 "without IK in %zu (the animation's own swing); in the "
                 "source clips %s.",
                 fg->name, mean_r[0][0], mean_r[0][1], p99_r[0][0],
                 p99_r[0][1], mean_r[1][0], mean_r[1][1], p99_r[1][0],
                 p99_r[1][1], src.mean_cms, src.p99_cms, FAST_CMS, fast_on,
                 fast_both, src_fast);
  smg_graph_destroy(g);
}

/* The figure: the CMU graph's straight path again (runs are
 * deterministic), IK on and off. */
static void draw_straight(eval_ctx* ctx, const void* blob, size_t size) {
  static double xz[2 * MAX_PATH_POINTS];
  static float path[2 * MAX_PATH_POINTS];
  smg_graph* g = NULL;
  feet_joints j;
  eval_constraint cons[4];
  feet_run on, off;
  uint32_t walk = 0, nc;
  size_t n = build_path(&k_paths[0], xz, MAX_PATH_POINTS), i;
  if (smg_graph_load_memory(blob, size, NULL, &g) != SMG_OK) return;
  if (find_feet(blob, size, &j)) {
    smg_graph_find_style(g, "walk", &walk);
    for (i = 0; i < 2 * n; ++i) path[i] = (float)xz[i];
    nc = constraints(g, em_polyline_length(xz, n), cons);
    run_one(g, &j, path, (uint32_t)n, cons, nc, walk, 0, &on);
    run_one(g, &j, path, (uint32_t)n, cons, nc, walk, SMG_CHARACTER_NO_IK,
            &off);
    if (on.ok && off.ok) figure(ctx, &on, &off);
    free(on.speed);
    free(off.speed);
    free(on.any_speed);
    free(off.any_speed);
  }
  smg_graph_destroy(g);
}

static void table_head(eval_ctx* ctx) {
  eval_md(ctx, "| Graph | path / data | IK | flag-based skate (cm/frame) | "
               "planted-toe speed mean / p95 / p99 (cm/s) | planted pairs | "
               "pairs over %.0f cm/s (IK on: of which the toe moves as fast "
               "at that frame without IK) | lowest toe (cm) |\n"
               "|---|---|---|---:|---:|---:|---:|---:|\n", FAST_CMS);
}

void eval_section_feet(eval_ctx* ctx, const void* blob, size_t size) {
  smg_bake_result mixed, dribble;
  char err[512];
  feet_graph fg;
  int have_mixed = 0, have_dribble = 0;
  eval_md(ctx,
          "## 2b. Feet from geometry\n\n"
          "How still the toes are while they are on the floor, measured from "
          "the exported toe positions only (no contact flags; "
          "[evaluation.md](evaluation.md), section 2b): a toe is "
          "planted over two consecutive frames when it is within %.1f cm of "
          "its floor level (the %.0fth percentile of its height over the "
          "run) in both; planted-toe speed = its horizontal displacement / "
          "dt. Every path of section 2, foot IK on and off; the flag-based "
          "skate of section 2 beside it; the graph's own source clips (as "
          "baked, i.e. retargeted) as the reference.\n\n",
          100.0 * EVAL_FEET_PLANT_BAND_M, EVAL_FEET_FLOOR_PERCENTILE);
  if (!ctx->have_cmu) {
    eval_md(ctx, "Not produced: the CMU clips were not found.\n\n");
    if (ctx->check) printf("SKIP CMU feet from geometry: no clips\n");
    return;
  }
  table_head(ctx);
  if (blob) {
    fg.name = "CMU paper set";
    fg.blob = blob;
    fg.size = size;
    fg.with_constraints = 1;
    fg.splice = NULL;
    feet_graph_run(ctx, &fg);
  }
  fg.splice = NULL;
  if (bake_pair(ctx, "02_01", "06_01", SMG_BAKE_ROLE_LOWER, "walk",
                SMG_BAKE_MIRROR_DEFAULT, &mixed, err,
                sizeof(err)) == SMG_OK) {
    have_mixed = 1;
    fg.name = "02_01 + 06_01 (two performers)";
    fg.blob = mixed.blob;
    fg.size = mixed.blob_size;
    fg.with_constraints = 0;
    feet_graph_run(ctx, &fg);
  } else {
    eval_md(ctx, "\nTwo-performer graph not produced: %s\n", err);
    eval_check(ctx, 0, "two-performer bake: %s", err);
  }
  /* the splice test's graph (section 3), dribbling from 0.15 L on */
  if (!ctx->quick &&
      bake_pair(ctx, "06_01", "06_10", SMG_BAKE_ROLE_UPPER, "dribble",
                SMG_BAKE_MIRROR_NO, &dribble, err, sizeof(err)) == SMG_OK) {
    have_dribble = 1;
    fg.name = "06_01 + 06_10 dribble (section 3)";
    fg.blob = dribble.blob;
    fg.size = dribble.blob_size;
    fg.with_constraints = 0;
    fg.splice = "dribble";
    feet_graph_run(ctx, &fg);
  } else if (!ctx->quick) {
    eval_md(ctx, "\nDribble graph not produced: %s\n", err);
  }
  /* issue 14's (a) and (b): another studio's performer and skeleton */
  if (!ctx->quick && !ctx->have_bandai) {
    eval_md(ctx, "\nBandai Namco graphs not produced: the clips are not "
                 "at `%s`.\n", ctx->bandai_dir);
  } else if (!ctx->quick) {
    static const char* const names[2] = {
        "Bandai Namco (own skeleton)",
        "CMU paper set + Bandai Namco (CMU skeleton)"};
    int k;
    for (k = 0; k < 2; ++k) {
      smg_bake_result bn;
      if (bake_bandai(ctx, k, &bn, err, sizeof(err)) == SMG_OK) {
        fg.name = names[k];
        fg.blob = bn.blob;
        fg.size = bn.blob_size;
        fg.with_constraints = 0;
        fg.splice = NULL;
        feet_graph_run(ctx, &fg);
      } else {
        eval_md(ctx, "\n%s graph not produced: %s\n", names[k], err);
      }
      smg_bake_result_free(&bn);
    }
  }
  eval_md(ctx, "\n");
  if (have_mixed) smg_bake_result_free(&mixed);
  if (have_dribble) smg_bake_result_free(&dribble);
  if (blob && !ctx->check) {
    draw_straight(ctx, blob, size);
    eval_figure_swing(ctx, blob, size);
  }
}
