/*
 * sync.c - synchronization of the upper body with the lower body (paper
 * III.C.3). The upper body's playback rate is warped so that its cycle
 * follows the lower body's:
 *  - A range starts at the splice point (where the baker already matched
 *    upper and lower) and runs to the next splice or transition point; the
 *    lower window used for registration never crosses the range's end.
 *  - Without constraint points ahead, ranges follow the support legs
 *    (Menardais et al. 2004): each frame is described by its support state
 *    (left/right contact) and gait phase from FRMI, so aligning these
 *    features aligns support-leg changes of the upper clip's own recorded
 *    feet with the locomotion's.
 *  - Inside the range a small dynamic time warp (Kovar & Gleicher 2003
 *    registration, open-ended on the upper side) aligns the next
 *    SMGI_SYNC_LOWER lower frames with the next SMGI_SYNC_UPPER upper
 *    frames; the slope of the warp is the playback rate, clamped to
 *    [0.5, 2] and smoothed. When the upper clip carries no gait
 *    information every alignment costs the same and ties prefer the
 *    diagonal, so the rate stays 1.
 * The warp is recomputed only when the lower playhead enters a new frame:
 * at most 8 x 16 cells, bounded and amortized.
 */
#include <math.h>
#include <stdlib.h>

#include "sync.h"

#include "rmath.h"
#include "tuning.h"

static void features(const smg_graph* g, uint32_t frame, float* f) {
  const smgi_frame* fr = &g->data.frames[frame];
  f[0] = (fr->flags & SMGI_FRAME_LEFT_CONTACT) ? 1.0f : 0.0f;
  f[1] = (fr->flags & SMGI_FRAME_RIGHT_CONTACT) ? 1.0f : 0.0f;
  if (fr->phase >= 0.0f) {
    smgi_sincosf(2.0f * SMGI_PI * fr->phase, &f[3], &f[2]);
  } else {
    f[2] = f[3] = 0.0f;
  }
}

static float dist(const float* a, const float* b) {
  float d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2],
        d3 = a[3] - b[3];
  return d0 * d0 + d1 * d1 + d2 * d2 + d3 * d3;
}

/* Gait phase of the k-th lower frame ahead of the playhead (upper = 0)
 * or of the k-th upper frame ahead (upper = 1); -1 when unknown. */
static float phase_at(const smg_graph* g, const smgi_lower* l,
                      const smgi_upper* u, uint32_t k, int upper) {
  if (!upper) {
    uint32_t entry, offset;
    if (!smgi_q_locate(l, g->data.lower_edges, k, &entry, &offset)) return -1.0f;
    const smgi_edge* e = &g->data.lower_edges[smgi_q_at_c(l, entry)->edge];
    return g->data.frames[e->first_frame + offset].phase;
  }
  const smgi_edge* ue = g->data.upper_edges;
  uint32_t edge = u->edge, off = (uint32_t)u->t + k;
  if (off >= ue[edge].frame_count) {
    off -= ue[edge].frame_count;
    edge = u->next;
    if (off >= ue[edge].frame_count) return -1.0f;
  }
  return g->data.frames[ue[edge].first_frame + off].phase;
}

/* Mean phase advance per frame over the next `count` frames (cycles per
 * frame), skipping unknown phases and jumps (graph transitions). */
static int phase_speed(const smg_graph* g, const smgi_lower* l,
                       const smgi_upper* u, uint32_t count, int upper,
                       float* out) {
  float sum = 0.0f;
  uint32_t used = 0;
  float prev = phase_at(g, l, u, 0, upper);
  for (uint32_t k = 1; k < count; ++k) {
    float p = phase_at(g, l, u, k, upper);
    if (p >= 0.0f && prev >= 0.0f) {
      float d = p - prev;
      d -= floorf(d); /* [0, 1): phase only moves forward */
      if (d < 0.2f) {
        sum += d;
        ++used;
      }
    }
    prev = p;
  }
  if (used < 2u || !(sum > 0.0f)) return 0;
  *out = sum / (float)used;
  return 1;
}

void smgi_sync_update(smgi_sync* sy, const smgi_upper* u,
                      const smgi_lower* l, const smgi_step_in* in) {
  if (u->action == 0) {
    smgi_sync_reset(sy);
    return;
  }
  const smg_graph* g = in->graph;
  const smgi_edge* le = g->data.lower_edges;
  const smgi_edge* ue = g->data.upper_edges;
  float lf[SMGI_SYNC_LOWER][4], uf[SMGI_SYNC_UPPER][4];

  /* lower window, clipped at the end of the synchronizing range */
  float range_end = smgi_next_constraint_arc(in->cons, in->progress);
  uint32_t n = 0;
  for (; n < SMGI_SYNC_LOWER; ++n) {
    uint32_t entry, offset;
    if (!smgi_q_locate(l, g->data.lower_edges, n, &entry, &offset)) break;
    const smgi_qentry* q = smgi_q_at_c(l, entry);
    const smgi_edge* e = &le[q->edge];
    float s = q->s_start +
              (q->s_end - q->s_start) * (float)offset / (float)e->frame_count;
    if (n > 0 && s >= range_end) break;
    features(g, e->first_frame + offset, lf[n]);
  }
  if (n < 3u) return; /* too short to register: keep the current rate */

  /* upper window: the current edge, then the chosen successor */
  uint32_t m = 0;
  uint32_t edge = u->edge, off = (uint32_t)u->t;
  for (; m < SMGI_SYNC_UPPER; ++m) {
    if (off >= ue[edge].frame_count) {
      if (edge != u->edge) break;
      edge = u->next;
      off = 0;
    }
    features(g, ue[edge].first_frame + off, uf[m]);
    ++off;
  }
  if (m < 3u) return;

  /* With gait phase on both sides (FRMI), the rate is the ratio of their
   * phase speeds - the upper cycle then takes as long as the lower one -
   * with a gentle pull towards equal phase (Menardais et al.: the same
   * support leg at the same time). The short windows below cannot see a
   * whole cycle, and a warp over a fraction of a cycle mistook the
   * 06_10 dribble (1.41 s cycle) over the 06_01 walk (1.23 s) for a rate
   * of 0.8 instead of 1.14. */
  {
    float sl, su;
    if (phase_speed(g, l, u, n, 0, &sl) && phase_speed(g, l, u, m, 1, &su) &&
        su > 1e-4f) {
      float pl = phase_at(g, l, u, 0, 0), pu = phase_at(g, l, u, 0, 1);
      float rate = sl / su;
      if (pl >= 0.0f && pu >= 0.0f) {
        float dphi = pl - pu;
        dphi -= floorf(dphi + 0.5f); /* (-0.5, 0.5] cycles */
        /* Continuous with the last update's error: once the lock has
         * chosen which way to make up a difference it keeps going that
         * way, even when further jumps (an action graph that had to keep
         * transitions between different gait phases, docs/baker.md) take
         * the difference past half a cycle. Wrapped, it would turn round
         * there and make the rest up the other way: a whole stride
         * slipped against the legs. Up to a cycle; a difference beyond is
         * let go as a slip. */
        float prev = sy->error;
        if (prev == prev) dphi += floorf(prev - dphi + 0.5f);
        if (dphi > 1.0f) dphi -= 1.0f;
        if (dphi < -1.0f) dphi += 1.0f;
        sy->error = dphi;
        rate *= 1.0f + SMGI_SYNC_PHASE_LOCK * dphi;
      } else {
        sy->error = NAN;
      }
      rate = smgi_clampf(rate, SMGI_SYNC_RATE_MIN, SMGI_SYNC_RATE_MAX);
      sy->rate += SMGI_SYNC_SMOOTH * (rate - sy->rate);
      sy->rate = smgi_clampf(sy->rate, SMGI_SYNC_RATE_MIN, SMGI_SYNC_RATE_MAX);
      return;
    }
  }

  /* DTW with an open end on the upper side */
  float C[SMGI_SYNC_LOWER][SMGI_SYNC_UPPER];
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < m; ++j) {
      float d = dist(lf[i], uf[j]);
      float best;
      if (i == 0 && j == 0) {
        best = 0.0f;
      } else {
        /* ties prefer the diagonal (rate 1), then the lower's step */
        float diag = (i > 0 && j > 0) ? C[i - 1u][j - 1u] : INFINITY;
        float up = i > 0 ? C[i - 1u][j] : INFINITY;
        float left = j > 0 ? C[i][j - 1u] : INFINITY;
        best = diag;
        if (up < best) best = up;
        if (left < best) best = left;
      }
      C[i][j] = d + best;
    }
  }
  uint32_t jend = 0;
  float cbest = INFINITY;
  for (uint32_t j = 0; j < m; ++j) {
    float c = C[n - 1u][j];
    /* equal cost: prefer the end nearest the diagonal */
    int nearer = abs((int)j - (int)(n - 1u)) < abs((int)jend - (int)(n - 1u));
    if (c < cbest - 1e-6f || (fabsf(c - cbest) <= 1e-6f && nearer)) {
      cbest = c;
      jend = j;
    }
  }
  float rate = (float)jend / (float)(n - 1u);
  rate = smgi_clampf(rate, SMGI_SYNC_RATE_MIN, SMGI_SYNC_RATE_MAX);
  sy->rate += SMGI_SYNC_SMOOTH * (rate - sy->rate);
  sy->rate = smgi_clampf(sy->rate, SMGI_SYNC_RATE_MIN, SMGI_SYNC_RATE_MAX);
}
