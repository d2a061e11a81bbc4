#include "scene/SceneShading.h"

#include "core/error.h"
#include "core/models/models.h"

#include <cctype>

namespace aniso
{
namespace
{
// The defaults of `aniso render --light`, so the GUI and the command line show the same scene.
constexpr std::string_view kDefaultLights = "dir:-1,-1.5,2:3;dir:2,-0.5,0.6:1";

SceneKey textKey(std::string_view name, std::string_view label, std::string_view defaultText,
                 std::string_view help, std::vector<std::string_view> choices, Affects roles)
{
  SceneKey key;
  key.spec.name = name;
  key.spec.label = label;
  key.spec.type = ParameterType::Text;
  key.spec.defaultText = defaultText;
  key.spec.help = help;
  key.spec.choices = std::move(choices);
  key.spec.roles = roles;
  return key;
}

std::string trimmed(const std::string& text)
{
  std::string::size_type begin = 0;
  std::string::size_type end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
  {
    ++begin;
  }
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
  {
    --end;
  }
  return text.substr(begin, end - begin);
}
} // namespace

std::vector<SceneKey> shadingSceneKeys()
{
  std::vector<std::string_view> models;
  for (const ShadingModelInfo& info : shadingModels())
  {
    models.push_back(info.name);
  }
  std::vector<std::string_view> samples{kUniformSampleMaterial};
  for (const SampleMaterialInfo& info : sampleMaterials())
  {
    samples.push_back(info.name);
  }
  using A = Affects;
  std::vector<SceneKey> keys;
  keys.push_back(textKey("model", "Shading model", kEnvironmentModel,
                         "how the surface is shaded: Ashikhmin-Shirley under the environment "
                         "(as-env) or one of the other models",
                         std::move(models), A::FrameCost | A::LitModels | A::SurfaceModels));
  keys.push_back(textKey("sample-material", "Sample material", kUniformSampleMaterial,
                         "the shift-variant material of the lit models: uniform (from n_u, n_v, "
                         "F0 and albedo) or a built-in sample",
                         std::move(samples), A::FrameCost | A::LitModels));
  keys.push_back(textKey("lights", "Lights", kDefaultLights,
                         "point and directional lights of the lit models, separated by ';'", {},
                         A::FrameCost | A::LitModels | A::SurfaceModels));
  return keys;
}

std::vector<Light> parseLightList(const std::string& text, const std::string& subject)
{
  std::vector<Light> lights;
  if (trimmed(text) == kNoLights)
  {
    return lights;
  }
  std::string::size_type start = 0;
  while (start <= text.size())
  {
    std::string::size_type end = text.find(kLightSeparator, start);
    if (end == std::string::npos)
    {
      end = text.size();
    }
    const std::string one = trimmed(text.substr(start, end - start));
    // Only a wholly empty text means no light: an empty item between separators is a typo.
    if (one.empty())
    {
      if (trimmed(text).empty())
      {
        break;
      }
      throw errorAbout(subject, "an empty light between separators");
    }
    try
    {
      lights.push_back(parseLight(one));
    }
    catch (const Error& e)
    {
      throw errorAbout(subject, e.what());
    }
    start = end + 1;
  }
  if (lights.size() > std::size_t(kMaxSceneLights))
  {
    throw errorAbout(subject, "at most " + std::to_string(kMaxSceneLights) + " lights (" +
                                  std::to_string(lights.size()) + " given)");
  }
  return lights;
}

std::string formatLightList(const std::vector<Light>& lights)
{
  if (lights.empty())
  {
    return std::string(kNoLights);
  }
  std::string text;
  for (const Light& light : lights)
  {
    if (!text.empty())
    {
      text += kLightSeparator;
    }
    text += formatLight(light);
  }
  return text;
}

std::vector<std::string_view> surfaceModelKeys(std::string_view model)
{
  if (model == "leadr")
  {
    return {"leadr-tiles", "leadr-roughness", "leadr-scale", "leadr-grid", "leadr-filter"};
  }
  if (model == "microstructure")
  {
    return {"structure", "structure-tiles", "structure-depth", "micro-grid",      "jitter-grid",
            "masking",   "self-shadow",     "micro-brdf",      "micro-roughness", "blinn-exponent"};
  }
  return {};
}

void installShadingValidators(SceneModel& model)
{
  model.setValidator("lights", [](const std::string& text, const std::string& subject)
                     { parseLightList(text, subject); });
}
} // namespace aniso
