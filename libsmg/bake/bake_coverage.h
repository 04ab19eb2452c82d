/*
 * bake_coverage.h - the coverage pass of big bakes (bake_coverage.c): which
 * clips add motion that the clips already kept do not cover.
 *
 * A library of hours holds the same walk cycle hundreds of times. Every
 * copy used to add nodes, transitions and blend frames, so the graph and
 * the blob grew with the data. Per label, in clip order, a clip is COVERED
 * when every one of its windows has a window of an earlier kept clip of
 * the same label within that label's radius in the pose-feature space of
 * the pair search (bake_pair_search.h): wherever the character would play
 * the covered clip, a kept clip holds a pose about as near as a typical
 * transition's. The first clip of a label is always kept, so no label is
 * lost; a clip with any window nothing covers is kept whole.
 */
#ifndef BAKE_COVERAGE_H
#define BAKE_COVERAGE_H

#include <stdint.h>

#include "bake_pointcloud.h"
#include "smg.h"

typedef struct smgb_coverage_job {
  const smgb_cloud* cloud;     /* valid[f]: window f is a clip's window */
  const double* heading;       /* as smgb_pair_search.row_heading */
  uint32_t window;
  uint32_t clip_count;
  const uint32_t* clip_first;  /* cloud frame of each clip's frame 0,
                                  SMGI_NONE: not in this cloud */
  const uint32_t* clip_frames;
  const uint32_t* clip_label;
  uint32_t label_count;
  const float* radius;         /* per label: RMS metres (as the windowed
                                  distance's), 0 = cover nothing */
  uint32_t threads;
} smgb_coverage_job;

/* covered[c] = 1 for every covered clip, 0 for the others. Deterministic:
 * labels are independent and each is decided in clip order, whatever the
 * thread count. */
smg_result smgb_cover_clips(const smgb_coverage_job* job, uint8_t* covered);

#endif /* BAKE_COVERAGE_H */
