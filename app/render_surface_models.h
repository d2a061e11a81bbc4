#pragma once
// The options of `aniso render` for the LEADR and microstructure models (--model leadr,
// --model microstructure): the relief LEADR filters (--height-map, --normal-map or a built-in
// one) and the structure, grid, masking, shadowing and BRDF of the microstructure sampling.
#include "app/cli.h"
#include "core/image/image.h"
#include "vtkpasses/render/LeadrMaterial.h"
#include "vtkpasses/render/MicrostructureMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <functional>
#include <string_view>

namespace aniso::cli
{
// Adds the options to COMMAND (--height-map and --normal-map are the command's own).
void addSurfaceModelOptions(Command& command);

// For --model leadr or microstructure: sets SETTINGS.installMaterial from the options and the
// lights (render_models.h) and returns true; false for any other model, after checking that
// none of these options was given (UsageError otherwise).
bool applySurfaceModelOptions(const Arguments& arguments, RenderSettings& settings);

// The value of a declared parameter (core/parameters/parameters.cxx) by its key: an option of the
// command line or a scene key of the window, which share those declarations.
using DeclaredValues = std::function<const ParameterValue&(std::string_view key)>;

// LEADR's settings from the declared leadr-* parameters: tiles, slope grid, base roughness,
// filter; the environment on. The moments, surface colours and lights are the caller's.
LeadrSettings leadrSettingsOf(const DeclaredValues& values);
// The microstructure's structure, options and tiles from the declared parameters (structure,
// micro-grid, masking, ...); lights, F0 and the TPR map are the caller's. Throws aniso::Error
// "structure: reason" for an unknown structure.
MicrostructureSettings microstructureSettingsOf(const DeclaredValues& values);

// The built-in relief of --model leadr without a map: 64 x 64 heights of 96 random-phase waves
// (integer frequencies up to 6 per tile, slopes of about 0.3 deviation per axis), tiling.
Image builtinLeadrRelief();
} // namespace aniso::cli
