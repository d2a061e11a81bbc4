#include "vtkpasses/mesh/MeshLoader.h"

#include "core/error.h"
#include "vtkpasses/mesh/OffReader.h"
#include "vtkpasses/mesh/PlyReader.h"
#include "vtkpasses/mesh/StlReader.h"
#include "vtkpasses/mesh/VtkErrorText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <new>
#include <optional>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>
#include <vector>
#include <vtkAppendPolyData.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
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
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

namespace aniso
{
namespace
{
const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off", ".vtk", ".vtp", ".gltf", ".glb"};

// VTK's message as a user reads it: its words (VtkErrorText.h), in one line of printable text.
VtkErrorText parseVtkMessage(const char* raw)
{
  VtkErrorText message = parseVtkErrorText(raw);
  const std::string& text = message.text;
  // One line of printable text: readers quote raw file bytes in their messages, and a user
  // message must carry neither binary junk nor a whole line of a corrupt file, so it stops at
  // the first unprintable byte.
  constexpr size_t kMaxLength = 160;
  std::string clean;
  bool cut = false;
  for (char c : text)
  {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x7f || (u < 0x20 && !std::isspace(u)))
    {
      cut = true;
      break;
    }
    if (std::isspace(u) && (clean.empty() || clean.back() == ' '))
    {
      continue;
    }
    clean += std::isspace(u) ? ' ' : c;
  }
  while (!clean.empty() && clean.back() == ' ')
  {
    clean.pop_back();
  }
  if (clean.rfind("* ", 0) == 0)
  {
    clean.erase(0, 2); // jsoncpp's bullet before "Line N, Column M"
  }
  if (clean.size() > kMaxLength)
  {
    clean.resize(kMaxLength);
    cut = true;
  }
  if (cut)
  {
    clean += "...";
  }
  message.text = clean;
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

  std::vector<VtkErrorText> Errors;
  std::vector<VtkErrorText> Warnings;

protected:
  CapturingOutputWindow() = default;
};
vtkStandardNewMacro(CapturingOutputWindow);

// Installs the capturing window and silences vtkLogger's stderr copy of the same messages for
// the lifetime of the object; restores both afterwards. Both are process-wide: loadMesh
// serialises loads with loadMutex().
class ScopedVtkMessageCapture
{
public:
  ScopedVtkMessageCapture()
      : Previous(vtkOutputWindow::GetInstance()),
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
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkLogger::Verbosity PreviousVerbosity;
  vtkNew<CapturingOutputWindow> Window;
};

std::mutex& loadMutex()
{
  static std::mutex instance;
  return instance;
}

bool isPipelineClass(const std::string& origin)
{
  return origin == "vtkExecutive" || origin == "vtkStreamingDemandDrivenPipeline" ||
         origin == "vtkCompositeDataPipeline" || origin == "vtkDemandDrivenPipeline";
}

// The reader's first own message: the most specific one (the pipeline's "returned failure" and
// the readers' follow-up "failed to load" messages add nothing a user can act on).
void throwIfReaderFailed(const std::string& path, vtkAlgorithm* reader,
                         const ScopedVtkMessageCapture& capture)
{
  const auto& errors = capture.messages().Errors;
  std::string reason;
  for (const VtkErrorText& message : errors)
  {
    if (!isPipelineClass(message.origin) && !message.text.empty())
    {
      reason = message.text;
      break;
    }
  }
  if (reason.empty() && !errors.empty())
  {
    reason = "the reader failed (corrupt file, or not in this format)";
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
  flipTextureV(merged);
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

vtkSmartPointer<vtkPolyData> readObj(const std::string& path, ScopedVtkMessageCapture& capture)
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

// The formats read by VTK's readers; run inside the isolated child process.
vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, const std::string& ext,
                                         ScopedVtkMessageCapture& capture)
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

// Reading with VTK's readers in a child process. They are not hardened against hostile files
// (VTK 9.1's legacy reader crashes on truncated input, for one): a crash, a runaway allocation
// or an endless loop then ends the child, not the application. The child sends back its
// messages and the surface as VTK XML (VTK's own output, read back safely).
constexpr int kReaderTimeoutSeconds = 120;

enum class Record : char
{
  Error = 'E',
  Warning = 'W',
  Data = 'D'
};

bool writeAll(int fd, const char* data, size_t size)
{
  while (size > 0)
  {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      return false;
    }
    data += written;
    size -= static_cast<size_t>(written);
  }
  return true;
}

void sendRecord(int fd, Record tag, const std::string& payload)
{
  const uint64_t size = payload.size();
  char header[1 + sizeof(size)];
  header[0] = static_cast<char>(tag);
  std::memcpy(header + 1, &size, sizeof(size));
  if (!writeAll(fd, header, sizeof(header)) || !writeAll(fd, payload.data(), payload.size()))
  {
    ::_exit(3);
  }
}

std::string toXml(vtkPolyData* polyData)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(polyData);
  writer->WriteToOutputStringOn();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  writer->SetHeaderTypeToUInt64();
  writer->SetIdTypeToInt64();
  if (writer->Write() != 1)
  {
    throw std::runtime_error("the surface could not be passed back from the reader process");
  }
  return writer->GetOutputString();
}

// Bounds the child's address space to what it has plus a budget proportional to the file, so a
// hostile size field fails as an allocation error instead of exhausting the machine.
void limitChildMemory(uintmax_t fileSize)
{
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  std::ifstream statm("/proc/self/statm");
  unsigned long long pages = 0;
  if (!(statm >> pages) || pageSize <= 0)
  {
    return;
  }
  const unsigned long long current = pages * static_cast<unsigned long long>(pageSize);
  const unsigned long long budget =
      std::max<unsigned long long>(512ull << 20, 64ull * static_cast<unsigned long long>(fileSize));
  struct rlimit limit;
  limit.rlim_cur = limit.rlim_max = static_cast<rlim_t>(current + budget);
  ::setrlimit(RLIMIT_AS, &limit);
}

[[noreturn]] void runChild(int fd, const std::string& path, const std::string& ext,
                           uintmax_t fileSize)
{
  // Nothing the readers print may reach the terminal.
  const int devNull = ::open("/dev/null", O_WRONLY);
  if (devNull >= 0)
  {
    ::dup2(devNull, STDOUT_FILENO);
    ::dup2(devNull, STDERR_FILENO);
  }
  limitChildMemory(fileSize);
  try
  {
    ScopedVtkMessageCapture capture;
    vtkSmartPointer<vtkPolyData> polyData = readWithVtk(path, ext, capture);
    for (const VtkErrorText& warning : capture.messages().Warnings)
    {
      if (!warning.text.empty())
      {
        sendRecord(fd, Record::Warning, warning.text);
      }
    }
    sendRecord(fd, Record::Data, toXml(polyData));
  }
  catch (const Error& e)
  {
    sendRecord(fd, Record::Error, e.what());
  }
  catch (const std::bad_alloc&)
  {
    sendRecord(fd, Record::Error, path + ": the reader ran out of memory (corrupt sizes?)");
  }
  catch (const std::exception& e)
  {
    sendRecord(fd, Record::Error, path + ": the reader failed: " + e.what());
  }
  ::close(fd);
  ::_exit(0); // no static destructors or atexit handlers of the parent's libraries
}

// Reads the child's records until it closes the pipe or the time runs out.
bool receiveAll(int fd, std::string& received)
{
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(kReaderTimeoutSeconds);
  char buffer[1 << 16];
  while (true)
  {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
    {
      return false;
    }
    struct pollfd pfd = {fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready <= 0)
    {
      return false;
    }
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      return true; // end of data (or an error, which the record parsing then reports)
    }
    received.append(buffer, static_cast<size_t>(got));
  }
}

vtkSmartPointer<vtkPolyData> fromXml(const std::string& xml, const std::string& path)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(xml);
  reader->Update();
  if (reader->GetErrorCode() != vtkErrorCode::NoError || !reader->GetOutput())
  {
    throw errorAbout(path, "the surface could not be passed back from the reader process");
  }
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  return output;
}

vtkSmartPointer<vtkPolyData> readIsolated(const std::string& path, const std::string& ext,
                                          uintmax_t fileSize, std::vector<std::string>& warnings)
{
  int fds[2];
  // Close-on-exec: a process another thread starts meanwhile must not hold the write end open.
  if (::pipe2(fds, O_CLOEXEC) != 0)
  {
    throw errorAbout(path, "cannot start the reader process (no pipe)");
  }
  const pid_t child = ::fork();
  if (child < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw errorAbout(path, "cannot start the reader process");
  }
  if (child == 0)
  {
    ::close(fds[0]);
    runChild(fds[1], path, ext, fileSize);
  }
  ::close(fds[1]);
  std::string received;
  const bool finished = receiveAll(fds[0], received);
  ::close(fds[0]);
  if (!finished)
  {
    ::kill(child, SIGKILL);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (!finished)
  {
    throw errorAbout(path, "the reader did not finish within " +
                               std::to_string(kReaderTimeoutSeconds) + " s (corrupt file?)");
  }
  if (WIFSIGNALED(status))
  {
    throw errorAbout(path, "the reader crashed on this file (corrupt or unsupported content)");
  }

  vtkSmartPointer<vtkPolyData> polyData;
  size_t position = 0;
  while (position < received.size())
  {
    uint64_t size = 0;
    if (received.size() - position < 1 + sizeof(size))
    {
      break;
    }
    const auto tag = static_cast<Record>(received[position]);
    std::memcpy(&size, received.data() + position + 1, sizeof(size));
    position += 1 + sizeof(size);
    if (size > received.size() - position)
    {
      break;
    }
    const std::string payload = received.substr(position, static_cast<size_t>(size));
    position += static_cast<size_t>(size);
    switch (tag)
    {
    case Record::Error:
      throw Error(payload);
    case Record::Warning:
      warnings.push_back(payload);
      break;
    case Record::Data:
      polyData = fromXml(payload, path);
      break;
    }
  }
  if (!polyData)
  {
    throw errorAbout(path, "the reader process ended without a result (corrupt file?)");
  }
  return polyData;
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
  return readIsolated(path, ext, fileSize, warnings);
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
  ScopedVtkMessageCapture capture;
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
