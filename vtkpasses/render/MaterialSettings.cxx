#include "vtkpasses/render/MaterialSettings.h"

#include "core/image/image.h"
#include "core/maps/map_files.h"
#include "core/maps/quaternion_map.h"
#include "core/parameters/choices.h"
#include "core/parameters/material_library.h"
#include "core/parameters/parameters.h"

#include <utility>

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

void readMaterialMaps(const Material& material, MaterialSettings& settings)
{
  const auto text = [&](std::string_view key) -> const std::string&
  { return material.value(key).text; };
  const auto shared = [](Image image) { return std::make_shared<const Image>(std::move(image)); };
  const BumpMapping bump = parseBumpMapping(text("bump"));
  if (bump == BumpMapping::Normal && !text("normal-map").empty())
  {
    settings.normalMap = shared(readSignedMap(text("normal-map")));
  }
  else if (bump == BumpMapping::Quaternion && !text("quaternion-map").empty())
  {
    settings.quaternionMap = shared(readSignedMap(text("quaternion-map")));
  }
  else if (bump == BumpMapping::Quaternion && !text("normal-map").empty())
  {
    ImageInfo info;
    const Image normals = readImage(text("normal-map"), &info);
    settings.quaternionMap = shared(bakeQuaternionMap(normals, info.integerFormat, nullptr));
  }
  if (!text("tpr").empty())
  {
    settings.tprMap = shared(readTprMap(text("tpr"), material.name + ": tpr"));
  }
  const std::pair<std::string_view, std::shared_ptr<const Image> MaterialSettings::*> plain[] = {
      {"height-map", &MaterialSettings::heightMap},
      {"albedo-map", &MaterialSettings::albedoMap},
      {"ao-map", &MaterialSettings::occlusionMap},
      {"metallic-map", &MaterialSettings::metallicMap}};
  for (const auto& [key, map] : plain)
  {
    if (!text(key).empty())
    {
      settings.*map = shared(readImage(text(key)));
    }
  }
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
