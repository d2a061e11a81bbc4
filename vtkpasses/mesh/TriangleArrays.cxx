#include "vtkpasses/mesh/TriangleArrays.h"

#include "vtkpasses/mesh/GeometryAccess.h"

#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso
{
using geometry::forEachCell;
using geometry::pointAt;
using geometry::tupleAt;

TriangleMesh triangleMesh(vtkPolyData* surface)
{
  vtkDataArray* normals = surface->GetPointData()->GetArray("Normals");
  vtkDataArray* tangents = surface->GetPointData()->GetArray("Tangents");
  if (!normals || !tangents)
  {
    throw errorAbout("mesh", "a prepared surface with Normals and Tangents is needed");
  }
  TriangleMesh mesh;
  const vtkIdType points = surface->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i)
  {
    mesh.positions.push_back(pointAt(surface->GetPoints(), i));
    mesh.normals.push_back(tupleAt(normals, i));
    mesh.tangents.push_back(tupleAt(tangents, i));
  }
  forEachCell(surface->GetPolys(),
                        [&](vtkIdType count, const vtkIdType* ids)
                        {
                          if (count == 3)
                          {
                            mesh.triangles.push_back({static_cast<uint32_t>(ids[0]),
                                                      static_cast<uint32_t>(ids[1]),
                                                      static_cast<uint32_t>(ids[2])});
                          }
                        });
  return mesh;
}

} // namespace aniso
