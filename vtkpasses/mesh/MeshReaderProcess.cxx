#include "vtkpasses/mesh/MeshReaderProcess.h"

#include "core/error.h"
#include "vtkpasses/mesh/VtkErrorText.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <new>
#include <poll.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

extern char** environ;

namespace aniso
{
namespace
{
constexpr const char* kProgramName = "aniso-mesh-reader";

enum class Record : char
{
  Error = 'E',
  Warning = 'W',
  Name = 'N',      // the name of the part whose Data comes next
  Material = 'M',  // its material (ReaderBlock::material)
  Placement = 'P', // its placement: 16 numbers as text
  Data = 'D'
};

std::string placementText(const PartMatrix& m)
{
  std::string text;
  char number[32];
  for (double v : m)
  {
    std::snprintf(number, sizeof(number), "%.17g ", v);
    text += number;
  }
  return text;
}

PartMatrix placementFromText(const std::string& text, const std::string& path)
{
  PartMatrix m{};
  const char* p = text.c_str();
  for (double& v : m)
  {
    char* end = nullptr;
    v = std::strtod(p, &end);
    if (end == p)
    {
      throw errorAbout(path, "the reader sent a malformed placement");
    }
    p = end;
  }
  return m;
}

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
} // namespace

std::string meshReaderProgram()
{
  std::vector<std::string> candidates;
  if (const char* set = std::getenv("ANISO_MESH_READER"); set && *set)
  {
    candidates.emplace_back(set);
  }
  else
  {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec)
    {
      candidates.push_back((self.parent_path() / kProgramName).string());
      candidates.push_back((self.parent_path() / ".." / "libexec" / "aniso" / kProgramName).string());
    }
#ifdef ANISO_MESH_READER_BUILD_PATH
    candidates.emplace_back(ANISO_MESH_READER_BUILD_PATH);
#endif
  }
  std::string looked;
  for (const std::string& candidate : candidates)
  {
    if (::access(candidate.c_str(), X_OK) == 0)
    {
      return candidate;
    }
    looked += (looked.empty() ? "" : ", ") + candidate;
  }
  throw Error(std::string(kProgramName) + ": the mesh reader program is missing (looked for " +
              looked + ")");
}

namespace
{
// Standard output and error to /dev/null, the memory limit, then SEND (which reads and sends the
// records) with every error it throws sent as an Error record.
int serveRead(int fd, const std::string& path, uintmax_t fileSize,
              const std::function<void(const VtkMessageCapture&)>& send)
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
    VtkMessageCapture capture;
    send(capture);
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
  return 0;
}

void sendWarnings(int fd, const VtkMessageCapture& capture)
{
  for (const VtkErrorText& warning : capture.warnings())
  {
    if (!warning.text.empty())
    {
      sendRecord(fd, Record::Warning, warning.text);
    }
  }
}
} // namespace

int runMeshReader(int fd, const std::string& path, const std::string& ext, uintmax_t fileSize,
                  const VtkRead& read)
{
  return serveRead(fd, path, fileSize,
                   [&](const VtkMessageCapture& capture)
                   {
                     vtkSmartPointer<vtkPolyData> polyData = read(path, ext, capture);
                     sendWarnings(fd, capture);
                     sendRecord(fd, Record::Data, toXml(polyData));
                   });
}

int runMeshReaderBlocks(int fd, const std::string& path, const std::string& ext, uintmax_t fileSize,
                        const VtkReadBlocks& read)
{
  return serveRead(fd, path, fileSize,
                   [&](const VtkMessageCapture& capture)
                   {
                     std::vector<std::string> warnings;
                     std::vector<ReaderBlock> blocks = read(path, ext, capture, warnings);
                     sendWarnings(fd, capture);
                     for (const std::string& warning : warnings)
                     {
                       sendRecord(fd, Record::Warning, warning);
                     }
                     for (ReaderBlock& block : blocks)
                     {
                       sendRecord(fd, Record::Name, block.name);
                       if (!block.material.empty())
                       {
                         sendRecord(fd, Record::Material, block.material);
                       }
                       if (block.placement != kIdentityPlacement)
                       {
                         sendRecord(fd, Record::Placement, placementText(block.placement));
                       }
                       sendRecord(fd, Record::Data, toXml(block.polyData));
                       block.polyData = nullptr; // each part's memory goes once it is sent
                     }
                   });
}

namespace
{
// Runs the reader program on PATH (its parts when BLOCKS) and returns what it sent: one entry
// per Data record, with the Name record before it. Throws as readInReaderProcess says.
std::vector<ReaderBlock> runReaderProgram(const std::string& path, const std::string& ext,
                                          uintmax_t fileSize, bool blocks,
                                          std::vector<std::string>& warnings,
                                          const std::vector<std::string>& readArguments)
{
  std::string program;
  try
  {
    program = meshReaderProgram();
  }
  catch (const Error& e)
  {
    throw errorAbout(path, e.what());
  }
  int fds[2];
  // Close-on-exec: a process another thread starts meanwhile must not hold the write end open;
  // the reader gets the write end as its standard output only.
  if (::pipe2(fds, O_CLOEXEC) != 0)
  {
    throw errorAbout(path, "cannot start the reader process (no pipe)");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  // Nothing the readers print may reach the terminal.
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const std::string sizeText = std::to_string(fileSize);
  std::vector<char*> argv = {const_cast<char*>(program.c_str()), const_cast<char*>(path.c_str()),
                             const_cast<char*>(ext.c_str()), const_cast<char*>(sizeText.c_str())};
  if (blocks)
  {
    argv.push_back(const_cast<char*>(kReaderBlocksArgument));
  }
  for (const std::string& argument : readArguments)
  {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);
  pid_t child = -1;
  const int spawned = ::posix_spawn(&child, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (spawned != 0)
  {
    ::close(fds[0]);
    throw errorAbout(path, "cannot start the reader process " + program + " (" +
                               std::strerror(spawned) + ")");
  }
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

  std::vector<ReaderBlock> results;
  ReaderBlock next;
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
    case Record::Name:
      next.name = payload;
      break;
    case Record::Material:
      next.material = payload;
      break;
    case Record::Placement:
      next.placement = placementFromText(payload, path);
      break;
    case Record::Data:
      next.polyData = fromXml(payload, path);
      results.push_back(std::move(next));
      next = ReaderBlock();
      break;
    }
  }
  if (results.empty())
  {
    throw errorAbout(path, "the reader process ended without a result (corrupt file?)");
  }
  return results;
}
} // namespace

vtkSmartPointer<vtkPolyData> readInReaderProcess(const std::string& path, const std::string& ext,
                                                 uintmax_t fileSize,
                                                 std::vector<std::string>& warnings,
                                                 const std::vector<std::string>& readArguments)
{
  return runReaderProgram(path, ext, fileSize, false, warnings, readArguments).back().polyData;
}

std::vector<ReaderBlock> readBlocksInReaderProcess(const std::string& path, const std::string& ext,
                                                   uintmax_t fileSize,
                                                   std::vector<std::string>& warnings,
                                                   const std::vector<std::string>& readArguments)
{
  return runReaderProgram(path, ext, fileSize, true, warnings, readArguments);
}
} // namespace aniso
