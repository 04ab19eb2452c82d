// body_graph.cpp - reads a graph's skeleton for the generated body.
#include "body_graph.h"

#include <cstring>

bool body_skeleton_from_graph(const smg_graph* graph, BodySkeleton* out, std::string* error) {
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
  return true;
}
