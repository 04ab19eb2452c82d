/*
 * bake_body.c - what the graph stages need to know about the skeleton:
 * the body split at the pelvis (Heck et al. 2006: lower = root + legs,
 * upper = the spine base's subtree), the left/right counterpart of every
 * joint (by name), the leg chains, and which joints are measured by the
 * lower graph's point cloud and by Horn's torso fit.
 *
 * Names follow the CMU/BVH convention (Hips, LowerBack, LeftUpLeg, ...).
 * A skeleton without them is rejected with a message naming the joint.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_graph.h"

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

/* Left<->Right, then a leading L<->R followed by an upper-case letter
 * (LHipJoint, RThumb). Writes the counterpart name or "" when none. */
static void counterpart_name(const char* n, char* out, size_t size) {
  const char* hit;
  out[0] = '\0';
  if ((hit = strstr(n, "Left")) != NULL) {
    snprintf(out, size, "%.*sRight%s", (int)(hit - n), n, hit + 4);
  } else if ((hit = strstr(n, "Right")) != NULL) {
    snprintf(out, size, "%.*sLeft%s", (int)(hit - n), n, hit + 5);
  } else if ((n[0] == 'L' || n[0] == 'R') && n[1] >= 'A' && n[1] <= 'Z') {
    snprintf(out, size, "%c%s", n[0] == 'L' ? 'R' : 'L', n + 1);
  }
}

static smg_result need_joint(smgb_bake* b, const char* name, uint32_t* out) {
  int32_t j = smgb_skeleton_find(&b->skel, name);
  if (j < 0) {
    smgb_fail(b, "skeleton: unknown joint names for the body split: no "
                 "joint named '%s' (expected the CMU/BVH names Hips, "
                 "LowerBack, LeftUpLeg, LeftLeg, LeftFoot, LeftToeBase, "
                 "Right...)", name);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  *out = (uint32_t)j;
  return SMG_OK;
}

smg_result smgb_body_init(smgb_bake* b) {
  const smgb_skeleton* s = &b->skel;
  smgb_body* body = &b->body;
  uint32_t J = s->joint_count, j;
  static const char* const leg_names[2][4] = {
      {"LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase"},
      {"RightUpLeg", "RightLeg", "RightFoot", "RightToeBase"}};
  smg_result r;
  int i;

  memset(body, 0, sizeof *body);
  body->joint_count = J;
  if (J > SMGB_MAX_JOINTS) {
    smgb_fail(b, "skeleton: %u joints; at most %d are supported", J,
              SMGB_MAX_JOINTS);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if (J < 2) {
    smgb_fail(b, "skeleton: %u joint(s); need a root, legs and a spine", J);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  if ((r = need_joint(b, "LowerBack", &body->spine_base)) != SMG_OK) {
    /* Hierarchies without the CMU helper joint: the root's child that
     * leads to "Spine". */
    int32_t sp = smgb_skeleton_find(s, "Spine");
    if (sp < 0) return r;
    while (s->parents[sp] > 0) sp = s->parents[sp];
    body->spine_base = (uint32_t)sp;
    b->error[0] = '\0';
  }
  if (body->spine_base == 0) {
    smgb_fail(b, "skeleton: the spine base cannot be the root joint");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  for (i = 0; i < 4; ++i) {
    if ((r = need_joint(b, leg_names[0][i], &body->left_leg[i])) != SMG_OK)
      return r;
    if ((r = need_joint(b, leg_names[1][i], &body->right_leg[i])) != SMG_OK)
      return r;
  }
  for (i = 0; i < 4; ++i) {
    if (in_subtree(s, body->left_leg[i], body->spine_base) ||
        in_subtree(s, body->right_leg[i], body->spine_base)) {
      smgb_fail(b, "skeleton: leg joint '%s' is under the spine base '%s'",
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
    smgb_fail(b, "out of memory (body tables)");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  for (j = 0; j < J; ++j) {
    char other[SMGB_NAME_MAX + 8];
    int32_t m;
    body->body_part[j] = j == 0 ? SMG_BODY_ROOT
                         : in_subtree(s, j, body->spine_base) ? SMG_BODY_UPPER
                                                               : SMG_BODY_LOWER;
    counterpart_name(s->names[j], other, sizeof other);
    m = other[0] ? smgb_skeleton_find(s, other) : -1;
    body->mirror[j] = m >= 0 ? (uint32_t)m : j;
    if (body->body_part[j] != SMG_BODY_UPPER && (j == 0 || has_length(s, j)))
      body->lower_points[body->lower_point_count++] = j;
  }
  /* Torso points for Horn: the spine base's subtree cut at the arms
   * (the shoulder joint "…Arm" is kept, what hangs below it moves with the
   * action and must not steer the fit). */
  for (j = 0; j < J; ++j) {
    int32_t p = s->parents[j];
    int below_arm = 0;
    if (body->body_part[j] != SMG_BODY_UPPER || j == body->spine_base ||
        !has_length(s, j))
      continue;
    while (p >= 0 && (uint32_t)p != body->spine_base) {
      if (strstr(s->names[p], "Arm")) below_arm = 1;
      p = s->parents[p];
    }
    if (!below_arm) body->torso_points[body->torso_point_count++] = j;
  }
  if (body->torso_point_count < 3) {
    smgb_fail(b, "skeleton: only %u torso joint(s) above the arms under '%s';"
                 " Horn's fit needs 3", body->torso_point_count,
              s->names[body->spine_base]);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  body->leg_length = smgb_skeleton_leg_length(s);
  return smgb_segments_init(b);
}

void smgb_body_free(smgb_body* body) {
  free(body->body_part);
  free(body->mirror);
  free(body->mass_ratio);
  free(body->lower_points);
  free(body->torso_points);
  memset(body, 0, sizeof *body);
}
