#include "core/models/models.h"

#include "core/brdf/shading_frame.h"
#include "core/error.h"
#include "core/models/samples.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
namespace
{
// What the lit models read: the uniform material's parameters (unless a sample material is
// given) and the lights.
const std::vector<std::string_view> kLitParameters = {"nu", "nv", "f0", "albedo", "exposure"};

std::vector<ShadingModelInfo> makeModels()
{
  std::vector<ShadingModelInfo> m;
  m.push_back({kEnvironmentModel,
               "Ashikhmin-Shirley (environment)",
               "Ashikhmin-Shirley specular by importance sampling of the environment, Lambert "
               "diffuse from SH9 irradiance (source 1)",
               true,
               false,
               {"nu", "nv", "f0", "albedo", "samples", "method", "filtered", "half-vectors",
                "lut-size", "lut-samples", "env", "env-rotation", "exposure"}});
  m.push_back({"ashikhmin-shirley", "Ashikhmin-Shirley",
               "Ashikhmin-Shirley specular and its coupled diffuse term under point and "
               "directional lights, on the shift-variant material",
               false, true, kLitParameters});
  m.push_back({"banks", "Banks",
               "Banks's fibre model: fibres along the tangent, diffuse from the fibre normal "
               "closest to the light, highlight on the reflection cone",
               false, true, kLitParameters});
  m.push_back({"blinn-phong", "Anisotropic Blinn-Phong",
               "normalised anisotropic Blinn-Phong with the exponent from the t/alpha_x and "
               "b/alpha_y material textures, k_s in their alpha",
               false, true, kLitParameters});
  m.push_back({"ward", "Ward",
               "Ward's anisotropic Gaussian, factored into S(p) = 1/sqrt(p) and "
               "E(m, d) = exp(-2m/(1+d)) as source 2 evaluates it",
               false, true, kLitParameters});
  m.push_back({"heidrich-seidel", "Heidrich-Seidel",
               "Heidrich-Seidel line lighting on surfaces: the fibre highlight of (l.t, v.t) "
               "plus Lambert on the surface normal",
               false, true, kLitParameters});
  m.push_back({"leadr", "LEADR mapping",
               "linearly filterable slope moments of a height or normal map: anisotropic "
               "Beckmann with Smith masking, environment on a slope-space grid, SH9 diffuse "
               "(source 3)",
               true, true, {"f0", "albedo", "env", "env-rotation", "exposure"}});
  m.push_back({"microstructure", "Small-scale microstructure",
               "a repeating albedo/normal/height structure sampled K x K per pixel with normal, "
               "parallax or occlusion masking, self-shadowing, GGX or Blinn-Phong (source 4)",
               false, true, {"f0", "exposure"}});
  return m;
}

struct LitName
{
  LitModel model;
  std::string_view name;
};
constexpr LitName kLitNames[] = {{LitModel::AshikhminShirley, "ashikhmin-shirley"},
                                 {LitModel::Banks, "banks"},
                                 {LitModel::BlinnPhong, "blinn-phong"},
                                 {LitModel::Ward, "ward"},
                                 {LitModel::HeidrichSeidel, "heidrich-seidel"}};

template <class Rows>
std::string joinedNames(const Rows& rows, std::string_view separator)
{
  std::string text;
  for (const auto& row : rows)
  {
    text += (text.empty() ? "" : std::string(separator)) + std::string(row.name);
  }
  return text;
}
} // namespace

const std::vector<ShadingModelInfo>& shadingModels()
{
  static const std::vector<ShadingModelInfo> models = makeModels();
  return models;
}

const ShadingModelInfo* findShadingModel(std::string_view name)
{
  for (const ShadingModelInfo& model : shadingModels())
  {
    if (model.name == name)
    {
      return &model;
    }
  }
  return nullptr;
}

const ShadingModelInfo& shadingModel(std::string_view name, const std::string& subject)
{
  if (const ShadingModelInfo* model = findShadingModel(name))
  {
    return *model;
  }
  throw errorAbout(subject, "'" + std::string(name) + "' is not one of " + shadingModelNames(", "));
}

std::string shadingModelNames(std::string_view separator)
{
  return joinedNames(shadingModels(), separator);
}

bool litModelFromName(std::string_view name, LitModel& model)
{
  for (const LitName& row : kLitNames)
  {
    if (row.name == name)
    {
      model = row.model;
      return true;
    }
  }
  return false;
}

std::string_view litModelName(LitModel model)
{
  for (const LitName& row : kLitNames)
  {
    if (row.model == model)
    {
      return row.name;
    }
  }
  return {};
}

glm::dvec3 shadeLitModel(LitModel model, const SvTexel& texel, const Frame& frame,
                         const glm::dvec3& position, const glm::dvec3& viewWorld,
                         const std::vector<Light>& lights)
{
  switch (model)
  {
  case LitModel::AshikhminShirley:
    return shadeAshikhminShirley(toAshikhminShirley(texel), frame, position, viewWorld, lights);
  case LitModel::Banks:
    return shadeBanks(toBanks(texel), frame, position, viewWorld, lights);
  case LitModel::BlinnPhong:
    return shadeBlinnPhongAniso(toBlinnPhong(texel), frame, position, viewWorld, lights);
  case LitModel::Ward:
  {
    // The factored form in the frame's own tangent space (t = +X, b = +Y, n = +Z).
    const WardMaterial ward = toWard(texel);
    const ScaledTangents scaled = scaledTangents(Frame{}, ward.alphaX, ward.alphaY);
    return shadeBrdfWithLights(
        lights, frame, position, viewWorld,
        [&](const glm::dvec3& v, const glm::dvec3& l)
        { return evalWardFactored(ward, scaled, glm::dvec3(0.0, 0.0, 1.0), v, l); });
  }
  case LitModel::HeidrichSeidel:
    return shadeHeidrichSeidel(toHeidrichSeidel(texel), frame, position, viewWorld, lights);
  }
  return glm::dvec3(0.0);
}

const std::vector<SampleMaterialInfo>& sampleMaterials()
{
  static const std::vector<SampleMaterialInfo> samples = {
      {"scratched-plate", "polished steel scratched along both axes", "plate"},
      {"brushed-latitudinal", "steel brushed along the parallels of the sphere", "sphere"},
      {"brushed-longitudinal", "steel brushed along the meridians of the sphere", "sphere"},
      {"marble", "polished marble with raised, rougher veins", "plate"}};
  return samples;
}

std::string sampleMaterialNames(std::string_view separator)
{
  return joinedNames(sampleMaterials(), separator);
}

SvMaps makeSampleMaterial(std::string_view name, const std::string& subject)
{
  if (name == "scratched-plate")
  {
    return scratchedPlate(512);
  }
  if (name == "brushed-latitudinal")
  {
    return uniformSvMaps(brushedMetal(BrushDirection::Latitudinal));
  }
  if (name == "brushed-longitudinal")
  {
    return uniformSvMaps(brushedMetal(BrushDirection::Longitudinal));
  }
  if (name == "marble")
  {
    return veinedMarble(512);
  }
  throw errorAbout(subject,
                   "'" + std::string(name) + "' is not one of " + sampleMaterialNames(", "));
}

SvTexel uniformTexel(const AsLobe& lobe, const glm::dvec3& f0, const glm::dvec3& albedo)
{
  auto alpha = [](double n)
  { return std::clamp(std::sqrt(2.0 / (n + 2.0)), kSvMinAlpha, kSvMaxAlpha); };
  SvTexel texel;
  texel.alphaX = alpha(lobe.nu);
  texel.alphaY = alpha(lobe.nv);
  texel.specular = std::clamp((f0.x + f0.y + f0.z) / 3.0, 0.0, 1.0);
  texel.diffuse = glm::clamp(albedo, 0.0, 1.0);
  return texel;
}
} // namespace aniso
