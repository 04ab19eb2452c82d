// world.cpp - the demo's simulation state on top of the libsmg runtime.
#include "world.h"

#include "body_graph.h"
#include "palette.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace {

// Runtime capacities the demo asks for. Drawing stops adding points when
// the path is full (the HUD says so) so the demo's copy never diverges
// from the runtime's.
constexpr uint32_t kPathCapacity = 4096;
constexpr uint32_t kConstraintCapacity = 64;
constexpr size_t kFootprints = 48;
constexpr size_t kTrailMax = 400;
constexpr float kDrawSpacing = 0.15f;  // metres between drawn points

void collect_log(uint32_t level, const char* message, void* user) {
  if (level == SMG_LOG_ERROR || level == SMG_LOG_WARNING) {
    auto* s = static_cast<std::string*>(user);
    if (!s->empty()) *s += "; ";
    *s += message;
  }
}

glm::vec3 joint_position(const std::vector<float>& m, int j) {
  const float* c = &m[size_t(j) * 16 + 12];
  return glm::vec3(c[0], c[1], c[2]);
}

std::string lower(const std::string& s) {
  std::string out = s;
  for (char& c : out) c = char(std::tolower((unsigned char)c));
  return out;
}

// The runtime accepts constraints only within its copy of the path; each
// character's translated copy may differ from the demo's length by float
// rounding, so a marker at the very end is clamped per character.
float clamp_to_path(const smg_character* ch, float s) {
  float length = 0.0f;
  if (smg_character_get_path_length(ch, &length) == SMG_OK && s > length && s < length + 1e-2f) return length;
  return s;
}

}  // namespace

std::vector<glm::vec2> crowd_offsets(int n, float spacing) {
  std::vector<glm::vec2> cells;
  int r = 0;
  while (int(cells.size()) < n) {
    // All grid cells on the square ring of radius r, nearest first.
    std::vector<glm::vec2> ring;
    for (int x = -r; x <= r; ++x)
      for (int z = -r; z <= r; ++z)
        if (std::max(std::abs(x), std::abs(z)) == r) ring.push_back(glm::vec2(x, z) * spacing);
    std::stable_sort(ring.begin(), ring.end(), [](glm::vec2 a, glm::vec2 b) {
      return glm::dot(a, a) < glm::dot(b, b);
    });
    for (glm::vec2 c : ring)
      if (int(cells.size()) < n) cells.push_back(c);
    ++r;
  }
  return cells;
}

World::~World() {
  destroy_characters();
  if (graph_) smg_graph_destroy(graph_);
}

bool World::check(smg_result r, const char* what) {
  if (r == SMG_OK) return true;
  last_error_ = std::string(what) + ": " + smg_result_string(r);
  ++error_count_;
  return false;
}

bool World::load(const std::string& path, std::string* error) {
  std::string log;
  smg_graph_desc desc;
  std::memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.logger.func = collect_log;
  desc.logger.user = &log;
  smg_graph* g = nullptr;
  smg_result r = smg_graph_load_file(path.c_str(), &desc, &g);
  if (r != SMG_OK) {
    *error = "cannot load graph '" + path + "': " + smg_result_string(r);
    if (!log.empty()) *error += " (" + log + ")";
    return false;
  }
  smg_graph_info info;
  std::memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  r = smg_graph_get_info(g, &info);
  if (r != SMG_OK || info.joint_count == 0 || info.style_count == 0 || info.action_count == 0) {
    *error = "graph '" + path + "' has no skeleton, style or action (" + smg_result_string(r) + ")";
    smg_graph_destroy(g);
    return false;
  }
  graph_ = g;
  info_ = info;
  joint_count_ = info.joint_count;
  style_count_ = info.style_count;
  action_count_ = info.action_count;
  build_layout();
  // A bad body only costs the skinned view; the skeleton view still works.
  BodySkeleton skeleton;
  if (!body_skeleton_from_graph(graph_, &skeleton, &body_error_) ||
      !build_body(skeleton, kBodyCellsPerHeight, &body_, &body_error_) ||
      !build_body(skeleton, kBodyCoarseCellsPerHeight, &coarse_body_, &body_error_)) {
    body_ = BodyMesh();
    coarse_body_ = BodyMesh();
  }
  return true;
}

// Bone radii by joint name (CMU naming, with generic fallbacks). The bone
// that starts at joint j and ends at its child gets radius[j].
void World::build_layout() {
  layout_ = JointLayout();
  for (uint32_t j = 0; j < joint_count_; ++j) {
    smg_joint_info ji;
    std::memset(&ji, 0, sizeof ji);
    ji.struct_size = sizeof ji;
    if (smg_graph_get_joint(graph_, j, &ji) != SMG_OK) {
      ji.parent = j == 0 ? SMG_NO_PARENT : 0;
      ji.name = "";
      ji.body_part = SMG_BODY_LOWER;
    }
    std::string n = lower(ji.name ? ji.name : "");
    layout_.parent.push_back(ji.parent);
    layout_.body_part.push_back(ji.body_part);
    layout_.name.push_back(ji.name ? ji.name : "");
    float r = 0.04f;
    if (n.find("upleg") != std::string::npos || n.find("thigh") != std::string::npos) r = 0.075f;
    else if (n.find("leg") != std::string::npos || n.find("knee") != std::string::npos) r = 0.058f;
    else if (n.find("foot") != std::string::npos || n.find("ankle") != std::string::npos) r = 0.045f;
    else if (n.find("toe") != std::string::npos) r = 0.035f;
    else if (n.find("forearm") != std::string::npos) r = 0.04f;
    else if (n.find("shoulder") != std::string::npos) r = 0.05f;
    else if (n.find("arm") != std::string::npos) r = 0.05f;
    else if (n.find("hand") != std::string::npos || n.find("finger") != std::string::npos ||
             n.find("thumb") != std::string::npos) r = 0.022f;
    else if (n.find("spine") != std::string::npos || n.find("back") != std::string::npos ||
             n.find("chest") != std::string::npos) r = 0.105f;
    else if (n.find("neck") != std::string::npos) r = 0.05f;
    else if (n.find("hip") != std::string::npos || n.find("pelvis") != std::string::npos) r = 0.075f;
    layout_.radius.push_back(r);
    bool finger = n.find("finger") != std::string::npos || n.find("thumb") != std::string::npos ||
                  n.find("index") != std::string::npos;
    layout_.skip.push_back(finger ? 1 : 0);
    if (n == "head") layout_.head = int(j);
    if (n == "neck1" || (n == "neck" && layout_.neck < 0)) layout_.neck = int(j);
    if (n == "leftfoot") layout_.left_foot = int(j);
    if (n == "lefttoebase") layout_.left_toe = int(j);
    if (n == "rightfoot") layout_.right_foot = int(j);
    if (n == "righttoebase") layout_.right_toe = int(j);
  }
  // Sanitise the hierarchy so drawing never indexes out of range.
  for (uint32_t j = 0; j < joint_count_; ++j)
    if (layout_.parent[j] >= int32_t(j)) layout_.parent[j] = SMG_NO_PARENT;
}

void World::destroy_characters() {
  for (Character& c : characters_)
    if (c.handle) smg_character_destroy(c.handle);
  characters_.clear();
}

bool World::spawn(int n, std::string* error) {
  destroy_characters();
  trail_.clear();
  if (!graph_) {
    *error = "no graph loaded";
    return false;
  }
  std::vector<glm::vec2> offsets = crowd_offsets(n, 1.6f);
  glm::vec2 dir(0.0f, 1.0f);
  glm::vec2 start = path_.empty() ? glm::vec2(0.0f) : path_.point_at(0.0f, &dir);
  for (int i = 0; i < n; ++i) {
    smg_character_desc d;
    std::memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.flags = (ik_ ? 0u : SMG_CHARACTER_NO_IK) | (steering_ ? 0u : SMG_CHARACTER_NO_STEERING) |
              (swing_clearance_ ? 0u : SMG_CHARACTER_NO_SWING_CLEARANCE);
    d.path_capacity = kPathCapacity;
    d.constraint_capacity = kConstraintCapacity;
    d.seed = uint32_t(i + 1);
    d.position[0] = start.x + offsets[size_t(i)].x;
    d.position[2] = start.y + offsets[size_t(i)].y;
    d.heading = std::atan2(dir.x, dir.y);
    d.error_threshold = threshold_;
    Character c;
    c.offset = offsets[size_t(i)];
    smg_result r = smg_character_create(graph_, &d, &c.handle);
    if (r != SMG_OK) {
      *error = "cannot create character " + std::to_string(i) + ": " + smg_result_string(r);
      destroy_characters();
      return false;
    }
    c.matrices.assign(size_t(joint_count_) * 16, 0.0f);
    c.footprints.resize(kFootprints);
    c.state.struct_size = sizeof c.state;
    characters_.push_back(std::move(c));
    push_path_to(characters_.back());
    apply_markers_to(characters_.back());
    // Read the initial pose so the first frame can draw before any step.
    Character& cc = characters_.back();
    check(smg_character_get_model_matrices(cc.handle, SMG_SPACE_WORLD, cc.matrices.data(), joint_count_),
          "smg_character_get_model_matrices");
    check(smg_character_get_state(cc.handle, &cc.state), "smg_character_get_state");
  }
  return true;
}

void World::push_path_to(Character& c) {
  std::vector<float> xz;
  xz.reserve(path_.size() * 2);
  for (glm::vec2 p : path_.points()) {
    xz.push_back(p.x + c.offset.x);
    xz.push_back(p.y + c.offset.y);
  }
  check(smg_character_set_path(c.handle, xz.empty() ? nullptr : xz.data(), uint32_t(path_.size())),
        "smg_character_set_path");
}

void World::apply_markers_to(Character& c) {
  size_t index = size_t(&c - characters_.data());
  for (Marker& m : markers_) {
    uint32_t id = 0;
    smg_result r = m.kind == MarkerKind::Transition
                       ? smg_character_add_transition(c.handle, m.arc_length, m.value, &id)
                       : smg_character_add_splice(c.handle, m.arc_length, m.value, &id);
    check(r, m.kind == MarkerKind::Transition ? "smg_character_add_transition" : "smg_character_add_splice");
    if (m.ids.size() <= index) m.ids.resize(index + 1, 0);
    m.ids[index] = r == SMG_OK ? id : 0;
  }
}

void World::begin_path(glm::vec2 p) {
  path_.clear();
  path_.add(p, 0.0f);
  for (Character& c : characters_) push_path_to(c);
}

void World::extend_path(glm::vec2 p) {
  if (path_.size() >= kPathCapacity) {
    last_error_ = "path is full (" + std::to_string(kPathCapacity) + " points)";
    return;
  }
  if (!path_.add(p, kDrawSpacing)) return;
  for (Character& c : characters_) {
    float xz[2] = {p.x + c.offset.x, p.y + c.offset.y};
    check(smg_character_append_path(c.handle, xz, 1), "smg_character_append_path");
  }
}

void World::set_path(const std::vector<glm::vec2>& points) {
  path_.clear();
  for (glm::vec2 p : points)
    if (path_.size() < kPathCapacity) path_.add(p, 0.01f);
  for (Character& c : characters_) push_path_to(c);
}

void World::append_path(const std::vector<glm::vec2>& points) {
  size_t before = path_.size();
  for (glm::vec2 p : points)
    if (path_.size() < kPathCapacity) path_.add(p, 0.01f);
  size_t added = path_.size() - before;
  if (added == 0) return;
  for (Character& c : characters_) {
    std::vector<float> xz;
    for (size_t i = before; i < path_.size(); ++i) {
      xz.push_back(path_.points()[i].x + c.offset.x);
      xz.push_back(path_.points()[i].y + c.offset.y);
    }
    check(smg_character_append_path(c.handle, xz.data(), uint32_t(added)), "smg_character_append_path");
  }
}

void World::clear_path() {
  path_.clear();
  for (Character& c : characters_) check(smg_character_clear_path(c.handle), "smg_character_clear_path");
}

int World::add_marker(MarkerKind kind, float s, uint32_t value) {
  if (!std::isfinite(s) || s < 0.0f) {
    last_error_ = "marker arc length must be >= 0";
    return 0;
  }
  if ((kind == MarkerKind::Transition && value >= style_count_) ||
      (kind == MarkerKind::Splice && value >= action_count_)) {
    last_error_ = "unknown style or action index " + std::to_string(value);
    return 0;
  }
  Marker m;
  m.kind = kind;
  m.value = value;
  m.arc_length = s;
  for (size_t i = 0; i < characters_.size(); ++i) {
    uint32_t id = 0;
    float si = clamp_to_path(characters_[i].handle, s);
    smg_result r = kind == MarkerKind::Transition
                       ? smg_character_add_transition(characters_[i].handle, si, value, &id)
                       : smg_character_add_splice(characters_[i].handle, si, value, &id);
    if (!check(r, kind == MarkerKind::Transition ? "smg_character_add_transition" : "smg_character_add_splice")) {
      // Keep all characters consistent: undo the ones already added.
      for (size_t k = 0; k < i; ++k) smg_character_remove_constraint(characters_[k].handle, m.ids[k]);
      return 0;
    }
    m.ids.push_back(id);
  }
  m.uid = next_uid_++;
  markers_.push_back(m);
  return m.uid;
}

const Marker* World::find_marker(int uid) const {
  for (const Marker& m : markers_)
    if (m.uid == uid) return &m;
  return nullptr;
}

bool World::move_marker(int uid, float s) {
  if (!std::isfinite(s)) return false;
  s = std::max(0.0f, s);
  for (Marker& m : markers_) {
    if (m.uid != uid) continue;
    m.arc_length = s;
    for (size_t i = 0; i < characters_.size() && i < m.ids.size(); ++i)
      if (m.ids[i])  // 0: the runtime refused it for this character (respawn on a shorter path)
        check(smg_character_move_constraint(characters_[i].handle, m.ids[i], clamp_to_path(characters_[i].handle, s)),
            "smg_character_move_constraint");
    return true;
  }
  last_error_ = "no marker #" + std::to_string(uid);
  return false;
}

bool World::remove_marker(int uid) {
  for (size_t k = 0; k < markers_.size(); ++k) {
    if (markers_[k].uid != uid) continue;
    for (size_t i = 0; i < characters_.size() && i < markers_[k].ids.size(); ++i)
      if (markers_[k].ids[i])
        check(smg_character_remove_constraint(characters_[i].handle, markers_[k].ids[i]),
            "smg_character_remove_constraint");
    markers_.erase(markers_.begin() + long(k));
    return true;
  }
  last_error_ = "no marker #" + std::to_string(uid);
  return false;
}

void World::clear_markers() {
  markers_.clear();
  for (Character& c : characters_)
    check(smg_character_clear_constraints(c.handle), "smg_character_clear_constraints");
}

// The marker with the largest arc length at or before s wins.
static uint32_t value_at(const std::vector<Marker>& markers, MarkerKind kind, float s) {
  uint32_t v = 0;
  float best = -1.0f;
  for (const Marker& m : markers) {
    if (m.kind != kind || m.arc_length > s) continue;
    // Strictly greater, as the runtime: among equal arc lengths the marker
    // placed first (markers_ is in creation order) wins.
    if (m.arc_length > best) {
      best = m.arc_length;
      v = m.value;
    }
  }
  return v;
}

uint32_t World::style_at(float s) const { return value_at(markers_, MarkerKind::Transition, s); }
uint32_t World::action_at(float s) const { return value_at(markers_, MarkerKind::Splice, s); }

void World::set_error_threshold(float metres) {
  threshold_ = metres;
  for (Character& c : characters_)
    check(smg_character_set_error_threshold(c.handle, metres), "smg_character_set_error_threshold");
}

void World::set_ik(bool on) {
  ik_ = on;
  for (Character& c : characters_) check(smg_character_set_ik(c.handle, on ? 1u : 0u), "smg_character_set_ik");
}

void World::set_steering(bool on) {
  steering_ = on;
  for (Character& c : characters_)
    check(smg_character_set_steering(c.handle, on ? 1u : 0u), "smg_character_set_steering");
}

void World::set_swing_clearance(bool on) {
  swing_clearance_ = on;
  for (Character& c : characters_)
    check(smg_character_set_swing_clearance(c.handle, on ? 1u : 0u, 0.0f), "smg_character_set_swing_clearance");
}

void World::set_style_now(uint32_t style) {
  for (Character& c : characters_) check(smg_character_set_style(c.handle, style), "smg_character_set_style");
}

void World::set_action_now(uint32_t action) {
  for (Character& c : characters_) check(smg_character_set_action(c.handle, action), "smg_character_set_action");
}

const char* World::style_name(uint32_t s) const {
  const char* n = nullptr;
  if (graph_ && smg_graph_get_style_name(graph_, s, &n) == SMG_OK && n) return n;
  return "?";
}

const char* World::action_name(uint32_t a) const {
  const char* n = nullptr;
  if (graph_ && smg_graph_get_action_name(graph_, a, &n) == SMG_OK && n) return n;
  return "?";
}

glm::vec3 World::style_colour_of(uint32_t s) const { return style_colour(style_name(s), s); }
glm::vec3 World::action_colour_of(uint32_t a) const { return action_colour(action_name(a), a); }

void World::step(float dt) {
  using clock = std::chrono::steady_clock;
  double total = 0.0, worst = 0.0;
  for (Character& c : characters_) {
    auto t0 = clock::now();
    smg_result r1 = smg_character_step(c.handle, dt);
    smg_result r2 = smg_character_get_model_matrices(c.handle, SMG_SPACE_WORLD, c.matrices.data(), joint_count_);
    auto t1 = clock::now();
    check(r1, "smg_character_step");
    check(r2, "smg_character_get_model_matrices");
    double us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    total += us;
    worst = std::max(worst, us);

    c.previous_flags = c.state.flags;
    check(smg_character_get_state(c.handle, &c.state), "smg_character_get_state");
    for (Footprint& f : c.footprints) f.age += dt;
    // A footprint where a foot touches down (contact flag rising edge).
    const uint32_t flags[2] = {SMG_STATE_LEFT_CONTACT, SMG_STATE_RIGHT_CONTACT};
    const int heel[2] = {layout_.left_foot, layout_.right_foot};
    const int toe[2] = {layout_.left_toe, layout_.right_toe};
    for (int side = 0; side < 2; ++side) {
      if (!(c.state.flags & flags[side]) || (c.previous_flags & flags[side]) || heel[side] < 0) continue;
      glm::vec3 h = joint_position(c.matrices, heel[side]);
      glm::vec3 t = toe[side] >= 0 ? joint_position(c.matrices, toe[side]) : h + glm::vec3(0, 0, 0.15f);
      Footprint& f = c.footprints[c.next_footprint];
      c.next_footprint = (c.next_footprint + 1) % c.footprints.size();
      f.heel = glm::vec2(h.x, h.z);
      f.toe = glm::vec2(t.x, t.z);
      f.age = 0.0f;
      f.left = side == 0;
    }
  }
  sim_time_ += dt;
  step_us_total_ = total;
  step_us_avg_ = characters_.empty() ? 0.0 : total / double(characters_.size());
  step_us_max_ = worst;

  if (trail_enabled && !characters_.empty() && dt > 0.0f && sim_time_ >= next_trail_time_) {
    const Character& c = characters_[0];
    TrailPose p;
    p.style = c.state.style;
    p.action = c.state.action;
    for (uint32_t j = 0; j < joint_count_; ++j) p.joints.push_back(joint_position(c.matrices, int(j)));
    p.matrices = c.matrices;
    if (trail_.size() >= kTrailMax) trail_.erase(trail_.begin());
    trail_.push_back(std::move(p));
    next_trail_time_ = sim_time_ + trail_interval;
  }
}
