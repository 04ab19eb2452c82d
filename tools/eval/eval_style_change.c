/*
 * eval_style_change.c - where a style change happened on a straight line,
 * from the hips (definitions in eval_style_change.h).
 */
#include "eval_style_change.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_feet_geom.h"

/* Whether the hips of frame i lie in the measured stretch. */
static int measured(const eval_style_line* line, const eval_track* t,
                    size_t i) {
  const double arc = t->hips[3 * i + 2];
  return arc >= line->margin && arc <= line->length - line->margin;
}

double eval_style_floor(const eval_style_line* line, const eval_track* t) {
  size_t first = t->frames, last = 0;
  for (size_t i = 0; i < t->frames; ++i) {
    if (!measured(line, t, i)) continue;
    if (first == t->frames) first = i;
    last = i;
  }
  if (first == t->frames) return NAN;
  const double* toes = t->toes + 6 * first;
  const size_t n = last - first + 1;
  const double a = eval_feet_floor_level(toes, 6, n);
  const double b = eval_feet_floor_level(toes + 3, 6, n);
  return a < b ? a : b;
}

/* The signature of frame i over the window centred on it. */
static void signature(const eval_style_line* line, const eval_track* t,
                      size_t i, double floor_y, double* out) {
  const size_t h = (size_t)(EVAL_SIG_WINDOW * line->rate / 2.0);
  const size_t a = i >= h ? i - h : 0;
  const size_t b = i + h < t->frames ? i + h : t->frames - 1;
  const double n = (double)(b - a + 1);
  double travelled = 0.0, y = 0.0, yy = 0.0, x = 0.0, xx = 0.0;
  for (size_t k = a; k <= b; ++k) {
    const double* p = t->hips + 3 * k;
    if (k > a) travelled += hypot(p[0] - p[-3], p[2] - p[-1]);
    y += p[1];
    yy += p[1] * p[1];
    x += p[0];
    xx += p[0] * p[0];
  }
  out[EVAL_SIG_SPEED] =
      b > a ? travelled * line->rate / (double)(b - a) : 0.0;
  out[EVAL_SIG_HEIGHT] = y / n - floor_y;
  out[EVAL_SIG_BOUNCE] = sqrt(fmax(yy / n - (y / n) * (y / n), 0.0));
  out[EVAL_SIG_SWAY] = sqrt(fmax(xx / n - (x / n) * (x / n), 0.0));
}

/* A run's windows in the measured stretch: arc length and signature. */
typedef struct series {
  size_t n;
  double* arc;
  double* v; /* EVAL_SIG_DIM per window */
} series;

static void series_free(series* s) {
  free(s->arc);
  free(s->v);
  memset(s, 0, sizeof *s);
}

static int series_of(const eval_style_line* line, const eval_track* t,
                     series* s) {
  const double fl = eval_style_floor(line, t);
  memset(s, 0, sizeof *s);
  if (t->frames == 0) return 0;
  s->arc = (double*)malloc(t->frames * sizeof(double));
  s->v = (double*)malloc(t->frames * EVAL_SIG_DIM * sizeof(double));
  if (!s->arc || !s->v) {
    series_free(s);
    return 0;
  }
  for (size_t i = 0; i < t->frames; ++i) {
    if (!measured(line, t, i)) continue;
    s->arc[s->n] = t->hips[3 * i + 2];
    signature(line, t, i, fl, s->v + EVAL_SIG_DIM * s->n);
    ++s->n;
  }
  return s->n >= 2;
}

static void series_stats(const series* s, double* mean, double* sd) {
  for (int d = 0; d < EVAL_SIG_DIM; ++d) {
    double m = 0.0, q = 0.0;
    for (size_t i = 0; i < s->n; ++i) m += s->v[EVAL_SIG_DIM * i + d];
    m /= (double)s->n;
    for (size_t i = 0; i < s->n; ++i) {
      const double e = s->v[EVAL_SIG_DIM * i + d] - m;
      q += e * e;
    }
    mean[d] = m;
    sd[d] = sqrt(q / (double)s->n);
  }
}

/* Squared distance, in units u, from window v to the nearest window of
 * series c; `own` >= 0 leaves out c's windows that overlap window `own`
 * of the same run (a window matches itself and its neighbours). */
static double nearest(const double* v, const series* c, const double* u,
                      long own, long overlap) {
  double best = INFINITY;
  for (size_t j = 0; j < c->n; ++j) {
    if (own >= 0 && labs((long)j - own) < overlap) continue;
    double q = 0.0;
    for (int d = 0; d < EVAL_SIG_DIM; ++d) {
      const double e = (v[d] - c->v[EVAL_SIG_DIM * j + d]) / u[d];
      q += e * e;
    }
    if (q < best) best = q;
  }
  return best;
}

/* Label each window of s: 1 when its nearest window of the calibration
 * runs is B's. `own` (0: A, 1: B, -1: neither) is the calibration run s
 * itself is. */
static void label_windows(const series* s, const series* ca,
                          const series* cb, const double* u, int own,
                          long overlap, unsigned char* lab) {
  for (size_t i = 0; i < s->n; ++i) {
    const double* v = s->v + EVAL_SIG_DIM * i;
    const double da = nearest(v, ca, u, own == 0 ? (long)i : -1, overlap);
    const double db = nearest(v, cb, u, own == 1 ? (long)i : -1, overlap);
    lab[i] = db < da;
  }
}

/* The split (at least a metre of windows on each side) that agrees with
 * the most labels, A before and B after: *at gets the arc halfway between
 * the windows either side; returns the share of windows it agrees with
 * (0 when the series is too short). */
static double best_split(const series* s, const unsigned char* lab,
                         double* at) {
  size_t b_total = 0, b_before = 0, best_k = 0, best_wrong = (size_t)-1;
  for (size_t i = 0; i < s->n; ++i) b_total += lab[i];
  for (size_t k = 1; k < s->n; ++k) {
    b_before += lab[k - 1];
    if (s->arc[k - 1] - s->arc[0] < 1.0 || s->arc[s->n - 1] - s->arc[k] < 1.0)
      continue;
    /* B labels before the split and A labels after it */
    const size_t wrong = b_before + (s->n - k) - (b_total - b_before);
    if (wrong < best_wrong) {
      best_wrong = wrong;
      best_k = k;
    }
  }
  if (best_k == 0) return 0.0;
  *at = 0.5 * (s->arc[best_k - 1] + s->arc[best_k]);
  return 1.0 - (double)best_wrong / (double)s->n;
}

int eval_style_change_measure(const eval_style_line* line,
                              const eval_track* a, const eval_track* b,
                              const eval_track* sw, eval_style_change* out) {
  const eval_track* t[3] = {a, b, sw};
  const long overlap = (long)(EVAL_SIG_WINDOW * line->rate);
  series s[3];
  double u[EVAL_SIG_DIM];
  unsigned char* lab = NULL;
  int ok = 1;
  memset(s, 0, sizeof s);
  memset(out, 0, sizeof *out);
  for (int k = 0; k < 3 && ok; ++k) ok = series_of(line, t[k], &s[k]);
  if (ok) {
    size_t nmax = s[0].n > s[1].n ? s[0].n : s[1].n;
    if (s[2].n > nmax) nmax = s[2].n;
    lab = (unsigned char*)malloc(nmax);
    ok = lab != NULL;
  }
  if (ok) {
    series_stats(&s[0], out->mean[0], out->sd[0]);
    series_stats(&s[1], out->mean[1], out->sd[1]);
    for (int d = 0; d < EVAL_SIG_DIM; ++d)
      u[d] = fmax(0.5 * (out->sd[0][d] + out->sd[1][d]), 1e-3);
    /* how well the labels tell the styles apart on runs without a
     * change */
    size_t right = 0;
    label_windows(&s[0], &s[0], &s[1], u, 0, overlap, lab);
    for (size_t i = 0; i < s[0].n; ++i) right += !lab[i];
    label_windows(&s[1], &s[0], &s[1], u, 1, overlap, lab);
    for (size_t i = 0; i < s[1].n; ++i) right += lab[i];
    out->told = (double)right / (double)(s[0].n + s[1].n);
    label_windows(&s[2], &s[0], &s[1], u, -1, overlap, lab);
    out->agree = best_split(&s[2], lab, &out->at);
  }
  free(lab);
  for (int k = 0; k < 3; ++k) series_free(&s[k]);
  return ok;
}
