/*
 * standing.h - standing motion found in a pool of frames, without any
 * configuration: stretches of at least SMGI_STAND_MIN_SECONDS in which the
 * hips' ground point stays nearly still and does not turn, with both feet
 * on the floor. They are the starts and ends of locomotion clips and the
 * lower bodies of actions performed standing (a wave, a raised hand).
 *
 * Shared by the runtime (graph_derived.c: the idle motion a character
 * plays at rest) and the baker's report (`smg-bake --info`). It reads only
 * what every blob holds (FRMI ground frames and contact labels, CLIP
 * ranges), so blobs baked before it get standing motion too. Thresholds
 * are relative to the skeleton's leg length and the pool's frame rate,
 * never to particular clips. Pure, deterministic, no allocation.
 */
#ifndef SMG_STANDING_H
#define SMG_STANDING_H

#include <stdint.h>

#include "smg_format.h"

#define SMGI_STAND_MIN_SECONDS 1.0f /* shortest stretch kept */
#define SMGI_STAND_SPEED 0.1f   /* leg lengths per second the ground point
                                   may move (8 cm/s for a 0.8 m leg: a
                                   weight shift, not a step) */
#define SMGI_STAND_TURN 0.35f   /* rad/s it may turn (20 deg/s) */
#define SMGI_STAND_DRIFT 0.15f  /* leg lengths it may stray from where the
                                   stretch began (longer drifts split) */
#define SMGI_STAND_SPAN 0.25f   /* s: speeds over +-this (steps last
                                   longer, sway less) */

typedef struct smgi_stand {
  uint32_t first, count; /* pool frames [first, first + count) */
  uint32_t clip;         /* the clip they belong to */
  uint32_t reserved;
} smgi_stand;

/* Writes up to `cap` stretches to `out` (may be NULL with cap 0), in pool
 * order, and returns how many there are in all. Blend clips (transitions)
 * are skipped; frames outside every clip are never used. */
uint32_t smgi_standing_find(const smgi_frame* frames, uint32_t frame_count,
                            const smgi_clip* clips, uint32_t clip_count,
                            float frame_rate, float leg_length,
                            smgi_stand* out, uint32_t cap);

#endif /* SMG_STANDING_H */
