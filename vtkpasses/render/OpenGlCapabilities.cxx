#include "vtkpasses/render/OpenGlCapabilities.h"

#include "core/error.h"

#include <string>
#include <vtkOpenGLRenderWindow.h>
#include <vtk_glew.h>

namespace aniso
{
namespace
{
constexpr int kMajor = 3;
constexpr int kMinor = 2;
constexpr const char* kHint =
    "a newer graphics driver, or Mesa's software renderer (LIBGL_ALWAYS_SOFTWARE=1, without "
    "MESA_GL_VERSION_OVERRIDE)";

// Whether a 4 x 4 RGBA32F texture can be a complete framebuffer's colour attachment. The
// bindings it changes are put back.
bool floatTargets()
{
  GLint previousFramebuffer = 0;
  GLint previousTexture = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFramebuffer);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
  GLuint texture = 0;
  GLuint framebuffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 4, 4, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previousTexture));
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
  while (glGetError() != GL_NO_ERROR)
  {
  }
  return complete;
}
} // namespace

void requireRenderCapabilities(vtkOpenGLRenderWindow* window)
{
  window->MakeCurrent();
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  GLint major = 0;
  GLint minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const std::string found = std::string("OpenGL ") + (version ? version : "of unknown version") +
                            " (" + (renderer ? renderer : "unknown renderer") + ")";
  if (major < kMajor || (major == kMajor && minor < kMinor))
  {
    throw errorAbout("OpenGL", "this display offers " + found + "; aniso needs OpenGL " +
                                   std::to_string(kMajor) + "." + std::to_string(kMinor) +
                                   " or later with float render targets; try " + kHint);
  }
  if (!floatTargets())
  {
    throw errorAbout("OpenGL", "this display's " + found +
                                   " cannot render into float (RGBA32F) targets, which the "
                                   "progressive accumulation needs; try " +
                                   kHint);
  }
}
} // namespace aniso
