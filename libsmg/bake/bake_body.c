/*
 * bake_body.c - what the graph stages need to know about the skeleton:
 * the body split at the pelvis (Heck et al. 2006: lower = root + legs,
 * upper = the spine base's subtree), the left/right counterpart of every
 * joint (by name), the leg chains, and which joints are measured by the
 * lower graph's point cloud and by Horn's torso fit.
 *
 * Which joint is which comes from the body roles (bake_roles.h: names of
 * the common conventions, or a bone map); a skeleton without them is
 * rejected with a message naming the file and the missing role.
 */
#include <stdlib.h>
#include <string.h>

#include "bake_body.h"

/* Zero-length helper joints (CMU LHipJoint, LowerBack, ...) sit exactly on
 * their parent; measuring them would only double-weight the parent. */
static int has_length(const smgb_skeleton* s, uint32_t j) {
  const float* o = s->offsets[j];
  return o[0] * o[0] + o[1] * o[1] + o[2] * o[2] > 1e-8f;
}

static int in_subtree(const smgb_skeleton* s, uint32_t j, uint32_t root) {
  int32_t p = (int32_t)j;
  while (p >= 0) {
    if ((uint32_t)p == root) return 1;
    p = s->parents[p];
  }
  return 0;
}

smg_result smgb_body_init(smgb_body* body, const smgb_skeleton* s,
                          const char* bone_map, const char* source,
                          smgb_report* report) {
  uint32_t J = s->joint_count, j;
  static const smgb_role leg_roles[2][4] = {
      {SMGB_ROLE_LEFT_UPPER_LEG, SMGB_ROLE_LEFT_LOWER_LEG, SMGB_ROLE_LEFT_FOOT,
       SMGB_ROLE_LEFT_TOES},
      {SMGB_ROLE_RIGHT_UPPER_LEG, SMGB_ROLE_RIGHT_LOWER_LEG,
       SMGB_ROLE_RIGHT_FOOT, SMGB_ROLE_RIGHT_TOES}};
  smgb_error err;
  smg_result r;
  int i;

  memset(body, 0, sizeof *body);
  body->joint_count = J;
  if (J > SMGB_MAX_JOINTS) {
    smgb_fail(report, "skeleton: %u joints; at most %d are supported", J,
              SMGB_MAX_JOINTS);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (J < 2) {
    smgb_fail(report, "skeleton: %u joint(s); need a root, legs and a spine", J);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  r = smgb_roles_find(s, bone_map, source, &body->roles, &err);
  if (r != SMG_OK) {
    smgb_fail(report, "%s", err.message);
    return r;
  }
  if (body->roles.joint[SMGB_ROLE_PELVIS] != 0) {
    smgb_fail(report, "%s: the pelvis '%s' must be the skeleton's root joint "
                 "(joint 0 is '%s'); a static joint above a translating "
                 "pelvis is folded away only by the BVH importer",
              source ? source : "skeleton",
              s->names[body->roles.joint[SMGB_ROLE_PELVIS]], s->names[0]);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  body->spine_base = (uint32_t)body->roles.joint[SMGB_ROLE_SPINE_BASE];
  for (i = 0; i < 4; ++i) {
    body->left_leg[i] = (uint32_t)body->roles.joint[leg_roles[0][i]];
    body->right_leg[i] = (uint32_t)body->roles.joint[leg_roles[1][i]];
  }
  for (i = 0; i < 4; ++i) {
    if (in_subtree(s, body->left_leg[i], body->spine_base) ||
        in_subtree(s, body->right_leg[i], body->spine_base)) {
      smgb_fail(report, "skeleton: leg joint '%s' is under the spine base '%s'",
                s->names[body->left_leg[i]], s->names[body->spine_base]);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  }

  body->body_part = calloc(J, sizeof *body->body_part);
  body->mirror = calloc(J, sizeof *body->mirror);
  body->mass_ratio = calloc(J, sizeof *body->mass_ratio);
  body->lower_points = calloc(J, sizeof *body->lower_points);
  body->torso_points = calloc(J, sizeof *body->torso_points);
  if (!body->body_part || !body->mirror || !body->mass_ratio ||
      !body->lower_points || !body->torso_points) {
    smgb_fail(report, "out of memory (body tables)");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  {
    int32_t* partner = (int32_t*)malloc(sizeof *partner * J);
    if (!partner) {
      smgb_fail(report, "out of memory (body tables)");
      return SMG_ERROR_OUT_OF_MEMORY;
    }
    /* The rule smgb_clip_mirror_partners is given, so the blob's mirror
     * table matches the mirrored clips. */
    smgb_roles_partners(s, &body->roles, partner);
    for (j = 0; j < J; ++j) body->mirror[j] = (uint32_t)partner[j];
    free(partner);
  }
  for (j = 0; j < J; ++j) {
    body->body_part[j] = j == 0 ? SMG_BODY_ROOT
                         : in_subtree(s, j, body->spine_base) ? SMG_BODY_UPPER
                                                               : SMG_BODY_LOWER;
    if (body->body_part[j] != SMG_BODY_UPPER && (j == 0 || has_length(s, j)))
      body->lower_points[body->lower_point_count++] = j;
  }
  /* Torso points for Horn: the spine base's subtree cut at the arms (the
   * upper-arm joint is kept, what hangs below it moves with the action and
   * must not steer the fit). */
  for (j = 0; j < J; ++j) {
    int32_t p = s->parents[j];
    int below_arm = 0;
    if (body->body_part[j] != SMG_BODY_UPPER || j == body->spine_base ||
        !has_length(s, j))
      continue;
    while (p >= 0 && (uint32_t)p != body->spine_base) {
      if (p == body->roles.joint[SMGB_ROLE_LEFT_UPPER_ARM] ||
          p == body->roles.joint[SMGB_ROLE_RIGHT_UPPER_ARM])
        below_arm = 1;
      p = s->parents[p];
    }
    if (!below_arm) body->torso_points[body->torso_point_count++] = j;
  }
  if (body->torso_point_count < 3) {
    smgb_fail(report, "skeleton: only %u torso joint(s) above the arms under '%s';"
                 " Horn's fit needs 3", body->torso_point_count,
              s->names[body->spine_base]);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  body->leg_length = smgb_roles_leg_length(s, &body->roles);
  return smgb_segments_init(body, s, report);
}

void smgb_body_free(smgb_body* body) {
  free(body->body_part);
  free(body->mirror);
  free(body->mass_ratio);
  free(body->lower_points);
  free(body->torso_points);
  memset(body, 0, sizeof *body);
}
