// hud.cpp - the ImGui heads-up display: measurements (frame time, runtime
// cost per character, current style/action, distance from the path) and
// the tools and controls.
#include "app.h"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace {

ImVec4 colour(glm::vec3 c) { return ImVec4(c.r, c.g, c.b, 1.0f); }

const char* kMicro = "\xC2\xB5s";  // "µs" in UTF-8 (the default font has it)

void stats(App& app) {
  const World& w = app.world;
  const smg_graph_info& info = w.info();
  if (app.headless)  // pictures: only the simulation runs per frame
    ImGui::Text("headless: %.3f ms per simulated frame   sim %.1f s", app.frame_ms, w.sim_time());
  else
    ImGui::Text("frame %.2f ms (%.0f fps)   sim %.1f s%s", app.frame_ms,
                app.frame_ms > 0 ? 1000.0 / app.frame_ms : 0.0, w.sim_time(), app.paused ? "  [paused]" : "");
  ImGui::Text("step+pose %.1f %s/character (max %.1f)", app.step_us_avg, kMicro, app.step_us_max);
  ImGui::Text("characters %d   total %.0f %s/frame", int(w.characters().size()),
              app.step_us_avg * double(w.characters().size()), kMicro);
  ImGui::TextDisabled("graph: %u joints, %u styles, %u actions, %u frames, %.0f Hz", info.joint_count,
                      info.style_count, info.action_count, info.frame_count, double(info.frame_rate));
  if (w.characters().empty()) return;
  const smg_character_state& s = w.characters()[0].state;
  ImGui::Separator();
  ImGui::Text("style");
  ImGui::SameLine();
  ImGui::TextColored(colour(w.style_colour_of(s.style)), "%s", w.style_name(s.style));
  ImGui::SameLine();
  ImGui::Text("  action");
  ImGui::SameLine();
  ImGui::TextColored(colour(w.action_colour_of(s.action)), "%s", w.action_name(s.action));
  ImGui::Text("distance from path %.3f m", double(s.path_error));
  ImGui::Text("along path %.2f / %.2f m   feet %s%s", double(s.path_distance), double(w.path().length()),
              (s.flags & SMG_STATE_LEFT_CONTACT) ? "L" : "-", (s.flags & SMG_STATE_RIGHT_CONTACT) ? "R" : "-");
  // What the root steering adds to the motion (smg_character_state).
  ImGui::Text("steering %.1f deg/s  %.1f cm/s   playback %.2fx", double(s.steer_turn_rate) * 57.29578,
              double(s.steer_slide_speed) * 100.0, double(s.playback_rate));
  if (s.flags & SMG_STATE_PATH_END_REACHED) ImGui::TextDisabled("(end of path reached)");
}

void tools(App& app) {
  World& w = app.world;
  int tool = int(app.tool);
  ImGui::RadioButton("Draw (1)", &tool, int(Tool::Draw));
  ImGui::SameLine();
  ImGui::RadioButton("Transition (2)", &tool, int(Tool::Transition));
  ImGui::SameLine();
  ImGui::RadioButton("Splice (3)", &tool, int(Tool::Splice));
  app.tool = Tool(tool);

  ImGui::SetNextItemWidth(140);
  if (ImGui::BeginCombo("style##tool", w.style_name(app.tool_style))) {
    for (uint32_t i = 0; i < w.style_count(); ++i) {
      ImGui::PushStyleColor(ImGuiCol_Text, colour(w.style_colour_of(i)));
      if (ImGui::Selectable(w.style_name(i), i == app.tool_style)) {
        app.tool_style = i;
        app.tool = Tool::Transition;
      }
      ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140);
  if (ImGui::BeginCombo("action##tool", w.action_name(app.tool_action))) {
    for (uint32_t i = 0; i < w.action_count(); ++i) {
      ImGui::PushStyleColor(ImGuiCol_Text, colour(w.action_colour_of(i)));
      if (ImGui::Selectable(w.action_name(i), i == app.tool_action)) {
        app.tool_action = i;
        app.tool = Tool::Splice;
      }
      ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }

  // Marker list: drag the distance, or delete.
  int remove = 0;
  for (const Marker& m : w.markers()) {
    ImGui::PushID(m.uid);
    bool t = m.kind == MarkerKind::Transition;
    ImGui::TextColored(colour(t ? w.style_colour_of(m.value) : w.action_colour_of(m.value)), "#%d %s %s", m.uid,
                       t ? "transition" : "splice", t ? w.style_name(m.value) : w.action_name(m.value));
    ImGui::SameLine(220);
    float s = m.arc_length;
    ImGui::SetNextItemWidth(90);
    if (ImGui::DragFloat("m", &s, 0.05f, 0.0f, w.path().length(), "%.2f")) w.move_marker(m.uid, s);
    if (ImGui::IsItemActive()) app.view.selected_marker = m.uid;
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) remove = m.uid;
    ImGui::PopID();
  }
  if (remove) {
    w.remove_marker(remove);
    if (app.view.selected_marker == remove) app.view.selected_marker = 0;
  }
}

void controls(App& app) {
  World& w = app.world;
  float threshold = w.error_threshold();
  if (ImGui::SliderFloat("search threshold (m)", &threshold, 0.02f, 2.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    w.set_error_threshold(threshold);
  bool ik = w.ik();
  if (ImGui::Checkbox("foot IK", &ik)) w.set_ik(ik);
  ImGui::SameLine();
  bool steering = w.steering();
  if (ImGui::Checkbox("steering", &steering)) w.set_steering(steering);
  ImGui::SameLine();
  bool swing = w.swing_clearance();
  if (ImGui::Checkbox("swing clearance", &swing)) w.set_swing_clearance(swing);
  ImGui::SameLine();
  ImGui::Checkbox("follow camera (F)", &app.camera.follow);
  ImGui::SameLine();
  ImGui::Checkbox("pause", &app.paused);
  ImGui::Checkbox("footprints", &app.view.show_footprints);
  ImGui::SameLine();
  ImGui::Checkbox("skeleton (K)", &app.view.show_skeleton);
  ImGui::SameLine();
  if (ImGui::Checkbox("trail", &w.trail_enabled) && !w.trail_enabled) w.clear_trail();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("speed", &app.speed, 0.1f, 2.0f, "%.2fx");
  if (ImGui::Button("clear path")) w.clear_path();
  ImGui::SameLine();
  if (ImGui::Button("clear markers")) w.clear_markers();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputInt("##n", &app.characters_wanted, 1, 10);
  if (app.characters_wanted < 1) app.characters_wanted = 1;
  if (app.characters_wanted > 1000) app.characters_wanted = 1000;
  ImGui::SameLine();
  if (ImGui::Button("respawn")) {
    std::string err;
    if (!w.spawn(app.characters_wanted, &err)) app.status = err;
  }
}

}  // namespace

void draw_hud(App& app) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(470, 0), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.72f);
  ImGui::Begin("libsmg demo", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
  stats(app);
  if (ImGui::CollapsingHeader("tools", ImGuiTreeNodeFlags_DefaultOpen)) tools(app);
  if (ImGui::CollapsingHeader("controls", ImGuiTreeNodeFlags_DefaultOpen)) controls(app);
  if (ImGui::CollapsingHeader("help")) {
    ImGui::TextWrapped(
        "Left drag: draw a path (start near its end to extend it). Transition/Splice tool: click on the path. "
        "Drag a marker to move it; right click or Delete removes it. Right drag: orbit, middle drag: pan, "
        "wheel: zoom. F: follow, Space: pause, H: hide this panel, F12: screenshot.");
  }
  if (!app.status.empty()) ImGui::TextWrapped("%s", app.status.c_str());
  // A runtime error stays on screen for a few seconds, then is cleared.
  static std::string shown;
  static double shown_since = 0.0;
  const std::string& err = app.world.last_error();
  if (err != shown) {
    shown = err;
    shown_since = ImGui::GetTime();
  }
  if (!err.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "runtime: %s", err.c_str());
    if (!app.headless && ImGui::GetTime() - shown_since > 6.0) app.world.clear_error();
  }
  ImGui::End();
}
