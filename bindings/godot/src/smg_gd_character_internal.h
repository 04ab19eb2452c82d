/* smg_gd_character_internal.h - the SmgCharacter instance, shared by the
 * files of the class, each using only those below it:
 *   smg_gd_character_class.c    registration, create/destroy, notifications
 *   smg_gd_character_methods.c  the methods, properties and signals scripts see
 *   smg_gd_character_frame.c    one frame: step, move, pose, signals
 *   smg_gd_character_scene.c    ground probes, root motion, events
 *   smg_gd_character.c          the libsmg character's lifetime
 * Joint-to-bone matching lives in smg_gd_bone_map.c, the replayable path and
 * constraints in smg_gd_path_mirror.c. */
#ifndef SMG_GD_CHARACTER_INTERNAL_H
#define SMG_GD_CHARACTER_INTERNAL_H

#include "gd_class.h"
#include "smg_gd_bone_map.h"
#include "smg_gd_character.h"
#include "smg_gd_graph.h"
#include "smg_gd_path_mirror.h"

#define SMG_GD_CHARACTER_CLASS "SmgCharacter"

/* root_motion_mode: who moves the character. MOVE_NODE: the library sets
 * the node's transform (path points in its parent's space); ENGINE_MOVER:
 * the node is left where it is, a script moves it (e.g. its CharacterBody3D
 * parent) by get_root_motion() and reports back with set_ground_position()
 * (path points and positions in global space). */
#define SMG_GD_MOVE_NODE 0
#define SMG_GD_ENGINE_MOVER 1

typedef struct smg_gd_character {
	GDExtensionObjectPtr owner;
	gd_variant graph_var;   /* Ref<SmgGraph> or nil */
	smg_gd_blob *blob;      /* the graph `ch` was created on (retained) */
	smg_character *ch;

	gd_node_path skeleton_path;
	gd_variant bone_map_var; /* Ref<BoneMap> or nil: humanoid rigs */
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

	/* In a game scene (smg_gd_character_scene.c) */
	int64_t root_motion_mode; /* SMG_GD_MOVE_NODE or SMG_GD_ENGINE_MOVER */
	float root_motion[4];     /* the last frame's root delta: x, y, z, yaw */
	bool ground_probing;      /* ray cast the ground under the probes */
	int64_t ground_mask;      /* physics layers the rays see */
	bool ground_given;        /* the library holds measured heights */
	smg_event *events;        /* the last frame's events, all sub-steps */
	uint32_t event_count, event_cap;

	uint32_t last_style, last_action;
	uint64_t modifier_frame; /* last frame an SmgSkeletonModifier posed us */
} smg_gd_character;

/* Destroys the libsmg character, then releases its graph and bone map. */
void smg_gd_character_teardown(smg_gd_character *self);
/* The node's transform in its parent's space. */
gd_transform3d smg_gd_character_xform(smg_gd_character *self);
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

/* Before a step: ground heights under the probes by physics ray casts
 * (with ground_probing), else the flat floor (smg_gd_character_scene.c). */
void smg_gd_character_probe_ground(smg_gd_character *self);
/* After a step: keep its events and add its root motion to the frame's. */
void smg_gd_character_collect(smg_gd_character *self);
/* Emit the frame's events as signals; the node may be freed by a handler
 * (oid: its instance id). */
void smg_gd_character_emit_events(smg_gd_character *self, GDObjectInstanceID oid);
/* The libsmg space to global space: the parent's global transform in
 * MOVE_NODE mode (identity without a Node3D parent), identity otherwise. */
gd_transform3d smg_gd_character_space(smg_gd_character *self);
/* The methods of smg_gd_character_scene.c, registered with the others. */
void smg_gd_character_register_scene_methods(void);

/* The methods, properties and signals scripts see (registered once). */
void smg_gd_character_register_methods(void);

#endif
