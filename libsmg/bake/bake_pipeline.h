/*
 * bake_pipeline.h - the stage driver (bake_pipeline.c) behind
 * smg_bake_run.
 */
#ifndef BAKE_PIPELINE_H
#define BAKE_PIPELINE_H

#include "smg_bake.h"

/* Bake `desc` (resolved to full size, bake_desc.h) into the zeroed,
 * full-size `out`. */
smg_result smgb_pipeline_run(const smg_bake_desc* desc, smg_bake_result* out);

#endif /* BAKE_PIPELINE_H */
