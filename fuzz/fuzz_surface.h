#pragma once
// What the mesh harnesses check of every surface they get: sanitizeSurface promises finite
// points, so a point that is not finite is a finding (abort).
#include <cmath>
#include <cstdlib>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso::fuzz
{
inline void checkFinite(vtkPolyData* surface)
{
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      std::abort();
    }
  }
}
} // namespace aniso::fuzz
