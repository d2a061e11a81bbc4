#pragma once
// What a material that shades a vtkActor through shader replacements does the same way
// whatever it computes: it observes the actor's OpenGL mapper (for the mesh about to be drawn,
// and for every shader update, where uniforms and textures are set), inserts its GLSL after
// VTK's tags (keeping each tag, so VTK's code and later replacements still apply) and maps the
// mesh's point arrays to vertex attributes. Detaching removes all of it. Not a vtkObject.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace aniso
{
struct ShaderCode
{
  // (tag, code inserted after it), e.g. {"//VTK::Light::Impl", "..."}.
  std::vector<std::pair<std::string, std::string>> vertex;
  std::vector<std::pair<std::string, std::string>> fragment;
  // (vertex attribute, point array) pairs the code reads.
  std::vector<std::pair<std::string, std::string>> attributes;
};

class ShaderHook
{
public:
  // Called with the mapper's input once it is known (at attach if it has points, and after
  // each draw), so the caller can install the variant the mesh needs.
  using MeshCallback = std::function<void(vtkPolyData*)>;
  // Called with the shader program before each draw: set uniforms and bind textures here.
  // Exceptions are caught and reported as a VTK warning (they must not unwind through VTK).
  using ShaderCallback = std::function<void(vtkShaderProgram*)>;

  ShaderHook();
  ~ShaderHook();
  ShaderHook(const ShaderHook&) = delete;
  ShaderHook& operator=(const ShaderHook&) = delete;

  // Hooks ACTOR drawn by RENDERER (detaching from any previous actor first). The actor's mapper
  // must be a vtkOpenGLPolyDataMapper; aniso::Error "material: reason" otherwise.
  void attach(vtkActor* actor, vtkRenderer* renderer, MeshCallback onMesh, ShaderCallback onShader);
  void detach();

  // Activates TEXTURE for the coming draw and points SAMPLER at its unit (call from the shader
  // callback). The unit is freed once the renderer has drawn, as vtkOpenGLTexture::PostRender
  // does for VTK's own textures: no texture stays active between frames or after detaching.
  void bindTexture(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture);

  // Replaces the installed code (if any) by CODE on the attached actor.
  void install(const ShaderCode& code);

  vtkActor* actor() const;
  vtkRenderer* renderer() const;

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace aniso
