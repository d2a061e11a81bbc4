#pragma once
// What the renderer needs of an OpenGL context, checked once the context exists: OpenGL 3.2 or
// later (VTK 9.1's polydata shaders) and float colour render targets (the progressive
// accumulation's RGBA32F mean). Without them, one clear error instead of VTK's messages, black
// images or a crash later.
class vtkOpenGLRenderWindow;

namespace aniso
{
// Throws aniso::Error "OpenGL: reason" (the version and renderer found, what is needed, what
// to try) unless WINDOW's context (made current here) has what the renderer needs.
void requireRenderCapabilities(vtkOpenGLRenderWindow* window);
} // namespace aniso
