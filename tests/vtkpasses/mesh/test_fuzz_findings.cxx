// Every mesh file fuzzing found (tests/data/fuzz/<harness>/, and open/ for crashes left inside
// VTK or OpenCASCADE) loaded as the application loads files: loadMesh and loadMeshBlocks, the
// reader program in a process of its own. What each must give: for the findings fixed in the
// project (obj/, vtk/, step/) a clear refusal naming the file, or a surface whose every point is
// finite; for the open ones, whose reader crashes or runs out of memory, the same refusal
// ("PATH: the reader crashed on this file ...", "PATH: the reader ran out of memory ..."), the
// application itself untouched. The reference is the file's own fault,
// stated in tests/data/fuzz/README.md: none of these files is a valid mesh.
#include "core/error.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace
{
namespace fs = std::filesystem;

std::vector<std::string> findings(const std::string& folder)
{
  std::vector<std::string> files;
  const fs::path dir = fs::path(ANISO_SOURCE_DIR) / "tests/data/fuzz" / folder;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
  {
    files.push_back(entry.path().string());
  }
  return files;
}

bool allFinite(vtkPolyData* surface)
{
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return false;
    }
  }
  return true;
}

constexpr const char* kCrashed = "the reader crashed on this file";
constexpr const char* kOutOfMemory = "the reader ran out of memory";

bool readerDied(const std::string& what)
{
  return what.find(kCrashed) != std::string::npos || what.find(kOutOfMemory) != std::string::npos;
}

// A refusal names the file; a result is finite. CRASHES: the reader program crashes on it (an
// open finding) or meets its memory limit, so it must be refused so; otherwise the project's own checks must
// catch it before the reader does (a crash there would be the finding back).
void expectSafe(const std::string& path, bool crashes)
{
  const bool mustRefuse = crashes;
  SCOPED_TRACE(path);
  bool refused = false;
  try
  {
    const aniso::LoadedMesh mesh = aniso::loadMesh(path);
    EXPECT_TRUE(allFinite(mesh.polyData)) << "a point that is not finite";
  }
  catch (const aniso::Error& e)
  {
    refused = true;
    const std::string what = e.what();
    EXPECT_NE(what.find(fs::path(path).filename().string()), std::string::npos)
        << "the error does not name the file: " << what;
    EXPECT_EQ(readerDied(what), crashes) << what;
  }
  try
  {
    const aniso::LoadedBlocks parts = aniso::loadMeshBlocks(path);
    EXPECT_FALSE(parts.blocks.empty());
    for (const aniso::MeshBlock& block : parts.blocks)
    {
      EXPECT_TRUE(allFinite(block.mesh.polyData)) << block.name;
    }
    EXPECT_FALSE(crashes) << "read as parts, though its reader crashes";
  }
  catch (const aniso::Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find(fs::path(path).filename().string()), std::string::npos)
        << "the error does not name the file: " << what;
    EXPECT_EQ(readerDied(what), crashes) << what;
  }
  if (mustRefuse)
  {
    EXPECT_TRUE(refused) << "read, though its reader crashes";
  }
  std::printf("%s: %s\n", fs::path(path).filename().c_str(), refused ? "refused" : "read");
}

TEST(FuzzFindings, FixedInTheProjectAreRefusedOrRead)
{
  int files = 0;
  for (const char* folder : {"obj", "vtk", "glb", "step"})
  {
    for (const std::string& path : findings(folder))
    {
      expectSafe(path, false);
      ++files;
    }
  }
  EXPECT_GE(files, 8);
}

// Crashes left inside VTK's legacy reader and OpenCASCADE, and a VTP whose compression header
// makes VTK's XML reader allocate 7.8 GB: the reader program dies (or meets its memory limit),
// the application reports it with the file's name.
TEST(FuzzFindings, OpenOnesEndTheReaderNotTheApplication)
{
  int files = 0;
  for (const std::string& path : findings("open"))
  {
    expectSafe(path, true);
    ++files;
  }
  EXPECT_GE(files, 5);
}
} // namespace
