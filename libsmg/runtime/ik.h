/*
 * ik.h - foot cleanup (ik.c): per foot, the contact anchor and the
 * correction the last solve applied; per leg, the joints a solve moves.
 */
#ifndef SMG_IK_H
#define SMG_IK_H

#include <stdint.h>

#include "graph_data.h"
#include "pose.h"
#include "smg.h"

typedef struct smgi_foot {
  uint32_t planted;    /* contact currently anchored */
  float anchor[3];     /* world toe position held while planted (x and z
                          are held; the height is always the animation's) */
  float toe[3];        /* the animated toe at the previous step (y
                          INFINITY: none yet) */
  float floor_y;       /* height the toe was last held at (-INFINITY:
                          none yet) */
  float stand_y;       /* lowest height the animated toe has stood at
                          (on uneven ground: above its ground, as the
                          data has it): the floor swing clearance keeps
                          the toe above (INFINITY: none yet) */
  float lift;          /* how far swing clearance raises the foot now */
  float shown[2];      /* x, z of the toe as shown at the previous step
                          (INFINITY: none yet) */
  uint32_t landing;    /* planted, but the animated toe still descends:
                          the anchor follows it until it stops */
  uint32_t let_go;     /* released during a contact (its anchor drifted
                          too far): not planted again before the weight
                          is back to 0 or the contact ends */
  float weight;        /* IK blend weight 0..1 */
  uint32_t guided;     /* placed by the caller this step (smgi_ik_guide) */
  float guide[3];      /* where: toe x, z and the ankle's raise above the
                          animation */
  float fix[2][4];     /* world-space hip and knee rotations the last solve
                          added (identity when the foot was not solved): the
                          next solve starts from them */
} smgi_foot;

/* Uneven ground (smg_character_set_ground): heights the engine measured at
 * the probes before the step; off, the feet stay on the data's flat floor
 * and nothing below is used. */
typedef struct smgi_ground {
  uint32_t on;
  float foot[2];        /* measured at the foot probes */
  float root;           /* measured at the root probe */
  float root_y;         /* the root's ground height as carried (smoothed);
                           NAN: none yet */
  float drop;           /* how far the pelvis is lowered, metres */
  float foot_y[2];      /* ground height each toe is placed on (moves at a
                           bounded rate); NAN: none yet */
  float prev_toe[2][2]; /* x, z of each toe at the previous step (probes);
                           INFINITY: none yet */
} smgi_ground;

typedef struct smgi_ik {
  uint32_t enabled;
  float swing_clearance; /* metres a fast swinging toe keeps above its
                            floor (0: none) */
  float swing_default;   /* the default clearance for this skeleton
                            (settings.c): the lift's rates scale with at
                            least this, so a lift left when clearance is
                            turned off still returns */
  smgi_foot feet[2];
  /* 2J: per leg f at f*J, the joints whose world transforms IK changes,
   * parents first: hip, knee, ankle, then the hip's other descendants not
   * below the ankle (leg_side[f] of them: they turn with hip or knee), then
   * those below the ankle (leg_below[f]: the solved ankle keeps its world
   * rotation, so they only move with it). */
  uint32_t* leg_joints;
  uint32_t leg_ok[2];      /* hip > 0, knee's parent hip, ankle's parent knee */
  uint32_t leg_side[2], leg_below[2];
  smgi_ground ground;
} smgi_ik;

/* Fill ik->leg_joints and the per-leg counts for the graph's skeleton,
 * using `mark` (joint_count bytes) as scratch. A leg that is not a
 * hip-knee-ankle parent chain is left without IK. */
void smgi_ik_init_legs(smgi_ik* ik, const smg_graph* g, uint8_t* mark);
/* Feet unplanted, with no correction to start the next solve from. */
void smgi_ik_reset(smgi_ik* ik);
/* Anchor feet in contact and solve their legs on the pose: its local
 * rotations and the cached world transforms (kept true for every joint
 * moved). On uneven ground the body is carried onto it first
 * (smgi_ground). */
/* For the next smgi_ik_apply only: hold foot f's toe at (x, z), its ankle
 * `raise` metres above where the animation has it, whatever the contact
 * labels say (rest.c places the feet of a character coming to rest or
 * turning on the spot); the foot stays planted there afterwards. */
void smgi_ik_guide(smgi_ik* ik, uint32_t f, float x, float z, float raise);
void smgi_ik_apply(smgi_ik* ik, smgi_pose* pose, const smg_graph* g,
                   float dt);
/* Ground off (the data's flat floor): nothing carried. */
void smgi_ground_reset(smgi_ground* ground);
/* Where the engine should measure the ground for the next step: x, z of
 * the left and right toes (xz holds 4 floats). */
void smgi_ground_probes(const smgi_ik* ik, const smgi_pose* pose,
                        const smg_graph* g, float* xz);

#endif /* SMG_IK_H */
