#include "app/bake_command.h"

#include "app/cli.h"
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/lut/lut.h"
#include "core/lut/lut_cache.h"
#include "core/maps/quaternion_map.h"
#include "core/maps/tpr_map.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace aniso::cli
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kMaxMapSide = 8192; // TPR and irradiance images: 8192^2 RG floats is 512 MB
const char* const kFaceNames[6] = {"px", "nx", "py", "ny", "pz", "nz"};

// ---------------------------------------------------------------- options shared by kinds

Option outputOption(const std::string& valueName, std::string_view help)
{
  Option o = textOption("--output", valueName, help);
  o.alias = "-o";
  o.required = true;
  return o;
}

Option cacheOption()
{
  return textOption("--cache", "DIR|none",
                    "LUT cache directory, or none to bake without the disk cache; by default "
                    "$XDG_CACHE_HOME/aniso, else ~/.cache/aniso");
}

Option envOption()
{
  Option o = parameterOption("env");
  o.valueName = "FILE|builtin:studio";
  return o;
}

Option imageSizeOption(std::string_view help, std::string_view defaultText)
{
  return textOption("--size", "N|WxH", help, defaultText);
}

// ---------------------------------------------------------------- checks before any work

std::string lowercaseExtension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

fs::path parentOf(const fs::path& path)
{
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// The directory that will receive an output must exist (checked before a long bake).
void checkOutputDirectory(const std::string& output, const fs::path& directory)
{
  std::error_code ec;
  if (!fs::exists(directory, ec))
  {
    throw errorAbout(output, "directory '" + directory.string() + "' does not exist");
  }
  if (!fs::is_directory(directory, ec))
  {
    throw errorAbout(output, "'" + directory.string() + "' is not a directory");
  }
  if (::access(directory.c_str(), W_OK) != 0)
  {
    throw errorAbout(output, "directory '" + directory.string() + "' is not writable");
  }
}

// The extension is part of the command line (usage error); the directory is run-time.
void checkOutputFile(const std::string& output, const std::vector<std::string>& extensions)
{
  const std::string ext = lowercaseExtension(output);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
  {
    std::string list;
    for (const auto& e : extensions)
    {
      list += (list.empty() ? "" : " or ") + e;
    }
    throw usageError(output, "output file must end in " + list);
  }
  std::error_code ec;
  if (fs::is_directory(output, ec))
  {
    throw errorAbout(output, "is a directory");
  }
  checkOutputDirectory(output, parentOf(output));
}

// ---------------------------------------------------------------- writing

// Text files get the same guarantee as writeImage: a temporary file renamed into place.
void writeTextAtomically(const std::string& path, const std::string& text)
{
  const fs::path target(path);
  std::string pattern =
      (parentOf(target) / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0)
  {
    throw errorAbout(path, std::strerror(errno));
  }
  // mkstemp creates the file private (0600); give it the mode a plain create would.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  std::size_t written = 0;
  while (written < text.size())
  {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0)
    {
      const int error = errno;
      ::close(fd);
      ::unlink(pattern.c_str());
      throw errorAbout(path, std::strerror(error));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 || std::rename(pattern.c_str(), path.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(pattern.c_str());
    throw errorAbout(path, std::strerror(error));
  }
}

// Several images that only make sense together (a cubemap's faces and levels): written into a
// temporary directory beside them, then renamed into place; on failure none is left.
void writeImageSet(const std::vector<std::pair<fs::path, const Image*>>& files)
{
  const fs::path directory = parentOf(files.front().first);
  std::string pattern = (directory / ".aniso-bake-XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
  {
    throw errorAbout(directory.string(),
                     std::string("cannot create a temporary directory: ") + std::strerror(errno));
  }
  const fs::path staging(pattern);
  std::vector<fs::path> placed;
  std::error_code ec;
  try
  {
    for (const auto& [target, image] : files)
    {
      const fs::path staged = staging / target.filename();
      try
      {
        writeImage(staged.string(), *image);
      }
      catch (const Error& e)
      {
        // Name the file the user asked for, not the staging copy.
        std::string reason = e.what();
        const std::string prefix = staged.string() + ": ";
        if (reason.rfind(prefix, 0) == 0)
        {
          reason.erase(0, prefix.size());
        }
        throw errorAbout(target.string(), reason);
      }
    }
    for (const auto& entry : files)
    {
      fs::rename(staging / entry.first.filename(), entry.first, ec);
      if (ec)
      {
        throw errorAbout(entry.first.string(), ec.message());
      }
      placed.push_back(entry.first);
    }
  }
  catch (...)
  {
    for (const auto& p : placed)
    {
      fs::remove(p, ec);
    }
    fs::remove_all(staging, ec);
    throw;
  }
  fs::remove_all(staging, ec);
}

// ---------------------------------------------------------------- reporting

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string formatDuration(double ms)
{
  char buffer[32];
  if (ms < 1000.0)
  {
    std::snprintf(buffer, sizeof buffer, "%.1f ms", ms);
  }
  else
  {
    std::snprintf(buffer, sizeof buffer, "%.2f s", ms / 1000.0);
  }
  return buffer;
}

std::string cacheDirectoryOf(const Arguments& a)
{
  return a.has("--cache") ? a.text("--cache") : std::string();
}

std::string cacheReport(const LutCache& cache)
{
  const LutCacheStats stats = cache.stats();
  const std::string& directory = cache.directory();
  if (directory.empty())
  {
    return "no disk cache";
  }
  if (stats.diskHits > 0)
  {
    return "read from the cache in " + directory;
  }
  if (stats.diskWriteFailures > 0)
  {
    return "not cached: cannot write to " + directory;
  }
  return "cached in " + directory;
}

AsLobe lobeOf(const Arguments& a)
{
  AsLobe lobe;
  lobe.nu = a.real("--nu");
  lobe.nv = a.real("--nv");
  return lobe;
}

// ---------------------------------------------------------------- the kinds

struct Kind
{
  std::string name;
  std::string summary;
  Command command;
  int (*run)(const Arguments&, std::ostream&);
};

int runHalfVector(const Arguments& a, std::ostream& out)
{
  const std::string output = a.text("--output");
  checkOutputFile(output, {".exr"});
  const AsLobe lobe = lobeOf(a);
  const int size = a.integer("--size");
  LutCache cache(cacheDirectoryOf(a));

  const auto start = Clock::now();
  const auto lut = cache.halfVector(lobe, size);
  const double ms = millisecondsSince(start);

  Image image(size, size, 4);
  image.data = lut->rgba;
  writeImage(output, image);
  out << "halfvector: wrote " << output << " (" << size << "x" << size
      << " RGBA float: h in tangent space, A = log2 p_h) for n_u " << formatNumber(lobe.nu)
      << ", n_v " << formatNumber(lobe.nv) << "\n"
      << "  baked in " << formatDuration(ms) << " (" << cacheReport(cache) << ")\n";
  return 0;
}

int runBrdf(const Arguments& a, std::ostream& out)
{
  const std::string output = a.text("--output");
  checkOutputFile(output, {".exr"});
  const AsLobe lobe = lobeOf(a);
  const int size = a.integer("--size");
  const int samples = a.integer("--samples");
  LutCache cache(cacheDirectoryOf(a));

  const auto start = Clock::now();
  const auto lut = cache.brdf(lobe, size, samples);
  const double ms = millisecondsSince(start);

  Image image(size, size, 2);
  image.data = lut->rg;
  writeImage(output, image);
  out << "brdf: wrote " << output << " (" << size << "x" << size
      << " RG float: R = s, G = b, albedo = F0 s + b) for n_u " << formatNumber(lobe.nu) << ", n_v "
      << formatNumber(lobe.nv) << ", " << samples << " samples\n"
      << "  baked in " << formatDuration(ms) << " (" << cacheReport(cache) << ")\n";
  return 0;
}

int runQuaternion(const Arguments& a, std::ostream& out)
{
  const std::string input = a.positionals.at(0);
  const std::string output = a.text("--output");
  checkOutputFile(output, {".exr"});

  ImageInfo info;
  const Image normals = readImage(input, &info);
  const std::string encoding = a.text("--encoding");
  const bool unorm = encoding == "auto" ? info.integerFormat : encoding == "unorm";

  QuaternionBakeStats stats;
  const auto start = Clock::now();
  Image map;
  try
  {
    map = bakeQuaternionMap(normals, unorm, &stats);
  }
  catch (const Error& e)
  {
    throw errorAbout(input, e.what()); // the core names "normal map"; the user needs the file
  }
  const double ms = millisecondsSince(start);

  writeImage(output, map);
  out << "quaternion: wrote " << output << " (" << map.width << "x" << map.height
      << " RGBA float: RGB = (a, b, c), A = 1) from " << input << " ("
      << (unorm ? "n = 2 c - 1" : "n as stored") << ")\n"
      << "  texels " << stats.texels << ", non-unit " << stats.nonUnit << ", invalid "
      << stats.invalid << ", antipodal " << stats.antipodal << "\n"
      << "  baked in " << formatDuration(ms) << "\n";
  return 0;
}

int runTpr(const Arguments& a, std::ostream& out)
{
  const bool fromImage = a.has("--angle-image");
  if (fromImage && a.has("--pattern"))
  {
    throw usageError("--angle-image", "cannot be combined with --pattern");
  }
  if (fromImage && a.has("--size"))
  {
    throw usageError("--size", "not used with --angle-image (the map has the image's size)");
  }
  TprParams params;
  if (!fromImage)
  {
    try
    {
      params = parseTprPattern(a.text("--pattern"));
    }
    catch (const Error& e)
    {
      throw usageError("--pattern", e.what());
    }
  }
  const auto [width, height] = parseImageSize(a.text("--size"), "--size", kMaxMapSide);
  const std::string output = a.text("--output");
  checkOutputFile(output, {".exr"});

  Image map;
  double ms = 0.0;
  std::string source;
  if (fromImage)
  {
    const std::string input = a.text("--angle-image");
    const Image angles = readImage(input);
    const auto start = Clock::now();
    try
    {
      map = tprFromAngleImage(angles);
    }
    catch (const Error& e)
    {
      throw errorAbout(input, e.what());
    }
    ms = millisecondsSince(start);
    source = "angle image " + input;
  }
  else
  {
    const auto start = Clock::now();
    map = bakeTprMap(params, width, height);
    ms = millisecondsSince(start);
    source = "pattern " + a.text("--pattern");
  }
  writeImage(output, map);
  out << "tpr: wrote " << output << " (" << map.width << "x" << map.height
      << " RG float: rotated tangent (x, y)) from " << source << "\n"
      << "  baked in " << formatDuration(ms) << "\n";
  return 0;
}

// -o DIR (existing, or ending in '/') writes DIR/cube_*; anything else is a file prefix
// (a trailing .exr is dropped).
fs::path cubemapPrefix(const std::string& output)
{
  std::error_code ec;
  if (output.back() == '/' || fs::is_directory(output, ec))
  {
    return fs::path(output) / "cube";
  }
  fs::path prefix(output);
  if (lowercaseExtension(output) == ".exr")
  {
    prefix.replace_extension();
  }
  return prefix;
}

int runCubemap(const Arguments& a, std::ostream& out)
{
  const std::string spec = a.text("--env");
  const int size = a.integer("--size");
  const int supersample = a.integer("--supersample");
  const std::string output = a.text("--output");
  const fs::path prefix = cubemapPrefix(output);
  checkOutputDirectory(output, parentOf(prefix));

  const auto start = Clock::now();
  const auto env = openEnvironment(spec);
  const Cubemap cube = buildCubemap(*env, size, supersample);
  const double ms = millisecondsSince(start);

  std::vector<std::pair<fs::path, const Image*>> files;
  for (std::size_t level = 0; level < cube.mips.size(); ++level)
  {
    for (std::size_t face = 0; face < 6; ++face)
    {
      const std::string name = prefix.filename().string() + "_" + kFaceNames[face] + "_m" +
                               std::to_string(level) + ".exr";
      files.emplace_back(prefix.parent_path() / name, &cube.mips[level][face]);
    }
  }
  writeImageSet(files);
  out << "cubemap: wrote 6 faces x " << cube.mips.size() << " levels (" << size << "x" << size
      << " down to " << cube.mips.back()[0].width << "x" << cube.mips.back()[0].height
      << ", RGB float) of " << spec << "\n"
      << "  " << prefix.string() << "_{px,nx,py,ny,pz,nz}_m{0.." << cube.mips.size() - 1
      << "}.exr\n"
      << "  baked in " << formatDuration(ms) << "\n";
  return 0;
}

std::string sh9Text(const Sh9& sh, const std::string& spec)
{
  static const int lm[9][2] = {{0, 0},  {1, -1}, {1, 0}, {1, 1}, {2, -2},
                               {2, -1}, {2, 0},  {2, 1}, {2, 2}};
  std::ostringstream s;
  s << "# aniso SH9: real spherical-harmonic coefficients c_lm of the radiance of " << spec << "\n"
    << "# world Z up, unit d = (x, y, z): Y00 = 0.282095, Y1-1 = 0.488603 y, Y10 = 0.488603 z,\n"
    << "# Y11 = 0.488603 x, Y2-2 = 1.092548 x y, Y2-1 = 1.092548 y z, Y20 = 0.315392 (3 z^2 - 1),\n"
    << "# Y21 = 1.092548 x z, Y22 = 0.546274 (x^2 - y^2)\n"
    << "# irradiance E(n) = sum of A_l c_lm Y_lm(n), A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4\n"
    << "# l m R G B\n";
  for (std::size_t k = 0; k < 9; ++k)
  {
    s << lm[k][0] << " " << lm[k][1] << " " << formatNumber(sh[k].x) << " " << formatNumber(sh[k].y)
      << " " << formatNumber(sh[k].z) << "\n";
  }
  return s.str();
}

int runIrradiance(const Arguments& a, std::ostream& out)
{
  const std::string spec = a.text("--env");
  const std::string output = a.text("--output");
  checkOutputFile(output, {".txt", ".exr"});
  const bool asImage = lowercaseExtension(output) == ".exr";
  if (!asImage && a.has("--size"))
  {
    throw usageError("--size", "only used for an .exr output");
  }
  const auto [width, height] = parseImageSize(a.text("--size"), "--size", kMaxMapSide);

  const auto start = Clock::now();
  const auto env = openEnvironment(spec);
  const Sh9 sh = projectSh9(*env);
  if (!asImage)
  {
    const double ms = millisecondsSince(start);
    writeTextAtomically(output, sh9Text(sh, spec));
    out << "irradiance: wrote " << output << " (9 RGB SH coefficients, 'l m R G B' per line) of "
        << spec << "\n"
        << "  projected in " << formatDuration(ms) << "\n";
    return 0;
  }
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const glm::dvec2 uv((x + 0.5) / width, 1.0 - (y + 0.5) / height);
      const glm::dvec3 e = irradianceSh9(sh, equirectToDirection(uv));
      for (int c = 0; c < 3; ++c)
      {
        image.at(x, y, c) = static_cast<float>(e[c]);
      }
    }
  }
  const double ms = millisecondsSince(start);
  writeImage(output, image);
  out << "irradiance: wrote " << output << " (" << width << "x" << height
      << " RGB float equirectangular irradiance E(n)) of " << spec << "\n"
      << "  projected and rendered in " << formatDuration(ms) << "\n";
  return 0;
}

const std::vector<Kind>& kinds()
{
  static const std::vector<Kind> table = []
  {
    std::vector<Kind> k;
    k.push_back(
        {"halfvector",
         "half-vector lookup table of the AS lobe (RGBA EXR)",
         {"aniso bake halfvector [options] -o FILE.exr",
          "Bakes the half-vector lookup table of the Ashikhmin-Shirley lobe: texel (i, j) holds "
          "the\nhalf vector sampled at xi = ((i + 0.5) / N, (j + 0.5) / N).",
          {},
          {parameterOption("nu"), parameterOption("nv"), parameterOption("lut-size", "--size"),
           cacheOption(), outputOption("FILE.exr", "output EXR file")},
          "Output: N x N RGBA 32-bit float; RGB = h in tangent space (t = +X, b = +Y, n = +Z),\n"
          "A = log2 p_h(h). Row j of the file (row 0 first) holds xi2 = (j + 0.5) / N.\n"
          "Example: aniso bake halfvector --nu 20000 --nv 70 --size 64 -o hv.exr\n"},
         runHalfVector});
    k.push_back(
        {"brdf",
         "BRDF size/bias lookup table (RG EXR)",
         {"aniso bake brdf [options] -o FILE.exr",
          "Bakes the BRDF lookup table: per view direction, the size s and bias b of the\n"
          "directional albedo F0 s + b, by importance sampling.",
          {},
          {parameterOption("nu"), parameterOption("nv"), parameterOption("lut-size", "--size"),
           parameterOption("lut-samples", "--samples"), cacheOption(),
           outputOption("FILE.exr", "output EXR file")},
          "Output: N x N RG 32-bit float, R = s, G = b. Texel (i, j) (row 0 first) is at\n"
          "u = (i + 0.5) / N = (2/pi) atan(|b.v| / |t.v|), v = (j + 0.5) / N = sqrt(n.v).\n"
          "Example: aniso bake brdf --nu 20000 --nv 70 --size 64 --samples 1024 -o brdf.exr\n"},
         runBrdf});
    Option encoding = textOption(
        "--encoding", "MODE",
        "how texel values encode the normal: unorm (n = 2 c - 1), snorm (as stored), or auto "
        "(unorm for integer files, snorm for float files)",
        "auto");
    encoding.choices = {"auto", "unorm", "snorm"};
    k.push_back(
        {"quaternion",
         "quaternion map from a normal map (RGBA EXR)",
         {"aniso bake quaternion [options] NORMALMAP -o FILE.exr",
          "Bakes a quaternion map from a tangent-space normal map (any format OpenImageIO "
          "reads:\n8/16-bit or float, 3 or 4 channels) and counts the texels that needed care.",
          {"NORMALMAP"},
          {encoding, outputOption("FILE.exr", "output EXR file")},
          "Output: RGBA 32-bit float of the normal map's size, RGB = (a, b, c), A = 1.\n"
          "Prints the texel count and how many were non-unit, invalid or antipodal (z = -1).\n"
          "Example: aniso bake quaternion normals.png -o q.exr\n"},
         runQuaternion});
    k.push_back(
        {"tpr",
         "tangent-plane rotation map from a pattern or angle image (RG EXR)",
         {"aniso bake tpr [options] -o FILE.exr",
          "Bakes a tangent-plane rotation map: the rotated tangent (x, y) per texel, from a "
          "named\npattern or from an angle image.",
          {},
          {textOption("--pattern", "SPEC",
                      "linear[:DEG], circular[:U,V], radial[:U,V], spiral[:U,V[:PITCH]] or wave",
                      "linear:0"),
           textOption("--angle-image", "FILE",
                      "image whose first channel in [0, 1] is the angle in [0, pi] from +u "
                      "(instead of --pattern)"),
           imageSizeOption("map size, N for N x N", "512"),
           outputOption("FILE.exr", "output EXR file")},
          "Output: W x H RG 32-bit float, (x, y) = the unit tangent; row 0 is the top (v = 1).\n"
          "Example: aniso bake tpr --pattern circular:0.5,0.5 --size 512x512 -o tpr.exr\n"},
         runTpr});
    Option supersample = textOption("--supersample", "N", "samples per texel along each axis");
    supersample.spec.type = ParameterType::Integer;
    supersample.spec.defaultValue = {2.0, 2.0, 2.0};
    supersample.spec.minimum = 1.0;
    supersample.spec.maximum = 16.0;
    k.push_back(
        {"cubemap",
         "float cubemap faces and mips of an environment (RGB EXRs)",
         {"aniso bake cubemap [options] -o PREFIX|DIR/",
          "Bakes an environment into float cubemap faces with a full mip chain.",
          {},
          {envOption(), parameterOption("cube-size", "--size"), supersample,
           outputOption("PREFIX|DIR/", "file prefix, or an existing directory for files cube_*")},
          "Output: RGB 32-bit float EXR files PREFIX_F_mK.exr for the faces F = px nx py ny pz nz\n"
          "(OpenGL order +X -X +Y -Y +Z -Z) and the levels K = 0 (N x N) to log2 N (1 x 1).\n"
          "Row 0 of a face is OpenGL's t = 0 (upload rows in file order). All files are\n"
          "written or none.\n"
          "Example: aniso bake cubemap --env builtin:studio --size 256 -o out/studio\n"
          "writes out/studio_px_m0.exr (256 x 256) ... out/studio_nz_m8.exr (1 x 1).\n"},
         runCubemap});
    k.push_back(
        {"irradiance",
         "SH9 irradiance of an environment (text, or EXR)",
         {"aniso bake irradiance [options] -o FILE.txt|FILE.exr",
          "Projects an environment onto 9 spherical harmonics (bands 0 to 2), the diffuse\n"
          "lighting of the renderer.",
          {},
          {envOption(), imageSizeOption("equirectangular size of an .exr output", "128x64"),
           outputOption("FILE.txt|FILE.exr", "output: coefficients (.txt) or irradiance (.exr)")},
          "Output .txt: '#' comment lines, then 9 lines 'l m R G B' of radiance coefficients\n"
          "in the order (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2); the irradiance\n"
          "is E(n) = sum A_l c_lm Y_lm(n) with A_0 = pi, A_1 = 2 pi/3, A_2 = pi/4.\n"
          "Output .exr: W x H RGB 32-bit float equirectangular map of E(n) (Blender's layout);\n"
          "the diffuse radiance of albedo a is a E / pi.\n"
          "Example: aniso bake irradiance --env builtin:studio -o sh9.txt\n"},
         runIrradiance});
    return k;
  }();
  return table;
}

std::string kindNames()
{
  std::string s;
  for (const auto& kind : kinds())
  {
    s += (s.empty() ? "" : ", ") + kind.name;
  }
  return s;
}

std::string bakeHelp()
{
  const std::size_t width = terminalWidth();
  return "Usage: aniso bake KIND [options] -o OUTPUT\n\n" +
         wrapText("Bakes lookup tables, maps and environment data to files (32-bit float EXR, "
                  "or text).",
                  0, width) +
         "\n\nKinds:\n" + bakeKindsSummary(2) + "\n" +
         wrapText("Run 'aniso bake KIND --help' for the options of a kind. Exit codes: 0 done, 1 "
                  "run-time failure, 2 bad command line; on failure no output file is left "
                  "behind.",
                  0, width) +
         "\n";
}
} // namespace

std::string bakeKindsSummary(int indent)
{
  std::string s;
  for (const auto& kind : kinds())
  {
    s += std::string(static_cast<std::size_t>(indent), ' ') + kind.name +
         std::string(12 - kind.name.size(), ' ') +
         wrapText(kind.summary, static_cast<std::size_t>(indent) + 12, terminalWidth()) + "\n";
  }
  return s;
}

int runBake(const std::vector<std::string>& args, std::ostream& out)
{
  if (args.empty())
  {
    throw usageError("bake", "missing KIND (one of " + kindNames() + ")");
  }
  if (args[0] == "-h" || args[0] == "--help")
  {
    out << bakeHelp();
    return 0;
  }
  for (const auto& kind : kinds())
  {
    if (kind.name == args[0])
    {
      const Arguments parsed =
          parseArguments(kind.command, std::vector<std::string>(args.begin() + 1, args.end()));
      if (parsed.helpRequested)
      {
        out << helpText(kind.command);
        return 0;
      }
      return kind.run(parsed, out);
    }
  }
  if (args[0].size() > 1 && args[0][0] == '-')
  {
    throw usageError(args[0], "expected a KIND before options (one of " + kindNames() + ")");
  }
  throw usageError(args[0], "unknown bake kind (one of " + kindNames() + ")");
}
} // namespace aniso::cli
