/* gd_api.c - loading Godot's GDExtension interface and thin helpers over it. */
#include "gd_api.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

gd_interface gd;
GDExtensionMethodBindPtr gd_binds[GDB_COUNT_];
GDExtensionPtrBuiltInMethod gd_builtins[GDBB_COUNT_];
GDExtensionPtrUtilityFunction gd_utilities[GDU_COUNT_];

static GDExtensionPtrDestructor dtor_string, dtor_string_name, dtor_node_path;
static GDExtensionVariantFromTypeConstructorFunc from_int, from_string, from_sn, from_object, from_bool, from_float,
	from_vec3;
static GDExtensionTypeFromVariantConstructorFunc to_object, to_vec3;
static GDExtensionObjectPtr engine_singleton;

bool gd_api_load(GDExtensionInterfaceGetProcAddress get_proc, GDExtensionClassLibraryPtr lib) {
	memset(&gd, 0, sizeof gd);
	gd.lib = lib;
	bool ok = true;
	/* Each name is the interface function's registered name; a missing one
	 * means a Godot older than this binding supports. */
#define LOAD(field)                                                                  \
	do {                                                                             \
		gd.field = (__typeof__(gd.field))(void (*)(void))get_proc(#field);          \
		if (!gd.field) {                                                             \
			fprintf(stderr, "libsmg_godot: Godot lacks interface function " #field "\n"); \
			ok = false;                                                              \
		}                                                                            \
	} while (0)
	LOAD(get_godot_version2);
	LOAD(mem_alloc);
	LOAD(mem_free);
	LOAD(print_error);
	LOAD(print_warning);
	LOAD(string_name_new_with_utf8_chars);
	LOAD(string_new_with_utf8_chars);
	LOAD(string_to_utf8_chars);
	LOAD(variant_new_copy);
	LOAD(variant_new_nil);
	LOAD(variant_destroy);
	LOAD(variant_get_type);
	LOAD(variant_get);
	LOAD(variant_can_convert_strict);
	LOAD(get_variant_from_type_constructor);
	LOAD(get_variant_to_type_constructor);
	LOAD(variant_get_ptr_constructor);
	LOAD(variant_get_ptr_destructor);
	LOAD(variant_get_ptr_builtin_method);
	LOAD(variant_get_ptr_utility_function);
	LOAD(packed_byte_array_operator_index_const);
	LOAD(packed_vector3_array_operator_index_const);
	LOAD(object_method_bind_call);
	LOAD(object_method_bind_ptrcall);
	LOAD(object_destroy);
	LOAD(global_get_singleton);
	LOAD(object_get_instance_binding);
	LOAD(object_set_instance_binding);
	LOAD(object_set_instance);
	LOAD(object_cast_to);
	LOAD(object_get_instance_from_id);
	LOAD(object_get_instance_id);
	LOAD(ref_set_object);
	LOAD(classdb_construct_object2);
	LOAD(classdb_get_method_bind);
	LOAD(classdb_get_class_tag);
	LOAD(classdb_register_extension_class5);
	LOAD(classdb_register_extension_class_method);
	LOAD(classdb_register_extension_class_property);
	LOAD(classdb_register_extension_class_property_group);
	LOAD(classdb_register_extension_class_signal);
	LOAD(classdb_unregister_extension_class);
#undef LOAD
	gd.editor_help_load_xml_from_utf8_chars_and_len = (GDExtensionsInterfaceEditorHelpLoadXmlFromUtf8CharsAndLen)(
		void (*)(void))get_proc("editor_help_load_xml_from_utf8_chars_and_len");
	return ok;
}

bool gd_api_init_scene(void) {
	bool ok = true;
	dtor_string = gd.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_STRING);
	dtor_string_name = gd.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_STRING_NAME);
	dtor_node_path = gd.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_NODE_PATH);
	from_int = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_INT);
	from_string = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_STRING);
	from_sn = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_STRING_NAME);
	from_object = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_OBJECT);
	to_object = gd.get_variant_to_type_constructor(GDEXTENSION_VARIANT_TYPE_OBJECT);
	from_bool = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_BOOL);
	from_float = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_FLOAT);
	from_vec3 = gd.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_VECTOR3);
	to_vec3 = gd.get_variant_to_type_constructor(GDEXTENSION_VARIANT_TYPE_VECTOR3);

	for (int i = 0; i < GDB_COUNT_; i++) {
		const smg_gd_bind_spec *s = &smg_gd_bind_specs[i];
		gd_string_name c, m;
		gd_sn_init(&c, s->cls);
		gd_sn_init(&m, s->name);
		gd_binds[i] = gd.classdb_get_method_bind(&c, &m, s->hash);
		gd_sn_destroy(&c);
		gd_sn_destroy(&m);
		if (!gd_binds[i]) {
			GD_ERR("libsmg_godot: engine method %s.%s (hash %lld) not found", s->cls, s->name,
				(long long)s->hash);
			ok = false;
		}
	}
	for (int i = 0; i < GDBB_COUNT_; i++) {
		const smg_gd_bind_spec *s = &smg_gd_builtin_specs[i];
		GDExtensionVariantType t = GDEXTENSION_VARIANT_TYPE_NIL;
		if (!strcmp(s->cls, "PackedVector3Array")) t = GDEXTENSION_VARIANT_TYPE_PACKED_VECTOR3_ARRAY;
		else if (!strcmp(s->cls, "PackedByteArray")) t = GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY;
		else if (!strcmp(s->cls, "PackedStringArray")) t = GDEXTENSION_VARIANT_TYPE_PACKED_STRING_ARRAY;
		else if (!strcmp(s->cls, "NodePath")) t = GDEXTENSION_VARIANT_TYPE_NODE_PATH;
		gd_string_name m;
		gd_sn_init(&m, s->name);
		gd_builtins[i] = t == GDEXTENSION_VARIANT_TYPE_NIL ? NULL
			: gd.variant_get_ptr_builtin_method(t, &m, s->hash);
		gd_sn_destroy(&m);
		if (!gd_builtins[i]) {
			GD_ERR("libsmg_godot: builtin method %s.%s not found", s->cls, s->name);
			ok = false;
		}
	}
	for (int i = 0; i < GDU_COUNT_; i++) {
		gd_string_name n;
		gd_sn_init(&n, smg_gd_utility_specs[i].name);
		gd_utilities[i] = gd.variant_get_ptr_utility_function(&n, smg_gd_utility_specs[i].hash);
		gd_sn_destroy(&n);
		if (!gd_utilities[i]) {
			GD_ERR("libsmg_godot: utility function %s not found", smg_gd_utility_specs[i].name);
			ok = false;
		}
	}
	engine_singleton = gd_singleton("Engine");
	return ok;
}

void gd_api_deinit_scene(void) {
	engine_singleton = NULL;
}

/* ---- strings ---- */
void gd_sn_init(gd_string_name *sn, const char *utf8) { gd.string_name_new_with_utf8_chars(sn, utf8); }
void gd_sn_destroy(gd_string_name *sn) { dtor_string_name(sn); }
void gd_str_init(gd_string *s, const char *utf8) { gd.string_new_with_utf8_chars(s, utf8); }
void gd_str_destroy(gd_string *s) { dtor_string(s); }

size_t gd_str_to_c(const gd_string *s, char *buf, size_t cap) {
	GDExtensionInt n = gd.string_to_utf8_chars(s, NULL, 0);
	if (n < 0) n = 0;
	if (cap > 0) {
		size_t w = (size_t)n < cap - 1 ? (size_t)n : cap - 1;
		if (w > 0) gd.string_to_utf8_chars(s, buf, (GDExtensionInt)w);
		buf[w] = '\0';
	}
	return (size_t)n;
}

void gd_node_path_init(gd_node_path *np, const char *utf8) {
	gd_string s;
	gd_str_init(&s, utf8);
	const void *args[1] = { &s };
	/* NodePath constructor 2 is NodePath(String from). */
	gd.variant_get_ptr_constructor(GDEXTENSION_VARIANT_TYPE_NODE_PATH, 2)(np, args);
	gd_str_destroy(&s);
}
void gd_node_path_copy(gd_node_path *dst, const gd_node_path *src) {
	const void *args[1] = { src };
	gd.variant_get_ptr_constructor(GDEXTENSION_VARIANT_TYPE_NODE_PATH, 1)(dst, args);
}
void gd_node_path_destroy(gd_node_path *np) { dtor_node_path(np); }
bool gd_node_path_is_empty(const gd_node_path *np) {
	GDExtensionBool r = 1;
	gd_builtins[GDBB_NodePath_is_empty]((GDExtensionTypePtr)np, NULL, &r, 0);
	return r != 0;
}

/* ---- packed arrays ---- */
void gd_packed_init(gd_packed *a, GDExtensionVariantType type) {
	gd.variant_get_ptr_constructor(type, 0)(a, NULL);
}
void gd_packed_destroy(gd_packed *a, GDExtensionVariantType type) {
	gd.variant_get_ptr_destructor(type)(a);
}
int64_t gd_packed_v3_size(const gd_packed *a) {
	int64_t n = 0;
	gd_builtins[GDBB_PackedVector3Array_size]((GDExtensionTypePtr)a, NULL, &n, 0);
	return n;
}
const gd_vec3 *gd_packed_v3_at(const gd_packed *a, int64_t i) {
	return (const gd_vec3 *)gd.packed_vector3_array_operator_index_const(a, i);
}
int64_t gd_packed_bytes_size(const gd_packed *a) {
	int64_t n = 0;
	gd_builtins[GDBB_PackedByteArray_size]((GDExtensionTypePtr)a, NULL, &n, 0);
	return n;
}
const uint8_t *gd_packed_bytes_data(const gd_packed *a) {
	return gd_packed_bytes_size(a) > 0 ? gd.packed_byte_array_operator_index_const(a, 0) : NULL;
}
void gd_packed_strings_push(gd_packed *a, const char *utf8) {
	gd_string s;
	GDExtensionBool r;
	gd_str_init(&s, utf8);
	const void *args[1] = { &s };
	gd_builtins[GDBB_PackedStringArray_push_back](a, args, &r, 1);
	gd_str_destroy(&s);
}

/* ---- variants ---- */
void gd_variant_nil(gd_variant *v) { gd.variant_new_nil(v); }
void gd_variant_destroy(gd_variant *v) { gd.variant_destroy(v); }
void gd_variant_from_int(gd_variant *v, int64_t i) { from_int(v, &i); }
void gd_variant_from_bool(gd_variant *v, bool b) {
	GDExtensionBool x = b;
	from_bool(v, &x);
}
void gd_variant_from_float(gd_variant *v, double f) { from_float(v, &f); }
void gd_variant_from_vec3(gd_variant *v, gd_vec3 x) { from_vec3(v, &x); }
bool gd_variant_to_vec3(const gd_variant *v, gd_vec3 *out) {
	if (gd.variant_get_type(v) != GDEXTENSION_VARIANT_TYPE_VECTOR3) return false;
	to_vec3(out, (GDExtensionVariantPtr)v);
	return true;
}
bool gd_variant_get_key(const gd_variant *v, const char *key, gd_variant *out) {
	gd_variant k;
	GDExtensionBool valid = 0;
	gd_variant_from_cstr(&k, key);
	gd.variant_get(v, &k, out, &valid);
	gd_variant_destroy(&k);
	if (!valid) {
		gd_variant_destroy(out);
		gd_variant_nil(out);
	}
	return valid != 0;
}
void gd_variant_from_cstr(gd_variant *v, const char *utf8) {
	gd_string s;
	gd_str_init(&s, utf8);
	from_string(v, &s);
	gd_str_destroy(&s);
}
void gd_variant_from_sn(gd_variant *v, const gd_string_name *sn) { from_sn(v, (GDExtensionTypePtr)sn); }
void gd_variant_from_object(gd_variant *v, GDExtensionObjectPtr o) {
	if (!o) {
		gd.variant_new_nil(v);
		return;
	}
	from_object(v, &o);
}
GDExtensionObjectPtr gd_variant_object(const gd_variant *v) {
	if (gd.variant_get_type(v) != GDEXTENSION_VARIANT_TYPE_OBJECT) return NULL;
	GDExtensionObjectPtr o = NULL;
	to_object(&o, (GDExtensionVariantPtr)v);
	return o;
}

/* ---- objects ---- */
GDExtensionObjectPtr gd_cast(GDExtensionConstObjectPtr obj, const char *class_name) {
	if (!obj) return NULL;
	gd_string_name n;
	gd_sn_init(&n, class_name);
	void *tag = gd.classdb_get_class_tag(&n);
	gd_sn_destroy(&n);
	if (!tag || !gd.object_cast_to(obj, tag)) return NULL;
	/* An extension class's tag is its engine parent's (Godot gives
	 * extension classes no tag of their own), so the cast alone takes any
	 * Node3D for an SmgCharacter: ask the object itself, which knows its
	 * extension class and script subclasses. */
	gd_string s;
	gd_str_init(&s, class_name);
	GDExtensionBool is = 0;
	const void *a[1] = { &s };
	gd_call(GDB_Object_is_class, (GDExtensionObjectPtr)obj, a, &is);
	gd_str_destroy(&s);
	return is ? (GDExtensionObjectPtr)obj : NULL;
}

void gd_call(int bind, GDExtensionObjectPtr obj, const void *const *args, void *ret) {
	gd.object_method_bind_ptrcall(gd_binds[bind], obj, (const GDExtensionConstTypePtr *)args, ret);
}

bool gd_call_variant(int bind, GDExtensionObjectPtr obj, const gd_variant *const *args, int argc, gd_variant *ret) {
	GDExtensionCallError err;
	memset(&err, 0, sizeof err);
	gd.object_method_bind_call(gd_binds[bind], obj, (const GDExtensionConstVariantPtr *)args, argc, ret, &err);
	return err.error == GDEXTENSION_CALL_OK;
}

void gd_emit(GDExtensionObjectPtr obj, const char *signal, const gd_variant *args, int argc) {
	gd_string_name sn;
	gd_variant vs, ret;
	const GDExtensionConstVariantPtr *pp;
	GDExtensionConstVariantPtr ptrs[8];
	GDExtensionCallError err;
	if (argc > 7) argc = 7;
	gd_sn_init(&sn, signal);
	gd_variant_from_sn(&vs, &sn);
	ptrs[0] = &vs;
	for (int i = 0; i < argc; i++) ptrs[i + 1] = &args[i];
	pp = ptrs;
	gd.object_method_bind_call(gd_binds[GDB_Object_emit_signal], obj, pp, argc + 1, &ret, &err);
	gd_variant_destroy(&ret);
	gd_variant_destroy(&vs);
	gd_sn_destroy(&sn);
}

GDExtensionObjectPtr gd_singleton(const char *name) {
	gd_string_name n;
	gd_sn_init(&n, name);
	GDExtensionObjectPtr o = gd.global_get_singleton(&n);
	gd_sn_destroy(&n);
	return o;
}

bool gd_is_editor(void) {
	GDExtensionBool r = 0;
	if (engine_singleton) gd_call(GDB_Engine_is_editor_hint, engine_singleton, NULL, &r);
	return r != 0;
}

/* ---- messages ---- */
void gd_error_at(const char *func, const char *file, int line, const char *fmt, ...) {
	char buf[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	gd.print_error(buf, func, file, line, 1);
}

void gd_warning_at(const char *func, const char *file, int line, const char *fmt, ...) {
	char buf[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	gd.print_warning(buf, func, file, line, 1);
}

void gd_print(const char *fmt, ...) {
	char buf[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	gd_variant v, ret;
	gd_variant_from_cstr(&v, buf);
	GDExtensionConstTypePtr args[1] = { &v };
	gd_utilities[GDU_print](&ret, args, 1);
	gd_variant_destroy(&v);
}
