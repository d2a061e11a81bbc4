#pragma once
// The LEADR and microstructure models' settings from their declared parameters
// (core/parameters/parameters.cxx): the options of `aniso render --model leadr|microstructure`
// and the window's scene keys share those declarations, and both make the models' materials
// here. What is not a declared parameter (colours, lights, the relief's moments, the TPR map)
// each caller reads its own way.
#include "core/image/image.h"
#include "core/leadr/leadr.h"
#include "core/lights/light.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <functional>
#include <glm/vec3.hpp>
#include <memory>
#include <string_view>
#include <vector>

namespace aniso
{
class EnvironmentLighting;

// The value of a declared parameter by its key: an option of the command line or a scene key.
using DeclaredValues = std::function<const ParameterValue&(std::string_view key)>;

// What a surface model takes besides its declared parameters. The functions are called only
// for the model that reads them, in the order its settings are made (each may throw).
struct SurfaceModelInputs
{
  glm::dvec3 f0{1.0};     // LEADR's and the microstructure's F0
  glm::dvec3 albedo{1.0}; // LEADR's diffuse colour
  std::function<std::vector<Light>()> lights;
  std::function<std::shared_ptr<const LeadrMips>()> leadrMoments;
  std::function<std::shared_ptr<const Image>()> tprMap; // null: the structure does not turn
  // env-lights: LEADR adds the environment's sources as lights (LeadrSettings::
  // environmentLights) when its lighting has them baked.
  bool environmentLights = false;
  // Called with the lighting before LEADR's material is made, to bake what environmentLights
  // reads (the command line; the window's worker has baked it): empty = nothing baked here.
  std::function<void(EnvironmentLighting&)> prepareLighting;
};

// The material of MODEL "leadr" or "microstructure" (for RenderSettings::installMaterial): the
// declared parameters (LEADR's leadr-* keys: tiles, slope grid, base roughness, filter, with the
// environment on; the microstructure's structure, micro-grid, masking, ...) and INPUTS, the
// settings validated; an empty installer for any other model. Throws aniso::Error
// "name: reason" (for an unknown structure, "structure: ...").
MaterialInstaller surfaceModelInstaller(std::string_view model, const DeclaredValues& values,
                                        const SurfaceModelInputs& inputs);

// The built-in relief LEADR filters without a map: 64 x 64 heights of 96 random-phase waves
// (integer frequencies up to 6 per tile, slopes of about 0.3 deviation per axis), tiling.
Image builtinLeadrRelief();
} // namespace aniso
