/* smg_gd_character.c - SmgCharacter (Node3D): one libsmg character that
 * follows a path drawn at run time and drives a Skeleton3D.
 *
 * Each frame (internal process, so user scripts keep their own _process) it
 * steps the libsmg character, moves its own transform with the root motion
 * (ground position and heading, in its parent's space, which is also the
 * space of the path points) and writes the joint rotations into the target
 * Skeleton3D, matching bones by name. The skeleton is normally a child with
 * an identity transform; its root bone gets the pelvis position relative to
 * this node. Bones the graph does not know are left alone, and graph joints
 * the skeleton lacks are skipped.
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

#include "gd_class.h"
#include "smg_gd_character.h"
#include "smg_gd_graph.h"

#define CLASS "SmgCharacter"

enum { KIND_TRANSITION = 1, KIND_SPLICE = 2 };

typedef struct constraint_rec {
	int64_t id;      /* ours: stable across graph reloads */
	int kind;
	float distance;  /* metres along the path */
	uint32_t value;  /* style or action */
	uint32_t smg_id; /* libsmg's id on the current character */
} constraint_rec;

typedef struct smg_gd_character {
	GDExtensionObjectPtr owner;
	gd_variant graph_var;   /* Ref<SmgGraph> or nil */
	smg_gd_blob *blob;      /* the graph `ch` was created on (retained) */
	smg_character *ch;
	float *rot;             /* 4 * joint_count, pose scratch */

	gd_node_path skeleton_path;
	GDObjectInstanceID skel_id;
	int64_t skel_version;
	int32_t *bone_of_joint; /* joint -> bone index, -1 if missing */
	float *rest_of_joint;   /* 8 per joint: global rest rotation of its
	                         * bone and of that bone's parent (x,y,z,w) */
	bool rests_identity;    /* every mapped bone rests world-aligned */
	bool warned_skeleton, warned_bones, warned_step;

	int64_t style, action;
	double threshold;
	bool ik, active, in_editor;
	bool steering;          /* root steering (smg.h): on by default */
	double steer_limits[3]; /* turn rate rad/s, slide ratio, stop s; 0 = default */
	double swing_clearance; /* foot IK's swing clearance, metres; 0 = default,
	                         * negative = off (as the inspector shows it) */

	float *path_xz;         /* mirror of the path, replayed after reload */
	uint32_t path_count, path_cap;
	constraint_rec *cons;
	uint32_t con_count, con_cap;
	int64_t next_id;

	uint32_t last_style, last_action;
	bool end_reached;
	uint64_t modifier_frame; /* last frame an SmgSkeletonModifier posed us */
} smg_gd_character;

#define PATH_CAPACITY 4096u
#define CONSTRAINT_CAPACITY 64u
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
	free(self->rot);
	self->rot = NULL;
	free(self->bone_of_joint);
	self->bone_of_joint = NULL;
	free(self->rest_of_joint);
	self->rest_of_joint = NULL;
	self->skel_id = 0;
	self->warned_bones = false;
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

/* Make `ch` match the current graph: nothing to do, rebuild after a reload,
 * or tear down when the graph went away. false: no character. */
static bool ensure_character(smg_gd_character *self) {
	smg_gd_blob *b = current_blob(self);
	if (b == self->blob && self->ch) return true;
	teardown(self);
	if (!b) return false;

	gd_transform3d t = get_xform(self);
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
	d.path_capacity = PATH_CAPACITY;
	d.constraint_capacity = CONSTRAINT_CAPACITY;
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
	self->rot = calloc((size_t)b->joint_count * 4u + 4u, sizeof(float));
	if (!self->rot) {
		GD_ERR("SmgCharacter: out of memory");
		teardown(self);
		return false;
	}
	/* Replay what the user gave the previous character. */
	if (self->path_count > 0) {
		r = smg_character_set_path(self->ch, self->path_xz, self->path_count);
		if (r != SMG_OK) GD_ERR("SmgCharacter: path rejected by the new graph: %s", smg_result_string(r));
	}
	for (uint32_t i = 0; i < self->con_count; i++) {
		constraint_rec *c = &self->cons[i];
		r = c->kind == KIND_TRANSITION ? smg_character_add_transition(self->ch, c->distance, c->value, &c->smg_id)
		                               : smg_character_add_splice(self->ch, c->distance, c->value, &c->smg_id);
		if (r != SMG_OK) {
			GD_WARN("SmgCharacter: constraint %lld dropped after the graph changed: %s", (long long)c->id,
				smg_result_string(r));
			self->cons[i--] = self->cons[--self->con_count];
		}
	}
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (smg_character_get_state(self->ch, &st) == SMG_OK) {
		self->last_style = st.style;
		self->last_action = st.action;
		self->end_reached = (st.flags & SMG_STATE_PATH_END_REACHED) != 0;
	}
	return true;
}

/* For methods that need a character: prints the Godot error itself. */
static bool need_character(smg_gd_character *self, const char *what) {
	if (ensure_character(self)) return true;
	if (!gd_variant_object(&self->graph_var))
		GD_ERR("SmgCharacter.%s: no graph set (assign an SmgGraph to the 'graph' property first)", what);
	else if (!current_blob(self))
		GD_ERR("SmgCharacter.%s: the SmgGraph has no graph loaded", what);
	return false;
}

static int64_t to_godot_error(smg_result r) {
	switch (r) {
	case SMG_OK: return GD_OK;
	case SMG_ERROR_INVALID_ARGUMENT: return GD_ERR_INVALID_PARAMETER;
	case SMG_ERROR_OUT_OF_MEMORY: return GD_ERR_OUT_OF_MEMORY;
	case SMG_ERROR_OUT_OF_RANGE:
	case SMG_ERROR_UNKNOWN_STYLE:
	case SMG_ERROR_UNKNOWN_ACTION: return GD_ERR_PARAMETER_RANGE_ERROR;
	case SMG_ERROR_CAPACITY: return GD_ERR_OUT_OF_MEMORY;
	case SMG_ERROR_NOT_FOUND: return GD_ERR_DOES_NOT_EXIST;
	default: return GD_FAILED;
	}
}

/* ---------------- skeleton ---------------- */

static GDExtensionObjectPtr find_skeleton(smg_gd_character *self) {
	if (!gd_node_path_is_empty(&self->skeleton_path)) {
		GDExtensionObjectPtr n = NULL;
		const void *a[1] = { &self->skeleton_path };
		gd_call(GDB_Node_get_node_or_null, self->owner, a, &n);
		return gd_cast(n, "Skeleton3D");
	}
	/* Default: the first Skeleton3D child. */
	int64_t count = 0;
	GDExtensionBool internal = 0;
	const void *ca[1] = { &internal };
	gd_call(GDB_Node_get_child_count, self->owner, ca, &count);
	for (int64_t i = 0; i < count; i++) {
		GDExtensionObjectPtr c = NULL;
		const void *a[2] = { &i, &internal };
		gd_call(GDB_Node_get_child, self->owner, a, &c);
		GDExtensionObjectPtr s = gd_cast(c, "Skeleton3D");
		if (s) return s;
	}
	return NULL;
}

/* Rotation of a rest transform's basis (columns normalised: a scaled
 * rest keeps its orientation), as (x,y,z,w). */
static void basis_rotation(const gd_transform3d *t, float *q) {
	float m[3][3];
	for (int c = 0; c < 3; c++) {
		float l = sqrtf(t->basis[0][c] * t->basis[0][c] + t->basis[1][c] * t->basis[1][c] +
		                t->basis[2][c] * t->basis[2][c]);
		for (int r = 0; r < 3; r++) m[r][c] = l > 0.0f ? t->basis[r][c] / l : (r == c);
	}
	float tr = m[0][0] + m[1][1] + m[2][2];
	if (tr > 0.0f) {
		float s = sqrtf(tr + 1.0f) * 2.0f;
		q[3] = 0.25f * s;
		q[0] = (m[2][1] - m[1][2]) / s;
		q[1] = (m[0][2] - m[2][0]) / s;
		q[2] = (m[1][0] - m[0][1]) / s;
	} else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
		float s = sqrtf(1.0f + m[0][0] - m[1][1] - m[2][2]) * 2.0f;
		q[3] = (m[2][1] - m[1][2]) / s;
		q[0] = 0.25f * s;
		q[1] = (m[0][1] + m[1][0]) / s;
		q[2] = (m[0][2] + m[2][0]) / s;
	} else if (m[1][1] > m[2][2]) {
		float s = sqrtf(1.0f + m[1][1] - m[0][0] - m[2][2]) * 2.0f;
		q[3] = (m[0][2] - m[2][0]) / s;
		q[0] = (m[0][1] + m[1][0]) / s;
		q[1] = 0.25f * s;
		q[2] = (m[1][2] + m[2][1]) / s;
	} else {
		float s = sqrtf(1.0f + m[2][2] - m[0][0] - m[1][1]) * 2.0f;
		q[3] = (m[1][0] - m[0][1]) / s;
		q[0] = (m[0][2] + m[2][0]) / s;
		q[1] = (m[1][2] + m[2][1]) / s;
		q[2] = 0.25f * s;
	}
}

/* The global rest rotation of `bone` (identity for -1). */
static void bone_global_rest(GDExtensionObjectPtr skel, int64_t bone, float *q) {
	q[0] = q[1] = q[2] = 0.0f;
	q[3] = 1.0f;
	if (bone < 0) return;
	gd_transform3d t;
	memset(&t, 0, sizeof t);
	const void *a[1] = { &bone };
	gd_call(GDB_Skeleton3D_get_bone_global_rest, skel, a, &t);
	basis_rotation(&t, q);
}

/* Bones by name, refreshed when the skeleton or its bone list changes. */
static void map_bones(smg_gd_character *self, GDExtensionObjectPtr skel) {
	GDObjectInstanceID id = gd.object_get_instance_id(skel);
	int64_t version = 0;
	gd_call(GDB_Skeleton3D_get_version, skel, NULL, &version);
	if (id == self->skel_id && version == self->skel_version && self->bone_of_joint) return;
	uint32_t n = self->blob->joint_count;
	int32_t *map = realloc(self->bone_of_joint, (n ? n : 1) * sizeof *map);
	if (!map) return;
	self->bone_of_joint = map;
	float *rest = realloc(self->rest_of_joint, (n ? n : 1) * 8 * sizeof *rest);
	if (!rest) {
		free(map);
		self->bone_of_joint = NULL;
		return;
	}
	self->rest_of_joint = rest;
	self->rests_identity = true;
	self->skel_id = id;
	self->skel_version = version;
	uint32_t matched = 0;
	for (uint32_t j = 0; j < n; j++) {
		smg_joint_info ji;
		memset(&ji, 0, sizeof ji);
		ji.struct_size = sizeof ji;
		map[j] = -1;
		if (smg_graph_get_joint(self->blob->graph, j, &ji) != SMG_OK || !ji.name) continue;
		char bone_name[256];
		smg_gd_bone_name(ji.name, bone_name, sizeof bone_name);
		gd_string name;
		gd_str_init(&name, bone_name);
		int64_t bone = -1;
		const void *a[1] = { &name };
		gd_call(GDB_Skeleton3D_find_bone, skel, a, &bone);
		gd_str_destroy(&name);
		if (bone >= 0 && bone <= INT32_MAX) {
			map[j] = (int32_t)bone;
			matched++;
			/* A rig whose bones have their own rest orientation (not the
			 * graph's world-aligned rest) gets its rotations conjugated in
			 * write_pose_to. */
			int64_t parent = -1;
			const void *pa[1] = { &bone };
			gd_call(GDB_Skeleton3D_get_bone_parent, skel, pa, &parent);
			bone_global_rest(skel, bone, &rest[8 * j]);
			bone_global_rest(skel, parent, &rest[8 * j + 4]);
			for (int k = 0; k < 8; k++)
				if (fabsf(rest[8 * j + k] - (k % 4 == 3 ? 1.0f : 0.0f)) > 1e-6f)
					self->rests_identity = false;
		}
	}
	if (matched < n && !self->warned_bones) {
		self->warned_bones = true;
		GD_WARN("SmgCharacter: %u of %u graph joints have no bone of the same name in the skeleton; "
		        "they are not animated", n - matched, n);
	}
}

static void quat_mul(const float *a, const float *b, float *out) {
	float x = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
	float y = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
	float z = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
	float w = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
	out[0] = x;
	out[1] = y;
	out[2] = z;
	out[3] = w;
}

/* Writes the current pose into skel (bones by name). */
static void write_pose_to(smg_gd_character *self, GDExtensionObjectPtr skel) {
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (!self->ch || !self->blob || smg_character_get_state(self->ch, &st) != SMG_OK) return;
	map_bones(self, skel);
	if (!self->bone_of_joint) return;
	uint32_t n = self->blob->joint_count;
	float root[3];
	if (smg_character_get_local_pose(self->ch, root, self->rot, n) != SMG_OK) return;

	/* Joint 0 comes in parent space; this node already carries
	 * (position, heading), so express the root relative to it. */
	float h = st.heading, c = cosf(h), s = sinf(h);
	float dx = root[0] - st.position[0], dz = root[2] - st.position[2];
	gd_vec3 root_local = { c * dx - s * dz, root[1], s * dx + c * dz };
	float inv_yaw[4] = { 0.0f, sinf(-h * 0.5f), 0.0f, cosf(-h * 0.5f) };
	quat_mul(inv_yaw, &self->rot[0], &self->rot[0]);

	for (uint32_t j = 0; j < n; j++) {
		int64_t bone = self->bone_of_joint[j];
		if (bone < 0) continue;
		if (!self->rests_identity) {
			/* graph rotations are relative to a world-aligned rest: bone
			 * pose = parent bone's global rest^-1 * q * bone's global rest */
			const float *r = &self->rest_of_joint[8 * j];
			float pi[4] = { -r[4], -r[5], -r[6], r[7] }, t[4];
			quat_mul(&self->rot[4 * j], r, t);
			quat_mul(pi, t, &self->rot[4 * j]);
		}
		const void *a[2] = { &bone, &self->rot[4 * j] };
		gd_call(GDB_Skeleton3D_set_bone_pose_rotation, skel, a, NULL);
		if (j == 0) {
			const void *p[2] = { &bone, &root_local };
			gd_call(GDB_Skeleton3D_set_bone_pose_position, skel, p, NULL);
		}
	}
}

static uint64_t process_frame(void) {
	GDExtensionObjectPtr engine = gd_singleton("Engine");
	uint64_t f = 0;
	if (engine) gd_call(GDB_Engine_get_process_frames, engine, NULL, &f);
	return f;
}

/* The pose goes in from here unless an SmgSkeletonModifier applies it in
 * the skeleton's modifier stage (it did so in the last two frames). */
static void write_pose(smg_gd_character *self) {
	if (self->modifier_frame && self->modifier_frame + 2 >= process_frame()) return;
	GDExtensionObjectPtr skel = find_skeleton(self);
	if (!skel) {
		if (!self->warned_skeleton) {
			self->warned_skeleton = true;
			GD_WARN("SmgCharacter: no target Skeleton3D (set 'skeleton' or add a Skeleton3D child); "
			        "only the node moves");
		}
		return;
	}
	self->warned_skeleton = false;
	write_pose_to(self, skel);
}

bool smg_gd_character_apply_pose(GDExtensionObjectPtr character, GDExtensionObjectPtr skel) {
	smg_gd_character *self = gd_object_self(character, CLASS);
	if (!self || !skel) return false;
	self->modifier_frame = process_frame();
	if (!ensure_character(self)) return false;
	write_pose_to(self, skel);
	return true;
}

/* ---------------- per frame ---------------- */

/* Steps, moves the node, poses the skeleton, then emits signals last: a
 * handler may free this node or change its graph, so nothing touches
 * `self` after the first emit unless the node is verified alive. */
static int64_t step(smg_gd_character *self, double dt) {
	if (!ensure_character(self)) return GD_ERR_UNCONFIGURED;
	if (!(dt >= 0.0)) dt = 0.0; /* also NaN */
	smg_result r = SMG_OK;
	while (dt > 0.0 && r == SMG_OK) {
		double d = dt > MAX_STEP ? MAX_STEP : dt;
		r = smg_character_step(self->ch, (float)d);
		dt -= d;
	}
	if (r != SMG_OK) {
		if (!self->warned_step) GD_ERR("SmgCharacter: step failed: %s", smg_result_string(r));
		self->warned_step = true;
		return to_godot_error(r);
	}
	self->warned_step = false;
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (smg_character_get_state(self->ch, &st) != SMG_OK) return GD_FAILED;

	gd_transform3d t = get_xform(self);
	float c = cosf(st.heading), s = sinf(st.heading);
	gd_transform3d nt = { { { c, 0, s }, { 0, 1, 0 }, { -s, 0, c } }, { st.position[0], t.origin[1], st.position[2] } };
	const void *ta[1] = { &nt };
	gd_call(GDB_Node3D_set_transform, self->owner, ta, NULL);
	write_pose(self);

	bool style_changed = st.style != self->last_style;
	bool action_changed = st.action != self->last_action;
	bool end = (st.flags & SMG_STATE_PATH_END_REACHED) != 0;
	bool end_now = end && !self->end_reached;
	self->last_style = st.style;
	self->last_action = st.action;
	self->end_reached = end;

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
	if (end_now && gd.object_get_instance_from_id(oid)) gd_emit(owner, "path_end_reached", NULL, 0);
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
		step(self, dt);
	}
}

/* ---------------- methods ---------------- */

#define SELF smg_gd_character *self = vself

static void m_set_graph(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].o && !smg_gd_graph_from_object(a[0].o)) {
		GD_ERR("SmgCharacter.graph: expected an SmgGraph");
		return;
	}
	gd_variant_destroy(&self->graph_var);
	gd_variant_from_object(&self->graph_var, a[0].o);
	ensure_character(self); /* quietly: a graph may be assigned before loading */
}

static void m_get_graph(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->o = gd_variant_object(&self->graph_var);
}

static void m_set_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	gd_node_path_destroy(&self->skeleton_path);
	gd_node_path_copy(&self->skeleton_path, &a[0].np);
	self->skel_id = 0;
	self->warned_skeleton = false;
}

static void m_get_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	gd_node_path_copy(&r->np, &self->skeleton_path);
}

static void m_set_style(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].i < 0 || a[0].i > UINT32_MAX) {
		GD_ERR("SmgCharacter.style: %lld is not a style index", (long long)a[0].i);
		return;
	}
	if (self->ch) {
		smg_result res = smg_character_set_style(self->ch, (uint32_t)a[0].i);
		if (res != SMG_OK) {
			GD_ERR("SmgCharacter.style: %lld rejected: %s", (long long)a[0].i, smg_result_string(res));
			return;
		}
	}
	self->style = a[0].i;
}

static void m_get_style(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = self->ch ? (int64_t)self->last_style : self->style;
}

static void m_set_action(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].i < 0 || a[0].i > UINT32_MAX) {
		GD_ERR("SmgCharacter.action: %lld is not an action index", (long long)a[0].i);
		return;
	}
	if (self->ch) {
		smg_result res = smg_character_set_action(self->ch, (uint32_t)a[0].i);
		if (res != SMG_OK) {
			GD_ERR("SmgCharacter.action: %lld rejected: %s", (long long)a[0].i, smg_result_string(res));
			return;
		}
	}
	self->action = a[0].i;
}

static void m_get_action(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = self->ch ? (int64_t)self->last_action : self->action;
}

static void m_set_error_threshold(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (!(a[0].f > 0.0) || !isfinite(a[0].f)) {
		GD_ERR("SmgCharacter.error_threshold: must be a positive number of metres");
		return;
	}
	if (self->ch) {
		smg_result res = smg_character_set_error_threshold(self->ch, (float)a[0].f);
		if (res != SMG_OK) {
			GD_ERR("SmgCharacter.error_threshold: rejected: %s", smg_result_string(res));
			return;
		}
	}
	self->threshold = a[0].f;
}

static void m_get_error_threshold(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->threshold;
}

static void m_set_ik_enabled(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	self->ik = a[0].b != 0;
	if (self->ch) smg_character_set_ik(self->ch, self->ik ? 1u : 0u);
}

static void m_is_ik_enabled(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->b = self->ik;
}

static void m_set_steering_enabled(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	self->steering = a[0].b != 0;
	if (self->ch) smg_character_set_steering(self->ch, self->steering ? 1u : 0u);
}

static void m_is_steering_enabled(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->b = self->steering;
}

/* One of the three steering limits (0 = the library's default); the
 * library refuses negative or non-finite values and keeps the old ones. */
static void set_steer_limit(smg_gd_character *self, int which, double v, const char *name) {
	double l[3] = { self->steer_limits[0], self->steer_limits[1], self->steer_limits[2] };
	l[which] = v;
	if (!(v >= 0.0) || !isfinite(v)) {
		GD_ERR("SmgCharacter.%s: must be >= 0 (0 = default)", name);
		return;
	}
	if (self->ch) {
		smg_result res = smg_character_set_steering_limits(self->ch, (float)l[0], (float)l[1], (float)l[2]);
		if (res != SMG_OK) {
			GD_ERR("SmgCharacter.%s: rejected: %s", name, smg_result_string(res));
			return;
		}
	}
	self->steer_limits[which] = v;
}

static void m_set_steer_turn_rate(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	set_steer_limit(self, 0, a[0].f, "steer_turn_rate");
}

static void m_get_steer_turn_rate(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->steer_limits[0];
}

static void m_set_steer_slide_ratio(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	set_steer_limit(self, 1, a[0].f, "steer_slide_ratio");
}

static void m_get_steer_slide_ratio(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->steer_limits[1];
}

static void m_set_stop_seconds(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	set_steer_limit(self, 2, a[0].f, "stop_seconds");
}

static void m_get_stop_seconds(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->steer_limits[2];
}

/* Swing clearance in metres: 0 = the library's default (0.04 leg
 * lengths), negative = off (SMG_CHARACTER_NO_SWING_CLEARANCE): one
 * inspector field for both. */
static void m_set_swing_clearance(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	double v = a[0].f;
	if (!isfinite(v)) {
		GD_ERR("SmgCharacter.swing_clearance: must be finite (0 = default, < 0 = off)");
		return;
	}
	if (self->ch) {
		smg_result res = smg_character_set_swing_clearance(self->ch, v >= 0.0 ? 1u : 0u,
			v > 0.0 ? (float)v : 0.0f);
		if (res != SMG_OK) {
			GD_ERR("SmgCharacter.swing_clearance: rejected: %s", smg_result_string(res));
			return;
		}
	}
	self->swing_clearance = v;
}

static void m_get_swing_clearance(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->swing_clearance;
}

static void m_set_active(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	self->active = a[0].b != 0;
}

static void m_is_active(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->b = self->active;
}

/* Points (x, z) from a PackedVector3Array (y ignored: the ground plane). */
static float *points_xz(const gd_packed *pts, uint32_t *count, const char *what) {
	int64_t n = gd_packed_v3_size(pts);
	*count = 0;
	if (n <= 0) return NULL;
	if (n > PATH_CAPACITY) {
		GD_ERR("SmgCharacter.%s: %lld points, at most %u", what, (long long)n, PATH_CAPACITY);
		return NULL;
	}
	float *xz = malloc((size_t)n * 2 * sizeof(float));
	if (!xz) return NULL;
	for (int64_t i = 0; i < n; i++) {
		const gd_vec3 *p = gd_packed_v3_at(pts, i);
		if (!p || !isfinite(p->x) || !isfinite(p->z)) {
			GD_ERR("SmgCharacter.%s: point %lld is not finite", what, (long long)i);
			free(xz);
			return NULL;
		}
		xz[2 * i] = p->x;
		xz[2 * i + 1] = p->z;
	}
	*count = (uint32_t)n;
	return xz;
}

static bool mirror_reserve(smg_gd_character *self, uint32_t n) {
	if (n <= self->path_cap) return true;
	uint32_t cap = self->path_cap ? self->path_cap : 64;
	while (cap < n) cap *= 2;
	float *p = realloc(self->path_xz, (size_t)cap * 2 * sizeof(float));
	if (!p) return false;
	self->path_xz = p;
	self->path_cap = cap;
	return true;
}

static int64_t set_path_points(smg_gd_character *self, const gd_packed *pts, const char *what) {
	if (gd_packed_v3_size(pts) <= 0) {
		GD_ERR("SmgCharacter.%s: empty path (use clear_path() to stop)", what);
		return GD_ERR_INVALID_PARAMETER;
	}
	if (!need_character(self, what)) return GD_ERR_UNCONFIGURED;
	uint32_t n;
	float *xz = points_xz(pts, &n, what);
	if (!xz) return GD_ERR_INVALID_PARAMETER;
	smg_result r = smg_character_set_path(self->ch, xz, n);
	if (r != SMG_OK || !mirror_reserve(self, n)) {
		free(xz);
		if (r != SMG_OK) GD_ERR("SmgCharacter.%s: %s", what, smg_result_string(r));
		return r != SMG_OK ? to_godot_error(r) : GD_ERR_OUT_OF_MEMORY;
	}
	memcpy(self->path_xz, xz, (size_t)n * 2 * sizeof(float));
	self->path_count = n;
	self->end_reached = false;
	free(xz);
	return GD_OK;
}

static void m_set_path(void *vself, const gd_value *a, gd_value *r) {
	r->i = set_path_points(vself, &a[0].pa, "set_path");
}

static void m_set_path_curve(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	GDExtensionObjectPtr curve = gd_cast(a[0].o, "Curve3D");
	if (!curve) {
		GD_ERR("SmgCharacter.set_path_curve: expected a Curve3D");
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	gd_packed pts;
	gd_packed_init(&pts, GDEXTENSION_VARIANT_TYPE_PACKED_VECTOR3_ARRAY);
	gd_call(GDB_Curve3D_get_baked_points, curve, NULL, &pts);
	r->i = set_path_points(self, &pts, "set_path_curve");
	gd_packed_destroy(&pts, GDEXTENSION_VARIANT_TYPE_PACKED_VECTOR3_ARRAY);
}

static void m_append_path_points(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (gd_packed_v3_size(&a[0].pa) <= 0) {
		r->i = GD_OK; /* nothing to add */
		return;
	}
	if (!need_character(self, "append_path_points")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	uint32_t n;
	float *xz = points_xz(&a[0].pa, &n, "append_path_points");
	if (!xz) {
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	smg_result res = self->path_count == 0 ? smg_character_set_path(self->ch, xz, n)
	                                       : smg_character_append_path(self->ch, xz, n);
	if (res == SMG_OK && mirror_reserve(self, self->path_count + n)) {
		memcpy(self->path_xz + 2 * (size_t)self->path_count, xz, (size_t)n * 2 * sizeof(float));
		self->path_count += n;
		self->end_reached = false;
		r->i = GD_OK;
	} else {
		if (res != SMG_OK) GD_ERR("SmgCharacter.append_path_points: %s", smg_result_string(res));
		r->i = res != SMG_OK ? to_godot_error(res) : GD_ERR_OUT_OF_MEMORY;
	}
	free(xz);
}

static void m_clear_path(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	if (!need_character(self, "clear_path")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	smg_result res = smg_character_clear_path(self->ch);
	if (res == SMG_OK) self->path_count = 0;
	else GD_ERR("SmgCharacter.clear_path: %s", smg_result_string(res));
	r->i = to_godot_error(res);
}

static smg_character_state state_of(smg_gd_character *self) {
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (self->ch) smg_character_get_state(self->ch, &st);
	return st;
}

static void m_get_path_length(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	float len = 0.0f;
	if (self->ch) smg_character_get_path_length(self->ch, &len);
	r->f = len;
}
static void m_get_path_distance(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	r->f = state_of(vself).path_distance;
}
static void m_get_path_error(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	r->f = state_of(vself).path_error;
}
static void m_is_path_end_reached(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	r->b = (state_of(vself).flags & SMG_STATE_PATH_END_REACHED) != 0;
}
static void m_get_root_position(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	smg_character_state st = state_of(self);
	r->v3 = (gd_vec3){ st.position[0], st.position[1], st.position[2] };
}
static void m_get_time(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	r->f = state_of(vself).time;
}

static constraint_rec *find_con(smg_gd_character *self, int64_t id) {
	for (uint32_t i = 0; i < self->con_count; i++)
		if (self->cons[i].id == id) return &self->cons[i];
	return NULL;
}

static int64_t add_constraint(smg_gd_character *self, int kind, double dist, int64_t value, const char *what) {
	if (!need_character(self, what)) return -1;
	if (!isfinite(dist) || dist < 0.0 || value < 0 || value > UINT32_MAX) {
		GD_ERR("SmgCharacter.%s: bad distance %g or index %lld", what, dist, (long long)value);
		return -1;
	}
	if (self->con_count == self->con_cap) {
		uint32_t cap = self->con_cap ? self->con_cap * 2 : 8;
		constraint_rec *c = realloc(self->cons, cap * sizeof *c);
		if (!c) return -1;
		self->cons = c;
		self->con_cap = cap;
	}
	uint32_t sid = 0;
	smg_result res = kind == KIND_TRANSITION
		? smg_character_add_transition(self->ch, (float)dist, (uint32_t)value, &sid)
		: smg_character_add_splice(self->ch, (float)dist, (uint32_t)value, &sid);
	if (res != SMG_OK) {
		GD_ERR("SmgCharacter.%s(%g, %lld): %s", what, dist, (long long)value, smg_result_string(res));
		return -1;
	}
	constraint_rec *c = &self->cons[self->con_count++];
	c->id = ++self->next_id;
	c->kind = kind;
	c->distance = (float)dist;
	c->value = (uint32_t)value;
	c->smg_id = sid;
	return c->id;
}

static void m_add_transition(void *vself, const gd_value *a, gd_value *r) {
	r->i = add_constraint(vself, KIND_TRANSITION, a[0].f, a[1].i, "add_transition");
}
static void m_add_splice(void *vself, const gd_value *a, gd_value *r) {
	r->i = add_constraint(vself, KIND_SPLICE, a[0].f, a[1].i, "add_splice");
}

static void m_move_constraint(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (!need_character(self, "move_constraint")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	constraint_rec *c = find_con(self, a[0].i);
	if (!c) {
		GD_ERR("SmgCharacter.move_constraint: no constraint with id %lld", (long long)a[0].i);
		r->i = GD_ERR_DOES_NOT_EXIST;
		return;
	}
	if (!isfinite(a[1].f) || a[1].f < 0.0) {
		GD_ERR("SmgCharacter.move_constraint: bad distance %g", a[1].f);
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	smg_result res = smg_character_move_constraint(self->ch, c->smg_id, (float)a[1].f);
	if (res == SMG_OK) c->distance = (float)a[1].f;
	else GD_ERR("SmgCharacter.move_constraint: %s", smg_result_string(res));
	r->i = to_godot_error(res);
}

static void m_remove_constraint(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (!need_character(self, "remove_constraint")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	constraint_rec *c = find_con(self, a[0].i);
	if (!c) {
		GD_ERR("SmgCharacter.remove_constraint: no constraint with id %lld", (long long)a[0].i);
		r->i = GD_ERR_DOES_NOT_EXIST;
		return;
	}
	smg_result res = smg_character_remove_constraint(self->ch, c->smg_id);
	if (res != SMG_OK) GD_ERR("SmgCharacter.remove_constraint: %s", smg_result_string(res));
	*c = self->cons[--self->con_count]; /* gone from our list either way */
	r->i = to_godot_error(res);
}

static void m_clear_constraints(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	if (!need_character(self, "clear_constraints")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	smg_result res = smg_character_clear_constraints(self->ch);
	self->con_count = 0;
	r->i = to_godot_error(res);
}

static void m_step(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (!need_character(self, "step")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	if (!(a[0].f >= 0.0) || !isfinite(a[0].f)) {
		GD_ERR("SmgCharacter.step: delta must be >= 0 (got %g)", a[0].f);
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	r->i = step(self, a[0].f);
}

/* Builds a Skeleton3D for the graph, adds it as a child and returns it. */
static void m_create_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->o = NULL;
	GDExtensionObjectPtr gobj = gd_variant_object(&self->graph_var);
	if (!need_character(self, "create_skeleton") || !gobj) return;
	GDExtensionObjectPtr skel = smg_gd_graph_build_skeleton(smg_gd_graph_from_object(gobj));
	if (!skel) {
		GD_ERR("SmgCharacter.create_skeleton: could not build a skeleton");
		return;
	}
	GDExtensionBool readable = 1;
	int64_t internal = 0;
	const void *aa[3] = { &skel, &readable, &internal };
	gd_call(GDB_Node_add_child, self->owner, aa, NULL);
	self->skel_id = 0;
	r->o = skel;
}

static const gd_method methods[] = {
	{ "set_graph", m_set_graph, GT_NIL, NULL, 1, { { "graph", GT_REF, "SmgGraph" } }, 0 },
	{ "get_graph", m_get_graph, GT_REF, "SmgGraph", 0, { { 0 } }, 1 },
	{ "set_skeleton", m_set_skeleton, GT_NIL, NULL, 1, { { "path", GT_NODE_PATH, NULL } }, 0 },
	{ "get_skeleton", m_get_skeleton, GT_NODE_PATH, NULL, 0, { { 0 } }, 1 },
	{ "set_style", m_set_style, GT_NIL, NULL, 1, { { "style", GT_INT, NULL } }, 0 },
	{ "get_style", m_get_style, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "set_action", m_set_action, GT_NIL, NULL, 1, { { "action", GT_INT, NULL } }, 0 },
	{ "get_action", m_get_action, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "set_error_threshold", m_set_error_threshold, GT_NIL, NULL, 1, { { "metres", GT_FLOAT, NULL } }, 0 },
	{ "get_error_threshold", m_get_error_threshold, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_ik_enabled", m_set_ik_enabled, GT_NIL, NULL, 1, { { "enabled", GT_BOOL, NULL } }, 0 },
	{ "is_ik_enabled", m_is_ik_enabled, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "set_steering_enabled", m_set_steering_enabled, GT_NIL, NULL, 1, { { "enabled", GT_BOOL, NULL } }, 0 },
	{ "is_steering_enabled", m_is_steering_enabled, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "set_steer_turn_rate", m_set_steer_turn_rate, GT_NIL, NULL, 1, { { "radians_per_second", GT_FLOAT, NULL } }, 0 },
	{ "get_steer_turn_rate", m_get_steer_turn_rate, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_steer_slide_ratio", m_set_steer_slide_ratio, GT_NIL, NULL, 1, { { "ratio", GT_FLOAT, NULL } }, 0 },
	{ "get_steer_slide_ratio", m_get_steer_slide_ratio, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_stop_seconds", m_set_stop_seconds, GT_NIL, NULL, 1, { { "seconds", GT_FLOAT, NULL } }, 0 },
	{ "get_stop_seconds", m_get_stop_seconds, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_swing_clearance", m_set_swing_clearance, GT_NIL, NULL, 1, { { "metres", GT_FLOAT, NULL } }, 0 },
	{ "get_swing_clearance", m_get_swing_clearance, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_active", m_set_active, GT_NIL, NULL, 1, { { "active", GT_BOOL, NULL } }, 0 },
	{ "is_active", m_is_active, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "set_path", m_set_path, GT_INT, NULL, 1, { { "points", GT_PV3, NULL } }, 0 },
	{ "set_path_curve", m_set_path_curve, GT_INT, NULL, 1, { { "curve", GT_REF, "Curve3D" } }, 0 },
	{ "append_path_points", m_append_path_points, GT_INT, NULL, 1, { { "points", GT_PV3, NULL } }, 0 },
	{ "clear_path", m_clear_path, GT_INT, NULL, 0, { { 0 } }, 0 },
	{ "get_path_length", m_get_path_length, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "get_path_distance", m_get_path_distance, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "get_path_error", m_get_path_error, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "is_path_end_reached", m_is_path_end_reached, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "get_root_position", m_get_root_position, GT_VEC3, NULL, 0, { { 0 } }, 1 },
	{ "get_time", m_get_time, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "add_transition", m_add_transition, GT_INT, NULL, 2,
	  { { "distance", GT_FLOAT, NULL }, { "style", GT_INT, NULL } }, 0 },
	{ "add_splice", m_add_splice, GT_INT, NULL, 2,
	  { { "distance", GT_FLOAT, NULL }, { "action", GT_INT, NULL } }, 0 },
	{ "move_constraint", m_move_constraint, GT_INT, NULL, 2,
	  { { "id", GT_INT, NULL }, { "distance", GT_FLOAT, NULL } }, 0 },
	{ "remove_constraint", m_remove_constraint, GT_INT, NULL, 1, { { "id", GT_INT, NULL } }, 0 },
	{ "clear_constraints", m_clear_constraints, GT_INT, NULL, 0, { { 0 } }, 0 },
	{ "step", m_step, GT_INT, NULL, 1, { { "delta", GT_FLOAT, NULL } }, 0 },
	{ "create_skeleton", m_create_skeleton, GT_OBJECT, "Skeleton3D", 0, { { 0 } }, 0 },
};

/* ---------------- class ---------------- */

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	smg_gd_character *self = calloc(1, sizeof *self);
	if (!self) return NULL;
	gd_variant_nil(&self->graph_var);
	gd_node_path_init(&self->skeleton_path, "");
	self->threshold = 0.25;
	self->ik = true;
	self->steering = true;
	self->active = true;
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
	gd_node_path_destroy(&self->skeleton_path);
	free(self->path_xz);
	free(self->cons);
	free(self);
}

void smg_gd_character_register(void) {
	gd_register_class(CLASS, "Node3D", create, destroy, notification, NULL);
	gd_register_methods(CLASS, methods, (int)(sizeof methods / sizeof methods[0]));

	gd_arg p_graph = { "graph", GT_REF, "SmgGraph" };
	gd_register_property(CLASS, &p_graph, GD_PROPERTY_HINT_RESOURCE_TYPE, "SmgGraph", "set_graph", "get_graph");
	gd_arg p_skel = { "skeleton", GT_NODE_PATH, NULL };
	gd_register_property(CLASS, &p_skel, GD_PROPERTY_HINT_NODE_PATH_VALID_TYPES, "Skeleton3D", "set_skeleton",
		"get_skeleton");
	gd_arg p_style = { "style", GT_INT, NULL };
	gd_register_property(CLASS, &p_style, GD_PROPERTY_HINT_RANGE, "0,15,1,or_greater", "set_style", "get_style");
	gd_arg p_action = { "action", GT_INT, NULL };
	gd_register_property(CLASS, &p_action, GD_PROPERTY_HINT_RANGE, "0,15,1,or_greater", "set_action", "get_action");
	gd_arg p_thr = { "error_threshold", GT_FLOAT, NULL };
	gd_register_property(CLASS, &p_thr, GD_PROPERTY_HINT_RANGE, "0.01,5.0,0.01,suffix:m", "set_error_threshold",
		"get_error_threshold");
	gd_arg p_ik = { "ik_enabled", GT_BOOL, NULL };
	gd_register_property(CLASS, &p_ik, GD_PROPERTY_HINT_NONE, NULL, "set_ik_enabled", "is_ik_enabled");
	gd_arg p_steer = { "steering_enabled", GT_BOOL, NULL };
	gd_register_property(CLASS, &p_steer, GD_PROPERTY_HINT_NONE, NULL, "set_steering_enabled", "is_steering_enabled");
	gd_arg p_turn = { "steer_turn_rate", GT_FLOAT, NULL };
	gd_register_property(CLASS, &p_turn, GD_PROPERTY_HINT_RANGE, "0,6.3,0.01,suffix:rad/s", "set_steer_turn_rate",
		"get_steer_turn_rate");
	gd_arg p_slide = { "steer_slide_ratio", GT_FLOAT, NULL };
	gd_register_property(CLASS, &p_slide, GD_PROPERTY_HINT_RANGE, "0,1,0.01", "set_steer_slide_ratio",
		"get_steer_slide_ratio");
	gd_arg p_stop = { "stop_seconds", GT_FLOAT, NULL };
	gd_register_property(CLASS, &p_stop, GD_PROPERTY_HINT_RANGE, "0,5,0.05,suffix:s", "set_stop_seconds",
		"get_stop_seconds");
	gd_arg p_swing = { "swing_clearance", GT_FLOAT, NULL };
	gd_register_property(CLASS, &p_swing, GD_PROPERTY_HINT_RANGE, "-0.01,0.2,0.005,suffix:m", "set_swing_clearance",
		"get_swing_clearance");
	gd_arg p_active = { "active", GT_BOOL, NULL };
	gd_register_property(CLASS, &p_active, GD_PROPERTY_HINT_NONE, NULL, "set_active", "is_active");

	gd_arg sig_style[2] = { { "style", GT_INT, NULL }, { "style_name", GT_STRING, NULL } };
	gd_register_signal(CLASS, "style_changed", sig_style, 2);
	gd_arg sig_action[2] = { { "action", GT_INT, NULL }, { "action_name", GT_STRING, NULL } };
	gd_register_signal(CLASS, "action_changed", sig_action, 2);
	gd_register_signal(CLASS, "path_end_reached", NULL, 0);
}

void smg_gd_character_unregister(void) {
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
}
