#pragma once
// A part's surface where its placement (core/placement.h) puts it.
#include "core/placement.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// A copy of SURFACE (a prepared surface: SurfacePreparation.h) placed by MATRIX: points by it,
// "Normals" by the inverse transpose of its linear part, "Tangents" by the linear part then
// made orthogonal to the normal, both unit again; cells and the other arrays are shared. The
// AS lobe depends on (h.t)^2 and (h.b)^2 only, so a mirroring placement (b = n x t turning
// over) shades the same. MATRIX must be affine and invertible (the scene checks that).
vtkSmartPointer<vtkPolyData> placedSurface(vtkPolyData* surface, const PartMatrix& matrix);
} // namespace aniso
