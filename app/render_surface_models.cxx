#include "app/render_surface_models.h"

#include "app/render_models.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/maps/map_files.h"
#include "core/parameters/choices.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/SurfaceModelSettings.h"

#include <memory>
#include <string_view>

namespace aniso::cli
{
namespace
{
// An option of a declared parameter (core/parameters/parameters.cxx, shared with the window's
// scene keys) that only MODEL reads.
struct ModelOption
{
  std::string_view model;
  std::string_view key;
  std::string_view name;      // "--" + key but for the grid, --grid on the command line
  std::string_view valueName; // for a number; a choice lists its values
  std::string_view help = {}; // replaces the declared help
};

const ModelOption kModelOptions[] = {
    {"leadr", "leadr-scale", "--leadr-scale", "S",
     "leadr: heights of --height-map (or the built-in relief) times S (texture units)"},
    {"leadr", "leadr-tiles", "--leadr-tiles", "N"},
    {"leadr", "leadr-roughness", "--leadr-roughness", "ALPHA"},
    {"leadr", "leadr-grid", "--leadr-grid", "N"},
    {"leadr", "leadr-filter", "--leadr-filter", ""},
    {"microstructure", "structure", "--structure", "",
     "microstructure: the repeating structure; it turns with --tpr (grooves with --tpr circular "
     "on --builtin disk: a brushed disk)"},
    {"microstructure", "micro-grid", "--grid", "K"},
    {"microstructure", "jitter-grid", "--jitter-grid", ""},
    {"microstructure", "masking", "--masking", ""},
    {"microstructure", "self-shadow", "--self-shadow", ""},
    {"microstructure", "micro-brdf", "--micro-brdf", ""},
    {"microstructure", "micro-roughness", "--micro-roughness", "ALPHA"},
    {"microstructure", "blinn-exponent", "--blinn-exponent", "E"},
    {"microstructure", "structure-depth", "--structure-depth", "D"},
    {"microstructure", "structure-tiles", "--structure-tiles", "N"},
};

const ModelOption& modelOption(std::string_view key)
{
  for (const ModelOption& o : kModelOptions)
  {
    if (o.key == key)
    {
      return o;
    }
  }
  throw errorAbout(std::string(key), "not an option of the surface models");
}

// The option of M: a choice lists its values, a number shows its value name.
Option declaredOption(const ModelOption& m)
{
  Option o = parameterOption(m.key, std::string(m.name), m.help);
  for (std::string_view choice : o.spec.choices)
  {
    o.choices.emplace_back(choice);
  }
  // A choice shows WORD and its choices on a line of their own (helpText).
  if (!o.choices.empty())
  {
    o.valueName = "WORD";
  }
  else if (!m.valueName.empty())
  {
    o.valueName = std::string(m.valueName);
  }
  return o;
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

void addSurfaceModelOptions(Command& c)
{
  for (const ModelOption& m : kModelOptions)
  {
    c.options.push_back(declaredOption(m));
  }
}

bool applySurfaceModelOptions(const Arguments& a, RenderSettings& settings)
{
  const std::string model = a.text("--model");
  for (const ModelOption& m : kModelOptions)
  {
    if (m.model != model && a.has(std::string(m.name)))
    {
      throw usageError(std::string(m.name), "only applies to --model " + std::string(m.model));
    }
  }
  const DeclaredValues values = [&a](std::string_view key) -> const ParameterValue&
  { return a.value(std::string(modelOption(key).name)); };
  SurfaceModelInputs inputs;
  inputs.f0 = settings.material.f0;
  inputs.albedo = settings.material.albedo;
  inputs.lights = [&a] { return lightsFromOptions(a); };
  inputs.leadrMoments = [&a] { return leadrMoments(a); };
  inputs.tprMap = [&a]() -> std::shared_ptr<const Image>
  {
    // The structure turns with the map (a brushed disk with circular grooves).
    return a.has("--tpr") ? std::make_shared<const Image>(readTprMap(a.text("--tpr"), "--tpr"))
                          : nullptr;
  };
  // env-lights: LEADR's lights are the environment's sources too, baked here (offscreen) as the
  // window's worker bakes them: the analysis, and the split when env-sampling resolves to
  // sources (LEADR then reads the residual).
  inputs.environmentLights = parseOnOff("env-lights", a.text("--env-lights")) == OnOff::On;
  const EnvironmentSampling sampling = settings.material.environmentSampling;
  inputs.prepareLighting = [sampling](EnvironmentLighting& lighting)
  {
    lighting.analysis();
    lighting.prepare(sampling);
  };
  MaterialInstaller installer = surfaceModelInstaller(model, values, inputs);
  if (!installer)
  {
    return false;
  }
  settings.installMaterial = std::move(installer);
  return true;
}
} // namespace aniso::cli
