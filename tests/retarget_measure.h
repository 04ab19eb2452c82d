/*
 * retarget_measure.h - what a retargeted blob looks like from the outside:
 * a character walks a path through the public API (smg.h) and the
 * exported joint positions are measured: bone lengths against the rig,
 * toe height at rest, geometric planted-toe speed and path error.
 * Header-only, shared by the retargeting tests and their measurement.
 */
#ifndef RETARGET_MEASURE_H
#define RETARGET_MEASURE_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smg.h"

typedef struct rm_result {
  double bone_error_m;    /* max |exported bone length - rig bone length| */
  double toe_floor_cm[2]; /* per toe: 5th percentile of its height */
  double toe_low_cm;      /* lowest toe height over the run */
  double planted_cms;     /* mean horizontal toe speed over frame pairs with
                             the toe within 2.5 cm of its floor level in
                             both frames (both toes) */
  double planted_p95_cms;
  double path_error_mean_m, path_error_max_m;
  int reached_end;
  uint32_t frames;
} rm_result;

static int rm_cmp(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* Walk `path_xz` (n points) at 30 Hz for at most `seconds`. `rig_len` (J
 * floats) are the target's bone lengths; toes[2] the toe joints; flags are
 * smg_character_desc.flags (SMG_CHARACTER_NO_IK). */
static inline int rm_walk(smg_graph* g, const float* path_xz, uint32_t n,
                          float seconds, uint32_t flags, const double* rig_len,
                          const uint32_t toes[2], rm_result* out) {
  smg_graph_info info;
  smg_character* ch = NULL;
  smg_character_desc cd;
  uint32_t J, f, frames = (uint32_t)(seconds * 30.0f), k, pairs = 0;
  float* m;
  double *toe, *speeds, err_sum = 0.0;
  memset(out, 0, sizeof *out);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (smg_graph_get_info(g, &info) != SMG_OK) return -1;
  J = info.joint_count;
  memset(&cd, 0, sizeof cd);
  cd.struct_size = sizeof cd;
  cd.flags = flags;
  if (smg_character_create(g, &cd, &ch) != SMG_OK) return -1;
  if (smg_character_set_path(ch, path_xz, n) != SMG_OK) {
    smg_character_destroy(ch);
    return -1;
  }
  m = (float*)malloc(sizeof(float) * 16 * J);
  toe = (double*)malloc(sizeof(double) * 2 * 3 * frames);
  speeds = (double*)malloc(sizeof(double) * 2 * frames);
  if (!m || !toe || !speeds) {
    free(m); free(toe); free(speeds);
    smg_character_destroy(ch);
    return -1;
  }
  out->toe_low_cm = 1e9;
  for (f = 0; f < frames; ++f) {
    smg_character_state st;
    uint32_t j;
    smg_character_step(ch, 1.0f / 30.0f);
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    smg_character_get_state(ch, &st);
    smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, m, J);
    for (j = 1; j < J; ++j) {
      smg_joint_info ji;
      double d[3], e;
      memset(&ji, 0, sizeof ji);
      ji.struct_size = sizeof ji;
      smg_graph_get_joint(g, j, &ji);
      for (k = 0; k < 3; ++k)
        d[k] = (double)m[16 * j + 12 + k] - m[16 * (uint32_t)ji.parent + 12 + k];
      e = fabs(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - rig_len[j]);
      if (e > out->bone_error_m) out->bone_error_m = e;
    }
    for (k = 0; k < 2; ++k) {
      const float* t = m + 16 * toes[k] + 12;
      toe[6 * f + 3 * k + 0] = t[0];
      toe[6 * f + 3 * k + 1] = t[1];
      toe[6 * f + 3 * k + 2] = t[2];
      if (100.0 * t[1] < out->toe_low_cm) out->toe_low_cm = 100.0 * t[1];
    }
    err_sum += st.path_error;
    if (st.path_error > out->path_error_max_m)
      out->path_error_max_m = st.path_error;
    ++out->frames;
    if (st.flags & SMG_STATE_PATH_END_REACHED) {
      out->reached_end = 1;
      break;
    }
  }
  frames = out->frames;
  out->path_error_mean_m = frames ? err_sum / frames : 0.0;
  for (k = 0; k < 2; ++k) { /* floor level: 5th percentile of height */
    for (f = 0; f < frames; ++f) speeds[f] = toe[6 * f + 3 * k + 1];
    qsort(speeds, frames, sizeof *speeds, rm_cmp);
    out->toe_floor_cm[k] = frames ? 100.0 * speeds[(frames - 1) / 20] : 0.0;
  }
  for (k = 0; k < 2; ++k) {
    double floor_y = out->toe_floor_cm[k] / 100.0;
    for (f = 1; f < frames; ++f) {
      const double* a = toe + 6 * (f - 1) + 3 * k;
      const double* b = toe + 6 * f + 3 * k;
      if (a[1] - floor_y < 0.025 && b[1] - floor_y < 0.025) {
        double dx = b[0] - a[0], dz = b[2] - a[2];
        speeds[pairs++] = 100.0 * 30.0 * sqrt(dx * dx + dz * dz);
      }
    }
  }
  if (pairs) {
    double s = 0.0;
    for (f = 0; f < pairs; ++f) s += speeds[f];
    out->planted_cms = s / pairs;
    qsort(speeds, pairs, sizeof *speeds, rm_cmp);
    out->planted_p95_cms = speeds[(pairs - 1) * 95 / 100];
  }
  free(m);
  free(toe);
  free(speeds);
  smg_character_destroy(ch);
  return 0;
}

#endif /* RETARGET_MEASURE_H */
