#include "vtkpasses/render/SurfaceShaderMaterial.h"

#include "aniso_shaders.h"
#include "core/error.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/ShaderHook.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <vtkActor.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkShaderProgram.h>

namespace aniso
{
namespace
{
constexpr const char* kFrameMarker = "//LEADR_FRAME";
} // namespace

void validateShaderLights(const std::vector<Light>& lights)
{
  if (lights.size() > std::size_t(kMaxShaderLights))
  {
    throw errorAbout("light", "at most " + std::to_string(kMaxShaderLights) + " lights (got " +
                                  std::to_string(lights.size()) + ")");
  }
  for (const Light& light : lights)
  {
    validateLight(light);
  }
}

class SurfaceShaderMaterial::Impl
{
public:
  std::string name;
  std::vector<Light> lights;
  std::vector<Light> environmentLights; // directional, environment coordinates
  SurfaceShaderMaterial* owner = nullptr;
  ShaderHook hook;

  // The code is the same for every mesh that has the arrays: install it once.
  void onMesh(vtkPolyData* poly)
  {
    if (hook.installed() || poly->GetNumberOfPoints() == 0)
    {
      return;
    }
    if (!meshArraysOf(poly).all())
    {
      vtkGenericWarningMacro(<< name
                             << ": the mesh needs Normals, Tangents and TCoords; drawn unshaded");
      return;
    }
    std::string implementation = owner->fragmentImplementation();
    const std::size_t at = implementation.find(kFrameMarker);
    if (at != std::string::npos)
    {
      implementation.replace(at, std::string(kFrameMarker).size(), shaders::kLeadrFsFrame);
    }
    ShaderCode code;
    code.vertex = {{tags::kVertexDec, shaders::kLeadrVsDec},
                   {tags::kVertexImpl, shaders::kLeadrVsImpl}};
    code.fragment = {
        {tags::kFragmentDec, std::string(shaders::kLeadrFsLights) + owner->fragmentDeclarations()},
        {tags::kFragmentUniformFlow, shaders::kLeadrFsUniformFlow},
        {tags::kFragmentImpl, implementation}};
    code.attributes = meshAttributes("leadr", {true, true, true});
    code.uniform = "leadrClipToWorld";
    code.discardFrozenPixels = true;
    hook.install(code);
  }

  void onShader(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    hook.setTransforms(program, "leadr");
    // Point lights move with the surface into the frame it is drawn in (DrawingFrame.h).
    const DrawingFrame drawing = drawingFrame(hook.actor());
    std::vector<float> vectors;     // 4 per light
    std::vector<float> intensities; // 3 per light
    std::vector<Light> drawn = lights;
    if (!environmentLights.empty())
    {
      // R_z(+angle): the inverse of the lighting's world-to-environment rotation.
      const glm::dmat3 toWorld = glm::transpose(owner->lighting().worldToEnvironment());
      for (Light light : environmentLights)
      {
        light.vector = toWorld * light.vector;
        drawn.push_back(light);
      }
    }
    for (const Light& given : drawn)
    {
      const Light light = drawing.lightToDrawing(given);
      const bool point = light.type == LightType::Point;
      const glm::dvec3 v = point ? light.vector : glm::normalize(light.vector);
      vectors.insert(vectors.end(), {float(v.x), float(v.y), float(v.z), point ? 1.0f : 0.0f});
      intensities.insert(intensities.end(), {float(light.intensity.x), float(light.intensity.y),
                                             float(light.intensity.z)});
    }
    const int count = static_cast<int>(drawn.size());
    program->SetUniformi("leadrLightCount", count);
    if (count > 0)
    {
      program->SetUniform4fv("leadrLightVector", count, vectors.data());
      program->SetUniform3fv("leadrLightIntensity", count, intensities.data());
    }
    owner->setModelUniforms(program, window);
  }
};

SurfaceShaderMaterial::SurfaceShaderMaterial(std::shared_ptr<EnvironmentLighting> lighting,
                                             std::string name)
    : impl_(std::make_unique<Impl>()), lighting_(std::move(lighting))
{
  if (!lighting_)
  {
    throw errorAbout("environment", "a material needs lighting");
  }
  impl_->name = std::move(name);
  impl_->owner = this;
}

SurfaceShaderMaterial::~SurfaceShaderMaterial()
{
  impl_->hook.detach();
}

void SurfaceShaderMaterial::apply(vtkActor* actor, vtkRenderer* renderer)
{
  auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (vtkPolyData* poly = mapper ? mapper->GetInput() : nullptr)
  {
    if (poly->GetNumberOfPoints() > 0 && !meshArraysOf(poly).all())
    {
      throw errorAbout("mesh", impl_->name + " needs normals, tangents and texture coordinates");
    }
  }
  impl_->hook.attach(actor, renderer, impl_.get());
}

void SurfaceShaderMaterial::detach()
{
  impl_->hook.detach();
}

void SurfaceShaderMaterial::setLights(const std::vector<Light>& lights)
{
  validateShaderLights(lights);
  impl_->lights = lights;
  changed();
}

void SurfaceShaderMaterial::setEnvironmentLights(const std::vector<Light>& lights)
{
  std::vector<Light> all = impl_->lights;
  for (const Light& light : lights)
  {
    if (light.type != LightType::Directional)
    {
      throw errorAbout("light", "an environment light is directional");
    }
    all.push_back(light);
  }
  validateShaderLights(all);
  impl_->environmentLights = lights;
  changed();
}

void SurfaceShaderMaterial::bindTexture(vtkShaderProgram* program, const char* sampler,
                                        vtkTextureObject* texture)
{
  impl_->hook.bindTexture(program, sampler, texture);
}

vtkRenderer* SurfaceShaderMaterial::renderer() const
{
  return impl_->hook.renderer();
}

void SurfaceShaderMaterial::changed()
{
  impl_->hook.changed();
}
} // namespace aniso
