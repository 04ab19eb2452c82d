/* gd_class.c - method/property/signal registration and the two call paths. */
#include "gd_class.h"

#include <string.h>

static GDExtensionVariantType variant_type(gd_type t) {
	switch (t) {
	case GT_BOOL: return GDEXTENSION_VARIANT_TYPE_BOOL;
	case GT_INT: return GDEXTENSION_VARIANT_TYPE_INT;
	case GT_FLOAT: return GDEXTENSION_VARIANT_TYPE_FLOAT;
	case GT_STRING: return GDEXTENSION_VARIANT_TYPE_STRING;
	case GT_VEC3: return GDEXTENSION_VARIANT_TYPE_VECTOR3;
	case GT_NODE_PATH: return GDEXTENSION_VARIANT_TYPE_NODE_PATH;
	case GT_PV3: return GDEXTENSION_VARIANT_TYPE_PACKED_VECTOR3_ARRAY;
	case GT_PSA: return GDEXTENSION_VARIANT_TYPE_PACKED_STRING_ARRAY;
	case GT_OBJECT:
	case GT_REF: return GDEXTENSION_VARIANT_TYPE_OBJECT;
	case GT_NIL: break;
	}
	return GDEXTENSION_VARIANT_TYPE_NIL;
}

/* Types that own memory (need a destructor when we own the value). */
static bool owns_memory(gd_type t) {
	return t == GT_STRING || t == GT_NODE_PATH || t == GT_PV3 || t == GT_PSA;
}

static void destroy_value(gd_type t, gd_value *v) {
	if (owns_memory(t)) gd.variant_get_ptr_destructor(variant_type(t))(v);
}

/* ptrcall argument -> borrowed gd_value (same representation as Godot's
 * ptrcall encoding: bool is one byte, ints int64, floats double, objects a
 * pointer to the object pointer, builtins the value itself). */
static void value_from_ptr(gd_type t, const void *p, gd_value *v) {
	memset(v, 0, sizeof *v);
	switch (t) {
	case GT_BOOL: v->b = *(const uint8_t *)p ? 1 : 0; break;
	case GT_INT: v->i = *(const int64_t *)p; break;
	case GT_FLOAT: v->f = *(const double *)p; break;
	case GT_STRING: memcpy(&v->s, p, sizeof v->s); break;
	case GT_NODE_PATH: memcpy(&v->np, p, sizeof v->np); break;
	case GT_VEC3: memcpy(&v->v3, p, sizeof v->v3); break;
	case GT_PV3:
	case GT_PSA: memcpy(&v->pa, p, sizeof v->pa); break;
	case GT_OBJECT:
	case GT_REF: v->o = p ? *(GDExtensionObjectPtr const *)p : NULL; break;
	case GT_NIL: break;
	}
}

/* Variant argument -> owned gd_value; false if the type does not fit. */
static bool value_from_variant(gd_type t, GDExtensionConstVariantPtr var, gd_value *v) {
	GDExtensionVariantType have = gd.variant_get_type(var);
	GDExtensionVariantType want = variant_type(t);
	memset(v, 0, sizeof *v);
	if (have == want) {
		gd.get_variant_to_type_constructor(want)(v, (GDExtensionVariantPtr)var);
		return true;
	}
	/* The conversions GDScript itself makes silently. */
	if (t == GT_FLOAT && have == GDEXTENSION_VARIANT_TYPE_INT) {
		int64_t i;
		gd.get_variant_to_type_constructor(have)(&i, (GDExtensionVariantPtr)var);
		v->f = (double)i;
		return true;
	}
	if (t == GT_INT && have == GDEXTENSION_VARIANT_TYPE_FLOAT) {
		double f;
		gd.get_variant_to_type_constructor(have)(&f, (GDExtensionVariantPtr)var);
		v->i = (int64_t)f;
		return true;
	}
	if ((t == GT_OBJECT || t == GT_REF) && have == GDEXTENSION_VARIANT_TYPE_NIL) {
		v->o = NULL;
		return true;
	}
	return false;
}

static void ret_to_ptr(gd_type t, gd_value *v, void *r) {
	switch (t) {
	case GT_BOOL: *(uint8_t *)r = v->b ? 1 : 0; break;
	case GT_INT: *(int64_t *)r = v->i; break;
	case GT_FLOAT: *(double *)r = v->f; break;
	case GT_VEC3: memcpy(r, &v->v3, sizeof v->v3); break;
	case GT_STRING:
	case GT_NODE_PATH:
	case GT_PV3:
	case GT_PSA:
		/* r holds a constructed (empty) value: release it, move ours in. */
		gd.variant_get_ptr_destructor(variant_type(t))(r);
		memcpy(r, v, t == GT_STRING || t == GT_NODE_PATH ? sizeof(void *) : sizeof(gd_packed));
		break;
	case GT_OBJECT: *(GDExtensionObjectPtr *)r = v->o; break;
	case GT_REF: gd.ref_set_object(r, v->o); break; /* r is a Ref<>: takes a reference */
	case GT_NIL: break;
	}
}

static void ret_to_variant(gd_type t, gd_value *v, GDExtensionVariantPtr r) {
	if (t == GT_NIL) return;
	if ((t == GT_OBJECT || t == GT_REF) && !v->o) {
		gd.variant_new_nil(r);
		return;
	}
	gd.get_variant_from_type_constructor(variant_type(t))(r, v);
	destroy_value(t, v);
}

static void call_wrapper(void *method_userdata, GDExtensionClassInstancePtr inst,
	const GDExtensionConstVariantPtr *args, GDExtensionInt argc, GDExtensionVariantPtr r_ret,
	GDExtensionCallError *err) {
	const gd_method *m = method_userdata;
	gd_value vals[GD_MAX_ARGS], ret;
	if (argc < m->argc || argc > m->argc) {
		err->error = argc < m->argc ? GDEXTENSION_CALL_ERROR_TOO_FEW_ARGUMENTS
		                            : GDEXTENSION_CALL_ERROR_TOO_MANY_ARGUMENTS;
		err->expected = m->argc;
		return;
	}
	for (int i = 0; i < m->argc; i++) {
		if (!value_from_variant(m->args[i].type, args[i], &vals[i])) {
			for (int j = 0; j < i; j++) destroy_value(m->args[j].type, &vals[j]);
			err->error = GDEXTENSION_CALL_ERROR_INVALID_ARGUMENT;
			err->argument = i;
			err->expected = (int32_t)variant_type(m->args[i].type);
			return;
		}
	}
	memset(&ret, 0, sizeof ret);
	m->fn(inst, vals, &ret);
	for (int i = 0; i < m->argc; i++) destroy_value(m->args[i].type, &vals[i]);
	ret_to_variant(m->ret, &ret, r_ret);
	err->error = GDEXTENSION_CALL_OK;
}

static void ptrcall_wrapper(void *method_userdata, GDExtensionClassInstancePtr inst,
	const GDExtensionConstTypePtr *args, GDExtensionTypePtr r_ret) {
	const gd_method *m = method_userdata;
	gd_value vals[GD_MAX_ARGS], ret;
	for (int i = 0; i < m->argc; i++) value_from_ptr(m->args[i].type, args[i], &vals[i]);
	memset(&ret, 0, sizeof ret);
	m->fn(inst, vals, &ret);
	if (m->ret != GT_NIL && r_ret) ret_to_ptr(m->ret, &ret, r_ret);
	else destroy_value(m->ret, &ret);
}

/* PropertyInfo with its own StringNames/Strings, released by info_free. */
typedef struct info_store {
	gd_string_name name, cls;
	gd_string hint_string;
} info_store;

static GDExtensionPropertyInfo info_make(info_store *st, const gd_arg *a, uint32_t hint,
	const char *hint_string) {
	gd_sn_init(&st->name, a->name ? a->name : "");
	gd_sn_init(&st->cls, a->cls ? a->cls : "");
	gd_str_init(&st->hint_string, hint_string ? hint_string : (a->cls ? a->cls : ""));
	if (a->cls && hint == GD_PROPERTY_HINT_NONE && a->type == GT_REF) hint = GD_PROPERTY_HINT_RESOURCE_TYPE;
	GDExtensionPropertyInfo pi = {
		.type = variant_type(a->type),
		.name = &st->name,
		.class_name = &st->cls,
		.hint = hint,
		.hint_string = &st->hint_string,
		.usage = GD_PROPERTY_USAGE_DEFAULT,
	};
	return pi;
}

static void info_free(info_store *st) {
	gd_sn_destroy(&st->name);
	gd_sn_destroy(&st->cls);
	gd_str_destroy(&st->hint_string);
}

void gd_register_class(const char *cls, const char *parent, GDExtensionClassCreateInstance2 create,
	GDExtensionClassFreeInstance destroy, GDExtensionClassNotification2 notify,
	GDExtensionClassGetVirtual2 get_virtual) {
	gd_string_name cname, pname;
	GDExtensionClassCreationInfo5 ci;
	memset(&ci, 0, sizeof ci);
	ci.is_exposed = 1;
	ci.create_instance_func = create;
	ci.free_instance_func = destroy;
	ci.notification_func = notify;
	ci.get_virtual_func = get_virtual;
	gd_sn_init(&cname, cls);
	gd_sn_init(&pname, parent);
	gd.classdb_register_extension_class5(gd.lib, &cname, &pname, &ci);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&pname);
}

void gd_register_methods(const char *cls, const gd_method *methods, int count) {
	gd_string_name cname;
	gd_sn_init(&cname, cls);
	for (int k = 0; k < count; k++) {
		const gd_method *m = &methods[k];
		gd_string_name mname;
		info_store ret_st, arg_st[GD_MAX_ARGS];
		GDExtensionPropertyInfo ret_pi, arg_pi[GD_MAX_ARGS];
		GDExtensionClassMethodArgumentMetadata arg_meta[GD_MAX_ARGS];
		gd_arg ret_arg = { "", m->ret, m->ret_cls };
		gd_sn_init(&mname, m->name);
		ret_pi = info_make(&ret_st, &ret_arg, GD_PROPERTY_HINT_NONE, NULL);
		for (int i = 0; i < m->argc; i++) {
			arg_pi[i] = info_make(&arg_st[i], &m->args[i], GD_PROPERTY_HINT_NONE, NULL);
			arg_meta[i] = m->args[i].type == GT_INT ? GDEXTENSION_METHOD_ARGUMENT_METADATA_INT_IS_INT64
			            : m->args[i].type == GT_FLOAT ? GDEXTENSION_METHOD_ARGUMENT_METADATA_REAL_IS_DOUBLE
			            : GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
		}
		GDExtensionClassMethodInfo mi = {
			.name = &mname,
			.method_userdata = (void *)m,
			.call_func = call_wrapper,
			.ptrcall_func = ptrcall_wrapper,
			.method_flags = GDEXTENSION_METHOD_FLAGS_DEFAULT | (m->is_const ? GDEXTENSION_METHOD_FLAG_CONST : 0),
			.has_return_value = m->ret != GT_NIL,
			.return_value_info = &ret_pi,
			.return_value_metadata = m->ret == GT_INT ? GDEXTENSION_METHOD_ARGUMENT_METADATA_INT_IS_INT64
			                       : m->ret == GT_FLOAT ? GDEXTENSION_METHOD_ARGUMENT_METADATA_REAL_IS_DOUBLE
			                       : GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE,
			.argument_count = (uint32_t)m->argc,
			.arguments_info = arg_pi,
			.arguments_metadata = arg_meta,
			.default_argument_count = 0,
			.default_arguments = NULL,
		};
		gd.classdb_register_extension_class_method(gd.lib, &cname, &mi);
		gd_sn_destroy(&mname);
		info_free(&ret_st);
		for (int i = 0; i < m->argc; i++) info_free(&arg_st[i]);
	}
	gd_sn_destroy(&cname);
}

void gd_register_property(const char *cls, const gd_arg *prop, uint32_t hint, const char *hint_string,
	const char *setter, const char *getter) {
	gd_string_name cname, sname, gname;
	info_store st;
	GDExtensionPropertyInfo pi = info_make(&st, prop, hint, hint_string);
	gd_sn_init(&cname, cls);
	gd_sn_init(&sname, setter ? setter : "");
	gd_sn_init(&gname, getter);
	gd.classdb_register_extension_class_property(gd.lib, &cname, &pi, &sname, &gname);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&sname);
	gd_sn_destroy(&gname);
	info_free(&st);
}

void gd_register_signal(const char *cls, const char *name, const gd_arg *args, int argc) {
	gd_string_name cname, sname;
	info_store st[GD_MAX_ARGS];
	GDExtensionPropertyInfo pi[GD_MAX_ARGS];
	if (argc > GD_MAX_ARGS) argc = GD_MAX_ARGS;
	for (int i = 0; i < argc; i++) pi[i] = info_make(&st[i], &args[i], GD_PROPERTY_HINT_NONE, NULL);
	gd_sn_init(&cname, cls);
	gd_sn_init(&sname, name);
	gd.classdb_register_extension_class_signal(gd.lib, &cname, &sname, pi, argc);
	gd_sn_destroy(&cname);
	gd_sn_destroy(&sname);
	for (int i = 0; i < argc; i++) info_free(&st[i]);
}

/* Instance bindings tie our instance struct to its engine object, keyed by
 * our library token; the struct itself is owned by the class's free func. */
static void *binding_create(void *token, void *instance) {
	(void)token;
	(void)instance;
	return NULL;
}
static void binding_free(void *token, void *instance, void *binding) {
	(void)token;
	(void)instance;
	(void)binding;
}
static GDExtensionBool binding_reference(void *token, void *binding, GDExtensionBool reference) {
	(void)token;
	(void)binding;
	(void)reference;
	return 1;
}
static const GDExtensionInstanceBindingCallbacks binding_callbacks = {
	binding_create, binding_free, binding_reference
};

static void send_postinitialize(GDExtensionObjectPtr obj) {
	int64_t what = GD_Object_NOTIFICATION_POSTINITIALIZE;
	GDExtensionBool reversed = 0;
	const void *args[2] = { &what, &reversed };
	gd_call(GDB_Object_notification, obj, args, NULL);
}

GDExtensionObjectPtr gd_object_create(const char *parent, const char *cls, void *self, GDExtensionBool notify) {
	gd_string_name p, c;
	gd_sn_init(&p, parent);
	gd_sn_init(&c, cls);
	GDExtensionObjectPtr obj = gd.classdb_construct_object2(&p);
	if (obj) {
		gd.object_set_instance(obj, &c, self);
		gd.object_set_instance_binding(obj, gd.lib, self, &binding_callbacks);
		if (notify) send_postinitialize(obj);
	}
	gd_sn_destroy(&p);
	gd_sn_destroy(&c);
	return obj;
}

void *gd_object_self(GDExtensionObjectPtr obj, const char *cls) {
	if (!obj || !gd_cast(obj, cls)) return NULL;
	return gd.object_get_instance_binding(obj, gd.lib, &binding_callbacks);
}

GDExtensionObjectPtr gd_engine_new(const char *cls) {
	gd_string_name c;
	gd_sn_init(&c, cls);
	GDExtensionObjectPtr obj = gd.classdb_construct_object2(&c);
	gd_sn_destroy(&c);
	if (obj) send_postinitialize(obj);
	return obj;
}
