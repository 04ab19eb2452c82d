/* smg_gd_character_internal.h - the SmgCharacter instance, shared by its
 * lifetime and frame code (smg_gd_character.c) and its script-facing
 * methods (smg_gd_character_methods.c). Joint-to-bone matching lives in
 * smg_gd_bone_map.c, the replayable path and constraints in
 * smg_gd_path_mirror.c. */
#ifndef SMG_GD_CHARACTER_INTERNAL_H
#define SMG_GD_CHARACTER_INTERNAL_H

#include "gd_class.h"
#include "smg_gd_bone_map.h"
#include "smg_gd_character.h"
#include "smg_gd_graph.h"
#include "smg_gd_path_mirror.h"

#define SMG_GD_CHARACTER_CLASS "SmgCharacter"

typedef struct smg_gd_character {
	GDExtensionObjectPtr owner;
	gd_variant graph_var;   /* Ref<SmgGraph> or nil */
	smg_gd_blob *blob;      /* the graph `ch` was created on (retained) */
	smg_character *ch;

	gd_node_path skeleton_path;
	smg_gd_bone_map bones;
	bool warned_skeleton, warned_step;

	/* settings, kept to create the next character after a graph reload */
	int64_t style, action;
	double threshold;
	bool ik, active, in_editor;
	bool steering;          /* root steering (smg.h): on by default */
	double steer_limits[3]; /* turn rate rad/s, slide ratio, stop s; 0 = default */
	double swing_clearance; /* foot IK's swing clearance, metres; 0 = default,
	                         * negative = off (as the inspector shows it) */
	smg_gd_path_mirror mirror;

	uint32_t last_style, last_action;
	bool end_reached;
	uint64_t modifier_frame; /* last frame an SmgSkeletonModifier posed us */
} smg_gd_character;

/* Make `ch` match the current graph: nothing to do, rebuild after a reload
 * (replaying the mirror), or tear down when the graph went away. false: no
 * character. */
bool smg_gd_character_ensure(smg_gd_character *self);
/* smg_gd_character_ensure for methods that need a character: prints the
 * Godot error ("SmgCharacter.<what>: no graph set ...") itself. */
bool smg_gd_character_need(smg_gd_character *self, const char *what);
/* One frame: steps libsmg (long frames split), moves the node, poses the
 * skeleton, emits the signals. Returns a Godot Error code. */
int64_t smg_gd_character_step(smg_gd_character *self, double dt);

/* The methods, properties and signals scripts see (registered once). */
void smg_gd_character_register_methods(void);

#endif
