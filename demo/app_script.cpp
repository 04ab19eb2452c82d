// app_script.cpp - applies replay-script commands to the running demo.
#include "app.h"

#include <cstdio>
#include <cstring>

namespace {

bool find_style(const World& w, const std::string& name, uint32_t* out) {
  if (smg_graph_find_style(w.graph(), name.c_str(), out) == SMG_OK) return true;
  int i = 0;
  if (parse_int(name, &i) && i >= 0 && uint32_t(i) < w.style_count()) {
    *out = uint32_t(i);
    return true;
  }
  return false;
}

bool find_action(const World& w, const std::string& name, uint32_t* out) {
  if (smg_graph_find_action(w.graph(), name.c_str(), out) == SMG_OK) return true;
  int i = 0;
  if (parse_int(name, &i) && i >= 0 && uint32_t(i) < w.action_count()) {
    *out = uint32_t(i);
    return true;
  }
  return false;
}

std::vector<glm::vec2> points(const std::vector<std::string>& a, size_t from) {
  std::vector<glm::vec2> p;
  for (size_t i = from; i + 1 < a.size(); i += 2) {
    float x = 0, z = 0;
    parse_float(a[i], &x);
    parse_float(a[i + 1], &z);
    p.push_back(glm::vec2(x, z));
  }
  return p;
}

std::string names(const World& w, bool styles) {
  std::string s;
  uint32_t n = styles ? w.style_count() : w.action_count();
  for (uint32_t i = 0; i < n; ++i) s += std::string(i ? ", " : "") + (styles ? w.style_name(i) : w.action_name(i));
  return s;
}

// Applies one command; returns "" or a message.
std::string apply(App& app, const ScriptCommand& c, bool* shot, std::string* shot_path) {
  World& w = app.world;
  const auto& a = c.args;
  float f = 0.0f;
  int n = 0;
  if (c.verb == "path") {
    w.set_path(points(a, 0));
    w.clear_trail();
  } else if (c.verb == "append") {
    w.append_path(points(a, 0));
  } else if (c.verb == "transition" || c.verb == "splice") {
    bool t = c.verb == "transition";
    uint32_t v = 0;
    if (t ? !find_style(w, a[1], &v) : !find_action(w, a[1], &v))
      return "unknown " + std::string(t ? "style" : "action") + " '" + a[1] + "' (this graph has: " + names(w, t) + ")";
    parse_float(a[0], &f);
    if (!w.add_marker(t ? MarkerKind::Transition : MarkerKind::Splice, f, v)) return w.last_error();
  } else if (c.verb == "move") {
    parse_int(a[0], &n);
    parse_float(a[1], &f);
    if (!w.move_marker(n, f)) return w.last_error();
  } else if (c.verb == "remove") {
    parse_int(a[0], &n);
    if (!w.remove_marker(n)) return w.last_error();
  } else if (c.verb == "select") {
    parse_int(a[0], &n);
    app.view.selected_marker = n;
  } else if (c.verb == "clear") {
    if (a[0] == "path" || a[0] == "all") w.clear_path();
    if (a[0] == "markers" || a[0] == "all") w.clear_markers();
  } else if (c.verb == "camera") {
    float v[5] = {0, 0, 0, 0, 0};
    for (size_t i = 0; i < a.size(); ++i) parse_float(a[i], &v[i]);
    app.camera.yaw = glm::radians(v[0]);
    app.camera.pitch = glm::clamp(glm::radians(v[1]), glm::radians(3.0f), glm::radians(89.0f));
    app.camera.distance = glm::clamp(v[2], 1.5f, 250.0f);
    if (a.size() == 5) {
      app.camera.target.x = v[3];
      app.camera.target.z = v[4];
      app.camera.follow = false;
    }
  } else if (c.verb == "follow") {
    app.camera.follow = a[0] == "on";
  } else if (c.verb == "ik") {
    w.set_ik(a[0] == "on");
  } else if (c.verb == "hud") {
    app.hud = a[0] == "on";
  } else if (c.verb == "skeleton") {
    app.view.show_skeleton = a[0] == "on" || !app.renderer.has_body();
  } else if (c.verb == "footprints") {
    app.view.show_footprints = a[0] == "on";
  } else if (c.verb == "trail") {
    w.trail_enabled = a[0] == "on";
    if (a.size() == 2) parse_float(a[1], &w.trail_interval);
    if (!w.trail_enabled) w.clear_trail();
  } else if (c.verb == "threshold") {
    parse_float(a[0], &f);
    w.set_error_threshold(f);
  } else if (c.verb == "tool") {
    app.tool = a[0] == "draw" ? Tool::Draw : a[0] == "transition" ? Tool::Transition : Tool::Splice;
  } else if (c.verb == "style") {
    uint32_t v = 0;
    if (!find_style(w, a[0], &v)) return "unknown style '" + a[0] + "' (this graph has: " + names(w, true) + ")";
    w.set_style_now(v);
  } else if (c.verb == "action") {
    uint32_t v = 0;
    if (!find_action(w, a[0], &v)) return "unknown action '" + a[0] + "' (this graph has: " + names(w, false) + ")";
    w.set_action_now(v);
  } else if (c.verb == "mouse" || c.verb == "wheel" || c.verb == "key") {
    // Synthetic input through the same handler as real SDL events, so
    // scripts (and the smoke test) exercise drawing and picking by mouse.
    SDL_Event e;
    std::memset(&e, 0, sizeof e);
    if (c.verb == "mouse") {
      float x = 0, y = 0;
      size_t at = a[0] == "move" ? 1 : 2;
      parse_float(a[at], &x);
      parse_float(a[at + 1], &y);
      if (a[0] == "move") {
        e.type = SDL_MOUSEMOTION;
        e.motion.x = int(x);
        e.motion.y = int(y);
        e.motion.xrel = int(x - app.mouse.x);
        e.motion.yrel = int(y - app.mouse.y);
      } else {
        e.type = a[0] == "down" ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        e.button.button = Uint8(a[1] == "left" ? SDL_BUTTON_LEFT : a[1] == "right" ? SDL_BUTTON_RIGHT : SDL_BUTTON_MIDDLE);
        e.button.x = int(x);
        e.button.y = int(y);
      }
    } else if (c.verb == "wheel") {
      parse_float(a[0], &f);
      e.type = SDL_MOUSEWHEEL;
      e.wheel.y = int(f);
    } else {
      e.type = SDL_KEYDOWN;
      const std::string& k = a[0];
      e.key.keysym.sym = k == "delete" ? SDLK_DELETE : k == "1" ? SDLK_1 : k == "2" ? SDLK_2 : k == "3" ? SDLK_3
                         : k == "f" ? SDLK_f : k == "h" ? SDLK_h : k == "f12" ? SDLK_F12 : SDLK_SPACE;
    }
    handle_event(app, e);
  } else if (c.verb == "screenshot") {
    *shot = true;
    *shot_path = a[0];
  }
  return "";
}

}  // namespace

bool run_script_commands(App& app, bool* screenshot_requested, std::string* screenshot_path) {
  bool ok = true;
  while (app.script_next < app.script.size() && app.script[app.script_next].frame <= app.frame) {
    const ScriptCommand& c = app.script[app.script_next++];
    app.world.clear_error();
    std::string problem = apply(app, c, screenshot_requested, screenshot_path);
    if (problem.empty() && !app.world.last_error().empty()) problem = app.world.last_error();
    if (!problem.empty()) {
      std::fprintf(stderr, "smg-demo: %s:%d: frame %d %s: %s\n", app.options.script.c_str(), c.line, c.frame,
                   c.verb.c_str(), problem.c_str());
      ++app.script_errors;
      ok = false;
    }
  }
  return ok;
}
