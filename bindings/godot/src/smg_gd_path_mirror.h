/* smg_gd_path_mirror.h - SmgCharacter's own copy of the path and of the
 * transition/splice points it gave libsmg.
 *
 * libsmg keeps no copy a new character could start from, so when the
 * SmgGraph reloads, the character is rebuilt and replays this mirror. Every
 * edit goes to libsmg first and reaches the mirror only when libsmg took
 * it, so the two never disagree. Constraint ids handed to scripts are ours
 * and stay valid across rebuilds (libsmg's ids change). */
#ifndef SMG_GD_PATH_MIRROR_H
#define SMG_GD_PATH_MIRROR_H

#include <stdbool.h>

#include "gd_api.h"
#include "smg.h"

/* Passed to smg_character_desc: the most points and constraints one
 * character holds. */
#define SMG_GD_PATH_CAPACITY 4096u
#define SMG_GD_CONSTRAINT_CAPACITY 64u

typedef enum smg_gd_constraint_kind { SMG_GD_TRANSITION = 1, SMG_GD_SPLICE = 2 } smg_gd_constraint_kind;

typedef struct smg_gd_constraint {
	int64_t id;      /* ours: stable across graph reloads */
	smg_gd_constraint_kind kind;
	float distance;  /* metres along the path */
	uint32_t value;  /* style or action */
	uint32_t smg_id; /* libsmg's id on the current character */
} smg_gd_constraint;

typedef struct smg_gd_path_mirror {
	float *path_xz;
	uint32_t path_count, path_cap;
	smg_gd_constraint *cons;
	uint32_t con_count, con_cap;
	int64_t next_id;
} smg_gd_path_mirror;

void smg_gd_mirror_free(smg_gd_path_mirror *m);

/* Gives a freshly created character everything the mirror holds; a
 * constraint the new graph refuses is dropped with a warning. */
void smg_gd_mirror_replay(smg_gd_path_mirror *m, smg_character *ch);

/* The path edits of SmgCharacter (`what` names the method in errors).
 * They return a Godot Error code and print the Godot error themselves. */
int64_t smg_gd_mirror_set_path(smg_gd_path_mirror *m, smg_character *ch, const gd_packed *points,
	const char *what);
int64_t smg_gd_mirror_append_path(smg_gd_path_mirror *m, smg_character *ch, const gd_packed *points);
int64_t smg_gd_mirror_clear_path(smg_gd_path_mirror *m, smg_character *ch);

/* A transition (value = style) or splice (value = action) point: our id
 * (> 0), or -1 with a Godot error. */
int64_t smg_gd_mirror_add(smg_gd_path_mirror *m, smg_character *ch, smg_gd_constraint_kind kind, double distance,
	int64_t value, const char *what);
int64_t smg_gd_mirror_move(smg_gd_path_mirror *m, smg_character *ch, int64_t id, double distance);
int64_t smg_gd_mirror_remove(smg_gd_path_mirror *m, smg_character *ch, int64_t id);
int64_t smg_gd_mirror_clear_constraints(smg_gd_path_mirror *m, smg_character *ch);

/* The Godot Error code closest to a libsmg result. */
int64_t smg_gd_error_of(smg_result r);

#endif
