/* gd_api.h - the small slice of Godot's GDExtension C interface that the
 * libsmg binding uses, loaded once at start-up, plus helpers for strings,
 * variants, engine method calls and error messages.
 *
 * Everything is resolved by name from the interface and by hash from the
 * extension_api.json of the Godot we build against (smg_gd_api_gen.h,
 * generated at build time), so a Godot whose API differs fails loudly at
 * load instead of crashing later. */
#ifndef SMG_GD_API_H
#define SMG_GD_API_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "gdextension_interface.h"
#include "smg_gd_api_gen.h"

/* Opaque builtin values, sized as the dumped API says. Godot's String,
 * StringName and NodePath are one pointer; packed arrays two; a Variant is
 * 24 bytes on a single-precision 64-bit build. */
typedef struct { void *p; } gd_string;
typedef struct { void *p; } gd_string_name;
typedef struct { void *p; } gd_node_path;
typedef struct { void *p[2]; } gd_packed;
typedef struct { _Alignas(8) unsigned char b[GDSIZE_Variant]; } gd_variant;
typedef struct { float x, y, z; } gd_vec3;
typedef struct { float x, y, z, w; } gd_quat;
/* Basis rows (row-major 3x3), then origin. */
typedef struct { float basis[3][3]; float origin[3]; } gd_transform3d;

_Static_assert(sizeof(gd_string) == GDSIZE_String, "String size");
_Static_assert(sizeof(gd_string_name) == GDSIZE_StringName, "StringName size");
_Static_assert(sizeof(gd_node_path) == GDSIZE_NodePath, "NodePath size");
_Static_assert(sizeof(gd_packed) == GDSIZE_PackedVector3Array, "packed size");
_Static_assert(sizeof(gd_packed) == GDSIZE_PackedByteArray, "packed size");
_Static_assert(sizeof(gd_packed) == GDSIZE_PackedStringArray, "packed size");
_Static_assert(sizeof(gd_vec3) == GDSIZE_Vector3, "Vector3 size");
_Static_assert(sizeof(gd_quat) == GDSIZE_Quaternion, "Quaternion size");
_Static_assert(sizeof(gd_transform3d) == GDSIZE_Transform3D, "Transform3D size");
_Static_assert(SMG_GD_PRECISION_SINGLE, "the binding expects a single-precision Godot");

/* Interface functions we use, loaded by gd_api_load(). */
typedef struct gd_interface {
	GDExtensionClassLibraryPtr lib;
	GDExtensionInterfaceGetGodotVersion2 get_godot_version2;
	GDExtensionInterfaceMemAlloc mem_alloc;
	GDExtensionInterfaceMemFree mem_free;
	GDExtensionInterfacePrintError print_error;
	GDExtensionInterfacePrintWarning print_warning;
	GDExtensionInterfaceStringNameNewWithUtf8Chars string_name_new_with_utf8_chars;
	GDExtensionInterfaceStringNewWithUtf8Chars string_new_with_utf8_chars;
	GDExtensionInterfaceStringToUtf8Chars string_to_utf8_chars;
	GDExtensionInterfaceVariantNewCopy variant_new_copy;
	GDExtensionInterfaceVariantNewNil variant_new_nil;
	GDExtensionInterfaceVariantDestroy variant_destroy;
	GDExtensionInterfaceVariantGetType variant_get_type;
	GDExtensionInterfaceVariantGet variant_get;
	GDExtensionInterfaceVariantCanConvertStrict variant_can_convert_strict;
	GDExtensionInterfaceGetVariantFromTypeConstructor get_variant_from_type_constructor;
	GDExtensionInterfaceGetVariantToTypeConstructor get_variant_to_type_constructor;
	GDExtensionInterfaceVariantGetPtrConstructor variant_get_ptr_constructor;
	GDExtensionInterfaceVariantGetPtrDestructor variant_get_ptr_destructor;
	GDExtensionInterfaceVariantGetPtrBuiltinMethod variant_get_ptr_builtin_method;
	GDExtensionInterfaceVariantGetPtrUtilityFunction variant_get_ptr_utility_function;
	GDExtensionInterfacePackedByteArrayOperatorIndexConst packed_byte_array_operator_index_const;
	GDExtensionInterfacePackedVector3ArrayOperatorIndexConst packed_vector3_array_operator_index_const;
	GDExtensionInterfaceObjectMethodBindCall object_method_bind_call;
	GDExtensionInterfaceObjectMethodBindPtrcall object_method_bind_ptrcall;
	GDExtensionInterfaceObjectDestroy object_destroy;
	GDExtensionInterfaceGlobalGetSingleton global_get_singleton;
	GDExtensionInterfaceObjectGetInstanceBinding object_get_instance_binding;
	GDExtensionInterfaceObjectSetInstanceBinding object_set_instance_binding;
	GDExtensionInterfaceObjectSetInstance object_set_instance;
	GDExtensionInterfaceObjectCastTo object_cast_to;
	GDExtensionInterfaceObjectGetInstanceFromId object_get_instance_from_id;
	GDExtensionInterfaceObjectGetInstanceId object_get_instance_id;
	GDExtensionInterfaceRefSetObject ref_set_object;
	GDExtensionInterfaceClassdbConstructObject2 classdb_construct_object2;
	GDExtensionInterfaceClassdbGetMethodBind classdb_get_method_bind;
	GDExtensionInterfaceClassdbGetClassTag classdb_get_class_tag;
	GDExtensionInterfaceClassdbRegisterExtensionClass5 classdb_register_extension_class5;
	GDExtensionInterfaceClassdbRegisterExtensionClassMethod classdb_register_extension_class_method;
	GDExtensionInterfaceClassdbRegisterExtensionClassProperty classdb_register_extension_class_property;
	GDExtensionInterfaceClassdbRegisterExtensionClassPropertyGroup classdb_register_extension_class_property_group;
	GDExtensionInterfaceClassdbRegisterExtensionClassSignal classdb_register_extension_class_signal;
	GDExtensionInterfaceClassdbUnregisterExtensionClass classdb_unregister_extension_class;
	/* optional (NULL when missing): only the editor shows class docs */
	GDExtensionsInterfaceEditorHelpLoadXmlFromUtf8CharsAndLen editor_help_load_xml_from_utf8_chars_and_len;
} gd_interface;

extern gd_interface gd;

/* Engine method binds, builtin methods and utility functions, indexed by
 * the GDB_*, GDBB_*, GDU_* enums of smg_gd_api_gen.h. */
extern GDExtensionMethodBindPtr gd_binds[GDB_COUNT_];
extern GDExtensionPtrBuiltInMethod gd_builtins[GDBB_COUNT_];
extern GDExtensionPtrUtilityFunction gd_utilities[GDU_COUNT_];

/* Load the interface functions (entry point). false: something missing. */
bool gd_api_load(GDExtensionInterfaceGetProcAddress get_proc, GDExtensionClassLibraryPtr lib);
/* Resolve binds and common names (SCENE initialization level). */
bool gd_api_init_scene(void);
void gd_api_deinit_scene(void);

/* ---- strings ---- */
void gd_sn_init(gd_string_name *sn, const char *utf8);
void gd_sn_destroy(gd_string_name *sn);
void gd_str_init(gd_string *s, const char *utf8);
void gd_str_destroy(gd_string *s);
/* Copies at most cap-1 bytes of UTF-8 plus NUL; returns the full length. */
size_t gd_str_to_c(const gd_string *s, char *buf, size_t cap);
void gd_node_path_init(gd_node_path *np, const char *utf8);
void gd_node_path_copy(gd_node_path *dst, const gd_node_path *src);
void gd_node_path_destroy(gd_node_path *np);
bool gd_node_path_is_empty(const gd_node_path *np);

/* ---- packed arrays ---- */
void gd_packed_init(gd_packed *a, GDExtensionVariantType type);
void gd_packed_destroy(gd_packed *a, GDExtensionVariantType type);
int64_t gd_packed_v3_size(const gd_packed *a);
const gd_vec3 *gd_packed_v3_at(const gd_packed *a, int64_t i);
int64_t gd_packed_bytes_size(const gd_packed *a);
const uint8_t *gd_packed_bytes_data(const gd_packed *a);
void gd_packed_strings_push(gd_packed *a, const char *utf8);

/* ---- variants ---- */
void gd_variant_nil(gd_variant *v);
void gd_variant_destroy(gd_variant *v);
void gd_variant_from_int(gd_variant *v, int64_t i);
void gd_variant_from_cstr(gd_variant *v, const char *utf8);
void gd_variant_from_bool(gd_variant *v, bool b);
void gd_variant_from_float(gd_variant *v, double f);
void gd_variant_from_vec3(gd_variant *v, gd_vec3 x);
/* false (and *out untouched) unless v holds a Vector3. */
bool gd_variant_to_vec3(const gd_variant *v, gd_vec3 *out);
/* v[key] (e.g. a Dictionary's entry) into *out, which the caller destroys;
 * false and nil when there is none. */
bool gd_variant_get_key(const gd_variant *v, const char *key, gd_variant *out);
void gd_variant_from_sn(gd_variant *v, const gd_string_name *sn);
void gd_variant_from_object(gd_variant *v, GDExtensionObjectPtr o);
/* The object a Variant holds, or NULL (nil or another type). */
GDExtensionObjectPtr gd_variant_object(const gd_variant *v);

/* ---- objects ---- */
/* obj cast to the class (incl. subclasses) or NULL. */
GDExtensionObjectPtr gd_cast(GDExtensionConstObjectPtr obj, const char *class_name);
/* ptrcall of an engine method bind (index into gd_binds). */
void gd_call(int bind, GDExtensionObjectPtr obj, const void *const *args, void *ret);
/* The Variant call of an engine method bind: Godot manages the reference
 * counts of what goes in and out (Ref<> returns, Dictionaries). obj NULL
 * for a static method; *ret is initialised and the caller destroys it.
 * false: the call failed (wrong arguments). */
bool gd_call_variant(int bind, GDExtensionObjectPtr obj, const gd_variant *const *args, int argc, gd_variant *ret);
/* emit_signal(name, args...) on obj. */
void gd_emit(GDExtensionObjectPtr obj, const char *signal, const gd_variant *args, int argc);
GDExtensionObjectPtr gd_singleton(const char *name);
bool gd_is_editor(void);

/* ---- messages (Godot's ERROR:/WARNING: lines, shown in the editor) ---- */
void gd_error_at(const char *func, const char *file, int line, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
void gd_warning_at(const char *func, const char *file, int line, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
void gd_print(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
#define GD_ERR(...) gd_error_at(__func__, __FILE__, __LINE__, __VA_ARGS__)
#define GD_WARN(...) gd_warning_at(__func__, __FILE__, __LINE__, __VA_ARGS__)

#endif
