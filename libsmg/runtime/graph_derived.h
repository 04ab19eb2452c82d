/*
 * graph_derived.h - tables the runtime derives from a validated blob once at
 * load time (graph.c calls smgi_graph_derived_build after validation and
 * smgi_graph_derived_free in destroy). They turn per-frame questions such as
 * "how far is the nearest run edge from this node?" or "which splice
 * candidates exist at this lower frame?" into O(1) lookups, so character
 * stepping never scans the graph.
 */
#ifndef SMG_GRAPH_DERIVED_H
#define SMG_GRAPH_DERIVED_H

#include <stdint.h>

#include "graph_data.h"
#include "idle.h"
#include "stopping.h"
#include "tuning.h"

#define SMGI_HOPS_UNREACHABLE 255u
/* edge_style_time's unit (1 / this seconds) and its cap (8.5 s) */
#define SMGI_STYLE_TIME_HZ 30.0
#define SMGI_STYLE_TIME_FAR 254u

/* What the sequence search reads of lower node n where it stops choosing
 * (smgi_seq_leaf), in one 128-byte record aligned to 64 bytes (two cache
 * lines): on a big graph (tens of thousands of nodes, tables far larger
 * than the caches) each of these was a table of its own and a cache miss
 * of its own for every node the search reached.
 *  - natural: the out-edge continuing the node's original motion
 *    (first_frame == the node's frame, not a transition), else its
 *    cheapest, else SMGI_NONE;
 *  - trail[4 k .. 4 k + 3]: the natural continuation sampled every
 *    SMGI_TRAIL_STEP_SECONDS (at the first edge end past each step): dx,
 *    dz, dheading in the node's ground frame and the arc length;
 *    trail_frames[k] the frames elapsed there (equal to the previous
 *    sample's when the continuation ended), trail_edge[k] the edge
 *    playing then and trail_label[k] its label (SMGI_TRAIL_LABEL_WIDE
 *    when it does not fit 16 bits: read the edge's). The search values
 *    what follows its last choice from this in O(1) per sample; the
 *    label beside it spares the style term a read of each sample's edge
 *    record (a cache miss of its own on a big graph) unless the label
 *    differs from the wanted one;
 *  - turn[0], turn[1]: the largest heading change to the left (+) and to
 *    the right (magnitude) that any edge sequence from the node reaches
 *    within SMGI_TURN_SECONDS - whether a turn is possible soon, beyond
 *    what the planner searches (a straight walking loop whose exits to
 *    turning clips are far away looks as good as any other until then). */
#define SMGI_TRAIL_LABEL_WIDE 0xffffu
typedef struct smgi_node_next {
  float trail[4u * SMGI_TRAIL_SAMPLES];
  float trail_frames[SMGI_TRAIL_SAMPLES];
  uint32_t trail_edge[SMGI_TRAIL_SAMPLES];
  float turn[2];
  uint32_t natural;
  uint16_t trail_label[SMGI_TRAIL_SAMPLES];
  uint32_t unused[3]; /* zero: pads the record to 128 bytes */
} smgi_node_next;
/* two cache lines exactly (SMGI_TRAIL_SAMPLES is 4) */
typedef char smgi_node_next_is_128_bytes[sizeof(smgi_node_next) == 128u ? 1
                                                                         : -1];

/* What the sequence search reads of lower edge e when it weighs it
 * (smgi_seq_step), in one 48-byte record; a node's out-edges are side by
 * side, as in LEDG. On a big graph the LEDG record, the mid-edge sample
 * (a table of its own) and the `to` node's out-edge range (in its
 * node_next record) were three cache misses per edge weighed; here they
 * are one or two per node expanded.
 *  - displacement, arc_length, frame_count, to, label: as in LEDG;
 *  - mid (edges of 4+ frames, else zero): the root's ground transform at
 *    frame frame_count / 2 relative to the edge's start (x, z, heading),
 *    i.e. inverse(ground(from.frame)) * ground(mid). The search places it
 *    with the same rotation as the edge's end instead of composing two
 *    transforms from two pose records;
 *  - to_first_edge, to_edge_count: the `to` node's out-edges (LNOD), where
 *    the search goes on from. */
typedef struct smgi_search_edge {
  float displacement[3];
  float arc_length;
  float mid[3];
  uint32_t to;
  uint32_t frame_count;
  uint32_t label;
  uint32_t to_first_edge, to_edge_count;
} smgi_search_edge;
typedef char smgi_search_edge_is_48_bytes[sizeof(smgi_search_edge) == 48u
                                              ? 1
                                              : -1];

typedef struct smgi_derived {
  /* lower_hops[node * style_count + style]: number of edges to traverse
   * from `node` before an out-edge labelled `style` is available (0: the
   * node itself has one); SMGI_HOPS_UNREACHABLE when none can be reached.
   * What tells edge_style_time's "far" from "unreachable", and its hop
   * worth (style_time_hop). */
  const uint8_t* lower_hops;
  /* Per style and lower edge, how much motion lies between the edge's
   * from node (edge_style_time[2 * (style * lower_edge_count + edge)]) and
   * its to node (the byte after) and an out-edge of the style: the
   * shortest sum of edge durations to a node that has one, in steps of
   * 1 / SMGI_STYLE_TIME_HZ s (rounded; SMGI_STYLE_TIME_FAR at and beyond
   * that, SMGI_HOPS_UNREACHABLE where lower_hops says no path exists).
   * The search's style term reads both for an edge it weighs against the
   * wanted style, in hops (style_time_hop). Time, not edges: a clip's
   * edges are many and short where transitions leave it often, so a hop
   * count made a detour through a third style (a few long edges, each
   * near the wanted style) look nearer than the direct transition a few
   * short edges along the old style. A node's out-edges are contiguous,
   * so their pairs are too (on a big graph every `to` row of a node table
   * was a cache miss of its own), and a style's pairs for all edges are 2
   * bytes an edge: for the few styles a crowd wants at once they stay in
   * the cache. */
  const uint8_t* edge_style_time;
  /* style_time_hop[style]: what one step of edge_style_time towards the
   * style weighs in hops: the graph's hop counts to it over its times,
   * summed over every node a step or more (and less than the cap) away.
   * The search's style weight was set per hop; in these units the same
   * weight holds on average for each wanted style on any graph, and hop
   * for hop (to the steps' rounding) on one whose edges all last as
   * long. */
  const float* style_time_hop;
  /* Same as lower_hops for the upper graph and actions. */
  const uint8_t* upper_hops;
  /* Splices at lower frame f are splices[splice_first[f] ..
   * splice_first[f + 1]) (SPLC is sorted by lower_frame); frame_count + 1
   * entries. */
  const uint32_t* splice_first;
  /* The lower nodes with out-edges, by label and then index: those of
   * style s are start_nodes[start_first[s] .. start_first[s + 1])
   * (style_count + 1 offsets); first_start is the first of all (SMGI_NONE:
   * no node has edges). Where a new character starts (planner.c) without
   * a scan of every node. */
  const uint32_t* start_first;
  const uint32_t* start_nodes;
  uint32_t first_start;
  /* First upper edge labelled with each action (SMGI_NONE if none): the
   * entry used when a splice must happen but no candidate was found. */
  const uint32_t* action_first_edge;
  /* node_next[node]: what the planner's sequence search reads of a lower
   * node, in one record (below). */
  const struct smgi_node_next* node_next;
  /* search_edges[edge]: what the search reads of a lower edge, in one
   * record (above). */
  const smgi_search_edge* search_edges;
  /* The style whose motion turns most tightly (heading change per metre of
   * its nodes' natural continuations, node_next.trail): where a character
   * that got far off its path goes to get back (CMU runs, for one, barely
   * turn). */
  uint32_t agile_style;
  /* style_can_stop[style]: 1 when some lower edge of the style has a
   * frame with both feet down, or a frame where support passes straight
   * from one foot to the other - a pose a character can come to rest on
   * (walks have them, runs with their flight phases do not) - and whose
   * speed is below the walk-run transition (SMGI_STOP_FROUDE): a runner
   * slows to a walk before it stops. */
  const uint8_t* style_can_stop;
  /* The fastest style that can stop (SMGI_NONE: none) and its mean speed
   * (m/s): what a character in a style that cannot stop slows to over its
   * last metres. */
  uint32_t stop_style;
  float stop_speed;
  /* The standing motion played at rest (idle.h; count 0: none). */
  smgi_idle idle;
  /* Stopping and starting motion in the data (stopping.h), in pool order
   * of `first`; none (count 0, NULL tables) where every clip ends and
   * begins in motion, as in all the shared graphs. For stop k,
   * stop_left[stop_left_first[k] + f - stops[k].first] is the hips'
   * ground travel left from pool frame f in [first, rest] to rest: what
   * distance matching reads (stop_match.c). */
  const smgi_stop_seg* stops;
  uint32_t stop_count;
  uint32_t start_count; /* of them, starts */
  float stop_longest;   /* m: the longest way a stop travels from its
                           first frame to rest (0: no stops) */
  const float* stop_left;
  const uint32_t* stop_left_first;
  /* start_entry[k] for start k: its last node standing before it moves
   * off (the latest node with out-edges whose frame lies in [first,
   * rest]), where a character at rest enters it; SMGI_NONE for stops and
   * starts without one. */
  const uint32_t* start_entry;
  void* stop_block; /* owns the three tables */
} smgi_derived;

/* Build g->derived through g->allocator. The graph must be validated. */
smg_result smgi_graph_derived_build(smg_graph* g);
/* Free g->derived (NULL-safe) and set it to NULL. */
void smgi_graph_derived_free(smg_graph* g);

static inline const smgi_derived* smgi_derived_of(const smg_graph* g) {
  return (const smgi_derived*)g->derived;
}

#endif /* SMG_GRAPH_DERIVED_H */
