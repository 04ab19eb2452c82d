// body_gltf.cpp - smg-body-gltf: writes the generated body (demo/body.h) of
// a blob's skeleton as a glTF 2.0 file (one self-contained .gltf, buffer
// embedded as base64; .glb when the name ends so): a node per joint with
// the joint's name and rest offset (and, for a body built around a posed
// bind, that pose's rotations), one skinned mesh (positions, normals, 4
// joints and weights per vertex, vertex colours: lower body, upper body,
// skin) and its inverse bind matrices. Engines load it as a rigged
// character whose bones carry the graph's joint names, e.g. the Godot demo
// (bindings/godot/demo). The file is written by the export tools' glTF
// writer (tools/gltf), which smg-synth --glb shares.
//
// usage: smg-body-gltf BLOB OUT.gltf
#include "gltf_body.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: smg-body-gltf BLOB OUT.gltf\n");
    return 2;
  }
  smg_graph* g = nullptr;
  smg_result r = smg_graph_load_file(argv[1], nullptr, &g);
  if (r != SMG_OK) {
    std::fprintf(stderr, "smg-body-gltf: cannot load '%s': %s\n", argv[1], smg_result_string(r));
    return 1;
  }
  char error[512];
  gltf_body body;
  r = gltf_body_from_graph(g, &body, error, sizeof error);
  if (r != SMG_OK) {
    std::fprintf(stderr, "smg-body-gltf: %s: %s\n", argv[1], error[0] ? error : smg_result_string(r));
    smg_graph_destroy(g);
    return 1;
  }
  gltf_scene scene{};
  scene.generator = "libsmg smg-body-gltf (generated body, not a scanned or modelled character)";
  scene.root_name = "Body";
  scene.mesh_name = "BodyMesh";
  scene.skeleton = &body.skeleton;
  scene.mesh = &body.mesh;
  size_t len = std::strlen(argv[2]);
  uint32_t format = len >= 4 && !std::strcmp(argv[2] + len - 4, ".glb") ? GLTF_BINARY : GLTF_TEXT;
  r = gltf_write_file(argv[2], &scene, format, error, sizeof error);
  const uint32_t nj = body.skeleton.joint_count, nv = body.mesh.vertex_count, nt = body.mesh.index_count / 3;
  gltf_body_free(&body);
  smg_graph_destroy(g);
  if (r != SMG_OK) {
    std::fprintf(stderr, "smg-body-gltf: cannot write '%s': %s\n", argv[2], error);
    return 1;
  }
  std::printf("smg-body-gltf: wrote %s (%u joints, %u vertices, %u triangles)\n", argv[2], nj, nv, nt);
  return 0;
}
