// Built-in meshes against their analytic definitions (docs/METHOD.md conventions): positions on the
// implicit surface, normals and tangents from the closed-form parametrisation, the UV
// convention recovered from positions with atan2/acos, outward winding (signed volume and face
// normals), and area/volume against the closed-form values of the smooth shapes.
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshValidation.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace aniso
{
namespace
{
using test::kPi;

double wrap01(double x)
{
  return x - std::floor(x);
}

// Every vertex: unit tangent orthogonal to the unit normal, both float-accurate.
void expectOrthonormalFrames(vtkPolyData* mesh)
{
  vtkPointData* pd = mesh->GetPointData();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 n = test::vec3(pd->GetNormals(), i);
    const glm::dvec3 t = test::vec3(pd->GetTangents(), i);
    ASSERT_NEAR(glm::length(n), 1.0, 1e-6) << "point " << i;
    ASSERT_NEAR(glm::length(t), 1.0, 1e-6) << "point " << i;
    ASSERT_NEAR(glm::dot(n, t), 0.0, 1e-6) << "point " << i;
  }
}

// Outward, counter-clockwise winding: each face normal agrees with its vertex normals, and
// the UV triangle is counter-clockwise too (a right-handed UV map: t x b = n with b = n x t).
void expectConsistentWinding(vtkPolyData* mesh)
{
  vtkPointData* pd = mesh->GetPointData();
  test::forEachTriangle(mesh,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c)
                        {
                          const glm::dvec3 face = test::faceNormalUnnormalised(mesh, a, b, c);
                          for (vtkIdType id : {a, b, c})
                          {
                            EXPECT_GT(glm::dot(face, test::vec3(pd->GetNormals(), id)), 0.0);
                          }
                          const glm::dvec2 uv0 = test::vec2(pd->GetTCoords(), a);
                          const glm::dvec2 d1 = test::vec2(pd->GetTCoords(), b) - uv0;
                          const glm::dvec2 d2 = test::vec2(pd->GetTCoords(), c) - uv0;
                          EXPECT_GT(d1.x * d2.y - d1.y * d2.x, 0.0);
                        });
}

TEST(BuiltinSphere, PositionsNormalsTangentsAndUvFollowTheAnalyticParametrisation)
{
  vtkSmartPointer<vtkPolyData> sphere = makeSphere(128, 64);
  vtkPointData* pd = sphere->GetPointData();
  ASSERT_NE(pd->GetNormals(), nullptr);
  ASSERT_NE(pd->GetTangents(), nullptr);
  ASSERT_NE(pd->GetTCoords(), nullptr);
  // 63 rings of 129 vertices (seam duplicated) plus one pole vertex per fan triangle.
  EXPECT_EQ(sphere->GetNumberOfPoints(), 63 * 129 + 2 * 128);
  EXPECT_EQ(sphere->GetNumberOfPolys(), 2 * 128 + 2 * 128 * 62);

  int poleVertices = 0;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(sphere, i);
    const glm::dvec3 n = test::vec3(pd->GetNormals(), i);
    const glm::dvec3 t = test::vec3(pd->GetTangents(), i);
    const glm::dvec2 uv = test::vec2(pd->GetTCoords(), i);
    ASSERT_NEAR(glm::length(p), 1.0, 1e-6);
    // The unit sphere's normal is its position.
    ASSERT_NEAR(glm::length(n - p), 0.0, 1e-6);
    // v = latitude: 1 - theta / pi with theta the polar angle from +Z.
    EXPECT_NEAR(uv.y, 1.0 - std::acos(std::clamp(p.z, -1.0, 1.0)) / kPi, 1e-6);
    const double radial = std::hypot(p.x, p.y);
    double phi = 0.0;
    if (radial < 1e-9)
    {
      // Pole: longitude is undefined; the vertex carries the longitude of its fan slice.
      ++poleVertices;
      phi = 2.0 * kPi * uv.x;
    }
    else
    {
      phi = std::atan2(p.y, p.x);
      // u = atan2(y, x) / (2 pi) wrapped to [0, 1); the seam copy at phi = 0 has u = 1.
      const double expectedU = wrap01(phi / (2.0 * kPi));
      const bool seamCopy = std::abs(uv.x - 1.0) < 1e-6 && expectedU < 1e-6;
      if (!seamCopy)
      {
        EXPECT_NEAR(uv.x, expectedU, 1e-6) << "point " << i;
      }
    }
    // dP/du normalised = (-sin phi, cos phi, 0): along the parallels.
    const glm::dvec3 expectedT(-std::sin(phi), std::cos(phi), 0.0);
    ASSERT_NEAR(glm::length(t - expectedT), 0.0, 1e-6) << "point " << i;
    // b = n x t points north (towards +v), so the frame is right-handed in UV.
    EXPECT_GE(glm::cross(n, t).z, -1e-6);
  }
  EXPECT_EQ(poleVertices, 2 * 128);
  expectOrthonormalFrames(sphere);
  expectConsistentWinding(sphere);
}

TEST(BuiltinSphere, PoleVerticesSitAtTheMidLongitudeOfTheirSlice)
{
  // Each pole vertex closes one fan triangle whose other two vertices are on the first ring at
  // longitudes phi_i and phi_{i+1}; its u must be their mean.
  vtkSmartPointer<vtkPolyData> sphere = makeSphere(16, 8);
  vtkDataArray* tc = sphere->GetPointData()->GetTCoords();
  int fans = 0;
  test::forEachTriangle(sphere,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c)
                        {
                          if (std::abs(std::abs(test::point(sphere, a).z) - 1.0) < 1e-9)
                          {
                            ++fans;
                            EXPECT_NEAR(test::vec2(tc, a).x,
                                        0.5 * (test::vec2(tc, b).x + test::vec2(tc, c).x), 1e-6);
                          }
                        });
  EXPECT_EQ(fans, 2 * 16);
}

TEST(BuiltinSphere, AreaAndVolumeApproachTheSmoothSphere)
{
  // The inscribed polyhedron falls short of 4 pi and 4 pi / 3 by about (2 pi / n)^2 / 6 per
  // direction of subdivision (4e-4 for the 128 segments around, plus the same order for the 64
  // from pole to pole): a relative 2e-3 bound holds with margin. A positive volume also proves
  // outward winding.
  vtkSmartPointer<vtkPolyData> sphere = makeSphere();
  EXPECT_NEAR(test::surfaceArea(sphere) / (4.0 * kPi), 1.0, 2e-3);
  EXPECT_NEAR(test::signedVolume(sphere) / (4.0 * kPi / 3.0), 1.0, 2e-3);
}

TEST(BuiltinTorus, GeometryFrameAndUvFollowTheAnalyticParametrisation)
{
  const double R = 1.0;
  const double r = 0.35;
  vtkSmartPointer<vtkPolyData> torus = makeTorus(128, 64, R, r);
  vtkPointData* pd = torus->GetPointData();
  for (vtkIdType i = 0; i < torus->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(torus, i);
    const glm::dvec3 n = test::vec3(pd->GetNormals(), i);
    const glm::dvec3 t = test::vec3(pd->GetTangents(), i);
    const glm::dvec2 uv = test::vec2(pd->GetTCoords(), i);
    const double phi = std::atan2(p.y, p.x);
    const double rho = std::hypot(p.x, p.y);
    // Implicit torus: (rho - R)^2 + z^2 = r^2.
    ASSERT_NEAR(std::hypot(rho - R, p.z), r, 1e-6);
    // Normal: from the tube centre circle to the point, divided by r.
    const glm::dvec3 tubeCentre(R * std::cos(phi), R * std::sin(phi), 0.0);
    ASSERT_NEAR(glm::length(n - (p - tubeCentre) / r), 0.0, 1e-5);
    ASSERT_NEAR(glm::length(t - glm::dvec3(-std::sin(phi), std::cos(phi), 0.0)), 0.0, 1e-6);
    // u around the main axis, v around the tube from the outer equator towards +Z; seams at
    // 0 and 1 are both valid.
    const double expectedU = wrap01(phi / (2.0 * kPi));
    const double expectedV = wrap01(std::atan2(p.z, rho - R) / (2.0 * kPi));
    EXPECT_NEAR(std::min(std::abs(uv.x - expectedU), std::abs(std::abs(uv.x - expectedU) - 1.0)),
                0.0, 1e-6);
    EXPECT_NEAR(std::min(std::abs(uv.y - expectedV), std::abs(std::abs(uv.y - expectedV) - 1.0)),
                0.0, 1e-6);
  }
  expectOrthonormalFrames(torus);
  expectConsistentWinding(torus);
  // Pappus: area 4 pi^2 R r, volume 2 pi^2 R r^2. Inscribed polygons of n sides lose about
  // (2 pi / n)^2 / 6 of each circle: 1.6e-3 for the tube's 64 plus 4e-4 for the 128 around,
  // so 3e-3 bounds the deficit with margin.
  EXPECT_NEAR(test::surfaceArea(torus) / (4.0 * kPi * kPi * R * r), 1.0, 3e-3);
  EXPECT_NEAR(test::signedVolume(torus) / (2.0 * kPi * kPi * R * r * r), 1.0, 3e-3);
}

TEST(BuiltinPlate, IsTheTwoByTwoSquareFacingZWithUAlongX)
{
  vtkSmartPointer<vtkPolyData> plate = makePlate(32);
  vtkPointData* pd = plate->GetPointData();
  double bounds[6];
  plate->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[0], -1.0);
  EXPECT_DOUBLE_EQ(bounds[1], 1.0);
  EXPECT_DOUBLE_EQ(bounds[2], -1.0);
  EXPECT_DOUBLE_EQ(bounds[3], 1.0);
  EXPECT_DOUBLE_EQ(bounds[4], 0.0);
  EXPECT_DOUBLE_EQ(bounds[5], 0.0);
  for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(plate, i);
    EXPECT_EQ(test::vec3(pd->GetNormals(), i), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(test::vec3(pd->GetTangents(), i), glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).x, (p.x + 1.0) / 2.0, 1e-6);
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).y, (p.y + 1.0) / 2.0, 1e-6);
  }
  expectConsistentWinding(plate);
  EXPECT_NEAR(test::surfaceArea(plate), 4.0, 1e-9);
}

TEST(BuiltinMeshes, PassTheLoaderValidationUnchanged)
{
  // The validation a file goes through finds nothing to drop or merge: no zero-area faces at
  // the poles, and seam/pole duplicates differ in their UVs so they are kept.
  for (BuiltinMesh kind : {BuiltinMesh::Sphere, BuiltinMesh::Torus, BuiltinMesh::Plate})
  {
    LoadedMesh mesh = makeBuiltinMesh(kind);
    MeshReport report;
    vtkSmartPointer<vtkPolyData> clean = sanitizeSurface(mesh.polyData, mesh.report.source, report);
    EXPECT_EQ(report.zeroAreaTrianglesDropped, 0) << mesh.report.source;
    EXPECT_EQ(report.duplicateVerticesMerged, 0) << mesh.report.source;
    EXPECT_EQ(report.nonManifoldEdges, 0) << mesh.report.source;
    EXPECT_EQ(clean->GetNumberOfPolys(), mesh.polyData->GetNumberOfPolys());
    EXPECT_EQ(mesh.report.triangles, mesh.polyData->GetNumberOfPolys());
    EXPECT_TRUE(mesh.report.hasNormals && mesh.report.hasTangents && mesh.report.hasTCoords);
    EXPECT_EQ(mesh.report.source, "builtin:" + builtinMeshName(kind));
  }
}

TEST(BuiltinMeshes, NamesParseAndUnknownNamesAreRejected)
{
  EXPECT_EQ(parseBuiltinMesh("sphere"), BuiltinMesh::Sphere);
  EXPECT_EQ(parseBuiltinMesh("torus"), BuiltinMesh::Torus);
  EXPECT_EQ(parseBuiltinMesh("plate"), BuiltinMesh::Plate);
  try
  {
    parseBuiltinMesh("cube");
    FAIL() << "an unknown name must be rejected";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()),
              "--builtin: unknown built-in mesh 'cube' (expected sphere|torus|plate|disk)");
  }
  EXPECT_THROW(makeSphere(2, 64), Error);
  EXPECT_THROW(makeTorus(128, 64, 0.3, 0.35), Error);
}
} // namespace
} // namespace aniso
