/* smg_gd_character_frame.c - SmgCharacter's frame: each frame (internal
 * process, so user scripts keep their own _process) it steps the libsmg
 * character, moves its own transform with the root motion (ground position
 * and heading, in its parent's space, which is also the space of the path
 * points) and writes the joint rotations into the target Skeleton3D,
 * matching bones by name. The skeleton is normally a child with an identity
 * transform; its root bone gets the pelvis position relative to this node
 * (the matching: smg_gd_bone_map.c). Signals go out last. */
#include <math.h>
#include <string.h>

#include "smg_gd_character_internal.h"

#define CLASS SMG_GD_CHARACTER_CLASS
#define MAX_STEP 0.25 /* seconds; longer frames (hitches) are split */

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
		gd_transform3d t = smg_gd_character_xform(self);
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
