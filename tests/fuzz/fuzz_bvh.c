/*
 * fuzz_bvh.c - fuzz target for the BVH reader (smgb_bvh_parse) and the clip
 * operations that follow it in the baker (mirror, resample, ground, FK).
 *
 * Every input is parsed twice (explicit unit without T-pose skip, guessed
 * unit with skip); a parse that succeeds must give a consistent clip that
 * the processing functions accept without crashing or leaking.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake_clip.h"
#include "bake_roles.h"
#include "bake_synthetic.h"
#include "fuzz.h"

/* Seeds 1 and 2: small hand-shaped files the synthetic walk does not
 * cover - rotation channels in other orders, a joint with one channel, a
 * non-root joint with position channels (its offset moves), and (seed 2)
 * a static root above the translating pelvis, as rigs exported from
 * MotionBuilder or Mixamo have. Built here rather than kept as files. */
typedef struct text {
  char buf[4096];
  size_t len;
} text;

static void put(text* t, const char* s) {
  size_t n = strlen(s);
  if (t->len + n < sizeof t->buf) {
    memcpy(t->buf + t->len, s, n + 1);
    t->len += n;
  }
}

static void put_leg(text* t, const char* side, const char* x,
                    const char* order) {
  put(t, "\tJOINT "), put(t, side), put(t, "UpLeg\n\t{\n\t\tOFFSET ");
  put(t, x), put(t, " -6 0\n\t\tCHANNELS 3 "), put(t, order);
  put(t, "\n\t\tJOINT "), put(t, side);
  put(t, "Foot\n\t\t{\n\t\t\tOFFSET 0 -80 0\n\t\t\tCHANNELS 1 "
         "Xrotation\n\t\t\tEnd Site\n\t\t\t{\n\t\t\t\tOFFSET 0 -5 "
         "12\n\t\t\t}\n\t\t}\n\t}\n");
}

static int hand_shaped_seed(int static_root, uint8_t** data, size_t* size) {
  /* three frames: rest, moderate angles, wrapped and exponent-written */
  static const char* const frames[3] = {
      "0 90 0 0 0 0 0 0 0 0 0 0 0 0 0 10 0 0 0 0",
      "1.5 91 2 10 -20 30 5 -6 7 8 9 -10 11 12 0 10 0 -14 15 -16",
      "3 90.5 4.25 -170 179 -1e2 0.5 6 -7e0 8 9 10 -11 12 0 10 0 14 -15 "
      "16"};
  text t;
  int f;
  t.len = 0;
  t.buf[0] = '\0';
  put(&t, "HIERARCHY\n");
  if (static_root)
    put(&t, "ROOT joint_Root\n{\n\tOFFSET 0 0 0\n\tCHANNELS 6 Xposition "
            "Yposition Zposition Zrotation Xrotation Yrotation\n\tJOINT "
            "Hips\n");
  else
    put(&t, "ROOT Hips\n");
  put(&t, "{\n\tOFFSET 0 0 0\n\tCHANNELS 6 Xposition Yposition Zposition "
          "Zrotation Yrotation Xrotation\n");
  put_leg(&t, "Left", "9", "Zrotation Xrotation Yrotation");
  put_leg(&t, "Right", "-9", "Yrotation Xrotation Zrotation");
  put(&t, "\tJOINT Spine\n\t{\n\t\tOFFSET 0 10 0\n\t\tCHANNELS 6 "
          "Xposition Yposition Zposition Xrotation Yrotation Zrotation\n"
          "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 50 0\n\t\t}\n\t}\n}\n");
  if (static_root) put(&t, "}\n");
  put(&t, "MOTION\nFrames: 3\nFrame Time: 0.0333333\n");
  for (f = 0; f < 3; ++f) {
    if (static_root) put(&t, "5 0 -2 0 0 90 ");
    put(&t, frames[f]);
    put(&t, "\n");
  }
  *data = (uint8_t*)malloc(t.len);
  if (!*data) return -1;
  memcpy(*data, t.buf, t.len);
  *size = t.len;
  return 0;
}

/* Seed 0, a real-shaped file: the 31-joint CMU hierarchy of a generated
 * (synthetic) walk, 1 s at 120 frames/s like the CMU captures, written by
 * the baker's own BVH writer; real clips are this shape, only longer
 * (the libFuzzer run allows inputs of real clip sizes: mk/fuzz.mk). */
int fuzz_seed(uint32_t index, uint8_t** data, size_t* size) {
  char dir[64], path[96];
  smgb_synth_params p;
  smgb_clip clip;
  smgb_error err;
  smg_result r;
  FILE* f;
  long n = -1;
  if (index == 1 || index == 2) return hand_shaped_seed(index == 2, data, size);
  if (index > 2) return FUZZ_SEED_NONE;
  snprintf(dir, sizeof dir, "/tmp/smg-fuzz-bvh-XXXXXX");
  if (!mkdtemp(dir)) return -1;
  snprintf(path, sizeof path, "%s/seed.bvh", dir);
  memset(&p, 0, sizeof p);
  p.kind = SMGB_SYNTH_WALK;
  p.duration = 1.0f;
  p.frame_rate = 120.0f;
  p.turn_rate = 0.3f;
  r = smgb_synth_generate(&p, &clip, NULL);
  if (r == SMG_OK) {
    r = smgb_bvh_save(path, &clip, &err);
    smgb_clip_free(&clip);
  }
  f = r == SMG_OK ? fopen(path, "rb") : NULL;
  if (f && fseek(f, 0, SEEK_END) == 0) n = ftell(f);
  *data = n > 0 ? (uint8_t*)malloc((size_t)n) : NULL;
  if (*data && (fseek(f, 0, SEEK_SET) != 0 ||
                fread(*data, 1, (size_t)n, f) != (size_t)n)) {
    free(*data);
    *data = NULL;
  }
  *size = (size_t)n;
  if (f) fclose(f);
  remove(path);
  rmdir(dir);
  return *data ? 0 : -1;
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
