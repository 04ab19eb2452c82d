// offscreen.cpp - framebuffer objects for headless rendering.
#include "offscreen.h"

#include "gl_api.h"

#include <algorithm>

using namespace demo_gl;

bool Offscreen::create(int width, int height, std::string* error) {
  width_ = width;
  height_ = height;
  GLint max_samples = 0, max_size = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width > max_size || height > max_size) {
    *error = "screenshot size " + std::to_string(width) + "x" + std::to_string(height) +
             " exceeds this OpenGL's limit of " + std::to_string(max_size);
    return false;
  }
  int samples = std::min(4, int(max_samples));
  glGenRenderbuffers(1, &ms_colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, ms_colour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &ms_depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, ms_depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
  glGenFramebuffers(1, &ms_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ms_depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    *error = "cannot create the multisampled offscreen framebuffer";
    return false;
  }
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, width, height);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    *error = "cannot create the offscreen resolve framebuffer";
    return false;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return glGetError() == GL_NO_ERROR || (*error = "OpenGL error creating offscreen buffers", false);
}

void Offscreen::destroy() {
  glDeleteFramebuffers(1, &ms_fbo_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &ms_colour_);
  glDeleteRenderbuffers(1, &ms_depth_);
  glDeleteRenderbuffers(1, &colour_);
  ms_fbo_ = fbo_ = ms_colour_ = ms_depth_ = colour_ = 0;
}

void Offscreen::bind() { glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo_); }

void Offscreen::resolve() {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
}
