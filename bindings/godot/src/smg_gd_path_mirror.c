/* smg_gd_path_mirror.c - the path and transition/splice points an
 * SmgCharacter gave libsmg, kept to replay them on a rebuilt character
 * (see smg_gd_path_mirror.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smg_gd_path_mirror.h"

void smg_gd_mirror_free(smg_gd_path_mirror *m) {
	free(m->path_xz);
	free(m->cons);
	memset(m, 0, sizeof *m);
}

int64_t smg_gd_error_of(smg_result r) {
	switch (r) {
	case SMG_OK: return GD_OK;
	case SMG_ERROR_INVALID_ARGUMENT: return GD_ERR_INVALID_PARAMETER;
	case SMG_ERROR_OUT_OF_MEMORY: return GD_ERR_OUT_OF_MEMORY;
	case SMG_ERROR_OUT_OF_RANGE:
	case SMG_ERROR_UNKNOWN_STYLE:
	case SMG_ERROR_UNKNOWN_ACTION: return GD_ERR_PARAMETER_RANGE_ERROR;
	case SMG_ERROR_CAPACITY: return GD_ERR_OUT_OF_MEMORY;
	case SMG_ERROR_NOT_FOUND: return GD_ERR_DOES_NOT_EXIST;
	default: return GD_FAILED;
	}
}

static smg_result add_to(smg_character *ch, const smg_gd_constraint *c, uint32_t *smg_id) {
	return c->kind == SMG_GD_TRANSITION ? smg_character_add_transition(ch, c->distance, c->value, smg_id)
	                                    : smg_character_add_splice(ch, c->distance, c->value, smg_id);
}

void smg_gd_mirror_replay(smg_gd_path_mirror *m, smg_character *ch) {
	if (m->path_count > 0) {
		smg_result r = smg_character_set_path(ch, m->path_xz, m->path_count);
		if (r != SMG_OK) GD_ERR("SmgCharacter: path rejected by the new graph: %s", smg_result_string(r));
	}
	for (uint32_t i = 0; i < m->con_count; i++) {
		smg_gd_constraint *c = &m->cons[i];
		smg_result r = add_to(ch, c, &c->smg_id);
		if (r != SMG_OK) {
			GD_WARN("SmgCharacter: constraint %lld dropped after the graph changed: %s", (long long)c->id,
				smg_result_string(r));
			m->cons[i--] = m->cons[--m->con_count];
		}
	}
}

/* Points (x, z) from a PackedVector3Array (y ignored: the ground plane);
 * NULL with a Godot error when there are too many or one is not finite. */
static float *points_xz(const gd_packed *pts, uint32_t *count, const char *what) {
	int64_t n = gd_packed_v3_size(pts);
	*count = 0;
	if (n <= 0) return NULL;
	if (n > SMG_GD_PATH_CAPACITY) {
		GD_ERR("SmgCharacter.%s: %lld points, at most %u", what, (long long)n, SMG_GD_PATH_CAPACITY);
		return NULL;
	}
	float *xz = malloc((size_t)n * 2 * sizeof(float));
	if (!xz) return NULL;
	for (int64_t i = 0; i < n; i++) {
		const gd_vec3 *p = gd_packed_v3_at(pts, i);
		if (!p || !isfinite(p->x) || !isfinite(p->z)) {
			GD_ERR("SmgCharacter.%s: point %lld is not finite", what, (long long)i);
			free(xz);
			return NULL;
		}
		xz[2 * i] = p->x;
		xz[2 * i + 1] = p->z;
	}
	*count = (uint32_t)n;
	return xz;
}

static bool reserve_path(smg_gd_path_mirror *m, uint32_t n) {
	if (n <= m->path_cap) return true;
	uint32_t cap = m->path_cap ? m->path_cap : 64;
	while (cap < n) cap *= 2;
	float *p = realloc(m->path_xz, (size_t)cap * 2 * sizeof(float));
	if (!p) return false;
	m->path_xz = p;
	m->path_cap = cap;
	return true;
}

int64_t smg_gd_mirror_set_path(smg_gd_path_mirror *m, smg_character *ch, const gd_packed *points,
	const char *what) {
	uint32_t n;
	float *xz = points_xz(points, &n, what);
	if (!xz) return GD_ERR_INVALID_PARAMETER;
	smg_result r = smg_character_set_path(ch, xz, n);
	if (r != SMG_OK || !reserve_path(m, n)) {
		free(xz);
		if (r != SMG_OK) GD_ERR("SmgCharacter.%s: %s", what, smg_result_string(r));
		return r != SMG_OK ? smg_gd_error_of(r) : GD_ERR_OUT_OF_MEMORY;
	}
	memcpy(m->path_xz, xz, (size_t)n * 2 * sizeof(float));
	m->path_count = n;
	free(xz);
	return GD_OK;
}

int64_t smg_gd_mirror_append_path(smg_gd_path_mirror *m, smg_character *ch, const gd_packed *points) {
	uint32_t n;
	float *xz = points_xz(points, &n, "append_path_points");
	if (!xz) return GD_ERR_INVALID_PARAMETER;
	smg_result r = m->path_count == 0 ? smg_character_set_path(ch, xz, n) : smg_character_append_path(ch, xz, n);
	int64_t err = GD_OK;
	if (r == SMG_OK && reserve_path(m, m->path_count + n)) {
		memcpy(m->path_xz + 2 * (size_t)m->path_count, xz, (size_t)n * 2 * sizeof(float));
		m->path_count += n;
	} else {
		if (r != SMG_OK) GD_ERR("SmgCharacter.append_path_points: %s", smg_result_string(r));
		err = r != SMG_OK ? smg_gd_error_of(r) : GD_ERR_OUT_OF_MEMORY;
	}
	free(xz);
	return err;
}

int64_t smg_gd_mirror_clear_path(smg_gd_path_mirror *m, smg_character *ch) {
	smg_result r = smg_character_clear_path(ch);
	if (r == SMG_OK) m->path_count = 0;
	else GD_ERR("SmgCharacter.clear_path: %s", smg_result_string(r));
	return smg_gd_error_of(r);
}

static smg_gd_constraint *find(smg_gd_path_mirror *m, int64_t id) {
	for (uint32_t i = 0; i < m->con_count; i++)
		if (m->cons[i].id == id) return &m->cons[i];
	return NULL;
}

int64_t smg_gd_mirror_add(smg_gd_path_mirror *m, smg_character *ch, smg_gd_constraint_kind kind, double distance,
	int64_t value, const char *what) {
	if (!isfinite(distance) || distance < 0.0 || value < 0 || value > UINT32_MAX) {
		GD_ERR("SmgCharacter.%s: bad distance %g or index %lld", what, distance, (long long)value);
		return -1;
	}
	if (m->con_count == m->con_cap) {
		uint32_t cap = m->con_cap ? m->con_cap * 2 : 8;
		smg_gd_constraint *c = realloc(m->cons, cap * sizeof *c);
		if (!c) return -1;
		m->cons = c;
		m->con_cap = cap;
	}
	smg_gd_constraint c = { m->next_id + 1, kind, (float)distance, (uint32_t)value, 0 };
	smg_result r = add_to(ch, &c, &c.smg_id);
	if (r != SMG_OK) {
		GD_ERR("SmgCharacter.%s(%g, %lld): %s", what, distance, (long long)value, smg_result_string(r));
		return -1;
	}
	m->cons[m->con_count++] = c;
	m->next_id = c.id;
	return c.id;
}

int64_t smg_gd_mirror_move(smg_gd_path_mirror *m, smg_character *ch, int64_t id, double distance) {
	smg_gd_constraint *c = find(m, id);
	if (!c) {
		GD_ERR("SmgCharacter.move_constraint: no constraint with id %lld", (long long)id);
		return GD_ERR_DOES_NOT_EXIST;
	}
	if (!isfinite(distance) || distance < 0.0) {
		GD_ERR("SmgCharacter.move_constraint: bad distance %g", distance);
		return GD_ERR_INVALID_PARAMETER;
	}
	smg_result r = smg_character_move_constraint(ch, c->smg_id, (float)distance);
	if (r == SMG_OK) c->distance = (float)distance;
	else GD_ERR("SmgCharacter.move_constraint: %s", smg_result_string(r));
	return smg_gd_error_of(r);
}

int64_t smg_gd_mirror_remove(smg_gd_path_mirror *m, smg_character *ch, int64_t id) {
	smg_gd_constraint *c = find(m, id);
	if (!c) {
		GD_ERR("SmgCharacter.remove_constraint: no constraint with id %lld", (long long)id);
		return GD_ERR_DOES_NOT_EXIST;
	}
	smg_result r = smg_character_remove_constraint(ch, c->smg_id);
	if (r != SMG_OK) GD_ERR("SmgCharacter.remove_constraint: %s", smg_result_string(r));
	*c = m->cons[--m->con_count]; /* gone from the mirror either way */
	return smg_gd_error_of(r);
}

int64_t smg_gd_mirror_clear_constraints(smg_gd_path_mirror *m, smg_character *ch) {
	smg_result r = smg_character_clear_constraints(ch);
	m->con_count = 0;
	return smg_gd_error_of(r);
}
