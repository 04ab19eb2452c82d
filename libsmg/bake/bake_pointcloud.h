/*
 * bake_pointcloud.h - windowed point-cloud distance grid and its local
 * minima (bake_pointcloud.c), shared by the transition and splice
 * searches.
 */
#ifndef BAKE_POINTCLOUD_H
#define BAKE_POINTCLOUD_H

#include <stdint.h>

#include "bake_report.h"
#include "smg.h"

typedef struct smgb_cloud {
  uint32_t frames, points;
  const double* xyz;           /* frames * points * 3 */
  const double* weights;       /* points */
  const uint8_t* valid;        /* frames: window starting here is usable */
} smgb_cloud;

typedef struct smgb_minimum {
  uint32_t i, j;               /* cloud frame indices (row, column) */
  float dist;                  /* RMS distance, metres */
  double align[3];             /* column window -> row window (x, z, h) */
} smgb_minimum;

/* Accept a local minimum (i, j)? 1 = keep. */
typedef int (*smgb_pair_filter)(uint32_t i, uint32_t j, void* user);

typedef struct smgb_grid_job {
  const smgb_cloud* rows;
  const smgb_cloud* cols;
  uint32_t window;
  int align;                   /* 1: optimal 2-D alignment (Kovar) */
  smgb_pair_filter filter;
  void* filter_user;
  uint32_t threads;
  smgb_report* report;         /* progress + errors (may be NULL) */
} smgb_grid_job;

smg_result smgb_grid_minima(const smgb_grid_job* job, smgb_minimum** out,
                            uint32_t* out_count);
/* Distance of one window pair (reference implementation, tests). */
double smgb_window_distance(const smgb_cloud* A, uint32_t i,
                            const smgb_cloud* B, uint32_t j, uint32_t k,
                            int align, double out_align[3]);

#endif /* BAKE_POINTCLOUD_H */
