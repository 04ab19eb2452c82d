/*
 * stopping.h - stopping and starting motion found in a pool of frames,
 * without any configuration: within a locomotion clip, a *stop* is the
 * stretch where the hips slow from the clip's own locomotion speed to a
 * standing stretch (standing.h: still, both feet down), a *start* the
 * stretch from a standing stretch until they reach that speed again.
 * Users' capture has them (a walk that ends standing, one that sets off
 * from standing); the runtime plays a stop by distance matching
 * (stop_match.c) and begins from a start at rest.
 *
 * Shared by the runtime (graph_derived.c, at load) and the baker's
 * report. It reads only FRMI and CLIP, so blobs baked before it get them
 * too. Thresholds are relative to the leg length, the frame rate and the
 * clip's own speeds, never to particular clips. Pure, deterministic, no
 * allocation.
 */
#ifndef SMG_STOPPING_H
#define SMG_STOPPING_H

#include <stdint.h>

#include "smg_format.h"

#define SMGI_STOP_MOVING 0.5f /* leg lengths per second: slower clips do
                                 not walk (0.4 m/s for a 0.8 m leg; the
                                 standing bound is a fifth of it) */
#define SMGI_STOP_CRUISE 0.9f /* share of the clip's locomotion speed at
                                 which slowing begins / starting ends */

#define SMGI_STOP_KIND_STOP 0u
#define SMGI_STOP_KIND_START 1u

typedef struct smgi_stop_seg {
  uint32_t first;  /* pool frame: a stop begins at locomotion speed, a start
                      with the standing stretch it sets off from */
  uint32_t rest;   /* pool frame where the hips stand (a stop's end, a
                      start's last frame before moving off) */
  uint32_t last;   /* pool frame: a stop's last still frame, a start's
                      first frame back at locomotion speed */
  uint32_t clip;   /* the clip they belong to */
  uint32_t kind;   /* SMGI_STOP_KIND_* */
  uint32_t style;  /* the clip's label */
  float speed;     /* m/s: the clip's locomotion speed */
  float travel;    /* m: a stop's ground travel of the hips from `first`
                      to `rest` (a start's from `rest` to `last`) */
} smgi_stop_seg;

/* Writes up to `cap` segments to `out` (may be NULL with cap 0), in pool
 * order of `first`, and returns how many there are in all. Only lower,
 * non-blend clips are read. */
uint32_t smgi_stopping_find(const smgi_frame* frames, uint32_t frame_count,
                            const smgi_clip* clips, uint32_t clip_count,
                            float frame_rate, float leg_length,
                            smgi_stop_seg* out, uint32_t cap);

/* Ground travel of the hips (summed frame to frame) over pool frames
 * [a, b]: what is left of a stop from frame a when it rests at b. */
float smgi_stopping_travel(const smgi_frame* frames, uint32_t a, uint32_t b);

#endif /* SMG_STOPPING_H */
