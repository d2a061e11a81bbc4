#pragma once
// `aniso render [MESH] [options] -o FILE`: headless rendering of one object with an anisotropic
// material to a PNG (display-transformed, 8-bit sRGB) or an EXR (linear radiance, alpha =
// coverage). Needs an X display (xvfb-run where there is none).
#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
// ARGS are the arguments after "render". Prints what it wrote to OUT; throws UsageError for a
// bad command line and aniso::Error for a run-time failure, leaving no partial output behind.
int runRender(const std::vector<std::string>& args, std::ostream& out);

// One line for `aniso --help`.
std::string renderSummary();
} // namespace aniso::cli
