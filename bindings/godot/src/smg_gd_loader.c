/* smg_gd_loader.c - SmgGraphLoader (ResourceFormatLoader): makes .smg files
 * ordinary Godot resources, so load("res://walker.smg") returns a loaded
 * SmgGraph, the editor's FileSystem dock lists .smg files as SmgGraph, a
 * .smg can be dropped on SmgCharacter.graph, and scenes refer to it as an
 * ext_resource. Registered with ResourceLoader for the extension's life. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "gd_class.h"
#include "smg_gd_graph.h"
#include "smg_gd_loader.h"

#define CLASS "SmgGraphLoader"

static gd_string_name sn_get_exts, sn_handles, sn_get_type, sn_load;
static gd_string_name sn_SmgGraph, sn_Resource;
static gd_variant loader_ref; /* keeps our registered loader alive */
static bool loader_registered;

static bool same_name(GDExtensionConstStringNamePtr a, const gd_string_name *b) {
	return *(void *const *)a == b->p; /* StringNames are interned */
}

static bool is_smg_path(const gd_string *path) {
	char buf[4096];
	size_t n = gd_str_to_c(path, buf, sizeof buf);
	return n < sizeof buf && n >= 4 && strcasecmp(buf + n - 4, ".smg") == 0;
}

/* _get_recognized_extensions() -> PackedStringArray (ret is constructed) */
static void v_get_exts(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args, GDExtensionTypePtr ret) {
	(void)inst;
	(void)args;
	gd_packed_strings_push((gd_packed *)ret, "smg");
}

/* _handles_type(type: StringName) -> bool */
static void v_handles(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args, GDExtensionTypePtr ret) {
	(void)inst;
	*(uint8_t *)ret = same_name(args[0], &sn_SmgGraph) || same_name(args[0], &sn_Resource);
}

/* _get_resource_type(path: String) -> String (ret is constructed) */
static void v_get_type(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args, GDExtensionTypePtr ret) {
	(void)inst;
	gd_str_destroy((gd_string *)ret);
	gd_str_init((gd_string *)ret, is_smg_path((const gd_string *)args[0]) ? "SmgGraph" : "");
}

/* _load(path, original_path, use_sub_threads, cache_mode) -> Variant:
 * the SmgGraph, or an int Error (Godot's convention for failed loads). */
static void v_load(GDExtensionClassInstancePtr inst, const GDExtensionConstTypePtr *args, GDExtensionTypePtr ret) {
	(void)inst;
	char path[4096];
	int64_t err = GD_ERR_FILE_CANT_READ;
	if (gd_str_to_c((const gd_string *)args[0], path, sizeof path) < sizeof path) {
		GDExtensionObjectPtr obj = gd_engine_new("SmgGraph");
		smg_gd_graph *g = smg_gd_graph_from_object(obj);
		if (g) {
			gd_variant_from_object((gd_variant *)ret, obj); /* ret (Nil) now owns it */
			err = smg_gd_graph_load(g, path);
			if (err == GD_OK) return;
			gd_variant_destroy((gd_variant *)ret);      /* frees the graph */
		} else if (obj) {
			gd.object_destroy(obj);
		}
	}
	gd_variant_from_int((gd_variant *)ret, err);
}

static GDExtensionClassCallVirtual get_virtual(void *ud, GDExtensionConstStringNamePtr name, uint32_t hash) {
	(void)ud;
	(void)hash;
	if (same_name(name, &sn_get_exts)) return v_get_exts;
	if (same_name(name, &sn_handles)) return v_handles;
	if (same_name(name, &sn_get_type)) return v_get_type;
	if (same_name(name, &sn_load)) return v_load;
	return NULL;
}

/* The loader keeps no state: the instance is a token. */
static char instance_token;

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	return gd_object_create("ResourceFormatLoader", CLASS, &instance_token, notify);
}

static void destroy(void *ud, GDExtensionClassInstancePtr inst) {
	(void)ud;
	(void)inst;
}

void smg_gd_loader_register(void) {
	gd_sn_init(&sn_get_exts, "_get_recognized_extensions");
	gd_sn_init(&sn_handles, "_handles_type");
	gd_sn_init(&sn_get_type, "_get_resource_type");
	gd_sn_init(&sn_load, "_load");
	gd_sn_init(&sn_SmgGraph, "SmgGraph");
	gd_sn_init(&sn_Resource, "Resource");
	gd_variant_nil(&loader_ref);

	gd_register_class(CLASS, "ResourceFormatLoader", create, destroy, NULL, get_virtual);

	GDExtensionObjectPtr loader = gd_engine_new(CLASS);
	GDExtensionObjectPtr rl = gd_singleton("ResourceLoader");
	if (!loader || !rl) {
		GD_ERR("libsmg_godot: could not register the .smg resource loader");
		return;
	}
	gd_variant_from_object(&loader_ref, loader);
	GDExtensionBool at_front = 0;
	const void *a[2] = { &loader, &at_front };
	gd_call(GDB_ResourceLoader_add_resource_format_loader, rl, a, NULL);
	loader_registered = true;
}

void smg_gd_loader_unregister(void) {
	GDExtensionObjectPtr loader = gd_variant_object(&loader_ref);
	GDExtensionObjectPtr rl = gd_singleton("ResourceLoader");
	if (loader_registered && loader && rl) {
		const void *a[1] = { &loader };
		gd_call(GDB_ResourceLoader_remove_resource_format_loader, rl, a, NULL);
	}
	loader_registered = false;
	gd_variant_destroy(&loader_ref);
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&sn_get_exts);
	gd_sn_destroy(&sn_handles);
	gd_sn_destroy(&sn_get_type);
	gd_sn_destroy(&sn_load);
	gd_sn_destroy(&sn_SmgGraph);
	gd_sn_destroy(&sn_Resource);
}
