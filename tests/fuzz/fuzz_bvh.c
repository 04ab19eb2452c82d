/*
 * fuzz_bvh.c - fuzz target for the BVH reader (smgb_bvh_parse) and the clip
 * operations that follow it in the baker (mirror, resample, ground, FK).
 *
 * Every input is parsed twice (explicit unit without T-pose skip, guessed
 * unit with skip); a parse that succeeds must give a consistent clip that
 * the processing functions accept without crashing or leaking.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bake_clip.h"
#include "bake_roles.h"
#include "fuzz.h"

/* Small but varied: a static root above a translating pelvis (folded
 * away by the importer), left/right names, several channel orders, a
 * channel subset, constant non-root translation, End Sites, 3 frames. */
static const char k_seed[] =
    "HIERARCHY\n"
    "ROOT joint_Root\n{\n\tOFFSET 0 0 0\n"
    "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
    "Yrotation\n"
    "\tJOINT Hips\n\t{\n\tOFFSET 0 0 0\n"
    "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
    "Xrotation\n"
    "\tJOINT LeftUpLeg\n\t{\n\t\tOFFSET 9 -6 0\n"
    "\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
    "\t\tJOINT LeftFoot\n\t\t{\n\t\t\tOFFSET 0 -80 0\n"
    "\t\t\tCHANNELS 1 Xrotation\n"
    "\t\t\tEnd Site\n\t\t\t{\n\t\t\t\tOFFSET 0 -5 12\n\t\t\t}\n\t\t}\n\t}\n"
    "\tJOINT RightUpLeg\n\t{\n\t\tOFFSET -9 -6 0\n"
    "\t\tCHANNELS 3 Yrotation Xrotation Zrotation\n"
    "\t\tJOINT RightFoot\n\t\t{\n\t\t\tOFFSET 0 -80 0\n"
    "\t\t\tCHANNELS 1 Xrotation\n"
    "\t\t\tEnd Site\n\t\t\t{\n\t\t\t\tOFFSET 0 -5 12\n\t\t\t}\n\t\t}\n\t}\n"
    "\tJOINT Spine\n\t{\n\t\tOFFSET 0 10 0\n"
    "\t\tCHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation "
    "Zrotation\n"
    "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 50 0\n\t\t}\n\t}\n"
    "\t}\n"
    "}\n"
    "MOTION\nFrames: 3\nFrame Time: 0.0333333\n"
    "5 0 -2 0 0 90 "
    "0 90 0 0 0 0 0 0 0 0 0 0 0 0 0 10 0 0 0 0\n"
    "5 0 -2 0 0 90 "
    "1.5 91 2 10 -20 30 5 -6 7 8 9 -10 11 12 0 10 0 -14 15 -16\n"
    "5 0 -2 0 0 90 "
    "3 90.5 4.25 -170 179 -1e2 0.5 6 -7e0 8 9 10 -11 12 0 10 0 14 -15 "
    "16\n";

int fuzz_seed(uint8_t** data, size_t* size) {
  *size = sizeof k_seed - 1;
  *data = (uint8_t*)malloc(*size);
  if (!*data) return 1;
  memcpy(*data, k_seed, *size);
  return 0;
}

static volatile float g_sink;

static void exercise(const smgb_clip* c) {
  smgb_clip m, r;
  uint32_t J = c->skeleton.joint_count, f, S = SMGB_STRIDE(J);
  float* pos = (float*)malloc(sizeof(float) * 3 * J);
  float* rot = (float*)malloc(sizeof(float) * 4 * J);
  float acc = 0.0f;
  if (!pos || !rot) goto out;
  for (f = 0; f < c->frame_count; ++f) {
    smgb_fk(&c->skeleton, c->poses + (size_t)f * S, pos, rot);
    acc += pos[3 * (J - 1) + 1] + rot[4 * (J - 1) + 3];
  }
  if (smgb_clip_mirror(c, &m) == SMG_OK) {
    acc += m.poses[0];
    smgb_clip_ground(&m);
    smgb_clip_free(&m);
  }
  /* Resample to a rate that keeps the output small. */
  if (c->frame_count < 2000 && smgb_clip_resample(c, 30.0f, &r) == SMG_OK) {
    acc += r.poses[r.frame_count * S - 1];
    smgb_clip_free(&r);
  }
  acc += smgb_skeleton_leg_length(&c->skeleton);
  {
    /* Body roles, with and without a bone map, and mirror partners. */
    smgb_roles roles;
    smgb_error err;
    int32_t* partner = (int32_t*)malloc(sizeof(int32_t) * J);
    if (smgb_roles_find(&c->skeleton, "left_foot=LeftFoot\nhead=Spine",
                        "fuzz.bvh", &roles, &err) != SMG_OK &&
        err.message[0] == '\0')
      abort();
    smgb_roles_guess(&c->skeleton, &roles);
    acc += smgb_roles_leg_length(&c->skeleton, &roles);
    if (partner) {
      smgb_roles_partners(&c->skeleton, &roles, partner);
      acc += (float)partner[J - 1];
      free(partner);
    }
  }
  g_sink = acc;
out:
  free(pos);
  free(rot);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smgb_clip c;
  smgb_error err;
  int pass;
  for (pass = 0; pass < 2; ++pass) {
    smg_result r = smgb_bvh_parse((const char*)data, size, "fuzz.bvh",
                                  pass ? 0.0f : 0.01f, (uint32_t)pass, &c,
                                  &err);
    if (r != SMG_OK) {
      /* Failures always explain themselves. */
      if (err.message[0] == '\0') abort();
      continue;
    }
    if (c.skeleton.joint_count == 0 || c.frame_count == 0 ||
        c.skeleton.parents[0] != -1 || !(c.frame_rate > 0.0f))
      abort();
    exercise(&c);
    smgb_clip_free(&c);
  }
  return 0;
}
