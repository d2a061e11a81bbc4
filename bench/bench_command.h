#pragma once
// `aniso bench [--quick] [--out DIR] [--size N]`: time against error of the renderer's
// configurations and of VTK's own PBR anisotropy on the benchmark scene set, against the CPU
// reference integrator; writes a CSV file, a Markdown report and an SVG + PNG plot. Needs an X
// display (xvfb-run where there is none).
#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
// ARGS are the arguments after "bench". Prints progress and the report to OUT; throws
// UsageError for a bad command line and aniso::Error for a run-time failure.
int runBenchCommand(const std::vector<std::string>& args, std::ostream& out);

// One line for `aniso --help`.
std::string benchSummary();
} // namespace aniso::cli
