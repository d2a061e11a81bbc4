#include "vtkpasses/mesh/BrushingModel.h"

#include "core/error.h"
#include "core/frame.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/GeometryAccess.h"
#include "vtkpasses/mesh/MeshArrays.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>
#include <vector>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
std::string trim(const std::string& s)
{
  const size_t first = s.find_first_not_of(" \t");
  const size_t last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// "X,Y,Z" -> vector; `what` names the part in messages ("axis", "centre", "point").
glm::dvec3 parseTriple(const std::string& text, const std::string& subject,
                       const std::string& whole, const char* what)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream(text);
  while (std::getline(stream, part, ','))
  {
    parts.push_back(trim(part));
  }
  if (!text.empty() && text.back() == ',')
  {
    parts.push_back("");
  }
  if (parts.size() != 3)
  {
    throw errorAbout(subject,
                     "'" + whole + "': the " + what + " needs three comma-separated numbers X,Y,Z");
  }
  glm::dvec3 value(0.0);
  for (int i = 0; i < 3; ++i)
  {
    const std::string& token = parts[static_cast<size_t>(i)];
    char* end = nullptr;
    const double number = std::strtod(token.c_str(), &end);
    if (token.empty() || *end != '\0' || !std::isfinite(number))
    {
      throw errorAbout(subject, "'" + whole + "': '" + token + "' in the " + what +
                                    " is not a finite number");
    }
    value[i] = number;
  }
  return value;
}

glm::dvec3 unitAxis(const glm::dvec3& axis, const std::string& subject, const std::string& whole)
{
  // Scaled by its largest component first, so that tiny and huge axes neither underflow to a
  // zero length nor overflow to an infinite one.
  const double largest = std::max({std::abs(axis.x), std::abs(axis.y), std::abs(axis.z)});
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    throw errorAbout(subject, "'" + whole + "': the axis has zero length");
  }
  const glm::dvec3 scaled = axis / largest;
  const double scaledLength = glm::length(scaled);
  const double length = largest * scaledLength;
  // An axis that is unit to rounding is kept as it is: dividing by a length one ulp off 1
  // would move it again, and toString's spelling would not parse back to the same model.
  if (std::abs(length - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon())
  {
    return axis;
  }
  return scaled / scaledLength;
}

// The shortest spelling of each number that reads back to it ("0.9", not 0.90000000000000002).
std::string formatTriple(const glm::dvec3& v)
{
  return formatNumber(v.x) + ',' + formatNumber(v.y) + ',' + formatNumber(v.z);
}

using geometry::tupleAt;

glm::dvec3 pointAt(vtkPolyData* surface, vtkIdType id)
{
  return geometry::pointAt(surface->GetPoints(), id);
}

constexpr double kVanishingProjection = 1e-6; // relative to the direction's length
constexpr double kOnAxisFraction = 1e-9;      // of the bounding-box diagonal

// The angle of a triangle's corner at `at`, between the edges to `b` and `c`.
double cornerAngle(const glm::dvec3& at, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 u = b - at;
  const glm::dvec3 v = c - at;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

// Per-point dP/du: the unit directions of the triangles around each point, weighted by their
// corner angle there. Angle weights do not depend on how a grid's quads were split, so on a
// regular grid the left and right neighbours balance and the average lands on the true dP/du.
std::vector<glm::dvec3> accumulateUvTangents(vtkPolyData* surface, vtkDataArray* tcoords)
{
  std::vector<glm::dvec3> sum(static_cast<size_t>(surface->GetNumberOfPoints()), glm::dvec3(0.0));
  geometry::forEachCell(
      surface->GetPolys(),
      [&](vtkIdType count, const vtkIdType* ids)
      {
        if (count != 3)
        {
          return;
        }
        const glm::dvec3 p[3] = {pointAt(surface, ids[0]), pointAt(surface, ids[1]),
                                 pointAt(surface, ids[2])};
        const glm::dvec3 e1 = p[1] - p[0];
        const glm::dvec3 e2 = p[2] - p[0];
        // Component-wise: the array may carry a third texture coordinate.
        auto uv = [tcoords](vtkIdType id, int c) { return tcoords->GetComponent(id, c); };
        const double du1 = uv(ids[1], 0) - uv(ids[0], 0);
        const double dv1 = uv(ids[1], 1) - uv(ids[0], 1);
        const double du2 = uv(ids[2], 0) - uv(ids[0], 0);
        const double dv2 = uv(ids[2], 1) - uv(ids[0], 1);
        const double det = du1 * dv2 - du2 * dv1;
        if (det == 0.0)
        {
          return; // the UV map collapses this triangle: it says nothing about dP/du
        }
        const glm::dvec3 dPdu = (e1 * dv2 - e2 * dv1) / det;
        const double length = glm::length(dPdu);
        if (!(length > 0.0) || !std::isfinite(length))
        {
          return;
        }
        const glm::dvec3 direction = dPdu / length;
        for (int k = 0; k < 3; ++k)
        {
          sum[static_cast<size_t>(ids[k])] +=
              direction * cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
        }
      });
  return sum;
}
bool isFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A cell vector field at the points: each triangle's vector, weighted by the angle of its corner
// there; triangles with a non-finite vector are left out. FINITE tells the points that had at
// least one finite face.
std::vector<glm::dvec3> averageCellVectors(vtkPolyData* surface, vtkDataArray* cellVectors,
                                           std::vector<char>& finite)
{
  const size_t count = static_cast<size_t>(surface->GetNumberOfPoints());
  std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
  finite.assign(count, 0);
  // Polygons follow vertices and lines in VTK's cell order.
  vtkIdType cell = surface->GetNumberOfVerts() + surface->GetNumberOfLines();
  geometry::forEachCell(
      surface->GetPolys(),
      [&](vtkIdType n, const vtkIdType* ids)
      {
        const glm::dvec3 v = tupleAt(cellVectors, cell++);
        if (n != 3 || !isFinite(v))
        {
          return;
        }
        const glm::dvec3 p[3] = {pointAt(surface, ids[0]), pointAt(surface, ids[1]),
                                 pointAt(surface, ids[2])};
        for (int k = 0; k < 3; ++k)
        {
          sum[static_cast<size_t>(ids[k])] += v * cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
          finite[static_cast<size_t>(ids[k])] = 1;
        }
      });
  return sum;
}

// The point or cell array NAME of 2 or 3 components; else an error listing the vector arrays.
vtkDataArray* vectorArray(vtkPolyData* surface, const std::string& name, bool& perCell,
                          const std::string& subject)
{
  vtkDataArray* array = surface->GetPointData()->GetArray(name.c_str());
  perCell = false;
  if (!array)
  {
    array = surface->GetCellData()->GetArray(name.c_str());
    perCell = array != nullptr;
  }
  const vtkIdType expected = perCell ? surface->GetNumberOfCells() : surface->GetNumberOfPoints();
  if (array && (array->GetNumberOfComponents() == 2 || array->GetNumberOfComponents() == 3) &&
      array->GetNumberOfTuples() == expected)
  {
    return array;
  }
  std::string vectors;
  for (const std::string& candidate : vectorArrayNames(surface))
  {
    vectors += (vectors.empty() ? "" : ", ") + candidate;
  }
  const std::string has =
      vectors.empty() ? "it has no vector arrays" : "its vector arrays: " + vectors;
  if (array)
  {
    const int components = array->GetNumberOfComponents();
    throw errorAbout(subject, "tangents 'array:" + name + "': the array has " +
                                  std::to_string(components) +
                                  (components == 1 ? " component" : " components") +
                                  ", a direction needs 2 or 3 (" + has + ")");
  }
  throw errorAbout(subject, "tangents 'array:" + name + "': the mesh has no point or cell array '" +
                                name + "' (" + has + ")");
}
} // namespace

std::string brushingModelSyntax()
{
  return "uv|axis:X,Y,Z|around:X,Y,Z[@CX,CY,CZ]|radial:X,Y,Z|face-u|face-v|array:NAME";
}

BrushingModel parseBrushingModel(const std::string& text, const std::string& subject)
{
  const std::string whole = trim(text);
  const std::string expected = " (expected " + brushingModelSyntax() + ")";
  if (whole.empty())
  {
    throw errorAbout(subject, "empty brushing model" + expected);
  }
  const size_t colon = whole.find(':');
  const std::string name = whole.substr(0, colon);
  const std::string args = colon == std::string::npos ? std::string() : whole.substr(colon + 1);
  BrushingModel model;
  if (name == "uv" || name == "face-u" || name == "face-v")
  {
    if (colon != std::string::npos)
    {
      throw errorAbout(subject, "'" + whole + "': " + name + " takes no parameters");
    }
    model.kind = name == "uv"       ? BrushingKind::Uv
                 : name == "face-u" ? BrushingKind::FaceU
                                    : BrushingKind::FaceV;
    return model;
  }
  if (name == "array")
  {
    model.kind = BrushingKind::Array;
    model.array = trim(args);
    if (model.array.empty())
    {
      throw errorAbout(subject, "'" + whole +
                                    "' needs the name of a vector array, as in "
                                    "array:velocity");
    }
    return model;
  }
  if (name != "axis" && name != "around" && name != "radial")
  {
    throw errorAbout(subject, "unknown brushing model '" + name + "'" + expected);
  }
  if (colon == std::string::npos)
  {
    throw errorAbout(subject, "'" + whole + "' needs X,Y,Z, as in " + name + ":0,0,1");
  }
  if (name == "axis")
  {
    model.kind = BrushingKind::Axis;
    model.vector = unitAxis(parseTriple(args, subject, whole, "axis"), subject, whole);
  }
  else if (name == "around")
  {
    model.kind = BrushingKind::Around;
    const size_t at = args.find('@');
    model.vector =
        unitAxis(parseTriple(args.substr(0, at), subject, whole, "axis"), subject, whole);
    if (at != std::string::npos)
    {
      model.centre = parseTriple(args.substr(at + 1), subject, whole, "centre");
    }
  }
  else
  {
    model.kind = BrushingKind::Radial;
    model.vector = parseTriple(args, subject, whole, "point");
  }
  return model;
}

std::string toString(const BrushingModel& model)
{
  switch (model.kind)
  {
  case BrushingKind::Uv:
    return "uv";
  case BrushingKind::Axis:
    return "axis:" + formatTriple(model.vector);
  case BrushingKind::Around:
    return "around:" + formatTriple(model.vector) +
           (model.centre ? "@" + formatTriple(*model.centre) : std::string());
  case BrushingKind::Radial:
    return "radial:" + formatTriple(model.vector);
  case BrushingKind::FaceU:
    return "face-u";
  case BrushingKind::FaceV:
    return "face-v";
  case BrushingKind::Array:
    return "array:" + model.array;
  }
  return "uv";
}

TangentStats computeBrushingTangents(vtkPolyData* surface, const BrushingModel& model,
                                     const std::string& subject)
{
  vtkPointData* pd = surface->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    throw errorAbout(subject, "tangents need point normals, and the surface has none");
  }
  vtkDataArray* tcoords = pd->GetTCoords();
  if (model.kind == BrushingKind::Uv && (!tcoords || tcoords->GetNumberOfComponents() < 2))
  {
    throw errorAbout(
        subject, "tangents 'uv' need texture coordinates, and the mesh has none (use axis:X,Y,Z, "
                 "around:X,Y,Z or radial:X,Y,Z)");
  }

  vtkDataArray* faceTangents = nullptr;
  if (model.kind == BrushingKind::FaceU || model.kind == BrushingKind::FaceV)
  {
    const char* name = model.kind == BrushingKind::FaceU ? kBRepTangentUArray : kBRepTangentVArray;
    faceTangents = pd->GetArray(name);
    if (!faceTangents || faceTangents->GetNumberOfComponents() != 3 ||
        faceTangents->GetNumberOfTuples() != surface->GetNumberOfPoints())
    {
      throw errorAbout(subject, "tangents '" + toString(model) +
                                    "' need the faces of a CAD part (a STEP or IGES file), and "
                                    "this mesh has none");
    }
  }

  vtkDataArray* field = nullptr;
  std::vector<glm::dvec3> cellAverages;
  std::vector<char> cellFinite;
  if (model.kind == BrushingKind::Array)
  {
    bool perCell = false;
    field = vectorArray(surface, model.array, perCell, subject);
    if (perCell)
    {
      cellAverages = averageCellVectors(surface, field, cellFinite);
    }
  }

  const vtkIdType count = surface->GetNumberOfPoints();
  double bounds[6];
  surface->GetBounds(bounds);
  const glm::dvec3 low(bounds[0], bounds[2], bounds[4]);
  const glm::dvec3 high(bounds[1], bounds[3], bounds[5]);
  const double onAxis = kOnAxisFraction * glm::length(high - low);
  const glm::dvec3 centre = model.centre ? *model.centre : 0.5 * (low + high);

  std::vector<glm::dvec3> uvSums;
  if (model.kind == BrushingKind::Uv)
  {
    uvSums = accumulateUvTangents(surface, tcoords);
  }

  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(3);
  tangents->SetNumberOfTuples(count);
  TangentStats stats;
  stats.points = count;
  for (vtkIdType i = 0; i < count; ++i)
  {
    const glm::dvec3 rawNormal = tupleAt(normals, i);
    const double normalLength = glm::length(rawNormal);
    if (!(normalLength > 0.0) || !std::isfinite(normalLength))
    {
      throw errorAbout(subject, "point " + std::to_string(i) + " has a zero or non-finite normal");
    }
    const glm::dvec3 n = rawNormal / normalLength;
    const glm::dvec3 p = pointAt(surface, i);
    glm::dvec3 direction(0.0);
    bool defined = true;
    switch (model.kind)
    {
    case BrushingKind::Uv:
      direction = uvSums[static_cast<size_t>(i)];
      break;
    case BrushingKind::Axis:
      direction = model.vector;
      break;
    case BrushingKind::Around:
    {
      const glm::dvec3 radius = p - centre;
      direction = glm::cross(model.vector, radius);
      defined = glm::length(radius - glm::dot(radius, model.vector) * model.vector) > onAxis;
      break;
    }
    case BrushingKind::Radial:
      direction = p - model.vector;
      defined = glm::length(direction) > onAxis;
      break;
    case BrushingKind::FaceU:
    case BrushingKind::FaceV:
      direction = tupleAt(faceTangents, i);
      defined = std::isfinite(glm::length(direction));
      break;
    case BrushingKind::Array:
      if (cellAverages.empty())
      {
        direction = tupleAt(field, i);
        defined = isFinite(direction);
      }
      else
      {
        direction = cellAverages[static_cast<size_t>(i)];
        defined = cellFinite[static_cast<size_t>(i)] != 0;
      }
      if (!defined)
      {
        ++stats.nonFinitePoints;
        direction = glm::dvec3(0.0);
      }
      // Huge components: scaled down first so that the length below stays finite.
      else if (const double largest =
                   std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
               largest > 0.0)
      {
        direction /= largest;
      }
      break;
    }
    const double length = glm::length(direction);
    const glm::dvec3 projected = direction - glm::dot(direction, n) * n;
    const double projectedLength = glm::length(projected);
    defined = defined && length > 0.0 && projectedLength > kVanishingProjection * length;
    glm::dvec3 t;
    if (defined)
    {
      t = projected / projectedLength;
    }
    else
    {
      t = Frame::fromNormalTangent(n, glm::dvec3(0.0)).t;
      ++stats.fallbackPoints;
    }
    tangents->SetTuple3(i, t.x, t.y, t.z);
  }
  pd->SetTangents(tangents);
  return stats;
}
} // namespace aniso
