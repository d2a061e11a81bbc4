#include "vtkpasses/mesh/MeshValidation.h"

#include "core/error.h"
#include "vtkpasses/mesh/GeometryAccess.h"
#include "vtkpasses/mesh/MeshArrays.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <unordered_map>
#include <utility>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>

namespace aniso
{
namespace
{
using Triangle = std::array<vtkIdType, 3>;
using geometry::pointAt;

// Twice the area below this fraction of the longest edge squared counts as zero: the triangle's
// height is under 1e-10 of its length, so its normal is rounding noise.
constexpr double kZeroAreaRatio = 1e-10;

bool isZeroArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 e1 = b - a;
  const glm::dvec3 e2 = c - a;
  const glm::dvec3 e3 = c - b;
  const double longest2 = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
  return glm::length(glm::cross(e1, e2)) <= kZeroAreaRatio * longest2;
}

// Splits a quad along the diagonal that keeps both halves facing the same way (the one inside a
// concave quad), preferring the shorter diagonal when both do.
void triangulateQuad(vtkPoints* points, const vtkIdType* ids, std::vector<Triangle>& out)
{
  const glm::dvec3 p0 = pointAt(points, ids[0]);
  const glm::dvec3 p1 = pointAt(points, ids[1]);
  const glm::dvec3 p2 = pointAt(points, ids[2]);
  const glm::dvec3 p3 = pointAt(points, ids[3]);
  const bool diagonal02Valid =
      glm::dot(glm::cross(p1 - p0, p2 - p0), glm::cross(p2 - p0, p3 - p0)) >= 0.0;
  const bool diagonal13Valid =
      glm::dot(glm::cross(p2 - p1, p3 - p1), glm::cross(p3 - p1, p0 - p1)) >= 0.0;
  const glm::dvec3 d02 = p2 - p0;
  const glm::dvec3 d13 = p3 - p1;
  bool use02 = glm::dot(d02, d02) <= glm::dot(d13, d13);
  if (use02 && !diagonal02Valid && diagonal13Valid)
  {
    use02 = false;
  }
  else if (!use02 && !diagonal13Valid && diagonal02Valid)
  {
    use02 = true;
  }
  if (use02)
  {
    out.push_back({ids[0], ids[1], ids[2]});
    out.push_back({ids[0], ids[2], ids[3]});
  }
  else
  {
    out.push_back({ids[1], ids[2], ids[3]});
    out.push_back({ids[1], ids[3], ids[0]});
  }
}

// Ear cutting costs O(n^2) and more: beyond this many vertices (no real mesh face has them, a
// hostile file might) a fan is used directly.
constexpr vtkIdType kMaxEarCutVertices = 1024;

// Ear-cutting for larger polygons (handles concave planar ones); a fan when it fails, the
// zero-area step then removes whatever slivers that leaves.
void triangulatePolygon(vtkPoints* points, vtkIdType count, const vtkIdType* ids,
                        std::vector<Triangle>& out)
{
  if (count > kMaxEarCutVertices)
  {
    for (vtkIdType i = 1; i + 1 < count; ++i)
    {
      out.push_back({ids[0], ids[i], ids[i + 1]});
    }
    return;
  }
  vtkNew<vtkPolygon> polygon;
  polygon->GetPointIds()->SetNumberOfIds(count);
  polygon->GetPoints()->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    polygon->GetPointIds()->SetId(i, ids[i]);
    polygon->GetPoints()->SetPoint(i, points->GetPoint(ids[i]));
  }
  vtkNew<vtkIdList> local;
  if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (count - 2))
  {
    for (vtkIdType i = 0; i + 2 < local->GetNumberOfIds(); i += 3)
    {
      out.push_back({ids[local->GetId(i)], ids[local->GetId(i + 1)], ids[local->GetId(i + 2)]});
    }
    return;
  }
  for (vtkIdType i = 1; i + 1 < count; ++i)
  {
    out.push_back({ids[0], ids[i], ids[i + 1]});
  }
}

void appendStrip(vtkIdType count, const vtkIdType* ids, std::vector<Triangle>& out)
{
  for (vtkIdType i = 0; i + 2 < count; ++i)
  {
    // Every other triangle of a strip is wound the other way round.
    if (i % 2 == 0)
    {
      out.push_back({ids[i], ids[i + 1], ids[i + 2]});
    }
    else
    {
      out.push_back({ids[i + 1], ids[i], ids[i + 2]});
    }
  }
}

bool idsValid(vtkIdType count, const vtkIdType* ids, vtkIdType pointCount)
{
  return std::all_of(ids, ids + count,
                     [pointCount](vtkIdType id) { return id >= 0 && id < pointCount; });
}

bool touchesNonFinite(vtkIdType count, const vtkIdType* ids, const std::vector<char>& nonFinite)
{
  return std::any_of(ids, ids + count, [&nonFinite](vtkIdType id) { return nonFinite[id] != 0; });
}

// Faces (polygons and strips) to triangles, after the id, vertex and NaN checks.
// SOURCE_CELLS receives, for each triangle, the id of the input cell it came from (VTK's cell
// order: vertices, lines, polygons, strips), for the cell data to follow it.
std::vector<Triangle> collectTriangles(vtkPolyData* input, const std::vector<char>& nonFinite,
                                       MeshReport& report, std::vector<vtkIdType>& sourceCells)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  std::vector<Triangle> triangles;
  triangles.reserve(static_cast<size_t>(input->GetNumberOfPolys()));

  vtkIdType cellId = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto visit = [&](vtkCellArray* cells, bool strip)
  {
    const auto add = [&](vtkIdType count, const vtkIdType* ids)
    {
      if (count < 3 || !idsValid(count, ids, pointCount))
      {
        ++report.invalidCellsDropped;
        return;
      }
      if (touchesNonFinite(count, ids, nonFinite))
      {
        ++report.nonFiniteFacesDropped;
        return;
      }
      if (strip)
      {
        appendStrip(count, ids, triangles);
      }
      else if (count == 3)
      {
        triangles.push_back({ids[0], ids[1], ids[2]});
      }
      else if (count == 4)
      {
        triangulateQuad(points, ids, triangles);
      }
      else
      {
        triangulatePolygon(points, count, ids, triangles);
      }
    };
    geometry::forEachCell(cells,
                          [&](vtkIdType count, const vtkIdType* ids)
                          {
                            add(count, ids);
                            // Every triangle this cell made carries its id.
                            sourceCells.resize(triangles.size(), cellId++);
                          });
  };
  visit(input->GetPolys(), false);
  visit(input->GetStrips(), true);
  return triangles;
}

// Merge keys of all points, flat: position then every numeric point attribute, with -0 turned
// into +0 (they compare equal, so they must hash equal). Points are then compared bit for bit.
class MergeKeys
{
public:
  MergeKeys(vtkPoints* points, vtkPointData* pointData, const std::vector<char>& used)
  {
    std::vector<vtkDataArray*> arrays;
    this->Width = 3;
    for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
    {
      if (vtkDataArray* array = pointData->GetArray(a))
      {
        arrays.push_back(array);
        this->Width += static_cast<size_t>(array->GetNumberOfComponents());
      }
    }
    this->Values.assign(used.size() * this->Width, 0.0);
    std::vector<double> tuple;
    for (size_t i = 0; i < used.size(); ++i)
    {
      if (!used[i])
      {
        continue;
      }
      double* key = &this->Values[i * this->Width];
      points->GetPoint(static_cast<vtkIdType>(i), key);
      size_t offset = 3;
      for (vtkDataArray* array : arrays)
      {
        tuple.resize(static_cast<size_t>(array->GetNumberOfComponents()));
        array->GetTuple(static_cast<vtkIdType>(i), tuple.data());
        std::copy(tuple.begin(), tuple.end(), key + offset);
        offset += tuple.size();
      }
      for (size_t k = 0; k < this->Width; ++k)
      {
        key[k] += 0.0;
      }
    }
  }

  size_t hash(vtkIdType id) const
  {
    // splitmix64's finaliser per 64-bit word: float-derived doubles differ only in their high
    // bits, which a plain multiplicative hash would not spread over the buckets.
    uint64_t h = 0x9e3779b97f4a7c15ull;
    const double* key = &this->Values[static_cast<size_t>(id) * this->Width];
    for (size_t k = 0; k < this->Width; ++k)
    {
      uint64_t bits = 0;
      std::memcpy(&bits, key + k, sizeof(bits));
      h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
      h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
      h ^= h >> 31;
    }
    return static_cast<size_t>(h);
  }

  bool equal(vtkIdType a, vtkIdType b) const
  {
    return std::memcmp(&this->Values[static_cast<size_t>(a) * this->Width],
                       &this->Values[static_cast<size_t>(b) * this->Width],
                       this->Width * sizeof(double)) == 0;
  }

private:
  size_t Width = 3;
  std::vector<double> Values;
};

// Float copy of `source` with `components` components (extra ones are dropped: a glTF tangent's
// handedness sign, a third texture coordinate). Counts non-finite tuples, and zero-length ones
// when `unit` asks for a normalised result.
vtkSmartPointer<vtkFloatArray> floatCopy(vtkDataArray* source, int components, const char* name,
                                         bool unit, int64_t& invalid)
{
  auto result = vtkSmartPointer<vtkFloatArray>::New();
  result->SetName(name);
  result->SetNumberOfComponents(components);
  const vtkIdType tuples = source->GetNumberOfTuples();
  result->SetNumberOfTuples(tuples);
  invalid = 0;
  for (vtkIdType i = 0; i < tuples; ++i)
  {
    double v[3] = {0.0, 0.0, 0.0};
    bool finite = true;
    for (int c = 0; c < components; ++c)
    {
      v[c] = source->GetComponent(i, c);
      finite = finite && std::isfinite(v[c]);
    }
    double scale = 1.0;
    if (finite && unit)
    {
      const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      finite = length > 1e-12;
      scale = finite ? 1.0 / length : 1.0;
    }
    if (!finite)
    {
      ++invalid;
    }
    for (int c = 0; c < components; ++c)
    {
      result->SetComponent(i, c, v[c] * scale);
    }
  }
  return result;
}

vtkDataArray* findArray(vtkPointData* pd, vtkDataArray* active,
                        std::initializer_list<const char*> names)
{
  if (active)
  {
    return active;
  }
  for (const char* name : names)
  {
    if (vtkDataArray* array = pd->GetArray(name))
    {
      return array;
    }
  }
  return nullptr;
}

// Replaces the reader's normals, texture coordinates and tangents by float arrays with the
// contract's names; invalid normals or texture coordinates are discarded as a whole.
void normaliseAttributes(vtkPointData* pd, MeshReport& report)
{
  vtkSmartPointer<vtkDataArray> normals =
      findArray(pd, pd->GetNormals(), {"Normals", "NORMAL", "Normal"});
  vtkSmartPointer<vtkDataArray> tcoords =
      findArray(pd, pd->GetTCoords(), {"TCoords", "TEXCOORD_0", "TextureCoordinates"});
  vtkSmartPointer<vtkDataArray> tangents =
      findArray(pd, pd->GetTangents(), {"Tangents", "TANGENT", "Tangent"});
  for (vtkDataArray* array : {normals.Get(), tcoords.Get(), tangents.Get()})
  {
    if (array && array->GetName())
    {
      pd->RemoveArray(array->GetName());
    }
  }
  pd->SetNormals(nullptr);
  pd->SetTCoords(nullptr);
  pd->SetTangents(nullptr);

  if (normals && normals->GetNumberOfComponents() >= 3)
  {
    int64_t invalid = 0;
    auto copy = floatCopy(normals, 3, "Normals", true, invalid);
    report.invalidNormals = invalid;
    if (invalid == 0)
    {
      pd->SetNormals(copy);
    }
  }
  if (tcoords && tcoords->GetNumberOfComponents() >= 2)
  {
    int64_t invalid = 0;
    auto copy = floatCopy(tcoords, 2, "TCoords", false, invalid);
    report.invalidTCoords = invalid;
    if (invalid == 0)
    {
      pd->SetTCoords(copy);
    }
  }
  if (tangents && tangents->GetNumberOfComponents() >= 3)
  {
    // Zero or NaN tangents are kept here and replaced in SurfacePreparation, which knows the
    // normals they must be orthogonal to.
    int64_t invalid = 0;
    pd->SetTangents(floatCopy(tangents, 3, "Tangents", false, invalid));
  }
}

std::string plural(int64_t count, const char* singular, const char* pluralForm)
{
  return std::to_string(count) + " " + (count == 1 ? singular : pluralForm);
}
} // namespace

std::vector<std::string> MeshReport::notes() const
{
  std::vector<std::string> out;
  if (invalidCellsDropped > 0)
  {
    out.push_back(plural(invalidCellsDropped, "face", "faces") +
                  " with invalid vertex indices or fewer than 3 vertices dropped");
  }
  if (nonSurfaceCellsDropped > 0)
  {
    out.push_back(plural(nonSurfaceCellsDropped, "vertex or line cell", "vertex and line cells") +
                  " dropped (only surfaces are rendered)");
  }
  if (nonFiniteVertices > 0)
  {
    out.push_back(plural(nonFiniteVertices, "vertex has", "vertices have") +
                  " NaN/Inf coordinates; " +
                  (lineSegments > 0
                       ? std::string("the lines through them split there")
                       : plural(nonFiniteFacesDropped, "face", "faces") + " using them dropped"));
  }
  if (zeroLengthSegmentsDropped > 0)
  {
    out.push_back(
        plural(zeroLengthSegmentsDropped, "zero-length line segment", "zero-length line segments") +
        " dropped");
  }
  if (zeroAreaTrianglesDropped > 0)
  {
    out.push_back(plural(zeroAreaTrianglesDropped, "zero-area triangle", "zero-area triangles") +
                  " dropped");
  }
  if (duplicateVerticesMerged > 0)
  {
    out.push_back(plural(duplicateVerticesMerged, "duplicate vertex", "duplicate vertices") +
                  " merged (same position and attributes)");
  }
  if (unusedVerticesRemoved > 0)
  {
    out.push_back(plural(unusedVerticesRemoved, "unused vertex", "unused vertices") + " removed");
  }
  if (nonManifoldEdges > 0)
  {
    out.push_back(plural(nonManifoldEdges, "non-manifold edge", "non-manifold edges") +
                  " (shared by more than two triangles) kept");
  }
  if (invalidNormals > 0)
  {
    out.push_back("file normals discarded (" + plural(invalidNormals, "entry is", "entries are") +
                  " NaN, Inf or zero); recomputed");
  }
  if (malformedArraysDropped > 0)
  {
    out.push_back(
        plural(malformedArraysDropped, "point or cell attribute", "point or cell attributes") +
        " without one value per vertex or face dropped");
  }
  if (invalidTCoords > 0)
  {
    out.push_back("texture coordinates discarded (" +
                  plural(invalidTCoords, "entry is", "entries are") + " NaN or Inf)");
  }
  for (const auto& [array, count] : nonFiniteArrayValues)
  {
    out.push_back(array + ": " + plural(count, "value is", "values are") + " NaN or Inf (kept)");
  }
  for (const std::string& warning : readerWarnings)
  {
    out.push_back("reader: " + warning);
  }
  return out;
}

EdgeCounts countEdges(vtkPolyData* triangles)
{
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  vtkCellArray* polys = triangles->GetPolys();
  edges.reserve(static_cast<size_t>(3 * polys->GetNumberOfCells()));
  geometry::forEachCell(polys,
                        [&edges](vtkIdType count, const vtkIdType* ids)
                        {
                          for (vtkIdType i = 0; i < count; ++i)
                          {
                            const vtkIdType a = ids[i];
                            const vtkIdType b = ids[(i + 1) % count];
                            edges.emplace_back(std::min(a, b), std::max(a, b));
                          }
                        });
  std::sort(edges.begin(), edges.end());
  EdgeCounts counts;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    const size_t uses = j - i;
    if (uses == 1)
    {
      ++counts.boundary;
    }
    else if (uses == 2)
    {
      ++counts.manifold;
    }
    else
    {
      ++counts.nonManifold;
    }
    i = j;
  }
  return counts;
}

vtkSmartPointer<vtkPolyData> sanitizeSurface(vtkPolyData* input, const std::string& subject,
                                             MeshReport& report)
{
  if (!input)
  {
    throw errorAbout(subject, "the reader produced no data");
  }
  vtkPoints* points = input->GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  report.pointsRead = pointCount;
  report.cellsRead = input->GetNumberOfCells();
  report.nonSurfaceCellsDropped = input->GetNumberOfVerts() + input->GetNumberOfLines();

  std::vector<char> nonFinite(static_cast<size_t>(pointCount), 0);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    const glm::dvec3 p = pointAt(points, i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      nonFinite[i] = 1;
      ++report.nonFiniteVertices;
    }
  }

  std::vector<vtkIdType> sourceCells;
  std::vector<Triangle> triangles = collectTriangles(input, nonFinite, report, sourceCells);
  const size_t facesBeforeAreaCheck = triangles.size();
  size_t kept = 0;
  for (size_t i = 0; i < triangles.size(); ++i)
  {
    const Triangle& t = triangles[i];
    if (!isZeroArea(pointAt(points, t[0]), pointAt(points, t[1]), pointAt(points, t[2])))
    {
      triangles[kept] = t;
      sourceCells[kept] = sourceCells[i];
      ++kept;
    }
  }
  triangles.resize(kept);
  sourceCells.resize(kept);
  report.zeroAreaTrianglesDropped = static_cast<int64_t>(facesBeforeAreaCheck - triangles.size());

  if (triangles.empty())
  {
    std::string reason = "no faces";
    if (report.nonFiniteFacesDropped > 0 || report.zeroAreaTrianglesDropped > 0 ||
        report.invalidCellsDropped > 0)
    {
      reason = "no valid faces (" + std::to_string(report.nonFiniteFacesDropped) +
               " with NaN/Inf vertices, " + std::to_string(report.zeroAreaTrianglesDropped) +
               " of zero area, " + std::to_string(report.invalidCellsDropped) +
               " with invalid vertex indices)";
    }
    else if (report.nonSurfaceCellsDropped > 0)
    {
      reason = "no faces (only " + std::to_string(report.nonSurfaceCellsDropped) +
               " vertex or line cells)";
    }
    throw errorAbout(subject, reason);
  }

  // Merge and compact in one pass over the used points, in their original order.
  std::vector<char> used(static_cast<size_t>(pointCount), 0);
  for (const Triangle& t : triangles)
  {
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  vtkPointData* inPd = input->GetPointData();
  // Only numeric arrays with one tuple per point take part in keys and output: a shorter array
  // (a corrupt file) would be read past its end.
  auto fits = [pointCount](vtkDataArray* array) {
    return array && array->GetNumberOfTuples() == pointCount && array->GetNumberOfComponents() > 0;
  };
  vtkNew<vtkPointData> numericPd;
  for (int a = 0; a < inPd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inPd->GetArray(a);
    if (fits(array))
    {
      numericPd->AddArray(array);
    }
    else if (array)
    {
      ++report.malformedArraysDropped;
    }
  }
  numericPd->SetNormals(fits(inPd->GetNormals()) ? inPd->GetNormals() : nullptr);
  numericPd->SetTCoords(fits(inPd->GetTCoords()) ? inPd->GetTCoords() : nullptr);
  numericPd->SetTangents(fits(inPd->GetTangents()) ? inPd->GetTangents() : nullptr);

  const MergeKeys keys(points, numericPd, used);
  auto hash = [&keys](vtkIdType id) { return keys.hash(id); };
  auto equal = [&keys](vtkIdType a, vtkIdType b) { return keys.equal(a, b); };
  // Maps the first point with a given key to its output id.
  std::unordered_map<vtkIdType, vtkIdType, decltype(hash), decltype(equal)> firstWithKey(
      static_cast<size_t>(pointCount), hash, equal);
  std::vector<vtkIdType> newId(static_cast<size_t>(pointCount), -1);
  vtkIdType usedCount = 0;
  vtkIdType outCount = 0;
  std::vector<vtkIdType> representative;
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    if (!used[i])
    {
      continue;
    }
    ++usedCount;
    auto inserted = firstWithKey.emplace(i, outCount);
    if (inserted.second)
    {
      representative.push_back(i);
      ++outCount;
    }
    newId[i] = inserted.first->second;
  }
  report.duplicateVerticesMerged = usedCount - outCount;
  // NaN vertices are counted on their own, not as unused ones.
  report.unusedVerticesRemoved = 0;
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    if (!used[i] && !nonFinite[i])
    {
      ++report.unusedVerticesRemoved;
    }
  }

  auto output = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(points->GetDataType());
  outPoints->SetNumberOfPoints(outCount);
  vtkPointData* outPd = output->GetPointData();
  outPd->CopyAllOn();
  outPd->CopyAllocate(numericPd, outCount);
  for (vtkIdType i = 0; i < outCount; ++i)
  {
    outPoints->SetPoint(i, points->GetPoint(representative[static_cast<size_t>(i)]));
    outPd->CopyData(numericPd, representative[static_cast<size_t>(i)], i);
  }
  output->SetPoints(outPoints);

  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(triangles.size()),
                       3 * static_cast<vtkIdType>(triangles.size()));
  for (const Triangle& t : triangles)
  {
    const vtkIdType ids[3] = {newId[t[0]], newId[t[1]], newId[t[2]]};
    polys->InsertNextCell(3, ids);
  }
  output->SetPolys(polys);

  // Cell arrays with one value per input cell follow their cells: each triangle takes the
  // value of the face it came from.
  vtkCellData* inCd = input->GetCellData();
  vtkCellData* outCd = output->GetCellData();
  for (int a = 0; a < inCd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inCd->GetArray(a);
    if (!array)
    {
      continue;
    }
    if (array->GetNumberOfTuples() != input->GetNumberOfCells() ||
        array->GetNumberOfComponents() < 1)
    {
      ++report.malformedArraysDropped;
      continue;
    }
    vtkSmartPointer<vtkDataArray> copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->SetName(array->GetName());
    copy->SetNumberOfComponents(array->GetNumberOfComponents());
    copy->SetNumberOfTuples(static_cast<vtkIdType>(sourceCells.size()));
    for (size_t i = 0; i < sourceCells.size(); ++i)
    {
      copy->SetTuple(static_cast<vtkIdType>(i), sourceCells[i], array);
    }
    outCd->AddArray(copy);
  }

  normaliseAttributes(outPd, report);
  report.nonFiniteArrayValues.clear();
  for (const ArrayInfo& info : describeArrays(output))
  {
    if (info.nonFinite > 0 && !isGeometryArray(info.name))
    {
      report.nonFiniteArrayValues.emplace_back(
          std::string(info.perCell ? "cell" : "point") + " array '" + info.name + "'",
          info.nonFinite);
    }
  }

  const EdgeCounts edges = countEdges(output);
  report.nonManifoldEdges = edges.nonManifold;
  report.boundaryEdges = edges.boundary;
  report.points = outCount;
  report.triangles = static_cast<int64_t>(triangles.size());
  report.hasNormals = outPd->GetNormals() != nullptr;
  report.hasTCoords = outPd->GetTCoords() != nullptr;
  report.hasTangents = outPd->GetTangents() != nullptr;
  return output;
}
} // namespace aniso
