/*
 * bake_pair_search.h - near-linear search for local minima of the windowed
 * point-cloud distance (bake_pair_search.c).
 *
 * The full grid (smgb_grid_minima) evaluates every window pair: O(F^2).
 * This search finds, for every row window, its nearest column windows in a
 * compact pose feature space (a kd-tree over a few principal components of
 * the window's point cloud sampled at its start, middle and end, placed in
 * the window's own floor frame), then walks from each such pair downhill on
 * the exact distance grid to its local minimum. The exact distance is
 * computed only for the cells on those walks; nothing of size F x F is
 * stored. Minima follow the grid's rule (a cell no larger than its earlier
 * neighbours and smaller than its later ones), over the pairs the filter
 * accepts.
 */
#ifndef BAKE_PAIR_SEARCH_H
#define BAKE_PAIR_SEARCH_H

#include <stdint.h>

#include "bake_pointcloud.h"

typedef struct smgb_pair_search {
  const smgb_cloud* rows;
  const smgb_cloud* cols;
  /* Heading (radians about +Y) of each row / column frame's body, used
   * only to put features in the window's own frame when align = 1; NULL
   * when the clouds are already in a body frame. */
  const double* row_heading;
  const double* col_heading;
  /* Column groups, each searched separately (nearest windows in one
   * group do not crowd out another's). Without row_group every row takes
   * the `neighbours` nearest of every group (splicing: a group per
   * action); with it, the `neighbours` nearest of its own group
   * row_group[i] and the `other_neighbours` nearest of each other group
   * (lower graph: a group per style, so that style changes are found; upper
   * graph: 0, transitions stay within an action). NULL col_group: one
   * group. */
  const uint32_t* col_group;
  const uint32_t* row_group;
  uint32_t group_count;
  uint32_t window;
  uint32_t neighbours;
  uint32_t other_neighbours;
  /* Only rows i with i % row_stride == 0 start walks (0 or 1: all). For
   * searches that keep one candidate per stretch of source frames (label
   * changes, splices): the walks reach the minima between those rows. */
  uint32_t row_stride;
  int align;                   /* 1: optimal 2-D alignment (Kovar) */
  smgb_pair_filter filter;     /* pairs it rejects are not searched */
  void* filter_user;
  uint32_t threads;
  smgb_report* report;         /* progress (may be NULL) */
} smgb_pair_search;

/* Local minima (sorted by row, then column; each once) reached from every
 * row's nearest neighbours. Deterministic: the same for any thread count. */
smg_result smgb_pair_search_minima(const smgb_pair_search* job,
                                   smgb_minimum** out, uint32_t* out_count);

/* The pose features the search's kd-trees hold: *out gets `*dims` floats
 * per window of job->rows (zeros where the window is not valid), on the
 * principal axes of job->cols' windows. A window's features are its
 * point cloud sampled at 3 of its k steps (in the window's own floor frame
 * when align = 1), each point scaled by sqrt(w_p), so the squared feature
 * distance of two windows is about 3 / k of their windowed distance D
 * (less by what the dropped axes hold). */
smg_result smgb_pair_features(const smgb_pair_search* job, float** out,
                              uint32_t* dims);

#endif /* BAKE_PAIR_SEARCH_H */
