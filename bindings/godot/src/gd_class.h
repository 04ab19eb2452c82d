/* gd_class.h - registering C functions as methods, properties and signals of
 * an extension class, without a C++ binding layer.
 *
 * Each method is written once, as gd_method_fn over typed values; the
 * wrappers here serve both of Godot's call paths: the dynamic Variant call
 * (untyped GDScript, Callable, emit) and the typed ptrcall (typed GDScript).
 * Argument types are checked on the dynamic path so a wrong call gives a
 * script error instead of reading garbage. */
#ifndef SMG_GD_CLASS_H
#define SMG_GD_CLASS_H

#include "gd_api.h"

typedef enum gd_type {
	GT_NIL,       /* no return value */
	GT_BOOL,
	GT_INT,
	GT_FLOAT,
	GT_STRING,
	GT_VEC3,
	GT_NODE_PATH,
	GT_PV3,       /* PackedVector3Array */
	GT_PSA,       /* PackedStringArray */
	GT_OBJECT,    /* an Object that is not reference counted (a Node) */
	GT_REF        /* a RefCounted object (Resource) */
} gd_type;

/* One typed value. Arguments are borrowed (never destroy them); a returned
 * String/NodePath/packed array is owned and handed over to Godot; returned
 * objects are borrowed (Godot takes its own reference). */
typedef union gd_value {
	GDExtensionBool b;
	int64_t i;
	double f;
	gd_string s;
	gd_node_path np;
	gd_vec3 v3;
	gd_packed pa;
	GDExtensionObjectPtr o;
} gd_value;

typedef void (*gd_method_fn)(void *self, const gd_value *args, gd_value *ret);

#define GD_MAX_ARGS 6

typedef struct gd_arg {
	const char *name;
	gd_type type;
	const char *cls; /* class name for GT_OBJECT/GT_REF, else NULL */
} gd_arg;

typedef struct gd_method {
	const char *name;
	gd_method_fn fn;
	gd_type ret;
	const char *ret_cls;
	int argc;
	gd_arg args[GD_MAX_ARGS];
	int is_const;
} gd_method;

/* Register extension class `cls` deriving from `parent`: an exposed class
 * whose instances are made by `create` and freed by `destroy`; notify and
 * get_virtual may be NULL. */
void gd_register_class(const char *cls, const char *parent, GDExtensionClassCreateInstance2 create,
	GDExtensionClassFreeInstance destroy, GDExtensionClassNotification2 notify,
	GDExtensionClassGetVirtual2 get_virtual);

/* `methods` must stay alive while the class is registered (static). */
void gd_register_methods(const char *cls, const gd_method *methods, int count);
void gd_register_property(const char *cls, const gd_arg *prop, uint32_t hint, const char *hint_string,
	const char *setter, const char *getter);
void gd_register_signal(const char *cls, const char *name, const gd_arg *args, int argc);

/* Instances of our classes: the engine object of class `parent` that
 * carries `self` as its extension instance (found again by gd_object_self).
 * notify: send NOTIFICATION_POSTINITIALIZE as Godot asks us to. */
GDExtensionObjectPtr gd_object_create(const char *parent, const char *cls, void *self, GDExtensionBool notify);
/* Our instance struct behind obj if obj is a `cls` (or subclass), else NULL. */
void *gd_object_self(GDExtensionObjectPtr obj, const char *cls);
/* A new engine object (e.g. "Skeleton3D"), fully initialized. */
GDExtensionObjectPtr gd_engine_new(const char *cls);

#endif
