// body_graph.cpp - reads a graph's skeleton for the generated body.
#include "body_graph.h"

#include <cmath>
#include <cstring>
#include <vector>

// The rest pose stands like the motion when it is about as tall as the
// character's first pose and its joints' heights rise and fall with that
// pose's (a T-pose's arms differ, its legs and spine agree).
bool body_rest_is_upright(const BodySkeleton& sk, const float* first) {
  const size_t n = sk.parent.size();
  std::vector<double> a(n), b(n);
  glm::vec3 p0(0.0f);
  std::vector<glm::vec3> P(n);
  for (size_t j = 0; j < n; ++j) {
    P[j] = (sk.parent[j] >= 0 ? P[size_t(sk.parent[j])] : p0) + sk.rest_offset[j];
    a[j] = double(P[j].y - P[0].y);
    b[j] = double(first[j * 16 + 13] - first[13]);
  }
  double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  for (size_t j = 0; j < n; ++j) {
    amin = std::fmin(amin, a[j]);
    amax = std::fmax(amax, a[j]);
    bmin = std::fmin(bmin, b[j]);
    bmax = std::fmax(bmax, b[j]);
    sa += a[j];
    sb += b[j];
    saa += a[j] * a[j];
    sbb += b[j] * b[j];
    sab += a[j] * b[j];
  }
  double N = double(n), va = N * saa - sa * sa, vb = N * sbb - sb * sb;
  if (!(va > 0.0) || !(vb > 0.0)) return false;
  double correlation = (N * sab - sa * sb) / std::sqrt(va * vb);
  return amax - amin >= 0.8 * (bmax - bmin) && correlation > 0.5;
}

bool body_skeleton_from_graph(smg_graph* graph, BodySkeleton* out, std::string* error) {
  *out = BodySkeleton();
  smg_graph_info info;
  std::memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  smg_result r = smg_graph_get_info(graph, &info);
  if (r != SMG_OK) {
    *error = std::string("smg_graph_get_info: ") + smg_result_string(r);
    return false;
  }
  for (uint32_t j = 0; j < info.joint_count; ++j) {
    smg_joint_info ji;
    std::memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    r = smg_graph_get_joint(graph, j, &ji);
    if (r != SMG_OK) {
      *error = "smg_graph_get_joint(" + std::to_string(j) + "): " + smg_result_string(r);
      return false;
    }
    out->parent.push_back(ji.parent);
    out->rest_offset.push_back(glm::vec3(ji.rest_offset[0], ji.rest_offset[1], ji.rest_offset[2]));
    out->upper.push_back(ji.body_part == SMG_BODY_UPPER ? 1 : 0);
  }
  // A throw-away character's first pose, in character space (upright,
  // floor at y = 0).
  smg_character* ch = nullptr;
  r = smg_character_create(graph, nullptr, &ch);
  std::vector<float> first(size_t(info.joint_count) * 16);
  if (r == SMG_OK) r = smg_character_get_model_matrices(ch, SMG_SPACE_CHARACTER, first.data(), info.joint_count);
  if (ch) smg_character_destroy(ch);
  if (r != SMG_OK) {
    *error = std::string("the first pose for the body: ") + smg_result_string(r);
    return false;
  }
  if (!body_rest_is_upright(*out, first.data()))
    for (uint32_t j = 0; j < info.joint_count; ++j) {
      glm::mat4 m;
      for (int c = 0; c < 4; ++c)
        m[c] = glm::vec4(first[j * 16 + uint32_t(c) * 4], first[j * 16 + uint32_t(c) * 4 + 1],
                         first[j * 16 + uint32_t(c) * 4 + 2], first[j * 16 + uint32_t(c) * 4 + 3]);
      out->pose.push_back(m);
    }
  return true;
}
