/* smg_gd_bone_map.h - an SmgCharacter's graph joints matched to the bones
 * of a Skeleton3D, and the pose written through that match. A joint goes to
 * the bone a BoneMap gives for its SkeletonProfileHumanoid name (when the
 * character has a BoneMap), else to the bone of its own name, else to the
 * bone named as the profile names it (a rig Godot's importer renamed).
 *
 * The match is refreshed whenever the skeleton or its bone list changes
 * (instance id, Skeleton3D version). Bones the graph does not know are left
 * alone; graph joints the skeleton lacks are skipped (one warning). */
#ifndef SMG_GD_BONE_MAP_H
#define SMG_GD_BONE_MAP_H

#include <stdbool.h>

#include "gd_api.h"
#include "smg.h"

/* How much of libsmg's pose each bone takes (SmgSkeletonModifier's mask):
 * 1 = libsmg's rotation, 0 = the pose the skeleton already has (rest or the
 * AnimationTree's), between = a blend of the two. A bone named in `bones`
 * takes its own weight, every other bone its joint's body part's. */
typedef struct smg_gd_mask {
	float part[3];          /* by SMG_BODY_ROOT, _LOWER, _UPPER */
	uint32_t count;         /* per-bone weights: */
	char **bones;           /* skeleton bone names */
	float *weights;
} smg_gd_mask;

typedef struct smg_gd_bone_map {
	uint32_t joint_count;
	float *rot;             /* 4 * joint_count + 4: pose scratch */
	GDObjectInstanceID skel_id;
	int64_t skel_version;
	int32_t *bone_of_joint; /* joint -> bone index, -1 if missing */
	float *rest_of_joint;   /* 8 per joint: global rest rotation of its
	                         * bone and of that bone's parent (x,y,z,w) */
	uint8_t *part_of_joint; /* SMG_BODY_* of each joint */
	bool rests_identity;    /* every mapped bone rests world-aligned */
	const gd_variant *bone_map; /* the owner's BoneMap (or nil), read at
	                             * each match; may be NULL */
	bool warned;            /* the missing-joints warning was printed */
} smg_gd_bone_map;

/* Ready for a graph of joint_count joints; false: out of memory. */
bool smg_gd_bone_map_init(smg_gd_bone_map *m, uint32_t joint_count);
void smg_gd_bone_map_free(smg_gd_bone_map *m);
/* Match again on the next pose (the target skeleton may have changed). */
void smg_gd_bone_map_invalidate(smg_gd_bone_map *m);

/* The skeleton at `path` from `owner`, or with an empty path the owner's
 * first Skeleton3D child; NULL if there is none. */
GDExtensionObjectPtr smg_gd_find_skeleton(GDExtensionObjectPtr owner, const gd_node_path *path);

/* Writes ch's current pose into skel: joint rotations converted to each
 * bone's own rest axes, and the root bone's position relative to the
 * character node, which itself carries (position, heading). mask NULL:
 * the whole pose. */
void smg_gd_bone_map_write_pose(smg_gd_bone_map *m, const smg_graph *graph, const smg_character *ch,
	GDExtensionObjectPtr skel, const smg_gd_mask *mask);

#endif
