/*
 * bake_state.c - lifetime of the state one bake shares between its stages
 * (bake_state.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_state.h"

void smgb_bake_init(smgb_bake* b, smg_bake_progress_fn progress,
                    void* progress_user) {
  memset(b, 0, sizeof *b);
  smgb_report_init(&b->report, progress, progress_user);
  smgb_options_resolve(NULL, &b->opt, &b->report);
  snprintf(b->actions[0], SMGB_LABEL_MAX, "none");
  b->action_count = 1;
}

void smgb_bake_free(smgb_bake* b) {
  free(b->poses);
  free(b->frames);
  free(b->positions);
  free(b->clips);
  free(b->splices);
  smgb_graph_free(&b->lower);
  smgb_graph_free(&b->upper);
  smgb_body_free(&b->body);
  smgb_skeleton_free(&b->skel);
  smgb_report_free(&b->report);
  memset(b, 0, sizeof *b);
}
