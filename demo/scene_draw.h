// scene_draw.h - turns the World (path, markers, characters) into renderer
// geometry: coloured path ribbons, marker poles, skinned bodies or capsule
// skeletons, footprints and the strobe trail.
#pragma once

#include "renderer.h"
#include "world.h"

struct SceneView {
  int selected_marker = 0;  // uid drawn highlighted
  int hovered_marker = 0;
  bool show_footprints = true;
  bool show_path_copies = true;
  bool show_skeleton = false;  // capsule skeletons instead of skinned bodies
};

void draw_scene(Renderer& r, const World& world, const SceneView& view);

// Ground position and top of a marker's pole (for picking).
glm::vec3 marker_base(const World& world, const Marker& m);
glm::vec3 marker_top(const Marker& m, glm::vec3 base);
