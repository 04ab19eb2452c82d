/*
 * test_gltf_export.c - smg-synth --glb: a 10 s take re-imported with assimp
 * has the graph's joints, one key per frame in every channel, and joint
 * positions (forward kinematics of the imported keys) within 1 mm of the
 * BVH export of the same take, also imported with assimp; with and without
 * the skinned body. The writer refuses bad input without touching the
 * target or leaving a temporary file.
 */
#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmocka.h>

#include <assimp/cimport.h>
#include <assimp/scene.h>

#include "cli_testutil.h"
#include "gltf_write.h"
#include "smg.h"

#define FPS 30
#define SECONDS 10
#define FRAMES (FPS * SECONDS)
#define MAX_JOINTS 256

static char dir[512];

static int setup(void** state) {
  (void)state;
  return smgt_scratch_dir("test_gltf_export", "export/gltf", dir, sizeof dir);
}

static int teardown(void** state) {
  (void)state;
  smgt_run("rm -rf '%s'", dir);
  return 0;
}

static const struct aiNodeAnim* channel_of(const struct aiAnimation* a, const char* name) {
  for (unsigned i = 0; i < a->mNumChannels; ++i)
    if (!strcmp(a->mChannels[i]->mNodeName.data, name)) return a->mChannels[i];
  return NULL;
}

/* Node-local matrix at key `frame`: the channel's keys where it has them,
 * the node's own transform otherwise. */
static void local_at(const struct aiNode* n, const struct aiAnimation* a, unsigned frame,
                     struct aiMatrix4x4* out) {
  const struct aiNodeAnim* c = channel_of(a, n->mName.data);
  struct aiVector3D s, t;
  struct aiQuaternion q;
  aiDecomposeMatrix(&n->mTransformation, &s, &q, &t);
  if (c && c->mNumRotationKeys)
    q = c->mRotationKeys[frame < c->mNumRotationKeys ? frame
                                                     : c->mNumRotationKeys - 1]
            .mValue;
  if (c && c->mNumPositionKeys)
    t = c->mPositionKeys[frame < c->mNumPositionKeys ? frame
                                                     : c->mNumPositionKeys - 1]
            .mValue;
  struct aiMatrix3x3 r;
  struct aiMatrix3x3 sm;
  aiIdentityMatrix3(&sm);
  sm.a1 = s.x;
  sm.b2 = s.y;
  sm.c3 = s.z;
  aiMatrix3FromQuaternion(&r, &q);
  aiMultiplyMatrix3(&r, &sm);
  aiIdentityMatrix4(out);
  out->a1 = r.a1, out->a2 = r.a2, out->a3 = r.a3, out->a4 = t.x;
  out->b1 = r.b1, out->b2 = r.b2, out->b3 = r.b3, out->b4 = t.y;
  out->c1 = r.c1, out->c2 = r.c2, out->c3 = r.c3, out->c4 = t.z;
}

/* World position of `n` at key `frame` (forward kinematics to the root). */
static void world_at(const struct aiNode* n, const struct aiAnimation* a, unsigned frame,
                     double* p) {
  struct aiMatrix4x4 m, l;
  aiIdentityMatrix4(&m);
  for (; n; n = n->mParent) {
    local_at(n, a, frame, &l);
    aiMultiplyMatrix4(&l, &m); /* l = l * m */
    m = l;
  }
  p[0] = m.a4;
  p[1] = m.b4;
  p[2] = m.c4;
}

static void synth(const char* extra, const char* bvh, const char* glb) {
  char path[600];
  snprintf(path, sizeof path, "%s/path.txt", dir);
  FILE* f = fopen(path, "w");
  assert_non_null(f);
  fprintf(f, "0 0\n0 4\n3 7\n8 7\n12 3\n12 -2\n");
  fclose(f);
  assert_int_equal(
      smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' --seconds %d "
              "--fps %d --transition 6:run --splice 3:1 %s -o '%s' --glb '%s' "
              ">/dev/null",
              SMG_BUILD_DIR, SMG_BUILD_DIR, path, SECONDS, FPS, extra, bvh,
              glb),
      0);
}

static void compare_take(int with_body) {
  char bvh[600], glb[600], blob[600];
  snprintf(bvh, sizeof bvh, "%s/take.bvh", dir);
  snprintf(glb, sizeof glb, "%s/take.glb", dir);
  snprintf(blob, sizeof blob, "%s/default.smg", SMG_BUILD_DIR);
  synth(with_body ? "" : "--no-body", bvh, glb);

  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_file(blob, NULL, &g), SMG_OK);
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  const uint32_t J = info.joint_count;
  assert_true(J > 1 && J <= MAX_JOINTS);

  const struct aiScene* sb = aiImportFile(bvh, 0);
  const struct aiScene* sg = aiImportFile(glb, 0);
  assert_non_null(sb);
  if (!sg) fprintf(stderr, "assimp: %s\n", aiGetErrorString());
  assert_non_null(sg);
  assert_int_equal(sg->mNumAnimations, 1);
  assert_int_equal(sb->mNumAnimations, 1);
  const struct aiAnimation* ab = sb->mAnimations[0];
  const struct aiAnimation* ag = sg->mAnimations[0];
  /* one rotation channel per joint; the root's carries the translation */
  assert_int_equal(ag->mNumChannels, J);
  assert_int_equal(sg->mNumMeshes, with_body ? 1u : 0u);
  if (with_body) {
    assert_int_equal(sg->mMeshes[0]->mNumBones, J);
    assert_true(sg->mMeshes[0]->mNumVertices > 100);
  }

  const struct aiNode* nb[MAX_JOINTS];
  const struct aiNode* ng[MAX_JOINTS];
  for (uint32_t j = 0; j < J; ++j) {
    smg_joint_info ji;
    memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    assert_int_equal(smg_graph_get_joint(g, j, &ji), SMG_OK);
    /* the node named like the joint, depth first */
    const struct aiNode* stack[1024];
    int top = 0;
    nb[j] = ng[j] = NULL;
    stack[top++] = sb->mRootNode;
    while (top && !nb[j]) {
      const struct aiNode* n = stack[--top];
      if (!strcmp(n->mName.data, ji.name)) nb[j] = n;
      for (unsigned c = 0; c < n->mNumChildren && top < 1024; ++c)
        stack[top++] = n->mChildren[c];
    }
    top = 0;
    stack[top++] = sg->mRootNode;
    while (top && !ng[j]) {
      const struct aiNode* n = stack[--top];
      if (!strcmp(n->mName.data, ji.name)) ng[j] = n;
      for (unsigned c = 0; c < n->mNumChildren && top < 1024; ++c)
        stack[top++] = n->mChildren[c];
    }
    assert_non_null(nb[j]);
    assert_non_null(ng[j]);
    const struct aiNodeAnim* c = channel_of(ag, ji.name);
    assert_non_null(c);
    assert_int_equal(c->mNumRotationKeys, FRAMES);
    if (j == 0) assert_int_equal(c->mNumPositionKeys, FRAMES);
    /* key times: frame / fps in the animation's ticks */
    double tps = ag->mTicksPerSecond > 0 ? ag->mTicksPerSecond : 1.0;
    assert_true(fabs(c->mRotationKeys[FRAMES - 1].mTime / tps -
                     (FRAMES - 1) / (double)FPS) < 1e-4);
  }
  const struct aiNodeAnim* root_b = channel_of(ab, nb[0]->mName.data);
  assert_non_null(root_b);
  assert_int_equal(root_b->mNumRotationKeys, FRAMES);

  double worst = 0.0;
  for (unsigned f = 0; f < FRAMES; ++f)
    for (uint32_t j = 0; j < J; ++j) {
      double pb[3], pg[3];
      world_at(nb[j], ab, f, pb);
      world_at(ng[j], ag, f, pg);
      double d = sqrt((pb[0] - pg[0]) * (pb[0] - pg[0]) +
                      (pb[1] - pg[1]) * (pb[1] - pg[1]) +
                      (pb[2] - pg[2]) * (pb[2] - pg[2]));
      if (d > worst) worst = d;
    }
  printf("glTF vs BVH (%s): %u joints, %d frames, worst joint distance "
         "%.3f mm\n",
         with_body ? "with body" : "skeleton", J, FRAMES, worst * 1000.0);
  assert_true(worst < 0.001);
  aiReleaseImport(sb);
  aiReleaseImport(sg);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

static void test_take_with_body(void** state) {
  (void)state;
  compare_take(1);
}

static void test_take_skeleton_only(void** state) {
  (void)state;
  compare_take(0);
}

/* Names in `dir` other than `keep`: a writer that failed left something. */
static int stray_files(const char* keep) {
  DIR* d = opendir(dir);
  struct dirent* e;
  int n = 0;
  assert_non_null(d);
  while ((e = readdir(d)))
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
        strcmp(e->d_name, keep))
      ++n;
  closedir(d);
  return n;
}

static void test_bad_input_leaves_target(void** state) {
  (void)state;
  char target[600], error[256];
  smgt_run("rm -f '%s'/*", dir);
  snprintf(target, sizeof target, "%s/old.glb", dir);
  FILE* f = fopen(target, "w");
  assert_non_null(f);
  fputs("old", f);
  fclose(f);

  int32_t parent[3] = {-1, 0, 1};
  const char* name[3] = {"a", "b", "c"};
  float t[9] = {0, 0, 0, 0, 1, 0, 0, 1, 0};
  float frames[2 * 15];
  gltf_skeleton s = {3, parent, name, t, NULL, NULL};
  gltf_animation a = {2, 30.0f, frames, 15};
  gltf_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.generator = "test";
  sc.root_name = "root";
  sc.skeleton = &s;
  sc.animation = &a;
  for (int i = 0; i < 2; ++i) {
    float* fr = frames + 15 * i;
    fr[0] = fr[1] = fr[2] = 0.0f;
    for (int j = 0; j < 3; ++j) {
      fr[3 + 4 * j] = fr[4 + 4 * j] = fr[5 + 4 * j] = 0.0f;
      fr[6 + 4 * j] = 1.0f;
    }
  }
  /* the good scene writes */
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_OK);
  f = fopen(target, "w");
  assert_non_null(f);
  fputs("old", f);
  fclose(f);

  /* each fault alone: refused, named, the target untouched */
  frames[15 + 1] = NAN;
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(error, "frame 1"));
  frames[15 + 1] = 0.0f;
  frames[3 + 4 + 3] = 2.0f; /* joint 1 frame 0: not unit */
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(error, "joint 1"));
  frames[3 + 4 + 3] = 1.0f;
  parent[2] = 2; /* not an earlier joint */
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  parent[2] = 1;
  a.stride = 14; /* shorter than a frame */
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  a.stride = 15;

  float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, nrm[9] = {0, 0, 1, 0, 0, 1,
                                                         0, 0, 1};
  uint16_t jn[12] = {0};
  float w[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  uint32_t idx[3] = {0, 1, 3}; /* vertex 3 does not exist */
  gltf_mesh m = {3, 3, pos, nrm, jn, w, NULL, idx};
  sc.mesh = &m;
  sc.mesh_name = "mesh";
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(error, "vertex 3"));
  idx[2] = 2;
  jn[4] = 3; /* joint 3 of 3 */
  assert_int_equal(gltf_write_file(target, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_INVALID_ARGUMENT);
  jn[4] = 0;
  /* a target in a folder that does not exist: I/O error, nothing made */
  char missing[700];
  snprintf(missing, sizeof missing, "%s/no-such-dir/x.glb", dir);
  assert_int_equal(gltf_write_file(missing, &sc, GLTF_BINARY, error,
                                   sizeof error),
                   SMG_ERROR_IO);

  f = fopen(target, "r");
  assert_non_null(f);
  char buf[8] = {0};
  assert_int_equal(fread(buf, 1, sizeof buf, f), 3);
  fclose(f);
  assert_string_equal(buf, "old");
  assert_int_equal(stray_files("old.glb"), 0);

  /* with everything fixed, the mesh scene writes as text too */
  snprintf(target, sizeof target, "%s/mesh.gltf", dir);
  assert_int_equal(gltf_write_file(target, &sc, GLTF_TEXT, error,
                                   sizeof error),
                   SMG_OK);
  const struct aiScene* back = aiImportFile(target, 0);
  if (!back) fprintf(stderr, "assimp: %s\n", aiGetErrorString());
  assert_non_null(back);
  assert_int_equal(back->mNumMeshes, 1);
  assert_int_equal(back->mMeshes[0]->mNumVertices, 3);
  aiReleaseImport(back);
}

static void test_synth_glb_errors(void** state) {
  (void)state;
  char path[600], bvh[600], glb[600];
  snprintf(path, sizeof path, "%s/path.txt", dir);
  snprintf(bvh, sizeof bvh, "%s/e.bvh", dir);
  snprintf(glb, sizeof glb, "%s/no-such-dir/e.glb", dir);
  FILE* f = fopen(path, "w");
  assert_non_null(f);
  fprintf(f, "0 0\n0 4\n");
  fclose(f);
  assert_int_not_equal(
      smgt_run("'%s/smg-synth' -g '%s/default.smg' -p '%s' --seconds 1 -o "
              "'%s' --glb '%s' >/dev/null 2>&1",
              SMG_BUILD_DIR, SMG_BUILD_DIR, path, bvh, glb),
      0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_take_with_body),
      cmocka_unit_test(test_take_skeleton_only),
      cmocka_unit_test(test_bad_input_leaves_target),
      cmocka_unit_test(test_synth_glb_errors),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
