#pragma once
// The last geometry step before shading: normals and tangents on a clean triangle surface.
//
// Contract with the shading side (what prepareSurface returns):
//   a vtkPolyData of triangles only, with point arrays
//     "Normals"  float, 3 components, unit length;
//     "Tangents" float, 3 components, unit length, orthogonal to the normal (to float rounding),
//                along +u of the UV map (dP/du) or along the brushing direction: the direction
//                n_u acts along; the shader builds b = n x t (docs/METHOD.md);
//     "TCoords"  float, 2 components, when the mesh has texture coordinates;
//   each set as the active normals, tangents and texture coordinates of the point data.
//
// Normals: the mesh's own (unit, validated by sanitizeSurface) are kept unless
// SurfaceOptions::recomputeNormals is set. Otherwise vtkPolyDataNormals makes them with
// splitting at the feature angle (vertices on sharper edges are duplicated, so a CAD part keeps
// its hard edges), consistent winding, and outward orientation when the surface is closed and
// manifold (VTK's auto-orientation assumes that). A vertex normal is the unweighted mean of its
// faces' normals; where they cancel (a sheet folded onto itself) the vertex takes the normal of
// one of its faces, so every normal is unit.
//
// Tangents, by SurfaceOptions::brushing (BrushingModel.h):
//   unset   the mesh's own tangents when all are valid (built-in meshes carry the analytic
//           dP/du; glTF TANGENT is defined along +u); else from the UVs; else face-u on a CAD
//           part (its faces' dS/du: a turned face brushed round its axis); else axis:1,0,0
//           (linear brushing along X), the common brushed-metal look.
//   uv      the mesh's own tangents when all are valid, else computed from the UVs; with
//           neither, an aniso::Error (the user asked for something the mesh cannot give).
//   axis, around, radial, face-u, face-v, array:NAME   always generated from the model.
// Every other point array of the mesh (scalar and vector fields) is kept, and carried to the
// vertices that splitting adds; cell arrays are kept per triangle.
// A mesh tangent is invalid when it is not finite or its part orthogonal to the normal is
// shorter than 1e-3 of it (within 0.06 degrees of the normal); one invalid tangent makes the
// whole field be regenerated, since a half-kept field would have visible discontinuities.
#include "vtkpasses/mesh/BrushingModel.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
struct SurfaceOptions
{
  double featureAngleDegrees = 30.0; // edges sharper than this keep separate normals
  bool recomputeNormals = false;     // ignore the mesh's normals
  std::optional<BrushingModel> brushing;
};

struct SurfaceReport
{
  bool normalsComputed = false;
  bool normalsAutoOriented = false;
  double featureAngleDegrees = 0.0;
  int64_t pointsAddedBySplitting = 0;
  int64_t repairedNormals = 0;     // zero normals (faces cancelling) replaced by a face normal
  std::string tangentSource;       // "mesh" or a brushing model spelled as on the CLI
  int64_t invalidMeshTangents = 0; // mesh tangents that forced a regeneration
  int64_t fallbackTangents = 0;    // points with the deterministic fallback tangent
  int64_t nonFiniteFieldTangents = 0; // of those, where array:NAME's field was NaN or Inf

  std::vector<std::string> notes() const; // one sentence per thing worth telling the user
};

struct PreparedSurface
{
  vtkSmartPointer<vtkPolyData> polyData;
  SurfaceReport report;
};

// Normals split at `featureAngleDegrees` (0 < angle <= 180), consistently wound; oriented
// outwards when `autoOrient`. Existing normals are replaced; other point arrays are carried to
// the split vertices.
vtkSmartPointer<vtkPolyData> computeFeatureNormals(vtkPolyData* triangles,
                                                   double featureAngleDegrees, bool autoOrient);

// `mesh` is a sanitised triangle surface (loadMesh, makeBuiltinMesh); it is not modified.
// `subject` (file path or builtin name) prefixes error messages.
PreparedSurface prepareSurface(vtkPolyData* mesh, const SurfaceOptions& options,
                               const std::string& subject);
} // namespace aniso
