/*
 * bake_pool_compact.c - the pool without the covered clips
 * (bake_pool_compact.h). A covered clip is on no graph edge, so nothing
 * played at run time reads its frames; keeping them would make the blob
 * grow with the library's repetitions.
 */
#include "bake_pool_compact.h"

#include <stdlib.h>
#include <string.h>

/* New index of pool frame f: f minus the covered frames before it. */
static uint32_t moved(const smgb_bake* b, const uint32_t* shift,
                      uint32_t f) {
  return f - shift[b->frames[f].clip];
}

static void renumber_graph(const smgb_bake* b, const uint32_t* shift,
                           smgb_graph* g) {
  uint32_t i;
  for (i = 0; i < g->node_count; ++i)
    g->nodes[i].frame = moved(b, shift, g->nodes[i].frame);
  for (i = 0; i < g->edge_count; ++i) {
    g->edges[i].a = moved(b, shift, g->edges[i].a);
    g->edges[i].b = moved(b, shift, g->edges[i].b);
  }
}

void smgb_pool_drop_covered(smgb_bake* b) {
  uint32_t c, nc = 0, frames = 0, dropped = 0;
  uint32_t* shift; /* per clip: covered frames before it */
  uint32_t* new_index;
  size_t J3 = 3u * b->J;
  for (c = 0; c < b->clip_count; ++c) dropped += b->clips[c].covered != 0;
  if (dropped == 0) return;
  shift = malloc(b->clip_count * sizeof *shift);
  new_index = malloc(b->clip_count * sizeof *new_index);
  if (!shift || !new_index) {
    /* nothing lost but size: the covered clips stay, without nodes */
    free(shift);
    free(new_index);
    return;
  }
  for (c = 0; c < b->clip_count; ++c) {
    shift[c] = frames;
    new_index[c] = nc;
    if (b->clips[c].covered) {
      frames += b->clips[c].count;
      new_index[c] = SMGI_NONE;
    } else {
      ++nc;
    }
  }
  /* graph frames first: moved() reads the frame records' clips */
  renumber_graph(b, shift, &b->lower);
  renumber_graph(b, shift, &b->upper);
  for (c = 0; c < b->clip_count; ++c) {
    const smgb_pool_clip* pc = &b->clips[c];
    uint32_t to = pc->first - shift[c], f;
    if (pc->covered) continue;
    if (shift[c] > 0) {
      memmove(b->poses + (size_t)to * b->stride,
              b->poses + (size_t)pc->first * b->stride,
              (size_t)pc->count * b->stride * sizeof *b->poses);
      memmove(b->frames + to, b->frames + pc->first,
              (size_t)pc->count * sizeof *b->frames);
      memmove(b->positions + (size_t)to * J3,
              b->positions + (size_t)pc->first * J3,
              (size_t)pc->count * J3 * sizeof *b->positions);
    }
    for (f = to; f < to + pc->count; ++f) b->frames[f].clip = new_index[c];
  }
  for (c = 0; c < b->clip_count; ++c) {
    smgb_pool_clip pc = b->clips[c];
    uint32_t at = new_index[c];
    if (at == SMGI_NONE) continue;
    pc.first -= shift[c];
    pc.source_clip = new_index[pc.source_clip] == SMGI_NONE
                         ? at
                         : new_index[pc.source_clip];
    b->clips[at] = pc;
  }
  /* the dropped tail's records are zeroed: determinism does not depend on
   * what a later append finds there */
  memset(b->frames + (b->frame_count - frames), 0,
         (size_t)frames * sizeof *b->frames);
  b->clip_count = nc;
  b->frame_count -= frames;
  b->source_frame_count -= frames;
  b->covered_clips = dropped;
  b->covered_frames = frames;
  free(shift);
  free(new_index);
}
