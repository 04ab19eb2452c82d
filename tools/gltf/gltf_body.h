/*
 * gltf_body.h - the generated body of a graph's skeleton (demo/body.h: no
 * model file, built from the hierarchy and joint positions alone) as the
 * glTF writer's skeleton and skinned mesh, for the export tools.
 */
#ifndef SMG_GLTF_BODY_H
#define SMG_GLTF_BODY_H

#include "gltf_write.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gltf_body {
  gltf_skeleton skeleton; /* bind pose of the body */
  gltf_mesh mesh;
  void* storage;          /* owns the arrays above */
} gltf_body;

/* Builds the body. Fails with SMG_ERROR_INVALID_ARGUMENT and a message
 * when the skeleton gives no body (empty or inconsistent), or
 * SMG_ERROR_OUT_OF_MEMORY. `out` is usable only on SMG_OK; free it with
 * gltf_body_free. */
smg_result gltf_body_from_graph(smg_graph* graph, gltf_body* out, char* error,
                                size_t error_size);
void gltf_body_free(gltf_body* body);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SMG_GLTF_BODY_H */
