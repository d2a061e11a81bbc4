#pragma once
// The camera transforms VTK's OpenGL mappers use, for shaders that reconstruct view rays.
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

class vtkMatrix4x4;
class vtkRenderer;
class vtkShaderProgram;

namespace aniso
{
// World to clip coordinates of RENDERER's active camera at the renderer's tiled aspect ratio,
// z in [-1, 1]: the matrix VTK's mappers draw with (vtkOpenGLCamera::GetKeyMatrices).
glm::dmat4 worldToClip(vtkRenderer* renderer);
// Its inverse: clip coordinates to homogeneous world coordinates.
glm::dmat4 clipToWorld(vtkRenderer* renderer);

glm::dmat4 toGlm(vtkMatrix4x4* matrix);

// Uploads a matrix uniform (as float, column-major as GLSL reads it); false if the program
// has no such uniform.
bool setUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& m);
bool setUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat3& m);
} // namespace aniso
