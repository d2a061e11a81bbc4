#pragma once
// Built-in meshes with analytic normals, tangents and texture coordinates (docs/METHOD.md conventions).
//
//   sphere: radius 1 at the origin, poles on +-Z. A point at longitude phi = atan2(y, x) and
//           polar angle theta (from +Z) has u = phi / (2 pi) in [0, 1] (u = 0 at +X, growing
//           towards +Y; the seam at phi = 0 is duplicated with u = 0 and u = 1) and
//           v = 1 - theta / pi (v = 1 at the north pole). Normal = position. Tangent = dP/du
//           normalised = (-sin phi, cos phi, 0): along the parallels, so n_u acts along them and
//           b = n x t points north (+v). Each pole is a ring of vertices, one per triangle of the
//           pole fan, at the fan triangle's mid-longitude: the tangent there is
//           (-sin phi, cos phi, 0) for that phi, defined and orthogonal to n = +-Z.
//   torus:  axis Z, major radius 1, minor radius 0.35. u = phi / (2 pi) around the main axis,
//           v = psi / (2 pi) around the tube (psi = 0 on the outer equator, growing towards +Z).
//           P = ((R + r cos psi) cos phi, (R + r cos psi) sin phi, r sin psi),
//           n = (cos psi cos phi, cos psi sin phi, sin psi), t = (-sin phi, cos phi, 0).
//   plate:  the square [-1, 1]^2 in the XY plane, normal +Z, u = (x + 1) / 2 along +X,
//           v = (y + 1) / 2 along +Y, t = +X.
//   disk:   the unit disk x^2 + y^2 <= 1 in the XY plane, with the plate's normal, tangent and
//           UVs (u = (x + 1) / 2, v = (y + 1) / 2), so a circular TPR map centred at (0.5, 0.5)
//           turns around its centre: rings of vertices around a centre vertex.
// Output follows the contract of SurfacePreparation.h: triangles wound counter-clockwise seen
// from outside, float point arrays "Normals", "Tangents" (unit, orthogonal to the normal) and
// "TCoords", all set active.
#include "vtkpasses/mesh/MeshLoader.h"

#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
enum class BuiltinMesh
{
  Sphere,
  Torus,
  Plate,
  Disk
};

// "sphere", "torus", "plate", "disk"; anything else is an aniso::Error "SUBJECT: reason".
BuiltinMesh parseBuiltinMesh(const std::string& name, const std::string& subject = "--builtin");
std::string builtinMeshName(BuiltinMesh mesh);
std::string builtinMeshNames(); // "sphere|torus|plate|disk", for help texts

// Resolutions: the defaults are smooth at full-screen sizes.
vtkSmartPointer<vtkPolyData> makeSphere(int segmentsAround = 128, int segmentsPoleToPole = 64);
vtkSmartPointer<vtkPolyData> makeTorus(int segmentsAround = 128, int segmentsAroundTube = 64,
                                       double majorRadius = 1.0, double minorRadius = 0.35);
vtkSmartPointer<vtkPolyData> makePlate(int segmentsPerSide = 32);
vtkSmartPointer<vtkPolyData> makeDisk(int segmentsAround = 128, int rings = 32);

// The mesh at its default resolution with a report, so callers treat it like a loaded file.
LoadedMesh makeBuiltinMesh(BuiltinMesh mesh);
} // namespace aniso
