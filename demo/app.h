// app.h - the demo application state shared by the main loop, input
// handling, the ImGui HUD and script replay.
#pragma once

#include "camera.h"
#include "renderer.h"
#include "scene_draw.h"
#include "script.h"
#include "world.h"

#include <SDL.h>

#include <string>
#include <vector>

struct Options {
  std::string graph;             // blob to load
  int characters = 1;
  std::string script;            // replay script ("" = none)
  int frames = -1;               // stop after this many frames (-1 = never)
  std::string screenshot;        // write a PNG after `frames` frames
  int width = 1280, height = 720;
  float dt = 1.0f / 60.0f;       // fixed simulation step
  bool hud = true;
};

enum class Tool { Draw, Transition, Splice };

struct App {
  Options options;
  bool headless = false;         // offscreen rendering for --screenshot
  SDL_Window* window = nullptr;
  SDL_GLContext gl = nullptr;
  Renderer renderer;
  World world;
  OrbitCamera camera;
  SceneView view;

  Tool tool = Tool::Draw;
  uint32_t tool_style = 0, tool_action = 0;
  bool hud = true;
  bool paused = false;
  float speed = 1.0f;
  int characters_wanted = 1;
  bool quit = false;
  bool want_screenshot = false;  // F12 in the window

  // Mouse interaction.
  bool drawing = false, orbiting = false, panning = false;
  int dragging_marker = 0;
  glm::vec2 mouse{0.0f};

  // Script replay.
  std::vector<ScriptCommand> script;
  size_t script_next = 0;
  long frame = 0;                // simulation frames done
  int script_errors = 0;

  // Timing shown in the HUD.
  double frame_ms = 0.0;         // wall-clock time per rendered frame (EMA)
  double step_us_avg = 0.0, step_us_max = 0.0;  // per character (EMA)
  double step_us_sum = 0.0, step_us_worst = 0.0;  // over the whole run
  long step_frames = 0;
  std::string status;            // last message for the user

  int viewport_width() const;
  int viewport_height() const;
};

// input.cpp: SDL events that are not consumed by ImGui.
void handle_event(App& app, const SDL_Event& e);
// hud.cpp: the ImGui windows (call between ImGui::NewFrame and Render).
void draw_hud(App& app);
// app_script.cpp: run the commands due at app.frame. Returns false on a
// command that cannot be applied (unknown style, marker, ...).
bool run_script_commands(App& app, bool* screenshot_requested, std::string* screenshot_path);
// screenshot.cpp: PNG of the current framebuffer contents (rows flipped).
bool save_framebuffer_png(const std::string& path, int width, int height, std::string* error);
