// body.h - a smooth skinned body generated from any skeleton (no model
// file): round cones around the bones of a bind pose and an ellipsoid
// head, blended into one implicit surface, polygonised on a grid, each
// vertex weighted to up to 4 joints by how close it lies to their bones.
// Works from the hierarchy and joint positions alone (no joint names), so any
// rig a blob carries gets a body. Knows nothing about OpenGL or libsmg.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

// The skeleton and the pose the body is built around (its bind pose): the
// rest pose, where every joint's local rotation is the identity and joint j
// sits at the sum of the rest offsets from the root down to j (the
// runtime's FK with identity rotations), or `pose` when given. A T-pose
// rest keeps the arms clear of the torso; rigs whose rest offsets live in
// rotated joint frames have no upright rest pose and need `pose`.
struct BodySkeleton {
  std::vector<int> parent;           // -1 for a root; parent[j] < j
  std::vector<glm::vec3> rest_offset;  // from the parent, metres
  std::vector<uint8_t> upper;        // 1 = upper body (thinner limbs)
  std::vector<glm::mat4> pose;       // empty, or per joint its model matrix (rigid, upright, floor y = 0)
};

// What a vertex is dressed in: lower body, upper body, bare skin (in this
// order on the body, so a blend of neighbours is a value in between).
enum BodyMaterial : uint8_t { kBodyLower = 0, kBodyUpper = 1, kBodySkin = 2 };

struct BodyVertex {
  glm::vec3 position;   // bind pose, metres
  glm::vec3 normal;     // outward, unit
  uint16_t joints[4];   // influences, weights sorted descending
  float weights[4];     // sum to 1; unused slots are 0 with joint 0
  float material;       // 0..2: BodyMaterial, blended near boundaries
};

struct BodyMesh {
  std::vector<BodyVertex> vertices;
  std::vector<uint32_t> indices;        // triangles, counter-clockwise outside
  std::vector<glm::mat4> inverse_bind;  // per joint: inverse of its bind-pose matrix
  float height = 0.0f;                  // bind-pose joint height range, metres
};

// The resolution the demos use: 40 cells over the body's height gives ~3k
// triangles for a human, smooth enough close up and light enough for a
// crowd of 50 on a software rasteriser.
constexpr int kBodyCellsPerHeight = 40;
// Half that for bodies small on screen (crowds): ~0.9k triangles.
constexpr int kBodyCoarseCellsPerHeight = 20;

// Builds the body. cells_per_height sets the grid resolution (cells over
// the skeleton's height). Fails with a message for an empty or
// inconsistent skeleton.
bool build_body(const BodySkeleton& skeleton, int cells_per_height, BodyMesh* out, std::string* error);

// Skinning matrices for one pose: model[j] (column-major 4x4, as
// smg_character_get_model_matrices writes them) times inverse_bind[j].
void body_skin_matrices(const BodyMesh& mesh, const float* model, glm::mat4* out);

// Linear-blend skinning of one vertex on the CPU (what the vertex shader
// does), for tests and tools.
glm::vec3 body_skin_point(const BodyVertex& v, const glm::mat4* skin);
