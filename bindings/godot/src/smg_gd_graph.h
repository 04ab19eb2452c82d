/* smg_gd_graph.h - SmgGraph, a Resource holding one loaded libsmg graph. */
#ifndef SMG_GD_GRAPH_H
#define SMG_GD_GRAPH_H

#include "gd_api.h"
#include "smg.h"

/* A loaded graph and the blob bytes it lives in, shared by reference count
 * between the SmgGraph resource and every character created on it. This is
 * what makes "free in any order" and "reload while characters run" safe:
 * libsmg refuses to destroy a graph with live characters (SMG_ERROR_IN_USE),
 * so the graph is destroyed only when the last holder lets go, and every
 * holder destroys its characters before letting go. */
typedef struct smg_gd_blob {
	smg_graph *graph;
	void *alloc; /* holds the blob bytes the graph uses in place
	              * (64-byte aligned inside) */
	uint32_t refs;
	uint32_t joint_count;
} smg_gd_blob;

smg_gd_blob *smg_gd_blob_retain(smg_gd_blob *b);
void smg_gd_blob_release(smg_gd_blob *b);

typedef struct smg_gd_graph smg_gd_graph;

void smg_gd_graph_register(void);
void smg_gd_graph_unregister(void);

/* The SmgGraph behind a Godot object, or NULL if obj is not an SmgGraph. */
smg_gd_graph *smg_gd_graph_from_object(GDExtensionObjectPtr obj);
/* The graph currently loaded (borrowed; NULL when nothing is loaded). */
smg_gd_blob *smg_gd_graph_blob(const smg_gd_graph *g);

/* Loads path into g (see SmgGraph.load); returns a Godot Error code. */
int64_t smg_gd_graph_load(smg_gd_graph *g, const char *path);

/* A new Skeleton3D matching the graph's joints (names, parents, rest
 * offsets), or NULL with a Godot error. The caller owns the node. */
GDExtensionObjectPtr smg_gd_graph_build_skeleton(smg_gd_graph *g);

/* The Skeleton3D bone name of a graph joint: Godot rejects ':' and '/' in
 * bone names and its importers write '_' instead ("mixamorig:Hips" ->
 * "mixamorig_Hips"), so both build_skeleton and the character's bone lookup
 * use this spelling. */
static inline void smg_gd_bone_name(const char *joint, char *out, size_t size) {
	size_t i = 0;
	if (!size) return;
	for (; joint && joint[i] && i + 1 < size; i++)
		out[i] = (joint[i] == ':' || joint[i] == '/') ? '_' : joint[i];
	out[i] = '\0';
}

#endif
