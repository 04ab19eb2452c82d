/*
 * bake_upper.c - body segments and their centres of gravity.
 *
 * The upper-body graph and the splice search compare upper-body SEGMENT
 * CENTRES OF GRAVITY (the paper, III.B.2), weighted by the segments' mass
 * ratios. Table used (Ae, Tang, Yokoi 1996, "Estimation of inertia
 * properties of the body segments in Japanese athletes", male athletes;
 * mass = fraction of body mass, COG = fraction of the segment length from
 * its proximal end):
 *
 *   segment      mass    COG    joints (proximal -> distal)
 *   head+neck    0.069   0.821  from the vertex; here the head's parent
 *                               (CMU Neck1) -> Head with ratio 1.0 (the
 *                               skeleton has no head-top joint; the head
 *                               COG lies near the skull base, which is the
 *                               Head joint)
 *   trunk        0.489   0.493  from the suprasternale: Neck -> spine base
 *   upper arm    0.027   0.529  Arm -> ForeArm
 *   forearm      0.016   0.415  ForeArm -> Hand
 *   hand         0.006   0.891  Hand -> finger base (index; the wrist
 *                               when the rig has no fingers)
 *   thigh        0.110   0.475  UpLeg -> Leg
 *   shank        0.051   0.406  Leg -> Foot
 *   foot         0.011   0.595  Foot -> ToeBase
 *
 * Joints are body roles (bake_roles.h). Masses sum to 1.000 over the 14
 * segments. Each segment's mass is stored
 * in smgi_joint.mass_ratio of the hierarchy-higher of its two joints.
 */
#include <math.h>
#include <string.h>

#include "bake_upper.h"
#include "bake_math.h"

typedef struct seg_def {
  const char* name;
  int proximal, distal;        /* smgb_role; proximal -1: distal's parent */
  float mass, ratio;
  uint32_t upper;
} seg_def;

static const seg_def k_segments[] = {
    {"trunk", SMGB_ROLE_NECK, SMGB_ROLE_SPINE_BASE, 0.489f, 0.493f, 1},
    {"head", -1, SMGB_ROLE_HEAD, 0.069f, 1.0f, 1},
    {"left upper arm", SMGB_ROLE_LEFT_UPPER_ARM, SMGB_ROLE_LEFT_LOWER_ARM,
     0.027f, 0.529f, 1},
    {"left forearm", SMGB_ROLE_LEFT_LOWER_ARM, SMGB_ROLE_LEFT_HAND, 0.016f,
     0.415f, 1},
    {"left hand", SMGB_ROLE_LEFT_HAND, SMGB_ROLE_LEFT_FINGERS, 0.006f, 0.891f,
     1},
    {"right upper arm", SMGB_ROLE_RIGHT_UPPER_ARM, SMGB_ROLE_RIGHT_LOWER_ARM,
     0.027f, 0.529f, 1},
    {"right forearm", SMGB_ROLE_RIGHT_LOWER_ARM, SMGB_ROLE_RIGHT_HAND, 0.016f,
     0.415f, 1},
    {"right hand", SMGB_ROLE_RIGHT_HAND, SMGB_ROLE_RIGHT_FINGERS, 0.006f,
     0.891f, 1},
    {"left thigh", SMGB_ROLE_LEFT_UPPER_LEG, SMGB_ROLE_LEFT_LOWER_LEG, 0.110f,
     0.475f, 0},
    {"left shank", SMGB_ROLE_LEFT_LOWER_LEG, SMGB_ROLE_LEFT_FOOT, 0.051f,
     0.406f, 0},
    {"left foot", SMGB_ROLE_LEFT_FOOT, SMGB_ROLE_LEFT_TOES, 0.011f, 0.595f, 0},
    {"right thigh", SMGB_ROLE_RIGHT_UPPER_LEG, SMGB_ROLE_RIGHT_LOWER_LEG,
     0.110f, 0.475f, 0},
    {"right shank", SMGB_ROLE_RIGHT_LOWER_LEG, SMGB_ROLE_RIGHT_FOOT, 0.051f,
     0.406f, 0},
    {"right foot", SMGB_ROLE_RIGHT_FOOT, SMGB_ROLE_RIGHT_TOES, 0.011f, 0.595f,
     0},
};

smg_result smgb_segments_init(smgb_body* body, const smgb_skeleton* skel,
                              smgb_report* report) {
  const smgb_roles* roles = &body->roles;
  size_t i;
  body->segment_count = 0;
  body->upper_segment_count = 0;
  /* Upper segments first so that COG arrays index them 0..upper-1. The
   * required roles are all present (smgb_roles_find checked them). */
  for (i = 0; i < sizeof k_segments / sizeof k_segments[0]; ++i) {
    const seg_def* d = &k_segments[i];
    int32_t q = roles->joint[d->distal];
    int32_t p = d->proximal >= 0 ? roles->joint[d->proximal]
                                 : (q >= 0 ? skel->parents[q] : -1);
    smgb_segment* s;
    /* A hand without a finger joint: COG at the wrist. */
    if (q < 0 && p >= 0 && strstr(d->name, "hand")) q = p;
    if (p < 0 || q < 0) {
      smgb_fail(report, "skeleton: segment '%s' has no %s joint", d->name,
                p < 0 ? "proximal" : "distal");
      return SMG_ERROR_INVALID_ARGUMENT;
    }
    s = &body->segments[body->segment_count++];
    s->proximal = (uint32_t)p;
    s->distal = (uint32_t)q;
    s->mass = d->mass;
    s->ratio = d->ratio;
    s->upper = d->upper;
    s->name = d->name;
    if (d->upper) ++body->upper_segment_count;
    body->mass_ratio[p < q ? p : q] += d->mass;
  }
  return SMG_OK;
}

void smgb_upper_weights(const smgb_bake* b, double* out_w) {
  uint32_t i;
  for (i = 0; i < b->body.upper_segment_count; ++i)
    out_w[i] = b->body.segments[i].mass;
}

void smgb_upper_cogs(const smgb_bake* b, uint32_t f, double* out) {
  const float* P = b->positions + (size_t)f * 3u * b->J;
  const smgi_frame* fr = &b->frames[f];
  double g[3];
  uint32_t i;
  g[0] = fr->root2d[0];
  g[1] = fr->root2d[1];
  g[2] = fr->root2d[2];
  for (i = 0; i < b->body.upper_segment_count; ++i) {
    const smgb_segment* s = &b->body.segments[i];
    const float* a = P + 3u * s->proximal;
    const float* c = P + 3u * s->distal;
    double x = a[0] + s->ratio * (c[0] - a[0]);
    double y = a[1] + s->ratio * (c[1] - a[1]);
    double z = a[2] + s->ratio * (c[2] - a[2]);
    double lx, lz;
    smgb_g_inverse_apply(g, x, z, &lx, &lz);
    out[3 * i + 0] = lx;
    out[3 * i + 1] = y;
    out[3 * i + 2] = lz;
  }
}
