#pragma once
// Tangent fields from a brushing model, for meshes without UVs (most CAD and scientific meshes)
// and for overriding the UV direction. t is the direction n_u acts along (docs/METHOD.md).
//
//   uv                   t = dP/du from the texture coordinates: per triangle
//                        dP/du = (e1 dv2 - e2 dv1) / (du1 dv2 - du2 dv1), accumulated at its
//                        corners weighted by the corner angle, then made orthogonal to n.
//   axis:X,Y,Z           linear brushing: t = the axis projected into the tangent plane.
//   around:X,Y,Z         turned/lathed parts: t = axis x (p - c) projected into the tangent plane,
//   around:X,Y,Z@CX,CY,CZ  c = the given point on the axis, else the bounding-box centre.
//   radial:X,Y,Z         brushing out from a point: t = (p - point) projected into the plane.
//   face-u, face-v       a CAD part's own faces (STEP, IGES: CadReader.h): t = dS/du or dS/dv of
//                        the face's surface at the point (the arrays "BRepTangentU" and
//                        "BRepTangentV"), projected into the plane. OpenCASCADE's cylinders,
//                        cones, spheres, tori and surfaces of revolution have u around their
//                        axis, so face-u brushes a turned part round, face-v along its axis (a
//                        cone's along its generatrix); a plane's u is its X direction.
//   array:NAME           a vector field of the mesh: t = the point array NAME (2 or 3
//                        components, a 2-component one read as (x, y, 0)) projected into the
//                        tangent plane. A cell array NAME (no point array of that name) is
//                        averaged to the points first: each face's vector weighted by the angle
//                        of its corner at the point, faces with a NaN or Inf component left out.
//                        Vertices whose value is NaN or Inf (a point array) or that touch only
//                        such faces take the fallback and are counted in nonFinitePoints too.
// Where the projection vanishes (the direction is along the normal, or p lies on the axis or at
// the point), t falls back to the deterministic tangent of Frame::fromNormalTangent (core/frame.h,
// the X axis projected, or Y when n is near X) and the point is counted (face-u and face-v where the
// face's derivative vanishes, at a pole or a cone's apex). "Vanishes" means the
// projection is shorter than 1e-6 of the direction, or p is within 1e-9 of the mesh's size from
// the axis or point.
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

class vtkPolyData;

namespace aniso
{
enum class BrushingKind
{
  Uv,
  Axis,
  Around,
  Radial,
  FaceU,
  FaceV,
  Array
};

struct BrushingModel
{
  BrushingKind kind = BrushingKind::Uv;
  glm::dvec3 vector{0.0, 0.0, 1.0}; // unit axis (Axis, Around) or the centre point (Radial)
  std::optional<glm::dvec3> centre; // Around: a point on the axis; unset = bounding-box centre
  std::string array;                // Array: the name of the point or cell array
};

// The CLI spelling "uv|axis:X,Y,Z|around:X,Y,Z[@CX,CY,CZ]|radial:X,Y,Z|face-u|face-v|array:NAME".
// Errors are aniso::Error "SUBJECT: reason" (unknown model, missing or non-numeric components,
// zero-length axis, no array name).
BrushingModel parseBrushingModel(const std::string& text,
                                 const std::string& subject = "--tangents");
std::string toString(const BrushingModel& model); // parses back to the same model
std::string brushingModelSyntax();                // for help texts

struct TangentStats
{
  int64_t points = 0;
  int64_t fallbackPoints = 0; // where the model gave no direction in the tangent plane
  int64_t nonFinitePoints = 0; // of those, where the array's value was NaN or Inf (array:NAME)
};

// Writes the float point array "Tangents" (unit, orthogonal to "Normals", set active) of a
// triangle surface that has unit point normals. Uv needs "TCoords": without them it throws
// aniso::Error "SUBJECT: reason"; so do face-u and face-v without their array, and array:NAME
// when the mesh has no point or cell array NAME of 2 or 3 components (the message lists the
// vector arrays it has).
TangentStats computeBrushingTangents(vtkPolyData* surface, const BrushingModel& model,
                                     const std::string& subject);
} // namespace aniso
