#include "vtkpasses/render/LitModelMaterial.h"

#include "aniso_shaders.h"
#include "core/error.h"
#include "core/lights/env_lights.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/ShaderHook.h"
#include "vtkpasses/render/TextureUpload.h"

#include <array>
#include <glm/geometric.hpp>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>

namespace aniso
{
namespace
{
const char* modelDefine(LitModel model)
{
  switch (model)
  {
  case LitModel::AshikhminShirley:
    return "LIT_MODEL_ASHIKHMIN_SHIRLEY";
  case LitModel::Banks:
    return "LIT_MODEL_BANKS";
  case LitModel::BlinnPhong:
    return "LIT_MODEL_BLINN_PHONG";
  case LitModel::Ward:
    return "LIT_MODEL_WARD";
  case LitModel::HeidrichSeidel:
    return "LIT_MODEL_HEIDRICH_SEIDEL";
  }
  return "LIT_MODEL_ASHIKHMIN_SHIRLEY";
}

std::shared_ptr<const SvMaps> defaultMaps()
{
  static const auto maps = std::make_shared<const SvMaps>(uniformSvMaps(SvTexel{}));
  return maps;
}
} // namespace

std::string litVariantDefines(const LitModelVariant& v)
{
  std::string d = "#define LIT_MAX_LIGHTS " + std::to_string(LitModelMaterial::kMaxLights) + "\n";
  d += std::string("#define ") + modelDefine(v.model) + "\n";
  if (v.normals)
  {
    d += "#define LIT_HAVE_NORMALS\n";
  }
  if (v.tangents)
  {
    d += "#define LIT_HAVE_TANGENTS\n";
  }
  if (v.tcoords)
  {
    d += "#define LIT_HAVE_TCOORDS\n";
  }
  if (v.lines)
  {
    d += "#define LIT_LINE\n";
  }
  return d;
}

class LitModelMaterial::Impl
{
public:
  LitModelSettings settings;
  LitModelVariant installed; // while hook.installed()
  MeshArrays mesh;

  // The textures and the maps they were made from (held, so new maps at a freed address are
  // never taken for the old ones).
  vtkWeakPointer<vtkOpenGLRenderWindow> textureWindow;
  std::shared_ptr<const SvMaps> uploadedMaps;
  std::array<vtkSmartPointer<vtkTextureObject>, 3> textures;
  // Last, so it lets go of the actor (and the textures it activated) before the rest goes.
  ShaderHook hook;

  void onMesh(vtkPolyData* poly)
  {
    mesh = meshArraysOf(poly);
    updateVariant();
  }

  void updateVariant()
  {
    // A line set's frame is its tangent and the view; its maps are the uniform texel's.
    const bool lines = mesh.lines && mesh.tangents;
    const LitModelVariant v{settings.model, mesh.normals && !lines, mesh.tangents,
                            mesh.tcoords && !lines, lines};
    if (hook.installed() && installed == v)
    {
      return;
    }
    const std::string defines = litVariantDefines(v);
    ShaderCode code;
    code.vertex = {{tags::kVertexDec, defines + shaders::kLitVsDec},
                   {tags::kVertexImpl, shaders::kLitVsImpl}};
    code.fragment = {{tags::kFragmentDec, defines + shaders::kLitFsDec},
                     {tags::kFragmentUniformFlow, shaders::kLitFsUniformFlow},
                     {tags::kFragmentImpl, shaders::kLitFsImpl}};
    if (v.lines)
    {
      code.geometry = lineGeometryCode("lit");
    }
    code.attributes = meshAttributes("lit", {v.normals, v.tangents, v.tcoords});
    code.uniform = "litLightCount";
    code.discardFrozenPixels = true;
    hook.install(code);
    installed = v;
  }

  void updateTextures(vtkOpenGLRenderWindow* window)
  {
    const std::shared_ptr<const SvMaps> maps = settings.maps ? settings.maps : defaultMaps();
    // A texture of handle 0 was released with the window's context: upload them again.
    if (textureWindow == window && uploadedMaps == maps && textures[0] &&
        textures[0]->GetHandle() != 0)
    {
      return;
    }
    textures[0] = uploadMapTexture(window, maps->tangentAlpha, 4, "tangent and roughness map");
    textures[1] = uploadMapTexture(window, maps->albedoSpecular, 4, "albedo and specular map");
    textures[2] = uploadMapTexture(window, maps->normal, 3, "normal map");
    textureWindow = window;
    uploadedMaps = maps;
  }

  // Uniforms and textures, every time the mapper draws: nothing here changes the shader.
  void onShader(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    updateTextures(window);
    hook.setTransforms(program, "lit");

    float vectors[kMaxLights][4] = {};
    float intensities[kMaxLights][3] = {};
    const int count = static_cast<int>(settings.lights.size());
    const DrawingFrame drawing = drawingFrame(hook.actor()); // point lights move with the surface
    for (int i = 0; i < count; ++i)
    {
      const Light light = drawing.lightToDrawing(settings.lights[std::size_t(i)]);
      const bool point = light.type == LightType::Point;
      const glm::dvec3 vector = point ? light.vector : glm::normalize(light.vector);
      for (int c = 0; c < 3; ++c)
      {
        vectors[i][c] = static_cast<float>(vector[c]);
        intensities[i][c] = static_cast<float>(light.intensity[c]);
      }
      vectors[i][3] = point ? 1.0f : 0.0f;
    }
    program->SetUniformi("litLightCount", count);
    program->SetUniform4fv("litLightVector", kMaxLights, vectors);
    program->SetUniform3fv("litLightIntensity", kMaxLights, intensities);

    const char* samplers[3] = {"litTangentAlpha", "litAlbedoSpecular", "litNormalMap"};
    for (std::size_t i = 0; i < textures.size(); ++i)
    {
      hook.bindTexture(program, samplers[i], textures[i]);
    }
  }
};

LitModelMaterial::LitModelMaterial(const LitModelSettings& settings)
    : impl_(std::make_unique<Impl>())
{
  validate(settings);
  impl_->settings = settings;
}

LitModelMaterial::~LitModelMaterial() = default;

void LitModelMaterial::validate(const LitModelSettings& s)
{
  if (s.lights.size() > std::size_t(kMaxLights))
  {
    throw errorAbout("lights", std::to_string(s.lights.size()) + " given, at most " +
                                   std::to_string(kMaxLights));
  }
  for (const Light& light : s.lights)
  {
    validateLight(light);
  }
  if (s.maps)
  {
    sampleSvMaps(*s.maps, {0.0, 0.0}); // the core's checks: "material maps: reason"
  }
}

void LitModelMaterial::apply(vtkActor* actor, vtkRenderer* renderer)
{
  impl_->hook.attach(actor, renderer, impl_.get());
}

void LitModelMaterial::detach()
{
  impl_->hook.detach();
}

void LitModelMaterial::setSettings(const LitModelSettings& settings)
{
  validate(settings);
  impl_->settings = settings;
  if (impl_->hook.installed())
  {
    impl_->updateVariant();
  }
  impl_->hook.changed(); // lights and maps live outside VTK's objects
}

const LitModelSettings& LitModelMaterial::settings() const
{
  return impl_->settings;
}

MaterialInstaller litModelInstaller(const LitModelSettings& settings)
{
  LitModelMaterial::validate(settings);
  return [settings](vtkActor* actor, vtkRenderer* renderer,
                    const std::shared_ptr<EnvironmentLighting>&) -> std::shared_ptr<void>
  {
    auto material = std::make_shared<LitModelMaterial>(settings);
    material->apply(actor, renderer);
    return material;
  };
}

std::vector<Light> withEnvironmentLights(const std::vector<Light>& lights,
                                         const EnvAnalysis* analysis, double rotationDegrees)
{
  std::vector<Light> all = lights;
  if (analysis && int(all.size()) < LitModelMaterial::kMaxLights)
  {
    EnvLightOptions options;
    options.maxLights = LitModelMaterial::kMaxLights - int(all.size());
    const std::vector<Light> sources = environmentSourceLights(*analysis, rotationDegrees, options);
    all.insert(all.end(), sources.begin(), sources.end());
  }
  return all;
}

MaterialInstaller litModelInstaller(const LitModelSettings& settings, bool environmentLights)
{
  if (!environmentLights)
  {
    return litModelInstaller(settings);
  }
  LitModelMaterial::validate(settings);
  return [settings](vtkActor* actor, vtkRenderer* renderer,
                    const std::shared_ptr<EnvironmentLighting>& lighting) -> std::shared_ptr<void>
  {
    LitModelSettings lit = settings;
    if (lighting)
    {
      lit.lights =
          withEnvironmentLights(lit.lights, &lighting->analysis(), lighting->rotationDegrees());
    }
    auto material = std::make_shared<LitModelMaterial>(lit);
    material->apply(actor, renderer);
    return material;
  };
}
} // namespace aniso
