#pragma once
// Reader for STL (binary and ASCII), written here because VTK 9.1's vtkSTLReader trusts the
// binary header's triangle count when it sizes its buffers (an int overflow on hostile files).
//
// Binary when the size is exactly 84 + 50 * (the header's count); otherwise ASCII when the file
// starts with "solid" and holds "vertex" lines; otherwise binary with as many whole triangles
// as the file holds (many exporters write a wrong count: a warning says so). Corners that are
// bit-for-bit equal are merged, since STL repeats every shared corner per triangle: the result
// is the connected surface the feature-angle normals need. Facet normals are ignored (the
// renderer computes vertex normals split at sharp edges). ASCII loops of more than three
// vertices are kept as polygons; a truncated ASCII file keeps its complete facets, with a warning.
// Errors are aniso::Error "PATH: reason".
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
vtkSmartPointer<vtkPolyData> readStl(const std::string& path, std::vector<std::string>& warnings);
} // namespace aniso
