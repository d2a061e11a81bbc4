#pragma once
// `aniso bake KIND [options] -o OUTPUT`: the offline bakers of the core as command-line tools
// (lookup tables, quaternion and TPR maps, cubemaps, SH9 irradiance), writing float EXR or text.
#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
// ARGS are the arguments after "bake". Prints what it made to OUT; throws UsageError for a bad
// command line and aniso::Error for a run-time failure, leaving no partial output behind.
int runBake(const std::vector<std::string>& args, std::ostream& out);

// The kinds, one line each, indented by INDENT spaces (for the help texts).
std::string bakeKindsSummary(int indent);
} // namespace aniso::cli
