/*
 * bake_output.c - fill an smgi_graph_data from the bake state and serialise
 * it with smgi_blob_write (deterministic: every record is memset to zero
 * before its fields are set, strings are appended in a fixed order).
 *
 * Edge labels: an original edge carries its clip's style/action; a
 * transition carries the label of the node it arrives at (the style it
 * leads into), and SMGI_EDGE_STYLE_CHANGE when that differs from the
 * `from` node's. SMGI_EDGE_MIRRORED marks edges playing (or blending from)
 * a mirrored clip.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_internodal.h"
#include "bake_output.h"
#include "blob.h"
#include "quat_pack.h"

typedef struct strtab {
  char* data;
  uint32_t size, cap;
} strtab;

static uint32_t str_add(strtab* s, const char* str) {
  uint32_t n = (uint32_t)strlen(str) + 1u, at = s->size;
  if (s->size + n > s->cap) {
    uint32_t cap = s->cap ? s->cap * 2 : 1024;
    char* d;
    while (cap < s->size + n) cap *= 2;
    d = realloc(s->data, cap);
    if (!d) return SMGI_NONE;
    s->data = d;
    s->cap = cap;
  }
  memcpy(s->data + s->size, str, n);
  s->size += n;
  return at;
}

static int fill_graph(const smgb_bake* b, const smgb_graph* g,
                      smgi_node** out_nodes, smgi_edge** out_edges) {
  smgi_node* nodes = calloc(g->node_count ? g->node_count : 1, sizeof *nodes);
  smgi_edge* edges = calloc(g->edge_count ? g->edge_count : 1, sizeof *edges);
  uint32_t n, e;
  if (!nodes || !edges) {
    free(nodes);
    free(edges);
    return 0;
  }
  for (n = 0; n < g->node_count; ++n) {
    nodes[n].frame = g->nodes[n].frame;
    nodes[n].label = g->nodes[n].label;
    nodes[n].first_edge = 0;
    nodes[n].edge_count = 0;
  }
  /* edges are sorted by `from` */
  for (e = g->edge_count; e-- > 0;) {
    nodes[g->edges[e].from].first_edge = e;
    nodes[g->edges[e].from].edge_count++;
  }
  {
    uint32_t next = 0;
    for (n = 0; n < g->node_count; ++n) {
      if (nodes[n].edge_count == 0) nodes[n].first_edge = next;
      next = nodes[n].first_edge + nodes[n].edge_count;
    }
  }
  for (e = 0; e < g->edge_count; ++e) {
    const smgb_edge* s = &g->edges[e];
    smgi_edge* d = &edges[e];
    uint32_t lf = g->nodes[s->from].label, lt = g->nodes[s->to].label;
    d->from = s->from;
    d->to = s->to;
    d->first_frame = s->first_frame;
    d->frame_count = s->frame_count;
    smgb_edge_internodal(b, g, s, d->displacement, &d->arc_length);
    d->cost = s->kind == SMGB_EDGE_TRANSITION ? s->cost : 0.0f;
    d->label = lt;
    d->flags = 0;
    if (s->kind == SMGB_EDGE_TRANSITION) d->flags |= SMGI_EDGE_TRANSITION;
    if (lf != lt) d->flags |= SMGI_EDGE_STYLE_CHANGE;
    if ((b->clips[b->frames[s->a].clip].flags & SMGI_CLIP_MIRROR) ||
        (s->kind == SMGB_EDGE_TRANSITION &&
         (b->clips[b->frames[s->b].clip].flags & SMGI_CLIP_MIRROR)))
      d->flags |= SMGI_EDGE_MIRRORED;
  }
  *out_nodes = nodes;
  *out_edges = edges;
  return 1;
}

smg_result smgb_write_blob(smgb_bake* b, void** out_blob, size_t* out_size) {
  smgi_graph_data g;
  smgi_info info;
  strtab st;
  smgi_joint* joints = NULL;
  smgi_label *styles = NULL, *actions = NULL;
  smgi_clip* clips = NULL;
  smgi_node *ln = NULL, *un = NULL;
  smgi_edge *le = NULL, *ue = NULL;
  smgi_splice* splices = NULL;
  unsigned char* packed = NULL;
  uint32_t i, bad = 0;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  char err[256];

  memset(&g, 0, sizeof g);
  memset(&info, 0, sizeof info);
  memset(&st, 0, sizeof st);
  joints = calloc(b->J, sizeof *joints);
  styles = calloc(b->style_count ? b->style_count : 1, sizeof *styles);
  actions = calloc(b->action_count, sizeof *actions);
  clips = calloc(b->clip_count, sizeof *clips);
  splices = calloc(b->splice_count ? b->splice_count : 1, sizeof *splices);
  /* the pool stays float; only the blob's POSE records are quantised */
  packed = malloc((size_t)(b->frame_count ? b->frame_count : 1) *
                  SMGI_POSE_RECORD_SIZE(b->J));
  if (!joints || !styles || !actions || !clips || !splices || !packed)
    goto oom;
  for (i = 0; i < b->frame_count; ++i) {
    uint32_t nonunit = smgi_pose_pack(
        b->poses + (size_t)i * b->stride, b->J,
        packed + (size_t)i * SMGI_POSE_RECORD_SIZE(b->J));
    if (nonunit) {
      /* the v1 reader's unit check, now done at pack time */
      smgb_fail(&b->report, "writing the blob: POSE[%u] has %u rotation(s) that are "
                   "not finite unit quaternions", (unsigned)i,
                (unsigned)nonunit);
      r = SMG_ERROR_BLOB_VALUE;
      goto done;
    }
  }

  for (i = 0; i < b->J; ++i) {
    smgi_joint* j = &joints[i];
    j->name = str_add(&st, b->skel.names[i]);
    j->parent = b->skel.parents[i];
    j->body_part = b->body.body_part[i];
    j->mirror = b->body.mirror[i];
    j->offset[0] = b->skel.offsets[i][0];
    j->offset[1] = b->skel.offsets[i][1];
    j->offset[2] = b->skel.offsets[i][2];
    j->mass_ratio = b->body.mass_ratio[i];
    bad |= j->name == SMGI_NONE;
  }
  for (i = 0; i < b->style_count; ++i) {
    styles[i].name = str_add(&st, b->styles[i]);
    bad |= styles[i].name == SMGI_NONE;
  }
  for (i = 0; i < b->action_count; ++i) {
    actions[i].name = str_add(&st, b->actions[i]);
    bad |= actions[i].name == SMGI_NONE;
  }
  for (i = 0; i < b->clip_count; ++i) {
    clips[i].name = str_add(&st, b->clips[i].name);
    clips[i].first_frame = b->clips[i].first;
    clips[i].frame_count = b->clips[i].count;
    clips[i].label = b->clips[i].label;
    clips[i].flags = b->clips[i].flags;
    clips[i].source_clip = b->clips[i].source_clip;
    bad |= clips[i].name == SMGI_NONE;
  }
  if (bad) goto oom;
  /* zero the pool's padding-free tail: nothing to do, records are dense */
  if (!fill_graph(b, &b->lower, &ln, &le)) goto oom;
  if (!fill_graph(b, &b->upper, &un, &ue)) goto oom;
  for (i = 0; i < b->splice_count; ++i) {
    const smgb_splice* s = &b->splices[i];
    smgi_splice* d = &splices[i];
    d->lower_frame = s->lower_frame;
    d->action = s->action;
    d->upper_edge = s->upper_edge;
    d->upper_offset = s->upper_offset;
    d->distance = s->distance;
    d->correction[0] = (float)s->correction[0];
    d->correction[1] = (float)s->correction[1];
    d->correction[2] = (float)s->correction[2];
    d->correction[3] = (float)s->correction[3];
  }

  info.frame_rate = b->opt.frame_rate;
  info.joint_count = b->J;
  info.pelvis_joint = 0;
  info.spine_base_joint = b->body.spine_base;
  memcpy(info.left_leg, b->body.left_leg, sizeof info.left_leg);
  memcpy(info.right_leg, b->body.right_leg, sizeof info.right_leg);
  info.leg_length = b->body.leg_length;
  info.ground_height = 0.0f;
  info.window_seconds = (float)b->opt.window / b->opt.frame_rate;
  info.bake_flags = b->bake_flags;
  info.lower_nodes_before_simplify = b->lower_nodes_before;
  info.lower_edges_before_simplify = b->lower_edges_before;
  info.upper_nodes_before_simplify = b->upper_nodes_before;
  info.upper_edges_before_simplify = b->upper_edges_before;

  g.info = &info;
  g.strings = st.data;
  g.strings_size = st.size;
  g.joints = joints;
  g.joint_count = b->J;
  g.styles = styles;
  g.style_count = b->style_count;
  g.actions = actions;
  g.action_count = b->action_count;
  g.clips = clips;
  g.clip_count = b->clip_count;
  g.poses = packed;
  g.frame_count = b->frame_count;
  g.frames = b->frames;
  g.lower_nodes = ln;
  g.lower_node_count = b->lower.node_count;
  g.lower_edges = le;
  g.lower_edge_count = b->lower.edge_count;
  g.upper_nodes = un;
  g.upper_node_count = b->upper.node_count;
  g.upper_edges = ue;
  g.upper_edge_count = b->upper.edge_count;
  g.splices = splices;
  g.splice_count = b->splice_count;
  r = smgi_blob_write(&g, NULL, out_blob, out_size, err, sizeof err);
  if (r != SMG_OK) smgb_fail(&b->report, "writing the blob: %s", err);
  goto done;
oom:
  smgb_fail(&b->report, "out of memory writing the blob");
  r = SMG_ERROR_OUT_OF_MEMORY;
done:
  free(packed);
  free(st.data);
  free(joints);
  free(styles);
  free(actions);
  free(clips);
  free(ln);
  free(le);
  free(un);
  free(ue);
  free(splices);
  return r;
}
