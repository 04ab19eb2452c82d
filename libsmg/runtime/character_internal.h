/*
 * character_internal.h - what an smg_character is, shared by the runtime's
 * character files (character.c, path.c, constraints.c, planner.c,
 * playback.c, upper.c, sync.c, pose.c, ik.c). Every buffer is carved out of
 * one block allocated at create, so stepping never allocates.
 */
#ifndef SMG_CHARACTER_INTERNAL_H
#define SMG_CHARACTER_INTERNAL_H

#include <stdint.h>

#include "graph_derived.h"
#include "graph_internal.h"
#include "rmath.h"
#include "smg.h"

#define SMGI_QUEUE_CAP 64u        /* committed + planned lower edges */
#define SMGI_MAX_CANDIDATES 64u   /* out-edges ranked per planning step */
#define SMGI_PLAN_BUDGET 256u     /* edge evaluations per step (look-ahead
                                     included; ~25 us at most) */
#define SMGI_LOOK_BUDGET 48u      /* look-ahead edge evaluations per candidate */
#define SMGI_SEARCH_SECONDS 1.2f  /* look-ahead window below a candidate */
#define SMGI_MAX_RANK 3u          /* backtracking tries per node */
#define SMGI_MAX_BACKTRACKS 8u    /* backtracks before accepting the best */
#define SMGI_SPLICE_WINDOW 20u    /* lower frames searched for a splice */
#define SMGI_SYNC_LOWER 8u        /* DTW window, lower frames */
#define SMGI_SYNC_UPPER 16u       /* DTW window, upper frames */
#define SMGI_POSE_STACK_JOINTS 64u /* pose scratch on the stack up to here
                                      (1 KiB) */

/* A constraint on the path. */
typedef struct smgi_constraint {
  uint32_t id;     /* > 0 */
  uint32_t kind;   /* SMGI_CONSTRAINT_* */
  uint32_t value;  /* style or action */
  float arc;       /* metres along the path */
} smgi_constraint;

#define SMGI_CONSTRAINT_TRANSITION 0u
#define SMGI_CONSTRAINT_SPLICE 1u

/* One lower-graph edge in the queue. The head entry is playing; the others
 * are planned and may be dropped and re-planned at any time. */
typedef struct smgi_qentry {
  uint32_t edge;
  uint32_t seq;         /* increases by one per pushed entry */
  smgi_xform2 W;        /* ground transform at the edge start */
  smgi_xform2 M;        /* W * inverse(ground(from.frame)): frame -> world */
  float s_start, s_end; /* planned progress along the path */
  uint32_t seg_end;     /* path segment hint at s_end */
  uint16_t rank;        /* which candidate (0 = best) this was */
  uint16_t cand_count;  /* candidates that were available */
  float err;            /* distance error of the choice */
} smgi_qentry;

/* The path: interleaved (x, z) points with cumulative arc lengths. */
typedef struct smgi_path {
  float* xz;       /* 2 * capacity */
  float* cum;      /* capacity: arc length at each point */
  uint32_t count, capacity;
  float length;
} smgi_path;

/* A scheduled switch of the upper body to a splice candidate. */
typedef struct smgi_pending_splice {
  uint32_t valid;
  uint32_t seq;     /* queue entry holding the lower frame */
  uint32_t offset;  /* frame offset inside that entry's edge */
  uint32_t splice;  /* SPLC index */
} smgi_pending_splice;

typedef struct smgi_foot {
  uint32_t planted;    /* contact currently anchored */
  float anchor[3];     /* world toe position at contact start */
  float weight;        /* IK blend weight 0..1 */
  float fix[2][4];     /* world-space hip and knee rotations the last solve
                          added (identity when the foot was not solved): the
                          next solve starts from them */
} smgi_foot;

struct smg_character {
  smg_graph* graph;
  smg_allocator allocator;
  uint32_t joint_count;
  uint32_t flags;
  uint32_t ik_enabled;
  uint32_t rng;
  float plan_phase;        /* 0..1 of a step added to the horizon (planner.c) */
  float horizon;           /* seconds */
  float error_threshold;   /* metres */
  float fps;

  /* path and constraints */
  smgi_path path;
  smgi_constraint* constraints;
  uint32_t constraint_count, constraint_capacity, next_id;
  uint32_t base_style, base_action;  /* set_style/set_action and initial */
  float base_style_arc, base_action_arc; /* where they apply from */
  float anchor[2];         /* where to stay when there is no path to follow */

  /* progress of the character along the path */
  float progress;          /* arc length of the root's projection */
  uint32_t seg;            /* segment of that projection */
  float path_error;

  /* lower playback */
  smgi_qentry* queue;      /* ring of SMGI_QUEUE_CAP */
  uint32_t q_head, q_count, next_seq;
  uint32_t q_frames;       /* sum of frame counts of the queued edges */
  float t;                 /* frames into the head edge (fractional) */
  uint32_t backtracks;     /* since the last within-threshold choice */
  uint32_t lower_node;
  uint32_t style;
  uint32_t end_reached;
  double time;
  uint32_t last_lower_frame; /* integer lower frame last processed */

  /* upper playback */
  uint32_t action;         /* action being played (0 = lower's own) */
  uint32_t uedge, unext;   /* current and next upper edge */
  float ut;                /* frames into uedge */
  float correction[4];     /* Horn correction at the spine base */
  float fade;              /* crossfade progress 0..1 (1 = done) */
  float fade_rate;         /* 1 / window seconds */
  uint32_t upper_node;
  smgi_pending_splice pending;
  float want_time;         /* seconds an unmet action has waited */
  float sync_rate;

  /* feet */
  smgi_foot feet[2];

  /* output pose and scratch, joint_count-sized */
  float root[3];           /* world position of joint 0 */
  float heading;           /* ground heading of the character */
  float ground[2];         /* ground position (x, z) */
  uint32_t contacts;       /* SMG_STATE_*_CONTACT bits of the frame */
  float* rot;              /* 4J: output local rotations */
  float* tmp;              /* 4J: crossfade sampling scratch, only for
                              skeletons of more than SMGI_POSE_STACK_JOINTS
                              joints (NULL otherwise: pose.c uses the
                              stack) */
  float* snap;             /* 4J: upper-body snapshot for crossfades */
  float* wpos;             /* 3J: world joint positions of the pose */
  float* wrot;             /* 4J: world joint rotations of the pose */
  /* 2J: per leg f at f*J, the joints whose world transforms IK changes,
   * parents first: hip, knee, ankle, then the hip's other descendants not
   * below the ankle (leg_side[f] of them: they turn with hip or knee), then
   * those below the ankle (leg_below[f]: the solved ankle keeps its world
   * rotation, so they only move with it). */
  uint32_t* leg_joints;
  uint32_t leg_ok[2];      /* hip > 0, knee's parent hip, ankle's parent knee */
  uint32_t leg_side[2], leg_below[2];
};

/* ---- path.c ---- */
void smgi_path_reset(smgi_path* p);
/* Point and tangent heading at arc length s (clamped); *seg is a hint in
 * and the segment out. */
void smgi_path_eval(const smgi_path* p, float s, uint32_t* seg, float* x,
                    float* z, float* heading);
/* Nearest point search starting at segment *seg, walking while the
 * distance shrinks (bounded steps). Returns arc length, writes *seg and the
 * distance. */
float smgi_path_project_local(const smgi_path* p, float x, float z,
                              uint32_t* seg, float* out_dist);
/* Copy `count` points to index `from`, extend the arc lengths and, if
 * `project`, return the exact nearest point to (px, pz) on the whole path
 * (arc length; *seg, *out_dist set) in the same pass. */
float smgi_path_load(smgi_path* p, const float* xz, uint32_t from,
                     uint32_t count, int project, float px, float pz,
                     uint32_t* seg, float* out_dist);
int smgi_all_finite(const float* v, uint32_t n);
/* Global nearest point (O(n)). */
float smgi_path_project_global(const smgi_path* p, float x, float z,
                               uint32_t* seg, float* out_dist);

/* ---- constraints.c ---- */
uint32_t smgi_style_at(const smg_character* ch, float s);
uint32_t smgi_action_at(const smg_character* ch, float s, float* out_arc);
/* Arc of the first splice/transition constraint strictly after s, or a
 * huge value. */
float smgi_next_constraint_arc(const smg_character* ch, float s);

/* ---- planner.c ---- */
/* Plan until the horizon is covered or `budget` candidate evaluations were
 * spent; this step's `step_frames` (plus one to interpolate) of lookahead
 * beyond the playhead are guaranteed regardless of budget. */
void smgi_plan(smg_character* ch, uint32_t budget, float step_frames);
/* Path or constraints changed: drop planned entries, keep the head. */
void smgi_replan(smg_character* ch);
/* First edge at create. */
smg_result smgi_plan_start(smg_character* ch, float x, float z, float h);

/* ---- queue helpers (playback.c) ---- */
static inline smgi_qentry* smgi_q_at(smg_character* ch, uint32_t i) {
  return &ch->queue[(ch->q_head + i) & (SMGI_QUEUE_CAP - 1u)];
}
static inline const smgi_qentry* smgi_q_at_c(const smg_character* ch,
                                             uint32_t i) {
  return &ch->queue[(ch->q_head + i) & (SMGI_QUEUE_CAP - 1u)];
}
/* Frames planned beyond the playhead. */
float smgi_frames_ahead(const smg_character* ch);
/* Lower frame sample position: entry index and frame offset of the
 * playhead plus k frames (returns 0 when beyond the queue). */
int smgi_q_locate(const smg_character* ch, uint32_t k, uint32_t* entry,
                  uint32_t* offset);
smg_result smgi_step(smg_character* ch, float dt);

/* ---- pose.c ---- */
/* Prefetch the pose buffers the step rewrites and the lower-body records
 * it will sample. Called before planning: in a big crowd these lines were
 * evicted since the character's last step, and the planner's work hides
 * the fetches. A hint only (no effect on results). */
void smgi_pose_prefetch(const smg_character* ch);
void smgi_pose_compose(smg_character* ch);
void smgi_fk(const smg_graph* g, const float* root, const float* rot,
             float* wpos, float* wrot);
/* Re-run FK of the cached world transforms for `count` joints listed
 * parents first (after IK changed some of their local rotations). */
void smgi_fk_joints(smg_character* ch, const uint32_t* list, uint32_t count);

/* ---- upper.c ---- */
void smgi_upper_advance(smg_character* ch, float lower_frames);
void smgi_upper_update_splice(smg_character* ch, float dt, int new_frame);
void smgi_upper_start(smg_character* ch);
/* Upper frame at fractional time: writes upper joint rotations into out
 * (4J, only upper joints touched). */
void smgi_upper_sample(const smg_character* ch, float* out);

/* ---- sync.c ---- */
void smgi_sync_update(smg_character* ch);

/* ---- ik.c ---- */
/* Feet unplanted, with no correction to start the next solve from. */
void smgi_ik_reset(smg_character* ch);
void smgi_ik_apply(smg_character* ch, float dt);

#endif /* SMG_CHARACTER_INTERNAL_H */
