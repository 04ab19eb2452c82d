/*
 * sync.h - synchronization of the upper body with the lower body (sync.c,
 * paper III.C.3): the rate the upper body plays at relative to the lower.
 */
#ifndef SMG_SYNC_H
#define SMG_SYNC_H

#include "smg.h"

typedef struct smgi_sync {
  float rate; /* upper frames per lower frame */
} smgi_sync;

/* Recompute the rate; called when the lower playhead enters a new frame. */
void smgi_sync_update(smg_character* ch);

#endif /* SMG_SYNC_H */
