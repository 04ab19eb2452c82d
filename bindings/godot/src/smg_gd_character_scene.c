/* smg_gd_character_scene.c - SmgCharacter in a game scene: libsmg's event
 * queue as signals, the root motion for the engine's mover and the ground
 * measured by physics ray casts (docs/api-guide.md, "In a game scene").
 *
 * Events and root motion are read after every libsmg step; a frame longer
 * than one step (split in smg_gd_character_step) adds its steps' root
 * motion and keeps all their events, so a script sees one frame's worth.
 * The ground is measured before every step where libsmg asks for it
 * (smg_character_get_ground_probes): three rays straight down through the
 * probes, in the physics space of the node's World3D. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smg_gd_character_internal.h"

#define CLASS SMG_GD_CHARACTER_CLASS
#define SELF smg_gd_character *self = vself
/* The rays start this far above the character's current ground height and
 * end this far below it: a step up or down within a leg's reach is seen,
 * a ceiling or a floor far below is not. */
#define RAY_UP 1.0f
#define RAY_DOWN 2.0f

static const gd_transform3d IDENTITY = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { 0, 0, 0 } };

gd_transform3d smg_gd_character_space(smg_gd_character *self) {
	if (self->root_motion_mode == SMG_GD_ENGINE_MOVER) return IDENTITY;
	GDExtensionObjectPtr parent = NULL;
	gd_call(GDB_Node_get_parent, self->owner, NULL, &parent);
	parent = gd_cast(parent, "Node3D");
	if (!parent) return IDENTITY;
	gd_transform3d t;
	gd_call(GDB_Node3D_get_global_transform, parent, NULL, &t);
	return t;
}

static gd_vec3 to_global(const gd_transform3d *t, float x, float y, float z) {
	return (gd_vec3){ t->basis[0][0] * x + t->basis[0][1] * y + t->basis[0][2] * z + t->origin[0],
		t->basis[1][0] * x + t->basis[1][1] * y + t->basis[1][2] * z + t->origin[1],
		t->basis[2][0] * x + t->basis[2][1] * y + t->basis[2][2] * z + t->origin[2] };
}

/* The height (libsmg space) of a global point, for a rigid transform. */
static float local_height(const gd_transform3d *t, gd_vec3 p) {
	float d[3] = { p.x - t->origin[0], p.y - t->origin[1], p.z - t->origin[2] };
	return t->basis[0][1] * d[0] + t->basis[1][1] * d[1] + t->basis[2][1] * d[2];
}

/* The first hit of a ray from `from` to `to` in `space`; false: none. */
static bool cast_ray(GDExtensionObjectPtr space, gd_vec3 from, gd_vec3 to, int64_t mask, gd_vec3 *hit) {
	gd_variant vf, vt, vm, query, result, pos;
	gd_variant_from_vec3(&vf, from);
	gd_variant_from_vec3(&vt, to);
	gd_variant_from_int(&vm, mask);
	const gd_variant *qa[3] = { &vf, &vt, &vm };
	bool ok = gd_call_variant(GDB_PhysicsRayQueryParameters3D_create, NULL, qa, 3, &query);
	bool found = false;
	if (ok) {
		const gd_variant *ra[1] = { &query };
		if (gd_call_variant(GDB_PhysicsDirectSpaceState3D_intersect_ray, space, ra, 1, &result)) {
			if (gd_variant_get_key(&result, "position", &pos)) {
				found = gd_variant_to_vec3(&pos, hit);
				gd_variant_destroy(&pos);
			}
		}
		gd_variant_destroy(&result);
	}
	gd_variant_destroy(&query);
	gd_variant_destroy(&vm);
	gd_variant_destroy(&vt);
	gd_variant_destroy(&vf);
	return found;
}

/* The physics space of the node's world; NULL outside a tree. *world holds
 * the World3D reference while the space is used. */
static GDExtensionObjectPtr direct_space(smg_gd_character *self, gd_variant *world) {
	gd_variant space;
	gd_variant_nil(&space);
	if (!gd_call_variant(GDB_Node3D_get_world_3d, self->owner, NULL, 0, world) || !gd_variant_object(world))
		return NULL;
	GDExtensionObjectPtr s = NULL;
	if (gd_call_variant(GDB_World3D_get_direct_space_state, gd_variant_object(world), NULL, 0, &space))
		s = gd_variant_object(&space); /* owned by the physics server, not counted */
	gd_variant_destroy(&space);
	return s;
}

void smg_gd_character_probe_ground(smg_gd_character *self) {
	if (!self->ground_probing) {
		if (self->ground_given) smg_character_set_ground(self->ch, NULL);
		self->ground_given = false;
		return;
	}
	float xz[6];
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (smg_character_get_ground_probes(self->ch, xz, 3) != SMG_OK ||
	    smg_character_get_state(self->ch, &st) != SMG_OK)
		return;
	gd_variant world;
	gd_variant_nil(&world);
	GDExtensionObjectPtr space = direct_space(self, &world);
	if (space) {
		gd_transform3d t = smg_gd_character_space(self);
		float ref = st.position[1], h[3];
		for (int i = 0; i < 3; i++) {
			gd_vec3 hit;
			gd_vec3 from = to_global(&t, xz[2 * i], ref + RAY_UP, xz[2 * i + 1]);
			gd_vec3 to = to_global(&t, xz[2 * i], ref - RAY_DOWN, xz[2 * i + 1]);
			/* nothing under a probe (off an edge): keep the current height */
			h[i] = cast_ray(space, from, to, self->ground_mask, &hit) ? local_height(&t, hit) : ref;
		}
		smg_ground g;
		memset(&g, 0, sizeof g);
		g.struct_size = sizeof g;
		g.foot_height[0] = h[0];
		g.foot_height[1] = h[1];
		g.root_height = h[2];
		smg_result r = smg_character_set_ground(self->ch, &g);
		if (r == SMG_OK)
			self->ground_given = true;
		else
			GD_ERR("SmgCharacter: ground heights rejected: %s", smg_result_string(r));
	}
	gd_variant_destroy(&world);
}

void smg_gd_character_collect(smg_gd_character *self) {
	smg_root_motion rm;
	memset(&rm, 0, sizeof rm);
	rm.struct_size = sizeof rm;
	if (smg_character_get_root_motion(self->ch, &rm) == SMG_OK) {
		for (int i = 0; i < 3; i++) self->root_motion[i] += rm.translation[i];
		self->root_motion[3] += rm.yaw;
	}
	uint32_t n = 0;
	if (smg_character_get_events(self->ch, NULL, 0, &n) != SMG_OK || n == 0) return;
	if (self->event_count + n > self->event_cap) {
		uint32_t cap = self->event_count + n + 16u;
		smg_event *e = realloc(self->events, cap * sizeof *e);
		if (!e) {
			GD_ERR("SmgCharacter: out of memory for events");
			return;
		}
		self->events = e;
		self->event_cap = cap;
	}
	smg_event *dst = &self->events[self->event_count];
	dst[0].struct_size = sizeof *dst;
	if (smg_character_get_events(self->ch, dst, n, &n) == SMG_OK) self->event_count += n;
}

void smg_gd_character_emit_events(smg_gd_character *self, GDObjectInstanceID oid) {
	uint32_t n = self->event_count;
	if (n == 0) return;
	/* A handler may free the node or rebuild its character: emit from a
	 * copy, and stop once the node is gone. */
	smg_event *ev = malloc(n * sizeof *ev);
	if (!ev) return;
	memcpy(ev, self->events, n * sizeof *ev);
	self->event_count = 0;
	gd_transform3d t = smg_gd_character_space(self);
	GDExtensionObjectPtr owner = self->owner;
	for (uint32_t i = 0; i < n && gd.object_get_instance_from_id(oid); i++) {
		const smg_event *e = &ev[i];
		gd_variant a[3];
		if (e->type == SMG_EVENT_CONSTRAINT) {
			/* only what a constraint asked for, and only if it was reached */
			if (e->id == 0 || (e->flags & SMG_EVENT_SUPERSEDED)) continue;
			gd_variant_from_int(&a[0], e->id);
			gd_variant_from_int(&a[1], e->value);
			gd_variant_from_bool(&a[2], (e->flags & SMG_EVENT_SPLICE) != 0);
			gd_emit(owner, "constraint_reached", a, 3);
		} else if (e->type == SMG_EVENT_FOOTSTEP) {
			gd_variant_from_int(&a[0], e->id);
			gd_variant_from_vec3(&a[1], to_global(&t, e->position[0], e->position[1], e->position[2]));
			gd_variant_from_float(&a[2], e->strength);
			gd_emit(owner, "footstep", a, 3);
		} else if (e->type == SMG_EVENT_PATH_END) {
			gd_emit(owner, "path_end_reached", NULL, 0);
			continue;
		} else {
			continue;
		}
		for (int k = 0; k < 3; k++) gd_variant_destroy(&a[k]);
	}
	free(ev);
}

/* ---------------- methods ---------------- */

static void m_set_root_motion_mode(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].i != SMG_GD_MOVE_NODE && a[0].i != SMG_GD_ENGINE_MOVER) {
		GD_ERR("SmgCharacter.root_motion_mode: %lld is not 0 (library moves the node) or 1 (engine mover)",
			(long long)a[0].i);
		return;
	}
	if (a[0].i == self->root_motion_mode) return;
	self->root_motion_mode = a[0].i;
	/* the library's space changes (parent <-> global): start again at the
	 * node, replaying the path and points */
	if (self->ch) {
		smg_result res = smg_character_destroy(self->ch);
		if (res != SMG_OK) GD_ERR("SmgCharacter.root_motion_mode: destroy failed: %s", smg_result_string(res));
		self->ch = NULL;
		smg_gd_character_ensure(self); /* rebuilt on the same graph */
	}
}

static void m_get_root_motion_mode(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = self->root_motion_mode;
}

static void m_get_root_motion(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->v3 = (gd_vec3){ self->root_motion[0], self->root_motion[1], self->root_motion[2] };
}

static void m_get_root_motion_yaw(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->f = self->root_motion[3];
}

static void m_set_ground_position(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	if (!smg_gd_character_need(self, "set_ground_position")) {
		r->i = GD_ERR_UNCONFIGURED;
		return;
	}
	float p[3] = { a[0].v3.x, a[0].v3.y, a[0].v3.z };
	smg_result res = smg_character_set_ground_position(self->ch, p, (float)a[1].f);
	if (res != SMG_OK) GD_ERR("SmgCharacter.set_ground_position: rejected: %s", smg_result_string(res));
	r->i = smg_gd_error_of(res);
}

static void m_get_heading(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	r->f = self->ch && smg_character_get_state(self->ch, &st) == SMG_OK ? st.heading : 0.0;
}

static void m_set_ground_probing(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	self->ground_probing = a[0].b != 0;
}

static void m_is_ground_probing(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->b = self->ground_probing;
}

static void m_set_ground_collision_mask(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)r;
	if (a[0].i < 0 || a[0].i > 0xFFFFFFFFll) {
		GD_ERR("SmgCharacter.ground_collision_mask: %lld is not a 32-bit layer mask", (long long)a[0].i);
		return;
	}
	self->ground_mask = a[0].i;
}

static void m_get_ground_collision_mask(void *vself, const gd_value *a, gd_value *r) {
	SELF;
	(void)a;
	r->i = self->ground_mask;
}

static const gd_method methods[] = {
	{ "set_root_motion_mode", m_set_root_motion_mode, GT_NIL, NULL, 1, { { "mode", GT_INT, NULL } }, 0 },
	{ "get_root_motion_mode", m_get_root_motion_mode, GT_INT, NULL, 0, { { 0 } }, 1 },
	{ "get_root_motion", m_get_root_motion, GT_VEC3, NULL, 0, { { 0 } }, 1 },
	{ "get_root_motion_yaw", m_get_root_motion_yaw, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_ground_position", m_set_ground_position, GT_INT, NULL, 2,
	  { { "position", GT_VEC3, NULL }, { "heading", GT_FLOAT, NULL } }, 0 },
	{ "get_heading", m_get_heading, GT_FLOAT, NULL, 0, { { 0 } }, 1 },
	{ "set_ground_probing", m_set_ground_probing, GT_NIL, NULL, 1, { { "enabled", GT_BOOL, NULL } }, 0 },
	{ "is_ground_probing", m_is_ground_probing, GT_BOOL, NULL, 0, { { 0 } }, 1 },
	{ "set_ground_collision_mask", m_set_ground_collision_mask, GT_NIL, NULL, 1, { { "mask", GT_INT, NULL } }, 0 },
	{ "get_ground_collision_mask", m_get_ground_collision_mask, GT_INT, NULL, 0, { { 0 } }, 1 },
};

void smg_gd_character_register_scene_methods(void) {
	gd_register_methods(CLASS, methods, (int)(sizeof methods / sizeof methods[0]));
	gd_arg p_mode = { "root_motion_mode", GT_INT, NULL };
	gd_register_property(CLASS, &p_mode, GD_PROPERTY_HINT_ENUM, "Library Moves Node,Engine Mover",
		"set_root_motion_mode", "get_root_motion_mode");
	gd_arg p_probe = { "ground_probing", GT_BOOL, NULL };
	gd_register_property(CLASS, &p_probe, GD_PROPERTY_HINT_NONE, NULL, "set_ground_probing", "is_ground_probing");
	gd_arg p_mask = { "ground_collision_mask", GT_INT, NULL };
	gd_register_property(CLASS, &p_mask, GD_PROPERTY_HINT_LAYERS_3D_PHYSICS, NULL, "set_ground_collision_mask",
		"get_ground_collision_mask");

	gd_arg sig_c[3] = { { "id", GT_INT, NULL }, { "value", GT_INT, NULL }, { "is_splice", GT_BOOL, NULL } };
	gd_register_signal(CLASS, "constraint_reached", sig_c, 3);
	gd_arg sig_f[3] = { { "foot", GT_INT, NULL }, { "position", GT_VEC3, NULL }, { "strength", GT_FLOAT, NULL } };
	gd_register_signal(CLASS, "footstep", sig_f, 3);
}
