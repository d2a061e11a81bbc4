#include "MeshLoader.h"

#include "OffReader.h"
#include "error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
#include <system_error>
#include <vector>
#include <vtkAppendPolyData.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkErrorCode.h>
#include <vtkGLTFReader.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkXMLPolyDataReader.h>

namespace aniso
{
namespace
{
const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off", ".vtk", ".vtp", ".gltf", ".glb"};

struct VtkMessage
{
  std::string origin; // the VTK class that printed it
  std::string text;   // without the "ERROR: In file, line" line and the object address
};

// "ERROR: In ./IO/x.cxx, line 12\nvtkXReader (0x55d...): reason\n\n" -> {vtkXReader, reason}.
VtkMessage parseVtkMessage(const char* raw)
{
  std::string text = raw ? raw : "";
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
      text.rfind("Generic Warning: In ", 0) == 0)
  {
    const size_t newline = text.find('\n');
    text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
  }
  VtkMessage message;
  const size_t open = text.find(" (");
  const size_t close = text.find("): ");
  if (open != std::string::npos && close != std::string::npos && open < close &&
      text.find_first_of(" \n") == open)
  {
    message.origin = text.substr(0, open);
    text = text.substr(close + 3);
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  const size_t first = text.find_first_not_of(" \t\r");
  const size_t last = text.find_last_not_of(" \t\r");
  message.text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  return message;
}

// Collects what VTK would print, so that it becomes the error message instead of stderr noise.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow)

      void DisplayText(const char*) override
  {
  }
  void DisplayDebugText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    this->Errors.push_back(parseVtkMessage(text));
  }
  void DisplayWarningText(const char* text) override
  {
    this->Warnings.push_back(parseVtkMessage(text));
  }
  void DisplayGenericWarningText(const char* text) override
  {
    this->Warnings.push_back(parseVtkMessage(text));
  }

  std::vector<VtkMessage> Errors;
  std::vector<VtkMessage> Warnings;

protected:
  CapturingOutputWindow() = default;
};
vtkStandardNewMacro(CapturingOutputWindow);

// Installs the capturing window and silences vtkLogger's stderr copy of the same messages for
// the lifetime of the object; restores both afterwards. VTK's output window is process-wide, so
// loads are serialised.
class ScopedVtkMessageCapture
{
public:
  ScopedVtkMessageCapture()
      : Lock(mutex()), Previous(vtkOutputWindow::GetInstance()),
        PreviousVerbosity(vtkLogger::GetCurrentVerbosityCutoff())
  {
    vtkOutputWindow::SetInstance(this->Window);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~ScopedVtkMessageCapture()
  {
    vtkOutputWindow::SetInstance(this->Previous);
    vtkLogger::SetStderrVerbosity(this->PreviousVerbosity);
  }
  ScopedVtkMessageCapture(const ScopedVtkMessageCapture&) = delete;
  ScopedVtkMessageCapture& operator=(const ScopedVtkMessageCapture&) = delete;

  const CapturingOutputWindow& messages() const { return *this->Window; }

private:
  static std::mutex& mutex()
  {
    static std::mutex instance;
    return instance;
  }

  std::lock_guard<std::mutex> Lock;
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkLogger::Verbosity PreviousVerbosity;
  vtkNew<CapturingOutputWindow> Window;
};

bool isPipelineClass(const std::string& origin)
{
  return origin == "vtkExecutive" || origin == "vtkStreamingDemandDrivenPipeline" ||
         origin == "vtkCompositeDataPipeline" || origin == "vtkDemandDrivenPipeline";
}

// The reader's own messages first (the pipeline's "returned failure" adds nothing a user can
// act on); at most three, joined.
void throwIfReaderFailed(const std::string& path, vtkAlgorithm* reader,
                         const ScopedVtkMessageCapture& capture)
{
  const auto& errors = capture.messages().Errors;
  std::string reason;
  int shown = 0;
  for (const VtkMessage& message : errors)
  {
    if (isPipelineClass(message.origin) || message.text.empty() || shown == 3)
    {
      continue;
    }
    reason += (shown++ > 0 ? "; " : "") + message.text;
  }
  if (reason.empty() && !errors.empty())
  {
    reason = "the reader failed";
  }
  const unsigned long code =
      reader ? reader->GetErrorCode() : static_cast<unsigned long>(vtkErrorCode::NoError);
  if (reason.empty() && code != vtkErrorCode::NoError)
  {
    reason = std::string("read error (") + vtkErrorCode::GetStringFromErrorCode(code) + ")";
  }
  if (!reason.empty())
  {
    throw errorAbout(path, reason);
  }
}

std::string lowerExtension(const std::filesystem::path& path)
{
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

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

vtkSmartPointer<vtkPolyData> readGltf(const std::string& path, ScopedVtkMessageCapture& capture)
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
  return merged;
}

template <typename Reader>
vtkSmartPointer<vtkPolyData> readPolyData(const std::string& path, ScopedVtkMessageCapture& capture)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  return output;
}

vtkSmartPointer<vtkPolyData> readLegacy(const std::string& path, ScopedVtkMessageCapture& capture)
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

vtkSmartPointer<vtkPolyData> readByExtension(const std::string& path, const std::string& ext,
                                             ScopedVtkMessageCapture& capture)
{
  if (ext == ".obj")
  {
    return readPolyData<vtkOBJReader>(path, capture);
  }
  if (ext == ".ply")
  {
    return readPolyData<vtkPLYReader>(path, capture);
  }
  if (ext == ".stl")
  {
    return readPolyData<vtkSTLReader>(path, capture);
  }
  if (ext == ".vtp")
  {
    return readPolyData<vtkXMLPolyDataReader>(path, capture);
  }
  if (ext == ".vtk")
  {
    return readLegacy(path, capture);
  }
  if (ext == ".gltf" || ext == ".glb")
  {
    return readGltf(path, capture);
  }
  if (ext == ".off")
  {
    return readOff(path);
  }
  throw errorAbout(path, "unknown mesh format '" + ext + "'");
}

// Existence, type, readability and size, before any reader sees the file.
void checkFile(const std::filesystem::path& file, const std::string& path)
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
  checkFile(file, path);

  LoadedMesh mesh;
  mesh.report.source = path;
  ScopedVtkMessageCapture capture;
  vtkSmartPointer<vtkPolyData> raw;
  try
  {
    raw = readByExtension(path, ext, capture);
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
  for (const VtkMessage& warning : capture.messages().Warnings)
  {
    if (!warning.text.empty())
    {
      mesh.report.readerWarnings.push_back(warning.text);
    }
  }
  mesh.polyData = sanitizeSurface(raw, path, mesh.report);
  return mesh;
}
} // namespace aniso
