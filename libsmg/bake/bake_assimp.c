/*
 * bake_assimp.c - skeletal animation from glTF/GLB/FBX (and anything else
 * assimp reads) through assimp's C API.
 *
 * The skeleton is the part of the node hierarchy that the chosen animation
 * drives: the topmost animated node (or, when several subtrees are
 * animated, their lowest common ancestor) is the root joint, and every node
 * below it that is animated or has animated descendants is a joint (mesh
 * nodes, end sites and other static leaves are dropped). The transforms of
 * the nodes above the root (e.g. an FBX "Armature" with its axis conversion
 * and centimetre scale) are folded into the root's rotation, the root
 * translation and, as a uniform scale, every offset.
 *
 * An unanimated root bone of a skinned mesh above the animated joints is
 * part of the skeleton too.
 * Channels are sampled at the animation's own key spacing (the rate of its
 * densest rotation channel, e.g. 30 or 60 Hz; snapped to an integer rate;
 * at least 30 Hz for sparse keyframes),
 * with linear translation and slerp rotation between keys. As in the BVH
 * reader, only the root may translate over time: a joint whose translation
 * keys move is rejected with SMG_ERROR_UNSUPPORTED; constant ones become the
 * joint's offset. Scale keys are ignored.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__unix__) || defined(__APPLE__)
#include <errno.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#define SMGB_ASSIMP_PROBE 1
#else
#define SMGB_ASSIMP_PROBE 0
#endif

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "bake_clip.h"
#include "bake_import_util.h"
#include "bake_math.h"

#define SMGB_ASSIMP_MAX_JOINTS 512u
#define SMGB_ASSIMP_MAX_FRAMES 10000000u
#define SMGB_ASSIMP_MAX_POSE_BYTES ((size_t)1 << 30)

/* Affine transform: 3x3 linear part (row-major) + translation. */
typedef struct affine {
  double m[9];
  double t[3];
} affine;

static void affine_from_ai(const struct aiMatrix4x4* a, affine* o) {
  o->m[0] = a->a1; o->m[1] = a->a2; o->m[2] = a->a3; o->t[0] = a->a4;
  o->m[3] = a->b1; o->m[4] = a->b2; o->m[5] = a->b3; o->t[1] = a->b4;
  o->m[6] = a->c1; o->m[7] = a->c2; o->m[8] = a->c3; o->t[2] = a->c4;
}

static void affine_mul(const affine* a, const affine* b, affine* o) {
  affine r;
  int i, j;
  for (i = 0; i < 3; ++i) {
    for (j = 0; j < 3; ++j)
      r.m[3 * i + j] = a->m[3 * i] * b->m[j] + a->m[3 * i + 1] * b->m[3 + j] +
                       a->m[3 * i + 2] * b->m[6 + j];
    r.t[i] = a->m[3 * i] * b->t[0] + a->m[3 * i + 1] * b->t[1] +
             a->m[3 * i + 2] * b->t[2] + a->t[i];
  }
  *o = r;
}

static void affine_point(const affine* a, const double p[3], double o[3]) {
  int i;
  double r[3];
  for (i = 0; i < 3; ++i)
    r[i] = a->m[3 * i] * p[0] + a->m[3 * i + 1] * p[1] + a->m[3 * i + 2] * p[2] +
           a->t[i];
  o[0] = r[0]; o[1] = r[1]; o[2] = r[2];
}

/* Split the linear part into uniform scale * rotation. Returns 0 for a
 * reflection or a degenerate/non-uniform scale. */
static int affine_rotation(const affine* a, double* scale, double q[4]) {
  double X[3], Y[3], Z[3], sx, sy, sz, s, det;
  int i;
  for (i = 0; i < 3; ++i) {
    X[i] = a->m[3 * i];
    Y[i] = a->m[3 * i + 1];
    Z[i] = a->m[3 * i + 2];
  }
  sx = sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
  sy = sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
  sz = sqrt(Z[0] * Z[0] + Z[1] * Z[1] + Z[2] * Z[2]);
  det = X[0] * (Y[1] * Z[2] - Y[2] * Z[1]) - Y[0] * (X[1] * Z[2] - X[2] * Z[1]) +
        Z[0] * (X[1] * Y[2] - X[2] * Y[1]);
  if (!(sx > 1e-12) || !(sy > 1e-12) || !(sz > 1e-12) || !(det > 0.0))
    return 0;
  s = (sx + sy + sz) / 3.0;
  if (fabs(sx - s) > 1e-3 * s || fabs(sy - s) > 1e-3 * s ||
      fabs(sz - s) > 1e-3 * s)
    return 0;
  for (i = 0; i < 3; ++i) {
    X[i] /= sx;
    Y[i] /= sy;
    Z[i] /= sz;
  }
  smgb_q_from_axes(X, Y, Z, q);
  *scale = s;
  return 1;
}

/* ---- node bookkeeping ----------------------------------------------------- */

typedef struct node_info {
  const struct aiNode* node;
  int32_t parent;   /* index in the flat node list */
  int32_t channel;  /* channel in the animation, -1 if none */
  int bone;         /* named as a bone by a skinned mesh */
  int keep;         /* a joint */
  int32_t joint;    /* joint index when kept */
} node_info;

typedef struct flat_nodes {
  node_info* v;
  uint32_t count, cap;
} flat_nodes;

/* Flatten the hierarchy in depth-first order (iteratively: hostile files
 * may nest deeply). Returns 0 on allocation failure or too many nodes. */
static int flatten(const struct aiNode* root, flat_nodes* out) {
  const struct aiNode** stack;
  int32_t* parent_stack;
  uint32_t sp = 0, cap = 1024;
  const uint32_t limit = 1u << 20;
  stack = (const struct aiNode**)malloc(sizeof *stack * cap);
  parent_stack = (int32_t*)malloc(sizeof *parent_stack * cap);
  if (!stack || !parent_stack) goto fail;
  stack[sp] = root;
  parent_stack[sp++] = -1;
  while (sp > 0) {
    const struct aiNode* n = stack[--sp];
    int32_t parent = parent_stack[sp], self;
    unsigned c;
    if (out->count == out->cap) {
      uint32_t ncap = out->cap ? out->cap * 2 : 256;
      node_info* nv;
      if (ncap > limit) goto fail;
      nv = (node_info*)realloc(out->v, sizeof *nv * ncap);
      if (!nv) goto fail;
      out->v = nv;
      out->cap = ncap;
    }
    self = (int32_t)out->count++;
    memset(&out->v[self], 0, sizeof out->v[self]);
    out->v[self].node = n;
    out->v[self].parent = parent;
    out->v[self].channel = -1;
    out->v[self].joint = -1;
    /* Push children in reverse so they come out in file order. */
    if (sp + n->mNumChildren > cap) {
      uint32_t ncap = cap;
      const struct aiNode** ns;
      int32_t* np;
      while (sp + n->mNumChildren > ncap) ncap *= 2;
      if (ncap > limit) goto fail;
      ns = (const struct aiNode**)realloc((void*)stack, sizeof *ns * ncap);
      if (!ns) goto fail;
      stack = ns;
      np = (int32_t*)realloc(parent_stack, sizeof *np * ncap);
      if (!np) goto fail;
      parent_stack = np;
      cap = ncap;
    }
    for (c = n->mNumChildren; c-- > 0;) {
      if (!n->mChildren[c]) continue;
      stack[sp] = n->mChildren[c];
      parent_stack[sp++] = self;
    }
  }
  free((void*)stack);
  free(parent_stack);
  return 1;
fail:
  free((void*)stack);
  free(parent_stack);
  return 0;
}

/* ---- sampling ------------------------------------------------------------- */

/* The last of n keys (n >= 2) whose time is at or before t. Both key
 * types start with their time: `time` points at the first key's, `stride`
 * is the key size. */
static uint32_t key_before(const double* time, size_t stride, uint32_t n,
                           double t) {
  const char* base = (const char*)time;
  uint32_t lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    uint32_t mid = (lo + hi) / 2;
    if (*(const double*)(base + (size_t)mid * stride) <= t) lo = mid;
    else hi = mid;
  }
  return lo;
}

static int sample_position(const struct aiNodeAnim* ch, double t, double o[3]) {
  uint32_t n, i;
  double u;
  const struct aiVectorKey* k;
  if (!ch || ch->mNumPositionKeys == 0 || !ch->mPositionKeys) return 0;
  k = ch->mPositionKeys;
  n = ch->mNumPositionKeys;
  if (n == 1 || t <= k[0].mTime) {
    o[0] = k[0].mValue.x; o[1] = k[0].mValue.y; o[2] = k[0].mValue.z;
    return 1;
  }
  if (t >= k[n - 1].mTime) {
    o[0] = k[n - 1].mValue.x; o[1] = k[n - 1].mValue.y; o[2] = k[n - 1].mValue.z;
    return 1;
  }
  i = key_before(&k[0].mTime, sizeof *k, n, t);
  u = (k[i + 1].mTime > k[i].mTime)
          ? (t - k[i].mTime) / (k[i + 1].mTime - k[i].mTime) : 0.0;
  o[0] = k[i].mValue.x + (k[i + 1].mValue.x - k[i].mValue.x) * u;
  o[1] = k[i].mValue.y + (k[i + 1].mValue.y - k[i].mValue.y) * u;
  o[2] = k[i].mValue.z + (k[i + 1].mValue.z - k[i].mValue.z) * u;
  return 1;
}

static int sample_rotation(const struct aiNodeAnim* ch, double t, double q[4]) {
  uint32_t n, i;
  double a[4], b[4], u;
  const struct aiQuatKey* k;
  if (!ch || ch->mNumRotationKeys == 0 || !ch->mRotationKeys) return 0;
  k = ch->mRotationKeys;
  n = ch->mNumRotationKeys;
  if (n == 1 || t <= k[0].mTime) i = 0, u = 0.0;
  else if (t >= k[n - 1].mTime) i = n - 1, u = 0.0;
  else {
    i = key_before(&k[0].mTime, sizeof *k, n, t);
    u = (k[i + 1].mTime > k[i].mTime)
            ? (t - k[i].mTime) / (k[i + 1].mTime - k[i].mTime) : 0.0;
  }
  a[0] = k[i].mValue.x; a[1] = k[i].mValue.y;
  a[2] = k[i].mValue.z; a[3] = k[i].mValue.w;
  smgb_q_normalize(a);
  if (u <= 0.0) {
    memcpy(q, a, sizeof a);
    return 1;
  }
  b[0] = k[i + 1].mValue.x; b[1] = k[i + 1].mValue.y;
  b[2] = k[i + 1].mValue.z; b[3] = k[i + 1].mValue.w;
  smgb_q_normalize(b);
  smgb_q_slerp(a, b, u, q);
  return 1;
}

static int finite_channel(const struct aiNodeAnim* ch) {
  uint32_t i;
  for (i = 0; i < ch->mNumPositionKeys; ++i) {
    const struct aiVectorKey* k = &ch->mPositionKeys[i];
    if (!isfinite(k->mTime) || !isfinite(k->mValue.x) ||
        !isfinite(k->mValue.y) || !isfinite(k->mValue.z) ||
        fabs(k->mValue.x) > 1e9 || fabs(k->mValue.y) > 1e9 ||
        fabs(k->mValue.z) > 1e9)
      return 0;
  }
  for (i = 0; i < ch->mNumRotationKeys; ++i) {
    const struct aiQuatKey* k = &ch->mRotationKeys[i];
    if (!isfinite(k->mTime) || !isfinite(k->mValue.x) ||
        !isfinite(k->mValue.y) || !isfinite(k->mValue.z) ||
        !isfinite(k->mValue.w))
      return 0;
  }
  return 1;
}

/* Units from the leg length, else the hips height. */
static double guess_unit(const smgb_skeleton* s, double hips_height) {
  double size = smgb_skeleton_leg_length(s);
  if (!(size > 0.0)) size = fabs(hips_height) * 0.9;
  return smgb_unit_from_leg(size);
}

/* assimp is a large parser of untrusted files, and some malformed ones
 * crash it (fuzzing found a NULL dereference in assimp 5.2's glTF 2 reader;
 * docs/reliability.md). Where processes can be forked, each file is first
 * read by a child process, which reports over a pipe that assimp returned;
 * without that report the import fails with an error naming the file
 * instead of taking the baker down. The child only parses and exits; the
 * real import follows in this process. Returns 1 when the file can be
 * read here (or no probe is possible). */
static int assimp_survives(const char* path, struct aiPropertyStore* props) {
#if SMGB_ASSIMP_PROBE
  /* The child dies of the signal itself, whatever handler the host
   * process installed: a sanitizer's, a fuzzer's or an engine's crash
   * reporter would take the crash as the host's own. Its exit status is
   * not the verdict (a sanitizer's handler or a leak checker may exit
   * with an error code of its own); the report sent after the parse is. */
  static const int fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
  int fds[2], status = 0;
  char parsed = 0;
  ssize_t n;
  size_t i;
  pid_t pid;
  if (pipe(fds) != 0) return 1; /* no probe: import directly */
  fflush(NULL); /* nothing buffered is written twice */
  pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return 1;
  }
  if (pid == 0) {
    const struct aiScene* s;
    close(fds[0]);
    for (i = 0; i < sizeof fatal / sizeof fatal[0]; ++i)
      signal(fatal[i], SIG_DFL);
    s = aiImportFileExWithProperties(path, aiProcess_ValidateDataStructure,
                                     NULL, props);
    if (s) aiReleaseImport(s);
    if (props) aiReleasePropertyStore(props);
    parsed = 1;
    if (write(fds[1], &parsed, 1) != 1) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  do n = read(fds[0], &parsed, 1);
  while (n < 0 && errno == EINTR);
  close(fds[0]);
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) break;
  return n == 1 && parsed == 1;
#else
  (void)path;
  (void)props;
  return 1;
#endif
}

/* ---- import, step by step ------------------------------------------------ */

/* One file's import: the scene and what the steps below derive from it. */
typedef struct assimp_import {
  const char* path;
  smgb_error* err;
  const struct aiScene* scene;
  const struct aiAnimation* anim;
  double tps;                  /* animation ticks per second */
  flat_nodes nodes;
  int32_t root;                /* skeleton root (index in nodes) */
  uint32_t J;
  affine parent_global;        /* global transform of the root's parent */
  double parent_scale, parent_q[4];
  double* rest_q;              /* per joint: rest rotation */
  double* rest_t;              /* per joint: rest translation */
  const struct aiNodeAnim** chans; /* per joint: channel or NULL */
  double t_min, t_max;         /* key time range, ticks */
  uint32_t densest;            /* joint with the most rotation keys */
  double rate;                 /* sampling rate, Hz */
  smgb_clip clip;
} assimp_import;

/* The file read by assimp (after the probe: a file that crashes assimp
 * is refused without reading it here). */
static smg_result open_scene(assimp_import* a) {
  struct aiPropertyStore* props;
  FILE* fp = fopen(a->path, "rb");
  if (!fp) {
    smgb_imp_errorf(a->err, "%s: cannot open file", a->path);
    return SMG_ERROR_IO;
  }
  fclose(fp);
  props = aiCreatePropertyStore();
  if (props)
    aiSetImportPropertyInteger(props, AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, 0);
  if (!assimp_survives(a->path, props)) {
    if (props) aiReleasePropertyStore(props);
    smgb_imp_errorf(a->err, "%s: assimp crashed reading the file (a "
                    "malformed glTF/GLB/FBX file); nothing was imported",
                    a->path);
    return SMG_ERROR_PARSE;
  }
  a->scene = aiImportFileExWithProperties(
      a->path, aiProcess_ValidateDataStructure, NULL, props);
  if (props) aiReleasePropertyStore(props);
  if (!a->scene) {
    smgb_imp_errorf(a->err, "%s: assimp could not read the file: %s",
                    a->path, aiGetErrorString());
    return SMG_ERROR_PARSE;
  }
  return SMG_OK;
}

/* The requested animation and its tick rate. */
static smg_result pick_animation(assimp_import* a, uint32_t index) {
  const struct aiScene* scene = a->scene;
  if (!scene->mRootNode || scene->mNumAnimations == 0 || !scene->mAnimations) {
    smgb_imp_errorf(a->err, "%s: the file has no skeletal animation",
                    a->path);
    return SMG_ERROR_PARSE;
  }
  if (index >= scene->mNumAnimations) {
    smgb_imp_errorf(a->err, "%s: animation %u requested, the file has %u",
                    a->path, index, scene->mNumAnimations);
    return SMG_ERROR_OUT_OF_RANGE;
  }
  a->anim = scene->mAnimations[index];
  if (!a->anim || a->anim->mNumChannels == 0 || !a->anim->mChannels) {
    smgb_imp_errorf(a->err, "%s: animation %u has no node channels", a->path,
                    index);
    return SMG_ERROR_PARSE;
  }
  a->tps = a->anim->mTicksPerSecond > 0.0 && isfinite(a->anim->mTicksPerSecond)
               ? a->anim->mTicksPerSecond
               : 25.0; /* assimp's documented default */
  return SMG_OK;
}

/* The node hierarchy flattened, each animation channel attached to the
 * node of its name, and the bones of skinned meshes marked (an unanimated
 * root bone above the animated joints still belongs to the skeleton;
 * static leaf bones such as BVH end sites do not). */
static smg_result read_nodes(assimp_import* a) {
  const struct aiScene* scene = a->scene;
  flat_nodes* nodes = &a->nodes;
  uint32_t i, c;
  if (!flatten(scene->mRootNode, nodes)) {
    smgb_imp_errorf(a->err, "%s: node hierarchy too large or out of memory",
                    a->path);
    return SMG_ERROR_CAPACITY;
  }
  for (c = 0; c < a->anim->mNumChannels; ++c) {
    const struct aiNodeAnim* ch = a->anim->mChannels[c];
    if (!ch) continue;
    if (!finite_channel(ch)) {
      smgb_imp_errorf(a->err, "%s: channel '%.60s' has non-finite or huge "
                      "keys", a->path, ch->mNodeName.data);
      return SMG_ERROR_PARSE;
    }
    for (i = 0; i < nodes->count; ++i) {
      if (nodes->v[i].channel < 0 &&
          strcmp(nodes->v[i].node->mName.data, ch->mNodeName.data) == 0) {
        nodes->v[i].channel = (int32_t)c;
        break;
      }
    }
  }
  for (c = 0; c < scene->mNumMeshes && scene->mMeshes; ++c) {
    const struct aiMesh* mesh = scene->mMeshes[c];
    unsigned b;
    if (!mesh || !mesh->mBones) continue;
    for (b = 0; b < mesh->mNumBones; ++b) {
      if (!mesh->mBones[b]) continue;
      for (i = 0; i < nodes->count; ++i) {
        if (strcmp(nodes->v[i].node->mName.data,
                   mesh->mBones[b]->mName.data) == 0) {
          nodes->v[i].bone = 1;
          break;
        }
      }
    }
  }
  return SMG_OK;
}

/* Skeleton root: the lowest common ancestor of all animated nodes, raised
 * to the topmost bone above it. */
static smg_result find_root(assimp_import* a) {
  const flat_nodes* nodes = &a->nodes;
  int32_t root = -1;
  uint32_t i;
  for (i = 0; i < nodes->count; ++i) {
    int32_t x, y;
    if (nodes->v[i].channel < 0) continue;
    if (root < 0) {
      root = (int32_t)i;
      continue;
    }
    /* LCA by walking up (depth-first order: ancestors have lower index). */
    x = root;
    y = (int32_t)i;
    while (x != y) {
      if (x > y) x = nodes->v[x].parent;
      else y = nodes->v[y].parent;
      if (x < 0 || y < 0) break;
    }
    root = x >= 0 && y >= 0 ? x : 0;
  }
  if (root < 0) {
    smgb_imp_errorf(a->err, "%s: no animation channel matches a node",
                    a->path);
    return SMG_ERROR_PARSE;
  }
  while (nodes->v[root].parent >= 0 && nodes->v[nodes->v[root].parent].bone)
    root = nodes->v[root].parent;
  a->root = root;
  return SMG_OK;
}

/* Joints: the animated nodes under the root and their ancestors up to it,
 * numbered in depth-first order. */
static smg_result number_joints(assimp_import* a) {
  flat_nodes* nodes = &a->nodes;
  int32_t root = a->root;
  uint32_t i;
  for (i = nodes->count; i-- > (uint32_t)root;) {
    int32_t p;
    if (nodes->v[i].channel < 0 && !nodes->v[i].keep && (int32_t)i != root)
      continue;
    nodes->v[i].keep = 1;
    p = nodes->v[i].parent;
    if ((int32_t)i != root && p >= root) nodes->v[p].keep = 1;
  }
  for (i = (uint32_t)root; i < nodes->count; ++i) {
    int32_t x = (int32_t)i;
    if (!nodes->v[i].keep) continue;
    while (x > root) x = nodes->v[x].parent; /* is it below the root? */
    if (x != root) {
      nodes->v[i].keep = 0;
      continue;
    }
    if (a->J >= SMGB_ASSIMP_MAX_JOINTS) {
      smgb_imp_errorf(a->err, "%s: skeleton has more than %u joints",
                      a->path, SMGB_ASSIMP_MAX_JOINTS);
      return SMG_ERROR_CAPACITY;
    }
    nodes->v[i].joint = (int32_t)a->J++;
  }
  return SMG_OK;
}

/* The nodes above the root (an FBX "Armature" with its axis conversion
 * and centimetre scale) as one uniform scale and rotation. */
static smg_result above_root(assimp_import* a) {
  int32_t x = a->nodes.v[a->root].parent;
  memset(&a->parent_global, 0, sizeof a->parent_global);
  a->parent_global.m[0] = a->parent_global.m[4] = a->parent_global.m[8] = 1.0;
  while (x >= 0) {
    affine local;
    affine_from_ai(&a->nodes.v[x].node->mTransformation, &local);
    affine_mul(&local, &a->parent_global, &a->parent_global);
    x = a->nodes.v[x].parent;
  }
  if (!affine_rotation(&a->parent_global, &a->parent_scale, a->parent_q)) {
    smgb_imp_errorf(a->err, "%s: the nodes above the skeleton root mirror or "
                    "scale non-uniformly (unsupported)", a->path);
    return SMG_ERROR_UNSUPPORTED;
  }
  return SMG_OK;
}

/* The key time range, and the joint with the densest rotation keys. */
static void note_key_times(assimp_import* a, uint32_t j,
                           const struct aiNodeAnim* ch) {
  if (ch->mNumRotationKeys > 0) {
    const struct aiQuatKey* k = ch->mRotationKeys;
    if (k[0].mTime < a->t_min) a->t_min = k[0].mTime;
    if (k[ch->mNumRotationKeys - 1].mTime > a->t_max)
      a->t_max = k[ch->mNumRotationKeys - 1].mTime;
    if (!a->chans[a->densest] ||
        ch->mNumRotationKeys > a->chans[a->densest]->mNumRotationKeys)
      a->densest = j;
  }
  if (ch->mNumPositionKeys > 0) {
    const struct aiVectorKey* k = ch->mPositionKeys;
    if (k[0].mTime < a->t_min) a->t_min = k[0].mTime;
    if (k[ch->mNumPositionKeys - 1].mTime > a->t_max)
      a->t_max = k[ch->mNumPositionKeys - 1].mTime;
  }
}

/* Joint j (node i): its unique name, parent, rest transform, channel. */
static smg_result read_joint(assimp_import* a, uint32_t i, int32_t j) {
  const node_info* n = &a->nodes.v[i];
  smgb_skeleton* s = &a->clip.skeleton;
  const char* nm = n->node->mName.data;
  affine local;
  double scale;
  int32_t k;
  if (strlen(nm) >= SMGB_NAME_MAX || nm[0] == '\0') {
    smgb_imp_errorf(a->err, "%s: joint name '%.60s' is empty or longer than "
                    "%d characters", a->path, nm, SMGB_NAME_MAX - 1);
    return SMG_ERROR_PARSE;
  }
  for (k = 0; k < j; ++k)
    if (strcmp(s->names[k], nm) == 0) {
      smgb_imp_errorf(a->err, "%s: duplicate joint name '%s'", a->path, nm);
      return SMG_ERROR_PARSE;
    }
  memcpy(s->names[j], nm, strlen(nm) + 1);
  s->parents[j] = (int32_t)i == a->root ? -1 : a->nodes.v[n->parent].joint;
  affine_from_ai(&n->node->mTransformation, &local);
  if (!affine_rotation(&local, &scale, a->rest_q + 4 * j)) {
    /* A scaled joint: keep its rotation only (scale ignored). */
    double X[3] = {local.m[0], local.m[3], local.m[6]};
    double Y[3] = {local.m[1], local.m[4], local.m[7]};
    double Z[3] = {local.m[2], local.m[5], local.m[8]};
    smgb_q_from_axes(X, Y, Z, a->rest_q + 4 * j);
  }
  a->rest_t[3 * j + 0] = local.t[0];
  a->rest_t[3 * j + 1] = local.t[1];
  a->rest_t[3 * j + 2] = local.t[2];
  if (n->channel >= 0) {
    const struct aiNodeAnim* ch = a->anim->mChannels[n->channel];
    a->chans[j] = ch;
    note_key_times(a, (uint32_t)j, ch);
  }
  return SMG_OK;
}

/* Every joint: the skeleton's names and parents, rest transforms and
 * channels. */
static smg_result read_joints(assimp_import* a) {
  uint32_t i, J = a->J;
  smgb_skeleton* s = &a->clip.skeleton;
  smg_result r;
  a->rest_q = (double*)malloc(sizeof *a->rest_q * 4 * J);
  a->rest_t = (double*)malloc(sizeof *a->rest_t * 3 * J);
  a->chans = (const struct aiNodeAnim**)calloc(J, sizeof *a->chans);
  s->joint_count = J;
  s->names = (char(*)[SMGB_NAME_MAX])calloc(J, SMGB_NAME_MAX);
  s->parents = (int32_t*)malloc(sizeof(int32_t) * J);
  s->offsets = (float(*)[3])malloc(sizeof(float) * 3 * J);
  if (!a->rest_q || !a->rest_t || !a->chans || !s->names ||
      !s->parents || !s->offsets) {
    smgb_imp_errorf(a->err, "%s: out of memory", a->path);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  a->t_min = 1e300;
  a->t_max = -1e300;
  for (i = (uint32_t)a->root; i < a->nodes.count; ++i) {
    int32_t j = a->nodes.v[i].joint;
    if (j >= 0 && (r = read_joint(a, i, j)) != SMG_OK) return r;
  }
  if (!(a->t_max >= a->t_min)) a->t_min = a->t_max = 0.0;
  return SMG_OK;
}

/* Sampling rate from the densest rotation channel's key spacing (snapped
 * to an integer rate), and the clip's frames allocated. */
static smg_result frame_timing(assimp_import* a) {
  const struct aiNodeAnim* ch = a->chans[a->densest];
  double nf;
  uint32_t frames;
  a->rate = 30.0;
  if (ch && ch->mNumRotationKeys >= 2) {
    double span = ch->mRotationKeys[ch->mNumRotationKeys - 1].mTime -
                  ch->mRotationKeys[0].mTime;
    if (span > 0.0) {
      double r = (ch->mNumRotationKeys - 1) * a->tps / span,
             ri = floor(r + 0.5);
      a->rate = (ri >= 1.0 && fabs(r - ri) <= 1e-3 * ri) ? ri : r;
    }
  }
  /* Sparse keyframes (hand animation: a few keys per second) are sampled
   * at 30 Hz so the interpolation between keys is kept. */
  if (a->rate < 24.0) a->rate = 30.0;
  if (!(a->rate >= 1.0) || a->rate > 1000.0) {
    smgb_imp_errorf(a->err, "%s: implausible key rate %.3g per second",
                    a->path, a->rate);
    return SMG_ERROR_PARSE;
  }
  nf = floor((a->t_max - a->t_min) / a->tps * a->rate + 1e-6) + 1.0;
  if (nf > SMGB_ASSIMP_MAX_FRAMES ||
      nf * SMGB_STRIDE(a->J) * sizeof(float) >
          (double)SMGB_ASSIMP_MAX_POSE_BYTES) {
    smgb_imp_errorf(a->err, "%s: animation too long (%.0f frames)", a->path,
                    nf);
    return SMG_ERROR_CAPACITY;
  }
  frames = (uint32_t)nf;
  a->clip.poses =
      (float*)malloc(sizeof(float) * (size_t)frames * SMGB_STRIDE(a->J));
  if (!a->clip.poses) {
    smgb_imp_errorf(a->err, "%s: out of memory for %u frames", a->path,
                    frames);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  a->clip.frame_count = frames;
  a->clip.frame_rate = (float)a->rate;
  return SMG_OK;
}

/* Offsets (file units, times the parents' uniform scale) from the first
 * frame; non-root translation must stay constant. */
static smg_result read_offsets(assimp_import* a) {
  smgb_skeleton* s = &a->clip.skeleton;
  uint32_t i;
  for (i = 0; i < a->J; ++i) {
    const struct aiNodeAnim* ch = a->chans[i];
    double t0[3] = {a->rest_t[3 * i], a->rest_t[3 * i + 1],
                    a->rest_t[3 * i + 2]};
    /* The root's offset is informational (its position is per frame): keep
     * the rest transform, as the BVH reader keeps the root OFFSET. */
    if (i > 0) sample_position(ch, a->t_min, t0);
    s->offsets[i][0] = (float)(t0[0] * a->parent_scale);
    s->offsets[i][1] = (float)(t0[1] * a->parent_scale);
    s->offsets[i][2] = (float)(t0[2] * a->parent_scale);
    if (i > 0 && ch && ch->mNumPositionKeys > 1) {
      uint32_t k;
      double tol =
          1e-4 + 1e-2 * sqrt(t0[0] * t0[0] + t0[1] * t0[1] + t0[2] * t0[2]);
      for (k = 0; k < ch->mNumPositionKeys; ++k) {
        const struct aiVector3D* v = &ch->mPositionKeys[k].mValue;
        if (fabs(v->x - t0[0]) > tol || fabs(v->y - t0[1]) > tol ||
            fabs(v->z - t0[2]) > tol) {
          smgb_imp_errorf(a->err, "%s: joint '%s' has animated translation "
                          "(key %u); only the root may translate",
                          a->path, s->names[i], k);
          return SMG_ERROR_UNSUPPORTED;
        }
      }
    }
  }
  return SMG_OK;
}

/* Every frame sampled: root position through the nodes above the root,
 * rotations slerped, each quaternion on the side of its predecessor. */
static void sample_frames(assimp_import* a) {
  uint32_t f, i, stride = SMGB_STRIDE(a->J);
  for (f = 0; f < a->clip.frame_count; ++f) {
    double t = a->t_min + f * a->tps / a->rate;
    float* pose = a->clip.poses + (size_t)f * stride;
    if (t > a->t_max) t = a->t_max;
    for (i = 0; i < a->J; ++i) {
      const double* rq = a->rest_q + 4 * i;
      double q[4] = {rq[0], rq[1], rq[2], rq[3]};
      sample_rotation(a->chans[i], t, q);
      if (i == 0) {
        double p[3] = {a->rest_t[0], a->rest_t[1], a->rest_t[2]};
        sample_position(a->chans[0], t, p);
        affine_point(&a->parent_global, p, p);
        pose[0] = (float)p[0];
        pose[1] = (float)p[1];
        pose[2] = (float)p[2];
        smgb_q_mul(a->parent_q, q, q);
      }
      smgb_q_normalize(q);
      pose[3 + 4 * i + 0] = (float)q[0];
      pose[3 + 4 * i + 1] = (float)q[1];
      pose[3 + 4 * i + 2] = (float)q[2];
      pose[3 + 4 * i + 3] = (float)q[3];
      if (f > 0) {
        const float* pq = pose - stride + 3 + 4 * i;
        float* cq = pose + 3 + 4 * i;
        if (pq[0] * cq[0] + pq[1] * cq[1] + pq[2] * cq[2] + pq[3] * cq[3] < 0) {
          cq[0] = -cq[0]; cq[1] = -cq[1]; cq[2] = -cq[2]; cq[3] = -cq[3];
        }
      }
    }
  }
}

/* File units to metres: unit_scale, or a guess from the leg length. */
static void to_metres(assimp_import* a, float unit_scale) {
  smgb_clip* c = &a->clip;
  uint32_t f, i, stride = SMGB_STRIDE(a->J);
  double scale = unit_scale > 0.0f ? unit_scale
                                   : guess_unit(&c->skeleton, c->poses[1]);
  for (i = 0; i < a->J; ++i) {
    c->skeleton.offsets[i][0] = (float)(c->skeleton.offsets[i][0] * scale);
    c->skeleton.offsets[i][1] = (float)(c->skeleton.offsets[i][1] * scale);
    c->skeleton.offsets[i][2] = (float)(c->skeleton.offsets[i][2] * scale);
  }
  for (f = 0; f < c->frame_count; ++f) {
    float* pose = c->poses + (size_t)f * stride;
    pose[0] = (float)(pose[0] * scale);
    pose[1] = (float)(pose[1] * scale);
    pose[2] = (float)(pose[2] * scale);
  }
}

smg_result smgb_assimp_load(const char* path, float unit_scale,
                            uint32_t animation_index, smgb_clip* out,
                            smgb_error* err) {
  assimp_import a;
  const char* base;
  smg_result r;
  if (err) err->message[0] = '\0';
  if (!path || !out || !isfinite(unit_scale) || unit_scale < 0.0f ||
      unit_scale > 1e3f) {
    smgb_imp_errorf(err, "%s: invalid argument to smgb_assimp_load",
                    path ? path : "(null)");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  memset(&a, 0, sizeof a);
  a.path = path;
  a.err = err;
  r = open_scene(&a);
  if (r == SMG_OK) r = pick_animation(&a, animation_index);
  if (r == SMG_OK) r = read_nodes(&a);
  if (r == SMG_OK) r = find_root(&a);
  if (r == SMG_OK) r = number_joints(&a);
  if (r == SMG_OK) r = above_root(&a);
  if (r == SMG_OK) r = read_joints(&a);
  if (r == SMG_OK) r = frame_timing(&a);
  if (r == SMG_OK) r = read_offsets(&a);
  if (r == SMG_OK) {
    sample_frames(&a);
    to_metres(&a, unit_scale);
    base = strrchr(path, '/');
    snprintf(a.clip.name, sizeof a.clip.name, "%s", base ? base + 1 : path);
    *out = a.clip;
    memset(&a.clip, 0, sizeof a.clip);
  }
  smgb_clip_free(&a.clip);
  free(a.nodes.v);
  free(a.rest_q);
  free(a.rest_t);
  free((void*)a.chans);
  if (a.scene) aiReleaseImport(a.scene);
  return r;
}
