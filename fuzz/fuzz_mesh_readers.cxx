// libFuzzer harness of the project's own mesh readers (PLY, STL, OFF; ANISO_FUZZ_FORMAT picks
// one at build time) and of the CPU path after them: sanitizeSurface, then prepareSurface with
// computed normals and a brushing model. Accepted outcomes: a surface whose every point is
// finite, or an aniso::Error naming the file. Anything else (a crash, a sanitizer report, a
// hang, another exception) is a finding.
#include "core/error.h"
#include "fuzz/fuzz_input.h"
#include "fuzz/fuzz_surface.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/mesh/OffReader.h"
#include "vtkpasses/mesh/PlyReader.h"
#include "vtkpasses/mesh/StlReader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>
#include <vtkObject.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace
{
#define ANISO_STRINGIFY2(x) #x
#define ANISO_STRINGIFY(x) ANISO_STRINGIFY2(x)
const std::string kFormat = ANISO_STRINGIFY(ANISO_FUZZ_FORMAT);

vtkSmartPointer<vtkPolyData> readFormat(const std::string& path)
{
  if (kFormat == "ply")
  {
    return aniso::readPly(path);
  }
  if (kFormat == "stl")
  {
    std::vector<std::string> warnings;
    return aniso::readStl(path, warnings);
  }
  return aniso::readOff(path);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  const std::string path = aniso::fuzz::writeInput(data, size, "." + kFormat);
  try
  {
    vtkSmartPointer<vtkPolyData> read = readFormat(path);
    aniso::MeshReport report;
    vtkSmartPointer<vtkPolyData> clean = aniso::sanitizeSurface(read, path, report);
    aniso::fuzz::checkFinite(clean);
    aniso::SurfaceOptions options;
    options.recomputeNormals = size % 2 == 0;
    options.brushing = aniso::parseBrushingModel("around:0,0,1");
    aniso::PreparedSurface prepared = aniso::prepareSurface(clean, options, path);
    aniso::fuzz::checkFinite(prepared.polyData);
  }
  catch (const aniso::Error&)
  {
  }
  return 0;
}
