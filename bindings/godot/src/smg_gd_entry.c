/* smg_gd_entry.c - the GDExtension entry point of the extension library: loads the
 * interface and registers SmgGraph, SmgCharacter, SmgSkeletonModifier and the .smg
 * resource loader (SmgGraphLoader) at the SCENE level, and in the editor
 * their class reference at the EDITOR level. */
#include <stdio.h>

#include "gd_api.h"
#include "smg_gd_character.h"
#include "smg_gd_docs.h"
#include "smg_gd_graph.h"
#include "smg_gd_loader.h"
#include "smg_gd_modifier.h"

static bool registered;

static void initialize(void *ud, GDExtensionInitializationLevel level) {
	(void)ud;
	if (level == GDEXTENSION_INITIALIZATION_EDITOR && registered) smg_gd_docs_load();
	if (level != GDEXTENSION_INITIALIZATION_SCENE) return;
	if (!gd_api_init_scene()) {
		GD_ERR("libsmg_godot: this Godot's API does not match the one the extension was built for "
		       "(" SMG_GD_GODOT_VERSION "); SmgGraph and SmgCharacter are not available");
		return;
	}
	smg_gd_graph_register();
	smg_gd_character_register();
	smg_gd_modifier_register();
	smg_gd_loader_register();
	registered = true;
}

static void deinitialize(void *ud, GDExtensionInitializationLevel level) {
	(void)ud;
	if (level != GDEXTENSION_INITIALIZATION_SCENE || !registered) return;
	smg_gd_loader_unregister(); /* users of other classes first */
	smg_gd_modifier_unregister();
	smg_gd_character_unregister();
	smg_gd_graph_unregister();
	gd_api_deinit_scene();
	registered = false;
}

/* The one exported symbol (Windows: the DLL exports only what is marked
 * dllexport, so libsmg linked in stays private there too). */
#ifdef _WIN32
#define SMG_GD_EXPORT __declspec(dllexport)
#else
#define SMG_GD_EXPORT __attribute__((visibility("default")))
#endif

SMG_GD_EXPORT GDExtensionBool smg_godot_init(GDExtensionInterfaceGetProcAddress get_proc,
	GDExtensionClassLibraryPtr lib, GDExtensionInitialization *init) {
	if (!gd_api_load(get_proc, lib)) {
		fprintf(stderr, "libsmg_godot: Godot's GDExtension interface lacks functions this extension needs\n");
		return 0;
	}
	init->minimum_initialization_level = GDEXTENSION_INITIALIZATION_SCENE;
	init->userdata = NULL;
	init->initialize = initialize;
	init->deinitialize = deinitialize;
	return 1;
}
