#pragma once
// The options of `aniso render` for the LEADR and microstructure models (--model leadr,
// --model microstructure): the relief LEADR filters (--height-map, --normal-map or a built-in
// one) and the structure, grid, masking, shadowing and BRDF of the microstructure sampling.
#include "OffscreenRenderer.h"
#include "cli.h"
#include "image/image.h"

namespace aniso::cli
{
// Adds the options to COMMAND (--height-map and --normal-map are the command's own).
void addSurfaceModelOptions(Command& command);

// For --model leadr or microstructure: sets SETTINGS.installMaterial from the options and the
// lights (render_models.h) and returns true; false for any other model, after checking that
// none of these options was given (UsageError otherwise).
bool applySurfaceModelOptions(const Arguments& arguments, RenderSettings& settings);

// The built-in relief of --model leadr without a map: 64 x 64 heights of 96 random-phase waves
// (integer frequencies up to 6 per tile, slopes of about 0.3 deviation per axis), tiling.
Image builtinLeadrRelief();
} // namespace aniso::cli
