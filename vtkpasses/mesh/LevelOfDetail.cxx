#include "vtkpasses/mesh/LevelOfDetail.h"

#include <algorithm>
#include <cmath>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricClustering.h>
#include <vtkTriangle.h>

namespace aniso
{
namespace
{
double surfaceArea(vtkPolyData* surface)
{
  double area = 0.0;
  vtkPoints* points = surface->GetPoints();
  vtkCellArray* polys = surface->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  double a[3], b[3], c[3];
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n != 3)
    {
      continue;
    }
    points->GetPoint(ids[0], a);
    points->GetPoint(ids[1], b);
    points->GetPoint(ids[2], c);
    area += vtkTriangle::TriangleArea(a, b, c);
  }
  return area;
}

vtkSmartPointer<vtkPolyData> cluster(vtkPolyData* surface, const int divisions[3])
{
  vtkNew<vtkQuadricClustering> clustering;
  clustering->SetInputData(surface);
  clustering->AutoAdjustNumberOfDivisionsOff();
  clustering->SetNumberOfDivisions(divisions[0], divisions[1], divisions[2]);
  clustering->UseInputPointsOn();
  clustering->CopyCellDataOff();
  clustering->Update();
  vtkPolyData* clustered = clustering->GetOutput();
  // Clustering folds a few slivers over (a triangle whose winding faces against its points'
  // normals): dropped, as a view that culls back faces or lights them would show them.
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(clustered);
  vtkDataArray* normals = clustered->GetPointData()->GetNormals();
  if (!normals)
  {
    return out;
  }
  vtkNew<vtkCellArray> kept;
  kept->AllocateEstimate(clustered->GetNumberOfPolys(), 3);
  vtkCellArray* polys = clustered->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n != 3)
    {
      continue;
    }
    double p[3][3], face[3];
    double facing = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      clustered->GetPoint(ids[k], p[k]);
    }
    vtkTriangle::ComputeNormal(p[0], p[1], p[2], face);
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        facing += face[c] * normals->GetComponent(ids[k], c);
      }
    }
    if (facing > 0.0)
    {
      kept->InsertNextCell(3, ids);
    }
  }
  out->SetPolys(kept);
  return out;
}
} // namespace

vtkIdType partStandInTriangles(vtkIdType partTriangles, vtkIdType sceneTriangles, vtkIdType limit,
                               vtkIdType maxTriangles)
{
  const vtkIdType scene = std::max(sceneTriangles, partTriangles);
  if (partTriangles <= 0 || scene <= limit || maxTriangles < 1)
  {
    return 0;
  }
  const double share = double(maxTriangles) * double(partTriangles) / double(scene);
  return std::max(kInteractivePartTriangles, static_cast<vtkIdType>(share));
}

vtkSmartPointer<vtkPolyData> interactiveLevelOfDetail(vtkPolyData* surface, vtkIdType limit,
                                                      vtkIdType maxTriangles)
{
  if (!surface || surface->GetNumberOfPolys() <= limit || maxTriangles < 1)
  {
    return nullptr;
  }
  // A surface crosses about area / h^2 cells of side h and clustering leaves about two triangles
  // per cell crossed: h from the area, then smaller grids while the result has too many.
  const double area = surfaceArea(surface);
  double bounds[6];
  surface->GetBounds(bounds);
  const double extent[3] = {bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]};
  const double largest = std::max({extent[0], extent[1], extent[2]});
  if (!(area > 0.0) || !(largest > 0.0) || !std::isfinite(area) || !std::isfinite(largest))
  {
    return nullptr;
  }
  double cell = std::sqrt(2.0 * area / double(maxTriangles));
  for (int attempt = 0; attempt < 8; ++attempt)
  {
    int divisions[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      // Cells as near cubes as the box allows; a flat axis gets one.
      const double count = std::ceil(extent[axis] / cell);
      divisions[axis] = static_cast<int>(std::clamp(count, 1.0, 4096.0));
    }
    vtkSmartPointer<vtkPolyData> coarse = cluster(surface, divisions);
    const vtkIdType triangles = coarse->GetNumberOfPolys();
    if (triangles <= maxTriangles)
    {
      return triangles > 0 ? coarse : nullptr;
    }
    cell *= std::max(1.05, std::sqrt(double(triangles) / double(maxTriangles)));
  }
  return nullptr;
}
} // namespace aniso
