#pragma once
// A file's polylines (streamlines, fibre tracts, hair) as the line set the renderer draws as
// illuminated lines (docs/METHOD.md, "Lines"): every polyline of the input, sanitised for lines,
// with its own points and a unit tangent at each of them.
//
// sanitizeLines() applies, in this order:
//   1. line cells whose point ids are out of range are dropped (counted in invalidCellsDropped);
//   2. a point with a NaN or Inf coordinate splits its polyline there (the point is left out,
//      the pieces on either side stay; counted in nonFiniteVertices);
//   3. zero-length segments are dropped: a point closer to the previous kept point of its
//      polyline than 1e-9 of the finite points' bounding-box diagonal (or exactly equal, for a
//      box of no extent) is left out (counted in zeroLengthSegmentsDropped);
//   4. what remains of a polyline with fewer than two points is dropped (invalidCellsDropped);
//   5. each polyline gets its own copy of its points (a point shared by two polylines has a
//      tangent on each), with the float point array "Tangents" (3, unit, set as the active
//      tangents): the line direction by central differences, (p[i+1] - p[i-1]) / |...| inside a
//      polyline, the one segment's direction at its ends (and at a turn back, where the central
//      difference vanishes, the incoming segment's).
// Vertices, faces and every other point or cell array of the input are not part of the result.
// The report's counts are set as sanitizeSurface sets them (pointsRead, cellsRead, ...);
// `points` and `lineSegments` count the result, `triangles` is 0, hasTangents is true.
// If no segment survives, an aniso::Error "SUBJECT: reason" names what removed them.
#include "vtkpasses/mesh/MeshValidation.h"

#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// True when POLY holds line cells (polylines).
bool hasLineCells(vtkPolyData* poly);
// True when POLY holds faces (polygons or strips).
bool hasFaceCells(vtkPolyData* poly);
// True when POLY is a line set (lines, no faces): what the materials draw as illuminated lines.
bool isLineSet(vtkPolyData* poly);

vtkSmartPointer<vtkPolyData> sanitizeLines(vtkPolyData* input, const std::string& subject,
                                           MeshReport& report);
} // namespace aniso
