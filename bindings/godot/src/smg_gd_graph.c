/* smg_gd_graph.c - SmgGraph (Resource): loads a baked libsmg graph blob from
 * a res://, user:// or absolute path through Godot's FileAccess (so it also
 * works from an exported .pck), and answers questions about it: joints,
 * styles, actions, and a matching Skeleton3D for users without a rig. */
#include "smg_gd_graph.h"

#include <stdlib.h>
#include <string.h>

#include "gd_class.h"

#define CLASS "SmgGraph"

struct smg_gd_graph {
	GDExtensionObjectPtr owner;
	char *blob_path;    /* as given by the user (UTF-8) */
	smg_gd_blob *blob;  /* NULL when nothing is loaded */
};

/* ---- shared blob ---- */

smg_gd_blob *smg_gd_blob_retain(smg_gd_blob *b) {
	if (b) b->refs++;
	return b;
}

void smg_gd_blob_release(smg_gd_blob *b) {
	if (!b || --b->refs > 0) return;
	smg_result r = smg_graph_destroy(b->graph);
	if (r != SMG_OK) {
		/* Cannot happen while every character releases its blob only after
		 * destroying itself; leak rather than free memory in use. */
		GD_ERR("SmgGraph: graph not destroyed: %s", smg_result_string(r));
		return;
	}
	free(b->alloc);
	free(b);
}

/* libsmg explains a rejected blob (which section, which index) here. */
static void log_to_godot(uint32_t level, const char *message, void *user) {
	(void)user;
	if (level == SMG_LOG_ERROR) GD_ERR("SmgGraph: %s", message);
	else if (level == SMG_LOG_WARNING) GD_WARN("SmgGraph: %s", message);
}

static char *dup_cstr(const char *s) {
	size_t n = strlen(s) + 1;
	char *d = malloc(n);
	if (d) memcpy(d, s, n);
	return d;
}

/* Read the whole file through FileAccess into 64-byte aligned memory (libsmg
 * uses the blob in place and needs 16-byte alignment). */
static int64_t load_blob(const char *path, smg_gd_blob **out) {
	gd_string gpath;
	GDExtensionBool exists = 0;
	gd_str_init(&gpath, path);
	const void *args[1] = { &gpath };
	gd_call(GDB_FileAccess_file_exists, NULL, args, &exists);
	if (!exists) {
		gd_str_destroy(&gpath);
		GD_ERR("SmgGraph: graph file '%s' not found", path);
		return GD_ERR_FILE_NOT_FOUND;
	}
	gd_packed bytes;
	gd_packed_init(&bytes, GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY);
	gd_call(GDB_FileAccess_get_file_as_bytes, NULL, args, &bytes);
	gd_str_destroy(&gpath);
	int64_t size = gd_packed_bytes_size(&bytes);
	if (size <= 0) {
		int64_t open_err = 0;
		gd_call(GDB_FileAccess_get_open_error, NULL, NULL, &open_err);
		gd_packed_destroy(&bytes, GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY);
		GD_ERR("SmgGraph: cannot read graph file '%s' (%s, Godot error %lld)", path,
			open_err ? "open failed" : "empty file", (long long)open_err);
		return open_err ? GD_ERR_FILE_CANT_READ : GD_ERR_FILE_CORRUPT;
	}
	/* aligned by hand: C11's aligned_alloc is missing from Windows' C library */
	smg_gd_blob *b = calloc(1, sizeof *b);
	void *alloc = malloc((size_t)size + 63u);
	if (!b || !alloc) {
		free(b);
		free(alloc);
		gd_packed_destroy(&bytes, GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY);
		GD_ERR("SmgGraph: out of memory reading '%s' (%lld bytes)", path, (long long)size);
		return GD_ERR_OUT_OF_MEMORY;
	}
	void *mem = (void *)(((uintptr_t)alloc + 63u) & ~(uintptr_t)63u);
	memcpy(mem, gd_packed_bytes_data(&bytes), (size_t)size);
	gd_packed_destroy(&bytes, GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY);

	smg_graph_desc desc;
	memset(&desc, 0, sizeof desc);
	desc.struct_size = sizeof desc;
	desc.logger.func = log_to_godot;
	desc.logger.user = NULL;
	smg_graph *graph = NULL;
	smg_result r = smg_graph_load_memory(mem, (size_t)size, &desc, &graph);
	if (r != SMG_OK) {
		free(alloc);
		free(b);
		GD_ERR("SmgGraph: '%s' is not a valid libsmg graph: %s", path, smg_result_string(r));
		return r == SMG_ERROR_OUT_OF_MEMORY ? GD_ERR_OUT_OF_MEMORY : GD_ERR_FILE_CORRUPT;
	}
	smg_graph_info info;
	memset(&info, 0, sizeof info);
	info.struct_size = sizeof info;
	smg_graph_get_info(graph, &info);
	b->graph = graph;
	b->alloc = alloc;
	b->refs = 1;
	b->joint_count = info.joint_count;
	*out = b;
	return GD_OK;
}

/* Loads `path`; on failure the resource is left empty (not the old graph),
 * so what the inspector shows is what is loaded. Characters notice the
 * change on their next frame and rebuild on the new graph. */
int64_t smg_gd_graph_load(smg_gd_graph *self, const char *path) {
	smg_gd_blob *nb = NULL;
	int64_t err;
	char *p = dup_cstr(path);
	if (!p) return GD_ERR_OUT_OF_MEMORY;
	free(self->blob_path);
	self->blob_path = p;
	if (!path[0]) {
		err = GD_OK; /* empty path: just unload */
	} else {
		err = load_blob(path, &nb);
	}
	smg_gd_blob_release(self->blob);
	self->blob = nb;
	gd_call(GDB_Resource_emit_changed, self->owner, NULL, NULL);
	return err;
}

smg_gd_graph *smg_gd_graph_from_object(GDExtensionObjectPtr obj) { return gd_object_self(obj, CLASS); }
smg_gd_blob *smg_gd_graph_blob(const smg_gd_graph *g) { return g ? g->blob : NULL; }

/* ---- methods ---- */

#define SELF smg_gd_graph *self = vself
#define NEED_GRAPH(ret_on_fail)                                                     \
	do {                                                                            \
		if (!self->blob) {                                                          \
			GD_ERR("SmgGraph: no graph loaded (set blob_path or call load())");    \
			ret_on_fail;                                                            \
			return;                                                                 \
		}                                                                           \
	} while (0)

static void m_load(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	char path[4096];
	if (gd_str_to_c(&a[0].s, path, sizeof path) >= sizeof path) {
		GD_ERR("SmgGraph.load: path too long");
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	if (!path[0]) {
		GD_ERR("SmgGraph.load: empty path");
		r->i = GD_ERR_INVALID_PARAMETER;
		return;
	}
	r->i = smg_gd_graph_load(self, path);
}

static void m_set_blob_path(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	char path[4096];
	if (gd_str_to_c(&a[0].s, path, sizeof path) >= sizeof path) {
		GD_ERR("SmgGraph.blob_path: path too long");
		return;
	}
	if (self->blob_path && !strcmp(self->blob_path, path) && (self->blob || !path[0])) return;
	smg_gd_graph_load(self, path);
}

static void m_get_blob_path(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	gd_str_init(&r->s, self->blob_path ? self->blob_path : "");
}

static void m_is_loaded(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->b = self->blob != NULL;
}

static void m_get_joint_count(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = self->blob ? self->blob->joint_count : 0;
}

static bool joint(smg_gd_graph *self, int64_t i, smg_joint_info *ji) {
	memset(ji, 0, sizeof *ji);
	ji->struct_size = sizeof *ji;
	if (!self->blob) {
		GD_ERR("SmgGraph: no graph loaded");
		return false;
	}
	if (i < 0 || i >= self->blob->joint_count || smg_graph_get_joint(self->blob->graph, (uint32_t)i, ji) != SMG_OK) {
		GD_ERR("SmgGraph: joint index %lld out of range (0..%u)", (long long)i, self->blob->joint_count);
		return false;
	}
	return true;
}

static void m_get_joint_name(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	smg_joint_info ji;
	gd_str_init(&r->s, joint(self, a[0].i, &ji) && ji.name ? ji.name : "");
}

static void m_get_joint_parent(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	smg_joint_info ji;
	r->i = joint(self, a[0].i, &ji) ? ji.parent : -1;
}

static void m_get_joint_rest_offset(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	smg_joint_info ji;
	if (joint(self, a[0].i, &ji)) r->v3 = (gd_vec3){ ji.rest_offset[0], ji.rest_offset[1], ji.rest_offset[2] };
}

static smg_graph_info graph_info(const smg_gd_graph *self) {
	smg_graph_info info;
	memset(&info, 0, sizeof info);
	info.struct_size = sizeof info;
	if (self->blob) smg_graph_get_info(self->blob->graph, &info);
	return info;
}

static void m_get_style_count(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = graph_info(self).style_count;
}
static void m_get_action_count(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = graph_info(self).action_count;
}
static void m_get_frame_rate(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = graph_info(self).frame_rate;
}

/* get_style_name / get_action_name: index -> name, "" with an error for
 * an index the graph does not have or when no graph is loaded. */
static void label_name(smg_gd_graph *self, const gd_value *a, gd_value *r, const char *kind,
	smg_result (*get)(const smg_graph *, uint32_t, const char **)) {
	const char *name = NULL;
	if (!self->blob) {
		GD_ERR("SmgGraph: no graph loaded");
	} else if (a[0].i < 0 || a[0].i > UINT32_MAX || get(self->blob->graph, (uint32_t)a[0].i, &name) != SMG_OK) {
		GD_ERR("SmgGraph: no %s %lld", kind, (long long)a[0].i);
		name = NULL;
	}
	gd_str_init(&r->s, name ? name : "");
}

static void m_get_style_name(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	label_name(self, a, r, "style", smg_graph_get_style_name);
}

static void m_get_action_name(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	label_name(self, a, r, "action", smg_graph_get_action_name);
}

static void m_find_style(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	char name[256];
	uint32_t idx;
	r->i = -1;
	NEED_GRAPH((void)0);
	gd_str_to_c(&a[0].s, name, sizeof name);
	if (smg_graph_find_style(self->blob->graph, name, &idx) == SMG_OK) r->i = idx;
}

static void m_find_action(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	char name[256];
	uint32_t idx;
	r->i = -1;
	NEED_GRAPH((void)0);
	gd_str_to_c(&a[0].s, name, sizeof name);
	if (smg_graph_find_action(self->blob->graph, name, &idx) == SMG_OK) r->i = idx;
}

static void names(smg_gd_graph *self, gd_value *r, bool styles) {
	gd_packed_init(&r->pa, GDEXTENSION_VARIANT_TYPE_PACKED_STRING_ARRAY);
	if (!self->blob) return;
	smg_graph_info info = graph_info(self);
	uint32_t n = styles ? info.style_count : info.action_count;
	for (uint32_t i = 0; i < n; i++) {
		const char *name = NULL;
		smg_result res = styles ? smg_graph_get_style_name(self->blob->graph, i, &name)
		                        : smg_graph_get_action_name(self->blob->graph, i, &name);
		gd_packed_strings_push(&r->pa, res == SMG_OK && name ? name : "");
	}
}
static void m_get_style_names(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	names(vself, r, true);
}
static void m_get_action_names(void *vself, const gd_value *a, gd_value *r) {
	(void)a;
	names(vself, r, false);
}

/* A Skeleton3D with one bone per graph joint (same names, parents and rest
 * offsets, identity rest rotations): exactly what SmgCharacter drives. */
static void m_build_skeleton(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->o = NULL;
	NEED_GRAPH((void)0);
	r->o = smg_gd_graph_build_skeleton(self);
}

GDExtensionObjectPtr smg_gd_graph_build_skeleton(smg_gd_graph *self) {
	if (!self || !self->blob) {
		GD_ERR("SmgGraph.build_skeleton: no graph loaded");
		return NULL;
	}
	GDExtensionObjectPtr skel = gd_engine_new("Skeleton3D");
	if (!skel) {
		GD_ERR("SmgGraph.build_skeleton: cannot create a Skeleton3D");
		return NULL;
	}
	uint32_t n = self->blob->joint_count;
	for (uint32_t j = 0; j < n; j++) {
		smg_joint_info ji;
		memset(&ji, 0, sizeof ji);
		ji.struct_size = sizeof ji;
		if (smg_graph_get_joint(self->blob->graph, j, &ji) != SMG_OK) break;
		char bone_name[256];
		smg_gd_bone_name(ji.name, bone_name, sizeof bone_name);
		gd_string name;
		gd_str_init(&name, bone_name);
		const void *aa[1] = { &name };
		int64_t bone = -1;
		gd_call(GDB_Skeleton3D_add_bone, skel, aa, &bone);
		gd_str_destroy(&name);
		if (bone < 0) {
			GD_ERR("SmgGraph.build_skeleton: could not add bone for joint %u", j);
			continue;
		}
		gd_transform3d rest = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
			{ ji.rest_offset[0], ji.rest_offset[1], ji.rest_offset[2] } };
		const void *ra[2] = { &bone, &rest };
		gd_call(GDB_Skeleton3D_set_bone_rest, skel, ra, NULL);
		gd_vec3 pos = { ji.rest_offset[0], ji.rest_offset[1], ji.rest_offset[2] };
		const void *pa[2] = { &bone, &pos };
		gd_call(GDB_Skeleton3D_set_bone_pose_position, skel, pa, NULL);
		if (ji.parent >= 0 && (uint32_t)ji.parent < j) {
			int64_t parent = ji.parent;
			const void *pp[2] = { &bone, &parent };
			gd_call(GDB_Skeleton3D_set_bone_parent, skel, pp, NULL);
		}
	}
	return skel;
}

static const gd_method methods[] = {
	{ "load", m_load, GT_INT, NULL, 1, { { "path", GT_STRING, NULL } }, 0 },
	{ "set_blob_path", m_set_blob_path, GT_NIL, NULL, 1, { { "path", GT_STRING, NULL } }, 0 },
	{ "get_blob_path", m_get_blob_path, GT_STRING, NULL, 0, { { 0 } }, 1 },
	{ "is_loaded", m_is_loaded, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "get_joint_count", m_get_joint_count, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "get_joint_name", m_get_joint_name, GT_STRING, NULL, 1, { { "joint", GT_INT, NULL } }, 1 },
	{ "get_joint_parent", m_get_joint_parent, GT_INT, NULL, 1, { { "joint", GT_INT, NULL } }, 1 },
	{ "get_joint_rest_offset", m_get_joint_rest_offset, GT_VEC3, NULL, 1, { { "joint", GT_INT, NULL } }, 1 },
	{ "get_style_count", m_get_style_count, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "get_action_count", m_get_action_count, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "get_frame_rate", m_get_frame_rate, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "get_style_name", m_get_style_name, GT_STRING, NULL, 1, { { "style", GT_INT, NULL } }, 1 },
	{ "get_action_name", m_get_action_name, GT_STRING, NULL, 1, { { "action", GT_INT, NULL } }, 1 },
	{ "find_style", m_find_style, GT_INT, NULL, 1, { { "name", GT_STRING, NULL } }, 1 },
	{ "find_action", m_find_action, GT_INT, NULL, 1, { { "name", GT_STRING, NULL } }, 1 },
	{ "get_style_names", m_get_style_names, GT_PSA, NULL, 0, { { 0 } }, 1 },
	{ "get_action_names", m_get_action_names, GT_PSA, NULL, 0, { { 0 } }, 1 },
	{ "build_skeleton", m_build_skeleton, GT_OBJECT, "Skeleton3D", 0, { { 0 } }, 1 },
};

/* ---- class ---- */

static GDExtensionObjectPtr create(void *ud, GDExtensionBool notify) {
	(void)ud;
	smg_gd_graph *self = calloc(1, sizeof *self);
	if (!self) return NULL;
	self->owner = gd_object_create("Resource", CLASS, self, notify);
	if (!self->owner) {
		free(self);
		return NULL;
	}
	return self->owner;
}

static void destroy(void *ud, GDExtensionClassInstancePtr inst) {
	(void)ud;
	smg_gd_graph *self = inst;
	smg_gd_blob_release(self->blob); /* characters keep theirs alive */
	free(self->blob_path);
	free(self);
}

void smg_gd_graph_register(void) {
	gd_register_class(CLASS, "Resource", create, destroy, NULL, NULL);
	gd_register_methods(CLASS, methods, (int)(sizeof methods / sizeof methods[0]));
	gd_arg prop = { "blob_path", GT_STRING, NULL };
	gd_register_property(CLASS, &prop, GD_PROPERTY_HINT_FILE, "*.smg", "set_blob_path", "get_blob_path");
}

void smg_gd_graph_unregister(void) {
	gd_string_name cname;
	gd_sn_init(&cname, CLASS);
	gd.classdb_unregister_extension_class(gd.lib, &cname);
	gd_sn_destroy(&cname);
}
