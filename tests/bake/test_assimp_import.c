/*
 * test_assimp_import.c - glTF/GLB through assimp's C API: a synthetic clip
 * is written as BVH, converted by assimp's own exporter to glTF 2 (.gltf and
 * .glb), and loaded back with smgb_assimp_load; skeleton and poses must
 * match the source within float tolerance. Bad inputs give clear errors.
 * (assimp 5.2's FBX and Collada exporters write files its own importers
 * reject, so FBX is not round-tripped; a real FBX from Debian's
 * assimp-testmodels is loaded when that package is installed.)
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <assimp/cexport.h>
#include <assimp/cimport.h>
#include <assimp/scene.h>

#include "bake_clip.h"
#include "bake_synthetic.h"
#include "import_helpers.h"

static char g_dir[256];
static char g_bvh[400];
static smgb_clip g_src;

static int setup(void** state) {
  smgb_synth_params p;
  smgb_error err;
  (void)state;
  imp_tempdir(g_dir, sizeof g_dir);
  if (!g_dir[0]) return -1;
  memset(&p, 0, sizeof p);
  p.kind = SMGB_SYNTH_RUN;
  p.turn_rate = 0.5f;
  p.duration = smgt_quick() ? 0.5f : 2.0f;
  p.frame_rate = 30.0f;
  if (smgb_synth_generate(&p, &g_src, NULL) != SMG_OK) return -1;
  snprintf(g_bvh, sizeof g_bvh, "%s/source.bvh", g_dir);
  return smgb_bvh_save(g_bvh, &g_src, &err) == SMG_OK ? 0 : -1;
}

static int teardown(void** state) {
  (void)state;
  smgb_clip_free(&g_src);
  imp_rmdir(g_dir);
  return 0;
}

static void expect_same(const smgb_clip* a, const smgb_clip* b) {
  uint32_t j;
  assert_int_equal(b->skeleton.joint_count, a->skeleton.joint_count);
  assert_int_equal(b->frame_count, a->frame_count);
  assert_float_equal(b->frame_rate, a->frame_rate, 0.0f);
  for (j = 0; j < a->skeleton.joint_count; ++j) {
    assert_string_equal(b->skeleton.names[j], a->skeleton.names[j]);
    assert_int_equal(b->skeleton.parents[j], a->skeleton.parents[j]);
    if (j > 0) {
      assert_float_equal(b->skeleton.offsets[j][0], a->skeleton.offsets[j][0], 1e-6f);
      assert_float_equal(b->skeleton.offsets[j][1], a->skeleton.offsets[j][1], 1e-6f);
      assert_float_equal(b->skeleton.offsets[j][2], a->skeleton.offsets[j][2], 1e-6f);
    }
  }
  assert_true(imp_rot_diff(a, b) < 1e-5);
}

static void test_bvh_through_assimp(void** state) {
  smgb_clip c;
  smgb_error err;
  (void)state;
  if (smgb_assimp_load(g_bvh, 1.0f, 0, &c, &err) != SMG_OK)
    fail_msg("%s", err.message);
  expect_same(&g_src, &c);
  smgb_clip_free(&c);
}

static const char* g_self; /* argv[0] */

/* Fixture conversion with assimp's exporter. Run in a separate process
 * (system() execs a shell, which valgrind does not follow): assimp 5.2's
 * glTF exporter writes uninitialised padding bytes, an error inside assimp,
 * not in the importer under test. */
static int export_main(const char* in, const char* format, const char* out) {
  const struct aiScene* scene = aiImportFile(in, 0);
  aiReturn r;
  if (!scene) return 1;
  r = aiExportScene(scene, format, out, 0);
  aiReleaseImport(scene);
  return r == aiReturn_SUCCESS ? 0 : 1;
}

static void export_and_load(const char* format, const char* file) {
  char path[500], cmd[1600];
  smgb_clip c;
  smgb_error err;
  snprintf(path, sizeof path, "%s/%s", g_dir, file);
  snprintf(cmd, sizeof cmd, "'%s' --export '%s' %s '%s'", g_self, g_bvh,
           format, path);
  assert_int_equal(system(cmd), 0);
  if (smgb_assimp_load(path, 0.0f, 0, &c, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_string_equal(c.name, file);
  expect_same(&g_src, &c); /* unit 0: guessed as metres */
  smgb_clip_free(&c);
}

static void test_glb_round_trip(void** state) {
  (void)state;
  export_and_load("glb2", "clip.glb");
}

static void test_gltf_round_trip(void** state) {
  (void)state;
  export_and_load("gltf2", "clip.gltf");
}

/* A real FBX file (Blender export, Z-up armature) from Debian's
 * assimp-testmodels, when installed: loads with its 10 bones, 40 frames at
 * 25 Hz, unit quaternions and actual motion. */
static void test_fbx_testmodel(void** state) {
  static const char path[] = "/usr/share/assimp/models/FBX/huesitos.fbx";
  FILE* fp = fopen(path, "rb");
  smgb_clip c;
  smgb_error err;
  uint32_t f, j, S;
  double moved = 0.0;
  (void)state;
  if (!fp) {
    printf("SKIP: %s absent (apt-get install assimp-testmodels)\n", path);
    skip();
    return;
  }
  fclose(fp);
  if (smgb_assimp_load(path, 1.0f, 0, &c, &err) != SMG_OK)
    fail_msg("%s", err.message);
  assert_int_equal(c.skeleton.joint_count, 10);
  assert_string_equal(c.skeleton.names[0], "Armature");
  assert_string_equal(c.skeleton.names[1], "Bone");
  assert_int_equal(c.skeleton.parents[0], -1);
  assert_int_equal(c.frame_count, 40);
  assert_float_equal(c.frame_rate, 25.0f, 0.0f);
  S = SMGB_STRIDE(10);
  for (f = 0; f < c.frame_count; ++f) {
    for (j = 0; j < 10; ++j) {
      const float* q = c.poses + (size_t)f * S + 3 + 4 * j;
      const float* q0 = c.poses + 3 + 4 * j;
      double d = q[0] * q0[0] + q[1] * q0[1] + q[2] * q0[2] + q[3] * q0[3];
      assert_float_equal(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3],
                         1.0, 1e-5);
      if (1.0 - fabs(d) > moved) moved = 1.0 - fabs(d);
    }
  }
  assert_true(moved > 1e-3);
  smgb_clip_free(&c);
}

static void test_bad_files(void** state) {
  char path[500];
  smgb_clip c;
  smgb_error err;
  smg_result r;
  (void)state;
  r = smgb_assimp_load("/nonexistent/clip.glb", 0.0f, 0, &c, &err);
  assert_int_equal(r, SMG_ERROR_IO);
  assert_non_null(strstr(err.message, "/nonexistent/clip.glb"));
  snprintf(path, sizeof path, "%s/junk.glb", g_dir);
  assert_true(imp_write_file(path, "glTF\x02garbage garbage garbage"));
  r = smgb_assimp_load(path, 0.0f, 0, &c, &err);
  assert_int_equal(r, SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "junk.glb"));
  /* A mesh without any animation. */
  snprintf(path, sizeof path, "%s/static.obj", g_dir);
  assert_true(imp_write_file(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  r = smgb_assimp_load(path, 0.0f, 0, &c, &err);
  assert_int_equal(r, SMG_ERROR_PARSE);
  assert_non_null(strstr(err.message, "no skeletal animation"));
  /* Animation index out of range. */
  r = smgb_assimp_load(g_bvh, 0.0f, 3, &c, &err);
  assert_int_equal(r, SMG_ERROR_OUT_OF_RANGE);
  assert_non_null(strstr(err.message, "animation 3"));
  assert_int_equal(smgb_assimp_load(g_bvh, -1.0f, 0, &c, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_assimp_load(NULL, 0.0f, 0, &c, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
}

int main(int argc, char** argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bvh_through_assimp),
      cmocka_unit_test(test_glb_round_trip),
      cmocka_unit_test(test_gltf_round_trip),
      cmocka_unit_test(test_fbx_testmodel),
      cmocka_unit_test(test_bad_files),
  };
  if (argc == 5 && strcmp(argv[1], "--export") == 0)
    return export_main(argv[2], argv[3], argv[4]);
  g_self = argv[0];
  return cmocka_run_group_tests(tests, setup, teardown);
}
