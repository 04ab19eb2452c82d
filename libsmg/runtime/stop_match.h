/*
 * stop_match.h - distance matching into stopping motion from the data
 * (stopping.h): near the path's end, the planner looks for a short route
 * of graph edges from where its plan ends into a stop whose rest lands on
 * the end, the entry frame chosen by the stop's remaining travel, as
 * shipping engines choose where to begin a stop animation. The route runs
 * on through the stop's own frames to its rest; the steering then plays
 * it at normal rate to the rest (steer.c) and the rest stage takes over.
 * Likewise, where the plan stands still in such data with path ahead,
 * a route into a start (smgi_start_match) sets it off as the data does.
 * Bounded work (SMGI_STOP_ROUTE_BUDGET edges looked at), no allocation.
 */
#ifndef SMG_STOP_MATCH_H
#define SMG_STOP_MATCH_H

#include <stdint.h>

#include "graph_data.h"
#include "path.h"
#include "rmath.h"

#define SMGI_STOP_ROUTE_LEAD 6u  /* edges before the stop's entry, at most */
#define SMGI_STOP_ROUTE_CAP 16u  /* edges in a route, entry to rest */
#define SMGI_STOP_ROUTE_BUDGET 1024u /* edges looked at per search */
#define SMGI_STOP_MATCH 0.5f     /* leg lengths the rest may miss the end
                                    by (0.4 m for a 0.8 m leg): the
                                    steering slides it out over the
                                    route, a tenth of its 3-4 m */

typedef struct smgi_stop_route {
  uint32_t edges[SMGI_STOP_ROUTE_CAP];
  uint32_t count;
  uint32_t rest_offset; /* the rest's frame offset in the last edge */
  float miss;           /* m: where the hips rest from the path's end */
} smgi_stop_route;

/* From `node` placed at W (the ground transform at its frame), `s` metres
 * along `path`: the route into a stop whose rest lands nearest the path's
 * end, if one lands within SMGI_STOP_MATCH leg lengths; 0 if none. */
int smgi_stop_match(const smg_graph* g, const smgi_path* path,
                    uint32_t node, smgi_xform2 W, float s,
                    smgi_stop_route* out);

/* Whether pool frame f stands still in a stop or start of the data (a
 * stop's frames from its rest on, a start's before it moves off). */
int smgi_stop_still(const smg_graph* g, uint32_t f);

/* From `node` placed at W, `s` metres along `path`, standing still: the
 * route into a start (stopping.h) that moves off soonest, run on through
 * its frames until it is back at locomotion speed, among those that set
 * off within SMGI_START_TURN of the path's direction; 0 if none. The
 * route's rest_offset is unused (0). */
#define SMGI_START_TURN 0.7854f /* rad (45 deg): the steering turns the
                                   rest on the way */
int smgi_start_match(const smg_graph* g, const smgi_path* path,
                     uint32_t seg, uint32_t node, smgi_xform2 W,
                     smgi_stop_route* out);

/* At rest, standing where W places the ground: the start whose last
 * standing node (graph_derived.h, start_entry) moves off soonest along
 * the path, entered there with that node's frame placed at W (standing
 * frames are one pose; the rest stage covers the change of stance), run
 * on until it is back at speed; 0 if none sets off within
 * SMGI_START_TURN of the path's direction. */
int smgi_start_jump(const smg_graph* g, const smgi_path* path, uint32_t seg,
                    smgi_xform2 W, smgi_stop_route* out);

#endif /* SMG_STOP_MATCH_H */
