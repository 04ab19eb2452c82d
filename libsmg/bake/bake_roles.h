/*
 * bake_roles.h - body roles: which joint of a skeleton is the pelvis, the
 * spine base, each leg's hip/knee/ankle/toe, the neck, head and arms.
 *
 * Every stage that needs to know the body (body split, leg chains, segment
 * centres of gravity, leg length, unit guess, mirroring) asks this module
 * instead of looking up joint names itself. Roles are recognised from the
 * common naming conventions (CMU, Bandai Namco, Mixamo "mixamorig:",
 * Godot's SkeletonProfileHumanoid, Unity/VRM humanoid, Unreal and Blender
 * style "thigh_l"/"thigh.L") and can be named explicitly with a bone map
 * (manifest `bones` statement, smg_bake_clip_desc.bones):
 *
 *   "left_foot=Foot_L\nright_foot=Foot_R"   (one role=joint per line)
 *
 * Recognition splits a joint name into words (camelCase, '_', '.', '-',
 * ' '), drops a namespace ("ns:") and rig prefixes ("mixamorig", "Bip01"),
 * takes a word "L"/"Left"/"R"/"Right" as the side, and matches the rest
 * against per-role synonyms (see bake_roles.c). Where several joints match
 * one role, the one closest to the root wins (Spine before Spine1).
 */
#ifndef BAKE_ROLES_H
#define BAKE_ROLES_H

#include <stdint.h>

#include "bake_report.h"
#include "bake_skeleton.h"
#include "smg.h"

typedef enum smgb_role {
  SMGB_ROLE_PELVIS = 0,     /* the translating root (joint 0 in a bake) */
  SMGB_ROLE_SPINE_BASE,     /* first upper-body joint (pelvis child) */
  SMGB_ROLE_NECK,
  SMGB_ROLE_HEAD,
  SMGB_ROLE_LEFT_UPPER_LEG, /* hip joint (thigh) */
  SMGB_ROLE_LEFT_LOWER_LEG, /* knee (shin) */
  SMGB_ROLE_LEFT_FOOT,      /* ankle */
  SMGB_ROLE_LEFT_TOES,      /* ball of the foot */
  SMGB_ROLE_RIGHT_UPPER_LEG,
  SMGB_ROLE_RIGHT_LOWER_LEG,
  SMGB_ROLE_RIGHT_FOOT,
  SMGB_ROLE_RIGHT_TOES,
  SMGB_ROLE_LEFT_UPPER_ARM, /* shoulder joint (upper arm bone) */
  SMGB_ROLE_LEFT_LOWER_ARM, /* elbow */
  SMGB_ROLE_LEFT_HAND,      /* wrist */
  SMGB_ROLE_RIGHT_UPPER_ARM,
  SMGB_ROLE_RIGHT_LOWER_ARM,
  SMGB_ROLE_RIGHT_HAND,
  /* optional roles: -1 when absent */
  SMGB_ROLE_LEFT_SHOULDER,  /* clavicle */
  SMGB_ROLE_RIGHT_SHOULDER,
  SMGB_ROLE_LEFT_FINGERS,   /* a finger base (index), hand COG direction */
  SMGB_ROLE_RIGHT_FINGERS,
  SMGB_ROLE_COUNT
} smgb_role;

/* Roles before this one are required by a bake. */
#define SMGB_ROLE_REQUIRED_COUNT ((int)SMGB_ROLE_LEFT_SHOULDER)

typedef struct smgb_roles {
  int32_t joint[SMGB_ROLE_COUNT]; /* joint index per role, -1 = none */
} smgb_roles;

/* Role name as written in bone maps and errors ("left_upper_leg"). */
const char* smgb_role_name(smgb_role role);
/* Role from its name; -1 when unknown. */
int smgb_role_from_name(const char* name);
/* The role with the other side (left_foot <-> right_foot); itself when
 * central. */
smgb_role smgb_role_counterpart(smgb_role role);

/* Check a bone map's syntax and role names (not the joints: those are
 * checked against a skeleton by smgb_roles_find). `source` names the map
 * in errors. NULL or "" is a valid empty map. */
smg_result smgb_bone_map_check(const char* map, const char* source,
                               smgb_error* err);

/* Find every role of `s`: the bone map first (a role it names must exist,
 * else SMG_ERROR_INVALID_ARGUMENT naming `source`, the role and the joint),
 * then by name, then structurally (pelvis = common ancestor of the legs
 * and head, spine base = the pelvis child leading to the head). Missing
 * required roles fail with a message naming `source` and the role. */
smg_result smgb_roles_find(const smgb_skeleton* s, const char* bone_map,
                           const char* source, smgb_roles* out,
                           smgb_error* err);
/* Same recognition without the bone map and without failing: roles not
 * found are -1. */
void smgb_roles_guess(const smgb_skeleton* s, smgb_roles* out);

/* Hip-to-ankle rest length of the left leg (sum of bone lengths from the
 * upper-leg joint down to the foot), metres; 0 when the roles are missing
 * or the foot is not below the upper leg. */
float smgb_roles_leg_length(const smgb_skeleton* s, const smgb_roles* r);

/* The left/right counterpart of a joint name, written to `out`; returns 0
 * (out = "") when the name carries no side. Recognised after an optional
 * "ns:" prefix: Left.../Right..., left.../right..., a leading L/R before an
 * upper-case letter or '_' (LHipJoint, L_Hip), and the word endings _L/_R,
 * .L/.R, _l/_r, " L"/" R", ...Left/...Right. mirror(mirror(n)) == n. */
int smgb_roles_counterpart_name(const char* name, char out[SMGB_NAME_MAX]);

/* Left/right counterpart of every joint of `s` (partner[j] = j for central
 * and unpaired joints): pairs of names (smgb_roles_counterpart_name), then
 * the joints of paired roles (left_foot/right_foot, ...) of `r`, which may
 * be NULL. Only mutual pairs are kept. The blob's mirror table and
 * smgb_clip_mirror_partners use it, so both agree. */
void smgb_roles_partners(const smgb_skeleton* s, const smgb_roles* r,
                         int32_t* partner);

/* Hip-to-ankle rest length of the left leg with the roles recognised by
 * name (smgb_roles_guess), metres; 0 if not found. */
float smgb_skeleton_leg_length(const smgb_skeleton* s);

#endif /* BAKE_ROLES_H */
