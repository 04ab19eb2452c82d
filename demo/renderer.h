// renderer.h - the demo's OpenGL 3.3 core renderer: a ground plane with a
// procedural grid, flat decals on the ground (path, footprints, marker
// rings), instanced lit spheres and cylinders (bones, joints, marker
// poles) and GPU-skinned bodies, all with planar projected shadows. Knows
// nothing about libsmg.
#pragma once

#include "body.h"
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
  // A skinned body (the meshes given to set_body) posed by one skinning
  // matrix per joint; `centre` (world) picks the level of detail by its
  // size on screen; lower/upper body colours, lightened by `ghost`.
  void body(const glm::mat4* skin, glm::vec3 centre, glm::vec3 lower, glm::vec3 upper, float ghost);
  // The meshes body() draws: detailed, and coarse for bodies small on
  // screen (same skeleton); false if they cannot be uploaded.
  bool set_body(const BodyMesh& detailed, const BodyMesh& coarse, std::string* error);
  // Ground decals: triangles lying on y ~ 0, drawn over the grid.
  std::vector<FlatVertex>& decals() { return decals_; }
  // Draws everything queued: ground, decals, shadows, lit meshes.
  void end();

  int instance_count() const { return last_instances_; }
  bool has_body() const { return lods_[0].index_count > 0; }

 private:
  struct Mesh {
    unsigned vao = 0, vbo = 0, ibo = 0, instance_vbo = 0;
    int index_count = 0;
  };
  bool build_mesh(Mesh* mesh, const std::vector<float>& vertices, const std::vector<unsigned>& indices);
  void draw_instances(const Mesh& mesh, const std::vector<Instance>& instances);
  void draw_bodies(bool shadow);

  // Skinned bodies: per level of detail the mesh, the queued instances
  // colours and skinning matrices; those go in a texture buffer (the 3
  // affine rows of instance i, joint j at texels 3 * (i * joints + j) ...),
  // so one instanced draw poses the whole crowd.
  struct BodyColours {
    glm::vec4 lower, upper;  // upper.a = ghost (lightening)
  };
  struct BodyLod {
    unsigned vao = 0, vbo = 0, ibo = 0, instance_vbo = 0;
    int index_count = 0;
    std::vector<glm::vec4> rows;
    std::vector<BodyColours> colours;
  };
  unsigned body_program_ = 0;
  BodyLod lods_[2];
  unsigned joint_tbo_ = 0, joint_texture_ = 0;
  int body_joints_ = 0, max_body_instances_ = 0;
  float body_height_ = 0.0f;
  float proj_y_ = 1.0f;  // projection's y scale (clip y per metre at depth 1)

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
