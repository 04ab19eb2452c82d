/*
 * bake_pool.c - the frame pool: every clip frame (on the reference
 * skeleton, at the working frame rate), their world joint positions (forward
 * kinematics done once here, so no later stage runs FK) and their ground
 * frames (root2d). Blend frames are appended later by bake_transition.c.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_contacts.h"
#include "bake_pool.h"
#include "bake_math.h"
#include "bake_options.h"
#include "bake_threads.h"

smg_result smgb_pool_reserve(smgb_bake* b, uint32_t frames) {
  uint32_t need = b->frame_count + frames, cap;
  float *p, *pos;
  smgi_frame* fr;
  if (need <= b->frame_cap) return SMG_OK;
  cap = b->frame_cap ? b->frame_cap : 256;
  while (cap < need) cap *= 2;
  p = realloc(b->poses, (size_t)cap * b->stride * sizeof *p);
  if (p) b->poses = p;
  fr = realloc(b->frames, (size_t)cap * sizeof *fr);
  if (fr) b->frames = fr;
  pos = realloc(b->positions, (size_t)cap * 3u * b->J * sizeof *pos);
  if (pos) b->positions = pos;
  if (!p || !fr || !pos) {
    smgb_fail(&b->report, "out of memory (frame pool of %u frames)", cap);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  /* New records start zeroed: determinism does not depend on realloc. */
  memset(b->frames + b->frame_cap, 0,
         (size_t)(cap - b->frame_cap) * sizeof *fr);
  b->frame_cap = cap;
  return SMG_OK;
}

void smgb_pose_ground(const float* pose, double g[3]) {
  double q[4];
  q[0] = pose[3]; q[1] = pose[4]; q[2] = pose[5]; q[3] = pose[6];
  smgb_q_normalize(q);
  g[0] = pose[0];
  g[1] = pose[2];
  g[2] = smgb_heading_of(q);
}

void smgb_pool_derive(smgb_bake* b, uint32_t first, uint32_t count) {
  uint32_t f;
  for (f = first; f < first + count; ++f) {
    const float* pose = b->poses + (size_t)f * b->stride;
    double g[3];
    smgb_fk(&b->skel, pose, b->positions + (size_t)f * 3u * b->J, NULL);
    smgb_pose_ground(pose, g);
    b->frames[f].root2d[0] = (float)g[0];
    b->frames[f].root2d[1] = (float)g[1];
    b->frames[f].root2d[2] = (float)g[2];
  }
}

smgb_pool_clip* smgb_pool_new_clip(smgb_bake* b, const char* name,
                                   uint32_t count, uint32_t label,
                                   uint32_t flags, uint32_t source_clip) {
  smgb_pool_clip* c;
  if (b->clip_count == b->clip_cap) {
    uint32_t cap = b->clip_cap ? b->clip_cap * 2 : 16;
    smgb_pool_clip* nc = realloc(b->clips, cap * sizeof *nc);
    if (!nc) {
      smgb_fail(&b->report, "out of memory (clip table)");
      return NULL;
    }
    b->clips = nc;
    b->clip_cap = cap;
  }
  c = &b->clips[b->clip_count];
  memset(c, 0, sizeof *c);
  snprintf(c->name, sizeof c->name, "%s", name);
  c->first = b->frame_count;
  c->count = count;
  c->label = label;
  c->flags = flags;
  c->source_clip = source_clip == SMGI_NONE ? b->clip_count : source_clip;
  ++b->clip_count;
  return c;
}

smg_result smgb_pool_append_clip(smgb_bake* b, const smgb_clip* clip,
                                 const char* name, uint32_t label,
                                 uint32_t flags, uint32_t source_clip) {
  smgb_pool_clip* c;
  uint32_t f, index;
  smg_result r;
  if (clip->skeleton.joint_count != b->J) {
    smgb_fail(&b->report, "%s: %u joints, reference skeleton has %u", name,
              clip->skeleton.joint_count, b->J);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if ((r = smgb_pool_reserve(b, clip->frame_count)) != SMG_OK) return r;
  c = smgb_pool_new_clip(b, name, clip->frame_count, label, flags,
                         source_clip);
  if (!c) return SMG_ERROR_OUT_OF_MEMORY;
  index = (uint32_t)(c - b->clips);
  memcpy(b->poses + (size_t)b->frame_count * b->stride, clip->poses,
         (size_t)clip->frame_count * b->stride * sizeof(float));
  for (f = 0; f < clip->frame_count; ++f) {
    smgi_frame* fr = &b->frames[b->frame_count + f];
    memset(fr, 0, sizeof *fr);
    fr->clip = index;
    fr->phase = -1.0f;
  }
  b->frame_count += clip->frame_count;
  return SMG_OK;
}

smg_result smgb_pool_add_clip(smgb_bake* b, const smgb_clip* clip,
                              const char* name, uint32_t label,
                              uint32_t flags, uint32_t source_clip) {
  smg_result r = smgb_pool_append_clip(b, clip, name, label, flags,
                                       source_clip);
  if (r == SMG_OK) {
    uint32_t index = b->clip_count - 1u;
    smgb_pool_derive(b, b->clips[index].first, b->clips[index].count);
    smgb_contacts_clip(b, index);
  }
  return r;
}

typedef struct derive_worker {
  smgb_bake* b;
  uint32_t first_clip, t, n;
} derive_worker;

static void* derive_run(void* arg) {
  const derive_worker* w = arg;
  uint32_t c;
  for (c = w->first_clip + w->t; c < w->b->clip_count; c += w->n) {
    smgb_pool_derive(w->b, w->b->clips[c].first, w->b->clips[c].count);
    smgb_contacts_clip(w->b, c);
  }
  return NULL;
}

void smgb_pool_derive_clips(smgb_bake* b, uint32_t first_clip,
                            uint32_t threads) {
  derive_worker w[SMGB_MAX_THREADS];
  uint32_t t, n = threads < 1u ? 1u : threads;
  if (n > SMGB_MAX_THREADS) n = SMGB_MAX_THREADS;
  for (t = 0; t < n; ++t) {
    w[t].b = b;
    w[t].first_clip = first_clip;
    w[t].t = t;
    w[t].n = n;
  }
  smgb_run_workers(w, sizeof w[0], n, derive_run);
}

uint32_t smgb_pool_clip_of(const smgb_bake* b, uint32_t frame) {
  return b->frames[frame].clip;
}
