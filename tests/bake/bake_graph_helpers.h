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
#include "bake_graph.h"
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

#endif /* BAKE_GRAPH_HELPERS_H */
