#pragma once
// The options of `aniso render` for the LEADR and microstructure models (--model leadr,
// --model microstructure): the relief LEADR filters (--height-map, --normal-map or a built-in
// one) and the structure, grid, masking, shadowing and BRDF of the microstructure sampling.
#include "app/cli.h"
#include "vtkpasses/render/OffscreenRenderer.h"

namespace aniso::cli
{
// Adds the options to COMMAND (--height-map and --normal-map are the command's own).
void addSurfaceModelOptions(Command& command);

// For --model leadr or microstructure: sets SETTINGS.installMaterial from the options and the
// lights (render_models.h) and returns true; false for any other model, after checking that
// none of these options was given (UsageError otherwise).
bool applySurfaceModelOptions(const Arguments& arguments, RenderSettings& settings);
} // namespace aniso::cli
