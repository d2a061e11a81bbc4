#pragma once
// `aniso render [MESH...] [options] -o FILE`: headless rendering of one object, or a scene of
// parts (one a mesh file, each with its own material: app/render_parts.h), with anisotropic
// materials to a PNG (display-transformed, 8-bit sRGB) or an EXR (linear radiance, alpha =
// coverage). Needs an X display (xvfb-run where there is none).
#include "vtkpasses/render/ViewSettings.h"

#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
// ARGS are the arguments after "render". Prints what it wrote to OUT and warnings (a mesh file
// of several that could not be loaded, then skipped) to ERR, one line each; throws UsageError
// for a bad command line and aniso::Error for a run-time failure, leaving no partial output
// behind.
int runRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The view `aniso render ARGS` places its camera by (renderOffscreen: placeCamera of
// fittedToFrame): --view, --azimuth and --elevation, --ortho; the three-quarter view
// (defaultViewSettings) when none is given. Throws UsageError as runRender does.
ViewSettings renderViewSettings(const std::vector<std::string>& args);

// One line for `aniso --help`.
std::string renderSummary();
} // namespace aniso::cli
