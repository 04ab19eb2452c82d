/*
 * upper.h - the upper body (upper.c): which action plays, where in the
 * action graph, the splice scheduled next, the Horn correction at the
 * spine base and the crossfade from the previous upper body. Inputs:
 * the step's (step_in.h), the lower timeline, the pose shown (faded from)
 * and the sync rate; it owns its state and draws from the character's
 * seeded rng, which the caller passes.
 */
#ifndef SMG_UPPER_H
#define SMG_UPPER_H

#include <stdint.h>

#include "graph_data.h"
#include "lower.h"
#include "smg.h"
#include "step_in.h"

/* A scheduled switch of the upper body to a splice candidate. */
typedef struct smgi_pending_splice {
  uint32_t valid;
  uint32_t seq;     /* lower queue entry holding the lower frame */
  uint32_t offset;  /* frame offset inside that entry's edge */
  uint32_t splice;  /* SPLC index */
} smgi_pending_splice;

typedef struct smgi_upper {
  uint32_t action;        /* action being played (0 = the lower's own) */
  uint32_t edge, next;    /* current and next upper edge */
  float t;                /* frames into edge */
  uint32_t node;          /* upper node last passed */
  float correction[4];    /* Horn correction at the spine base */
  float fade;             /* crossfade progress 0..1 (1 = done) */
  float fade_rate;        /* 1 / window seconds */
  float* snap;            /* 4J: the pose faded from */
  smgi_pending_splice pending;
  float want_time;        /* seconds an unmet action has waited */
} smgi_upper;

/* The initial action at create (`shown`: 4J rotations the switch fades
 * from; `rng`: the character's seeded choices). */
void smgi_upper_start(smgi_upper* u, const smg_graph* g, uint32_t* rng,
                      const float* shown, uint32_t action);
/* Advance the upper playhead by `lower_frames` times the sync rate and
 * the crossfade by dt. Returns 1 when the upper body entered an action's
 * edge anew (here: a dead end re-entered its action): synchronization
 * then starts afresh (smgi_sync_reset). */
int smgi_upper_advance(smgi_upper* u, const smg_graph* g, uint32_t* rng,
                       const float* shown, float lower_frames,
                       float sync_rate, float dt);
/* Follow splice points (the constraints at the character's progress, the
 * lower frames coming up): schedule, and switch when the frame has come.
 * Returns 1 when it switched into an action's edge; a switch back to
 * action 0 returns 0 (nothing to synchronize: smgi_sync_update resets
 * the rate on the next new lower frame). */
int smgi_upper_update_splice(smgi_upper* u, const smgi_lower* lower,
                             const smgi_step_in* in, uint32_t* rng,
                             const float* shown, float dt, int new_frame);
/* The planner dropped planned entries: a switch scheduled on one of them
 * is forgotten (only the entry playing was kept). */
void smgi_upper_plan_dropped(smgi_upper* u, const smgi_lower* lower);
/* Upper frame at fractional time: writes upper joint rotations into out
 * (4J, only upper joints touched). */
void smgi_upper_sample(const smgi_upper* u, const smg_graph* g, float* out);

#endif /* SMG_UPPER_H */
