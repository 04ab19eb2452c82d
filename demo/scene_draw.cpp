// scene_draw.cpp - what the demo scene looks like.
#include "scene_draw.h"

#include "palette.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr float kDecalY = 0.004f;

void quad(std::vector<FlatVertex>& out, glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, glm::vec4 col) {
  auto v = [&](glm::vec2 p) { out.push_back({glm::vec3(p.x, kDecalY, p.y), col}); };
  v(a); v(b); v(c);
  v(a); v(c); v(d);
}

void disc(std::vector<FlatVertex>& out, glm::vec2 c, float r, glm::vec4 col, int segments = 12) {
  for (int i = 0; i < segments; ++i) {
    float a0 = 2.0f * float(M_PI) * float(i) / float(segments), a1 = 2.0f * float(M_PI) * float(i + 1) / float(segments);
    out.push_back({glm::vec3(c.x, kDecalY, c.y), col});
    out.push_back({glm::vec3(c.x + r * std::cos(a0), kDecalY, c.y + r * std::sin(a0)), col});
    out.push_back({glm::vec3(c.x + r * std::cos(a1), kDecalY, c.y + r * std::sin(a1)), col});
  }
}

void ring(std::vector<FlatVertex>& out, glm::vec2 c, float r0, float r1, glm::vec4 col) {
  const int segments = 24;
  for (int i = 0; i < segments; ++i) {
    float a0 = 2.0f * float(M_PI) * float(i) / segments, a1 = 2.0f * float(M_PI) * float(i + 1) / segments;
    glm::vec2 u0(std::cos(a0), std::sin(a0)), u1(std::cos(a1), std::sin(a1));
    quad(out, c + u0 * r0, c + u0 * r1, c + u1 * r1, c + u1 * r0, col);
  }
}

// Path ribbon from `offset` copy of the base path; segments coloured by the
// style in force there, split exactly at transition markers.
void path_ribbon(std::vector<FlatVertex>& out, const World& world, glm::vec2 offset, float width, float alpha,
                 bool joins) {
  const Polyline& p = world.path();
  if (p.size() < 2) {
    if (p.size() == 1) disc(out, p.points()[0] + offset, width, glm::vec4(world.style_colour_of(0), alpha));
    return;
  }
  std::vector<float> cuts;
  for (const Marker& m : world.markers())
    if (m.kind == MarkerKind::Transition) cuts.push_back(m.arc_length);
  std::sort(cuts.begin(), cuts.end());
  float h = width * 0.5f;
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    float s0 = p.arc_length_at(i), s1 = p.arc_length_at(i + 1);
    // Split this segment at any transition inside it.
    float a = s0;
    auto it = std::upper_bound(cuts.begin(), cuts.end(), s0);
    while (a < s1) {
      float b = (it != cuts.end() && *it < s1) ? *it : s1;
      if (it != cuts.end() && *it < s1) ++it;
      glm::vec2 dir;
      glm::vec2 pa = p.point_at(a, &dir) + offset, pb = p.point_at(b) + offset;
      glm::vec2 n(-dir.y * h, dir.x * h);
      glm::vec4 col(world.style_colour_of(world.style_at(0.5f * (a + b))), alpha);
      quad(out, pa - n, pa + n, pb + n, pb - n, col);
      if (joins && i > 0 && a == s0) disc(out, pa, h, col, 8);
      a = b;
    }
  }
}

glm::vec3 joint(const Character& c, size_t j) {
  const float* m = &c.matrices[j * 16 + 12];
  return glm::vec3(m[0], m[1], m[2]);
}

glm::vec3 lighten(glm::vec3 c, float k) { return c + (glm::vec3(1.0f) - c) * k; }

// Capsule skeleton: bones coloured by style (lower body) or action (upper
// body; action 0 keeps the style colour), skin-coloured joints and head, a
// planted foot drawn white.
void skeleton(Renderer& r, const World& world, const std::vector<glm::vec3>& pos, uint32_t style, uint32_t action,
              uint32_t contact_flags, float ghost) {
  const JointLayout& L = world.joints();
  glm::vec3 lower = world.style_colour_of(style);
  glm::vec3 upper = action == 0 ? lower : world.action_colour_of(action);
  glm::vec3 skin = kSkinColour;
  if (ghost > 0.0f) {
    lower = lighten(lower, ghost);
    upper = lighten(upper, ghost);
    skin = lighten(skin, ghost);
  }
  for (size_t j = 0; j < pos.size(); ++j) {
    int p = L.parent[j];
    if (p < 0 || L.skip[j]) continue;
    // Zero-length helper bones (CMU LHipJoint, Neck, ...) draw nothing.
    if (glm::length(pos[j] - pos[size_t(p)]) < 1e-3f) continue;
    float radius = L.radius[size_t(p)];
    glm::vec3 col = L.body_part[size_t(p)] == SMG_BODY_UPPER ? upper : lower;
    bool left_foot = int(p) == L.left_foot || int(p) == L.left_toe;
    bool right_foot = int(p) == L.right_foot || int(p) == L.right_toe;
    if ((left_foot && (contact_flags & SMG_STATE_LEFT_CONTACT)) ||
        (right_foot && (contact_flags & SMG_STATE_RIGHT_CONTACT)))
      col = lighten(col, 0.75f);
    r.cylinder(pos[size_t(p)], pos[j], radius * 0.8f, glm::vec4(col, 1.0f));
    r.sphere(pos[j], radius * 0.8f, glm::vec4(skin, 1.0f), false);
  }
  if (!pos.empty()) r.sphere(pos[0], 0.085f, glm::vec4(lower, 1.0f));
  if (L.head >= 0) {
    glm::vec3 up(0.0f, 1.0f, 0.0f);
    if (L.neck >= 0) {
      glm::vec3 d = pos[size_t(L.head)] - pos[size_t(L.neck)];
      if (glm::length(d) > 1e-4f) up = glm::normalize(d);
    }
    r.sphere(pos[size_t(L.head)] + up * 0.07f, 0.11f, glm::vec4(skin, 1.0f));
  }
}

// The generated body posed by world-space model matrices, coloured like the
// capsules: lower body by style, upper body by action (style for none).
void body(Renderer& r, const World& world, const std::vector<float>& matrices, uint32_t style, uint32_t action,
          float ghost, std::vector<glm::mat4>* skin) {
  glm::vec3 lower = world.style_colour_of(style);
  glm::vec3 upper = action == 0 ? lower : world.action_colour_of(action);
  skin->resize(world.body().inverse_bind.size());
  body_skin_matrices(world.body(), matrices.data(), skin->data());
  glm::vec3 root(matrices[12], matrices[13], matrices[14]);
  r.body(skin->data(), root, lower, upper, ghost);
}

}  // namespace

glm::vec3 marker_base(const World& world, const Marker& m) {
  glm::vec2 p = world.path().point_at(m.arc_length);
  return glm::vec3(p.x, 0.0f, p.y);
}

glm::vec3 marker_top(const Marker& m, glm::vec3 base) {
  return base + glm::vec3(0.0f, m.kind == MarkerKind::Splice ? 1.1f : 0.7f, 0.0f);
}

void draw_scene(Renderer& r, const World& world, const SceneView& view) {
  std::vector<FlatVertex>& decals = r.decals();
  const auto& chars = world.characters();

  // Footprints first so the path draws over them.
  if (view.show_footprints) {
    for (const Character& c : chars) {
      for (const Footprint& f : c.footprints) {
        if (f.age > 8.0f) continue;
        float a = 0.55f * (1.0f - f.age / 8.0f);
        glm::vec2 d = f.toe - f.heel;
        float len = glm::length(d);
        glm::vec2 u = len > 1e-4f ? d / len : glm::vec2(0, 1);
        glm::vec2 n(-u.y, u.x);
        glm::vec2 heel = f.heel - u * 0.05f, toe = f.toe + u * 0.06f;
        glm::vec4 col = f.left ? glm::vec4(0.10f, 0.10f, 0.16f, a) : glm::vec4(0.16f, 0.10f, 0.10f, a);
        quad(decals, heel - n * 0.035f, heel + n * 0.035f, toe + n * 0.05f, toe - n * 0.05f, col);
      }
    }
  }

  // Other characters' copies of the path: thin and faint.
  if (view.show_path_copies && chars.size() > 1)
    for (size_t i = 1; i < chars.size(); ++i) path_ribbon(decals, world, chars[i].offset, 0.05f, 0.35f, false);
  path_ribbon(decals, world, glm::vec2(0.0f), 0.14f, 1.0f, true);
  if (!world.path().empty()) {
    disc(decals, world.path().points().front(), 0.16f, glm::vec4(0.15f, 0.15f, 0.18f, 1.0f));
    glm::vec2 dir;
    glm::vec2 end = world.path().point_at(world.path().length(), &dir);
    glm::vec2 n(-dir.y, dir.x);
    glm::vec4 col(world.style_colour_of(world.style_at(world.path().length())), 1.0f);
    decals.push_back({glm::vec3(end.x + n.x * 0.22f, kDecalY, end.y + n.y * 0.22f), col});
    decals.push_back({glm::vec3(end.x - n.x * 0.22f, kDecalY, end.y - n.y * 0.22f), col});
    decals.push_back({glm::vec3(end.x + dir.x * 0.35f, kDecalY, end.y + dir.y * 0.35f), col});
  }

  // Markers: transitions are short poles in the new style's colour,
  // splices taller poles with a ball in the action's colour.
  // Markers live on the path; with no path (cleared) they wait unseen.
  for (const Marker& m : world.path().size() < 2 ? std::vector<Marker>() : world.markers()) {
    glm::vec3 base = marker_base(world, m), top = marker_top(m, base);
    glm::vec3 col = m.kind == MarkerKind::Transition ? world.style_colour_of(m.value) : world.action_colour_of(m.value);
    bool sel = m.uid == view.selected_marker, hov = m.uid == view.hovered_marker;
    glm::vec2 g(base.x, base.z);
    ring(decals, g, 0.18f, 0.30f, glm::vec4(col, 1.0f));
    if (sel || hov) ring(decals, g, 0.34f, sel ? 0.44f : 0.39f, glm::vec4(1.0f, 1.0f, 1.0f, sel ? 1.0f : 0.6f));
    r.cylinder(base, top, 0.025f, glm::vec4(0.25f, 0.25f, 0.28f, 1.0f));
    r.sphere(top, m.kind == MarkerKind::Splice ? 0.13f : 0.09f, glm::vec4(col, 1.0f));
  }

  // Strobe trail of character 0 (Fig. 4 of the paper).
  const bool bodies = !view.show_skeleton && r.has_body();
  std::vector<glm::mat4> skin;
  for (const TrailPose& t : world.trail()) {
    if (bodies) body(r, world, t.matrices, t.style, t.action, 0.45f, &skin);
    else skeleton(r, world, t.joints, t.style, t.action, 0, 0.45f);
  }
  if (bodies) {
    for (const Character& c : chars) body(r, world, c.matrices, c.state.style, c.state.action, 0.0f, &skin);
    return;
  }
  std::vector<glm::vec3> pos(world.joint_count());
  for (const Character& c : chars) {
    for (size_t j = 0; j < pos.size(); ++j) pos[j] = joint(c, j);
    skeleton(r, world, pos, c.state.style, c.state.action, c.state.flags, 0.0f);
  }
}
