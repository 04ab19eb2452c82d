/*
 * step_in.h - what every stage may read of the character besides its own
 * state: the graph, the path, the constraints and where the character is
 * along the path. The step (step.c) and the API (character.c) fill it from
 * the character; stages get it `const` and never see the character itself.
 */
#ifndef SMG_STEP_IN_H
#define SMG_STEP_IN_H

#include <stdint.h>

#include "constraints.h"
#include "graph_data.h"
#include "path.h"

typedef struct smgi_step_in {
  const smg_graph* graph;
  const smgi_path* path;         /* what to follow */
  const smgi_constraints* cons;  /* transition and splice points */
  float fps;                     /* the graph's frame rate */
  float progress;                /* arc length of the ground position's
                                    projection onto the path */
  uint32_t seg;                  /* segment of that projection */
  float path_error;              /* distance of the ground position from
                                    the path */
  float anchor[2];               /* where to stay without a path */
  double time;                   /* seconds stepped */
} smgi_step_in;

#endif /* SMG_STEP_IN_H */
