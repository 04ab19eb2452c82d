// palette.cpp - meaning-carrying colours.
#include "palette.h"

#include <cctype>
#include <string>

const glm::vec3 kSkinColour(0.93f, 0.80f, 0.62f);
const glm::vec3 kSkyColour(0.74f, 0.80f, 0.87f);

static std::string lower(const char* s) {
  std::string out;
  for (; s && *s; ++s) out += char(std::tolower((unsigned char)*s));
  return out;
}

static bool has(const std::string& s, const char* word) { return s.find(word) != std::string::npos; }

// Cold, saturated hues that never look like skin and never like each other.
static const glm::vec3 kExtra[] = {
    {0.58f, 0.30f, 0.85f}, {0.05f, 0.65f, 0.70f}, {0.85f, 0.25f, 0.60f},
    {0.35f, 0.35f, 0.75f}, {0.10f, 0.50f, 0.35f}, {0.60f, 0.15f, 0.30f},
};

glm::vec3 style_colour(const char* name, unsigned index) {
  std::string n = lower(name);
  if (has(n, "walk")) return {0.16f, 0.42f, 0.90f};
  if (has(n, "run") || has(n, "jog")) return {0.88f, 0.16f, 0.14f};
  return kExtra[index % (sizeof kExtra / sizeof kExtra[0])];
}

glm::vec3 action_colour(const char* name, unsigned index) {
  std::string n = lower(name);
  if (index == 0 || n == "none") return {0.55f, 0.57f, 0.62f};
  if (has(n, "punch") || has(n, "box") || has(n, "strike")) return {0.12f, 0.70f, 0.22f};
  if (has(n, "dribble") || has(n, "ball")) return {0.95f, 0.45f, 0.05f};
  if (has(n, "wash")) return {0.10f, 0.70f, 0.75f};
  if (has(n, "scoop") || has(n, "lift") || has(n, "bend")) return {0.70f, 0.20f, 0.70f};
  return kExtra[(index + 3) % (sizeof kExtra / sizeof kExtra[0])];
}
