// screenshot.cpp - reads the bound framebuffer and writes a PNG.
#include "app.h"
#include "gl_api.h"

#include <stb_image_write.h>

#include <vector>

using namespace demo_gl;

bool save_framebuffer_png(const std::string& path, int width, int height, std::string* error) {
  std::vector<unsigned char> pixels(size_t(width) * size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  if (glGetError() != GL_NO_ERROR) {
    *error = "glReadPixels failed";
    return false;
  }
  // OpenGL rows start at the bottom; PNG rows at the top.
  size_t stride = size_t(width) * 3;
  std::vector<unsigned char> flipped(pixels.size());
  for (int y = 0; y < height; ++y)
    std::copy(pixels.begin() + long(size_t(y) * stride), pixels.begin() + long(size_t(y + 1) * stride),
              flipped.begin() + long(size_t(height - 1 - y) * stride));
  if (!stbi_write_png(path.c_str(), width, height, 3, flipped.data(), int(stride))) {
    *error = "cannot write PNG '" + path + "'";
    return false;
  }
  return true;
}
