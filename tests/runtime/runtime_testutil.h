/*
 * runtime_testutil.h - helpers shared by the runtime tests: load the
 * fixture graph, the synthetic default blob and (when ../shared exists) a
 * CMU graph baked in-process; path builders; a counting allocator.
 */
#ifndef SMG_RUNTIME_TESTUTIL_H
#define SMG_RUNTIME_TESTUTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "fixture_graph.h"
#include "smg.h"
#include "test_env.h"

/* The fixture as a loaded graph; *blob must be freed with smgi_blob_free
 * after smg_graph_destroy. */
static inline smg_graph* rt_fixture(void** blob) {
  size_t size = 0;
  smg_graph* g = NULL;
  *blob = NULL;
  if (fixture_graph_blob(blob, &size) != SMG_OK) return NULL;
  if (smg_graph_load_memory(*blob, size, NULL, &g) != SMG_OK) {
    smgi_blob_free(*blob, NULL);
    *blob = NULL;
    return NULL;
  }
  return g;
}

static inline void rt_fixture_free(smg_graph* g, void* blob) {
  if (g) smg_graph_destroy(g);
  if (blob) smgi_blob_free(blob, NULL);
}

/* cmocka group state: the fixture graph loaded once for a test file. */
typedef struct rt_fixture_ctx {
  void* blob;
  smg_graph* g;
} rt_fixture_ctx;

static inline int rt_fixture_setup(void** state) {
  rt_fixture_ctx* c = (rt_fixture_ctx*)calloc(1, sizeof *c);
  if (!c) return -1;
  c->g = rt_fixture(&c->blob);
  if (!c->g) {
    free(c);
    return -1;
  }
  *state = c;
  return 0;
}

static inline int rt_fixture_teardown(void** state) {
  rt_fixture_ctx* c = (rt_fixture_ctx*)*state;
  rt_fixture_free(c->g, c->blob);
  free(c);
  return 0;
}

/* build/default.smg: `make` produces it. */
static inline smg_graph* rt_default_graph(void) {
  smg_graph* g = NULL;
  char path[1024];
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  smg_result r = smg_graph_load_file(path, NULL, &g);
  if (r != SMG_OK) {
    fprintf(stderr,
            "runtime tests: cannot load %s (%s); run `make` first, it bakes "
            "the synthetic default blob\n",
            path, smg_result_string(r));
    return NULL;
  }
  return g;
}

/* Straight line from (0,0) along +Z, n points over `length` metres. */
static inline void rt_line(float* xz, uint32_t n, float length) {
  for (uint32_t i = 0; i < n; ++i) {
    xz[2 * i] = 0.0f;
    xz[2 * i + 1] = length * (float)i / (float)(n - 1);
  }
}

/* Straight `a` metres along +Z, then a 90-degree turn of radius `r`
 * (0: a sharp corner) towards +X when `left` (the character's left when
 * facing +Z with Y up) or -X, then `b` metres straight. At most 61
 * points. */
static inline uint32_t rt_turn_r(float* xz, float a, float b, int left,
                                 float r) {
  uint32_t n = 0;
  float sg = left ? 1.0f : -1.0f;
  for (int i = 0; i <= 20; ++i) {
    xz[2 * n] = 0.0f;
    xz[2 * n + 1] = a * (float)i / 20.0f;
    ++n;
  }
  if (r > 0.0f) {
    for (int i = 1; i <= 20; ++i) {
      float t = 1.5707963f * (float)i / 20.0f;
      xz[2 * n] = sg * (r - r * cosf(t));
      xz[2 * n + 1] = a + r * sinf(t);
      ++n;
    }
  }
  for (int i = 1; i <= 20; ++i) {
    xz[2 * n] = sg * (r + b * (float)i / 20.0f);
    xz[2 * n + 1] = a + r;
    ++n;
  }
  return n;
}

static inline uint32_t rt_turn(float* xz, float a, float b, int left) {
  return rt_turn_r(xz, a, b, left, 0.0f);
}

/* Counting allocator. */
typedef struct rt_counter {
  long allocs, frees;
} rt_counter;

static inline void* rt_count_alloc(size_t size, size_t align, void* user) {
  rt_counter* c = (rt_counter*)user;
  void* p = NULL;
  c->allocs++;
  if (align < sizeof(void*)) align = sizeof(void*);
  if (posix_memalign(&p, align, size ? size : 1) != 0) return NULL;
  return p;
}

static inline void rt_count_free(void* p, void* user) {
  rt_counter* c = (rt_counter*)user;
  if (p) c->frees++;
  free(p);
}

static inline int rt_pose_finite(const float* root, const float* rot,
                                 uint32_t J) {
  for (int k = 0; k < 3; ++k)
    if (!isfinite(root[k])) return 0;
  for (uint32_t i = 0; i < 4 * J; ++i)
    if (!isfinite(rot[i])) return 0;
  return 1;
}

/* A zeroed character descriptor (defaults) standing on the path's first
 * point, facing its second. */
static inline void rt_desc_on_path(smg_character_desc* d, const float* xz) {
  memset(d, 0, sizeof *d);
  d->struct_size = sizeof *d;
  d->position[0] = xz[0];
  d->position[2] = xz[1];
  d->heading = atan2f(xz[2] - xz[0], xz[3] - xz[1]);
}

/* The graph's joint count, checked to fit a test's arrays of `cap`. */
static inline uint32_t rt_joint_count(const smg_graph* g, uint32_t cap) {
  smg_graph_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_true(info.joint_count <= cap);
  return info.joint_count;
}

/* The toes of a graph with CMU joint names (the fixture, the synthetic
 * default and the CMU graphs). */
static inline void rt_toes(const smg_graph* g, uint32_t toe[2]) {
  assert_int_equal(smg_graph_find_joint(g, "LeftToeBase", &toe[0]), SMG_OK);
  assert_int_equal(smg_graph_find_joint(g, "RightToeBase", &toe[1]), SMG_OK);
}

/* The graph's skeleton as parent indices and rest offsets (J joints), for
 * tests that rebuild world transforms from a reported local pose. */
static inline void rt_skeleton(const smg_graph* g, uint32_t J,
                               int32_t* parent, float (*offset)[3]) {
  for (uint32_t j = 0; j < J; ++j) {
    smg_joint_info ji;
    memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    assert_int_equal(smg_graph_get_joint(g, j, &ji), SMG_OK);
    parent[j] = ji.parent;
    memcpy(offset[j], ji.rest_offset, sizeof offset[j]);
  }
}

/* Reference forward kinematics, written out here (not rmath.h's) so the
 * runtime's own FK and IK cache can be checked against it: world
 * positions (3J) and rotations (4J) from a reported local pose. */
static inline void rt_q_mul(const float* a, const float* b, float* o) {
  o[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  o[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  o[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  o[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
}

static inline void rt_fk(uint32_t J, const int32_t* parent,
                         float (*offset)[3], const float* root,
                         const float* rot, float* wpos, float* wrot) {
  memcpy(wpos, root, sizeof(float) * 3u);
  memcpy(wrot, rot, sizeof(float) * 4u);
  for (uint32_t j = 1; j < J; ++j) {
    const uint32_t p = (uint32_t)parent[j];
    const float* q = wrot + 4u * p;
    /* offset rotated by the parent: q * (offset, 0) * conj(q) */
    const float v[4] = {offset[j][0], offset[j][1], offset[j][2], 0.0f};
    const float qc[4] = {-q[0], -q[1], -q[2], q[3]};
    float r[4], c[4];
    rt_q_mul(q, v, r);
    rt_q_mul(r, qc, c);
    for (int k = 0; k < 3; ++k) wpos[3u * j + k] = wpos[3u * p + k] + c[k];
    rt_q_mul(q, rot + 4u * j, wrot + 4u * j);
  }
}

#endif /* SMG_RUNTIME_TESTUTIL_H */
