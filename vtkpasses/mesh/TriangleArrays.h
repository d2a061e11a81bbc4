#pragma once
// A prepared surface as the plain arrays the CPU reference's ray caster reads
// (core/reference/pixel_geometry.h): points, "Normals", "Tangents" and the triangles.
#include "core/reference/pixel_geometry.h"

class vtkPolyData;

namespace aniso
{
// Throws aniso::Error "mesh: reason" for a surface without "Normals" and "Tangents". Polygons
// other than triangles are left out (prepared surfaces hold triangles only).
TriangleMesh triangleMesh(vtkPolyData* surface);
} // namespace aniso
