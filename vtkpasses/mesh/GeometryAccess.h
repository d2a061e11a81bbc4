#pragma once
// Accessors shared by the geometry code: VTK points and tuples as glm vectors, a loop over the
// cells of a cell array, and the whole-file read of the hand-written readers.
#include "core/error.h"

#include <algorithm>
#include <fstream>
#include <glm/vec3.hpp>
#include <iterator>
#include <string>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

namespace aniso::geometry
{
inline glm::dvec3 pointAt(vtkPoints* points, vtkIdType id)
{
  double p[3];
  points->GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

// The first three components (missing ones read as 0).
inline glm::dvec3 tupleAt(vtkDataArray* array, vtkIdType id)
{
  glm::dvec3 v(0.0);
  const int components = std::min(array->GetNumberOfComponents(), 3);
  for (int c = 0; c < components; ++c)
  {
    v[c] = array->GetComponent(id, c);
  }
  return v;
}

// Calls f(count, ids) for every cell. A cell array whose offsets do not fit its connectivity
// (out of order, past its end: a hostile file's, which VTK's readers and the reader program's
// XML pass on as they are) is walked cell by cell, and a cell whose ids lie outside the
// connectivity is passed as an empty cell (count 0), so that callers count it and never read
// past the array (fuzz_vtk; tests/data/fuzz/vtk).
template <typename F>
void forEachCell(vtkCellArray* cells, F&& f)
{
  if (!cells)
  {
    return;
  }
  if (!cells->IsValid())
  {
    vtkDataArray* offsets = cells->GetOffsetsArray();
    const vtkIdType size = cells->GetNumberOfConnectivityIds();
    const vtkIdType n = offsets ? offsets->GetNumberOfTuples() - 1 : 0;
    vtkNew<vtkIdList> cell;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double start = offsets->GetComponent(i, 0);
      const double end = offsets->GetComponent(i + 1, 0);
      if (!(start >= 0.0 && start <= end && end <= double(size)))
      {
        static const vtkIdType none = 0;
        f(vtkIdType(0), &none);
        continue;
      }
      cells->GetCellAtId(i, cell);
      f(cell->GetNumberOfIds(), static_cast<const vtkIdType*>(cell->GetPointer(0)));
    }
    return;
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(count, ids);
    f(count, ids);
  }
}

inline std::string readFileBytes(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    throw errorAbout(path, "cannot be opened");
  }
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}
} // namespace aniso::geometry
