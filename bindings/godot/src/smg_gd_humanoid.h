/* smg_gd_humanoid.h - a graph's joints named as Godot's
 * SkeletonProfileHumanoid names them ("Hips", "LeftUpperLeg", ...), so that
 * a BoneMap (profile bone -> skeleton bone) or a rig already renamed to the
 * profile by Godot's importer can be matched without renaming bones. */
#ifndef SMG_GD_HUMANOID_H
#define SMG_GD_HUMANOID_H

#include <stdint.h>

#include "smg.h"

/* out[j]: the profile name of joint j (a static string), or NULL where the
 * joint has no counterpart in the profile (e.g. CMU's LHipJoint, fingers).
 * Limbs are recognised by the usual spellings of side and part (CMU,
 * Mixamo, "_l"/"_r" suffixes, thigh/shin/calf, clavicle, ...), the spine by
 * its place between the hips and the neck. */
void smg_gd_humanoid_names(const smg_graph *graph, uint32_t joint_count, const char **out);

#endif
