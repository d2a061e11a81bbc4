// Normals split at sharp edges and the tangent policy of prepareSurface: a cube gets one normal
// per face corner (24 vertices, each with its face's geometric normal, pointing outwards), a
// sphere stays smooth (normals = positions), the feature angle is honoured, and the returned
// surface always meets the shading contract (float unit "Normals", "Tangents" orthogonal to them,
// active attributes).
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <vector>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

namespace aniso
{
namespace
{
// The unit cube [0, 1]^3 as 8 shared corners and 12 triangles, wound outwards (or inwards).
vtkSmartPointer<vtkPolyData> sharedCornerCube(bool inward = false)
{
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  // Corner index = x + 2 y + 4 z; each quad counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  vtkNew<vtkCellArray> polys;
  for (const auto& q : quads)
  {
    for (const auto& tri : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}})
    {
      const vtkIdType ids[3] = {tri[0], inward ? tri[2] : tri[1], inward ? tri[1] : tri[2]};
      polys->InsertNextCell(3, ids);
    }
  }
  cube->SetPoints(points);
  cube->SetPolys(polys);
  return cube;
}

void expectContract(vtkPolyData* surface)
{
  vtkPointData* pd = surface->GetPointData();
  ASSERT_NE(pd->GetNormals(), nullptr);
  ASSERT_NE(pd->GetTangents(), nullptr);
  EXPECT_STREQ(pd->GetNormals()->GetName(), "Normals");
  EXPECT_STREQ(pd->GetTangents()->GetName(), "Tangents");
  EXPECT_EQ(pd->GetNormals()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(pd->GetTangents()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(pd->GetNormals()->GetNumberOfComponents(), 3);
  EXPECT_EQ(pd->GetTangents()->GetNumberOfComponents(), 3);
  EXPECT_EQ(surface->GetNumberOfPolys(), surface->GetNumberOfCells()); // triangles only
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 n = test::vec3(pd->GetNormals(), i);
    const glm::dvec3 t = test::vec3(pd->GetTangents(), i);
    ASSERT_NEAR(glm::length(n), 1.0, 1e-6);
    ASSERT_NEAR(glm::length(t), 1.0, 1e-6);
    ASSERT_NEAR(glm::dot(n, t), 0.0, 1e-6);
  }
}

// Each triangle's three vertex normals equal its geometric normal, which points away from the
// cube centre; returns how many vertices carry each distinct normal.
std::map<std::array<int, 3>, int> expectFaceNormals(vtkPolyData* cube)
{
  vtkDataArray* normals = cube->GetPointData()->GetNormals();
  test::forEachTriangle(
      cube,
      [&](vtkIdType a, vtkIdType b, vtkIdType c)
      {
        const glm::dvec3 face = glm::normalize(test::faceNormalUnnormalised(cube, a, b, c));
        const glm::dvec3 centroid =
            (test::point(cube, a) + test::point(cube, b) + test::point(cube, c)) / 3.0;
        EXPECT_GT(glm::dot(face, centroid - glm::dvec3(0.5)), 0.0) << "outward";
        for (vtkIdType id : {a, b, c})
        {
          EXPECT_NEAR(glm::length(test::vec3(normals, id) - face), 0.0, 1e-6);
        }
      });
  std::map<std::array<int, 3>, int> uses;
  for (vtkIdType i = 0; i < cube->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 n = test::vec3(normals, i);
    ++uses[{static_cast<int>(std::lround(n.x)), static_cast<int>(std::lround(n.y)),
            static_cast<int>(std::lround(n.z))}];
  }
  return uses;
}

TEST(FeatureNormals, CubeCornersSplitIntoOneNormalPerFace)
{
  // 90-degree edges are sharper than 30 degrees: each corner splits into its three faces'
  // normals, 6 faces x 4 corners = 24 vertices, 6 directions used 4 times each.
  vtkSmartPointer<vtkPolyData> cube = computeFeatureNormals(sharedCornerCube(), 30.0, true);
  EXPECT_EQ(cube->GetNumberOfPoints(), 24);
  const auto uses = expectFaceNormals(cube);
  EXPECT_EQ(uses.size(), 6u);
  for (const auto& entry : uses)
  {
    EXPECT_EQ(entry.second, 4);
  }
}

TEST(FeatureNormals, InwardWoundClosedCubeIsOrientedOutwards)
{
  vtkSmartPointer<vtkPolyData> cube = computeFeatureNormals(sharedCornerCube(true), 30.0, true);
  EXPECT_EQ(cube->GetNumberOfPoints(), 24);
  expectFaceNormals(cube);
  EXPECT_GT(test::signedVolume(cube), 0.0); // the winding was turned too
}

TEST(FeatureNormals, AngleAboveTheEdgesKeepsCornersShared)
{
  // With a 100-degree feature angle no cube edge is sharp: the 8 corners stay shared, each with
  // the normalised sum of the unit normals of its triangles (VTK averages faces unweighted),
  // computed here from the geometry.
  vtkSmartPointer<vtkPolyData> input = sharedCornerCube();
  std::vector<glm::dvec3> sums(8, glm::dvec3(0.0));
  test::forEachTriangle(input,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c)
                        {
                          const glm::dvec3 n =
                              glm::normalize(test::faceNormalUnnormalised(input, a, b, c));
                          for (vtkIdType id : {a, b, c})
                          {
                            sums[static_cast<size_t>(id)] += n;
                          }
                        });
  vtkSmartPointer<vtkPolyData> cube = computeFeatureNormals(input, 100.0, true);
  ASSERT_EQ(cube->GetNumberOfPoints(), 8);
  for (vtkIdType i = 0; i < 8; ++i)
  {
    // Same corner order: nothing was split or reordered.
    ASSERT_EQ(test::point(cube, i), test::point(input, i));
    EXPECT_NEAR(glm::length(test::vec3(cube->GetPointData()->GetNormals(), i) -
                            glm::normalize(sums[static_cast<size_t>(i)])),
                0.0, 1e-6);
  }
}

TEST(FeatureNormals, SphereStaysSmooth)
{
  // Neighbouring faces of a 128 x 64 sphere differ by under 3 degrees, far below 30: no vertex
  // splits. Every face normal is within one grid step h = pi / 64 of the position of each of its
  // vertices, so their average is too: n . p > cos(h).
  LoadedMesh sphere = makeBuiltinMesh(BuiltinMesh::Sphere);
  MeshReport report;
  // Without UVs and frames the seam and pole copies are exact duplicates and merge: a closed
  // surface.
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(sphere.polyData);
  bare->GetPointData()->Initialize();
  vtkSmartPointer<vtkPolyData> merged = sanitizeSurface(bare, "sphere", report);
  EXPECT_EQ(report.boundaryEdges, 0);
  EXPECT_EQ(merged->GetNumberOfPoints(), 63 * 128 + 2);
  vtkSmartPointer<vtkPolyData> smooth = computeFeatureNormals(merged, 30.0, true);
  EXPECT_EQ(smooth->GetNumberOfPoints(), merged->GetNumberOfPoints());
  const double bound = std::cos(test::kPi / 64.0);
  for (vtkIdType i = 0; i < smooth->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = glm::normalize(test::point(smooth, i));
    EXPECT_GT(glm::dot(test::vec3(smooth->GetPointData()->GetNormals(), i), p), bound);
  }
}

TEST(FeatureNormals, AngleOutsideTheRangeIsRejected)
{
  EXPECT_THROW(computeFeatureNormals(sharedCornerCube(), 0.0, true), Error);
  EXPECT_THROW(computeFeatureNormals(sharedCornerCube(), 181.0, true), Error);
  EXPECT_THROW(computeFeatureNormals(sharedCornerCube(), std::nan(""), true), Error);
}

TEST(PrepareSurface, BuiltinSphereKeepsItsAnalyticFrame)
{
  LoadedMesh sphere = makeBuiltinMesh(BuiltinMesh::Sphere);
  for (const std::optional<BrushingModel>& brushing :
       {std::optional<BrushingModel>(), std::optional<BrushingModel>(BrushingModel{})})
  {
    PreparedSurface prepared = prepareSurface(sphere.polyData, {30.0, false, brushing}, "sphere");
    expectContract(prepared.polyData);
    EXPECT_FALSE(prepared.report.normalsComputed);
    EXPECT_EQ(prepared.report.tangentSource, "mesh");
    ASSERT_EQ(prepared.polyData->GetNumberOfPoints(), sphere.polyData->GetNumberOfPoints());
    vtkPointData* pd = prepared.polyData->GetPointData();
    ASSERT_NE(pd->GetTCoords(), nullptr);
    for (vtkIdType i = 0; i < prepared.polyData->GetNumberOfPoints(); ++i)
    {
      const glm::dvec3 p = test::point(prepared.polyData, i);
      const double phi = std::hypot(p.x, p.y) < 1e-9
                             ? 2.0 * test::kPi * test::vec2(pd->GetTCoords(), i).x
                             : std::atan2(p.y, p.x);
      ASSERT_NEAR(glm::length(test::vec3(pd->GetTangents(), i) -
                              glm::dvec3(-std::sin(phi), std::cos(phi), 0.0)),
                  0.0, 1e-6);
    }
  }
}

TEST(PrepareSurface, BrushingModelReplacesTheMeshTangents)
{
  LoadedMesh plate = makeBuiltinMesh(BuiltinMesh::Plate);
  SurfaceOptions options;
  options.brushing = parseBrushingModel("axis:0,1,0");
  PreparedSurface prepared = prepareSurface(plate.polyData, options, "plate");
  expectContract(prepared.polyData);
  EXPECT_EQ(prepared.report.tangentSource, "axis:0,1,0");
  for (vtkIdType i = 0; i < prepared.polyData->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(glm::length(test::vec3(prepared.polyData->GetPointData()->GetTangents(), i) -
                            glm::dvec3(0, 1, 0)),
                0.0, 1e-6);
  }
  // The input keeps its own tangents (+X).
  EXPECT_EQ(test::vec3(plate.polyData->GetPointData()->GetTangents(), 0), glm::dvec3(1, 0, 0));
}

TEST(PrepareSurface, CadMeshWithoutNormalsOrUvsGetsSplitNormalsAndDefaultBrushing)
{
  // No normals, no UVs: feature normals (24 vertices) and the default linear brushing along X,
  // which has no direction on the two faces facing +-X: 8 fallback vertices.
  vtkSmartPointer<vtkPolyData> cube = sharedCornerCube();
  PreparedSurface prepared = prepareSurface(cube, {}, "part.stl");
  expectContract(prepared.polyData);
  EXPECT_TRUE(prepared.report.normalsComputed);
  EXPECT_TRUE(prepared.report.normalsAutoOriented);
  EXPECT_EQ(prepared.report.pointsAddedBySplitting, 16);
  EXPECT_EQ(prepared.report.tangentSource, "axis:1,0,0");
  EXPECT_EQ(prepared.report.fallbackTangents, 8);
  EXPECT_EQ(prepared.polyData->GetPointData()->GetTCoords(), nullptr);
  EXPECT_FALSE(prepared.report.notes().empty());
  EXPECT_EQ(cube->GetNumberOfPoints(), 8); // the input is left as it was
  EXPECT_EQ(cube->GetPointData()->GetNormals(), nullptr);
}

TEST(PrepareSurface, ExplicitUvWithoutTextureCoordinatesIsAnError)
{
  SurfaceOptions options;
  options.brushing = BrushingModel{};
  EXPECT_THROW(prepareSurface(sharedCornerCube(), options, "part.stl"), Error);
}

TEST(PrepareSurface, TangentsAlongTheNormalAreRegeneratedFromTheUvs)
{
  // The sphere with its tangents overwritten by its normals (the "tangent parallel to normal"
  // defect): the whole field is regenerated from the UVs, which gives back the parallels.
  LoadedMesh sphere = makeBuiltinMesh(BuiltinMesh::Sphere);
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(sphere.polyData);
  vtkNew<vtkFloatArray> parallel;
  parallel->DeepCopy(broken->GetPointData()->GetNormals());
  parallel->SetName("Tangents");
  broken->GetPointData()->SetTangents(parallel);
  PreparedSurface prepared = prepareSurface(broken, {}, "sphere");
  expectContract(prepared.polyData);
  EXPECT_EQ(prepared.report.invalidMeshTangents, broken->GetNumberOfPoints());
  EXPECT_EQ(prepared.report.tangentSource, "uv");
  vtkDataArray* analytic = sphere.polyData->GetPointData()->GetTangents();
  // Same vertex order (no normals were recomputed). The discrete dP/du is exact up to rounding
  // except on the UV seam, where it tilts by half a slice (see test_brushing_model): 2 sin(dphi / 4).
  const double seamTilt = 2.0 * std::sin(2.0 * test::kPi / 128.0 / 4.0);
  for (vtkIdType i = 0; i < prepared.polyData->GetNumberOfPoints(); ++i)
  {
    EXPECT_LT(glm::length(test::vec3(prepared.polyData->GetPointData()->GetTangents(), i) -
                          test::vec3(analytic, i)),
              seamTilt + 1e-5);
  }
}

TEST(PrepareSurface, RecomputedNormalsCarryUvsAndTangentsToSplitVertices)
{
  // The plate has no sharp edge: recomputing its normals keeps +Z everywhere, and the UVs and
  // mesh tangents travel with the (unsplit) vertices.
  LoadedMesh plate = makeBuiltinMesh(BuiltinMesh::Plate);
  SurfaceOptions options;
  options.recomputeNormals = true;
  PreparedSurface prepared = prepareSurface(plate.polyData, options, "plate");
  expectContract(prepared.polyData);
  EXPECT_TRUE(prepared.report.normalsComputed);
  EXPECT_FALSE(prepared.report.normalsAutoOriented); // an open sheet is not auto-oriented
  EXPECT_EQ(prepared.report.tangentSource, "mesh");
  ASSERT_NE(prepared.polyData->GetPointData()->GetTCoords(), nullptr);
  for (vtkIdType i = 0; i < prepared.polyData->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(test::vec3(prepared.polyData->GetPointData()->GetNormals(), i).z, 1.0, 1e-6);
  }
}

TEST(PrepareSurface, FoldedNonManifoldSheetStillGetsFiniteFrames)
{
  // Two triangles on the same three vertices, wound opposite ways: their normals cancel at the
  // shared vertices. Whatever VTK makes of it, the result must be finite unit frames.
  auto folded = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> polys;
  const vtkIdType a[3] = {0, 1, 2};
  const vtkIdType b[3] = {0, 2, 1};
  const vtkIdType c[3] = {0, 1, 3};
  polys->InsertNextCell(3, a);
  polys->InsertNextCell(3, b);
  polys->InsertNextCell(3, c);
  folded->SetPoints(points);
  folded->SetPolys(polys);
  PreparedSurface prepared = prepareSurface(folded, {}, "folded");
  expectContract(prepared.polyData);
}
} // namespace
} // namespace aniso
