#include "vtkpasses/mesh/MeshLoader.h"

#include "core/error.h"
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/OffReader.h"
#include "vtkpasses/mesh/PlyReader.h"
#include "vtkpasses/mesh/StlReader.h"
#include "vtkpasses/mesh/VtkErrorText.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
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
const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off", ".vtk", ".vtp", ".gltf", ".glb"};

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

vtkSmartPointer<vtkPolyData> readByExtension(const std::string& path, const std::string& ext,
                                             uintmax_t fileSize, std::vector<std::string>& warnings)
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
  return readInReaderProcess(path, ext, fileSize, warnings);
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
} // namespace

LoadedMesh loadMesh(const std::string& path)
{
  const std::filesystem::path file(path);
  const std::string ext = lowerExtension(file);
  if (std::find(std::begin(kExtensions), std::end(kExtensions), ext) == std::end(kExtensions))
  {
    const std::string what =
        ext.empty() ? "no file extension" : "unknown mesh format '" + ext + "'";
    throw errorAbout(path, what + " (expected " + meshFilePatterns() + ")");
  }
  const uintmax_t fileSize = checkFile(file, path);

  std::lock_guard<std::mutex> lock(loadMutex());
  LoadedMesh mesh;
  mesh.report.source = path;
  // The validation's own VTK calls (polygon triangulation) stay quiet too.
  VtkMessageCapture capture;
  vtkSmartPointer<vtkPolyData> raw;
  try
  {
    raw = readByExtension(path, ext, fileSize, mesh.report.readerWarnings);
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
  ObjNonFiniteEntries objNonFinite;
  if (ext == ".obj")
  {
    objNonFinite = countObjNonFiniteEntries(path);
    vtkPointData* pd = raw->GetPointData();
    if (objNonFinite.tcoords > 0)
    {
      removeActiveArray(pd, pd->GetTCoords());
      pd->RemoveArray("TCoords");
    }
    if (objNonFinite.normals > 0)
    {
      removeActiveArray(pd, pd->GetNormals());
      pd->RemoveArray("Normals");
    }
  }
  mesh.polyData = sanitizeSurface(raw, path, mesh.report);
  mesh.report.invalidTCoords += objNonFinite.tcoords;
  mesh.report.invalidNormals += objNonFinite.normals;
  return mesh;
}
} // namespace aniso
