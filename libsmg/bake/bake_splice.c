/*
 * bake_splice.c - splice candidates (the paper, III.B.2).
 *
 * Between locomotion frames l (original frames on lower-graph edges) and
 * action frames u (original frames on upper-graph edges) the window
 * distance compares their upper-body segment COGs, each expressed in its
 * own root ground frame (no alignment: the runtime places the action's
 * upper body on the locomotion's pelvis as it is). Its local minima are
 * the candidates; they are found from each locomotion window's nearest
 * windows of every action (bake_pair_search.h), so the cost grows with
 * the frames, not with their product. Lower frames are grouped into regions of
 * splice_region_seconds; per (region, action) the best candidate is always
 * kept (so every action can be entered within about a region of any
 * locomotion frame) and up to splices_per_region - 1 more if they are
 * below the action's splice_percentile.
 *
 * At each candidate, Horn's method (bake_horn.c) fits the rotation that
 * takes the action's torso points (spine chain, neck, head, shoulders;
 * relative to the spine base, in the action's pelvis frame) onto the
 * locomotion's, over the window. The runtime applies it at the spine base:
 *   local'(spine_base) = correction * local_action(spine_base)
 * which is right because the spine base's parent is the pelvis (root).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_horn.h"
#include "bake_pointcloud.h"
#include "bake_splice.h"
#include "bake_upper.h"
#include "bake_math.h"
#include "bake_pair_search.h"

/* Start cells per locomotion window and action for the minimum search
 * (bake_pair_search.h). */
#define SMGB_SPLICE_NEIGHBOURS 8u
/* Below this many grid cells (locomotion x action frames) the full grid
 * is used: exact, and quicker than the search at that size. */
#define SMGB_SPLICE_EXACT_CELLS 50000000ull

typedef struct scand {
  smgb_minimum m;
  uint32_t region, action;
} scand;

static int scand_cmp(const void* pa, const void* pb) {
  const scand* a = pa;
  const scand* b = pb;
  if (a->region != b->region) return a->region < b->region ? -1 : 1;
  if (a->action != b->action) return a->action < b->action ? -1 : 1;
  if (a->m.dist != b->m.dist) return a->m.dist < b->m.dist ? -1 : 1;
  if (a->m.i != b->m.i) return a->m.i < b->m.i ? -1 : 1;
  if (a->m.j != b->m.j) return a->m.j < b->m.j ? -1 : 1;
  return 0;
}

static int splice_cmp(const void* pa, const void* pb) {
  const smgb_splice* a = pa;
  const smgb_splice* b = pb;
  if (a->lower_frame != b->lower_frame)
    return a->lower_frame < b->lower_frame ? -1 : 1;
  if (a->action != b->action) return a->action < b->action ? -1 : 1;
  if (a->distance != b->distance) return a->distance < b->distance ? -1 : 1;
  if (a->upper_edge != b->upper_edge)
    return a->upper_edge < b->upper_edge ? -1 : 1;
  if (a->upper_offset != b->upper_offset)
    return a->upper_offset < b->upper_offset ? -1 : 1;
  return 0;
}

static int float_cmp(const void* pa, const void* pb) {
  float a = *(const float*)pa, b = *(const float*)pb;
  return a < b ? -1 : a > b ? 1 : 0;
}

/* Torso points of pool frame f relative to the spine base, in the pelvis
 * frame. */
static void torso_points(const smgb_bake* b, uint32_t f, double* out) {
  const float* P = b->positions + (size_t)f * 3u * b->J;
  const float* pose = b->poses + (size_t)f * b->stride;
  const float* sb = P + 3u * b->body.spine_base;
  double q[4], qi[4];
  uint32_t i;
  q[0] = pose[3]; q[1] = pose[4]; q[2] = pose[5]; q[3] = pose[6];
  smgb_q_normalize(q);
  smgb_q_conj(q, qi);
  for (i = 0; i < b->body.torso_point_count; ++i) {
    const float* p = P + 3u * b->body.torso_points[i];
    double v[3];
    v[0] = p[0] - sb[0];
    v[1] = p[1] - sb[1];
    v[2] = p[2] - sb[2];
    smgb_q_rotate(qi, v, out + 3 * i);
  }
}

/* Pelvis rotation of pool frame f relative to its ground frame (heading
 * removed): the tilt and twist the pelvis has at that moment of its gait. */
static void pelvis_in_ground(const smgb_bake* b, uint32_t f, double q[4]) {
  const float* pose = b->poses + (size_t)f * b->stride;
  double r[4], y[4];
  r[0] = pose[3]; r[1] = pose[4]; r[2] = pose[5]; r[3] = pose[6];
  smgb_q_normalize(r);
  smgb_q_yaw(-(double)b->frames[f].root2d[2], y);
  smgb_q_mul(y, r, q);
}

/* The correction turns the action's upper body about the pelvis's up axis
 * so that it faces, relative to the locomotion's direction of travel,
 * where it faced in the action; its bend relative to the pelvis stays the
 * action's own.
 *
 * Horn's method fits the rotation that keeps the action's torso where the
 * action had it relative to the ground on a pelvis that tilts and twists
 * like the locomotion's: per window frame t the action's torso points a_t
 * (spine base frame, in the action's pelvis frame) should appear in the
 * locomotion's pelvis frame as
 *   b_t = pelvis_loco(t)^-1 * pelvis_action(t) * a_t
 * (pelvis rotations relative to their ground frames). Of that rotation
 * only the twist about the locomotion pelvis's mean up axis is kept: the
 * swing part would carry the action's pelvis tilt into the spine, and a
 * performer keeps the spine's posture relative to the pelvis, not to the
 * ground (on the CMU 06_01 walk + 06_10 dribble test against the original
 * dribble, pelvis frame: the whole fit is 3.5 cm mean off, the twist 0.1 cm;
 * fitting the action's torso onto the locomotion's own torso, as before,
 * was 3.7 cm: it bent the action's posture into the walk's). */
static void fit_correction(const smgb_bake* b, uint32_t lf, uint32_t uf,
                           double q[4], double* a, double* l) {
  uint32_t k = b->opt.window, T = b->body.torso_point_count, t, i;
  double up[3] = {0.0, 0.0, 0.0}, y[3] = {0.0, 1.0, 0.0}, n, d;
  for (t = 0; t < k; ++t) {
    double pl[4], pa[4], pli[4], rel[4];
    double* at = a + (size_t)t * T * 3u;
    double* bt = l + (size_t)t * T * 3u;
    torso_points(b, uf + t, at);
    pelvis_in_ground(b, lf + t, pl);
    pelvis_in_ground(b, uf + t, pa);
    smgb_q_conj(pl, pli);
    smgb_q_mul(pli, pa, rel);
    for (i = 0; i < T; ++i) smgb_q_rotate(rel, at + 3u * i, bt + 3u * i);
  }
  smgb_horn(a, l, NULL, k * T, q);
  /* keep the twist about the locomotion pelvis's mean up axis */
  for (t = 0; t < k; ++t) {
    double pl[4], pli[4], u[3];
    pelvis_in_ground(b, lf + t, pl);
    smgb_q_conj(pl, pli);
    smgb_q_rotate(pli, y, u);
    up[0] += u[0];
    up[1] += u[1];
    up[2] += u[2];
  }
  n = sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  if (!(n > 1e-9)) return; /* cannot happen for unit rotations */
  d = (q[0] * up[0] + q[1] * up[1] + q[2] * up[2]) / (n * n);
  q[0] = d * up[0];
  q[1] = d * up[1];
  q[2] = d * up[2];
  smgb_q_normalize(q);
}

smg_result smgb_find_splices(smgb_bake* b) {
  uint32_t k = b->opt.window, P = b->body.upper_segment_count;
  uint32_t FL = 0, FU = 0, c, f, e, i, nmin = 0, nkept = 0;
  uint32_t region_frames, regions = 0;
  uint32_t *map_l = NULL, *map_u = NULL, *uedge = NULL, *uoff = NULL;
  uint32_t* region_of = NULL;
  uint8_t *on_lower = NULL, *vl = NULL, *vu = NULL;
  double *xl = NULL, *xu = NULL, *w = NULL, *ta = NULL, *tl = NULL;
  smgb_minimum* mins = NULL;
  scand* cands = NULL;
  float* thr = NULL;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  smgb_cloud L, U;
  smgb_pair_search job;
  uint32_t* action_of = NULL;

  b->splice_count = 0;
  b->splice_coverage = 0.0f;
  b->splice_max_gap = 0.0f;
  if (b->upper.edge_count == 0 || b->lower.edge_count == 0) return SMG_OK;
  region_frames = (uint32_t)lround(b->opt.splice_region_seconds *
                                   b->opt.frame_rate);
  if (region_frames < 1) region_frames = 1;

  on_lower = calloc(b->frame_count, 1);
  uedge = malloc(b->frame_count * sizeof *uedge);
  uoff = malloc(b->frame_count * sizeof *uoff);
  if (!on_lower || !uedge || !uoff) goto oom;
  for (f = 0; f < b->frame_count; ++f) uedge[f] = SMGI_NONE;
  for (e = 0; e < b->lower.edge_count; ++e) {
    const smgb_edge* ed = &b->lower.edges[e];
    if (ed->kind != SMGB_EDGE_ORIGINAL) continue;
    memset(on_lower + ed->first_frame, 1, ed->frame_count);
  }
  for (e = 0; e < b->upper.edge_count; ++e) {
    const smgb_edge* ed = &b->upper.edges[e];
    if (ed->kind != SMGB_EDGE_ORIGINAL) continue;
    for (f = 0; f < ed->frame_count; ++f) {
      uedge[ed->first_frame + f] = e;
      uoff[ed->first_frame + f] = f;
    }
  }
  for (c = 0; c < b->clip_count; ++c) {
    if (b->clips[c].flags & SMGI_CLIP_BLEND) continue;
    if (b->clips[c].flags & SMGI_CLIP_LOWER) FL += b->clips[c].count;
    if (b->clips[c].flags & SMGI_CLIP_UPPER) FU += b->clips[c].count;
  }
  map_l = malloc(FL * sizeof *map_l);
  region_of = malloc(FL * sizeof *region_of);
  map_u = malloc(FU * sizeof *map_u);
  vl = malloc(FL);
  vu = malloc(FU);
  xl = malloc((size_t)FL * P * 3u * sizeof *xl);
  xu = malloc((size_t)FU * P * 3u * sizeof *xu);
  w = malloc(P * sizeof *w);
  ta = malloc((size_t)k * b->body.torso_point_count * 3u * sizeof *ta);
  tl = malloc((size_t)k * b->body.torso_point_count * 3u * sizeof *tl);
  thr = malloc(b->action_count * sizeof *thr);
  action_of = malloc((FU ? FU : 1) * sizeof *action_of);
  if (!map_l || !region_of || !map_u || !vl || !vu || !xl || !xu || !w ||
      !ta || !tl || !thr || !action_of)
    goto oom;
  FL = FU = 0;
  for (c = 0; c < b->clip_count; ++c) {
    const smgb_pool_clip* pc = &b->clips[c];
    if (pc->flags & SMGI_CLIP_BLEND) continue;
    for (f = 0; f < pc->count; ++f) {
      uint32_t pf = pc->first + f;
      if (pc->flags & SMGI_CLIP_LOWER) {
        map_l[FL] = pf;
        region_of[FL] = regions + f / region_frames;
        vl[FL] = f + k <= pc->count && on_lower[pf];
        smgb_upper_cogs(b, pf, xl + (size_t)FL * P * 3u);
        ++FL;
      } else if (pc->flags & SMGI_CLIP_UPPER) {
        map_u[FU] = pf;
        action_of[FU] = pc->label;
        vu[FU] = f + k <= pc->count && uedge[pf] != SMGI_NONE;
        smgb_upper_cogs(b, pf, xu + (size_t)FU * P * 3u);
        ++FU;
      }
    }
    if (pc->flags & SMGI_CLIP_LOWER)
      regions += (pc->count + region_frames - 1) / region_frames;
  }
  smgb_upper_weights(b, w);
  L.frames = FL; L.points = P; L.xyz = xl; L.weights = w; L.valid = vl;
  U.frames = FU; U.points = P; U.xyz = xu; U.weights = w; U.valid = vu;
  memset(&job, 0, sizeof job);
  job.rows = &L;
  job.cols = &U;
  job.window = k;
  job.align = 0;
  job.col_group = action_of; /* every action gets its nearest windows */
  job.group_count = b->action_count;
  job.neighbours = SMGB_SPLICE_NEIGHBOURS;
  job.threads = b->opt.threads;
  job.report = &b->report;
  if ((uint64_t)FL * FU <= SMGB_SPLICE_EXACT_CELLS) {
    /* small sets: every minimum of the full grid */
    smgb_grid_job grid;
    memset(&grid, 0, sizeof grid);
    grid.rows = &L;
    grid.cols = &U;
    grid.window = k;
    grid.align = 0;
    grid.threads = b->opt.threads;
    grid.report = &b->report;
    r = smgb_grid_minima(&grid, &mins, &nmin);
  } else {
    r = smgb_pair_search_minima(&job, &mins, &nmin);
  }
  if (r != SMG_OK) {
    smgb_fail(&b->report, "splice search: distance grid failed (%s)",
              smg_result_string(r));
    goto done;
  }
  r = SMG_ERROR_OUT_OF_MEMORY;
  cands = malloc((nmin ? nmin : 1) * sizeof *cands);
  if (!cands) goto oom;
  for (i = 0; i < nmin; ++i) {
    cands[i].m = mins[i];
    cands[i].region = region_of[mins[i].i];
    cands[i].action = b->clips[b->frames[map_u[mins[i].j]].clip].label;
  }
  /* per-action percentile threshold */
  {
    float* d = malloc((nmin ? nmin : 1) * sizeof *d);
    uint32_t a;
    if (!d) goto oom;
    for (a = 0; a < b->action_count; ++a) {
      uint32_t n = 0;
      for (i = 0; i < nmin; ++i)
        if (cands[i].action == a) d[n++] = cands[i].m.dist;
      thr[a] = 0.0f;
      if (n) {
        uint32_t at;
        qsort(d, n, sizeof *d, float_cmp);
        at = (uint32_t)floor((n - 1) * (double)b->opt.splice_percentile /
                             100.0);
        thr[a] = d[at];
      }
    }
    free(d);
  }
  qsort(cands, nmin, sizeof *cands, scand_cmp);
  for (i = 0; i < nmin;) {
    uint32_t g = i, t;
    while (g < nmin && cands[g].region == cands[i].region &&
           cands[g].action == cands[i].action)
      ++g;
    for (t = i; t < g && t - i < b->opt.splices_per_region; ++t) {
      if (t > i && cands[t].m.dist > thr[cands[t].action]) break;
      cands[nkept++] = cands[t];
    }
    i = g;
  }
  free(b->splices);
  b->splices = malloc((nkept ? nkept : 1) * sizeof *b->splices);
  if (!b->splices) goto oom;
  b->splice_cap = nkept;
  for (i = 0; i < nkept; ++i) {
    smgb_splice* s = &b->splices[i];
    uint32_t lf = map_l[cands[i].m.i], uf = map_u[cands[i].m.j];
    memset(s, 0, sizeof *s);
    s->lower_frame = lf;
    s->upper_frame = uf;
    s->action = cands[i].action;
    s->upper_edge = uedge[uf];
    s->upper_offset = uoff[uf];
    s->distance = cands[i].m.dist;
    fit_correction(b, lf, uf, s->correction, ta, tl);
    if ((i & 63u) == 0) smgb_progress(&b->report, 0.9f + 0.1f * i / (nkept + 1));
  }
  b->splice_count = nkept;
  qsort(b->splices, nkept, sizeof *b->splices, splice_cmp);

  /* coverage: for each lower frame on an edge, the distance (same clip) to
   * the nearest candidate of every action */
  {
    uint32_t covered = 0, total = 0, a, maxgap = 0, s0 = 0, s1;
    uint32_t* near = malloc(b->frame_count * sizeof *near);
    if (!near) goto oom;
    for (f = 0; f < b->frame_count; ++f) near[f] = 0;
    for (c = 0; c < b->clip_count; ++c) {
      const smgb_pool_clip* pc = &b->clips[c];
      if (!(pc->flags & SMGI_CLIP_LOWER) || (pc->flags & SMGI_CLIP_BLEND))
        continue;
      for (f = pc->first; f < pc->first + pc->count; ++f) near[f] = 0;
      /* splices are sorted by lower frame: the clip's own are one run */
      while (s0 < b->splice_count &&
             b->splices[s0].lower_frame < pc->first)
        ++s0;
      s1 = s0;
      while (s1 < b->splice_count &&
             b->splices[s1].lower_frame < pc->first + pc->count)
        ++s1;
      for (a = 1; a < b->action_count; ++a) {
        /* two sweeps over the clip: distance to the previous / next
         * candidate of action a */
        uint32_t last = SMGI_NONE, s;
        uint32_t* dist = malloc(pc->count * sizeof *dist);
        if (!dist) { free(near); goto oom; }
        for (f = 0; f < pc->count; ++f) dist[f] = UINT32_MAX;
        for (s = s0; s < s1; ++s)
          if (b->splices[s].action == a)
            dist[b->splices[s].lower_frame - pc->first] = 0;
        for (f = 0; f < pc->count; ++f) {
          if (dist[f] == 0) last = f;
          if (last != SMGI_NONE && f - last < dist[f]) dist[f] = f - last;
        }
        last = SMGI_NONE;
        for (f = pc->count; f-- > 0;) {
          if (dist[f] == 0) last = f;
          if (last != SMGI_NONE && last - f < dist[f]) dist[f] = last - f;
        }
        for (f = 0; f < pc->count; ++f)
          if (dist[f] > near[pc->first + f]) near[pc->first + f] = dist[f];
        free(dist);
      }
      for (f = pc->first; f < pc->first + pc->count; ++f) {
        if (!on_lower[f]) continue;
        ++total;
        if (near[f] <= (uint32_t)lround(b->opt.frame_rate)) ++covered;
        if (near[f] > maxgap) maxgap = near[f];
      }
    }
    free(near);
    b->splice_coverage = total ? (float)covered / (float)total : 0.0f;
    b->splice_max_gap =
        maxgap == UINT32_MAX ? INFINITY : (float)maxgap / b->opt.frame_rate;
  }
  r = SMG_OK;
  goto done;
oom:
  smgb_fail(&b->report, "out of memory in the splice search");
  r = SMG_ERROR_OUT_OF_MEMORY;
done:
  free(map_l);
  free(map_u);
  free(uedge);
  free(uoff);
  free(region_of);
  free(on_lower);
  free(vl);
  free(vu);
  free(xl);
  free(xu);
  free(w);
  free(ta);
  free(tl);
  free(mins);
  free(cands);
  free(thr);
  free(action_of);
  return r;
}
