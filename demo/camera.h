// camera.h - orbit/zoom camera around a target on the ground, optionally
// following a character, and mouse-ray casting onto the ground plane.
#pragma once

#include <glm/glm.hpp>

struct OrbitCamera {
  glm::vec3 target{0.0f, 0.9f, 0.0f};  // point looked at (about hip height)
  float yaw = 0.7f;                     // radians about +Y
  float pitch = 0.55f;                  // radians above the ground
  float distance = 9.0f;                // metres from target
  float fovy = glm::radians(45.0f);
  bool follow = false;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;

  void orbit(float dx_pixels, float dy_pixels);
  void zoom(float wheel_steps);
  // Moves the target in the ground plane by a screen drag.
  void pan(float dx_pixels, float dy_pixels, int viewport_height);
  // Eases the target towards a ground position (follow mode), dt seconds.
  void follow_towards(glm::vec3 ground_position, float dt);

  // Intersects the ray through pixel (x, y) (origin top-left) with y = 0.
  // Returns false when the ray misses the ground (looking at the sky).
  bool ground_hit(float x, float y, int width, int height, glm::vec2* out_xz) const;
  // Projects a world point to pixels (origin top-left); false if behind.
  bool to_screen(glm::vec3 p, int width, int height, glm::vec2* out) const;
};
