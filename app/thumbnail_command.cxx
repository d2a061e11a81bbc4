#include "app/thumbnail_command.h"

#include "app/cli.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "core/image/image.h"
#include "core/parameters/choices.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ViewSettings.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <unistd.h>
#include <vtkPolyData.h>

namespace aniso::cli
{
namespace
{
namespace fs = std::filesystem;

// The largest side: the freedesktop thumbnail sizes go up to 1024 (xx-large).
constexpr int kMaxThumbnailSide = 4096;

// What keeps a thumbnail fast: one frame, few samples, small tables and cubemap. The lookup
// tables of these inputs are cached on disk after the first thumbnail (core/lut/lut_cache).
constexpr int kSamples = 8;
constexpr int kLutSize = 32;
constexpr int kLutSamples = 256;
constexpr int kCubeSize = 64;

Command thumbnailCommand()
{
  Command c;
  c.usage = "aniso thumbnail IN OUT SIZE";
  c.summary = "Write a SIZE x SIZE PNG preview of the mesh file IN (OBJ, PLY, STL, OFF, VTK, VTP, "
              "VTM, glTF, STEP, IGES), or of a built-in mesh builtin:sphere, builtin:torus, "
              "builtin:plate or builtin:disk, to OUT, for file managers: one frame of " +
              std::to_string(kSamples) +
              " samples with the default material under the default environment, transparent "
              "around the part, seen from a three-quarter view above. OUT is written as PNG "
              "whatever its name ends in. Needs an X display; where there is none, run it under "
              "xvfb-run.";
  c.positionals = {"IN", "OUT", "SIZE"};
  Option time;
  time.name = "--time";
  time.spec.type = ParameterType::Text;
  time.spec.help = "print the time of each stage (read, prepare, render, write)";
  c.options.push_back(time);
  c.details = "The desktop's thumbnailer entry (share/thumbnailers/aniso.thumbnailer) runs\n"
              "  aniso thumbnail %i %o %s\n"
              "Example:\n"
              "  aniso thumbnail part.step part.png 256\n";
  return c;
}

int parseSide(const std::string& text)
{
  if (text.find_first_not_of("0123456789") != std::string::npos)
  {
    throw usageError("SIZE", "'" + text + "' is not a whole number of pixels");
  }
  return parseImageSize(text, "SIZE", kMaxThumbnailSide).first;
}

// A temporary PNG beside OUTPUT (same directory, so the rename cannot cross file systems).
fs::path temporaryBeside(const fs::path& output)
{
  const fs::path directory = output.has_parent_path() ? output.parent_path() : fs::path(".");
  return directory /
         ("." + output.filename().string() + "." + std::to_string(::getpid()) + ".tmp.png");
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

std::string thumbnailSummary()
{
  return "write a small PNG preview of a mesh file (for file managers' thumbnails)";
}

int runThumbnail(const std::vector<std::string>& args, std::ostream& out)
{
  const Command command = thumbnailCommand();
  const Arguments a = parseArguments(command, args);
  if (a.helpRequested)
  {
    out << helpText(command);
    return 0;
  }
  const std::string& input = a.positionals[0];
  const fs::path output = a.positionals[1];
  const int side = parseSide(a.positionals[2]);
  std::error_code ec;
  const fs::path directory = output.has_parent_path() ? output.parent_path() : fs::path(".");
  if (!fs::is_directory(directory, ec))
  {
    throw errorAbout(output.string(), "directory '" + directory.string() + "' does not exist");
  }
  if (fs::is_directory(output, ec))
  {
    throw errorAbout(output.string(), "is a directory");
  }

  const auto start = std::chrono::steady_clock::now();
  LoadedMesh mesh;
  if (input.rfind("builtin:", 0) == 0)
  {
    mesh = makeBuiltinMesh(parseBuiltinMesh(input.substr(8), "IN"));
  }
  else
  {
    if (!fs::exists(input, ec))
    {
      throw errorAbout(input, "no such file");
    }
    mesh = loadMesh(input);
  }
  const double readSeconds = secondsSince(start);

  const auto prepareStart = std::chrono::steady_clock::now();
  RenderSettings settings;
  settings.surface = prepareSurface(mesh.polyData, SurfaceOptions{}, input).polyData;
  const ParameterSet parameters; // the declared defaults
  settings.material = materialFromParameters(parameters);
  settings.material.samples = kSamples;
  settings.material.lutSize = kLutSize;
  settings.material.brdfLutSamples = kLutSamples;
  settings.material.environmentSampling = EnvironmentSampling::Off; // no analysis to wait for
  settings.display = displayFromParameters(parameters);
  settings.display.background = BackgroundMode::Transparent;
  settings.environment = openEnvironment(parameters.text("env"));
  settings.environmentRotationDegrees = parameters.real("env-rotation");
  settings.cubeSize = kCubeSize;
  settings.view = defaultViewSettings(); // the three-quarter view of `aniso render` and the window
  settings.width = side;
  settings.height = side;
  settings.frames = 1;
  settings.jitter = false;
  const double prepareSeconds = secondsSince(prepareStart);

  const auto renderStart = std::chrono::steady_clock::now();
  const RenderResult result = renderOffscreen(settings);
  const double renderSeconds = secondsSince(renderStart);

  const auto writeStart = std::chrono::steady_clock::now();
  const fs::path temporary = temporaryBeside(output);
  try
  {
    writeImage(temporary.string(), result.display);
    fs::rename(temporary, output);
  }
  catch (const fs::filesystem_error& e)
  {
    fs::remove(temporary, ec);
    throw errorAbout(output.string(), "could not be written: " + e.code().message());
  }
  catch (...)
  {
    fs::remove(temporary, ec);
    throw;
  }
  const double writeSeconds = secondsSince(writeStart);

  if (a.has("--time"))
  {
    std::ostringstream line;
    line.setf(std::ios::fixed);
    line.precision(1);
    line << "thumbnail: " << output.string() << " (" << side << "x" << side << ") of " << input
         << ": read " << readSeconds * 1e3 << " ms, prepare " << prepareSeconds * 1e3
         << " ms, render " << renderSeconds * 1e3 << " ms, write " << writeSeconds * 1e3
         << " ms, total " << secondsSince(start) * 1e3 << " ms on " << result.renderer << "\n";
    out << line.str();
  }
  return 0;
}
} // namespace aniso::cli
