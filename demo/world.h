// world.h - everything the demo simulates: the loaded graph, the drawn path
// with its transition and splice markers, and the characters that follow
// offset copies of it. All runtime calls go through include/smg.h only.
//
// Markers are the demo's view of runtime constraints: one marker is one
// constraint on every character (each character has its own constraint id).
// Every edit is forwarded to the runtime at once; nothing is restarted.
#pragma once

#include "body.h"
#include "path.h"
#include "smg.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

enum class MarkerKind { Transition, Splice };

struct Marker {
  int uid = 0;             // stable demo id (1, 2, ... in creation order)
  MarkerKind kind = MarkerKind::Transition;
  uint32_t value = 0;      // style (transition) or action (splice)
  float arc_length = 0.0f; // metres along the path
  std::vector<uint32_t> ids;  // runtime constraint id per character
};

struct Footprint {
  glm::vec2 heel{0.0f}, toe{0.0f};
  float age = 1e9f;  // seconds since planted
  bool left = true;
};

// A frozen pose for the strobe trail (the paper's Fig. 4 look).
struct TrailPose {
  std::vector<glm::vec3> joints;
  std::vector<float> matrices;  // 16 per joint, world space (for the body)
  uint32_t style = 0, action = 0;
};

struct Character {
  smg_character* handle = nullptr;
  glm::vec2 offset{0.0f};            // this character's copy of the path
  std::vector<float> matrices;       // 16 * joint_count, world space
  smg_character_state state{};
  uint32_t previous_flags = 0;
  std::vector<Footprint> footprints; // ring buffer
  size_t next_footprint = 0;
};

struct JointLayout {
  std::vector<int32_t> parent;
  std::vector<uint32_t> body_part;
  std::vector<std::string> name;
  std::vector<float> radius;   // capsule radius of the bone starting here
  std::vector<uint8_t> skip;   // finger bones: too small to see, not drawn
  int head = -1, neck = -1;    // for the head sphere
  int left_foot = -1, left_toe = -1, right_foot = -1, right_toe = -1;
};

class World {
 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World();

  // Loads and validates a blob. On failure *error says why.
  bool load(const std::string& path, std::string* error);
  // (Re)creates n characters standing at their offsets. Keeps the path and
  // markers and re-applies them.
  bool spawn(int n, std::string* error);

  // --- path editing (base path; each character gets base + its offset) ---
  void begin_path(glm::vec2 p);             // replace with one point
  void extend_path(glm::vec2 p);            // append while drawing
  void set_path(const std::vector<glm::vec2>& points);
  void append_path(const std::vector<glm::vec2>& points);
  void clear_path();
  const Polyline& path() const { return path_; }

  // --- markers ---
  int add_marker(MarkerKind kind, float arc_length, uint32_t value);  // uid or 0
  bool move_marker(int uid, float arc_length);
  bool remove_marker(int uid);
  void clear_markers();
  const std::vector<Marker>& markers() const { return markers_; }
  const Marker* find_marker(int uid) const;
  // Style/action in force at arc length s according to the markers.
  uint32_t style_at(float s) const;
  uint32_t action_at(float s) const;

  // --- controls ---
  void set_error_threshold(float metres);
  float error_threshold() const { return threshold_; }
  void set_ik(bool on);
  bool ik() const { return ik_; }
  void set_steering(bool on);
  bool steering() const { return steering_; }
  void set_swing_clearance(bool on);
  bool swing_clearance() const { return swing_clearance_; }
  void set_style_now(uint32_t style);
  void set_action_now(uint32_t action);

  // Steps every character by dt and reads its pose; measures the cost.
  void step(float dt);

  // --- trail of character 0 ---
  bool trail_enabled = false;
  float trail_interval = 0.5f;  // seconds between frozen poses
  const std::vector<TrailPose>& trail() const { return trail_; }
  void clear_trail() { trail_.clear(); }

  // --- read-only views ---
  const smg_graph* graph() const { return graph_; }
  uint32_t joint_count() const { return joint_count_; }
  uint32_t style_count() const { return style_count_; }
  uint32_t action_count() const { return action_count_; }
  const char* style_name(uint32_t s) const;
  const char* action_name(uint32_t a) const;
  glm::vec3 style_colour_of(uint32_t s) const;
  glm::vec3 action_colour_of(uint32_t a) const;
  const JointLayout& joints() const { return layout_; }
  // The body generated from the graph's skeleton, detailed and coarse;
  // empty (no triangles) when it could not be made, body_error() says why.
  const BodyMesh& body() const { return body_; }
  const BodyMesh& coarse_body() const { return coarse_body_; }
  const std::string& body_error() const { return body_error_; }
  const std::vector<Character>& characters() const { return characters_; }
  const smg_graph_info& info() const { return info_; }
  double sim_time() const { return sim_time_; }

  // Cost of the last step: microseconds of smg_character_step +
  // smg_character_get_model_matrices, average and max per character.
  double step_us_avg() const { return step_us_avg_; }
  double step_us_max() const { return step_us_max_; }
  double step_us_total() const { return step_us_total_; }

  // The last runtime error (for the HUD / the script log); "" if none.
  const std::string& last_error() const { return last_error_; }
  void clear_error() { last_error_.clear(); }
  // Number of runtime calls that failed since start.
  int error_count() const { return error_count_; }

 private:
  bool check(smg_result r, const char* what);
  void destroy_characters();
  void push_path_to(Character& c);
  void apply_markers_to(Character& c);
  void build_layout();

  smg_graph* graph_ = nullptr;
  smg_graph_info info_{};
  uint32_t joint_count_ = 0, style_count_ = 0, action_count_ = 0;
  JointLayout layout_;
  BodyMesh body_, coarse_body_;
  std::string body_error_;
  std::vector<Character> characters_;
  Polyline path_;
  std::vector<Marker> markers_;
  int next_uid_ = 1;
  float threshold_ = 0.25f;
  bool ik_ = true;
  bool steering_ = true;
  bool swing_clearance_ = true;
  double sim_time_ = 0.0;
  double step_us_avg_ = 0.0, step_us_max_ = 0.0, step_us_total_ = 0.0;
  std::vector<TrailPose> trail_;
  double next_trail_time_ = 0.0;
  std::string last_error_;
  int error_count_ = 0;
};

// Grid offsets for n characters: character 0 at (0, 0), the rest in
// rings around it, `spacing` metres apart.
std::vector<glm::vec2> crowd_offsets(int n, float spacing);
