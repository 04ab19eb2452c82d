/*
 * gltf_write.c - checks a character scene (gltf_write.h) and assembles its
 * glTF document: node 0 holds the character, then the mesh node (when
 * there is a mesh), then one node per joint in joint order; one skin over
 * all joints; one animation whose samplers share one time accessor.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_bytes.h"

/* How far from unit length a quaternion may be (float rounding of a
 * normalised quaternion stays far below this; more is a wrong input). */
#define UNIT_TOLERANCE 1e-2f

#define FLOAT_COMPONENT 5126
#define USHORT_COMPONENT 5123
#define UINT_COMPONENT 5125
#define ARRAY_BUFFER 34962
#define ELEMENT_ARRAY_BUFFER 34963

typedef struct doc {
  gltf_bytes json, bin, views, accessors;
  uint32_t count; /* accessors (one view each) */
} doc;

static smg_result bad(char* error, size_t error_size, const char* fmt, ...)
    SMG_PRINTF_CHECK(3, 4)
    ;
static smg_result bad(char* error, size_t error_size, const char* fmt, ...) {
  va_list ap;
  if (error && error_size) {
    va_start(ap, fmt);
    vsnprintf(error, error_size, fmt, ap);
    va_end(ap);
  }
  return SMG_ERROR_INVALID_ARGUMENT;
}

static int finite_all(const float* v, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

static int unit_quat(const float* q) {
  float n2;
  if (!finite_all(q, 4)) return 0;
  n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  return fabsf(sqrtf(n2) - 1.0f) < UNIT_TOLERANCE;
}

static smg_result check_skeleton(const gltf_skeleton* s, char* error,
                                 size_t error_size) {
  uint32_t j;
  if (!s->joint_count || !s->parent || !s->name || !s->translation)
    return bad(error, error_size, "skeleton: no joints");
  for (j = 0; j < s->joint_count; ++j) {
    if (s->parent[j] < -1 || s->parent[j] >= (int32_t)j)
      return bad(error, error_size,
                 "skeleton: joint %u: parent %d is not an earlier joint", j,
                 s->parent[j]);
    if (!s->name[j] || !s->name[j][0])
      return bad(error, error_size, "skeleton: joint %u has no name", j);
    if (!finite_all(s->translation + 3 * (size_t)j, 3))
      return bad(error, error_size,
                 "skeleton: joint %u: translation not finite", j);
    if (s->rotation && !unit_quat(s->rotation + 4 * (size_t)j))
      return bad(error, error_size,
                 "skeleton: joint %u: rotation is not a unit quaternion", j);
    if (s->inverse_bind && !finite_all(s->inverse_bind + 16 * (size_t)j, 16))
      return bad(error, error_size,
                 "skeleton: joint %u: inverse bind matrix not finite", j);
  }
  return SMG_OK;
}

static smg_result check_mesh(const gltf_mesh* m, uint32_t joints, char* error,
                             size_t error_size) {
  uint32_t v, k;
  if (!m->vertex_count || !m->index_count || m->index_count % 3 ||
      !m->position || !m->normal || !m->joints || !m->weights || !m->index)
    return bad(error, error_size,
               "mesh: needs vertices, normals, joints, weights and "
               "triangles (%u indices)",
               m->index_count);
  for (v = 0; v < m->vertex_count; ++v) {
    float sum = 0.0f;
    if (!finite_all(m->position + 3 * (size_t)v, 3) ||
        !finite_all(m->normal + 3 * (size_t)v, 3) ||
        (m->color && !finite_all(m->color + 4 * (size_t)v, 4)))
      return bad(error, error_size, "mesh: vertex %u: value not finite", v);
    for (k = 0; k < 4; ++k) {
      float w = m->weights[4 * (size_t)v + k];
      if (m->joints[4 * (size_t)v + k] >= joints)
        return bad(error, error_size,
                   "mesh: vertex %u: joint %u out of range (%u joints)", v,
                   m->joints[4 * (size_t)v + k], joints);
      if (!(w >= 0.0f && w <= 1.0f))
        return bad(error, error_size, "mesh: vertex %u: weight %g", v,
                   (double)w);
      sum += w;
    }
    if (fabsf(sum - 1.0f) > UNIT_TOLERANCE)
      return bad(error, error_size, "mesh: vertex %u: weights sum to %g", v,
                 (double)sum);
  }
  for (k = 0; k < m->index_count; ++k)
    if (m->index[k] >= m->vertex_count)
      return bad(error, error_size,
                 "mesh: index %u: vertex %u out of range (%u vertices)", k,
                 m->index[k], m->vertex_count);
  return SMG_OK;
}

static smg_result check_animation(const gltf_animation* a, uint32_t joints,
                                  char* error, size_t error_size) {
  uint32_t f, j;
  if (!a->frame_count || !a->frames || !(a->fps > 0.0f) ||
      !isfinite(a->fps) || a->stride < 3 + 4 * (size_t)joints)
    return bad(error, error_size,
               "animation: %u frames at %g fps, %zu floats per frame "
               "(need >= 1 frame, fps > 0, >= %zu floats)",
               a->frame_count, (double)a->fps, a->stride,
               3 + 4 * (size_t)joints);
  for (f = 0; f < a->frame_count; ++f) {
    const float* fr = a->frames + a->stride * f;
    if (!finite_all(fr, 3))
      return bad(error, error_size,
                 "animation: frame %u: root translation not finite", f);
    for (j = 0; j < joints; ++j)
      if (!unit_quat(fr + 3 + 4 * (size_t)j))
        return bad(error, error_size,
                   "animation: frame %u, joint %u: rotation is not a unit "
                   "quaternion",
                   f, j);
  }
  return SMG_OK;
}

/* One accessor over its own buffer view. `extra` is added JSON (min/max). */
static uint32_t add_accessor(doc* d, const void* data, size_t bytes,
                             int target, int component, size_t count,
                             const char* type, const char* extra) {
  size_t offset;
  gltf_bytes_pad(&d->bin, 4, 0);
  offset = d->bin.size;
  gltf_bytes_append(&d->bin, data, bytes);
  gltf_bytes_printf(&d->views,
                    "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu",
                    d->count ? "," : "", offset, bytes);
  if (target) gltf_bytes_printf(&d->views, ",\"target\":%d", target);
  gltf_bytes_printf(&d->views, "}");
  gltf_bytes_printf(&d->accessors,
                    "%s{\"bufferView\":%u,\"componentType\":%d,\"count\":%zu,"
                    "\"type\":\"%s\"%s}",
                    d->count ? "," : "", d->count, component, count, type,
                    extra ? extra : "");
  return d->count++;
}

/* Accessor over `n` floats read with a stride (gathered into the buffer). */
static uint32_t add_gathered(doc* d, const float* src, size_t stride,
                             size_t count, size_t width, const char* type,
                             int quaternion) {
  size_t i, k;
  float prev[4] = {0, 0, 0, 1};
  size_t offset;
  gltf_bytes_pad(&d->bin, 4, 0);
  offset = d->bin.size;
  for (i = 0; i < count; ++i) {
    float v[4];
    memcpy(v, src + stride * i, width * sizeof(float));
    if (quaternion) {
      /* unit length, and the sign nearest the previous key, so LINEAR
       * interpolation between keys takes the short way round */
      float n = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
      float s = (v[0] * prev[0] + v[1] * prev[1] + v[2] * prev[2] +
                 v[3] * prev[3]) < 0.0f
                    ? -1.0f / n
                    : 1.0f / n;
      for (k = 0; k < 4; ++k) v[k] *= s;
      memcpy(prev, v, sizeof prev);
    }
    gltf_bytes_append(&d->bin, v, width * sizeof(float));
  }
  /* the bytes are in place: describe them like add_accessor does */
  gltf_bytes_printf(&d->views,
                    "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
                    d->count ? "," : "", offset, d->bin.size - offset);
  gltf_bytes_printf(&d->accessors,
                    "%s{\"bufferView\":%u,\"componentType\":%d,\"count\":%zu,"
                    "\"type\":\"%s\"}",
                    d->count ? "," : "", d->count, FLOAT_COMPONENT, count,
                    type);
  return d->count++;
}

/* q = a * b (Hamilton), and v rotated by q. */
static void quat_mul(const float* a, const float* b, float* q) {
  float r[4];
  r[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  r[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
  r[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
  r[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  memcpy(q, r, sizeof r);
}

static void quat_rotate(const float* q, const float* v, float* out) {
  float p[4] = {v[0], v[1], v[2], 0.0f}, c[4] = {-q[0], -q[1], -q[2], q[3]};
  float t[4];
  quat_mul(q, p, t);
  quat_mul(t, c, t);
  out[0] = t[0];
  out[1] = t[1];
  out[2] = t[2];
}

/* Inverse bind matrices of the skeleton's bind pose (rigid: the inverse is
 * the transposed rotation and the rotated, negated translation). */
static int inverse_binds(const gltf_skeleton* s, float* out) {
  uint32_t j;
  float(*wq)[4] = (float(*)[4])malloc(sizeof(float) * 7 * s->joint_count);
  float(*wt)[3];
  if (!wq) return 0;
  wt = (float(*)[3])(wq + s->joint_count);
  for (j = 0; j < s->joint_count; ++j) {
    static const float identity[4] = {0, 0, 0, 1};
    const float* lq = s->rotation ? s->rotation + 4 * (size_t)j : identity;
    const float* lt = s->translation + 3 * (size_t)j;
    float n = sqrtf(lq[0] * lq[0] + lq[1] * lq[1] + lq[2] * lq[2] +
                    lq[3] * lq[3]);
    float q[4] = {lq[0] / n, lq[1] / n, lq[2] / n, lq[3] / n}, inv[4], t[3];
    float* m = out + 16 * (size_t)j;
    int32_t p = s->parent[j];
    if (p >= 0) {
      quat_rotate(wq[p], lt, t);
      wt[j][0] = wt[p][0] + t[0];
      wt[j][1] = wt[p][1] + t[1];
      wt[j][2] = wt[p][2] + t[2];
      quat_mul(wq[p], q, wq[j]);
    } else {
      memcpy(wt[j], lt, sizeof wt[j]);
      memcpy(wq[j], q, sizeof wq[j]);
    }
    inv[0] = -wq[j][0];
    inv[1] = -wq[j][1];
    inv[2] = -wq[j][2];
    inv[3] = wq[j][3];
    {
      float x = inv[0], y = inv[1], z = inv[2], w = inv[3];
      /* column-major rotation of inv */
      m[0] = 1 - 2 * (y * y + z * z);
      m[1] = 2 * (x * y + z * w);
      m[2] = 2 * (x * z - y * w);
      m[4] = 2 * (x * y - z * w);
      m[5] = 1 - 2 * (x * x + z * z);
      m[6] = 2 * (y * z + x * w);
      m[8] = 2 * (x * z + y * w);
      m[9] = 2 * (y * z - x * w);
      m[10] = 1 - 2 * (x * x + y * y);
      m[3] = m[7] = m[11] = 0.0f;
      m[15] = 1.0f;
    }
    quat_rotate(inv, wt[j], t);
    m[12] = -t[0];
    m[13] = -t[1];
    m[14] = -t[2];
  }
  free(wq);
  return 1;
}

static void minmax3(const float* v, uint32_t n, char* out, size_t size) {
  float lo[3] = {v[0], v[1], v[2]}, hi[3] = {v[0], v[1], v[2]};
  uint32_t i, k;
  for (i = 1; i < n; ++i)
    for (k = 0; k < 3; ++k) {
      if (v[3 * (size_t)i + k] < lo[k]) lo[k] = v[3 * (size_t)i + k];
      if (v[3 * (size_t)i + k] > hi[k]) hi[k] = v[3 * (size_t)i + k];
    }
  snprintf(out, size, ",\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]",
           (double)lo[0], (double)lo[1], (double)lo[2], (double)hi[0],
           (double)hi[1], (double)hi[2]);
}

static void write_nodes(doc* d, const gltf_scene* sc, uint32_t first_joint) {
  const gltf_skeleton* s = sc->skeleton;
  uint32_t j, c;
  int any = 0;
  gltf_bytes_printf(&d->json, "\"nodes\":[{\"name\":");
  gltf_bytes_json_string(&d->json, sc->root_name);
  gltf_bytes_printf(&d->json, ",\"children\":[");
  if (sc->mesh) {
    gltf_bytes_printf(&d->json, "1");
    any = 1;
  }
  for (j = 0; j < s->joint_count; ++j)
    if (s->parent[j] < 0) {
      gltf_bytes_printf(&d->json, "%s%u", any ? "," : "", first_joint + j);
      any = 1;
    }
  gltf_bytes_printf(&d->json, "]}");
  if (sc->mesh) {
    gltf_bytes_printf(&d->json, ",{\"name\":");
    gltf_bytes_json_string(&d->json, sc->mesh_name);
    gltf_bytes_printf(&d->json, ",\"mesh\":0,\"skin\":0}");
  }
  for (j = 0; j < s->joint_count; ++j) {
    const float* t = s->translation + 3 * (size_t)j;
    gltf_bytes_printf(&d->json, ",{\"name\":");
    gltf_bytes_json_string(&d->json, s->name[j]);
    gltf_bytes_printf(&d->json, ",\"translation\":[%.9g,%.9g,%.9g]",
                      (double)t[0], (double)t[1], (double)t[2]);
    if (s->rotation) {
      const float* q = s->rotation + 4 * (size_t)j;
      float n = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      gltf_bytes_printf(&d->json, ",\"rotation\":[%.9g,%.9g,%.9g,%.9g]",
                        (double)(q[0] / n), (double)(q[1] / n),
                        (double)(q[2] / n), (double)(q[3] / n));
    }
    any = 0;
    for (c = j + 1; c < s->joint_count; ++c)
      if (s->parent[c] == (int32_t)j) {
        gltf_bytes_printf(&d->json, "%s%u", any ? "," : ",\"children\":[",
                          first_joint + c);
        any = 1;
      }
    gltf_bytes_printf(&d->json, "%s}", any ? "]" : "");
  }
  gltf_bytes_printf(&d->json, "]");
}

static void write_mesh(doc* d, const gltf_mesh* m) {
  char mm[256];
  uint32_t a_pos, a_nrm, a_jnt, a_wts, a_col = 0, a_idx;
  size_t nv = m->vertex_count;
  minmax3(m->position, m->vertex_count, mm, sizeof mm);
  a_pos = add_accessor(d, m->position, nv * 12, ARRAY_BUFFER, FLOAT_COMPONENT,
                       nv, "VEC3", mm);
  a_nrm = add_accessor(d, m->normal, nv * 12, ARRAY_BUFFER, FLOAT_COMPONENT,
                       nv, "VEC3", NULL);
  a_jnt = add_accessor(d, m->joints, nv * 8, ARRAY_BUFFER, USHORT_COMPONENT,
                       nv, "VEC4", NULL);
  a_wts = add_accessor(d, m->weights, nv * 16, ARRAY_BUFFER, FLOAT_COMPONENT,
                       nv, "VEC4", NULL);
  if (m->color)
    a_col = add_accessor(d, m->color, nv * 16, ARRAY_BUFFER, FLOAT_COMPONENT,
                         nv, "VEC4", NULL);
  a_idx = add_accessor(d, m->index, (size_t)m->index_count * 4,
                       ELEMENT_ARRAY_BUFFER, UINT_COMPONENT, m->index_count,
                       "SCALAR", NULL);
  gltf_bytes_printf(&d->json,
                    ",\"meshes\":[{\"name\":\"body\",\"primitives\":[{"
                    "\"attributes\":{\"POSITION\":%u,\"NORMAL\":%u,"
                    "\"JOINTS_0\":%u,\"WEIGHTS_0\":%u",
                    a_pos, a_nrm, a_jnt, a_wts);
  if (m->color) gltf_bytes_printf(&d->json, ",\"COLOR_0\":%u", a_col);
  gltf_bytes_printf(&d->json,
                    "},\"indices\":%u,\"material\":0}]}],\"materials\":[{"
                    "\"name\":\"body\",\"pbrMetallicRoughness\":{"
                    "\"baseColorFactor\":[1,1,1,1],\"metallicFactor\":0,"
                    "\"roughnessFactor\":0.8}}]",
                    a_idx);
}

static void write_animation(doc* d, const gltf_animation* a, uint32_t joints,
                            const int32_t* parent, uint32_t first_joint) {
  char mm[96];
  uint32_t f, j, a_time, sampler = 0;
  float* times;
  gltf_bytes samplers = {NULL, 0, 0, 0}, channels = {NULL, 0, 0, 0};
  times = (float*)malloc(sizeof(float) * a->frame_count);
  if (!times) {
    d->json.failed = 1;
    return;
  }
  for (f = 0; f < a->frame_count; ++f) times[f] = (float)((double)f / a->fps);
  snprintf(mm, sizeof mm, ",\"min\":[%.9g],\"max\":[%.9g]", (double)times[0],
           (double)times[a->frame_count - 1]);
  a_time = add_accessor(d, times, sizeof(float) * a->frame_count, 0,
                        FLOAT_COMPONENT, a->frame_count, "SCALAR", mm);
  free(times);
  for (j = 0; j < joints; ++j) {
    /* the frames carry the root joint's translation; other roots keep
     * their bind translation */
    int translated = j == 0 && parent[0] < 0;
    uint32_t a_rot = add_gathered(d, a->frames + 3 + 4 * (size_t)j, a->stride,
                                  a->frame_count, 4, "VEC4", 1);
    gltf_bytes_printf(&samplers,
                      "%s{\"input\":%u,\"output\":%u,\"interpolation\":"
                      "\"LINEAR\"}",
                      sampler ? "," : "", a_time, a_rot);
    gltf_bytes_printf(&channels,
                      "%s{\"sampler\":%u,\"target\":{\"node\":%u,\"path\":"
                      "\"rotation\"}}",
                      sampler ? "," : "", sampler, first_joint + j);
    ++sampler;
    if (translated) {
      uint32_t a_tr = add_gathered(d, a->frames, a->stride, a->frame_count, 3,
                                   "VEC3", 0);
      gltf_bytes_printf(&samplers,
                        ",{\"input\":%u,\"output\":%u,\"interpolation\":"
                        "\"LINEAR\"}",
                        a_time, a_tr);
      gltf_bytes_printf(&channels,
                        ",{\"sampler\":%u,\"target\":{\"node\":%u,\"path\":"
                        "\"translation\"}}",
                        sampler, first_joint + j);
      ++sampler;
    }
  }
  gltf_bytes_printf(&d->json, ",\"animations\":[{\"name\":\"take\",");
  gltf_bytes_printf(&d->json, "\"samplers\":[");
  gltf_bytes_append(&d->json, samplers.data, samplers.size);
  gltf_bytes_printf(&d->json, "],\"channels\":[");
  gltf_bytes_append(&d->json, channels.data, channels.size);
  gltf_bytes_printf(&d->json, "]}]");
  if (samplers.failed || channels.failed) d->json.failed = 1;
  gltf_bytes_free(&samplers);
  gltf_bytes_free(&channels);
}

/* One root joint (joint 0): the skin names it as the skeleton's root. */
static int single_root(const gltf_skeleton* s) {
  uint32_t j;
  for (j = 1; j < s->joint_count; ++j)
    if (s->parent[j] < 0) return 0;
  return s->parent[0] < 0;
}

smg_result gltf_write_file(const char* path, const gltf_scene* sc,
                           uint32_t format, char* error, size_t error_size) {
  doc d;
  smg_result r;
  uint32_t j, first_joint, ibm_accessor;
  float* ibm = NULL;
  const gltf_skeleton* s;
  if (error && error_size) error[0] = '\0';
  if (!path || !path[0] || !sc || !sc->skeleton || !sc->generator ||
      !sc->root_name || (sc->mesh && !sc->mesh_name) ||
      (format != GLTF_TEXT && format != GLTF_BINARY))
    return bad(error, error_size, "gltf: no path, scene or skeleton");
  s = sc->skeleton;
  if ((r = check_skeleton(s, error, error_size)) != SMG_OK ||
      (sc->mesh && (r = check_mesh(sc->mesh, s->joint_count, error,
                                   error_size)) != SMG_OK) ||
      (sc->animation && (r = check_animation(sc->animation, s->joint_count,
                                             error, error_size)) != SMG_OK))
    return r;
  memset(&d, 0, sizeof d);
  first_joint = sc->mesh ? 2u : 1u;
  gltf_bytes_printf(&d.json, "{\"asset\":{\"version\":\"2.0\",\"generator\":");
  gltf_bytes_json_string(&d.json, sc->generator);
  gltf_bytes_printf(&d.json, "},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],");
  write_nodes(&d, sc, first_joint);
  if (sc->mesh) write_mesh(&d, sc->mesh);
  if (!s->inverse_bind) {
    ibm = (float*)malloc(sizeof(float) * 16 * s->joint_count);
    if (!ibm || !inverse_binds(s, ibm)) d.json.failed = 1;
  }
  if (!d.json.failed) {
    ibm_accessor = add_accessor(
        &d, s->inverse_bind ? s->inverse_bind : ibm,
        sizeof(float) * 16 * s->joint_count, 0, FLOAT_COMPONENT,
        s->joint_count, "MAT4", NULL);
    gltf_bytes_printf(&d.json, ",\"skins\":[{\"name\":\"skeleton\",");
    if (single_root(s))
      gltf_bytes_printf(&d.json, "\"skeleton\":%u,", first_joint);
    gltf_bytes_printf(&d.json, "\"joints\":[");
    for (j = 0; j < s->joint_count; ++j)
      gltf_bytes_printf(&d.json, "%s%u", j ? "," : "", first_joint + j);
    gltf_bytes_printf(&d.json, "],\"inverseBindMatrices\":%u}]",
                      ibm_accessor);
  }
  free(ibm);
  if (sc->animation)
    write_animation(&d, sc->animation, s->joint_count, s->parent, first_joint);
  gltf_bytes_printf(&d.json, ",\"accessors\":[");
  gltf_bytes_append(&d.json, d.accessors.data, d.accessors.size);
  gltf_bytes_printf(&d.json, "],\"bufferViews\":[");
  gltf_bytes_append(&d.json, d.views.data, d.views.size);
  gltf_bytes_printf(&d.json, "]");
  if (d.views.failed || d.accessors.failed) d.json.failed = 1;
  r = gltf_file_write(path, &d.json, &d.bin, format, error, error_size);
  gltf_bytes_free(&d.json);
  gltf_bytes_free(&d.bin);
  gltf_bytes_free(&d.views);
  gltf_bytes_free(&d.accessors);
  return r;
}

smg_result gltf_skeleton_from_graph(const smg_graph* graph,
                                    uint32_t joint_count, int32_t* parent,
                                    const char** name, float* translation,
                                    gltf_skeleton* out) {
  smg_graph_info info;
  uint32_t j;
  smg_result r;
  if (!graph || !parent || !name || !translation || !out)
    return SMG_ERROR_INVALID_ARGUMENT;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if ((r = smg_graph_get_info(graph, &info)) != SMG_OK) return r;
  if (info.joint_count != joint_count) return SMG_ERROR_BUFFER_TOO_SMALL;
  for (j = 0; j < joint_count; ++j) {
    smg_joint_info ji;
    memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    if ((r = smg_graph_get_joint(graph, j, &ji)) != SMG_OK) return r;
    parent[j] = ji.parent;
    name[j] = ji.name;
    /* the root's place is the animation's; its bind sits at the origin */
    translation[3 * j] = ji.parent < 0 ? 0.0f : ji.rest_offset[0];
    translation[3 * j + 1] = ji.parent < 0 ? 0.0f : ji.rest_offset[1];
    translation[3 * j + 2] = ji.parent < 0 ? 0.0f : ji.rest_offset[2];
  }
  memset(out, 0, sizeof *out);
  out->joint_count = joint_count;
  out->parent = parent;
  out->name = name;
  out->translation = translation;
  return SMG_OK;
}
