// input.cpp - mouse and keyboard in the 3D view: draw the path (left drag),
// place transition/splice markers (left click on the path), drag markers,
// delete them (right click or Delete), orbit (right drag), pan (middle
// drag), zoom (wheel).
#include "app.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// Screen distance from point p to segment ab.
float segment_distance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  glm::vec2 ab = b - a;
  float t = glm::dot(ab, ab) > 0.0f ? glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + ab * t));
}

// The marker whose pole is within 14 pixels of the mouse, nearest first.
int pick_marker(const App& app, glm::vec2 mouse) {
  int best = 0;
  float best_d = 14.0f;
  int w = app.viewport_width(), h = app.viewport_height();
  if (app.world.path().size() < 2) return 0;  // markers are not drawn then
  for (const Marker& m : app.world.markers()) {
    glm::vec3 base = marker_base(app.world, m), top = marker_top(m, base);
    glm::vec2 sa, sb;
    if (!app.camera.to_screen(base, w, h, &sa) || !app.camera.to_screen(top, w, h, &sb)) continue;
    float d = segment_distance(mouse, sa, sb);
    if (d < best_d) {
      best_d = d;
      best = m.uid;
    }
  }
  return best;
}

// How close (metres) a click must be to the path to hit it: a few pixels'
// worth at the current zoom, never less than half a metre.
float path_tolerance(const App& app) { return std::max(0.5f, app.camera.distance * 0.04f); }

void left_down(App& app) {
  glm::vec2 hit;
  bool on_ground = app.camera.ground_hit(app.mouse.x, app.mouse.y, app.viewport_width(), app.viewport_height(), &hit);
  int picked = pick_marker(app, app.mouse);
  if (picked) {
    app.dragging_marker = picked;
    app.view.selected_marker = picked;
    return;
  }
  if (!on_ground) return;
  const Polyline& path = app.world.path();
  if (app.tool == Tool::Draw) {
    // Starting near the end of the current path extends it; anywhere else
    // starts a new path (markers are kept at their arc lengths).
    if (!path.empty() && glm::length(hit - path.points().back()) < std::max(0.8f, app.camera.distance * 0.05f)) {
      app.world.extend_path(hit);
      app.status = "extending the path";
    } else {
      app.world.begin_path(hit);
      app.world.clear_trail();
      app.status = "drawing a new path";
    }
    app.drawing = true;
    return;
  }
  if (path.size() < 2) {
    app.status = "draw a path first (tool: Draw)";
    return;
  }
  float dist = 0.0f;
  float s = path.nearest(hit, &dist);
  if (dist > path_tolerance(app)) {
    app.status = "click on the path to place a marker";
    return;
  }
  bool transition = app.tool == Tool::Transition;
  int uid = app.world.add_marker(transition ? MarkerKind::Transition : MarkerKind::Splice, s,
                                 transition ? app.tool_style : app.tool_action);
  if (uid) {
    app.view.selected_marker = uid;
    app.dragging_marker = uid;  // a click-and-drag places and moves at once
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s #%d: %s at %.2f m", transition ? "transition" : "splice", uid,
                  transition ? app.world.style_name(app.tool_style) : app.world.action_name(app.tool_action), s);
    app.status = buf;
  } else {
    app.status = "could not add the marker: " + app.world.last_error();
  }
}

void mouse_move(App& app, float dx, float dy) {
  int w = app.viewport_width(), h = app.viewport_height();
  if (app.orbiting) app.camera.orbit(dx, dy);
  if (app.panning) app.camera.pan(dx, dy, h);
  glm::vec2 hit;
  bool on_ground = app.camera.ground_hit(app.mouse.x, app.mouse.y, w, h, &hit);
  if (app.drawing && on_ground) app.world.extend_path(hit);
  if (app.dragging_marker && on_ground) {
    float dist = 0.0f;
    float s = app.world.path().nearest(hit, &dist);
    app.world.move_marker(app.dragging_marker, s);
  }
  if (!app.drawing && !app.dragging_marker) app.view.hovered_marker = pick_marker(app, app.mouse);
}

void delete_marker(App& app, int uid) {
  if (uid && app.world.remove_marker(uid)) {
    app.status = "deleted marker #" + std::to_string(uid);
    if (app.view.selected_marker == uid) app.view.selected_marker = 0;
    if (app.view.hovered_marker == uid) app.view.hovered_marker = 0;
  }
}

}  // namespace

void handle_event(App& app, const SDL_Event& e) {
  ImGuiIO& io = ImGui::GetIO();
  switch (e.type) {
    case SDL_QUIT:
      app.quit = true;
      break;
    case SDL_MOUSEBUTTONDOWN:
      app.mouse = glm::vec2(float(e.button.x), float(e.button.y));
      if (io.WantCaptureMouse) break;
      if (e.button.button == SDL_BUTTON_LEFT) {
        left_down(app);
      } else if (e.button.button == SDL_BUTTON_RIGHT) {
        int picked = pick_marker(app, app.mouse);
        if (picked) delete_marker(app, picked);
        else app.orbiting = true;
      } else if (e.button.button == SDL_BUTTON_MIDDLE) {
        app.panning = true;
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (e.button.button == SDL_BUTTON_LEFT) {
        app.drawing = false;
        app.dragging_marker = 0;
      } else if (e.button.button == SDL_BUTTON_RIGHT) {
        app.orbiting = false;
      } else if (e.button.button == SDL_BUTTON_MIDDLE) {
        app.panning = false;
      }
      break;
    case SDL_MOUSEMOTION:
      app.mouse = glm::vec2(float(e.motion.x), float(e.motion.y));
      mouse_move(app, float(e.motion.xrel), float(e.motion.yrel));
      break;
    case SDL_MOUSEWHEEL:
      if (!io.WantCaptureMouse) app.camera.zoom(float(e.wheel.y));
      break;
    case SDL_KEYDOWN:
      if (io.WantCaptureKeyboard) break;
      switch (e.key.keysym.sym) {
        case SDLK_DELETE:
        case SDLK_BACKSPACE:
          delete_marker(app, app.view.selected_marker ? app.view.selected_marker : app.view.hovered_marker);
          break;
        case SDLK_1: app.tool = Tool::Draw; break;
        case SDLK_2: app.tool = Tool::Transition; break;
        case SDLK_3: app.tool = Tool::Splice; break;
        case SDLK_f: app.camera.follow = !app.camera.follow; break;
        case SDLK_h: app.hud = !app.hud; break;
        case SDLK_k: app.view.show_skeleton = !app.view.show_skeleton || !app.renderer.has_body(); break;
        case SDLK_SPACE: app.paused = !app.paused; break;
        case SDLK_ESCAPE: app.quit = true; break;
        case SDLK_F12: app.want_screenshot = true; break;
        default: break;
      }
      break;
    default:
      break;
  }
}
