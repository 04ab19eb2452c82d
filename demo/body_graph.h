// body_graph.h - the skeleton of a loaded graph as the generated body
// (body.h) needs it: parents, rest offsets and upper-body flags from
// smg_graph_get_joint, nothing from joint names, and the bind pose: the rest
// pose when it stands upright like the motion does (T- or A-pose rigs),
// otherwise a new character's first pose (rigs whose rest offsets live in
// rotated joint frames, whose identity pose is no human posture).
#pragma once

#include "body.h"
#include "smg.h"

#include <string>

bool body_skeleton_from_graph(smg_graph* graph, BodySkeleton* out, std::string* error);

// Whether the rest pose of `skeleton` stands like `first_pose` (16 floats
// per joint, character-space model matrices): about as tall, and the joint
// heights correlated.
bool body_rest_is_upright(const BodySkeleton& skeleton, const float* first_pose);
