#pragma once
// A CAD-like benchmark part: a turned flange (axis Z) with a hub, a bore, chamfers, a fillet
// and six bolt holes. Flat faces are meshed as structured quads around each hole (an O-grid
// per 60-degree sector), so tangents interpolate smoothly; turned faces are surfaces of
// revolution. Sizes: outer radius 1, flange 0.18 thick, hub radius 0.42 up to z = 0.55, bore
// radius 0.25, holes of radius 0.07 on a 0.72 circle.
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso::bench
{
// A closed triangle surface wound counter-clockwise seen from outside, points merged, no normals
// or tangents yet (prepareSurface adds normals split at the sharp edges and the tangents).
vtkSmartPointer<vtkPolyData> makeFlange();
} // namespace aniso::bench
