/* smg_gd_bone_map.c - graph joints to Skeleton3D bones by name, and the
 * pose written through that match (see smg_gd_bone_map.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gd_class.h"
#include "rmath.h"
#include "smg_gd_bone_map.h"
#include "smg_gd_graph.h"
#include "smg_gd_humanoid.h"

bool smg_gd_bone_map_init(smg_gd_bone_map *m, uint32_t joint_count) {
	smg_gd_bone_map_free(m);
	m->rot = calloc((size_t)joint_count * 4u + 4u, sizeof(float));
	m->joint_count = joint_count;
	return m->rot != NULL;
}

void smg_gd_bone_map_free(smg_gd_bone_map *m) {
	free(m->rot);
	free(m->bone_of_joint);
	free(m->rest_of_joint);
	free(m->part_of_joint);
	memset(m, 0, sizeof *m);
}

void smg_gd_bone_map_invalidate(smg_gd_bone_map *m) {
	m->skel_id = 0;
}

GDExtensionObjectPtr smg_gd_find_skeleton(GDExtensionObjectPtr owner, const gd_node_path *path) {
	if (!gd_node_path_is_empty(path)) {
		GDExtensionObjectPtr n = NULL;
		const void *a[1] = { path };
		gd_call(GDB_Node_get_node_or_null, owner, a, &n);
		return gd_cast(n, "Skeleton3D");
	}
	int64_t count = 0;
	GDExtensionBool internal = 0;
	const void *ca[1] = { &internal };
	gd_call(GDB_Node_get_child_count, owner, ca, &count);
	for (int64_t i = 0; i < count; i++) {
		GDExtensionObjectPtr c = NULL;
		const void *a[2] = { &i, &internal };
		gd_call(GDB_Node_get_child, owner, a, &c);
		GDExtensionObjectPtr s = gd_cast(c, "Skeleton3D");
		if (s) return s;
	}
	return NULL;
}

/* Rotation of a rest transform's basis (columns normalised: a scaled
 * rest keeps its orientation), as (x,y,z,w). */
static void basis_rotation(const gd_transform3d *t, float *q) {
	float m[3][3];
	for (int c = 0; c < 3; c++) {
		float l = sqrtf(t->basis[0][c] * t->basis[0][c] + t->basis[1][c] * t->basis[1][c] +
		                t->basis[2][c] * t->basis[2][c]);
		for (int r = 0; r < 3; r++) m[r][c] = l > 0.0f ? t->basis[r][c] / l : (r == c);
	}
	float tr = m[0][0] + m[1][1] + m[2][2];
	if (tr > 0.0f) {
		float s = sqrtf(tr + 1.0f) * 2.0f;
		q[3] = 0.25f * s;
		q[0] = (m[2][1] - m[1][2]) / s;
		q[1] = (m[0][2] - m[2][0]) / s;
		q[2] = (m[1][0] - m[0][1]) / s;
	} else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
		float s = sqrtf(1.0f + m[0][0] - m[1][1] - m[2][2]) * 2.0f;
		q[3] = (m[2][1] - m[1][2]) / s;
		q[0] = 0.25f * s;
		q[1] = (m[0][1] + m[1][0]) / s;
		q[2] = (m[0][2] + m[2][0]) / s;
	} else if (m[1][1] > m[2][2]) {
		float s = sqrtf(1.0f + m[1][1] - m[0][0] - m[2][2]) * 2.0f;
		q[3] = (m[0][2] - m[2][0]) / s;
		q[0] = (m[0][1] + m[1][0]) / s;
		q[1] = 0.25f * s;
		q[2] = (m[1][2] + m[2][1]) / s;
	} else {
		float s = sqrtf(1.0f + m[2][2] - m[0][0] - m[1][1]) * 2.0f;
		q[3] = (m[1][0] - m[0][1]) / s;
		q[0] = (m[0][2] + m[2][0]) / s;
		q[1] = (m[1][2] + m[2][1]) / s;
		q[2] = 0.25f * s;
	}
}

/* The global rest rotation of `bone` (identity for -1). */
static void bone_global_rest(GDExtensionObjectPtr skel, int64_t bone, float *q) {
	q[0] = q[1] = q[2] = 0.0f;
	q[3] = 1.0f;
	if (bone < 0) return;
	gd_transform3d t;
	memset(&t, 0, sizeof t);
	const void *a[1] = { &bone };
	gd_call(GDB_Skeleton3D_get_bone_global_rest, skel, a, &t);
	basis_rotation(&t, q);
}

static int64_t find_bone(GDExtensionObjectPtr skel, const char *name) {
	gd_string s;
	gd_str_init(&s, name);
	int64_t bone = -1;
	const void *a[1] = { &s };
	gd_call(GDB_Skeleton3D_find_bone, skel, a, &bone);
	gd_str_destroy(&s);
	return bone;
}

/* The skeleton bone a BoneMap gives for a profile bone name, or -1. */
static int64_t find_mapped_bone(GDExtensionObjectPtr skel, GDExtensionObjectPtr bone_map, const char *profile) {
	gd_string_name in, out;
	gd_sn_init(&in, profile);
	gd_sn_init(&out, "");
	const void *a[1] = { &in };
	gd_call(GDB_BoneMap_get_skeleton_bone_name, bone_map, a, &out);
	gd_string s;
	const void *ca[1] = { &out };
	gd.variant_get_ptr_constructor(GDEXTENSION_VARIANT_TYPE_STRING, 2)(&s, ca); /* String(StringName) */
	char name[256];
	gd_str_to_c(&s, name, sizeof name);
	gd_str_destroy(&s);
	gd_sn_destroy(&out);
	gd_sn_destroy(&in);
	return name[0] ? find_bone(skel, name) : -1;
}

/* Bones matched, refreshed when the skeleton or its bone list changes. */
static void match_bones(smg_gd_bone_map *m, const smg_graph *graph, GDExtensionObjectPtr skel) {
	GDObjectInstanceID id = gd.object_get_instance_id(skel);
	int64_t version = 0;
	gd_call(GDB_Skeleton3D_get_version, skel, NULL, &version);
	if (id == m->skel_id && version == m->skel_version && m->bone_of_joint) return;
	uint32_t n = m->joint_count;
	int32_t *map = realloc(m->bone_of_joint, (n ? n : 1) * sizeof *map);
	if (!map) return;
	m->bone_of_joint = map;
	float *rest = realloc(m->rest_of_joint, (n ? n : 1) * 8 * sizeof *rest);
	if (!rest) {
		free(map);
		m->bone_of_joint = NULL;
		return;
	}
	m->rest_of_joint = rest;
	uint8_t *part = realloc(m->part_of_joint, n ? n : 1);
	if (!part) {
		free(map);
		m->bone_of_joint = NULL;
		return;
	}
	m->part_of_joint = part;
	m->rests_identity = true;
	m->skel_id = id;
	m->skel_version = version;
	uint32_t matched = 0;
	const char **profile = calloc(n ? n : 1, sizeof *profile);
	if (profile) smg_gd_humanoid_names(graph, n, profile);
	GDExtensionObjectPtr bone_map = m->bone_map ? gd_cast(gd_variant_object(m->bone_map), "BoneMap") : NULL;
	for (uint32_t j = 0; j < n; j++) {
		smg_joint_info ji;
		memset(&ji, 0, sizeof ji);
		ji.struct_size = sizeof ji;
		map[j] = -1;
		part[j] = SMG_BODY_UPPER;
		if (smg_graph_get_joint(graph, j, &ji) != SMG_OK || !ji.name) continue;
		if (ji.body_part <= SMG_BODY_UPPER) part[j] = (uint8_t)ji.body_part;
		const char *prof = profile ? profile[j] : NULL;
		int64_t bone = bone_map && prof ? find_mapped_bone(skel, bone_map, prof) : -1;
		if (bone < 0) {
			char bone_name[256];
			smg_gd_bone_name(ji.name, bone_name, sizeof bone_name);
			bone = find_bone(skel, bone_name);
		}
		if (bone < 0 && prof) bone = find_bone(skel, prof);
		if (bone >= 0 && bone <= INT32_MAX) {
			map[j] = (int32_t)bone;
			matched++;
			/* A rig whose bones have their own rest orientation (not the
			 * graph's world-aligned rest) gets its rotations conjugated in
			 * smg_gd_bone_map_write_pose. */
			int64_t parent = -1;
			const void *pa[1] = { &bone };
			gd_call(GDB_Skeleton3D_get_bone_parent, skel, pa, &parent);
			bone_global_rest(skel, bone, &rest[8 * j]);
			bone_global_rest(skel, parent, &rest[8 * j + 4]);
			for (int k = 0; k < 8; k++)
				if (fabsf(rest[8 * j + k] - (k % 4 == 3 ? 1.0f : 0.0f)) > 1e-6f) m->rests_identity = false;
		}
	}
	free(profile);
	if (matched < n && !m->warned) {
		m->warned = true;
		GD_WARN("SmgCharacter: %u of %u graph joints have no bone in the skeleton (by BoneMap, name or "
		        "humanoid profile name); they are not animated", n - matched, n);
	}
}

/* The mask's weight of joint j (mapped to `bone`). */
static float joint_weight(const smg_gd_bone_map *m, const smg_gd_mask *mask, GDExtensionObjectPtr skel, uint32_t j,
	int64_t bone) {
	if (!mask) return 1.0f;
	for (uint32_t k = 0; k < mask->count; k++) {
		gd_string name;
		gd_str_init(&name, mask->bones[k]);
		int64_t b = -1;
		const void *a[1] = { &name };
		gd_call(GDB_Skeleton3D_find_bone, skel, a, &b);
		gd_str_destroy(&name);
		if (b == bone) return mask->weights[k];
	}
	return mask->part[m->part_of_joint[j]];
}

void smg_gd_bone_map_write_pose(smg_gd_bone_map *m, const smg_graph *graph, const smg_character *ch,
	GDExtensionObjectPtr skel, const smg_gd_mask *mask) {
	smg_character_state st;
	memset(&st, 0, sizeof st);
	st.struct_size = sizeof st;
	if (!m->rot || smg_character_get_state(ch, &st) != SMG_OK) return;
	match_bones(m, graph, skel);
	if (!m->bone_of_joint) return;
	uint32_t n = m->joint_count;
	float root[3];
	if (smg_character_get_local_pose(ch, root, m->rot, n) != SMG_OK) return;

	/* Joint 0 comes in parent space; the character node already carries
	 * (position with the ground height, heading), so express the root
	 * relative to it. */
	float h = st.heading, c = cosf(h), s = sinf(h);
	float dx = root[0] - st.position[0], dz = root[2] - st.position[2];
	gd_vec3 root_local = { c * dx - s * dz, root[1] - st.position[1], s * dx + c * dz };
	float inv_yaw[4];
	smgi_q_yaw(-h, inv_yaw);
	smgi_q_mul(inv_yaw, &m->rot[0], &m->rot[0]);

	for (uint32_t j = 0; j < n; j++) {
		int64_t bone = m->bone_of_joint[j];
		if (bone < 0) continue;
		if (!m->rests_identity) {
			/* graph rotations are relative to a world-aligned rest: bone
			 * pose = parent bone's global rest^-1 * q * bone's global rest */
			const float *r = &m->rest_of_joint[8 * j];
			float parent_inv[4], t[4];
			smgi_q_conj(&r[4], parent_inv);
			smgi_q_mul(&m->rot[4 * j], r, t);
			smgi_q_mul(parent_inv, t, &m->rot[4 * j]);
		}
		float w = joint_weight(m, mask, skel, j, bone);
		if (!(w > 0.0f)) continue; /* the skeleton's own pose stays */
		const void *ba[1] = { &bone };
		if (w < 1.0f) {
			/* blend from the pose already there (rest, or what an
			 * AnimationTree wrote before the modifier stage) */
			gd_quat cur = { 0, 0, 0, 1 };
			gd_call(GDB_Skeleton3D_get_bone_pose_rotation, skel, ba, &cur);
			float c4[4] = { cur.x, cur.y, cur.z, cur.w };
			smgi_q_nlerp(c4, &m->rot[4 * j], w, &m->rot[4 * j]);
		}
		const void *a[2] = { &bone, &m->rot[4 * j] };
		gd_call(GDB_Skeleton3D_set_bone_pose_rotation, skel, a, NULL);
		if (j == 0) {
			gd_vec3 pos = root_local;
			if (w < 1.0f) {
				gd_vec3 cur = { 0, 0, 0 };
				gd_call(GDB_Skeleton3D_get_bone_pose_position, skel, ba, &cur);
				pos = (gd_vec3){ cur.x + w * (pos.x - cur.x), cur.y + w * (pos.y - cur.y), cur.z + w * (pos.z - cur.z) };
			}
			const void *p[2] = { &bone, &pos };
			gd_call(GDB_Skeleton3D_set_bone_pose_position, skel, p, NULL);
		}
	}
}
