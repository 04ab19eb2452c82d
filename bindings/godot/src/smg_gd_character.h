/* smg_gd_character.h - SmgCharacter, a Node3D that follows a path with
 * libsmg motion and drives a Skeleton3D. */
#ifndef SMG_GD_CHARACTER_H
#define SMG_GD_CHARACTER_H

#include <stdbool.h>

#include "gd_api.h"
#include "smg_gd_bone_map.h"

void smg_gd_character_register(void);
/* Writes the character's current pose into skel through `mask` (for
 * SmgSkeletonModifier). false: character is not an SmgCharacter or has no
 * graph. */
bool smg_gd_character_apply_pose(GDExtensionObjectPtr character, GDExtensionObjectPtr skel,
	const smg_gd_mask *mask);
void smg_gd_character_unregister(void);

#endif
