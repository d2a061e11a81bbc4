// Placing a part (vtkpasses/mesh/PartPlacement, core/placement.h): a prepared sphere placed by a
// rotation, a scale and a shift has its points where the matrix puts them, its normals those of
// the analytic surface it became (a sphere's turned normals; an ellipsoid's gradient
// (x/a^2, y/b^2, z/c^2) for a non-uniform scale), its tangents the turned ones made orthogonal
// to the normal, all unit; the input is left as it was; and checkPlacement refuses non-affine,
// singular and non-finite matrices.
#include "core/error.h"
#include "core/placement.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/PartPlacement.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace
{
using aniso::PartMatrix;

glm::dvec3 tupleOf(vtkDataArray* a, vtkIdType i)
{
  double v[3];
  a->GetTuple(i, v);
  return {v[0], v[1], v[2]};
}

glm::dvec3 pointOf(vtkPolyData* p, vtkIdType i)
{
  double v[3];
  p->GetPoint(i, v);
  return {v[0], v[1], v[2]};
}

vtkSmartPointer<vtkPolyData> preparedSphere()
{
  aniso::SurfaceOptions options;
  options.brushing = aniso::parseBrushingModel("axis:1,0,0", "tangents");
  return aniso::prepareSurface(aniso::makeSphere(48, 24), options, "sphere").polyData;
}

TEST(PartPlacement, RotationScaleAndShiftMoveEverything)
{
  const vtkSmartPointer<vtkPolyData> sphere = preparedSphere();
  // 90 degrees about z, scale 2, shift (5, -1, 3): (x, y, z) -> (-2y + 5, 2x - 1, 2z + 3).
  const PartMatrix m{0.0, -2.0, 0.0, 5.0, 2.0, 0.0, 0.0, -1.0, 0.0, 0.0, 2.0, 3.0, 0, 0, 0, 1};
  const vtkSmartPointer<vtkPolyData> placed = aniso::placedSurface(sphere, m);
  ASSERT_EQ(placed->GetNumberOfPoints(), sphere->GetNumberOfPoints());
  ASSERT_EQ(placed->GetNumberOfPolys(), sphere->GetNumberOfPolys());
  vtkDataArray* n0 = sphere->GetPointData()->GetNormals();
  vtkDataArray* t0 = sphere->GetPointData()->GetTangents();
  vtkDataArray* n1 = placed->GetPointData()->GetNormals();
  vtkDataArray* t1 = placed->GetPointData()->GetTangents();
  ASSERT_TRUE(n1 && t1);
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = pointOf(sphere, i);
    const glm::dvec3 q = pointOf(placed, i);
    EXPECT_NEAR(glm::length(q - glm::dvec3(-2.0 * p.y + 5.0, 2.0 * p.x - 1.0, 2.0 * p.z + 3.0)),
                0.0, 1e-5);
    const auto turn = [](const glm::dvec3& v) { return glm::dvec3(-v.y, v.x, v.z); };
    EXPECT_NEAR(glm::length(tupleOf(n1, i) - turn(tupleOf(n0, i))), 0.0, 1e-5);
    EXPECT_NEAR(glm::length(tupleOf(t1, i) - turn(tupleOf(t0, i))), 0.0, 1e-5);
  }
  // The input is untouched.
  EXPECT_NE(placed->GetPoints(), sphere->GetPoints());
  EXPECT_EQ(sphere->GetPointData()->GetNormals(), n0);
}

TEST(PartPlacement, NonUniformScaleGivesTheEllipsoidsNormals)
{
  const vtkSmartPointer<vtkPolyData> sphere = preparedSphere();
  const double a = 3.0, b = 1.0, c = 0.5;
  const PartMatrix m{a, 0, 0, 0, 0, b, 0, 0, 0, 0, c, 0, 0, 0, 0, 1};
  const vtkSmartPointer<vtkPolyData> placed = aniso::placedSurface(sphere, m);
  vtkDataArray* n = placed->GetPointData()->GetNormals();
  vtkDataArray* t = placed->GetPointData()->GetTangents();
  double worst = 0.0;
  for (vtkIdType i = 0; i < placed->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 q = pointOf(placed, i);
    // The sphere's mesh normals are its analytic ones to mesh precision: compare with the
    // ellipsoid's gradient at the same point through the same map.
    const glm::dvec3 mapped = glm::normalize(tupleOf(sphere->GetPointData()->GetNormals(), i) /
                                             glm::dvec3(a, b, c));
    EXPECT_NEAR(glm::length(tupleOf(n, i) - mapped), 0.0, 1e-5);
    const glm::dvec3 gradient = glm::normalize(q / glm::dvec3(a * a, b * b, c * c));
    worst = std::max(worst, glm::length(tupleOf(n, i) - gradient));
    EXPECT_NEAR(glm::length(tupleOf(t, i)), 1.0, 1e-5);
    EXPECT_NEAR(glm::dot(tupleOf(t, i), tupleOf(n, i)), 0.0, 1e-5);
  }
  EXPECT_LT(worst, 0.05); // a faceted sphere's normals against the smooth ellipsoid's
}

TEST(PartPlacement, BadMatricesAreRefused)
{
  const auto reason = [](const PartMatrix& m)
  {
    try
    {
      aniso::checkPlacement(m, "part");
    }
    catch (const aniso::Error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(reason(aniso::kIdentityPlacement), "");
  PartMatrix projective = aniso::kIdentityPlacement;
  projective[12] = 0.1;
  EXPECT_NE(reason(projective).find("part: a placement's last row"), std::string::npos);
  PartMatrix flat = aniso::kIdentityPlacement;
  flat[10] = 0.0;
  EXPECT_NE(reason(flat).find("singular"), std::string::npos);
  PartMatrix nan = aniso::kIdentityPlacement;
  nan[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(reason(nan).find("finite"), std::string::npos);
  PartMatrix mirror = aniso::kIdentityPlacement;
  mirror[0] = -1.0;
  EXPECT_EQ(reason(mirror), ""); // a mirrored part is a part
}
} // namespace
