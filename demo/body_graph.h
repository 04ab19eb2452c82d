// body_graph.h - the rest skeleton of a loaded graph, as the generated body
// (body.h) needs it: parents, rest offsets and upper-body flags from
// smg_graph_get_joint, nothing from joint names.
#pragma once

#include "body.h"
#include "smg.h"

#include <string>

bool body_skeleton_from_graph(const smg_graph* graph, BodySkeleton* out, std::string* error);
