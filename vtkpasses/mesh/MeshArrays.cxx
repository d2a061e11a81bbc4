#include "vtkpasses/mesh/MeshArrays.h"

#include "vtkpasses/mesh/CadReader.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <limits>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
ArrayInfo describe(vtkDataArray* array, bool perCell)
{
  ArrayInfo info;
  info.name = array->GetName();
  info.perCell = perCell;
  info.components = array->GetNumberOfComponents();
  info.values = array->GetNumberOfTuples();
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    bool finite = true;
    double squares = 0.0;
    double largest = 0.0;
    for (int c = 0; c < info.components; ++c)
    {
      const double v = array->GetComponent(i, c);
      finite = finite && std::isfinite(v);
      largest = std::max(largest, std::abs(v));
    }
    if (!finite)
    {
      ++info.nonFinite;
      continue;
    }
    double value = array->GetComponent(i, 0);
    if (info.components > 1)
    {
      // Scaled by the largest component, so that huge components do not overflow.
      for (int c = 0; c < info.components && largest > 0.0; ++c)
      {
        const double v = array->GetComponent(i, c) / largest;
        squares += v * v;
      }
      value = largest * std::sqrt(squares);
    }
    low = std::min(low, value);
    high = std::max(high, value);
  }
  if (info.nonFinite == info.values)
  {
    low = high = std::numeric_limits<double>::quiet_NaN();
  }
  info.minimum = low;
  info.maximum = high;
  return info;
}
} // namespace

bool isGeometryArray(const std::string& name)
{
  return name == "Normals" || name == "TCoords" || name == "Tangents" ||
         name == kBRepTangentUArray || name == kBRepTangentVArray;
}

std::vector<ArrayInfo> describeArrays(vtkPolyData* surface)
{
  std::vector<ArrayInfo> out;
  for (const bool perCell : {false, true})
  {
    vtkFieldData* data = perCell ? static_cast<vtkFieldData*>(surface->GetCellData())
                                 : static_cast<vtkFieldData*>(surface->GetPointData());
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = data->GetArray(a);
      if (array && array->GetName() && array->GetNumberOfComponents() > 0)
      {
        out.push_back(describe(array, perCell));
      }
    }
  }
  return out;
}

std::vector<std::string> vectorArrayNames(vtkPolyData* surface)
{
  std::vector<std::string> names;
  for (const ArrayInfo& info : describeArrays(surface))
  {
    if ((info.components == 2 || info.components == 3) && !isGeometryArray(info.name) &&
        std::find(names.begin(), names.end(), info.name) == names.end())
    {
      names.push_back(info.name);
    }
  }
  return names;
}

std::string formatArrayInfo(const ArrayInfo& info)
{
  // Six significant digits: a listing to read, not to parse back.
  const auto number = [](double v)
  {
    if (std::isnan(v))
    {
      return std::string("nan");
    }
    std::ostringstream out;
    out << std::setprecision(6) << v;
    return out.str();
  };
  return info.name + "\t" + (info.perCell ? "cell" : "point") + "\t" +
         std::to_string(info.components) +
         (info.components == 1 ? " component\t" : " components\t") + number(info.minimum) + ".." +
         number(info.maximum) + (info.components > 1 ? " (length)" : "") + "\t" +
         std::to_string(info.nonFinite) + " NaN/Inf";
}
} // namespace aniso
