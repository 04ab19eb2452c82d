// gl_api.h - the few OpenGL 3.3 core entry points the demo uses, loaded at
// run time through SDL_GL_GetProcAddress (no GL loader library needed).
//
// The pointers live in namespace demo_gl so they never clash with (or
// interpose on) the C symbols that libGL itself exports. Rendering files
// say `using namespace demo_gl;` and then call glClear(...) as usual.
#pragma once

#include <GL/glcorearb.h>

#include <string>

#define DEMO_GL_FUNCTIONS(X)                                              \
  X(PFNGLCLEARPROC, glClear)                                              \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                    \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                                \
  X(PFNGLVIEWPORTPROC, glViewport)                                        \
  X(PFNGLENABLEPROC, glEnable)                                            \
  X(PFNGLDISABLEPROC, glDisable)                                          \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                      \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                      \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                      \
  X(PFNGLCOLORMASKPROC, glColorMask)                                      \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                                  \
  X(PFNGLSTENCILOPPROC, glStencilOp)                                      \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                                  \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                              \
  X(PFNGLCULLFACEPROC, glCullFace)                                        \
  X(PFNGLGETSTRINGPROC, glGetString)                                      \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                  \
  X(PFNGLGETERRORPROC, glGetError)                                        \
  X(PFNGLFINISHPROC, glFinish)                                            \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                    \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                    \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                  \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                              \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                  \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                        \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                              \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                  \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                      \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                              \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                    \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                    \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                      \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                      \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                    \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                    \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                        \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                          \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                          \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                    \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                    \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                    \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                    \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                              \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                  \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)          \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)                  \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer)                \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                  \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                            \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                  \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                              \
  X(PFNGLTEXBUFFERPROC, glTexBuffer)                                      \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                    \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)              \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                          \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                          \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                    \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)          \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)            \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                        \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                        \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                  \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)

namespace demo_gl {
#define DEMO_GL_DECLARE(type, name) extern type name;
DEMO_GL_FUNCTIONS(DEMO_GL_DECLARE)
#undef DEMO_GL_DECLARE
}  // namespace demo_gl

// Loads every pointer above from the current context. Returns false and
// names the first missing function in *error. Call after the GL context is
// current.
bool demo_gl_load(std::string* error);

// Parses GL_VERSION of the current context ("4.5 (Core Profile) Mesa ...")
// into major/minor; false if it cannot be read.
bool demo_gl_version(int* major, int* minor);
