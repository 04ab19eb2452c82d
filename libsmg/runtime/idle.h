/*
 * idle.h - the standing motion a character plays at rest, chosen once at
 * load (idle.c, called by graph_derived.c) from the stretches standing.h
 * finds in the pool: the longest one whose feet stand naturally close
 * (toes at most SMGI_IDLE_STANCE leg lengths apart), one from a
 * locomotion clip (the whole body stands) before one from an action.
 *
 * From an action the arms would wave unasked, so at rest its trunk (the
 * upper-body joints without a mirror partner: spine, neck, head) plays
 * with its lower body, frame for frame (the spine's turn on the hips
 * belongs to the hips' own sway), and the arms (the upper-body joints
 * with a partner) hold their rotations of the stretch's frame in which
 * their ends hang lowest: before the arms rise or after they come down.
 */
#ifndef SMG_IDLE_H
#define SMG_IDLE_H

#include <stddef.h>
#include <stdint.h>

#include "graph_data.h"

#define SMGI_IDLE_STANCE 0.5f /* leg lengths between the toes, at most */
#define SMGI_IDLE_TRUNK_SECONDS 1.0f /* from an action: the trunk averaged
                                        over this long (rest.c) */
#define SMGI_IDLE_SWING_DEFAULT 0.4f /* s a step takes in a graph without
                                        labelled swings */

typedef struct smgi_idle {
  uint32_t first, count; /* pool frames; count 0: the graph has none */
  uint32_t whole;        /* 1: from a locomotion clip, the whole body
                            stands; 0: from an action performed standing,
                            only its lower body is standing motion */
  /* left and right toe (x, z) at `first`, in that frame's ground frame
   * (FRMI root2d): where the feet stand relative to the hips */
  float toe[2][2];
  uint32_t arms;         /* whole 0: the pool frame whose arms the upper
                            body holds at rest (see above) */
  float floor;           /* the lower toe's height there (POSE space less
                            the ground height): where the motion's floor is */
  /* how far its hips' ground point strays from where it stands at
   * `first` (m, most over the stretch): a performer shifting weight while
   * waving stands a few centimetres off the spot the settling aims for */
  float sway;
  /* how long a foot swings in the graph's locomotion (median of its
   * labelled swings, seconds): the steps made at rest take as long */
  float swing_seconds;
  /* whole 0: the trunk's rotations averaged over SMGI_IDLE_TRUNK_SECONDS
   * about each frame of the stretch, count + 1 entries (the last about
   * the frame after it, the ends repeated) of smgi_idle_trunk_count
   * quaternions, each entry's signs those of its own frame; built at load
   * (smgi_idle_calm_build) so that standing plays them, not their sums.
   * NULL: none (whole 1, or no standing motion). */
  float* calm;
  uint32_t calm_joints; /* quaternions per entry of calm */
} smgi_idle;

/* Whether joint j is part of the trunk: an upper-body joint without a
 * mirror partner (spine, neck, head; an arm's joints have one). */
static inline int smgi_idle_trunk(const smgi_joint* joints, uint32_t j) {
  return joints[j].body_part == SMG_BODY_UPPER && joints[j].mirror == j;
}

/* The trunk's joints the calm table holds: those of smgi_idle_trunk but
 * the spine base (whose turn on the hips belongs to the hips' own sway:
 * played as is), in joint order. */
static inline int smgi_idle_calmed(const smg_graph* g, uint32_t j) {
  return j != g->data.info->spine_base_joint &&
         smgi_idle_trunk(g->data.joints, j);
}
uint32_t smgi_idle_trunk_count(const smg_graph* g);
/* Floats of idle's calm table (0: it has none). */
size_t smgi_idle_calm_floats(const smg_graph* g, const smgi_idle* idle);
/* Fills idle's calm table of smgi_idle_calm_floats floats. */
void smgi_idle_calm_build(const smg_graph* g, const smgi_idle* idle,
                          float* calm);

/* Clip-space position of joint j in pool frame f (the chain from the root
 * composed joint by joint: a leg is a handful of joints). */
void smgi_frame_joint(const smg_graph* g, uint32_t f, uint32_t j,
                      float* out);
/* Chooses g's idle motion (validated data). Bounded by the pool's size;
 * no allocation. */
void smgi_idle_choose(const smg_graph* g, smgi_idle* out);

#endif /* SMG_IDLE_H */
