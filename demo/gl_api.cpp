// gl_api.cpp - loads the demo's OpenGL entry points through SDL.
#include "gl_api.h"

#include <SDL.h>

#include <cstdio>

namespace demo_gl {
#define DEMO_GL_DEFINE(type, name) type name = nullptr;
DEMO_GL_FUNCTIONS(DEMO_GL_DEFINE)
#undef DEMO_GL_DEFINE
}  // namespace demo_gl

bool demo_gl_load(std::string* error) {
#define DEMO_GL_LOAD(type, name)                                           \
  demo_gl::name = reinterpret_cast<type>(SDL_GL_GetProcAddress(#name));    \
  if (!demo_gl::name) {                                                    \
    *error = std::string("OpenGL function ") + #name + " is not available"; \
    return false;                                                          \
  }
  DEMO_GL_FUNCTIONS(DEMO_GL_LOAD)
#undef DEMO_GL_LOAD
  return true;
}

bool demo_gl_version(int* major, int* minor) {
  const GLubyte* v = demo_gl::glGetString(GL_VERSION);
  if (!v) return false;
  return std::sscanf(reinterpret_cast<const char*>(v), "%d.%d", major, minor) == 2;
}
