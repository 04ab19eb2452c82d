/*
 * bake_skeleton.c - skeleton copy/free/lookup and forward kinematics
 * (bake_skeleton.h).
 *
 * FK: W_0 = q_0, P_0 = t; W_j = W_parent q_j, P_j = P_parent + W_parent
 * offset_j.
 */
#include <stdlib.h>
#include <string.h>

#include "bake_math.h"
#include "bake_skeleton.h"

void smgb_skeleton_free(smgb_skeleton* s) {
  if (!s) return;
  free(s->names);
  free(s->parents);
  free(s->offsets);
  memset(s, 0, sizeof *s);
}

smg_result smgb_skeleton_copy(const smgb_skeleton* src, smgb_skeleton* out) {
  smgb_skeleton s;
  uint32_t n;
  if (!src || !out || src->joint_count == 0 || !src->names || !src->parents ||
      !src->offsets)
    return SMG_ERROR_INVALID_ARGUMENT;
  n = src->joint_count;
  memset(&s, 0, sizeof s);
  s.joint_count = n;
  s.names = (char(*)[SMGB_NAME_MAX])malloc(sizeof *s.names * n);
  s.parents = (int32_t*)malloc(sizeof *s.parents * n);
  s.offsets = (float(*)[3])malloc(sizeof *s.offsets * n);
  if (!s.names || !s.parents || !s.offsets) {
    smgb_skeleton_free(&s);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  memcpy(s.names, src->names, sizeof *s.names * n);
  memcpy(s.parents, src->parents, sizeof *s.parents * n);
  memcpy(s.offsets, src->offsets, sizeof *s.offsets * n);
  *out = s;
  return SMG_OK;
}

/* The part of a joint name after any namespace ("mixamorig:LeftArm"). */
static const char* strip_namespace(const char* name) {
  const char* c = strrchr(name, ':');
  return c ? c + 1 : name;
}

int32_t smgb_skeleton_find(const smgb_skeleton* s, const char* name) {
  uint32_t i;
  if (!s || !name || !s->names) return -1;
  for (i = 0; i < s->joint_count; ++i)
    if (strcmp(s->names[i], name) == 0) return (int32_t)i;
  /* Fall back to a namespace-free match (assimp/FBX rigs). */
  for (i = 0; i < s->joint_count; ++i)
    if (strcmp(strip_namespace(s->names[i]), name) == 0) return (int32_t)i;
  return -1;
}

void smgb_fk(const smgb_skeleton* s, const float* pose, float* out_positions,
             float* out_rotations) {
  uint32_t j, J;
  /* World rotations are needed for every parent; keep them in the caller's
   * buffer when given, else in a small stack cache per call chunk. */
  double stackbuf[4 * 64];
  double* W;
  double* heap = NULL;
  if (!s || !pose || !out_positions || !s->parents || !s->offsets) return;
  J = s->joint_count;
  if (J == 0) return;
  if (J <= 64) {
    W = stackbuf;
  } else {
    heap = (double*)malloc(sizeof(double) * 4 * J);
    if (!heap) return;
    W = heap;
  }
  for (j = 0; j < J; ++j) {
    double q[4], *w = W + 4 * j;
    int k;
    for (k = 0; k < 4; ++k) q[k] = pose[3 + 4 * j + k];
    smgb_q_normalize(q);
    if (j == 0 || s->parents[j] < 0 || (uint32_t)s->parents[j] >= j) {
      for (k = 0; k < 4; ++k) w[k] = q[k];
      out_positions[3 * j + 0] = pose[0];
      out_positions[3 * j + 1] = pose[1];
      out_positions[3 * j + 2] = pose[2];
    } else {
      uint32_t p = (uint32_t)s->parents[j];
      double off[3] = {s->offsets[j][0], s->offsets[j][1], s->offsets[j][2]};
      smgb_q_rotate(W + 4 * p, off, off);
      out_positions[3 * j + 0] = (float)(out_positions[3 * p + 0] + off[0]);
      out_positions[3 * j + 1] = (float)(out_positions[3 * p + 1] + off[1]);
      out_positions[3 * j + 2] = (float)(out_positions[3 * p + 2] + off[2]);
      smgb_q_mul(W + 4 * p, q, w);
    }
    if (out_rotations)
      for (k = 0; k < 4; ++k) out_rotations[4 * j + k] = (float)w[k];
  }
  free(heap);
}
