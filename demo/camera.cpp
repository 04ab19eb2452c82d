// camera.cpp - orbit camera maths.
#include "camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

glm::vec3 OrbitCamera::eye() const {
  float c = std::cos(pitch);
  return target + distance * glm::vec3(c * std::sin(yaw), std::sin(pitch), c * std::cos(yaw));
}

glm::mat4 OrbitCamera::view() const {
  return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
  // A near plane of 0.1 m keeps enough depth precision for decals a few
  // millimetres above the ground at 100 m.
  return glm::perspective(fovy, aspect > 0.0f ? aspect : 1.0f, 0.1f, 600.0f);
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw -= dx * 0.008f;
  pitch = glm::clamp(pitch + dy * 0.008f, glm::radians(3.0f), glm::radians(89.0f));
}

void OrbitCamera::zoom(float steps) {
  distance = glm::clamp(distance * std::pow(0.88f, steps), 1.5f, 250.0f);
}

void OrbitCamera::pan(float dx, float dy, int viewport_height) {
  // Metres per pixel at the target distance.
  float scale = 2.0f * distance * std::tan(fovy * 0.5f) / float(viewport_height > 0 ? viewport_height : 1);
  glm::vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
  glm::vec3 forward(-std::sin(yaw), 0.0f, -std::cos(yaw));
  target += (-dx * right + dy * forward) * scale;
}

void OrbitCamera::follow_towards(glm::vec3 p, float dt) {
  float k = 1.0f - std::exp(-dt * 3.0f);
  target.x += (p.x - target.x) * k;
  target.z += (p.z - target.z) * k;
}

bool OrbitCamera::ground_hit(float x, float y, int width, int height, glm::vec2* out) const {
  if (width <= 0 || height <= 0) return false;
  glm::mat4 inv = glm::inverse(projection(float(width) / float(height)) * view());
  float nx = 2.0f * x / float(width) - 1.0f, ny = 1.0f - 2.0f * y / float(height);
  glm::vec4 a = inv * glm::vec4(nx, ny, -1.0f, 1.0f), b = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
  glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  glm::vec3 d = p1 - p0;
  if (d.y > -1e-6f) return false;  // parallel to or away from the ground
  float t = -p0.y / d.y;
  glm::vec3 hit = p0 + d * t;
  if (glm::length(glm::vec2(hit.x, hit.z) - glm::vec2(target.x, target.z)) > 400.0f) return false;
  *out = glm::vec2(hit.x, hit.z);
  return true;
}

bool OrbitCamera::to_screen(glm::vec3 p, int width, int height, glm::vec2* out) const {
  if (width <= 0 || height <= 0) return false;
  glm::vec4 c = projection(float(width) / float(height)) * view() * glm::vec4(p, 1.0f);
  if (c.w <= 1e-4f) return false;
  *out = glm::vec2((c.x / c.w * 0.5f + 0.5f) * float(width), (0.5f - c.y / c.w * 0.5f) * float(height));
  return true;
}
