// renderer.h - the demo's OpenGL 3.3 core renderer: a ground plane with a
// procedural grid, flat decals on the ground (path, footprints, marker
// rings), and instanced lit spheres and cylinders (bones, joints, marker
// poles) with planar projected shadows. Knows nothing about libsmg.
#pragma once

#include "camera.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

struct Instance {
  glm::mat4 model;
  glm::vec4 colour;
};

struct FlatVertex {
  glm::vec3 position;
  glm::vec4 colour;
};

class Renderer {
 public:
  bool init(std::string* error);
  void shutdown();

  // Starts a frame into the currently bound framebuffer of size w x h.
  void begin(int width, int height, const OrbitCamera& camera);
  // Queue geometry for this frame.
  // Joint spheres inside a capsule's shadow need not cast their own.
  void sphere(glm::vec3 centre, float radius, glm::vec4 colour, bool casts_shadow = true);
  void cylinder(glm::vec3 a, glm::vec3 b, float radius, glm::vec4 colour);
  // Ground decals: triangles lying on y ~ 0, drawn over the grid.
  std::vector<FlatVertex>& decals() { return decals_; }
  // Draws everything queued: ground, decals, shadows, lit meshes.
  void end();

  int instance_count() const { return last_instances_; }

 private:
  struct Mesh {
    unsigned vao = 0, vbo = 0, ibo = 0, instance_vbo = 0;
    int index_count = 0;
  };
  bool build_mesh(Mesh* mesh, const std::vector<float>& vertices, const std::vector<unsigned>& indices);
  void draw_instances(const Mesh& mesh, const std::vector<Instance>& instances);

  unsigned lit_program_ = 0, ground_program_ = 0, flat_program_ = 0;
  Mesh sphere_, cylinder_;
  unsigned ground_vao_ = 0, ground_vbo_ = 0;
  unsigned flat_vao_ = 0, flat_vbo_ = 0;
  std::vector<Instance> spheres_, shadow_spheres_, cylinders_;
  std::vector<FlatVertex> decals_;
  glm::mat4 view_proj_{1.0f};
  glm::vec3 eye_{0.0f}, target_{0.0f};
  int width_ = 0, height_ = 0;
  int last_instances_ = 0;
};
