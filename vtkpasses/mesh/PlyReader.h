#pragma once
// Reader for PLY (ASCII, binary little- and big-endian), written here because VTK 9.1's
// vtkPLYReader is not safe on hostile files (it reads past its buffers on short lines and uses
// a closed file when x, y or z is missing).
//
// Reads the "vertex" element's x, y, z, optional nx, ny, nz (-> "Normals") and texture
// coordinates u/v, s/t or texture_u/texture_v (-> "TCoords"), and the "face" element's list
// vertex_indices (or vertex_index). Every other scalar property of the vertex element becomes a
// point array named as the property (float; double for double and 32-bit integer properties), three in a row named NAME_x, NAME_y, NAME_z one
// 3-component array NAME (a vector field for the tangent model array:NAME); colours (red, green,
// blue) are such arrays too. Every other element and property is parsed and skipped.
// Rejected with an aniso::Error "PATH: reason": a missing or malformed header, unknown types,
// no vertex element with x, y, z, counts larger than the data can hold (checked before any
// allocation), truncated data, negative list lengths, non-numeric ASCII values.
#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
vtkSmartPointer<vtkPolyData> readPly(const std::string& path);
} // namespace aniso
