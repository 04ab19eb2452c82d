/* smg_gd_character.h - SmgCharacter, a Node3D that follows a path with
 * libsmg motion and drives a Skeleton3D. */
#ifndef SMG_GD_CHARACTER_H
#define SMG_GD_CHARACTER_H

void smg_gd_character_register(void);
void smg_gd_character_unregister(void);

#endif
