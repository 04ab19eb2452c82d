/* smg_gd_character.c - SmgCharacter (Node3D): one libsmg character that
 * follows a path drawn at run time and drives a Skeleton3D. This file holds
 * the libsmg character's lifetime, the bottom of the binding's one-way
 * chain: the class registration (smg_gd_character_class.c) sits above the
 * script methods (smg_gd_character_methods.c), which sit above the frame
 * (smg_gd_character_frame.c), which sits above the scene services
 * (smg_gd_character_scene.c); each uses only what is below it.
 *
 * Robustness: the character holds a reference to its SmgGraph and to the
 * loaded graph itself (smg_gd_blob), so freeing nodes or resources in any
 * order is safe; when the SmgGraph reloads, the character is rebuilt on the
 * new graph on its next use and its path and constraints are replayed. The
 * skeleton is found again by instance id every frame, never by a stored
 * pointer, so freeing it first is safe too. Calls that need a graph when
 * none is loaded print a Godot error and return an error code. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smg_gd_character_internal.h"

#define CLASS SMG_GD_CHARACTER_CLASS

/* ---------------- graph and character lifetime ---------------- */

void smg_gd_character_teardown(smg_gd_character *self) {
	if (self->ch) {
		smg_result r = smg_character_destroy(self->ch);
		if (r != SMG_OK) GD_ERR("SmgCharacter: destroy failed: %s", smg_result_string(r));
		self->ch = NULL;
	}
	smg_gd_blob_release(self->blob); /* after the character: graph may go now */
	self->blob = NULL;
	smg_gd_bone_map_free(&self->bones);
}

static smg_gd_blob *current_blob(smg_gd_character *self) {
	return smg_gd_graph_blob(smg_gd_graph_from_object(gd_variant_object(&self->graph_var)));
}

static float heading_of(const gd_transform3d *t) {
	/* forward (+Z) in parent space is the basis' third column */
	return atan2f(t->basis[0][2], t->basis[2][2]);
}

gd_transform3d smg_gd_character_xform(smg_gd_character *self) {
	gd_transform3d t;
	memset(&t, 0, sizeof t);
	gd_call(GDB_Node3D_get_transform, self->owner, NULL, &t);
	return t;
}

static bool in_tree(smg_gd_character *self) {
	GDExtensionBool r = 0;
	gd_call(GDB_Node_is_inside_tree, self->owner, NULL, &r);
	return r != 0;
}

bool smg_gd_character_ensure(smg_gd_character *self) {
	smg_gd_blob *b = current_blob(self);
	if (b == self->blob && self->ch) return true;
	smg_gd_character_teardown(self);
	if (!b) return false;

	/* libsmg's space: the parent's (the node moves in it) or, with the
	 * engine's mover, global space */
	gd_transform3d t = smg_gd_character_xform(self);
	if (self->root_motion_mode == SMG_GD_ENGINE_MOVER) {
		if (!in_tree(self)) return false; /* no global transform yet */
		gd_call(GDB_Node3D_get_global_transform, self->owner, NULL, &t);
	}
	smg_graph_info info;
	memset(&info, 0, sizeof info);
	info.struct_size = sizeof info;
	smg_graph_get_info(b->graph, &info);

	smg_character_desc d;
	memset(&d, 0, sizeof d);
	d.struct_size = sizeof d;
	d.flags = (self->ik ? 0 : SMG_CHARACTER_NO_IK) | (self->steering ? 0 : SMG_CHARACTER_NO_STEERING);
	d.steer_turn_rate = (float)self->steer_limits[0];
	d.steer_slide_ratio = (float)self->steer_limits[1];
	d.stop_seconds = (float)self->steer_limits[2];
	if (self->swing_clearance < 0.0)
		d.flags |= SMG_CHARACTER_NO_SWING_CLEARANCE;
	else
		d.swing_clearance = (float)self->swing_clearance;
	d.initial_style = self->style >= 0 && self->style < info.style_count ? (uint32_t)self->style : 0;
	d.initial_action = self->action >= 0 && self->action < info.action_count ? (uint32_t)self->action : 0;
	d.path_capacity = SMG_GD_PATH_CAPACITY;
	d.constraint_capacity = SMG_GD_CONSTRAINT_CAPACITY;
	d.position[0] = t.origin[0];
	d.position[2] = t.origin[2];
	d.heading = heading_of(&t);
	d.error_threshold = (float)self->threshold;
	smg_result r = smg_character_create(b->graph, &d, &self->ch);
	if (r != SMG_OK) {
		self->ch = NULL;
		GD_ERR("SmgCharacter: cannot create the libsmg character: %s", smg_result_string(r));
		return false;
	}
	self->blob = smg_gd_blob_retain(b);
	self->ground_given = false;
	if (self->root_motion_mode == SMG_GD_ENGINE_MOVER && t.origin[1] != 0.0f) {
		/* start on the mover's floor, not at y = 0 */
		float p[3] = { t.origin[0], t.origin[1], t.origin[2] };
		smg_character_set_ground_position(self->ch, p, heading_of(&t));
	}
	if (!smg_gd_bone_map_init(&self->bones, b->joint_count)) {
		GD_ERR("SmgCharacter: out of memory");
		smg_gd_character_teardown(self);
		return false;
	}
	self->bones.bone_map = &self->bone_map_var;
	/* Replay what the user gave the previous character. */
	smg_gd_mirror_replay(&self->mirror, self->ch);
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (smg_character_get_state(self->ch, &st) == SMG_OK) {
		self->last_style = st.style;
		self->last_action = st.action;
	}
	return true;
}

bool smg_gd_character_need(smg_gd_character *self, const char *what) {
	if (smg_gd_character_ensure(self)) return true;
	if (!gd_variant_object(&self->graph_var))
		GD_ERR("SmgCharacter.%s: no graph set (assign an SmgGraph to the 'graph' property first)", what);
	else if (!current_blob(self))
		GD_ERR("SmgCharacter.%s: the SmgGraph has no graph loaded", what);
	else if (self->root_motion_mode == SMG_GD_ENGINE_MOVER && !in_tree(self))
		GD_ERR("SmgCharacter.%s: in engine-mover mode the node must be in the scene tree first", what);
	return false;
}
