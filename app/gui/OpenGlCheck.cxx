#include "app/gui/OpenGlCheck.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>

namespace aniso
{
namespace
{
constexpr int kMajor = 3;
constexpr int kMinor = 2;
constexpr unsigned int kRgba32f = 0x8814; // GL_RGBA32F

std::string versionText(const QSurfaceFormat& format)
{
  return std::to_string(format.majorVersion()) + "." + std::to_string(format.minorVersion());
}

const char* kHint = "a newer graphics driver, or Mesa's software renderer "
                    "(LIBGL_ALWAYS_SOFTWARE=1, without MESA_GL_VERSION_OVERRIDE)";
} // namespace

std::string openGlShortcoming()
{
  QOffscreenSurface surface;
  surface.setFormat(QSurfaceFormat::defaultFormat());
  surface.create();
  QOpenGLContext context;
  context.setFormat(QSurfaceFormat::defaultFormat());
  if (!context.create() || !surface.isValid() || !context.makeCurrent(&surface))
  {
    return "no OpenGL " + std::to_string(kMajor) + "." + std::to_string(kMinor) +
           " context could be made on this display; try " + kHint;
  }
  const QSurfaceFormat format = context.format();
  QOpenGLFunctions* gl = context.functions();
  const auto* renderer = reinterpret_cast<const char*>(gl->glGetString(0x1F01)); // GL_RENDERER
  const std::string found =
      "OpenGL " + versionText(format) + " (" + (renderer ? renderer : "unknown renderer") + ")";
  std::string shortcoming;
  if (format.majorVersion() < kMajor ||
      (format.majorVersion() == kMajor && format.minorVersion() < kMinor))
  {
    shortcoming = "this display offers " + found + "; aniso needs OpenGL " +
                  std::to_string(kMajor) + "." + std::to_string(kMinor) +
                  " or later with float render targets; try " + kHint;
  }
  else
  {
    QOpenGLFramebufferObjectFormat target;
    target.setInternalTextureFormat(kRgba32f);
    QOpenGLFramebufferObject fbo(4, 4, target);
    if (!fbo.isValid())
    {
      shortcoming = "this display's " + found +
                    " cannot render into float (RGBA32F) targets, which the progressive "
                    "accumulation needs; try " +
                    kHint;
    }
  }
  context.doneCurrent();
  return shortcoming;
}
} // namespace aniso
