// offscreen.h - a multisampled framebuffer of exactly the requested size,
// for headless screenshots that do not depend on the window or screen.
#pragma once

#include <string>

class Offscreen {
 public:
  bool create(int width, int height, std::string* error);
  void destroy();
  void bind();      // render into the multisampled buffer
  void resolve();   // resolve into the single-sample buffer and bind it for reading
 private:
  unsigned ms_fbo_ = 0, ms_colour_ = 0, ms_depth_ = 0;
  unsigned fbo_ = 0, colour_ = 0;
  int width_ = 0, height_ = 0;
};
