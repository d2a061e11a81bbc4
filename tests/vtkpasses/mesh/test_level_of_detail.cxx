// The stand-in of a large surface while the view moves (LevelOfDetail.h): none for a surface at
// or under the limit; at most the asked triangles otherwise; every point one of the surface's
// own with its normal, tangent and texture coordinates exactly; the same shape (area against
// the torus's analytic area, bounds) and the same facing (winding against the normals).
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/LevelOfDetail.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <map>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
constexpr double kMajor = 1.0;
constexpr double kMinor = 0.35;

vtkSmartPointer<vtkPolyData> preparedTorus(int around, int tube)
{
  vtkSmartPointer<vtkPolyData> torus = makeTorus(around, tube, kMajor, kMinor);
  return prepareSurface(torus, SurfaceOptions{}, "torus").polyData;
}

// Every value of a point: position, then each point array's components in array order.
std::vector<double> pointValues(vtkPolyData* surface, vtkIdType id)
{
  double p[3];
  surface->GetPoint(id, p);
  std::vector<double> v(p, p + 3);
  vtkPointData* data = surface->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      v.push_back(array->GetComponent(id, c));
    }
  }
  return v;
}

TEST(LevelOfDetail, NoneAtOrUnderTheLimit)
{
  vtkSmartPointer<vtkPolyData> surface = preparedTorus(100, 50); // 10 000 triangles
  ASSERT_EQ(surface->GetNumberOfPolys(), 10000);
  EXPECT_EQ(interactiveLevelOfDetail(surface, 10000, 1000), nullptr);
  EXPECT_NE(interactiveLevelOfDetail(surface, 9999, 1000), nullptr);
}

TEST(LevelOfDetail, ALargeTorusKeepsItsShapeAttributesAndFacing)
{
  vtkSmartPointer<vtkPolyData> surface = preparedTorus(400, 200); // 160 000 triangles
  ASSERT_GT(surface->GetNumberOfPolys(), kInteractiveTriangleLimit);
  vtkSmartPointer<vtkPolyData> coarse = interactiveLevelOfDetail(surface);
  ASSERT_NE(coarse, nullptr);
  const vtkIdType triangles = coarse->GetNumberOfPolys();
  EXPECT_LE(triangles, kInteractiveTriangles);
  EXPECT_GE(triangles, kInteractiveTriangles / 4) << "far coarser than asked";
  EXPECT_EQ(coarse->GetNumberOfPolys(), coarse->GetNumberOfCells()) << "triangles only";

  // The same arrays, active as in the surface.
  vtkPointData* in = surface->GetPointData();
  vtkPointData* out = coarse->GetPointData();
  ASSERT_EQ(out->GetNumberOfArrays(), in->GetNumberOfArrays());
  ASSERT_NE(out->GetNormals(), nullptr);
  ASSERT_NE(out->GetTangents(), nullptr);
  EXPECT_EQ(out->GetTCoords() != nullptr, in->GetTCoords() != nullptr);

  // Each point and its attributes are those of a point of the surface (points on the seam are
  // duplicated there with other texture coordinates: any of them).
  std::multimap<std::array<double, 3>, vtkIdType> byPosition;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    byPosition.emplace(std::array<double, 3>{p[0], p[1], p[2]}, i);
  }
  int unmatched = 0;
  for (vtkIdType i = 0; i < coarse->GetNumberOfPoints(); ++i)
  {
    const std::vector<double> values = pointValues(coarse, i);
    const auto range = byPosition.equal_range({values[0], values[1], values[2]});
    bool found = false;
    for (auto it = range.first; it != range.second && !found; ++it)
    {
      found = pointValues(surface, it->second) == values;
    }
    unmatched += found ? 0 : 1;
  }
  EXPECT_EQ(unmatched, 0) << "of " << coarse->GetNumberOfPoints() << " points";

  // Shape: the area of the torus (4 pi^2 R r) within 2 % (the surface's own chords lose 0.01 %;
  // the stand-in's coarser chords cut a little more), bounds within a cell of the surface's.
  const double analytic = 4.0 * test::kPi * test::kPi * kMajor * kMinor;
  EXPECT_NEAR(test::surfaceArea(coarse), analytic, 0.02 * analytic);
  double a[6], b[6];
  surface->GetBounds(a);
  coarse->GetBounds(b);
  const double cell = std::sqrt(2.0 * analytic / double(kInteractiveTriangles));
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], a[i], 2.0 * cell) << "bound " << i;
  }

  // Facing: each triangle's winding agrees with its vertices' normals (clustering folds a few
  // slivers over, 280 of 38 176 here, which a culling or two-sided view would show).
  int flipped = 0;
  vtkDataArray* normals = out->GetNormals();
  test::forEachTriangle(coarse,
                        [&](vtkIdType i, vtkIdType j, vtkIdType k)
                        {
                          const glm::dvec3 mean = test::vec3(normals, i) + test::vec3(normals, j) +
                                                  test::vec3(normals, k);
                          const glm::dvec3 face = test::faceNormalUnnormalised(coarse, i, j, k);
                          flipped += glm::dot(face, mean) <= 0.0 ? 1 : 0;
                        });
  EXPECT_EQ(flipped, 0) << "of " << triangles;
}
// A part of a file of many parts (partStandInTriangles): nothing while the parts together are
// within the limit; over it, each part its share of the stand-in triangles in proportion to its
// own (so the shares add up to at most the stand-in's total), never under the floor; one part
// alone is the single-surface rule. A small torus (960 triangles) cut to its share of a scene
// of 200 such parts keeps its size: bounds within a cell of the clustering grid.
TEST(LevelOfDetail, APartOfAManyPartSceneGetsItsShare)
{
  EXPECT_EQ(partStandInTriangles(960, 200 * 960, 200000, 40000), 0);
  EXPECT_EQ(partStandInTriangles(960, 200 * 960), 200);
  EXPECT_EQ(partStandInTriangles(960, 200 * 960) * 200, kInteractiveTriangles);
  EXPECT_EQ(partStandInTriangles(10, 200 * 960), kInteractivePartTriangles);
  EXPECT_EQ(partStandInTriangles(300000, 300000), kInteractiveTriangles);
  EXPECT_EQ(partStandInTriangles(50000, 50000), 0);
  EXPECT_EQ(partStandInTriangles(0, 200 * 960), 0);

  vtkSmartPointer<vtkPolyData> part =
      prepareSurface(makeTorus(24, 20, kMajor, kMinor), SurfaceOptions{}, "torus").polyData;
  ASSERT_EQ(part->GetNumberOfPolys(), 960);
  const vtkIdType share = partStandInTriangles(960, 200 * 960);
  vtkSmartPointer<vtkPolyData> coarse = interactiveLevelOfDetail(part, share, share);
  ASSERT_NE(coarse, nullptr);
  EXPECT_LE(coarse->GetNumberOfPolys(), share);
  EXPECT_GT(coarse->GetNumberOfPolys(), share / 4);
  double a[6], b[6];
  part->GetBounds(a);
  coarse->GetBounds(b);
  const double cell = std::sqrt(2.0 * test::surfaceArea(part) / double(share));
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], a[i], 2.0 * cell) << "bound " << i;
  }
}
} // namespace
} // namespace aniso
