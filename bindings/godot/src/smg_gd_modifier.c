/* smg_gd_modifier.c - SmgSkeletonModifier (SkeletonModifier3D): applies an
 * SmgCharacter's pose in the skeleton's modifier stage, the Godot 4.3+ way
 * to drive bones. Put it under the Skeleton3D; it finds its character by
 * the `character` NodePath or, when empty, as the nearest SmgCharacter
 * ancestor. The character keeps stepping and moving itself; while a modifier
 * serves it, it stops writing bone poses directly, so the pose blends with
 * `influence` and other modifiers (look-at, IK, ...) that come after it. Like
 * every SkeletonModifier3D result, the pose is transient: read it with
 * Skeleton3D.get_bone_pose*() from the modification_processed signal.
 *
 * The mask: per body part (root, lower, upper: smg_joint_info.body_part)
 * and per bone, how much of libsmg's pose a bone takes; the rest stays as
 * the skeleton had it before this modifier ran, i.e. the AnimationTree's
 * (AnimationMixer) pose, which Godot applies before the modifier stage. */
#include <stdlib.h>
#include <string.h>

#include "gd_class.h"
#include "smg_gd_character.h"
#include "smg_gd_modifier.h"

#define CLASS "SmgSkeletonModifier"

typedef struct smg_gd_modifier {
	GDExtensionObjectPtr owner;
	gd_node_path character_path;
	smg_gd_mask mask;
	bool warned;
} smg_gd_modifier;

static gd_string_name sn_process_with_delta, sn_process;

static GDExtensionObjectPtr find_character(smg_gd_modifier *self) {
	if (!gd_node_path_is_empty(&self->character_path)) {
		GDExtensionObjectPtr n = NULL;
		const void *a[1] = { &self->character_path };
		gd_call(GDB_Node_get_node_or_null, self->owner, a, &n);
		return gd_cast(n, "SmgCharacter");
	}
	GDExtensionObjectPtr n = self->owner;
	for (int depth = 0; n && depth < 64; depth++) {
		GDExtensionObjectPtr parent = NULL;
		gd_call(GDB_Node_get_parent, n, NULL, &parent);
		if (gd_cast(parent, "SmgCharacter")) return parent;
		n = parent;
	}
	return NULL;
}

static void apply(smg_gd_modifier *self) {
	GDExtensionObjectPtr skel = NULL;
	gd_call(GDB_SkeletonModifier3D_get_skeleton, self->owner, NULL, &skel);
	GDExtensionObjectPtr ch = find_character(self);
	if (!skel || !ch) {
		if (!self->warned)
			GD_WARN("SmgSkeletonModifier: needs a Skeleton3D parent and an SmgCharacter (set 'character' or "
			        "place the skeleton under one)");
		self->warned = true;
		return;
	}
	self->warned = false;
	smg_gd_character_apply_pose(ch, skel, &self->mask);
}

static void virt_process_with_delta(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args,
	GDExtensionTypePtr ret) {
	(void)args; /* delta: the character steps itself in its own process */
	(void)ret;
	apply(inst);
}

static void virt_process(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args,
	GDExtensionTypePtr ret) {
	(void)args;
	(void)ret;
	apply(inst);
}

/* StringNames are interned: equal names share one data pointer. */
static bool same_name(GDExtensionConstStringNamePtr a, const gd_string_name *b) {
	return *(void *const *)a == b->p;
}

static GDExtensionClassCallVirtual get_virtual(void *ud, GDExtensionConstStringNamePtr name, uint32_t hash) {
	(void)ud;
	(void)hash;
	if (same_name(name, &sn_process_with_delta)) return virt_process_with_delta;
	if (same_name(name, &sn_process)) return virt_process;
	return NULL;
}

#define SELF smg_gd_modifier *self = vself

static void m_set_character(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	gd_node_path_destroy(&self->character_path);
	gd_node_path_copy(&self->character_path, &a[0].np);
	self->warned = false;
}

static void m_get_character(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	gd_node_path_copy(&r->np, &self->character_path);
}

/* ---- the mask: body-part weights and per-bone weights ---- */

static bool weight_ok(double w, const char *what) {
	if (w >= 0.0 && w <= 1.0) return true;
	GD_ERR("SmgSkeletonModifier.%s: weight must be in [0, 1] (got %g)", what, w);
	return false;
}

#define PART_WEIGHT(which, setter, getter, name)                                  \
	static void setter(void *vself, const gd_value *a, gd_value *r) {              \
		SELF;                                                                      \
		(void)r;                                                                   \
		if (weight_ok(a[0].f, name)) self->mask.part[which] = (float)a[0].f;       \
	}                                                                              \
	static void getter(void *vself, const gd_value *a, gd_value *r) {              \
		SELF;                                                                      \
		(void)a;                                                                   \
		r->f = self->mask.part[which];                                             \
	}
PART_WEIGHT(SMG_BODY_ROOT, m_set_root_weight, m_get_root_weight, "root_weight")
PART_WEIGHT(SMG_BODY_LOWER, m_set_lower_body_weight, m_get_lower_body_weight, "lower_body_weight")
PART_WEIGHT(SMG_BODY_UPPER, m_set_upper_body_weight, m_get_upper_body_weight, "upper_body_weight")

static int64_t find_override(const smg_gd_mask *m, const char *bone) {
	for (uint32_t k = 0; k < m->count; k++)
		if (!strcmp(m->bones[k], bone)) return k;
	return -1;
}

static void m_set_bone_weight(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	char bone[256];
	gd_str_to_c(&a[0].s, bone, sizeof bone);
	if (!bone[0] || !weight_ok(a[1].f, "set_bone_weight")) return;
	int64_t k = find_override(&self->mask, bone);
	if (k < 0) {
		uint32_t n = self->mask.count + 1;
		char **names = realloc(self->mask.bones, n * sizeof *names);
		if (names) self->mask.bones = names;
		float *w = realloc(self->mask.weights, n * sizeof *w);
		if (w) self->mask.weights = w;
		char *copy = names && w ? strdup(bone) : NULL;
		if (!copy) {
			GD_ERR("SmgSkeletonModifier.set_bone_weight: out of memory");
			return;
		}
		k = self->mask.count++;
		self->mask.bones[k] = copy;
	}
	self->mask.weights[k] = (float)a[1].f;
}

static void m_get_bone_weight(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	char bone[256];
	gd_str_to_c(&a[0].s, bone, sizeof bone);
	int64_t k = find_override(&self->mask, bone);
	r->f = k >= 0 ? self->mask.weights[k] : -1.0;
}

static void clear_overrides(smg_gd_mask *m) {
	for (uint32_t k = 0; k < m->count; k++) free(m->bones[k]);
	free(m->bones);
	free(m->weights);
	m->bones = NULL;
	m->weights = NULL;
	m->count = 0;
}

static void m_clear_bone_weights(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	(void)r;
	clear_overrides(&self->mask);
}

static const gd_method methods[] = {
	{ "set_character", m_set_character, GT_NIL, NULL, 1, { { "path", GT_NODE_PATH, NULL } }, 0 },
	{ "get_character", m_get_character, GT_NODE_PATH, NULL, 0, { { 0 } }, 1 },
	{ "set_root_weight", m_set_root_weight, GT_NIL, NULL, 1, { { "weight", GT_FLOAT, NULL } }, 0 },
	{ "get_root_weight", m_get_root_weight, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_lower_body_weight", m_set_lower_body_weight, GT_NIL, NULL, 1, { { "weight", GT_FLOAT, NULL } }, 0 },
	{ "get_lower_body_weight", m_get_lower_body_weight, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_upper_body_weight", m_set_upper_body_weight, GT_NIL, NULL, 1, { { "weight", GT_FLOAT, NULL } }, 0 },
	{ "get_upper_body_weight", m_get_upper_body_weight, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_bone_weight", m_set_bone_weight, GT_NIL, NULL, 2,
	  { { "bone", GT_STRING, NULL }, { "weight", GT_FLOAT, NULL } }, 0 },
	{ "get_bone_weight", m_get_bone_weight, GT_FLOAT, NULL, 1, { { "bone", GT_STRING, NULL } }, 1 },
	{ "clear_bone_weights", m_clear_bone_weights, GT_NIL, NULL, 0, { { 0 } }, 0 },
};

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	smg_gd_modifier *self = calloc(1, sizeof *self);
	if (!self) return NULL;
	gd_node_path_init(&self->character_path, "");
	self->mask.part[SMG_BODY_ROOT] = self->mask.part[SMG_BODY_LOWER] = self->mask.part[SMG_BODY_UPPER] = 1.0f;
	self->owner = gd_object_create("SkeletonModifier3D", CLASS, self, notify);
	if (!self->owner) {
		gd_node_path_destroy(&self->character_path);
		free(self);
		return NULL;
	}
	return self->owner;
}

static void destroy(void *ud, GDExtensionClassInstancePtr inst) {
	(void)ud;
	smg_gd_modifier *self = inst;
	gd_node_path_destroy(&self->character_path);
	clear_overrides(&self->mask);
	free(self);
}

void smg_gd_modifier_register(void) {
	gd_sn_init(&sn_process_with_delta, "_process_modification_with_delta");
	gd_sn_init(&sn_process, "_process_modification");
	gd_register_class(CLASS, "SkeletonModifier3D", create, destroy, NULL, get_virtual);
	gd_register_methods(CLASS, methods, (int)(sizeof methods / sizeof methods[0]));
	gd_arg p_char = { "character", GT_NODE_PATH, NULL };
	gd_register_property(CLASS, &p_char, GD_PROPERTY_HINT_NODE_PATH_VALID_TYPES, "SmgCharacter", "set_character",
		"get_character");
	static const char *const parts[3][3] = { { "root_weight", "set_root_weight", "get_root_weight" },
		{ "lower_body_weight", "set_lower_body_weight", "get_lower_body_weight" },
		{ "upper_body_weight", "set_upper_body_weight", "get_upper_body_weight" } };
	for (int i = 0; i < 3; i++) {
		gd_arg p = { parts[i][0], GT_FLOAT, NULL };
		gd_register_property(CLASS, &p, GD_PROPERTY_HINT_RANGE, "0,1,0.01", parts[i][1], parts[i][2]);
	}
}

void smg_gd_modifier_unregister(void) {
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&sn_process_with_delta);
	gd_sn_destroy(&sn_process);
}
