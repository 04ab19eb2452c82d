/*
 * eval_behaviour.c - section "Doing what was asked, like a person"
 * (issue 24): every measure of the issue, computed from the exported poses
 * alone (joint world positions and rotations from the public API, never
 * the runtime's flags), on the CMU graph, the sparse graph
 * (data/cmu-sparse.manifest) and the Bandai Namco graph (tables only: its
 * licence forbids sharing motion made from it).
 *
 *  - walking and running speed of the graph: the hips' median window speed
 *    (eval_gait.h, 1 s) on the straight path started in `walk` and in `run`,
 *    from 3 m after the start to 4 m before the end; the style-held
 *    threshold is midway between them;
 *  - style held: started in `walk` with a transition to `run` 4 m along
 *    the path; share of the frames from 3 m after the transition to 4 m
 *    before the end (the hips' place along the path) in which the hips'
 *    1 s window speed exceeds the threshold;
 *  - per path, started in `walk` and in `run`: the hips' distance from the
 *    path (as section 2c), the planted-toe speed (eval_feet_geom.h), the
 *    pelvis facing against the direction of travel (95th percentile over
 *    the frames moving faster than 0.5 m/s), the cadence (longest over
 *    median swing of both toes until the hips stop) and the rest after
 *    the end (toe heights, ankle spacing, the smallest joint-rotation
 *    range over any 2 s; the same among the upper-body joints alone, and
 *    the hands' median mean speed over 2 s on the body, in the pelvis's
 *    frame: a standing upper body that moves, calmly);
 *  - start and a path behind a standing character: after an 8 m walk and
 *    a rest, a 12 m path ahead of the pelvis, and (in a second run) an
 *    8 m path behind it.
 *
 * CMU only: filmstrips of the stop and the start (side view, one pose
 * every few frames).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_ctx.h"
#include "eval_run.h"
#include "eval_feet_geom.h"
#include "eval_gait.h"
#include "eval_joints.h"
#include "eval_metrics.h"
#include "svg_plot.h"

#define BH_RATE 30.0
#define BH_DT (1.0 / BH_RATE)
#define BH_HALF 15             /* frames: half of a 1 s window */
#define BH_MAX_POINTS 4096
#define BH_END_RADIUS 0.5      /* hips this near the last point: arrived */
#define BH_STILL_M 0.05        /* hips stopped: within this of where they end */
#define BH_REST_S 4.0          /* recorded after arriving */
#define BH_MOVING 0.5          /* m/s: pelvis facing judged above this */
#define BH_WINDOW_BACK 0.5     /* path tracking window, metres */
#define BH_WINDOW_AHEAD 1.5
#define BH_TRANSITION_M 4.0    /* transition to run this far along */
#define BH_HELD_FROM 3.0       /* judged from this far after it ... */
#define BH_HELD_TO 4.0         /* ... to this far before the end */
#define BH_MAX_SWINGS 512
#define BH_BEFORE_END_M 2.0    /* cadence of the path alone: until this far
                                * before the end (stops are judged apart) */
#define PI 3.14159265358979323846

/* ---- recording ---------------------------------------------------------- */

typedef struct bh_rec {
  smg_character* ch;
  uint32_t J;
  size_t n, cap;
  double* pos;  /* 3 J per frame: joint world positions */
  double* hipq; /* 4 per frame: pelvis world rotation */
  double* loc;  /* 4 J per frame: local joint rotations */
  float* mats;
  float* local;
} bh_rec;

typedef struct bh_graph {
  smg_graph* g;
  const char* key, *name;
  eval_joints j;
  unsigned char* upper; /* per joint: 1 for an upper-body joint */
  uint32_t walk, run;
  int have_run;
  double walk_speed, run_speed, threshold;
  double fwd[3];
  int have_fwd;
} bh_graph;

static void rec_free(bh_rec* r) {
  if (r->ch) smg_character_destroy(r->ch);
  free(r->pos);
  free(r->hipq);
  free(r->loc);
  free(r->mats);
  free(r->local);
  memset(r, 0, sizeof(*r));
}

static int set_path(bh_rec* r, const double* xz, size_t n) {
  float pts[2 * BH_MAX_POINTS];
  size_t i;
  if (n > BH_MAX_POINTS) return 0;
  for (i = 0; i < 2 * n; ++i) pts[i] = (float)xz[i];
  return smg_character_set_path(r->ch, pts, (uint32_t)n) == SMG_OK;
}

/* A character at the path's first point facing its second, `seconds` of
 * frames of room; frame 0 recorded by the first step call. */
static int rec_open(bh_graph* bg, const double* xz, size_t n, uint32_t style,
                    double seconds, bh_rec* r) {
  smg_character_desc cd;
  smg_graph_info info;
  memset(r, 0, sizeof(*r));
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if (smg_graph_get_info(bg->g, &info) != SMG_OK || n < 2) return 0;
  r->J = info.joint_count;
  r->cap = (size_t)(seconds * BH_RATE) + 2;
  r->pos = (double*)malloc(r->cap * 3 * r->J * sizeof(double));
  r->hipq = (double*)malloc(r->cap * 4 * sizeof(double));
  r->loc = (double*)malloc(r->cap * 4 * r->J * sizeof(double));
  r->mats = (float*)malloc(16 * (size_t)r->J * sizeof(float));
  r->local = (float*)malloc((3 + 4 * (size_t)r->J) * sizeof(float));
  if (!r->pos || !r->hipq || !r->loc || !r->mats || !r->local) return 0;
  memset(&cd, 0, sizeof(cd));
  cd.struct_size = sizeof(cd);
  cd.initial_style = style;
  cd.path_capacity = BH_MAX_POINTS;
  cd.constraint_capacity = 8;
  cd.position[0] = (float)xz[0];
  cd.position[2] = (float)xz[1];
  cd.heading = (float)atan2(xz[2] - xz[0], xz[3] - xz[1]);
  if (smg_character_create(bg->g, &cd, &r->ch) != SMG_OK) return 0;
  return set_path(r, xz, n);
}

/* Steps (except before frame 0) and records `frames` frames. */
static int rec_steps(bh_rec* r, const bh_graph* bg, size_t frames) {
  size_t f, j;
  for (f = 0; f < frames && r->n < r->cap; ++f) {
    size_t i = r->n;
    if (i > 0 && smg_character_step(r->ch, (float)BH_DT) != SMG_OK) return 0;
    if (smg_character_get_model_matrices(r->ch, SMG_SPACE_WORLD, r->mats,
                                         r->J) != SMG_OK ||
        smg_character_get_local_pose(r->ch, r->local, r->local + 3, r->J) !=
            SMG_OK)
      return 0;
    for (j = 0; j < r->J; ++j) {
      r->pos[(i * r->J + j) * 3] = r->mats[16 * j + 12];
      r->pos[(i * r->J + j) * 3 + 1] = r->mats[16 * j + 13];
      r->pos[(i * r->J + j) * 3 + 2] = r->mats[16 * j + 14];
    }
    for (j = 0; j < 4 * r->J; ++j) r->loc[i * 4 * r->J + j] = r->local[3 + j];
    em_quat_from_matrix(r->mats + 16 * bg->j.hips, r->hipq + 4 * i);
    r->n++;
  }
  return 1;
}

static const double* jp(const bh_rec* r, size_t frame, uint32_t joint) {
  return r->pos + (frame * r->J + joint) * 3;
}

/* Steps until the hips are within BH_END_RADIUS of (ex, ez), then
 * BH_REST_S more (or until the recording is full). */
static int rec_until_rest(bh_rec* r, const bh_graph* bg, double ex,
                          double ez) {
  while (r->n < r->cap) {
    const double* h;
    if (!rec_steps(r, bg, 1)) return 0;
    h = jp(r, r->n - 1, bg->j.hips);
    if (hypot(h[0] - ex, h[2] - ez) < BH_END_RADIUS) break;
  }
  return rec_steps(r, bg, (size_t)(BH_REST_S * BH_RATE));
}

/* First frame in [first, last) from which the hips stay within BH_STILL_M
 * of where they are at last - 1. */
static size_t stop_frame(const bh_rec* r, uint32_t hips, size_t first,
                         size_t last) {
  const double* e = jp(r, last - 1, hips);
  size_t i = last;
  while (i > first) {
    const double* h = jp(r, i - 1, hips);
    if (hypot(h[0] - e[0], h[2] - e[2]) > BH_STILL_M) break;
    --i;
  }
  return i;
}

/* Hips' arc along the path per frame, tracked with a moving window. */
static void track_arc(const bh_rec* r, uint32_t hips, size_t first,
                      size_t last, const double* path, size_t n,
                      double* arc, double* dist) {
  double s = 0.0;
  size_t i;
  for (i = first; i < last; ++i) {
    const double* h = jp(r, i, hips);
    double d = em_polyline_distance_window(path, n, h[0], h[2],
                                           s - BH_WINDOW_BACK,
                                           s + BH_WINDOW_AHEAD, &s);
    arc[i] = s;
    if (dist) dist[i] = d;
  }
}

static double window_speed(const bh_rec* r, uint32_t hips, size_t first,
                           size_t last, size_t i) {
  return eval_gait_window_speed(jp(r, first, hips), 3 * r->J, last - first,
                                i - first, BH_HALF, BH_DT);
}

/* Travel heading over the 1 s window centred on i (within [first, last)). */
static double travel_heading(const bh_rec* r, uint32_t hips, size_t first,
                             size_t last, size_t i) {
  size_t a = i >= first + BH_HALF ? i - BH_HALF : first;
  size_t b = i + BH_HALF < last ? i + BH_HALF : last - 1;
  return eval_gait_travel_heading(r->pos + hips * 3, 3 * r->J, a, b);
}

/* A toe's floor level at every recorded frame (eval_gait.h; malloc'd,
 * NULL when out of memory). */
static double* toe_levels(const bh_rec* r, uint32_t toe) {
  double* level = (double*)malloc((r->n ? r->n : 1) * sizeof(double));
  if (level && eval_gait_floor_levels(r->pos + toe * 3, 3 * r->J, r->n,
                                      BH_DT, level) != 0) {
    free(level);
    level = NULL;
  }
  return level;
}

/* Longest and median swing of both toes over frames [first, last). */
static void cadence(const bh_rec* r, const bh_graph* bg, size_t first,
                    size_t last, double* longest, double* median) {
  static double sw[2 * BH_MAX_SWINGS];
  const uint32_t toe[2] = {bg->j.ltoe, bg->j.rtoe};
  size_t m = 0, k, i;
  *longest = NAN;
  *median = NAN;
  for (k = 0; k < 2; ++k) {
    double* level = toe_levels(r, toe[k]);
    if (!level) return;
    m += eval_gait_swings(r->pos + toe[k] * 3, 3 * r->J, first, last, level,
                          BH_DT, sw + m, BH_MAX_SWINGS);
    free(level);
  }
  if (!m) return;
  *longest = 0.0;
  for (i = 0; i < m; ++i)
    if (sw[i] > *longest) *longest = sw[i];
  *median = eval_gait_median(sw, m);
}

/* ---- per-path runs ------------------------------------------------------ */

typedef struct bh_path_result {
  int ok;
  double mean_cm, max_cm, feet_cms, pelvis_p95_deg;
  double swing_ratio, swing_longest, swing_median;
  double swing_ratio_path; /* the same before the last BH_BEFORE_END_M */
  double rest_s, rest_toe_cm, rest_ankles_m, rest_motion_deg;
  double rest_upper_deg, rest_hands_cms;
} bh_path_result;

/* Joint h in the pelvis's frame at frame i: where a hand is on the body,
 * whatever the body's own sway over the feet. */
static void hand_on_pelvis(const bh_rec* r, const bh_graph* bg, size_t i,
                           uint32_t h, double* out) {
  const double* p = jp(r, i, h);
  const double* o = jp(r, i, bg->j.hips);
  const double* q = r->hipq + 4 * i;
  const double inv[4] = {-q[0], -q[1], -q[2], q[3]};
  const double v[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
  em_quat_rotate(inv, v, out);
}

/* Rest measures over frames [first, last). */
static void rest_measures(const bh_rec* r, const bh_graph* bg, size_t first,
                          size_t last, bh_path_result* out) {
  const uint32_t toe[2] = {bg->j.ltoe, bg->j.rtoe};
  const size_t win = (size_t)(2.0 * BH_RATE), hop = (size_t)(BH_RATE / 2);
  double top = 0.0, apart = 0.0, least = INFINITY;
  double least_upper = INFINITY, hands[64];
  size_t i, k, a, nw = 0;
  out->rest_s = (double)(last - first) * BH_DT;
  for (k = 0; k < 2; ++k) {
    double level = eval_feet_floor_level(r->pos + toe[k] * 3, 3 * r->J,
                                         r->n);
    for (i = first; i < last; ++i) {
      double h = jp(r, i, toe[k])[1] - level;
      if (h > top) top = h;
    }
  }
  for (i = first; i < last; ++i) {
    const double* l = jp(r, i, bg->j.lfoot);
    const double* q = jp(r, i, bg->j.rfoot);
    double d = hypot(l[0] - q[0], l[2] - q[2]);
    if (d > apart) apart = d;
  }
  for (a = first; a + win <= last; a += hop) {
    double most = 0.0;
    for (k = 0; k < r->J; ++k) {
      double v = eval_gait_rotation_range_deg(r->loc + a * 4 * r->J + 4 * k,
                                              4 * r->J, win);
      if (v > most) most = v;
    }
    if (most < least) least = most;
  }
  /* the upper body alone (the legs stand still or shift the weight; is
   * the rest of the body a stop frame?), and the hands' mean speed on the
   * body (in the pelvis's frame) over the same windows: a wave is not a
   * calm stand */
  for (a = first; a + win <= last; a += hop) {
    double most = 0.0, path = 0.0;
    int nh = 0;
    for (k = 0; k < r->J; ++k) {
      double v;
      if (!bg->upper || !bg->upper[k]) continue;
      v = eval_gait_rotation_range_deg(r->loc + a * 4 * r->J + 4 * k,
                                       4 * r->J, win);
      if (v > most) most = v;
    }
    if (most < least_upper) least_upper = most;
    for (k = 0; k < 2; ++k) {
      uint32_t h = k ? bg->j.rhand : bg->j.lhand;
      if (h >= r->J) continue;
      for (i = a + 1; i < a + win; ++i) {
        double p[3], q[3];
        hand_on_pelvis(r, bg, i - 1, h, p);
        hand_on_pelvis(r, bg, i, h, q);
        path += sqrt((q[0] - p[0]) * (q[0] - p[0]) +
                     (q[1] - p[1]) * (q[1] - p[1]) +
                     (q[2] - p[2]) * (q[2] - p[2]));
      }
      nh++;
    }
    if (nh && nw < 64)
      hands[nw++] = 100.0 * path / nh / ((double)(win - 1) * BH_DT);
  }
  out->rest_upper_deg = isfinite(least_upper) ? least_upper : NAN;
  /* the median window: the first holds the end of the settling, arms
   * coming to hang from their stride */
  out->rest_hands_cms = nw ? eval_gait_median(hands, nw) : NAN;
  out->rest_toe_cm = last > first ? 100.0 * top : NAN;
  out->rest_ankles_m = last > first ? apart : NAN;
  out->rest_motion_deg = isfinite(least) ? least : NAN;
}

/* The pelvis's facing over the 1 s window centred on i, taken as the
 * travel direction is (eval_gait_window_facing): the way the body faces
 * over a stride, without the twist every step gives the pelvis. */
static double window_facing(const bh_rec* r, const bh_graph* bg,
                            size_t first, size_t last, size_t i) {
  size_t a = i >= first + BH_HALF ? i - BH_HALF : first;
  size_t b = i + BH_HALF < last ? i + BH_HALF : last - 1;
  return eval_gait_window_facing(r->hipq, r->pos + bg->j.hips * 3, 3 * r->J,
                                 a, b, bg->fwd);
}

/* Pelvis facing against travel, 95th percentile (degrees) over moving
 * frames in [first, last). */
static double pelvis_p95(const bh_rec* r, const bh_graph* bg, size_t first,
                         size_t last) {
  double* v;
  size_t i, m = 0;
  double p = NAN;
  if (!bg->have_fwd || last <= first) return NAN;
  v = (double*)malloc((last - first) * sizeof(double));
  if (!v) return NAN;
  for (i = first; i < last; ++i) {
    double t = travel_heading(r, bg->j.hips, first, r->n, i);
    double f = window_facing(r, bg, first, r->n, i);
    if (!(window_speed(r, bg->j.hips, first, r->n, i) > BH_MOVING) ||
        !isfinite(t) || !isfinite(f))
      continue;
    v[m++] = fabs(eval_gait_angle_diff(f, t)) * 180.0 / PI;
  }
  if (m) {
    eval_gait_median(v, m); /* sorts */
    p = em_percentile_sorted(v, m, 95.0);
  }
  free(v);
  return p;
}

static double planted_toes(const bh_rec* r, const bh_graph* bg, size_t first,
                           size_t last) {
  const double* toes[2];
  eval_feet_geom fg;
  if (last <= first + 1) return NAN;
  toes[0] = jp(r, first, bg->j.ltoe);
  toes[1] = jp(r, first, bg->j.rtoe);
  eval_feet_geom_measure(toes, 2, 3 * r->J, last - first, BH_DT, NULL, &fg);
  return fg.mean_cms;
}

static void path_run(bh_graph* bg, const double* path, size_t n,
                     uint32_t style, bh_path_result* out) {
  bh_rec r;
  double length = em_polyline_length(path, n);
  double *arc = NULL, *dist = NULL, sum = 0.0, worst = 0.0;
  size_t reach, stop;
  memset(out, 0, sizeof(*out));
  if (!rec_open(bg, path, n, style, length / 0.6 + 20.0, &r) ||
      !rec_until_rest(&r, bg, path[2 * n - 2], path[2 * n - 1]))
    goto done;
  arc = (double*)malloc(r.n * sizeof(double));
  dist = (double*)malloc(r.n * sizeof(double));
  if (!arc || !dist) goto done;
  track_arc(&r, bg->j.hips, 0, r.n, path, n, arc, dist);
  for (reach = 0; reach < r.n; ++reach) {
    const double* h = jp(&r, reach, bg->j.hips);
    sum += dist[reach];
    if (dist[reach] > worst) worst = dist[reach];
    if (hypot(h[0] - path[2 * n - 2], h[2] - path[2 * n - 1]) <
        BH_END_RADIUS)
      break;
  }
  if (reach == r.n) reach = r.n - 1;
  out->mean_cm = 100.0 * sum / (double)(reach + 1);
  out->max_cm = 100.0 * worst;
  out->feet_cms = planted_toes(&r, bg, 0, reach + 1);
  out->pelvis_p95_deg = pelvis_p95(&r, bg, 0, reach + 1);
  stop = stop_frame(&r, bg->j.hips, 0, r.n);
  cadence(&r, bg, 0, stop, &out->swing_longest, &out->swing_median);
  out->swing_ratio = out->swing_longest / out->swing_median;
  {
    /* the turns alone: before the stop's last metres begin */
    size_t before = 0;
    double lo, me;
    while (before < stop && arc[before] < length - BH_BEFORE_END_M) ++before;
    cadence(&r, bg, 0, before, &lo, &me);
    out->swing_ratio_path = lo / me;
  }
  rest_measures(&r, bg, stop, r.n, out);
  out->ok = 1;
done:
  free(arc);
  free(dist);
  rec_free(&r);
}

/* Median 1 s window speed between 3 m after the start and 4 m before the
 * end of a straight run in `style`; calibrates the pelvis forward axis
 * from it when `calibrate`. */
static double steady_speed(bh_graph* bg, const double* path, size_t n,
                           uint32_t style, int calibrate) {
  bh_rec r;
  double length = em_polyline_length(path, n), s = NAN;
  double *arc = NULL, *v = NULL, *travel = NULL;
  size_t i, m = 0;
  if (!rec_open(bg, path, n, style, length / 0.6 + 20.0, &r) ||
      !rec_until_rest(&r, bg, path[2 * n - 2], path[2 * n - 1]))
    goto done;
  arc = (double*)malloc(r.n * sizeof(double));
  v = (double*)malloc(r.n * sizeof(double));
  travel = (double*)malloc(r.n * sizeof(double));
  if (!arc || !v || !travel) goto done;
  track_arc(&r, bg->j.hips, 0, r.n, path, n, arc, NULL);
  for (i = 0; i < r.n; ++i) {
    int steady = arc[i] >= BH_HELD_FROM && arc[i] <= length - BH_HELD_TO;
    travel[i] = steady ? travel_heading(&r, bg->j.hips, 0, r.n, i) : NAN;
    if (steady) v[m++] = window_speed(&r, bg->j.hips, 0, r.n, i);
  }
  s = eval_gait_median(v, m);
  if (calibrate)
    bg->have_fwd =
        eval_gait_calibrate_forward(r.hipq, travel, r.n, bg->fwd) == 0;
done:
  free(arc);
  free(v);
  free(travel);
  rec_free(&r);
  return s;
}

/* Share of judged frames at running speed after a transition to run. */
static double style_held(bh_graph* bg, const double* path, size_t n) {
  bh_rec r;
  double length = em_polyline_length(path, n), share = NAN;
  double* arc = NULL;
  size_t i, judged = 0, fast = 0;
  uint32_t id;
  if (!rec_open(bg, path, n, bg->walk, length / 0.6 + 20.0, &r) ||
      smg_character_add_transition(r.ch, BH_TRANSITION_M, bg->run, &id) !=
          SMG_OK ||
      !rec_until_rest(&r, bg, path[2 * n - 2], path[2 * n - 1]))
    goto done;
  arc = (double*)malloc(r.n * sizeof(double));
  if (!arc) goto done;
  track_arc(&r, bg->j.hips, 0, r.n, path, n, arc, NULL);
  for (i = 0; i < r.n; ++i) {
    if (arc[i] < BH_TRANSITION_M + BH_HELD_FROM ||
        arc[i] > length - BH_HELD_TO)
      continue;
    judged++;
    fast += window_speed(&r, bg->j.hips, 0, r.n, i) > bg->threshold;
  }
  if (judged) share = (double)fast / (double)judged;
done:
  free(arc);
  rec_free(&r);
  return share;
}

/* ---- start, and a path behind ------------------------------------------ */

typedef struct bh_start_result {
  int ok;
  double swing_first, swing_steady, swing_ratio; /* start */
  double reach80_s, steady_speed;
  double face_s, face_moved_m, face_toes_cms;    /* path behind */
  double rest_toe_cm, rest_ankles_m, rest_motion_deg;
} bh_start_result;

#define BH_LEAD_M 8.0
#define BH_AHEAD_M 12.0
#define BH_BEHIND_M 8.0
#define BH_STAND_S 2.0

/* An 8 m walk along +z, a rest of BH_STAND_S after the hips stop; *given
 * is the frame at which the next path is given, *x, *z, *facing where the
 * character stands and which way its pelvis faces. */
static int walk_and_stand(bh_graph* bg, double seconds, bh_rec* r,
                          size_t* given, double* x, double* z,
                          double* facing) {
  double lead[4] = {0.0, 0.0, 0.0, BH_LEAD_M};
  size_t stop;
  if (!rec_open(bg, lead, 2, bg->walk, seconds, r)) return 0;
  while (r->n < r->cap) {
    const double* h;
    if (!rec_steps(r, bg, 1)) return 0;
    h = jp(r, r->n - 1, bg->j.hips);
    if (hypot(h[0], h[2] - BH_LEAD_M) < BH_END_RADIUS) break;
  }
  /* until the hips have been still for BH_STAND_S */
  while (r->n < r->cap) {
    if (!rec_steps(r, bg, 1)) return 0;
    stop = stop_frame(r, bg->j.hips, 0, r->n);
    if ((double)(r->n - stop) * BH_DT >= BH_STAND_S) break;
  }
  *given = r->n;
  *x = jp(r, r->n - 1, bg->j.hips)[0];
  *z = jp(r, r->n - 1, bg->j.hips)[2];
  *facing = bg->have_fwd ? eval_gait_facing(r->hipq + 4 * (r->n - 1),
                                            bg->fwd)
                         : 0.0;
  return isfinite(*facing);
}

/* Start: a 12 m path ahead of the standing character. */
static int start_run(bh_graph* bg, bh_rec* r, size_t* given,
                     bh_start_result* out) {
  double x, z, f, path[4], *arc = NULL, *v = NULL;
  double first_long = 0.0, steady_sw[BH_MAX_SWINGS];
  const uint32_t toe[2] = {bg->j.ltoe, bg->j.rtoe};
  size_t i, m = 0, ns = 0, steady_a = 0, steady_b = 0, stop, k;
  int ok = 0;
  if (!walk_and_stand(bg, 60.0, r, given, &x, &z, &f)) goto done;
  path[0] = x, path[1] = z;
  path[2] = x + BH_AHEAD_M * sin(f), path[3] = z + BH_AHEAD_M * cos(f);
  if (!set_path(r, path, 2) || !rec_until_rest(r, bg, path[2], path[3]))
    goto done;
  arc = (double*)malloc(r->n * sizeof(double));
  v = (double*)malloc(r->n * sizeof(double));
  if (!arc || !v) goto done;
  track_arc(r, bg->j.hips, *given, r->n, path, 2, arc, NULL);
  stop = stop_frame(r, bg->j.hips, *given, r->n);
  for (i = *given; i < stop; ++i)
    if (arc[i] >= BH_HELD_FROM && arc[i] <= BH_AHEAD_M - BH_HELD_TO) {
      if (!steady_a) steady_a = i;
      steady_b = i + 1;
      v[m++] = window_speed(r, bg->j.hips, *given, r->n, i);
    }
  out->steady_speed = eval_gait_median(v, m);
  /* swings in the first 2 s after the path is given, and in the steady
   * stretch */
  for (k = 0; k < 2; ++k) {
    const double* t = r->pos + toe[k] * 3;
    double* level = toe_levels(r, toe[k]);
    double sw[64];
    size_t c;
    if (!level) goto done;
    c = eval_gait_swings(t, 3 * r->J, *given,
                         *given + (size_t)(2.0 * BH_RATE), level, BH_DT, sw,
                         64);
    for (i = 0; i < c; ++i)
      if (sw[i] > first_long) first_long = sw[i];
    if (steady_b > steady_a)
      ns += eval_gait_swings(t, 3 * r->J, steady_a, steady_b, level, BH_DT,
                             steady_sw + ns, BH_MAX_SWINGS - ns);
    free(level);
  }
  out->swing_first = first_long;
  out->swing_steady = eval_gait_median(steady_sw, ns);
  out->swing_ratio = out->swing_first / out->swing_steady;
  /* trailing 0.5 s speed reaching 80 % of the steady speed */
  out->reach80_s = NAN;
  for (i = *given + (size_t)(BH_RATE / 2); i < r->n; ++i) {
    const double* a = jp(r, i - (size_t)(BH_RATE / 2), bg->j.hips);
    double len = 0.0;
    size_t q;
    for (q = i - (size_t)(BH_RATE / 2) + 1; q <= i; ++q)
      len += hypot(jp(r, q, bg->j.hips)[0] - jp(r, q - 1, bg->j.hips)[0],
                   jp(r, q, bg->j.hips)[2] - jp(r, q - 1, bg->j.hips)[2]);
    (void)a;
    if (len / 0.5 >= 0.8 * out->steady_speed) {
      out->reach80_s = (double)(i - *given) * BH_DT;
      break;
    }
  }
  ok = 1;
done:
  free(arc);
  free(v);
  return ok;
}

/* A path behind the standing character. */
static int behind_run(bh_graph* bg, bh_start_result* out) {
  bh_rec r;
  double x, z, f, path[4], dir;
  size_t given, i, end;
  int ok = 0;
  if (!walk_and_stand(bg, 40.0, &r, &given, &x, &z, &f)) goto done;
  dir = f + PI;
  path[0] = x, path[1] = z;
  path[2] = x + BH_BEHIND_M * sin(dir), path[3] = z + BH_BEHIND_M * cos(dir);
  if (!set_path(&r, path, 2) ||
      !rec_steps(&r, bg, (size_t)(3.0 * BH_RATE)))
    goto done;
  out->face_s = NAN;
  end = given + (size_t)(1.5 * BH_RATE);
  for (i = given; i < r.n; ++i) {
    double fi = eval_gait_facing(r.hipq + 4 * i, bg->fwd);
    if (isfinite(fi) &&
        fabs(eval_gait_angle_diff(fi, dir)) <= 30.0 * PI / 180.0) {
      const double* h = jp(&r, i, bg->j.hips);
      out->face_s = (double)(i - given) * BH_DT;
      out->face_moved_m = hypot(h[0] - x, h[2] - z);
      end = i + 1;
      break;
    }
  }
  if (!isfinite(out->face_s)) {
    const double* h = jp(&r, r.n - 1, bg->j.hips);
    out->face_moved_m = hypot(h[0] - x, h[2] - z);
  }
  if (end > r.n) end = r.n;
  out->face_toes_cms = planted_toes(&r, bg, given, end);
  ok = 1;
done:
  rec_free(&r);
  return ok;
}

/* ---- filmstrips (CMU only) --------------------------------------------- */

/* Side view of poses [first, last) every `every` frames, each shifted to
 * its own slot; the travel direction is +z. */
static void filmstrip(eval_ctx* ctx, const bh_graph* bg, const bh_rec* r,
                      size_t first, size_t last, size_t every,
                      const char* file, const char* title) {
  smg_joint_info ji;
  int32_t parent[256];
  int leg[256];
  svp_figure* fig;
  char full[1200], label[64];
  uint32_t k;
  size_t i, slot = 0;
  const double spacing = 0.75;
  if (r->J > 256 || last <= first) return;
  for (k = 0; k < r->J; ++k) {
    memset(&ji, 0, sizeof(ji));
    ji.struct_size = sizeof(ji);
    if (smg_graph_get_joint(bg->g, k, &ji) != SMG_OK) return;
    parent[k] = ji.parent;
    leg[k] = 0;
  }
  /* the chains from each toe up to (not including) the pelvis */
  for (k = bg->j.ltoe; k != bg->j.hips && parent[k] >= 0;
       k = (uint32_t)parent[k])
    leg[k] = 1;
  for (k = bg->j.rtoe; k != bg->j.hips && parent[k] >= 0;
       k = (uint32_t)parent[k])
    leg[k] = 2;
  fig = svp_create(900, 300, title);
  if (!fig) return;
  snprintf(label, sizeof(label), "poses %.2f s apart (s since the first)",
           (double)every * BH_DT);
  svp_set_labels(fig, label, "height (m)");
  svp_set_equal_aspect(fig, 1);
  for (i = first; i < last; i += every, ++slot) {
    const double base = jp(r, i, bg->j.hips)[2];
    const double off = (double)slot * spacing;
    double fx[2], fy[2];
    for (k = 0; k < r->J; ++k) {
      double x[2], y[2];
      static const char* const colour[3] = {"#555555", "#1f5fd6", "#d62728"};
      if (parent[k] < 0) continue;
      x[0] = jp(r, i, (uint32_t)parent[k])[2] - base + off;
      y[0] = jp(r, i, (uint32_t)parent[k])[1];
      x[1] = jp(r, i, k)[2] - base + off;
      y[1] = jp(r, i, k)[1];
      svp_line(fig, x, y, 2, colour[leg[k]], 1.6, 0, NULL);
    }
    fx[0] = off - 0.3, fx[1] = off + 0.3;
    fy[0] = fy[1] = 0.0;
    svp_line(fig, fx, fy, 2, "#bbbbbb", 1.0, 0, NULL);
    snprintf(label, sizeof(label), "%.1f", (double)(i - first) * BH_DT);
    svp_text(fig, off, -0.12, label, "#333333");
  }
  svp_legend_entry(fig, "left leg", "#1f5fd6", 0, SVP_CIRCLE);
  svp_legend_entry(fig, "right leg", "#d62728", 0, SVP_CIRCLE);
  eval_img_path(ctx, file, full, sizeof(full));
  if (svp_write(fig, full) != 0) eval_log("cannot write %s", full);
  svp_destroy(fig);
}

/* ---- one graph ---------------------------------------------------------- */

typedef struct bh_path_spec {
  const char* key, *title;
  int tight;  /* corner-like: the max error and 75 % style targets */
  int held;   /* in the style-held set */
} bh_path_spec;

static const bh_path_spec k_paths[] = {
    {"straight", "straight 20 m", 0, 1},
    {"s-curve", "S-curve, r = 4 m", 0, 1},
    {"circle-r5", "circle r = 5 m", 0, 1},
    {"corner-left", "corner left 90 deg", 1, 1},
    {"corner-right", "corner right 90 deg", 1, 1},
    {"u-turn", "U-turn, 2 m across", 1, 0},
    {"circle-r2", "circle r = 2 m", 1, 0},
    {"scribble", "scribble, 1.2 m loops", 1, 1},
};
#define BH_PATHS (sizeof(k_paths) / sizeof(k_paths[0]))

/* The figures of one graph that the targets read (worst over runs). */
typedef struct bh_summary {
  int measured;
  double walk_speed, run_speed, threshold;
  double held_smooth, held_tight;       /* least shares */
  double swing_ratio;                   /* largest */
  double swing_ratio_path;              /* largest, before the last 2 m */
  double rest_toe_cm, rest_ankles_m, rest_motion_deg;
  double rest_upper_deg, rest_hands_cms;
  double start_swing_ratio, start_reach_s;
  double face_s, face_moved_m, face_toes_cms;
  double smooth_mean_cm, tight_max_cm, feet_cms, pelvis_deg;
  int standing;                         /* the rest-motion target applies */
} bh_summary;


static double worse_max(double a, double b) {
  return !isfinite(b) ? (isfinite(a) ? INFINITY : a) : (a > b ? a : b);
}
static double worse_min(double a, double b) {
  return !isfinite(b) ? -INFINITY : (a < b ? a : b);
}

static void behave_graph(eval_ctx* ctx, bh_graph* bg, int figures,
                         bh_summary* s) {
  static double path[2 * BH_MAX_POINTS];
  char b[14][24];
  size_t k, n;
  int st;
  s->measured = 1;
  s->held_smooth = s->held_tight = INFINITY;
  s->swing_ratio = s->swing_ratio_path = 0.0;
  s->rest_toe_cm = s->rest_ankles_m = 0.0;
  s->rest_motion_deg = s->rest_upper_deg = INFINITY;
  s->rest_hands_cms = 0.0;
  s->smooth_mean_cm = s->tight_max_cm = s->feet_cms = s->pelvis_deg = 0.0;
  n = eval_read_path("data/paths/straight.txt", path, BH_MAX_POINTS);
  s->walk_speed = n >= 2 ? steady_speed(bg, path, n, bg->walk, 1) : NAN;
  s->run_speed = n >= 2 && bg->have_run
                     ? steady_speed(bg, path, n, bg->run, 0)
                     : NAN;
  s->threshold = bg->threshold = 0.5 * (s->walk_speed + s->run_speed);
  eval_md(ctx,
          "**%s**: walking speed %s m/s, running speed %s m/s, style-held "
          "threshold %s m/s.\n\n",
          bg->name, eval_fmt(b[0], sizeof(b[0]), "%.2f", s->walk_speed),
          eval_fmt(b[1], sizeof(b[1]), "%.2f", s->run_speed),
          eval_fmt(b[2], sizeof(b[2]), "%.2f", s->threshold));

  /* style held */
  eval_md(ctx, "| path | style held: share at running speed |\n|---|---|\n");
  for (k = 0; k < BH_PATHS; ++k) {
    char file[256];
    double share = NAN;
    if (!k_paths[k].held) continue;
    snprintf(file, sizeof(file), "data/paths/%s.txt", k_paths[k].key);
    n = eval_read_path(file, path, BH_MAX_POINTS);
    if (n >= 2 && bg->have_run && isfinite(bg->threshold))
      share = style_held(bg, path, n);
    eval_log("behaviour %s %-12s style held %.3f", bg->key, k_paths[k].key,
             share);
    eval_md(ctx, "| %s | %s %% |\n", k_paths[k].title,
            eval_fmt(b[0], sizeof(b[0]), "%.0f", 100.0 * share));
    if (k_paths[k].tight)
      s->held_tight = worse_min(s->held_tight, share);
    else
      s->held_smooth = worse_min(s->held_smooth, share);
  }
  eval_md(ctx, "\n");

  /* every path, walking and running */
  eval_md(ctx,
          "| path | style | path error mean / max cm | planted toes cm/s | "
          "pelvis vs travel p95 deg | swings: longest / median s (ratio) | "
          "ratio before the last 2 m | "
          "at rest: s | toes above floor cm | ankles apart m | least "
          "rotation range in 2 s deg | the same, upper body | hands on the "
          "body, median 2 s mean cm/s |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (k = 0; k < BH_PATHS; ++k) {
    char file[256];
    snprintf(file, sizeof(file), "data/paths/%s.txt", k_paths[k].key);
    n = eval_read_path(file, path, BH_MAX_POINTS);
    for (st = 0; st < 2; ++st) {
      bh_path_result r;
      if (st == 1 && !bg->have_run) continue;
      memset(&r, 0, sizeof(r));
      if (n >= 2) path_run(bg, path, n, st ? bg->run : bg->walk, &r);
      if (!r.ok) {
        eval_md(ctx, "| %s | %s | run failed | | | | | | | | | | |\n",
                k_paths[k].title, st ? "run" : "walk");
        s->swing_ratio = INFINITY;
        continue;
      }
      eval_log("behaviour %s %-12s %-4s err %.1f/%.1f feet %.1f pelvis %.1f "
               "swing %.2f/%.2f rest %.1f s toe %.1f ankles %.2f motion %.2f "
               "upper %.2f hands %.1f",
               bg->key, k_paths[k].key, st ? "run" : "walk", r.mean_cm,
               r.max_cm, r.feet_cms, r.pelvis_p95_deg, r.swing_longest,
               r.swing_median, r.rest_s, r.rest_toe_cm, r.rest_ankles_m,
               r.rest_motion_deg, r.rest_upper_deg, r.rest_hands_cms);
      eval_md(ctx,
              "| %s | %s | %s / %s | %s | %s | %s / %s (%s) | %s | %s | %s | "
              "%s | %s | %s | %s |\n",
              k_paths[k].title, st ? "run" : "walk",
              eval_fmt(b[0], sizeof(b[0]), "%.1f", r.mean_cm),
              eval_fmt(b[1], sizeof(b[1]), "%.1f", r.max_cm),
              eval_fmt(b[2], sizeof(b[2]), "%.1f", r.feet_cms),
              eval_fmt(b[3], sizeof(b[3]), "%.1f", r.pelvis_p95_deg),
              eval_fmt(b[4], sizeof(b[4]), "%.2f", r.swing_longest),
              eval_fmt(b[5], sizeof(b[5]), "%.2f", r.swing_median),
              eval_fmt(b[6], sizeof(b[6]), "%.2f", r.swing_ratio),
              eval_fmt(b[11], sizeof(b[11]), "%.2f", r.swing_ratio_path),
              eval_fmt(b[7], sizeof(b[7]), "%.1f", r.rest_s),
              eval_fmt(b[8], sizeof(b[8]), "%.1f", r.rest_toe_cm),
              eval_fmt(b[9], sizeof(b[9]), "%.2f", r.rest_ankles_m),
              eval_fmt(b[10], sizeof(b[10]), "%.2f", r.rest_motion_deg),
              eval_fmt(b[12], sizeof(b[12]), "%.2f", r.rest_upper_deg),
              eval_fmt(b[13], sizeof(b[13]), "%.1f", r.rest_hands_cms));
      s->swing_ratio = worse_max(s->swing_ratio, r.swing_ratio);
      s->swing_ratio_path = worse_max(s->swing_ratio_path, r.swing_ratio_path);
      s->rest_toe_cm = worse_max(s->rest_toe_cm, r.rest_toe_cm);
      s->rest_ankles_m = worse_max(s->rest_ankles_m, r.rest_ankles_m);
      s->rest_motion_deg = worse_min(s->rest_motion_deg, r.rest_motion_deg);
      s->rest_upper_deg = worse_min(s->rest_upper_deg, r.rest_upper_deg);
      s->rest_hands_cms = worse_max(s->rest_hands_cms, r.rest_hands_cms);
      s->feet_cms = worse_max(s->feet_cms, r.feet_cms);
      s->pelvis_deg = worse_max(s->pelvis_deg, r.pelvis_p95_deg);
      if (k_paths[k].tight)
        s->tight_max_cm = worse_max(s->tight_max_cm, r.max_cm);
      else
        s->smooth_mean_cm = worse_max(s->smooth_mean_cm, r.mean_cm);
    }
  }
  eval_md(ctx, "\n");

  /* start and a path behind */
  {
    bh_rec r;
    bh_start_result sr;
    size_t given = 0;
    memset(&sr, 0, sizeof(sr));
    s->start_swing_ratio = s->start_reach_s = NAN;
    s->face_s = s->face_moved_m = s->face_toes_cms = NAN;
    if (start_run(bg, &r, &given, &sr)) {
      s->start_swing_ratio = sr.swing_ratio;
      s->start_reach_s = sr.reach80_s;
      if (figures && ctx->img_dir) {
        size_t stop = stop_frame(&r, bg->j.hips, 0, given);
        size_t a = stop > (size_t)(1.5 * BH_RATE)
                       ? stop - (size_t)(1.5 * BH_RATE)
                       : 0;
        filmstrip(ctx, bg, &r, a, stop + (size_t)BH_RATE, 4,
                  "eval-behaviour-stop.svg",
                  "CMU graph: the last steps of an 8 m walk and the stop");
        filmstrip(ctx, bg, &r, given, given + (size_t)(2.5 * BH_RATE), 4,
                  "eval-behaviour-start.svg",
                  "CMU graph: from standing, a 12 m path ahead is given");
      }
    }
    rec_free(&r);
    if (behind_run(bg, &sr)) {
      s->face_s = sr.face_s;
      s->face_moved_m = sr.face_moved_m;
      s->face_toes_cms = sr.face_toes_cms;
    }
    eval_log("behaviour %s start: first swing %.2f s vs steady %.2f s, "
             "80 %% of %.2f m/s after %.2f s; behind: faces after %.2f s, "
             "moved %.2f m, toes %.1f cm/s",
             bg->key, sr.swing_first, sr.swing_steady, sr.steady_speed,
             sr.reach80_s, sr.face_s, sr.face_moved_m, sr.face_toes_cms);
    eval_md(ctx,
            "Start (an 8 m walk, %.0f s standing, then a 12 m path ahead): "
            "longest swing in the first 2 s %s s, median swing of the "
            "steady walk %s s; steady speed %s m/s, 80 %% of it after %s "
            "s. Path behind (the same stand, an 8 m path behind the "
            "pelvis): the pelvis faces within 30 deg of it after %s s, the "
            "hips %s m from where they stood; planted toes meanwhile %s "
            "cm/s.\n\n",
            BH_STAND_S, eval_fmt(b[0], sizeof(b[0]), "%.2f", sr.swing_first),
            eval_fmt(b[1], sizeof(b[1]), "%.2f", sr.swing_steady),
            eval_fmt(b[2], sizeof(b[2]), "%.2f", sr.steady_speed),
            eval_fmt(b[3], sizeof(b[3]), "%.2f", sr.reach80_s),
            eval_fmt(b[4], sizeof(b[4]), "%.2f", sr.face_s),
            eval_fmt(b[5], sizeof(b[5]), "%.2f", sr.face_moved_m),
            eval_fmt(b[6], sizeof(b[6]), "%.1f", sr.face_toes_cms));
  }
}

/* ---- the section -------------------------------------------------------- */

typedef struct bh_target {
  const char* what;
  int lower;       /* the value must be at least `bound` (else at most) */
  double bound;
  const char* fmt;
  int diagnostic;  /* shown for what it explains, not judged */
} bh_target;

static const bh_target k_targets[] = {
    {"style held, straight / circle r = 5 / S-curve (least share, %)", 1,
     90.0, "%.0f", 0},
    {"style held, corners / scribble (least share, %)", 1, 75.0, "%.0f", 0},
    {"cadence: longest / median swing until the hips stop, the stop "
     "included (largest)", 0, 1.6, "%.2f", 0},
    {"cadence on the path alone, before its last 2 m (diagnostic: the "
     "turns apart from the stop)", 0, 1.6, "%.2f", 1},
    {"at rest: toes above their floor level (cm, largest)", 0, 2.5, "%.1f", 0},
    {"at rest: ankles apart (m, largest)", 0, 0.40, "%.2f", 0},
    {"at rest: least rotation range of any 2 s (deg; graphs with standing "
     "motion)", 1, 1.0, "%.2f", 0},
    {"at rest: the same among the upper-body joints (deg; graphs with "
     "standing motion)", 1, 0.5, "%.2f", 0},
    {"at rest: hands' mean speed on the body, median 2 s (cm/s, largest; "
     "diagnostic: a wave moves them tens of cm/s)", 0, 0.0, "%.1f", 1},
    {"start: longest swing in the first 2 s / steady median swing", 0, 1.5,
     "%.2f", 0},
    {"start: 80 % of the steady speed after (s)", 0, 1.5, "%.2f", 0},
    {"path behind: pelvis within 30 deg of the path after (s)", 0, 1.5,
     "%.2f", 0},
    {"path behind: hips moved by then (m)", 0, 0.5, "%.2f", 0},
    {"path behind: planted toes meanwhile (cm/s)", 0, 20.0, "%.1f", 0},
    {"keep: path error mean, smooth paths (cm, largest)", 0, 5.0, "%.1f", 0},
    {"keep: path error max, corner-like paths (cm, largest)", 0, 45.0,
     "%.1f", 0},
    {"keep: planted toes (cm/s, largest run mean)", 0, 20.0, "%.1f", 0},
    {"keep: pelvis vs travel, 95th percentile (deg, largest)", 0, 10.0,
     "%.1f", 0},
};
#define BH_TARGETS (sizeof(k_targets) / sizeof(k_targets[0]))

static double target_value(const bh_summary* s, size_t t) {
  switch (t) {
    case 0: return 100.0 * s->held_smooth;
    case 1: return 100.0 * s->held_tight;
    case 2: return s->swing_ratio;
    case 3: return s->swing_ratio_path;
    case 4: return s->rest_toe_cm;
    case 5: return s->rest_ankles_m;
    case 6: return s->rest_motion_deg;
    case 7: return s->rest_upper_deg;
    case 8: return s->rest_hands_cms;
    case 9: return s->start_swing_ratio;
    case 10: return s->start_reach_s;
    case 11: return s->face_s;
    case 12: return s->face_moved_m;
    case 13: return s->face_toes_cms;
    case 14: return s->smooth_mean_cm;
    case 15: return s->tight_max_cm;
    case 16: return s->feet_cms;
    default: return s->pelvis_deg;
  }
}

/* The graphs: the paper-size CMU set, the sparse set, Bandai Namco
 * (tables only). `standing`: the data holds standing motion (the Bandai
 * Namco set's upper-body clips are performed standing), so the rest must
 * not be a frozen frame. */
typedef struct bh_graph_spec {
  const char* key, *name, *manifest;
  int blob; /* 0 CMU, 1 sparse, 2 Bandai Namco */
  int figures, standing;
} bh_graph_spec;

static const bh_graph_spec k_graphs[] = {
    {"cmu", "CMU graph", NULL, 0, 1, 0},
    {"sparse", "Sparse graph", "data/cmu-sparse.manifest", 1, 0, 0},
    {"bandai", "Bandai Namco graph", NULL, 2, 0, 1},
};
#define BH_GRAPHS (sizeof(k_graphs) / sizeof(k_graphs[0]))

/* Per joint, 1 for an upper-body joint (malloc'd; NULL when out of
 * memory or the graph cannot say). */
static unsigned char* upper_joints(const smg_graph* g) {
  smg_graph_info info;
  unsigned char* up;
  uint32_t k;
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if (smg_graph_get_info(g, &info) != SMG_OK || info.joint_count == 0)
    return NULL;
  up = (unsigned char*)calloc(info.joint_count, 1);
  for (k = 0; up && k < info.joint_count; ++k) {
    smg_joint_info ji;
    memset(&ji, 0, sizeof(ji));
    ji.struct_size = sizeof(ji);
    if (smg_graph_get_joint(g, k, &ji) != SMG_OK) {
      free(up);
      return NULL;
    }
    up[k] = ji.body_part == SMG_BODY_UPPER;
  }
  return up;
}

void eval_section_behaviour(eval_ctx* ctx, const void* cmu_blob,
                            size_t cmu_size) {
  bh_summary sum[BH_GRAPHS];
  size_t k, t;
  int passed = 0, judged = 0;
  if (ctx->check) return;
  memset(sum, 0, sizeof(sum));
  eval_md(ctx,
          "## 2d. Doing what was asked, like a person (issue 24)\n\n"
          "Measured from the exported poses alone "
          "(`tools/eval/eval_behaviour.c`, `eval_gait.c`): joint world "
          "positions and the pelvis's world rotation from "
          "`smg_character_get_model_matrices`, local rotations from "
          "`smg_character_get_local_pose`, stepped at %.0f Hz. A *swing* is "
          "a stretch of at least %.1f s with a toe more than %.1f cm above "
          "its floor level (the lowest height of its latest stance, frames "
          "slower than 0.3 m/s: graphs of several performers plant the toe "
          "at heights a few cm apart); a "
          "window speed is the hips' ground path length over 1 s. "
          "Walking and running speeds: the hips' median window speed on the "
          "straight path started in `walk` and in `run`, from 3 m after the "
          "start to 4 m before the end; *style held* starts in `walk` with a "
          "transition to `run` %.0f m along the path and counts the frames "
          "from %.0f m after it to %.0f m before the end (the hips' place "
          "along the path) whose window speed exceeds the midway speed. "
          "Every path is also run started in `walk` and in `run` and "
          "recorded until %.0f s after the hips come within %.1f m of the "
          "end: path error (as section 2c), planted-toe speed (section 2c), "
          "the pelvis's facing against the direction of travel (its forward "
          "axis calibrated on the straight walk; both over a 1 s "
          "window, i.e. over a stride, so the twist of each step is not "
          "counted: the travel as the chord, the facing as the mean of the "
          "frames' facings weighted by the hips' travel in each, as the "
          "chord weights them; "
          "95th percentile over frames faster than %.1f m/s), swings until "
          "the hips stop (from then on they stay within %.0f cm), and at "
          "rest (after the stop) the toes' height above their floor level "
          "over the run (5th percentile), "
          "the ankles' horizontal distance and the least, over 2 s windows "
          "every 0.5 s, of the largest rotation range of any joint, the "
          "same among the upper-body joints alone (is the upper body a "
          "stop frame?), and the median over those windows of the hands' "
          "(wrists') mean speed in the pelvis's frame (a calm stand, not a "
          "wave; the first window holds the end of the settling). Start: "
          "an 8 m walk, %.0f s standing, then a 12 m path ahead of the "
          "pelvis; 80 %% of the steady speed (median window speed 3 m after "
          "the start to 4 m before the end) is reached when the hips' mean "
          "speed over the last 0.5 s is at least that. Path behind: the "
          "same stand, an 8 m path straight behind the pelvis.\n\n",
          BH_RATE, EVAL_GAIT_SWING_MIN_S, 100.0 * EVAL_GAIT_SWING_M,
          BH_TRANSITION_M, BH_HELD_FROM, BH_HELD_TO, BH_REST_S,
          BH_END_RADIUS, BH_MOVING, 100.0 * BH_STILL_M, BH_STAND_S);
  for (k = 0; k < BH_GRAPHS; ++k) {
    const bh_graph_spec* gs = &k_graphs[k];
    void* owned = NULL;
    const void* blob = NULL;
    size_t size = 0;
    bh_graph bg;
    memset(&bg, 0, sizeof(bg));
    bg.key = gs->key;
    bg.name = gs->name;
    sum[k].standing = gs->standing;
    if (gs->blob < 2 && !ctx->have_cmu) continue;
    if (gs->blob == 2 && !ctx->have_bandai) continue;
    if (gs->blob == 0) {
      blob = cmu_blob;
      size = cmu_size;
    } else {
      eval_log("baking %s for the behaviour section...",
               gs->blob == 1 ? gs->manifest : ctx->bandai_manifest);
      owned = eval_bake_to_memory(gs->blob == 1 ? gs->manifest
                                                : ctx->bandai_manifest,
                                  gs->blob == 1 ? ctx->cmu_dir
                                                : ctx->bandai_dir,
                                  &size);
      blob = owned;
    }
    if (!blob || smg_graph_load_memory(blob, size, NULL, &bg.g) != SMG_OK ||
        !eval_find_joints(bg.g, &bg.j) ||
        smg_graph_find_style(bg.g, "walk", &bg.walk) != SMG_OK) {
      eval_md(ctx, "**%s**: not available in this run.\n\n", gs->name);
    } else {
      bg.have_run = smg_graph_find_style(bg.g, "run", &bg.run) == SMG_OK;
      bg.upper = upper_joints(bg.g);
      behave_graph(ctx, &bg, gs->figures, &sum[k]);
    }
    free(bg.upper);
    if (bg.g) smg_graph_destroy(bg.g);
    free(owned);
  }
  if (ctx->img_dir && sum[0].measured)
    eval_md(ctx,
            "The stop and the start on the CMU graph, seen from the side "
            "(each pose in its own slot, the time under it):\n\n"
            "![CMU graph, stop](%s/eval-behaviour-stop.svg)\n"
            "![CMU graph, start](%s/eval-behaviour-start.svg)\n\n",
            ctx->img_rel, ctx->img_rel);
  eval_md(ctx, "Targets (issue 24):\n\n| target | bound |");
  for (k = 0; k < BH_GRAPHS; ++k) eval_md(ctx, " %s |", k_graphs[k].name);
  eval_md(ctx, "\n|---|---|");
  for (k = 0; k < BH_GRAPHS; ++k) eval_md(ctx, "---|");
  eval_md(ctx, "\n");
  for (t = 0; t < BH_TARGETS; ++t) {
    const bh_target* tg = &k_targets[t];
    if (tg->diagnostic)
      eval_md(ctx, "| %s | (not a target) |", tg->what);
    else
      eval_md(ctx, "| %s | %s %g |", tg->what, tg->lower ? ">=" : "<=",
              tg->bound);
    for (k = 0; k < BH_GRAPHS; ++k) {
      char v[32];
      double x = target_value(&sum[k], t);
      int ok = tg->lower ? x >= tg->bound : x <= tg->bound;
      if (!sum[k].measured) {
        eval_md(ctx, " not measured |");
        continue;
      }
      eval_fmt(v, sizeof(v), tg->fmt, x);
      if (tg->diagnostic) {
        eval_md(ctx, " %s |", v);
        continue;
      }
      if ((t == 6 || t == 7) && !sum[k].standing) {
        eval_md(ctx, " %s (no standing motion in the data) |", v);
        continue;
      }
      eval_md(ctx, " %s %s |", v, ok ? "pass" : "**FAIL**");
      eval_check(ctx, ok, "behaviour, %s: %s: %s (bound %s %g)",
                 k_graphs[k].name, tg->what, v, tg->lower ? ">=" : "<=",
                 tg->bound);
      passed += ok;
      judged++;
    }
    eval_md(ctx, "\n");
  }
  eval_md(ctx,
          "\nThe fifth target of the issue, step + pose <= 2.0 us per "
          "character, is measured by `make bench-runtime` (docs/runtime.md)."
          "\n\n");
  eval_summary(ctx,
               "**Doing what was asked, like a person** (section 2d, issue "
               "24): %d of %d target checks pass over the CMU, sparse and "
               "Bandai Namco graphs.",
               passed, judged);
}
