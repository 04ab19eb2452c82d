// path.cpp - arc-length queries on the drawn polyline.
#include "path.h"

#include <cmath>
#include <limits>

void Polyline::clear() {
  points_.clear();
  cumulative_.clear();
}

bool Polyline::add(glm::vec2 p, float min_spacing) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  if (points_.empty()) {
    points_.push_back(p);
    cumulative_.push_back(0.0f);
    return true;
  }
  float d = glm::length(p - points_.back());
  if (d < min_spacing || d <= 0.0f) return false;
  points_.push_back(p);
  cumulative_.push_back(cumulative_.back() + d);
  return true;
}

glm::vec2 Polyline::point_at(float s, glm::vec2* direction) const {
  if (direction) *direction = glm::vec2(0.0f, 1.0f);
  if (points_.empty()) return glm::vec2(0.0f);
  if (points_.size() == 1) return points_[0];
  // Binary search for the segment containing s.
  size_t lo = 0, hi = points_.size() - 1;
  if (s <= 0.0f) {
    hi = 1;
  } else if (s >= length()) {
    lo = points_.size() - 2;
  } else {
    while (hi - lo > 1) {
      size_t mid = (lo + hi) / 2;
      if (cumulative_[mid] <= s) lo = mid; else hi = mid;
    }
  }
  hi = lo + 1;
  float seg = cumulative_[hi] - cumulative_[lo];
  float t = seg > 0.0f ? (s - cumulative_[lo]) / seg : 0.0f;
  t = glm::clamp(t, 0.0f, 1.0f);
  glm::vec2 a = points_[lo], b = points_[hi];
  if (direction && seg > 0.0f) *direction = (b - a) / seg;
  return a + (b - a) * t;
}

float Polyline::nearest(glm::vec2 p, float* distance) const {
  float best_d = std::numeric_limits<float>::infinity(), best_s = 0.0f;
  if (points_.size() == 1) {
    best_d = glm::length(p - points_[0]);
  }
  for (size_t i = 0; i + 1 < points_.size(); ++i) {
    glm::vec2 a = points_[i], ab = points_[i + 1] - a;
    float len2 = glm::dot(ab, ab);
    float t = len2 > 0.0f ? glm::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    float d = glm::length(p - (a + ab * t));
    if (d < best_d) {
      best_d = d;
      best_s = cumulative_[i] + t * (cumulative_[i + 1] - cumulative_[i]);
    }
  }
  if (distance) *distance = best_d;
  return best_s;
}
