/* smg_gd_humanoid.c - graph joints to SkeletonProfileHumanoid bone names
 * (see smg_gd_humanoid.h). */
#include <ctype.h>
#include <string.h>

#include "smg_gd_humanoid.h"

enum { SIDE_NONE, SIDE_LEFT, SIDE_RIGHT };

/* Limb part spellings (lower case, separators removed) -> profile part. */
static const struct { const char *spelling, *part; } LIMBS[] = {
	{ "upleg", "UpperLeg" }, { "upperleg", "UpperLeg" }, { "thigh", "UpperLeg" }, { "hip", "UpperLeg" },
	{ "leg", "LowerLeg" }, { "lowerleg", "LowerLeg" }, { "shin", "LowerLeg" }, { "calf", "LowerLeg" },
	{ "knee", "LowerLeg" }, { "foot", "Foot" }, { "ankle", "Foot" }, { "toebase", "Toes" }, { "toes", "Toes" },
	{ "toe", "Toes" }, { "ball", "Toes" }, { "shoulder", "Shoulder" }, { "clavicle", "Shoulder" },
	{ "collar", "Shoulder" }, { "arm", "UpperArm" }, { "upperarm", "UpperArm" }, { "forearm", "LowerArm" },
	{ "lowerarm", "LowerArm" }, { "elbow", "LowerArm" }, { "hand", "Hand" }, { "wrist", "Hand" },
};

/* Every profile name this file hands out, as static strings. */
static const char *const SIDED[2][8] = {
	{ "LeftUpperLeg", "LeftLowerLeg", "LeftFoot", "LeftToes", "LeftShoulder", "LeftUpperArm", "LeftLowerArm",
	  "LeftHand" },
	{ "RightUpperLeg", "RightLowerLeg", "RightFoot", "RightToes", "RightShoulder", "RightUpperArm",
	  "RightLowerArm", "RightHand" },
};
static const char *const PARTS[8] = { "UpperLeg", "LowerLeg", "Foot", "Toes", "Shoulder", "UpperArm", "LowerArm",
	"Hand" };

static const char *sided(int side, const char *part) {
	for (int i = 0; i < 8; i++)
		if (!strcmp(PARTS[i], part)) return SIDED[side == SIDE_LEFT ? 0 : 1][i];
	return NULL;
}

/* name without a namespace ("mixamorig:Hips"/"mixamorig_Hips" -> "Hips"),
 * side taken off, lower case, separators dropped. */
static int normalise(const char *name, char *out, size_t cap) {
	const char *colon = strrchr(name, ':');
	if (colon) name = colon + 1;
	if (!strncmp(name, "mixamorig", 9)) name += 9 + (name[9] == '_');
	int side = SIDE_NONE;
	size_t len = strlen(name);
	if (!strncmp(name, "Left", 4) || !strncmp(name, "left", 4)) {
		side = SIDE_LEFT;
		name += 4;
		len -= 4;
	} else if (!strncmp(name, "Right", 5) || !strncmp(name, "right", 5)) {
		side = SIDE_RIGHT;
		name += 5;
		len -= 5;
	} else if ((name[0] == 'L' || name[0] == 'R') && isupper((unsigned char)name[1])) {
		side = name[0] == 'L' ? SIDE_LEFT : SIDE_RIGHT; /* CMU: LHipJoint, RThumb */
		name += 1;
		len -= 1;
	} else if (len > 2 && (name[len - 2] == '_' || name[len - 2] == '.') &&
	           (tolower((unsigned char)name[len - 1]) == 'l' || tolower((unsigned char)name[len - 1]) == 'r')) {
		side = tolower((unsigned char)name[len - 1]) == 'l' ? SIDE_LEFT : SIDE_RIGHT; /* UpperArm_L */
		len -= 2;
	}
	size_t n = 0;
	for (size_t i = 0; i < len && n + 1 < cap; i++)
		if (isalnum((unsigned char)name[i])) out[n++] = (char)tolower((unsigned char)name[i]);
	out[n] = '\0';
	return side;
}

static uint32_t parent_of(const smg_graph *g, uint32_t j) {
	smg_joint_info ji;
	memset(&ji, 0, sizeof ji);
	ji.struct_size = sizeof ji;
	if (smg_graph_get_joint(g, j, &ji) != SMG_OK || ji.parent < 0) return UINT32_MAX;
	return (uint32_t)ji.parent;
}

static int taken(const char **out, uint32_t n, const char *profile) {
	for (uint32_t j = 0; j < n; j++)
		if (out[j] && !strcmp(out[j], profile)) return 1;
	return 0;
}

void smg_gd_humanoid_names(const smg_graph *g, uint32_t n, const char **out) {
	uint32_t hips = UINT32_MAX, neck = UINT32_MAX;
	for (uint32_t j = 0; j < n; j++) {
		out[j] = NULL;
		smg_joint_info ji;
		memset(&ji, 0, sizeof ji);
		ji.struct_size = sizeof ji;
		if (smg_graph_get_joint(g, j, &ji) != SMG_OK || !ji.name) continue;
		char base[64];
		int side = normalise(ji.name, base, sizeof base);
		const char *p = NULL;
		if (side != SIDE_NONE) {
			for (size_t k = 0; k < sizeof LIMBS / sizeof LIMBS[0] && !p; k++)
				if (!strcmp(base, LIMBS[k].spelling)) p = sided(side, LIMBS[k].part);
		} else if (!strcmp(base, "hips") || !strcmp(base, "pelvis")) {
			p = "Hips";
		} else if (!strcmp(base, "head")) {
			p = "Head";
		} else if (!strcmp(base, "neck")) {
			p = "Neck";
		}
		if (p && !taken(out, j, p)) out[j] = p;
	}
	for (uint32_t j = 0; j < n; j++) {
		if (out[j] && !strcmp(out[j], "Hips")) hips = j;
		if (out[j] && !strcmp(out[j], "Neck")) neck = j;
	}
	if (hips == UINT32_MAX && n > 0 && !out[0]) out[hips = 0] = "Hips"; /* the root is the pelvis */
	if (neck == UINT32_MAX || hips == UINT32_MAX) return;
	/* the spine: the joints between the hips and the neck, from the hips */
	uint32_t chain[16], k = 0;
	for (uint32_t j = parent_of(g, neck); j != UINT32_MAX && j != hips && k < 16; j = parent_of(g, j))
		chain[k++] = j;
	if (k == 16) return; /* no hips above the neck */
	/* chain[k-1] is next to the hips */
	if (k >= 1 && !out[chain[k - 1]]) out[chain[k - 1]] = "Spine";
	if (k >= 2 && !out[chain[k - 2]]) out[chain[k - 2]] = "Chest";
	if (k >= 3 && !out[chain[0]]) out[chain[0]] = "UpperChest";
}
