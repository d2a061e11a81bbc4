#pragma once
// Small accessors shared by the geometry tests: read VTK arrays as glm vectors, and the
// geometric measures (area, signed volume) that serve as independent references.
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace aniso::test
{
constexpr double kPi = 3.14159265358979323846;

inline glm::dvec3 point(vtkPolyData* mesh, vtkIdType id)
{
  double p[3];
  mesh->GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

inline glm::dvec3 vec3(vtkDataArray* array, vtkIdType id)
{
  return {array->GetComponent(id, 0), array->GetComponent(id, 1), array->GetComponent(id, 2)};
}

inline glm::dvec2 vec2(vtkDataArray* array, vtkIdType id)
{
  return {array->GetComponent(id, 0), array->GetComponent(id, 1)};
}

// Calls f(a, b, c) with the point ids of every triangle.
template <typename F>
void forEachTriangle(vtkPolyData* mesh, F&& f)
{
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(count, ids);
    if (count == 3)
    {
      f(ids[0], ids[1], ids[2]);
    }
  }
}

inline glm::dvec3 faceNormalUnnormalised(vtkPolyData* mesh, vtkIdType a, vtkIdType b, vtkIdType c)
{
  const glm::dvec3 p0 = point(mesh, a);
  return glm::cross(point(mesh, b) - p0, point(mesh, c) - p0);
}

inline double surfaceArea(vtkPolyData* mesh)
{
  double area = 0.0;
  forEachTriangle(mesh, [&](vtkIdType a, vtkIdType b, vtkIdType c)
                  { area += 0.5 * glm::length(faceNormalUnnormalised(mesh, a, b, c)); });
  return area;
}

// Divergence theorem: positive for a closed surface wound counter-clockwise seen from outside.
inline double signedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  forEachTriangle(
      mesh, [&](vtkIdType a, vtkIdType b, vtkIdType c)
      { volume += glm::dot(point(mesh, a), glm::cross(point(mesh, b), point(mesh, c))) / 6.0; });
  return volume;
}

inline bool allFinite(vtkPolyData* mesh)
{
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = point(mesh, i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    {
      return false;
    }
  }
  return true;
}
} // namespace aniso::test
