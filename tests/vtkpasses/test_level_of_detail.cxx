// The stand-in of a large surface while the view moves (LevelOfDetail.h): none for a surface at
// or under the limit; at most the asked triangles otherwise; every point one of the surface's
// own with its normal, tangent and texture coordinates exactly; the same shape (area against
// the torus's analytic area, bounds) and the same facing (winding against the normals).
#include "BuiltinMeshes.h"
#include "LevelOfDetail.h"
#include "SurfacePreparation.h"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <vector>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangle.h>

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

double area(vtkPolyData* surface)
{
  double sum = 0.0;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  double a[3], b[3], c[3];
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    surface->GetPoint(ids[0], a);
    surface->GetPoint(ids[1], b);
    surface->GetPoint(ids[2], c);
    sum += vtkTriangle::TriangleArea(a, b, c);
  }
  return sum;
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
  const double analytic = 4.0 * M_PI * M_PI * kMajor * kMinor;
  EXPECT_NEAR(area(coarse), analytic, 0.02 * analytic);
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
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkDataArray* normals = out->GetNormals();
  vtkCellArray* polys = coarse->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double p0[3], p1[3], p2[3], face[3];
    coarse->GetPoint(ids[0], p0);
    coarse->GetPoint(ids[1], p1);
    coarse->GetPoint(ids[2], p2);
    vtkTriangle::ComputeNormal(p0, p1, p2, face);
    double mean[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        mean[c] += normals->GetComponent(ids[k], c);
      }
    }
    flipped += (face[0] * mean[0] + face[1] * mean[1] + face[2] * mean[2]) <= 0.0 ? 1 : 0;
  }
  EXPECT_EQ(flipped, 0) << "of " << triangles;
}
} // namespace
} // namespace aniso
