#pragma once
// Reader for Geomview's ASCII OFF format, which VTK lacks.
//
// Accepted: the header keywords OFF, COFF, NOFF, CNOFF, STOFF, STCOFF, STNOFF, STCNOFF (optional
// per-vertex normals N, colours C and texture coordinates ST), '#' comments, the counts on the
// header line or the next one, one vertex or face per line, CRLF line ends. Per vertex:
// "x y z [nx ny nz] [colour...] [s t]"; per face: "n i0 ... i(n-1) [colour...]". Normals and
// texture coordinates become the point arrays "Normals" and "TCoords"; colours are ignored.
// Faces with fewer than 3 vertices are skipped (points and lines are not surfaces).
// Rejected with an aniso::Error "PATH: reason": binary OFF, 4OFF/nOFF (not 3-D), a missing or
// malformed header, non-numeric tokens, counts that do not fit the file, vertex indices out of
// range, truncation. Nothing is allocated from the header counts before the data is seen, so a
// hostile header cannot exhaust memory.
#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
vtkSmartPointer<vtkPolyData> readOff(const std::string& path);
} // namespace aniso
