// renderer.cpp - shaders, meshes and draw order of the demo scene.
#include "renderer.h"

#include "gl_api.h"
#include "palette.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

using namespace demo_gl;

namespace {

// Light travels along kLightDir; mostly from above so shadows stay compact
// and readable under the feet.
const glm::vec3 kLightDir = glm::normalize(glm::vec3(-0.35f, -1.0f, -0.25f));

const char* kLitVS = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;
layout(location = 6) in vec4 i_colour;
uniform mat4 u_view_proj;
uniform mat4 u_flatten;   // identity, or the planar shadow projection
out vec3 v_normal;
out vec3 v_world;
out vec4 v_colour;
void main() {
  vec4 w = u_flatten * (i_model * vec4(a_position, 1.0));
  v_world = w.xyz / w.w;
  // Instances are scaled uniformly across the normal's plane, so the
  // model matrix itself maps normals correctly after normalising.
  v_normal = mat3(i_model) * a_normal;
  v_colour = i_colour;
  gl_Position = u_view_proj * w;
}
)";

const char* kLitFS = R"(#version 330 core
in vec3 v_normal;
in vec3 v_world;
in vec4 v_colour;
uniform int u_shadow;
uniform vec3 u_light_dir;
uniform vec3 u_eye;
uniform vec3 u_sky;
out vec4 frag;
void main() {
  if (u_shadow == 1) { frag = vec4(0.0, 0.0, 0.05, 0.38); return; }
  vec3 n = normalize(v_normal);
  float diffuse = max(dot(n, -u_light_dir), 0.0);
  float hemi = 0.5 + 0.5 * n.y;                 // sky above, ground below
  vec3 v = normalize(u_eye - v_world);
  float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0);
  vec3 c = v_colour.rgb * (0.30 + 0.22 * hemi + 0.62 * diffuse) + 0.10 * rim;
  float fog = clamp((length(u_eye - v_world) - 60.0) / 140.0, 0.0, 1.0);
  frag = vec4(mix(c, u_sky, fog), v_colour.a);
}
)";

// Linear-blend skinning with up to 4 joints per vertex. Each skinning
// matrix is stored as its 3 affine rows (3 texels); instance i's joints
// start at texel 3 * i * u_joint_count of u_joints. Blending the rows
// first skins the position with 3 dot products.
// Colours: lower body, upper body (per instance) and skin, blended by the
// vertex's material (0..2), lightened by the instance's ghost factor (strobe trail).
const char* kBodyVS = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in uvec4 a_joints;
layout(location = 3) in vec4 a_weights;
layout(location = 4) in float a_material;
layout(location = 5) in vec4 i_lower;
layout(location = 6) in vec4 i_upper;
uniform samplerBuffer u_joints;
uniform int u_joint_count;
uniform mat4 u_view_proj;
uniform mat4 u_flatten;
uniform vec3 u_skin;
out vec3 v_normal;
out vec3 v_world;
out vec4 v_colour;
void main() {
  int base = 3 * gl_InstanceID * u_joint_count;
  vec4 r0 = vec4(0.0), r1 = vec4(0.0), r2 = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    int t = base + 3 * int(a_joints[k]);
    r0 += a_weights[k] * texelFetch(u_joints, t);
    r1 += a_weights[k] * texelFetch(u_joints, t + 1);
    r2 += a_weights[k] * texelFetch(u_joints, t + 2);
  }
  vec4 p = vec4(a_position, 1.0);
  vec4 w = u_flatten * vec4(dot(r0, p), dot(r1, p), dot(r2, p), 1.0);
  v_world = w.xyz / w.w;
  v_normal = vec3(dot(r0.xyz, a_normal), dot(r1.xyz, a_normal), dot(r2.xyz, a_normal));
  vec3 c = mix(mix(i_lower.rgb, i_upper.rgb, clamp(a_material, 0.0, 1.0)), u_skin, clamp(a_material - 1.0, 0.0, 1.0));
  v_colour = vec4(c + (vec3(1.0) - c) * i_upper.a, 1.0);
  gl_Position = u_view_proj * w;
}
)";

const char* kGroundVS = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_proj;
uniform vec3 u_centre;
out vec3 v_world;
void main() {
  v_world = a_position + vec3(u_centre.x, 0.0, u_centre.z);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

// Grid lines every metre, stronger every 5 m, antialiased with fwidth; the
// x and z axes are tinted so the origin is easy to find.
const char* kGroundFS = R"(#version 330 core
in vec3 v_world;
uniform vec3 u_eye;
uniform vec3 u_sky;
out vec4 frag;
float grid(vec2 p, float spacing, float width) {
  vec2 q = p / spacing;
  vec2 d = abs(fract(q - 0.5) - 0.5) / (fwidth(q) * width);
  return 1.0 - min(min(d.x, d.y), 1.0);
}
void main() {
  vec2 p = v_world.xz;
  vec3 c = vec3(0.60, 0.62, 0.64);
  c = mix(c, vec3(0.47, 0.49, 0.52), grid(p, 1.0, 1.0) * 0.7);
  c = mix(c, vec3(0.36, 0.38, 0.42), grid(p, 5.0, 1.6) * 0.8);
  vec2 axis = abs(p) / (fwidth(p) * 1.5);
  c = mix(c, vec3(0.55, 0.40, 0.40), (1.0 - min(axis.y, 1.0)) * 0.6);
  c = mix(c, vec3(0.40, 0.45, 0.58), (1.0 - min(axis.x, 1.0)) * 0.6);
  float fog = clamp((length(u_eye - v_world) - 50.0) / 150.0, 0.0, 1.0);
  frag = vec4(mix(c, u_sky, fog), 1.0);
}
)";

const char* kFlatVS = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;
uniform mat4 u_view_proj;
out vec4 v_colour;
void main() {
  v_colour = a_colour;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

const char* kFlatFS = R"(#version 330 core
in vec4 v_colour;
out vec4 frag;
void main() { frag = v_colour; }
)";

unsigned compile(GLenum type, const char* source, std::string* error) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetShaderInfoLog(s, sizeof log - 1, nullptr, log);
    *error = std::string("shader compile failed: ") + log;
    glDeleteShader(s);
    return 0;
  }
  return s;
}

unsigned link(const char* vs, const char* fs, std::string* error) {
  GLuint v = compile(GL_VERTEX_SHADER, vs, error);
  if (!v) return 0;
  GLuint f = compile(GL_FRAGMENT_SHADER, fs, error);
  if (!f) {
    glDeleteShader(v);
    return 0;
  }
  GLuint p = glCreateProgram();
  glAttachShader(p, v);
  glAttachShader(p, f);
  glLinkProgram(p);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetProgramInfoLog(p, sizeof log - 1, nullptr, log);
    *error = std::string("shader link failed: ") + log;
    glDeleteProgram(p);
    return 0;
  }
  return p;
}

GLint loc(unsigned program, const char* name) { return glGetUniformLocation(program, name); }

// Unit sphere (radius 1) as interleaved position+normal.
void sphere_mesh(std::vector<float>* v, std::vector<unsigned>* idx) {
  // Small enough for Mesa's software rasteriser with 100 characters.
  const int rings = 6, segments = 10;
  for (int r = 0; r <= rings; ++r) {
    float phi = float(M_PI) * float(r) / rings;
    for (int s = 0; s <= segments; ++s) {
      float theta = 2.0f * float(M_PI) * float(s) / segments;
      glm::vec3 n(std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta));
      v->insert(v->end(), {n.x, n.y, n.z, n.x, n.y, n.z});
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      unsigned a = unsigned(r * (segments + 1) + s), b = a + unsigned(segments + 1);
      idx->insert(idx->end(), {a, a + 1, b, b, a + 1, b + 1});
    }
}

// Open cylinder of radius 1 from y = 0 to y = 1 (spheres close the ends).
void cylinder_mesh(std::vector<float>* v, std::vector<unsigned>* idx) {
  const int segments = 10;
  for (int s = 0; s <= segments; ++s) {
    float theta = 2.0f * float(M_PI) * float(s) / segments;
    float x = std::cos(theta), z = std::sin(theta);
    v->insert(v->end(), {x, 0.0f, z, x, 0.0f, z});
    v->insert(v->end(), {x, 1.0f, z, x, 0.0f, z});
  }
  for (int s = 0; s < segments; ++s) {
    unsigned a = unsigned(2 * s);
    idx->insert(idx->end(), {a, a + 1, a + 2, a + 2, a + 1, a + 3});
  }
}

// y = eps plane projection along the light direction, column-major.
glm::mat4 flatten_matrix(glm::vec3 l, float eps) {
  glm::mat4 m(1.0f);
  m[1][0] = -l.x / l.y;
  m[1][1] = 0.0f;
  m[1][2] = -l.z / l.y;
  m[3][0] = l.x / l.y * eps;
  m[3][1] = eps;
  m[3][2] = l.z / l.y * eps;
  return m;
}

}  // namespace

bool Renderer::build_mesh(Mesh* mesh, const std::vector<float>& vertices, const std::vector<unsigned>& indices) {
  glGenVertexArrays(1, &mesh->vao);
  glBindVertexArray(mesh->vao);
  glGenBuffers(1, &mesh->vbo);
  glBindBuffer(GL_ARRAY_BUFFER, mesh->vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  glGenBuffers(1, &mesh->ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(unsigned)), indices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &mesh->instance_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, mesh->instance_vbo);
  for (int c = 0; c < 4; ++c) {
    glEnableVertexAttribArray(GLuint(2 + c));
    glVertexAttribPointer(GLuint(2 + c), 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<void*>(offsetof(Instance, model) + sizeof(glm::vec4) * size_t(c)));
    glVertexAttribDivisor(GLuint(2 + c), 1);
  }
  glEnableVertexAttribArray(6);
  glVertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, sizeof(Instance), reinterpret_cast<void*>(offsetof(Instance, colour)));
  glVertexAttribDivisor(6, 1);
  glBindVertexArray(0);
  mesh->index_count = int(indices.size());
  return true;
}

bool Renderer::init(std::string* error) {
  lit_program_ = link(kLitVS, kLitFS, error);
  if (!lit_program_) return false;
  ground_program_ = link(kGroundVS, kGroundFS, error);
  if (!ground_program_) return false;
  flat_program_ = link(kFlatVS, kFlatFS, error);
  if (!flat_program_) return false;
  body_program_ = link(kBodyVS, kLitFS, error);
  if (!body_program_) return false;

  std::vector<float> v;
  std::vector<unsigned> i;
  sphere_mesh(&v, &i);
  build_mesh(&sphere_, v, i);
  v.clear();
  i.clear();
  cylinder_mesh(&v, &i);
  build_mesh(&cylinder_, v, i);

  // Ground: a 500 m square that moves with the camera target.
  const float h = 250.0f;
  const float quad[] = {-h, 0, -h, h, 0, -h, h, 0, h, -h, 0, -h, h, 0, h, -h, 0, h};
  glGenVertexArrays(1, &ground_vao_);
  glBindVertexArray(ground_vao_);
  glGenBuffers(1, &ground_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);

  glGenVertexArrays(1, &flat_vao_);
  glBindVertexArray(flat_vao_);
  glGenBuffers(1, &flat_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, flat_vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(FlatVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(FlatVertex),
                        reinterpret_cast<void*>(offsetof(FlatVertex, colour)));
  glBindVertexArray(0);
  if (glGetError() != GL_NO_ERROR) {
    *error = "OpenGL error while creating the renderer's resources";
    return false;
  }
  return true;
}

void Renderer::shutdown() {
  for (Mesh* m : {&sphere_, &cylinder_}) {
    glDeleteVertexArrays(1, &m->vao);
    glDeleteBuffers(1, &m->vbo);
    glDeleteBuffers(1, &m->ibo);
    glDeleteBuffers(1, &m->instance_vbo);
  }
  glDeleteVertexArrays(1, &ground_vao_);
  glDeleteBuffers(1, &ground_vbo_);
  glDeleteVertexArrays(1, &flat_vao_);
  glDeleteBuffers(1, &flat_vbo_);
  glDeleteProgram(lit_program_);
  glDeleteProgram(ground_program_);
  glDeleteProgram(flat_program_);
  glDeleteProgram(body_program_);
  for (BodyLod& lod : lods_) {
    glDeleteVertexArrays(1, &lod.vao);
    for (unsigned b : {lod.vbo, lod.ibo, lod.instance_vbo}) glDeleteBuffers(1, &b);
  }
  glDeleteBuffers(1, &joint_tbo_);
  glDeleteTextures(1, &joint_texture_);
}

bool Renderer::set_body(const BodyMesh& detailed, const BodyMesh& coarse, std::string* error) {
  const BodyMesh* meshes[2] = {&detailed, &coarse};
  for (int l = 0; l < 2; ++l) {
    const BodyMesh& mesh = *meshes[l];
    BodyLod& lod = lods_[l];
    if (!lod.vao) {
      glGenVertexArrays(1, &lod.vao);
      glGenBuffers(1, &lod.vbo);
      glGenBuffers(1, &lod.ibo);
      glGenBuffers(1, &lod.instance_vbo);
    }
    glBindVertexArray(lod.vao);
    glBindBuffer(GL_ARRAY_BUFFER, lod.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(BodyVertex)), mesh.vertices.data(),
                 GL_STATIC_DRAW);
    const GLsizei stride = sizeof(BodyVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 4, GL_UNSIGNED_SHORT, stride, reinterpret_cast<void*>(offsetof(BodyVertex, joints)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, weights)));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, material)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, lod.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, lod.instance_vbo);
    for (int c = 0; c < 2; ++c) {
      glEnableVertexAttribArray(GLuint(5 + c));
      glVertexAttribPointer(GLuint(5 + c), 4, GL_FLOAT, GL_FALSE, sizeof(BodyColours),
                            reinterpret_cast<void*>(sizeof(glm::vec4) * size_t(c)));
      glVertexAttribDivisor(GLuint(5 + c), 1);
    }
    glBindVertexArray(0);
    lod.index_count = int(mesh.indices.size());
  }
  if (!joint_tbo_) {
    glGenBuffers(1, &joint_tbo_);
    glGenTextures(1, &joint_texture_);
  }
  body_joints_ = int(detailed.inverse_bind.size());
  body_height_ = detailed.height;
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  max_body_instances_ = body_joints_ > 0 ? int(max_texels / (3 * body_joints_)) : 0;
  if (max_body_instances_ < 1 || coarse.inverse_bind.size() != detailed.inverse_bind.size() ||
      glGetError() != GL_NO_ERROR) {
    *error = "cannot upload the body meshes (" + std::to_string(body_joints_) + " joints, texture buffers of " +
             std::to_string(max_texels) + " texels)";
    for (BodyLod& lod : lods_) lod.index_count = 0;
    return false;
  }
  return true;
}

void Renderer::begin(int width, int height, const OrbitCamera& camera) {
  width_ = width;
  height_ = height;
  glm::mat4 projection = camera.projection(float(width) / float(height > 0 ? height : 1));
  proj_y_ = projection[1][1];
  view_proj_ = projection * camera.view();
  eye_ = camera.eye();
  target_ = camera.target;
  spheres_.clear();
  shadow_spheres_.clear();
  cylinders_.clear();
  decals_.clear();
  for (BodyLod& lod : lods_) {
    lod.rows.clear();
    lod.colours.clear();
  }
}

void Renderer::body(const glm::mat4* skin, glm::vec3 centre, glm::vec3 lower, glm::vec3 upper, float ghost) {
  if (!has_body()) return;
  // Bodies under kCoarseBelow pixels tall take the coarse mesh, whose
  // cells are then a few pixels: the same picture for half the work.
  const float kCoarseBelow = 150.0f;
  glm::vec4 clip = view_proj_ * glm::vec4(centre, 1.0f);
  float pixels = clip.w > 1e-4f ? body_height_ * proj_y_ / clip.w * 0.5f * float(height_) : 1e9f;
  BodyLod& lod = lods_[pixels < kCoarseBelow ? 1 : 0];
  for (int j = 0; j < body_joints_; ++j) {
    glm::mat4 t = glm::transpose(skin[j]);  // rows; the 4th is (0 0 0 1)
    lod.rows.insert(lod.rows.end(), {t[0], t[1], t[2]});
  }
  lod.colours.push_back({glm::vec4(lower, 0.0f), glm::vec4(upper, ghost)});
}

// Draws every queued body, per level of detail as many per instanced draw
// as the texture buffer holds.
void Renderer::draw_bodies(bool shadow) {
  if (lods_[0].colours.empty() && lods_[1].colours.empty()) return;
  glUseProgram(body_program_);
  glUniformMatrix4fv(loc(body_program_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj_));
  glUniform3fv(loc(body_program_, "u_light_dir"), 1, glm::value_ptr(kLightDir));
  glUniform3fv(loc(body_program_, "u_eye"), 1, glm::value_ptr(eye_));
  glUniform3fv(loc(body_program_, "u_sky"), 1, glm::value_ptr(kSkyColour));
  glUniform3fv(loc(body_program_, "u_skin"), 1, glm::value_ptr(kSkinColour));
  glm::mat4 flatten = shadow ? flatten_matrix(kLightDir, 0.003f) : glm::mat4(1.0f);
  glUniformMatrix4fv(loc(body_program_, "u_flatten"), 1, GL_FALSE, glm::value_ptr(flatten));
  glUniform1i(loc(body_program_, "u_shadow"), shadow ? 1 : 0);
  glUniform1i(loc(body_program_, "u_joint_count"), body_joints_);
  glUniform1i(loc(body_program_, "u_joints"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, joint_texture_);
  for (const BodyLod& lod : lods_) {
    glBindVertexArray(lod.vao);
    const size_t total = lod.colours.size();
    for (size_t first = 0; first < total; first += size_t(max_body_instances_)) {
      size_t count = std::min(total - first, size_t(max_body_instances_));
      glBindBuffer(GL_TEXTURE_BUFFER, joint_tbo_);
      glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(count * size_t(body_joints_) * 3 * sizeof(glm::vec4)),
                   &lod.rows[first * size_t(body_joints_) * 3], GL_STREAM_DRAW);
      glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, joint_tbo_);
      glBindBuffer(GL_ARRAY_BUFFER, lod.instance_vbo);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * sizeof(BodyColours)), &lod.colours[first], GL_STREAM_DRAW);
      glDrawElementsInstanced(GL_TRIANGLES, lod.index_count, GL_UNSIGNED_INT, nullptr, GLsizei(count));
    }
  }
  glBindTexture(GL_TEXTURE_BUFFER, 0);
}

void Renderer::sphere(glm::vec3 c, float r, glm::vec4 colour, bool casts_shadow) {
  glm::mat4 m(r);
  m[3] = glm::vec4(c, 1.0f);
  spheres_.push_back({m, colour});
  if (casts_shadow) shadow_spheres_.push_back({m, colour});
}

void Renderer::cylinder(glm::vec3 a, glm::vec3 b, float r, glm::vec4 colour) {
  glm::vec3 d = b - a;
  float len = glm::length(d);
  if (!(len > 1e-5f)) return;
  glm::vec3 y = d / len;
  // Any axis not parallel to y gives an orthonormal frame.
  glm::vec3 helper = std::fabs(y.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  glm::vec3 x = glm::normalize(glm::cross(helper, y));
  glm::vec3 z = glm::cross(x, y);
  glm::mat4 m;
  m[0] = glm::vec4(x * r, 0.0f);
  m[1] = glm::vec4(d, 0.0f);
  m[2] = glm::vec4(z * r, 0.0f);
  m[3] = glm::vec4(a, 1.0f);
  cylinders_.push_back({m, colour});
}

void Renderer::draw_instances(const Mesh& mesh, const std::vector<Instance>& instances) {
  if (instances.empty()) return;
  glBindVertexArray(mesh.vao);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.instance_vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size() * sizeof(Instance)), instances.data(), GL_STREAM_DRAW);
  glDrawElementsInstanced(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr, GLsizei(instances.size()));
}

void Renderer::end() {
  glViewport(0, 0, width_, height_);
  glClearColor(kSkyColour.r, kSkyColour.g, kSkyColour.b, 1.0f);
  glClearStencil(0);
  glStencilMask(0xff);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);

  // 1. Ground.
  glUseProgram(ground_program_);
  glUniformMatrix4fv(loc(ground_program_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj_));
  glUniform3fv(loc(ground_program_, "u_centre"), 1, glm::value_ptr(target_));
  glUniform3fv(loc(ground_program_, "u_eye"), 1, glm::value_ptr(eye_));
  glUniform3fv(loc(ground_program_, "u_sky"), 1, glm::value_ptr(kSkyColour));
  glBindVertexArray(ground_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 6);

  // 2. Decals on the ground: pulled towards the camera so they win the
  // depth test against the ground, never written to depth.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-2.0f, -4.0f);
  if (!decals_.empty()) {
    glUseProgram(flat_program_);
    glUniformMatrix4fv(loc(flat_program_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj_));
    glBindVertexArray(flat_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, flat_vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(decals_.size() * sizeof(FlatVertex)), decals_.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(decals_.size()));
  }

  // 3. Planar shadows; the stencil lets each pixel darken only once where
  // several bones overlap.
  glUseProgram(lit_program_);
  glUniformMatrix4fv(loc(lit_program_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj_));
  glUniform3fv(loc(lit_program_, "u_light_dir"), 1, glm::value_ptr(kLightDir));
  glUniform3fv(loc(lit_program_, "u_eye"), 1, glm::value_ptr(eye_));
  glUniform3fv(loc(lit_program_, "u_sky"), 1, glm::value_ptr(kSkyColour));
  glm::mat4 flatten = flatten_matrix(kLightDir, 0.003f);
  glUniformMatrix4fv(loc(lit_program_, "u_flatten"), 1, GL_FALSE, glm::value_ptr(flatten));
  glUniform1i(loc(lit_program_, "u_shadow"), 1);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  draw_instances(sphere_, shadow_spheres_);
  draw_instances(cylinder_, cylinders_);
  // A flattened body seen from above keeps the winding of its light-facing
  // side: culling the rest rasterises each shadow once instead of twice.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  draw_bodies(true);
  glDisable(GL_CULL_FACE);
  glUseProgram(lit_program_);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);

  // 4. Lit meshes.
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glm::mat4 identity(1.0f);
  glUniformMatrix4fv(loc(lit_program_, "u_flatten"), 1, GL_FALSE, glm::value_ptr(identity));
  glUniform1i(loc(lit_program_, "u_shadow"), 0);
  draw_instances(sphere_, spheres_);
  draw_instances(cylinder_, cylinders_);
  // Bodies are closed and wound outward: culling halves the fragment work.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  draw_bodies(false);
  glDisable(GL_CULL_FACE);

  glBindVertexArray(0);
  glUseProgram(0);
  last_instances_ = int(spheres_.size() + cylinders_.size());
}
