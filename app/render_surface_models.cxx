#include "app/render_surface_models.h"

#include "app/render_models.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/maps/map_files.h"
#include "core/microstructure/microstructure.h"
#include "core/models/height_field.h"
#include "core/parameters/choices.h"
#include "vtkpasses/render/LeadrMaterial.h"
#include "vtkpasses/render/MicrostructureMaterial.h"

#include <cmath>
#include <memory>

namespace aniso::cli
{
namespace
{
// The option NAME of declared parameter KEY (core/parameters/parameters.cxx, shared with the
// window's scene keys): a choice lists its values, a number shows VALUE_NAME.
Option declaredOption(std::string_view key, std::string name, const std::string& valueName,
                      std::string_view help = {})
{
  Option o = parameterOption(key, std::move(name), help);
  for (std::string_view choice : o.spec.choices)
  {
    o.choices.emplace_back(choice);
  }
  if (!o.choices.empty())
  {
    o.valueName = o.choices.front();
    for (std::size_t i = 1; i < o.choices.size(); ++i)
    {
      o.valueName += "|" + o.choices[i];
    }
  }
  else if (!valueName.empty())
  {
    o.valueName = valueName;
  }
  return o;
}

const char* const kLeadrOptions[] = {"--leadr-scale", "--leadr-tiles", "--leadr-roughness",
                                     "--leadr-grid", "--leadr-filter"};
const char* const kMicroOptions[] = {"--structure",       "--grid",           "--jitter-grid",
                                     "--masking",         "--self-shadow",    "--micro-brdf",
                                     "--micro-roughness", "--blinn-exponent", "--structure-depth",
                                     "--structure-tiles"};

void refuse(const Arguments& a, const char* const* begin, const char* const* end,
            const std::string& model)
{
  for (const char* const* name = begin; name != end; ++name)
  {
    if (a.has(*name))
    {
      throw usageError(*name, "only applies to --model " + model);
    }
  }
}

// The option of declared parameter KEY: "--" + KEY but for the grid, --grid on the command line.
std::string optionOf(std::string_view key)
{
  return key == "micro-grid" ? std::string("--grid") : "--" + std::string(key);
}

std::shared_ptr<const LeadrMips> leadrMoments(const Arguments& a)
{
  const double scale = a.real("--leadr-scale");
  if (a.has("--normal-map") && a.has("--height-map"))
  {
    throw usageError("--normal-map", "LEADR filters one relief: --normal-map or --height-map");
  }
  if (a.has("--normal-map"))
  {
    ImageInfo info;
    const Image normals = readImage(a.text("--normal-map"), &info);
    if (scale != 1.0)
    {
      throw usageError("--leadr-scale", "scales a height map, not --normal-map");
    }
    return std::make_shared<const LeadrMips>(bakeLeadrFromNormals(normals, info.integerFormat));
  }
  const Image height =
      a.has("--height-map") ? readImage(a.text("--height-map")) : builtinLeadrRelief();
  return std::make_shared<const LeadrMips>(bakeLeadrFromHeight(height, scale));
}
} // namespace

Image builtinLeadrRelief()
{
  // Slope deviation 0.3 per axis over a 64 x 64 tile: close to Gaussian, as LEADR assumes.
  return randomWaveHeight(64, 0.3);
}

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

void addSurfaceModelOptions(Command& c)
{
  c.options.push_back(declaredOption("leadr-scale", "--leadr-scale", "S",
                                     "leadr: heights of --height-map (or the built-in relief) "
                                     "times S (texture units)"));
  c.options.push_back(declaredOption("leadr-tiles", "--leadr-tiles", "N"));
  c.options.push_back(declaredOption("leadr-roughness", "--leadr-roughness", "ALPHA"));
  c.options.push_back(declaredOption("leadr-grid", "--leadr-grid", "N"));
  c.options.push_back(declaredOption("leadr-filter", "--leadr-filter", ""));
  c.options.push_back(declaredOption("structure", "--structure", "",
                                     "microstructure: the repeating structure; it turns with "
                                     "--tpr (grooves with --tpr circular on --builtin disk: a "
                                     "brushed disk)"));
  c.options.push_back(declaredOption("micro-grid", "--grid", "K"));
  c.options.push_back(declaredOption("jitter-grid", "--jitter-grid", ""));
  c.options.push_back(declaredOption("masking", "--masking", ""));
  c.options.push_back(declaredOption("self-shadow", "--self-shadow", ""));
  c.options.push_back(declaredOption("micro-brdf", "--micro-brdf", ""));
  c.options.push_back(declaredOption("micro-roughness", "--micro-roughness", "ALPHA"));
  c.options.push_back(declaredOption("blinn-exponent", "--blinn-exponent", "E"));
  c.options.push_back(declaredOption("structure-depth", "--structure-depth", "D"));
  c.options.push_back(declaredOption("structure-tiles", "--structure-tiles", "N"));
}

bool applySurfaceModelOptions(const Arguments& a, RenderSettings& settings)
{
  const std::string model = a.text("--model");
  if (model != "leadr")
  {
    refuse(a, std::begin(kLeadrOptions), std::end(kLeadrOptions), "leadr");
  }
  if (model != "microstructure")
  {
    refuse(a, std::begin(kMicroOptions), std::end(kMicroOptions), "microstructure");
  }
  const DeclaredValues values = [&a](std::string_view key) -> const ParameterValue&
  { return a.value(optionOf(key)); };
  if (model == "leadr")
  {
    LeadrSettings leadr = leadrSettingsOf(values);
    leadr.moments = leadrMoments(a);
    leadr.surface.f0 = settings.material.f0;
    leadr.surface.diffuse = settings.material.albedo;
    leadr.lights = lightsFromOptions(a);
    settings.installMaterial = LeadrShadingMaterial::installer(leadr);
    return true;
  }
  if (model == "microstructure")
  {
    MicrostructureSettings micro = microstructureSettingsOf(values);
    micro.options.f0 = settings.material.f0;
    micro.lights = lightsFromOptions(a);
    if (a.has("--tpr"))
    {
      // The structure turns with the map (a brushed disk with circular grooves).
      micro.tprMap = std::make_shared<const Image>(readTprMap(a.text("--tpr"), "--tpr"));
    }
    settings.installMaterial = MicrostructureShadingMaterial::installer(micro);
    return true;
  }
  return false;
}
} // namespace aniso::cli
