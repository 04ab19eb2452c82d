/*
 * fuzz_runtime.c - fuzz target for the character API: the input bytes are a
 * program of character calls on a loaded graph (the fixture, loaded once
 * through smg_graph_load_memory): characters created with odd descriptors,
 * paths with extreme, duplicate and far-away points (and NaN/inf, which
 * must be refused), appends, constraints added/moved/removed anywhere,
 * style and action switches, IK, steering and swing-clearance settings
 * (bad values included), thresholds, and steps with dt
 * from 0 to past the limit. After every step every output must be finite
 * and bounded: the root never moves faster than the data allows, the
 * skeleton stays around the root, rotations stay unit, state fields stay
 * finite. Only public smg.h calls are made.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "fixture_graph.h"
#include "fuzz.h"
#include "smg.h"

/* The fixture's fastest root motion is the 3 m/s run; no blend or
 * correction may exceed it by much. Per step: this speed times dt, plus a
 * small allowance for the foot IK's and splices' root adjustments. */
#define FUZZ_MAX_SPEED 10.0f
#define FUZZ_JUMP_SLACK 0.05f
/* Far from the origin the root is only known to a few of the coordinate's
 * float spacings: it is the placement of the queued motion (rounded at
 * that spacing) applied to a clip-local frame (rounded again), blended
 * between the two entries a crossfade samples. A re-plan that replaces
 * the second entry rounds afresh: at x = -10^6 m (spacing 6.25 cm) one
 * step of 10^-6 s moved the root by 4 spacings (0.25 m; found by the
 * runtime fuzz target, tests/fuzz/regress/runtime/). */
#define FUZZ_ROUNDING_SPACINGS 4.0f
/* every joint within this distance of the character's ground position */
#define FUZZ_BODY_RADIUS 3.0f
#define FUZZ_PATH_MAX 64

typedef struct reader {
  const uint8_t* p;
  size_t left;
} reader;

static uint8_t take(reader* r) {
  if (!r->left) return 0;
  --r->left;
  return *r->p++;
}

static uint32_t take16(reader* r) {
  uint32_t lo = take(r);
  return lo | ((uint32_t)take(r) << 8);
}

/* A coordinate: an extreme value, the previous one nudged (0 = duplicate
 * point), or anything within +-327 m. */
static float take_coord(reader* r, float prev) {
  static const float extreme[] = {0.0f,   -0.0f,  1e-7f, -1e-7f, 1e4f,
                                  -1e4f,  1e6f,   -1e6f, 1e15f,  -1e15f,
                                  3e38f,  -3e38f, NAN,   INFINITY, 1e-38f,
                                  0.5f};
  uint8_t sel = take(r);
  if (sel < 16) return extreme[sel];
  if (sel < 160) return prev + (float)(int8_t)take(r) * 0.05f;
  return (float)(int16_t)take16(r) * 0.01f;
}

/* An arc length: a fraction of the path, beyond it, or odd values. */
static float take_arc(reader* r, float len) {
  static const float odd[] = {-1.0f, -0.0f, NAN, INFINITY, 1e30f, 1e-30f};
  uint8_t sel = take(r);
  if (sel < 6) return odd[sel];
  return len * (float)take(r) / 200.0f; /* up to 1.27 x the length */
}

static float take_dt(reader* r) {
  static const float dts[] = {0.0f,  1e-6f, 1.0f / 240, 1.0f / 120,
                              1.0f / 60, 1.0f / 30, 0.1f, 0.25f,
                              0.5f,  1.0f,  1.0001f, -1.0f,
                              NAN,   INFINITY, 1.0f / 60, 1.0f / 30};
  return dts[take(r) & 15u];
}

static smg_graph* g_graph;
static void* g_blob;
static uint32_t g_joints, g_styles, g_actions;

static void cleanup(void) {
  if (g_graph) smg_graph_destroy(g_graph);
  if (g_blob) smgi_blob_free(g_blob, NULL);
}

static int load_graph(void) {
  size_t size = 0;
  void* blob = NULL;
  smg_graph_info info;
  if (g_graph) return 1;
  if (fixture_graph_blob(&blob, &size) != SMG_OK) abort();
  g_blob = blob;
  if (smg_graph_load_memory(blob, size, NULL, &g_graph) != SMG_OK) abort();
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (smg_graph_get_info(g_graph, &info) != SMG_OK) abort();
  g_joints = info.joint_count;
  g_styles = info.style_count;
  g_actions = info.action_count;
  atexit(cleanup);
  return 1;
}

/* A float's spacing at x: far from the origin (up to SMG_MAX_COORDINATE,
 * where it is 6 cm) one step of the root can only be a whole number of
 * these, however short the step. */
static float ulp(float x) {
  x = fabsf(x);
  return nextafterf(x, INFINITY) - x;
}

static int finite3(const float* v) {
  return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* Every output after a step: finite, bounded, no jump. */
static void check_outputs(const smg_character* ch, float dt, float* prev) {
  static float rot[4 * 64], mats[16 * 64];
  float root[3], dx, dz;
  smg_character_state st;
  uint32_t j;
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  if (smg_character_get_state(ch, &st) != SMG_OK) abort();
  if (!finite3(st.position) || !isfinite(st.heading) ||
      !isfinite(st.path_distance) || !isfinite(st.path_error) ||
      !isfinite(st.sync_rate) || !isfinite(st.time) ||
      st.style >= g_styles || st.action >= g_actions)
    abort();
  if (smg_character_get_local_pose(ch, root, rot, g_joints) != SMG_OK)
    abort();
  if (!finite3(root)) abort();
  for (j = 0; j < g_joints; ++j) {
    const float* q = rot + 4 * j;
    float n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (!(n2 > 0.99f && n2 < 1.01f)) abort();
  }
  dx = root[0] - prev[0];
  dz = root[2] - prev[2];
  if (!(sqrtf(dx * dx + dz * dz) <=
        FUZZ_MAX_SPEED * dt + FUZZ_JUMP_SLACK +
            FUZZ_ROUNDING_SPACINGS * (ulp(prev[0]) + ulp(prev[2]))))
    abort();
  memcpy(prev, root, sizeof root);
  if (smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, mats,
                                       g_joints) != SMG_OK)
    abort();
  for (j = 0; j < 16 * g_joints; ++j)
    if (!isfinite(mats[j])) abort();
  for (j = 0; j < g_joints; ++j) {
    const float* t = mats + 16 * j + 12;
    if (!(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] <=
          FUZZ_BODY_RADIUS * FUZZ_BODY_RADIUS))
      abort();
  }
  if (smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                       g_joints) != SMG_OK)
    abort();
  for (j = 0; j < 16 * g_joints; ++j)
    if (!isfinite(mats[j])) abort();
}

static smg_character* create(reader* r, float* prev) {
  static const float horizons[] = {0.0f, 0.1f, 2.0f, 10.0f, 1e9f, -1.0f,
                                   NAN, 0.5f};
  static const float thresholds[] = {0.0f, 1e-6f, 0.25f, 5.0f, 1e9f,
                                     -1.0f, INFINITY, 1.0f};
  static float rot[4 * 64];
  smg_character_desc d;
  smg_character* ch = NULL;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.flags = take(r) & 15u; /* 8 is no flag: must be refused */
  d.initial_style = take(r) % (g_styles + 1);
  d.initial_action = take(r) % (g_actions + 1);
  d.path_capacity = take(r) % (FUZZ_PATH_MAX + 1);
  d.constraint_capacity = take(r) % 9u;
  d.seed = take16(r);
  d.position[0] = take_coord(r, 0.0f);
  d.position[2] = take_coord(r, 0.0f);
  d.heading = (float)(int8_t)take(r) * 0.1f;
  d.horizon = horizons[take(r) & 7u];
  d.error_threshold = thresholds[take(r) & 7u];
  if (smg_character_create(g_graph, &d, &ch) != SMG_OK) return NULL;
  if (smg_character_get_local_pose(ch, prev, rot, g_joints) != SMG_OK)
    abort();
  return ch;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  reader r;
  smg_character* ch;
  float xz[2 * FUZZ_PATH_MAX], prev[3], len;
  uint32_t ids[16], nid = 0, steps = 0;
  load_graph();
  r.p = data;
  r.left = size;
  ch = create(&r, prev);
  if (!ch) return 0;
  while (r.left && steps < 2000) {
    uint8_t op = take(&r) % 16u;
    uint32_t n, k, id = 0;
    if (smg_character_get_path_length(ch, &len) != SMG_OK || !isfinite(len))
      abort();
    switch (op) {
      case 0: /* set or append a path */
      case 1:
        n = take(&r) % (FUZZ_PATH_MAX + 1);
        for (k = 0; k < n; ++k) {
          xz[2 * k] = take_coord(&r, k ? xz[2 * k - 2] : prev[0]);
          xz[2 * k + 1] = take_coord(&r, k ? xz[2 * k - 1] : prev[2]);
        }
        if (op == 0)
          smg_character_set_path(ch, xz, n);
        else
          smg_character_append_path(ch, xz, n);
        break;
      case 2:
        smg_character_clear_path(ch);
        break;
      case 3: /* constraints, anywhere */
      case 4:
        if (op == 3)
          smg_character_add_transition(ch, take_arc(&r, len),
                                       take(&r) % (g_styles + 1), &id);
        else
          smg_character_add_splice(ch, take_arc(&r, len),
                                   take(&r) % (g_actions + 1), &id);
        if (id && nid < 16) ids[nid++] = id;
        break;
      case 5: /* move a known id, or any id */
        smg_character_move_constraint(
            ch, nid && (take(&r) & 1u) ? ids[take(&r) % nid] : take(&r),
            take_arc(&r, len));
        break;
      case 6:
        if (nid) {
          k = take(&r) % nid;
          smg_character_remove_constraint(ch, ids[k]);
          ids[k] = ids[--nid];
        } else {
          smg_character_remove_constraint(ch, take(&r));
        }
        break;
      case 7:
        smg_character_clear_constraints(ch);
        nid = 0;
        break;
      case 8:
        smg_character_set_style(ch, take(&r) % (g_styles + 1));
        break;
      case 9:
        smg_character_set_action(ch, take(&r) % (g_actions + 1));
        break;
      case 10:
        smg_character_set_ik(ch, take(&r) % 3u);
        break;
      case 11: /* the per-character settings, bad values included */
        k = take(&r) % 4u;
        if (k == 0)
          smg_character_set_error_threshold(ch, take_coord(&r, 0.25f));
        else if (k == 1)
          smg_character_set_swing_clearance(ch, take(&r) % 3u,
                                            take_coord(&r, 0.0f));
        else if (k == 2)
          smg_character_set_steering(ch, take(&r) % 3u);
        else
          smg_character_set_steering_limits(ch, take_coord(&r, 0.0f),
                                            take_coord(&r, 0.0f),
                                            take_coord(&r, 0.0f));
        break;
      case 12: /* start over with another character */
        smg_character_destroy(ch);
        nid = 0;
        ch = create(&r, prev);
        if (!ch) return 0;
        break;
      default: { /* a run of steps with one dt */
        float dt = take_dt(&r);
        n = 1 + take(&r) % 32u;
        for (k = 0; k < n; ++k, ++steps) {
          if (smg_character_step(ch, dt) != SMG_OK) break; /* refused dt */
          check_outputs(ch, dt, prev);
        }
        break;
      }
    }
  }
  smg_character_destroy(ch);
  return 0;
}

/* A walk along a bent path with a splice, a transition and steps. */
int fuzz_seed(uint32_t index, uint8_t** data, size_t* size) {
  static const uint8_t seed[] = {
      /* create: flags, style, action, path cap, constraint cap, seed,
       * x (nudge 0), z (nudge 0), heading, horizon, threshold */
      0, 0, 0, 40, 8, 7, 0, 20, 0, 20, 0, 0, 2, 2,
      /* set_path, 6 points nudged along z then x */
      0, 6, 20, 0, 20, 40, 20, 0, 20, 40, 20, 40, 20, 0, 20, 40, 20, 20,
      20, 40, 20, 40, 20, 0,
      /* add splice at 20 %, action 1; transition at 50 %, style 1 */
      4, 6, 40, 1, 3, 6, 100, 1,
      /* 32 steps at 1/60, 32 at 1/30 */
      13, 4, 31, 13, 5, 31,
      /* IK off, style 0, 32 steps at 1/120, append 2 points, 32 steps */
      10, 0, 8, 0, 13, 3, 31, 1, 2, 20, 10, 20, 10, 20, 10, 20, 10, 13,
      5, 31};
  if (index) return FUZZ_SEED_NONE;
  *size = sizeof seed;
  *data = (uint8_t*)malloc(sizeof seed);
  if (!*data) return -1;
  memcpy(*data, seed, sizeof seed);
  return 0;
}
