#pragma once
// VTK's readers (VtkReaders.h) run in a program of their own, aniso-mesh-reader, started with
// posix_spawn for each file: a crash, a runaway allocation or an endless loop there ends that
// process, not the application. It is never a fork of the application, whose other threads
// (LUT and environment bakes, background loads) may hold locks that a forked child would wait
// for forever. The reader bounds its own address space (what it starts with plus a budget of
// 64 times FILE_SIZE, at least 512 MiB; the loader counts a .vtm's files in it), prints nothing,
// and sends back its messages and the surface as VTK XML (VTK's own output, read back safely)
// through a pipe; it is killed after kReaderTimeoutSeconds. Asked for the file's parts (a fourth
// argument, "blocks"), it sends each part's name and surface in turn, the same way. Arguments
// after those (KEY=VALUE, see CadReader.h) tell the readers how to read (a CAD file's
// tessellation).
#include "core/placement.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
class VtkMessageCapture;

constexpr int kReaderTimeoutSeconds = 120;
// The reader program's fourth argument that asks for the file's parts.
constexpr const char* kReaderBlocksArgument = "blocks";

// The application's side: reads PATH (lower-case extension EXT, FILE_SIZE bytes) in the reader
// program, given READ_ARGUMENTS (KEY=VALUE) after its own; its warnings are appended to
// WARNINGS. Throws aniso::Error "PATH: reason" (the reader's error, a crash, the time limit, a
// program that cannot be started).
vtkSmartPointer<vtkPolyData>
readInReaderProcess(const std::string& path, const std::string& ext, uintmax_t fileSize,
                    std::vector<std::string>& warnings,
                    const std::vector<std::string>& readArguments = {});

// One part of a file as the reader program hands it back: the name the file gives it (empty
// when it gives none; not necessarily unique), its surface, unsanitised (never null, possibly
// without cells), in the part's own frame, what the file says of its finish and where the file
// places it.
struct ReaderBlock
{
  ReaderBlock() = default;
  ReaderBlock(std::string name_, vtkSmartPointer<vtkPolyData> polyData_)
      : name(std::move(name_)), polyData(std::move(polyData_))
  {
  }

  std::string name;
  vtkSmartPointer<vtkPolyData> polyData;
  // The part's material as a material library document (core/parameters/material_library) of
  // exactly one material, named as the file names it; empty when the file says nothing of it.
  std::string material;
  // From the part's own frame (its surface's coordinates) to the file's scene.
  PartMatrix placement = kIdentityPlacement;
};

// The same for the file's parts (VtkReaders.h, readBlocksWithVtk), in file order, at least one.
std::vector<ReaderBlock>
readBlocksInReaderProcess(const std::string& path, const std::string& ext, uintmax_t fileSize,
                          std::vector<std::string>& warnings,
                          const std::vector<std::string>& readArguments = {});

// Where the reader program is: $ANISO_MESH_READER when set, else beside the running executable,
// else in ../libexec/aniso/ from it (the installed layout), else where this build made it. Throws
// aniso::Error naming the places looked at when it is in none of them.
std::string meshReaderProgram();

// The reader program's side: reads PATH with READ and writes what came of it to FD (the
// parent's pipe); standard output and error go to /dev/null first. Returns the exit status.
using VtkRead = std::function<vtkSmartPointer<vtkPolyData>(
    const std::string& path, const std::string& ext, const VtkMessageCapture& capture)>;
int runMeshReader(int fd, const std::string& path, const std::string& ext, uintmax_t fileSize,
                  const VtkRead& read);

// The same for the file's parts; READ's WARNINGS are sent with VTK's.
using VtkReadBlocks = std::function<std::vector<ReaderBlock>(
    const std::string& path, const std::string& ext, const VtkMessageCapture& capture,
    std::vector<std::string>& warnings)>;
int runMeshReaderBlocks(int fd, const std::string& path, const std::string& ext, uintmax_t fileSize,
                        const VtkReadBlocks& read);
} // namespace aniso
