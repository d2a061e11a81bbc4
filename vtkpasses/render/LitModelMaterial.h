#pragma once
// The lit shading models of source 2 (Ashikhmin-Shirley, Banks, anisotropic Blinn-Phong, Ward,
// Heidrich-Seidel) under point and directional lights, given to any vtkActor whose mapper is a
// vtkOpenGLPolyDataMapper. Like AnisoMaterial it injects GLSL through shader replacements (VTK's
// tags kept), binds the shift-variant material's maps as named textures and sets the lights as
// uniform arrays when the mapper draws, so moving a light never recompiles; the model and the
// mesh's arrays ("Normals", "Tangents", "TCoords") choose the compiled variant. Each pixel
// renormalises the interpolated vectors and builds its frame as core/brdf/shading_frame.h does,
// then shades as core/models/models.h's shadeLitModel does on the CPU.
#include "core/env/env_sources.h"
#include "core/lights/light.h"
#include "core/models/models.h"
#include "core/models/sv_material.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace aniso
{
struct LitModelSettings
{
  LitModel model = LitModel::AshikhminShirley;
  std::vector<Light> lights;          // at most LitModelMaterial::kMaxLights
  std::shared_ptr<const SvMaps> maps; // the material; null = uniformSvMaps(SvTexel{})
};

// The variant: what changes the compiled shader.
struct LitModelVariant
{
  LitModel model = LitModel::AshikhminShirley;
  bool normals = false;
  bool tangents = false;
  bool tcoords = false;
  bool lines = false; // an illuminated line set (LIT_LINE; docs/METHOD.md, "Lines")
  bool operator==(const LitModelVariant& o) const
  {
    return model == o.model && normals == o.normals && tangents == o.tangents &&
           tcoords == o.tcoords && lines == o.lines;
  }
  bool operator!=(const LitModelVariant& o) const { return !(*this == o); }
};

// "#define LIT_..." lines of a variant (GL-free, so the variant logic is testable alone).
std::string litVariantDefines(const LitModelVariant& variant);

class LitModelMaterial
{
public:
  static constexpr int kMaxLights = 8;

  // Invalid settings throw aniso::Error "name: reason".
  explicit LitModelMaterial(const LitModelSettings& settings = {});
  ~LitModelMaterial();
  LitModelMaterial(const LitModelMaterial&) = delete;
  LitModelMaterial& operator=(const LitModelMaterial&) = delete;

  // Gives the material to ACTOR drawn by RENDERER; the actor's mapper must be an OpenGL
  // polydata mapper (aniso::Error otherwise). Applying again moves it.
  void apply(vtkActor* actor, vtkRenderer* renderer);
  void detach();

  // New lights and material are uniforms and textures; a new model recompiles. Invalid
  // settings throw aniso::Error and keep the previous ones.
  void setSettings(const LitModelSettings& settings);
  const LitModelSettings& settings() const;

  // Throws aniso::Error "lights: ..." / "light: ..." / "material maps: ..." unless SETTINGS
  // can be rendered.
  static void validate(const LitModelSettings& settings);

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// For RenderSettings::installMaterial: renders SETTINGS' model instead of the environment
// material (validated here, so a bad setting fails before any window opens).
MaterialInstaller litModelInstaller(const LitModelSettings& settings);
// The same, ENVIRONMENTLIGHTS (env-lights): the settings' lights and the sources of the
// renderer's lighting (its analysis, made now when not yet made: offscreen) as directional
// lights turned by the lighting's rotation, up to kMaxLights in all
// (core/lights/env_lights.h).
MaterialInstaller litModelInstaller(const LitModelSettings& settings, bool environmentLights);
// SETTINGS' lights followed by the sources of ANALYSIS turned by ROTATIONDEGREES, up to
// LitModelMaterial::kMaxLights in all (none when ANALYSIS is null).
std::vector<Light> withEnvironmentLights(const std::vector<Light>& lights,
                                         const EnvAnalysis* analysis, double rotationDegrees);
} // namespace aniso
