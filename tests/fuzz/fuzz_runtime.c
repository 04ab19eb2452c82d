/*
 * fuzz_runtime.c - fuzz target for the character API: the input bytes are a
 * program of character calls on a loaded graph (the fixture, loaded once
 * through smg_graph_load_memory): characters created with odd descriptors,
 * paths with extreme, duplicate and far-away points (and NaN/inf, which
 * must be refused), appends, constraints added/moved/removed anywhere,
 * style and action switches, IK, steering and swing-clearance settings
 * (bad values included), thresholds, the game-scene calls (ground heights
 * at the probes or anywhere, an engine's mover putting the character
 * elsewhere, events read into odd buffers), and steps with dt
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

/* The events of the last step: read with odd capacities and element
 * sizes; what is read must make sense. */
static void check_events(const smg_character* ch, reader* r) {
  /* room for 16 elements of up to 255 bytes */
  static smg_event buf[16 * 256 / sizeof(smg_event) + 1];
  uint32_t count = 0, n = 0, k, size;
  smg_result res;
  if (smg_character_get_events(ch, NULL, 0, &count) != SMG_OK) abort();
  size = take(r) & 1u ? (uint32_t)sizeof(smg_event) : take(r);
  buf[0].struct_size = size;
  k = take(r) % 17u;
  res = smg_character_get_events(ch, buf, k, &n);
  if (size < sizeof(smg_event) || size % 4u) {
    if (res != SMG_ERROR_INVALID_ARGUMENT) abort();
    return;
  }
  if (res == SMG_ERROR_BUFFER_TOO_SMALL) {
    if (n != count || k >= count) abort();
    return;
  }
  if (res != SMG_OK || n != count) abort();
  for (k = 0; k < n; ++k) {
    smg_event copy;
    const smg_event* e = &copy;
    memcpy(&copy, (const unsigned char*)buf + (size_t)k * size, sizeof copy);
    if (copy.struct_size != size) abort();
    if (e->type < SMG_EVENT_CONSTRAINT || e->type > SMG_EVENT_PATH_END ||
        !finite3(e->position) || !isfinite(e->strength) ||
        !(e->strength >= 0.0f) || !isfinite(e->arc_length))
      abort();
    if (e->type == SMG_EVENT_FOOTSTEP && e->id > 1u) abort();
    if (e->type == SMG_EVENT_CONSTRAINT &&
        e->value >= ((e->flags & SMG_EVENT_SPLICE) ? g_actions : g_styles))
      abort();
  }
}

/* An engine's mover: the root motion, moved on (or anywhere: bad values
 * included) and handed back. The root may then be anywhere: prev follows. */
static void mover(smg_character* ch, reader* r, float* prev) {
  static float rot[4 * 64];
  smg_root_motion m;
  smg_character_state st;
  float p[3];
  memset(&m, 0, sizeof m);
  m.struct_size = sizeof m;
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  if (smg_character_get_root_motion(ch, &m) != SMG_OK ||
      smg_character_get_state(ch, &st) != SMG_OK)
    abort();
  if (!finite3(m.translation) || !finite3(m.local_translation) ||
      !isfinite(m.yaw))
    abort();
  p[0] = take_coord(r, st.position[0] + m.translation[0]);
  p[1] = take_coord(r, st.position[1]);
  p[2] = take_coord(r, st.position[2] + m.translation[2]);
  smg_character_set_ground_position(ch, p, take_coord(r, st.heading));
  if (smg_character_get_local_pose(ch, prev, rot, g_joints) != SMG_OK)
    abort();
}

/* Ground heights at the probes, or odd ones; sometimes taken back. */
static void ground(smg_character* ch, reader* r) {
  smg_ground gr;
  float p[6];
  uint32_t k;
  if (smg_character_get_ground_probes(ch, p, 3) != SMG_OK) abort();
  for (k = 0; k < 6; ++k)
    if (!isfinite(p[k])) abort();
  if (take(r) % 8u == 0u) {
    smg_character_set_ground(ch, NULL);
    return;
  }
  memset(&gr, 0, sizeof gr);
  gr.struct_size = take(r) % 4u ? (uint32_t)sizeof gr : take(r);
  gr.flags = take(r) % 8u == 0u;
  gr.foot_height[0] = take_coord(r, 0.0f);
  gr.foot_height[1] = take_coord(r, gr.foot_height[0]);
  gr.root_height = take_coord(r, gr.foot_height[1]);
  smg_character_set_ground(ch, &gr);
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
    /* the three highest bytes are the game-scene calls (ops 16-18; they
     * were steps before those existed), the others as they always were */
    const uint8_t byte = take(&r);
    uint8_t op = byte >= 253u ? (uint8_t)(16u + byte - 253u) : byte % 16u;
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
      case 16:
        ground(ch, &r);
        break;
      case 17:
        mover(ch, &r, prev);
        break;
      case 18:
        check_events(ch, &r);
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

/* Seed 0: a walk along a bent path with a splice, a transition and steps.
 * Seed 1: the same walk in a game scene: ground heights, a mover that
 * takes the root motion, events read after the steps. */
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
  static const uint8_t scene[] = {
      /* ground: struct_size as is, no flags, heights 0, +0.05, +0.05 m */
      253, 1, 1, 1, 20, 0, 20, 1, 20, 0,
      /* 8 steps at 1/60, events (size as is, capacity 16), mover (moved
       * on by the root motion, nudged), 8 steps, events, mover */
      13, 4, 7, 255, 1, 16, 254, 20, 0, 20, 0, 20, 1, 20, 0,
      13, 4, 7, 255, 1, 16, 254, 20, 0, 20, 0, 20, 0, 20, 0,
      /* ground again higher, 16 steps at 1/30, events, taken back */
      253, 1, 1, 1, 20, 4, 20, 0, 20, 0, 13, 5, 15, 255, 1, 16, 253, 0, 13,
      4, 3};
  size_t n;
  if (index > 1) return FUZZ_SEED_NONE;
  n = index ? sizeof seed + sizeof scene : sizeof seed;
  *data = (uint8_t*)malloc(n);
  if (!*data) return -1;
  memcpy(*data, seed, sizeof seed);
  if (index) memcpy(*data + sizeof seed, scene, sizeof scene);
  *size = n;
  return 0;
}
