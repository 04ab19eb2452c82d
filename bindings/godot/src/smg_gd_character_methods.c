/* smg_gd_character_methods.c - what scripts see of SmgCharacter: its
 * methods, inspector properties and signals. Each wrapper checks its
 * arguments, keeps the setting for the next rebuilt character and passes it
 * to libsmg; path and constraint edits go through the path mirror
 * (smg_gd_path_mirror.c). Errors are Godot error messages plus an Error
 * return value. */
#include <math.h>
#include <string.h>

#include "smg_gd_character_internal.h"

#define CLASS SMG_GD_CHARACTER_CLASS
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
	smg_gd_character_ensure(self); /* quietly: a graph may be assigned before loading */
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
	smg_gd_bone_map_invalidate(&self->bones);
	self->warned_skeleton = false;
}

static void m_get_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	gd_node_path_copy(&r->np, &self->skeleton_path);
}

static void m_set_bone_map(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].o && !gd_cast(a[0].o, "BoneMap")) {
		GD_ERR("SmgCharacter.bone_map: expected a BoneMap");
		return;
	}
	gd_variant_destroy(&self->bone_map_var);
	gd_variant_from_object(&self->bone_map_var, a[0].o);
	smg_gd_bone_map_invalidate(&self->bones);
	self->bones.warned = false;
}

static void m_get_bone_map(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->o = gd_variant_object(&self->bone_map_var);
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

/* set_path and set_path_curve: an empty array is an error (clear_path()
 * stops), checked before the graph so the message names the real fault. */
static int64_t set_path_points(smg_gd_character *self, const gd_packed *pts, const char *what) {
	if (gd_packed_v3_size(pts) <= 0) {
		GD_ERR("SmgCharacter.%s: empty path (use clear_path() to stop)", what);
		return GD_ERR_INVALID_PARAMETER;
	}
	if (!smg_gd_character_need(self, what)) return GD_ERR_UNCONFIGURED;
	return smg_gd_mirror_set_path(&self->mirror, self->ch, pts, what);
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
	if (!smg_gd_character_need(self, "append_path_points")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	r->i = smg_gd_mirror_append_path(&self->mirror, self->ch, &a[0].pa);
}

static void m_clear_path(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = smg_gd_character_need(self, "clear_path") ? smg_gd_mirror_clear_path(&self->mirror, self->ch)
	                                                 : GD_ERR_UNCONFIGURED;
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

static int64_t add_constraint(smg_gd_character *self, smg_gd_constraint_kind kind, double dist, int64_t value,
	const char *what) {
	if (!smg_gd_character_need(self, what)) return -1;
	return smg_gd_mirror_add(&self->mirror, self->ch, kind, dist, value, what);
}

static void m_add_transition(void *vself, const gd_value *a, gd_value *r) {
	r->i = add_constraint(vself, SMG_GD_TRANSITION, a[0].f, a[1].i, "add_transition");
}
static void m_add_splice(void *vself, const gd_value *a, gd_value *r) {
	r->i = add_constraint(vself, SMG_GD_SPLICE, a[0].f, a[1].i, "add_splice");
}

static void m_move_constraint(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	r->i = smg_gd_character_need(self, "move_constraint")
		? smg_gd_mirror_move(&self->mirror, self->ch, a[0].i, a[1].f)
		: GD_ERR_UNCONFIGURED;
}

static void m_remove_constraint(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	r->i = smg_gd_character_need(self, "remove_constraint")
		? smg_gd_mirror_remove(&self->mirror, self->ch, a[0].i)
		: GD_ERR_UNCONFIGURED;
}

static void m_clear_constraints(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = smg_gd_character_need(self, "clear_constraints")
		? smg_gd_mirror_clear_constraints(&self->mirror, self->ch)
		: GD_ERR_UNCONFIGURED;
}

static void m_step(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (!smg_gd_character_need(self, "step")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	if (!(a[0].f >= 0.0) || !isfinite(a[0].f)) {
		GD_ERR("SmgCharacter.step: delta must be >= 0 (got %g)", a[0].f);
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	r->i = smg_gd_character_step(self, a[0].f);
}

/* Builds a Skeleton3D for the graph, adds it as a child and returns it. */
static void m_create_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->o = NULL;
	GDExtensionObjectPtr gobj = gd_variant_object(&self->graph_var);
	if (!smg_gd_character_need(self, "create_skeleton") || !gobj) return;
	GDExtensionObjectPtr skel = smg_gd_graph_build_skeleton(smg_gd_graph_from_object(gobj));
	if (!skel) {
		GD_ERR("SmgCharacter.create_skeleton: could not build a skeleton");
		return;
	}
	GDExtensionBool readable = 1;
	int64_t internal = 0;
	const void *aa[3] = { &skel, &readable, &internal };
	gd_call(GDB_Node_add_child, self->owner, aa, NULL);
	smg_gd_bone_map_invalidate(&self->bones);
	r->o = skel;
}

static const gd_method methods[] = {
	{ "set_graph", m_set_graph, GT_NIL, NULL, 1, { { "graph", GT_REF, "SmgGraph" } }, 0 },
	{ "get_graph", m_get_graph, GT_REF, "SmgGraph", 0, { { 0 } }, 1 },
	{ "set_skeleton", m_set_skeleton, GT_NIL, NULL, 1, { { "path", GT_NODE_PATH, NULL } }, 0 },
	{ "get_skeleton", m_get_skeleton, GT_NODE_PATH, NULL, 0, { { 0 } }, 1 },
	{ "set_bone_map", m_set_bone_map, GT_NIL, NULL, 1, { { "bone_map", GT_REF, "BoneMap" } }, 0 },
	{ "get_bone_map", m_get_bone_map, GT_REF, "BoneMap", 0, { { 0 } }, 1 },
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

void smg_gd_character_register_methods(void) {
	gd_register_methods(CLASS, methods, (int)(sizeof methods / sizeof methods[0]));
	smg_gd_character_register_scene_methods();

	gd_arg p_graph = { "graph", GT_REF, "SmgGraph" };
	gd_register_property(CLASS, &p_graph, GD_PROPERTY_HINT_RESOURCE_TYPE, "SmgGraph", "set_graph", "get_graph");
	gd_arg p_skel = { "skeleton", GT_NODE_PATH, NULL };
	gd_register_property(CLASS, &p_skel, GD_PROPERTY_HINT_NODE_PATH_VALID_TYPES, "Skeleton3D", "set_skeleton",
		"get_skeleton");
	gd_arg p_bmap = { "bone_map", GT_REF, "BoneMap" };
	gd_register_property(CLASS, &p_bmap, GD_PROPERTY_HINT_RESOURCE_TYPE, "BoneMap", "set_bone_map", "get_bone_map");
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
