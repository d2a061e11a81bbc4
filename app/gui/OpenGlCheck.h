#pragma once
// What the window needs of OpenGL, checked once at start before any VTK window exists: a context
// of the format QVTKOpenGLNativeWidget asks for, OpenGL 3.2 or later (VTK 9.1's renderers), and
// float colour render targets (the progressive accumulation draws into RGBA32F). A machine
// without them gets one clear message instead of VTK's errors or a crash later.
#include <string>

namespace aniso
{
// Empty when the default surface format's context has what the window needs, else the reason
// in one sentence (the version and renderer found, what is needed, what to try). Needs a
// QGuiApplication.
std::string openGlShortcoming();
} // namespace aniso
