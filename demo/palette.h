// palette.h - colours that carry meaning in the demo (as in the paper's
// Fig. 4): locomotion styles colour the path and the lower body (walk blue,
// run red), upper-body actions colour the splice markers and the upper body
// (punch green). Unknown names get distinct colours from a fixed palette.
#pragma once

#include <glm/glm.hpp>

glm::vec3 style_colour(const char* name, unsigned index);
glm::vec3 action_colour(const char* name, unsigned index);

// Fixed colours of things that are not styles or actions. The smoke test's
// PNG checker looks for kSkinColour (the character's joints and head), so
// nothing else in the scene uses a warm colour like it.
extern const glm::vec3 kSkinColour;
extern const glm::vec3 kSkyColour;
