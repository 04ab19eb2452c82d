/*
 * bake_graph_helpers.h - helpers for the baker graph tests: synthetic
 * in-memory clips for smg_bake_run, blob reading, graph views for SCC
 * checks. Header-only; include after <cmocka.h>.
 */
#ifndef BAKE_GRAPH_HELPERS_H
#define BAKE_GRAPH_HELPERS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_clip.h"
#include "bake_graph_build.h"
#include "bake_horn.h"
#include "bake_pointcloud.h"
#include "bake_pool.h"
#include "bake_scc.h"
#include "bake_simplify.h"
#include "bake_state.h"
#include "bake_transition.h"
#include "bake_manifest.h"
#include "bake_math.h"
#include "bake_synthetic.h"
#include "blob.h"
#include "smg_bake.h"
#include "test_env.h"


/* A set of synthetic clips held in memory, as smg_bake_clip_desc. */
#define BG_MAX_CLIPS 8
typedef struct bg_set {
  smgb_clip clips[BG_MAX_CLIPS];
  smg_bake_memory_clip mem[BG_MAX_CLIPS];
  smg_bake_clip_desc descs[BG_MAX_CLIPS];
  const char* names[BG_MAX_CLIPS][64];
  smgb_synth_truth truth[BG_MAX_CLIPS];
  uint32_t count;
} bg_set;

static inline void bg_add(bg_set* s, smgb_synth_kind kind, float duration,
                          float turn, uint32_t role, const char* label) {
  smgb_synth_params p;
  uint32_t i = s->count, j;
  smgb_clip* c = &s->clips[i];
  memset(&p, 0, sizeof p);
  p.kind = kind;
  p.duration = duration;
  p.frame_rate = 30.0f;
  p.turn_rate = turn;
  if (smgb_synth_generate(&p, c, &s->truth[i]) != SMG_OK)
    fail_msg("smgb_synth_generate failed");
  for (j = 0; j < c->skeleton.joint_count && j < 64; ++j)
    s->names[i][j] = c->skeleton.names[j];
  memset(&s->mem[i], 0, sizeof s->mem[i]);
  s->mem[i].joint_count = c->skeleton.joint_count;
  s->mem[i].joint_names = s->names[i];
  s->mem[i].parents = c->skeleton.parents;
  s->mem[i].offsets = &c->skeleton.offsets[0][0];
  s->mem[i].poses = c->poses;
  s->mem[i].frame_count = c->frame_count;
  s->mem[i].frame_rate = c->frame_rate;
  memset(&s->descs[i], 0, sizeof s->descs[i]);
  s->descs[i].struct_size = sizeof s->descs[i];
  s->descs[i].role = role;
  s->descs[i].memory = &s->mem[i];
  s->descs[i].label = label;
  s->descs[i].name = label;
  s->count++;
}

static inline void bg_free(bg_set* s) {
  uint32_t i;
  for (i = 0; i < s->count; ++i) smgb_clip_free(&s->clips[i]);
  s->count = 0;
}

/* walk + run (straight and turning) + punch + wave: a small full set. */
static inline void bg_standard(bg_set* s, float seconds) {
  memset(s, 0, sizeof *s);
  bg_add(s, SMGB_SYNTH_WALK, seconds, 0.0f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(s, SMGB_SYNTH_WALK, seconds, 0.4f, SMG_BAKE_ROLE_LOWER, "walk");
  bg_add(s, SMGB_SYNTH_RUN, seconds, 0.0f, SMG_BAKE_ROLE_LOWER, "run");
  bg_add(s, SMGB_SYNTH_RUN, seconds, 0.3f, SMG_BAKE_ROLE_LOWER, "run");
  bg_add(s, SMGB_SYNTH_PUNCH, seconds, 0.0f, SMG_BAKE_ROLE_UPPER, "punch");
  bg_add(s, SMGB_SYNTH_WAVE, seconds, 0.0f, SMG_BAKE_ROLE_UPPER, "wave");
}

static inline smg_result bg_bake(const bg_set* s, const smg_bake_options* o,
                                 smg_bake_result* res) {
  smg_bake_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = s->descs;
  d.clip_count = s->count;
  if (o) d.options = *o;
  memset(res, 0, sizeof *res);
  res->struct_size = sizeof *res;
  return smg_bake_run(&d, res);
}

/* Bakes a manifest file (clips found in data_dir, or beside it when NULL)
 * at its own frame rate, onto the target rig `rig` when not NULL; fails
 * the test with the manifest's or the bake's message. */
static inline void bg_bake_manifest(const char* manifest, const char* data_dir,
                                    const char* rig, smg_bake_result* res) {
  smgb_manifest m;
  smgb_error err;
  smg_bake_clip_desc descs[64];
  smg_bake_desc d;
  if (smgb_manifest_load(manifest, data_dir, &m, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_true(m.clip_count <= 64);
  assert_int_equal(smgb_manifest_descs(&m, descs, m.clip_count), SMG_OK);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.clips = descs;
  d.clip_count = m.clip_count;
  d.options.struct_size = sizeof d.options;
  d.options.frame_rate = m.frame_rate;
  d.target_path = rig;
  d.target_unit_scale = rig ? 1.0f : 0.0f;
  memset(res, 0, sizeof *res);
  res->struct_size = sizeof *res;
  if (smg_bake_run(&d, res) != SMG_OK) fail_msg("%s: %s", manifest, res->error);
  smgb_manifest_free(&m);
}

static inline void bg_read(const smg_bake_result* res, smgi_graph_data* g) {
  char err[256];
  smg_result r = smgi_blob_read(res->blob, res->blob_size, 0, g, err,
                                sizeof err);
  if (r != SMG_OK) fail_msg("smgi_blob_read: %s", err);
}

/* Number of strongly connected components among the nodes of one graph
 * (restricted to nodes with `label`, or all when label == SMGI_NONE). */
static inline int32_t bg_components(const smgi_node* nodes, uint32_t nn,
                                    const smgi_edge* edges, uint32_t ne,
                                    uint32_t label) {
  smgb_graph g;
  uint32_t* comp;
  uint32_t* remap = malloc((nn + 1) * sizeof *remap);
  uint32_t n, e;
  int32_t c;
  memset(&g, 0, sizeof g);
  for (n = 0; n < nn; ++n) {
    remap[n] = SMGI_NONE;
    if (label != SMGI_NONE && nodes[n].label != label) continue;
    remap[n] = g.node_count;
    smgb_graph_add_node(&g, nodes[n].frame, nodes[n].label, NULL);
  }
  for (e = 0; e < ne; ++e) {
    smgb_edge ed;
    if (remap[edges[e].from] == SMGI_NONE || remap[edges[e].to] == SMGI_NONE)
      continue;
    memset(&ed, 0, sizeof ed);
    ed.from = remap[edges[e].from];
    ed.to = remap[edges[e].to];
    smgb_graph_add_edge(&g, &ed);
  }
  comp = malloc((g.node_count + 1) * sizeof *comp);
  c = smgb_scc(&g, comp);
  free(comp);
  free(remap);
  smgb_graph_free(&g);
  return c;
}

static inline int32_t bg_joint(const smgb_clip* c, const char* name) {
  int32_t j = smgb_skeleton_find(&c->skeleton, name);
  if (j < 0) fail_msg("no joint %s", name);
  return j;
}

static inline void bg_put(float* pose, int32_t j, const double q[4]) {
  int c;
  for (c = 0; c < 4; ++c) pose[3 + 4 * j + c] = (float)q[c];
}

static inline void bg_axis_q(int axis, double angle, double q[4]) {
  q[0] = q[1] = q[2] = 0.0;
  q[axis] = sin(0.5 * angle);
  q[3] = cos(0.5 * angle);
}

/* Replace the upper body of clip c (a synthetic walk) with a motion of
 * `per_stride` cycles per gait cycle (stride period T): the spine base
 * cancels the pelvis's rotation but for its heading (the ground frame's),
 * so the upper body's pose in the ground frame is a function of that
 * motion's phase alone, like a dribbler's arm that repeats on either foot
 * rather than once per stride. */
static inline void bg_retime_upper_body(smgb_clip* c, double T,
                                        double per_stride) {
  int32_t base = bg_joint(c, "LowerBack"), rarm = bg_joint(c, "RightArm");
  int32_t rfore = bg_joint(c, "RightForeArm"), larm = bg_joint(c, "LeftArm");
  int32_t lfore = bg_joint(c, "LeftForeArm");
  uint32_t f, S = SMGB_STRIDE(c->skeleton.joint_count);
  for (f = 0; f < c->frame_count; ++f) {
    float* pose = c->poses + (size_t)f * S;
    double u = 2.0 * 3.14159265358979323846 * per_stride * (double)f /
               ((double)c->frame_rate * T);
    double root[4], inv[4], a[4], b[4], q[4];
    int k;
    for (k = 0; k < 4; ++k) root[k] = pose[3 + k];
    smgb_q_conj(root, inv);
    smgb_q_yaw(smgb_heading_of(root), b);
    smgb_q_mul(inv, b, q);
    bg_axis_q(1, 0.25 * sin(u), a);
    bg_axis_q(0, 0.15 + 0.1 * cos(u), b);
    smgb_q_mul(q, a, root);
    smgb_q_mul(root, b, a);
    smgb_q_normalize(a);
    bg_put(pose, base, a);
    bg_axis_q(2, -1.2 + 0.5 * sin(u), q);
    bg_put(pose, rarm, q);
    bg_axis_q(1, 0.8 + 0.6 * cos(u), q);
    bg_put(pose, rfore, q);
    bg_axis_q(2, 1.3, q);
    bg_put(pose, larm, q);
    bg_axis_q(1, -0.3, q);
    bg_put(pose, lfore, q);
  }
}

#endif /* BAKE_GRAPH_HELPERS_H */
