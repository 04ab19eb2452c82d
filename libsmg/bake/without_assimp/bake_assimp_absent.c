/*
 * bake_assimp_absent.c - smgb_assimp_load for bakers built without assimp
 * (the Windows build, mk/windows.mk: Debian has no assimp for MinGW).
 *
 * BVH files import as everywhere else; a glTF/GLB/FBX clip or rig fails
 * with an error that names the file and says what is missing, so a
 * manifest written for the Linux baker fails clearly instead of baking a
 * different graph.
 */
#include <stddef.h>

#include "bake_clip.h"
#include "bake_import_util.h"

smg_result smgb_assimp_load(const char* path, float unit_scale,
                            uint32_t animation_index, smgb_clip* out,
                            smgb_error* err) {
  (void)unit_scale;
  (void)animation_index;
  (void)out;
  smgb_imp_errorf(err,
                  "%s: this smg-bake was built without assimp, so it reads "
                  "BVH only (convert the clip to BVH, or bake glTF/FBX with "
                  "a baker built with assimp)",
                  path ? path : "(null)");
  return path ? SMG_ERROR_UNSUPPORTED : SMG_ERROR_INVALID_ARGUMENT;
}
