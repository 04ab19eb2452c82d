/* smg_gd_character_class.c - the SmgCharacter class as Godot sees it:
 * creation with the inspector's defaults, destruction, the notifications
 * that drive the frame, and registration of the class and its methods. */
#include <stdlib.h>

#include "smg_gd_character_internal.h"

#define CLASS SMG_GD_CHARACTER_CLASS

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
	smg_gd_character_teardown(self);                       /* character, then its graph ref */
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
