// body_gltf.cpp - smg-body-gltf: writes the generated body (demo/body.h) of
// a blob's skeleton as a glTF 2.0 file (one self-contained .gltf, buffer
// embedded as base64): a node per joint with the joint's name and rest
// offset (and, for a body built around a posed bind, that pose's
// rotations), one skinned mesh (positions, normals, 4 joints and weights per
// vertex, vertex colours: lower body, upper body, skin) and its inverse
// bind matrices. Engines load it as a rigged character whose bones carry
// the graph's joint names, e.g. the Godot demo (bindings/godot/demo).
//
// usage: smg-body-gltf BLOB OUT.gltf
#include "../body.h"
#include "../body_graph.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Clothing and skin colours of the vertex materials (linear RGB).
const float kColours[3][4] = {{0.20f, 0.27f, 0.50f, 1.0f}, {0.80f, 0.42f, 0.22f, 1.0f}, {0.93f, 0.80f, 0.62f, 1.0f}};

std::string base64(const std::vector<unsigned char>& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    unsigned v = unsigned(in[i]) << 16;
    if (i + 1 < in.size()) v |= unsigned(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

std::string json_string(const char* s) {
  std::string out = "\"";
  for (; s && *s; ++s) {
    unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

std::string num(float f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", double(f));
  return buf;
}

// The binary buffer and its views/accessors, appended one array at a time.
struct Builder {
  std::vector<unsigned char> bin;
  std::string views, accessors;
  int count = 0;

  int add(const void* data, size_t bytes, int target, int component, size_t elements, const char* type,
          const std::string& extra = "") {
    while (bin.size() % 4) bin.push_back(0);
    size_t offset = bin.size();
    const unsigned char* p = static_cast<const unsigned char*>(data);
    bin.insert(bin.end(), p, p + bytes);
    if (count) {
      views += ",";
      accessors += ",";
    }
    views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) + ",\"byteLength\":" + std::to_string(bytes) +
             (target ? ",\"target\":" + std::to_string(target) : "") + "}";
    accessors += "{\"bufferView\":" + std::to_string(count) + ",\"componentType\":" + std::to_string(component) +
                 ",\"count\":" + std::to_string(elements) + ",\"type\":\"" + type + "\"" + extra + "}";
    return count++;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: smg-body-gltf BLOB OUT.gltf\n");
    return 2;
  }
  smg_graph* g = nullptr;
  smg_result r = smg_graph_load_file(argv[1], nullptr, &g);
  if (r != SMG_OK) {
    std::fprintf(stderr, "smg-body-gltf: cannot load '%s': %s\n", argv[1], smg_result_string(r));
    return 1;
  }
  BodySkeleton sk;
  BodyMesh mesh;
  std::string error;
  if (!body_skeleton_from_graph(g, &sk, &error) || !build_body(sk, kBodyCellsPerHeight, &mesh, &error)) {
    std::fprintf(stderr, "smg-body-gltf: %s: %s\n", argv[1], error.c_str());
    smg_graph_destroy(g);
    return 1;
  }
  const size_t nj = sk.parent.size(), nv = mesh.vertices.size();
  std::vector<float> pos, nrm, wts, col, ibm;
  std::vector<uint16_t> jnt;
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const BodyVertex& v : mesh.vertices) {
    pos.insert(pos.end(), {v.position.x, v.position.y, v.position.z});
    nrm.insert(nrm.end(), {v.normal.x, v.normal.y, v.normal.z});
    for (int k = 0; k < 4; ++k) {
      jnt.push_back(v.joints[k]);
      wts.push_back(v.weights[k]);
      int m = std::min(int(v.material), 1);  // blend between materials m and m + 1
      float f = std::min(std::max(v.material - float(m), 0.0f), 1.0f);
      col.push_back(kColours[m][k] + (kColours[m + 1][k] - kColours[m][k]) * f);
    }
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  for (const glm::mat4& m : mesh.inverse_bind) ibm.insert(ibm.end(), &m[0][0], &m[0][0] + 16);
  Builder b;
  std::string minmax = ",\"min\":[" + num(lo.x) + "," + num(lo.y) + "," + num(lo.z) + "],\"max\":[" + num(hi.x) +
                       "," + num(hi.y) + "," + num(hi.z) + "]";
  int a_pos = b.add(pos.data(), pos.size() * 4, 34962, 5126, nv, "VEC3", minmax);
  int a_nrm = b.add(nrm.data(), nrm.size() * 4, 34962, 5126, nv, "VEC3");
  int a_jnt = b.add(jnt.data(), jnt.size() * 2, 34962, 5123, nv, "VEC4");
  int a_wts = b.add(wts.data(), wts.size() * 4, 34962, 5126, nv, "VEC4");
  int a_col = b.add(col.data(), col.size() * 4, 34962, 5126, nv, "VEC4");
  int a_idx = b.add(mesh.indices.data(), mesh.indices.size() * 4, 34963, 5125, mesh.indices.size(), "SCALAR");
  int a_ibm = b.add(ibm.data(), ibm.size() * 4, 0, 5126, nj, "MAT4");

  // Nodes: 0 the character, 1 the mesh, 2 + j joint j.
  std::string nodes, roots, joints;
  for (size_t j = 0; j < nj; ++j) {
    smg_joint_info ji;
    std::memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    smg_graph_get_joint(g, uint32_t(j), &ji);
    std::string children;
    for (size_t c = j + 1; c < nj; ++c)
      if (sk.parent[c] == int(j)) children += (children.empty() ? "" : ",") + std::to_string(2 + c);
    glm::vec3 t = sk.rest_offset[j];
    // A body built around a posed bind gets that pose's local rotations, so
    // the file shows the body as built; a rest-pose body has none.
    std::string rotation;
    if (!sk.pose.empty()) {
      glm::mat3 world(sk.pose[j]);
      glm::mat3 parent = sk.parent[j] >= 0 ? glm::mat3(sk.pose[size_t(sk.parent[j])]) : glm::mat3(1.0f);
      glm::quat q = glm::normalize(glm::quat_cast(glm::transpose(parent) * world));
      rotation = ",\"rotation\":[" + num(q.x) + "," + num(q.y) + "," + num(q.z) + "," + num(q.w) + "]";
      if (sk.parent[j] < 0) t = glm::vec3(sk.pose[j][3]);
    }
    nodes += ",{\"name\":" + json_string(ji.name) + ",\"translation\":[" + num(t.x) + "," + num(t.y) + "," +
             num(t.z) + "]" + rotation + (children.empty() ? "" : ",\"children\":[" + children + "]") + "}";
    if (sk.parent[j] < 0) roots += "," + std::to_string(2 + j);
    joints += (j ? "," : "") + std::to_string(2 + j);
  }
  std::string json =
      "{\"asset\":{\"version\":\"2.0\",\"generator\":\"libsmg smg-body-gltf (generated body, not a scanned or "
      "modelled character)\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"name\":\"Body\",\"children\":[1" +
      roots + "]},{\"name\":\"BodyMesh\",\"mesh\":0,\"skin\":0}" + nodes + "],\"meshes\":[{\"name\":\"body\"," +
      "\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(a_pos) + ",\"NORMAL\":" +
      std::to_string(a_nrm) + ",\"JOINTS_0\":" + std::to_string(a_jnt) + ",\"WEIGHTS_0\":" + std::to_string(a_wts) +
      ",\"COLOR_0\":" + std::to_string(a_col) + "},\"indices\":" + std::to_string(a_idx) +
      ",\"material\":0}]}],\"materials\":[{\"name\":\"body\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1],"
      "\"metallicFactor\":0,\"roughnessFactor\":0.8}}],\"skins\":[{\"joints\":[" + joints +
      "],\"inverseBindMatrices\":" + std::to_string(a_ibm) + "}],\"accessors\":[" + b.accessors +
      "],\"bufferViews\":[" + b.views + "],\"buffers\":[{\"byteLength\":" + std::to_string(b.bin.size()) +
      ",\"uri\":\"data:application/octet-stream;base64," + base64(b.bin) + "\"}]}\n";
  smg_graph_destroy(g);
  std::string tmp = std::string(argv[2]) + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  bool ok = f && std::fwrite(json.data(), 1, json.size(), f) == json.size();
  if (f) ok = std::fclose(f) == 0 && ok;
  if (!ok || std::rename(tmp.c_str(), argv[2]) != 0) {
    std::fprintf(stderr, "smg-body-gltf: cannot write '%s'\n", argv[2]);
    std::remove(tmp.c_str());
    return 1;
  }
  std::printf("smg-body-gltf: wrote %s (%zu joints, %zu vertices, %zu triangles)\n", argv[2], nj, nv,
              mesh.indices.size() / 3);
  return 0;
}
