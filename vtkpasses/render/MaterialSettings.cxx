#include "vtkpasses/render/MaterialSettings.h"

#include "core/parameters/parameters.h"

namespace aniso
{
MaterialSettings materialFromParameters(const ParameterSet& parameters, MaterialSettings base)
{
  base.lobe = parameters.lobe();
  base.f0 = parameters.color("f0");
  base.albedo = parameters.color("albedo");
  base.samples = parameters.integer("samples");
  base.lutSize = parameters.integer("lut-size");
  base.brdfLutSamples = parameters.integer("lut-samples");
  base.method = parseSpecularMethod(parameters.text("method"));
  base.filtered = parseOnOff("filtered", parameters.text("filtered")) == OnOff::On;
  base.halfVectors = parseHalfVectorSource(parameters.text("half-vectors"));
  base.environmentSampling = parseEnvironmentSampling(parameters.text("env-sampling"));
  base.heightScale = parameters.real("height-scale");
  base.field = fieldMappingFromParameters(parameters);
  return base;
}

std::optional<ReferenceMaterial> referenceMaterialOf(const MaterialSettings& settings,
                                                     std::string& why)
{
  if (settings.usesMaps())
  {
    why = "the reference does not integrate maps (normal, quaternion, TPR, height, albedo, "
          "occlusion or metallic)";
    return std::nullopt;
  }
  if (settings.field)
  {
    why = "the reference does not integrate a data field (field)";
    return std::nullopt;
  }
  return ReferenceMaterial{settings.lobe, settings.f0, settings.albedo};
}
} // namespace aniso
