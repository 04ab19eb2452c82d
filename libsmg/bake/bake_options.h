/*
 * bake_options.h - the baker's options: their defaults and limits (the one
 * place they are written down) and the one function that turns a caller's
 * smg_bake_options into the resolved values every stage reads.
 *
 * A caller's zero means "the default"; anything else must be a finite,
 * non-negative number no larger than its limit. smg-bake's help text and
 * docs/baker.md quote these defaults.
 */
#ifndef BAKE_OPTIONS_H
#define BAKE_OPTIONS_H

#include <stdint.h>

#include "bake_report.h"
#include "smg_bake.h"

/* Defaults (smg_bake_options fields left 0). */
#define SMGB_DEFAULT_FRAME_RATE 30.0f            /* Hz */
#define SMGB_DEFAULT_WINDOW_SECONDS (1.0f / 3.0f)
#define SMGB_DEFAULT_TRANSITION_PERCENTILE 30.0f
#define SMGB_DEFAULT_MAX_EDGE_SECONDS 1.0f
#define SMGB_DEFAULT_SPLICE_PERCENTILE 30.0f
#define SMGB_DEFAULT_SPLICE_REGION_SECONDS 0.5f
#define SMGB_DEFAULT_SPLICES_PER_REGION 2u
#define SMGB_DEFAULT_CONTACT_HEIGHT 0.06f        /* metres */
#define SMGB_DEFAULT_CONTACT_SPEED 0.6f          /* m/s */
#define SMGB_DEFAULT_THREADS 2u

/* Limits: larger values are rejected, except threads, which is capped
 * (more workers than this gain nothing on the distance grids). */
#define SMGB_MAX_FRAME_RATE 1000.0f
#define SMGB_MAX_WINDOW_SECONDS 10.0f
#define SMGB_MAX_PERCENTILE 100.0f
#define SMGB_MAX_TRANSITION_THRESHOLD 100.0f     /* metres */
#define SMGB_MAX_EDGE_SECONDS_LIMIT 3600.0f
#define SMGB_MAX_SPLICE_REGION_SECONDS 3600.0f
#define SMGB_MAX_SPLICES_PER_REGION 1000u
#define SMGB_MAX_CONTACT_HEIGHT 10.0f
#define SMGB_MAX_CONTACT_SPEED 100.0f
#define SMGB_MAX_THREADS 8u

/* Resolved options (defaults applied). */
typedef struct smgb_options {
  float frame_rate;
  float window_seconds;
  uint32_t window;             /* k frames */
  float transition_percentile; /* 0..100 */
  float transition_threshold;  /* metres RMS, 0 = none */
  float max_edge_seconds;
  uint32_t max_edge_frames;
  float splice_percentile;
  float splice_region_seconds;
  uint32_t splices_per_region;
  float contact_height, contact_speed;
  uint32_t threads;
  uint32_t no_mirror;
} smgb_options;

/* Check `in` (NULL or struct_size 0: all defaults) and fill `out`. Every
 * value out of range is recorded in `report` (all of them, not only the
 * first); then SMG_ERROR_INVALID_ARGUMENT and `out` holds the defaults. */
smg_result smgb_options_resolve(const smg_bake_options* in, smgb_options* out,
                                smgb_report* report);

#endif /* BAKE_OPTIONS_H */
