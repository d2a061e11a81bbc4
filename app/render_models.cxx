#include "render_models.h"

#include "LitModelMaterial.h"
#include "materials/models.h"
#include "render_surface_models.h"

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
} // namespace

void addModelOptions(Command& command)
{
  // Help texts are string_views: the composed texts must outlive the command table.
  static const std::string modelHelp =
      "shading model: " + shadingModelNames(", ") +
      " (as-env: Ashikhmin-Shirley under the environment; the others under --light)";
  Option model = textOption("--model", "NAME", modelHelp, kEnvironmentModel);
  for (const ShadingModelInfo& info : shadingModels())
  {
    model.choices.emplace_back(info.name);
  }
  command.options.push_back(model);
  static const std::string lightHelp =
      "a light, repeatable (at most " + std::to_string(LitModelMaterial::kMaxLights) +
      "): dir:X,Y,Z:INTENSITY (direction towards the light, irradiance) or "
      "point:X,Y,Z:INTENSITY (position, radiant intensity); INTENSITY is one number or R,G,B; "
      "default " +
      std::string(kDefaultLights[0]) + " and " + kDefaultLights[1];
  Option light = textOption("--light", "SPEC", lightHelp);
  light.repeatable = true;
  command.options.push_back(light);
  static const std::string sampleHelp = "built-in shift-variant material for " + litModelNames() +
                                        ": " + sampleMaterialNames(", ") +
                                        " (instead of the uniform one made from --nu, --nv, --f0, "
                                        "--albedo)";
  Option sample = textOption("--sample-material", "NAME", sampleHelp);
  for (const SampleMaterialInfo& info : sampleMaterials())
  {
    sample.choices.emplace_back(info.name);
  }
  command.options.push_back(sample);
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
  const std::string name = a.text("--model");
  const ShadingModelInfo& info = shadingModel(name, "--model");
  if (a.has("--light") && !info.lights)
  {
    throw usageError("--light", "model " + name + " is not lit by lights");
  }
  if (applySurfaceModelOptions(a, settings))
  {
    if (a.has("--sample-material"))
    {
      throw usageError("--sample-material", "only applies to " + litModelNames());
    }
    return;
  }
  LitModel model;
  if (!litModelFromName(name, model))
  {
    if (a.has("--sample-material"))
    {
      throw usageError("--sample-material", "only applies to " + litModelNames());
    }
    return;
  }
  LitModelSettings lit;
  lit.model = model;
  lit.lights = lightsFromOptions(a);
  lit.maps = a.has("--sample-material")
                 ? std::make_shared<const SvMaps>(
                       makeSampleMaterial(a.text("--sample-material"), "--sample-material"))
                 : std::make_shared<const SvMaps>(uniformSvMaps(uniformTexel(
                       settings.material.lobe, settings.material.f0, settings.material.albedo)));
  settings.installMaterial = litModelInstaller(lit);
}

std::string modelSummary(const Arguments& a)
{
  const std::string name = a.text("--model");
  if (!isLit(name))
  {
    return "model " + name;
  }
  return "model " + name + ", " + std::to_string(lightsFromOptions(a).size()) +
         " light(s), material " +
         (a.has("--sample-material") ? a.text("--sample-material") : std::string("uniform"));
}
} // namespace aniso::cli
