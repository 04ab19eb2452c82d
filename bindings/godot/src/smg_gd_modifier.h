/* smg_gd_modifier.h - SmgSkeletonModifier, a SkeletonModifier3D that applies
 * an SmgCharacter's pose in the skeleton's modifier stage. */
#ifndef SMG_GD_MODIFIER_H
#define SMG_GD_MODIFIER_H

void smg_gd_modifier_register(void);
void smg_gd_modifier_unregister(void);

#endif
