/*
 * fixture_graph.h - a small, valid, hand-built motion graph for tests.
 *
 * Header-only (static inline functions, no allocation except in
 * fixture_graph_blob). Fill a fixture_graph with fixture_graph_build(); its
 * `data` member is an smgi_graph_data whose pointers aim into the struct
 * itself, ready for smgi_blob_write. The struct is ~100 KB: make it static
 * or heap-allocate it (fixture_graph_new/_delete), don't put it on a small
 * stack.
 *
 * What it contains (synthetic, analytic motion; NOT motion capture):
 *   Skeleton  the 31-joint CMU hierarchy (Hips, LHipJoint, LeftUpLeg, ...,
 *             RThumb; same names and order as the CMU BVH files) with the
 *             rest offsets of CMU subject 02 in metres (x 0.056444).
 *             Legs: left {2,3,4,5}, right {7,8,9,10}; pelvis 0; spine
 *             base 11 (LowerBack). Body parts: 0 root, 1..10 lower,
 *             11..30 upper. Mirrors pair Left.. with Right.. joints. Mass ratios
 *             after Ae et al. 1996 (sum 1).
 *   Rate      30 frames per second. Root height ~0.95 m, floor at y = 0.
 *   Styles    0 "walk", 1 "run".   Actions 0 "none", 1 "punch".
 *   Frames    (clip-space root motion; every clip starts at the origin,
 *             heading 0, facing +Z)
 *     [  0, 30)  clip 0 "walk_straight"  one gait cycle, 1.2 m/s along +Z
 *     [ 30, 60)  clip 1 "walk_left"      same gait turning left +45 deg
 *     [ 60, 90)  clip 2 "walk_right"     same gait turning right -45 deg
 *     [ 90,110)  clip 3 "run_straight"   one run cycle, 3.0 m/s along +Z
 *     [110,120)  clip 4 "walk_to_run"    blend (SMGI_CLIP_BLEND) walk->run
 *     [120,130)  clip 5 "run_to_walk"    blend run->walk
 *     [130,160)  clip 6 "walk_punch"     upper clip (action 1): walking
 *                                        with a right-arm punch
 *   Phase     FRMI.phase is the gait phase in [0,1), 0 = left foot-strike;
 *             contact flags are set from it.
 *   Lower graph (node -> edges, edges sorted by `from`):
 *     node 0 "walk" (frame 0): e0 0->0 straight [0,30), e1 0->0 left
 *       [30,60), e2 0->0 right [60,90), e3 0->1 walk_to_run [110,120)
 *       (TRANSITION|STYLE_CHANGE, label run, cost 0.2)
 *     node 1 "run" (frame 90): e4 1->1 run [90,110), e5 1->0 run_to_walk
 *       [120,130) (TRANSITION|STYLE_CHANGE, label walk, cost 0.2)
 *   Upper graph: node 0 (frame 130), node 1 (frame 145), both "punch";
 *     e0 0->1 [130,145), e1 1->0 [145,160).
 *   Splices: (lower_frame 0, punch, upper edge 0, offset 0, identity),
 *            (15, punch, edge 1, offset 0, 5 deg about Y),
 *            (90, punch, edge 0, offset 3, 10 deg about Y).
 *   Each edge's displacement is the ground transform (dx, dz, dheading) of
 *   the pose after its last frame relative to its from-node's frame, and
 *   its arc_length the ground distance travelled: the same meaning the
 *   baker produces.
 */
#ifndef SMG_TESTS_FIXTURE_GRAPH_H
#define SMG_TESTS_FIXTURE_GRAPH_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "quat_pack.h"
#include "smg_format.h"

#define FIXTURE_JOINTS 31u
#define FIXTURE_FRAMES 160u
#define FIXTURE_STRIDE (3u + 4u * FIXTURE_JOINTS)
#define FIXTURE_CLIPS 7u
#define FIXTURE_LOWER_NODES 2u
#define FIXTURE_LOWER_EDGES 6u
#define FIXTURE_UPPER_NODES 2u
#define FIXTURE_UPPER_EDGES 2u
#define FIXTURE_SPLICES 3u
#define FIXTURE_STRINGS_MAX 1024u
#define FIXTURE_FPS 30.0f
#define FIXTURE_WALK_SPEED 1.2f
#define FIXTURE_RUN_SPEED 3.0f
#define FIXTURE_PI 3.14159265358979f

typedef struct fixture_graph {
  smgi_info info;
  char strings[FIXTURE_STRINGS_MAX];
  uint32_t strings_used;
  smgi_joint joints[FIXTURE_JOINTS];
  smgi_label styles[2];
  smgi_label actions[2];
  smgi_clip clips[FIXTURE_CLIPS];
  float poses[FIXTURE_FRAMES * FIXTURE_STRIDE]; /* generated, floats */
  /* the blob's POSE records packed from `poses` (uint32_t for alignment) */
  uint32_t pose_records[FIXTURE_FRAMES *
                        SMGI_POSE_RECORD_SIZE(FIXTURE_JOINTS) / 4u];
  smgi_frame frames[FIXTURE_FRAMES];
  smgi_node lower_nodes[FIXTURE_LOWER_NODES];
  smgi_edge lower_edges[FIXTURE_LOWER_EDGES];
  smgi_node upper_nodes[FIXTURE_UPPER_NODES];
  smgi_edge upper_edges[FIXTURE_UPPER_EDGES];
  smgi_splice splices[FIXTURE_SPLICES];
  /* ground (x, z, heading) just after each clip's last frame, clip space */
  float clip_end_ground[FIXTURE_CLIPS][3];
  smgi_graph_data data; /* the view to hand to smgi_blob_write */
} fixture_graph;

/* ---- small helpers --------------------------------------------------------- */

static inline uint32_t fixture_add_string(fixture_graph* f, const char* s) {
  uint32_t off = f->strings_used, n = (uint32_t)strlen(s) + 1u;
  if (off + n > FIXTURE_STRINGS_MAX) abort(); /* fixture bug, not a test */
  memcpy(f->strings + off, s, n);
  f->strings_used += n;
  return off;
}

/* q = axis-angle (unit axis) */
static inline void fixture_quat_axis(float* q, float ax, float ay, float az,
                                     float angle) {
  float s = sinf(0.5f * angle);
  q[0] = ax * s;
  q[1] = ay * s;
  q[2] = az * s;
  q[3] = cosf(0.5f * angle);
}

/* out = a * b (apply b first) */
static inline void fixture_quat_mul(float* out, const float* a,
                                    const float* b) {
  float r[4];
  r[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  r[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  r[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  r[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  memcpy(out, r, sizeof r);
}

/* ---- skeleton ----------------------------------------------------------- */

static inline void fixture_build_skeleton(fixture_graph* f) {
  /* CMU subject 02 offsets in file units; scaled to metres below. */
  static const struct {
    const char* name;
    int32_t parent;
    uint32_t part, mirror;
    float off[3];
    float mass;
  } k[FIXTURE_JOINTS] = {
      {"Hips", -1, 0, 0, {0, 0, 0}, 0.187f},
      {"LHipJoint", 0, 1, 6, {0, 0, 0}, 0},
      {"LeftUpLeg", 1, 1, 7, {1.65674f, -1.80282f, 0.62477f}, 0.110f},
      {"LeftLeg", 2, 1, 8, {2.59720f, -7.13576f, 0}, 0.051f},
      {"LeftFoot", 3, 1, 9, {2.49236f, -6.84770f, 0}, 0.011f},
      {"LeftToeBase", 4, 1, 10, {0.19704f, -0.54136f, 2.14581f}, 0},
      {"RHipJoint", 0, 1, 1, {0, 0, 0}, 0},
      {"RightUpLeg", 6, 1, 2, {-1.61070f, -1.80282f, 0.62476f}, 0.110f},
      {"RightLeg", 7, 1, 3, {-2.59502f, -7.12977f, 0}, 0.051f},
      {"RightFoot", 8, 1, 4, {-2.46780f, -6.78024f, 0}, 0.011f},
      {"RightToeBase", 9, 1, 5, {-0.23024f, -0.63258f, 2.13368f}, 0},
      {"LowerBack", 0, 2, 11, {0, 0, 0}, 0},
      {"Spine", 11, 2, 12, {0.01961f, 2.05450f, -0.14112f}, 0.151f},
      {"Spine1", 12, 2, 13, {0.01021f, 2.06436f, -0.05921f}, 0.151f},
      {"Neck", 13, 2, 14, {0, 0, 0}, 0},
      {"Neck1", 14, 2, 15, {0.00713f, 1.56711f, 0.14968f}, 0},
      {"Head", 15, 2, 16, {0.03429f, 1.56041f, -0.10006f}, 0.069f},
      {"LeftShoulder", 13, 2, 24, {0, 0, 0}, 0},
      {"LeftArm", 17, 2, 25, {3.54205f, 0.90436f, -0.17364f}, 0.027f},
      {"LeftForeArm", 18, 2, 26, {4.86513f, 0, 0}, 0.016f},
      {"LeftHand", 19, 2, 27, {3.35554f, 0, 0}, 0.006f},
      {"LeftFingerBase", 20, 2, 28, {0, 0, 0}, 0},
      {"LeftHandIndex1", 21, 2, 29, {0.66117f, 0, 0}, 0},
      {"LThumb", 20, 2, 30, {0, 0, 0}, 0},
      {"RightShoulder", 13, 2, 17, {0, 0, 0}, 0},
      {"RightArm", 24, 2, 18, {-3.49802f, 0.75994f, -0.32616f}, 0.027f},
      {"RightForeArm", 25, 2, 19, {-5.02649f, 0, 0}, 0.016f},
      {"RightHand", 26, 2, 20, {-3.36431f, 0, 0}, 0.006f},
      {"RightFingerBase", 27, 2, 21, {0, 0, 0}, 0},
      {"RightHandIndex1", 28, 2, 22, {-0.73041f, 0, 0}, 0},
      {"RThumb", 27, 2, 23, {0, 0, 0}, 0},
  };
  const float unit = 0.056444f;
  uint32_t j;
  for (j = 0; j < FIXTURE_JOINTS; ++j) {
    smgi_joint* jt = &f->joints[j];
    jt->name = fixture_add_string(f, k[j].name);
    jt->parent = k[j].parent;
    jt->body_part = k[j].part;
    jt->mirror = k[j].mirror;
    jt->offset[0] = k[j].off[0] * unit;
    jt->offset[1] = k[j].off[1] * unit;
    jt->offset[2] = k[j].off[2] * unit;
    jt->mass_ratio = k[j].mass;
  }
}

/* ---- motion --------------------------------------------------------------- */

/* Gait parameters; blends interpolate them linearly. */
typedef struct fixture_gait {
  float speed;    /* m/s */
  float cycle;    /* seconds per gait cycle (two steps) */
  float hip_amp;  /* thigh swing, radians */
  float knee_amp; /* knee flexion, radians */
  float arm_amp;  /* arm swing, radians */
  float bob;      /* root vertical bob, metres */
} fixture_gait;

static inline fixture_gait fixture_walk(void) {
  fixture_gait g = {FIXTURE_WALK_SPEED, 1.0f, 0.45f, 0.6f, 0.3f, 0.02f};
  return g;
}

static inline fixture_gait fixture_run(void) {
  fixture_gait g = {FIXTURE_RUN_SPEED, 20.0f / FIXTURE_FPS, 0.8f, 1.3f, 0.6f,
                    0.05f};
  return g;
}

static inline fixture_gait fixture_gait_lerp(fixture_gait a, fixture_gait b,
                                             float t) {
  fixture_gait g;
  g.speed = a.speed + (b.speed - a.speed) * t;
  g.cycle = a.cycle + (b.cycle - a.cycle) * t;
  g.hip_amp = a.hip_amp + (b.hip_amp - a.hip_amp) * t;
  g.knee_amp = a.knee_amp + (b.knee_amp - a.knee_amp) * t;
  g.arm_amp = a.arm_amp + (b.arm_amp - a.arm_amp) * t;
  g.bob = a.bob + (b.bob - a.bob) * t;
  return g;
}

/* Write one pose: ground (x, z, heading), gait phase in [0,1), punch in
 * [0,1] (right arm extension). */
static inline void fixture_pose(float* p, const fixture_gait* g, float x,
                                float z, float heading, float phase,
                                float punch) {
  const float w = 2.0f * FIXTURE_PI * phase;
  float q[4], a[4], b[4];
  uint32_t j;
  for (j = 0; j < FIXTURE_JOINTS; ++j) {
    float* r = p + 3 + 4 * j;
    r[0] = r[1] = r[2] = 0.0f;
    r[3] = 1.0f;
  }
  p[0] = x;
  p[1] = 0.95f + g->bob * cosf(2.0f * w);
  p[2] = z;
  fixture_quat_axis(p + 3, 0, 1, 0, heading); /* root: yaw only */
  /* Thighs: negative X rotation swings the leg forward (+Z). Left leg is
   * forward at left foot-strike (phase 0). */
  fixture_quat_axis(p + 3 + 4 * 2, 1, 0, 0, -g->hip_amp * cosf(w));
  fixture_quat_axis(p + 3 + 4 * 7, 1, 0, 0, g->hip_amp * cosf(w));
  /* Knees flex (positive X) during each leg's swing half. */
  fixture_quat_axis(p + 3 + 4 * 3, 1, 0, 0,
                    g->knee_amp * fmaxf(0.0f, -sinf(w)));
  fixture_quat_axis(p + 3 + 4 * 8, 1, 0, 0,
                    g->knee_amp * fmaxf(0.0f, sinf(w)));
  /* Arms: drop from the T-pose (about Z), then swing opposite the legs. */
  fixture_quat_axis(a, 1, 0, 0, g->arm_amp * cosf(w));
  fixture_quat_axis(b, 0, 0, 1, -1.3f);
  fixture_quat_mul(p + 3 + 4 * 18, a, b);
  /* Right arm: swing, or raise forward to punch (about Y brings the arm
   * from -X towards +Z, then un-drop it). */
  fixture_quat_axis(a, 1, 0, 0, -g->arm_amp * cosf(w) * (1.0f - punch));
  fixture_quat_axis(b, 0, 0, 1, 1.3f * (1.0f - punch));
  fixture_quat_mul(q, a, b);
  fixture_quat_axis(a, 0, 1, 0, 1.5f * punch);
  fixture_quat_mul(p + 3 + 4 * 25, a, q);
  /* Forearms bend a little; the punching one straightens. */
  fixture_quat_axis(p + 3 + 4 * 19, 0, 1, 0, 0.3f);
  fixture_quat_axis(p + 3 + 4 * 26, 0, 1, 0, -0.3f - 1.2f * (1.0f - punch));
  /* Spine counter-rotates against the pelvis a little. */
  fixture_quat_axis(p + 3 + 4 * 12, 0, 1, 0, 0.08f * cosf(w));
}

static inline uint32_t fixture_contact_flags(float phase, int running) {
  uint32_t fl = 0;
  float stance = running ? 0.35f : 0.6f;
  float right = phase - 0.5f;
  if (right < 0.0f) right += 1.0f;
  if (phase < stance) fl |= SMGI_FRAME_LEFT_CONTACT;
  if (right < stance) fl |= SMGI_FRAME_RIGHT_CONTACT;
  return fl;
}

/* Generate `count` frames of clip `clip` starting at POSE index `first`:
 * gait blends from a to b over the clip, turning at `turn` radians per
 * clip, punch amplitude `punch` (0: none, >0: one punch peaking mid-clip).
 * A blend's phase runs once through [0,1) so it starts and ends at a left
 * foot-strike, meeting the phase-0 nodes at both ends. Records the ground after the last frame in clip_end_ground. */
static inline void fixture_gen_clip(fixture_graph* f, uint32_t clip,
                                    uint32_t first, uint32_t count,
                                    fixture_gait a, fixture_gait b,
                                    float turn, float punch, int running,
                                    int blend) {
  const float dt = 1.0f / FIXTURE_FPS;
  float x = 0, z = 0, h = 0, phase = 0;
  uint32_t i;
  for (i = 0; i < count; ++i) {
    float t = (float)i / (float)count;
    fixture_gait g = fixture_gait_lerp(a, b, t);
    float* p = f->poses + (size_t)(first + i) * FIXTURE_STRIDE;
    float pf = punch > 0 ? punch * sinf(FIXTURE_PI * t) : 0.0f;
    smgi_frame* fr = &f->frames[first + i];
    /* blends are timed to span exactly one cycle (see below) */
    if (blend) phase = t;
    fixture_pose(p, &g, x, z, h, phase, pf);
    fr->root2d[0] = x;
    fr->root2d[1] = z;
    fr->root2d[2] = h;
    fr->clip = clip;
    fr->phase = phase;
    fr->flags = fixture_contact_flags(phase, running);
    /* advance one frame along heading h at the current speed */
    x += g.speed * dt * sinf(h);
    z += g.speed * dt * cosf(h);
    h += turn / (float)count;
    phase += dt / g.cycle;
    if (phase >= 1.0f) phase -= 1.0f;
  }
  f->clip_end_ground[clip][0] = x;
  f->clip_end_ground[clip][1] = z;
  f->clip_end_ground[clip][2] = h;
}

/* Ground transform of `to` relative to `from`, both (x, z, heading). */
static inline void fixture_relative(float* out, const float* from,
                                    const float* to) {
  float dx = to[0] - from[0], dz = to[1] - from[1];
  float c = cosf(from[2]), s = sinf(from[2]);
  /* rotate by -heading: forward (sin h, cos h) maps to (0, 1) */
  out[0] = c * dx - s * dz;
  out[1] = s * dx + c * dz;
  out[2] = to[2] - from[2];
}

static inline void fixture_edge(fixture_graph* f, smgi_edge* e,
                                const smgi_node* nodes, uint32_t from,
                                uint32_t to, uint32_t first, uint32_t count,
                                const float* end_ground, uint32_t label,
                                uint32_t flags, float cost) {
  const float* start = f->frames[nodes[from].frame].root2d;
  uint32_t i;
  float arc = 0;
  memset(e, 0, sizeof *e);
  e->from = from;
  e->to = to;
  e->first_frame = first;
  e->frame_count = count;
  fixture_relative(e->displacement, start, end_ground);
  for (i = 0; i < count; ++i) {
    const float* a = f->frames[first + i].root2d;
    const float* b = i + 1 < count ? f->frames[first + i + 1].root2d
                                   : end_ground;
    arc += sqrtf((b[0] - a[0]) * (b[0] - a[0]) +
                 (b[1] - a[1]) * (b[1] - a[1]));
  }
  e->arc_length = arc;
  e->cost = cost;
  e->label = label;
  e->flags = flags;
}

static inline void fixture_clip(smgi_clip* c, uint32_t name, uint32_t first,
                                uint32_t count, uint32_t label,
                                uint32_t flags) {
  c->name = name;
  c->first_frame = first;
  c->frame_count = count;
  c->label = label;
  c->flags = flags;
  c->source_clip = SMGI_NONE;
}

/* Fill `f` completely (it need not be zeroed first). */
static inline void fixture_graph_build(fixture_graph* f) {
  const fixture_gait walk = fixture_walk(), run = fixture_run();
  const float turn = 0.25f * FIXTURE_PI;
  smgi_graph_data* d = &f->data;
  uint32_t i;

  memset(f, 0, sizeof *f);
  fixture_add_string(f, ""); /* offset 0: empty string */
  fixture_build_skeleton(f);
  f->styles[0].name = fixture_add_string(f, "walk");
  f->styles[1].name = fixture_add_string(f, "run");
  f->actions[0].name = fixture_add_string(f, "none");
  f->actions[1].name = fixture_add_string(f, "punch");

  fixture_clip(&f->clips[0], fixture_add_string(f, "walk_straight"), 0, 30,
               0, SMGI_CLIP_LOWER);
  fixture_clip(&f->clips[1], fixture_add_string(f, "walk_left"), 30, 30, 0,
               SMGI_CLIP_LOWER);
  fixture_clip(&f->clips[2], fixture_add_string(f, "walk_right"), 60, 30, 0,
               SMGI_CLIP_LOWER);
  fixture_clip(&f->clips[3], fixture_add_string(f, "run_straight"), 90, 20,
               1, SMGI_CLIP_LOWER);
  fixture_clip(&f->clips[4], fixture_add_string(f, "walk_to_run"), 110, 10,
               1, SMGI_CLIP_LOWER | SMGI_CLIP_BLEND);
  fixture_clip(&f->clips[5], fixture_add_string(f, "run_to_walk"), 120, 10,
               0, SMGI_CLIP_LOWER | SMGI_CLIP_BLEND);
  fixture_clip(&f->clips[6], fixture_add_string(f, "walk_punch"), 130, 30, 1,
               SMGI_CLIP_UPPER);

  fixture_gen_clip(f, 0, 0, 30, walk, walk, 0.0f, 0.0f, 0, 0);
  fixture_gen_clip(f, 1, 30, 30, walk, walk, turn, 0.0f, 0, 0);
  fixture_gen_clip(f, 2, 60, 30, walk, walk, -turn, 0.0f, 0, 0);
  fixture_gen_clip(f, 3, 90, 20, run, run, 0.0f, 0.0f, 1, 0);
  fixture_gen_clip(f, 4, 110, 10, walk, run, 0.0f, 0.0f, 1, 1);
  fixture_gen_clip(f, 5, 120, 10, run, walk, 0.0f, 0.0f, 0, 1);
  fixture_gen_clip(f, 6, 130, 30, walk, walk, 0.0f, 1.0f, 0, 0);

  /* lower graph */
  f->lower_nodes[0].frame = 0;
  f->lower_nodes[0].first_edge = 0;
  f->lower_nodes[0].edge_count = 4;
  f->lower_nodes[0].label = 0;
  f->lower_nodes[1].frame = 90;
  f->lower_nodes[1].first_edge = 4;
  f->lower_nodes[1].edge_count = 2;
  f->lower_nodes[1].label = 1;
  fixture_edge(f, &f->lower_edges[0], f->lower_nodes, 0, 0, 0, 30,
               f->clip_end_ground[0], 0, 0, 0.0f);
  fixture_edge(f, &f->lower_edges[1], f->lower_nodes, 0, 0, 30, 30,
               f->clip_end_ground[1], 0, 0, 0.0f);
  fixture_edge(f, &f->lower_edges[2], f->lower_nodes, 0, 0, 60, 30,
               f->clip_end_ground[2], 0, 0, 0.0f);
  fixture_edge(f, &f->lower_edges[3], f->lower_nodes, 0, 1, 110, 10,
               f->clip_end_ground[4], 1,
               SMGI_EDGE_TRANSITION | SMGI_EDGE_STYLE_CHANGE, 0.2f);
  fixture_edge(f, &f->lower_edges[4], f->lower_nodes, 1, 1, 90, 20,
               f->clip_end_ground[3], 1, 0, 0.0f);
  fixture_edge(f, &f->lower_edges[5], f->lower_nodes, 1, 0, 120, 10,
               f->clip_end_ground[5], 0,
               SMGI_EDGE_TRANSITION | SMGI_EDGE_STYLE_CHANGE, 0.2f);

  /* upper graph: the punch clip cut in two at frame 145 */
  f->upper_nodes[0].frame = 130;
  f->upper_nodes[0].first_edge = 0;
  f->upper_nodes[0].edge_count = 1;
  f->upper_nodes[0].label = 1;
  f->upper_nodes[1].frame = 145;
  f->upper_nodes[1].first_edge = 1;
  f->upper_nodes[1].edge_count = 1;
  f->upper_nodes[1].label = 1;
  fixture_edge(f, &f->upper_edges[0], f->upper_nodes, 0, 1, 130, 15,
               f->frames[145].root2d, 1, 0, 0.0f);
  fixture_edge(f, &f->upper_edges[1], f->upper_nodes, 1, 0, 145, 15,
               f->clip_end_ground[6], 1, 0, 0.0f);

  /* splices */
  f->splices[0].lower_frame = 0;
  f->splices[0].action = 1;
  f->splices[0].upper_edge = 0;
  f->splices[0].upper_offset = 0;
  f->splices[0].distance = 0.02f;
  fixture_quat_axis(f->splices[0].correction, 0, 1, 0, 0.0f);
  f->splices[1].lower_frame = 15;
  f->splices[1].action = 1;
  f->splices[1].upper_edge = 1;
  f->splices[1].upper_offset = 0;
  f->splices[1].distance = 0.04f;
  fixture_quat_axis(f->splices[1].correction, 0, 1, 0,
                    5.0f * FIXTURE_PI / 180.0f);
  f->splices[2].lower_frame = 90;
  f->splices[2].action = 1;
  f->splices[2].upper_edge = 0;
  f->splices[2].upper_offset = 3;
  f->splices[2].distance = 0.3f;
  fixture_quat_axis(f->splices[2].correction, 0, 1, 0,
                    10.0f * FIXTURE_PI / 180.0f);

  /* global facts */
  f->info.frame_rate = FIXTURE_FPS;
  f->info.joint_count = FIXTURE_JOINTS;
  f->info.pelvis_joint = 0;
  f->info.spine_base_joint = 11;
  f->info.left_leg[0] = 2;
  f->info.left_leg[1] = 3;
  f->info.left_leg[2] = 4;
  f->info.left_leg[3] = 5;
  f->info.right_leg[0] = 7;
  f->info.right_leg[1] = 8;
  f->info.right_leg[2] = 9;
  f->info.right_leg[3] = 10;
  f->info.leg_length = 0.0f;
  for (i = 3; i <= 4; ++i) {
    const float* o = f->joints[i].offset;
    f->info.leg_length += sqrtf(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
  }
  f->info.ground_height = 0.0f;
  f->info.window_seconds = 10.0f / FIXTURE_FPS;
  f->info.lower_nodes_before_simplify = FIXTURE_LOWER_NODES;
  f->info.lower_edges_before_simplify = FIXTURE_LOWER_EDGES;
  f->info.upper_nodes_before_simplify = FIXTURE_UPPER_NODES;
  f->info.upper_edges_before_simplify = FIXTURE_UPPER_EDGES;

  memset(d, 0, sizeof *d);
  d->info = &f->info;
  d->strings = f->strings;
  d->strings_size = f->strings_used;
  d->joints = f->joints;
  d->joint_count = FIXTURE_JOINTS;
  d->styles = f->styles;
  d->style_count = 2;
  d->actions = f->actions;
  d->action_count = 2;
  d->clips = f->clips;
  d->clip_count = FIXTURE_CLIPS;
  for (i = 0; i < FIXTURE_FRAMES; ++i)
    if (smgi_pose_pack(f->poses + (size_t)i * FIXTURE_STRIDE, FIXTURE_JOINTS,
                       (unsigned char*)f->pose_records +
                           (size_t)i * SMGI_POSE_RECORD_SIZE(FIXTURE_JOINTS)))
      abort(); /* fixture bug: a rotation is not unit */
  d->poses = (const unsigned char*)f->pose_records;
  d->frame_count = FIXTURE_FRAMES;
  d->frames = f->frames;
  d->lower_nodes = f->lower_nodes;
  d->lower_node_count = FIXTURE_LOWER_NODES;
  d->lower_edges = f->lower_edges;
  d->lower_edge_count = FIXTURE_LOWER_EDGES;
  d->upper_nodes = f->upper_nodes;
  d->upper_node_count = FIXTURE_UPPER_NODES;
  d->upper_edges = f->upper_edges;
  d->upper_edge_count = FIXTURE_UPPER_EDGES;
  d->splices = f->splices;
  d->splice_count = FIXTURE_SPLICES;
}

/* Heap-allocated, built fixture (NULL on out of memory). */
static inline fixture_graph* fixture_graph_new(void) {
  fixture_graph* f = (fixture_graph*)malloc(sizeof *f);
  if (f) fixture_graph_build(f);
  return f;
}

static inline void fixture_graph_delete(fixture_graph* f) { free(f); }

/* The fixture serialised as a blob (16-byte aligned, malloc-based; free
 * with smgi_blob_free(data, NULL)). Returns SMG_OK or the writer's error. */
static inline smg_result fixture_graph_blob(void** out_data,
                                            size_t* out_size) {
  fixture_graph* f = fixture_graph_new();
  smg_result r;
  if (!f) return SMG_ERROR_OUT_OF_MEMORY;
  r = smgi_blob_write(&f->data, NULL, out_data, out_size, NULL, 0);
  fixture_graph_delete(f);
  return r;
}

#endif /* SMG_TESTS_FIXTURE_GRAPH_H */
