#pragma once
// `aniso thumbnail IN OUT SIZE`: a SIZE x SIZE PNG preview of the mesh file IN (or a built-in
// mesh, builtin:NAME) for file managers (the freedesktop thumbnailer entry calls it as
// `aniso thumbnail %i %o %s`). One frame of few samples with small lookup tables and a small
// environment cubemap, drawn offscreen like `aniso render` (an X display is needed), the
// declared default material under the declared default environment, transparent around the
// part, seen from a three-quarter view above. OUT is written as PNG whatever its name ends in
// (thumbnailers pass temporary names), through a temporary file beside it and a rename, so a
// failed run leaves nothing at OUT.
#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
// ARGS are the arguments after "thumbnail". Prints nothing unless --time is given (then one
// line of the stages' times); throws UsageError for a bad command line and aniso::Error naming
// the file for a run-time failure.
int runThumbnail(const std::vector<std::string>& args, std::ostream& out);

// One line for `aniso --help`.
std::string thumbnailSummary();
} // namespace aniso::cli
