/*
 * eval_run.h - drive one libsmg character along a path through the public
 * runtime API (smg.h) at a fixed rate and record everything the metrics
 * need: per-frame state, world joint positions, the local pose, and the
 * wall-clock cost of each step.
 */
#ifndef EVAL_RUN_H
#define EVAL_RUN_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

#define EVAL_KIND_TRANSITION 0u /* value = style */
#define EVAL_KIND_SPLICE 1u     /* value = action */

typedef struct eval_constraint {
  uint32_t kind;
  float arc;     /* requested arc length along the path, metres */
  uint32_t value;
} eval_constraint;

typedef struct eval_run_desc {
  const float* path_xz;  /* interleaved (x, z) */
  uint32_t path_count;
  const eval_constraint* constraints;
  uint32_t constraint_count;
  uint32_t initial_style, initial_action;
  float rate;            /* steps per second (fixed dt = 1 / rate) */
  float max_seconds;     /* stop after this much simulated time */
  float extra_seconds;   /* keep stepping this long after the end */
  uint32_t seed;
  uint32_t character_flags; /* SMG_CHARACTER_* (e.g. SMG_CHARACTER_NO_IK) */
} eval_run_desc;

typedef struct eval_trace {
  size_t frames;         /* recorded frames (frame 0 = first pose) */
  uint32_t joint_count;
  double dt;
  double first_pose_seconds; /* set_path + constraints + first step + pose */
  int reached_end;       /* SMG_STATE_PATH_END_REACHED was seen */
  /* per frame */
  double* joints;        /* 3 * joint_count world positions */
  double* root_rot;      /* 4: world rotation of joint 0 */
  float* local;          /* 3 + 4 * joint_count: smg_character_get_local_pose */
  double* ground;        /* 3: state position x, z and heading */
  uint32_t* style;
  uint32_t* action;
  uint32_t* flags;
  uint32_t* upper_node;
  double* path_distance;
  double* path_error;
  double* sync_rate;
  double* step_seconds;  /* step + model matrices, wall clock */
} eval_trace;

/* Runs the character; on success the trace is filled (free with
 * eval_trace_free). error gets a one-line reason on failure. */
smg_result eval_run(smg_graph* graph, const eval_run_desc* desc,
                    eval_trace* out, char* error, size_t error_size);
void eval_trace_free(eval_trace* t);

/* World position of joint j at frame i. */
static inline const double* eval_joint(const eval_trace* t, size_t i,
                                       uint32_t j) {
  return t->joints + (i * t->joint_count + j) * 3;
}

/* Reads a path file ("x z" lines, '#' comments, as data/paths/ and
 * smg-synth use) into xz (2 per point); returns the point count, 0 when
 * the file cannot be read or has more than cap points. */
size_t eval_read_path(const char* file, double* xz, size_t cap);

#endif /* EVAL_RUN_H */
