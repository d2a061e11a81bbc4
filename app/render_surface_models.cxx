#include "render_surface_models.h"

#include "LeadrMaterial.h"
#include "MicrostructureMaterial.h"
#include "leadr/leadr.h"
#include "maps/map_files.h"
#include "materials/texture_sampling.h"
#include "microstructure/microstructure.h"
#include "render_models.h"

#include <cmath>
#include <memory>

namespace aniso::cli
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

Option number(std::string name, std::string valueName, ParameterType type, double value,
              double minimum, double maximum, std::string_view help)
{
  Option o;
  o.name = std::move(name);
  o.valueName = std::move(valueName);
  o.spec.type = type;
  o.spec.defaultValue = {value, 0.0, 0.0};
  o.spec.minimum = minimum;
  o.spec.maximum = maximum;
  o.spec.help = help;
  return o;
}

Option choice(std::string name, std::string_view help, std::vector<std::string> choices)
{
  Option o = textOption(std::move(name), "", help, choices.front());
  o.valueName = choices.front();
  for (std::size_t i = 1; i < choices.size(); ++i)
  {
    o.valueName += "|" + choices[i];
  }
  o.choices = std::move(choices);
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

MicroPattern patternFromName(const std::string& name)
{
  if (name == "inverted-pyramids")
    return MicroPattern::InvertedPyramids;
  if (name == "grooves")
    return MicroPattern::Grooves;
  if (name == "silk")
    return MicroPattern::Silk;
  return MicroPattern::Pyramids;
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
  constexpr int size = 64;
  constexpr int waves = 96;
  struct Wave
  {
    double fx, fy, amplitude, phase;
  };
  std::vector<Wave> relief;
  for (std::uint32_t k = 0; relief.size() < std::size_t(waves); ++k)
  {
    const double fx = std::floor(hashedUniform(7, k, 0) * 13.0) - 6.0;
    const double fy = std::floor(hashedUniform(7, k, 1) * 13.0) - 6.0;
    const double f = std::hypot(fx, fy);
    if (f >= 1.0)
    {
      // Amplitude 1 / f: every wave adds the same slope variance, (2 pi)^2 / 2.
      relief.push_back({fx, fy, 1.0 / f, 2.0 * kPi * hashedUniform(7, k, 2)});
    }
  }
  const double scale = 0.3 * std::sqrt(2.0 / (waves * 0.5 * 4.0 * kPi * kPi));
  Image height(size, size, 1);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const double u = (x + 0.5) / size;
      const double v = 1.0 - (y + 0.5) / size;
      double h = 0.0;
      for (const Wave& w : relief)
      {
        h += w.amplitude * std::sin(2.0 * kPi * (w.fx * u + w.fy * v) + w.phase);
      }
      height.at(x, y, 0) = float(scale * h);
    }
  }
  return height;
}

void addSurfaceModelOptions(Command& c)
{
  c.options.push_back(number("--leadr-scale", "S", ParameterType::Real, 1.0, 0.0, 1e6,
                             "leadr: heights of --height-map times S (texture units)"));
  c.options.push_back(number("--leadr-tiles", "N", ParameterType::Real, 8.0, 1e-3, 1e6,
                             "leadr: repeats of the relief per unit of texture coordinate"));
  c.options.push_back(number("--leadr-roughness", "ALPHA", ParameterType::Real, 0.15,
                             kLeadrMinAlpha, kLeadrMaxAlpha,
                             "leadr: base Beckmann roughness added to every texel"));
  c.options.push_back(number("--leadr-grid", "N", ParameterType::Integer, 4.0, 1.0, 16.0,
                             "leadr: slope-space grid N x N for the environment and diffuse"));
  c.options.push_back(choice("--leadr-filter",
                             "leadr: the slope moments, or only their mean (plain normal mapping)",
                             {"leadr", "normal-mapping"}));
  c.options.push_back(choice("--structure",
                             "microstructure: the repeating structure; it turns with --tpr "
                             "(grooves with --tpr circular on --builtin disk: a brushed disk)",
                             {"pyramids", "inverted-pyramids", "grooves", "silk"}));
  c.options.push_back(number("--grid", "K", ParameterType::Integer, 4.0, 1.0, 64.0,
                             "microstructure: K x K samples per pixel"));
  c.options.push_back(
      choice("--jitter-grid", "microstructure: one random point per grid cell", {"off", "on"}));
  c.options.push_back(choice("--masking",
                             "microstructure: normal mapping, parallax or parallax occlusion",
                             {"pom", "parallax", "normal"}));
  c.options.push_back(
      choice("--self-shadow", "microstructure: shadows of the structure per light", {"off", "on"}));
  c.options.push_back(choice("--micro-brdf",
                             "microstructure: GGX with Smith-Schlick or normalised Blinn-Phong",
                             {"ggx", "blinn-phong"}));
  c.options.push_back(number("--micro-roughness", "ALPHA", ParameterType::Real, 0.3, 1e-3, 1.0,
                             "microstructure: GGX alpha"));
  c.options.push_back(number("--blinn-exponent", "E", ParameterType::Real, 100.0, 0.0, 1e6,
                             "microstructure: Blinn-Phong exponent"));
  c.options.push_back(number("--structure-depth", "D", ParameterType::Real, 0.1, 1e-3,
                             kMicroMaxDepth, "microstructure: relief depth in tile widths"));
  c.options.push_back(number("--structure-tiles", "N", ParameterType::Real, 64.0, 1e-3, 1e6,
                             "microstructure: tiles per unit of texture coordinate"));
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
  if (model == "leadr")
  {
    LeadrSettings leadr;
    leadr.moments = leadrMoments(a);
    leadr.surface.f0 = settings.material.f0;
    leadr.surface.diffuse = settings.material.albedo;
    leadr.surface.baseAlphaX = leadr.surface.baseAlphaY = a.real("--leadr-roughness");
    leadr.tiles = a.real("--leadr-tiles");
    leadr.gridN = a.integer("--leadr-grid");
    leadr.plainNormals = a.text("--leadr-filter") == "normal-mapping";
    leadr.environment = true;
    leadr.lights = lightsFromOptions(a);
    settings.installMaterial = LeadrShadingMaterial::installer(leadr);
    return true;
  }
  if (model == "microstructure")
  {
    MicrostructureSettings micro;
    micro.structure = std::make_shared<const Microstructure>(makeMicrostructure(
        patternFromName(a.text("--structure")), 64, a.real("--structure-depth")));
    MicroShadingOptions& o = micro.options;
    o.samplesPerAxis = a.integer("--grid");
    o.jittered = a.text("--jitter-grid") == "on";
    const std::string masking = a.text("--masking");
    o.masking = masking == "normal"     ? MicroMasking::Normal
                : masking == "parallax" ? MicroMasking::Parallax
                                        : MicroMasking::ParallaxOcclusion;
    o.selfShadowing = a.text("--self-shadow") == "on";
    o.brdf = a.text("--micro-brdf") == "blinn-phong" ? MicroBrdf::BlinnPhong
                                                     : MicroBrdf::GgxSmithSchlick;
    o.roughness = a.real("--micro-roughness");
    o.blinnExponent = a.real("--blinn-exponent");
    o.f0 = settings.material.f0;
    micro.tiles = a.real("--structure-tiles");
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
