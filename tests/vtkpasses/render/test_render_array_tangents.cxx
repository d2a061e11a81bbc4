// Brushing along a vector field of the file: a disk whose point array "flow" runs around its
// centre, (-y, x, 0), written by VTK's own writers as VTP (vtkXMLPolyDataWriter), legacy VTK
// (vtkPolyDataWriter) and VTU (vtkXMLUnstructuredGridWriter, read back as its outer surface), is
// loaded, prepared with the tangent model array:flow and rendered. Each image must match, pixel
// for pixel within float rounding, the built-in disk prepared with around:0,0,1 (the analytic
// circular brushing the field describes); a disk brushed along X must not (the comparison sees
// the highlight's shape). Small images, one frame.
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 48;

RenderSettings diskScene(vtkSmartPointer<vtkPolyData> surface)
{
  RenderSettings s;
  s.surface = std::move(surface);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 64;
  s.material.lobe = AsLobe{2000.0, 20.0};
  s.material.f0 = glm::dvec3(1.0);
  s.material.albedo = glm::dvec3(0.0);
  s.material.method = SpecularMethod::Exact;
  s.material.filtered = false;
  s.material.samples = 16;
  s.display.background = BackgroundMode::Transparent;
  s.view.direction = viewDirectionFromAngles(25.0, 50.0);
  s.width = kSize;
  s.height = kSize;
  s.frames = 2;
  s.jitter = false;
  return s;
}

vtkSmartPointer<vtkPolyData> prepared(vtkPolyData* mesh, const std::string& model)
{
  SurfaceOptions options;
  options.brushing = parseBrushingModel(model);
  return prepareSurface(mesh, options, model).polyData;
}

// Mean absolute difference over the pixels either image covers, relative to the mean radiance.
double relativeL1(const Image& a, const Image& b)
{
  double difference = 0.0;
  double total = 0.0;
  for (int i = 0; i < a.width * a.height; ++i)
  {
    const size_t at = size_t(i) * 4;
    if (a.data[at + 3] <= 0.0f && b.data[at + 3] <= 0.0f)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      difference += std::abs(double(a.data[at + size_t(c)]) - double(b.data[at + size_t(c)]));
      total += std::abs(double(b.data[at + size_t(c)]));
    }
  }
  return total > 0.0 ? difference / total : 1.0;
}

TEST(RenderArrayTangents, AFieldAroundTheCentreBrushesLikeAround)
{
  ANISO_REQUIRE_DISPLAY();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("aniso-test-array-tangents-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);

  // The built-in disk (normals +Z) without its own tangents, the field added as "flow".
  vtkSmartPointer<vtkPolyData> disk = makeDisk(96, 12);
  disk->GetPointData()->SetTangents(nullptr);
  disk->GetPointData()->RemoveArray("Tangents");
  disk->GetPointData()->RemoveArray("TCoords");
  vtkNew<vtkFloatArray> flow;
  flow->SetName("flow");
  flow->SetNumberOfComponents(3);
  flow->SetNumberOfTuples(disk->GetNumberOfPoints());
  for (vtkIdType i = 0; i < disk->GetNumberOfPoints(); ++i)
  {
    double p[3];
    disk->GetPoint(i, p);
    flow->SetTuple3(i, -p[1], p[0], 0.0);
  }
  disk->GetPointData()->AddArray(flow);

  const std::string vtp = (dir / "disk.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetInputData(disk);
  xml->SetFileName(vtp.c_str());
  ASSERT_EQ(xml->Write(), 1);
  const std::string legacy = (dir / "disk.vtk").string();
  vtkNew<vtkPolyDataWriter> old;
  old->SetInputData(disk);
  old->SetFileName(legacy.c_str());
  ASSERT_EQ(old->Write(), 1);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(disk->GetPoints());
  grid->GetPointData()->ShallowCopy(disk->GetPointData());
  grid->SetCells(VTK_TRIANGLE, disk->GetPolys());
  const std::string vtu = (dir / "disk.vtu").string();
  vtkNew<vtkXMLUnstructuredGridWriter> unstructured;
  unstructured->SetInputData(grid);
  unstructured->SetFileName(vtu.c_str());
  ASSERT_EQ(unstructured->Write(), 1);

  const RenderResult around = renderOffscreen(diskScene(prepared(disk, "around:0,0,1")));
  ASSERT_GT(around.coveredPixels, kSize * kSize / 4);
  EXPECT_EQ(nonFiniteValues(around.linear), 0);
  for (const std::string& file : {vtp, legacy, vtu})
  {
    SCOPED_TRACE(file);
    const LoadedMesh mesh = loadMesh(file);
    const RenderResult field = renderOffscreen(diskScene(prepared(mesh.polyData, "array:flow")));
    EXPECT_EQ(nonFiniteValues(field.linear), 0);
    const double error = relativeL1(field.linear, around.linear);
    std::printf("%s: relative L1 against around:0,0,1 = %.3g\n", file.c_str(), error);
    EXPECT_LT(error, 2e-3);
    if (error >= 2e-3)
    {
      keepImages("array_tangents", field.linear, around.linear);
    }
  }
  const RenderResult linear = renderOffscreen(diskScene(prepared(disk, "axis:1,0,0")));
  const double control = relativeL1(linear.linear, around.linear);
  std::printf("axis:1,0,0: relative L1 against around:0,0,1 = %.3g\n", control);
  EXPECT_GT(control, 0.1);
  std::filesystem::remove_all(dir);
}
} // namespace
} // namespace aniso::test
