/*
 * sync.h - synchronization of the upper body with the lower body (sync.c,
 * paper III.C.3): the rate the upper body plays at relative to the lower.
 */
#ifndef SMG_SYNC_H
#define SMG_SYNC_H

#include <math.h>

#include "lower.h"
#include "smg.h"
#include "step_in.h"
#include "upper.h"

typedef struct smgi_sync {
  float rate;  /* upper frames per lower frame */
  float error; /* lower - upper gait phase at the last update, cycles,
                  kept continuous from update to update (NaN: none yet) */
} smgi_sync;

/* No rate warp, no phase difference yet: at the start and whenever the
 * upper body switches (smgi_upper_* report it). */
static inline void smgi_sync_reset(smgi_sync* s) {
  s->rate = 1.0f;
  s->error = NAN;
}

/* Recompute the rate from the upper body's frames ahead and the lower
 * timeline's; called when the lower playhead enters a new frame. */
void smgi_sync_update(smgi_sync* s, const smgi_upper* u, const smgi_lower* l,
                      const smgi_step_in* in);

#endif /* SMG_SYNC_H */
