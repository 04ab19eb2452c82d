/*
 * bake_pool_compact.h - take the covered clips out of the frame pool
 * (bake_pool_compact.c).
 */
#ifndef BAKE_POOL_COMPACT_H
#define BAKE_POOL_COMPACT_H

#include "bake_state.h"

/* Removes every clip marked `covered` (bake_coverage.h) and its frames
 * from the pool (poses, frame records, positions, the clip table) and
 * renumbers what refers to pool frames and clips: both graphs' nodes and
 * edges, frame records' clip, mirrors' source_clip (a mirror whose
 * original left is its own source). Call after both graphs are built and
 * before transitions are materialized; covered clips have no nodes. Counts
 * them in covered_clips / covered_frames. */
void smgb_pool_drop_covered(smgb_bake* b);

#endif /* BAKE_POOL_COMPACT_H */
