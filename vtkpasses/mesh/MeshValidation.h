#pragma once
// Turning whatever a reader produced into a clean triangle surface, and saying what was changed.
//
// sanitizeSurface() applies, in this order:
//   1. cells whose point ids are out of range are dropped (hostile or broken files);
//   2. vertices and lines are dropped (the renderer draws surfaces only);
//   3. faces touching a vertex with NaN/Inf coordinates are dropped;
//   4. polygons and strips are triangulated (quads along the diagonal inside them, larger
//      polygons by ear cutting with a fan as the fallback);
//   5. zero-area triangles are dropped: twice the area below 1e-10 of the longest edge squared,
//      i.e. the triangle has no usable normal even in double precision;
//   6. duplicate vertices are merged when their position AND every point attribute (normals,
//      texture coordinates, colours, ...) are bitwise equal. Vertices that share a position
//      but differ in an attribute are kept apart on purpose: they encode UV seams and hard
//      edges, which a position-only merge (vtkCleanPolyData) would destroy;
//   7. vertices no triangle uses are removed;
//   8. point normals, texture coordinates and tangents are converted to float arrays named
//      "Normals" (3), "TCoords" (2) and "Tangents" (3, the xyz of a 4-component glTF tangent)
//      and set active. A normals or texture-coordinate array with any non-finite or zero-length
//      entry is discarded as a whole (normals are then recomputed by SurfacePreparation);
//      tangents are validated later against the normals. Every other numeric point array is
//      kept as it is (scalar and vector fields: BrushingModel's array:NAME). Point attributes
//      without one value per vertex (corrupt files) are dropped;
//   9. numeric cell arrays with one value per cell are kept as cell data of the triangles, each
//      triangle with the value of the face it came from (a quad's two triangles share it);
//      others are dropped.
// Non-manifold and boundary edges are counted, not changed.
// If no triangle survives, an aniso::Error "SUBJECT: reason" names what removed them.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// What the loader found and did; every count is zero for a clean mesh.
struct MeshReport
{
  std::string source; // the file path, or "builtin:NAME"

  int64_t pointsRead = 0;
  int64_t cellsRead = 0;
  int64_t invalidCellsDropped = 0;    // point ids out of range, or fewer than 3 points in a face
  int64_t nonSurfaceCellsDropped = 0; // vertices and lines
  int64_t nonFiniteVertices = 0;      // vertices with a NaN or Inf coordinate
  int64_t nonFiniteFacesDropped = 0;  // faces using such a vertex
  int64_t zeroAreaTrianglesDropped = 0;
  int64_t duplicateVerticesMerged = 0;
  int64_t unusedVerticesRemoved = 0;
  int64_t nonManifoldEdges = 0; // edges shared by more than two triangles (kept)
  int64_t boundaryEdges = 0;    // edges used by one triangle (kept)
  int64_t invalidNormals = 0;   // entries that made the file's normals be discarded
  int64_t invalidTCoords = 0;   // entries that made the file's texture coordinates be discarded
  int64_t malformedArraysDropped = 0; // point (cell) attributes without one tuple per vertex (cell)
  int64_t zeroLengthSegmentsDropped = 0; // of a line set (LineSet.h)
  // Data arrays (not the surface's own normals, texture coordinates and tangents) with NaN or
  // Inf values: "point array 'NAME'" or "cell array 'NAME'", and how many tuples. Kept as they
  // are: the tangent model array:NAME gives such vertices the fallback tangent.
  std::vector<std::pair<std::string, int64_t>> nonFiniteArrayValues;

  int64_t points = 0;       // in the result
  int64_t triangles = 0;    // in the result
  int64_t lineSegments = 0; // in the result, for a line set (LineSet.h)
  bool hasNormals = false;
  bool hasTCoords = false;
  bool hasTangents = false;

  std::vector<std::string> readerWarnings; // messages the reader printed, without VTK's prefixes

  // One sentence per non-zero count (what was dropped, merged or discarded), for the user.
  std::vector<std::string> notes() const;
};

struct EdgeCounts
{
  int64_t boundary = 0;    // used by exactly one triangle
  int64_t manifold = 0;    // used by exactly two
  int64_t nonManifold = 0; // used by three or more
};

// Edge use counts of a triangle mesh (edges are unordered point-id pairs).
EdgeCounts countEdges(vtkPolyData* triangles);

// The steps listed above. `subject` prefixes the error message (usually the file path).
// `report` receives the counts; source and readerWarnings are left as the caller set them.
vtkSmartPointer<vtkPolyData> sanitizeSurface(vtkPolyData* input, const std::string& subject,
                                             MeshReport& report);
} // namespace aniso
