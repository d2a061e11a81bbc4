#include "vtkpasses/mesh/VtkReaders.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <system_error>
#include <unistd.h>
#include <vector>
#include <vtkAppendPolyData.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkGLTFReader.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

namespace aniso
{
namespace
{
// Y-up glTF into the Z-up world: (x, y, z) -> (x, -z, y), a rotation, so it keeps handedness
// and applies unchanged to normals and tangents (a 4th tangent component, the handedness sign,
// is left alone).
void rotateYUpToZUp(vtkPolyData* polyData)
{
  auto rotate = [](vtkDataArray* array)
  {
    if (!array || array->GetNumberOfComponents() < 3)
    {
      return;
    }
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      const double y = array->GetComponent(i, 1);
      const double z = array->GetComponent(i, 2);
      array->SetComponent(i, 1, -z);
      array->SetComponent(i, 2, y);
    }
    array->Modified();
  };
  if (polyData->GetPoints())
  {
    rotate(polyData->GetPoints()->GetData());
  }
  vtkPointData* pd = polyData->GetPointData();
  std::vector<vtkDataArray*> vectors = {pd->GetNormals(), pd->GetTangents()};
  for (const char* name : {"NORMAL", "TANGENT"})
  {
    vectors.push_back(pd->GetArray(name));
  }
  std::sort(vectors.begin(), vectors.end());
  vectors.erase(std::unique(vectors.begin(), vectors.end()), vectors.end());
  for (vtkDataArray* array : vectors)
  {
    rotate(array);
  }
  polyData->Modified();
}

// glTF puts the texture origin at the image's top left, VTK and OpenGL at the bottom left:
// v -> 1 - v, as Blender's importer does, so an image lines up the same way in both.
void flipTextureV(vtkPolyData* polyData)
{
  vtkPointData* pd = polyData->GetPointData();
  vtkDataArray* tcoords = pd->GetTCoords() ? pd->GetTCoords() : pd->GetArray("TEXCOORD_0");
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    return;
  }
  for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
  {
    tcoords->SetComponent(i, 1, 1.0 - tcoords->GetComponent(i, 1));
  }
  tcoords->Modified();
}

vtkSmartPointer<vtkPolyData> readGltf(const std::string& path, const VtkMessageCapture& capture)
{
  vtkNew<vtkGLTFReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkMultiBlockDataSet* blocks = reader->GetOutput();
  if (!blocks)
  {
    throw errorAbout(path, "the glTF reader produced no scene");
  }
  // The reader has already applied each node's global transform to its primitives.
  vtkNew<vtkAppendPolyData> append;
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(blocks->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  int pieces = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (auto* piece = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
    {
      append->AddInputData(piece);
      ++pieces;
    }
  }
  if (pieces == 0)
  {
    throw errorAbout(path, "no faces (the glTF scene holds no mesh)");
  }
  append->Update();
  throwIfReaderFailed(path, append, capture);
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->DeepCopy(append->GetOutput());
  rotateYUpToZUp(merged);
  flipTextureV(merged);
  return merged;
}

template <typename Reader>
vtkSmartPointer<vtkPolyData> readPolyData(const std::string& path, const VtkMessageCapture& capture)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  return output;
}

vtkSmartPointer<vtkPolyData> readLegacy(const std::string& path, const VtkMessageCapture& capture)
{
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkDataSet* data = reader->GetOutput();
  if (!data)
  {
    throw errorAbout(path, "not a VTK legacy dataset");
  }
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  // Volumes and grids are shown by their outer surface.
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  surface->Update();
  throwIfReaderFailed(path, surface, capture);
  vtkSmartPointer<vtkPolyData> output = surface->GetOutput();
  return output;
}

// vtkOBJReader reads vertex coordinates as floats through an input stream: "nan", "inf" or a
// value beyond the float range fails the extraction and leaves 0 or the previous line's values
// in the vertex, a finite position that no later check can tell from a real one. So vertex
// lines with such a coordinate are rewritten (in a private copy) to hold FLT_MAX there, and the
// points that come out with a coordinate at +-FLT_MAX are made NaN, for sanitizeSurface to drop
// with their faces and count. Returns the copy's text, or nothing when every vertex is fine.
std::optional<std::string> objWithMarkedVertices(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text;
  std::string line;
  bool marked = false;
  while (std::getline(in, line))
  {
    size_t at = line.find_first_not_of(" \t");
    if (at != std::string::npos && line.compare(at, 2, "v ") == 0)
    {
      std::string rewritten = line.substr(0, at + 1);
      at += 1;
      for (int field = 0; field < 3; ++field)
      {
        const size_t start = line.find_first_not_of(" \t", at);
        if (start == std::string::npos)
        {
          break;
        }
        size_t end = line.find_first_of(" \t\r", start);
        end = end == std::string::npos ? line.size() : end;
        const std::string token = line.substr(start, end - start);
        char* parsedEnd = nullptr;
        const double value = std::strtod(token.c_str(), &parsedEnd);
        const bool number = parsedEnd != token.c_str();
        const bool unfit = number && (!std::isfinite(value) ||
                                      std::abs(value) >= double(std::numeric_limits<float>::max()));
        rewritten += line.substr(at, start - at);
        rewritten += unfit ? "3.40282347e+38" : token;
        marked = marked || unfit;
        at = end;
      }
      line = rewritten + line.substr(at);
    }
    text += line;
    text += '\n';
  }
  if (!marked)
  {
    return std::nullopt;
  }
  return text;
}

vtkSmartPointer<vtkPolyData> readObj(const std::string& path, const VtkMessageCapture& capture)
{
  const std::optional<std::string> marked = objWithMarkedVertices(path);
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("aniso_obj_vertices_" + std::to_string(::getpid()) + ".obj");
  if (marked)
  {
    std::ofstream(copy, std::ios::binary) << *marked;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(marked ? copy.c_str() : path.c_str());
  reader->Update();
  if (marked)
  {
    std::error_code ignored;
    std::filesystem::remove(copy, ignored);
  }
  throwIfReaderFailed(path, reader, capture);
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  vtkPoints* points = output ? output->GetPoints() : nullptr;
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    constexpr double kFloatMax = double(std::numeric_limits<float>::max());
    if (std::abs(p[0]) >= kFloatMax || std::abs(p[1]) >= kFloatMax || std::abs(p[2]) >= kFloatMax)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      points->SetPoint(i, nan, nan, nan);
    }
  }
  return output;
}

} // namespace

vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, const std::string& ext,
                                         const VtkMessageCapture& capture)
{
  if (ext == ".obj")
  {
    return readObj(path, capture);
  }
  if (ext == ".vtp")
  {
    return readPolyData<vtkXMLPolyDataReader>(path, capture);
  }
  if (ext == ".vtk")
  {
    return readLegacy(path, capture);
  }
  return readGltf(path, capture);
}
} // namespace aniso
