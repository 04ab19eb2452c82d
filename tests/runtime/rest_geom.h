/*
 * rest_geom.h - stopping, starting and turning on the spot, measured from
 * the poses a character exports (world joint positions) and nothing else:
 * no contact flags, no playback rate, no state besides the time.
 *
 * A run is recorded at a fixed step: per frame, the hips, both ankles and
 * both toes (world x, y, z) and every joint's local rotation. The legs are
 * found from the skeleton alone (rest_legs): each lower-body chain from
 * the root down to its deepest joint; toe = that joint, ankle = its
 * parent, thigh = the chain's joint three above the toe.
 *
 * Definitions (the issue's, docs/evaluation.md):
 *   floor level  of a toe: the 5th percentile of its height over the run;
 *   swing        a stretch of at least 0.1 s with the toe more than 2.5 cm
 *                above its floor level;
 *   planted      a toe within 2.5 cm of its floor level in two frames in a
 *                row; its speed is its horizontal travel between them;
 *   facing       the pelvis's forward direction: the line from the right
 *                thigh to the left one turned a quarter about +Y.
 */
#ifndef SMG_REST_GEOM_H
#define SMG_REST_GEOM_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "smg.h"

#define RG_MAX_FRAMES 1200 /* 40 s at 30 Hz */
#define RG_MAX_JOINTS 80
#define RG_BAND 0.025f     /* m: toe near its floor level */
#define RG_MIN_SWING 0.1f  /* s */
#define RG_ARRIVED 0.5f    /* m: hips this near the path's end have arrived */
#define RG_STILL 0.05f     /* m: hips within this of where they end stand */

typedef struct rg_legs {
  uint32_t toe[2], ankle[2], thigh[2]; /* [0] = left (facing +Z: +X) */
} rg_legs;

typedef struct rg_run {
  uint32_t n, J;
  float dt;
  float hips[RG_MAX_FRAMES][3];
  float toe[RG_MAX_FRAMES][2][3];
  float ankle[RG_MAX_FRAMES][2][3];
  float thigh[RG_MAX_FRAMES][2][3];
  float rot[RG_MAX_FRAMES][RG_MAX_JOINTS][4];
} rg_run;

/* The two legs: lower-body joints whose parent is the root start a chain
 * each; its toe is the deepest joint below it. Returns 0 when the skeleton
 * has no two such chains of four joints. Left/right is settled by
 * rg_orient from the first recorded frame. */
static inline int rg_find_legs(const smg_graph* g, uint32_t J, rg_legs* L) {
  int32_t parent[RG_MAX_JOINTS];
  uint32_t depth[RG_MAX_JOINTS], body[RG_MAX_JOINTS];
  if (J > RG_MAX_JOINTS) return 0;
  for (uint32_t j = 0; j < J; ++j) {
    smg_joint_info ji;
    memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    if (smg_graph_get_joint(g, j, &ji) != SMG_OK) return 0;
    parent[j] = ji.parent;
    body[j] = ji.body_part;
    depth[j] = ji.parent < 0 ? 0u : depth[ji.parent] + 1u;
  }
  uint32_t legs = 0;
  for (uint32_t top = 1; top < J && legs < 2; ++top) {
    if (parent[top] != 0 || body[top] != SMG_BODY_LOWER) continue;
    uint32_t deep = top;
    for (uint32_t j = top + 1; j < J; ++j) {
      uint32_t a = j;
      while (a > top && parent[a] >= 0) a = (uint32_t)parent[a];
      if (a == top && depth[j] > depth[deep]) deep = j;
    }
    if (depth[deep] < depth[top] + 3u) continue;
    L->toe[legs] = deep;
    L->ankle[legs] = (uint32_t)parent[deep];
    uint32_t t = (uint32_t)parent[parent[deep]];
    L->thigh[legs] = (uint32_t)parent[t];
    ++legs;
  }
  return legs == 2;
}

/* Record the current pose of ch as frame r->n. */
static inline int rg_record(rg_run* r, const smg_character* ch,
                            const rg_legs* L) {
  static float m[16 * RG_MAX_JOINTS];
  float root[3];
  if (r->n >= RG_MAX_FRAMES) return 0;
  if (smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, m, r->J) !=
          SMG_OK ||
      smg_character_get_local_pose(ch, root, &r->rot[r->n][0][0], r->J) !=
          SMG_OK)
    return 0;
  memcpy(r->hips[r->n], m + 12, sizeof(float) * 3u);
  for (int f = 0; f < 2; ++f) {
    memcpy(r->toe[r->n][f], m + 16u * L->toe[f] + 12u, sizeof(float) * 3u);
    memcpy(r->ankle[r->n][f], m + 16u * L->ankle[f] + 12u,
           sizeof(float) * 3u);
    memcpy(r->thigh[r->n][f], m + 16u * L->thigh[f] + 12u,
           sizeof(float) * 3u);
  }
  r->n++;
  return 1;
}

/* Record ch from its current pose on, one step of r->dt at a time,
 * until `after` seconds after its hips came within RG_ARRIVED of the
 * path's end (ex, ez). 0 when a step or a record fails, or the run does
 * not fit. */
static inline int rg_record_stop(rg_run* r, smg_character* ch,
                                 const rg_legs* L, float ex, float ez,
                                 float after) {
  if (!rg_record(r, ch, L)) return 0;
  uint32_t more = 0u;
  int arrived = 0;
  for (;;) {
    if (smg_character_step(ch, r->dt) != SMG_OK || !rg_record(r, ch, L))
      return 0;
    const float* h = r->hips[r->n - 1u];
    if (!arrived && hypotf(h[0] - ex, h[2] - ez) < RG_ARRIVED) {
      arrived = 1;
      more = (uint32_t)(after / r->dt + 0.5f);
    } else if (arrived && --more == 0u) {
      return 1;
    }
  }
}

/* First frame of the rest: from it on the hips stay within RG_STILL of
 * where they end. */
static inline uint32_t rg_rest_start(const rg_run* r) {
  const float* e = r->hips[r->n - 1u];
  uint32_t rest = r->n;
  while (rest > 0u && hypotf(r->hips[rest - 1u][0] - e[0],
                             r->hips[rest - 1u][2] - e[2]) <= RG_STILL)
    --rest;
  return rest;
}

static inline int rg_cmpf(const void* a, const void* b) {
  float x = *(const float*)a, y = *(const float*)b;
  return (x > y) - (x < y);
}

/* Floor level of toe f: the 5th percentile of its height over the run. */
static inline float rg_floor(const rg_run* r, int f) {
  static float h[RG_MAX_FRAMES];
  for (uint32_t i = 0; i < r->n; ++i) h[i] = r->toe[i][f][1];
  qsort(h, r->n, sizeof(float), rg_cmpf);
  return h[(r->n * 5u) / 100u];
}

/* The pelvis's facing at frame i (radians, heading convention of smg.h:
 * 0 faces +Z, forward = (sin h, 0, cos h)). */
static inline float rg_facing(const rg_run* r, uint32_t i) {
  float ax = r->thigh[i][0][0] - r->thigh[i][1][0];
  float az = r->thigh[i][0][2] - r->thigh[i][1][2];
  /* forward = (left - right) x up = (-az, 0, ax) */
  return atan2f(-az, ax);
}

/* Swings of either toe, as [start, end) frame pairs; returns the count. */
static inline uint32_t rg_swings(const rg_run* r, uint32_t (*sw)[2],
                                 uint32_t cap) {
  uint32_t k = 0;
  const uint32_t min = (uint32_t)ceilf(RG_MIN_SWING / r->dt - 1e-3f);
  for (int f = 0; f < 2; ++f) {
    const float fl = rg_floor(r, f);
    uint32_t start = 0;
    int up = 0;
    for (uint32_t i = 0; i <= r->n; ++i) {
      int u = i < r->n && r->toe[i][f][1] > fl + RG_BAND;
      if (u && !up) start = i;
      if (!u && up && i - start >= min && k < cap) {
        sw[k][0] = start;
        sw[k][1] = i;
        ++k;
      }
      up = u;
    }
  }
  return k;
}

/* Horizontal hips speed at frame i, over a window of +-w frames. */
static inline float rg_speed(const rg_run* r, uint32_t i, uint32_t w) {
  uint32_t a = i > w ? i - w : 0, b = i + w < r->n ? i + w : r->n - 1u;
  if (b <= a) return 0.0f;
  float dx = r->hips[b][0] - r->hips[a][0], dz = r->hips[b][2] - r->hips[a][2];
  return sqrtf(dx * dx + dz * dz) / ((float)(b - a) * r->dt);
}

/* A start from rest at frame p0, judged as the issue does: the longest
 * swing beginning in its first 2 s against the median swing of the
 * steady walk 3-7 s in (*swing_ratio), that walk's median hips speed
 * (*steady, m/s, 0.5 s windows) and the seconds until the hips first move
 * at 80 % of it (*reach_80; INFINITY: never). 0 when the steady walk has
 * fewer than three swings to take a median of. */
static inline int rg_start_gait(const rg_run* r, uint32_t p0,
                                float* swing_ratio, float* steady,
                                float* reach_80) {
  const float fps = 1.0f / r->dt;
  const uint32_t hw = (uint32_t)(0.25f * fps);
  *swing_ratio = *steady = 0.0f;
  *reach_80 = INFINITY;
  const uint32_t early = p0 + (uint32_t)(2.0f * fps);
  const uint32_t s0 = p0 + (uint32_t)(3.0f * fps);
  const uint32_t s1 = p0 + (uint32_t)(7.0f * fps);
  uint32_t sw[256][2];
  uint32_t k = rg_swings(r, sw, 256), c = 0;
  float len[256], longest = 0.0f;
  for (uint32_t i = 0; i < k; ++i) {
    float l = (float)(sw[i][1] - sw[i][0]);
    if (sw[i][0] >= p0 && sw[i][0] < early && l > longest) longest = l;
    if (sw[i][0] >= s0 && sw[i][1] <= s1) len[c++] = l;
  }
  if (c < 3) return 0;
  qsort(len, c, sizeof(float), rg_cmpf);
  *swing_ratio = longest / len[c / 2u];
  float v[256];
  uint32_t nv = 0;
  for (uint32_t i = s0; i < s1 && nv < 256; ++i) v[nv++] = rg_speed(r, i, hw);
  qsort(v, nv, sizeof(float), rg_cmpf);
  *steady = v[nv / 2u];
  for (uint32_t i = p0; i < s1; ++i)
    if (rg_speed(r, i, hw) >= 0.8f * *steady) {
      *reach_80 = (float)(i - p0) * r->dt;
      break;
    }
  return 1;
}

/* Planted toe speeds (cm/s) over frames [a, b): the fastest, and the
 * 95th percentile in *p95 when given. */
static inline float rg_planted(const rg_run* r, uint32_t a, uint32_t b,
                               float* p95) {
  static float v[2 * RG_MAX_FRAMES];
  uint32_t n = 0;
  float best = 0.0f;
  for (int f = 0; f < 2; ++f) {
    const float fl = rg_floor(r, f);
    for (uint32_t i = a > 0 ? a : 1u; i < b && i < r->n; ++i) {
      if (r->toe[i][f][1] > fl + RG_BAND ||
          r->toe[i - 1][f][1] > fl + RG_BAND)
        continue;
      float dx = r->toe[i][f][0] - r->toe[i - 1][f][0];
      float dz = r->toe[i][f][2] - r->toe[i - 1][f][2];
      float sp = 100.0f * sqrtf(dx * dx + dz * dz) / r->dt;
      v[n++] = sp;
      if (sp > best) best = sp;
    }
  }
  if (p95) {
    qsort(v, n, sizeof(float), rg_cmpf);
    *p95 = n ? v[(n * 95u) / 100u] : 0.0f;
  }
  return best;
}

/* Fastest planted toe (cm/s) over frames [a, b). */
static inline float rg_planted_max(const rg_run* r, uint32_t a, uint32_t b) {
  return rg_planted(r, a, b, NULL);
}

/* Swap the legs when the pose at frame 0 faces away from `heading`. */
static inline void rg_orient(rg_run* r, rg_legs* L, float heading) {
  float d = remainderf(rg_facing(r, 0) - heading, 6.2831853f);
  if (fabsf(d) < 1.5707963f) return;
  for (int k = 0; k < 3; ++k) {
    uint32_t* v = k == 0 ? L->toe : k == 1 ? L->ankle : L->thigh;
    uint32_t t = v[0];
    v[0] = v[1];
    v[1] = t;
  }
  r->n = 0;
}

/* The largest range (degrees) any joint's local rotation covers over
 * frames [a, a + w): the angle between its two most different
 * orientations in the window, found against the window's first frame
 * (at least half the true range, and exactly it for motion about one
 * axis). */
static inline float rg_motion_range(const rg_run* r, uint32_t a, uint32_t w) {
  float best = 0.0f;
  for (uint32_t j = 0; j < r->J; ++j) {
    const float* q0 = r->rot[a][j];
    for (uint32_t i = a + 1; i < a + w && i < r->n; ++i) {
      const float* q = r->rot[i][j];
      float d = fabsf(q0[0] * q[0] + q0[1] * q[1] + q0[2] * q[2] +
                      q0[3] * q[3]);
      float deg = 2.0f * acosf(d > 1.0f ? 1.0f : d) * 57.29578f;
      if (deg > best) best = deg;
    }
  }
  return best;
}

#endif /* SMG_REST_GEOM_H */
