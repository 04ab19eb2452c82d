/* smg_gd_character.c - SmgCharacter (Node3D): one libsmg character that
 * follows a path drawn at run time and drives a Skeleton3D.
 *
 * Each frame (internal process, so user scripts keep their own _process) it
 * steps the libsmg character, moves its own transform with the root motion
 * (ground position and heading, in its parent's space, which is also the
 * space of the path points) and writes the joint rotations into the target
 * Skeleton3D, matching bones by name. The skeleton is normally a child with
 * an identity transform; its root bone gets the pelvis position relative to
 * this node (the matching: smg_gd_bone_map.c). This file holds the
 * character's lifetime and frame; the methods scripts call are in
 * smg_gd_character_methods.c.
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
#define MAX_STEP 0.25 /* seconds; longer frames (hitches) are split */

/* ---------------- graph and character lifetime ---------------- */

static void teardown(smg_gd_character *self) {
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

static gd_transform3d get_xform(smg_gd_character *self) {
	gd_transform3d t;
	memset(&t, 0, sizeof t);
	gd_call(GDB_Node3D_get_transform, self->owner, NULL, &t);
	return t;
}

static const char *style_name(smg_gd_character *self, uint32_t s) {
	const char *n = NULL;
	if (!self->blob || smg_graph_get_style_name(self->blob->graph, s, &n) != SMG_OK) n = NULL;
	return n ? n : "";
}
static const char *action_name(smg_gd_character *self, uint32_t a) {
	const char *n = NULL;
	if (!self->blob || smg_graph_get_action_name(self->blob->graph, a, &n) != SMG_OK) n = NULL;
	return n ? n : "";
}

static bool in_tree(smg_gd_character *self) {
	GDExtensionBool r = 0;
	gd_call(GDB_Node_is_inside_tree, self->owner, NULL, &r);
	return r != 0;
}

bool smg_gd_character_ensure(smg_gd_character *self) {
	smg_gd_blob *b = current_blob(self);
	if (b == self->blob && self->ch) return true;
	teardown(self);
	if (!b) return false;

	/* libsmg's space: the parent's (the node moves in it) or, with the
	 * engine's mover, global space */
	gd_transform3d t = get_xform(self);
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
		teardown(self);
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

/* ---------------- pose ---------------- */

static uint64_t process_frame(void) {
	GDExtensionObjectPtr engine = gd_singleton("Engine");
	uint64_t f = 0;
	if (engine) gd_call(GDB_Engine_get_process_frames, engine, NULL, &f);
	return f;
}

/* The pose goes in from here unless an SmgSkeletonModifier applies it in
 * the skeleton's modifier stage (it did so in the last two frames). The
 * skeleton is looked up every frame, never kept as a pointer, so freeing
 * or replacing it is safe. */
/* An active SmgSkeletonModifier under skel: it applies the pose, from the
 * first frame on (a pose written here would stay under its mask). */
static bool has_modifier(GDExtensionObjectPtr skel) {
	int64_t count = 0;
	GDExtensionBool internal = 0;
	const void *ca[1] = { &internal };
	gd_call(GDB_Node_get_child_count, skel, ca, &count);
	for (int64_t i = 0; i < count; i++) {
		GDExtensionObjectPtr c = NULL;
		const void *a[2] = { &i, &internal };
		gd_call(GDB_Node_get_child, skel, a, &c);
		GDExtensionObjectPtr m = gd_cast(c, "SmgSkeletonModifier");
		GDExtensionBool active = 0;
		if (m) gd_call(GDB_SkeletonModifier3D_is_active, m, NULL, &active);
		if (active) return true;
	}
	return false;
}

static void write_pose(smg_gd_character *self) {
	if (self->modifier_frame && self->modifier_frame + 2 >= process_frame()) return;
	GDExtensionObjectPtr skel = smg_gd_find_skeleton(self->owner, &self->skeleton_path);
	if (skel && has_modifier(skel)) return;
	if (!skel) {
		if (!self->warned_skeleton) {
			self->warned_skeleton = true;
			GD_WARN("SmgCharacter: no target Skeleton3D (set 'skeleton' or add a Skeleton3D child); "
			        "only the node moves");
		}
		return;
	}
	self->warned_skeleton = false;
	smg_gd_bone_map_write_pose(&self->bones, self->blob->graph, self->ch, skel, NULL);
}

bool smg_gd_character_apply_pose(GDExtensionObjectPtr character, GDExtensionObjectPtr skel,
	const smg_gd_mask *mask) {
	smg_gd_character *self = gd_object_self(character, CLASS);
	if (!self || !skel) return false;
	self->modifier_frame = process_frame();
	if (!smg_gd_character_ensure(self)) return false;
	smg_gd_bone_map_write_pose(&self->bones, self->blob->graph, self->ch, skel, mask);
	return true;
}

/* ---------------- per frame ---------------- */

/* Steps, moves the node, poses the skeleton, then emits signals last: a
 * handler may free this node or change its graph, so nothing touches
 * `self` after the first emit unless the node is verified alive. */
int64_t smg_gd_character_step(smg_gd_character *self, double dt) {
	if (!smg_gd_character_ensure(self)) return GD_ERR_UNCONFIGURED;
	if (!(dt >= 0.0)) dt = 0.0; /* also NaN */
	smg_result r = SMG_OK;
	self->event_count = 0;
	memset(self->root_motion, 0, sizeof self->root_motion);
	while (dt > 0.0 && r == SMG_OK) {
		double d = dt > MAX_STEP ? MAX_STEP : dt;
		smg_gd_character_probe_ground(self);
		r = smg_character_step(self->ch, (float)d);
		if (r == SMG_OK) smg_gd_character_collect(self);
		dt -= d;
	}
	if (r != SMG_OK) {
		if (!self->warned_step) GD_ERR("SmgCharacter: step failed: %s", smg_result_string(r));
		self->warned_step = true;
		return smg_gd_error_of(r);
	}
	self->warned_step = false;
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (smg_character_get_state(self->ch, &st) != SMG_OK) return GD_FAILED;

	if (self->root_motion_mode == SMG_GD_MOVE_NODE) {
		/* the node's height: its own, or the ground's once heights are given */
		gd_transform3d t = get_xform(self);
		float c = cosf(st.heading), s = sinf(st.heading);
		float y = self->ground_given ? st.position[1] : t.origin[1];
		gd_transform3d nt = { { { c, 0, s }, { 0, 1, 0 }, { -s, 0, c } }, { st.position[0], y, st.position[2] } };
		const void *ta[1] = { &nt };
		gd_call(GDB_Node3D_set_transform, self->owner, ta, NULL);
	}
	write_pose(self);

	bool style_changed = st.style != self->last_style;
	bool action_changed = st.action != self->last_action;
	self->last_style = st.style;
	self->last_action = st.action;

	GDExtensionObjectPtr owner = self->owner;
	GDObjectInstanceID oid = gd.object_get_instance_id(owner);
	if (style_changed) {
		gd_variant a[2];
		gd_variant_from_int(&a[0], st.style);
		gd_variant_from_cstr(&a[1], style_name(self, st.style));
		gd_emit(owner, "style_changed", a, 2);
		gd_variant_destroy(&a[0]);
		gd_variant_destroy(&a[1]);
	}
	if (action_changed && gd.object_get_instance_from_id(oid)) {
		gd_variant a[2];
		gd_variant_from_int(&a[0], st.action);
		/* self may have been rebuilt by a handler, but it is alive */
		gd_variant_from_cstr(&a[1], action_name(self, st.action));
		gd_emit(owner, "action_changed", a, 2);
		gd_variant_destroy(&a[0]);
		gd_variant_destroy(&a[1]);
	}
	if (gd.object_get_instance_from_id(oid)) smg_gd_character_emit_events(self, oid);
	return GD_OK;
}

static void notification(GDExtensionClassInstancePtr inst, int32_t what, GDExtensionBool reversed) {
	(void)reversed;
	smg_gd_character *self = inst;
	if (what == GD_Node_NOTIFICATION_READY) {
		self->in_editor = gd_is_editor();
		GDExtensionBool on = !self->in_editor;
		const void *a[1] = { &on };
		gd_call(GDB_Node_set_process_internal, self->owner, a, NULL);
	} else if (what == GD_Node_NOTIFICATION_INTERNAL_PROCESS) {
		if (!self->active || self->in_editor) return;
		double dt = 0.0;
		gd_call(GDB_Node_get_process_delta_time, self->owner, NULL, &dt);
		smg_gd_character_step(self, dt);
	}
}

/* ---------------- class ---------------- */

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	smg_gd_character *self = calloc(1, sizeof *self);
	if (!self) return NULL;
	gd_variant_nil(&self->graph_var);
	gd_variant_nil(&self->bone_map_var);
	gd_node_path_init(&self->skeleton_path, "");
	self->threshold = 0.25;
	self->ik = true;
	self->steering = true;
	self->active = true;
	self->ground_mask = 0xFFFFFFFF;
	self->owner = gd_object_create("Node3D", CLASS, self, notify);
	if (!self->owner) {
		gd_node_path_destroy(&self->skeleton_path);
		free(self);
		return NULL;
	}
	return self->owner;
}

static void destroy(void *ud, GDExtensionClassInstancePtr inst) {
	(void)ud;
	smg_gd_character *self = inst;
	teardown(self);                       /* character, then its graph ref */
	gd_variant_destroy(&self->graph_var); /* then the resource itself */
	gd_variant_destroy(&self->bone_map_var);
	gd_node_path_destroy(&self->skeleton_path);
	smg_gd_mirror_free(&self->mirror);
	free(self->events);
	free(self);
}

void smg_gd_character_register(void) {
	gd_register_class(CLASS, "Node3D", create, destroy, notification, NULL);
	smg_gd_character_register_methods();
}

void smg_gd_character_unregister(void) {
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
}
