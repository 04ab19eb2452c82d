/*
 * upper.h - the upper body (upper.c): which action plays, where in the
 * action graph, the splice scheduled next, the Horn correction at the
 * spine base and the crossfade from the previous upper body.
 */
#ifndef SMG_UPPER_H
#define SMG_UPPER_H

#include <stdint.h>

#include "smg.h"

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

/* The initial action at create. */
void smgi_upper_start(smg_character* ch);
/* Advance the upper playhead by `lower_frames` times the sync rate. */
void smgi_upper_advance(smg_character* ch, float lower_frames);
/* Follow splice points: schedule, and switch when the frame has come. */
void smgi_upper_update_splice(smg_character* ch, float dt, int new_frame);
/* Upper frame at fractional time: writes upper joint rotations into out
 * (4J, only upper joints touched). */
void smgi_upper_sample(const smg_character* ch, float* out);

#endif /* SMG_UPPER_H */
