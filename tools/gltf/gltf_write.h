/*
 * gltf_write.h - writes a character as one glTF 2.0 file: a skeleton (a
 * node per joint with its rest TRS, and a skin with inverse bind
 * matrices), optionally a skinned mesh and a sampled animation. Shared by
 * the tools that export motion or bodies for engines and DCC tools
 * (smg-synth --glb, smg-body-gltf).
 *
 * Conventions are glTF's (and libsmg's): metres, +Y up, quaternions
 * (x, y, z, w), column-major matrices. The animation has one sampler per
 * channel, LINEAR interpolation, a rotation channel per joint and a
 * translation channel for the root joint, which is what assimp and
 * Blender's importer expect of a skeletal take.
 *
 * Every input is checked before anything is written (finite numbers,
 * parents before children, joint and vertex indices in range, unit
 * quaternions); the file goes to a temporary file beside the target and is
 * renamed over it only when complete, so a failure leaves no partial file.
 */
#ifndef SMG_GLTF_WRITE_H
#define SMG_GLTF_WRITE_H

#include <stddef.h>
#include <stdint.h>

#include "smg.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The skeleton in its bind pose. */
typedef struct gltf_skeleton {
  uint32_t joint_count;      /* >= 1 */
  const int32_t* parent;     /* -1 for a root, otherwise < the joint's index */
  const char* const* name;   /* per joint, non-empty UTF-8 */
  const float* translation;  /* 3 per joint: local bind translation, metres */
  const float* rotation;     /* 4 per joint: local bind rotation; NULL =
                                identity (the rest pose) */
  const float* inverse_bind; /* 16 per joint; NULL = the inverse of the
                                bind pose above */
} gltf_skeleton;

/* A mesh skinned to the skeleton (at most 4 influences per vertex). */
typedef struct gltf_mesh {
  uint32_t vertex_count, index_count; /* index_count: 3 per triangle */
  const float* position;              /* 3 per vertex, bind pose */
  const float* normal;                /* 3 per vertex, unit */
  const uint16_t* joints;             /* 4 per vertex, < joint_count */
  const float* weights;               /* 4 per vertex, >= 0, sum 1 */
  const float* color;                 /* 4 per vertex (linear RGBA) or NULL */
  const uint32_t* index;              /* < vertex_count */
} gltf_mesh;

/* A take sampled at a fixed rate, one frame as
 * smg_character_get_local_pose writes it: the root joint's translation (3
 * floats) and every joint's local rotation (4 floats each). */
typedef struct gltf_animation {
  uint32_t frame_count; /* >= 1 */
  float fps;            /* > 0 */
  const float* frames;  /* frame_count * stride floats */
  size_t stride;        /* floats per frame, >= 3 + 4 * joint_count */
} gltf_animation;

typedef struct gltf_scene {
  const char* generator;   /* asset.generator */
  const char* root_name;   /* the node holding the character */
  const char* mesh_name;   /* the mesh node (with a mesh) */
  const gltf_skeleton* skeleton;
  const gltf_mesh* mesh;           /* NULL: skeleton only */
  const gltf_animation* animation; /* NULL: bind pose only */
} gltf_scene;

#define GLTF_TEXT 0u   /* .gltf, its buffer embedded as base64 */
#define GLTF_BINARY 1u /* .glb */

/* Writes `scene` to `path` (GLTF_TEXT or GLTF_BINARY). On failure returns
 * SMG_ERROR_INVALID_ARGUMENT (bad input: the message names the joint,
 * vertex or frame), SMG_ERROR_OUT_OF_MEMORY or SMG_ERROR_IO, leaves `path`
 * as it was and puts a message in `error`. */
smg_result gltf_write_file(const char* path, const gltf_scene* scene,
                           uint32_t format, char* error, size_t error_size);

/* Fills the rest-pose skeleton of a loaded graph: names, parents and rest
 * offsets (root at the origin), identity rotations. The arrays hold
 * joint_count entries (3 per joint for translation). */
smg_result gltf_skeleton_from_graph(const smg_graph* graph,
                                    uint32_t joint_count, int32_t* parent,
                                    const char** name, float* translation,
                                    gltf_skeleton* out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SMG_GLTF_WRITE_H */
