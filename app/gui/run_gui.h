#pragma once
// The window of `aniso [MESH] [--session F] [--reference-view wipe|error] [--screenshot FILE
// [--quit]]`.
#include <string>
#include <vector>

namespace aniso::gui
{
// Whether ARGS (the command line without the program name) asks for the window: no arguments,
// a window option first, or a first argument that names a mesh (a path: an existing file, or
// any text with a '.' or '/'; or builtin:sphere|torus|plate) rather than a command.
bool isGuiCommandLine(const std::vector<std::string>& args);

// The window options, for the main help text.
std::string guiUsage();

// Opens the window and runs until it closes; returns the exit code. With --screenshot FILE the
// view is exported once the scene is loaded (and the application quits with --quit);
// --window-screenshot FILE saves the whole window, docks included, once the view has reached
// its quality. --reference-view wipe|error turns View > Reference on with the Reference dock
// showing the wipe or the error map; the window's screenshot then waits for the reference to be
// complete (and fails, exit 1, where the view has none). Throws aniso::cli::UsageError for a bad
// command line and aniso::Error for a failure of a scripted step.
int runGui(const std::vector<std::string>& args);
} // namespace aniso::gui
