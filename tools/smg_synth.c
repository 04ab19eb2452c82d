/*
 * smg-synth - run the libsmg runtime offline: load a graph blob, give one
 * character a path (and transition/splice points), step it at a fixed rate
 * for N seconds and write the motion as BVH on the blob's skeleton (metres),
 * optionally with a per-frame CSV of root, contacts and path tracking for
 * evaluation tools, and as glTF 2.0 (.glb) for engines and DCC tools: the
 * skeleton, the take as one animation and the generated skinned body
 * (tools/gltf; --no-body for the skeleton alone).
 *
 *   smg-synth -g BLOB -p PATH.txt [--transition S:style]... [--splice
 *             S:action]... [--seconds N] [--fps F] [--seed N] [--no-ik]
 *             [--no-steering] [--steer-turn-rate R] [--steer-slide-ratio F]
 *             [--stop-seconds S] [--no-swing-clearance] [--swing-clearance M]
 *             [--csv FILE] [--glb FILE [--no-body]] -o OUT.bvh
 *
 * PATH.txt holds one "x z" pair (metres) per line; '#' starts a comment.
 * style/action are names from the blob (smg-bake --info lists them) or
 * indices. S is the arc length along the path in metres.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_body.h"
#include "gltf_write.h"
#include "smg.h"

#define MAX_CONSTRAINTS 256

typedef struct constraint_arg {
  int splice;
  float arc;
  const char* label;
} constraint_arg;

static void usage(FILE* f) {
  fprintf(f,
          "usage: smg-synth -g BLOB -p PATH.txt [--transition S:style]... "
          "[--splice S:action]...\n"
          "                 [--seconds N] [--fps F] [--seed N] [--no-ik] "
          "[--csv FILE] -o OUT.bvh\n"
          "                 [--glb FILE.glb [--no-body]]\n"
          "                 [--no-steering] [--steer-turn-rate RAD_PER_S] "
          "[--steer-slide-ratio F] [--stop-seconds S]\n"
          "                 [--no-swing-clearance] [--swing-clearance M]\n"
          "  PATH.txt: one \"x z\" point per line (metres, '#' comments)\n"
          "  S: arc length along the path (metres); style/action: name or "
          "index\n"
          "  defaults: --seconds 10 --fps 30; steering on with the "
          "library's limits (0 = default); swing clearance on, 0 = "
          "0.04 leg lengths\n");
}

static int fail(const char* what, smg_result r) {
  fprintf(stderr, "smg-synth: %s: %s\n", what, smg_result_string(r));
  return 1;
}

/* Read "x z" lines into a malloc'd array; returns point count or -1. */
static long read_path(const char* file, float** out) {
  FILE* f = fopen(file, "r");
  if (!f) {
    fprintf(stderr, "smg-synth: cannot open %s: %s\n", file, strerror(errno));
    return -1;
  }
  size_t cap = 256, n = 0;
  float* xz = (float*)malloc(sizeof(float) * 2 * cap);
  char line[512];
  long lineno = 0;
  while (xz && fgets(line, sizeof line, f)) {
    ++lineno;
    char* hash = strchr(line, '#');
    if (hash) *hash = 0;
    char* p = line;
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
    if (!*p) continue;
    char *e1, *e2;
    float x = strtof(p, &e1);
    float z = strtof(e1, &e2);
    if (e1 == p || e2 == e1 || !isfinite(x) || !isfinite(z)) {
      fprintf(stderr, "smg-synth: %s:%ld: expected \"x z\"\n", file, lineno);
      free(xz);
      fclose(f);
      return -1;
    }
    if (n == cap) {
      cap *= 2;
      float* nx = (float*)realloc(xz, sizeof(float) * 2 * cap);
      if (!nx) {
        free(xz);
        xz = NULL;
        break;
      }
      xz = nx;
    }
    xz[2 * n] = x;
    xz[2 * n + 1] = z;
    ++n;
  }
  fclose(f);
  if (!xz) {
    fprintf(stderr, "smg-synth: out of memory reading %s\n", file);
    return -1;
  }
  *out = xz;
  return (long)n;
}

static int parse_constraint(const char* s, int splice, constraint_arg* c) {
  const char* colon = strchr(s, ':');
  char* end;
  if (!colon) return 0;
  c->arc = strtof(s, &end);
  if (end != colon || !isfinite(c->arc)) return 0;
  c->label = colon + 1;
  c->splice = splice;
  return *c->label != 0;
}

/* Name or index of a style/action. */
static smg_result lookup(const smg_graph* g, int action, const char* label,
                         uint32_t* out) {
  char* end;
  unsigned long v = strtoul(label, &end, 10);
  if (*label && *end == 0) {
    *out = (uint32_t)v;
    return SMG_OK;
  }
  return action ? smg_graph_find_action(g, label, out)
                : smg_graph_find_style(g, label, out);
}

/* Quaternion (x,y,z,w) to BVH ZYX Euler degrees (R = Rz * Ry * Rx). */
static void quat_to_zyx(const float* q, double* z, double* y, double* x) {
  double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  double r00 = 1 - 2 * (qy * qy + qz * qz), r01 = 2 * (qx * qy - qz * qw);
  double r10 = 2 * (qx * qy + qz * qw), r11 = 1 - 2 * (qx * qx + qz * qz);
  double r20 = 2 * (qx * qz - qy * qw), r21 = 2 * (qy * qz + qx * qw);
  double r22 = 1 - 2 * (qx * qx + qy * qy);
  const double deg = 180.0 / 3.14159265358979323846;
  /* y from atan2, well conditioned at +-90 degrees (asin of a clamped
   * sine was off by up to a quarter of a degree there: a character
   * heading along x, y = 90, was written 4 mm off at a metre) */
  const double cy = sqrt(r00 * r00 + r10 * r10);
  *y = atan2(-r20, cy) * deg;
  if (cy > 1e-6) {
    *x = atan2(r21, r22) * deg;
    *z = atan2(r10, r00) * deg;
  } else { /* gimbal lock: put it all in z */
    *x = 0.0;
    *z = atan2(-r01, r11) * deg;
  }
}

/* The take as glTF: the generated body skinned to the skeleton when the
 * skeleton gives one (else, or with no_body, the skeleton alone), the
 * frames as one animation. */
static int write_glb(const char* file, smg_graph* g, uint32_t J,
                     const float* frames, size_t stride, long nframes,
                     float fps, int no_body) {
  char error[512];
  gltf_body body;
  gltf_skeleton rest;
  gltf_animation anim;
  gltf_scene scene;
  int32_t* parent = (int32_t*)malloc(sizeof(int32_t) * J);
  const char** name = (const char**)malloc(sizeof(char*) * J);
  float* translation = (float*)malloc(sizeof(float) * 3 * J);
  int has_body = 0;
  smg_result r = SMG_ERROR_OUT_OF_MEMORY;
  memset(&scene, 0, sizeof scene);
  if (parent && name && translation)
    r = gltf_skeleton_from_graph(g, J, parent, name, translation, &rest);
  if (r == SMG_OK && !no_body) {
    has_body = gltf_body_from_graph(g, &body, error, sizeof error) == SMG_OK;
    if (!has_body)
      fprintf(stderr, "smg-synth: %s: no body (%s): skeleton only\n", file,
              error);
  }
  if (r == SMG_OK) {
    anim.frame_count = (uint32_t)nframes;
    anim.fps = fps;
    anim.frames = frames;
    anim.stride = stride;
    scene.generator = "libsmg smg-synth (generated body, not a scanned or "
                      "modelled character)";
    scene.root_name = "Character";
    scene.mesh_name = "BodyMesh";
    scene.skeleton = has_body ? &body.skeleton : &rest;
    scene.mesh = has_body ? &body.mesh : NULL;
    scene.animation = &anim;
    r = gltf_write_file(file, &scene, GLTF_BINARY, error, sizeof error);
    if (r != SMG_OK) fprintf(stderr, "smg-synth: %s\n", error);
  } else {
    fprintf(stderr, "smg-synth: %s: %s\n", file, smg_result_string(r));
  }
  if (has_body) gltf_body_free(&body);
  free(parent);
  free((void*)name);
  free(translation);
  return r == SMG_OK;
}

static void write_hierarchy(FILE* f, const smg_graph* g, uint32_t J,
                            uint32_t j, int depth) {
  smg_joint_info ji;
  memset(&ji, 0, sizeof ji);
  ji.struct_size = sizeof ji;
  smg_graph_get_joint(g, j, &ji);
  for (int i = 0; i < depth; ++i) fputc('\t', f);
  fprintf(f, "%s %s\n", j == 0 ? "ROOT" : "JOINT", ji.name);
  for (int i = 0; i < depth; ++i) fputc('\t', f);
  fprintf(f, "{\n");
  for (int i = 0; i <= depth; ++i) fputc('\t', f);
  fprintf(f, "OFFSET %.6f %.6f %.6f\n", j == 0 ? 0.0 : ji.rest_offset[0],
          j == 0 ? 0.0 : ji.rest_offset[1], j == 0 ? 0.0 : ji.rest_offset[2]);
  for (int i = 0; i <= depth; ++i) fputc('\t', f);
  if (j == 0)
    fprintf(f, "CHANNELS 6 Xposition Yposition Zposition Zrotation "
               "Yrotation Xrotation\n");
  else
    fprintf(f, "CHANNELS 3 Zrotation Yrotation Xrotation\n");
  int children = 0;
  for (uint32_t c = j + 1; c < J; ++c) {
    smg_joint_info ci;
    memset(&ci, 0, sizeof ci);
    ci.struct_size = sizeof ci;
    smg_graph_get_joint(g, c, &ci);
    if (ci.parent == (int32_t)j) {
      write_hierarchy(f, g, J, c, depth + 1);
      ++children;
    }
  }
  if (!children) {
    for (int i = 0; i <= depth; ++i) fputc('\t', f);
    fprintf(f, "End Site\n");
    for (int i = 0; i <= depth; ++i) fputc('\t', f);
    fprintf(f, "{\n");
    for (int i = 0; i <= depth + 1; ++i) fputc('\t', f);
    fprintf(f, "OFFSET 0.000000 0.000000 0.000000\n");
    for (int i = 0; i <= depth; ++i) fputc('\t', f);
    fprintf(f, "}\n");
  }
  for (int i = 0; i < depth; ++i) fputc('\t', f);
  fprintf(f, "}\n");
}

int main(int argc, char** argv) {
  const char *blob = NULL, *path_file = NULL, *out_file = NULL,
             *csv_file = NULL, *glb_file = NULL;
  int no_body = 0;
  float seconds = 10.0f, fps = 30.0f;
  uint32_t seed = 0, no_ik = 0, no_steering = 0, no_swing = 0;
  float steer_turn = 0.0f, steer_slide = 0.0f, stop_seconds = 0.0f;
  float swing_clearance = 0.0f;
  constraint_arg cons[MAX_CONSTRAINTS];
  int ncons = 0;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(a, "--no-ik")) {
      no_ik = 1;
      continue;
    } else if (!strcmp(a, "--no-steering")) {
      no_steering = 1;
      continue;
    } else if (!strcmp(a, "--no-swing-clearance")) {
      no_swing = 1;
      continue;
    } else if (!strcmp(a, "--no-body")) {
      no_body = 1;
      continue;
    }
    if (!v) {
      fprintf(stderr, "smg-synth: %s needs a value\n", a);
      usage(stderr);
      return 2;
    }
    ++i;
    if (!strcmp(a, "-g")) {
      blob = v;
    } else if (!strcmp(a, "-p")) {
      path_file = v;
    } else if (!strcmp(a, "-o")) {
      out_file = v;
    } else if (!strcmp(a, "--csv")) {
      csv_file = v;
    } else if (!strcmp(a, "--glb")) {
      glb_file = v;
    } else if (!strcmp(a, "--seconds")) {
      seconds = strtof(v, NULL);
    } else if (!strcmp(a, "--fps")) {
      fps = strtof(v, NULL);
    } else if (!strcmp(a, "--seed")) {
      seed = (uint32_t)strtoul(v, NULL, 10);
    } else if (!strcmp(a, "--steer-turn-rate")) {
      steer_turn = strtof(v, NULL);
    } else if (!strcmp(a, "--steer-slide-ratio")) {
      steer_slide = strtof(v, NULL);
    } else if (!strcmp(a, "--stop-seconds")) {
      stop_seconds = strtof(v, NULL);
    } else if (!strcmp(a, "--swing-clearance")) {
      swing_clearance = strtof(v, NULL);
    } else if (!strcmp(a, "--transition") || !strcmp(a, "--splice")) {
      if (ncons == MAX_CONSTRAINTS ||
          !parse_constraint(v, a[2] == 's', &cons[ncons])) {
        fprintf(stderr, "smg-synth: bad %s '%s' (want S:name)\n", a, v);
        return 2;
      }
      ++ncons;
    } else {
      fprintf(stderr, "smg-synth: unknown option %s\n", a);
      usage(stderr);
      return 2;
    }
  }
  if (!blob || !path_file || !out_file) {
    usage(stderr);
    return 2;
  }
  if (!(seconds > 0.0f && seconds < 1e6f) || !(fps >= 1.0f && fps <= 1000.0f)) {
    fprintf(stderr, "smg-synth: --seconds must be > 0, --fps in [1, 1000]\n");
    return 2;
  }

  smg_graph* g = NULL;
  smg_result r = smg_graph_load_file(blob, NULL, &g);
  if (r != SMG_OK) return fail(blob, r);
  float* xz = NULL;
  long n = read_path(path_file, &xz);
  if (n < 0) {
    smg_graph_destroy(g);
    return 1;
  }
  smg_character_desc d;
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.path_capacity = n > 0 ? (uint32_t)n : 1u;
  d.constraint_capacity = ncons > 0 ? (uint32_t)ncons : 1u;
  d.seed = seed;
  d.flags = (no_ik ? SMG_CHARACTER_NO_IK : 0u) |
            (no_steering ? SMG_CHARACTER_NO_STEERING : 0u) |
            (no_swing ? SMG_CHARACTER_NO_SWING_CLEARANCE : 0u);
  /* the library checks them (negative or non-finite: invalid argument) */
  d.steer_turn_rate = steer_turn;
  d.steer_slide_ratio = steer_slide;
  d.stop_seconds = stop_seconds;
  d.swing_clearance = swing_clearance;
  if (n > 0) {
    d.position[0] = xz[0];
    d.position[2] = xz[1];
    if (n > 1) d.heading = atan2f(xz[2] - xz[0], xz[3] - xz[1]);
  }
  smg_character* ch = NULL;
  int rc = 1;
  FILE* out = NULL;
  FILE* csv = NULL;
  float* frames = NULL;
  r = smg_character_create(g, &d, &ch);
  if (r != SMG_OK) {
    fail("create character", r);
    goto done;
  }
  r = smg_character_set_path(ch, xz, (uint32_t)n);
  if (r != SMG_OK) {
    fail("set path", r);
    goto done;
  }
  for (int i = 0; i < ncons; ++i) {
    uint32_t v = 0;
    r = lookup(g, cons[i].splice, cons[i].label, &v);
    if (r != SMG_OK) {
      fprintf(stderr, "smg-synth: unknown %s '%s'\n",
              cons[i].splice ? "action" : "style", cons[i].label);
      goto done;
    }
    r = cons[i].splice ? smg_character_add_splice(ch, cons[i].arc, v, NULL)
                       : smg_character_add_transition(ch, cons[i].arc, v, NULL);
    if (r != SMG_OK) {
      fprintf(stderr, "smg-synth: %s at %.3f m: %s\n",
              cons[i].splice ? "splice" : "transition", cons[i].arc,
              smg_result_string(r));
      goto done;
    }
  }

  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_graph_get_info(g, &info);
  const uint32_t J = info.joint_count;
  const long nframes = (long)ceilf(seconds * fps);
  const size_t stride = 3 + 4 * (size_t)J;
  frames = (float*)malloc(sizeof(float) * stride * (size_t)nframes);
  if (!frames) {
    fprintf(stderr, "smg-synth: out of memory\n");
    goto done;
  }
  if (csv_file) {
    csv = fopen(csv_file, "wb");
    if (!csv) {
      fprintf(stderr, "smg-synth: cannot write %s\n", csv_file);
      goto done;
    }
    fprintf(csv, "frame,time,root_x,root_y,root_z,ground_x,ground_z,heading,"
                 "style,action,left_contact,right_contact,path_distance,"
                 "path_error,sync_rate,end_reached,steer_turn_rate,"
                 "steer_slide_speed,playback_rate\n");
  }
  for (long i = 0; i < nframes; ++i) {
    if (i > 0 && (r = smg_character_step(ch, 1.0f / fps)) != SMG_OK) {
      fail("step", r);
      goto done;
    }
    float* fr = frames + stride * (size_t)i;
    smg_character_get_local_pose(ch, fr, fr + 3, J);
    if (csv) {
      smg_character_state s;
      memset(&s, 0, sizeof s);
      s.struct_size = sizeof s;
      smg_character_get_state(ch, &s);
      fprintf(csv, "%ld,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%u,%u,%d,%d,%.6f,"
                   "%.6f,%.4f,%d,%.5f,%.5f,%.4f\n",
              i, s.time, fr[0], fr[1], fr[2], s.position[0], s.position[2],
              s.heading, s.style, s.action,
              (s.flags & SMG_STATE_LEFT_CONTACT) != 0,
              (s.flags & SMG_STATE_RIGHT_CONTACT) != 0, s.path_distance,
              s.path_error, s.sync_rate,
              (s.flags & SMG_STATE_PATH_END_REACHED) != 0,
              s.steer_turn_rate, s.steer_slide_speed, s.playback_rate);
    }
  }

  out = fopen(out_file, "wb");
  if (!out) {
    fprintf(stderr, "smg-synth: cannot write %s: %s\n", out_file,
            strerror(errno));
    goto done;
  }
  fprintf(out, "HIERARCHY\n");
  write_hierarchy(out, g, J, 0, 0);
  fprintf(out, "MOTION\nFrames: %ld\nFrame Time: %.7f\n", nframes,
          1.0 / fps);
  for (long i = 0; i < nframes; ++i) {
    const float* fr = frames + stride * (size_t)i;
    fprintf(out, "%.6f %.6f %.6f", fr[0], fr[1], fr[2]);
    for (uint32_t j = 0; j < J; ++j) {
      double z, y, x;
      quat_to_zyx(fr + 3 + 4 * j, &z, &y, &x);
      fprintf(out, " %.4f %.4f %.4f", z, y, x);
    }
    fputc('\n', out);
  }
  if (fclose(out) != 0) {
    out = NULL;
    fprintf(stderr, "smg-synth: error writing %s\n", out_file);
    goto done;
  }
  out = NULL;
  if (glb_file &&
      !write_glb(glb_file, g, J, frames, stride, nframes, fps, no_body))
    goto done;
  rc = 0;
  printf("smg-synth: wrote %ld frames (%.2f s at %.0f fps, %u joints) to %s\n",
         nframes, (double)nframes / fps, fps, J, out_file);
done:
  if (out) fclose(out);
  if (csv) fclose(csv);
  free(frames);
  free(xz);
  if (ch) smg_character_destroy(ch);
  smg_graph_destroy(g);
  return rc;
}
