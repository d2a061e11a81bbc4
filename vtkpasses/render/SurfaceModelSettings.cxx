#include "vtkpasses/render/SurfaceModelSettings.h"

#include "core/error.h"
#include "core/microstructure/microstructure.h"
#include "core/models/height_field.h"
#include "core/parameters/choices.h"
#include "vtkpasses/render/LeadrMaterial.h"
#include "vtkpasses/render/MicrostructureMaterial.h"

#include <string>

namespace aniso
{
namespace
{
LeadrSettings leadrSettingsOf(const DeclaredValues& values)
{
  const auto real = [&values](std::string_view key) { return values(key).number[0]; };
  LeadrSettings leadr;
  leadr.surface.baseAlphaX = leadr.surface.baseAlphaY = real("leadr-roughness");
  leadr.tiles = real("leadr-tiles");
  leadr.gridN = int(real("leadr-grid"));
  leadr.plainNormals = parseLeadrFilter(values("leadr-filter").text) == LeadrFilter::NormalMapping;
  leadr.environment = true;
  return leadr;
}

MicrostructureSettings microstructureSettingsOf(const DeclaredValues& values)
{
  const auto real = [&values](std::string_view key) { return values(key).number[0]; };
  const auto text = [&values](std::string_view key) -> const std::string&
  { return values(key).text; };
  MicrostructureSettings micro;
  micro.structure = std::make_shared<const Microstructure>(
      makeMicrostructure(parseMicroPattern(text("structure")), 64, real("structure-depth")));
  MicroShadingOptions& o = micro.options;
  o.samplesPerAxis = int(real("micro-grid"));
  o.jittered = parseOnOff("jitter-grid", text("jitter-grid")) == OnOff::On;
  o.masking = parseMicroMasking(text("masking"));
  o.selfShadowing = parseOnOff("self-shadow", text("self-shadow")) == OnOff::On;
  o.brdf = parseMicroBrdf(text("micro-brdf"));
  o.roughness = real("micro-roughness");
  o.blinnExponent = real("blinn-exponent");
  micro.tiles = real("structure-tiles");
  return micro;
}
} // namespace

MaterialInstaller surfaceModelInstaller(std::string_view model, const DeclaredValues& values,
                                        const SurfaceModelInputs& inputs)
{
  if (model == "leadr")
  {
    LeadrSettings leadr = leadrSettingsOf(values);
    leadr.moments = inputs.leadrMoments();
    leadr.surface.f0 = inputs.f0;
    leadr.surface.diffuse = inputs.albedo;
    leadr.lights = inputs.lights();
    leadr.environmentLights = inputs.environmentLights;
    MaterialInstaller install = LeadrShadingMaterial::installer(leadr);
    if (!inputs.prepareLighting || !leadr.environmentLights)
    {
      return install;
    }
    return [install, prepare = inputs.prepareLighting](
               vtkActor* actor, vtkRenderer* renderer,
               const std::shared_ptr<EnvironmentLighting>& lighting)
    {
      if (lighting)
      {
        prepare(*lighting);
      }
      return install(actor, renderer, lighting);
    };
  }
  if (model == "microstructure")
  {
    MicrostructureSettings micro = microstructureSettingsOf(values);
    micro.options.f0 = inputs.f0;
    micro.lights = inputs.lights();
    micro.tprMap = inputs.tprMap();
    return MicrostructureShadingMaterial::installer(micro);
  }
  return {};
}

Image builtinLeadrRelief()
{
  // Slope deviation 0.3 per axis over a 64 x 64 tile: close to Gaussian, as LEADR assumes.
  return randomWaveHeight(64, 0.3);
}
} // namespace aniso
