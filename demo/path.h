// path.h - the demo's own copy of the drawn path: a polyline on the ground
// with cumulative arc lengths, so the UI can place markers at a distance,
// find the distance nearest to a mouse click and colour the path by style.
// The runtime keeps its own copy (smg_character_set_path); both measure arc
// length the same way (sum of straight segment lengths from the start).
#pragma once

#include <glm/glm.hpp>

#include <vector>

class Polyline {
 public:
  void clear();
  // Adds a point unless it is closer than min_spacing to the last one.
  // Returns true when the point was added.
  bool add(glm::vec2 p, float min_spacing);
  size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }
  const std::vector<glm::vec2>& points() const { return points_; }
  float length() const { return cumulative_.empty() ? 0.0f : cumulative_.back(); }
  float arc_length_at(size_t i) const { return cumulative_[i]; }

  // The point at arc length s (clamped to [0, length]) and the unit
  // direction of the segment there.
  glm::vec2 point_at(float s, glm::vec2* direction = nullptr) const;
  // Arc length of the point of the path nearest to p; *distance receives
  // how far p is from it. Returns 0 (distance infinity) on an empty path.
  float nearest(glm::vec2 p, float* distance) const;

 private:
  std::vector<glm::vec2> points_;
  std::vector<float> cumulative_;
};
