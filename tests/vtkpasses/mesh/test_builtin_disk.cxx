// The built-in disk (vtkpasses/mesh/BuiltinMeshes.h) against its analytic description: points on
// rings of radius k / rings in the XY plane, normal +Z, tangent +X, u = (x + 1) / 2 and
// v = (y + 1) / 2 (so a circular TPR map centred at (0.5, 0.5) turns around the disk's centre),
// every triangle counter-clockwise seen from +Z in space and in UV, the area that of the regular
// polygon it approximates, (n / 2) sin(2 pi / n), and the loader's validation finds nothing
// to drop or merge. "disk" names it.
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshValidation.h"

#include <cmath>
#include <gtest/gtest.h>

namespace aniso
{
namespace
{
TEST(BuiltinDisk, FollowsItsAnalyticDescription)
{
  constexpr int around = 48;
  constexpr int rings = 6;
  vtkSmartPointer<vtkPolyData> disk = makeDisk(around, rings);
  vtkPointData* pd = disk->GetPointData();
  ASSERT_NE(pd->GetNormals(), nullptr);
  ASSERT_NE(pd->GetTangents(), nullptr);
  ASSERT_NE(pd->GetTCoords(), nullptr);
  ASSERT_EQ(disk->GetNumberOfPoints(), 1 + around * rings);
  ASSERT_EQ(disk->GetNumberOfPolys(), around * (2 * rings - 1));
  for (vtkIdType id = 0; id < disk->GetNumberOfPoints(); ++id)
  {
    const glm::dvec3 p = test::point(disk, id);
    EXPECT_EQ(p.z, 0.0);
    // On one of the rings (or the centre).
    const double ring = std::hypot(p.x, p.y) * rings;
    EXPECT_NEAR(ring, std::round(ring), 1e-6);
    EXPECT_LE(std::round(ring), rings);
    const glm::dvec2 uv = test::vec2(pd->GetTCoords(), id);
    EXPECT_NEAR(uv.x, 0.5 * (p.x + 1.0), 1e-6);
    EXPECT_NEAR(uv.y, 0.5 * (p.y + 1.0), 1e-6);
    EXPECT_EQ(test::vec3(pd->GetNormals(), id), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(test::vec3(pd->GetTangents(), id), glm::dvec3(1.0, 0.0, 0.0));
  }
  test::forEachTriangle(disk,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c)
                        {
                          EXPECT_GT(test::faceNormalUnnormalised(disk, a, b, c).z, 0.0);
                          const glm::dvec2 uv0 = test::vec2(pd->GetTCoords(), a);
                          const glm::dvec2 d1 = test::vec2(pd->GetTCoords(), b) - uv0;
                          const glm::dvec2 d2 = test::vec2(pd->GetTCoords(), c) - uv0;
                          EXPECT_GT(d1.x * d2.y - d1.y * d2.x, 0.0);
                        });
  EXPECT_NEAR(test::surfaceArea(disk), 0.5 * around * std::sin(2.0 * test::kPi / around), 1e-5);
}

TEST(BuiltinDisk, IsNamedAndPassesTheLoaderValidation)
{
  EXPECT_EQ(parseBuiltinMesh("disk"), BuiltinMesh::Disk);
  EXPECT_EQ(builtinMeshName(BuiltinMesh::Disk), "disk");
  LoadedMesh mesh = makeBuiltinMesh(BuiltinMesh::Disk);
  EXPECT_EQ(mesh.report.source, "builtin:disk");
  MeshReport report;
  vtkSmartPointer<vtkPolyData> clean = sanitizeSurface(mesh.polyData, mesh.report.source, report);
  EXPECT_EQ(report.zeroAreaTrianglesDropped, 0);
  EXPECT_EQ(report.duplicateVerticesMerged, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(clean->GetNumberOfPolys(), mesh.polyData->GetNumberOfPolys());
  // One boundary: the outer ring.
  EXPECT_EQ(mesh.report.boundaryEdges, 128);
}
} // namespace
} // namespace aniso
