#pragma once
// The scene keys of the shading model (core/models/models.h): which model draws the surface, the
// built-in sample material the lit models use, and the lights. They live in the SceneModel like
// every other key, so sessions, undo and the view handle them with no extra plumbing. Qt-free.
#include "core/lights/light.h"
#include "scene/SceneModel.h"

#include <string>
#include <string_view>
#include <vector>

namespace aniso
{
// The sample-material value meaning "the uniform material of the environment model's
// parameters" (uniformTexel).
inline constexpr std::string_view kUniformSampleMaterial = "uniform";

// Lights in the "lights" key: formatLight texts separated by ';'.
inline constexpr char kLightSeparator = ';';

// "model" (a choice of shadingModels()' names, as-env first), "sample-material" (uniform, then
// sampleMaterials()' names) and "lights" (text, by default a key light from the upper front left
// and a weaker one from the right, as `aniso render` uses).
std::vector<SceneKey> shadingSceneKeys();

// The "lights" text of a scene without lights (declared texts cannot be empty).
inline constexpr std::string_view kNoLights = "none";

// The lights of TEXT (blanks around each light allowed; "none" or an empty text is no light).
// Throws aniso::Error "SUBJECT: reason" for a light parseLight rejects or more than
// LitModelMaterial's maximum of 8.
std::vector<Light> parseLightList(const std::string& text, const std::string& subject);
// The text parseLightList reads back to the same lights ("none" for none).
std::string formatLightList(const std::vector<Light>& lights);

// Lights a lit model can draw at once (LitModelMaterial::kMaxLights).
constexpr int kMaxSceneLights = 8;

// The declared parameters (core/parameters/parameters.h) of a surface model: LEADR's for "leadr", the
// microstructure's for "microstructure", none for any other model.
std::vector<std::string_view> surfaceModelKeys(std::string_view model);

// Makes MODEL reject a "lights" text that parseLightList rejects.
void installShadingValidators(SceneModel& model);
} // namespace aniso
