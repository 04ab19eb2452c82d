/*
 * bake_body.h - what the graph stages need to know about the reference
 * skeleton: the body split, leg chains, mirror map, measured joints and
 * the segment table (bake_body.c, segments in bake_upper.c).
 */
#ifndef BAKE_BODY_H
#define BAKE_BODY_H

#include <stdint.h>

#include "bake_report.h"
#include "bake_roles.h"
#include "bake_skeleton.h"
#include "smg.h"

#define SMGB_MAX_JOINTS 256 /* skeletons larger than this are rejected */

/* Skeleton-derived facts: body split, leg chains, segment table. */
#define SMGB_MAX_SEGMENTS 32
typedef struct smgb_segment {
  uint32_t proximal, distal;   /* joint indices */
  float mass;                  /* fraction of body mass */
  float ratio;                 /* COG = proximal + ratio*(distal-proximal) */
  uint32_t upper;              /* 1: upper-body segment */
  const char* name;
} smgb_segment;

typedef struct smgb_body {
  uint32_t joint_count;
  smgb_roles roles;            /* body roles of the reference skeleton */
  uint32_t spine_base;
  uint32_t left_leg[4], right_leg[4];
  uint32_t* body_part;         /* SMG_BODY_* per joint */
  uint32_t* mirror;            /* counterpart joint per joint */
  float* mass_ratio;           /* per joint (segment mass at its proximal) */
  uint32_t* lower_points;      /* joints measured by the lower graph */
  uint32_t lower_point_count;
  uint32_t* torso_points;      /* joints used by Horn's method */
  uint32_t torso_point_count;
  smgb_segment segments[SMGB_MAX_SEGMENTS];
  uint32_t segment_count;
  uint32_t upper_segment_count;
  float leg_length;
} smgb_body;

/* Recognise the body roles of `s` (bone_map may be NULL; `source` names
 * the skeleton's file in errors, which go to `report`) and derive the
 * tables. */
smg_result smgb_body_init(smgb_body* body, const smgb_skeleton* s,
                          const char* bone_map, const char* source,
                          smgb_report* report);
void smgb_body_free(smgb_body* body);

/* ---- bake_upper.c: segment table (Ae et al. 1996) ------------------------ */
smg_result smgb_segments_init(smgb_body* body, const smgb_skeleton* s,
                              smgb_report* report);

#endif /* BAKE_BODY_H */
