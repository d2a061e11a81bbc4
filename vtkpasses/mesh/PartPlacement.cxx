#include "vtkpasses/mesh/PartPlacement.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
// A copy of ARRAY (float, 3 components) with each tuple mapped by MAP.
template <typename Map>
vtkSmartPointer<vtkFloatArray> mapped(vtkDataArray* array, Map&& map)
{
  auto out = vtkSmartPointer<vtkFloatArray>::New();
  out->SetName(array->GetName());
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(array->GetNumberOfTuples());
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    double v[3];
    array->GetTuple(i, v);
    const glm::dvec3 r = map(i, glm::dvec3(v[0], v[1], v[2]));
    out->SetTuple3(i, r.x, r.y, r.z);
  }
  return out;
}

glm::dvec3 unit(const glm::dvec3& v)
{
  const double length = glm::length(v);
  return length > 0.0 ? v / length : v;
}
} // namespace

vtkSmartPointer<vtkPolyData> placedSurface(vtkPolyData* surface, const PartMatrix& m)
{
  auto placed = vtkSmartPointer<vtkPolyData>::New();
  placed->ShallowCopy(surface);
  // glm is column-major: element (row r, column c) of M is linear[c][r].
  glm::dmat3 linear;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[c][r] = m[std::size_t(4 * r + c)];
    }
  }
  const glm::dvec3 offset(m[3], m[7], m[11]);
  const glm::dmat3 normalMap = glm::transpose(glm::inverse(linear));

  vtkPoints* points = surface->GetPoints();
  vtkNew<vtkPoints> moved;
  moved->SetDataType(points->GetDataType());
  moved->SetNumberOfPoints(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const glm::dvec3 q = linear * glm::dvec3(p[0], p[1], p[2]) + offset;
    moved->SetPoint(i, q.x, q.y, q.z);
  }
  placed->SetPoints(moved);

  // New point data sharing every array but the two that turn with the part.
  vtkPointData* from = surface->GetPointData();
  vtkPointData* to = placed->GetPointData();
  to->ShallowCopy(from);
  vtkDataArray* normals = from->GetNormals();
  vtkSmartPointer<vtkFloatArray> newNormals;
  if (normals)
  {
    newNormals = mapped(normals, [&](vtkIdType, const glm::dvec3& n) { return unit(normalMap * n); });
    to->SetNormals(newNormals);
  }
  if (vtkDataArray* tangents = from->GetTangents())
  {
    to->SetTangents(mapped(tangents,
                           [&](vtkIdType i, const glm::dvec3& t)
                           {
                             glm::dvec3 turned = linear * t;
                             if (newNormals)
                             {
                               double n[3];
                               newNormals->GetTuple(i, n);
                               const glm::dvec3 normal(n[0], n[1], n[2]);
                               turned -= normal * glm::dot(normal, turned);
                             }
                             return unit(turned);
                           }));
  }
  return placed;
}
} // namespace aniso
