/*
 * smg_format.h - the graph blob's records and the in-memory view of them.
 *
 * This is the contract between the offline baker (which fills an
 * smgi_graph_data and serialises it with smgi_blob_write) and the runtime
 * (which validates a blob with smgi_blob_read and gets the same
 * smgi_graph_data back, its pointers aimed into the blob: load in place).
 * docs/blob-format.md describes the same layout in prose; keep both in step.
 *
 * Every record is made of 4-byte fields (uint32_t, int32_t, float) so the
 * layout has no padding and is the same on every little-endian compiler;
 * POSE records (float root, then 16-bit words) are sized to a multiple of 4
 * and zero-padded by the writer.
 * Internal symbols use the smgi_ prefix and are never exported.
 */
#ifndef SMG_FORMAT_H
#define SMG_FORMAT_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

/* ---- container ---------------------------------------------------------- */

#define SMGI_BLOB_MAGIC "SMGGRAPH"       /* 8 bytes, no NUL stored */
#define SMGI_BLOB_ENDIAN 0x01020304u     /* reads 0x04030201 if swapped */
#define SMGI_BLOB_VERSION 2u       /* 1: float POSE rotations (refused) */
#define SMGI_BLOB_ALIGN 16u              /* blob base and every section */
#define SMGI_MAX_SECTIONS 64u

#define SMGI_FOURCC(a, b, c, d)                                  \
  ((uint32_t)(uint8_t)(a) | ((uint32_t)(uint8_t)(b) << 8) |      \
   ((uint32_t)(uint8_t)(c) << 16) | ((uint32_t)(uint8_t)(d) << 24))

typedef struct smgi_blob_header {
  char magic[8];             /* SMGI_BLOB_MAGIC */
  uint32_t endian;           /* SMGI_BLOB_ENDIAN */
  uint32_t version;          /* SMGI_BLOB_VERSION */
  uint64_t total_size;       /* whole blob, bytes, multiple of 16 */
  uint32_t header_size;      /* sizeof(smgi_blob_header) = 64 */
  uint32_t section_count;    /* entries in the table after the header */
  uint64_t checksum;         /* SMG-WH64 of bytes [header_size, total) */
  uint32_t flags;            /* 0 */
  uint32_t reserved[5];      /* 0 */
} smgi_blob_header;          /* 64 bytes */

typedef struct smgi_blob_section {
  uint32_t tag;              /* SMGI_SEC_* fourcc */
  uint32_t alignment;        /* 16 */
  uint64_t offset;           /* from blob start, multiple of alignment */
  uint64_t size;             /* bytes = count * record size */
  uint32_t count;            /* records */
  uint32_t record_size;      /* bytes per record (checked per tag) */
} smgi_blob_section;         /* 32 bytes */

/* ---- section tags (all required) ------------------------------------------ */

#define SMGI_SEC_INFO SMGI_FOURCC('I', 'N', 'F', 'O') /* 1 smgi_info */
#define SMGI_SEC_STRS SMGI_FOURCC('S', 'T', 'R', 'S') /* char, NUL-separated */
#define SMGI_SEC_JNTS SMGI_FOURCC('J', 'N', 'T', 'S') /* smgi_joint */
#define SMGI_SEC_STYL SMGI_FOURCC('S', 'T', 'Y', 'L') /* smgi_label */
#define SMGI_SEC_ACTN SMGI_FOURCC('A', 'C', 'T', 'N') /* smgi_label */
#define SMGI_SEC_CLIP SMGI_FOURCC('C', 'L', 'I', 'P') /* smgi_clip */
#define SMGI_SEC_POSE SMGI_FOURCC('P', 'O', 'S', 'E') /* root + packed J */
#define SMGI_SEC_FRMI SMGI_FOURCC('F', 'R', 'M', 'I') /* smgi_frame */
#define SMGI_SEC_LNOD SMGI_FOURCC('L', 'N', 'O', 'D') /* smgi_node, lower */
#define SMGI_SEC_LEDG SMGI_FOURCC('L', 'E', 'D', 'G') /* smgi_edge, lower */
#define SMGI_SEC_UNOD SMGI_FOURCC('U', 'N', 'O', 'D') /* smgi_node, upper */
#define SMGI_SEC_UEDG SMGI_FOURCC('U', 'E', 'D', 'G') /* smgi_edge, upper */
#define SMGI_SEC_SPLC SMGI_FOURCC('S', 'P', 'L', 'C') /* smgi_splice */

#define SMGI_NONE 0xffffffffu /* "no index" in uint32_t index fields */

/* ---- records ------------------------------------------------------------ */

/* Global facts. Joint indices refer to JNTS. */
typedef struct smgi_info {
  float frame_rate;          /* frames per second of POSE (e.g. 30) */
  uint32_t joint_count;      /* J; must equal JNTS count */
  uint32_t pelvis_joint;     /* root joint (0): lower body's base */
  uint32_t spine_base_joint; /* first upper-body joint (CMU: LowerBack),
                                where the Horn correction is applied */
  uint32_t left_leg[4];      /* hip(UpLeg), knee(Leg), ankle(Foot), toe */
  uint32_t right_leg[4];
  float leg_length;          /* hip-to-ankle at rest, metres */
  float ground_height;       /* floor y in POSE root space, metres */
  float window_seconds;      /* transition/splice blend window length */
  uint32_t bake_flags;       /* informational: mirrored etc. */
  /* statistics printed by `smg-bake --info` */
  uint32_t lower_nodes_before_simplify, lower_edges_before_simplify;
  uint32_t upper_nodes_before_simplify, upper_edges_before_simplify;
  uint32_t reserved[8];
} smgi_info;

/* A skeleton joint. Parents precede children (parent < index). */
typedef struct smgi_joint {
  uint32_t name;             /* byte offset into STRS */
  int32_t parent;            /* -1 for joint 0 only */
  uint32_t body_part;        /* SMG_BODY_ROOT / _LOWER / _UPPER */
  uint32_t mirror;           /* joint index of the left/right counterpart
                                (itself when central) */
  float offset[3];           /* rest offset from parent, metres */
  float mass_ratio;          /* segment mass / body mass (Ae et al. 1996),
                                0 for helper joints */
} smgi_joint;

/* A style or action name. ACTN[0] is always "none". */
typedef struct smgi_label {
  uint32_t name;             /* byte offset into STRS */
  uint32_t flags;            /* reserved, 0 */
} smgi_label;

/* A source clip, for diagnostics and for per-frame provenance. */
typedef struct smgi_clip {
  uint32_t name;             /* byte offset into STRS (file name) */
  uint32_t first_frame;      /* its first frame in POSE */
  uint32_t frame_count;
  uint32_t label;            /* style (lower clips) or action (upper) */
  uint32_t flags;            /* SMGI_CLIP_* */
  uint32_t source_clip;      /* for a mirror: the clip it mirrors */
} smgi_clip;

#define SMGI_CLIP_LOWER 1u    /* feeds the locomotion graph */
#define SMGI_CLIP_UPPER 2u    /* feeds the action graph */
#define SMGI_CLIP_MIRROR 4u   /* reflected copy */
#define SMGI_CLIP_BLEND 8u    /* pseudo-clip holding blended transitions */

/* POSE: frame_count records of SMGI_POSE_RECORD_SIZE(J) bytes:
 *   float root[3]         root translation (metres, clip space, y up)
 *   uint8_t rot[J][6]     J local rotations, each a 48-bit "smallest three"
 *                         quaternion (quat_pack.h); joint 0's is the root's
 *                         orientation in clip space
 *   zero padding to a multiple of 4 bytes (2 bytes when J is odd).
 * Version 1 stored the rotations as 4 floats (508 bytes a frame for 31
 * joints, 200 now). Code that wants floats unpacks with smgi_pose_unpack
 * into SMGI_POSE_FLOATS(J) floats: root then J quaternions (x, y, z, w),
 * the baker's own pose layout. */
#define SMGI_POSE_ROT_OFFSET 12u
#define SMGI_POSE_RECORD_SIZE(joint_count) \
  ((12u + 6u * (uint32_t)(joint_count) + 3u) & ~3u)
#define SMGI_POSE_FLOATS(joint_count) (3u + 4u * (uint32_t)(joint_count))

/* Per-frame facts (FRMI, one per POSE frame). */
typedef struct smgi_frame {
  float root2d[3];           /* ground frame of this pose: x, z, heading
                                (heading = yaw of the root's forward) */
  uint32_t flags;            /* SMGI_FRAME_* */
  uint32_t clip;             /* index into CLIP */
  float phase;               /* gait phase in [0,1): 0 at left foot-strike;
                                -1 when undefined (no steps) */
} smgi_frame;

#define SMGI_FRAME_LEFT_CONTACT 1u
#define SMGI_FRAME_RIGHT_CONTACT 2u

/* A graph node: a pose where edges start and end. Out-edges of node n are
 * edges[first_edge .. first_edge + edge_count) (edges sorted by `from`). */
typedef struct smgi_node {
  uint32_t frame;            /* POSE index of the node's pose */
  uint32_t first_edge;
  uint32_t edge_count;
  uint32_t label;            /* style (lower graph) / action (upper) */
} smgi_node;

/* A graph edge plays POSE frames [first_frame, first_frame + frame_count)
 * and arrives at node `to` (whose frame is the next pose after them). All
 * frames of an edge are expressed in the coordinate space of node `from`'s
 * frame; the runtime places them with
 *   world = W * inverse(ground(from.frame)) * frame
 * where W is the character's ground transform when the edge starts. */
typedef struct smgi_edge {
  uint32_t from, to;         /* node indices */
  uint32_t first_frame;      /* POSE index */
  uint32_t frame_count;      /* >= 1 */
  float displacement[3];     /* ground transform from `from` to `to` in
                                from's ground frame: dx, dz, dheading */
  float arc_length;          /* root distance travelled over the edge */
  float cost;                /* transition distance (0: original motion) */
  uint32_t label;            /* style / action of the frames */
  uint32_t flags;            /* SMGI_EDGE_* */
  uint32_t reserved;
} smgi_edge;

#define SMGI_EDGE_TRANSITION 1u /* blended frames, not original motion */
#define SMGI_EDGE_MIRRORED 2u
#define SMGI_EDGE_STYLE_CHANGE 4u /* lower: from's label != to's label */

/* A splice candidate: at lower POSE frame `lower_frame`, the upper body may
 * switch to action `action`, entering the upper graph at edge `upper_edge`,
 * `upper_offset` frames into it. `correction` is the rotation (Horn 1987)
 * applied to the spine base so that the action's upper body interlocks
 * with the locomotion's pelvis. Sorted by (lower_frame, action, distance). */
typedef struct smgi_splice {
  uint32_t lower_frame;
  uint32_t action;
  uint32_t upper_edge;
  uint32_t upper_offset;
  float distance;            /* upper-body segment-COG distance */
  float correction[4];       /* quaternion x, y, z, w (unit) */
  uint32_t reserved;
} smgi_splice;

/* ---- the in-memory view --------------------------------------------------- */

/* Everything the runtime reads. After smgi_blob_read the pointers aim into
 * the blob; the baker fills them from its own arrays before writing. */
typedef struct smgi_graph_data {
  const smgi_info* info;
  const char* strings;       uint32_t strings_size;
  const smgi_joint* joints;  uint32_t joint_count;
  const smgi_label* styles;  uint32_t style_count;
  const smgi_label* actions; uint32_t action_count;
  const smgi_clip* clips;    uint32_t clip_count;
  const unsigned char* poses; uint32_t frame_count; /* POSE records, FRMI */
  const smgi_frame* frames;
  const smgi_node* lower_nodes; uint32_t lower_node_count;
  const smgi_edge* lower_edges; uint32_t lower_edge_count;
  const smgi_node* upper_nodes; uint32_t upper_node_count;
  const smgi_edge* upper_edges; uint32_t upper_edge_count;
  const smgi_splice* splices;   uint32_t splice_count;
} smgi_graph_data;

#endif /* SMG_FORMAT_H */
