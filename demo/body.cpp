// body.cpp - the generated skinned body (see body.h).
//
// Shape rules, all relative to the height S of the bind pose (the rest pose
// or a given pose, see body.h) so that any rig and scale works:
//  * a joint is *branching* when two or more of its child subtrees reach
//    further than 0.2 S (legs and spine at the pelvis, arms at the chest;
//    fingers at a hand do not count). Joints on the chain between branching
//    joints form the torso; joints above the lowest branching joint (a
//    floor-level root bone above the pelvis) carry no geometry.
//  * torso bones get one radius from the hip width (the spread of the
//    limbs leaving the lowest branching joint), flattened front to back;
//  * limb bones are round cones whose radius at a joint grows with the
//    length of the limb still hanging below it (thick thighs, thin wrists),
//    thinner in the upper body, never thinner than 0.6 grid cells;
//  * the highest leaf gets an ellipsoid head;
//  * the soles are cut flat at the lowest joint, where the runtime's foot
//    contacts put the floor.
// Bone p -> c is driven by joint p (the runtime rotates the segment with
// p's rotation). Vertices take the joints of the bones they lie closest to;
// near a joint two bones are about as close, which blends the weights.
#include "body.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace {

struct Primitive {
  glm::vec3 a, b;      // segment
  float ra, rb;        // radius at a and at b
  int joint;           // the joint that moves it
  uint8_t material;
  bool flat;           // torso: flattened along the depth axis
};

struct Shape {
  std::vector<Primitive> prims;
  float floor = -1e9f;       // flat soles: nothing below the lowest joint
  glm::vec3 depth_axis{0.0f, 0.0f, 1.0f};
  float depth_scale = 1.0f;  // > 1 makes the torso thinner along depth_axis
  float blend = 0.0f;        // smooth union radius
};

float prim_distance(const Shape& s, const Primitive& p, glm::vec3 x) {
  glm::vec3 ab = p.b - p.a;
  float len2 = glm::dot(ab, ab);
  float t = len2 > 1e-12f ? glm::clamp(glm::dot(x - p.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  glm::vec3 v = x - (p.a + ab * t);
  if (p.flat) v += s.depth_axis * (glm::dot(v, s.depth_axis) * (s.depth_scale - 1.0f));
  return glm::length(v) - (p.ra + (p.rb - p.ra) * t);
}

float smooth_min(float a, float b, float k) {
  float h = std::max(k - std::fabs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}

// Signed distance-like field: negative inside the body.
float field(const Shape& s, glm::vec3 x) {
  float d = 1e9f;
  for (const Primitive& p : s.prims) d = smooth_min(d, prim_distance(s, p, x), s.blend);
  return std::max(d, s.floor - x.y);
}

glm::vec3 gradient(const Shape& s, glm::vec3 x, float h) {
  glm::vec3 g(field(s, x + glm::vec3(h, 0, 0)) - field(s, x - glm::vec3(h, 0, 0)),
              field(s, x + glm::vec3(0, h, 0)) - field(s, x - glm::vec3(0, h, 0)),
              field(s, x + glm::vec3(0, 0, h)) - field(s, x - glm::vec3(0, 0, h)));
  float l = glm::length(g);
  return l > 1e-12f ? g / l : glm::vec3(0, 1, 0);
}

// The shape of the body around the rest pose (rules in the file comment).
bool make_shape(const BodySkeleton& sk, const std::vector<glm::vec3>& P, float S, float min_radius, Shape* shape,
                std::string* error) {
  const size_t n = P.size();
  std::vector<std::vector<int>> children(n);
  for (size_t j = 1; j < n; ++j)
    if (sk.parent[j] >= 0) children[size_t(sk.parent[j])].push_back(int(j));
  // Reach of the longest chain below each joint.
  std::vector<float> reach(n, 0.0f);
  for (size_t j = n; j-- > 0;)
    for (int c : children[j]) reach[j] = std::max(reach[j], glm::length(sk.rest_offset[size_t(c)]) + reach[size_t(c)]);
  auto branch_reach = [&](int c) { return glm::length(sk.rest_offset[size_t(c)]) + reach[size_t(c)]; };
  // (Bone lengths are the rest offsets' in any pose: FK is rigid.)
  std::vector<uint8_t> branching(n, 0), torso(n, 0), below_branch(n, 0), carrier(n, 0);
  for (size_t j = 0; j < n; ++j) {
    int limbs = 0;
    for (int c : children[j]) limbs += branch_reach(c) > 0.2f * S;
    branching[j] = limbs >= 2;
  }
  // below_branch: some strict ancestor is branching; torso: branching, or
  // between two branching joints (below one, above another).
  std::vector<uint8_t> above_branch(n, 0);  // some descendant (or itself) is branching
  for (size_t j = n; j-- > 0;) {
    above_branch[j] = branching[j];
    for (int c : children[j]) above_branch[j] |= above_branch[size_t(c)];
  }
  for (size_t j = 0; j < n; ++j) {
    int p = sk.parent[j];
    below_branch[j] = p >= 0 && (branching[size_t(p)] || below_branch[size_t(p)]);
    torso[j] = branching[j] || (below_branch[j] && above_branch[j]);
    carrier[j] = above_branch[j] && !branching[j] && !below_branch[j];
  }
  // The first branching joint down the hierarchy (the pelvis of a human).
  int pelvis = -1;
  for (size_t j = 0; j < n && pelvis < 0; ++j)
    if (branching[j]) pelvis = int(j);

  // Torso radius from the hip width: where each non-torso limb leaving the
  // pelvis is 0.04 S away from it.
  float torso_r = 0.065f * S;
  if (pelvis >= 0) {
    std::vector<glm::vec3> starts;
    for (int c : children[size_t(pelvis)]) {
      if (torso[size_t(c)] || branch_reach(c) <= 0.2f * S) continue;
      int k = c;
      while (glm::length(P[size_t(k)] - P[size_t(pelvis)]) < 0.04f * S && !children[size_t(k)].empty())
        k = children[size_t(k)][0];
      starts.push_back(P[size_t(k)]);
    }
    float width = 0.0f;
    glm::vec3 lateral(0.0f);
    for (size_t i = 0; i < starts.size(); ++i)
      for (size_t k = i + 1; k < starts.size(); ++k) {
        glm::vec3 d = starts[k] - starts[i];
        d.y = 0.0f;
        if (glm::length(d) > width) {
          width = glm::length(d);
          lateral = d / std::max(width, 1e-6f);
        }
      }
    if (width > 0.0f) {
      torso_r = glm::clamp(0.75f * width, 0.06f * S, 0.11f * S);
      shape->depth_axis = glm::normalize(glm::cross(lateral, glm::vec3(0, 1, 0)));
      shape->depth_scale = 1.5f;
    }
  }
  std::vector<float> radius(n);
  for (size_t j = 0; j < n; ++j) {
    if (torso[j]) {
      radius[j] = torso_r;
    } else {
      float r = 0.024f * S + 0.05f * reach[j];
      radius[j] = std::max(std::min(r * (sk.upper[j] ? 0.8f : 1.0f), 0.85f * torso_r), min_radius);
    }
  }
  for (size_t c = 0; c < n; ++c) {
    int p = sk.parent[c];
    if (p < 0 || carrier[size_t(p)]) continue;
    if (glm::length(sk.rest_offset[c]) < 1e-4f * S) continue;  // zero-length helper bones
    Primitive pr;
    pr.a = P[size_t(p)];
    pr.b = P[c];
    pr.ra = radius[size_t(p)];
    pr.rb = radius[c];
    pr.joint = p;
    pr.flat = torso[size_t(p)] && torso[c];
    bool hand = sk.upper[size_t(p)] && !torso[size_t(p)] && reach[size_t(p)] < 0.12f * S;
    pr.material = hand ? kBodySkin : sk.upper[size_t(p)] ? kBodyUpper : kBodyLower;
    shape->prims.push_back(pr);
  }
  // Head on the highest leaf (not a carrier: a lone chain has no head).
  int head = -1;
  for (size_t j = 0; j < n; ++j)
    if (children[j].empty() && below_branch[j] && (head < 0 || P[j].y > P[size_t(head)].y)) head = int(j);
  if (head >= 0 && sk.parent[size_t(head)] >= 0) {
    glm::vec3 dir = P[size_t(head)] - P[size_t(sk.parent[size_t(head)])];
    dir = glm::length(dir) > 1e-4f * S ? glm::normalize(dir) : glm::vec3(0, 1, 0);
    float rh = 0.068f * S;
    glm::vec3 centre = P[size_t(head)] + dir * (rh * 0.8f);
    shape->prims.push_back({centre - dir * (0.15f * rh), centre + dir * (0.15f * rh), 0.88f * rh, 0.88f * rh, head,
                            kBodySkin, false});
  }
  if (shape->prims.empty()) {
    *error = "the skeleton has no bones long enough to put a body on";
    return false;
  }
  shape->blend = 0.02f * S;
  return true;
}

// Up to 4 joints by closeness of their bones to x, weights sum to 1; the
// material likewise.
void weigh(const Shape& s, float S, BodyVertex* v) {
  const float sigma = 0.025f * S;
  std::vector<float> d(s.prims.size());
  float dmin = 1e9f;
  for (size_t i = 0; i < s.prims.size(); ++i) {
    d[i] = prim_distance(s, s.prims[i], v->position);
    dmin = std::min(dmin, d[i]);
  }
  // The same falloff blends the materials, so a sleeve or a waistline is
  // a short gradient rather than a jagged edge along the triangles.
  std::map<int, float> by_joint;
  float material = 0.0f, total = 0.0f;
  for (size_t i = 0; i < s.prims.size(); ++i) {
    float t = 1.0f - (d[i] - dmin) / sigma;
    if (t <= 0.0f) continue;
    by_joint[s.prims[i].joint] += t * t;
    material += t * t * float(s.prims[i].material);
    total += t * t;
  }
  std::vector<std::pair<float, int>> w;
  for (const auto& kv : by_joint) w.push_back({kv.second, kv.first});
  std::sort(w.begin(), w.end(), [](const std::pair<float, int>& a, const std::pair<float, int>& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  if (w.size() > 4) w.resize(4);
  float sum = 0.0f;
  for (const auto& x : w) sum += x.first;
  for (int k = 0; k < 4; ++k) {
    bool used = size_t(k) < w.size();
    v->joints[k] = used ? uint16_t(w[size_t(k)].second) : 0;
    v->weights[k] = used ? w[size_t(k)].first / sum : 0.0f;
  }
  v->material = material / total;
}

// Surface nets: one vertex per grid cell the surface crosses (the mean of
// the crossings on its edges, then pulled onto the surface), one quad per
// grid edge the surface crosses, joining the four cells around that edge.
void polygonise(const Shape& s, float cell, BodyMesh* out) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const Primitive& p : s.prims) {
    float r = std::max(p.ra, p.rb) * s.depth_scale + 2.0f * cell;
    lo = glm::min(lo, glm::min(p.a, p.b) - glm::vec3(r));
    hi = glm::max(hi, glm::max(p.a, p.b) + glm::vec3(r));
  }
  const int nx = int(std::ceil((hi.x - lo.x) / cell)) + 1, ny = int(std::ceil((hi.y - lo.y) / cell)) + 1,
            nz = int(std::ceil((hi.z - lo.z) / cell)) + 1;
  auto at = [&](int i, int j, int k) { return (size_t(k) * size_t(ny) + size_t(j)) * size_t(nx) + size_t(i); };
  auto pos = [&](int i, int j, int k) { return lo + glm::vec3(float(i), float(j), float(k)) * cell; };
  std::vector<float> f(size_t(nx) * size_t(ny) * size_t(nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) f[at(i, j, k)] = field(s, pos(i, j, k));

  std::vector<int32_t> vertex_of(f.size(), -1);  // by the cell's lowest corner
  static const int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  static const int kEdge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        float v[8];
        int inside = 0;
        for (int c = 0; c < 8; ++c) {
          v[c] = f[at(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2])];
          inside += v[c] < 0.0f;
        }
        if (inside == 0 || inside == 8) continue;
        glm::vec3 sum(0.0f);
        int crossings = 0;
        for (const auto& e : kEdge) {
          float a = v[e[0]], b = v[e[1]];
          if ((a < 0.0f) == (b < 0.0f)) continue;
          float t = a / (a - b);
          glm::vec3 pa(float(kCorner[e[0]][0]), float(kCorner[e[0]][1]), float(kCorner[e[0]][2]));
          glm::vec3 pb(float(kCorner[e[1]][0]), float(kCorner[e[1]][1]), float(kCorner[e[1]][2]));
          sum += pa + (pb - pa) * t;
          ++crossings;
        }
        glm::vec3 x = pos(i, j, k) + sum / float(crossings) * cell;
        // Two Newton steps onto the surface, kept inside the cell's reach.
        glm::vec3 start = x;
        for (int it = 0; it < 2; ++it) x -= gradient(s, x, 0.25f * cell) * field(s, x);
        if (glm::length(x - start) > cell) x = start;
        BodyVertex bv{};
        bv.position = x;
        bv.normal = gradient(s, x, 0.25f * cell);
        vertex_of[at(i, j, k)] = int32_t(out->vertices.size());
        out->vertices.push_back(bv);
      }
  auto triangle = [&](int32_t a, int32_t b, int32_t c) {
    if (a < 0 || b < 0 || c < 0 || a == b || b == c || a == c) return;
    const glm::vec3 &pa = out->vertices[size_t(a)].position, &pb = out->vertices[size_t(b)].position,
                    &pc = out->vertices[size_t(c)].position;
    glm::vec3 n = glm::cross(pb - pa, pc - pa);
    glm::vec3 outward = out->vertices[size_t(a)].normal + out->vertices[size_t(b)].normal + out->vertices[size_t(c)].normal;
    // Degenerate or edge-on to the surface (a sliver where the grid cuts
    // the flat soles): no facing to give it, and nothing to see.
    float facing = glm::dot(n, outward);
    if (!(std::fabs(facing) > 1e-3f * glm::length(n) * glm::length(outward))) return;
    if (facing < 0.0f) std::swap(b, c);
    out->indices.insert(out->indices.end(), {uint32_t(a), uint32_t(b), uint32_t(c)});
  };
  // Edges along axis a from grid point (i, j, k); the cells around it are
  // offset by 0/-1 along the other two axes.
  for (int k = 1; k + 1 < nz; ++k)
    for (int j = 1; j + 1 < ny; ++j)
      for (int i = 1; i + 1 < nx; ++i) {
        bool in0 = f[at(i, j, k)] < 0.0f;
        const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int axis = 0; axis < 3; ++axis) {
          bool in1 = f[at(i + step[axis][0], j + step[axis][1], k + step[axis][2])] < 0.0f;
          if (in0 == in1) continue;
          int u = (axis + 1) % 3, w = (axis + 2) % 3;
          int32_t q[4];
          for (int c = 0; c < 4; ++c) {
            int g[3] = {i, j, k};
            g[u] -= (c == 1 || c == 2) ? 1 : 0;
            g[w] -= (c >= 2) ? 1 : 0;
            q[c] = vertex_of[at(g[0], g[1], g[2])];
          }
          triangle(q[0], q[1], q[2]);
          triangle(q[0], q[2], q[3]);
        }
      }
}

}  // namespace

bool build_body(const BodySkeleton& sk, int cells_per_height, BodyMesh* out, std::string* error) {
  *out = BodyMesh();
  const size_t n = sk.parent.size();
  if (n == 0 || sk.rest_offset.size() != n || sk.upper.size() != n || (!sk.pose.empty() && sk.pose.size() != n)) {
    *error = "body: empty skeleton or mismatched joint arrays";
    return false;
  }
  if (n > 65535) {
    *error = "body: more than 65535 joints";
    return false;
  }
  if (cells_per_height < 8 || cells_per_height > 400) {
    *error = "body: cells_per_height must be 8..400";
    return false;
  }
  std::vector<glm::vec3> P(n);
  for (size_t j = 0; j < n; ++j) {
    int p = sk.parent[j];
    if (p >= int(j) || (p < 0 && p != -1)) {
      *error = "body: joint " + std::to_string(j) + " has parent " + std::to_string(p) + " (must come before it)";
      return false;
    }
    P[j] = sk.pose.empty() ? (p >= 0 ? P[size_t(p)] : glm::vec3(0.0f)) + sk.rest_offset[j] : glm::vec3(sk.pose[j][3]);
    if (!std::isfinite(P[j].x) || !std::isfinite(P[j].y) || !std::isfinite(P[j].z)) {
      *error = "body: joint " + std::to_string(j) + " of the bind pose is not finite";
      return false;
    }
  }
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (glm::vec3 p : P) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Bind-pose height; a skeleton lying down still gets a body from its extent.
  float S = hi.y - lo.y;
  glm::vec3 extent = hi - lo;
  if (S < 0.25f * std::max(extent.x, extent.z)) S = std::max(std::max(extent.x, extent.y), extent.z);
  if (!(S > 1e-4f) || !std::isfinite(S)) {
    *error = "body: the bind pose has no extent (all joints at one point)";
    return false;
  }
  // Limbs thinner than a grid cell would fall apart on the grid: a coarse
  // body gets slightly thicker wrists instead of missing hands.
  const float cell = S / float(cells_per_height);
  Shape shape;
  if (!make_shape(sk, P, S, 0.6f * cell, &shape, error)) return false;
  // The runtime plants the lowest joints (toes) on the floor, so the bind
  // pose's floor is at the lowest joint: cut the soles flat there.
  shape.floor = lo.y;
  polygonise(shape, cell, out);
  if (out->indices.empty()) {
    *error = "body: the surface produced no triangles";
    return false;
  }
  for (BodyVertex& v : out->vertices) weigh(shape, S, &v);
  out->inverse_bind.resize(n);
  for (size_t j = 0; j < n; ++j) {
    glm::mat4 m(1.0f);
    m[3] = glm::vec4(-P[j], 1.0f);
    out->inverse_bind[j] = sk.pose.empty() ? m : glm::inverse(sk.pose[j]);
  }
  out->height = S;
  return true;
}

void body_skin_matrices(const BodyMesh& mesh, const float* model, glm::mat4* out) {
  for (size_t j = 0; j < mesh.inverse_bind.size(); ++j) {
    glm::mat4 m;
    for (int c = 0; c < 4; ++c)
      m[c] = glm::vec4(model[j * 16 + size_t(c) * 4 + 0], model[j * 16 + size_t(c) * 4 + 1],
                       model[j * 16 + size_t(c) * 4 + 2], model[j * 16 + size_t(c) * 4 + 3]);
    out[j] = m * mesh.inverse_bind[j];
  }
}

glm::vec3 body_skin_point(const BodyVertex& v, const glm::mat4* skin) {
  glm::vec4 p(v.position, 1.0f), sum(0.0f);
  for (int k = 0; k < 4; ++k) sum += v.weights[k] * (skin[v.joints[k]] * p);
  return glm::vec3(sum);
}
