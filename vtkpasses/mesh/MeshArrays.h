#pragma once
// The data arrays a surface carries (scalar and vector fields of simulations and scans), as
// plain data for listings (`aniso render --list-arrays`) and for the lists the window offers
// (the tangent model array:NAME takes a vector array).
#include <cstdint>
#include <string>
#include <vector>

class vtkPolyData;

namespace aniso
{
struct ArrayInfo
{
  std::string name;
  bool perCell = false; // cell data (one value per triangle), else point data
  int components = 0;
  int64_t values = 0;    // tuples
  int64_t nonFinite = 0; // tuples with a NaN or Inf component
  // Over the finite tuples: the value (one component) or the length (several); both NaN when
  // no tuple is finite.
  double minimum = 0.0;
  double maximum = 0.0;
};

// The named numeric point arrays, then the cell arrays, in the surface's order.
std::vector<ArrayInfo> describeArrays(vtkPolyData* surface);

// True for the arrays the surface contract itself uses ("Normals", "TCoords", "Tangents") and a
// CAD part's "BRepTangentU"/"BRepTangentV": not fields of the data.
bool isGeometryArray(const std::string& name);

// The names of the point and cell arrays of 2 or 3 components that are fields of the data
// (not isGeometryArray), for the tangent model array:NAME.
std::vector<std::string> vectorArrayNames(vtkPolyData* surface);

// One line per array: "NAME<TAB>point|cell<TAB>C component(s)<TAB>MIN..MAX[ (length)]<TAB>K
// NaN/Inf".
std::string formatArrayInfo(const ArrayInfo& info);
} // namespace aniso
