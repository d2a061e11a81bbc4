#include "vtkpasses/mesh/MeshLoader.h"

#include "core/error.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/LineSet.h"
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/OffReader.h"
#include "vtkpasses/mesh/PlyReader.h"
#include "vtkpasses/mesh/StlReader.h"
#include "vtkpasses/mesh/VtkErrorText.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <new>
#include <optional>
#include <set>
#include <system_error>
#include <vector>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
const char* const kExtensions[] = {".obj",  ".ply", ".stl",  ".off", ".vtk",  ".vtp", ".vtu", ".vtm",
                                   ".gltf", ".glb", ".step", ".stp", ".iges", ".igs"};

std::mutex& loadMutex()
{
  static std::mutex instance;
  return instance;
}

std::string lowerExtension(const std::filesystem::path& path)
{
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// A .vtm is a small index of the files that hold its data (file="..." attributes, relative to
// its folder): the reader program's memory budget counts those files too. Indexes beyond 16 MiB
// are not looked into (they count as themselves).
uintmax_t readingSize(const std::filesystem::path& file, const std::string& ext, uintmax_t size)
{
  constexpr uintmax_t kMaxIndexBytes = 16u << 20;
  if (ext != ".vtm" || size > kMaxIndexBytes)
  {
    return size;
  }
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  uintmax_t total = size;
  const std::string key = "file=\"";
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
  {
    at += key.size();
    const size_t end = text.find('"', at);
    if (end == std::string::npos)
    {
      break;
    }
    std::error_code ec;
    const std::filesystem::path part = file.parent_path() / text.substr(at, end - at);
    const uintmax_t partSize = std::filesystem::file_size(part, ec);
    if (!ec)
    {
      total += partSize;
    }
    at = end;
  }
  return total;
}

// The reader program's arguments that carry OPTIONS (CadReader.h).
std::vector<std::string> readArguments(const std::string& ext, const MeshReadOptions& options)
{
  if (!isCadExtension(ext))
  {
    return {};
  }
  const CadDeflection& d = options.cadDeflection;
  return {std::string(d.absolute ? kCadAbsoluteDeflectionKey : kCadRelativeDeflectionKey) + "=" +
              formatNumber(d.value),
          std::string(kCadAngleKey) + "=" + formatNumber(options.cadAngleDegrees)};
}

vtkSmartPointer<vtkPolyData> readByExtension(const std::string& path, const std::string& ext,
                                             uintmax_t fileSize, std::vector<std::string>& warnings,
                                             const MeshReadOptions& options)
{
  if (ext == ".ply")
  {
    return readPly(path);
  }
  if (ext == ".stl")
  {
    return readStl(path, warnings);
  }
  if (ext == ".off")
  {
    return readOff(path);
  }
  return readInReaderProcess(path, ext, fileSize, warnings, readArguments(ext, options));
}

// Existence, type, readability and size, before any reader sees the file.
uintmax_t checkFile(const std::filesystem::path& file, const std::string& path)
{
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
  {
    throw errorAbout(path, "no such file");
  }
  if (std::filesystem::is_directory(status))
  {
    throw errorAbout(path, "is a directory, not a mesh file");
  }
  std::ifstream stream(file, std::ios::binary);
  if (!stream)
  {
    throw errorAbout(path, "cannot be opened for reading");
  }
  const auto size = std::filesystem::file_size(file, ec);
  if (ec)
  {
    throw errorAbout(path, "cannot read its size: " + ec.message());
  }
  if (size == 0)
  {
    throw errorAbout(path, "empty file");
  }
  return size;
}
} // namespace

std::string meshFilePatterns()
{
  std::string patterns;
  for (const char* ext : kExtensions)
  {
    patterns += (patterns.empty() ? "*" : " *") + std::string(ext);
  }
  return patterns;
}

namespace
{
// vtkOBJReader reads numbers with an input stream, which stops at "nan" or "inf" and leaves 0 or
// the previous line's value in their place: a NaN texture coordinate or normal in the file would
// arrive finite and wrong, where sanitizeSurface cannot see it. So the file's own vt and vn
// lines are checked, and the counts decide as sanitizeSurface does for the other readers.
struct ObjNonFiniteEntries
{
  int64_t tcoords = 0; // vt lines with a NaN or Inf among their first two numbers
  int64_t normals = 0; // vn lines with a NaN or Inf among their three numbers
};

ObjNonFiniteEntries countObjNonFiniteEntries(const std::string& path)
{
  ObjNonFiniteEntries counts;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line))
  {
    const char* p = line.c_str();
    while (*p == ' ' || *p == '\t')
    {
      ++p;
    }
    int fields = 0;
    int64_t* count = nullptr;
    if (std::strncmp(p, "vt", 2) == 0 && (p[2] == ' ' || p[2] == '\t'))
    {
      fields = 2;
      count = &counts.tcoords;
    }
    else if (std::strncmp(p, "vn", 2) == 0 && (p[2] == ' ' || p[2] == '\t'))
    {
      fields = 3;
      count = &counts.normals;
    }
    if (!count)
    {
      continue;
    }
    p += 2;
    for (int f = 0; f < fields; ++f)
    {
      char* end = nullptr;
      const double value = std::strtod(p, &end);
      if (end == p)
      {
        break; // not a number: the reader's own error handling applies
      }
      if (!std::isfinite(value))
      {
        ++*count;
        break;
      }
      p = end;
    }
  }
  return counts;
}

void removeActiveArray(vtkDataSetAttributes* data, vtkDataArray* array)
{
  if (array && array->GetName())
  {
    data->RemoveArray(array->GetName());
  }
}

// The file's texture coordinates or normals go when one of its vt or vn lines is NaN or Inf.
void dropObjNonFiniteArrays(vtkPolyData* raw, const ObjNonFiniteEntries& counts)
{
  vtkPointData* pd = raw->GetPointData();
  if (counts.tcoords > 0)
  {
    removeActiveArray(pd, pd->GetTCoords());
    pd->RemoveArray("TCoords");
  }
  if (counts.normals > 0)
  {
    removeActiveArray(pd, pd->GetNormals());
    pd->RemoveArray("Normals");
  }
}

// The lower-case extension of PATH, one of kExtensions; else an error naming the file.
std::string knownExtension(const std::filesystem::path& file, const std::string& path)
{
  const std::string ext = lowerExtension(file);
  if (std::find(std::begin(kExtensions), std::end(kExtensions), ext) == std::end(kExtensions))
  {
    const std::string what =
        ext.empty() ? "no file extension" : "unknown mesh format '" + ext + "'";
    throw errorAbout(path, what + " (expected " + meshFilePatterns() + ")");
  }
  return ext;
}

// READ's errors as aniso::Error "PATH: reason".
template <typename Read>
auto readingErrorsNamed(const std::string& path, Read&& read)
{
  try
  {
    return read();
  }
  catch (const Error&)
  {
    throw;
  }
  catch (const std::bad_alloc&)
  {
    throw errorAbout(path, "the reader ran out of memory (corrupt sizes in the file?)");
  }
  catch (const std::exception& e)
  {
    throw errorAbout(path, std::string("the reader failed: ") + e.what());
  }
}

// The parts' names: the file's, the stem where it gives none, " 2", " 3", ... on repeats.
// The formats whose files hold parts (loadMeshBlocks reads them in the reader program).
bool hasBlocks(const std::string& ext)
{
  static const std::set<std::string> withBlocks = {".obj",  ".vtm", ".gltf", ".glb",
                                                   ".step", ".stp", ".iges", ".igs"};
  return withBlocks.count(ext) > 0;
}

// The reader's material and placement of a part, into BLOCK; what is malformed is dropped with
// a warning "SUBJECT: reason".
// Relative map paths in the material are read against DIRECTORY (the file's).
void adoptFinishAndPlace(const ReaderBlock& raw, const std::string& directory,
                         const std::string& subject, MeshBlock& block,
                         std::vector<std::string>& warnings)
{
  if (!raw.material.empty())
  {
    try
    {
      const MaterialLibrary library = materialLibraryFromJson(raw.material, directory, subject);
      if (library.materials().size() != 1)
      {
        throw errorAbout(subject, "the reader sent " + std::to_string(library.materials().size()) +
                                      " materials for one part");
      }
      block.material = library.materials().front();
    }
    catch (const Error& e)
    {
      warnings.push_back(std::string(e.what()) + " (its material is left out)");
    }
  }
  try
  {
    checkPlacement(raw.placement, subject);
    block.placement = raw.placement;
  }
  catch (const Error& e)
  {
    warnings.push_back(std::string(e.what()) + " (placed where its coordinates are)");
  }
}

std::vector<std::string> uniqueNames(const std::vector<ReaderBlock>& blocks,
                                     const std::string& stem)
{
  std::set<std::string> used;
  std::vector<std::string> names;
  for (const ReaderBlock& block : blocks)
  {
    const std::string base = block.name.empty() ? stem : block.name;
    std::string name = base;
    for (int repeat = 2; used.count(name) > 0; ++repeat)
    {
      name = base + " " + std::to_string(repeat);
    }
    used.insert(name);
    names.push_back(name);
  }
  return names;
}
} // namespace

CadDeflection parseCadDeflection(const std::string& text, const std::string& subject)
{
  CadDeflection deflection;
  std::string number = text;
  if (number.size() > 2 && number.compare(number.size() - 2, 2, "mm") == 0)
  {
    deflection.absolute = true;
    number.resize(number.size() - 2);
  }
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0.0))
  {
    throw errorAbout(subject, "'" + text +
                                  "': expected a positive fraction of a part's size (0.001) or a "
                                  "length in millimetres (0.05mm)");
  }
  // A relative one within the declared cad-deflection's range (the window's).
  const ParameterSpec& spec = parameterSpec("cad-deflection");
  if (!deflection.absolute && !(value >= spec.minimum && value <= spec.maximum))
  {
    throw errorAbout(subject, "'" + text +
                                  "': a relative deflection is a fraction of the part's "
                                  "diagonal from " +
                                  formatNumber(spec.minimum) + " to " + formatNumber(spec.maximum) +
                                  " (for a length, write it in millimetres: " + text + "mm)");
  }
  deflection.value = value;
  return deflection;
}

std::string toString(const CadDeflection& deflection)
{
  return formatNumber(deflection.value) + (deflection.absolute ? "mm" : "");
}

namespace
{
// The file read by its reader, unsanitised, with what the reader said in REPORT (loadMesh's
// reading; the caller holds the load lock and a message capture).
vtkSmartPointer<vtkPolyData> readWhole(const std::string& path, const std::string& ext,
                                       uintmax_t fileSize, const MeshReadOptions& options,
                                       MeshReport& report, ObjNonFiniteEntries& objNonFinite)
{
  report.source = path;
  vtkSmartPointer<vtkPolyData> raw = readingErrorsNamed(
      path, [&] { return readByExtension(path, ext, fileSize, report.readerWarnings, options); });
  if (ext == ".obj")
  {
    objNonFinite = countObjNonFiniteEntries(path);
    dropObjNonFiniteArrays(raw, objNonFinite);
  }
  return raw;
}

// "NAME lines", made unique against TAKEN (which receives it).
std::string linePartName(const std::string& name, std::set<std::string>& taken)
{
  std::string candidate = name + " lines";
  for (int i = 2; taken.count(candidate); ++i)
  {
    candidate = name + " lines " + std::to_string(i);
  }
  taken.insert(candidate);
  return candidate;
}

// The line part of RAW's polylines, named NAME, or nothing (and a warning "SUBJECT: reason" in
// WARNINGS) when none of its lines is usable.
std::optional<MeshBlock> linePart(vtkPolyData* raw, const std::string& name,
                                  const std::string& path, const MeshReport& surfaceReport,
                                  std::vector<std::string>& warnings)
{
  MeshBlock block;
  block.name = name;
  block.lines = true;
  block.mesh.report.source = path;
  block.mesh.report.readerWarnings = surfaceReport.readerWarnings;
  try
  {
    block.mesh.polyData = sanitizeLines(raw, path + ": part " + name, block.mesh.report);
  }
  catch (const Error& e)
  {
    warnings.push_back(e.what());
    return std::nullopt;
  }
  return block;
}
} // namespace

LoadedMesh loadMesh(const std::string& path, const MeshReadOptions& options)
{
  const std::filesystem::path file(path);
  const std::string ext = knownExtension(file, path);
  const uintmax_t fileSize = readingSize(file, ext, checkFile(file, path));

  std::lock_guard<std::mutex> lock(loadMutex());
  LoadedMesh mesh;
  // The validation's own VTK calls (polygon triangulation) stay quiet too.
  VtkMessageCapture capture;
  ObjNonFiniteEntries objNonFinite;
  vtkSmartPointer<vtkPolyData> raw =
      readWhole(path, ext, fileSize, options, mesh.report, objNonFinite);
  mesh.polyData = sanitizeSurface(raw, path, mesh.report);
  mesh.report.invalidTCoords += objNonFinite.tcoords;
  mesh.report.invalidNormals += objNonFinite.normals;
  return mesh;
}

LoadedBlocks loadMeshBlocks(const std::string& path, const MeshReadOptions& options)
{
  const std::filesystem::path file(path);
  const std::string ext = knownExtension(file, path);
  const std::string stem = file.stem().string();
  LoadedBlocks loaded;
  const uintmax_t fileSize = readingSize(file, ext, checkFile(file, path));
  if (!hasBlocks(ext))
  {
    std::lock_guard<std::mutex> lock(loadMutex());
    VtkMessageCapture capture;
    MeshBlock block;
    block.name = stem;
    ObjNonFiniteEntries objNonFinite;
    vtkSmartPointer<vtkPolyData> raw =
        readWhole(path, ext, fileSize, options, block.mesh.report, objNonFinite);
    if (!hasLineCells(raw))
    {
      block.mesh.polyData = sanitizeSurface(raw, path, block.mesh.report);
      loaded.blocks.push_back(std::move(block));
      return loaded;
    }
    // Its polylines are a part of their own; the faces, when it has any, another.
    std::set<std::string> taken = {stem};
    const std::vector<std::string> readerWarnings = block.mesh.report.readerWarnings;
    if (hasFaceCells(raw))
    {
      block.mesh.polyData = sanitizeSurface(raw, path, block.mesh.report);
      block.mesh.report.nonSurfaceCellsDropped -= raw->GetNumberOfLines();
      loaded.blocks.push_back(std::move(block));
    }
    MeshBlock lines;
    lines.name = linePartName(stem, taken);
    lines.lines = true;
    lines.mesh.report.source = path;
    lines.mesh.report.readerWarnings = readerWarnings;
    try
    {
      // A file of lines only: its reason is the file's, as loadMesh gives a surface's.
      lines.mesh.polyData = sanitizeLines(
          raw, loaded.blocks.empty() ? path : path + ": part " + lines.name, lines.mesh.report);
      loaded.blocks.push_back(std::move(lines));
    }
    catch (const Error& e)
    {
      if (loaded.blocks.empty())
      {
        throw;
      }
      loaded.warnings.push_back(e.what());
    }
    return loaded;
  }

  std::lock_guard<std::mutex> lock(loadMutex());
  VtkMessageCapture capture;
  std::vector<std::string> readerWarnings;
  std::vector<ReaderBlock> raw =
      readingErrorsNamed(path,
                         [&]
                         {
                           return readBlocksInReaderProcess(path, ext, fileSize, readerWarnings,
                                                            readArguments(ext, options));
                         });
  ObjNonFiniteEntries objNonFinite;
  if (ext == ".obj")
  {
    objNonFinite = countObjNonFiniteEntries(path);
  }
  const std::vector<std::string> names = uniqueNames(raw, stem);
  std::set<std::string> taken(names.begin(), names.end());
  std::vector<std::string> reasons; // "part NAME: reason" of each part skipped
  for (size_t b = 0; b < raw.size(); ++b)
  {
    MeshBlock block;
    block.name = names[b];
    block.mesh.report.source = path;
    block.mesh.report.readerWarnings = readerWarnings;
    const std::string subject = path + ": part " + block.name;
    // A block's polylines are a part of their own, after its faces' part; a block of lines
    // only makes no surface part.
    std::optional<MeshBlock> lines;
    if (hasLineCells(raw[b].polyData))
    {
      std::vector<std::string> lineWarnings;
      lines = linePart(raw[b].polyData, linePartName(block.name, taken), path, block.mesh.report,
                       lineWarnings);
      for (const std::string& warning : lineWarnings)
      {
        loaded.warnings.push_back(warning);
        reasons.push_back(warning.substr(path.size() + 2));
      }
      if (lines)
      {
        lines->placement = raw[b].placement;
      }
    }
    if (hasLineCells(raw[b].polyData) && !hasFaceCells(raw[b].polyData))
    {
      if (lines)
      {
        loaded.blocks.push_back(std::move(*lines));
      }
      continue; // its lines' warning says why nothing of it is drawn
    }
    try
    {
      dropObjNonFiniteArrays(raw[b].polyData, objNonFinite);
      block.mesh.polyData = sanitizeSurface(raw[b].polyData, subject, block.mesh.report);
      if (lines)
      {
        block.mesh.report.nonSurfaceCellsDropped -= raw[b].polyData->GetNumberOfLines();
      }
    }
    catch (const Error& e)
    {
      loaded.warnings.push_back(e.what());
      reasons.push_back(std::string(e.what()).substr(path.size() + 2));
      if (lines)
      {
        loaded.blocks.push_back(std::move(*lines));
      }
      continue;
    }
    raw[b].polyData = nullptr;
    adoptFinishAndPlace(raw[b], file.parent_path().string(), subject, block, loaded.warnings);
    block.mesh.report.invalidTCoords += objNonFinite.tcoords;
    block.mesh.report.invalidNormals += objNonFinite.normals;
    loaded.blocks.push_back(std::move(block));
    if (lines)
    {
      loaded.blocks.push_back(std::move(*lines));
    }
  }
  if (loaded.blocks.empty())
  {
    if (reasons.size() == 1)
    {
      // One part: the file's own reason, as loadMesh gives it.
      const std::string prefix = "part " + names.front() + ": ";
      const std::string& reason = reasons.front();
      throw errorAbout(path, reason.rfind(prefix, 0) == 0 ? reason.substr(prefix.size()) : reason);
    }
    constexpr size_t kReasonsTold = 3;
    std::string told;
    for (size_t r = 0; r < reasons.size() && r < kReasonsTold; ++r)
    {
      told += (r == 0 ? "" : "; ") + reasons[r];
    }
    if (reasons.size() > kReasonsTold)
    {
      told += "; " + std::to_string(reasons.size() - kReasonsTold) + " more";
    }
    throw errorAbout(path, "none of its " + std::to_string(reasons.size()) + " parts is usable (" +
                               told + ")");
  }
  return loaded;
}
} // namespace aniso
