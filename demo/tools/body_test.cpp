// body_test.cpp - unit test of the generated skinned body (make test-demo):
// for each blob given, the mesh is well formed (indices, weights, normals
// outward), the bind pose skins to the rest mesh, and a walking frame
// skinned with the runtime's model matrices times the inverse bind matrices
// equals linear-blend skinning computed independently from the local pose
// (quaternion FK written here), and the feet meet the floor.
//
// usage: smg-demo-bodytest BLOB...
#include "../body.h"
#include "../body_graph.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "PASS" : "FAIL", what.c_str());
  if (!ok) ++failures;
}

// World joint rotations and positions from the runtime's local pose.
void local_fk(const BodySkeleton& sk, const float* root, const float* rot, std::vector<glm::quat>* R,
              std::vector<glm::vec3>* X) {
  size_t n = sk.parent.size();
  R->resize(n);
  X->resize(n);
  for (size_t j = 0; j < n; ++j) {
    glm::quat q(rot[j * 4 + 3], rot[j * 4 + 0], rot[j * 4 + 1], rot[j * 4 + 2]);  // stored x y z w
    int p = sk.parent[j];
    if (p < 0) {
      (*R)[j] = q;
      (*X)[j] = glm::vec3(root[0], root[1], root[2]);
    } else {
      (*R)[j] = (*R)[size_t(p)] * q;
      (*X)[j] = (*X)[size_t(p)] + (*R)[size_t(p)] * sk.rest_offset[j];
    }
  }
}

// Indices in range, at most 4 sorted weights summing to 1 on valid joints,
// unit normals, outward winding.
void well_formed(const std::string& name, const BodyMesh& mesh, size_t nj, size_t min_triangles) {
  const size_t nv = mesh.vertices.size();
  bool indices_ok = mesh.indices.size() % 3 == 0 && mesh.indices.size() >= 3 * min_triangles;
  for (uint32_t i : mesh.indices) indices_ok = indices_ok && i < nv;
  bool weights_ok = true;
  for (const BodyVertex& v : mesh.vertices) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      weights_ok = weights_ok && v.joints[k] < nj && v.weights[k] >= 0.0f;
      sum += v.weights[k];
      if (k > 0) weights_ok = weights_ok && v.weights[k] <= v.weights[k - 1];
    }
    weights_ok = weights_ok && std::fabs(sum - 1.0f) < 1e-5f && std::isfinite(v.position.x) &&
                 std::fabs(glm::length(v.normal) - 1.0f) < 1e-3f && v.material >= 0.0f && v.material <= 2.0f;
  }
  check(indices_ok, name + "at least " + std::to_string(min_triangles) + " triangles, indices in range");
  check(weights_ok, name + "weights: at most 4, sorted, sum 1, valid joints; unit normals; materials 0..2");
  // Outward: the enclosed volume is positive and triangle winding agrees
  // with the vertex normals.
  double volume = 0.0;
  size_t agree = 0;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const BodyVertex &a = mesh.vertices[mesh.indices[t]], &b = mesh.vertices[mesh.indices[t + 1]],
                     &c = mesh.vertices[mesh.indices[t + 2]];
    volume += double(glm::dot(a.position, glm::cross(b.position, c.position))) / 6.0;
    glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
    agree += glm::dot(n, a.normal + b.normal + c.normal) > 0.0f;
  }
  std::printf("  %zu vertices, volume %.4f m^3, %zu of %zu triangles wound with their normals\n", nv, volume, agree,
              mesh.indices.size() / 3);
  check(volume > 0.01 * double(mesh.height * mesh.height * mesh.height) && agree == mesh.indices.size() / 3,
        name + "normals outward (positive volume, every triangle wound with its normals)");
}

void test_blob(const char* path) {
  std::string name = std::string(path) + ": ";
  smg_graph* g = nullptr;
  if (smg_graph_load_file(path, nullptr, &g) != SMG_OK) {
    check(false, name + "load");
    return;
  }
  BodySkeleton sk;
  BodyMesh mesh;
  std::string err;
  auto t0 = std::chrono::steady_clock::now();
  bool ok = body_skeleton_from_graph(g, &sk, &err) && build_body(sk, kBodyCellsPerHeight, &mesh, &err);
  double build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  check(ok, name + "body built " + err);
  if (!ok) {
    smg_graph_destroy(g);
    return;
  }
  const size_t nj = sk.parent.size(), nv = mesh.vertices.size();
  std::printf("  %zu joints, %zu vertices, %zu triangles, rest height %.2f m, built in %.1f ms\n", nj, nv,
              mesh.indices.size() / 3, double(mesh.height), build_ms);

  well_formed(name + "detailed: ", mesh, nj, 1000);
  BodyMesh coarse;
  check(build_body(sk, kBodyCoarseCellsPerHeight, &coarse, &err), name + "coarse body built " + err);
  well_formed(name + "coarse: ", coarse, nj, 300);

  // --- generality: the same rig in centimetres under a floor-level root
  // bone (as many game rigs have) gets the same body, scaled, and the
  // root above the pelvis moves no vertex ---
  {
    std::vector<glm::vec3> P(nj);
    float floor_y = 1e9f;
    for (size_t j = 0; j < nj; ++j) {
      P[j] = (sk.parent[j] >= 0 ? P[size_t(sk.parent[j])] : glm::vec3(0)) + sk.rest_offset[j];
      floor_y = std::min(floor_y, P[j].y);
    }
    BodySkeleton big;
    big.parent.push_back(-1);
    big.rest_offset.push_back(glm::vec3(P[0].x, floor_y, P[0].z) * 100.0f);
    big.upper.push_back(0);
    for (size_t j = 0; j < nj; ++j) {
      big.parent.push_back(sk.parent[j] + 1);
      big.rest_offset.push_back((j == 0 ? glm::vec3(0.0f, P[0].y - floor_y, 0.0f) : sk.rest_offset[j]) * 100.0f);
      big.upper.push_back(sk.upper[j]);
    }
    BodyMesh m2;
    std::string e2;
    bool built = build_body(big, kBodyCellsPerHeight, &m2, &e2);
    size_t t1 = mesh.indices.size() / 3, t2 = m2.indices.size() / 3;
    bool root_free = true;
    for (const BodyVertex& v : m2.vertices)
      for (int k = 0; k < 4; ++k) root_free = root_free && !(v.joints[k] == 0 && v.weights[k] > 0.0f);
    std::printf("  in centimetres under a floor root: %zu triangles (%zu in metres), height %.1f\n", t2, t1,
                double(m2.height));
    check(built && root_free && t2 > t1 * 9 / 10 && t2 < t1 * 11 / 10 &&
              std::fabs(m2.height - 100.0f * mesh.height) < 0.01f * m2.height,
          name + "any scale and a floor-level root bone give the same body " + e2);
  }

  // --- bind pose: identity local rotations skin to the rest mesh ---
  std::vector<float> rest_model(nj * 16, 0.0f);
  {
    std::vector<float> root(3, 0.0f), rot(nj * 4, 0.0f);
    for (size_t j = 0; j < nj; ++j) rot[j * 4 + 3] = 1.0f;
    root[0] = sk.rest_offset[0].x;
    root[1] = sk.rest_offset[0].y;
    root[2] = sk.rest_offset[0].z;
    std::vector<glm::quat> R;
    std::vector<glm::vec3> X;
    local_fk(sk, root.data(), rot.data(), &R, &X);
    for (size_t j = 0; j < nj; ++j) {
      glm::mat4 m = glm::mat4_cast(R[j]);
      m[3] = glm::vec4(X[j], 1.0f);
      std::memcpy(&rest_model[j * 16], &m[0][0], 16 * sizeof(float));
    }
  }
  std::vector<glm::mat4> skin(nj);
  body_skin_matrices(mesh, rest_model.data(), skin.data());
  float bind_err = 0.0f;
  for (const BodyVertex& v : mesh.vertices) bind_err = std::max(bind_err, glm::length(body_skin_point(v, skin.data()) - v.position));
  std::printf("  bind pose: max |skinned - rest| = %.2g m\n", double(bind_err));
  check(bind_err < 1e-5f, name + "bind pose skins to the rest mesh");

  // --- a walking frame: runtime matrices x inverse bind vs independent LBS ---
  smg_character* ch = nullptr;
  smg_character_create(g, nullptr, &ch);
  const float xz[] = {0.0f, 0.0f, 0.0f, 12.0f};
  smg_character_set_path(ch, xz, 2);
  std::vector<float> model(nj * 16), root(3), rot(nj * 4);
  float lbs_err = 0.0f, lowest = 1e9f, lowest_joint = 1e9f;
  bool calls_ok = ch != nullptr;
  for (int f = 0; f < 150 && calls_ok; ++f) {
    calls_ok = smg_character_step(ch, 1.0f / 60.0f) == SMG_OK &&
               smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, model.data(), uint32_t(nj)) == SMG_OK &&
               smg_character_get_local_pose(ch, root.data(), rot.data(), uint32_t(nj)) == SMG_OK;
    if (!calls_ok || f % 10 != 9) continue;
    body_skin_matrices(mesh, model.data(), skin.data());
    std::vector<glm::quat> R;
    std::vector<glm::vec3> X;
    local_fk(sk, root.data(), rot.data(), &R, &X);
    std::vector<glm::vec3> P(nj);  // rest joint positions
    for (size_t j = 0; j < nj; ++j) P[j] = (sk.parent[j] >= 0 ? P[size_t(sk.parent[j])] : glm::vec3(0)) + sk.rest_offset[j];
    float frame_lowest = 1e9f;
    for (const BodyVertex& v : mesh.vertices) {
      glm::vec3 mine(0.0f);
      for (int k = 0; k < 4; ++k) mine += v.weights[k] * (R[v.joints[k]] * (v.position - P[v.joints[k]]) + X[v.joints[k]]);
      glm::vec3 gpu = body_skin_point(v, skin.data());
      lbs_err = std::max(lbs_err, glm::length(gpu - mine));
      frame_lowest = std::min(frame_lowest, gpu.y);
    }
    float joint_lowest = 1e9f;
    for (size_t j = 0; j < nj; ++j) joint_lowest = std::min(joint_lowest, X[j].y);
    lowest = std::min(lowest, frame_lowest);
    lowest_joint = std::min(lowest_joint, joint_lowest);
  }
  check(calls_ok, name + "runtime calls");
  std::printf("  walking: max |model x inverse bind - own LBS| = %.2g m; lowest vertex %.3f m, lowest joint %.3f m\n",
              double(lbs_err), double(lowest), double(lowest_joint));
  check(lbs_err < 1e-4f * mesh.height, name + "skinning matrices match FK-based linear blend skinning");
  // The soles: the lowest point of the body over the walk is at the floor
  // (y = 0), neither floating nor sunk by more than 2.5 cm.
  check(std::fabs(lowest) < 0.025f, name + "feet meet the floor");

  // --- a posed bind: rigs without an upright rest pose are built around a
  // character's first pose; here that path is forced on this rig. The
  // rest pose is chosen for it (upright), not for the same rig lying on
  // its side ---
  std::vector<float> first(nj * 16);
  smg_character* c2 = nullptr;
  bool first_ok = smg_character_create(g, nullptr, &c2) == SMG_OK &&
                  smg_character_get_model_matrices(c2, SMG_SPACE_CHARACTER, first.data(), uint32_t(nj)) == SMG_OK;
  if (c2) smg_character_destroy(c2);
  BodySkeleton lying = sk;
  for (glm::vec3& o : lying.rest_offset) o = glm::vec3(o.y, -o.x, o.z);  // 90 degrees about z
  check(first_ok && sk.pose.empty() && body_rest_is_upright(sk, first.data()) &&
            !body_rest_is_upright(lying, first.data()),
        name + "the upright rest pose is the bind pose; a rig lying on its side would take the first pose");
  BodySkeleton posed = sk;
  for (size_t j = 0; j < nj; ++j) {
    glm::mat4 m;
    std::memcpy(&m[0][0], &first[j * 16], 16 * sizeof(float));
    posed.pose.push_back(m);
  }
  BodyMesh pm;
  bool posed_ok = build_body(posed, kBodyCellsPerHeight, &pm, &err);
  check(posed_ok, name + "body built around the first pose " + err);
  if (posed_ok) {
    well_formed(name + "first-pose bind: ", pm, nj, 1000);
    std::vector<glm::mat4> pskin(nj);
    body_skin_matrices(pm, first.data(), pskin.data());
    float e0 = 0.0f;
    for (const BodyVertex& v : pm.vertices) e0 = std::max(e0, glm::length(body_skin_point(v, pskin.data()) - v.position));
    // A later frame of the walking character: runtime matrices x inverse
    // bind against LBS from the local pose and the bind pose's rotations.
    body_skin_matrices(pm, model.data(), pskin.data());
    std::vector<glm::quat> R;
    std::vector<glm::vec3> X;
    local_fk(sk, root.data(), rot.data(), &R, &X);
    float e1 = 0.0f;
    for (const BodyVertex& v : pm.vertices) {
      glm::vec3 mine(0.0f);
      for (int k = 0; k < 4; ++k) {
        const glm::mat4& b = posed.pose[v.joints[k]];
        glm::vec3 local = glm::transpose(glm::mat3(b)) * (v.position - glm::vec3(b[3]));
        mine += v.weights[k] * (R[v.joints[k]] * local + X[v.joints[k]]);
      }
      e1 = std::max(e1, glm::length(body_skin_point(v, pskin.data()) - mine));
    }
    std::printf("  first-pose bind: bind pose error %.2g m, walking frame vs own LBS %.2g m\n", double(e0), double(e1));
    check(e0 < 1e-5f * pm.height && e1 < 1e-4f * pm.height,
          name + "first-pose bind: skins to itself, and a walking frame matches FK-based LBS");
  }
  if (ch) smg_character_destroy(ch);
  smg_graph_destroy(g);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s BLOB...\n", argv[0]);
    return 2;
  }
  for (int i = 1; i < argc; ++i) test_blob(argv[i]);
  std::printf("body-test: %s\n", failures ? "FAILED" : "passed");
  return failures ? 1 : 0;
}
