// gltf_body.cpp - the demo's generated body (demo/body.h) laid out as the
// glTF writer's skeleton and mesh arrays (gltf_body.h).
#include "gltf_body.h"

#include "../../demo/body.h"
#include "../../demo/body_graph.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstdio>
#include <new>
#include <string>
#include <vector>

namespace {

// Clothing and skin colours of the vertex materials (linear RGB), in
// BodyMaterial order.
const float kColours[3][4] = {{0.20f, 0.27f, 0.50f, 1.0f}, {0.80f, 0.42f, 0.22f, 1.0f}, {0.93f, 0.80f, 0.62f, 1.0f}};

struct Storage {
  std::vector<int32_t> parent;
  std::vector<const char*> name;
  std::vector<float> translation, rotation, inverse_bind;
  std::vector<float> position, normal, weights, color;
  std::vector<uint16_t> joints;
  std::vector<uint32_t> index;
};

smg_result fill(smg_graph* graph, Storage* st, std::string* error) {
  BodySkeleton sk;
  BodyMesh mesh;
  if (!body_skeleton_from_graph(graph, &sk, error) || !build_body(sk, kBodyCellsPerHeight, &mesh, error))
    return SMG_ERROR_INVALID_ARGUMENT;
  const size_t nj = sk.parent.size();
  for (size_t j = 0; j < nj; ++j) {
    smg_joint_info ji{};
    ji.struct_size = sizeof ji;
    smg_result r = smg_graph_get_joint(graph, uint32_t(j), &ji);
    if (r != SMG_OK) {
      *error = "smg_graph_get_joint: " + std::string(smg_result_string(r));
      return r;
    }
    st->parent.push_back(sk.parent[j]);
    st->name.push_back(ji.name);
    glm::vec3 t = sk.rest_offset[j];
    // A body built around a posed bind gets that pose's local rotations, so
    // the file shows the body as built; a rest-pose body has identities.
    glm::quat q(1.0f, 0.0f, 0.0f, 0.0f);
    if (!sk.pose.empty()) {
      glm::mat3 world(sk.pose[j]);
      glm::mat3 parent = sk.parent[j] >= 0 ? glm::mat3(sk.pose[size_t(sk.parent[j])]) : glm::mat3(1.0f);
      q = glm::normalize(glm::quat_cast(glm::transpose(parent) * world));
      if (sk.parent[j] < 0) t = glm::vec3(sk.pose[j][3]);
    }
    st->translation.insert(st->translation.end(), {t.x, t.y, t.z});
    st->rotation.insert(st->rotation.end(), {q.x, q.y, q.z, q.w});
    const glm::mat4& m = mesh.inverse_bind[j];
    st->inverse_bind.insert(st->inverse_bind.end(), &m[0][0], &m[0][0] + 16);
  }
  for (const BodyVertex& v : mesh.vertices) {
    st->position.insert(st->position.end(), {v.position.x, v.position.y, v.position.z});
    st->normal.insert(st->normal.end(), {v.normal.x, v.normal.y, v.normal.z});
    int m = std::min(int(v.material), 1);  // blend between materials m and m + 1
    float f = std::min(std::max(v.material - float(m), 0.0f), 1.0f);
    for (int k = 0; k < 4; ++k) {
      st->joints.push_back(v.joints[k]);
      st->weights.push_back(v.weights[k]);
      st->color.push_back(kColours[m][k] + (kColours[m + 1][k] - kColours[m][k]) * f);
    }
  }
  st->index = mesh.indices;
  return SMG_OK;
}

}  // namespace

extern "C" smg_result gltf_body_from_graph(smg_graph* graph, gltf_body* out, char* error, size_t error_size) {
  if (error && error_size) error[0] = '\0';
  if (!graph || !out) return SMG_ERROR_INVALID_ARGUMENT;
  *out = gltf_body();
  Storage* st = new (std::nothrow) Storage();
  if (!st) return SMG_ERROR_OUT_OF_MEMORY;
  std::string message;
  smg_result r;
  try {
    r = fill(graph, st, &message);
  } catch (const std::bad_alloc&) {
    r = SMG_ERROR_OUT_OF_MEMORY;
    message = "out of memory building the body";
  }
  if (r != SMG_OK) {
    if (error && error_size) std::snprintf(error, error_size, "%s", message.c_str());
    delete st;
    return r;
  }
  out->storage = st;
  gltf_skeleton& s = out->skeleton;
  s.joint_count = uint32_t(st->parent.size());
  s.parent = st->parent.data();
  s.name = st->name.data();
  s.translation = st->translation.data();
  s.rotation = st->rotation.data();
  s.inverse_bind = st->inverse_bind.data();
  gltf_mesh& m = out->mesh;
  m.vertex_count = uint32_t(st->position.size() / 3);
  m.index_count = uint32_t(st->index.size());
  m.position = st->position.data();
  m.normal = st->normal.data();
  m.joints = st->joints.data();
  m.weights = st->weights.data();
  m.color = st->color.data();
  m.index = st->index.data();
  return SMG_OK;
}

extern "C" void gltf_body_free(gltf_body* body) {
  if (!body) return;
  delete static_cast<Storage*>(body->storage);
  *body = gltf_body();
}
