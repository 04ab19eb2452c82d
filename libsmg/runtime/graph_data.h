/*
 * graph_data.h - what an smg_graph is inside the runtime. Characters
 * read `data` (validated once at load, immutable afterwards) and bump
 * `character_count` so the graph cannot be destroyed under them.
 */
#ifndef SMG_GRAPH_DATA_H
#define SMG_GRAPH_DATA_H

#include <stdint.h>

#include "smg.h"
#include "quat_pack.h"
#include "rmath.h"
#include "smg_format.h"

struct smg_graph {
  smgi_graph_data data;      /* validated view into the blob */
  smg_allocator allocator;   /* resolved: never NULL functions */
  smg_logger logger;
  void* owned_blob;          /* the file's bytes when loaded from a file,
                                NULL when loaded in place */
  uint64_t blob_size;
  uint32_t format_version;
  uint32_t character_count;  /* live characters; changed only through
                                smgi_graph_retain/release (atomic) */
  void* derived;             /* smgi_derived (graph_derived.h): runtime
                                lookup tables built at load */
};

/* Runtime-derived tables (graph_derived.c): graph.c calls build after the
 * blob validated (failure fails the load) and free in destroy. */
smg_result smgi_graph_derived_build(smg_graph* graph);
void smgi_graph_derived_free(smg_graph* graph);

void smgi_graph_retain(smg_graph* graph);
void smgi_graph_release(smg_graph* graph);

/* POSE record i (SMGI_POSE_RECORD_SIZE bytes: root floats, then packed
 * rotations read with smgi_pose_rot + smgi_quat_unpack_raw). */
static inline const unsigned char* smgi_graph_pose(const smg_graph* g,
                                                   uint32_t i) {
  return smgi_pose_record(&g->data, i);
}

/* Frame `frame`'s ground transform (root2d: x, z, heading) and an edge's
 * ground displacement, as transforms: what the planner and the stop
 * matching chain edges with. */
static inline smgi_xform2 smgi_frame_ground(const smg_graph* g,
                                            uint32_t frame) {
  const float* r = g->data.frames[frame].root2d;
  smgi_xform2 x = {r[0], r[1], r[2]};
  return x;
}

static inline smgi_xform2 smgi_edge_displacement(const smgi_edge* e) {
  smgi_xform2 x = {e->displacement[0], e->displacement[1],
                   e->displacement[2]};
  return x;
}

/* Which joints smgi_sample_joints samples (joint 0, the root, never: its
 * rotation is placed in the world first). */
typedef enum smgi_joint_set {
  SMGI_JOINTS_ALL,       /* 1 .. J-1 */
  SMGI_JOINTS_NOT_UPPER, /* the lower body's own (an action replaces the
                            upper body) */
  SMGI_JOINTS_UPPER      /* SMG_BODY_UPPER joints only */
} smgi_joint_set;

/* The last POSE records a character's pose decoded (smgi_sample_frames),
 * kept as four-joint groups of x, y, z, w vectors: at 60 steps a second
 * on 30 fps data each record is sampled on about four steps (twice as
 * either end of the blend), and decoding was most of the sampling's cost.
 * Slots are filled on demand; `rot` is NULL where records are not kept
 * (no SSE2, or fewer than five joints). */
typedef struct smgi_decoded {
  uint32_t frame[2]; /* SMGI_NONE: empty */
  float* rot;        /* 2 * smgi_decoded_floats(J), or NULL */
} smgi_decoded;

/* Floats one slot of smgi_decoded takes for a skeleton of J joints (0:
 * records are not kept). */
uint32_t smgi_decoded_floats(uint32_t joint_count);

/* smgi_sample_joints of POSE records fa and fb, the same bits, decoding
 * through `dec` (straight from the records when its buffer is NULL). */
void smgi_sample_frames(const smg_graph* g, uint32_t fa, uint32_t fb,
                        float t, smgi_joint_set set, smgi_decoded* dec,
                        float* out);

/* out[4j .. 4j+4) = nlerp of joint j's rotations in POSE records ra and rb
 * at t, for the joints of `set` (others untouched); packed rotations are
 * decoded straight into the nlerp, four joints at a time where four
 * consecutive joints are wanted (graph_sample.c). */
void smgi_sample_joints(const smg_graph* g, const unsigned char* ra,
                        const unsigned char* rb, float t,
                        smgi_joint_set set, float* out);

#endif /* SMG_GRAPH_DATA_H */
