#include "vtkpasses/mesh/BuiltinMeshes.h"

#include "core/error.h"

#include <cmath>
#include <vector>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// Vertices with their analytic attributes, then triangles; turned into the contract's polydata.
class MeshBuilder
{
public:
  vtkIdType addVertex(const double position[3], const double normal[3], const double tangent[3],
                      double u, double v)
  {
    const vtkIdType id = this->Points->InsertNextPoint(position);
    this->Normals->InsertNextTuple(normal);
    this->Tangents->InsertNextTuple(tangent);
    const double uv[2] = {u, v};
    this->TCoords->InsertNextTuple(uv);
    return id;
  }

  void addTriangle(vtkIdType a, vtkIdType b, vtkIdType c)
  {
    const vtkIdType ids[3] = {a, b, c};
    this->Polys->InsertNextCell(3, ids);
  }

  vtkSmartPointer<vtkPolyData> build()
  {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(this->Points);
    polyData->SetPolys(this->Polys);
    this->Normals->SetName("Normals");
    this->Tangents->SetName("Tangents");
    this->TCoords->SetName("TCoords");
    polyData->GetPointData()->SetNormals(this->Normals);
    polyData->GetPointData()->SetTangents(this->Tangents);
    polyData->GetPointData()->SetTCoords(this->TCoords);
    return polyData;
  }

  MeshBuilder()
  {
    this->Normals->SetNumberOfComponents(3);
    this->Tangents->SetNumberOfComponents(3);
    this->TCoords->SetNumberOfComponents(2);
  }

private:
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkFloatArray> Tangents;
  vtkNew<vtkFloatArray> TCoords;
};

void requireAtLeast(int value, int minimum, const char* what)
{
  if (value < minimum)
  {
    throw errorAbout(what, "needs at least " + std::to_string(minimum) + " segments, got " +
                               std::to_string(value));
  }
}

// 2 pi i / n, with the last seam copy (i = n) at exactly 0: the two copies of a seam vertex
// differ only in their UVs, so a merge that ignores UVs finds them bit-for-bit equal.
double seamAngle(int i, int n)
{
  return i == n ? 0.0 : 2.0 * kPi * i / n;
}

// Two counter-clockwise triangles for the grid quad a(i, k) b(i+1, k) c(i+1, k+1) d(i, k+1),
// where a->b runs along +t and a->d along +b = n x t.
void addQuad(MeshBuilder& builder, vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
  builder.addTriangle(a, b, c);
  builder.addTriangle(a, c, d);
}
} // namespace

BuiltinMesh parseBuiltinMesh(const std::string& name, const std::string& subject)
{
  for (BuiltinMesh mesh :
       {BuiltinMesh::Sphere, BuiltinMesh::Torus, BuiltinMesh::Plate, BuiltinMesh::Disk})
  {
    if (name == builtinMeshName(mesh))
    {
      return mesh;
    }
  }
  throw errorAbout(subject,
                   "unknown built-in mesh '" + name + "' (expected " + builtinMeshNames() + ")");
}

std::string builtinMeshName(BuiltinMesh mesh)
{
  switch (mesh)
  {
  case BuiltinMesh::Sphere:
    return "sphere";
  case BuiltinMesh::Torus:
    return "torus";
  case BuiltinMesh::Plate:
    return "plate";
  case BuiltinMesh::Disk:
    return "disk";
  }
  return "sphere";
}

std::string builtinMeshNames()
{
  return "sphere|torus|plate|disk";
}

vtkSmartPointer<vtkPolyData> makeSphere(int segmentsAround, int segmentsPoleToPole)
{
  requireAtLeast(segmentsAround, 3, "sphere segments around");
  requireAtLeast(segmentsPoleToPole, 2, "sphere segments pole to pole");
  const int nu = segmentsAround;
  const int nv = segmentsPoleToPole;
  MeshBuilder builder;

  // Rings 1 .. nv-1 from north to south, each with a duplicated seam vertex (u = 0 and u = 1).
  std::vector<std::vector<vtkIdType>> rings(static_cast<size_t>(nv + 1));
  for (int j = 1; j < nv; ++j)
  {
    const double theta = kPi * j / nv;
    for (int i = 0; i <= nu; ++i)
    {
      const double phi = seamAngle(i, nu);
      const double p[3] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta)};
      const double t[3] = {-std::sin(phi), std::cos(phi), 0.0};
      rings[static_cast<size_t>(j)].push_back(builder.addVertex(
          p, p, t, static_cast<double>(i) / nu, 1.0 - static_cast<double>(j) / nv));
    }
  }
  // Pole fans: one pole vertex per triangle, at the triangle's mid-longitude, so its u and its
  // tangent are those of the slice it closes.
  for (int i = 0; i < nu; ++i)
  {
    const double phi = 2.0 * kPi * (i + 0.5) / nu;
    const double t[3] = {-std::sin(phi), std::cos(phi), 0.0};
    const double u = (i + 0.5) / nu;
    const double north[3] = {0.0, 0.0, 1.0};
    const double south[3] = {0.0, 0.0, -1.0};
    const vtkIdType n = builder.addVertex(north, north, t, u, 1.0);
    const vtkIdType s = builder.addVertex(south, south, t, u, 0.0);
    const auto& first = rings[1];
    const auto& last = rings[static_cast<size_t>(nv - 1)];
    builder.addTriangle(n, first[static_cast<size_t>(i)], first[static_cast<size_t>(i + 1)]);
    builder.addTriangle(s, last[static_cast<size_t>(i + 1)], last[static_cast<size_t>(i)]);
  }
  // Bands: ring j is north of ring j+1, so going south runs along -b; the quad is wound
  // accordingly to face outwards.
  for (int j = 1; j + 1 < nv; ++j)
  {
    const auto& upper = rings[static_cast<size_t>(j)];
    const auto& lower = rings[static_cast<size_t>(j + 1)];
    for (size_t i = 0; i < static_cast<size_t>(nu); ++i)
    {
      addQuad(builder, lower[i], lower[i + 1], upper[i + 1], upper[i]);
    }
  }
  return builder.build();
}

vtkSmartPointer<vtkPolyData> makeTorus(int segmentsAround, int segmentsAroundTube,
                                       double majorRadius, double minorRadius)
{
  requireAtLeast(segmentsAround, 3, "torus segments around");
  requireAtLeast(segmentsAroundTube, 3, "torus segments around the tube");
  if (!(minorRadius > 0.0) || !(majorRadius > minorRadius))
  {
    throw errorAbout("torus radii", "need 0 < minor < major");
  }
  const int nu = segmentsAround;
  const int nv = segmentsAroundTube;
  MeshBuilder builder;
  std::vector<vtkIdType> ids;
  for (int i = 0; i <= nu; ++i)
  {
    const double phi = seamAngle(i, nu);
    for (int k = 0; k <= nv; ++k)
    {
      const double psi = seamAngle(k, nv);
      const double ring = majorRadius + minorRadius * std::cos(psi);
      const double p[3] = {ring * std::cos(phi), ring * std::sin(phi), minorRadius * std::sin(psi)};
      const double n[3] = {std::cos(psi) * std::cos(phi), std::cos(psi) * std::sin(phi),
                           std::sin(psi)};
      const double t[3] = {-std::sin(phi), std::cos(phi), 0.0};
      ids.push_back(
          builder.addVertex(p, n, t, static_cast<double>(i) / nu, static_cast<double>(k) / nv));
    }
  }
  const auto at = [&ids, nv](int i, int k) { return ids[static_cast<size_t>(i * (nv + 1) + k)]; };
  for (int i = 0; i < nu; ++i)
  {
    for (int k = 0; k < nv; ++k)
    {
      addQuad(builder, at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1));
    }
  }
  return builder.build();
}

vtkSmartPointer<vtkPolyData> makePlate(int segmentsPerSide)
{
  requireAtLeast(segmentsPerSide, 1, "plate segments per side");
  const int n = segmentsPerSide;
  MeshBuilder builder;
  std::vector<vtkIdType> ids;
  const double normal[3] = {0.0, 0.0, 1.0};
  const double tangent[3] = {1.0, 0.0, 0.0};
  for (int k = 0; k <= n; ++k)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double u = static_cast<double>(i) / n;
      const double v = static_cast<double>(k) / n;
      const double p[3] = {2.0 * u - 1.0, 2.0 * v - 1.0, 0.0};
      ids.push_back(builder.addVertex(p, normal, tangent, u, v));
    }
  }
  const auto at = [&ids, n](int i, int k) { return ids[static_cast<size_t>(k * (n + 1) + i)]; };
  for (int k = 0; k < n; ++k)
  {
    for (int i = 0; i < n; ++i)
    {
      addQuad(builder, at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1));
    }
  }
  return builder.build();
}

vtkSmartPointer<vtkPolyData> makeDisk(int segmentsAround, int rings)
{
  requireAtLeast(segmentsAround, 3, "disk segments around");
  requireAtLeast(rings, 1, "disk rings");
  MeshBuilder builder;
  const double normal[3] = {0.0, 0.0, 1.0};
  const double tangent[3] = {1.0, 0.0, 0.0};
  const double centre[3] = {0.0, 0.0, 0.0};
  const vtkIdType middle = builder.addVertex(centre, normal, tangent, 0.5, 0.5);
  // ring k (1..rings) has segmentsAround vertices at radius k / rings; no seam, the UVs are planar.
  std::vector<vtkIdType> ids;
  for (int k = 1; k <= rings; ++k)
  {
    const double r = static_cast<double>(k) / rings;
    for (int i = 0; i < segmentsAround; ++i)
    {
      const double phi = 2.0 * kPi * i / segmentsAround;
      const double p[3] = {r * std::cos(phi), r * std::sin(phi), 0.0};
      ids.push_back(builder.addVertex(p, normal, tangent, 0.5 * (p[0] + 1.0), 0.5 * (p[1] + 1.0)));
    }
  }
  const auto at = [&ids, segmentsAround](int i, int k)
  { return ids[static_cast<size_t>((k - 1) * segmentsAround + i % segmentsAround)]; };
  for (int i = 0; i < segmentsAround; ++i)
  {
    builder.addTriangle(middle, at(i, 1), at(i + 1, 1));
  }
  for (int k = 1; k < rings; ++k)
  {
    for (int i = 0; i < segmentsAround; ++i)
    {
      addQuad(builder, at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k));
    }
  }
  return builder.build();
}

LoadedMesh makeBuiltinMesh(BuiltinMesh mesh)
{
  LoadedMesh result;
  switch (mesh)
  {
  case BuiltinMesh::Sphere:
    result.polyData = makeSphere();
    break;
  case BuiltinMesh::Torus:
    result.polyData = makeTorus();
    break;
  case BuiltinMesh::Plate:
    result.polyData = makePlate();
    break;
  case BuiltinMesh::Disk:
    result.polyData = makeDisk();
    break;
  }
  MeshReport& report = result.report;
  report.source = "builtin:" + builtinMeshName(mesh);
  report.points = report.pointsRead = result.polyData->GetNumberOfPoints();
  report.triangles = report.cellsRead = result.polyData->GetNumberOfCells();
  report.hasNormals = report.hasTCoords = report.hasTangents = true;
  // Seams and poles are open edges by construction (their vertices are duplicated for the UVs).
  const EdgeCounts edges = countEdges(result.polyData);
  report.boundaryEdges = edges.boundary;
  report.nonManifoldEdges = edges.nonManifold;
  return result;
}
} // namespace aniso
