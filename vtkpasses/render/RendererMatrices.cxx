#include "vtkpasses/render/RendererMatrices.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>

namespace aniso
{
glm::dmat4 toGlm(vtkMatrix4x4* matrix)
{
  glm::dmat4 m(1.0);
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      m[column][row] = matrix->GetElement(row, column);
    }
  }
  return m;
}

glm::dmat4 worldToClip(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  return toGlm(
      camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
}

bool setUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& m)
{
  glm::mat4 f(m);
  return program->SetUniformMatrix4x4(name, glm::value_ptr(f));
}

bool setUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat3& m)
{
  glm::mat3 f(m);
  return program->SetUniformMatrix3x3(name, glm::value_ptr(f));
}

glm::dmat4 clipToWorld(vtkRenderer* renderer)
{
  return glm::inverse(worldToClip(renderer));
}
} // namespace aniso
