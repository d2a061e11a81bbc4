// Every mesh file fuzzing found (tests/data/fuzz/<harness>/, and open/ for crashes left inside
// VTK or OpenCASCADE) loaded as the application loads files: loadMesh and loadMeshBlocks, the
// reader program in a process of its own. What each must give: for the findings fixed in the
// project (obj/, vtk/, step/) a clear refusal naming the file, or a surface whose every point is
// finite; for the open ones, whose reader crashes, the same refusal ("PATH: the reader crashed
// on this file ..."), the application itself untouched. The reference is the file's own fault,
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

// A refusal names the file; a result is finite. CRASHES: the reader program crashes on it (an
// open finding), so it must be refused as a crash; otherwise the project's own checks must
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
    EXPECT_EQ(what.find(kCrashed) != std::string::npos, crashes) << what;
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
    EXPECT_EQ(what.find(kCrashed) != std::string::npos, crashes) << what;
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
  for (const char* folder : {"obj", "vtk", "step"})
  {
    for (const std::string& path : findings(folder))
    {
      expectSafe(path, false);
      ++files;
    }
  }
  EXPECT_GE(files, 7);
}

// Crashes left inside VTK's legacy reader and OpenCASCADE: the reader program dies, the
// application reports it with the file's name.
TEST(FuzzFindings, OpenOnesEndTheReaderNotTheApplication)
{
  int files = 0;
  for (const std::string& path : findings("open"))
  {
    expectSafe(path, true);
    ++files;
  }
  EXPECT_GE(files, 4);
}
} // namespace
