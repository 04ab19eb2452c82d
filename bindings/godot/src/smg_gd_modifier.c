/* smg_gd_modifier.c - SmgSkeletonModifier (SkeletonModifier3D): applies an
 * SmgCharacter's pose in the skeleton's modifier stage, the Godot 4.3+ way
 * to drive bones. Put it under the Skeleton3D; it finds its character by
 * the `character` NodePath or, when empty, as the nearest SmgCharacter
 * ancestor. The character keeps stepping and moving itself; while a modifier
 * serves it, it stops writing bone poses directly, so the pose blends with
 * `influence` and other modifiers (look-at, IK, ...) that come after it. Like
 * every SkeletonModifier3D result, the pose is transient: read it with
 * Skeleton3D.get_bone_pose*() from the modification_processed signal. */
#include <stdlib.h>
#include <string.h>

#include "gd_class.h"
#include "smg_gd_character.h"
#include "smg_gd_modifier.h"

#define CLASS "SmgSkeletonModifier"

typedef struct smg_gd_modifier {
	GDExtensionObjectPtr owner;
	gd_node_path character_path;
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
	smg_gd_character_apply_pose(ch, skel);
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

static const gd_method methods[] = {
	{ "set_character", m_set_character, GT_NIL, NULL, 1, { { "path", GT_NODE_PATH, NULL } }, 0 },
	{ "get_character", m_get_character, GT_NODE_PATH, NULL, 0, { { 0 } }, 1 },
};

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	smg_gd_modifier *self = calloc(1, sizeof *self);
	if (!self) return NULL;
	gd_node_path_init(&self->character_path, "");
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
}

void smg_gd_modifier_unregister(void) {
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&sn_process_with_delta);
	gd_sn_destroy(&sn_process);
}
