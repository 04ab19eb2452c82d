/*
 * bake_internodal.c - the paper's "internodal data" (III.B.3): per edge,
 * what the runtime's path search needs without running forward kinematics:
 *   displacement = ground frame of the `to` node expressed in the ground
 *                  frame of the `from` node (dx, dz, dheading), computed
 *                  from the frames the edge actually stores: for a
 *                  transition the arrival frame is B_{b+k} placed in A's
 *                  space by the edge's alignment;
 *   arc_length   = length of the root's ground path from the `from` node
 *                  through the edge's frames to the arrival frame.
 * (Frame counts and costs are set by the graph stages.)
 */
#include <math.h>

#include "bake_internodal.h"
#include "bake_math.h"

static void frame_ground(const smgb_bake* b, uint32_t f, double g[3]) {
  g[0] = b->frames[f].root2d[0];
  g[1] = b->frames[f].root2d[1];
  g[2] = b->frames[f].root2d[2];
}

void smgb_edge_internodal(const smgb_bake* b, const smgb_graph* g,
                          const smgb_edge* e, float disp[3], float* arc) {
  double from[3], to[3], rel[3], prev[3], cur[3], len = 0.0;
  uint32_t t;
  frame_ground(b, g->nodes[e->from].frame, from);
  if (e->kind == SMGB_EDGE_TRANSITION) {
    double raw[3];
    frame_ground(b, g->nodes[e->to].frame, raw);
    smgb_g_compose(e->align, raw, to);
  } else {
    frame_ground(b, g->nodes[e->to].frame, to);
  }
  smgb_g_relative(from, to, rel);
  disp[0] = (float)rel[0];
  disp[1] = (float)rel[1];
  disp[2] = (float)rel[2];
  /* start at the from node itself (a blend's first frame is ~97 % of it)
   * so that arc_length >= |displacement| holds exactly */
  prev[0] = from[0];
  prev[1] = from[1];
  for (t = 1; t <= e->frame_count; ++t) {
    if (t < e->frame_count)
      frame_ground(b, e->first_frame + t, cur);
    else {
      cur[0] = to[0];
      cur[1] = to[1];
    }
    len += hypot(cur[0] - prev[0], cur[1] - prev[1]);
    prev[0] = cur[0];
    prev[1] = cur[1];
  }
  *arc = (float)len;
}
