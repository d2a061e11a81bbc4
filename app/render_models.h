#pragma once
// The shading-model options of `aniso render`: --model NAME (core/models/models.h), --light
// (repeatable) and --sample-material, kept apart from the environment material's options. A
// model other than as-env is drawn through RenderSettings::installMaterial.
#include "app/cli.h"
#include "core/lights/light.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <string>
#include <vector>

namespace aniso::cli
{
// Adds --model, --light, --sample-material and --compare to COMMAND.
void addModelOptions(Command& command);

// The lights of the command line (--light, in order), or the default pair when none is given.
// Throws UsageError for a bad light or more than LitModelMaterial::kMaxLights.
std::vector<Light> lightsFromOptions(const Arguments& arguments);

// Reads those options into SETTINGS: for a lit model, its installer with the lights and a
// uniform material made from settings.material (n_u, n_v, F0, albedo: see uniformTexel) unless
// --sample-material names one. Throws UsageError for options that do not apply to the model.
void applyModelOptions(const Arguments& arguments, RenderSettings& settings);

// --compare M1,M2,...: renders each model (as-env or a lit model) with SETTINGS and the model
// options, and puts the images side by side, left to right, each SETTINGS.width wide; then
// SETTINGS.width is the mosaic's. Frame times and covered pixels are those of all renders.
RenderResult renderComparison(const Arguments& arguments, RenderSettings& settings);

// What the summary line says about the model: "model banks, 2 light(s), material marble".
std::string modelSummary(const Arguments& arguments);
} // namespace aniso::cli
