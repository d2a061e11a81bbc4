#include "app/render_models.h"

#include "app/render_surface_models.h"
#include "core/models/models.h"
#include "core/parameters/choices.h"
#include "vtkpasses/render/LitModelMaterial.h"

#include <memory>

namespace aniso::cli
{
namespace
{
// A key light from the upper front left and a weaker one from the right, so highlights and
// their anisotropy show on the built-in meshes seen from the front (-Y).
const char* const kDefaultLights[] = {"dir:-1,-1.5,2:3", "dir:2,-0.5,0.6:1"};

bool isLit(const std::string& model)
{
  LitModel lit;
  return litModelFromName(model, lit);
}

// "ashikhmin-shirley, banks, ...": the models that take --sample-material.
std::string litModelNames()
{
  std::string names;
  for (const ShadingModelInfo& info : shadingModels())
  {
    if (isLit(std::string(info.name)))
    {
      names += (names.empty() ? "" : ", ") + std::string(info.name);
    }
  }
  return names;
}
// The installer of lit model MODEL with the command line's lights and material.
MaterialInstaller litInstaller(LitModel model, const Arguments& a, const RenderSettings& settings)
{
  LitModelSettings lit;
  lit.model = model;
  lit.lights = lightsFromOptions(a);
  lit.maps = a.has("--sample-material")
                 ? std::make_shared<const SvMaps>(
                       makeSampleMaterial(a.text("--sample-material"), "--sample-material"))
                 : std::make_shared<const SvMaps>(uniformSvMaps(uniformTexel(
                       settings.material.lobe, settings.material.f0, settings.material.albedo)));
  // env-lights: the environment's sources as lights too (analysed when the renderer's lighting
  // is made).
  return litModelInstaller(lit, parseOnOff("env-lights", a.text("--env-lights")) == OnOff::On);
}

constexpr std::size_t kMaxCompared = 8;

// The models of --compare, each as-env or a lit model.
std::vector<std::string> comparedModels(const Arguments& a)
{
  std::vector<std::string> names;
  const std::string& list = a.text("--compare");
  std::string::size_type start = 0;
  for (;;)
  {
    const std::string::size_type end = list.find(',', start);
    names.push_back(list.substr(start, end - start));
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  if (names.size() > kMaxCompared)
  {
    throw usageError("--compare", "at most " + std::to_string(kMaxCompared) + " models");
  }
  for (const std::string& name : names)
  {
    LitModel lit;
    if (name != kEnvironmentModel && !litModelFromName(name, lit))
    {
      throw usageError("--compare", "'" + name + "' is not one of as-env, " + litModelNames());
    }
  }
  return names;
}
} // namespace

void addModelOptions(Command& command)
{
  // Help texts are string_views: the composed texts must outlive the command table.
  static const std::string modelHelp =
      "shading model (as-env: Ashikhmin-Shirley under the environment; the others under "
      "--light)";
  Option model = textOption("--model", "NAME", modelHelp, kEnvironmentModel);
  for (const ShadingModelInfo& info : shadingModels())
  {
    model.choices.emplace_back(info.name);
  }
  model.group = kGroupModels;
  command.options.push_back(model);
  static const std::string lightHelp =
      "a light, repeatable (at most " + std::to_string(LitModelMaterial::kMaxLights) +
      "): dir:X,Y,Z:INTENSITY (direction towards the light, irradiance) or "
      "point:X,Y,Z:INTENSITY (position, radiant intensity); INTENSITY is one number or R,G,B; "
      "default " +
      std::string(kDefaultLights[0]) + " and " + kDefaultLights[1];
  Option light = textOption("--light", "SPEC", lightHelp);
  light.repeatable = true;
  light.group = kGroupLighting;
  command.options.push_back(light);
  static const std::string sampleHelp = "built-in shift-variant material for " + litModelNames() +
                                        " (instead of the uniform one made from --nu, --nv, --f0, "
                                        "--albedo)";
  Option sample = textOption("--sample-material", "NAME", sampleHelp);
  for (const SampleMaterialInfo& info : sampleMaterials())
  {
    sample.choices.emplace_back(info.name);
  }
  sample.group = kGroupModels;
  command.options.push_back(sample);
  static const std::string compareHelp =
      "render several models side by side, one tile of --size each, left to right, with the same "
      "mesh, camera, lights and material: a comma-separated list of as-env and " +
      litModelNames();
  Option compare = textOption("--compare", "M1,M2,...", compareHelp);
  compare.group = kGroupModels;
  command.options.push_back(compare);
  // The environment's sources as lights of the lit models and LEADR (a declared parameter, as the
  // window's scene key).
  Option environmentLights = parameterOption("env-lights");
  for (std::string_view choice : environmentLights.spec.choices)
  {
    environmentLights.choices.emplace_back(choice);
  }
  command.options.push_back(environmentLights);
  addSurfaceModelOptions(command);
}

std::vector<Light> lightsFromOptions(const Arguments& a)
{
  std::vector<std::string> texts = a.texts("--light");
  if (texts.empty())
  {
    texts.assign(std::begin(kDefaultLights), std::end(kDefaultLights));
  }
  if (texts.size() > std::size_t(LitModelMaterial::kMaxLights))
  {
    throw usageError("--light", "at most " + std::to_string(LitModelMaterial::kMaxLights) +
                                    " lights (" + std::to_string(texts.size()) + " given)");
  }
  std::vector<Light> lights;
  for (const std::string& text : texts)
  {
    try
    {
      lights.push_back(parseLight(text));
    }
    catch (const Error& e)
    {
      throw UsageError(e.what());
    }
  }
  return lights;
}

void applyModelOptions(const Arguments& a, RenderSettings& settings)
{
  if (a.has("--compare"))
  {
    if (a.has("--model"))
    {
      throw usageError("--compare", "give either --model or --compare");
    }
    comparedModels(a);
    lightsFromOptions(a);
    return;
  }
  const std::string name = a.text("--model");
  const ShadingModelInfo& info = shadingModel(name, "--model");
  if (a.has("--light") && !info.lights)
  {
    throw usageError("--light", "model " + name + " is not lit by lights");
  }
  LitModel model;
  const bool lit = litModelFromName(name, model);
  if (!lit && a.has("--sample-material"))
  {
    throw usageError("--sample-material", "only applies to " + litModelNames());
  }
  if (applySurfaceModelOptions(a, settings) || !lit)
  {
    return;
  }
  settings.installMaterial = litInstaller(model, a, settings);
}

RenderResult renderComparison(const Arguments& a, RenderSettings& settings)
{
  const std::vector<std::string> names = comparedModels(a);
  const int tile = settings.width;
  RenderResult mosaic;
  mosaic.linear = Image(tile * int(names.size()), settings.height, 4);
  mosaic.display = Image(mosaic.linear.width, settings.height, 4);
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    RenderSettings one = settings;
    LitModel lit;
    one.installMaterial =
        litModelFromName(names[i], lit) ? litInstaller(lit, a, settings) : MaterialInstaller{};
    const RenderResult result = renderOffscreen(one);
    for (int y = 0; y < settings.height; ++y)
    {
      for (int x = 0; x < tile; ++x)
      {
        for (int c = 0; c < 4; ++c)
        {
          mosaic.linear.at(int(i) * tile + x, y, c) = result.linear.at(x, y, c);
          mosaic.display.at(int(i) * tile + x, y, c) = result.display.at(x, y, c);
        }
      }
    }
    mosaic.frameSeconds.insert(mosaic.frameSeconds.end(), result.frameSeconds.begin(),
                               result.frameSeconds.end());
    mosaic.coveredPixels += result.coveredPixels;
    mosaic.renderer = result.renderer;
  }
  settings.width = mosaic.linear.width;
  return mosaic;
}

std::string modelSummary(const Arguments& a)
{
  if (a.has("--compare"))
  {
    return "models " + a.text("--compare") + " left to right";
  }
  const std::string name = a.text("--model");
  if (!isLit(name))
  {
    return "model " + name;
  }
  return "model " + name + ", " + std::to_string(lightsFromOptions(a).size()) + " light(s)" +
         (a.text("--env-lights") == "on" ? " and the environment's sources" : "") +
         ", material " +
         (a.has("--sample-material") ? a.text("--sample-material") : std::string("uniform"));
}
} // namespace aniso::cli
