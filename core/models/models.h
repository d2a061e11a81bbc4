#pragma once
// The shading models a material can be rendered with (docs/METHOD.md, sources 1 to 4), named once
// here so that `aniso render --model NAME`, the GUI and the tests list the same ones. GL-free.
// A new model is one more row in the table of models.cxx.
#include "core/models/sv_material.h"

#include <string>
#include <string_view>
#include <vector>

namespace aniso
{
struct ShadingModelInfo
{
  std::string_view name;        // "banks": option value, session key
  std::string_view title;       // "Banks": label in docks and galleries
  std::string_view description; // one sentence
  bool environment = false;     // lit by the environment map
  bool lights = false;          // lit by point and directional lights
  // Declared parameters (core/parameters/parameters.h) the model reads; docks show these.
  std::vector<std::string_view> parameters;
};

// The default model: Ashikhmin-Shirley under image-based lighting (source 1).
inline constexpr std::string_view kEnvironmentModel = "as-env";

// Every model, the default first.
const std::vector<ShadingModelInfo>& shadingModels();
// NAME's row, or null.
const ShadingModelInfo* findShadingModel(std::string_view name);
// NAME's row; throws aniso::Error "SUBJECT: 'NAME' is not one of as-env, banks, ...".
const ShadingModelInfo& shadingModel(std::string_view name, const std::string& subject);
// The names joined by SEPARATOR ("as-env|ashikhmin-shirley|..." for help texts).
std::string shadingModelNames(std::string_view separator = "|");

// The lit models of source 2, all rendering the same shift-variant material (SvMaps) through
// the conversions of sv_material.h.
enum class LitModel
{
  AshikhminShirley,
  Banks,
  BlinnPhong,
  Ward,
  HeidrichSeidel
};
// The lit model called NAME, if NAME is one ("ashikhmin-shirley", "banks", "blinn-phong",
// "ward", "heidrich-seidel").
bool litModelFromName(std::string_view name, LitModel& model);
std::string_view litModelName(LitModel model);

// Radiance of MODEL for TEXEL at a world-space point with shading frame FRAME, seen from
// direction VIEWWORLD (unit, towards the viewer), under LIGHTS: the core's CPU evaluation that
// the GL material reproduces (Ward in its factored half-vector form, as source 2 evaluates it).
glm::dvec3 shadeLitModel(LitModel model, const SvTexel& texel, const Frame& frame,
                         const glm::dvec3& position, const glm::dvec3& viewWorld,
                         const std::vector<Light>& lights);

// Built-in sample materials (core/models/samples.h) by name: "scratched-plate",
// "brushed-latitudinal", "brushed-longitudinal", "marble".
struct SampleMaterialInfo
{
  std::string_view name;
  std::string_view description;
  std::string_view mesh; // the built-in mesh it is made for: "plate" or "sphere"
};
const std::vector<SampleMaterialInfo>& sampleMaterials();
std::string sampleMaterialNames(std::string_view separator = "|");
// The maps of sample material NAME; throws aniso::Error "SUBJECT: 'NAME' is not one of ...".
SvMaps makeSampleMaterial(std::string_view name, const std::string& subject);

// A uniform material from the environment model's parameters, so --nu/--nv/--f0/--albedo mean
// the same under every model: alpha = sqrt(2 / (n + 2)) (the inverse of toAshikhminShirley),
// k_s = mean of F0, diffuse = albedo; alphas clamped to [kSvMinAlpha, kSvMaxAlpha].
SvTexel uniformTexel(const AsLobe& lobe, const glm::dvec3& f0, const glm::dvec3& albedo);
} // namespace aniso
