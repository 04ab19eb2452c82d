/*
 * eval_run.c - see eval_run.h. The character is created before the clock
 * starts (an engine creates characters at load time); "path given to first
 * pose" covers set_path, the constraints, the first step and reading the
 * first pose, which is what a player waits for after drawing.
 */
#include "eval_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_ctx.h"
#include "eval_metrics.h"

void eval_trace_free(eval_trace* t) {
  if (!t) return;
  free(t->joints);
  free(t->root_rot);
  free(t->local);
  free(t->ground);
  free(t->style);
  free(t->action);
  free(t->flags);
  free(t->upper_node);
  free(t->path_distance);
  free(t->path_error);
  free(t->sync_rate);
  free(t->step_seconds);
  memset(t, 0, sizeof(*t));
}

static int trace_alloc(eval_trace* t, size_t cap, uint32_t j) {
  t->joint_count = j;
  t->joints = (double*)malloc(cap * j * 3 * sizeof(double));
  t->root_rot = (double*)malloc(cap * 4 * sizeof(double));
  t->local = (float*)malloc(cap * (3 + 4 * (size_t)j) * sizeof(float));
  t->ground = (double*)malloc(cap * 3 * sizeof(double));
  t->style = (uint32_t*)malloc(cap * sizeof(uint32_t));
  t->action = (uint32_t*)malloc(cap * sizeof(uint32_t));
  t->flags = (uint32_t*)malloc(cap * sizeof(uint32_t));
  t->upper_node = (uint32_t*)malloc(cap * sizeof(uint32_t));
  t->path_distance = (double*)malloc(cap * sizeof(double));
  t->path_error = (double*)malloc(cap * sizeof(double));
  t->sync_rate = (double*)malloc(cap * sizeof(double));
  t->step_seconds = (double*)malloc(cap * sizeof(double));
  return t->joints && t->root_rot && t->local && t->ground && t->style &&
         t->action && t->flags && t->upper_node && t->path_distance &&
         t->path_error && t->sync_rate && t->step_seconds;
}

/* Copies frame i's results out of the character. */
static smg_result record(smg_character* ch, eval_trace* t, size_t i,
                         const float* mats) {
  smg_character_state st;
  smg_result r;
  uint32_t j, J = t->joint_count;
  memset(&st, 0, sizeof(st));
  st.struct_size = sizeof(st);
  if ((r = smg_character_get_state(ch, &st)) != SMG_OK) return r;
  if ((r = smg_character_get_local_pose(
           ch, t->local + i * (3 + 4 * (size_t)J),
           t->local + i * (3 + 4 * (size_t)J) + 3, J)) != SMG_OK)
    return r;
  for (j = 0; j < J; ++j) {
    double* p = t->joints + (i * J + j) * 3;
    p[0] = mats[16 * j + 12];
    p[1] = mats[16 * j + 13];
    p[2] = mats[16 * j + 14];
  }
  em_quat_from_matrix(mats, t->root_rot + 4 * i);
  t->ground[3 * i] = st.position[0];
  t->ground[3 * i + 1] = st.position[2];
  t->ground[3 * i + 2] = st.heading;
  t->style[i] = st.style;
  t->action[i] = st.action;
  t->flags[i] = st.flags;
  t->upper_node[i] = st.upper_node;
  t->path_distance[i] = st.path_distance;
  t->path_error[i] = st.path_error;
  t->sync_rate[i] = st.sync_rate;
  return SMG_OK;
}

smg_result eval_run(smg_graph* graph, const eval_run_desc* desc,
                    eval_trace* out, char* error, size_t error_size) {
  smg_graph_info info;
  smg_character_desc cd;
  smg_character* ch = NULL;
  smg_result r;
  float* mats = NULL;
  size_t cap, i;
  uint32_t c;
  double t0, dt, after_end = -1.0;

  if (error && error_size) error[0] = '\0';
  if (!graph || !desc || !out || !desc->path_xz || !desc->path_count ||
      !(desc->rate > 0.0f) || !(desc->max_seconds > 0.0f))
    return SMG_ERROR_INVALID_ARGUMENT;
  memset(out, 0, sizeof(*out));
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  if ((r = smg_graph_get_info(graph, &info)) != SMG_OK) return r;

  dt = 1.0 / desc->rate;
  cap = (size_t)ceil((desc->max_seconds + desc->extra_seconds) *
                     desc->rate) + 2;
  if (!trace_alloc(out, cap, info.joint_count) ||
      !(mats = (float*)malloc(16 * (size_t)info.joint_count * sizeof(float)))) {
    eval_trace_free(out);
    free(mats);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  out->dt = dt;

  memset(&cd, 0, sizeof(cd));
  cd.struct_size = sizeof(cd);
  cd.initial_style = desc->initial_style;
  cd.initial_action = desc->initial_action;
  cd.path_capacity = desc->path_count + 16;
  cd.constraint_capacity = desc->constraint_count + 8;
  cd.seed = desc->seed;
  cd.flags = desc->character_flags;
  cd.position[0] = desc->path_xz[0];
  cd.position[2] = desc->path_xz[1];
  if (desc->path_count > 1)
    cd.heading = (float)atan2(desc->path_xz[2] - desc->path_xz[0],
                              desc->path_xz[3] - desc->path_xz[1]);
  if ((r = smg_character_create(graph, &cd, &ch)) != SMG_OK) {
    if (error) snprintf(error, error_size, "smg_character_create: %s",
                        smg_result_string(r));
    goto fail;
  }

  /* The path is "given" here. */
  t0 = eval_now();
  r = smg_character_set_path(ch, desc->path_xz, desc->path_count);
  for (c = 0; r == SMG_OK && c < desc->constraint_count; ++c) {
    const eval_constraint* k = &desc->constraints[c];
    uint32_t id;
    r = k->kind == EVAL_KIND_SPLICE
            ? smg_character_add_splice(ch, k->arc, k->value, &id)
            : smg_character_add_transition(ch, k->arc, k->value, &id);
  }
  if (r == SMG_OK) r = smg_character_step(ch, (float)dt);
  if (r == SMG_OK)
    r = smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                         info.joint_count);
  out->first_pose_seconds = eval_now() - t0;
  out->step_seconds[0] = out->first_pose_seconds;
  if (r != SMG_OK) {
    if (error) snprintf(error, error_size, "first step: %s",
                        smg_result_string(r));
    goto fail;
  }
  if ((r = record(ch, out, 0, mats)) != SMG_OK) goto fail;
  out->frames = 1;

  for (i = 1; i < cap; ++i) {
    double s = eval_now();
    r = smg_character_step(ch, (float)dt);
    if (r == SMG_OK)
      r = smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                           info.joint_count);
    out->step_seconds[i] = eval_now() - s;
    if (r != SMG_OK) {
      if (error) snprintf(error, error_size, "step %zu: %s", i,
                          smg_result_string(r));
      goto fail;
    }
    if ((r = record(ch, out, i, mats)) != SMG_OK) goto fail;
    out->frames = i + 1;
    if ((out->flags[i] & SMG_STATE_PATH_END_REACHED) && after_end < 0) {
      out->reached_end = 1;
      after_end = 0.0;
    }
    if (after_end >= 0.0) {
      after_end += dt;
      if (after_end > desc->extra_seconds) break;
    }
    if ((double)i * dt > desc->max_seconds && after_end < 0.0) break;
  }
  free(mats);
  smg_character_destroy(ch);
  return SMG_OK;

fail:
  if (error && error_size && !error[0])
    snprintf(error, error_size, "%s", smg_result_string(r));
  free(mats);
  if (ch) smg_character_destroy(ch);
  eval_trace_free(out);
  return r;
}

size_t eval_read_path(const char* file, double* xz, size_t cap) {
  FILE* f = fopen(file, "r");
  char line[256];
  size_t n = 0;
  if (!f) return 0;
  while (fgets(line, sizeof(line), f)) {
    double x, z;
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    if (sscanf(line, "%lf %lf", &x, &z) != 2) continue;
    if (n == cap) {
      n = 0;
      break;
    }
    xz[2 * n] = x;
    xz[2 * n + 1] = z;
    ++n;
  }
  fclose(f);
  return n;
}
